"""Normal damping of a ball–raceway contact: Hunt–Crossley (dry impacts) and the lubricant's squeeze film (EHL).

Why: the dynamic model's normal force is Q = K δ^1.5 (1 + 1.5 α δ̇) (Hunt & Crossley 1975, eq. 12), i.e. a
dashpot c = 1.5 α Q in parallel with the Hertz spring k = 1.5 Q/δ.  The default α = 0.05 s/m was *chosen* for
steel-on-steel impacts (restitution e ≈ 1 − α v ≈ 0.95 at 1 m/s; docs/dynamics.md); it has no lubricated-contact
source, and it gives a loaded contact c/k = α δ ≈ 0.5 µs, i.e. a damping ratio ζ = ω α δ/2 ≈ 2·10⁻³ for the hub's
1.2 kHz tilt mode: the ring rings for seconds.  A lubricated contact loses more: the oil around the
Hertz zone is squeezed when the bodies approach.

Model "ehl" (this module; derived here from Reynolds' equation, not a fit from the literature — the fitted EHL
stiffness/damping expressions of Wijnant 1998 (thesis, Twente) and Nonato & Cavalca 2014 could not be retrieved
in this work and are *not* used):

1. Rigid isoviscous squeeze of the elliptic paraboloid gap h = h₀ + x²/(2R_x) + y²/(2R_y) (Reynolds' equation
   ∇·(h³∇p) = 12 η ḣ₀ with p → 0 far away).  p = −6 η ḣ₀ R/h² with R = R_x R_y/(R_x + R_y) solves it exactly
   (∇·(h³∇(h⁻²)) = −2(1/R_x + 1/R_y)), and the force is

       F = 12 π η R √(R_x R_y) (−ḣ₀)/h₀,   so   c_rigid = 12 π η R √(R_x R_y) / h₀,

   which for a sphere of radius R₀ on a plane (R_x = R_y = R₀, so R = R₀/2 and √(R_x R_y) = R₀) is Reynolds'
   classical 6 π η R₀²/h₀ (Reynolds 1886; Hamrock, Schmid & Jacobson 2004, *Fundamentals of Fluid Film
   Lubrication*, squeeze-film chapter).
2. The loaded contact is flattened: inside the Hertz area the film (piezoviscous, η(p) ≫ η₀) is taken as rigid —
   its thickness h_c and no flow through it at these frequencies — and outside, the gap is h_c plus the Hertz
   separation g_H(r).  For a small extra approach dδ at (to first order) fixed contact size, the surfaces outside
   move as under a flat punch: dg = −dδ (1 − (2/π) asin(a/r)) (Johnson 1985, *Contact Mechanics*, ch. 3: the
   surface displacements of the rigid flat punch's pressure and of the Hertz pressure outside the loaded circle),
   so the squeeze rate vanishes at the contact edge
   and tends to δ̇ far away.  Axisymmetric Reynolds with no flux at r = a:
   r h³ p′ = −12 η δ̇ ∫_a^r f(s) s ds, f = 1 − (2/π) asin(a/s), p(∞) = 0; c = ∫ p 2πr dr / δ̇
   (:func:`squeeze_flattened_circle`, a quadrature).  As a → 0 it tends to the rigid 6 π η R₀²/h.
3. The ellipse uses the circle of the same rigid damping (R₀² = 2 R √(R_x R_y)) and the same area (a₀ = √(ab)):
   c = c_rigid(ellipse) · Φ(a₀, R₀, h_c), Φ = flattened/rigid for that circle (an approximation: exact in the
   rigid limit, untested against a 2-D solution for elongated ellipses).

Assumptions and validity: isoviscous η₀ (inlet viscosity) outside the Hertz zone, full film (no cavitation of
the outlet: the separating half-cycle is overestimated), quasi-steady (squeeze time scales h/δ̇ ≫ flow time),
small vibration about the loaded state, h_c from Hamrock–Dowson (:mod:`.ehl`).  No source value was available to
validate the flattened model; tests/validation/test_contact_damping.py checks the rigid limits against Reynolds'
closed form and a numerical Reynolds solution.

In the dynamic model the squeeze coefficient enters as the Hunt–Crossley α that gives the same *total* damping of
the loaded contacts at the quasi-static start: α_ehl = Σ c_j / Σ 1.5 Q_j (:func:`equivalent_alpha`; case option
``contact_damping = "ehl"``).  HC's c ∝ Q while the squeeze c falls slowly with Q (Φ decreases as the Hertz zone
grows), so lightly loaded contacts get less damping than this model gives them, heavily loaded ones more.

Units: SI throughout ([Pa·s], [m], [N·s/m]).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError

#: default Hunt–Crossley coefficient of the dynamic model [s/m] (chosen for dry steel impacts; docs/dynamics.md)
HUNT_CROSSLEY_DEFAULT = 0.05


def _positive(name: str, v) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or not (math.isfinite(v) and v > 0):
        raise InputError(name, f"must be a positive finite number, got {v!r}", "check the value and its unit (SI)")
    return float(v)


def squeeze_rigid_ellipsoid(viscosity: float, rx: float, ry: float, gap: float) -> float:
    """c = 12 π η R √(R_x R_y)/h [N·s/m], R = R_x R_y/(R_x + R_y): the exact isoviscous squeeze-film damping of a
    rigid elliptic paraboloid at minimum gap h (module docstring, item 1).  viscosity η [Pa·s]; rx, ry [m]; gap [m]."""
    eta, rx, ry, h = (_positive(n, v) for n, v in (("viscosity", viscosity), ("rx", rx), ("ry", ry), ("gap", gap)))
    r = rx * ry / (rx + ry)
    return 12.0 * math.pi * eta * r * math.sqrt(rx * ry) / h


def hertz_separation(r, a: float, radius: float):
    """Separation of two bodies outside a Hertz circle of radius a [m] (sum of radii 1/R = 1/R₁ + 1/R₂, approach
    δ = a²/R): g(r) = r²/(2R) − δ + (a²/(πR))[(2 − r²/a²) asin(a/r) + √(r²/a² − 1)] [m], 0 for r ≤ a
    (Johnson 1985, *Contact Mechanics*, ch. 3: the displacement of the Hertz pressure outside the circle; checked
    here: g(a) = 0 and g → r²/(2R) − δ + 4a³/(3πR r) far away, the point-load displacement of the same force)."""
    r = np.asarray(r, dtype=float)
    x = np.maximum(r / a, 1.0)
    w = (a * a / (math.pi * radius)) * ((2.0 - x * x) * np.arcsin(1.0 / x) + np.sqrt(np.maximum(x * x - 1.0, 0.0)))
    return np.maximum(r * r / (2.0 * radius) - a * a / radius + w, 0.0)


def squeeze_flattened_circle(viscosity: float, radius: float, contact_radius: float, film: float,
                             n: int = 6000) -> float:
    """Squeeze-film damping [N·s/m] of a flattened (Hertz) circular contact of radius a with a rigid film h_c
    inside it (module docstring, item 2): a 1-D quadrature on a graded grid from r = a to 10⁴ (a + √(2Rh)).
    radius R [m]: the relative radius of curvature (1/R = 1/R₁ + 1/R₂; a sphere R₀ on a plane: R₀), so that the
    rigid gap is h + r²/(2R) and a = 0 gives 6 π η R²/h; contact_radius a ≥ 0 [m] (0: the rigid paraboloid);
    film h_c [m]."""
    eta, rr, h = (_positive(nm, v) for nm, v in (("viscosity", viscosity), ("radius", radius), ("film", film)))
    if isinstance(contact_radius, bool) or not (isinstance(contact_radius, (int, float))
                                                and math.isfinite(contact_radius) and contact_radius >= 0):
        raise InputError("contact_radius", f"must be ≥ 0, got {contact_radius!r}", "the Hertz radius in m")
    a = float(contact_radius)
    scale = a + math.sqrt(2.0 * rr * h)
    r = a + scale * np.concatenate([[0.0], np.geomspace(1e-9, 1e4, n)])
    if a > 0:
        g = hertz_separation(r, a, rr) + h
        f = 1.0 - (2.0 / math.pi) * np.arcsin(np.minimum(a / np.maximum(r, a), 1.0))
    else:
        g = r * r / (2.0 * rr) + h
        f = np.ones_like(r)
    # flux integral F(r) = ∫_a^r f s ds (trapezoid), pressure gradient −p′ = 12 η F /(r g³) per unit δ̇
    fs = f * r
    flux = np.concatenate([[0.0], np.cumsum(0.5 * (fs[1:] + fs[:-1]) * np.diff(r))])
    dp = np.zeros_like(r)
    pos = r > 0
    dp[pos] = 12.0 * eta * flux[pos] / (r[pos] * g[pos] ** 3)  # at r = 0 (a = 0) the flux vanishes as r²
    seg = 0.5 * (dp[1:] + dp[:-1]) * np.diff(r)
    p = np.concatenate([np.cumsum(seg[::-1])[::-1], [0.0]])  # p(r) = ∫_r^∞ (−p′) ds
    pr = p * r
    return float(2.0 * math.pi * np.sum(0.5 * (pr[1:] + pr[:-1]) * np.diff(r)))


def ehl_contact_damping(viscosity: float, rx: float, ry: float, semi_major: float, semi_minor: float,
                        film: float) -> float:
    """Squeeze-film damping of a loaded lubricated elliptic contact [N·s/m] (module docstring, item 3):
    c = c_rigid(R_x, R_y, h_c) · Φ(a₀ = √(ab), R₀, h_c), R₀² = 2 R √(R_x R_y).  viscosity η₀ [Pa·s] at the inlet;
    rx, ry [m]; Hertz semi-axes [m]; central film h_c [m]."""
    c_rigid = squeeze_rigid_ellipsoid(viscosity, rx, ry, film)
    a0 = math.sqrt(_positive("semi_major", semi_major) * _positive("semi_minor", semi_minor))
    r = rx * ry / (rx + ry)
    r0 = math.sqrt(2.0 * r * math.sqrt(rx * ry))
    phi = squeeze_flattened_circle(viscosity, r0, a0, film) / (6.0 * math.pi * viscosity * r0 * r0 / film)
    return c_rigid * phi


def hunt_crossley_coefficient(alpha: float, load: float) -> float:
    """Dashpot of the Hunt–Crossley law about a loaded state, c = 1.5 α Q [N·s/m] (d/dδ̇ of K δ^1.5(1 + 1.5 α δ̇))."""
    if not (math.isfinite(alpha) and alpha >= 0):
        raise InputError("contact_damping", f"must be ≥ 0, got {alpha!r}", "e.g. 0.05 (s/m)")
    return 1.5 * alpha * load


def contact_damping_table(result, lubricant, temperature: float, alpha: float = HUNT_CROSSLEY_DEFAULT) -> list[dict]:
    """Per loaded contact of a quasi-static solution: load Q [N], approach δ [m], Hertz stiffness k = 1.5 Q/δ
    [N/m], central film h_c [m] and entrainment speed [m/s] (:func:`bearingsim.lubrication.lubrication_report`),
    the squeeze damping c_ehl and the Hunt–Crossley c_hc = 1.5 α Q [N·s/m], and their time constants c/k [s]."""
    from ..lubrication import lubrication_report

    rep = lubrication_report(result, lubricant, temperature)
    eta0 = rep["dynamic_viscosity_Pa_s"]
    rows = [r.bearing for r in result.bearing.rows]
    out = []
    for ball in rep["balls"]:
        rb = rows[ball["row"]]
        for name in ("inner", "outer"):
            c = ball[name]
            if not c or not c["central_film_m"] > 0:
                continue
            q = c["load_N"]
            hz = rb.contact(q, name == "inner", c["contact_angle_rad"])
            c_ehl = ehl_contact_damping(eta0, c["rx_m"], c["ry_m"], c["semi_major_m"], c["semi_minor_m"],
                                        c["central_film_m"])
            k = 1.5 * q / hz.approach
            c_hc = hunt_crossley_coefficient(alpha, q)
            out.append({"ball": ball["index"], "row": ball["row"], "contact": name, "load_N": q,
                        "approach_m": hz.approach, "stiffness_N_m": k, "central_film_m": c["central_film_m"],
                        "entrainment_speed_m_s": c["entrainment_speed_m_s"], "c_ehl_N_s_m": c_ehl,
                        "c_hunt_crossley_N_s_m": c_hc, "tau_ehl_s": c_ehl / k, "tau_hunt_crossley_s": c_hc / k})
    if not out:
        raise InputError("loads", "no loaded lubricated contact in the quasi-static solution",
                         "the contact damping needs loaded balls and a positive entrainment speed")
    return out


def equivalent_alpha(result, lubricant, temperature: float) -> float:
    """Hunt–Crossley α [s/m] giving the loaded contacts of ``result`` the same total damping as the squeeze model:
    α = Σ c_ehl,j / Σ 1.5 Q_j (module docstring)."""
    tab = contact_damping_table(result, lubricant, temperature)
    return sum(t["c_ehl_N_s_m"] for t in tab) / sum(1.5 * t["load_N"] for t in tab)


def modal_damping_ratio(omega: float, damping, stiffness) -> float:
    """ζ ≈ ω Σc_j /(2 Σk_j) [-]: a mode of angular frequency ω [rad/s] carried by contacts of dashpots c_j [N·s/m]
    and springs k_j [N/m] that move together (the stiffness-weighted mean time constant c/k times ω/2; exact for one
    Kelvin–Voigt spring–dashpot; it ignores how much each contact moves in the mode)."""
    c = np.asarray(damping, dtype=float)
    k = np.asarray(stiffness, dtype=float)
    if c.shape != k.shape or c.size == 0 or np.any(k <= 0) or np.any(c < 0):
        raise InputError("stiffness", "need matching arrays of dashpots ≥ 0 and springs > 0", "")
    return float(_positive("omega", omega) * c.sum() / (2.0 * k.sum()))


def free_decay_damping_ratio(t, x) -> tuple[float, float]:
    """(ζ, f_d [Hz]) of a free decaying vibration x(t) [any unit]: least-squares fit of
    x = e^(−σ t)(A cos ω_d t + B sin ω_d t) + c₀ + c₁ t (ω_d started from the zero crossings of the detrended
    signal), ζ = σ/√(σ² + ω_d²).  Needs ≥ 2 periods of samples."""
    from scipy.optimize import least_squares

    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    if t.ndim != 1 or t.shape != x.shape or t.size < 16 or not np.all(np.isfinite(x)):
        raise InputError("x", "need ≥ 16 finite samples x(t) with matching times", "pass two 1-D arrays")
    tt = t - t[0]
    lin = np.polyval(np.polyfit(tt, x, 1), tt)
    d = x - lin
    zc = np.nonzero(np.diff(np.signbit(d)))[0]
    if zc.size < 4:
        raise InputError("x", "fewer than two periods of oscillation in the record", "give a longer record")
    w0 = math.pi * (zc.size - 1) / (tt[zc[-1]] - tt[zc[0]])
    amp = np.abs(d).max()

    def resid(p):
        s, w, a, b, c0, c1 = p
        return np.exp(-s * tt) * (a * np.cos(w * tt) + b * np.sin(w * tt)) + c0 + c1 * tt - x

    fit = least_squares(resid, [0.01 * w0, w0, amp, 0.0, lin[0], (lin[-1] - lin[0]) / max(tt[-1], 1e-300)],
                        x_scale=[w0 * 0.01, w0 * 0.1, amp, amp, amp, amp / max(tt[-1], 1e-300)])
    s, w = fit.x[0], abs(fit.x[1])
    return float(s / math.hypot(s, w)), float(w / (2 * math.pi))


__all__ = ["HUNT_CROSSLEY_DEFAULT", "squeeze_rigid_ellipsoid", "hertz_separation", "squeeze_flattened_circle",
           "ehl_contact_damping", "hunt_crossley_coefficient", "contact_damping_table", "equivalent_alpha",
           "modal_damping_ratio", "free_decay_damping_ratio"]
