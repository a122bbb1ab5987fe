"""The multirate refinement of ROS34PW2 steps (issue 14, eighteenth pass; :mod:`bearingsim.dynamics.integrate.multirate`).

Three kinds of check: the pieces (the masked right-hand side against the full one, the choice of the balls, the
latent interpolant, the turned block), the premise (at the hub's moment zero crossing a few balls hold the step),
and the engine on the path the user takes (Stepper): fewer steps, the ring and the balls within the tolerance of a
tight reference, the dense output of the refined balls on their own micro steps.  Consistency checks (dynamics
against dynamics), not literature validation."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import run as R
from bearingsim.dynamics.case import load_case
from bearingsim.dynamics.integrate import multirate as mrm

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
T0 = 9.1e-3  # the hub's moment zero crossing: the unloaded row's balls rattle (docs/development/history.md, eighteenth pass)


@pytest.fixture(scope="module")
def hub():
    """The hub case (b) and a plain-engine state at its first moment zero crossing."""
    c = load_case(EXAMPLES / "hub-moment-50hz.toml")
    m, ls, y, _ = R.build(c)
    st_ = R.Stepper(m, ls, y.copy(), tol=c.tolerance, method="ros34w", threads=1, multirate=0)
    st_.advance(T0)
    return c, m, ls, st_


@settings(max_examples=25, deadline=None)
@given(data=st.data())
def test_masked_rhs_is_the_full_one_on_the_active_balls(hub, data):
    """rhs_masked computes the active balls' derivatives bit for bit as the full right-hand side does (their
    raceway and pocket contacts need nothing of the other balls); with every ball active it is the full one on every
    ball (the rings' and cages' derivatives it does not compute)."""
    _, m, ls, s = hub
    args = fo.args_of(m, ls, memo=False)
    full = np.zeros_like(s.y)
    fo.rhs_args(s.t, s.y, full, args)
    act = np.array(data.draw(st.lists(st.booleans(), min_size=m.n_balls, max_size=m.n_balls)), dtype=np.int8)
    out = np.full_like(s.y, np.nan)
    fo.rhs_masked(s.t, s.y, out, args, act)
    for b in np.flatnonzero(act):
        o = ly.N_RING + ly.N_BALL * b
        assert np.array_equal(out[o:o + 9], full[o:o + 9]), b
    every = np.zeros_like(s.y)
    fo.rhs_masked(s.t, s.y, every, args, np.ones(m.n_balls, np.int8))
    balls = slice(ly.N_RING, ly.N_RING + ly.N_BALL * m.n_balls)
    assert np.array_equal(every[balls], full[balls])


@pytest.mark.parametrize("orbit", ["free", "held"])
def test_masked_rhs_reads_nothing_of_the_other_balls(orbit):
    """The refinement leaves the other balls' states unset (zeros in its work array, :func:`.multirate.latent`):
    the masked right-hand side must not read them — with the balls' azimuths held too, whose projection divides by
    each ball's orbit radius (a zero there stopped a held run with ZeroDivisionError before the projection skipped
    the other balls)."""
    import dataclasses

    c = dataclasses.replace(load_case(EXAMPLES / "hub-moment-50hz.toml"), ball_orbit=orbit)
    m, ls, y, _ = R.build(c)
    args = fo.args_of(m, ls, memo=False)
    full = np.zeros_like(y)
    fo.rhs_args(0.0, y, full, args)
    act = np.zeros(m.n_balls, np.int8)
    act[[1, 5, 20]] = 1
    ym = y.copy()
    for b in np.flatnonzero(act == 0):
        o = ly.N_RING + ly.N_BALL * b
        ym[o:o + 9] = 0.0
    out = np.zeros_like(y)
    fo.rhs_masked(0.0, ym, out, args, act)
    for b in np.flatnonzero(act):
        o = ly.N_RING + ly.N_BALL * b
        assert np.array_equal(out[o:o + 9], full[o:o + 9]), (orbit, b)


@settings(max_examples=200, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), nmax=st.integers(1, 10), spread=st.floats(0.0, 6.0))
def test_select_takes_the_largest_hot_balls(seed, nmax, spread):
    """The active balls are those whose summed scaled squared error exceeds 9 HOT, largest first, at most nmax;
    the remainder is the sum over every other state (a direct numpy statement of the rule)."""
    rng = np.random.default_rng(seed)
    nb, extra = 12, 7
    n = ly.N_RING + 9 * nb + extra
    r2 = 10.0 ** rng.uniform(-3.0, spread, size=n)
    blk = np.array([ly.N_RING + 9 * b for b in range(nb)], dtype=np.int64)
    sb = np.empty(nb)
    mask = np.zeros(nb, np.int8)
    rank = np.full(nmax, -1, np.int64)
    nact, rem = mrm.select(r2, blk, 9, nmax, sb, mask, rank)
    sums = np.array([r2[o:o + 9].sum() for o in blk])
    order = np.argsort(-sums, kind="stable")
    want = [b for b in order if sums[b] > 9.0 * mrm.HOT][:nmax]
    assert sorted(np.flatnonzero(mask)) == sorted(want) and nact == len(want)
    assert list(rank[:nact]) == want  # largest error first
    assert rem == pytest.approx(r2.sum() - sums[want].sum(), rel=1e-12, abs=1e-12 * r2.sum())
    # the groups: ranks dealt in turn (0, 2, 4 … to group 0), each group's balls in ball order, every ball once
    gmask = np.full((2, nb), 7, np.int8)
    gact = np.full((2, max(nmax, 1)), -1, np.int64)
    gn = np.full(2, -1, np.int64)
    mrm.split_groups(rank, nact, nb, gmask, gact, gn)
    for g in range(2):
        mine = sorted(want[g::2])
        assert list(gact[g, :gn[g]]) == mine and sorted(np.flatnonzero(gmask[g])) == mine, (g, want)
    assert gn.sum() == nact and not (gmask[0] & gmask[1]).any()


@settings(max_examples=50, deadline=None)
@given(c=st.lists(st.floats(-5.0, 5.0), min_size=3, max_size=3), h=st.floats(1e-7, 1e-2), th=st.floats(0.0, 1.0))
def test_latent_is_the_quadratic_through_the_step(c, h, th):
    """latent() reproduces any quadratic from its value and slope at t0 and its value at t0 + h, on the states
    outside [lo, hi) (the balls', left as they are)."""
    t0 = 0.3
    q = lambda t: c[0] + c[1] * (t - t0) + c[2] * (t - t0) ** 2  # noqa: E731
    dq = lambda t: c[1] + 2.0 * c[2] * (t - t0)  # noqa: E731
    out = np.full(4, 7.0)
    mrm.latent(t0, h, np.full(4, q(t0)), np.full(4, dq(t0)), np.full(4, q(t0 + h)), t0 + th * h, 1, 3, out)
    assert out[0] == pytest.approx(q(t0 + th * h), rel=1e-9, abs=1e-12)
    assert out[3] == out[0] and out[1] == out[2] == 7.0


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), a=st.floats(-3.2, 3.2))
def test_turned_block_is_t_j_tt(seed, a):
    """turned_block(J, cos, sin) = T J Tᵀ with T turning each of the ball's three vectors about x."""
    rng = np.random.default_rng(seed)
    jb = rng.normal(size=(9, 9))
    rot = np.array([[1.0, 0.0, 0.0], [0.0, np.cos(a), -np.sin(a)], [0.0, np.sin(a), np.cos(a)]])
    t = np.kron(np.eye(3), rot)
    out = np.zeros((9, 9))
    mrm.turned_block(jb, np.cos(a), np.sin(a), out)
    np.testing.assert_allclose(out, t @ jb @ t.T, rtol=1e-12, atol=1e-12)


