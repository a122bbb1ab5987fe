"""Friction torque and heat of a ball bearing at an operating point: two models.

1. **Palmgren** (Palmgren 1959, *Ball and Roller Bearing Engineering*, 3rd ed., as given by
   Harris & Kotzalas 2007, *Rolling Bearing Analysis* 5th ed.) — the classical empirical model:

   * load term (Harris & Kotzalas eqs. for M_l, table of z, y):
     ``M_l = f1 · P1 · d_m``,  ``f1 = z (P0/C0)^y`` with z, y per bearing type
     (deep groove: z = 0.0004–0.0006 (mid value 0.0005 used), y = 0.55; angular contact:
     z = 0.001, y = 0.33); P1 per type: deep groove ``P1 = max(3 Fa − 0.1 Fr, Fr)``,
     angular contact ``P1 = max(0.9 Fa cot α − 0.1 Fr, Fr)``; P0 the static equivalent load of
     ISO 76 (:func:`bearingsim.safety.equivalent_static_load`), C0 the static load rating of the bearing
     file or, when it gives none, the project's ISO 76 estimate (:func:`bearingsim.life.static_rating_estimate`);
   * viscous term: ``M_v = 1e-7 f0 (ν n)^(2/3) d_m³`` [N·mm, ν in mm²/s, n in rpm, d_m in mm]
     for ν n ≥ 2000, else ``M_v = 160e-7 f0 d_m³``; f0 per bearing type and lubrication
     method (table :data:`PALMGREN_F0`).

   An empirical estimate: its measured accuracy on the two checks of this project is in
   docs/friction.md (+37…+64 % on a jet-lubricated bearing at 1–2.5·10⁶ d_m n).
2. **Physics-based** — our own contact models at Jones' kinematics (the ball speeds of the
   quasi-static solution, :func:`bearingsim.statics.jones_harris.solve`):

   * per loaded contact, the sliced-contact kernel (:func:`bearingsim.contact.slices.contact_traction`,
     [S1] eqs. 1–5, called through :func:`bearingsim.lubrication.contact_at_jones_kinematics`) gives
     the power lost; run once with and once without the rolling viscous resistance (Zhou & Hoeprich
     1991 eq. 17) the difference is the **EHL rolling** loss, the rest is traction;
   * the traction power splits exactly into **spin** and **sliding**: with F_j the slice forces on
     the ball and v_j = s₀ + ω_rel × d_j the sliding velocities (ω_rel = ω_ball − ω_race, d_j from
     the contact centre), P_traction = −Σ F_j·v_j = −F·s₀ − ω_rel·M_c, M_c = Σ d_j × F_j; the spin
     part is −(ω_rel·n)(n·M_c) (n·M_c equals the kernel's moment about the ball centre along n,
     the centre lying on n); the remainder — sliding at the centre (zero under Jones' raceway
     control) plus the curvature (Heathcote) sliding across the ellipse — is **sliding**;
   * **drag** of the balls in the oil–air mixture, only when its oil volume fraction is known
     (``oil_volume_fraction``, or ``oil_flow`` through Parker's correlation
     :func:`parker_oil_fraction`): F = ½ c_d ρ_e (π D²/4) v², v = |ω_m| d_m/2 (Harris & Kotzalas
     2007 vol. 2, fluid drag on a ball orbiting in a stationary oil–air mist), c_d of a sphere by
     Schiller & Naumann (1933) for Re < 1000 and 0.44 above (Newton regime, Clift, Grace & Weber
     1978 table 5.2); ρ_e, μ_e the volume-weighted mixture of oil and air;
   * the torque on the rotating ring is the power over its speed, M = P/|ω| (the energy balance of
     a steady state with the other ring held), per source and in total.

3. **Cage and oil sources** (with ``cage`` and, for the jet, ``oil_flow``):

   * **cage land**: the guiding land is a concentric short journal bearing full of oil; Petroff's law
     (Petroff 1883; Hamrock, Schmid & Jacobson 2004, *Fundamentals of Machine Elements* 2nd ed., eq. 12.68):
     shear stress η Δω r/c over the area π d_L w_L, torque ``M_L = π η Δω d_L³ w_L / (4 c_L)``, power
     ``M_L |Δω|`` with Δω the cage's speed relative to the guiding ring (:func:`cage_land_torque`);
   * **cage pockets**: quasi-static cage balance (Harris & Kotzalas 2007 vol. 2 ch. 5, steady cage: the
     pocket forces of the Z balls drive the cage against its land torque), each pocket force
     ``Q_p = 2 M_L / (Z d_m)``; the ball's surface slides in its pocket at ``|ω_R| D/2``, friction
     coefficient μ_p (0.06, the ball–cage coefficient of seed 001), power ``Z μ_p Q_p |ω_R| D/2``
     (:func:`cage_pocket_power`);
   * **jet oil momentum**: the jet's oil enters with no tangential velocity and leaves the bearing with the
     balls' orbital velocity at the pitch circle; Euler's turbomachine equation (Dixon & Hall 2014, *Fluid
     Mechanics and Thermodynamics of Turbomachinery* 7th ed., eq. 2.12b) gives the work ``P = ṁ (ω_m d_m/2)²``,
     ṁ = ρ Q (:func:`jet_momentum_power`).

Everything SI inside ([N], [m], [N·m], [W], [rad/s], [K], [m²/s]); :func:`friction_summary` returns
a JSON-ready dict in SI.  Not modelled: seals, oil churning in a bath (only the ball drag), cage
windage, temperature rise of the contacts above the inlet temperature apart from the kernel's own
thermal corrections.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from .errors import InputError

#: Palmgren's f0 by bearing type and lubrication method (Harris & Kotzalas 2007, after Palmgren 1959).  STILL AS
#: RECALLED: a search of 2026-11 (docs/friction.md, "Sources") found no primary reproduction of the table; an open
#: code takes f0 = 0.75–2 for an oil-lubricated deep-groove bearing (no source given), nothing for angular contact:
#: (low, high) of the tabulated range; the mean is used.  "oil_jet" is the column "oil bath, vertical
#: shaft, or oil jet".  Paired / double-row angular contact sets use twice the single-row values (the
#: table's double-row column), which is what summing two single rows gives.
PALMGREN_F0 = {
    "deep_groove": {"grease": (0.7, 2.0), "oil_mist": (1.0, 1.0), "oil_bath": (2.0, 2.0), "oil_jet": (4.0, 4.0)},
    "angular_contact": {"grease": (2.0, 2.0), "oil_mist": (1.7, 1.7), "oil_bath": (3.3, 3.3),
                        "oil_jet": (6.6, 6.6)},
}
#: Palmgren's f1 = z (P0/C0)^y: (z_low, z_high, y) per bearing type (Harris & Kotzalas 2007, after Palmgren 1959).
#: STILL AS RECALLED (no primary reproduction found, docs/friction.md "Sources"); a second published variant for deep
#: groove, f1 = 0.0007 (P0/C0)^0.5 (older SKF catalogue form, used by an open code), gives 1.5–1.8 × our f1 at
#: P0/C0 = 0.2–0.01
PALMGREN_F1 = {"deep_groove": (0.0004, 0.0006, 0.55), "angular_contact": (0.001, 0.001, 0.33)}
METHODS = tuple(PALMGREN_F0["deep_groove"])
MODELS = ("both", "palmgren", "physical")

#: words for tables people read: each source of :func:`friction_summary` (its ``SOURCE_N_m`` / ``SOURCE_W`` keys)
SOURCE_LABELS = {"palmgren_load": "Palmgren load term M_l", "palmgren_viscous": "Palmgren viscous term M_v",
                 "palmgren_torque": "Palmgren total", "rolling": "rolling resistance of the EHL film",
                 "spin": "spin at the contacts", "sliding": "sliding (micro-slip) at the contacts",
                 "drag": "ball drag in the oil-air mixture", "cage_land": "cage land", "cage_pocket": "cage pockets",
                 "jet_momentum": "oil-jet momentum", "physical_torque": "physics-based total"}
#: words for :data:`MODELS` and the ``headline_model`` of :func:`friction_summary`
MODEL_LABELS = {"both": "Palmgren and physics-based", "palmgren": "Palmgren", "physical": "physics-based"}
#: words for the lubrication methods of :data:`METHODS` (Palmgren's f0 columns)
METHOD_LABELS = {"oil_bath": "oil bath", "oil_mist": "oil mist", "oil_jet": "oil jet", "grease": "grease"}

_R_AIR = 287.05  # specific gas constant of dry air [J/(kg K)]
_P_ATM = 101325.0  # [Pa]


# ------------------------------------------------------------------------------------------ Palmgren


def _row_bearings(bearing) -> list:
    """Single-row geometries of a bearing (the rows protocol of :mod:`bearingsim.geometry`)."""
    return [r.bearing for r in bearing.rows]


def _static_equivalent_load(fr: float, fa: float, kind: str, contact_angle: float) -> float:
    """ISO 76:2006 P0 of one row [N] by :func:`bearingsim.safety.equivalent_static_load`; an angular contact
    angle outside the standard's table (5°–45°) is clamped to it."""
    from .safety import equivalent_static_load

    a = min(max(contact_angle, math.radians(5.0)), math.radians(45.0)) if kind != "deep_groove" else 0.0
    return float(equivalent_static_load(fr, fa, a, 1, kind))


