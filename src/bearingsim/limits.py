"""Plausibility limits of quasi-static results: warnings and map flags.

A result past one of these limits is still the model's answer, but it lies where the model (or the
bearing) does not hold; it carries a warning (``StaticResult.warnings``, the ``warnings`` list of the
JSON, the readable output) and, in maps, a bit in the integer variable ``warning_flags``.

Limits and their sources:

* :data:`STATIC_PRESSURE_LIMIT` = 4.2 GPa — maximum Hertz contact pressure at which ISO 76:2006 defines
  the basic static load rating C₀ of radial and thrust ball bearings (4 600 MPa for self-aligning ball
  bearings, 4 200 MPa for all other ball bearings; the permanent deformation is then about 1e-4 of the
  ball diameter).  Above it the contact deforms plastically and the elastic (Hertz) model overestimates
  the stiffness.
* :data:`CONTACT_ANGLE_LIMIT` = 80° — a contact angle at which the contact ellipse of any catalogue
  groove reaches the land or shoulder (shoulder heights are 0.2–0.3 D for angular contact rings,
  Harris & Kotzalas 2007 vol. 1 ch. 2 "truncation of the contact ellipse"); the torus model lets the
  contact run on.  A loaded contact at |α| ≥ 90° is outside either ring and is reported as not
  converged by the solver itself (status 6), not as a warning.
* limiting speed — only when the bearing gives one (``bearing.limiting_speed`` [rad/s], > 0).
* :data:`MAX_NDM` = 1e7 mm·rpm — a speed factor n·d_m an order of magnitude beyond the fastest hybrid
  spindle bearings (≈ 3.5e6 mm·rpm, SKF super-precision catalogue speed ratings): the quasi-static model
  is not asked to answer there; :func:`check_speed` raises :class:`~bearingsim.errors.InputError`.
* lift-off — at speed, balls without load at the inner raceway that carry load at rest under the same
  loads (:func:`lift_off_count`: the count of unloaded balls at speed beyond the count at rest): they are
  held against the outer ring by their centrifugal force alone and are driven by the cage, not by rolling
  (skidding risk; Harris & Kotzalas 2007 vol. 2 ch. 3).  A partial load zone that the loads give at rest
  as well (a radial load with clearance, a hub row under a moment) is the normal state and is not flagged.

Flag bits of ``warning_flags`` (CF convention ``flag_masks``/``flag_meanings``, :func:`cf_attributes`):
"""

from __future__ import annotations

import math

import numpy as np

from .errors import InputError

STATIC_PRESSURE_LIMIT = 4.2e9  #: [Pa] ISO 76:2006 (ball bearings other than self-aligning)
CONTACT_ANGLE_LIMIT = math.radians(80.0)  #: [rad] contact ellipse at the shoulder (Harris & Kotzalas vol. 1 ch. 2)
MAX_NDM = 1.0e7  #: [mm·rpm] speed factor beyond any rolling bearing
#: [rad] a clearance that turns an angular contact row's free contact angle by more than 10° is implausible (the
#: clearances of angular contact rows are a few µm: the contact angle is the designed one)
FREE_ANGLE_SHIFT = math.radians(10.0)

#: bit constants of ``warning_flags`` (int32 bitmask); the names are the CF ``flag_meanings``
FLAG_PRESSURE = 1  #: maximum contact pressure above STATIC_PRESSURE_LIMIT
FLAG_CONTACT_ANGLE = 2  #: a loaded contact angle beyond CONTACT_ANGLE_LIMIT (or the shoulder)
FLAG_SPEED = 4  #: speed above the bearing's limiting speed
FLAG_LIFT_OFF = 8  #: at speed, a ball carries no load at the inner raceway while others do
FLAG_NOT_EQUILIBRIUM = 16  #: the point is not a verified equilibrium (converged is 0)
FLAGS = {
    "pressure_above_static_limit": FLAG_PRESSURE,
    "contact_angle_past_80deg": FLAG_CONTACT_ANGLE,
    "speed_above_limiting_speed": FLAG_SPEED,
    "ball_lift_off": FLAG_LIFT_OFF,
    "not_converged": FLAG_NOT_EQUILIBRIUM,
}
__doc__ += "\n".join(f"    {v:3d}  {k}" for k, v in FLAGS.items()) + "\n"


def cf_attributes() -> dict:
    """netCDF attributes of the ``warning_flags`` variable (CF conventions §3.5, flag_masks/flag_meanings)."""
    return {"flag_masks": np.array(list(FLAGS.values()), dtype=np.int32),
            "flag_meanings": " ".join(FLAGS), "long_name": "plausibility warnings (bitmask, bearingsim.limits)",
            "units": "1"}


def limiting_speed(bearing) -> float:
    """The bearing's limiting speed [rad/s], 0 when it gives none (a bearing set: the smallest of its rows)."""
    v = getattr(bearing, "limiting_speed", 0.0) or 0.0
    if not v:
        vals = [r.bearing.limiting_speed for r in bearing.rows]
        vals = [x for x in vals if x > 0]
        v = min(vals) if vals else 0.0
    try:
        v = float(v)
    except (TypeError, ValueError):
        return 0.0
    return v if math.isfinite(v) and v > 0 else 0.0


def check_speed(speed: float, pitch_diameter: float, field: str = "speed") -> None:
    """Refuse |speed| with n·d_m above :data:`MAX_NDM` (InputError naming ``field``); speed [rad/s], d_m [m]."""
    ndm = abs(speed) * 30.0 / math.pi * pitch_diameter * 1e3
    if ndm > MAX_NDM:
        nmax = MAX_NDM / (pitch_diameter * 1e3)
        raise InputError(field, f"{abs(speed) * 30 / math.pi:.4g} rpm gives n·d_m = {ndm:.3g} mm·rpm, beyond any "
                         f"rolling bearing (limit {MAX_NDM:.0e} mm·rpm)",
                         f"give at most {nmax:.0f} rpm for this bearing")


