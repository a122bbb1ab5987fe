"""Rating life of ball bearings: ISO 281:2007 basic and modified rating life, and the ISO/TS 16281:2008
reference rating life L10r from a computed load distribution.

ISO/TS 16281:2008 (Lundberg–Palmgren theory; Harris & Kotzalas 2007 vol. 2 ch. 8):

* dynamic equivalent rolling-element load of each raceway, from the ball loads Q_j of a row of Z balls
  (inner ring rotating, load fixed in space, so the inner raceway is "rotating relative to the load"):
      Q_ei = [ (1/Z) Σ Q_ij^3 ]^(1/3),   Q_eo = [ (1/Z) Σ Q_oj^(10/3) ]^(3/10)
* basic dynamic load rating of the raceway contacts, from the basic dynamic load rating C of the bearing
  (ISO/TS 16281:2008, the Lundberg–Palmgren ratio of the two raceways; i rows of Z balls):
      Q_ci = C / (0.407 Z i^0.7 cos α) · [1 + (1.044 ((1−γ)/(1+γ))^1.72 (f_i(2f_o−1)/(f_o(2f_i−1)))^0.41)^(10/3)]^0.3
      Q_co = C / (0.389 Z i^0.7 cos α) · [1 + (1.044 (…))^(−10/3)]^0.3
  with γ = D cos α / d_m and α the **nominal** contact angle of the bearing (0 for a deep-groove bearing,
  whatever its clearance): Q_ci and Q_co are ratings of the bearing as designed, the same for every load
  case.  0.407 = J_r/J_1, 0.389 = J_r/J_2 and 1.044 = J_2/J_1 are the Lundberg–Palmgren integrals of the
  rating condition (radial load, Stribeck distribution with ε = 0.5; :func:`lp_integrals` gives
  0.40681, 0.38954, 1.04432): the ISO 281 rating condition — radial load C with that distribution — gives
  10^6 revolutions.  (The free contact angle of a deep-groove bearing with clearance, cos α₀ = 1 − P_d/(2A),
  would give 2.8 % longer lives than ISO/TS 16281 for a 6305 with 10 µm clearance,
  tests/validation/test_iso16281.py.)
* raceway lives L_i = (Q_ci/Q_ei)^3, L_o = (Q_co/Q_eo)^3; row and system lives combine with the
  Weibull exponent e = 10/9:  L = (Σ L_k^(−10/9))^(−9/10)  [10^6 revolutions].

ISO 281:2007 (:func:`equivalent_dynamic_load`, :func:`rating_summary`):

* basic rating life L10 = (C/P)^3 [10^6 rev], P = X F_r + Y F_a with X, Y, e of table 3 for
  deep-groove (radial contact groove) and angular-contact ball bearings, single row and pairs/double row;
  for deep-groove bearings and nominal angles ≤ 15° X, Y, e depend on the relative axial load f₀F_a/C₀r,
  so C₀ and f₀ are needed (from the bearing file, else estimated: :func:`static_rating_estimate`, flagged);
  intermediate loads and angles by linear interpolation (ISO 281:2007 table 3, footnote);
* L10h = 10^6 L10 / (60 n) [h] at the operating speed n [r/min];
* modified rating life L_nm = a1 a_ISO L10: a1 from the reliability (the standard's table), a_ISO for ball
  bearings from the viscosity ratio κ = ν/ν1 and e_C C_u/P (the standard's formulae for radial ball bearings),
  ν1 the rated viscosity, e_C from a cleanliness level (table 11, the middle of its range), C_u the fatigue
  load limit (bearing file, else the ISO 281:2007 annex B estimate C_u = C₀/22 for d_m ≤ 100 mm, flagged);
* modified reference rating life L_nmr = a1 a_ISO L10r (ISO/TS 16281:2008) with a_ISO evaluated at the dynamic
  equivalent reference load P_ref = C / L10r^(1/3).

A bearing set reports, besides the system's figures, each row's reference life and pressure-based static safety
(``row_ratings``): the row that limits the set.

Units: forces [N], speeds [rad/s] inside, lives [10^6 rev] and [h], viscosities [m²/s].
"""

from __future__ import annotations

import functools
import math

import numpy as np

from .errors import InputError

E_WEIBULL = 10.0 / 9.0

#: ISO/TS 16281:2008 constants of the raceway ratings: J_r/J_1, J_r/J_2, J_2/J_1 of the rating
#: condition (ε = 0.5), rounded as in the standard
TS16281_JR_J1 = 0.407
TS16281_JR_J2 = 0.389
TS16281_J2_J1 = 1.044


def lp_integrals(eps: float) -> tuple[float, float, float]:
    """Lundberg–Palmgren integrals (J_r, J_1, J_2) of the point-contact Stribeck distribution
    Q(ψ)/Q_max = [1 − (1 − cos ψ)/(2ε)]^1.5 (Harris & Kotzalas 2007 vol. 2 ch. 8) [-]."""
    from scipy.integrate import quad  # here, not at import: scipy.integrate costs ~0.25 s of CLI start-up

    lim = math.pi if eps >= 1.0 else math.acos(1.0 - 2.0 * eps)

    def q(psi):
        return max(1.0 - (1.0 - math.cos(psi)) / (2.0 * eps), 0.0) ** 1.5

    jr = quad(lambda p: q(p) * math.cos(p), 0.0, lim)[0] / math.pi
    j1 = (quad(lambda p: q(p) ** 3, 0.0, lim)[0] / math.pi) ** (1.0 / 3.0)
    j2 = (quad(lambda p: q(p) ** (10.0 / 3.0), 0.0, lim)[0] / math.pi) ** 0.3
    return jr, j1, j2


def nominal_contact_angle(bearing) -> float:
    """Nominal contact angle α [rad] of ISO 281 / ISO/TS 16281: 0 for a deep-groove (radial contact groove)
    bearing, whatever its clearance; the design contact angle of an angular-contact bearing."""
    if getattr(bearing, "kind", "") == "deep_groove":
        return 0.0
    return float(bearing.contact_angle)


