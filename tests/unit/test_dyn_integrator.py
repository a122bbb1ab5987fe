"""The dynamic engine's integrators (DOPRI5, ROS2, ROS34PW2, the workspace contract) on problems with known solutions.

Order: the harmonic oscillator y'' = −ω² y (solution cos ωt) with constant steps must
show global error ∝ h⁵ (Hairer, Nørsett & Wanner, Solving ODEs I, §II.5: DOPRI5 is of
order 5).  Error control: the adaptive run's error must follow the tolerance.
"""

import math

import numpy as np
import pytest
from _blocks import arrowhead_system, ball_like_block  # tests/unit/_blocks.py
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from bearingsim.dynamics import integrate as ig
from bearingsim.dynamics.integrate import jacobian as jc
from bearingsim.dynamics.integrate.common import linear_rhs


@njit(cache=True)
def oscillator(t, y, dy, args):
    w = args[0]
    dy[0] = y[1]
    dy[1] = -w * w * y[0]


@njit(cache=True)
def forced(t, y, dy, args):
    # y' = -y + sin t, y(0) = 0: y = (sin t − cos t + e^(−t)) / 2
    dy[0] = -y[0] + math.sin(t)


def test_fifth_order_convergence():
    w = 2.0 * math.pi
    args = (w,)
    errs = []
    for n in (10, 20, 40, 80):
        y = np.array([1.0, 0.0])
        ig.fixed_steps(oscillator, args, 0.0, y, 1.0 / n, n)
        errs.append(abs(y[0] - math.cos(w)))
    orders = [math.log2(errs[i] / errs[i + 1]) for i in range(len(errs) - 1)]
    np.testing.assert_allclose(orders[-2:], 5.0, atol=0.15,
                               err_msg="Hairer, Nørsett & Wanner 1993 §II.5: DOPRI5 is of order 5")


def test_error_control_follows_tolerance():
    errs = []
    for tol in (1e-5, 1e-7, 1e-9):
        y = np.zeros(1)
        info = np.zeros(4)
        st, t, h = ig.advance(forced, (0.0,), 0.0, 10.0, y, 1e-3, np.full(1, tol), np.zeros(1), 1e-12, 10**6, info)
        assert st == ig.OK and t == 10.0
        exact = 0.5 * (math.sin(10.0) - math.cos(10.0) + math.exp(-10.0))
        errs.append(abs(y[0] - exact))
    assert errs[0] < 1e-4 and errs[1] < 1e-6 and errs[2] < 1e-8, errs
    assert errs[2] < errs[1] < errs[0]


def test_stops_exactly_and_is_deterministic():
    a = np.array([1.0, 0.0])
    b = np.array([1.0, 0.0])
    info = np.zeros(4)
    atol = np.full(2, 1e-9)
    rtol = np.zeros(2)
    _, t1, h1 = ig.advance(oscillator, (3.0,), 0.0, 0.37, a, 1e-3, atol, rtol, 1e-12, 10**6, info)
    _, t2, _ = ig.advance(oscillator, (3.0,), t1, 1.0, a, h1, atol, rtol, 1e-12, 10**6, info)
    _, t3, h3 = ig.advance(oscillator, (3.0,), 0.0, 0.37, b, 1e-3, atol, rtol, 1e-12, 10**6, info)
    _, t4, _ = ig.advance(oscillator, (3.0,), t3, 1.0, b, h3, atol, rtol, 1e-12, 10**6, info)
    assert t1 == 0.37 and t2 == 1.0
    assert np.array_equal(a, b)


@njit(cache=True)
def stiff(t, y, dy, args):
    # autonomous: y1' = −k (y1 − y3) − y2, y2' = y3, y3' = −y2 with y(0) = (1, 0, 1):
    # y1 = y3 = cos t, y2 = sin t for any k (stiff for k h ≫ 1; one implicit block of all three states)
    dy[0] = -args[0] * (y[0] - y[2]) - y[1]
    dy[1] = y[2]
    dy[2] = -y[1]


