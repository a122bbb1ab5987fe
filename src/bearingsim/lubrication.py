"""Lubrication report of a loaded bearing, and traction curves.

Orchestration only (models live in :mod:`bearingsim.contact.ehl`,
:mod:`bearingsim.contact.traction`, :mod:`bearingsim.contact.slices`):

* :func:`lubrication_report` — for each loaded ball of a quasi-static solution
  (:func:`bearingsim.statics.jones_harris.solve`) and each contact (inner, outer): Hertz
  contact, entraining speed, R_x, R_y, central/minimum film (Hamrock & Dowson 1977 with the
  Zhu–Cheng thermal factor), Λ, regime, and the tangential force, traction coefficient
  |F|/Q and power loss that the sliced-contact kernel gives at Jones' ball kinematics
  (the ball speeds of the static solution, evaluated in the cage frame).
* :func:`traction_vs_slide_roll` — μ(s) of one contact from the kernel (a ball rolling on
  a flat race with a prescribed slide–roll ratio), and :func:`plot_traction_curves` — the
  figure of μ vs s at several loads and speeds (seed 001 Fig. 4 shape).
"""

from __future__ import annotations

import math

import numpy as np

from .contact import ehl, hertz
from .contact import slices as S
from .errors import InputError
from .lubricants import get_lubricant

#: Operating (oil) temperature [K] that a computation with a lubricant takes when none is given: 60 °C, the
#: temperature at which ``bearingsim lubricants`` quotes the viscosities, a steady oil temperature of many
#: oil-bath and grease-lubricated bearings.  It sets the viscosity behind κ, a_ISO and the friction, so every
#: output that uses it says so (:func:`assumed_phrases`).
ASSUMED_TEMPERATURE = 333.15
#: Lubricant that a computation which needs one takes when none is given (a mineral oil of ISO VG 68)
ASSUMED_LUBRICANT = "iso-vg-68"

#: key of an assumed input in :func:`operating_conditions`' ``assumed`` → (what it is, the option that gives it)
_ASSUMED_WORDS = {"lubricant": ("lubricant {}", "--lubricant"),
                  "temperature_K": ("operating temperature {:.0f} °C", "--temperature"),
                  "oil_inlet_temperature_K": ("oil inlet temperature {:.0f} °C", "--temperature")}


def operating_conditions(lubricant=None, temperature: float | None = None, *, need_lubricant: bool = False,
                         lubricant_field: str = "lubricant", temperature_field: str = "temperature"):
    """The one rule for a lubricant and an operating temperature the caller does not give: a computation that
    uses a lubricant (one is given, a temperature is given, or ``need_lubricant``) takes
    :data:`ASSUMED_LUBRICANT` and :data:`ASSUMED_TEMPERATURE` for whichever of the two is missing, and returns
    what it assumed so that the output can say so.  Neither given and not needed: no lubricant.

    lubricant : library name, TOML path, Lubricant or None; temperature [K] or None.
    Returns (Lubricant or None, temperature [K] or None, assumed) with ``assumed`` a dict of the inputs filled
    in (``lubricant``: its name, ``temperature_K``), empty when everything was given.
    """
    assumed: dict = {}
    if lubricant is None and temperature is None and not need_lubricant:
        return None, None, assumed
    if lubricant is None:
        lubricant = assumed["lubricant"] = ASSUMED_LUBRICANT
    if temperature is None:
        temperature = assumed["temperature_K"] = ASSUMED_TEMPERATURE
    lub = get_lubricant(lubricant, lubricant_field)
    return lub, lub.check_temperature(temperature, temperature_field), assumed


def assumed_phrases(assumed: dict, options: dict | None = None) -> list[str]:
    """One phrase per assumed input of :func:`operating_conditions` (or the same keys): "operating temperature
    60 °C assumed — give --temperature".  ``options`` renames the option per key (the Python API's argument
    names, e.g. ``{"temperature_K": "temperature="}``)."""
    out = []
    for key, value in assumed.items():
        what, option = _ASSUMED_WORDS[key]
        shown = value - 273.15 if key.endswith("_K") else value
        out.append(f"{what.format(shown)} assumed — give {(options or {}).get(key, option)}")
    return out


def _contact_geometry(d, alpha, inner):
    """Contact-centre offset from the ball centre [m] and unit normal (race → ball) [-], in the
    row frame of :func:`bearingsim.statics._kernels.kinematics` (x axial, r radial): outer
    contact at +(D/2)(sin α_o, cos α_o), inner at −(D/2)(sin α_i, cos α_i)."""
    s, c = math.sin(alpha), math.cos(alpha)
    if inner:
        n = np.array([s, c, 0.0])
    else:
        n = np.array([-s, -c, 0.0])
    return -0.5 * d * n, n


