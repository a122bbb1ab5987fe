"""Independent recomputation of the ring balance of a quasi-static result (for the consistency tests).

Written from the model equations (bearingsim.statics._kernels module docstring; Harris & Kotzalas 2007
vol. 2 ch. 3), not from the library's ring assembly: the groove-centre offsets of every ball are computed
here from the ring displacement, every ball is re-solved from its own cold start with the per-ball kernel
``ball_solve`` (the ball model itself), the raceway control is chosen by Jones' criterion written out here,
and the forces and gyroscopic moments on the inner ring are summed here.
"""

from __future__ import annotations

import math

import numpy as np

from bearingsim.statics import _kernels as kn


def _offsets(par, q, psi):
    s = par[kn.P_SIGN]
    ric = par[kn.P_RIC]
    xg = par[kn.P_XROW] + s * (par[kn.P_XIC] + par[kn.P_AXOFF])
    cp, sp = math.cos(psi), math.sin(psi)
    t1 = np.array([s, 0.0, 0.0, s * ric * sp, -s * ric * cp])
    t2 = np.array([0.0, cp, sp, -xg * sp, xg * cp])
    w = np.array([0.0, 0.0, 0.0, s * sp, -s * cp])
    a1 = par[kn.P_DX0] + par[kn.P_AXOFF] + t1 @ q
    a2 = par[kn.P_DR0] + t2 @ q
    return a1, a2, t1, t2, w


def _ball(par, a1, a2, omega, inner):
    d, dm = par[kn.P_D], par[kn.P_DM]
    cg = par[kn.P_JB] * omega**2 * dm / d**2
    cf = 0.5 * par[kn.P_MASS] * dm * omega**2
    lam_i, lam_o = (1.0, 1.0) if inner else (0.0, 2.0)
    x = np.zeros(2)
    out = np.zeros(10)
    jac = np.zeros((5, 4))
    conv, _ = kn.ball_solve(a1, a2, par, cg, cf, lam_i, lam_o, int(inner), x, out, jac, 1e-12, 60)
    return bool(conv), x, out, lam_i


def ring_residual(rows: np.ndarray, loads: np.ndarray, omega: float, control: str, q: np.ndarray) -> tuple:
    """(max |loads + Σ ball forces| with moments divided by d_m/2 [N], every ball converged)."""
    res = np.array(loads, dtype=float)
    allconv = True
    for par in rows:
        z = int(par[kn.P_Z])
        for j in range(z):
            psi = par[kn.P_PSI0] + 2 * math.pi * j / z
            a1, a2, t1, t2, w = _offsets(par, np.asarray(q, dtype=float), psi)
            inner = control == "inner"
            conv, x, out, lam_i = _ball(par, a1, a2, omega, inner)
            if omega != 0.0 and control != "outer":
                for _ in range(3):
                    qi, qo = out[4], out[5]
                    if not qi > 0.0:
                        want = False  # open inner contact: outer raceway control
                    elif control == "inner":
                        want = True
                    else:
                        # Jones: outer control when Q_o a_o E_o cos(α_i − α_o) > Q_i a_i E_i
                        lo, li = math.hypot(x[0], x[1]), math.hypot(a1 - x[0], a2 - x[1])
                        cdiff = ((a2 - x[1]) / li) * (x[1] / lo) + ((a1 - x[0]) / li) * (x[0] / lo)
                        want = not (par[kn.P_CAO] * qo ** (4 / 3) * cdiff > par[kn.P_CAI] * qi ** (4 / 3))
                    if want == inner:
                        break
                    inner = want
                    conv, x, out, lam_i = _ball(par, a1, a2, omega, inner)
            allconv &= conv
            fx, fr, g = out[2], out[3], out[8]
            res += -(fx * t1 + fr * t2) + lam_i * g * par[kn.P_GRI] * w
    dm = rows[0, kn.P_DM]
    res[3:] *= 2.0 / dm
    return float(np.max(np.abs(res))), allconv


def load_scale(loads: np.ndarray, dm: float) -> float:
    la = np.abs(np.asarray(loads, dtype=float))
    return max(la[0], la[1], la[2], 2 * la[3] / dm, 2 * la[4] / dm, 1.0)