def palmgren_torque(bearing, fr: float, fa: float, speed: float, nu: float | None = None,
                    method: str = "oil_bath") -> dict:
    """Palmgren's friction torque of one row (module docstring, item 1).

    Parameters
    ----------
    bearing : BallBearing (one row)
    fr, fa : float  [N]  radial and axial load carried by the row
    speed : float  [rad/s]  speed of the rotating ring relative to the other
    nu : float | None  [m²/s]  kinematic viscosity at the operating temperature (None: no viscous term)
    method : lubrication method, one of :data:`METHODS`

    Returns a dict: ``load_N_m``, ``viscous_N_m`` (None without ν), and the factors used
    (f1, P1 [N], P0 [N], C0 [N], whether C0 was estimated, f0, ν n [mm²/s·rpm]).
    """
    if method not in METHODS:
        raise InputError("lubrication_method", f"unknown method {method!r}", f"use one of {', '.join(METHODS)}")
    from .life import nominal_contact_angle, static_rating_estimate

    kind = bearing.kind
    alpha = nominal_contact_angle(bearing)
    fr, fa = abs(float(fr)), abs(float(fa))
    c0 = float(getattr(bearing, "static_load_rating", 0.0) or 0.0)
    estimated = not c0 > 0
    if estimated:
        c0 = static_rating_estimate(bearing)[0]
    p0 = _static_equivalent_load(fr, fa, kind, alpha)
    z_lo, z_hi, y = PALMGREN_F1[kind]
    f1 = 0.5 * (z_lo + z_hi) * (p0 / c0) ** y
    if kind == "deep_groove":
        p1 = max(3.0 * fa - 0.1 * fr, fr)
    else:
        p1 = max(0.9 * fa / math.tan(alpha) - 0.1 * fr, fr) if alpha > 0 else max(3.0 * fa - 0.1 * fr, fr)
    dm = bearing.pitch_diameter
    out = {"load_N_m": f1 * p1 * dm, "viscous_N_m": None, "f1": f1, "P1_N": p1, "P0_N": p0,
           "C0_N": c0, "C0_estimated": estimated}
    if nu is not None:
        lo, hi = PALMGREN_F0[kind][method]
        f0 = 0.5 * (lo + hi)
        n_rpm = abs(speed) * 30.0 / math.pi
        nun = nu * 1e6 * n_rpm
        dm_mm = dm * 1e3
        if n_rpm == 0.0:
            mv = 0.0
        elif nun >= 2000.0:
            mv = 1e-7 * f0 * nun ** (2.0 / 3.0) * dm_mm**3 * 1e-3
        else:
            mv = 160e-7 * f0 * dm_mm**3 * 1e-3
        out.update(viscous_N_m=mv, f0=f0, f0_range=[lo, hi], nu_n_mm2_s_rpm=nun)
    return out


