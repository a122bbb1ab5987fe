"""Time integrator: explicit embedded Runge–Kutta 5(4) of Dormand & Prince with error control.

Choice (details in docs/dynamics.md).  The right-hand side is a numba kernel whose
cost is dominated by the contacts, so the integrator should need few evaluations per
unit of simulated time at the accuracy the contacts need.  The Hertz contact period of
an 11 mm ball (≈ 50 µs) is resolved by a few dozen steps of any explicit method; the
stiffer time scale is traction creep, whose eigenvalue λ ≈ (dμ/ds) Q / (u m_eff) sets a
stability limit |λ h| ≲ 3.3 for DOPRI5 on the negative real axis.  At the speeds and
loads of the issue's cases that limit (≈ 0.5–5 µs) is of the same order as the
accuracy-limited step, so an implicit method (which needs a Jacobian of all the
contacts and a linear solve per step) would not pay back its cost; the embedded error
estimate keeps the step stable automatically (an unstable step shows up as a large
error estimate and is rejected).  DOPRI5 (Dormand & Prince, J. Comput. Appl. Math. 6
(1980) 19; Hairer, Nørsett & Wanner, Solving ODEs I, 2nd ed., §II.5, Table 5.2) is
5th-order with a 4th-order error estimate, first-same-as-last (6 evaluations per
accepted step), with the standard step-size controller h ← h·min(5, max(0.2,
0.9·err^(−1/5))) (Hairer et al. eq. II.4.13).

Not cached by numba (``cache=True`` is unreliable for functions that take another
jitted function as an argument): each process compiles the integrator once (~3 s);
the right-hand sides themselves are cached.

Also here: the linearly implicit W-methods :func:`advance_ros2` (ROS2, second order) and
:func:`advance_ros34` (ROS34PW2, third order; the default for the lubricated kernel), both with
a block-diagonal per-ball Jacobian, ROS34PW2 also with the inner ring's block and the ring–ball
coupling (an arrowhead W solved through the ring's Schur complement) — see docs/dynamics.md for
why and for the measurements.

Determinism: no randomness, fixed arithmetic order, and every call of :func:`advance`
stops exactly at the requested time and returns the proposed next step, so a run
restarted from a checkpoint (t, y, h) repeats the same steps bit for bit.
"""

from __future__ import annotations

import numpy as np
from numba import njit

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

OK = 0
STEP_TOO_SMALL = 1
NOT_FINITE = 2
MAX_STEPS = 3
STATUS_TEXT = {OK: "ok", STEP_TOO_SMALL: "step size fell below the minimum (diverging or too stiff)",
               NOT_FINITE: "the state became non-finite", MAX_STEPS: "step limit reached"}


@njit
def _stages(fun, args, t, y, h, k1, k2, k3, k4, k5, k6, k7, ytmp, ynew):
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
def _error_norm(e, y, ynew, atol, rtol, info):
    """Scaled RMS norm of the local error estimate e (Hairer, Nørsett & Wanner, *Solving ODEs I*,
    1993, eq. II.4.11): √(Σ (e_i / (atol_i + rtol_i max(|y_i|, |ynew_i|)))² / n).

    info[2], info[3] ← index and scaled error of the worst component.  Returns (err, finite);
    a non-finite component gives err = 1e10 and finite = False.
    """
    n = y.shape[0]
    err = 0.0
    imax = 0
    emax = -1.0
    finite = True
    for i in range(n):
        r = e[i] / (atol[i] + rtol[i] * max(abs(y[i]), abs(ynew[i])))
        r2 = r * r
        if not np.isfinite(r2):
            finite = False
            imax = i
            break
        if r2 > emax:
            emax = r2
            imax = i
        err += r2
    info[2] = imax
    info[3] = np.sqrt(emax) if finite else np.inf
    return (np.sqrt(err / n) if finite else 1e10), finite


@njit
def _clip_step(t, h, t_end):
    """(step [s], last) with the step shortened to land exactly on t_end [s]; last is True when it does."""
    if t + h >= t_end:
        return t_end - t, True
    return h, False


