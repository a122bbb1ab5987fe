"""The dynamic engine's integrator (DOPRI5) on problems with known solutions.

Order: the harmonic oscillator y'' = −ω² y (solution cos ωt) with constant steps must
show global error ∝ h⁵ (Hairer, Nørsett & Wanner, Solving ODEs I, §II.5: DOPRI5 is of
order 5).  Error control: the adaptive run's error must follow the tolerance.
"""

import math

import numpy as np
from numba import njit

from bearingsim.dynamics import integrate as ig


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
                                        10**6, info, blk, 3, 20)
            assert st == ig.OK and t == 2.0
            steps[(k, tol)] = info[0] + info[1]
            errs.append(max(abs(y[0] - exact[0]), abs(y[1] - exact[1])))
        assert errs[0] < 1e-3 and errs[1] < 1e-5, errs
    # explicit stability alone would need > 3e5 steps at k = 1e6; the step count does not grow with k
    assert steps[(1e6, 1e-6)] < 300
    assert steps[(1e6, 1e-6)] <= 1.5 * steps[(1e4, 1e-6)]


def test_ros34w_restart_from_t_y_h_is_bitwise():
    """A run restarted from (t, y, h) after an interval repeats the same steps (checkpoint/resume)."""
    blk = np.array([0], dtype=np.int64)
    atol = np.full(3, 1e-7)
    rtol = np.zeros(3)
    info = np.zeros(4)
    a = np.array([1.0, 0.0, 1.0])
    _, t1, h1 = ig.advance_ros34(stiff, (1e5,), 0.0, 0.37, a, 1e-3, atol, rtol, 1e-12, 10**6, info, blk, 3, 20)
    b = a.copy()
    _, t2, _ = ig.advance_ros34(stiff, (1e5,), t1, 1.0, a, h1, atol, rtol, 1e-12, 10**6, info, blk, 3, 20)
    _, t3, _ = ig.advance_ros34(stiff, (1e5,), t1, 1.0, b, h1, atol, rtol, 1e-12, 10**6, info, blk, 3, 20)
    assert t2 == t3 == 1.0
    assert np.array_equal(a, b)