# ------------------------------------------------------------------------------------------ drag


def parker_oil_fraction(oil_flow: float, speed: float, pitch_diameter: float) -> float:
    """Volume fraction of oil in the oil–air mixture of a jet-lubricated bearing cavity [-].

    Parker (1984, NASA TP-2275) correlation as usually quoted: X [%] = 10^5.095 w^0.37 / (n d_m^1.7)
    with the oil flow w [cm³/min], the shaft speed n [rpm] and d_m [mm].  Inputs SI: oil_flow [m³/s],
    speed [rad/s], pitch_diameter [m].  The constant could not be checked against the report itself
    (docs/friction.md)."""
    if not (math.isfinite(oil_flow) and oil_flow > 0):
        raise InputError("oil_flow", f"must be positive, got {oil_flow!r}", 'e.g. "760 cm^3/min"')
    n = abs(speed) * 30.0 / math.pi
    if n == 0.0:
        return 1.0
    w = oil_flow * 1e6 * 60.0
    x = 10.0**5.095 * w**0.37 / (n * (pitch_diameter * 1e3) ** 1.7)
    return min(1.0, x / 100.0)


def sphere_drag_coefficient(re: float) -> float:
    """Drag coefficient of a sphere [-]: Schiller & Naumann (1933) 24/Re (1 + 0.15 Re^0.687) for Re < 1000,
    0.44 above (Newton regime; Clift, Grace & Weber 1978, table 5.2)."""
    if re <= 0.0:
        return 0.0
    if re < 1000.0:
        return 24.0 / re * (1.0 + 0.15 * re**0.687)
    return 0.44


