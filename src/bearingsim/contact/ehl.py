"""Elastohydrodynamic film of an elliptical (ball–raceway) contact.

One function per published model:

* :func:`hamrock_dowson_central` / :func:`hamrock_dowson_minimum` — isothermal
  fully flooded film thickness of Hamrock & Dowson (1977), J. Lubr. Technol. 99:264
  (minimum film, confirmed from the paper's abstract):

      H_min = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)),
      H_c   = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)),
      k = 1.03 (R_y/R_x)^0.64,  H = h/R_x,
      U = η₀ u/(E′ R_x),  G = α E′,  W = Q/(E′ R_x²),

  with u the mean entraining speed (u₁+u₂)/2 [m/s] and E′ = 2/[(1−ν₁²)/E₁+(1−ν₂²)/E₂]
  (the same E′ as :mod:`bearingsim.contact.hertz`).  The central-film formula is the
  one quoted in Hamrock & Dowson, *Ball Bearing Lubrication* (1981) and in the
  project's physics notes; its coefficients were not re-checked against the
  original paper by a search here.
* :func:`zhu_cheng_thermal_factor` — inlet shear heating reduction factor
  φ_T = [1 − 13.2 (p_H/E′) L^0.42] / [1 + 0.213 (1 + 2.23 S^0.83) L^0.64],
  L = (−dη/dT) u²/K (thermal loading), S = sliding/rolling speed.  Source: Zhu & Cheng
  as quoted by Zhou & Hoeprich, J. Tribol. 113 (1991) 590, eq. 21 (confirmed from the
  paper's text).  Zhou & Hoeprich apply it to the rolling resistance; we also apply it
  to the film thickness, which is what Zhu & Cheng derived it for.
* :func:`film_parameter` — Λ = h_min / √(σ₁² + σ₂²).
* :func:`regime` — lubrication regime on the Hamrock–Dowson map for elliptical
  contacts (isoviscous-rigid IR, piezoviscous-rigid PR, isoviscous-elastic IE,
  piezoviscous-elastic PE) in the dimensionless groups g_V = G W³/U², g_E = W^(8/3)/U²
  and ĥ = H (W/U)²:

      IR: ĥ = 128 α_r λ_b² [0.131 atan(α_r/2) + 1.683]²,  α_r = R_y/R_x, λ_b = (1 + 2/(3α_r))^-1
      PR: ĥ = 1.66 g_V^(2/3) (1 − e^(−0.68 k))
      IE: ĥ = 8.70 g_E^0.67 (1 − 0.85 e^(−0.31 k))
      PE: ĥ = 3.42 g_V^0.49 g_E^0.17 (1 − e^(−0.68 k))

  (Hamrock & Dowson, *Ball Bearing Lubrication*, Wiley 1981, ch. on lubrication
  regimes; Hamrock, *Fundamentals of Fluid Film Lubrication*, NASA RP-1255 (1991)
  ch. 22).  These formulae are written from those books as recalled: a search did
  not return their text, so they are NOT confirmed here.  The boundaries of the map
  are lines where the formulae of two adjacent regimes give the same film.  Our
  selection rule (not confirmed): IR when ĥ_IR ≥ ĥ_PR and ĥ_IR ≥ ĥ_IE; otherwise, when
  ĥ_IE ≥ ĥ_IR (elasticity matters), PE if ĥ_PE ≥ ĥ_IE else IE; otherwise (rigid,
  piezoviscous), PE if ĥ_PE ≤ ĥ_PR (elastic flattening thins the rigid-piezoviscous film)
  else PR.  It puts steel ball bearings with mineral oil in PE and soft contacts in IE,
  as the literature does, but its PR region is small and the IR/IE/PE boundaries are
  equal-film lines only where they do not cross between the two branches.  CAVEAT: a
  plain "largest ĥ" rule would put steel ball bearings in PR with these formulae, so a
  coefficient recalled here or the rule may differ from Hamrock & Dowson's.  The film
  thickness we report always uses the Hamrock–Dowson (1977) formulae; the regime only
  selects the rolling-resistance formula (IR closed form vs Zhou & Hoeprich's PE fit).
  A search found one third-party transcription (a Python file quoting a textbook, "page
  136") with the same IR and IE formulae (k → (R_y/R_x)^(2/π)) but a different PR formula,
  ĥ_PR = 1.41 g_V^0.375 (1 − e^(−0.0387 k)), and (1 − e^(−0.0387 k^(2/π))) in PE; we could not
  tell which is right, so the formulae above remain unconfirmed.

All inputs SI; lengths [m], speeds [m/s], loads [N], pressures [Pa], viscosity [Pa·s].
"""