def test_ros2w_is_stable_and_accurate_on_a_stiff_problem():
    """ROS2 W-method (Verwer et al. 1999): steps far beyond the explicit stability limit, error ∝ tolerance."""
    k = 1e6
    blk = np.array([0], dtype=np.int64)
    errs = []
    for tol in (1e-4, 1e-6):
        y = np.array([1.0, 0.0, 1.0])
        info = np.zeros(4)
        st, t, h = ig.advance_ros2(stiff, (k,), 0.0, 2.0, y, 1e-3, np.full(3, tol), np.zeros(3), 1e-12, 10**6,
                                   info, blk, 3, 20)
        assert st == ig.OK and t == 2.0
        assert info[0] < 20000, "explicit stability alone would need > 3e5 steps"
        errs.append(max(abs(y[0] - math.cos(2.0)), abs(y[1] - math.sin(2.0))))
    assert errs[0] < 1e-3 and errs[1] < 1e-5, errs


def test_ros34w_third_order_convergence_for_exact_and_zero_jacobian():
    """ROS34PW2 (Rang & Angermann 2005) is of order 3 as a W-method: the harmonic oscillator
    with constant steps gives global error ∝ h³ both with the exact Jacobian (one 2×2 block)
    and with J = 0 (the method then reduces to an explicit Runge–Kutta method of order 3)."""
    w = 2.0 * math.pi
    blk = np.array([0], dtype=np.int64)
    for nbk in (2, 0):
        errs = []
        for n in (20, 40, 80, 160):
            y = np.array([1.0, 0.0])
            ig.fixed_steps_ros34(oscillator, (w,), 0.0, y, 1.0 / n, n, blk, nbk)
            errs.append(abs(y[0] - math.cos(w)))
        orders = [math.log2(errs[i] / errs[i + 1]) for i in range(len(errs) - 1)]
        np.testing.assert_allclose(orders[-2:], 3.0, atol=0.1,
                                   err_msg=f"Rang & Angermann 2005: ROS34PW2 is a W-method of order 3 (nbk={nbk})")


def test_ros34w_is_stable_and_accurate_on_a_stiff_problem():
    """ROS34PW2: steps far beyond the explicit stability limit, independent of the stiffness, error ∝ tolerance."""
    blk = np.array([0], dtype=np.int64)
    exact = (math.cos(2.0), math.sin(2.0))
    steps = {}
    for k in (1e4, 1e6):
        errs = []
        for tol in (1e-4, 1e-6):
            y = np.array([1.0, 0.0, 1.0])
            info = np.zeros(4)
            st, t, h = ig.advance_ros34(stiff, (k,), 0.0, 2.0, y, 1e-3, np.full(3, tol), np.zeros(3), 1e-12,
                                        10**6, info, blk, 3, 20, ig.ros34_workspace(1, 3, False))
            assert st == ig.OK and t == 2.0
            steps[(k, tol)] = info[0] + info[1]
            errs.append(max(abs(y[0] - exact[0]), abs(y[1] - exact[1])))
        assert errs[0] < 1e-3 and errs[1] < 1e-5, errs
    # explicit stability alone would need > 3e5 steps at k = 1e6; the step count does not grow with k
    assert steps[(1e6, 1e-6)] < 300
    assert steps[(1e6, 1e-6)] <= 1.5 * steps[(1e4, 1e-6)]


