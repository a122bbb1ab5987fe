"""Operating clearance and preload: interference fits, temperatures, centrifugal expansion.

Harris & Kotzalas 2007 vol. 1 ch. 4 ("Bearing internal clearance and preload" / fitting practice);
thick-walled cylinder (Lamé) formulas, plane stress (Timoshenko & Goodier, Theory of Elasticity,
§§ 28, 32):

* Interference fit of the inner ring (bore d, raceway diameter D_i) on a hollow shaft (bore d_s),
  diametral interference I:
      p = I / { d [ (1/E_s)((d² + d_s²)/(d² − d_s²) − ν_s) + (1/E_r)((D_i² + d²)/(D_i² − d²) + ν_r) ] }
      ΔD_i = 2 p d² D_i / [E_r (D_i² − d²)]                     (raceway expansion)
  For equal materials and a solid shaft, ΔD_i = I d / D_i (Harris & Kotzalas vol. 1 ch. 4).
* Outer ring (outside diameter D, raceway D_o) in a housing of outside diameter D_h:
      p = I / { D [ (1/E_h)((D_h² + D²)/(D_h² − D²) + ν_h) + (1/E_r)((D² + D_o²)/(D² − D_o²) − ν_r) ] }
      ΔD_o = −2 p D² D_o / [E_r (D² − D_o²)]                    (raceway contraction)
  For equal materials, |ΔD_o| = I (D_o/D)(1 − (D/D_h)²)/(1 − (D_o/D_h)²).
* Temperatures (reference T_ref): raceway diameters grow by α ΔT D, balls by α_b ΔT_b D_w, and the
  fits change by ΔI_shaft = (α_s ΔT_s − α_i ΔT_i) d, ΔI_housing = (α_o ΔT_o − α_h ΔT_h) D (a fit that
  becomes loose carries no pressure).
* Centrifugal expansion of the rotating inner ring (annular disc of bore radius a, outer radius b,
  free; plane stress):
      u(b) = ρω²b/(8E) [ (3+ν)(1−ν)(a² + b²) + (3+ν)(1+ν) a² − (1−ν²) b² ],   ΔD_i = 2 u(b)
  (thin-ring limit u = ρω²b³/E).  The shaft's own expansion (which relieves the fit) is neglected.
* Diametral clearance change ΔP_d = ΔD_o − ΔD_i − 2 ΔD_w (negative = less clearance = more preload).
* Axial thermal growth of the shaft relative to the housing over the row spacing L,
  δL = (α_s ΔT_s − α_h ΔT_h) L, moves each inner ring away from the centre by δL/2: a back-to-back
  (DB) pair loses preload (Δe = −δL/2 per row), a face-to-face (DF) pair gains it (Δe = +δL/2).

Raceway diameters (groove bottoms) are taken as D_i = d_m − D_w and D_o = d_m + D_w unless given.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from ..errors import InputError

STEEL_EXPANSION = 11.5e-6  #: [1/K] bearing steel (SKF catalogue: 52100-type steel ≈ 11.5–12.5e-6 /K)
SILICON_NITRIDE_EXPANSION = 3.2e-6  #: [1/K] (SKF hybrid bearing property table: 3.2e-6 /K)
STEEL_E = 208e9  #: [Pa] default shaft and housing modulus
STEEL_NU = 0.3


def fit_pressure_shaft(interference, d, d_shaft_bore, d_raceway, e_shaft, nu_shaft, e_ring, nu_ring) -> float:
    """Contact pressure of an inner ring on a hollow shaft [Pa] (Lamé; Harris & Kotzalas vol. 1 ch. 4).

    interference : diametral [m]; d : bore [m]; d_shaft_bore : shaft bore (0 solid) [m];
    d_raceway : inner raceway diameter [m]; moduli [Pa]."""
    if interference <= 0:
        return 0.0
    cs = ((d**2 + d_shaft_bore**2) / (d**2 - d_shaft_bore**2) - nu_shaft) / e_shaft
    cr = ((d_raceway**2 + d**2) / (d_raceway**2 - d**2) + nu_ring) / e_ring
    return interference / (d * (cs + cr))


def inner_raceway_expansion(p, d, d_raceway, e_ring) -> float:
    """ΔD_i = 2 p d² D_i / [E (D_i² − d²)]  [m] (ring under internal pressure p [Pa], Lamé)."""
    return 2.0 * p * d**2 * d_raceway / (e_ring * (d_raceway**2 - d**2))


def fit_pressure_housing(interference, d_out, d_housing, d_raceway, e_housing, nu_housing, e_ring, nu_ring) -> float:
    """Contact pressure of an outer ring in a housing [Pa] (Lamé; Harris & Kotzalas vol. 1 ch. 4).

    d_out : ring outside diameter [m]; d_housing : housing outside diameter [m]; d_raceway : outer raceway [m]."""
    if interference <= 0:
        return 0.0
    ch = ((d_housing**2 + d_out**2) / (d_housing**2 - d_out**2) + nu_housing) / e_housing
    cr = ((d_out**2 + d_raceway**2) / (d_out**2 - d_raceway**2) - nu_ring) / e_ring
    return interference / (d_out * (ch + cr))


def outer_raceway_contraction(p, d_out, d_raceway, e_ring) -> float:
    """|ΔD_o| = 2 p D² D_o / [E (D² − D_o²)]  [m] (ring under external pressure p [Pa], Lamé)."""
    return 2.0 * p * d_out**2 * d_raceway / (e_ring * (d_out**2 - d_raceway**2))


def centrifugal_expansion(omega, bore, d_raceway, density, e, nu) -> float:
    """Diametral growth of a free rotating ring's outer surface [m] (rotating annular disc, plane stress).

    ΔD = 2 u(b),  u(b) = ρω²b/(8E) [(3+ν)(1−ν)(a²+b²) + (3+ν)(1+ν)a² − (1−ν²)b²],  a = bore/2, b = D_i/2
    (Timoshenko & Goodier § 32).  omega [rad/s], density [kg/m³], e [Pa]."""
    a = 0.5 * bore
    b = 0.5 * d_raceway
    u = density * omega**2 * b / (8.0 * e) * ((3 + nu) * (1 - nu) * (a * a + b * b) + (3 + nu) * (1 + nu) * a * a
                                             - (1 - nu * nu) * b * b)
    return 2.0 * u


@dataclass(frozen=True)
class OperatingClearance:
    """Mounting and operating conditions of a bearing (all SI; temperatures [K]).

    Parameters
    ----------
    shaft_interference, housing_interference : diametral interference [m] (negative = loose)
    shaft_bore : bore of a hollow shaft [m] (0 solid)
    housing_outside_diameter : [m] (0: rigid housing, infinitely thick)
    shaft_modulus, shaft_poisson, housing_modulus, housing_poisson : [Pa], [-]
    reference_temperature : temperature at which the fits and preload are given [K]
    inner_ring_temperature, outer_ring_temperature, ball_temperature, shaft_temperature,
    housing_temperature : operating temperatures [K] (None: the reference; balls: mean of the rings;
        shaft: inner ring; housing: outer ring)
    ring_expansion, ball_expansion, shaft_expansion, housing_expansion : [1/K] (None: from the materials)
    speed : inner-ring speed for the centrifugal expansion [rad/s]
    """

    shaft_interference: float = 0.0
    housing_interference: float = 0.0
    shaft_bore: float = 0.0
    housing_outside_diameter: float = 0.0
    shaft_modulus: float = STEEL_E
    shaft_poisson: float = STEEL_NU
    housing_modulus: float = STEEL_E
    housing_poisson: float = STEEL_NU
    reference_temperature: float = 293.15
    inner_ring_temperature: float | None = None
    outer_ring_temperature: float | None = None
    ball_temperature: float | None = None
    shaft_temperature: float | None = None
    housing_temperature: float | None = None
    ring_expansion: float | None = None
    ball_expansion: float | None = None
    shaft_expansion: float = STEEL_EXPANSION
    housing_expansion: float = STEEL_EXPANSION
    speed: float = 0.0

    def __post_init__(self):
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if v is None:
                continue
            if not math.isfinite(v):
                raise InputError(f"clearance.{f.name}", f"must be finite, got {v!r}", "give a finite value")
            if f.name.endswith("temperature") and v <= 0:
                raise InputError(f"clearance.{f.name}", f"{v} K is below absolute zero", 'e.g. "60 degC"')
            if f.name.endswith("modulus") and v <= 0:
                raise InputError(f"clearance.{f.name}", "must be positive", 'e.g. "208 GPa"')
            if f.name.endswith("poisson") and not (0 <= v < 0.5):
                raise InputError(f"clearance.{f.name}", f"must lie in [0, 0.5), got {v}", "e.g. 0.3")
        if self.shaft_bore < 0 or self.housing_outside_diameter < 0:
            raise InputError("clearance.shaft_bore", "diameters must not be negative", "give 0 for solid/rigid")

    # ---- per bearing ---------------------------------------------------------------------------
    def _temps(self):
        tref = self.reference_temperature
        ti = self.inner_ring_temperature if self.inner_ring_temperature is not None else tref
        to = self.outer_ring_temperature if self.outer_ring_temperature is not None else tref
        tb = self.ball_temperature if self.ball_temperature is not None else 0.5 * (ti + to)
        ts = self.shaft_temperature if self.shaft_temperature is not None else ti
        th = self.housing_temperature if self.housing_temperature is not None else to
        return tref, ti, to, tb, ts, th

    def change(self, bearing) -> dict:
        """Raceway and clearance changes of one single-row bearing [m] and fit pressures [Pa]."""
        d, dout = bearing.bore, bearing.outside_diameter
        if (self.shaft_interference != 0 or self.speed != 0) and not d > 0:
            raise InputError("bore", "the bearing file gives no bore: needed for the shaft fit and the "
                             "centrifugal expansion", 'add bore = "55 mm" to the bearing file')
        if self.housing_interference != 0 and not dout > 0:
            raise InputError("outside_diameter", "the bearing file gives no outside diameter: needed for the "
                             "housing fit", 'add outside_diameter = "90 mm" to the bearing file')
        dw, dm = bearing.ball_diameter, bearing.pitch_diameter
        di, do = dm - dw, dm + dw
        er, nur = bearing.ring_material.youngs_modulus, bearing.ring_material.poisson_ratio
        a_r = self.ring_expansion if self.ring_expansion is not None else STEEL_EXPANSION
        if self.ball_expansion is not None:
            a_b = self.ball_expansion
        else:
            a_b = SILICON_NITRIDE_EXPANSION if "nitride" in bearing.ball_material.name.lower() else STEEL_EXPANSION
        tref, ti, to, tb, ts, th = self._temps()
        i_s = self.shaft_interference + (self.shaft_expansion * (ts - tref) - a_r * (ti - tref)) * (d if d > 0 else 0)
        i_h = self.housing_interference + (a_r * (to - tref) - self.housing_expansion * (th - tref)) * \
            (dout if dout > 0 else 0)
        if self.shaft_bore >= d > 0:
            raise InputError("clearance.shaft_bore", "the shaft bore is not smaller than the bearing bore",
                             "check shaft_bore")
        p_s = fit_pressure_shaft(i_s, d, self.shaft_bore, di, self.shaft_modulus, self.shaft_poisson, er, nur) \
            if d > 0 else 0.0
        if dout > 0:
            if self.housing_outside_diameter > 0:
                if self.housing_outside_diameter <= dout:
                    raise InputError("clearance.housing_outside_diameter", "not larger than the bearing's outside "
                                     "diameter", "give the housing's outside diameter, or 0 for a rigid housing")
                p_h = fit_pressure_housing(i_h, dout, self.housing_outside_diameter, do, self.housing_modulus,
                                           self.housing_poisson, er, nur)
            else:
                # infinitely thick housing: (D_h² + D²)/(D_h² − D²) → 1
                p_h = 0.0 if i_h <= 0 else i_h / (dout * ((1 + self.housing_poisson) / self.housing_modulus
                                                          + ((dout**2 + do**2) / (dout**2 - do**2) - nur) / er))
        else:
            p_h = 0.0
        dDi_fit = inner_raceway_expansion(p_s, d, di, er) if p_s > 0 else 0.0
        dDo_fit = -outer_raceway_contraction(p_h, dout, do, er) if p_h > 0 else 0.0
        dDi_th = a_r * (ti - tref) * di
        dDo_th = a_r * (to - tref) * do
        dDw = a_b * (tb - tref) * dw
        dDi_cf = centrifugal_expansion(self.speed, d, di, bearing.ring_material.density, er, nur) \
            if self.speed != 0 else 0.0
        dpd = (dDo_fit + dDo_th) - (dDi_fit + dDi_th + dDi_cf) - 2.0 * dDw
        return {"shaft_fit_pressure_Pa": p_s, "housing_fit_pressure_Pa": p_h,
                "inner_raceway_fit_m": dDi_fit, "outer_raceway_fit_m": dDo_fit,
                "inner_raceway_thermal_m": dDi_th, "outer_raceway_thermal_m": dDo_th, "ball_thermal_m": dDw,
                "inner_raceway_centrifugal_m": dDi_cf, "diametral_clearance_change_m": dpd}

    def axial_offset_change(self, spacing: float, arrangement: str) -> float:
        """Δe per row [m] from the shaft's axial growth relative to the housing over ``spacing`` [m]."""
        tref, ti, to, tb, ts, th = self._temps()
        dl = (self.shaft_expansion * (ts - tref) - self.housing_expansion * (th - tref)) * spacing
        if arrangement == "DB":
            return -0.5 * dl
        if arrangement == "DF":
            return 0.5 * dl
        return 0.0

    def apply(self, system):
        """A copy of a bearing (system) with the operating clearance and offsets; for a system the
        preload at rest before and after is written to ``notes["operating_clearance"]``."""
        from . import arrangements as ar

        if not isinstance(system, ar.BearingSystem):
            ch = self.change(system)
            return dataclasses.replace(system, diametral_clearance=system.diametral_clearance
                                       + ch["diametral_clearance_change_m"])
        before = system.rest_preload() if any(r.axial_offset > 0 for r in system.rows) else None
        rows = []
        spacing = max(r.position for r in system.rows) - min(r.position for r in system.rows)
        de = self.axial_offset_change(spacing, system.arrangement)
        changes = []
        for r in system.rows:
            ch = self.change(r.bearing)
            changes.append(ch)
            b = dataclasses.replace(r.bearing, diametral_clearance=r.bearing.diametral_clearance
                                    + ch["diametral_clearance_change_m"])
            rows.append(dataclasses.replace(r, bearing=b, axial_offset=r.axial_offset + de))
        new = dataclasses.replace(system, rows=tuple(rows))
        after = new.rest_preload()
        notes = dict(system.notes)
        notes["operating_clearance"] = {
            "diametral_clearance_change_m": [c["diametral_clearance_change_m"] for c in changes],
            "axial_offset_change_m": de,
            "preload_before_N": None if before is None else [float(v) for v in before],
            "preload_after_N": [float(v) for v in after],
            "details": changes,
        }
        return dataclasses.replace(new, notes=notes)


#: the TOML reader moved to :mod:`bearingsim.io.clearance` (files are read at the edge); its names are
#: forwarded on first use (a module-level import would be a cycle: io.clearance imports this module)
_FORWARDED = ("_KEYS", "operating_clearance_from_dict")


def __getattr__(name: str):
    if name in _FORWARDED:
        from ..io import clearance as _reader

        return getattr(_reader, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