def ball_drag_power(ball_diameter: float, pitch_diameter: float, orbital_speed: float, oil_fraction: float,
                    oil_density: float, oil_viscosity: float, temperature: float) -> float:
    """Power [W] lost by one ball orbiting at ``orbital_speed`` [rad/s] in a stationary oil–air mixture
    (module docstring, item 2): F v with F = ½ c_d ρ_e (π D²/4) v², v = |ω_m| d_m/2.

    oil_fraction [-] volume fraction of oil; oil_density [kg/m³], oil_viscosity [Pa·s] at
    ``temperature`` [K]; air as an ideal gas at 1 atm, viscosity by Sutherland's law."""
    v = abs(orbital_speed) * 0.5 * pitch_diameter
    rho_air = _P_ATM / (_R_AIR * temperature)
    mu_air = 1.716e-5 * (temperature / 273.15) ** 1.5 * (273.15 + 110.4) / (temperature + 110.4)
    rho = oil_fraction * oil_density + (1.0 - oil_fraction) * rho_air
    mu = oil_fraction * oil_viscosity + (1.0 - oil_fraction) * mu_air
    re = rho * v * ball_diameter / mu
    cd = sphere_drag_coefficient(re)
    return 0.5 * cd * rho * (0.25 * math.pi * ball_diameter**2) * v**3


# ------------------------------------------------------------------------------------------ cage and jet

#: ball–cage pocket friction coefficient [-] (seed 001: sliding friction μ = 0.06 between balls and cage)
POCKET_FRICTION = 0.06
CAGE_GUIDANCES = ("outer", "inner")


@dataclasses.dataclass(frozen=True)
class CageLand:
    """Guiding land of a cage (module docstring, item 3).  All [m].

    diameter : land diameter d_L; width : total land width w_L (both sides); clearance : radial clearance c_L
    guidance : ``"outer"`` (outer-ring land, held ring) or ``"inner"`` (inner-ring land, rotating ring)
    estimated : whether the numbers come from :meth:`estimate` (flagged in outputs)"""

    diameter: float
    width: float
    clearance: float
    guidance: str = "outer"
    estimated: bool = False

    def __post_init__(self):
        for name in ("diameter", "width", "clearance"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v > 0):
                raise InputError(f"cage.{name}", f"must be positive and finite, got {v!r}", 'e.g. "0.1 mm"')
        if self.guidance not in CAGE_GUIDANCES:
            raise InputError("cage.guidance", f"unknown guidance {self.guidance!r}",
                             f"use one of {', '.join(CAGE_GUIDANCES)}")

    @classmethod
    def estimate(cls, bearing, guidance: str = "outer") -> "CageLand":
        """ESTIMATE from the ball set: land at d_m ± 0.6 D (the ring shoulders of an angular contact ring at
        about 0.3 D below the ball's equator), total width D (two lands of D/2), radial clearance 0.25 % of d_L
        (diametral guiding clearance 0.5 % of the land diameter, the middle of the 0.3–0.8 % usual for
        machined cages).  Rules of thumb, no source to cite: flagged ``estimated``."""
        d, dm = bearing.ball_diameter, bearing.pitch_diameter
        dl = dm + 0.6 * d if guidance == "outer" else dm - 0.6 * d
        return cls(diameter=dl, width=d, clearance=0.0025 * dl, guidance=guidance, estimated=True)


def cage_land_torque(land: CageLand, relative_speed: float, viscosity: float) -> float:
    """Petroff torque of the cage land [N·m]: π η Δω d_L³ w_L / (4 c_L) (module docstring, item 3).

    relative_speed : cage speed relative to the guiding ring [rad/s]; viscosity : η [Pa·s]"""
    return math.pi * viscosity * abs(relative_speed) * land.diameter**3 * land.width / (4.0 * land.clearance)