def raceway_ratings(bearing, c_row: float) -> tuple[float, float]:
    """(Q_ci, Q_co) [N]: basic dynamic load ratings of a ball on the inner and outer raceway of a row of
    rating ``c_row`` [N] (ISO/TS 16281:2008, module docstring; nominal contact angle, one row)."""
    a = nominal_contact_angle(bearing)
    g = bearing.ball_diameter * math.cos(a) / bearing.pitch_diameter
    fi, fo = bearing.inner_conformity, bearing.outer_conformity
    x = TS16281_J2_J1 * ((1.0 - g) / (1.0 + g)) ** 1.72 * (fi * (2.0 * fo - 1.0) / (fo * (2.0 * fi - 1.0))) ** 0.41
    zc = bearing.ball_count * math.cos(a)
    qci = c_row / (TS16281_JR_J1 * zc) * (1.0 + x ** (10.0 / 3.0)) ** 0.3
    qco = c_row / (TS16281_JR_J2 * zc) * (1.0 + x ** (-10.0 / 3.0)) ** 0.3
    return qci, qco


def _combine(lives) -> float:
    lives = [x for x in lives if x is not None]
    if not lives:
        return math.inf
    if any(x == 0 for x in lives):
        return 0.0
    return sum(x ** (-E_WEIBULL) for x in lives) ** (-1.0 / E_WEIBULL)


def _rows_and_ratings(bearing):
    """[(row bearing, row rating C [N])] of a bearing or a bearing system (0 when unknown)."""
    rows = bearing.rows  # the rows protocol (bearingsim.geometry): a BallBearing is one row of itself
    if len(rows) == 1 and rows[0].bearing is bearing:
        return [(bearing, float(bearing.dynamic_load_rating))]
    c_unit = float(getattr(bearing, "dynamic_load_rating", 0.0) or 0.0)
    out = []
    for r in rows:
        c = float(r.bearing.dynamic_load_rating)
        if c <= 0 and c_unit > 0:
            c = c_unit / len(rows) ** 0.7  # ISO 281: C of an i-row unit = i^0.7 C of one row
        out.append((r.bearing, c))
    return out


def row_reference_life(bearing, c_row: float, qi, qo) -> float:
    """ISO/TS 16281 reference rating life [10^6 revolutions] of one row of rating ``c_row`` [N] whose balls carry
    ``qi`` and ``qo`` [N] on the inner and outer raceway (inner ring rotating: Q_ei the cubic mean, Q_eo the
    10/3 mean over the row's Z balls; the two raceway lives combined with the Weibull exponent; ∞ without load)."""
    qi = np.maximum(np.asarray(qi, dtype=float), 0.0)
    qo = np.maximum(np.asarray(qo, dtype=float), 0.0)
    z = len(qi)
    qci, qco = raceway_ratings(bearing, c_row)
    qei = (float((qi * qi).dot(qi)) / z) ** (1.0 / 3.0)
    qeo = (float((qo ** (10.0 / 3.0)).sum()) / z) ** 0.3
    return float(_combine([(qci / qei) ** 3 if qei > 0 else None, (qco / qeo) ** 3 if qeo > 0 else None]))


def row_reference_lives(result) -> list[float] | None:
    """ISO/TS 16281 reference rating life of each row [10^6 revolutions] (its two raceways combined with the
    Weibull exponent; ∞ for a row without load), or ``None`` (no rating, or not converged)."""
    if not getattr(result, "converged", True):
        return None
    rows = _rows_and_ratings(result.bearing)
    if any(c <= 0 for _, c in rows):
        return None
    b = result.balls
    qi_all = np.maximum(b["inner_load_N"], 0.0)
    qo_all = np.maximum(b["outer_load_N"], 0.0)
    out = []
    for k, (brg, c) in enumerate(rows):
        if len(rows) == 1:
            qi, qo = qi_all, qo_all
        else:
            sel = b["row"] == k
            qi, qo = qi_all[sel], qo_all[sel]
        out.append(row_reference_life(brg, c, qi, qo))
    return out


def reference_rating_life(result) -> float | None:
    """ISO/TS 16281 basic reference rating life L10r [10^6 revolutions] from the ball loads of a
    :class:`~bearingsim.statics.jones_harris.StaticResult` (all raceways of all rows combined with the Weibull
    exponent); ``None`` when no dynamic load rating is known (``dynamic_load_rating`` in the bearing file) or
    the result did not converge.  The loads are the Jones–Harris ones; :mod:`bearingsim.iso16281` gives L10r on
    the standard's own load distribution (the same for a deep-groove row at rest without a moment, 2.3 % shorter
    for a 6305-like bearing under a pure moment: docs/life.md)."""
    rows = row_reference_lives(result)
    if rows is None:
        return None
    return float(_combine([x for x in rows if math.isfinite(x)]))


