"""Numba kernels of the Jones–Harris quasi-static model (plain float arrays in, floats out).

Orchestration, checks and packaging live in :mod:`bearingsim.statics.jones_harris`;
this module holds only the per-ball and per-ring arithmetic.  Two ring solvers: :func:`solve_ring`
(Newton on the ring displacement, every ball solved to convergence at each trial) and
:func:`solve_ring_coupled` (the batch solver: Newton on the ring and ball unknowns together, with
:func:`solve_ring` as its safeguard).

Model (Jones 1960; Harris & Kotzalas 2007 vol. 2 ch. 3, eqs. 3.22–3.61; [S0] eqs. 6–16).
Each row is described by a parameter vector (indices in :mod:`bearingsim.statics.layout`).  For ball j at azimuth ψ_j,
in the row's local axial–radial plane (ξ = s (x − x_row), r), the vector from the outer
groove-curvature centre (fixed) to the inner one is

    A₁ = Δx₀ + e + s u_x,    A₂ = Δr₀ + u_r,

where u is the displacement of the inner groove centre caused by the inner-ring
displacement q = (δx, δy, δz, γy, γz) (small rotations), e an axial preload offset and
s = ±1 the row's orientation.  The ball centre sits at (X₁, X₂) from the outer groove
centre; the two geometric constraints of [S0] (eqs. 6, 9)

    (A₁ − X₁)² + (A₂ − X₂)² = (r_i + δ_i)²,   X₁² + X₂² = (r_o + δ_o)²,   r = (f − ½) D,

are eliminated exactly (δ_i, δ_o follow from X), leaving the two force balances of the
ball ([S0] eq. 10) in the unknowns (X₁, X₂):

    Q_i sin α_i − Q_o sin α_o − λ_o G cos α_o + λ_i G cos α_i = 0
    Q_i cos α_i − Q_o cos α_o + λ_o G sin α_o − λ_i G sin α_i + F_c = 0

with Q = K δ^1.5, G = M_g / D, M_g = J ω_R ω_m sin β, F_c = ½ m d_m ω_m² ([S0] eqs. 11–12)
and λ_o = 2, λ_i = 0 for outer-raceway control, λ_o = λ_i = 1 for inner control.
The signs of the gyroscopic terms follow from the free-body diagram of the ball whose
spin vector (Jones) is ω_R (cos β, −sin β) in (ξ, r) with ω_R < 0: the moment the
raceways must apply to the ball is dH/dt = J |ω_R| ω_m sin β e_ψ (derivation in
docs/physics.md).  Ball speeds ω_m, ω_R and pitch angle β are Jones' rolling relations
(no slip at the contact centres; see :func:`kinematics`) evaluated at the current
contact angles; their derivatives are carried through the analytic Jacobian.

Robustness: every kernel is compiled with ``error_model="numpy"`` — a zero divisor (Jones'
relations at contact angles where they have no solution, ``po + pi = 0`` or ``cos α_i = γ′``) gives NaN,
never an exception — and the residual norms propagate NaN (:func:`_scaled_norm`), so a failed evaluation
is a rejected trial, never a small residual.  A singular ring Jacobian gets a Levenberg–Marquardt step
(:func:`regularised_step`) or status 2, never ``np.linalg.solve``'s LinAlgError.  Status codes (one table:
:data:`bearingsim.statics.layout.STATUS`) of the ring solvers: 0 converged, 1 iteration limit, 2 singular,
3 loaded contact past the groove bottom of an angular contact row, 6 loaded contact at |α| ≥ 90°
(:func:`contact_past_groove_edge`); the callers add 4 (a ball's own balance failed), 5 (the ring balance
fails the independent re-solve, :func:`equilibrium_residual`), 7 (internal error of one point in a batch)
and 8 (no ball loaded at the inner raceway: a free ring).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

# ---- row parameter layout and raceway control: the public contract of bearingsim.statics.layout ----------
from ..contact.hertz import series_constant
from . import layout as _layout
from .layout import (  # noqa: F401  (re-exported: the kernels read them as compile-time constants)
    CONTROL_AUTO,
    CONTROL_INNER,
    CONTROL_OUTER,
    NPAR,
    P_AXOFF,
    P_CAI,
    P_CAO,
    P_CPI,
    P_CPO,
    P_D,
    P_DM,
    P_DR0,
    P_DX0,
    P_GRI,
    P_JB,
    P_KI,
    P_KO,
    P_MASS,
    P_OROT,
    P_PSI0,
    P_RI,
    P_RIC,
    P_RO,
    P_SIGN,
    P_XIC,
    P_XROW,
    P_Z,
    STATUS,
)

#: the row formulas of :mod:`.layout` (written once there, in plain Python), compiled for the kernels
inner_groove_centre_axial = njit(cache=True, error_model="numpy")(_layout.inner_groove_centre_axial)
ball_speed_constants = njit(cache=True, error_model="numpy")(_layout.ball_speed_constants)


@njit(cache=True, error_model="numpy")
def kinematics(si, ci, so, co, gam):
    """Jones' ball speeds for outer-raceway control and inner-raceway control.

    Outer ring fixed, inner ring at ω; γ′ = D/d_m.  Returns, per unit ω,
    (ω_m/ω, ω_R/ω, β) for outer control and then for inner control.

    tan β = sin α_o / (cos α_o + γ′) (outer control), tan β = sin α_i / (cos α_i − γ′)
    (inner control); ω_R/ω = −1 / {γ′ cos β [C_o/(1 + γ′ cos α_o) + C_i/(1 − γ′ cos α_i)]},
    ω_m/ω = [C_o/(1 + γ′ cos α_o)] / [C_o/(1 + γ′ cos α_o) + C_i/(1 − γ′ cos α_i)],
    C = cos α + tan β sin α (Jones 1960, eqs. for the ball speeds with the outer ring
    fixed; Harris & Kotzalas 2007 vol. 2 ch. 2; re-derived from pure rolling at both
    contact centres in docs/physics.md).

    Sign convention (the one every user of these speeds applies as is; tested in
    tests/unit/test_kinematics_convention.py and tests/validation/test_jones_kinematics.py):
    the frame is the row's local frame (ξ = s (x − x_row) axial, r radial, t = ξ × r along
    the orbit), turning with the cage at ω_m [rad/s] about the bearing axis x.  The contact angles
    are those of ``ball_eval`` (sin α = axial / radial share of the groove-centre-to-ball-centre
    line): the outer contact centre is at +(D/2)(sin α_o, cos α_o), the inner one at
    −(D/2)(sin α_i, cos α_i) from the ball centre in (ξ, r).  The ball turns relative to the cage
    with the angular velocity Ω = ω_R (cos β, −sin β, 0) [rad/s]: ω_R is signed (ω_R/ω < 0), β is
    the pitch of the rotation axis from +ξ towards −r and does not depend on the sign of ω.
    ω_m and ω_R are proportional to the signed inner-ring speed ω (positive about +x), for outer
    and inner control alike.  With this Ω the sliding at both contact centres is zero and the
    spin about the controlling raceway's normal is zero.  In the global frame (x, r) Ω is a
    pseudo-vector: (ω_R cos β, −s ω_R sin β), so a mirrored row (s = −1) of a set keeps the
    axial component and reverses the radial one (as ``dynamics.model`` builds its start state).
    """
    res = np.empty(6)
    for k in range(2):
        if k == 0:
            t = so / (co + gam)
        else:
            t = si / (ci - gam)
        po = (co + t * so) / (1.0 + gam * co)
        pi = (ci + t * si) / (1.0 - gam * ci)
        cb = 1.0 / math.sqrt(1.0 + t * t)
        if po + pi == 0.0 or not math.isfinite(t):
            # contact angles for which the rolling relations have no solution (a contact past 90°):
            # undefined speeds, reported as NaN, never a division by zero
            res[3 * k] = math.nan
            res[3 * k + 1] = math.nan
            res[3 * k + 2] = math.nan
            continue
        res[3 * k] = po / (po + pi)
        res[3 * k + 1] = -1.0 / (gam * cb * (po + pi))
        res[3 * k + 2] = math.atan(t)
    return res


@njit(cache=True, error_model="numpy")
def rolling_angles(si, ci, so, co, di, do):
    """The contact angles (sin, cos) Jones' rolling relations take, inner then outer, and whether the inner or the
    outer one was replaced: the geometric ones, except for an open contact (approach di or do ≤ 0 [m]) whose groove
    centre the ball has passed (cos < 0: an unloaded ball opposite a radial load heavy enough to carry the inner
    groove centre past it), which takes the other contact's angle.  The relations divide by
    (cos α_o + tan β sin α_o)/(1 + γ′ cos α_o) + (cos α_i + tan β sin α_i)/(1 − γ′ cos α_i), which is 0 for such a
    ball: 6205 under 50 kN radial did not converge at any speed above 0 (residual NaN), while it did at rest."""
    inv_i = di <= 0.0 and ci < 0.0 and not (do <= 0.0 and co < 0.0)
    inv_o = do <= 0.0 and co < 0.0 and not inv_i
    if inv_i:
        return so, co, so, co, True, False
    if inv_o:
        return si, ci, si, ci, False, True
    return si, ci, so, co, False, False


@njit(cache=True, error_model="numpy")
def ball_eval(x1, x2, a1, a2, ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, out, jac, orot=0.0):
    """Residual, ring force and analytic derivatives for one ball.

    Parameters
    ----------
    x1, x2 : ball centre from the outer groove centre, axial and radial [m]
    a1, a2 : inner groove centre from the outer groove centre [m]
    ri, ro : (f − ½)D of inner and outer groove [m]; ki, ko [N/m^1.5]
    gam : D/d_m [-]; cg = J ω² d_m / D² [N]; cf = ½ m d_m ω² [N]
    lam_i, lam_o : gyroscopic-moment shares; inner_ctrl : 1 for inner control (sets β)
    orot : 1 when the outer ring turns at ω and the inner ring stands (row parameter ``P_OROT``), else 0
    out : float[10]  ← R1, R2, Fx, Fr, Qi, Qo, di, do, G, Fc
        R = ball residual [N]; (Fx, Fr) = force of the inner ring on the ball [N]
    jac : float[5, 4] ← rows dR1, dR2, dFx, dFr, dG; columns d/d(x1, x2, a1, a2)
    """
    u = x1
    v = x2
    p = a1 - x1
    q = a2 - x2
    lo = math.sqrt(u * u + v * v)
    li = math.sqrt(p * p + q * q)
    so = u / lo
    co = v / lo
    si = p / li
    ci = q / li
    do = lo - ro
    di = li - ri
    if do > 0.0:
        sq = math.sqrt(do)
        qo = ko * do * sq
        dqo = 1.5 * ko * sq
    else:
        qo = 0.0
        dqo = 0.0
    if di > 0.0:
        sq = math.sqrt(di)
        qi = ki * di * sq
        dqi = 1.5 * ki * sq
    else:
        qi = 0.0
        dqi = 0.0
    # d(trig)/d(x1, x2, a1, a2)
    dsi = (-ci * ci / li, si * ci / li, ci * ci / li, -si * ci / li)
    dci = (si * ci / li, -si * si / li, -si * ci / li, si * si / li)
    dso = (co * co / lo, -so * co / lo, 0.0, 0.0)
    dco = (-so * co / lo, so * so / lo, 0.0, 0.0)
    dQi = (-dqi * si, -dqi * ci, dqi * si, dqi * ci)
    dQo = (dqo * so, dqo * co, 0.0, 0.0)
    g = 0.0
    fc = 0.0
    g_si = g_ci = g_so = g_co = 0.0
    f_si = f_ci = f_so = f_co = 0.0
    ksi, kci, kso, kco, inv_i, inv_o = rolling_angles(si, ci, so, co, di, do)
    if cg > 0.0 or cf > 0.0:
        if inner_ctrl:
            den = kci - gam
            if den == 0.0:
                den = math.nan  # β = 90°: outside the rolling relations (NaN residual, never a crash)
            t = ksi / den
            t_si = 1.0 / den
            t_ci = -ksi / (den * den)
            t_so = 0.0
            t_co = 0.0
        else:
            den = kco + gam
            if den == 0.0:
                den = math.nan
            t = kso / den
            t_si = 0.0
            t_ci = 0.0
            t_so = 1.0 / den
            t_co = -kso / (den * den)
        ao = 1.0 + gam * kco
        ai = 1.0 - gam * kci
        po = (kco + t * kso) / ao
        pi = (kci + t * ksi) / ai
        s = po + pi
        if s == 0.0:
            # no rolling solution at these contact angles (Jones' relations divide by po + pi):
            # the ball's residual becomes NaN, which every solver treats as a failed trial
            s = math.nan
        s2 = s * s
        s3 = s2 * s
        # the cage's absolute orbit per unit ring speed: ω_m/ω = po/s with the inner ring turning, 1 − po/s =
        # pi/s with the outer ring turning (kinematic inversion: the relative speeds are those of the inner ring
        # at −ω, seen from the outer ring); the ball's spin relative to the cage then turns with +ω, so the
        # gyroscopic moment J ω_R ω_m sin β changes sign (Harris & Kotzalas 2007 vol. 2 ch. 2, outer ring rotating)
        if orot:
            nn = pi
            mm = po
            sg = -1.0
        else:
            nn = po
            mm = pi
            sg = 1.0
        g = sg * cg * t * nn / s2
        fc = cf * nn * nn / s2
        g_t = sg * cg * nn / s2
        g_n = sg * cg * t * (mm - nn) / s3
        g_m = -2.0 * sg * cg * t * nn / s3
        f_n = 2.0 * cf * nn * mm / s3
        f_m = -2.0 * cf * nn * nn / s3
        if orot:
            g_po, g_pi, f_po, f_pi = g_m, g_n, f_m, f_n
        else:
            g_po, g_pi, f_po, f_pi = g_n, g_m, f_n, f_m
        # partials with respect to (ksi, kci, kso, kco), including those through t
        po_t = kso / ao
        pi_t = ksi / ai
        dpo_si = po_t * t_si
        dpo_ci = po_t * t_ci
        dpo_so = t / ao + po_t * t_so
        dpo_co = (1.0 - gam * t * kso) / (ao * ao) + po_t * t_co
        dpi_si = t / ai + pi_t * t_si
        dpi_ci = (1.0 + gam * t * ksi) / (ai * ai) + pi_t * t_ci
        dpi_so = pi_t * t_so
        dpi_co = pi_t * t_co
        g_si = g_t * t_si + g_po * dpo_si + g_pi * dpi_si
        g_ci = g_t * t_ci + g_po * dpo_ci + g_pi * dpi_ci
        g_so = g_t * t_so + g_po * dpo_so + g_pi * dpi_so
        g_co = g_t * t_co + g_po * dpo_co + g_pi * dpi_co
        f_si = f_po * dpo_si + f_pi * dpi_si
        f_ci = f_po * dpo_ci + f_pi * dpi_ci
        f_so = f_po * dpo_so + f_pi * dpi_so
        f_co = f_po * dpo_co + f_pi * dpi_co
        if inv_i:  # the inner angle was the outer one: its partials are the outer angle's
            g_so += g_si
            g_co += g_ci
            f_so += f_si
            f_co += f_ci
            g_si = g_ci = f_si = f_ci = 0.0
        elif inv_o:
            g_si += g_so
            g_ci += g_co
            f_si += f_so
            f_ci += f_co
            g_so = g_co = f_so = f_co = 0.0
    fx = qi * si + lam_i * g * ci
    fr = qi * ci - lam_i * g * si
    ox = -qo * so - lam_o * g * co
    orr = -qo * co + lam_o * g * so
    out[0] = fx + ox
    out[1] = fr + orr + fc
    out[2] = fx
    out[3] = fr
    out[4] = qi
    out[5] = qo
    out[6] = di
    out[7] = do
    out[8] = g
    out[9] = fc
    for k in range(4):
        dgk = g_si * dsi[k] + g_ci * dci[k] + g_so * dso[k] + g_co * dco[k]
        dfck = f_si * dsi[k] + f_ci * dci[k] + f_so * dso[k] + f_co * dco[k]
        dfx = dQi[k] * si + qi * dsi[k] + lam_i * (dgk * ci + g * dci[k])
        dfr = dQi[k] * ci + qi * dci[k] - lam_i * (dgk * si + g * dsi[k])
        dox = -dQo[k] * so - qo * dso[k] - lam_o * (dgk * co + g * dco[k])
        dor = -dQo[k] * co - qo * dco[k] + lam_o * (dgk * so + g * dso[k])
        jac[0, k] = dfx + dox
        jac[1, k] = dfr + dor + dfck
        jac[2, k] = dfx
        jac[3, k] = dfr
        jac[4, k] = dgk


@njit(cache=True, error_model="numpy")
def ball_solve(a1, a2, par, cg, cf, lam_i, lam_o, inner_ctrl, x, out, jac, tol, maxit):
    """Solve the two force balances of one ball for its centre (X₁, X₂) by Newton–Raphson.

    ``x`` holds the start on entry and the solution on exit.  At zero speed the
    solution is closed form: the ball lies on the line of the groove centres and
    shares the approach in the ratio (K_o/K_i)^(2/3).  Returns (converged, iterations).
    """
    ri = par[P_RI]
    ro = par[P_RO]
    ki = par[P_KI]
    ko = par[P_KO]
    orot = par[P_OROT]
    gam = par[P_D] / par[P_DM]
    l = math.sqrt(a1 * a1 + a2 * a2)
    dn = l - (ri + ro)
    if cg == 0.0 and cf == 0.0:
        if dn > 0.0:
            do = dn / (1.0 + (ko / ki) ** (2.0 / 3.0))
        else:
            do = 0.5 * dn
        x[0] = (ro + do) * a1 / l
        x[1] = (ro + do) * a2 / l
        ball_eval(x[0], x[1], a1, a2, ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, out, jac, orot)
        return True, 0
    # a start that keeps the outer contact loaded (centrifugal force pushes the ball out)
    lo = math.sqrt(x[0] * x[0] + x[1] * x[1])
    if not (lo > ro) or not (abs(x[0]) < l + ro):
        do_min = (cf / ko) ** (2.0 / 3.0)
        if dn > 0.0:
            do = max(dn / (1.0 + (ko / ki) ** (2.0 / 3.0)), do_min)
        else:
            do = do_min
        x[0] = (ro + do) * a1 / l
        x[1] = (ro + do) * a2 / l
    scale = cf + 1.0
    it = 0
    conv = False
    ball_eval(x[0], x[1], a1, a2, ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, out, jac, orot)
    r0 = math.hypot(out[0], out[1])
    xs0 = 0.0
    xs1 = 0.0
    if r0 <= tol * scale:
        # the start already meets the tolerance (a warm start that did not move)
        return True, 0
    for it in range(1, maxit + 1):
        det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
        if det == 0.0 or not math.isfinite(det):
            break
        dx0 = -(jac[1, 1] * out[0] - jac[0, 1] * out[1]) / det
        dx1 = -(-jac[1, 0] * out[0] + jac[0, 0] * out[1]) / det
        if math.hypot(dx0, dx1) <= tol * par[P_D]:
            # the full Newton step is below the position tolerance: take it and stop (a line
            # search on round-off would only waste evaluations)
            x[0] += dx0
            x[1] += dx1
            ball_eval(x[0], x[1], a1, a2, ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, out, jac, orot)
            conv = True
            break
        # limit the step to a fraction of the groove-centre distance
        lim = 0.05 * (ri + ro)
        st = math.hypot(dx0, dx1)
        if st > lim:
            dx0 *= lim / st
            dx1 *= lim / st
        xs0 = x[0]
        xs1 = x[1]
        # take the step in polar coordinates about the outer groove centre (normal part along the
        # radius, tangential part as an arc): to first order the same Newton step, but a ball that
        # rolls along the outer groove (inner contact open) is not pushed into the outer raceway by
        # the chord, so the line search does not have to crawl
        ls0 = math.sqrt(xs0 * xs0 + xs1 * xs1)
        ns0 = xs0 / ls0
        ns1 = xs1 / ls0
        dn = ns0 * dx0 + ns1 * dx1
        dth = (ns1 * dx0 - ns0 * dx1) / ls0
        th0 = math.atan2(xs0, xs1)
        lam = 1.0
        for _ in range(30):
            lt = ls0 + lam * dn
            tht = th0 + lam * dth
            x[0] = lt * math.sin(tht)
            x[1] = lt * math.cos(tht)
            ball_eval(x[0], x[1], a1, a2, ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, out, jac, orot)
            r1 = math.hypot(out[0], out[1])
            if r1 <= (1.0 - 1e-4 * lam) * r0 or r1 <= tol * scale:
                break
            lam *= 0.5
        r0 = r1
        stepn = lam * math.hypot(dx0, dx1)
        if r0 <= tol * scale or stepn <= tol * par[P_D]:
            conv = True
            break
        if it >= 5 and out[4] == 0.0 and out[6] < -0.05 * (ri + ro):
            # far off the inner raceway (beyond any Newton overshoot): no force on the inner ring
            conv = True
            break
    if not conv and out[4] == 0.0 and out[6] < 0.0:
        # the ball has left the inner raceway: it exerts no force on the inner ring, and its
        # position along the outer groove (held by a tiny centrifugal force) does not matter
        conv = True
    return conv, it


@njit(cache=True, error_model="numpy")
def ball_total_derivative(jac, dfa):
    """dF/dA of the ring force at ball equilibrium: ∂F/∂A − ∂F/∂X (∂R/∂X)⁻¹ ∂R/∂A.

    Implicit differentiation of the ball balance (no extra solve).  Fills dfa[3, 2]
    for (Fx, Fr, G) with respect to (A₁, A₂).
    """
    det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
    # S = (dR/dX)^-1 dR/dA  (2x2)
    s00 = (jac[1, 1] * jac[0, 2] - jac[0, 1] * jac[1, 2]) / det
    s01 = (jac[1, 1] * jac[0, 3] - jac[0, 1] * jac[1, 3]) / det
    s10 = (-jac[1, 0] * jac[0, 2] + jac[0, 0] * jac[1, 2]) / det
    s11 = (-jac[1, 0] * jac[0, 3] + jac[0, 0] * jac[1, 3]) / det
    for r in range(2):
        dfa[r, 0] = jac[2 + r, 2] - (jac[2 + r, 0] * s00 + jac[2 + r, 1] * s10)
        dfa[r, 1] = jac[2 + r, 3] - (jac[2 + r, 0] * s01 + jac[2 + r, 1] * s11)
    dfa[2, 0] = jac[4, 2] - (jac[4, 0] * s00 + jac[4, 1] * s10)
    dfa[2, 1] = jac[4, 3] - (jac[4, 0] * s01 + jac[4, 1] * s11)


@njit(cache=True, error_model="numpy")
def control_weights(inner_ctrl):
    """(λ_i, λ_o) of the gyroscopic-moment share for raceway control: inner (1, 1) or outer (0, 2) (Harris)."""
    if inner_ctrl == 1:
        return 1.0, 1.0
    return 0.0, 2.0


@njit(cache=True, error_model="numpy")
def _ball_row_out(bo, a1, a2, xl, out, g):
    """One ball's row of the ``ballout`` table (layout in :func:`ring_assemble`): groove-centre offsets
    (A1, A2) [m], loads, approaches and kinematic terms from the ball solve ``out``, the gyroscopic
    factor g, and sin/cos of the inner and outer contact angles from the ball position xl [m]."""
    li = math.sqrt((a1 - xl[0]) ** 2 + (a2 - xl[1]) ** 2)
    lo = math.sqrt(xl[0] ** 2 + xl[1] ** 2)
    bo[0] = a1
    bo[1] = a2
    bo[2] = out[4]
    bo[3] = out[5]
    bo[4] = out[6]
    bo[5] = out[7]
    bo[6] = g
    bo[7] = out[9]
    bo[8] = (a1 - xl[0]) / li
    bo[9] = (a2 - xl[1]) / li
    bo[10] = xl[0] / lo
    bo[11] = xl[1] / lo


@njit(cache=True, error_model="numpy")
def _groove_offsets(par, s, ric, xg, cp, sp, qv, ta1, ta2, gw):
    """(A1, A2) [m] of a ball at azimuth ψ (cp, sp = cos ψ, sin ψ) for ring displacement qv, and their
    gradients: ta1, ta2 ← d(A1)/dq, d(A2)/dq (small rotations about y and z of the inner groove-centre
    point at axial position xg, radius ric, row sign s), gw ← the ring's rotation about the ball's
    tangential axis per unit q (maps a moment in the ball's plane onto the ring tilts)."""
    ta1[0] = s
    ta1[1] = 0.0
    ta1[2] = 0.0
    ta1[3] = s * ric * sp
    ta1[4] = -s * ric * cp
    ta2[0] = 0.0
    ta2[1] = cp
    ta2[2] = sp
    ta2[3] = -xg * sp
    ta2[4] = xg * cp
    gw[0] = 0.0
    gw[1] = 0.0
    gw[2] = 0.0
    gw[3] = s * sp
    gw[4] = -s * cp
    a1 = par[P_DX0] + par[P_AXOFF]
    a2 = par[P_DR0]
    for k in range(5):
        a1 += ta1[k] * qv[k]
        a2 += ta2[k] * qv[k]
    return a1, a2


@njit(cache=True, error_model="numpy")
def ring_assemble(rows, qv, omega, control, lam_state, xb, loads, res, kmat, ballout, tol, maxit):
    """Solve every ball for the ring displacement qv and assemble residual and stiffness.

    Parameters
    ----------
    rows : float[nrow, NPAR]; qv : float[5] (δx, δy, δz, γy, γz) [m, rad]
    omega : inner-ring speed [rad/s]; control : CONTROL_OUTER/INNER/AUTO
    lam_state : int[nrow, zmax] current control per ball (0 outer, 1 inner), updated for AUTO
    xb : float[nrow, zmax, 2] ball positions (warm start in, solution out); or float[nrow, zmax, 8]
         with (A1, A2, dX1/dA1, dX1/dA2, dX2/dA1, dX2/dA2) of the last solution after (X1, X2), which
         starts each ball solve at the tangent prediction X + dX/dA ΔA (same solution, fewer iterations)
    loads : float[5] external (Fa, Fr_y, Fr_z, M_y, M_z) [N, N·m] on the inner ring
    res : float[5] ← loads + Σ ball forces on the ring (zero at equilibrium)
    kmat : float[5, 5] ← stiffness −d(res)/dq
    ballout : float[nrow, zmax, 12] ← per ball: A1, A2, Qi, Qo, di, do, G, Fc, sin/cos αi, sin/cos αo
    Returns the worst ball (converged flag, iterations).
    """
    nrow = rows.shape[0]
    for k in range(5):
        res[k] = loads[k]
        for m in range(5):
            kmat[k, m] = 0.0
    out = np.empty(10)
    jac = np.empty((5, 4))
    dfa = np.empty((3, 2))
    xl = np.empty(2)
    ta1 = np.empty(5)
    ta2 = np.empty(5)
    gw = np.empty(5)
    allconv = True
    maxits = 0
    w2 = omega * omega
    # xb[r, j, 2:8], when present, holds the ball's last (A1, A2) and dX/dA (row-major) for the
    # first-order warm start below; with only (X1, X2) stored the start is the last position
    # (not at rest, where the ball solve is closed form; the tangents are cleared there)
    ext = xb.shape[2] >= 8
    ext_pred = ext and omega != 0.0
    for r in range(nrow):
        par = rows[r]
        z = int(par[P_Z])
        s = par[P_SIGN]
        ric = par[P_RIC]
        xg = inner_groove_centre_axial(par)  # inner groove centre, offset included
        cg, cf = ball_speed_constants(par, w2)
        for j in range(z):
            psi = par[P_PSI0] + 2.0 * math.pi * j / z
            cp = math.cos(psi)
            sp = math.sin(psi)
            # d(A1)/dq and d(A2)/dq (small rotations about y and z of the groove-centre point)
            a1, a2 = _groove_offsets(par, s, ric, xg, cp, sp, qv, ta1, ta2, gw)
            xl[0] = xb[r, j, 0]
            xl[1] = xb[r, j, 1]
            if ext_pred:
                # first-order warm start: X + (dX/dA) ΔA from the ball's last solution
                da1 = a1 - xb[r, j, 2]
                da2 = a2 - xb[r, j, 3]
                xl[0] += xb[r, j, 4] * da1 + xb[r, j, 5] * da2
                xl[1] += xb[r, j, 6] * da1 + xb[r, j, 7] * da2
            if control == CONTROL_AUTO and omega != 0.0:
                # auto control is decided from the outer-control solution of the ball at this displacement,
                # whatever the ball's state before: the ring forces are then a function of q alone (the cold
                # re-solve of equilibrium_residual gives the same balls), see the criterion below
                lam_state[r, j] = 0
            for _pass in range(4):
                inner_ctrl = lam_state[r, j]
                lam_i, lam_o = control_weights(inner_ctrl)
                conv, its = ball_solve(a1, a2, par, cg, cf, lam_i, lam_o, inner_ctrl, xl, out, jac, tol, maxit)
                if control == CONTROL_OUTER or omega == 0.0:
                    break
                qi = out[4]
                qo = out[5]
                if not (qi > 0.0):
                    # the inner contact is open: it transmits neither load nor the friction that would
                    # hold the gyroscopic moment, so the outer raceway controls the ball (λ_i = 0)
                    want = 0
                elif control == CONTROL_INNER or inner_ctrl == 1:
                    # inner control, or an auto ball that the criterion at its outer-control solution
                    # gave to the inner raceway (decided once: a ball whose criterion flips with its own
                    # control keeps that first decision instead of alternating between the two states)
                    want = 1
                elif _pass > 0:
                    # an auto ball back at outer control because its inner contact opened: final
                    want = 0
                else:
                    # raceway control criterion (Jones 1960; Harris & Kotzalas 2007 vol. 2 ch. 2):
                    # outer control when Q_o a_o E(κ_o) cos(α_i − α_o) > Q_i a_i E(κ_i)
                    lo = math.sqrt(xl[0] ** 2 + xl[1] ** 2)
                    li = math.sqrt((a1 - xl[0]) ** 2 + (a2 - xl[1]) ** 2)
                    cdiff = ((a2 - xl[1]) / li) * (xl[1] / lo) + ((a1 - xl[0]) / li) * (xl[0] / lo)
                    lhs = par[P_CAO] * qo ** (4.0 / 3.0) * cdiff
                    rhs = par[P_CAI] * qi ** (4.0 / 3.0)
                    want = 0 if lhs > rhs else 1
                if want == inner_ctrl:
                    break
                lam_state[r, j] = want
            lam_state[r, j] = inner_ctrl
            if not conv:
                allconv = False
            if its > maxits:
                maxits = its
            xb[r, j, 0] = xl[0]
            xb[r, j, 1] = xl[1]
            if ext:
                xb[r, j, 2] = a1
                xb[r, j, 3] = a2
                det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
                if ext_pred and conv and det != 0.0 and math.isfinite(det):
                    # dX/dA = −(∂R/∂X)⁻¹ ∂R/∂A at the ball's equilibrium (implicit differentiation)
                    xb[r, j, 4] = -(jac[1, 1] * jac[0, 2] - jac[0, 1] * jac[1, 2]) / det
                    xb[r, j, 5] = -(jac[1, 1] * jac[0, 3] - jac[0, 1] * jac[1, 3]) / det
                    xb[r, j, 6] = -(-jac[1, 0] * jac[0, 2] + jac[0, 0] * jac[1, 2]) / det
                    xb[r, j, 7] = -(-jac[1, 0] * jac[0, 3] + jac[0, 0] * jac[1, 3]) / det
                else:
                    xb[r, j, 4] = 0.0
                    xb[r, j, 5] = 0.0
                    xb[r, j, 6] = 0.0
                    xb[r, j, 7] = 0.0
            # out and jac hold the evaluation at the solution (last call of ball_solve)
            fx = out[2]
            fr = out[3]
            g = out[8]
            mpsi = lam_i * g * par[P_GRI]
            # generalized force of this ball on the ring: -(Fx dA1/dq + Fr dA2/dq) + Mpsi w
            for k in range(5):
                res[k] += -(fx * ta1[k] + fr * ta2[k]) + mpsi * gw[k]
            if out[4] > 0.0 or out[5] > 0.0:
                det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
                if det != 0.0 and math.isfinite(det):
                    ball_total_derivative(jac, dfa)
                    for k in range(5):
                        dfxq = dfa[0, 0] * ta1[k] + dfa[0, 1] * ta2[k]
                        dfrq = dfa[1, 0] * ta1[k] + dfa[1, 1] * ta2[k]
                        dgq = dfa[2, 0] * ta1[k] + dfa[2, 1] * ta2[k]
                        for m in range(5):
                            kmat[m, k] += ta1[m] * dfxq + ta2[m] * dfrq - lam_i * par[P_GRI] * gw[m] * dgq
            _ball_row_out(ballout[r, j], a1, a2, xl, out, g)
    return allconv, maxits


@njit(cache=True, error_model="numpy")
def solve_small(a, b, x, w):
    """x ← a⁻¹ b for a small dense system by Gaussian elimination with partial pivoting.

    a : float[n, n] (not modified), b : float[n], x : float[n] (output), w : float[n, n + 1]
    (workspace).  Returns False when a pivot is zero or not finite (singular system).  Replaces
    np.linalg.solve in the hot loops (no allocation, no LAPACK call overhead for n = 5).
    """
    n = b.shape[0]
    for i in range(n):
        for j in range(n):
            w[i, j] = a[i, j]
        w[i, n] = b[i]
    for c in range(n):
        p = c
        big = abs(w[c, c])
        for i in range(c + 1, n):
            v = abs(w[i, c])
            if v > big:
                big = v
                p = i
        if not (big > 0.0) or not math.isfinite(big):
            return False
        if p != c:
            for j in range(c, n + 1):
                t = w[c, j]
                w[c, j] = w[p, j]
                w[p, j] = t
        inv = 1.0 / w[c, c]
        for i in range(c + 1, n):
            f = w[i, c] * inv
            if f != 0.0:
                for j in range(c + 1, n + 1):
                    w[i, j] -= f * w[c, j]
    for i in range(n - 1, -1, -1):
        t = w[i, n]
        for j in range(i + 1, n):
            t -= w[i, j] * x[j]
        x[i] = t / w[i, i]
    return True


@njit(cache=True, error_model="numpy")
def regularised_step(kk, res, dq, wsol, dm, mu):
    """dq ← (K + μ d S)⁻¹ res with S = diag(1, 1, 1, d_m²/4, d_m²/4) and d the largest diagonal entry of
    K in force units (Levenberg 1944 / Marquardt 1963 damping of a singular Newton step).  ``kk`` is
    modified.  Returns False when no finite step exists (an empty or non-finite matrix)."""
    d = 0.0
    for k in range(5):
        v = abs(kk[k, k]) * (1.0 if k < 3 else 4.0 / (dm * dm))
        if math.isfinite(v) and v > d:
            d = v
    if not (d > 0.0):
        return False
    for k in range(5):
        kk[k, k] += mu * d * (1.0 if k < 3 else 0.25 * dm * dm)
    if not solve_small(kk, res, dq, wsol):
        return False
    for k in range(5):
        if not math.isfinite(dq[k]):
            return False
    return True


@njit(cache=True, error_model="numpy")
def solve_ring(rows, loads, omega, control, qv, lam_state, xb, kmat, ballout, tol_ball, tol_ring,
               maxit_ball, maxit_ring, load_scale):
    """Newton–Raphson on the five inner-ring displacements ([S0] eq. 13).

    The Jacobian is the assembled stiffness (implicit differentiation of every ball's
    balance), so each Newton step costs one pass over the balls.  A backtracking line
    search on the scaled residual keeps it safe when balls lose contact.

    Returns (status, iterations, residual_norm, ball_converged):
    status 0 converged; 1 max iterations; 2 singular stiffness (the load cannot be
    carried, e.g. an axial load pulling one angular contact row apart); 3 equilibrium
    found only with a loaded contact past the groove bottom of an angular contact row
    (:func:`contact_beyond_groove_bottom`), outside the model; 6 equilibrium found only with a
    loaded contact at |α| ≥ 90° (:func:`contact_past_groove_edge`), outside either ring.  A singular
    Jacobian gets a damped step (:func:`regularised_step`); none of these raise.
    """
    res = np.empty(5)
    res_try = np.empty(5)
    q_try = np.empty(5)
    k_try = np.empty((5, 5))
    dq = np.empty(5)
    kk = np.empty((5, 5))
    wsol = np.empty((5, 6))
    xb_save = xb.copy()
    # moments scaled by the pitch radius so that all residual entries are forces
    dm = rows[0, P_DM]
    bconv, _ = ring_assemble(rows, qv, omega, control, lam_state, xb, loads, res, kmat, ballout,
                             tol_ball, maxit_ball)
    rn = _scaled_norm(res, dm)
    it = 0
    status = 1
    if rn <= tol_ring * load_scale:
        # the start is already an equilibrium: it gets the same validity check as any other
        if contact_beyond_groove_bottom(rows, ballout):
            return 3, 0, rn, bconv
        if contact_past_groove_edge(rows, ballout):
            return 6, 0, rn, bconv
        return 0, 0, rn, bconv
    # displacement scale for step limiting: a fraction of the groove-centre distance
    amax = 0.0
    for r in range(rows.shape[0]):
        amax = max(amax, rows[r, P_RI] + rows[r, P_RO])
    for it in range(1, maxit_ring + 1):
        # Newton step K dq = res  (K = -dres/dq)
        for k in range(5):
            for m in range(5):
                kk[k, m] = kmat[k, m]
        # guard: regularise only exactly singular directions
        ok = True
        for k in range(5):
            if not (kk[k, k] > 0.0) or not math.isfinite(kk[k, k]):
                ok = False
        if not ok:
            # fall back to a small stiffness on empty diagonals so the step stays bounded
            diag_max = 0.0
            for k in range(5):
                if math.isfinite(kk[k, k]):
                    diag_max = max(diag_max, abs(kk[k, k]))
            if diag_max == 0.0:
                return 2, it, rn, bconv
            for k in range(5):
                if not (kk[k, k] > 0.0):
                    kk[k, k] = 1e-6 * diag_max * (1.0 if k < 3 else dm * dm / 4.0)
        if not solve_small(kk, res, dq, wsol):
            # singular Jacobian with positive diagonal: coupled directions without stiffness of their
            # own (a deep-groove bearing with clearance under radial load with one ball loaded: the
            # axial and tilt rows of that ball are proportional, the only stiffness there the
            # geometric term Q/(A + δ)).  Levenberg–Marquardt step (K + μ S) dq = res, μ small; the
            # residual has no component along such a direction at a symmetric state, so the step
            # stays there.  No equilibrium step at all → status 2, never an exception.
            if not regularised_step(kk, res, dq, wsol, dm, 1e-9):
                return 2, it, rn, bconv
        # step limit: translations ≤ 0.1 A, tilts ≤ 0.1 A / (d_m/2)
        smax = 0.0
        for k in range(5):
            sc = 1.0 if k < 3 else dm / 2.0
            smax = max(smax, abs(dq[k]) * sc)
        if smax > 0.1 * amax:
            for k in range(5):
                dq[k] *= 0.1 * amax / smax
        lam = 1.0
        accepted = False
        for _ in range(40):
            for k in range(5):
                q_try[k] = qv[k] + lam * dq[k]
            xb[:, :, :] = xb_save
            bconv, _ = ring_assemble(rows, q_try, omega, control, lam_state, xb, loads, res_try, k_try,
                                     ballout, tol_ball, maxit_ball)
            rt = _scaled_norm(res_try, dm)
            if rt < rn or rt <= tol_ring * load_scale:
                accepted = True
                break
            lam *= 0.5
        if not accepted:
            xb[:, :, :] = xb_save
            bconv, _ = ring_assemble(rows, qv, omega, control, lam_state, xb, loads, res, kmat, ballout,
                                     tol_ball, maxit_ball)
            return 1, it, rn, bconv
        for k in range(5):
            qv[k] = q_try[k]
            res[k] = res_try[k]
            for m in range(5):
                kmat[k, m] = k_try[k, m]
        xb_save[:, :, :] = xb
        step = 0.0
        for k in range(5):
            sc = 1.0 if k < 3 else dm / 2.0
            step = max(step, abs(lam * dq[k]) * sc)
        rn = rt
        if rn <= tol_ring * load_scale or (step <= 1e-13 * amax and rn <= 1e3 * tol_ring * load_scale):
            status = 0
            break
    if status == 0 and contact_beyond_groove_bottom(rows, ballout):
        return 3, it, rn, bconv
    if status == 0 and contact_past_groove_edge(rows, ballout):
        return 6, it, rn, bconv
    return status, it, rn, bconv


@njit(cache=True, error_model="numpy")
def contact_beyond_groove_bottom(rows, ballout):
    """True when a ball loaded by the inner ring of an angular contact row has a negative contact angle.

    An angular contact ring has a low shoulder on that side of the groove bottom; the
    torus model would let the contact run past it, which is outside the model.
    """
    for r in range(rows.shape[0]):
        if rows[r, P_DX0] <= 0.0:  # deep groove: both sides of the groove bottom exist
            continue
        for j in range(int(rows[r, P_Z])):
            bo = ballout[r, j]
            if bo[2] > 0.0 and (bo[8] < 0.0 or bo[10] < 0.0):
                return True
    return False


@njit(cache=True, error_model="numpy")
def contact_past_groove_edge(rows, ballout):
    """True when a loaded contact (inner or outer, any row) has |α| ≥ 90°: the contact point would lie at
    or beyond the height of its groove-curvature centre, which is outside either ring (the lands and
    shoulders of both rings lie below it), so the torus model has left the raceway."""
    for r in range(rows.shape[0]):
        for j in range(int(rows[r, P_Z])):
            bo = ballout[r, j]
            if (bo[2] > 0.0 and not (bo[9] > 0.0)) or (bo[3] > 0.0 and not (bo[11] > 0.0)):
                return True
    return False


@njit(cache=True, error_model="numpy")
def planar_radial_displacement(par, fr, psi_f):
    """Radial displacement δr [m] of a rigid inner ring of one deep-groove row under a radial load fr [N]
    in the direction ψ_F, balls in the plane (zero contact angle):

        F_r = Σ_j K_n (δr cos(ψ_j − ψ_F) − P_d/2)₊^1.5 cos(ψ_j − ψ_F)

    (Harris & Kotzalas 2007 vol. 1 §7.3, eqs. 7.21–7.25 written ball by ball), solved by bisection
    (the sum is increasing in δr).  P_d/2 = (r_i + r_o) − ΔR₀ is the radial play per side [m].
    Returns NaN when fr ≤ 0.
    """
    if not (fr > 0.0):
        return math.nan
    z = int(par[P_Z])
    kn_ = series_constant(par[P_KI], par[P_KO])
    h = par[P_RI] + par[P_RO] - par[P_DR0]
    cmax = 0.0
    for j in range(z):
        c = math.cos(par[P_PSI0] + 2.0 * math.pi * j / z - psi_f)
        if c > cmax:
            cmax = c
    lo = 0.0
    hi = (max(h, 0.0) + (fr / (kn_ * cmax)) ** (2.0 / 3.0)) / cmax
    for _ in range(200):
        f = -fr
        for j in range(z):
            c = math.cos(par[P_PSI0] + 2.0 * math.pi * j / z - psi_f)
            d = hi * c - h
            if d > 0.0:
                f += kn_ * d * math.sqrt(d) * c
        if f >= 0.0:
            break
        lo = hi
        hi *= 2.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if not (lo < mid < hi):
            break
        f = -fr
        for j in range(z):
            c = math.cos(par[P_PSI0] + 2.0 * math.pi * j / z - psi_f)
            d = mid * c - h
            if d > 0.0:
                f += kn_ * d * math.sqrt(d) * c
        if f < 0.0:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


@njit(cache=True, error_model="numpy")
def planar_radial_start(rows, loads, qv):
    """Start of the ring Newton for a single deep-groove row under a load with a radial part: the rigid-ring
    planar solution of :func:`planar_radial_displacement` for (q_y, q_z), so that the balls that carry the
    load are in contact from the first iterate (a start inside the clearance has no ball loaded, hence no
    stiffness).  qv[0], qv[3], qv[4] are left as they are.  Returns False (qv untouched) when it does not
    apply (several rows, an angular contact row, no radial load)."""
    if rows.shape[0] != 1 or rows[0, P_DX0] != 0.0:
        return False
    fr = math.hypot(loads[1], loads[2])
    if not (fr > 0.0) or not math.isfinite(fr):
        return False
    psi_f = math.atan2(loads[2], loads[1])
    dr = planar_radial_displacement(rows[0], fr, psi_f)
    if not math.isfinite(dr):
        return False
    qv[1] = dr * loads[1] / fr
    qv[2] = dr * loads[2] / fr
    return True


@njit(cache=True, error_model="numpy")
def equilibrium_residual(rows, loads, omega, control, qv, tol_ball, maxit_ball):
    """Independent check of a ring equilibrium: every ball re-solved from its own cold start (no warm start,
    raceway control from the control's default) at the ring displacement qv, the ring forces summed.
    Returns (scaled residual max |res_k| w_k [N] as :func:`_scaled_norm`, every ball converged)."""
    nrow = rows.shape[0]
    zmax = 0
    for r in range(nrow):
        zmax = max(zmax, int(rows[r, P_Z]))
    lam = np.full((nrow, zmax), 1 if control == CONTROL_INNER else 0, dtype=np.int64)
    xb = np.zeros((nrow, zmax, 2))
    res = np.empty(5)
    kmat = np.empty((5, 5))
    ballout = np.zeros((nrow, zmax, 12))
    bconv, _ = ring_assemble(rows, qv, omega, control, lam, xb, loads, res, kmat, ballout, tol_ball, maxit_ball)
    return _scaled_norm(res, rows[0, P_DM]), bconv


@njit(cache=True, error_model="numpy")
def azimuth_table(rows, trig):
    """trig[r, j] ← (cos ψ_j, sin ψ_j), ψ_j = ψ₀ + 2π j / Z: the ball azimuths of every row, computed
    once per batch instead of once per ball evaluation (same expression as :func:`ring_assemble`)."""
    for r in range(rows.shape[0]):
        par = rows[r]
        z = int(par[P_Z])
        for j in range(z):
            psi = par[P_PSI0] + 2.0 * math.pi * j / z
            trig[r, j, 0] = math.cos(psi)
            trig[r, j, 1] = math.sin(psi)


@njit(cache=True, error_model="numpy")
def ring_assemble_coupled(rows, qv, omega, lam_state, xb, loads, res, resc, kmat, ballout, tol, maxit, out, jac,
                          dfa, xl, ta1, ta2, gw, trig):
    """One Newton pass on the coupled ring–ball system (q and every ball's X₁, X₂): one ball evaluation each.

    :func:`ring_assemble` solves every ball's balance R(X, A) = 0 to convergence at each trial ring
    position.  Here each ball is evaluated once, at its tangent prediction X* = X + (dX/dA) ΔA (xb
    columns 2–7), and its force on the ring is also given corrected to first order for the ball
    residual left at X* (static condensation of the ball unknowns):

        F_c = F(X*) − ∂F/∂X (∂R/∂X)⁻¹ R(X*),    X ← X* − (∂R/∂X)⁻¹ R(X*),

    so that a ring step K⁻¹ res_c with the condensed stiffness K (the same as :func:`ring_assemble`'s,
    :func:`ball_total_derivative`) is Newton's step on all unknowns together (Harris & Kotzalas 2007
    vol. 2 §3 equations, solved as one system).  Balls without both contacts loaded, or with a
    singular 2x2 balance, are solved in full by :func:`ball_solve` instead.

    res ← loads + ball forces at X* (the true residual of the current iterate); resc ← the same
    with the condensed forces; kmat ← stiffness; ballout ← per-ball table at X* (as ring_assemble).
    Returns True when every ball meets the ball tolerance at X* (|R| ≤ tol (F_c + 1) [N] or a Newton
    correction ≤ tol D, the criteria of :func:`ball_solve`).  ``xb`` float[nrow, zmax, 8] is updated
    to the corrected positions and their tangents; ``omega`` > 0 and ``lam_state`` fixed (outer or
    inner control).  out, jac, dfa, xl, ta1, ta2, gw: workspaces (float[10], [5,4], [3,2], [2], [5]x3);
    trig : float[nrow, zmax, 2] cos ψ_j, sin ψ_j of the ball azimuths (:func:`azimuth_table`).
    """
    nrow = rows.shape[0]
    for k in range(5):
        res[k] = loads[k]
        resc[k] = loads[k]
        for m in range(5):
            kmat[k, m] = 0.0
    w2 = omega * omega
    allconv = True
    for r in range(nrow):
        par = rows[r]
        z = int(par[P_Z])
        s = par[P_SIGN]
        ric = par[P_RIC]
        xg = inner_groove_centre_axial(par)
        d = par[P_D]
        dm = par[P_DM]
        cg, cf = ball_speed_constants(par, w2)
        ri = par[P_RI]
        ro = par[P_RO]
        ki = par[P_KI]
        ko = par[P_KO]
        gri = par[P_GRI]
        gam = d / dm
        for j in range(z):
            cp = trig[r, j, 0]
            sp = trig[r, j, 1]
            a1, a2 = _groove_offsets(par, s, ric, xg, cp, sp, qv, ta1, ta2, gw)
            xbr = xb[r, j]
            da1 = a1 - xbr[2]
            da2 = a2 - xbr[3]
            xl[0] = xbr[0] + xbr[4] * da1 + xbr[5] * da2
            xl[1] = xbr[1] + xbr[6] * da1 + xbr[7] * da2
            inner_ctrl = lam_state[r, j]
            lam_i, lam_o = control_weights(inner_ctrl)
            single = False
            det = 0.0
            if xl[0] * xl[0] + xl[1] * xl[1] > ro * ro:
                ball_eval(xl[0], xl[1], a1, a2, ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, out, jac,
                          par[P_OROT])
                det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
                single = out[4] > 0.0 and out[5] > 0.0 and det != 0.0 and math.isfinite(det)
            e0 = 0.0
            e1 = 0.0
            if single:
                e0 = (jac[1, 1] * out[0] - jac[0, 1] * out[1]) / det
                e1 = (-jac[1, 0] * out[0] + jac[0, 0] * out[1]) / det
                if not (math.hypot(out[0], out[1]) <= tol * (cf + 1.0) or math.hypot(e0, e1) <= tol * d):
                    allconv = False
            else:
                conv, _its = ball_solve(a1, a2, par, cg, cf, lam_i, lam_o, inner_ctrl, xl, out, jac, tol, maxit)
                if not conv:
                    allconv = False
                det = jac[0, 0] * jac[1, 1] - jac[0, 1] * jac[1, 0]
            fx = out[2]
            fr = out[3]
            g = out[8]
            fxc = fx - (jac[2, 0] * e0 + jac[2, 1] * e1)
            frc = fr - (jac[3, 0] * e0 + jac[3, 1] * e1)
            gc = g - (jac[4, 0] * e0 + jac[4, 1] * e1)
            mg = lam_i * gri
            for k in range(5):
                res[k] -= fx * ta1[k] + fr * ta2[k] - mg * g * gw[k]
                resc[k] -= fxc * ta1[k] + frc * ta2[k] - mg * gc * gw[k]
            okdet = det != 0.0 and math.isfinite(det)
            if (out[4] > 0.0 or out[5] > 0.0) and okdet:
                ball_total_derivative(jac, dfa)
                for k in range(5):
                    dfxq = dfa[0, 0] * ta1[k] + dfa[0, 1] * ta2[k]
                    dfrq = dfa[1, 0] * ta1[k] + dfa[1, 1] * ta2[k]
                    dgq = mg * (dfa[2, 0] * ta1[k] + dfa[2, 1] * ta2[k])
                    for m in range(5):
                        kmat[m, k] += ta1[m] * dfxq + ta2[m] * dfrq - gw[m] * dgq
            _ball_row_out(ballout[r, j], a1, a2, xl, out, g)
            xbr[0] = xl[0] - e0
            xbr[1] = xl[1] - e1
            xbr[2] = a1
            xbr[3] = a2
            if okdet:
                xbr[4] = -(jac[1, 1] * jac[0, 2] - jac[0, 1] * jac[1, 2]) / det
                xbr[5] = -(jac[1, 1] * jac[0, 3] - jac[0, 1] * jac[1, 3]) / det
                xbr[6] = -(-jac[1, 0] * jac[0, 2] + jac[0, 0] * jac[1, 2]) / det
                xbr[7] = -(-jac[1, 0] * jac[0, 3] + jac[0, 0] * jac[1, 3]) / det
            else:
                xbr[4] = 0.0
                xbr[5] = 0.0
                xbr[6] = 0.0
                xbr[7] = 0.0
    return allconv


@njit(cache=True, error_model="numpy")
def _scaled_norm(res, dm):
    """max |res_k| w_k with w = (1, 1, 1, 2/d_m, 2/d_m) [N]; NaN when any entry is NaN (a failed ball
    evaluation must never look like a small residual: ``max(rn, nan)`` would silently drop it)."""
    rn = 0.0
    for k in range(5):
        v = abs(res[k]) * (1.0 if k < 3 else 2.0 / dm)
        if v > rn or v != v:
            rn = v
    return rn




#: trials of the coupled step (full, then halved) before handing over to solve_ring
NLS = 4


@njit(cache=True, error_model="numpy")
def solve_ring_coupled(rows, loads, omega, control, qv, lam_state, xb, kmat, ballout, tol_ball, tol_ring,
                       maxit_ball, maxit_ring, load_scale, xs, wk, wk2, trig):
    """Ring equilibrium by Newton on the coupled ring–ball system, :func:`solve_ring` as the safeguard.

    Used when ``omega`` > 0 and the raceway control is outer control (inner and auto control change a ball's
    control when its inner contact opens: :func:`solve_ring`; at rest the ball solve is closed form and
    :func:`solve_ring` is used).  Each coupled step K⁻¹ res_c is limited as in
    :func:`solve_ring` and halved up to NLS − 1 times until the condensed residual decreases; when it
    does not, the point continues with :func:`solve_ring` from the last accepted state.  A point is
    converged when, at the current iterate, every ball meets the ball tolerance and the ring residual
    (uncondensed) meets the ring tolerance — the criteria of :func:`solve_ring` — and then gets the
    groove-bottom check, so the status codes keep their meaning (0, 1, 2, 3).  Same equations
    (module docstring; [S0] eqs. 6–13), fewer ball evaluations: one per ball and iteration.
    xs : float[nrow, zmax, 8] workspace (saved ball state); wk : float[≥ 47]; wk2 : float[≥ 81] workspaces;
    trig : float[nrow, zmax, 2] from :func:`azimuth_table`.
    Returns (status, iterations, residual, ball_converged) as :func:`solve_ring`.
    """
    if omega == 0.0 or control != CONTROL_OUTER or xb.shape[2] < 8:
        # inner and auto control change a ball's control when its inner contact opens (ring_assemble):
        # the coupled step assumes a fixed control, so those go to the safeguarded solver
        return solve_ring(rows, loads, omega, control, qv, lam_state, xb, kmat, ballout, tol_ball, tol_ring,
                          maxit_ball, maxit_ring, load_scale)
    res = wk[0:5]
    resc = wk[5:10]
    dq = wk[10:15]
    qs = wk[15:20]
    out = wk[20:30]
    xl = wk[30:32]
    ta1 = wk[32:37]
    ta2 = wk[37:42]
    gw = wk[42:47]
    kk = wk2[0:25].reshape((5, 5))
    jac = wk2[25:45].reshape((5, 4))
    dfa = wk2[45:51].reshape((3, 2))
    wsol = wk2[51:81].reshape((5, 6))
    dm = rows[0, P_DM]
    amax = 0.0
    for r in range(rows.shape[0]):
        amax = max(amax, rows[r, P_RI] + rows[r, P_RO])
    bconv = ring_assemble_coupled(rows, qv, omega, lam_state, xb, loads, res, resc, kmat, ballout, tol_ball,
                                  maxit_ball, out, jac, dfa, xl, ta1, ta2, gw, trig)
    rn = _scaled_norm(res, dm)
    rc = _scaled_norm(resc, dm)
    it = 0
    while True:
        if bconv and rn <= tol_ring * load_scale:
            if contact_beyond_groove_bottom(rows, ballout):
                return 3, it, rn, bconv
            if contact_past_groove_edge(rows, ballout):
                return 6, it, rn, bconv
            return 0, it, rn, bconv
        if it >= maxit_ring:
            break
        ok = True
        for k in range(5):
            if not (kmat[k, k] > 0.0) or not math.isfinite(kmat[k, k]):
                ok = False
        if not ok or not solve_small(kmat, resc, dq, wsol):
            break
        smax = 0.0
        for k in range(5):
            smax = max(smax, abs(dq[k]) * (1.0 if k < 3 else dm / 2.0))
        if smax > 0.1 * amax:
            # the step limit of solve_ring
            for k in range(5):
                dq[k] *= 0.1 * amax / smax
        for k in range(5):
            qs[k] = qv[k]
        xs[:, :, :] = xb
        lam = 1.0
        accepted = False
        for _ls in range(NLS):
            for k in range(5):
                qv[k] = qs[k] + lam * dq[k]
            bc = ring_assemble_coupled(rows, qv, omega, lam_state, xb, loads, res, resc, kk, ballout, tol_ball,
                                       maxit_ball, out, jac, dfa, xl, ta1, ta2, gw, trig)
            rnt = _scaled_norm(res, dm)
            rct = _scaled_norm(resc, dm)
            if rct < rc or (bc and rnt <= tol_ring * load_scale):
                accepted = True
                break
            lam *= 0.5
            xb[:, :, :] = xs
        if not accepted:
            # no progress: back to the last accepted state, finish with the safeguarded solver
            for k in range(5):
                qv[k] = qs[k]
            break
        it += 1
        bconv = bc
        rn = rnt
        rc = rct
        for k in range(5):
            for m in range(5):
                kmat[k, m] = kk[k, m]
    st, it2, rn2, bc2 = solve_ring(rows, loads, omega, control, qv, lam_state, xb, kmat, ballout, tol_ball,
                                   tol_ring, maxit_ball, maxit_ring, load_scale)
    return st, it + it2, rn2, bc2