def test_ros34w_restart_from_t_y_h_is_bitwise():
    """A run restarted from (t, y, h) and the integrator's Jacobian after an interval repeats the same steps
    (checkpoint/resume)."""
    blk = np.array([0], dtype=np.int64)
    atol = np.full(3, 1e-7)
    rtol = np.zeros(3)
    info = np.zeros(4)
    a = np.array([1.0, 0.0, 1.0])
    ws = ig.ros34_workspace(1, 3, False)
    _, t1, h1 = ig.advance_ros34(stiff, (1e5,), 0.0, 0.37, a, 1e-3, atol, rtol, 1e-12, 10**6, info, blk, 3, 20, ws)
    b = a.copy()
    ws_b = tuple(x.copy() for x in ws)  # what a checkpoint holds: t, y, h and the integrator's Jacobian
    _, t2, _ = ig.advance_ros34(stiff, (1e5,), t1, 1.0, a, h1, atol, rtol, 1e-12, 10**6, info, blk, 3, 20, ws)
    _, t3, _ = ig.advance_ros34(stiff, (1e5,), t1, 1.0, b, h1, atol, rtol, 1e-12, 10**6, info, blk, 3, 20, ws_b)
    assert t2 == t3 == 1.0
    assert np.array_equal(a, b)


def test_ros34w_step_statistics_leave_the_steps_unchanged_and_count_every_attempt():
    """The profiling array of ROS34PW2 (benchmarks/bench_dynamics.py --steps) changes no step: the same state and
    step counts with and without it; it counts every attempted step (accepted or rejected) once under its largest
    component."""
    blk = np.array([0], dtype=np.int64)
    atol = np.full(3, 1e-7)
    rtol = np.zeros(3)
    runs = []
    for stats in (np.zeros(0), np.zeros(6)):
        y = np.array([1.0, 0.0, 1.0])
        info = np.zeros(4)
        ws = ig.ros34_workspace(1, 3, False)
        ig.advance_ros34(stiff, (1e4,), 0.0, 1.0, y, 0.5, atol, rtol, 1e-12, 10**6, info, blk, 3, 20, ws,
                         np.zeros(0), np.zeros((0, 2)), stats)
        runs.append((y, info.copy(), stats))
    (y0, i0, _), (y1, i1, st) = runs
    assert np.array_equal(y0, y1) and np.array_equal(i0, i1)
    assert i1[1] > 0  # the first step (0.5) is rejected: rejections are counted too
    assert st[3:].sum() == i1[0] + i1[1]
    assert st[:3].sum() > 0 and np.all(st[:3] >= 0)


def test_ros34w_counts_its_right_hand_sides_factorisations_and_refreshes_exactly():
    """info[4:7] (benchmarks/bench_dynamics.py --kernel, the cost model): a right-hand side per accepted step (f at
    its start), three per attempt (stages 2–4), nbk per Jacobian refresh of the blocks; a W factorisation per new
    step size, at least one per refresh.  Counted independently here by wrapping the right-hand side with a counter
    (a numba function with an array in its arguments)."""
    @njit
    def counted(t, y, dy, args):
        args[1][0] += 1.0
        stiff(t, y, dy, (args[0],))

    blk = np.array([0], dtype=np.int64)
    for jac_every in (1, 5, 20):
        y = np.array([1.0, 0.0, 1.0])
        info = np.zeros(ig.INFO_SIZE)
        calls = np.zeros(1)
        st, t, _ = ig.advance_ros34(counted, (1e4, calls), 0.0, 1.0, y, 0.5, np.full(3, 1e-7), np.zeros(3), 1e-12,
                                    10**6, info, blk, 3, jac_every, ig.ros34_workspace(1, 3, False))
        acc, rej, nfun, nfac, njac = info[0], info[1], info[4], info[5], info[6]
        assert st == ig.OK and t == 1.0 and rej > 0
        assert nfun == calls[0] == acc + 3 * (acc + rej) + 3 * njac, (info, calls)
        assert njac >= acc / jac_every and njac <= acc + rej
        assert njac <= nfac <= acc + rej