def _run(m, ls, s, tol, mr, t_end, dense=False):
    st_ = R.Stepper(m, ls, s.y.copy(), t=s.t, h=s.h, tol=tol, method="ros34w", threads=1, multirate=mr, dense=dense)
    st_.advance(t_end)
    return st_


def test_refinement_at_the_zero_crossing_takes_far_fewer_steps_within_the_tolerance(hub):
    """The premise and the engine: over 0.8 ms from the moment's zero crossing the plain engine takes ≈ 700 steps
    held by a few rattling balls; with the refinement ≈ 100 (refining ≈ 6 balls a step).  The result against a run
    at tol 1e-8: the balls' angular velocities as close as the plain run's, the ring within 5e-5 of its travel over
    the load cycle (measured 1.9e-5 — the method's coupling error: the ring feels the refined balls' forces of the
    large step; the plain run 2.6e-7; issue 14's bound on the ring 1e-4) — docs/development/history.md, eighteenth pass."""
    c, m, ls, s = hub
    t_end = T0 + 0.8e-3
    fine = _run(m, ls, s, 1e-8, 0, t_end)
    plain = _run(m, ls, s, c.tolerance, 0, t_end)
    multi = _run(m, ls, s, c.tolerance, 8, t_end)
    assert multi.steps < 0.25 * plain.steps, (multi.steps, plain.steps)  # measured 93 against 694
    w = multi.workspace.work
    assert w[5] > 0.8 * multi.steps and w[4] > 3 * w[5], list(w)  # most steps refine, several balls each
    # the ring's travel over the load cycle (a 20 ms plain run, samples every 0.5 ms)
    cyc = R.Stepper(m, ls, s.y.copy(), t=s.t, h=s.h, tol=c.tolerance, method="ros34w", threads=1, multirate=0)
    ring = []
    for k in range(1, 41):
        cyc.advance(s.t + k * 0.5e-3)
        ring.append(cyc.y[:5].copy())
    span = np.ptp(np.array(ring), axis=0)
    loaded = span > 0.01 * span.max()  # dx, dy, γz (the coordinates the moment moves)
    err_multi = (np.abs(multi.y[:5] - fine.y[:5]) / span)[loaded].max()
    err_plain = (np.abs(plain.y[:5] - fine.y[:5]) / span)[loaded].max()
    assert err_multi < 5e-5, (err_multi, err_plain)
    balls = np.array([ly.N_RING + ly.N_BALL * b for b in range(m.n_balls)])[:, None] + np.arange(6, 9)
    wmag = np.linalg.norm(fine.y[balls], axis=1)
    ew_multi = (np.linalg.norm(multi.y[balls] - fine.y[balls], axis=1) / wmag).max()
    ew_plain = (np.linalg.norm(plain.y[balls] - fine.y[balls], axis=1) / wmag).max()
    assert ew_multi < 2.0 * ew_plain + 1e-6, (ew_multi, ew_plain)


