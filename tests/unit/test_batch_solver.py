"""Batch-solver internals added for speed (statics/_kernels.py, statics/_batch.py), issue 3 item 7.

Invariants only: the hand-written small solve equals LAPACK, the first-order ball warm start
(xb with tangents) reaches the same equilibrium as the plain warm start, and every solution the
batch returns is an equilibrium when re-checked from scratch (cold ball solves), including the
lightly loaded balls of the unloaded row of the hub unit at low speed.
"""

import numpy as np
import pytest

from bearingsim.io import load_bearing
from bearingsim.statics import _kernels as kn
from bearingsim.statics import jones_harris as jh
from bearingsim.statics._batch import run_batch


def test_solve_small_equals_lapack_and_flags_singular():
    rng = np.random.default_rng(1)
    x = np.empty(5)
    w = np.empty((5, 6))
    for _ in range(50):
        a = rng.normal(size=(5, 5)) * np.array([1e8, 1e8, 1e8, 1e4, 1e4])
        b = rng.normal(size=5)
        assert kn.solve_small(a, b, x, w)
        ref = np.linalg.solve(a, b)
        np.testing.assert_allclose(x, ref, rtol=1e-10, atol=1e-12 * np.abs(ref).max())
    a = np.ones((5, 5))
    assert not kn.solve_small(a, np.ones(5), x, w)


def _ring_residual(rows, q, loads, omega):
    """Scaled ring residual |res|/scale at q with every ball solved from a cold start."""
    nrow = rows.shape[0]
    zmax = int(rows[:, kn.P_Z].max())
    lam = np.zeros((nrow, zmax), dtype=np.int64)
    xb = np.zeros((nrow, zmax, 2))
    res = np.zeros(5)
    conv, _ = kn.ring_assemble(rows, np.array(q, dtype=float), omega, kn.CONTROL_OUTER, lam, xb,
                               np.asarray(loads, dtype=float), res, np.zeros((5, 5)),
                               np.zeros((nrow, zmax, 12)), jh.TOL_BALL, 200)
    dm = rows[0, kn.P_DM]
    res[3:] *= 2.0 / dm
    scale = max(1.0, np.abs(loads[:3]).max(), 2.0 * np.abs(loads[3:]).max() / dm)
    return np.abs(res).max() / scale, conv


@pytest.mark.parametrize("ncol", [2, 8])
def test_ball_tangent_warm_start_same_equilibrium(ncol):
    """solve_ring from the same start with xb of 2 (position) or 8 (position + dX/dA) columns."""
    b = load_bearing("skf-7011-cdga-hc")
    rows = np.ascontiguousarray(b.row_vectors())
    z = int(rows[0, kn.P_Z])
    loads = np.array([2000.0, 800.0, -300.0, 10.0, -5.0])
    omega = 9000 * np.pi / 30
    q = np.array(jh.initial_guess(b, jh.Loads(*loads)), dtype=float)
    xb = np.zeros((1, z, ncol))
    kmat = np.zeros((5, 5))
    st, _, _, bconv = kn.solve_ring(rows, loads, omega, kn.CONTROL_OUTER, q, np.zeros((1, z), dtype=np.int64), xb,
                                    kmat, np.zeros((1, z, 12)), jh.TOL_BALL, jh.TOL_RING, jh.MAXIT_BALL,
                                    jh.MAXIT_RING, float(np.abs(loads[:3]).max()))
    assert st == 0 and bconv
    r = jh.solve(b, jh.Loads(*loads), omega)
    np.testing.assert_allclose(q, r.displacement, rtol=1e-8, atol=1e-15)
    rn, conv = _ring_residual(rows, q, loads, omega)
    assert conv and rn < 1e-9