def cage_pocket_power(land_torque: float, ball_count: int, pitch_diameter: float, ball_diameter: float,
                      spin_speed: float, friction: float = POCKET_FRICTION) -> float:
    """Sliding power in the Z pockets [W]: Z μ_p Q_p |ω_R| D/2, Q_p = 2 M_L/(Z d_m) (module docstring, item 3).

    land_torque [N·m]; pitch_diameter, ball_diameter [m]; spin_speed ω_R of the ball about its own axis [rad/s]"""
    q_p = 2.0 * land_torque / (ball_count * pitch_diameter)
    return ball_count * friction * q_p * abs(spin_speed) * 0.5 * ball_diameter


def jet_momentum_power(oil_flow: float, oil_density: float, orbital_speed: float, pitch_diameter: float) -> float:
    """Work done on the jet's oil [W]: ṁ (ω_m d_m/2)², ṁ = ρ Q (Euler's equation; module docstring, item 3).

    oil_flow Q [m³/s]; oil_density [kg/m³]; orbital_speed ω_m [rad/s]; pitch_diameter [m]"""
    if not (math.isfinite(oil_flow) and oil_flow >= 0):
        raise InputError("oil_flow", f"must not be negative, got {oil_flow!r}", 'e.g. "760 cm^3/min"')
    v = abs(orbital_speed) * 0.5 * pitch_diameter
    return oil_density * oil_flow * v * v


def cage_and_jet_losses(result, lubricant, temperature: float, cage: "CageLand | str | None" = None,
                        oil_flow: float | None = None) -> dict:
    """Cage land, cage pocket and jet momentum power [W] of a solved bearing (module docstring, item 3).

    cage : a :class:`CageLand`, ``"estimate"`` (:meth:`CageLand.estimate`, outer-land guided) or None (no
    cage terms); oil_flow [m³/s] (None: no jet term).  The cage speed is the mean orbital speed of the balls
    of each row; the land film has the oil's viscosity at ``temperature`` [K].
    Returns {"cage_land_W", "cage_pocket_W", "jet_momentum_W", "cage_land_estimated"}."""
    from .lubricants import get_lubricant

    lub_obj = get_lubricant(lubricant)
    eta, rho = lub_obj.dynamic_viscosity(temperature), lub_obj.density(temperature)
    balls = result.balls
    omega = float(result.speed)
    out = {"cage_land_W": None, "cage_pocket_W": None, "jet_momentum_W": None, "cage_land_estimated": None}
    rows = _row_bearings(result.bearing)
    row_of = np.asarray(balls["row"], dtype=int)
    wm_all = np.asarray(balls["orbital_speed_rad_s"], dtype=float)
    wr_all = np.asarray(balls["spin_speed_rad_s"], dtype=float)
    if cage is not None:
        land_w = pocket_w = 0.0
        estimated = False
        for k, rb in enumerate(rows):
            sel = row_of == k
            if not sel.any():
                continue
            land = CageLand.estimate(rb) if isinstance(cage, str) and cage == "estimate" else cage
            if not isinstance(land, CageLand):
                raise InputError("cage", f"expected a CageLand or 'estimate', got {cage!r}", 'use cage="estimate"')
            estimated = estimated or land.estimated
            wc = float(np.nanmean(wm_all[sel]))
            dw = wc - (omega if land.guidance == "inner" else 0.0)
            m_l = cage_land_torque(land, dw, eta)
            land_w += m_l * abs(dw)
            pocket_w += cage_pocket_power(m_l, rb.ball_count, rb.pitch_diameter, rb.ball_diameter,
                                          float(np.nanmean(np.abs(wr_all[sel]))))
        out.update(cage_land_W=land_w, cage_pocket_W=pocket_w, cage_land_estimated=estimated)
    if oil_flow is not None:
        share = float(oil_flow) / max(len(rows), 1)
        out["jet_momentum_W"] = sum(
            jet_momentum_power(share, rho, float(np.nanmean(wm_all[row_of == k])), rb.pitch_diameter)
            for k, rb in enumerate(rows) if (row_of == k).any())
    return out


# ------------------------------------------------------------------------------------------ physics


