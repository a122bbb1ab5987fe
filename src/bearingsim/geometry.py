"""Bearing geometry: a single-row ball bearing, checked on construction.

All fields are SI floats (units are parsed at the edge, :mod:`bearingsim.io`).

Geometry conventions (Harris & Kotzalas 2007 vol. 1 ch. 2): D ball diameter, d_m
pitch diameter, f = r/D groove conformity, A = (f_i + f_o − 1) D the distance between
the groove-curvature centres when the balls just touch both raceways, free contact
angle α₀.  An angular contact bearing is defined by its free contact angle; its
*centred position* (the origin of every displacement we report, ISO/TS 16281) is the
unloaded position with the balls just touching both raceways, minus any extra
diametral clearance P_d.  A deep-groove bearing has its groove centres in one plane;
its free contact angle follows from the clearance, cos α₀ = 1 − P_d / (2A)
(Harris & Kotzalas 2007 vol. 1 eq. 2.10).

Plausibility bounds: values outside them are refused with
:class:`~bearingsim.errors.InputError` when a bearing is built (from a file or in code).  They are
wide engineering bounds, meant to catch unit slips (a bare ``72.5`` read as metres, ``E = 1 Pa``)
and impossible geometry, not to judge a design.  :data:`LIMITS` holds the numbers.

========================  ==============================  ==================================================
field                     accepted                        why
========================  ==============================  ==================================================
ball_diameter D           0.5 mm – 200 mm                 miniature bearings (0.5–1 mm balls) to the largest
                                                          balls of slewing rings
pitch_diameter d_m        1.5 mm – 10 m, and > 1.05 D     smallest miniature bearings to large slewing
                                                          rings; the inner raceway must exist
ball_count Z              3 – 1000, and d_m sin(π/Z) > D  three balls centre a ring; slewing rings of some
                                                          metres carry a few hundred balls; neighbours must
                                                          not overlap (checked before anything is sized by Z)
inner/outer_conformity f  0.5 < f ≤ 1                     the groove radius exceeds the ball radius
contact_angle α₀          0 – 89°                         angular contact (up to thrust-like angles)
diametral_clearance P_d   ≥ −5 % A and α_f ≤ 80°          interference beyond 5 % of A is no preload; the free
                                                          contact angle once the clearance is taken up,
                                                          cos α_f = cos α₀ − P_d/(2A) (Harris & Kotzalas 2007
                                                          vol. 1 eq. 2.10 for α₀ = 0), past 80° puts the
                                                          contact on or over the groove shoulder
bore, outside_diameter    ≥ 0 (0 = unknown); bore < d_m−D, the rings must hold the ball set
                          OD > d_m+D
width                     ≥ 0 (0 = unknown), ≥ D if given  the rings enclose the balls
dynamic_load_rating C     ≥ 0 (0 = unknown), finite       a rating is a positive force
static_load_rating C₀     ≥ 0 (0 = unknown), finite       ISO 76 basic static load rating, a positive force
geometry_factor_f0 f₀     0 (unknown) or 5 – 30           ISO 76 factor (radial ball bearings ≈ 12–17)
fatigue_load_limit P_u    ≥ 0 (0 = unknown), ≤ C₀ if both  ISO 281 fatigue load limit; below the static rating
limiting_speed            ≥ 0 (0 = unknown), finite       a speed rating is positive (file: with its unit, rpm)
Young's modulus E         1 GPa – 1000 GPa                polymers (~2 GPa) to tungsten carbide (~600 GPa)
Poisson's ratio ν         0 ≤ ν < 0.5                     isotropic engineering solids
density ρ                 500 – 25 000 kg/m³              polymers to tungsten carbide (15 600 kg/m³)
========================  ==============================  ==================================================

(E, ν, ρ are checked by :class:`~bearingsim.materials.Material`, with the bounds in
:data:`bearingsim.materials.LIMITS`.)

The rows protocol
-----------------
Every bearing the solvers take — a :class:`BallBearing` (one row) and a
:class:`~bearingsim.statics.arrangements.BearingSystem` (a set or a double-row unit) — answers the same
three questions, and nothing downstream asks a bearing anything else about its rows:

* ``bearing.rows`` — a tuple of :class:`Row`: the single-row geometry of every row with its axial
  position, orientation, preload offset and first-ball azimuth (a :class:`BallBearing` is one
  :class:`Row` at the origin);
* ``bearing.load_point`` [m] — the axial position where the external loads act (0 for one row);
* ``bearing.row_vectors()`` — the kernel parameter vectors of the rows, float[nrow, NPAR] in the layout
  of :mod:`bearingsim.statics.layout`, kernel origin at the load point (:func:`row_vectors`, written
  once, from ``rows`` and ``load_point``).

Per-row physics (materials, conformities, Hertz constants, ratings) is read from ``row.bearing``; it is
never recovered from the kernel vectors.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .contact import hertz
from .errors import InputError
from .materials import Material
from .statics import layout as rl

#: plausibility bounds (module docstring table), SI: [m], [-], [rad]
LIMITS = {
    "ball_diameter": (0.5e-3, 0.2),
    "pitch_diameter": (1.5e-3, 10.0),
    "ball_count": (3, 1000),
    "max_free_contact_angle": (0.0, math.radians(80.0)),
}

_FLOAT_FIELDS = ("ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity", "contact_angle",
                 "diametral_clearance", "bore", "outside_diameter", "width", "dynamic_load_rating",
                 "limiting_speed", "static_load_rating", "geometry_factor_f0", "fatigue_load_limit")


def _real(value, name: str) -> float:
    """A finite real number (not a bool, a string or None) as float, else InputError naming ``name``."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | float | np.integer | np.floating):
        raise InputError(name, f"expected a number in SI units, got {type(value).__name__} {value!r}"[:160],
                         "give a float (SI units)")
    if not math.isfinite(value):
        raise InputError(name, f"must be finite, got {value!r}", "give a finite float")
    return float(value)