def test_hub_low_speed_batch_points_are_equilibria():
    """Hub unit (seed 001 loads tied to the moment) at 17.5 and 26 rad/s: the balls of the unloaded
    row are held only by the centrifugal force; each returned point must be an equilibrium when all
    balls are re-solved from scratch (residual ≤ 1e-9 of the load scale)."""
    hub = load_bearing("hub-seed001")
    rows = np.ascontiguousarray(hub.row_vectors())
    m = np.linspace(200, 400, 9)
    loads = np.column_stack([1890 * m / 600, 2785 + 965 * m / 600, 0 * m, 0 * m, m])
    for omega in (17.5, 26.2):
        out = run_batch(hub, loads, np.full(len(m), omega))
        assert out["converged"].all()
        for i in range(len(m)):
            rn, conv = _ring_residual(rows, out["q"][i], loads[i], omega)
            assert conv and rn < 1e-9, (omega, m[i], rn)


def test_solve_many_equals_single_solves():
    """The public batch API gives the single-point equilibria (warm starts change nothing)."""
    from bearingsim.statics.jones_harris import solve_many

    b = load_bearing("skf-7011-cdga-hc")
    rng = np.random.default_rng(7)
    loads = np.column_stack([rng.uniform(1000, 5000, 12), rng.uniform(-300, 300, 12), rng.uniform(-300, 300, 12),
                             rng.uniform(-5, 5, 12), rng.uniform(-5, 5, 12)])
    speeds = rng.uniform(0, 1200, 12)
    many = solve_many(b, loads, speeds)
    assert many.converged.all()
    for i in range(12):
        r = jh.solve(b, jh.Loads(*loads[i]), speeds[i])
        np.testing.assert_allclose(many.displacement[i], r.displacement, rtol=1e-8, atol=1e-14)
        np.testing.assert_allclose(many.stiffness[i], r.stiffness, rtol=1e-7, atol=1e-7 * abs(r.stiffness).max())


def test_batch_reports_points_that_fail_the_independent_check_as_status_5():
    """The compiled loop re-solves the balls from scratch at every converged point; a point whose balance
    then misses the tolerance is restarted once and otherwise gets status 5 (here forced with a negative
    tolerance, which no point can meet), and the equilibrium_residual kernel tells an equilibrium from a
    displaced ring."""
    from bearingsim.statics._batch import NSUMMARY, solve_batch

    b = load_bearing("skf-7011-cdga-hc")
    rows = b.row_vectors()
    loads = np.array([[1000.0, 0, 0, 0, 0], [3000.0, 200.0, 0, 0, 0]])
    omega = np.array([0.0, 1000.0])
    n = len(loads)
    outs = [np.zeros((n, 5)), np.zeros((n, 5, 5)), np.zeros(n, dtype=np.int64), np.zeros(n, dtype=np.int64),
            np.zeros(n), np.zeros((n, NSUMMARY))]
    q0 = jh.initial_guess(b, jh.Loads(*loads[0]))
    solve_batch(rows, loads, omega, kn.CONTROL_OUTER, q0, *outs, jh.TOL_BALL, jh.TOL_RING, jh.MAXIT_BALL,
                jh.MAXIT_RING, True, jh.TOL_VERIFY)
    assert list(outs[2]) == [0, 0]
    q_ok = outs[0][1].copy()
    rv, ok = kn.equilibrium_residual(rows, loads[1], 1000.0, kn.CONTROL_OUTER, q_ok, jh.TOL_BALL, jh.MAXIT_BALL)
    assert ok and rv <= jh.TOL_VERIFY * 3000.0
    q_bad = q_ok.copy()
    q_bad[0] *= 1.001
    rv_bad, _ = kn.equilibrium_residual(rows, loads[1], 1000.0, kn.CONTROL_OUTER, q_bad, jh.TOL_BALL, jh.MAXIT_BALL)
    assert rv_bad > 1e3 * jh.TOL_VERIFY * 3000.0
    solve_batch(rows, loads, omega, kn.CONTROL_OUTER, q0, *outs, jh.TOL_BALL, jh.TOL_RING, jh.MAXIT_BALL,
                jh.MAXIT_RING, True, -1.0)
    assert list(outs[2]) == [5, 5]