# ---- ISO 281:2007 table 3: X, Y, e ------------------------------------------------------------------
#: Sources of the values below (checked 2026-11, primary text of ISO 281:2007 not available to the project):
#: deep-groove, 15°, 30° and 40° rows and the i of pairs — the JTEKT (Koyo) catalogue, "Calculation of equivalent
#: radial / axial load" (koyousa.com/koyocatalog/technical/03/3_1_32.htm); also, deep-groove rows —
#: the ANSI/ABMA 9 table reproduced in "Rules of Thumb for Mechanical Engineers" (table 7a,
#: F_a/(iZD²) = 24.92 … 999.05 lbf/in², e 0.19 … 0.44, Y 2.30 … 1.00, X 0.56) and five independent open
#: transcriptions (docs/life.md lists them); 20°–45° rows — NSK "New 40° angular contact ball bearings" leaflet
#: (e 1.14, X 0.35, Y 0.57; pair 1/0.55 and 0.57/0.93) and the same transcriptions; 5°, 10°, 15° rows (single and
#: double row, e) — two independent open transcriptions of ISO 281:2007 table 3 that agree value for value with the
#: values below (docs/life.md).  The standard's text for the 5° single-row cell ("use the X, Y and e values
#: applicable to single row radial contact groove ball bearings") is followed: a single-row 5° bearing takes the
#: deep-groove e as well (not the 5° double-row e column, 0.23 … 0.52).
#: Relative axial load f₀F_a/C₀r of the rows below [-] (deep groove).  The table goes back to the axial load per
#: ball F_a/(i Z D_w²) = 25, 50, 100, 150, 200, 300, 500, 750, 1000 lbf/in² (0.172 … 6.89 N/mm², ISO/TR 1281-1);
#: since C₀r = f₀ i Z D_w² cos α (ISO 76), f₀F_a/C₀r = F_a/(i Z D_w² cos α) and the 5°, 10° and 15° columns are
#: those loads divided by cos α, as ISO 281:2007 prints them (_REL_LOAD_BY_ANGLE: 0.173 … 6.92 at 5°).  For
#: angular contact bearings the column is i f₀F_a/C₀r (only one row of a double-row bearing or a face-to-face /
#: back-to-back pair carries the axial load: per ball F_a/(Z D_w²)); NSK prints the same rule ("for i, use 2 for DB
#: or DF, and 1 for DT").
_REL_LOAD = (0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89)
_REL_LOAD_BY_ANGLE = {5: (0.173, 0.346, 0.692, 1.04, 1.38, 2.08, 3.46, 5.19, 6.92),
                      10: (0.175, 0.350, 0.700, 1.05, 1.40, 2.10, 3.50, 5.25, 7.00),
                      15: (0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35, 7.14)}
#: radial contact groove (deep-groove) ball bearings: e and Y (X = 0.56) for F_a/F_r > e, single and double row
_DG_E = (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44)
_DG_Y = (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00)
#: angular contact groove ball bearings, nominal angle [deg] -> (e, (X, Y) single row F_a/F_r > e,
#: (X1, Y1) double row / pair F_a/F_r ≤ e, (X2, Y2) double row / pair F_a/F_r > e); Y and e vary with the
#: relative axial load for 5°, 10° and 15° (tuples over _REL_LOAD_BY_ANGLE), X does not.  The e of the 5° row
#: is that of the double-row bearing (single row: the deep-groove values, :func:`_angular_entry`)
_AC_SMALL = {
    5: ((0.23, 0.26, 0.30, 0.34, 0.36, 0.40, 0.45, 0.50, 0.52),
        (0.56, (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00)),
        (1.0, (2.78, 2.40, 2.07, 1.87, 1.75, 1.58, 1.39, 1.26, 1.21)),
        (0.78, (3.74, 3.23, 2.78, 2.52, 2.36, 2.13, 1.87, 1.69, 1.63))),
    10: ((0.29, 0.32, 0.36, 0.38, 0.40, 0.44, 0.49, 0.54, 0.54),
         (0.46, (1.88, 1.71, 1.52, 1.41, 1.34, 1.23, 1.10, 1.01, 1.00)),
         (1.0, (2.18, 1.98, 1.76, 1.63, 1.55, 1.42, 1.27, 1.17, 1.16)),
         (0.75, (3.06, 2.78, 2.47, 2.29, 2.18, 2.00, 1.79, 1.64, 1.63))),
    15: ((0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56),
         (0.44, (1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00)),
         (1.0, (1.65, 1.57, 1.46, 1.38, 1.34, 1.26, 1.14, 1.12, 1.12)),
         (0.72, (2.39, 2.28, 2.11, 2.00, 1.93, 1.82, 1.66, 1.63, 1.63))),
}
_AC_LARGE = {
    20: (0.57, (0.43, 1.00), (1.0, 1.09), (0.70, 1.63)),
    25: (0.68, (0.41, 0.87), (1.0, 0.92), (0.67, 1.41)),
    30: (0.80, (0.39, 0.76), (1.0, 0.78), (0.63, 1.24)),
    35: (0.95, (0.37, 0.66), (1.0, 0.66), (0.60, 1.07)),
    40: (1.14, (0.35, 0.57), (1.0, 0.55), (0.57, 0.93)),
    45: (1.34, (0.33, 0.50), (1.0, 0.47), (0.54, 0.81)),
}
_ISO281_XY = {k: v for k, v in _AC_LARGE.items() if 25 <= k <= 40}  # the former table (kept importable)


def interp(x: float, xs, ys) -> float:
    """Piecewise-linear interpolation of a short table, clamped at its ends (plain Python: the tables have
    ten rows and numpy's call overhead would dominate)."""
    if x <= xs[0]:
        return float(ys[0])
    for k in range(1, len(xs)):
        if x <= xs[k]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return float(ys[k - 1] + t * (ys[k] - ys[k - 1]))
    return float(ys[-1])


def _at_load(values, rel_load: float, loads=_REL_LOAD) -> float:
    """Linear interpolation of a table-3 column in f₀F_a/C₀r (at the relative loads ``loads``), clamped to the
    table's range."""
    return interp(rel_load, loads, values)


def _angular_entry(deg: int, rel_load: float | None):
    """(e, (X, Y) single, (X1, Y1), (X2, Y2)) of the tabulated angle ``deg`` at the relative axial load; for the
    5°–15° rows e is the pair (e single row, e double row), which differ only at 5°."""
    if deg in _AC_LARGE:
        return _AC_LARGE[deg]
    e, (xs, ys), (x1, y1), (x2, y2) = _AC_SMALL[deg]
    col = _REL_LOAD_BY_ANGLE[deg]
    e_pair = _at_load(e, rel_load, col)
    if deg == 5:  # single row: "use the X, Y and e values applicable to single row radial contact groove ball bearings"
        e_single, y_single = _at_load(_DG_E, rel_load), _at_load(_DG_Y, rel_load)
    else:
        e_single, y_single = e_pair, _at_load(ys, rel_load, col)
    return ((e_single, e_pair), (xs, y_single), (x1, _at_load(y1, rel_load, col)), (x2, _at_load(y2, rel_load, col)))