@pytest.mark.parametrize("kinematic", [False, True])
def test_arrowhead_w_solve_equals_the_dense_one(kinematic):
    """The ring–ball coupled W of ROS34PW2 (ring block, ball blocks, coupling; Schur complement of the
    ring) solves like the assembled dense matrix (with the coupling's structure: J_br's position
    rows and J_rb's ring-position rows zero, as ring_jac and ring_rows make them), with general ball blocks and
    with the engine's (kinematic rows ṙ = v exact: the blocks inverted through their velocity part)."""
    rng = np.random.default_rng(3)
    nb, nbk, extra = 3, 9, 5
    n = ig.NR + nb * nbk + extra
    jac = rng.normal(size=(nb, nbk, nbk)) * 50
    if kinematic:
        jac = np.array([ball_like_block(rng, 50.0) for _ in range(nb)])
        assert all(ig._kinematic_rows(jb) for jb in jac)
    blk, jrr, jbr, jrb, dense = arrowhead_system(rng, jac, extra)
    hs, g = 1e-3, ig.R34_G
    winv = np.zeros((nb, nbk, nbk))
    q = np.zeros((nb, nbk, ig.NR))
    sinv = np.zeros((ig.NR, ig.NR))
    ig._coupled_w(jac, jrr, jbr, jrb, hs, g, winv, np.zeros((nbk, nbk)), q, sinv, np.zeros((ig.NR, ig.NR)),
                  np.zeros((nb, ig.NR, ig.NR)))
    v = rng.normal(size=n)
    out = np.zeros(n)
    ig._coupled_apply_w(winv, q, sinv, jrb, hs, g, blk, nbk, v, out, np.zeros((nb, nbk)), np.zeros(ig.NR))
    np.testing.assert_allclose(out, np.linalg.solve(np.eye(n) - g * hs * dense, v), rtol=1e-10, atol=1e-12)


@settings(max_examples=60, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), log_scale=st.floats(0.0, 8.0), log_c=st.floats(-9.0, -3.0),
       kinematic=st.booleans())
def test_block_w_inverse_equals_the_dense_inverse(seed, log_scale, log_c, kinematic):
    """(I + c J_b)⁻¹ through the block's velocity part (block elimination of the kinematic rows ṙ = v; Golub &
    Van Loan 2013 §3.2.11) equals the dense inverse, over J scales 1…1e8 and c = −γh from −1e-9 to −1e-3; a block
    without those rows takes the general Gauss–Jordan path and must agree as well."""
    rng = np.random.default_rng(seed)
    jb = ball_like_block(rng, 10.0**log_scale)
    if not kinematic:
        jb[1, 4] = 1.0 + 1e-9  # no longer exactly the kinematic rows: the general path
    c = -(10.0**log_c)
    w = np.eye(9) + c * jb
    assert ig._kinematic_rows(jb) == kinematic
    out = np.zeros((9, 9))
    ig.block_w_inverse(jb, c, np.zeros((9, 9)), out)
    resid = np.abs(w @ out - np.eye(9)).max()
    assert resid <= 1e-13 * np.linalg.cond(w), (
        f"block_w_inverse: |W W⁻¹ − I| = {resid:.2e} (cond {np.linalg.cond(w):.1e}, kinematic rows {kinematic})")


def _ros34_step_with_j_products(a_mat, jac, y, h):
    """One ROS34PW2 step of y' = A y with the Jacobian approximation ``jac`` in Hairer's form with the products
    J s_i written out (Hairer & Wanner, Solving ODEs II, §IV.7; Rang & Angermann 2005, Table 3): the
    reference for the engine's J-free stages."""
    g = ig.R34_G
    a = [[], [ig.R34_A21], [ig.R34_A31, ig.R34_A32], [ig.R34_A41, ig.R34_A42, ig.R34_A43]]
    cc = [[], [ig.R34_C21], [ig.R34_C31, ig.R34_C32], [ig.R34_C41, ig.R34_C42, ig.R34_C43]]
    w = np.eye(len(y)) - g * h * jac
    ks = []
    for i in range(4):
        yi = y + sum(a[i][j] * ks[j] for j in range(i))
        si = sum(cc[i][j] * ks[j] for j in range(i)) if i else np.zeros_like(y)
        ks.append(np.linalg.solve(w, h * (a_mat @ yi) + h * (jac @ si)))
    return y + sum(m * k for m, k in zip(ig.R34_M, ks))


