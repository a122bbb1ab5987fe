"""ROS2: the second-order linearly implicit W-method of Verwer, Spee, Blom & Hundsdorfer
(SIAM J. Sci. Comput. 20 (1999) 1456, eqs. 2.3–2.4) with a block-diagonal W = I − γ h J.

    W k₁ = f(t, y),  W k₂ = f(t + h, y + h k₁) − 2 k₁,  y₁ = y + (3/2) h k₁ + (1/2) h k₂,

γ = 1 + 1/√2.  Second order for *any* W (a W-method), L-stable for the exact Jacobian.  J holds the
per-ball blocks of ∂f/∂y (:func:`.jacobian.block_jac`), refreshed every ``jac_every`` steps and after
a rejection.  Error estimate y₁ − (y + h k₁) (first-order embedded solution);
h ← h·min(5, max(0.2, 0.9 err^(−1/2))).  An alternative to ROS34PW2 (:mod:`.ros34pw2`, the default
with the lubricated traction); chosen with ``integrator = "ros2w"``.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .base import Workspace
from .common import MAX_STEPS, NO_VECTORS, NOT_FINITE, OK, STEP_TOO_SMALL, Status, clip_step, error_norm
from .jacobian import block_jac, no_record
from .linalg import apply_w

ROS2_GAMMA = 1.0 + 1.0 / np.sqrt(2.0)


@njit
def integrate(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, vec=NO_VECTORS):
    """ROS2 from t to t_end in place (module docstring).  J: the blocks of ``nbk`` states starting at
    ``blk`` (start indices).  Same other arguments and return values as :func:`.dopri5.integrate`."""
    n = y.shape[0]
    nb = blk.shape[0]
    jac = np.zeros((nb, nbk, nbk))
    winv = np.zeros((nb, nbk, nbk))
    wm = np.zeros((nbk, nbk))
    f0 = np.empty(n)
    f1 = np.empty(n)
    k1 = np.empty(n)
    k2 = np.empty(n)
    yt = np.empty(n)
    ynew = np.empty(n)
    evec = np.empty(n)
    epsb = np.empty(nb)
    g = ROS2_GAMMA
    need_jac = True
    since = 0
    h_w = -1.0
    nacc = 0
    nrej = 0
    status = OK
    while t < t_end:
        if nacc + nrej >= max_steps:
            status = MAX_STEPS
            break
        hs, last = clip_step(t, h, t_end)
        fun(t, y, f0, args)
        if need_jac or since >= jac_every:
            e1, e2, e3 = no_record()
            block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb, e1, e2, e3)
            need_jac = False
            since = 0
            h_w = -1.0
        if hs != h_w:
            for b in range(nb):
                for i in range(nbk):
                    for j in range(nbk):
                        wm[i, j] = -g * hs * jac[b, i, j]
                    wm[i, i] += 1.0
                winv[b] = np.linalg.inv(wm)
            h_w = hs
        apply_w(winv, blk, nbk, f0, k1)
        for i in range(n):
            yt[i] = y[i] + hs * k1[i]
        fun(t + hs, yt, f1, args)
        for i in range(n):
            f1[i] -= 2.0 * k1[i]
        apply_w(winv, blk, nbk, f1, k2)
        for i in range(n):
            ynew[i] = y[i] + hs * (1.5 * k1[i] + 0.5 * k2[i])
            evec[i] = 0.5 * hs * (k1[i] + k2[i])
        err, finite = error_norm(evec, y, ynew, atol, rtol, info, vec)
        if err <= 1.0:
            for i in range(n):
                y[i] = ynew[i]
            t = t_end if last else t + hs
            nacc += 1
            since += 1
            # h·min(5, max(0.2, 0.9 err^(−1/2))) with the square root
            fac = 5.0 if err == 0.0 else min(5.0, max(0.2, 0.9 / np.sqrt(err)))
            if not (last and hs < h):
                h = hs * fac
        else:
            nrej += 1
            need_jac = True
            h = hs * max(0.2, 0.9 / np.sqrt(err))
            if h < h_min:
                status = STEP_TOO_SMALL if finite else NOT_FINITE
                break
    info[0] = nacc
    info[1] = nrej
    return status, t, h


def advance(ws: Workspace, t_end: float) -> Status:
    """Integrate the workspace to t_end [s] with ROS2 (the contract of :mod:`.base`; the engine's right-hand
    sides run the cached kernel of :mod:`.specialised`, the same code)."""
    kernel = ws.kernel
    if kernel is not None:
        status, t, h = kernel(ws.args, ws.t, float(t_end), ws.y, ws.h, ws.atol, ws.rtol, ws.h_min, ws.max_steps,
                              ws.info, ws.blk, ws.nbk, ws.jac_every, ws.vec)
    else:
        status, t, h = integrate(ws.fun, ws.args, ws.t, float(t_end), ws.y, ws.h, ws.atol, ws.rtol, ws.h_min,
                                 ws.max_steps, ws.info, ws.blk, ws.nbk, ws.jac_every, ws.vec)
    return ws.finish(status, t, h)
