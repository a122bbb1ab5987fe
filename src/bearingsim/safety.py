"""Static safety of ball bearings (ISO 76:2006).

* Static equivalent radial load (ISO 76:2006, with table 4 for radial ball bearings):
      P₀r = X₀ F_r + Y₀ F_a,   and P₀r = F_r when that is larger (single-row bearings, X₀ < 1)
  X₀ = 0.6, Y₀ = 0.5 for radial contact groove (deep-groove) bearings, single and double row; angular contact
  groove bearings: X₀ = 0.5 (single row) / 1 (double row, or a pair face-to-face/back-to-back), Y₀ from the
  table for 5°–45° (linear interpolation between tabulated angles; a tandem pair takes the single-row values).
* Static safety factor s₀ = C₀/P₀ (ISO 76:2006 annex, the ratio the bearing makers tabulate requirements for).
* Static safety factor from the computed contact pressure: ISO 76 defines C₀ of ball bearings as the load at
  which the most heavily loaded contact reaches 4 200 MPa.  In a Hertz point contact p_max ∝ Q^(1/3)
  (p_max = 3Q/(2πab) with a, b ∝ Q^(1/3): Hamrock & Brewe 1983, :mod:`bearingsim.contact.hertz`), so the factor
  by which the load may grow until p_max reaches 4 200 MPa is s₀,p = (4 200 MPa / p_max)³: the same meaning as C₀/P₀ — a
  ratio of loads — but from the actual load distribution (clearance, moments, preload, centrifugal forces)
  instead of the table's Stribeck distribution.

Units: forces [N], pressures [Pa], angles [rad].
"""

from __future__ import annotations

import math

from .life import interp
from .limits import STATIC_PRESSURE_LIMIT

#: ISO 76:2006 table 4, angular contact groove ball bearings: nominal angle [deg] -> Y₀ (single row);
#: the double row / pair value is twice it, X₀ = 0.5 (single) and 1 (double)
_Y0_ANGULAR = {5: 0.52, 10: 0.50, 15: 0.46, 20: 0.42, 25: 0.38, 30: 0.33, 35: 0.29, 40: 0.26, 45: 0.22}
_ANGLES = tuple(sorted(_Y0_ANGULAR))


def static_factors(contact_angle: float, rows: int = 1, kind: str = "angular_contact") -> tuple[float, float] | None:
    """(X₀, Y₀) [-] of ISO 76:2006 table 4; ``rows`` 1 (single row, tandem pair) or 2 (double row, pair
    face-to-face/back-to-back).  ``None`` for an angular contact angle outside 5°–45°."""
    if kind == "deep_groove":
        return 0.6, 0.5
    deg = math.degrees(contact_angle)
    if not 5.0 - 1e-9 <= deg <= 45.0 + 1e-9:
        return None
    y0 = interp(deg, _ANGLES, [_Y0_ANGULAR[a] for a in _ANGLES])
    return (0.5, y0) if rows == 1 else (1.0, 2.0 * y0)


def equivalent_static_load(fr: float, fa: float, contact_angle: float, rows: int = 1,
                           kind: str = "angular_contact") -> float | None:
    """P₀r [N] = max(X₀ F_r + Y₀ F_a, F_r) (ISO 76:2006); ``None`` outside table 4."""
    f = static_factors(contact_angle, rows, kind)
    if f is None:
        return None
    x0, y0 = f
    fr, fa = abs(fr), abs(fa)
    return max(x0 * fr + y0 * fa, fr)


def max_contact_pressure(result, row: int | None = None) -> float:
    """Largest Hertz pressure of any ball (of ``row``, or of all rows) on either raceway [Pa] (0 when no ball is
    loaded)."""
    b = result.balls
    if not len(b.get("inner_max_pressure_Pa", ())):
        return 0.0
    pi, po = b["inner_max_pressure_Pa"], b["outer_max_pressure_Pa"]
    if row is not None:
        sel = b["row"] == row
        if not sel.any():
            return 0.0
        pi, po = pi[sel], po[sel]
    return float(max(pi.max(), po.max()))


def pressure_safety_factor(result, limit: float = STATIC_PRESSURE_LIMIT, row: int | None = None) -> float | None:
    """s₀,p = (limit / p_max)³ [-] with the ISO 76 reference pressure 4 200 MPa (module docstring), over all
    rows or of one ``row``; ``None`` when no ball is loaded or the result did not converge."""
    if not getattr(result, "converged", True):
        return None
    p = max_contact_pressure(result, row)
    if not p > 0:
        return None
    return (limit / p) ** 3


def safety_warnings(summary: dict) -> list[str]:
    """Readable warnings of a :func:`bearingsim.life.rating_summary`: s₀ = C₀/P₀ below 1 (the static load
    exceeds the basic static load rating: permanent deformation above 1e-4 of the ball diameter, ISO 76)."""
    out = []
    s0 = summary.get("static_safety_factor")
    if s0 is not None and s0 < 1.0:
        est = " (C0 estimated)" if "static_load_rating_N" in summary.get("estimated", ()) else ""
        out.append(f"static safety factor s0 = C0/P0 = {s0:.3g} < 1{est}: the static equivalent load exceeds the "
                   "basic static load rating (ISO 76:2006): permanent raceway deformation")
    return out