def needs_static_rating(contact_angle: float, kind: str = "angular_contact") -> bool:
    """True when ISO 281 table 3 needs f₀F_a/C₀r: deep-groove bearings and nominal angles below 20°."""
    return kind == "deep_groove" or math.degrees(contact_angle) < 20.0 - 1e-9


def xy_factors(fr: float, fa: float, contact_angle: float, rows: int = 1, kind: str = "angular_contact",
               rel_load: float | None = None) -> tuple[float, float, float] | None:
    """(X, Y, e) of ISO 281:2007 table 3 [-] for radial load ``fr`` and axial load ``fa`` [N].

    ``kind`` "deep_groove" or "angular_contact" (nominal ``contact_angle`` [rad], 5°–45°; between tabulated
    angles X, Y and e are interpolated linearly); ``rows`` 1 (single row, or a tandem set) or 2 (double
    row, or a pair mounted face-to-face/back-to-back); ``rel_load`` [-] = f₀F_a/C₀r for deep-groove bearings and
    i f₀F_a/C₀r for angular contact bearings (i = ``rows``, C₀r of the whole unit), needed for deep-groove bearings
    and angles below 20° (clamped to the table's range, 0.172–6.89 for deep groove).  ``None`` when the table has no
    answer (angle outside 5°–45° for an angular contact bearing, or the relative load missing)."""
    fr, fa = abs(fr), abs(fa)
    ratio = fa / fr if fr > 0 else math.inf
    if kind == "deep_groove":
        if rel_load is None:
            return None
        e = _at_load(_DG_E, rel_load)
        if ratio <= e:
            return 1.0, 0.0, e
        return 0.56, _at_load(_DG_Y, rel_load), e
    deg = math.degrees(contact_angle)
    if not 5.0 - 1e-9 <= deg <= 45.0 + 1e-9:
        return None
    if needs_static_rating(contact_angle, kind) and rel_load is None:
        return None
    grid = (5, 10, 15, 20, 25, 30, 35, 40, 45)
    hi = next(g for g in grid if g >= deg - 1e-9)
    lo = max(g for g in grid if g <= deg + 1e-9)
    t = 0.0 if hi == lo else (deg - lo) / (hi - lo)
    a, b = _angular_entry(lo, rel_load), _angular_entry(hi, rel_load)

    def mix(u, v):
        return (1.0 - t) * u + t * v

    k_e = 0 if rows == 1 else 1

    def e_of(entry):
        return entry[0][k_e] if isinstance(entry[0], tuple) else entry[0]

    e = mix(e_of(a), e_of(b))
    if rows == 1:
        x, y = (1.0, 0.0) if ratio <= e else (mix(a[1][0], b[1][0]), mix(a[1][1], b[1][1]))
    else:
        k = 2 if ratio <= e else 3
        x, y = mix(a[k][0], b[k][0]), mix(a[k][1], b[k][1])
    return x, y, e


def equivalent_dynamic_load(fr: float, fa: float, contact_angle: float, rows: int = 1,
                            kind: str = "angular_contact", rel_load: float | None = None) -> float | None:
    """P = X F_r + Y F_a [N] (ISO 281:2007, with the factors of :func:`xy_factors`); ``None`` where
    table 3 gives no factors (deep groove and angles below 20° need ``rel_load`` = f₀F_a/C₀r)."""
    f = xy_factors(fr, fa, contact_angle, rows, kind, rel_load)
    if f is None:
        return None
    x, y, _ = f
    return x * abs(fr) + y * abs(fa)


def basic_rating_life(c: float, p: float) -> float:
    """ISO 281:2007: L10 = (C/P)^3 [10^6 revolutions] for ball bearings."""
    if p <= 0:
        return math.inf
    return (c / p) ** 3


def life_hours(l10: float, speed: float) -> float | None:
    """L_h = 10^6 L / (60 n) [h] (ISO 281:2007) for a life L [10^6 rev] at the speed [rad/s] (its
    magnitude); ``None`` at rest (no revolutions: no life in hours)."""
    n = abs(speed) * 30.0 / math.pi
    if not n > 0 or l10 is None or not math.isfinite(l10):
        return None
    return l10 * 1e6 / (60.0 * n)


def hours_text(hours) -> str:
    """A life in hours for people: thousands grouped above 100 h ("2,818 h"), three significant digits below
    ("0.244 h", "12.3 h": a short life is not printed "0 h"), "—" for none."""
    if hours is None or not math.isfinite(float(hours)):
        return "—"
    h = float(hours)
    return f"{h:,.0f} h" if h >= 100.0 else f"{h:.3g} h"


# ---- ISO 281:2007 modified rating life ---------------------------------------------------------------
#: life modification factor for reliability a1, reliability [%] -> a1 (ISO 281:2007, reliability table)
RELIABILITY_A1 = {90.0: 1.0, 95.0: 0.64, 96.0: 0.55, 97.0: 0.47, 98.0: 0.37, 99.0: 0.25, 99.2: 0.22,
                  99.4: 0.19, 99.6: 0.16, 99.8: 0.12, 99.9: 0.093, 99.92: 0.087, 99.94: 0.080, 99.95: 0.077}

#: contamination factor e_C (ISO 281:2007 table 11): level -> ((range for d_m < 100 mm), (range for d_m ≥ 100 mm));
#: :func:`contamination_factor` takes the middle of the range
CONTAMINATION = {
    "extreme": ((1.0, 1.0), (1.0, 1.0)),  # extreme cleanliness: particle size of the order of the film thickness
    "high": ((0.6, 0.8), (0.8, 0.9)),  # high cleanliness: oil through an extremely fine filter, sealed greased
    "normal": ((0.5, 0.6), (0.6, 0.8)),  # normal cleanliness: oil through a fine filter, shielded greased
    "slight": ((0.3, 0.5), (0.4, 0.6)),  # slight contamination
    "typical": ((0.1, 0.3), (0.2, 0.4)),  # typical contamination: no integral seals, coarse filter, wear particles
    "severe": ((0.0, 0.1), (0.0, 0.1)),  # severe contamination: heavily contaminated surroundings
    "very_severe": ((0.0, 0.0), (0.0, 0.0)),  # very severe contamination
}