def flags_from_summary(p_inner, p_outer, alpha_extremes, speed, lift_off, converged, vlim: float = 0.0) -> np.ndarray:
    """Bitmask per point from the batch summaries (arrays over points, SI): maximum pressures [Pa],
    contact-angle extremes (any number of arrays [rad], NaN where no ball is loaded), speed [rad/s],
    lift-off flags (bool; the caller applies the at-speed rule), converged flags (bool), limiting speed
    vlim [rad/s] (0: none)."""
    p = np.fmax(np.nan_to_num(np.asarray(p_inner, dtype=float)), np.nan_to_num(np.asarray(p_outer, dtype=float)))
    flags = np.where(p > STATIC_PRESSURE_LIMIT, FLAG_PRESSURE, 0).astype(np.int32)
    ang = np.zeros(p.shape, dtype=bool)
    for a in alpha_extremes:
        ang |= np.abs(np.nan_to_num(np.asarray(a, dtype=float))) > CONTACT_ANGLE_LIMIT
    flags |= np.where(ang, FLAG_CONTACT_ANGLE, 0).astype(np.int32)
    if vlim > 0:
        flags |= np.where(np.abs(np.asarray(speed, dtype=float)) > vlim, FLAG_SPEED, 0).astype(np.int32)
    flags |= np.where(np.asarray(lift_off, dtype=bool), FLAG_LIFT_OFF, 0).astype(np.int32)
    flags |= np.where(np.asarray(converged, dtype=bool), 0, FLAG_NOT_EQUILIBRIUM).astype(np.int32)
    return flags


def static_warnings(result, rest_inner_load=None) -> list[str]:
    """Readable warnings of a :class:`~bearingsim.statics.jones_harris.StaticResult` past the limits above;
    ``rest_inner_load`` : float[n_balls] the inner-raceway ball loads [N] of the equilibrium at rest under the
    same loads (lift-off is judged against it; None: no lift-off warning)."""
    out = []
    b = result.balls
    if not len(b.get("azimuth_rad", ())):
        return out
    pmax = float(max(np.max(b["inner_max_pressure_Pa"]), np.max(b["outer_max_pressure_Pa"])))
    if pmax > STATIC_PRESSURE_LIMIT:
        out.append(f"maximum contact pressure {pmax / 1e9:.3g} GPa exceeds the static limit "
                   f"{STATIC_PRESSURE_LIMIT / 1e9:.1f} GPa of ball bearings (ISO 76:2006): permanent deformation; "
                   "the elastic model no longer holds")
    angles = []
    for key, load in (("inner_contact_angle_rad", "inner_load_N"), ("outer_contact_angle_rad", "outer_load_N")):
        loaded = b[load] > 0
        if loaded.any():
            angles.append(float(np.max(np.abs(b[key][loaded]))))
    if angles and max(angles) > CONTACT_ANGLE_LIMIT:
        out.append(f"contact angle {math.degrees(max(angles)):.1f}° is past {math.degrees(CONTACT_ANGLE_LIMIT):.0f}°: "
                   "the contact ellipse runs over the groove shoulder (the model ignores the shoulder)")
    vlim = limiting_speed(result.bearing)
    if vlim > 0 and abs(result.speed) > vlim:
        out.append(f"speed {abs(result.speed) * 30 / math.pi:.0f} rpm exceeds the bearing's limiting speed "
                   f"{vlim * 30 / math.pi:.0f} rpm")
    for row in getattr(result.bearing, "rows", ()):
        rb = row.bearing
        if rb.kind == "angular_contact" and rb.diametral_clearance > 0:
            # free contact angle of the row with its clearance: cos α_f = cos α₀ − P_d / (2A) (Harris & Kotzalas
            # 2007 vol. 1 eq. 2.10 about the nominal angle)
            big_a = rb.total_curvature_distance
            af = math.acos(max(-1.0, min(1.0, math.cos(rb.contact_angle) - rb.diametral_clearance / (2 * big_a))))
            if af - rb.contact_angle > FREE_ANGLE_SHIFT:
                out.append(f"the diametral clearance {rb.diametral_clearance * 1e6:.4g} µm of the angular contact row "
                           f"{rb.name} turns its free contact angle from {math.degrees(rb.contact_angle):.1f}° to "
                           f"{math.degrees(af):.1f}°: an implausible clearance (check the value and its unit)")
                break
    qi = b["inner_load_N"]
    if rest_inner_load is not None and result.speed != 0 and np.any(qi > 0):
        nlift = lift_off_count(int(np.sum(~(qi > 0))), int(np.sum(~(np.asarray(rest_inner_load) > 0))))
        if nlift:
            out.append(f"{nlift} of {len(qi)} balls lifted off the inner raceway by their centrifugal force: "
                       f"loaded at rest under the same loads, unloaded at {abs(result.speed) * 30 / math.pi:.0f} "
                       "rpm (driven by the cage, skidding risk)")
    return out


def lift_off_count(free_at_speed, free_at_rest):
    """Balls lifted off by speed: balls without inner-raceway load at speed beyond those without it at rest
    under the same loads (the partial load zone of a radial load with clearance), ≥ 0 (ints or int arrays)."""
    return np.maximum(np.asarray(free_at_speed) - np.asarray(free_at_rest), 0)