@njit
def advance(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info):
    """Integrate y' = fun(t, y) from t to t_end in place with DOPRI5 and error control.

    Parameters
    ----------
    fun : numba function fun(t, y, dy, args)
    t, t_end : float [s]; y : float[n] (overwritten with y(t_end))
    h : first trial step [s]; atol, rtol : float[n] per-component tolerances
    h_min : smallest step allowed [s]; max_steps : int
    info : float[4] ← steps accepted, steps rejected, index of the component with the
        largest error at the last step, that error

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
        hs, last = _clip_step(t, h, t_end)
        _stages(fun, args, t, y, hs, k1, k2, k3, k4, k5, k6, k7, ytmp, ynew)
        for i in range(n):
            evec[i] = hs * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
        err, finite = _error_norm(evec, y, ynew, atol, rtol, info)
        if err <= 1.0:
            for i in range(n):
                y[i] = ynew[i]
                k1[i] = k7[i]
            if last:
                t = t_end
            else:
                t = t + hs
            nacc += 1
            fac = 5.0 if err == 0.0 else min(5.0, max(0.2, 0.9 * err ** -0.2))
            # a step shortened to land on t_end keeps the controller's proposal
            if not (last and hs < h):
                h = hs * fac
        else:
            nrej += 1
            h = hs * max(0.2, 0.9 * err ** -0.2)
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
        _stages(fun, args, t, y, h, k1, k2, k3, k4, k5, k6, k7, ytmp, ynew)
        for i in range(n):
            y[i] = ynew[i]
        t += h
    return t


ROS2_GAMMA = 1.0 + 1.0 / np.sqrt(2.0)


@njit
def _apply_w(winv, blk, nbk, v, out):
    """out = W⁻¹ v with W block diagonal: W_b on the blocks, identity elsewhere."""
    for i in range(v.shape[0]):
        out[i] = v[i]
    for b in range(blk.shape[0]):
        o = blk[b]
        for i in range(nbk):
            s = 0.0
            for j in range(nbk):
                s += winv[b, i, j] * v[o + j]
            out[o + i] = s


@njit
def advance_ros2(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every):
    """Linearly implicit W-method ROS2 (Verwer, Spee, Blom & Hundsdorfer, SIAM J. Sci. Comput. 20
    (1999) 1456, eqs. 2.3–2.4) with a block-diagonal W = I − γ h J.

        W k₁ = f(t, y),  W k₂ = f(t + h, y + h k₁) − 2 k₁,  y₁ = y + (3/2) h k₁ + (1/2) h k₂,

    γ = 1 + 1/√2.  Second order for *any* W (a W-method), L-stable for the exact
    Jacobian.  J holds only the blocks of ∂f/∂y of each body listed in ``blk`` (start
    indices, ``nbk`` states each), found by finite differences (perturbing one component
    of every block at once: the blocks do not depend on each other's states directly) and
    refreshed every ``jac_every`` steps or after a rejection.  The error estimate is
    y₁ − (y + h k₁) (first-order embedded solution); h ← h·min(5, max(0.2, 0.9 err^(−1/2))).
    Same arguments and return values as :func:`advance`.
    """
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
        hs, last = _clip_step(t, h, t_end)
        fun(t, y, f0, args)
        if need_jac or since >= jac_every:
            _block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb)
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
        _apply_w(winv, blk, nbk, f0, k1)
        for i in range(n):
            yt[i] = y[i] + hs * k1[i]
        fun(t + hs, yt, f1, args)
        for i in range(n):
            f1[i] -= 2.0 * k1[i]
        _apply_w(winv, blk, nbk, f1, k2)
        for i in range(n):
            ynew[i] = y[i] + hs * (1.5 * k1[i] + 0.5 * k2[i])
            evec[i] = 0.5 * hs * (k1[i] + k2[i])
        err, finite = _error_norm(evec, y, ynew, atol, rtol, info)
        if err <= 1.0:
            for i in range(n):
                y[i] = ynew[i]
            t = t_end if last else t + hs
            nacc += 1
            since += 1
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


# ROS34PW2 (Rang & Angermann, BIT 45 (2005) 761, Table 3): 4 stages, order 3 as a W-method
# (any approximation of the Jacobian), embedded order 2, L-stable for the exact Jacobian.
# Hairer form: (I − γhJ) k_i = h f(t + α_i h, y + Σ_j a_ij k_j) + hJ Σ_j c_ij k_j.
R34_G = 0.435866521508459
R34_A21 = 0.87173304301691801
R34_A31, R34_A32 = 0.84457060015369423, -0.11299064236484185
R34_A41, R34_A42, R34_A43 = 0.0, 0.0, 1.0
R34_C21 = -0.87173304301691801
R34_C31, R34_C32 = -0.90338057013044082, 0.054180672388095326
R34_C41, R34_C42, R34_C43 = 0.24212380706095346, -1.2232505839045147, 0.54526025533510214
R34_M = (0.24212380706095346, -1.2232505839045147, 1.5452602553351020, 0.43586652150845900)
R34_E = (0.37810903145819369, -0.096042292212423178, 0.5, 0.21793326075422950)
R34_ALPHA2 = R34_A21
R34_ALPHA3 = R34_A31 + R34_A32
R34_ALPHA4 = R34_A41 + R34_A42 + R34_A43
R34_GROW = 2.0  # largest step growth factor (fewer rejections than 5 on the contact problems)
R34_KI = 0.7 / 3.0  # PI controller exponents (Gustafsson: 0.7/(p+1), 0.4/(p+1), p = 2 the embedded order)
R34_KP = 0.4 / 3.0


@njit
def _block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb):
    """Finite-difference blocks of ∂f/∂y: one component of every block perturbed at once
    (the blocks' derivatives do not depend on each other's states directly)."""
    n = y.shape[0]
    nb = blk.shape[0]
    for j in range(nbk):
        for i in range(n):
            yt[i] = y[i]
        for b in range(nb):
            o = blk[b] + j
            e = 1e-7 * max(abs(y[o]), 1e4 * atol[o])
            epsb[b] = e
            yt[o] = y[o] + e
        fun(t, yt, f1, args)
        for b in range(nb):
            o = blk[b]
            for i in range(nbk):
                jac[b, i, j] = (f1[o + i] - f0[o + i]) / epsb[b]


@njit
def _jac_vec(jac, blk, nbk, v, out):
    """out = J v with J zero outside the blocks."""
    for i in range(v.shape[0]):
        out[i] = 0.0
    for b in range(blk.shape[0]):
        o = blk[b]
        for i in range(nbk):
            s = 0.0
            for j in range(nbk):
                s += jac[b, i, j] * v[o + j]
            out[o + i] = s


@njit
def _w_solve(winv, blk, nbk, hs, cpl, v, out):
    """out = W⁻¹ v: block-diagonal W, or the arrowhead W of the ring–ball coupling when ``cpl`` holds it."""
    jrr, jbr, jrb, q, sinv, z, r = cpl
    if jbr.shape[0] > 0:
        _coupled_apply_w(winv, q, sinv, jrb, hs, R34_G, blk, nbk, v, out, z, r)
    else:
        _apply_w(winv, blk, nbk, v, out)


@njit
def _j_times(jac, blk, nbk, cpl, v, out):
    """out = J v (ball blocks, plus the ring block and the coupling when ``cpl`` holds them)."""
    jrr, jbr, jrb, q, sinv, z, r = cpl
    if jbr.shape[0] > 0:
        _coupled_jac_vec(jac, jrr, jbr, jrb, blk, nbk, v, out)
    else:
        _jac_vec(jac, blk, nbk, v, out)


@njit
def no_coupling(nbk):
    """The ``cpl`` argument of :func:`_ros34_stages` without the ring–ball coupling."""
    return (np.zeros((NR, NR)), np.zeros((0, nbk, NR)), np.zeros((0, NR, nbk)), np.zeros((0, nbk, NR)),
            np.zeros((NR, NR)), np.zeros((0, nbk)), np.zeros(NR))


@njit
def _ros34_stages(fun, args, t, y, hs, f0, jac, winv, blk, nbk, k1, k2, k3, k4, yt, ft, jv, tv, cpl):
    """The four stages of ROS34PW2 (k_i include the factor h); f0 = f(t, y); ``cpl`` = (J_rr, J_br,
    J_rb, Q, S⁻¹, work, work) of the ring–ball coupling (:func:`_coupled_w`) or :func:`no_coupling`."""
    n = y.shape[0]
    for i in range(n):
        ft[i] = hs * f0[i]
    _w_solve(winv, blk, nbk, hs, cpl, ft, k1)
    # stage 2
    for i in range(n):
        yt[i] = y[i] + R34_A21 * k1[i]
        tv[i] = R34_C21 * k1[i]
    fun(t + R34_ALPHA2 * hs, yt, ft, args)
    _j_times(jac, blk, nbk, cpl, tv, jv)
    for i in range(n):
        ft[i] = hs * (ft[i] + jv[i])
    _w_solve(winv, blk, nbk, hs, cpl, ft, k2)
    # stage 3
    for i in range(n):
        yt[i] = y[i] + R34_A31 * k1[i] + R34_A32 * k2[i]
        tv[i] = R34_C31 * k1[i] + R34_C32 * k2[i]
    fun(t + R34_ALPHA3 * hs, yt, ft, args)
    _j_times(jac, blk, nbk, cpl, tv, jv)
    for i in range(n):
        ft[i] = hs * (ft[i] + jv[i])
    _w_solve(winv, blk, nbk, hs, cpl, ft, k3)
    # stage 4
    for i in range(n):
        yt[i] = y[i] + R34_A41 * k1[i] + R34_A42 * k2[i] + R34_A43 * k3[i]
        tv[i] = R34_C41 * k1[i] + R34_C42 * k2[i] + R34_C43 * k3[i]
    fun(t + R34_ALPHA4 * hs, yt, ft, args)
    _j_times(jac, blk, nbk, cpl, tv, jv)
    for i in range(n):
        ft[i] = hs * (ft[i] + jv[i])
    _w_solve(winv, blk, nbk, hs, cpl, ft, k4)


@njit
def _invert_small(a, out):
    """out = a⁻¹ by Gauss–Jordan elimination with partial pivoting (a is overwritten);
    for the 9×9 blocks this is ~10× faster than a LAPACK call from numba."""
    n = a.shape[0]
    for i in range(n):
        for j in range(n):
            out[i, j] = 0.0
        out[i, i] = 1.0
    for c in range(n):
        p = c
        big = abs(a[c, c])
        for r in range(c + 1, n):
            if abs(a[r, c]) > big:
                big = abs(a[r, c])
                p = r
        if p != c:
            for j in range(n):
                tmp = a[c, j]
                a[c, j] = a[p, j]
                a[p, j] = tmp
                tmp = out[c, j]
                out[c, j] = out[p, j]
                out[p, j] = tmp
        d = 1.0 / a[c, c]
        for j in range(n):
            a[c, j] *= d
            out[c, j] *= d
        for r in range(n):
            if r != c:
                f = a[r, c]
                if f != 0.0:
                    for j in range(n):
                        a[r, j] -= f * a[c, j]
                        out[r, j] -= f * out[c, j]


@njit
def _w_inverse(jac, hs, g, winv, wm):
    """winv[b] = (I − g hs J_b)⁻¹ for every block b."""
    nb = jac.shape[0]
    nbk = jac.shape[1]
    for b in range(nb):
        for i in range(nbk):
            for j in range(nbk):
                wm[i, j] = -g * hs * jac[b, i, j]
            wm[i, i] += 1.0
        _invert_small(wm, winv[b])


NR = 10  # inner-ring states (q, q̇) at the start of the state vector


@njit
def _ring_jac(fun, args, t, y, f0, atol, blk, nbk, jrr, jbr, yt, f1):
    """Finite-difference ring columns of ∂f/∂y: the ring's own block J_rr (10 × 10) and the balls'
    dependence on the ring J_br (per ball nbk × 10), one ring component perturbed at a time."""
    for j in range(NR):
        for i in range(y.shape[0]):
            yt[i] = y[i]
        e = 1e-7 * max(abs(y[j]), 1e4 * atol[j])
        yt[j] = y[j] + e
        fun(t, yt, f1, args)
        for i in range(NR):
            jrr[i, j] = (f1[i] - f0[i]) / e
        for b in range(blk.shape[0]):
            o = blk[b]
            for i in range(nbk):
                jbr[b, i, j] = (f1[o + i] - f0[o + i]) / e


@njit
def _ring_rows(jbr, rmass, bmass, jrb):
    """The ring's dependence on the balls J_rb from J_br by the symmetry of the contact stiffness and
    damping between two bodies (the force of a contact depends on the bodies' relative position and
    sliding velocity, and the ring feels minus the ball's force): M_r ∂a_r/∂(x_b, v_b, ω_b) =
    [M_b ∂a_b/∂(q_r, q̇_r, q̇_r)]ᵀ for the ring's accelerations (rows 5–9); its position rows do not
    depend on the balls.  An approximation (it drops the asymmetric parts: spin, the ring's
    gyroscopic terms, lever-arm changes), which a W-method tolerates without loss of order."""
    for b in range(jbr.shape[0]):
        mb = bmass[b, 0]
        jb = bmass[b, 1]
        for i in range(NR):
            for j in range(9):
                jrb[b, i, j] = 0.0
        for i in range(5):
            mr = rmass[i]
            for j in range(3):
                jrb[b, 5 + i, j] = mb / mr * jbr[b, 3 + j, i]  # positions ↔ ring positions
                jrb[b, 5 + i, 3 + j] = mb / mr * jbr[b, 3 + j, 5 + i]  # velocities ↔ ring rates
                jrb[b, 5 + i, 6 + j] = jb / mr * jbr[b, 6 + j, 5 + i]  # angular velocities ↔ ring rates


@njit
def _coupled_w(jac, jrr, jbr, jrb, hs, g, winv, wm, q, sinv, srr):
    """Arrowhead W = I − g hs J with ring block, ball blocks and ring–ball coupling: ball block
    inverses winv, Q_b = W_bb⁻¹ W_br, and the inverse of the ring's Schur complement
    S = W_rr − Σ_b W_rb Q_b."""
    nb = jac.shape[0]
    nbk = jac.shape[1]
    c = -g * hs
    for b in range(nb):
        for i in range(nbk):
            for j in range(nbk):
                wm[i, j] = c * jac[b, i, j]
            wm[i, i] += 1.0
        _invert_small(wm, winv[b])
    for i in range(NR):
        for j in range(NR):
            srr[i, j] = c * jrr[i, j]
        srr[i, i] += 1.0
    for b in range(nb):
        for i in range(nbk):
            for j in range(NR):
                acc = 0.0
                for k in range(nbk):
                    acc += winv[b, i, k] * c * jbr[b, k, j]
                q[b, i, j] = acc
        for i in range(NR):
            for j in range(NR):
                acc = 0.0
                for k in range(nbk):
                    acc += c * jrb[b, i, k] * q[b, k, j]
                srr[i, j] -= acc
    _invert_small(srr, sinv)


@njit
def _coupled_apply_w(winv, q, sinv, jrb, hs, g, blk, nbk, v, out, z, r):
    """out = W⁻¹ v for the arrowhead W of :func:`_coupled_w` (identity outside ring and balls)."""
    c = -g * hs
    for i in range(v.shape[0]):
        out[i] = v[i]
    nb = blk.shape[0]
    for i in range(NR):
        r[i] = v[i]
    for b in range(nb):
        o = blk[b]
        for i in range(nbk):
            acc = 0.0
            for j in range(nbk):
                acc += winv[b, i, j] * v[o + j]
            z[b, i] = acc
        for i in range(NR):
            acc = 0.0
            for j in range(nbk):
                acc += c * jrb[b, i, j] * z[b, j]
            r[i] -= acc
    for i in range(NR):
        acc = 0.0
        for j in range(NR):
            acc += sinv[i, j] * r[j]
        out[i] = acc
    for b in range(nb):
        o = blk[b]
        for i in range(nbk):
            acc = z[b, i]
            for j in range(NR):
                acc -= q[b, i, j] * out[j]
            out[o + i] = acc


@njit
def _coupled_jac_vec(jac, jrr, jbr, jrb, blk, nbk, v, out):
    """out = J v for the arrowhead J: the ball blocks (:func:`_jac_vec`), the ring block and the
    ring–ball coupling."""
    _jac_vec(jac, blk, nbk, v, out)
    for i in range(NR):
        acc = 0.0
        for j in range(NR):
            acc += jrr[i, j] * v[j]
        out[i] = acc
    for b in range(blk.shape[0]):
        o = blk[b]
        for i in range(nbk):
            acc = 0.0
            for j in range(NR):
                acc += jbr[b, i, j] * v[j]
            out[o + i] += acc
        for i in range(NR):
            acc = 0.0
            for j in range(nbk):
                acc += jrb[b, i, j] * v[o + j]
            out[i] += acc


def ros34_workspace(nb: int, nbk: int, coupled: bool) -> tuple:
    """The Jacobian that :func:`advance_ros34` keeps from one call to the next: (jac [nb, nbk, nbk],
    J_rr [10, 10], J_br [nc, nbk, 10], J_rb [nc, 10, nbk], state int64[2] = (steps since the refresh,
    1 when the arrays hold a Jacobian)), nc = nb when the ring is coupled, else 0.  A run restarted
    from a checkpoint repeats the same steps when the checkpoint holds this workspace too."""
    nc = nb if coupled else 0
    return (np.zeros((nb, nbk, nbk)), np.zeros((NR, NR)), np.zeros((nc, nbk, NR)), np.zeros((nc, NR, nbk)),
            np.zeros(2, dtype=np.int64))


@njit
def advance_ros34(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, ws,
                  rmass=np.zeros(0), bmass=np.zeros((0, 2))):
    """Third-order linearly implicit W-method ROS34PW2 (Rang & Angermann, BIT 45 (2005) 761)
    with the block-diagonal Jacobian of :func:`advance_ros2` (blocks ``blk`` of ``nbk``
    states, finite differences, refreshed every ``jac_every`` steps or after a rejection).

    Order 3 for any approximation of the Jacobian (a W-method), so the lagged block
    Jacobian — which omits the ball–ring and ball–cage coupling and ∂f/∂t — costs no
    order; the embedded second-order solution gives err ∝ h³ and the controller
    h ← h·min(5, max(0.2, 0.9 err^(−1/3))).  4 right-hand sides per step.
    With ``rmass`` = (m, m, m, I_t, I_t) of the inner ring (the first 10 states) and ``bmass``
    (m, J) per ball block, J also holds the ring's own block and the ring–ball coupling
    (:func:`_ring_jac`, :func:`_ring_rows`) and W is solved through the ring's Schur complement
    (:func:`_coupled_w`): the inner ring sliding against all its balls is a stiff mode at low
    rolling speed (docs/dynamics.md).  ``ws`` (:func:`ros34_workspace`) carries the Jacobian and
    the steps since its refresh from one call to the next (refreshed every ``jac_every`` steps and
    after two rejections in a row, and on the first call).
    Same arguments and return values as :func:`advance`.
    """
    n = y.shape[0]
    nb = blk.shape[0]
    jac, jrr, jbr, jrb, jst = ws
    winv = np.zeros((nb, nbk, nbk))
    wm = np.zeros((nbk, nbk))
    f0 = np.empty(n)
    f1 = np.empty(n)
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    yt = np.empty(n)
    ft = np.empty(n)
    jv = np.empty(n)
    tv = np.empty(n)
    ynew = np.empty(n)
    evec = np.empty(n)
    epsb = np.empty(nb)
    coupled = rmass.shape[0] == 5
    nc = nb if coupled else 0
    qm = np.zeros((nc, nbk, NR))
    sinv = np.zeros((NR, NR))
    srr = np.zeros((NR, NR))
    zb = np.zeros((nc, nbk))
    rr = np.zeros(NR)
    # the coupling's arrays, or empty ones (then W and J are the per-ball blocks alone)
    cpl = (jrr, jbr, jrb, qm, sinv, zb, rr) if coupled else no_coupling(nbk)
    need_jac = jst[1] == 0
    since = jst[0]
    h_w = -1.0
    nacc = 0
    nrej = 0
    status = OK
    have_f0 = False
    prev_rej = False
    err_prev = 1.0
    while t < t_end:
        if nacc + nrej >= max_steps:
            status = MAX_STEPS
            break
        hs, last = _clip_step(t, h, t_end)
        if not have_f0:
            fun(t, y, f0, args)
            have_f0 = True
        if need_jac or since >= jac_every:
            _block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb)
            if coupled:
                _ring_jac(fun, args, t, y, f0, atol, blk, nbk, jrr, jbr, yt, f1)
                _ring_rows(jbr, rmass, bmass, jrb)
            need_jac = False
            since = 0
            h_w = -1.0
        if hs != h_w:
            if coupled:
                _coupled_w(jac, jrr, jbr, jrb, hs, R34_G, winv, wm, qm, sinv, srr)
            else:
                _w_inverse(jac, hs, R34_G, winv, wm)
            h_w = hs
        _ros34_stages(fun, args, t, y, hs, f0, jac, winv, blk, nbk, k1, k2, k3, k4, yt, ft, jv, tv, cpl)
        for i in range(n):
            ynew[i] = y[i] + R34_M[0] * k1[i] + R34_M[1] * k2[i] + R34_M[2] * k3[i] + R34_M[3] * k4[i]
            evec[i] = ((R34_M[0] - R34_E[0]) * k1[i] + (R34_M[1] - R34_E[1]) * k2[i]
                       + (R34_M[2] - R34_E[2]) * k3[i] + (R34_M[3] - R34_E[3]) * k4[i])
        err, finite = _error_norm(evec, y, ynew, atol, rtol, info)
        if err <= 1.0:
            for i in range(n):
                y[i] = ynew[i]
            t = t_end if last else t + hs
            have_f0 = False
            prev_rej = False
            nacc += 1
            since += 1
            # PI step-size controller (Gustafsson 1991; Hairer & Wanner, Solving ODEs II, eq. IV.8.21)
            e_now = max(err, 1e-10)
            fac = 0.9 * e_now ** (-R34_KI) * (err_prev / e_now) ** R34_KP
            fac = min(R34_GROW, max(0.2, fac))
            err_prev = max(e_now, 1e-4)
            if not (last and hs < h):
                h = hs * fac
        else:
            nrej += 1
            # a W-method keeps its order with a lagged Jacobian: refresh it only when a
            # step is rejected twice in a row (the Jacobian may then limit stability)
            if prev_rej:
                need_jac = True
            prev_rej = True
            h = hs * max(0.2, 0.9 * err ** (-1.0 / 3.0))
            if h < h_min:
                status = STEP_TOO_SMALL if finite else NOT_FINITE
                break
    jst[0] = since
    jst[1] = 0 if need_jac else 1
    info[0] = nacc
    info[1] = nrej
    return status, t, h


@njit
def fixed_steps_ros34(fun, args, t, y, h, nsteps, blk, nbk):
    """``nsteps`` ROS34PW2 steps of constant size h with the block Jacobian refreshed every
    step (no error control) — for order tests.  ``nbk`` = 0 gives J = 0 (the W-method then
    is an explicit 4-stage Runge–Kutta method of order 3)."""
    n = y.shape[0]
    nb = blk.shape[0] if nbk > 0 else 0
    nk = max(nbk, 1)
    jac = np.zeros((nb, nk, nk))
    winv = np.zeros((nb, nk, nk))
    wm = np.zeros((nk, nk))
    bl = blk[:nb]
    cpl = no_coupling(nk)
    f0 = np.empty(n)
    f1 = np.empty(n)
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    yt = np.empty(n)
    ft = np.empty(n)
    jv = np.empty(n)
    tv = np.empty(n)
    epsb = np.empty(max(nb, 1))
    atol = np.full(n, 1e-12)
    for _ in range(nsteps):
        fun(t, y, f0, args)
        if nb > 0:
            _block_jac(fun, args, t, y, f0, atol, bl, nk, jac, yt, f1, epsb)
            _w_inverse(jac, h, R34_G, winv, wm)
        _ros34_stages(fun, args, t, y, h, f0, jac, winv, bl, nk, k1, k2, k3, k4, yt, ft, jv, tv, cpl)
        for i in range(n):
            y[i] = y[i] + R34_M[0] * k1[i] + R34_M[1] * k2[i] + R34_M[2] * k3[i] + R34_M[3] * k4[i]
        t += h
    return t