def reliability_factor(reliability: float, field: str = "reliability") -> float:
    """a1 [-] for a reliability [%] of the ISO 281:2007 table (90 % … 99.95 %; other values refused, naming
    ``field``)."""
    for k, v in RELIABILITY_A1.items():
        if abs(k - reliability) < 1e-9:
            return v
    raise InputError(field, f"{reliability!r} % is not a reliability of the ISO 281:2007 table",
                     "use one of " + ", ".join(f"{k:g}" for k in RELIABILITY_A1))


def contamination_factor(level, pitch_diameter: float) -> float:
    """e_C [-] for a cleanliness level of ISO 281:2007 table 11 (the middle of the table's range for the
    bearing's pitch diameter [m]), or a number in [0, 1] given directly."""
    if isinstance(level, int | float) and not isinstance(level, bool):
        if not 0.0 <= level <= 1.0:
            raise InputError("contamination", f"e_C must lie in [0, 1], got {level!r}",
                             "give a level name or a factor between 0 and 1")
        return float(level)
    key = str(level).strip().lower().replace("-", "_").replace(" ", "_")
    if key not in CONTAMINATION:
        raise InputError("contamination", f"unknown cleanliness level {level!r}",
                         "use one of " + ", ".join(CONTAMINATION) + " (ISO 281:2007 table 11) or a factor 0-1")
    lo, hi = CONTAMINATION[key][0 if pitch_diameter < 0.1 else 1]
    return 0.5 * (lo + hi)


def rated_viscosity(speed: float, pitch_diameter: float) -> float:
    """Rated (reference) viscosity ν1 [m²/s] for the speed [rad/s] and pitch diameter [m]
    (ISO 281:2007, n in r/min, D_pw in mm, ν1 in mm²/s):
    ν1 = 45 000 n^−0.83 D_pw^−0.5 for n < 1000 r/min, ν1 = 4 500 n^−0.5 D_pw^−0.5 for n ≥ 1000 r/min."""
    n = abs(speed) * 30.0 / math.pi
    if not n > 0:
        raise InputError("speed", "the rated viscosity needs a speed", 'give the operating speed, e.g. "1500 rpm"')
    dpw = pitch_diameter * 1e3
    nu1 = 45000.0 * n**-0.83 * dpw**-0.5 if n < 1000.0 else 4500.0 * n**-0.5 * dpw**-0.5
    return nu1 * 1e-6


def life_modification_factor(kappa: float, ec_cu_over_p: float) -> float:
    """a_ISO [-] of radial ball bearings (ISO 281:2007), κ clamped to 4 above (the standard's
    rule), a_ISO limited to 50; κ must be ≥ 0.1 (below, the formulae are not valid: InputError)."""
    if not kappa >= 0.1:
        raise InputError("kappa", f"viscosity ratio κ = {kappa:.3g} is below 0.1, outside ISO 281:2007",
                         "use a more viscous lubricant or a lower temperature")
    k = min(kappa, 4.0)
    if k < 0.4:
        inner = 2.5671 - 2.2649 / k**0.054381
    elif k < 1.0:
        inner = 2.5671 - 1.9987 / k**0.19087
    else:
        inner = 2.5671 - 1.9987 / k**0.071739
    x = max(ec_cu_over_p, 0.0)
    base = 1.0 - inner**0.83 * x ** (1.0 / 3.0)
    if base <= 0.0:
        return 50.0
    return min(0.1 * base**-9.3, 50.0)


# ---- ISO 76 static rating and ISO 281 fatigue load limit (estimates) -----------------------------------
#: maximum contact pressure at C₀ for ball bearings other than self-aligning [Pa] (ISO 76:2006)
C0_PRESSURE = 4.2e9
#: Stribeck's factor of ISO 76: Q_max = 5 F_r / (i Z cos α) at the static rating (ISO/TR 10657)
STRIBECK_STATIC = 5.0


def static_rating_estimate(bearing) -> tuple[float, float]:
    """Cached :func:`_static_rating_estimate` (a bearing is immutable; its Hertz constants cost ~60 µs)."""
    try:
        return _static_rating_cached(bearing)
    except TypeError:  # an unhashable bearing-like object
        return _static_rating_estimate(bearing)


def _static_rating_estimate(bearing) -> tuple[float, float]:
    """(C₀r [N], f₀ [-]) estimated from the ball set, as ISO 76 derives them: the radial load at which the
    most heavily loaded contact reaches 4 200 MPa, with Stribeck's Q_max = 5 C₀r/(Z cos α) (ISO 76:2006,
    derivation in ISO/TR 10657), Hertz pressure of this bearing's raceways and materials
    (:mod:`bearingsim.contact.hertz`); f₀ = C₀r / (Z D_w² cos α) with D_w in mm (ISO 76)."""
    a = nominal_contact_angle(bearing)
    p1 = max(bearing.contact(1.0, True, a).max_pressure, bearing.contact(1.0, False, a).max_pressure)
    q0 = (C0_PRESSURE / p1) ** 3
    c0 = bearing.ball_count * q0 * math.cos(a) / STRIBECK_STATIC
    f0 = c0 / (bearing.ball_count * (bearing.ball_diameter * 1e3) ** 2 * math.cos(a))
    return c0, f0


_static_rating_cached = functools.lru_cache(maxsize=256)(_static_rating_estimate)


