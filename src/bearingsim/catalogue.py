"""Catalogue estimates: the internal geometry of a ball bearing from its boundary dimensions and published
load ratings (ISO 281:2007 and ISO 76:2006 solved for the ball set).

Manufacturers publish d, D, B and the basic load ratings C (dynamic) and C₀ (static), rarely the ball set.
Both ratings are standard formulas of the ball set, so the ball set can be recovered from them:

* ISO 281:2007 eq. (7), radial ball bearings with D_w ≤ 25.4 mm [N, mm]:
      C_r = b_m f_c (i cos α)^0.7 Z^(2/3) D_w^1.8
  and for D_w > 25.4 mm (eq. 8): C_r = 3.647 b_m f_c (i cos α)^0.7 Z^(2/3) D_w^1.4,
  with b_m = 1.3 (ISO 281:2007 table 1, radial ball bearings other than filling-slot and insert bearings) and
  f_c from ISO 281:2007 table 2 (column: single-row radial contact groove ball bearings and single- and
  double-row angular contact groove ball bearings) as a function of γ = D_w cos α / D_pw, linearly
  interpolated as the standard prescribes (:data:`FC_TABLE`);
* ISO 76:2006 eq. (1), radial ball bearings [N, mm]:
      C₀r = f₀ i Z D_w² cos α
  with f₀ from ISO 76:2006 table 1 (radial contact groove and angular contact groove ball bearings), also a
  function of γ (:data:`F0_TABLE`).

Method (:func:`estimate_ball_set`): the pitch diameter is taken as D_pw ≈ (d + D)/2; every pair of a standard
ball size (:data:`INCH_BALLS`: inch sizes in 1/64 in steps to 1/2 in, 1/32 in to 1 in, 1/16 in to
1 1/2 in, the usual sizes of bearing balls; whole millimetres, :data:`METRIC_BALLS`, only if no inch ball set
reproduces both ratings within about 2 %) in
0.20–0.40 (D − d) and an integer ball count Z that fits on the pitch circle with a cage bridge,
D_pw sin(π/Z) ≥ (1 + gap) D_w (gap = 0.04 D_w, ASSUMED), is scored by

      s = ln²(C_ISO / C_published) + ln²(C₀,ISO / C₀,published)

and the lowest score wins.  The two ratings scale differently with the ball set (C₀ ∝ Z D_w², C ∝ Z^(2/3)
D_w^1.8), so together they fix both Z and D_w when the manufacturer's ratings follow the standards; a
manufacturer factor on C (e.g. improved steels) biases the estimate, and the residuals of the chosen ball set
(:class:`BallSetEstimate` ``c_error``, ``c0_error``) say how well the published ratings were reproduced.

Groove conformities are not in any rating; the ISO/TS 16281 values f_i = 0.52, f_o = 0.53 for radial ball
bearings (also Harris & Kotzalas 2007 vol. 1 ch. 2: 0.515–0.53 typical) are used (ASSUMED).  The radial
internal clearance of a deep-groove bearing is the mid-value of its CN (normal) group
(:data:`CN_CLEARANCE`, NSK CAT. No. E1102e table 9.9, the ISO 5753-1 values).

Validation against ball sets that are public: tests/validation/test_catalogue_estimate.py.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .errors import InputError

#: b_m of ISO 281:2007 table 1 for radial ball bearings (not filling-slot, not insert bearings) [-]
B_M = 1.3

#: ISO 281:2007 table 2, f_c of single-row radial contact groove and angular contact groove ball bearings
#: vs γ = D_w cos α / D_pw (units N, mm); γ = 0.01 … 0.40 in steps of 0.01
FC_TABLE = (
    np.round(np.arange(1, 41) * 0.01, 2),
    np.array([29.1, 35.8, 40.3, 43.8, 46.7, 49.1, 51.1, 52.8, 54.3, 55.5,
              56.6, 57.5, 58.2, 58.8, 59.3, 59.6, 59.8, 59.9, 60.0, 59.9,
              59.8, 59.6, 59.3, 59.0, 58.6, 58.2, 57.7, 57.1, 56.6, 56.0,
              55.3, 54.6, 53.9, 53.2, 52.4, 51.7, 50.9, 50.0, 49.2, 48.4]),
)

#: ISO 76:2006 table 1, f₀ of radial contact groove and angular contact groove ball bearings vs γ
#: (units N, mm); γ = 0.00 … 0.40 in steps of 0.01
F0_TABLE = (
    np.round(np.arange(0, 41) * 0.01, 2),
    np.array([14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5,
              16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4, 14.2,
              14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8,
              11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0, 9.8, 9.6, 9.4]),
)

#: radial internal clearance group CN of single-row deep groove ball bearings [µm] by nominal bore
#: d [mm]: (over, incl, min, max) — NSK Rolling Bearings CAT. No. E1102e table 9.9 (ISO 5753-1)
CN_CLEARANCE = (
    (0.0, 10.0, 2, 13), (10.0, 18.0, 3, 18), (18.0, 24.0, 5, 20), (24.0, 30.0, 5, 20), (30.0, 40.0, 6, 20),
    (40.0, 50.0, 6, 23), (50.0, 65.0, 8, 28), (65.0, 80.0, 10, 30), (80.0, 100.0, 12, 36),
    (100.0, 120.0, 15, 41), (120.0, 140.0, 18, 48), (140.0, 160.0, 18, 53), (160.0, 180.0, 20, 61),
    (180.0, 200.0, 25, 71),
)

#: conformities used for every estimated entry (ISO/TS 16281:2008 usual values for radial ball bearings)
INNER_CONFORMITY = 0.52
OUTER_CONFORMITY = 0.53

INCH = 25.4e-3


def _inch_balls() -> np.ndarray:
    """Inch ball diameters [m]: 1/64 in steps from 1/16 in to 1/2 in, 1/32 in to 1 in, 1/16 in to 1.5 in."""
    inch = [k / 64 for k in range(4, 33)] + [k / 32 for k in range(17, 33)] + [k / 16 for k in range(17, 25)]
    return np.round(np.array(inch) * INCH, 9)


#: standard inch ball diameters [m], tried first (:func:`estimate_ball_set`)
INCH_BALLS = _inch_balls()
#: whole-millimetre ball diameters 3–40 mm [m], tried when no inch ball set reproduces both ratings within 2 %
METRIC_BALLS = np.arange(3, 41) * 1e-3
#: all standard ball diameters [m]
STANDARD_BALLS = np.unique(np.concatenate([INCH_BALLS, METRIC_BALLS]))
#: a fit is accepted from the inch sizes alone when its score is below this (both ratings within ~2 %)
ACCEPT_SCORE = 0.02**2


def _table(table, gamma: float, what: str) -> float:
    x, y = table
    if not (math.isfinite(gamma) and x[0] - 1e-12 <= gamma <= x[-1] + 1e-12):
        raise InputError("ball set", f"γ = D_w cos α / D_pw = {gamma:.4g} is outside the {what} table "
                         f"({x[0]:g}–{x[-1]:g})", "check ball diameter, pitch diameter and contact angle")
    return float(np.interp(gamma, x, y))


def factor_fc(gamma: float) -> float:
    """f_c of ISO 281:2007 table 2 at γ = D_w cos α / D_pw, linear interpolation [N/mm^1.8 units]."""
    return _table(FC_TABLE, gamma, "ISO 281 f_c")


def factor_f0(gamma: float) -> float:
    """f₀ of ISO 76:2006 table 1 at γ = D_w cos α / D_pw, linear interpolation [-]."""
    return _table(F0_TABLE, gamma, "ISO 76 f0")


def dynamic_load_rating(ball_count: int, ball_diameter: float, pitch_diameter: float, contact_angle: float,
                        rows: int = 1) -> float:
    """Basic dynamic radial load rating C_r [N] of a radial ball bearing (ISO 281:2007 eqs. 7 and 8).

    ball_diameter, pitch_diameter [m]; contact_angle [rad]; rows i [-]."""
    dw = ball_diameter * 1e3
    ca = math.cos(contact_angle)
    fc = factor_fc(dw * ca / (pitch_diameter * 1e3))
    common = B_M * fc * (rows * ca) ** 0.7 * ball_count ** (2.0 / 3.0)
    return common * dw**1.8 if dw <= 25.4 else 3.647 * common * dw**1.4


def static_load_rating(ball_count: int, ball_diameter: float, pitch_diameter: float, contact_angle: float,
                       rows: int = 1) -> float:
    """Basic static radial load rating C₀r = f₀ i Z D_w² cos α [N] (ISO 76:2006 eq. 1).

    ball_diameter, pitch_diameter [m]; contact_angle [rad]; rows i [-]."""
    dw = ball_diameter * 1e3
    ca = math.cos(contact_angle)
    return factor_f0(dw * ca / (pitch_diameter * 1e3)) * rows * ball_count * dw**2 * ca


def cn_clearance(bore: float) -> tuple[float, float]:
    """(min, max) radial internal clearance of group CN of a deep groove ball bearing of bore ``bore`` [m],
    in [m] (:data:`CN_CLEARANCE`)."""
    d = round(bore * 1e3, 6)  # [mm]; rounded so that 40e-3 m is 40 mm, in the group "over 30 incl. 40"
    for lo, hi, cmin, cmax in CN_CLEARANCE:
        if (lo < d <= hi) or (lo == 0.0 and d <= hi):
            return cmin * 1e-6, cmax * 1e-6
    raise InputError("bore", f"{d:g} mm is outside the CN clearance table (up to 200 mm)",
                     "give the clearance explicitly")


@dataclass(frozen=True)
class BallSetEstimate:
    """A ball set fitted to published load ratings (:func:`estimate_ball_set`); SI units.

    ball_count [-], ball_diameter [m], pitch_diameter [m]; dynamic_load_rating, static_load_rating [N]: the ISO
    ratings of this ball set; c_error, c0_error [-]: their relative deviations from the published ratings;
    score [-]: ln² sum of the two; runner_up: the next best (Z, D_w [m], score) for judging uniqueness."""

    ball_count: int
    ball_diameter: float
    pitch_diameter: float
    dynamic_load_rating: float
    static_load_rating: float
    c_error: float
    c0_error: float
    score: float
    runner_up: tuple = field(default=())


def _positive(value, name: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise InputError(name, f"expected a number in SI units, got {value!r}"[:120], "give a float (SI units)")
    if not (math.isfinite(value) and value > 0):
        raise InputError(name, f"must be positive, got {value!r}", "give the catalogue value in SI units")
    return float(value)


def estimate_ball_set(bore: float, outside_diameter: float, contact_angle: float, dynamic_rating: float,
                      static_rating: float, *, gap: float = 0.04, pitch_diameter: float | None = None,
                      balls=None) -> BallSetEstimate:
    """The standard ball set (Z, D_w) whose ISO 281 / ISO 76 ratings best reproduce the published C and C₀
    (method in the module docstring).

    bore d, outside_diameter D [m]; contact_angle α [rad] (0 for deep groove); dynamic_rating C,
    static_rating C₀ [N] of ONE row; gap [-]: minimum cage bridge between neighbouring balls as a fraction of
    D_w; pitch_diameter [m] (default (d + D)/2); balls: candidate diameters [m] (default: :data:`INCH_BALLS`,
    then :data:`STANDARD_BALLS` if no inch set scores below :data:`ACCEPT_SCORE`)."""
    d = _positive(bore, "bore")
    big_d = _positive(outside_diameter, "outside_diameter")
    c = _positive(dynamic_rating, "dynamic_load_rating")
    c0 = _positive(static_rating, "static_load_rating")
    if big_d <= d:
        raise InputError("outside_diameter", f"{big_d * 1e3:g} mm is not larger than the bore {d * 1e3:g} mm",
                         "check the boundary dimensions")
    if not (math.isfinite(contact_angle) and 0.0 <= contact_angle < math.radians(60.0)):
        raise InputError("contact_angle", f"{contact_angle!r} rad is not a radial ball bearing's angle",
                         "give 0–45 deg in radians")
    dm = 0.5 * (d + big_d) if pitch_diameter is None else _positive(pitch_diameter, "pitch_diameter")
    section = big_d - d
    if balls is None:
        best = estimate_ball_set(d, big_d, contact_angle, c, c0, gap=gap, pitch_diameter=dm, balls=INCH_BALLS)
        if best.score <= ACCEPT_SCORE:
            return best
        return estimate_ball_set(d, big_d, contact_angle, c, c0, gap=gap, pitch_diameter=dm, balls=STANDARD_BALLS)
    cand = np.asarray(balls, dtype=float)
    results = []
    for dw in cand:
        if not 0.20 * section <= dw <= 0.40 * section:
            continue
        s = min(1.0, (1.0 + gap) * dw / dm)
        zmax = int(math.floor(math.pi / math.asin(s) + 1e-9)) if s < 1.0 else 0
        for z in range(3, zmax + 1):
            try:
                ci = dynamic_load_rating(z, dw, dm, contact_angle)
                c0i = static_load_rating(z, dw, dm, contact_angle)
            except InputError:
                continue
            score = math.log(ci / c) ** 2 + math.log(c0i / c0) ** 2
            results.append((score, z, float(dw), ci, c0i))
    if not results:
        raise InputError("ball set", "no standard ball set fits these boundary dimensions",
                         "check d, D and the contact angle")
    results.sort(key=lambda r: r[0])
    score, z, dw, ci, c0i = results[0]
    runner = (results[1][1], results[1][2], results[1][0]) if len(results) > 1 else ()
    return BallSetEstimate(ball_count=z, ball_diameter=dw, pitch_diameter=dm, dynamic_load_rating=ci,
                           static_load_rating=c0i, c_error=ci / c - 1.0, c0_error=c0i / c0 - 1.0, score=score,
                           runner_up=runner)


# ---- seat fits: ISO 286 tolerance classes against the normal-class bearing tolerances --------------------------
#: upper limits of the ISO 286 size ranges [mm] ("over the previous, up to and including this"; the first
#: range is over 6 up to 10 mm)
_STEPS = (10, 18, 30, 50, 80, 120, 180, 250, 315)
#: standard tolerance grades IT5–IT8 [µm] per size range (ISO 286-1 table 1)
_IT = {5: (6, 8, 9, 11, 13, 15, 18, 20, 23), 6: (9, 11, 13, 16, 19, 22, 25, 29, 32),
       7: (15, 18, 21, 25, 30, 35, 40, 46, 52), 8: (22, 27, 33, 39, 46, 54, 63, 72, 81)}
#: shaft fundamental deviations [µm] (ISO 286-1 tables 2–3): ("es", values) upper or ("ei", values) lower
_SHAFT = {"f": ("es", (-13, -16, -20, -25, -30, -36, -43, -50, -56)),
          "g": ("es", (-5, -6, -7, -9, -10, -12, -14, -15, -17)),
          "h": ("es", (0,) * 9),
          "j": ("ei", (-2, -3, -4, -5, -7, -9, -11, -13, -16)),  # j5 and j6
          "k": ("ei", (1, 1, 2, 2, 2, 3, 3, 4, 4)),
          "m": ("ei", (6, 7, 8, 9, 11, 13, 15, 17, 20)),
          "n": ("ei", (10, 12, 15, 17, 20, 23, 27, 31, 34)),
          "p": ("ei", (15, 18, 22, 26, 32, 37, 43, 50, 56))}
#: housing fundamental deviations [µm] (ISO 286-1 tables 2–3); J, K, M, N, P with their grade
_HOUSING = {"G": ("EI", (5, 6, 7, 9, 10, 12, 14, 15, 17)), "H": ("EI", (0,) * 9),
            "J6": ("ES", (5, 6, 8, 10, 13, 16, 18, 22, 25)), "J7": ("ES", (8, 10, 12, 14, 18, 22, 26, 30, 36)),
            "K6": ("ES", (2, 2, 2, 3, 4, 4, 4, 5, 5)), "K7": ("ES", (5, 6, 6, 7, 9, 10, 12, 13, 16)),
            "M6": ("ES", (-3, -4, -4, -4, -5, -6, -8, -8, -9)), "M7": ("ES", (0,) * 9),
            "N6": ("ES", (-7, -9, -11, -12, -14, -16, -20, -22, -25)),
            "N7": ("ES", (-4, -5, -7, -8, -9, -10, -12, -14, -14)),
            "P6": ("ES", (-12, -15, -18, -21, -26, -30, -36, -41, -47)),
            "P7": ("ES", (-9, -11, -14, -17, -21, -24, -28, -33, -36))}
#: lower deviation of the mean bore diameter Δdmp of normal-class radial bearings [µm] (upper 0), ISO 492
_BORE_DMP = (-8, -8, -10, -12, -15, -20, -25, -30, -35)
#: lower deviation of the mean outside diameter ΔDmp of normal-class radial bearings [µm] (upper 0), ISO 492,
#: by outside diameter over 6 up to (mm): 18, 30, 50, 80, 120, 150, 180, 250, 315
_OD_STEPS = (18, 30, 50, 80, 120, 150, 180, 250, 315)
_OD_DMP = (-8, -9, -11, -13, -15, -18, -25, -30, -35)


def _step(size_mm: float, steps, field: str) -> int:
    s = round(size_mm, 6)
    if 6 < s <= steps[-1]:
        for i, hi in enumerate(steps):
            if s <= hi:
                return i
    raise InputError(field, f"{size_mm:g} mm is outside the tolerance tables (over 6 up to {steps[-1]} mm)",
                     "give the interference as a length instead, e.g. \"12 um\"")


def fit_interference(fit: str, diameter: float, seat: str) -> tuple[float, float, float]:
    """(min, mean, max) diametral interference [m] (negative: clearance) of a bearing ring on its seat.

    ``fit``: an ISO 286 tolerance class of the shaft (``seat="shaft"``: f6, g5, g6, h5, h6, j5, j6, js5, js6,
    k5, k6, m5, m6, n6, p6; lower case) or of the housing bore (``seat="housing"``: G7, H6, H7, H8, J6, J7,
    JS6, JS7, K6, K7, M6, M7, N6, N7, P6, P7; upper case); ``diameter``: the bearing bore (shaft) or outside
    diameter (housing) [m].  The ring has the normal tolerance class of ISO 492 (bore and outside diameter
    between their nominal size and the lower deviation Δdmp, ΔDmp).  Interference = shaft − bore, or
    outside diameter − housing bore; the mean is the middle of the two limits.  Tables: ISO 286-1 standard
    tolerances and fundamental deviations, ISO 492 normal class (the same numbers as NSK CAT. No. E1102e
    tables 15.2 and 15.3, checked in tests/validation/test_catalogue_estimate.py)."""
    import re

    if not isinstance(fit, str):
        raise InputError("fit", f"expected an ISO 286 tolerance class, got {fit!r}", 'e.g. "k5" or "H7"')
    size = _positive(diameter, "bore" if seat == "shaft" else "outside_diameter") * 1e3
    m = re.fullmatch(r"([a-zA-Z]{1,2})(\d)", fit.strip())
    if seat == "shaft":
        field = "--shaft-fit"
        if not m or m.group(1) not in ("f", "g", "h", "j", "js", "k", "m", "n", "p") or int(m.group(2)) not in _IT:
            raise InputError(field, f"{fit!r} is not a shaft tolerance class of the table",
                             "use f6, g5, g6, h5, h6, j5, j6, js5, js6, k5, k6, m5, m6, n6, p6, or a length")
        i = _step(size, _STEPS, field)
        it = _IT[int(m.group(2))][i]
        if m.group(1) == "js":
            ei, es = -it / 2, it / 2
        else:
            kind, dev = _SHAFT[m.group(1)]
            ei, es = (dev[i] - it, dev[i]) if kind == "es" else (dev[i], dev[i] + it)
        low = _BORE_DMP[i]
        imin, imax = ei - 0.0, es - low
    elif seat == "housing":
        field = "--housing-fit"
        if not m or int(m.group(2)) not in _IT or not (
                m.group(1) in ("G", "H", "JS") or m.group(0).strip() in _HOUSING):
            raise InputError(field, f"{fit!r} is not a housing tolerance class of the table",
                             "use G7, H6, H7, H8, J6, J7, JS6, JS7, K6, K7, M6, M7, N6, N7, P6, P7, or a length")
        i = _step(size, _STEPS, field)
        it = _IT[int(m.group(2))][i]
        if m.group(1) == "JS":
            lo, hi = -it / 2, it / 2
        else:
            kind, dev = _HOUSING[m.group(1)] if m.group(1) in ("G", "H") else _HOUSING[m.group(0).strip()]
            lo, hi = (dev[i], dev[i] + it) if kind == "EI" else (dev[i] - it, dev[i])
        low = _OD_DMP[_step(size, _OD_STEPS, field)]
        imin, imax = low - hi, 0.0 - lo
    else:
        raise InputError("seat", f"unknown seat {seat!r}", 'use "shaft" or "housing"')
    return imin * 1e-6, 0.5 * (imin + imax) * 1e-6, imax * 1e-6


__all__ = ["B_M", "FC_TABLE", "F0_TABLE", "CN_CLEARANCE", "INCH_BALLS", "METRIC_BALLS", "STANDARD_BALLS",
           "INNER_CONFORMITY",
           "OUTER_CONFORMITY", "BallSetEstimate", "factor_fc", "factor_f0", "dynamic_load_rating",
           "static_load_rating", "cn_clearance", "estimate_ball_set", "fit_interference"]
