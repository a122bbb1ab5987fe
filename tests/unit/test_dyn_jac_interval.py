"""The Jacobian's refresh interval chosen from the run's record (issue 14, seventeenth pass):
:func:`bearingsim.dynamics.integrate.jacobian.refresh_interval` and :func:`record_attempt`, and the engine's use of
them.  Consistency and mechanism tests (the rule is an engine choice, not a physical model: its effect on the work
is measured by benchmarks/bench_dynamics.py, docs/development/history.md)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.dynamics import run as R
from bearingsim.dynamics.integrate import base
from bearingsim.dynamics.integrate.jacobian import JAC_EXPLORE, JAC_FORGET, record_attempt, refresh_interval

A = base.JAC_AGES
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
CASES = {"a": EXAMPLES / "spindle-7011.toml", "b": EXAMPLES / "hub-moment-50hz.toml"}


def load_bench_case(name):
    from bearingsim.dynamics.case import load_case

    return load_case(CASES[name])


def fill(mem, rhs, adv, intervals=40):
    """``intervals`` intervals of len(rhs) steps, step k costing rhs[k] right-hand sides and advancing adv[k] [s],
    recorded as the integrator does (refresh_interval at each refresh, then record_attempt per step)."""
    for _ in range(intervals):
        refresh_interval(mem, len(rhs), 9.0)
        for k in range(len(rhs)):
            record_attempt(mem, k, rhs[k], adv[k])


def best_interval(rhs, adv, cost, cap):
    """The cost-per-time minimiser written directly (numpy), for comparison."""
    c = [(cost + np.sum(rhs[:n])) / np.sum(adv[:n]) for n in range(1, cap + 1)]
    return int(np.argmin(c)) + 1


def test_no_record_gives_the_cap():
    mem = np.zeros(base.JAC_MEMORY)
    assert refresh_interval(mem, 20, 9.0) == 20


def test_record_counts_each_age_once_per_interval():
    mem = np.zeros(base.JAC_MEMORY)
    refresh_interval(mem, 20, 9.0)
    record_attempt(mem, 0, 3.0, 0.0)  # rejected
    record_attempt(mem, 0, 4.0, 2e-6)  # accepted at the same age
    record_attempt(mem, 1, 4.0, 3e-6)
    assert mem[3 + 2 * A + 0] == 1.0 and mem[3 + 2 * A + 1] == 1.0
    assert mem[3 + 0] == 7.0 and mem[3 + A + 0] == 2e-6 and mem[3 + A + 1] == 3e-6
    before = mem[3:].copy()
    refresh_interval(mem, 20, 9.0)
    np.testing.assert_allclose(mem[3:], before * (1.0 - JAC_FORGET), rtol=1e-15)
    assert mem[2] == -1.0  # the next interval's ages count afresh


@settings(max_examples=40, deadline=None)
@given(h1=st.floats(1e-7, 1e-5), decay=st.floats(0.0, 0.3), cap=st.integers(2, 40), cost=st.floats(1.0, 20.0))
def test_interval_minimises_the_cost_per_simulated_time(h1, decay, cap, cost):
    """Steps that shrink with the Jacobian's age (the 7011's stability limit) against a refresh's cost: the interval
    chosen is the minimiser of (Σ r_k + cost)/Σ τ_k; every JAC_EXPLORE-th interval it is lengthened."""
    n = cap
    adv = h1 / (1.0 + decay * np.arange(n)) ** 2
    rhs = np.full(n, 4.0)
    mem = np.zeros(base.JAC_MEMORY)
    fill(mem, rhs, adv)
    expect = best_interval(rhs, adv, cost, cap)
    got = refresh_interval(mem, cap, cost)
    if int(mem[1]) % JAC_EXPLORE == 0:
        expect = min(cap, max(2 * expect, expect + 5))
    assert got == expect, (got, expect)


def test_flat_steps_keep_the_cap_and_falling_ones_shorten_it():
    mem = np.zeros(base.JAC_MEMORY)
    fill(mem, np.full(20, 4.0), np.full(20, 2e-6))
    assert refresh_interval(mem, 20, 9.0) == 20
    mem = np.zeros(base.JAC_MEMORY)
    fill(mem, np.full(20, 4.0), 5e-6 / (1.0 + 0.25 * np.arange(20)))  # the 7011's profile: 5 µs, then falling
    assert refresh_interval(mem, 20, 9.0) < 10


def test_engine_shortens_the_interval_where_the_steps_fall_with_age():
    """The path the user takes (Stepper, the cached kernel), the 7011 spindle (a) over its first 3 ms with the
    Jacobian used as made (``jac_orbit=False``; turned with the balls' orbit, the default, its step no longer falls
    with age: tests/unit/test_dyn_orbit_turn.py): the record shows the step falling with the Jacobian's age (a
    stability limit that the aging J sets) and the interval chosen stays well below the cap of 20 (measured 8, 16
    when lengthened to explore) (docs/development/history.md, seventeenth pass)."""
    case = load_bench_case("a")
    m, ls, y, _ = R.build(case)
    st_ = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, dense=True, jac_orbit=False)
    chosen = []
    for k in range(1, 7):
        st_.advance(k * 0.5e-3)
        chosen.append(int(st_._ws[5][0]))
    mem = st_._ws[5]
    assert mem.shape == (base.JAC_MEMORY,) and mem[1] > 20, mem[1]  # enough refreshes seen
    visits = mem[3 + 2 * A:3 + 3 * A]
    tau = mem[3 + A:3 + 2 * A] / np.maximum(visits, 1e-300)
    assert tau[1] > 1.3 * tau[7], tau[:10]
    assert all(1 <= n <= 20 for n in chosen), chosen
    assert np.median(chosen) <= 10, chosen


def test_fixed_interval_has_no_record():
    case = load_bench_case("a")
    m, ls, y, _ = R.build(case)
    st_ = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, jac_adaptive=False)
    st_.advance(2e-4)
    assert st_._ws[5].shape == (0,)
    nfun, _, njac = (int(v) for v in st_.workspace.work[:3])
    assert njac <= st_.steps // st_.jac_every + 1 + st_.rejected