_linear = linear_rhs  # y′ = A y


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), log_h=st.floats(-6.0, -2.0))
def test_ros34w_stages_without_j_products_equal_the_written_out_method(seed, log_h):
    """The engine solves each stage as k_i = W⁻¹(h f(Y_i) + s_i/γ) − s_i/γ, using hJ = (I − W)/γ: one step on a
    linear ball-like system (stiff: |hλ| up to ≈ 10⁴) equals the method with the products J s_i written out (a
    dense reference with the same finite-difference Jacobian), to rounding."""
    rng = np.random.default_rng(seed)
    a_mat = ball_like_block(rng, 1.0)
    a_mat[3:, :] = -np.abs(rng.normal(size=(6, 9))) * 1e3 + rng.normal(size=(6, 9)) * 1e2
    a_mat[3:, 3:] -= np.eye(6) * 1e6  # stiff velocity rows (the balls' creep damping)
    y0 = rng.normal(size=9)
    h = 10.0**log_h
    blk = np.array([0], dtype=np.int64)
    jac = np.zeros((1, 9, 9))
    f0 = np.zeros(9)
    _linear(0.0, y0, f0, (a_mat,))
    ig._block_jac(_linear, (a_mat,), 0.0, y0, f0, np.full(9, 1e-12), blk, 9, jac, np.zeros(9), np.zeros(9),
                  np.zeros(1), *jc.no_record())  # the Jacobian fixed_steps_ros34 forms (same inputs, same numbers)
    assert ig._kinematic_rows(jac[0])
    ref = _ros34_step_with_j_products(a_mat, jac[0], y0, h)
    y = y0.copy()
    ig.fixed_steps_ros34(_linear, (a_mat,), 0.0, y, h, 1, blk, 9)
    np.testing.assert_allclose(y, ref, rtol=1e-9, atol=1e-12 * np.abs(ref).max(),
                               err_msg="Rang & Angermann 2005 (Hairer form): the J-free stages differ from the "
                                       "written-out method")


def test_ring_rows_by_reciprocity_match_the_finite_differences():
    """Without traction and damping the contact forces derive from a potential, so M_r ∂a_r/∂x_b =
    (m_b ∂a_b/∂q_r)ᵀ exactly (Maxwell–Betti reciprocity): the ring rows that ROS34PW2 builds from the
    ball columns (integrate._ring_rows) equal the ring's finite-difference response to each ball's
    position."""
    from bearingsim.dynamics import forces as fo
    from bearingsim.dynamics import layout as ly
    from bearingsim.dynamics import model as md
    from bearingsim.io import load_bearing
    from bearingsim.statics import _kernels as kn
    from bearingsim.statics import jones_harris as jh

    b = load_bearing("hub-seed001")
    m = md.build_model(b, traction="none", damping_alpha=0.0, ring_mass=3.0, ring_inertia=(0.01, 0.015))
    res = jh.solve(b, jh.Loads(fa=1000.0, fr_y=2000.0, m_z=200.0), 0.0)
    y = md.initial_state(m, res)
    loads = fo.constant_loads(fa=1000.0, fr_y=2000.0, m_z=200.0)
    args = fo.args_of(m, loads)
    f0 = np.zeros_like(y)
    fo.rhs_args(0.0, y, f0, args)
    blk = np.array([m.ball_slice(k).start for k in range(m.n_balls)], dtype=np.int64)
    jrr = np.zeros((ig.NR, ig.NR))
    jbr = np.zeros((m.n_balls, ly.N_BALL, ig.NR))
    atol = np.full(y.shape, 1e-9)
    ig._ring_jac(fo.rhs_args, args, 0.0, y, f0, atol, blk, ly.N_BALL, jrr, jbr, np.empty_like(y), np.empty_like(y))
    rmass = np.array([m.gp[ly.G_MR]] * 3 + [m.gp[ly.G_ITR]] * 2)
    bmass = np.array([[m.rows[r, kn.P_MASS], m.rows[r, kn.P_JB]] for r in m.ball_row])
    jrb = np.zeros((m.n_balls, ig.NR, ly.N_BALL))
    ig._ring_rows(jbr, rmass, bmass, jrb)
    worst = scale = 0.0
    for k in (0, 5, 16, 24):  # balls of both rows, in and out of the load zone
        o = blk[k]
        for j in range(3):
            e = 1e-9  # central differences: error ∝ (e/δ)², δ ≈ 10 µm
            fp, fm = np.zeros_like(y), np.zeros_like(y)
            yt = y.copy()
            yt[o + j] += e
            fo.rhs_args(0.0, yt, fp, args)
            yt[o + j] -= 2 * e
            fo.rhs_args(0.0, yt, fm, args)
            fd = (fp[5:10] - fm[5:10]) / (2 * e)
            worst = max(worst, np.abs(fd - jrb[k, 5:10, j]).max() * rmass.max())
            scale = max(scale, np.abs(fd).max() * rmass.max())
    assert scale > 0
    # measured 6.3e-5 of the largest entry: the one-sided differences inside _ring_jac and the small-angle
    # kinematics of the ring's tilts; a wrong mass ratio or a transposed block would be off by O(1)
    assert worst < 1e-4 * scale, (worst, scale)