def contact_at_jones_kinematics(lub, q, a, b, r_dev, d, dm, alpha_i, alpha_o, omega, omega_m, omega_r, beta,
                                inner, n_slices=10):
    """Kernel output (out[10]) and (u, s_centre) for one contact at Jones' ball kinematics.

    Cage frame (rotates with ω_m about x), row frame of :func:`bearingsim.statics._kernels.kinematics`
    (x axial, r radial, t = x × r along the orbit): ball centre fixed at (0, d_m/2, 0); inner race
    spins at ω − ω_m, outer at −ω_m about x; the ball at Ω = ω_R (cos β, −sin β, 0), the pinned
    convention of ``kinematics`` (ω, ω_m, ω_R signed as in :func:`bearingsim.statics.jones_harris.ball_table`).
    With it the sliding at both contact centres is zero (Jones 1960 pure rolling) and the spin
    about the normal of the controlling raceway is zero (tests/unit/test_kinematics_convention.py).
    Returns out[10] of :func:`bearingsim.contact.slices.contact_traction`, the entraining speed
    u [m/s] and the sliding speed at the contact centre [m/s].
    """
    cb = np.array([0.0, 0.5 * dm, 0.0])
    cr = np.zeros(3)
    wr_i = np.array([omega - omega_m, 0.0, 0.0])
    wr_o = np.array([-omega_m, 0.0, 0.0])
    wb = omega_r * np.array([math.cos(beta), -math.sin(beta), 0.0])
    alpha = alpha_i if inner else alpha_o
    off, n = _contact_geometry(d, alpha, inner)
    centre = cb + off
    # major axis of the contact ellipse: in the (x, r) plane, perpendicular to n
    major = np.array([-math.cos(alpha), math.sin(alpha), 0.0])
    if inner:
        major = -major
    wr = wr_i if inner else wr_o
    out = np.zeros(10)
    S.contact_traction(float(q), float(a), float(b), float(r_dev), centre, n, major, cb, np.zeros(3), wb, cr,
                       np.zeros(3), wr, lub, int(n_slices), out)
    ub = np.cross(wb, centre - cb)
    ur = np.cross(wr, centre - cr)
    e = 0.5 * (ub + ur)
    e -= (e @ n) * n
    s = ub - ur
    s -= (s @ n) * n
    return out, float(np.linalg.norm(e)), float(np.linalg.norm(s))