from __future__ import annotations

import math

from numba import njit

from ..errors import InputError

#: regime codes used by the kernels
IR, PR, IE, PE = 0, 1, 2, 3
REGIME_NAMES = ("IR", "PR", "IE", "PE")


@njit(cache=True, error_model="numpy")
def ellipticity_hd(rx, ry):
    """k = 1.03 (R_y/R_x)^0.64  [-]  (Hamrock & Dowson 1977)."""
    return 1.03 * (ry / rx) ** 0.64


@njit(cache=True)
def dimensionless_groups(u, q, eta0, alpha, e_eff, rx):
    """(U, G, W) of Hamrock & Dowson (1977): U = η₀u/(E′R_x), G = αE′, W = Q/(E′R_x²)  [-].

    u [m/s], q [N], eta0 [Pa·s], alpha [1/Pa], e_eff [Pa], rx [m].
    """
    return eta0 * u / (e_eff * rx), alpha * e_eff, q / (e_eff * rx * rx)


@njit(cache=True, error_model="numpy")
def hamrock_dowson_central(u, q, eta0, alpha, e_eff, rx, ry):
    """Isothermal central film thickness h_c [m] (Hamrock & Dowson 1977).

    u [m/s] mean entraining speed, q [N] load, eta0 [Pa·s], alpha [1/Pa], e_eff [Pa] E′,
    rx, ry [m] effective radii (rolling, transverse).  Returns 0 for u ≤ 0 or q ≤ 0.
    """
    if u <= 0.0 or q <= 0.0:
        return 0.0
    k = ellipticity_hd(rx, ry)
    U, G, W = dimensionless_groups(u, q, eta0, alpha, e_eff, rx)
    return rx * 2.69 * U**0.67 * G**0.53 * W ** (-0.067) * (1.0 - 0.61 * math.exp(-0.73 * k))


@njit(cache=True, error_model="numpy")
def hamrock_dowson_minimum(u, q, eta0, alpha, e_eff, rx, ry):
    """Isothermal minimum film thickness h_min [m] (Hamrock & Dowson 1977). Same arguments."""
    if u <= 0.0 or q <= 0.0:
        return 0.0
    k = ellipticity_hd(rx, ry)
    U, G, W = dimensionless_groups(u, q, eta0, alpha, e_eff, rx)
    return rx * 3.63 * U**0.68 * G**0.49 * W ** (-0.073) * (1.0 - math.exp(-0.68 * k))


@njit(cache=True, error_model="numpy")
def zhu_cheng_thermal_factor(p_hertz, e_eff, beta_eta, u, k_oil, slide_roll):
    """Inlet-shear thermal reduction factor φ_T [-] (Zhou & Hoeprich 1991, eq. 21).

    p_hertz [Pa] maximum Hertz pressure, e_eff [Pa] E′, beta_eta = −dη/dT [Pa·s/K] at the
    inlet temperature, u [m/s] rolling speed, k_oil [W/(m·K)] lubricant conductivity,
    slide_roll [-] |sliding|/rolling speed.  Clipped to [0, 1].
    """
    if u <= 0.0 or beta_eta <= 0.0:
        return 1.0
    L = beta_eta * u * u / k_oil
    s = abs(slide_roll)
    num = 1.0 - 13.2 * (p_hertz / e_eff) * L**0.42
    den = 1.0 + 0.213 * (1.0 + 2.23 * s**0.83) * L**0.64
    phi = num / den
    if phi < 0.0:
        return 0.0
    if phi > 1.0:
        return 1.0
    return phi


@njit(cache=True, error_model="numpy")
def regime_films(U, G, W, rx, ry):
    """ĥ of the four regimes (IR, PR, IE, PE) and (g_V, g_E); see the module docstring."""
    k = ellipticity_hd(rx, ry)
    ar = ry / rx
    lam_b = 1.0 / (1.0 + 2.0 / (3.0 * ar))
    gv = G * W**3 / (U * U)
    ge = W ** (8.0 / 3.0) / (U * U)
    h_ir = 128.0 * ar * lam_b**2 * (0.131 * math.atan(ar / 2.0) + 1.683) ** 2
    h_pr = 1.66 * gv ** (2.0 / 3.0) * (1.0 - math.exp(-0.68 * k))
    h_ie = 8.70 * ge**0.67 * (1.0 - 0.85 * math.exp(-0.31 * k))
    h_pe = 3.42 * gv**0.49 * ge**0.17 * (1.0 - math.exp(-0.68 * k))
    return h_ir, h_pr, h_ie, h_pe, gv, ge