def contact_losses(result, lubricant, temperature: float, roughness: float = 0.1e-6, n_slices: int = 10,
                   traction_model: str = "mixed", starvation_factor: float = 1.0) -> dict:
    """Power lost [W] in all loaded ball–race contacts at Jones' kinematics, split into EHL rolling,
    spin and sliding (module docstring, item 2).  Returns {"rolling_W", "spin_W", "sliding_W"}."""
    from .contact import hertz
    from .contact import slices as S
    from .lubricants import get_lubricant
    from .lubrication import contact_at_jones_kinematics

    lub_obj = get_lubricant(lubricant)
    lub_obj.check_temperature(temperature)
    rows = _row_bearings(result.bearing)
    balls = result.balls
    omega = float(result.speed)
    packs: dict = {}
    tot = {"rolling_W": 0.0, "spin_W": 0.0, "sliding_W": 0.0}
    for j in range(len(balls["azimuth_rad"])):
        rb = rows[int(balls["row"][j])]
        d, dm = rb.ball_diameter, rb.pitch_diameter
        e_eff = rb.effective_modulus
        ai, ao = float(balls["inner_contact_angle_rad"][j]), float(balls["outer_contact_angle_rad"][j])
        wm = float(balls["orbital_speed_rad_s"][j])
        wr = float(balls["spin_speed_rad_s"][j])
        beta = float(balls["pitch_angle_rad"][j])
        for inner in (True, False):
            q = float(balls["inner_load_N" if inner else "outer_load_N"][j])
            if not q > 0:
                continue
            alpha = ai if inner else ao
            f = rb.inner_conformity if inner else rb.outer_conformity
            rx, ry = hertz.raceway_radii(d, dm, f, alpha, inner)
            hz = hertz.point_contact_exact(q, rx, ry, e_eff)
            key = (id(rb), inner, round(alpha, 9))
            if key not in packs:
                packs[key] = tuple(S.pack_lubrication_parameters(
                    lub_obj, temperature, e_eff, rx, ry, roughness, model=traction_model,
                    starvation_factor=starvation_factor, rolling_resistance=rr) for rr in (True, False))
            lub_rr, lub_t = packs[key]
            r_dev = S.deformed_surface_radius(d, f * d)
            k_all, _, _ = contact_at_jones_kinematics(lub_rr, q, hz.a, hz.b, r_dev, d, dm, ai, ao, omega, wm, wr,
                                                      beta, inner, n_slices)
            k_t, _, _ = contact_at_jones_kinematics(lub_t, q, hz.a, hz.b, r_dev, d, dm, ai, ao, omega, wm, wr,
                                                    beta, inner, n_slices)
            # spin: relative angular velocity of ball and race along the normal (race -> ball)
            s, c = math.sin(alpha), math.cos(alpha)
            n = np.array([s, c, 0.0]) if inner else np.array([-s, -c, 0.0])
            w_ball = wr * np.array([math.cos(beta), -math.sin(beta), 0.0])
            w_race = np.array([(omega - wm) if inner else -wm, 0.0, 0.0])
            p_spin = -float((w_ball - w_race) @ n) * float(k_t[3:6] @ n)
            p_t = float(k_t[9])
            tot["rolling_W"] += float(k_all[9]) - p_t
            tot["spin_W"] += p_spin
            tot["sliding_W"] += p_t - p_spin
    return tot


def drag_loss(result, lubricant, temperature: float, oil_volume_fraction: float | None = None,
              oil_flow: float | None = None) -> tuple[float, float | None]:
    """(drag power [W], oil volume fraction used [-] or None) of all balls (module docstring, item 2).
    Zero and None when neither the fraction nor the oil flow [m³/s] is given."""
    from .lubricants import get_lubricant

    if oil_volume_fraction is None and oil_flow is None:
        return 0.0, None
    lub_obj = get_lubricant(lubricant)
    rows = _row_bearings(result.bearing)
    balls = result.balls
    rho, eta = lub_obj.density(temperature), lub_obj.dynamic_viscosity(temperature)
    total = 0.0
    used = None
    for j in range(len(balls["azimuth_rad"])):
        rb = rows[int(balls["row"][j])]
        if oil_volume_fraction is not None:
            x = float(oil_volume_fraction)
            if not (math.isfinite(x) and 0.0 <= x <= 1.0):
                raise InputError("oil_volume_fraction", f"must lie in [0, 1], got {x!r}", "e.g. 0.001")
        else:
            x = parker_oil_fraction(float(oil_flow), float(result.speed), rb.pitch_diameter)
        used = x
        wm = float(balls["orbital_speed_rad_s"][j])
        if not math.isfinite(wm):
            continue
        total += ball_drag_power(rb.ball_diameter, rb.pitch_diameter, wm, x, rho, eta, temperature)
    return total, used


