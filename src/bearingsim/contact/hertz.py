"""Hertz point contact of a ball on a raceway.

Two published models, one function each:

* :func:`point_contact_exact` — the classical Hertz solution with the complete
  elliptic integrals, ellipticity κ = a/b found from the curvature difference
  (Harris & Kotzalas, *Rolling Bearing Analysis* 5th ed. 2007, vol. 1, ch. 5,
  eqs. 5.29–5.39; Hamrock & Brewe, J. Lubr. Technol. 105 (1983) 171, eqs. 1–14).
* :func:`point_contact_hamrock_brewe` — the simplified formulae of Hamrock &
  Brewe (1983), eqs. 22–24: κ ≈ 1.0339 (R_y/R_x)^0.636, 𝓔 ≈ 1.0003 + 0.5968 R_x/R_y,
  𝓚 ≈ 1.5277 + 0.6023 ln(R_y/R_x).

Conventions: x is the rolling direction (minor axis b), y the transverse
direction along the groove (major axis a); R_x ≤ R_y for ball bearings.
Effective modulus E′ = 2 / [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]  [Pa] (Hamrock's definition).
For a load Q [N] (Hamrock & Brewe 1983, eqs. 11–13):

    a = (6 κ² 𝓔 Q R / (π E′))^(1/3),   b = (6 𝓔 Q R / (π κ E′))^(1/3),
    δ = 𝓚 [ (9 / (2 𝓔 R)) (Q / (π κ E′))² ]^(1/3),   p_max = 3Q / (2π a b),

with 1/R = 1/R_x + 1/R_y.  Hence Q = K δ^1.5 with
K = π κ E′ √(2 𝓔 R / (9 𝓚³))  [N/m^1.5].

The elliptic integrals are computed by the arithmetic–geometric mean in
numba-compiled code (exact to round-off; tested against scipy.special) so that
kernels can call them.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from numba import njit

from ..errors import InputError


@njit(cache=True)
def elliptic_ke(m):
    """Complete elliptic integrals of the first and second kind, K(m) and E(m).

    Parameter convention m = k² (as scipy.special.ellipk/ellipe), 0 ≤ m < 1.
    Arithmetic–geometric mean (Abramowitz & Stegun 1964, 17.6.1–17.6.4).
    """
    a = 1.0
    b = math.sqrt(1.0 - m)
    c = math.sqrt(m)
    s = 0.5 * c * c
    p = 1.0
    for _ in range(40):
        if abs(a - b) <= 1e-16 * a:
            break
        an = 0.5 * (a + b)
        bn = math.sqrt(a * b)
        c = 0.5 * (a - b)
        a = an
        b = bn
        p *= 2.0
        s += 0.5 * p * c * c
    K = math.pi / (2.0 * a)
    E = K * (1.0 - s)
    return K, E


@njit(cache=True)
def _curvature_difference_of_kappa(kappa):
    """F(κ) = [(κ²+1)𝓔 − 2𝓚] / [(κ²−1)𝓔]  (Harris & Kotzalas 2007 vol. 1 eq. 5.38), κ > 1."""
    m = 1.0 - 1.0 / (kappa * kappa)
    K, E = elliptic_ke(m)
    return ((kappa * kappa + 1.0) * E - 2.0 * K) / ((kappa * kappa - 1.0) * E), K, E


@njit(cache=True)
def ellipticity_exact(rx, ry):
    """Exact ellipticity κ = a/b and the elliptic integrals (𝓚, 𝓔) of a point contact.

    Parameters
    ----------
    rx, ry : float  [m]
        Effective radii of curvature in the rolling and transverse directions.

    Returns
    -------
    kappa, ellK, ellE : float
        Solves F(ρ) = (1/R_x − 1/R_y)/(1/R_x + 1/R_y) = F(κ) by Newton's method
        on ln κ with a bisection safeguard.  If R_x > R_y the axes are swapped by the
        caller (κ ≥ 1 always).
    """
    fr = (1.0 / rx - 1.0 / ry) / (1.0 / rx + 1.0 / ry)
    if fr <= 1e-14:
        return 1.0, math.pi / 2.0, math.pi / 2.0
    # bracket in t = ln κ; F increases monotonically from 0 (κ=1) to 1 (κ→∞)
    lo = 0.0
    hi = 1.0
    while _curvature_difference_of_kappa(math.exp(hi))[0] < fr:
        lo = hi
        hi *= 2.0
        if hi > 60.0:
            break
    t = 1.0337 * 0.636 * math.log(ry / rx) if ry > rx else 1e-3  # Hamrock–Brewe start
    if t <= lo or t >= hi:
        t = 0.5 * (lo + hi)
    for _ in range(100):
        f, K, E = _curvature_difference_of_kappa(math.exp(t))
        g = f - fr
        if g > 0.0:
            hi = t
        else:
            lo = t
        h = 1e-7 * max(1.0, t)
        f2 = _curvature_difference_of_kappa(math.exp(t + h))[0]
        d = (f2 - f) / h
        tn = t - g / d if d > 0.0 else 0.5 * (lo + hi)
        if tn <= lo or tn >= hi:
            tn = 0.5 * (lo + hi)
        if abs(tn - t) < 1e-15 * max(1.0, abs(t)) or hi - lo < 1e-15:
            t = tn
            break
        t = tn
    kappa = math.exp(t)
    _, K, E = _curvature_difference_of_kappa(kappa)
    return kappa, K, E


@njit(cache=True)
def ellipticity_hamrock_brewe(rx, ry):
    """Approximate κ, 𝓚, 𝓔 (Hamrock & Brewe 1983, eqs. 22–24), for R_y ≥ R_x."""
    r = ry / rx
    kappa = 1.0339 * r**0.636
    E = 1.0003 + 0.5968 / r
    K = 1.5277 + 0.6023 * math.log(r)
    return kappa, K, E


@njit(cache=True)
def contact_from_constants(q, rx, ry, e_eff, kappa, ellK, ellE):
    """Semi-axes a, b [m], approach δ [m], max pressure [Pa] and K [N/m^1.5].

    Hamrock & Brewe (1983) eqs. 11–13 with κ, 𝓚, 𝓔 given; q [N] ≥ 0.
    """
    r = 1.0 / (1.0 / rx + 1.0 / ry)
    kcon = math.pi * kappa * e_eff * math.sqrt(2.0 * ellE * r / (9.0 * ellK**3))
    if q <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, kcon
    a = (6.0 * kappa * kappa * ellE * q * r / (math.pi * e_eff)) ** (1.0 / 3.0)
    b = (6.0 * ellE * q * r / (math.pi * kappa * e_eff)) ** (1.0 / 3.0)
    delta = ellK * ((9.0 / (2.0 * ellE * r)) * (q / (math.pi * kappa * e_eff)) ** 2) ** (1.0 / 3.0)
    pmax = 3.0 * q / (2.0 * math.pi * a * b)
    return a, b, delta, pmax, kcon


class HertzContact(NamedTuple):
    """Result of a Hertz point-contact calculation (all SI)."""

    load: float  #: normal load Q [N]
    a: float  #: semi-major axis (transverse) [m]
    b: float  #: semi-minor axis (rolling direction) [m]
    approach: float  #: elastic approach δ of the two bodies [m]
    max_pressure: float  #: p_max = 3Q/(2πab) [Pa]
    kappa: float  #: ellipticity a/b [-]
    ell_k: float  #: complete elliptic integral of the first kind 𝓚 [-]
    ell_e: float  #: complete elliptic integral of the second kind 𝓔 [-]
    stiffness_constant: float  #: K in Q = K δ^1.5 [N/m^1.5]


def effective_modulus(e1: float, nu1: float, e2: float, nu2: float) -> float:
    """E′ = 2 / [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]  [Pa]  (Hamrock & Brewe 1983, eq. 5)."""
    return 2.0 / ((1.0 - nu1**2) / e1 + (1.0 - nu2**2) / e2)


def _check(q, rx, ry, e_eff):
    if not (q >= 0 and math.isfinite(q)):
        raise InputError("load", f"must be a finite non-negative force, got {q!r}", "give Q ≥ 0 N")
    for name, v in (("rx", rx), ("ry", ry)):
        if not (v > 0 and math.isfinite(v)):
            raise InputError(name, f"effective radius must be positive and finite, got {v!r}",
                             "check the ball diameter and groove radius "
                             "(a concave groove tighter than the ball is impossible)")
    if not (e_eff > 0):
        raise InputError("effective_modulus", f"must be positive, got {e_eff!r}", "check the materials")


def point_contact_exact(q: float, rx: float, ry: float, e_eff: float) -> HertzContact:
    """Hertz point contact, exact elliptic-integral solution.

    Parameters
    ----------
    q : float  [N]       normal load
    rx, ry : float  [m]  effective radii in the rolling and transverse directions (R_y ≥ R_x)
    e_eff : float  [Pa]  effective modulus E′ (:func:`effective_modulus`)

    Source: Harris & Kotzalas (2007) vol. 1 eqs. 5.29–5.39; Hamrock & Brewe (1983) eqs. 1–14.
    """
    _check(q, rx, ry, e_eff)
    if rx > ry:  # keep the major axis transverse
        rx, ry = ry, rx
    kappa, K, E = ellipticity_exact(rx, ry)
    out = contact_from_constants(q, rx, ry, e_eff, kappa, K, E)
    return HertzContact(q, out[0], out[1], out[2], out[3], kappa, K, E, out[4])


def point_contact_hamrock_brewe(q: float, rx: float, ry: float, e_eff: float) -> HertzContact:
    """Hertz point contact with the Hamrock & Brewe (1983) simplified κ, 𝓚, 𝓔 (eqs. 22–24).

    Same parameters and units as :func:`point_contact_exact`; accuracy a few per cent.
    """
    _check(q, rx, ry, e_eff)
    if rx > ry:
        rx, ry = ry, rx
    kappa, K, E = ellipticity_hamrock_brewe(rx, ry)
    out = contact_from_constants(q, rx, ry, e_eff, kappa, K, E)
    return HertzContact(q, out[0], out[1], out[2], out[3], kappa, K, E, out[4])


def raceway_radii(ball_diameter: float, pitch_diameter: float, conformity: float,
                  contact_angle: float, inner: bool) -> tuple[float, float]:
    """Effective radii (R_x, R_y) [m] of a ball–raceway contact.

    Curvatures (Harris & Kotzalas 2007 vol. 1 eqs. 2.27–2.34), γ = D cos α / d_m:
    ball ρ₁ₓ = ρ₁ᵧ = 2/D; inner ρ₂ₓ = (2/D) γ/(1−γ), outer ρ₂ₓ = −(2/D) γ/(1+γ);
    groove ρ₂ᵧ = −1/(f D).  R_x = 1/(ρ₁ₓ+ρ₂ₓ), R_y = 1/(ρ₁ᵧ+ρ₂ᵧ).

    Parameters
    ----------
    ball_diameter : float  [m]
    pitch_diameter : float  [m]
    conformity : float  [-]  groove radius / ball diameter, > 0.5
    contact_angle : float  [rad]
    inner : bool  True for the inner raceway, False for the outer one
    """
    d = ball_diameter
    gamma = d * math.cos(contact_angle) / pitch_diameter
    rho2x = (2.0 / d) * gamma / (1.0 - gamma) if inner else -(2.0 / d) * gamma / (1.0 + gamma)
    rho2y = -1.0 / (conformity * d)
    rx = 1.0 / (2.0 / d + rho2x)
    ry = 1.0 / (2.0 / d + rho2y)
    return rx, ry


@njit(cache=True, error_model="numpy")
def series_constant(k_inner, k_outer):
    """Ball's combined load–deflection constant K_n [N/m^1.5] of two contacts in series.

    K_n = [(1/K_i)^(2/3) + (1/K_o)^(2/3)]^(−3/2)  (Harris & Kotzalas 2007 vol. 1 eq. 7.4); compiled, so that
    the ring kernels of :mod:`bearingsim.statics._kernels` and Python callers share one spelling (a zero
    constant gives K_n = 0, not an exception).
    """
    return (k_inner ** (-2.0 / 3.0) + k_outer ** (-2.0 / 3.0)) ** (-1.5)


@njit(cache=True)
def load_from_approach(k, delta):
    """Q = K δ^1.5 [N] for an elastic approach δ ≥ 0 [m] and a load–deflection constant K [N/m^1.5]
    (Hamrock & Brewe 1983 eq. 13 inverted; Harris & Kotzalas 2007 vol. 1 eq. 7.1)."""
    return k * delta**1.5


@njit(cache=True)
def approach_from_load(k, q):
    """δ = (Q / K)^(2/3) [m] for a load Q ≥ 0 [N] (the inverse of :func:`load_from_approach`)."""
    return (q / k) ** (2.0 / 3.0)


@njit(cache=True)
def max_pressure_from_load(c_p, q):
    """p_max = C_p Q^(1/3) [Pa] for a load Q ≥ 0 [N] at fixed contact geometry.

    With R, κ, 𝓔 fixed, a and b grow as Q^(1/3) (Hamrock & Brewe 1983 eqs. 11–12), so
    p_max = 3Q/(2πab) = C_p Q^(1/3) with C_p the maximum pressure at Q = 1 N [Pa/N^(1/3)]
    (``max_pressure`` of a contact evaluated at 1 N, as in the row vectors of the statics)."""
    return c_p * q ** (1.0 / 3.0)


def sphere_on_flat(q: float, radius: float, e_eff: float) -> tuple[float, float, float]:
    """Closed-form Hertz sphere on a flat: contact radius, approach, max pressure.

    a = (3 Q R / (2 E′))^(1/3), δ = a²/R, p₀ = 3Q/(2πa²) with E′ as in
    :func:`effective_modulus` (Johnson, *Contact Mechanics* 1985, eqs. 4.22–4.23
    with E* = E′/2).  Used as a closed-form limit in the tests.
    """
    a = (3.0 * q * radius / (2.0 * e_eff)) ** (1.0 / 3.0)
    return a, a * a / radius, 3.0 * q / (2.0 * math.pi * a * a)


__all__ = [
    "HertzContact", "effective_modulus", "point_contact_exact", "point_contact_hamrock_brewe",
    "raceway_radii", "series_constant", "sphere_on_flat", "elliptic_ke", "ellipticity_exact",
    "ellipticity_hamrock_brewe", "contact_from_constants",
]