def test_dense_output_of_refined_balls_follows_their_micro_steps(hub):
    """A sample inside a refined step: the refined balls are interpolated on their own micro steps
    (:func:`~bearingsim.dynamics.integrate.common.dense_state`) and are as close to a tol-1e-9 run as the same
    engine stopped exactly there; the large step's Hermite interpolant alone is several times further off on their
    velocities (a rattling ball turns within a large step).  Per vector, relative to its magnitude; measured at
    60 / 100 µs after the zero crossing: 4.28e-5 / 7.29e-5 on the nodes, 4.32e-5 / 7.32e-5 stopped there, 2.40e-4 /
    4.09e-4 on the large step."""
    from bearingsim.dynamics.integrate.common import DST_NODES, hermite_one

    c, m, ls, s = hub
    for dt in (60e-6, 100e-6):
        t_out = s.t + dt
        dense = _run(m, ls, s, c.tolerance, 8, t_out, dense=True)
        dns, dst = dense._dense
        assert dense.t > t_out and int(dst[DST_NODES]) >= 3, (dense.t, dst[DST_NODES])  # the last step was refined
        act = np.flatnonzero(dns[3] != 0.0).reshape(-1, 9)
        got = dense.state_at(t_out)
        big = np.vectorize(hermite_one)(float(dst[0]), dns[0], dns[1], dense.t, dense.y, dns[2], t_out)
        fine = _run(m, ls, s, 1e-9, 0, t_out)
        clipped = _run(m, ls, s, c.tolerance, 8, t_out)  # the steps stop at t_out (no dense output)
        for part in (slice(0, 3), slice(3, 6), slice(6, 9)):  # positions, velocities, angular velocities
            idx = act[:, part]
            ref = fine.y[idx]

            def err(y, idx=idx, ref=ref):
                return (np.linalg.norm(y[idx] - ref, axis=1) / np.linalg.norm(ref, axis=1)).max()

            assert err(got) <= 1.5 * err(clipped.y) + 1e-9, (dt, part, err(got), err(clipped.y))
        vel = act[:, 3:6]
        ev = lambda y: (np.linalg.norm(y[vel] - fine.y[vel], axis=1) / np.linalg.norm(fine.y[vel], axis=1)).max()  # noqa: E731
        assert ev(big) > 3.0 * ev(got), (dt, ev(got), ev(big))



@pytest.mark.parametrize("orbit", ["free", "held"])
@settings(max_examples=12, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), nact=st.integers(0, 8))
def test_f_in_two_parts_is_f_bit_for_bit(orbit, seed, nact):
    """f at a refined step's end in two parts (:func:`~bearingsim.dynamics.forces.rhs_split`): the raceway contacts
    of the balls not refined beside the refinement, at the large step's state, then the rest once the refined balls'
    states are in — the same numbers as :func:`~bearingsim.dynamics.forces.rhs_args` at the final state bit for bit,
    the ring record that ROS34PW2 derives its ring columns from (memo row n_balls) included.  The refined balls'
    states differ between the two calls (the first must not read them)."""
    import dataclasses

    c = dataclasses.replace(load_case(EXAMPLES / "hub-moment-50hz.toml"), ball_orbit=orbit)
    m, ls, y0, _ = R.build(c)
    rng = np.random.default_rng(seed)
    y = y0 * (1.0 + 1e-4 * rng.standard_normal(y0.size))  # every contact loaded and sliding differently
    act = np.zeros(m.n_balls, np.int8)
    act[rng.choice(m.n_balls, nact, replace=False)] = 1
    y_large = y.copy()  # the refined balls elsewhere during the first part
    for b in np.flatnonzero(act):
        o = ly.N_RING + ly.N_BALL * b
        y_large[o:o + 9] *= 1.0 + 1e-3 * rng.standard_normal(9)
    t = 1.3e-3
    a_full = fo.args_of(m, ls)
    full = np.zeros_like(y)
    fo.rhs_args(t, y, full, a_full)
    a_split = fo.args_of(m, ls)
    work = fo.split_work(a_split)
    two = np.full_like(y, np.nan)
    fo.rhs_split(t, y_large, two, a_split, act, fo.PHASE_OTHERS, work)
    fo.rhs_split(t, y, two, a_split, act, fo.PHASE_REST, work)
    assert np.array_equal(two, full), np.abs(two - full).max()
    assert np.array_equal(a_split[10], a_full[10])  # the outer-contact memo and the ring record
