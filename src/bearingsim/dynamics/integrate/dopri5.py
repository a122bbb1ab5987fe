"""DOPRI5: the explicit embedded Runge–Kutta 5(4) pair of Dormand & Prince with error control.

Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19; Hairer, Nørsett & Wanner, *Solving ODEs I*,
2nd ed., §II.5, Table 5.2: fifth order with a fourth-order error estimate, first-same-as-last (6
evaluations per accepted step), step size h ← h·min(5, max(0.2, 0.9 err^(−1/5))) (eq. II.4.13).

The bearing engine uses it when the traction is "none" or "coulomb" (``integrator = "auto"``);
with the lubricated kernel, traction creep makes the problem stiff (eigenvalue
λ ≈ (dμ/ds) Q/(u m_eff), stability limit |λh| ≲ 3.3 on the negative real axis) and the W-method
ROS34PW2 (:mod:`.ros34pw2`) takes much longer steps (docs/dynamics.md).  An unstable step shows up
as a large error estimate and is rejected, so DOPRI5 stays correct there, only slow.

Compilation: numba does not cache on disk the kernels that take the right-hand side as an argument
(``stages``, ``integrate`` here, and those of the W-methods), so a process that calls them compiles them
once; ``advance`` on the engine's own right-hand sides calls their specialisations of :mod:`.specialised`
instead, which are cached (with them compiled inside).  The step control, error norm and linear algebra
(:mod:`.common`, :mod:`.linalg`) and the right-hand sides are cached on disk too.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .base import Workspace
from .common import (
    MAX_STEPS,
    NO_VECTORS,
    NOT_FINITE,
    OK,
    STEP_TOO_SMALL,
    Status,
    accept_factor,
    clip_step,
    error_norm,
    reject_factor,
)

# Dormand–Prince 5(4) tableau (Hairer, Nørsett & Wanner, Table II.5.2)
C2, C3, C4, C5 = 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0,
                          -1.0 / 40.0)
ERR_EXPONENT = 0.2  #: 1/(q + 1) with q = 4 the order of the embedded solution
GROW = 5.0  #: largest step growth factor


@njit
def stages(fun, args, t, y, h, k1, k2, k3, k4, k5, k6, k7, ytmp, ynew):
    """The stages k2…k7 of one step from (t, y) with k1 = f(t, y) given; ynew ← the 5th-order solution."""
    n = y.shape[0]
    for i in range(n):
        ytmp[i] = y[i] + h * A21 * k1[i]
    fun(t + C2 * h, ytmp, k2, args)
    for i in range(n):
        ytmp[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i])
    fun(t + C3 * h, ytmp, k3, args)
    for i in range(n):
        ytmp[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])
    fun(t + C4 * h, ytmp, k4, args)
    for i in range(n):
        ytmp[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
    fun(t + C5 * h, ytmp, k5, args)
    for i in range(n):
        ytmp[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i])
    fun(t + h, ytmp, k6, args)
    for i in range(n):
        ynew[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i])
    fun(t + h, ynew, k7, args)


@njit
def integrate(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, vec=NO_VECTORS):
    """Integrate y' = fun(t, y) from t to t_end in place with DOPRI5 and error control.

    Parameters
    ----------
    fun : numba function fun(t, y, dy, args)
    t, t_end : float [s]; y : float[n] (overwritten with y(t_end))
    h : first trial step [s]; atol, rtol : float[n] per-component tolerances
    h_min : smallest step allowed [s]; max_steps : int
    info : float[4] ← steps accepted, steps rejected, index of the component with the
        largest error at the last step, that error
    vec : int64[n, 2] or no rows — the vector each component's relative tolerance is measured on
        (:func:`.common.error_scale`; the stepper's are :func:`bearingsim.dynamics.model.error_vectors`)

    Returns (status, t reached, proposed next step).
    """
    n = y.shape[0]
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    k5 = np.empty(n)
    k6 = np.empty(n)
    k7 = np.empty(n)
    ytmp = np.empty(n)
    ynew = np.empty(n)
    evec = np.empty(n)
    fun(t, y, k1, args)
    nacc = 0
    nrej = 0
    status = OK
    while t < t_end:
        if nacc + nrej >= max_steps:
            status = MAX_STEPS
            break
        hs, last = clip_step(t, h, t_end)
        stages(fun, args, t, y, hs, k1, k2, k3, k4, k5, k6, k7, ytmp, ynew)
        for i in range(n):
            evec[i] = hs * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
        err, finite = error_norm(evec, y, ynew, atol, rtol, info, vec)
        if err <= 1.0:
            for i in range(n):
                y[i] = ynew[i]
                k1[i] = k7[i]
            if last:
                t = t_end
            else:
                t = t + hs
            nacc += 1
            fac = accept_factor(err, ERR_EXPONENT, GROW)
            # a step shortened to land on t_end keeps the controller's proposal
            if not (last and hs < h):
                h = hs * fac
        else:
            nrej += 1
            h = hs * reject_factor(err, ERR_EXPONENT)
            if h < h_min:
                status = STEP_TOO_SMALL if finite else NOT_FINITE
                break
    info[0] = nacc
    info[1] = nrej
    return status, t, h


@njit
def fixed_steps(fun, args, t, y, h, nsteps):
    """``nsteps`` DOPRI5 steps of constant size h (no error control) — for order tests."""
    n = y.shape[0]
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    k5 = np.empty(n)
    k6 = np.empty(n)
    k7 = np.empty(n)
    ytmp = np.empty(n)
    ynew = np.empty(n)
    for _ in range(nsteps):
        fun(t, y, k1, args)
        stages(fun, args, t, y, h, k1, k2, k3, k4, k5, k6, k7, ytmp, ynew)
        for i in range(n):
            y[i] = ynew[i]
        t += h
    return t


def advance(ws: Workspace, t_end: float) -> Status:
    """Integrate the workspace to t_end [s] with DOPRI5 (the contract of :mod:`.base`; the engine's right-hand
    sides run the cached kernel of :mod:`.specialised`, the same code)."""
    kernel = ws.kernel
    if kernel is not None:
        status, t, h = kernel(ws.args, ws.t, float(t_end), ws.y, ws.h, ws.atol, ws.rtol, ws.h_min, ws.max_steps,
                              ws.info, ws.vec)
    else:
        status, t, h = integrate(ws.fun, ws.args, ws.t, float(t_end), ws.y, ws.h, ws.atol, ws.rtol, ws.h_min,
                                 ws.max_steps, ws.info, ws.vec)
    return ws.finish(status, t, h)