@dataclass(frozen=True)
class Row:
    """One row of balls of a bearing (the rows protocol, module docstring).

    Parameters
    ----------
    bearing : BallBearing  the single-row geometry
    position : float  [m]  axial position of the row plane from the bearing's centre
    orientation : float  +1 or −1 (−1 mirrors the contact angle)
    axial_offset : float  [m]  preload offset e of the inner groove centres (local axial direction)
    first_ball_azimuth : float  [rad]
    """

    bearing: "BallBearing"
    position: float = 0.0
    orientation: float = 1.0
    axial_offset: float = 0.0
    first_ball_azimuth: float = 0.0

    def __post_init__(self):
        if not isinstance(self.bearing, BallBearing):
            raise InputError("rows.bearing", f"expected a single-row bearing, got {type(self.bearing).__name__}",
                             "give a catalogue name or a single-row TOML file for every row")
        for name in ("position", "orientation", "axial_offset", "first_ball_azimuth"):  # a finite SI float each
            object.__setattr__(self, name, _real(getattr(self, name), f"rows.{name}"))
        if self.orientation not in (1.0, -1.0):
            raise InputError("rows.orientation", f"must be +1 or -1, got {self.orientation!r}",
                             "+1: contact angle as defined, -1: mirrored")

    def vector(self, load_point: float = 0.0) -> np.ndarray:
        """Kernel parameter vector of this row (layout :mod:`bearingsim.statics.layout`), origin at
        ``load_point`` [m]."""
        return self.bearing.row_parameters(self.position - load_point, float(self.orientation), self.axial_offset,
                                           self.first_ball_azimuth)


def row_vectors(bearing) -> np.ndarray:
    """Kernel parameter vectors float[nrow, NPAR] of any bearing of the rows protocol (module docstring)."""
    lp = bearing.load_point
    return np.array([r.vector(lp) for r in bearing.rows])


#: the rings that can turn (the other one stands)
ROTATING_RINGS = ("inner", "outer")


def rotating_ring_of(bearing) -> str:
    """``"inner"`` or ``"outer"``: the turning ring of a bearing of the rows protocol (every row's)."""
    rings = {r.bearing.rotating_ring for r in bearing.rows}
    if len(rings) != 1:
        raise InputError("rotating_ring", "the rows of one bearing turn different rings",
                         "give every row the same rotating_ring")
    return rings.pop()