def fatigue_load_limit_estimate(c0: float, pitch_diameter: float) -> float:
    """C_u [N] of a ball bearing from its static rating (ISO 281:2007 annex B, simplified):
    C_u = C₀/22 for D_pw ≤ 100 mm, C_u = C₀/22 (100/D_pw)^0.5 above."""
    dpw = pitch_diameter * 1e3
    return c0 / 22.0 * (1.0 if dpw <= 100.0 else (100.0 / dpw) ** 0.5)


# ---- the summary of a solved operating point --------------------------------------------------------------
def _unit_data(bearing):
    """(kind, nominal angle [rad], rows i for table 3, number of rows, row bearing, reason or None)."""
    rows = bearing.rows  # the rows protocol (bearingsim.geometry)
    if len(rows) == 1 and rows[0].bearing is bearing:
        return bearing.kind, nominal_contact_angle(bearing), 1, 1, bearing, None
    row_b = rows[0].bearing
    if len(rows) > 2:
        return row_b.kind, nominal_contact_angle(row_b), 0, len(rows), row_b, \
            f"ISO 281 has no factors for a unit of {len(rows)} rows"
    # ISO 281:2007: a pair face-to-face or back-to-back (rows of opposite orientation) is rated as a double-row
    # bearing; a tandem pair (same orientation) takes the single-row factors with the rating of the set
    tandem = len(rows) == 1 or all(float(r.orientation) == float(rows[0].orientation) for r in rows)
    i_table = 1 if tandem else 2
    return row_b.kind, nominal_contact_angle(row_b), i_table, len(rows), row_b, None


def _rating(bearing, name: str, row_b, nrows: int) -> float:
    """A rating of the unit [N]: the bearing's field, else from the row's — i^0.7 C (ISO 281), i C₀
    (ISO 76) and i C_u (SKF, bearing pairs: P_u = 2 P_u of a single bearing) for i rows; 0 = unknown."""
    v = float(getattr(bearing, name, 0.0) or 0.0)
    if v <= 0 and row_b is not bearing:
        r = float(getattr(row_b, name, 0.0) or 0.0)
        v = nrows**0.7 * r if name == "dynamic_load_rating" else nrows * r
    return v


#: bearing fields -> the keys of :func:`rating_summary` they give
_RATING_KEYS = {"dynamic_load_rating": "dynamic_load_rating_N", "static_load_rating": "static_load_rating_N",
                "geometry_factor_f0": "geometry_factor_f0", "fatigue_load_limit": "fatigue_load_limit_N"}
#: the fields of the internal geometry (ball set)
_BALL_SET = {"ball_diameter", "ball_count", "pitch_diameter", "inner_conformity", "outer_conformity", "conformity",
             "contact_angle", "diametral_clearance"}


def _bearing_ratings_uncached(brg) -> tuple:
    """The load-independent part of :func:`rating_summary`: (kind, nominal angle, rows of table 3, number of rows,
    row bearing, reason or None, C, C₀, f₀, C_u [N, -], estimated keys, notes)."""
    notes: list[str] = []
    estimated: list[str] = []
    kind, alpha, i_table, nrows, row_b, why = _unit_data(brg)
    c = _rating(brg, "dynamic_load_rating", row_b, nrows)
    c0 = _rating(brg, "static_load_rating", row_b, nrows)
    f0 = float(getattr(brg, "geometry_factor_f0", 0.0) or getattr(row_b, "geometry_factor_f0", 0.0) or 0.0)
    cu = _rating(brg, "fatigue_load_limit", row_b, nrows)
    if c0 <= 0 or f0 <= 0:
        c0_est, f0_est = static_rating_estimate(row_b)
        if c0 <= 0:
            c0 = nrows * c0_est
            estimated.append("static_load_rating_N")
        if f0 <= 0:
            f0 = f0_est
            estimated.append("geometry_factor_f0")
    if cu <= 0:
        cu = fatigue_load_limit_estimate(c0, row_b.pitch_diameter)
        estimated.append("fatigue_load_limit_N")
    # figures the bearing file itself marks as estimates (its [sources] text starts with ESTIMATE/ASSUMED)
    marked = set(getattr(brg, "estimated", ()) or ())
    if row_b is not brg:
        marked |= set(getattr(row_b, "estimated", ()) or ())
    for field_name, key in _RATING_KEYS.items():
        if field_name in marked and key not in estimated:
            estimated.append(key)
    if marked & _BALL_SET:
        notes.append("the ball set (" + ", ".join(sorted(marked & _BALL_SET)) + ") is an estimate: the load "
                     "distribution, the reference rating life and the pressure-based s0 rest on it")
    return kind, alpha, i_table, nrows, row_b, why, c, c0, f0, cu, tuple(estimated), tuple(notes)


_bearing_ratings_cached = functools.lru_cache(maxsize=256)(_bearing_ratings_uncached)


def _bearing_ratings(brg) -> tuple:
    """Cached :func:`_bearing_ratings_uncached` (bearings are immutable; an unhashable one is computed)."""
    try:
        return _bearing_ratings_cached(brg)
    except TypeError:
        return _bearing_ratings_uncached(brg)