def lubrication_report(result, lubricant, temperature: float, roughness: float = 0.1e-6, n_slices: int = 10,
                       model: str = "mixed", fluid_model: str = "physical", starvation_factor: float = 1.0) -> dict:
    """Per loaded ball and contact: film, Λ, regime, traction and power at Jones' kinematics (all SI).

    Parameters
    ----------
    result : StaticResult from :func:`bearingsim.statics.jones_harris.solve`
    lubricant : library name, TOML path or Lubricant
    temperature : float  [K]  oil inlet temperature
    roughness : float  [m]  composite rms roughness of ball and raceway
    """
    lub_obj = get_lubricant(lubricant)
    lub_obj.check_temperature(temperature)
    if not (math.isfinite(roughness) and roughness >= 0):
        raise InputError("roughness", f"must be finite and >= 0, got {roughness!r}", 'e.g. "0.1 um"')
    S.check_strip_count(n_slices)
    row_bearings = [r.bearing for r in result.bearing.rows]  # the rows protocol (bearingsim.geometry)
    balls = result.balls
    omega = float(result.speed)  # signed, as the ball speeds of ball_table
    out_balls = []
    packs: dict = {}
    eta0 = lub_obj.dynamic_viscosity(temperature)
    beta_eta = lub_obj.viscosity_temperature_coefficient(temperature) * eta0
    for j in range(len(balls["azimuth_rad"])):
        r = int(balls["row"][j])
        rb = row_bearings[r]
        d, dm, f_i, f_o = rb.ball_diameter, rb.pitch_diameter, rb.inner_conformity, rb.outer_conformity
        e_eff = rb.effective_modulus
        ai, ao = float(balls["inner_contact_angle_rad"][j]), float(balls["outer_contact_angle_rad"][j])
        entry = {"index": j, "row": r, "azimuth_rad": float(balls["azimuth_rad"][j])}
        loaded = False
        for inner, name in ((True, "inner"), (False, "outer")):
            q = float(balls[f"{name}_load_N"][j])
            if not q > 0:
                entry[name] = None
                continue
            loaded = True
            alpha = ai if inner else ao
            rx, ry = hertz.raceway_radii(d, dm, f_i if inner else f_o, alpha, inner)
            hz = hertz.point_contact_exact(q, rx, ry, e_eff)
            key = (r, inner, round(alpha, 6))
            lub = S.pack_lubrication_parameters(lub_obj, temperature, e_eff, rx, ry, roughness, model=model,
                                                fluid_model=fluid_model, starvation_factor=starvation_factor)
            packs[key] = lub
            r_dev = S.deformed_surface_radius(d, (f_i if inner else f_o) * d)
            kout, u, s_c = contact_at_jones_kinematics(
                lub, q, hz.a, hz.b, r_dev, d, dm, ai, ao, omega, float(balls["orbital_speed_rad_s"][j]),
                float(balls["spin_speed_rad_s"][j]), float(balls["pitch_angle_rad"][j]), inner, n_slices)
            phi_t = ehl.zhu_cheng_thermal_factor(hz.max_pressure, e_eff, beta_eta, u, lub_obj.thermal_conductivity,
                                                 s_c / u if u > 0 else 0.0)
            hc, hmin = ehl.film_thickness(u, q, eta0, lub_obj.pressure_viscosity_coefficient, e_eff, rx, ry,
                                          thermal_factor=phi_t, starvation_factor=starvation_factor)
            fpar = ehl.film_parameter(hmin, roughness)
            reg = ehl.regime(u, q, eta0, lub_obj.pressure_viscosity_coefficient, e_eff, rx, ry) if u > 0 else None
            ft = float(np.linalg.norm(kout[0:3]))
            entry[name] = {
                "load_N": q, "contact_angle_rad": alpha, "semi_major_m": hz.a, "semi_minor_m": hz.b,
                "max_pressure_Pa": hz.max_pressure, "entrainment_speed_m_s": u, "centre_sliding_speed_m_s": s_c,
                "rx_m": rx, "ry_m": ry, "thermal_factor": phi_t, "central_film_m": hc, "minimum_film_m": hmin,
                "film_parameter": fpar if math.isfinite(fpar) else None, "regime": reg,
                "tangential_force_N": ft, "traction_coefficient": ft / q,
                "spin_moment_N_m": float(abs(kout[3:6] @ _contact_geometry(d, alpha, inner)[1])),
                "power_loss_W": float(kout[9]),
            }
        if loaded:
            out_balls.append(entry)
    return {
        "lubricant": lub_obj.name, "temperature_K": float(temperature), "roughness_m": float(roughness),
        "dynamic_viscosity_Pa_s": eta0, "pressure_viscosity_coefficient_1_Pa": lub_obj.pressure_viscosity_coefficient,
        "speed_rad_s": float(result.speed), "model": model, "fluid_model": fluid_model, "n_slices": n_slices,
        "converged": bool(result.converged), "balls": out_balls,
        "total_power_loss_W": float(sum((b[c] or {}).get("power_loss_W", 0.0) for b in out_balls
                                        for c in ("inner", "outer"))),
    }


def traction_vs_slide_roll(lubricant, temperature: float, load: float, rx: float, ry: float, e_eff: float,
                           rolling_speed: float, slide_roll, roughness: float = 0.0, n_slices: int = 10,
                           **options) -> np.ndarray:
    """Traction coefficient μ = |F_traction|/Q vs slide–roll ratio s [-] for one contact.

    The contact (R_x, R_y, E′ give its Hertz ellipse and film) is driven as a ball on a flat
    race (r_dev = ∞, no spin) at mean speed ``rolling_speed`` [m/s] with surface speeds
    u(1 ± s/2), sliding along the rolling direction; rolling resistance is left out so
    that μ is the traction coefficient of seed 001 Fig. 4.  ``options`` go to
    :func:`bearingsim.contact.slices.pack_lubrication_parameters` (default model "fluid").
    """
    if not (math.isfinite(load) and load > 0):
        raise InputError("load", f"must be positive, got {load!r}", "")
    S.check_strip_count(n_slices)
    if not (math.isfinite(rolling_speed) and rolling_speed > 0):
        raise InputError("rolling_speed", f"must be positive, got {rolling_speed!r}", "")
    options.setdefault("model", "fluid")
    options["rolling_resistance"] = False
    lub = S.pack_lubrication_parameters(lubricant, temperature, e_eff, rx, ry, roughness, **options)
    hz = hertz.point_contact_exact(load, rx, ry, e_eff)
    radius = 0.005
    s_arr = np.atleast_1d(np.asarray(slide_roll, dtype=float))
    if not np.all(np.isfinite(s_arr)):
        raise InputError("slide_roll", "must be finite", "")
    mu = np.empty_like(s_arr)
    out = np.zeros(10)
    for i, s in enumerate(s_arr):
        ub, ur = rolling_speed * (1 + s / 2), rolling_speed * (1 - s / 2)
        S.contact_traction(load, hz.a, hz.b, math.inf, np.zeros(3), np.array([0.0, 0.0, 1.0]),
                           np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, radius]), np.zeros(3),
                           np.array([ub / radius, 0.0, 0.0]), np.array([0.0, 0.0, -1.0]),
                           np.array([0.0, ur, 0.0]), np.zeros(3), lub, n_slices, out)
        mu[i] = math.hypot(out[0], out[1]) / load
    return mu