def test_coupled_ring_jacobian_lifts_the_low_speed_step_limit():
    """At 10 km/h the inner ring sliding against all its balls under film-elastic creep is a stiff mode
    that a per-ball Jacobian misses (steps of ≈ 0.35 µs, many rejected); with the ring block and the
    ring–ball coupling in W the steps are many times longer and the trajectory is the same to the
    tolerance.  (Without the multirate refinement, in the warm-up too: it takes the stiff balls' error off the step
    either way and would measure itself here — with it, and the two-group refinement's warm-up state, the per-ball
    Jacobian's run took 18 steps against 5; without it 19 against 3.)"""
    import dataclasses
    from pathlib import Path

    from bearingsim.dynamics.case import load_case
    from bearingsim.dynamics.run import Stepper, build
    from bearingsim.units import parse_quantity

    root = Path(__file__).resolve().parents[2]
    c = load_case(root / "examples" / "hub-moment-50hz.toml")
    from bearingsim.dynamics.loads import SpeedHistory

    c = dataclasses.replace(c, speed=SpeedHistory(parse_quantity("83.55 rpm", "speed", "speed")))  # 10 km/h
    m, ls, y, _ = build(c)
    warm = Stepper(m, ls, y.copy(), tol=1e-6, method="ros34w", multirate=0)
    warm.advance(2e-4)
    runs = {}
    for coupled in (True, False):
        st = Stepper(m, ls, warm.y.copy(), t=warm.t, h=warm.h, tol=1e-6, method="ros34w", ring_coupling=coupled,
                     multirate=0)
        st.advance(warm.t + 5e-5)
        runs[coupled] = st
    assert runs[False].steps > 5 * runs[True].steps, (runs[False].steps, runs[True].steps)
    span = np.abs(warm.y[0:5]).max()
    np.testing.assert_allclose(runs[True].y[0:5], runs[False].y[0:5], atol=1e-4 * span, rtol=0,
                               err_msg="same trajectory to the tolerance")