def rating_summary(result, lubricant=None, temperature: float | None = None, contamination="normal",
                   reliability: float = 90.0) -> dict:
    """ISO 281 / ISO 76 / ISO/TS 16281 figures of a solved operating point (SI and hours), JSON-ready.

    Keys: ``dynamic_load_rating_N``, ``static_load_rating_N``, ``geometry_factor_f0``,
    ``fatigue_load_limit_N``, ``equivalent_dynamic_load_N``, ``equivalent_static_load_N``,
    ``basic_rating_life_million_revolutions``, ``basic_rating_life_hours``, ``modified_rating_life_hours``,
    ``reference_rating_life_million_revolutions``, ``reference_rating_life_hours``,
    ``modified_reference_rating_life_hours``, ``static_safety_factor`` (C₀/P₀, ISO 76),
    ``static_safety_factor_pressure`` ((4200 MPa / p_max)³, :mod:`bearingsim.safety`), ``iso281_factors`` (X, Y, e
    of table 3 and the relative axial load used, or None), for a set ``row_ratings``
    (per row: reference life in 10⁶ rev and hours, pressure-based s₀), ``life_factors``
    (a1, a_ISO, κ, ν, ν1, e_C), ``estimated`` (the names of figures estimated, not from the bearing file)
    and ``life_notes`` (why a figure is absent).  ``lubricant`` (a :class:`~bearingsim.lubricants.Lubricant`)
    (or its library name / TOML path) and ``temperature`` [K] give ν for the modified lives; without them those are
    None with a note."""
    from .safety import equivalent_static_load, pressure_safety_factor

    brg = result.bearing
    kind, alpha, i_table, nrows, row_b, why, c, c0, f0, cu, est, bnotes = _bearing_ratings(brg)
    notes = list(bnotes)
    estimated = list(est)
    fr = math.hypot(result.loads.fr_y, result.loads.fr_z)
    fa = abs(result.loads.fa)
    out = {"dynamic_load_rating_N": c if c > 0 else None, "static_load_rating_N": c0, "geometry_factor_f0": f0,
           "fatigue_load_limit_N": cu}
    p = p0 = None
    if why:
        notes.append(why)
    else:
        # ISO 281:2007 table 3: f₀F_a/C₀r (radial contact groove), i f₀F_a/C₀r (angular contact: one row of a pair
        # face-to-face / back-to-back carries the axial load)
        rel = (f0 * fa / c0 * (1 if kind == "deep_groove" else i_table)) if needs_static_rating(alpha, kind) else None
        rel_max = _REL_LOAD[-1] / math.cos(alpha)  # 6.89 (deep groove) … 7.14 (15°)
        if rel is not None and rel > rel_max * (1 + 1e-3):
            notes.append(f"relative axial load (i)·f0·Fa/C0 = {rel:.3g} exceeds ISO 281 table 3 ({rel_max:.3g}): the "
                         "bearing is loaded beyond its permissible axial load; factors of the last row used")
        p = equivalent_dynamic_load(fr, fa, alpha, i_table, kind, rel)
        xye = xy_factors(fr, fa, alpha, i_table, kind, rel)
        out["iso281_factors"] = None if xye is None else {"X": xye[0], "Y": xye[1], "e": xye[2],
                                                          "relative_axial_load": rel}
        if p is None:
            notes.append(f"ISO 281 table 3 has no factors for a {math.degrees(alpha):.3g}° {kind} bearing")
        p0 = equivalent_static_load(fr, fa, alpha, i_table, kind)
    if math.hypot(result.loads.m_y, result.loads.m_z) > 0:
        notes.append("ISO 281 P ignores the moment load; the reference rating life (ISO/TS 16281) includes it")
    out.setdefault("iso281_factors", None)  # X, Y, e of ISO 281 table 3 and f0·Fa/C0r (None: no table 3 answer)
    out["equivalent_dynamic_load_N"] = p
    out["equivalent_static_load_N"] = p0
    l10 = None
    if c <= 0:
        notes.append("no dynamic load rating C in the bearing file: no ISO 281 or ISO/TS 16281 life")
    elif p is not None and p > 0:
        l10 = basic_rating_life(c, p)
    elif p is not None:
        if math.hypot(result.loads.m_y, result.loads.m_z) > 0:
            notes.append("no radial or axial load (P = 0): no ISO 281 basic rating life; the moment load enters the "
                         "reference rating life only")
        else:
            notes.append("no load: infinite rating life")
    row_lives = row_reference_lives(result) if c > 0 else None
    l10r = None if row_lives is None else float(_combine([x for x in row_lives if math.isfinite(x)]))
    if l10r is not None and not math.isfinite(l10r):
        l10r = None
    out["basic_rating_life_million_revolutions"] = l10
    out["reference_rating_life_million_revolutions"] = l10r
    at_rest = not abs(result.speed) > 0
    if at_rest and (l10 is not None or l10r is not None):
        notes.append("speed 0: lives in hours need the operating speed (--speed)")
    out["basic_rating_life_hours"] = life_hours(l10, result.speed) if l10 is not None else None
    out["reference_rating_life_hours"] = life_hours(l10r, result.speed) if l10r is not None else None
    factors = {"reliability_percent": float(reliability), "a1": reliability_factor(reliability)}
    lnm = lnmr = None
    if lubricant is None or temperature is None:
        if l10 is not None or l10r is not None:
            notes.append("no lubricant and temperature (--lubricant, --temperature): no modified rating life")
    elif not at_rest:
        if not hasattr(lubricant, "kinematic_viscosity"):  # a library name or a TOML path
            from .lubricants import get_lubricant

            lubricant = get_lubricant(lubricant)
        nu = lubricant.kinematic_viscosity(temperature)
        nu1 = rated_viscosity(result.speed, row_b.pitch_diameter)
        kappa = nu / nu1
        ec = contamination_factor(contamination, row_b.pitch_diameter)
        factors.update({"viscosity_m2_s": nu, "rated_viscosity_m2_s": nu1, "kappa": kappa, "e_C": ec,
                        "contamination": contamination if isinstance(contamination, str) else "given"})
        if kappa < 0.1:
            notes.append(f"viscosity ratio κ = {kappa:.3g} < 0.1: outside ISO 281, no modified rating life")
        else:
            if kappa > 4.0:
                notes.append(f"κ = {kappa:.3g} > 4: a_ISO at κ = 4 (ISO 281:2007)")
            if l10 is not None and p:
                a_iso = life_modification_factor(kappa, ec * cu / p)
                factors["a_ISO"] = a_iso
                lnm = life_hours(factors["a1"] * a_iso * l10, result.speed)
            if l10r is not None and c > 0:
                p_ref = c / l10r ** (1.0 / 3.0)  # dynamic equivalent reference load (ISO/TS 16281)
                a_iso_r = life_modification_factor(kappa, ec * cu / p_ref)
                factors["a_ISO_reference"] = a_iso_r
                lnmr = life_hours(factors["a1"] * a_iso_r * l10r, result.speed)
    out["modified_rating_life_hours"] = lnm
    out["modified_reference_rating_life_hours"] = lnmr
    out["life_factors"] = factors
    out["static_safety_factor"] = c0 / p0 if p0 else None
    out["static_safety_factor_pressure"] = pressure_safety_factor(result)
    if nrows > 1:
        # per row of a set: its share of the reference life and its pressure-based s0 (which row limits)
        out["row_ratings"] = [
            {"row": k, "reference_rating_life_million_revolutions":
                (row_lives[k] if row_lives is not None and math.isfinite(row_lives[k]) else None),
             "reference_rating_life_hours": (life_hours(row_lives[k], result.speed) if row_lives is not None
                                             and math.isfinite(row_lives[k]) else None),
             "static_safety_factor_pressure": pressure_safety_factor(result, row=k)}
            for k in range(nrows)]
    out["estimated"] = estimated
    out["life_notes"] = notes
    return out