def plot_traction_curves(lubricant="hub-grease-base-oil", temperature: float = 333.15, loads=(500.0, 2000.0, 5000.0),
                         speeds=(1.0, 5.0, 20.0), rx: float = 4.7e-3, ry: float = 0.144, e_eff: float = 2.286e11,
                         s_max: float = 0.05, ax=None, **options):
    """Figure of μ vs slide–roll ratio at several loads [N] and rolling speeds [m/s] (seed 001 Fig. 4 style).

    Defaults: the inner contact of the seed-001 hub bearing row (D = 11.1 mm, d_m = 61 mm,
    α = 35°, f_i ≈ 0.52) with steel (E′ = 228.6 GPa).  Returns the matplotlib Figure.
    """
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    s = np.linspace(0.0, s_max, 201)
    if ax is None:
        fig, ax = plt.subplots(figsize=(6, 4))
    else:
        fig = ax.figure
    for q in loads:
        for u in speeds:
            mu = traction_vs_slide_roll(lubricant, temperature, q, rx, ry, e_eff, u, s, **options)
            ax.plot(s, mu, label=f"Q = {q:g} N, u = {u:g} m/s")
    ax.set_xlabel("slide-roll ratio s [-]")
    ax.set_ylabel("traction coefficient μ [-]")
    name = getattr(lubricant, "name", lubricant)
    ax.set_title(f"{name}, {temperature - 273.15:.0f} °C")
    ax.set_xlim(0, s_max)
    ax.set_ylim(bottom=0)
    ax.legend(fontsize=7)
    fig.tight_layout()
    return fig


def physical_fluid_curve(lubricant, temperature: float, load: float, rx: float, ry: float, e_eff: float,
                         rolling_speed: float, s_end: float = 0.3, **options) -> tuple[float, float, float, float]:
    """(μ₀, μ_max, s_max, μ_∞) of the physical fluid model at one nominal contact condition.

    A fast path for dynamics: pass the result as ``fluid_curve`` with ``fluid_model="curve"``
    to :func:`bearingsim.contact.slices.pack_lubrication_parameters`; the kernel then
    evaluates the four-parameter curve (≈ 3× cheaper) fitted to the physical model at the
    given load [N] and rolling speed [m/s].  μ₀ = 0; μ_max and s_max are the peak of μ(s) on
    10⁻⁵ ≤ s ≤ s_end (or where μ first reaches 99 % of its largest value if there is no
    interior peak); μ_∞ = μ(s_end), lowered to 0.98 μ_max if the curve has not come down.
    """
    s = np.geomspace(1e-5, s_end, 300)
    mu = traction_vs_slide_roll(lubricant, temperature, load, rx, ry, e_eff, rolling_speed, s,
                                fluid_model="physical", **options)
    i = int(np.argmax(mu))
    mu_max = float(mu[i])
    if not mu_max > 0:
        raise InputError("load", "the physical model gives no traction at this condition", "check load and speed")
    if i == len(s) - 1:
        i = int(np.argmax(mu >= 0.99 * mu_max))
    mu_inf = float(min(mu[-1], 0.98 * mu_max))
    return 0.0, mu_max, float(s[i]), mu_inf


__all__ = ["ASSUMED_LUBRICANT", "ASSUMED_TEMPERATURE", "assumed_phrases", "operating_conditions",
           "physical_fluid_curve", "lubrication_report", "traction_vs_slide_roll", "plot_traction_curves",
           "contact_at_jones_kinematics"]