def test_every_method_advances_a_workspace_like_its_kernel():
    """The contract of integrate.base: METHODS[name].advance(ws, t_end) returns a Status, lands on t_end,
    books the steps and proposes the next step exactly as the kernel called with the same arguments —
    over two output intervals, so that ROS34PW2's Jacobian carried in the workspace counts too."""
    blk = np.array([0], dtype=np.int64)
    atol = np.full(3, 1e-7)
    rtol = np.zeros(3)
    for name, extra in (("dopri5", ()), ("ros2w", (blk, 3, 20)),
                        ("ros34w", (blk, 3, 20, ig.ros34_workspace(1, 3, False)))):
        ws = ig.Workspace(fun=stiff, args=(1e3,), y=np.array([1.0, 0.0, 1.0]), atol=atol, rtol=rtol, h=1e-3,
                          h_min=1e-12, max_steps=10**6, blk=blk, nbk=3, jac_every=20)
        y = ws.y.copy()
        t, h, steps = 0.0, 1e-3, 0
        kernel = ig.METHODS[name].integrate
        for t_end in (0.37, 1.0):
            assert ig.METHODS[name].advance(ws, t_end) is ig.Status.OK
            info = np.zeros(4)
            st, t, h = kernel(stiff, (1e3,), t, t_end, y, h, atol, rtol, 1e-12, 10**6, info, *extra)
            steps += int(info[0])
            assert st == ig.OK and ws.t == t == t_end and ws.h == h and ws.steps == steps
            assert np.array_equal(ws.y, y), name


def test_a_failing_workspace_reports_the_status_and_keeps_its_step():
    """Status.MAX_STEPS from the step limit; t is the time reached, h the step proposed before the call."""
    ws = ig.Workspace(fun=oscillator, args=(3.0,), y=np.array([1.0, 0.0]), atol=np.full(2, 1e-12),
                      rtol=np.zeros(2), h=1e-3, max_steps=5)
    st = ig.METHODS["dopri5"].advance(ws, 1.0)
    assert st is ig.Status.MAX_STEPS and ig.STATUS_TEXT[st] == "step limit reached"
    assert 0.0 < ws.t < 1.0 and ws.h == 1e-3 and ws.steps + ws.rejected == 5


# ---- dense output of ROS34PW2 (issue 14) --------------------------------------------------------------------
def test_hermite_interpolant_is_exact_for_cubics_and_lands_on_the_step_end():
    """The cubic Hermite interpolant (Hairer, Nørsett & Wanner, Solving ODEs I, §II.6 eq. 6.7) reproduces any
    cubic from its values and slopes at both ends, and θ = 1 gives y1 itself (``hermite_one``, the interpolant of
    the dense output, on every component)."""
    from bearingsim.dynamics.integrate.common import hermite_one

    hermite = np.vectorize(hermite_one)

    rng = np.random.default_rng(7)
    for _ in range(20):
        c = rng.normal(size=(4, 3))
        t0, t1 = sorted(rng.uniform(-2.0, 2.0, size=2))
        p = lambda t: c[0] + c[1] * t + c[2] * t**2 + c[3] * t**3  # noqa: E731
        dp = lambda t: c[1] + 2 * c[2] * t + 3 * c[3] * t**2  # noqa: E731
        for th in (0.0, 0.1, 0.5, 0.77, 0.999):
            t = t0 + th * (t1 - t0)
            np.testing.assert_allclose(hermite(t0, p(t0), dp(t0), t1, p(t1), dp(t1), t), p(t), rtol=1e-12,
                                       atol=1e-12, err_msg="HNW I eq. II.6.7: exact for cubics")
        y1 = p(t1)
        assert np.array_equal(hermite(t0, p(t0), dp(t0), t1, y1, dp(t1), t1), y1)
    # a non-cubic: the error is θ²(1 − θ)² h⁴ y⁽⁴⁾(ξ)/4! (the remainder of Hermite interpolation), here e^t on
    # [0, h] at θ = 1/3: it falls as h⁴ and lies between the remainder's values for ξ at the step's two ends
    for h in (0.4, 0.2, 0.1):
        th = 1.0 / 3.0
        err = math.exp(th * h) - hermite(0.0, np.array([1.0]), np.array([1.0]), h, np.array([math.exp(h)]),
                                         np.array([math.exp(h)]), th * h)[0]
        bound = th**2 * (1 - th) ** 2 * h**4 / 24
        assert bound <= err <= bound * math.exp(h), (h, err, bound)