def _table3_columns(alpha: float, kind: str, rows: int, needs_rel: bool):
    """The ISO 281 table-3 factors of one bearing as piecewise-linear columns in the relative axial load:
    (grid, e, X_high, Y_high, X_low, Y_low) [-], exact for :func:`xy_factors` at this angle (every column's
    breakpoints are in ``grid``; np.interp clamps like the table)."""
    if needs_rel:
        grid = sorted(set(_REL_LOAD) | {v for col in _REL_LOAD_BY_ANGLE.values() for v in col})
    else:
        grid = [1.0]
    cols = []
    for rel in grid:
        r = rel if needs_rel else None
        x_hi, y_hi, e = xy_factors(1.0, 1e9, alpha, rows, kind, r)
        x_lo, y_lo, _ = xy_factors(1.0, 0.0, alpha, rows, kind, r)
        cols.append((e, x_hi, y_hi, x_lo, y_lo))
    return (np.asarray(grid),) + tuple(np.asarray(c) for c in zip(*cols))


def basic_rating_life_arrays(bearing, fr, fa, speed) -> tuple[np.ndarray, np.ndarray]:
    """ISO 281:2007 basic rating life of one bearing (or bearing set) over arrays of operating points:
    (L10 [10^6 rev], L10h [h]), broadcast over ``fr`` (radial load magnitude [N]), ``fa`` (axial load [N]) and
    ``speed`` [rad/s].  Same rules as :func:`rating_summary` (P = X F_r + Y F_a of table 3 with f₀F_a/C₀r, or
    i f₀F_a/C₀r for angular contact, C₀ and f₀ from the bearing file or estimated, L10 = (C/P)^3,
    L10h = 10^6 L10/(60 n)); moments are not part of ISO 281's P.  L10 is +inf where P = 0, NaN where ISO 281
    gives no life (no C, angle outside table 3, more than two rows); L10h is NaN at speed 0."""
    fr, fa, speed = np.broadcast_arrays(np.abs(np.asarray(fr, float)), np.abs(np.asarray(fa, float)),
                                        np.abs(np.asarray(speed, float)))
    kind, alpha, i_table, _, _, why, c, c0, f0, _, _, _ = _bearing_ratings(bearing)
    nan = np.full(fr.shape, np.nan)
    if why or not c > 0:
        return nan, nan.copy()
    needs_rel = needs_static_rating(alpha, kind)
    if kind != "deep_groove" and xy_factors(1.0, 1.0, alpha, i_table, kind, 1.0) is None:
        return nan, nan.copy()
    grid, e_c, xh_c, yh_c, xl_c, yl_c = _table3_columns(alpha, kind, i_table, needs_rel)
    rel = f0 * fa / c0 * (1 if kind == "deep_groove" else i_table) if needs_rel else np.ones(fr.shape)
    e = np.interp(rel, grid, e_c)
    with np.errstate(divide="ignore", invalid="ignore"):
        high = np.where(fr > 0, fa / np.where(fr > 0, fr, 1.0) > e, fa > 0)
        x = np.where(high, np.interp(rel, grid, xh_c), np.interp(rel, grid, xl_c))
        y = np.where(high, np.interp(rel, grid, yh_c), np.interp(rel, grid, yl_c))
        p = x * fr + y * fa
        l10 = np.where(p > 0, (c / np.where(p > 0, p, 1.0)) ** 3, np.inf)
        n = speed * 30.0 / math.pi
        l10h = np.where(n > 0, l10 * 1e6 / (60.0 * np.where(n > 0, n, 1.0)), np.nan)
    return l10, l10h


def iso281_life(result) -> float | None:
    """ISO 281 basic rating life [10^6 rev] from the external loads of a result (None when not applicable:
    no rating, an arrangement outside ISO 281, or no load — an infinite life is not a JSON number)."""
    if getattr(result, "rating", None) is not None:
        return result.rating["basic_rating_life_million_revolutions"]
    return rating_summary(result)["basic_rating_life_million_revolutions"]


def apply_rating(result, lubricant=None, temperature: float | None = None, contamination="normal",
                 reliability: float = 90.0) -> dict:
    """Store :func:`rating_summary` on a :class:`~bearingsim.statics.jones_harris.StaticResult` (``rating``,
    ``basic_rating_life``, ``reference_rating_life``) and its static-safety warnings (``warnings``, once);
    returns the summary.  :func:`~bearingsim.statics.jones_harris.solve` calls it without lubricant; call it
    again with the operating lubricant and temperature for the modified rating lives."""
    from .safety import safety_warnings

    old = safety_warnings(result.rating) if getattr(result, "rating", None) else []
    s = rating_summary(result, lubricant, temperature, contamination, reliability)
    result.rating = s
    result.basic_rating_life = s["basic_rating_life_million_revolutions"]
    result.reference_rating_life = s["reference_rating_life_million_revolutions"]
    warnings = [w for w in (getattr(result, "warnings", None) or []) if w not in old]
    result.warnings = warnings + safety_warnings(s)
    return s