def with_rotating_ring(bearing, ring: str):
    """A copy of ``bearing`` (a :class:`BallBearing` or a bearing of rows) whose ``ring`` (``"inner"`` or
    ``"outer"``) turns; the bearing itself when it already does."""
    if ring not in ROTATING_RINGS:
        raise InputError("rotating_ring", f"must be inner or outer, got {ring!r}",
                         '"inner" (the shaft turns) or "outer" (the housing turns)')
    if isinstance(bearing, BallBearing):
        return bearing if bearing.rotating_ring == ring else dataclasses.replace(bearing, rotating_ring=ring)
    if rotating_ring_of(bearing) == ring:
        return bearing
    rows = tuple(dataclasses.replace(r, bearing=dataclasses.replace(r.bearing, rotating_ring=ring))
                 for r in bearing.rows)
    return dataclasses.replace(bearing, rows=rows)


@dataclass(frozen=True)
class BallBearing:
    """A single-row ball bearing.

    Parameters
    ----------
    name : str
    kind : str  ``"angular_contact"`` or ``"deep_groove"``
    ball_diameter : float  [m]
    ball_count : int  [-]
    pitch_diameter : float  [m]
    inner_conformity, outer_conformity : float  [-]  groove radius / ball diameter (> 0.5)
    contact_angle : float  [rad]  free contact angle α₀
    diametral_clearance : float  [m]  extra radial play in the centred position (negative: interference)
    ball_material, ring_material : Material
    bore, outside_diameter, width : float  [m]  boundary dimensions (0 when unknown)
    dynamic_load_rating : float  [N]  basic dynamic load rating C (0 when unknown)
    limiting_speed : float  [rad/s]  the manufacturer's limiting (mechanical) speed (0 when unknown): results above
        it carry a warning (:mod:`bearingsim.limits`)
    static_load_rating : float  [N]  basic static load rating C₀ (ISO 76:2006; 0 when unknown)
    geometry_factor_f0 : float  [-]  factor f₀ of ISO 76:2006 table 1, used by ISO 281 for f₀F_a/C₀ (0 when unknown)
    fatigue_load_limit : float  [N]  fatigue load limit P_u (ISO 281:2007 §9.3; 0 when unknown)
    rotating_ring : str  ``"inner"`` (the inner ring turns at the speed of a solve, the outer ring stands) or
        ``"outer"`` (the outer ring turns, e.g. a wheel hub on a standing spindle); the ball speeds, centrifugal
        force and gyroscopic moment follow from it (:func:`bearingsim.statics._kernels.ball_eval`)
    notes : dict  source of every number (the ``[sources]`` table of a file, field → text; a text starting with
        ``ESTIMATE`` or ``ASSUMED`` marks that field as estimated: :attr:`sources`, :attr:`estimated`)
    """

    name: str
    kind: str
    ball_diameter: float
    ball_count: int
    pitch_diameter: float
    inner_conformity: float
    outer_conformity: float
    contact_angle: float
    ball_material: Material
    ring_material: Material
    diametral_clearance: float = 0.0
    bore: float = 0.0
    outside_diameter: float = 0.0
    width: float = 0.0
    dynamic_load_rating: float = 0.0
    limiting_speed: float = 0.0
    static_load_rating: float = 0.0
    geometry_factor_f0: float = 0.0
    fatigue_load_limit: float = 0.0
    rotating_ring: str = "inner"
    notes: dict = field(default_factory=dict, compare=False, hash=False)

    def __post_init__(self):
        self._check_types()
        if self.rotating_ring not in ROTATING_RINGS:
            raise InputError("rotating_ring", f"must be inner or outer, got {self.rotating_ring!r}",
                             'rotating_ring = "inner" (the shaft turns) or "outer" (the housing turns)')
        d = self.ball_diameter
        if self.kind not in ("angular_contact", "deep_groove"):
            raise InputError("type", f"unknown bearing type {self.kind!r}",
                             'use "angular_contact" or "deep_groove"')
        zlo, zhi = LIMITS["ball_count"]
        if not zlo <= self.ball_count <= zhi:  # first: nothing may be sized by an absurd count
            raise InputError("ball_count", f"must be an integer in {zlo}–{zhi}, got {self.ball_count!r}",
                             "give the number of balls of one row, e.g. 16")
        if not (math.isfinite(d) and d > 0):
            raise InputError("ball_diameter", f"must be positive, got {d!r} m", 'e.g. "11.1 mm"')
        lo, hi = LIMITS["ball_diameter"]
        if not lo <= d <= hi:
            raise InputError("ball_diameter", f"{d * 1e3:.4g} mm is outside the plausible {lo * 1e3:g}–{hi * 1e3:g} mm",
                             'check the value and its unit, e.g. "11.1 mm"')
        if not (math.isfinite(self.pitch_diameter) and self.pitch_diameter > 0):
            raise InputError("pitch_diameter", f"must be positive, got {self.pitch_diameter!r} m", 'e.g. "61 mm"')
        lo, hi = LIMITS["pitch_diameter"]
        if not lo <= self.pitch_diameter <= hi:
            raise InputError("pitch_diameter", f"{self.pitch_diameter * 1e3:.6g} mm is outside the plausible "
                             f"{lo * 1e3:g} mm – {hi:g} m", 'check the value and its unit, e.g. "61 mm"')
        for fname in ("inner_conformity", "outer_conformity"):
            f = getattr(self, fname)
            if not (math.isfinite(f) and f > 0.5):
                groove = fname.replace("conformity", "groove_radius")
                raise InputError(fname, f"groove radius must exceed the ball radius: f = {f!r} ≤ 0.5",
                                 f"give {groove} > ball_diameter/2 (typical f = 0.515–0.54)")
            if f > 1.0:
                raise InputError(fname, f"conformity {f!r} is not a ball-bearing groove (f > 1)",
                                 "typical values are 0.515–0.54")
        if self.pitch_diameter <= d * 1.05:
            raise InputError("pitch_diameter", f"{self.pitch_diameter * 1e3:.4g} mm does not fit balls of "
                             f"{d * 1e3:.4g} mm (the inner raceway would vanish)",
                             "the pitch diameter must clearly exceed the ball diameter")
        if self.pitch_diameter * math.sin(math.pi / self.ball_count) <= d:
            zmax = int(math.pi / math.asin(min(1.0, d / self.pitch_diameter)))
            raise InputError("ball_count", f"{self.ball_count} balls of {d * 1e3:.4g} mm do not fit on a "
                             f"{self.pitch_diameter * 1e3:.4g} mm pitch circle (they would overlap)",
                             f"use at most {zmax} balls")
        if not (math.isfinite(self.contact_angle) and 0.0 <= self.contact_angle < math.radians(89.0)):
            raise InputError("contact_angle", f"must lie in [0, 89) deg, got {math.degrees(self.contact_angle)!r} deg",
                             'e.g. "15 deg" for a spindle bearing')
        for fname, what in (("bore", "a bore"), ("outside_diameter", "an outside diameter"), ("width", "a width"),
                            ("dynamic_load_rating", "a load rating"), ("limiting_speed", "a limiting speed"),
                            ("static_load_rating", "a static load rating"),
                            ("fatigue_load_limit", "a fatigue load limit")):
            v = getattr(self, fname)
            if not (math.isfinite(v) and v >= 0):
                raise InputError(fname, f"must be positive (or 0 when unknown), got {v!r}",
                                 f"give {what} > 0 with its unit, or leave it out")
        self._check_ratings()
        f0 = self.geometry_factor_f0
        if not (math.isfinite(f0) and (f0 == 0.0 or 5.0 <= f0 <= 30.0)):
            raise InputError("geometry_factor_f0", f"{f0!r} is not an ISO 76 factor f0 (radial ball bearings: "
                             "about 12–17)", "give the catalogue's f0, e.g. geometry_factor_f0 = 14, or leave it out")
        if 0 < self.static_load_rating < self.fatigue_load_limit:
            raise InputError("fatigue_load_limit", f"{self.fatigue_load_limit:.4g} N exceeds the static load rating "
                             f"{self.static_load_rating:.4g} N", "check both values and their units (kN vs N)")
        if self.bore > 0 and self.bore >= self.pitch_diameter - d:
            raise InputError("bore", "the bore is larger than the inner raceway (pitch_diameter − ball_diameter)",
                             "check bore, pitch diameter and ball diameter")
        if self.outside_diameter > 0 and self.outside_diameter <= self.pitch_diameter + d:
            raise InputError("outside_diameter", "smaller than the outer raceway (pitch_diameter + ball_diameter)",
                             "check outside diameter, pitch diameter and ball diameter")
        if self.width > 0 and self.width < d:
            raise InputError("width", f"{self.width * 1e3:.4g} mm is narrower than the balls ({d * 1e3:.4g} mm)",
                             "check width and ball diameter (the rings enclose the balls)")
        big_a = self.total_curvature_distance
        pd = self.diametral_clearance
        if not math.isfinite(pd):
            raise InputError("diametral_clearance", f"must be finite, got {pd!r}", 'e.g. "20 um"')
        if pd < -0.05 * big_a:
            raise InputError("diametral_clearance", f"{pd * 1e6:.4g} µm of interference "
                             "is beyond any realistic preload", "use a clearance ≥ −5 % of (f_i+f_o−1)·D")
        a_max = LIMITS["max_free_contact_angle"][1]
        pd_max = max(0.0, 2.0 * big_a * (math.cos(self.contact_angle if self.kind == "angular_contact" else 0.0)
                                         - math.cos(a_max)))
        if pd > 0 and pd > pd_max * (1.0 + 1e-12):
            raise InputError("diametral_clearance", f"{pd * 1e6:.4g} µm puts the free contact angle past "
                             f"{math.degrees(a_max):.0f}° (over the groove shoulder): the groove geometry allows at "
                             f"most {pd_max * 1e6:.4g} µm (2A(cos α₀ − cos 80°), A = (f_i+f_o−1)·D)",
                             "check the clearance, its unit and the conformities")

    def _check_ratings(self):
        """The load ratings C and C₀ [N] at most ten times the largest the ball set can have by ISO 281 / ISO 76:
        C₀ = f₀ Z D_w² cos α with f₀ ≤ 17 [N, mm]; C = b_m f_c (cos α)^0.7 Z^(2/3) D_w^1.8 (D_w ≤ 25.4 mm, else
        3.647 f_c … D_w^1.4) with b_m = 1.3, f_c ≤ 65 (ISO 281:2007 eqs. 1–2, table 1; ISO 76:2006 eq. 2)."""
        dw = self.ball_diameter * 1e3
        z = self.ball_count
        c_max = 10.0 * 1.3 * 65.0 * z ** (2.0 / 3.0) * (dw ** 1.8 if dw <= 25.4 else 3.647 * dw ** 1.4)
        c0_max = 10.0 * 17.0 * z * dw * dw
        for fname, top, what in (("dynamic_load_rating", c_max, "ISO 281"), ("static_load_rating", c0_max, "ISO 76")):
            v = getattr(self, fname)
            if v > top:
                raise InputError(fname, f"{v / 1e3:.4g} kN is more than ten times what {z} balls of {dw:.4g} mm can "
                                 f"be rated ({what}: at most {top / 10e3:.4g} kN)", "check the value and its unit "
                                 "(N or kN)")

    def _check_types(self):
        """API boundary: every field of the right type, else InputError naming it."""
        if not isinstance(self.name, str):
            raise InputError("name", f"expected a string, got {type(self.name).__name__}", 'e.g. name = "6205"')
        if not isinstance(self.kind, str):
            raise InputError("type", f"expected a string, got {type(self.kind).__name__}",
                             'use "angular_contact" or "deep_groove"')
        for fname in _FLOAT_FIELDS:
            v = getattr(self, fname)
            if isinstance(v, bool) or not isinstance(v, (int, float, np.integer, np.floating)):
                raise InputError(fname, f"expected a number in SI units, got {type(v).__name__} {v!r}"[:160],
                                 "give a float (SI: m, rad, N); quantities with units are read by bearingsim.io")
        z = self.ball_count
        if isinstance(z, (bool, np.bool_)) or not isinstance(z, (int, np.integer)):
            raise InputError("ball_count", f"must be an integer, got {type(z).__name__} {z!r}"[:160], "e.g. 16")
        for fname in ("ball_material", "ring_material"):
            if not isinstance(getattr(self, fname), Material):
                raise InputError(fname, f"expected a Material, got {type(getattr(self, fname)).__name__}",
                                 "use bearingsim.materials.get_material(name) or Material(...)")
        if not isinstance(self.notes, dict):
            raise InputError("notes", f"expected a dict, got {type(self.notes).__name__}", "e.g. notes={}")

    # ---- sources -----------------------------------------------------------
    @property
    def sources(self) -> dict:
        """Source of each documented field, field → text (the file's ``[sources]`` table; ``description``
        excluded)."""
        return {k: v for k, v in self.notes.items() if k != "description" and isinstance(v, str)}

    @property
    def estimated(self) -> tuple:
        """Names of the fields whose values are estimates or assumptions (source text starting with
        ``ESTIMATE`` or ``ASSUMED``), in file order."""
        return tuple(k for k, v in self.sources.items() if v.lstrip().upper().startswith(("ESTIMATE", "ASSUMED")))

    # ---- derived geometry -------------------------------------------------
    @property
    def total_curvature_distance(self) -> float:
        """A = (f_i + f_o − 1) D  [m] (Harris & Kotzalas 2007 vol. 1 eq. 2.6)."""
        return (self.inner_conformity + self.outer_conformity - 1.0) * self.ball_diameter

    @property
    def free_contact_angle(self) -> float:
        """α₀ [rad]; for a deep-groove bearing from the clearance, cos α₀ = 1 − P_d/(2A)."""
        if self.kind == "deep_groove":
            c = 1.0 - max(self.diametral_clearance, 0.0) / (2.0 * self.total_curvature_distance)
            return math.acos(min(1.0, c))
        return self.contact_angle

    @property
    def gamma(self) -> float:
        """γ = D cos α₀ / d_m  [-]."""
        return self.ball_diameter * math.cos(self.free_contact_angle) / self.pitch_diameter

    @property
    def ball_mass(self) -> float:
        """m = ρ π D³ / 6  [kg]."""
        return self.ball_material.density * math.pi * self.ball_diameter**3 / 6.0

    @property
    def ball_inertia(self) -> float:
        """J = m D² / 10  [kg·m²] (solid sphere)."""
        return self.ball_mass * self.ball_diameter**2 / 10.0

    @property
    def effective_modulus(self) -> float:
        """E′ of the ball–ring pair [Pa] (:func:`bearingsim.contact.hertz.effective_modulus`)."""
        b, r = self.ball_material, self.ring_material
        return hertz.effective_modulus(b.youngs_modulus, b.poisson_ratio, r.youngs_modulus, r.poisson_ratio)

    def raceway_radii(self, inner: bool, contact_angle: float | None = None) -> tuple[float, float]:
        """(R_x, R_y) [m] of the inner or outer contact at ``contact_angle`` (default α₀)."""
        a = self.free_contact_angle if contact_angle is None else _real(contact_angle, "contact_angle")
        f = self.inner_conformity if inner else self.outer_conformity
        return hertz.raceway_radii(self.ball_diameter, self.pitch_diameter, f, a, inner)

    def contact(self, load: float, inner: bool, contact_angle: float | None = None) -> hertz.HertzContact:
        """Exact Hertz contact of one ball on the inner or outer raceway under ``load`` [N]."""
        load = _real(load, "load")
        if load < 0:
            raise InputError("load", f"must be ≥ 0 N, got {load!r}", "give the ball load in N")
        rx, ry = self.raceway_radii(inner, contact_angle)
        return hertz.point_contact_exact(load, rx, ry, self.effective_modulus)

    @cached_property
    def contact_constants(self) -> tuple[float, float, float]:
        """(K_i, K_o, K_n) [N/m^1.5] at α₀ (Harris & Kotzalas 2007 vol. 1 eq. 7.4 for K_n).

        As in Harris's formulation and that of [S0], the constants are evaluated once at
        the free contact angle; their change with the loaded angle is below 0.5 % here.
        """
        ki = self.contact(1.0, True).stiffness_constant
        ko = self.contact(1.0, False).stiffness_constant
        return ki, ko, hertz.series_constant(ki, ko)

    # ---- the rows protocol (module docstring) ------------------------------------------------
    #: axial position where the loads act [m]: one row is loaded in its own plane
    load_point = 0.0

    @cached_property
    def rows(self) -> tuple:
        """One :class:`Row` at the origin."""
        return (Row(self),)

    def row_vectors(self) -> np.ndarray:
        """Kernel parameter vectors float[1, NPAR] (:func:`row_vectors`)."""
        return row_vectors(self)

    def row_parameters(self, x_row: float = 0.0, sign: float = 1.0, axial_offset: float = 0.0,
                       first_ball_azimuth: float = 0.0) -> np.ndarray:
        """Parameter vector of this bearing as a row for the kernels (layout in :mod:`.statics.layout`).

        x_row [m] axial position of the row plane; sign ±1 orientation; axial_offset [m]
        preload offset of the inner groove centres; first_ball_azimuth [rad].
        """
        x_row, axial_offset = _real(x_row, "x_row"), _real(axial_offset, "axial_offset")
        sign, first_ball_azimuth = _real(sign, "sign"), _real(first_ball_azimuth, "first_ball_azimuth")
        if sign not in (1.0, -1.0):
            raise InputError("sign", f"must be +1 or -1, got {sign!r}", "the row's orientation")
        p = self._base_row.copy()
        p[rl.P_XROW] = x_row
        p[rl.P_SIGN] = sign
        p[rl.P_PSI0] = first_ball_azimuth
        p[rl.P_AXOFF] = axial_offset
        return p

    @cached_property
    def _base_row(self) -> np.ndarray:
        d = self.ball_diameter
        a0 = self.free_contact_angle
        big_a = self.total_curvature_distance
        ri = (self.inner_conformity - 0.5) * d
        ro = (self.outer_conformity - 0.5) * d
        ki, ko, _ = self.contact_constants
        ci = self.contact(1.0, True)
        co = self.contact(1.0, False)
        p = np.zeros(rl.NPAR)
        p[rl.P_Z] = self.ball_count
        p[rl.P_OROT] = 1.0 if self.rotating_ring == "outer" else 0.0
        p[rl.P_D] = d
        p[rl.P_DM] = self.pitch_diameter
        p[rl.P_RI] = ri
        p[rl.P_RO] = ro
        p[rl.P_KI] = ki
        p[rl.P_KO] = ko
        if self.kind == "angular_contact":
            p[rl.P_DX0] = big_a * math.sin(a0)
            p[rl.P_DR0] = big_a * math.cos(a0) - 0.5 * self.diametral_clearance
            p[rl.P_XIC] = ri * math.sin(a0)
        else:
            p[rl.P_DX0] = 0.0
            p[rl.P_DR0] = big_a - 0.5 * self.diametral_clearance
            p[rl.P_XIC] = 0.0
        p[rl.P_RIC] = 0.5 * self.pitch_diameter + ri * math.cos(a0)
        p[rl.P_MASS] = self.ball_mass
        p[rl.P_JB] = self.ball_inertia
        p[rl.P_GRI] = self.inner_conformity * d
        p[rl.P_CPI] = ci.max_pressure
        p[rl.P_CPO] = co.max_pressure
        p[rl.P_CAI] = ci.a * ci.ell_e
        p[rl.P_CAO] = co.a * co.ell_e
        p.setflags(write=False)
        return p

    def summary(self) -> dict:
        """Main data in SI, for printing and JSON."""
        return {
            "name": self.name, "type": self.kind, "ball_diameter_m": self.ball_diameter,
            "ball_count": self.ball_count, "pitch_diameter_m": self.pitch_diameter,
            "inner_conformity": self.inner_conformity, "outer_conformity": self.outer_conformity,
            "free_contact_angle_rad": self.free_contact_angle,
            "diametral_clearance_m": self.diametral_clearance,
            "ball_material": self.ball_material.name, "ring_material": self.ring_material.name,
        }