# ------------------------------------------------------------------------------------------ summary


def _row_loads(result) -> list[tuple[float, float]]:
    """(Fr, Fa) [N] carried by each row: from the solve's row forces when stored, else the external loads."""
    rf = getattr(result, "row_forces", None)
    if rf is not None and len(rf):
        return [(float(math.hypot(r[1], r[2])), float(abs(r[0]))) for r in np.asarray(rf)]
    ld = result.loads
    return [(float(math.hypot(ld.fr_y, ld.fr_z)), float(abs(ld.fa)))]


def friction_summary(result, lubricant=None, temperature: float | None = None, *, model: str = "both",
                     lubrication_method: str = "oil_bath", roughness: float = 0.1e-6, n_slices: int = 10,
                     traction_model: str = "mixed", oil_volume_fraction: float | None = None,
                     oil_flow: float | None = None, cage: "CageLand | str | None" = None) -> dict:
    """Friction torque [N·m] and power loss [W] of a solved bearing, per source (all SI, JSON-ready).

    Parameters
    ----------
    result : StaticResult from :func:`bearingsim.statics.jones_harris.solve`
    lubricant : library name, TOML path or Lubricant; None: only Palmgren's load term (with a note)
    temperature : float  [K]  oil (inlet) temperature; required with a lubricant
    model : "both" | "palmgren" | "physical"
    lubrication_method : Palmgren's f0 column, one of :data:`METHODS`
    roughness : float  [m]  composite rms roughness (physical model)
    n_slices, traction_model : of the sliced-contact kernel (physical model)
    oil_volume_fraction : float [-] oil in the oil–air mixture (ball drag); or
    oil_flow : float  [m³/s]  jet oil flow, giving the fraction by :func:`parker_oil_fraction` and the jet
        momentum loss (:func:`jet_momentum_power`)
    cage : a :class:`CageLand`, ``"estimate"`` or None: the cage land and pocket losses (module docstring, item 3)

    Returns
    -------
    dict
        ``friction_torque_N_m`` and ``power_loss_W`` (Palmgren's total for "both" and
        "palmgren", the physical total for "physical"), ``headline_model``, Palmgren's
        ``palmgren_load_N_m``, ``palmgren_viscous_N_m``, ``palmgren_torque_N_m``, ``palmgren_power_W``,
        the physical ``rolling_N_m``, ``spin_N_m``, ``sliding_N_m``, ``drag_N_m``, ``cage_land_N_m``,
        ``cage_pocket_N_m``, ``jet_momentum_N_m`` (None when not computed), ``physical_torque_N_m``,
        ``physical_power_W`` and the same per source in W (``rolling_W`` …), the factors used
        (``palmgren_rows``) and ``notes``.  Parts not computed are None.
    """
    if model not in MODELS:
        raise InputError("model", f"unknown friction model {model!r}", f"use one of {', '.join(MODELS)}")
    if lubrication_method not in METHODS:
        raise InputError("lubrication_method", f"unknown method {lubrication_method!r}",
                         f"use one of {', '.join(METHODS)}")
    omega = abs(float(result.speed))
    notes: list[str] = []
    lub_obj = None
    if lubricant is not None:
        from .lubricants import get_lubricant

        if temperature is None:
            raise InputError("temperature", "a friction estimate with a lubricant needs its temperature",
                             'e.g. "60 degC"')
        lub_obj = get_lubricant(lubricant)
        lub_obj.check_temperature(temperature)
    out: dict = {"model": model, "speed_rad_s": float(result.speed), "converged": bool(result.converged),
                 "lubricant": None if lub_obj is None else lub_obj.name,
                 "temperature_K": None if temperature is None else float(temperature),
                 "lubrication_method": lubrication_method}
    for k in ("palmgren_load_N_m", "palmgren_viscous_N_m", "palmgren_torque_N_m", "palmgren_power_W",
              "rolling_N_m", "spin_N_m", "sliding_N_m", "drag_N_m", "physical_torque_N_m", "physical_power_W",
              "rolling_W", "spin_W", "sliding_W", "drag_W", "oil_volume_fraction", "cage_land_N_m",
              "cage_pocket_N_m", "jet_momentum_N_m", "cage_land_W", "cage_pocket_W", "jet_momentum_W",
              "cage_land_estimated"):
        out[k] = None
    if not result.converged:
        notes.append("the static solution did not converge: the friction figures rest on a non-equilibrium state")

    if model in ("both", "palmgren"):
        nu = None if lub_obj is None else lub_obj.kinematic_viscosity(temperature)
        rows_out = []
        ml = mv = 0.0
        for rb, (fr, fa) in zip(_row_bearings(result.bearing), _row_loads(result)):
            p = palmgren_torque(rb, fr, fa, omega, nu, lubrication_method)
            rows_out.append(p)
            ml += p["load_N_m"]
            mv += p["viscous_N_m"] or 0.0
            if p["C0_estimated"] and not any(getattr(rb, 'name', 'row') in n_ for n_ in notes):
                notes.append(f"C0 of {getattr(rb, 'name', 'row')} estimated from its ball set by the ISO 76 "
                             f"definition ({p['C0_N']:.0f} N): the file gives none")
        out["palmgren_rows"] = rows_out
        out["palmgren_load_N_m"] = ml
        if lub_obj is None:
            notes.append("no lubricant given: only Palmgren's load-dependent torque (no viscous term, no "
                         "physics-based model)")
            out["palmgren_torque_N_m"] = ml
        else:
            out["palmgren_viscous_N_m"] = mv
            out["palmgren_torque_N_m"] = ml + mv
        out["palmgren_power_W"] = out["palmgren_torque_N_m"] * omega

    if model in ("both", "physical") and lub_obj is not None:
        if omega == 0.0:
            notes.append("no rotation: the physics-based losses are zero")
            c = {"rolling_W": 0.0, "spin_W": 0.0, "sliding_W": 0.0}
            drag, x = 0.0, None
            extra = {}
        else:
            c = contact_losses(result, lub_obj, temperature, roughness, n_slices, traction_model)
            drag, x = drag_loss(result, lub_obj, temperature, oil_volume_fraction, oil_flow)
            extra = cage_and_jet_losses(result, lub_obj, temperature, cage, oil_flow)
            if extra["cage_land_estimated"]:
                notes.append("cage land geometry estimated from the ball set (friction.CageLand.estimate)")
        if x is None:
            notes.append("ball drag not computed: give the oil volume fraction of the oil-air mixture or the "
                         "jet oil flow")
        out.update(c)
        out["drag_W"] = drag if x is not None else None
        out["oil_volume_fraction"] = x
        out.update(extra)
        total = c["rolling_W"] + c["spin_W"] + c["sliding_W"] + drag + sum(
            extra.get(f"{k}_W") or 0.0 for k in ("cage_land", "cage_pocket", "jet_momentum"))
        out["physical_power_W"] = total
        for src in ("rolling", "spin", "sliding", "drag", "cage_land", "cage_pocket", "jet_momentum"):
            w = out[f"{src}_W"]
            out[f"{src}_N_m"] = None if w is None else (w / omega if omega > 0 else 0.0)
        out["physical_torque_N_m"] = total / omega if omega > 0 else 0.0
    elif model == "physical":
        notes.append("the physics-based model needs a lubricant and its temperature")

    if model == "physical":
        out["headline_model"] = "physical"
        out["friction_torque_N_m"] = out["physical_torque_N_m"]
        out["power_loss_W"] = out["physical_power_W"]
    else:
        out["headline_model"] = "palmgren"
        out["friction_torque_N_m"] = out["palmgren_torque_N_m"]
        out["power_loss_W"] = out["palmgren_power_W"]
    out["notes"] = notes
    return out


__all__ = ["friction_summary", "palmgren_torque", "contact_losses", "drag_loss", "ball_drag_power",
           "CageLand", "cage_land_torque", "cage_pocket_power", "jet_momentum_power", "cage_and_jet_losses",
           "POCKET_FRICTION", "CAGE_GUIDANCES",
           "sphere_drag_coefficient", "parker_oil_fraction", "PALMGREN_F0", "PALMGREN_F1", "METHODS", "MODELS",
           "SOURCE_LABELS", "MODEL_LABELS", "METHOD_LABELS"]
