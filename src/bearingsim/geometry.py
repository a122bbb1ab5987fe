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
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from .contact import hertz
from .errors import InputError
from .materials import Material
from .statics import _kernels as kn


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
    notes : dict  source of every number
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
    notes: dict = field(default_factory=dict, compare=False, hash=False)

    def __post_init__(self):
        d = self.ball_diameter
        if self.kind not in ("angular_contact", "deep_groove"):
            raise InputError("type", f"unknown bearing type {self.kind!r}",
                             'use "angular_contact" or "deep_groove"')
        if not (math.isfinite(d) and d > 0):
            raise InputError("ball_diameter", f"must be positive, got {d!r} m", 'e.g. "11.1 mm"')
        if not (math.isfinite(self.pitch_diameter) and self.pitch_diameter > 0):
            raise InputError("pitch_diameter", f"must be positive, got {self.pitch_diameter!r} m", 'e.g. "61 mm"')
        if not isinstance(self.ball_count, (int, np.integer)) or self.ball_count < 3:
            raise InputError("ball_count", f"must be an integer ≥ 3, got {self.ball_count!r}", "e.g. 16")
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
        if not (0.0 <= self.contact_angle < math.radians(89.0)):
            raise InputError("contact_angle", f"must lie in [0, 89) deg, got {math.degrees(self.contact_angle)!r} deg",
                             'e.g. "15 deg" for a spindle bearing')
        if self.bore > 0 and self.bore >= self.pitch_diameter - d:
            raise InputError("bore", "the bore is larger than the inner raceway (pitch_diameter − ball_diameter)",
                             "check bore, pitch diameter and ball diameter")
        if self.outside_diameter > 0 and self.outside_diameter <= self.pitch_diameter + d:
            raise InputError("outside_diameter", "smaller than the outer raceway (pitch_diameter + ball_diameter)",
                             "check outside diameter, pitch diameter and ball diameter")
        if self.diametral_clearance < -0.05 * self.total_curvature_distance:
            raise InputError("diametral_clearance", f"{self.diametral_clearance * 1e6:.4g} µm of interference "
                             "is beyond any realistic preload", "use a clearance ≥ −5 % of (f_i+f_o−1)·D")
        if self.kind == "deep_groove" and self.diametral_clearance > 1.9 * self.total_curvature_distance:
            raise InputError("diametral_clearance", "larger than the groove geometry allows (2A)",
                             "check the clearance and the conformities")

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
        a = self.free_contact_angle if contact_angle is None else contact_angle
        f = self.inner_conformity if inner else self.outer_conformity
        return hertz.raceway_radii(self.ball_diameter, self.pitch_diameter, f, a, inner)

    def contact(self, load: float, inner: bool, contact_angle: float | None = None) -> hertz.HertzContact:
        """Exact Hertz contact of one ball on the inner or outer raceway under ``load`` [N]."""
        rx, ry = self.raceway_radii(inner, contact_angle)
        return hertz.point_contact_exact(load, rx, ry, self.effective_modulus)

    @cached_property
    def contact_constants(self) -> tuple[float, float, float]:
        """(K_i, K_o, K_n) [N/m^1.5] at α₀ (Harris & Kotzalas 2007 vol. 1 eq. 7.4 for K_n).

        As in Harris's and the seed's formulation, the constants are evaluated once at
        the free contact angle; their change with the loaded angle is below 0.5 % here.
        """
        ki = self.contact(1.0, True).stiffness_constant
        ko = self.contact(1.0, False).stiffness_constant
        return ki, ko, hertz.series_constant(ki, ko)

    def row_parameters(self, x_row: float = 0.0, sign: float = 1.0, axial_offset: float = 0.0,
                       first_ball_azimuth: float = 0.0) -> np.ndarray:
        """Parameter vector of this bearing as a row for the kernels (layout in :mod:`._kernels`).

        x_row [m] axial position of the row plane; sign ±1 orientation; axial_offset [m]
        preload offset of the inner groove centres; first_ball_azimuth [rad].
        """
        p = self._base_row.copy()
        p[kn.P_XROW] = x_row
        p[kn.P_SIGN] = sign
        p[kn.P_PSI0] = first_ball_azimuth
        p[kn.P_AXOFF] = axial_offset
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
        p = np.zeros(kn.NPAR)
        p[kn.P_Z] = self.ball_count
        p[kn.P_D] = d
        p[kn.P_DM] = self.pitch_diameter
        p[kn.P_RI] = ri
        p[kn.P_RO] = ro
        p[kn.P_KI] = ki
        p[kn.P_KO] = ko
        if self.kind == "angular_contact":
            p[kn.P_DX0] = big_a * math.sin(a0)
            p[kn.P_DR0] = big_a * math.cos(a0) - 0.5 * self.diametral_clearance
            p[kn.P_XIC] = ri * math.sin(a0)
        else:
            p[kn.P_DX0] = 0.0
            p[kn.P_DR0] = big_a - 0.5 * self.diametral_clearance
            p[kn.P_XIC] = 0.0
        p[kn.P_RIC] = 0.5 * self.pitch_diameter + ri * math.cos(a0)
        p[kn.P_MASS] = self.ball_mass
        p[kn.P_JB] = self.ball_inertia
        p[kn.P_GRI] = self.inner_conformity * d
        p[kn.P_CPI] = ci.max_pressure
        p[kn.P_CPO] = co.max_pressure
        p[kn.P_CAI] = ci.a * ci.ell_e
        p[kn.P_CAO] = co.a * co.ell_e
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