def _ros34_dense(outputs, k=1e4, tol=1e-7):
    """The stiff problem above with ROS34PW2's dense output, sampled at ``outputs`` (a call per output): (samples,
    accepted steps, the largest error of the state at the ends of the steps the calls stopped at)."""
    from bearingsim.dynamics.integrate.common import dense_arrays, dense_state

    blk = np.array([0], dtype=np.int64)
    y = np.array([1.0, 0.0, 1.0])
    info = np.zeros(4)
    ws = ig.ros34_workspace(1, 3, False)
    dns, dst = dense_arrays(3)
    t, h, steps, out, end_err = 0.0, 1e-3, 0, [], 0.0
    for to in outputs:
        if to > t:
            st, t, h = ig.advance_ros34(stiff, (k,), t, to, y, h, np.full(3, tol), np.zeros(3), 1e-12, 10**6, info,
                                        blk, 3, 20, ws, dns=dns, dst=dst)
            assert st == ig.OK and t >= to
            steps += int(info[0])
            end_err = max(end_err, np.max(np.abs(y - [math.cos(t), math.sin(t), math.cos(t)])))
        out.append(dense_state(dns, dst, t, y, to))
    return np.array(out), steps, end_err


def test_ros34w_dense_output_steps_do_not_depend_on_the_output_times():
    """With dense output the steps run past the output times: samples every 0.05 and every 0.2 (and a single
    call to the end) come from the very same steps, bit for bit at the common times."""
    fine = np.linspace(0.0, 2.0, 41)[1:]
    a, na, _ = _ros34_dense(fine)
    b, nb, _ = _ros34_dense(fine[3::4])
    c, nc, _ = _ros34_dense([2.0])
    assert na == nb == nc
    assert np.array_equal(a[3::4], b) and np.array_equal(a[-1], c[-1])


def test_ros34w_dense_output_is_as_accurate_as_the_steps():
    """The interpolated samples between the steps are as close to the exact solution (y1 = y3 = cos t,
    y2 = sin t) as the steps' own ends are at that tolerance: the interpolant's O(h⁴) error is below the
    method's local error."""
    ts = np.linspace(0.0, 2.0, 201)[1:]
    for tol in (1e-5, 1e-7):
        y, _, end_err = _ros34_dense(ts, tol=tol)
        err = np.max(np.abs(y - np.stack([np.cos(ts), np.sin(ts), np.cos(ts)], axis=1)))
        assert err <= 1.1 * end_err, (tol, err, end_err)


def test_ros34w_keeps_the_step_and_w_on_a_small_growth():
    """RADAU5's rule (Hairer & Wanner, Solving ODEs II, §IV.8: quot1 = 1, quot2 = 1.2): a proposed growth of the step
    by a factor in [1, 1.2] keeps the step, so W is not formed again.  Without it every attempted step of the hub run
    forms W (its step size changes at every step: 31,978 factorisations for 31,978 attempts over 0.1 s); with it a
    third fewer.  The counts are the integrator's own (Workspace.work)."""
    from pathlib import Path

    from bearingsim.dynamics.case import load_case
    from bearingsim.dynamics.integrate import ros34pw2 as rp
    from bearingsim.dynamics.run import Stepper, build

    assert rp.R34_HOLD == 1.2
    root = Path(__file__).resolve().parents[2]
    c = load_case(root / "examples" / "hub-moment-50hz.toml")
    m, ls, y, _ = build(c)
    st = Stepper(m, ls, y.copy(), tol=c.tolerance, method="ros34w", threads=1, multirate=0)  # (the rule alone)
    st.advance(4e-3)
    attempts = st.steps + st.rejected
    nfac = int(st.workspace.work[1])
    assert attempts > 500
    assert nfac < 0.9 * attempts, (nfac, attempts)  # measured 739 / 892 (0.83; 0.39–0.90 per 2 ms window to 20 ms)