@njit(cache=True, error_model="numpy")
def regime_code(U, G, W, rx, ry):
    """Regime code IR=0, PR=1, IE=2, PE=3 on the Hamrock–Dowson map (module docstring)."""
    if U <= 0.0:
        return PE
    h_ir, h_pr, h_ie, h_pe, gv, ge = regime_films(U, G, W, rx, ry)
    return select_regime(h_ir, h_pr, h_ie, h_pe)


@njit(cache=True)
def select_regime(h_ir, h_pr, h_ie, h_pe):
    """Regime code from the four regime films ĥ [-] (selection rule of the module docstring, not confirmed)."""
    if h_ir >= h_pr and h_ir >= h_ie:
        return IR
    if h_ie >= h_ir:
        return PE if h_pe >= h_ie else IE
    return PE if h_pe <= h_pr else PR


# --------------------------------------------------------------------------- Python API


def _pos(name, v, allow_zero=False):
    ok = math.isfinite(v) and (v >= 0 if allow_zero else v > 0)
    if not ok:
        raise InputError(name, f"must be a finite {'non-negative' if allow_zero else 'positive'} number, got {v!r}",
                         "check the units and sign")
    return float(v)


def film_thickness(u: float, q: float, eta0: float, alpha: float, e_eff: float, rx: float, ry: float,
                   thermal_factor: float = 1.0, starvation_factor: float = 1.0) -> tuple[float, float]:
    """Central and minimum film thickness (h_c, h_min) [m].

    Hamrock & Dowson (1977) isothermal formulae multiplied by the thermal reduction
    factor φ_T (:func:`zhu_cheng_thermal_factor`, 1 = isothermal) and a starvation
    factor φ_s ∈ (0, 1] (1 = fully flooded; Zhou & Hoeprich 1991 eq. 23 use the same
    multiplicative form).

    Parameters
    ----------
    u : float  [m/s]   mean entraining speed (u₁+u₂)/2, ≥ 0
    q : float  [N]     normal load, ≥ 0
    eta0 : float  [Pa·s]  inlet viscosity at atmospheric pressure
    alpha : float  [1/Pa]  pressure–viscosity coefficient
    e_eff : float  [Pa]  E′
    rx, ry : float  [m]  effective radii in the rolling and transverse directions
    """
    _pos("entrainment_speed", u, True)
    _pos("load", q, True)
    _pos("viscosity", eta0)
    _pos("pressure_viscosity_coefficient", alpha)
    _pos("effective_modulus", e_eff)
    _pos("rx", rx)
    _pos("ry", ry)
    if not (0.0 < starvation_factor <= 1.0):
        raise InputError("starvation_factor", f"must lie in (0, 1], got {starvation_factor!r}",
                         "use 1 for a fully flooded contact")
    if not (0.0 <= thermal_factor <= 1.0):
        raise InputError("thermal_factor", f"must lie in [0, 1], got {thermal_factor!r}", "")
    f = thermal_factor * starvation_factor
    return (f * hamrock_dowson_central(u, q, eta0, alpha, e_eff, rx, ry),
            f * hamrock_dowson_minimum(u, q, eta0, alpha, e_eff, rx, ry))


def composite_roughness(*sigmas: float) -> float:
    """σ = √(Σ σᵢ²) [m] of the rms roughnesses σᵢ [m] of the surfaces."""
    for i, s in enumerate(sigmas):
        _pos(f"roughness[{i}]", s, True)
    return math.sqrt(sum(s * s for s in sigmas))


def film_parameter(h_min: float, sigma: float) -> float:
    """Λ = h_min / σ [-]; +inf for perfectly smooth surfaces (σ = 0)."""
    _pos("minimum_film", h_min, True)
    _pos("roughness", sigma, True)
    if sigma == 0.0:
        return math.inf
    return h_min / sigma


def regime(u: float, q: float, eta0: float, alpha: float, e_eff: float, rx: float, ry: float) -> str:
    """Lubrication regime 'IR' | 'PR' | 'IE' | 'PE' on the Hamrock–Dowson elliptical map."""
    _pos("entrainment_speed", u)
    _pos("load", q)
    U, G, W = dimensionless_groups(u, q, eta0, alpha, e_eff, rx)
    return REGIME_NAMES[regime_code(U, G, W, rx, ry)]


__all__ = ["hamrock_dowson_central", "hamrock_dowson_minimum", "zhu_cheng_thermal_factor", "film_thickness",
           "composite_roughness", "film_parameter", "regime", "regime_code", "regime_films",
           "dimensionless_groups", "ellipticity_hd", "IR", "PR", "IE", "PE", "REGIME_NAMES"]
