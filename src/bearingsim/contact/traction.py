"""Traction coefficient and rolling viscous resistance of a lubricated ball–raceway contact.

Models (one function each, numba kernels + Python wrappers that check input):

* :func:`four_parameter` — μ(s) = (A + B s) e^(−C s) + D, the curve used by dynamic
  bearing codes (Gupta, *Advanced Dynamics of Rolling Elements*, 1984); :func:`fit_four_parameter`
  finds A, B, C, D from μ₀ = μ(0), the peak μ_max at s_max and μ_∞ = μ(∞) in closed form
  (D = μ_∞, A = μ₀ − μ_∞, dμ/ds(s_max) = 0 ⇒ B = C A/(1 − C s_max), and one scalar
  equation A e^(−t)/(1 − t) = μ_max − μ_∞ for t = C s_max, solved by bisection).
* Boundary lubrication: the same four-parameter form with its own constants, a
  function of the slide–roll ratio only ([S1], section 3.1).  The default
  constants (μ₀ = 0, peak 0.12 at s = 0.01, μ_∞ = 0.10) are typical of boundary
  lubricated steel and were chosen here, not taken from a source.
* Fluid film, physically based (:func:`fluid_shear_stress`): Eyring shear thinning
  τ_v = τ₀ asinh(η γ̇/τ₀) capped smoothly by the limiting shear stress,
  τ = τ_L tanh(τ_v/τ_L) (the Bair–Winer limiting-shear-stress idea, Zhou & Hoeprich
  1991 eq. 35, in its steady form), with γ̇ = sliding speed / central film,
  η(p) from Roelands (1966), and τ_L = r_L [c₁ p /(c₂ + c₃ t) − c₄] — Dyson's formula for
  the limiting elastic shear modulus with τ_L = 0.25 G_∞ (Zhou & Hoeprich 1991 eqs. 36–37:
  G_∞ = 1.2 P/(2.52 + 0.024 t) − 10⁸, P [Pa], t [°C]), floored at
  ``lss_floor`` · p.  Shear heating raises the film temperature by
  ΔT = τ u_s [h/(12 k) + ½ · (4/(3√π)) √(t_c)/e_s] (mean Couette heating of the film
  conducted to both walls, plus the mean flash temperature of a half-space under a
  uniform flux for the transit time t_c = 2b/u, half the heat to each body;
  Carslaw & Jaeger 1959, §2.9), which lowers η by exp(−β ΔT) and τ_L through t.  The
  implicit heat balance τ = f(ΔT(τ)) is solved approximately by one secant step from
  τ = 0 and τ = f(0): τ ≈ τ₀²/(2τ₀ − τ₁), τ₀ = f(0), τ₁ = f(θ u_s τ₀) (exact when f is linear
  in τ over that interval; always between τ₁ and τ₀).
  μ_f = τ / p̄.
* Film elasticity (:func:`elastic_plastic_mean_stress`, option ``viscoelastic``, on by default):
  the steady law above is the viscous branch of the Maxwell film γ̇ = τ̇/G + F(τ)/η
  (Johnson & Tevaarwerk 1977, Proc. R. Soc. Lond. A 356:215, their constitutive equation;
  Zhou & Hoeprich 1991 eq. 35).  A film element crosses the contact in the transit time t_c = ℓ/u, and at high
  pressure (Deborah number η u/(G ℓ) ≫ 1) it never reaches the viscous stress: its stress
  grows elastically, τ = G γ̇ t, until it meets the viscous (yield) stress τ_y.  In this
  elastic/plastic limit (one of the regimes Johnson & Tevaarwerk identify) the mean over
  the transit, with τ_e = G γ̇ t_c = G s ℓ/h the stress reached elastically at the exit, is
      τ̄ = τ_e/2                    for τ_e ≤ τ_y,
      τ̄ = τ_y (1 − τ_y/(2 τ_e))     for τ_e > τ_y,
  continuous with its slope at τ_e = τ_y; it tends to τ_y when the film is viscous (τ_e ≫ τ_y)
  and to the linear elastic traction τ̄ = G s ℓ/(2h) at small slide–roll ratio s.  G is the
  limiting elastic shear modulus of Dyson's formula (the same G_∞ whose quarter is τ_L, i.e.
  G = τ_L/r_L at the inlet temperature), ℓ the contact length in the rolling direction.  Without
  it the initial slope of μ(s) is η(p) u/(h p̄), with a Roelands viscosity of 10¹⁰–10¹⁷ Pa·s at
  1–2 GPa: a Coulomb-like jump that is neither measured nor integrable at a useful step size.
* Mixed lubrication ([S1], ref. 8): μ = μ_b + (μ_f − μ_b) w(Λ), w = 0 for Λ ≤ Λ₁,
  1 for Λ ≥ Λ₂, linear in between (default Λ₁ = 1, Λ₂ = 3; the paper says only
  "proportionally to the film parameter"; the limits are our choice).
* Rolling viscous resistance ([S1] eq. 4): Zhou & Hoeprich (1991), J. Tribol. 113:590,
  eqs. 17, 21–23 for a line contact of length L (here one slice of the ellipse):
  F_R = φ_s φ_T 29.2 (R/α) L (G U)^0.648 W^0.246, W = w/(E′R), w = load per unit length.
  This is their fit of isothermal piezoviscous-elastic (PE) solutions; it is used in PE
  and, as a stand-in for which no formula was confirmed, in PR and IE.  In IR we use the
  closed form of the rigid isoviscous (Martin) line contact with Reynolds' exit
  condition, derived here:  F_R/L = 6 η u √(2R/h₀) · ½[(1 − ξ_e²)(π/2 + atan ξ_e) − ξ_e],
  ξ_e = 0.475130, h₀ = 4.89497 η u R/w, i.e. F_R/L = 2.0796 √(η u w)  (checked against a
  numerical Reynolds solution in tests/unit/test_traction.py).
* Oil-film force ([S1] eq. 5): the pressure-centre shift gives each body a
  tangential pressure force P_x,i with P_x,i R_i = 2 F_R R_x (Zhou & Hoeprich 1991, text
  after eq. 5: N e = P_x R_e = P_x,1 R_1 = P_x,2 R_2 = 2 F_r0 R_e), acting through that
  body's centre of curvature, in the rolling direction.

* Small-slip slope (creep; :func:`creep_slope`): at s → 0 the tangential force of a rolling contact is
  linear in the slide–roll ratio, F = K s, through two compliances in series ([J&T 1977] fit the linear
  region of their measured curves only after the solids' compliance is removed, and note it is comparable
  with the film's):
    - the film: the elastic limit of the Maxwell film above, τ̄ = G_f s ℓ/(2h) over the contact area πab
      (ℓ = 2 × the semi-axis in the rolling direction), K_f = G_f ℓ π a b/(2h);
    - the solids: Kalker's linear theory of rolling contact (Kalker 1967, thesis, Delft; Kalker 1990,
      *Three-dimensional elastic bodies in rolling contact*, Kluwer, §3): F = G c² C₁₁ ξ with c² = a b, G the
      combined shear modulus 2/G = 1/G₁ + 1/G₂ and C₁₁(a/b, ν) the longitudinal creep coefficient of his
      table (:data:`KALKER_C11`; a the semi-axis in the rolling direction, b across it — in a ball bearing a
      is the Hertz *minor* semi-axis), K_s = G a b C₁₁;
    1/K = 1/K_f + 1/K_s, dμ/ds = K/Q.  Either compliance → 0 recovers the other.

Units: stresses and pressures [Pa], speeds [m/s], lengths [m], temperatures [K] (°C only
inside Dyson's formula), viscosity [Pa·s].
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..errors import InputError

#: Martin rigid-isoviscous line contact constants (Reynolds exit condition)
MARTIN_XI_EXIT = 0.47512992  # numerical root, tests/unit/test_traction.py
MARTIN_LOAD = 4.894968  # w = MARTIN_LOAD * eta * u * R / h0, u = mean speed (u1+u2)/2


def _martin_rolling_constant() -> float:
    xe = MARTIN_XI_EXIT
    integral = 0.5 * ((1.0 - xe * xe) * (0.5 * math.pi + math.atan(xe)) - xe)
    return 6.0 * integral * math.sqrt(2.0 / MARTIN_LOAD)


#: F_R/L = MARTIN_ROLLING * sqrt(eta u w) in the IR regime
MARTIN_ROLLING = _martin_rolling_constant()


@njit(cache=True, error_model="numpy")
def four_parameter(s, A, B, C, D):
    """μ(s) = (A + B|s|) e^(−C|s|) + D  [-]  (Gupta 1984 form)."""
    s = abs(s)
    return (A + B * s) * math.exp(-C * s) + D


@njit(cache=True, error_model="numpy")
def mixed_weight(lam, lam1, lam2):
    """Weight of the fluid coefficient, w(Λ) ∈ [0, 1], linear between Λ₁ and Λ₂."""
    if lam <= lam1:
        return 0.0
    if lam >= lam2:
        return 1.0
    return (lam - lam1) / (lam2 - lam1)


@njit(cache=True, error_model="numpy")
def roelands_viscosity(p, eta0, ln_eta0_plus, z):
    """Roelands (1966): η = η₀ exp[(ln η₀ + 9.67)((1 + p/1.96e8)^z − 1)]  [Pa·s].

    ln_eta0_plus = ln η₀ + 9.67 (η₀ in Pa·s), z the Roelands index.
    """
    if p <= 0.0:
        return eta0
    return eta0 * math.exp(ln_eta0_plus * ((1.0 + p / 1.96e8) ** z - 1.0))


@njit(cache=True, error_model="numpy")
def limiting_shear_stress(p, t_celsius, r_l, c1, c2, c3, c4, floor):
    """τ_L = max(r_L [c₁ p/(c₂ + c₃ t) − c₄], floor·p)  [Pa]; Dyson via Zhou & Hoeprich eqs. 36–37."""
    tl = r_l * (c1 * p / (c2 + c3 * t_celsius) - c4)
    fl = floor * p
    return tl if tl > fl else fl


@njit(cache=True, error_model="numpy")
def _stress_at(dT, eta_p, gdot, tau0, p, t0c, r_l, c1, c2, c3, c4, floor, beta_v):
    eta = eta_p * math.exp(-beta_v * dT)
    tl = limiting_shear_stress(p, t0c + dT, r_l, c1, c2, c3, c4, floor)
    tv = tau0 * math.asinh(eta * gdot / tau0)
    return tl * math.tanh(tv / tl)


@njit(cache=True, error_model="numpy")
def fluid_shear_stress(p, u_s, h, theta, eta_p, tau0, t0c, r_l, c1, c2, c3, c4, floor, beta_v):
    """Mean fluid shear stress τ [Pa] of an EHL film (see module docstring).

    p [Pa] mean pressure; u_s [m/s] sliding speed (≥ 0); h [m] film; theta [K·m²/W] heat
    balance factor (ΔT = theta τ u_s); eta_p [Pa·s] viscosity at p and the inlet
    temperature; tau0 [Pa] Eyring stress; t0c [°C] inlet temperature; r_l, c1..c4, floor:
    limiting shear stress law; beta_v [1/K] temperature–viscosity coefficient.
    """
    if u_s <= 0.0 or p <= 0.0 or h <= 0.0:
        return 0.0
    gdot = u_s / h
    tau = _stress_at(0.0, eta_p, gdot, tau0, p, t0c, r_l, c1, c2, c3, c4, floor, beta_v)
    if theta <= 0.0:
        return tau
    tau1 = _stress_at(theta * tau * u_s, eta_p, gdot, tau0, p, t0c, r_l, c1, c2, c3, c4, floor, beta_v)
    # secant (regula falsi) step on g(τ) = f(θ u_s τ) − τ between τ = 0 and τ = f(0)
    return tau * tau / (2.0 * tau - tau1)


@njit(cache=True, error_model="numpy")
def elastic_plastic_mean_stress(tau_y, tau_e):
    """Mean shear stress over the transit of an elastic–perfectly-plastic EHL film [Pa].

    Johnson & Tevaarwerk (1977), elastic/plastic limit of the Maxwell film: the stress grows as
    G γ̇ t and is capped at the yield (viscous) stress τ_y [Pa]; τ_e = G γ̇ t_c [Pa] is the stress
    reached elastically at the exit.  τ̄ = τ_e/2 (τ_e ≤ τ_y), τ_y(1 − τ_y/(2τ_e)) otherwise.
    """
    if tau_e <= tau_y:
        return 0.5 * tau_e
    return tau_y * (1.0 - 0.5 * tau_y / tau_e)


@njit(cache=True, error_model="numpy")
def rolling_resistance_zh(U, G, w_dimless, rx, alpha, length):
    """F_R = 29.2 (R/α) L (G U)^0.648 W^0.246  [N]  (Zhou & Hoeprich 1991 eq. 17/43, isothermal)."""
    if U <= 0.0 or w_dimless <= 0.0:
        return 0.0
    return 29.2 * (rx / alpha) * length * (G * U) ** 0.648 * w_dimless**0.246


@njit(cache=True, error_model="numpy")
def rolling_resistance_ir(eta0, u, w_line, length):
    """Rigid isoviscous (Martin) line contact rolling resistance F_R = 2.0796 L √(η u w)  [N]."""
    if u <= 0.0 or w_line <= 0.0:
        return 0.0
    return MARTIN_ROLLING * length * math.sqrt(eta0 * u * w_line)


# --------------------------------------------------------------------------- creep (small slip)
#: Kalker's longitudinal creep coefficient C₁₁ (Kalker 1967 thesis, table of the linear theory; Kalker 1990,
#: *Three-dimensional elastic bodies in rolling contact*, Table E.3).  Checked entry by entry (all 19 rows × 3 ν)
#: against Table E.3 as reproduced in the CONTACT code of Vollebregt & Kalker (github.com/eve70a/CONTACT,
#: src/m_hertz.f90, subroutine linrol; tests/validation/test_kalker_table.py): no value differed.  Rows: the
#: ellipse's semi-axis ratio g, first a/b = 0.1 … 1 (a along the rolling direction shorter: ball bearings),
#: then b/a = 0.9 … 0.1; columns ν = 0, 0.25, 0.5.  The limit a/b → 0 is π²/(4(1 − ν)) (Kalker; the strip of
#: Carter's 2-D theory).
KALKER_NU = (0.0, 0.25, 0.5)
KALKER_C11_A_OVER_B = {  # a/b: (ν = 0, 0.25, 0.5)
    0.1: (2.51, 3.31, 4.85), 0.2: (2.59, 3.37, 4.81), 0.3: (2.68, 3.44, 4.80), 0.4: (2.78, 3.53, 4.82),
    0.5: (2.88, 3.62, 4.83), 0.6: (2.98, 3.72, 4.91), 0.7: (3.09, 3.81, 4.97), 0.8: (3.19, 3.91, 5.05),
    0.9: (3.29, 4.01, 5.12), 1.0: (3.40, 4.12, 5.20)}
KALKER_C11_B_OVER_A = {  # b/a: (ν = 0, 0.25, 0.5)
    0.9: (3.51, 4.22, 5.30), 0.8: (3.65, 4.36, 5.42), 0.7: (3.82, 4.54, 5.58), 0.6: (4.06, 4.78, 5.80),
    0.5: (4.37, 5.10, 6.11), 0.4: (4.84, 5.57, 6.57), 0.3: (5.57, 6.34, 7.34), 0.2: (6.96, 7.78, 8.82),
    0.1: (10.7, 11.7, 12.9)}


def _c11_grid() -> tuple[np.ndarray, np.ndarray]:
    """(x, C₁₁[x, ν]) on x = log(a/b): the a/b → 0 limit, the a/b rows and the b/a rows of the table."""
    xs = [math.log(0.01)]
    vals = [[math.pi**2 / (4.0 * (1.0 - nu)) for nu in KALKER_NU]]  # a/b → 0 (reached within 1 % at 0.1)
    for g in sorted(KALKER_C11_A_OVER_B):
        xs.append(math.log(g))
        vals.append(list(KALKER_C11_A_OVER_B[g]))
    for g in sorted(KALKER_C11_B_OVER_A, reverse=True):
        xs.append(math.log(1.0 / g))
        vals.append(list(KALKER_C11_B_OVER_A[g]))
    return np.array(xs), np.array(vals)


def kalker_c11(a_roll: float, b_lat: float, poisson: float) -> float:
    """Kalker's longitudinal creep coefficient C₁₁ [-] of an elliptic contact with semi-axis ``a_roll`` [m] in
    the rolling direction and ``b_lat`` [m] across it, Poisson ratio ν ∈ [0, 0.5].

    Linear interpolation of :data:`KALKER_C11_A_OVER_B` / :data:`KALKER_C11_B_OVER_A` in log(a/b) (between
    table rows the coefficient varies by < 4 %, so the interpolation error is well below that); below a/b = 0.1
    towards the strip limit π²/(4(1 − ν)) (taken at a/b = 0.01).  In ν: quadratic (Lagrange) interpolation of
    1/C₁₁ through the table's ν = 0, 0.25, 0.5 — exact in the strip limit, where 1/C₁₁ = 4(1 − ν)/π² is linear in
    ν (interpolating C₁₁ itself linearly is 2.6 % high there at ν = 0.3); the CONTACT code of Vollebregt & Kalker
    (``linrol``, github.com/eve70a/CONTACT, src/m_hertz.f90) interpolates the same way.  Valid 0.01 ≤ a/b ≤ 10.
    """
    for name, v in (("a_roll", a_roll), ("b_lat", b_lat)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(name, f"must be a positive length, got {v!r}", "give the contact semi-axis in m")
    if not (isinstance(poisson, (int, float)) and 0.0 <= poisson <= 0.5):
        raise InputError("poisson", f"must lie in [0, 0.5], got {poisson!r}", "e.g. 0.3 for steel")
    x = math.log(a_roll / b_lat)
    xs, vals = _c11_grid()
    if not (xs[0] - 1e-12 <= x <= xs[-1] + 1e-12):
        raise InputError("a_roll/b_lat", f"ratio {a_roll / b_lat:.3g} outside Kalker's table (0.01 … 10)",
                         "Kalker tabulates 0.1 ≤ a/b ≤ 10 (here extended to the strip limit at a/b = 0.01)")
    inv = [1.0 / float(np.interp(x, xs, vals[:, j])) for j in range(3)]
    n0, n1, n2 = KALKER_NU
    nu = poisson
    inv_c = (inv[0] * (nu - n1) * (nu - n2) / ((n0 - n1) * (n0 - n2))
             + inv[1] * (nu - n0) * (nu - n2) / ((n1 - n0) * (n1 - n2))
             + inv[2] * (nu - n0) * (nu - n1) / ((n2 - n0) * (n2 - n1)))
    return 1.0 / inv_c


def solid_creep_stiffness(a_roll: float, b_lat: float, shear_modulus: float, poisson: float) -> float:
    """K_s = G a b C₁₁ [N per unit slide–roll ratio]: Kalker's linear longitudinal creep force of the elastic
    solids, F = G a b C₁₁ s (Kalker 1990 eq. 3.5 form, c² = ab); G [Pa] the combined shear modulus."""
    if not (math.isfinite(shear_modulus) and shear_modulus > 0):
        raise InputError("shear_modulus", f"must be positive, got {shear_modulus!r}", "e.g. 79e9 Pa for steel")
    return shear_modulus * a_roll * b_lat * kalker_c11(a_roll, b_lat, poisson)


def film_creep_stiffness(a_roll: float, b_lat: float, film_modulus: float, film_thickness: float) -> float:
    """K_f = (8/3) G_f a_roll² b_lat / h [N per unit slide–roll ratio]: the small-slip limit of the
    elastic–plastic film of :func:`elastic_plastic_mean_stress` (Johnson & Tevaarwerk 1977, elastic regime of
    their Maxwell model) integrated over the Hertz ellipse as the sliced kernel does: a point at distance x from
    the leading edge carries τ = G_f s x/h, so a strip of chord ℓ(y) = 2 a_roll √(1 − y²/b_lat²) carries
    G_f s ℓ²/(2h) per unit width, and ∫ ℓ²/2 dy = (8/3) a_roll² b_lat.  (The uniform-chord form
    G_f ℓ π a b/(2h) with ℓ = 2 a_roll is larger by 3π/8 ≈ 1.18: it gives every strip the
    longest chord.)  ``film_modulus`` = inf: a rigid film (infinite stiffness)."""
    if not (film_modulus > 0):
        raise InputError("film_modulus", f"must be positive, got {film_modulus!r}", "e.g. 0.3e9 Pa, or inf")
    if math.isinf(film_modulus):
        return math.inf
    if not (math.isfinite(film_thickness) and film_thickness > 0):
        raise InputError("film_thickness", f"must be a positive length, got {film_thickness!r}",
                         "give the central film thickness in m (bearingsim.contact.ehl.film_thickness)")
    return 8.0 / 3.0 * film_modulus * a_roll * a_roll * b_lat / film_thickness


def series_stiffness(k_film: float, k_solid: float) -> float:
    """1/K = 1/K_f + 1/K_s [N per unit slip] (either may be inf: a rigid element)."""
    if not (k_film > 0 and k_solid > 0):
        raise InputError("creep stiffness", f"must be positive, got {k_film!r}, {k_solid!r}", "")
    if math.isinf(k_film):
        return k_solid
    if math.isinf(k_solid):
        return k_film
    return 1.0 / (1.0 / k_film + 1.0 / k_solid)


def creep_slope(load: float, a_roll: float, b_lat: float, shear_modulus: float, poisson: float,
                film_modulus: float = math.inf, film_thickness: float | None = None,
                solids: bool = True) -> float:
    """dμ/ds at s → 0 [1/slip] of a lubricated (or dry, film_modulus = inf) elliptic rolling contact.

    ``load`` Q [N]; ``a_roll``, ``b_lat`` the Hertz semi-axes along and across the rolling direction [m]
    (ball bearing: a_roll = the minor semi-axis b of :class:`~bearingsim.contact.hertz.HertzContact`);
    ``shear_modulus`` G of the solids [Pa] (2/G = 1/G₁ + 1/G₂), ``poisson`` ν; ``film_modulus`` G_f [Pa] (the
    film's elastic shear modulus; inf: no film compliance), ``film_thickness`` h [m]; ``solids=False`` drops
    the solids' compliance (the film alone, as the traction kernel has it).  Returns K/Q with
    1/K = 1/K_f + 1/K_s (module docstring: Kalker for the solids, Johnson & Tevaarwerk for the film).
    """
    if not (math.isfinite(load) and load > 0):
        raise InputError("load", f"must be positive, got {load!r}", "give the contact load in N")
    k_f = film_creep_stiffness(a_roll, b_lat, film_modulus, film_thickness if film_thickness is not None else 0.0) \
        if not math.isinf(film_modulus) else math.inf
    k_s = solid_creep_stiffness(a_roll, b_lat, shear_modulus, poisson) if solids else math.inf
    if math.isinf(k_f) and math.isinf(k_s):
        raise InputError("creep_slope", "both compliances are zero (rigid film and solids)",
                         "give a film modulus and thickness, or keep solids=True")
    return series_stiffness(k_f, k_s) / load


@njit(cache=True, error_model="numpy")
def solids_in_series_factor(film_modulus, ell, film, shear_modulus, c11):
    """φ = 1/(1 + G_f L₁/h), L₁ = 4 ℓ/(3 C₁₁ G) [-]: the factor on the film's elastic modulus G_f [Pa] that puts
    the solids' tangential compliance in series with the film's at every point of the contact (ℓ [m] the contact
    length in the rolling direction, 2 a_roll; h [m] the film; G [Pa] the solids' combined shear modulus).

    The solids' compliance is taken from Kalker's simplified theory of rolling contact (Kalker 1982, "A fast
    algorithm for the simplified theory of rolling contact", Vehicle System Dynamics 11:1–13, the FASTSIM
    flexibility L₁ = 8 a_roll/(3 C₁₁ G) [m/Pa]): a surface point's elastic tangential displacement is L₁ τ.
    A point at distance x from the leading edge has accumulated the slip s x, shared by the film (h τ/G_f) and
    the solids (L₁ τ): τ = s x/(h/G_f + L₁) = φ G_f s x/h.  Integrated over the ellipse this gives exactly the
    series stiffness 1/K = 1/K_f + 1/K_s of :func:`film_creep_stiffness` and :func:`solid_creep_stiffness`
    (Kalker's flexibility is chosen so that the solids alone give his linear creep force G a b C₁₁ s).
    τ_e = φ G_f ℓ s/h in :func:`elastic_plastic_mean_stress` therefore has the series slope at small slip and
    leaves the saturated (viscous) stress unchanged; between the two it is an approximation."""
    if film_modulus <= 0.0 or film <= 0.0:
        return 1.0
    return 1.0 / (1.0 + 4.0 * film_modulus * ell / (3.0 * film * shear_modulus * c11))


def solids_flexibility_coefficient(rx: float, ry: float, shear_modulus: float, poisson: float) -> float:
    """8/(3 C₁₁ G) [1/Pa]: Kalker's FASTSIM flexibility L₁ per unit rolling semi-axis (:func:`solids_in_series_factor`)
    of a Hertz point contact with effective radii ``rx`` (rolling direction) and ``ry`` (across) [m]; C₁₁ at the
    contact's semi-axis ratio a_roll/b_lat = 1/κ (κ the exact Hertz ellipticity, independent of the load) and
    Poisson ratio ν; G [Pa] the combined shear modulus (2/G = 1/G₁ + 1/G₂)."""
    from .hertz import ellipticity_exact

    for name, v in (("rx", rx), ("ry", ry), ("shear_modulus", shear_modulus)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(name, f"must be positive and finite, got {v!r}", "")
    kappa = ellipticity_exact(min(rx, ry), max(rx, ry))[0]
    ratio = 1.0 / kappa if rx <= ry else kappa  # a_roll / b_lat
    return 8.0 / (3.0 * kalker_c11(ratio, 1.0, poisson) * shear_modulus)


def dyson_shear_modulus(pressure: float, temperature: float) -> float:
    """G_∞ = 1.2 p/(2.52 + 0.024 t) − 10⁸ [Pa] (Dyson's formula as in Zhou & Hoeprich 1991 eq. 37; p [Pa],
    t [°C] = temperature [K] − 273.15): the limiting elastic shear modulus the traction kernel uses for the film
    (its τ_L = 0.25 G_∞).  Floored at 0."""
    t = temperature - 273.15
    return max(0.0, 1.2 * pressure / (2.52 + 0.024 * t) - 1e8)


# --------------------------------------------------------------------------- Python API


def fit_four_parameter(mu0: float, mu_max: float, s_max: float, mu_inf: float) -> tuple[float, float, float, float]:
    """(A, B, C, D) of μ(s) = (A + B s)e^(−C s) + D through μ(0) = μ₀, a peak μ_max at s_max, μ(∞) = μ_∞.

    Requires 0 ≤ μ₀, μ_∞ < μ_max and s_max > 0 (closed form + a bisection in t = C s_max).
    """
    for name, v in (("mu0", mu0), ("mu_max", mu_max), ("s_max", s_max), ("mu_inf", mu_inf)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v >= 0):
            raise InputError(name, f"must be a finite non-negative number, got {v!r}", "")
    if s_max <= 0:
        raise InputError("s_max", "must be positive", "give the slide-roll ratio of the peak, e.g. 0.01")
    if not (mu_max > mu0 and mu_max > mu_inf):
        raise InputError("mu_max", f"the peak {mu_max} must exceed mu0={mu0} and mu_inf={mu_inf}",
                         "give a curve with a maximum")
    D = mu_inf
    A = mu0 - mu_inf
    target = mu_max - mu_inf
    if A == 0.0:
        C = 1.0 / s_max
        B = math.e * target / s_max
        return A, B, C, D
    f = lambda t: A * math.exp(-t) / (1.0 - t) - target  # noqa: E731
    if A < 0:  # root in t > 1, f decreasing from +inf to 0- ... (A<0: f = |A| e^-t/(t-1) - target)
        lo, hi = 1.0 + 1e-15, 2.0
        while f(hi) > 0:
            hi *= 2.0
    else:  # root in [0, 1): f increasing from A - target <= 0 to +inf
        lo, hi = 0.0, 1.0 - 1e-15
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        fm = f(mid)
        if (fm > 0) == (f(lo) > 0):
            lo = mid
        else:
            hi = mid
    t = 0.5 * (lo + hi)
    C = t / s_max
    B = C * A / (1.0 - t)
    return A, B, C, D


def traction_curve(s, coefficients) -> np.ndarray:
    """μ(s) of the four-parameter curve for an array of slide–roll ratios s [-]."""
    A, B, C, D = coefficients
    s = np.abs(np.asarray(s, dtype=float))
    return (A + B * s) * np.exp(-C * s) + D


def mixed_coefficient(mu_boundary: float, mu_fluid: float, film_parameter: float,
                      lambda1: float = 1.0, lambda2: float = 3.0) -> float:
    """μ = μ_b + (μ_f − μ_b) w(Λ), w linear from 0 at Λ₁ to 1 at Λ₂ ([S1] §3.1)."""
    if not (0 <= lambda1 < lambda2):
        raise InputError("lambda1/lambda2", f"need 0 <= lambda1 < lambda2, got {lambda1}, {lambda2}", "")
    if math.isnan(film_parameter) or film_parameter < 0:
        raise InputError("film_parameter", f"must be >= 0, got {film_parameter!r}", "")
    return mu_boundary + (mu_fluid - mu_boundary) * mixed_weight(film_parameter, lambda1, lambda2)


def rolling_resistance(regime_name: str, eta0: float, alpha: float, e_eff: float, rx: float, u: float,
                       load: float, length: float, thermal_factor: float = 1.0,
                       starvation_factor: float = 1.0) -> float:
    """Rolling viscous resistance F_R [N] of a line contact of length `length` [m] carrying `load` [N].

    regime 'PE' | 'PR' | 'IE' use Zhou & Hoeprich (1991) eq. 17 (PR and IE: stand-in, see
    module docstring); 'IR' the Martin closed form.  Multiplied by φ_T φ_s (eqs. 22–23).
    """
    if regime_name not in ("IR", "PR", "IE", "PE"):
        raise InputError("regime", f"unknown regime {regime_name!r}", "use IR, PR, IE or PE")
    for name, v in (("viscosity", eta0), ("pressure_viscosity_coefficient", alpha), ("effective_modulus", e_eff),
                    ("rx", rx), ("length", length)):
        if not (math.isfinite(v) and v > 0):
            raise InputError(name, f"must be positive and finite, got {v!r}", "")
    for name, v in (("rolling_speed", u), ("load", load)):
        if not (math.isfinite(v) and v >= 0):
            raise InputError(name, f"must be finite and >= 0, got {v!r}", "")
    w = load / length
    if regime_name == "IR":
        f = rolling_resistance_ir(eta0, u, w, length)
    else:
        f = rolling_resistance_zh(eta0 * u / (e_eff * rx), alpha * e_eff, w / (e_eff * rx), rx, alpha, length)
    return thermal_factor * starvation_factor * f


__all__ = ["four_parameter", "fit_four_parameter", "traction_curve", "mixed_weight", "mixed_coefficient",
           "roelands_viscosity", "limiting_shear_stress", "fluid_shear_stress", "elastic_plastic_mean_stress",
           "rolling_resistance_zh",
           "rolling_resistance_ir", "rolling_resistance", "MARTIN_ROLLING", "KALKER_C11_A_OVER_B",
           "KALKER_C11_B_OVER_A",
           "kalker_c11", "solid_creep_stiffness", "film_creep_stiffness", "series_stiffness", "creep_slope",
           "solids_in_series_factor", "solids_flexibility_coefficient", "dyson_shear_modulus"]
