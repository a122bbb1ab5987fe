"""Cage ring input and section constants (the model: :mod:`bearingsim.cage_modes`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..materials import LIBRARY as _MATERIALS

_CAGE_STEEL = _MATERIALS["cage_steel"]  #: default cage material (assumed; materials.py)

#: names of the 6 DOF of a node, in order
NODE_DOF = ("ux", "uy", "uz", "theta_x", "theta_y", "theta_z")

# ---------------------------------------------------------------------------------------------
# section constants
# ---------------------------------------------------------------------------------------------
def rect_torsion_constant(a: float, c: float, terms: int = 50) -> float:
    """Saint-Venant torsion constant J [m⁴] of a solid a × c rectangle.

    J = (a c³/3) [1 − (192/π⁵)(c/a) Σ_{n = 1,3,5,…} tanh(nπa/(2c)) / n⁵] with a ≥ c
    (Timoshenko & Goodier, Theory of Elasticity, 3rd ed., ch. 10, rectangular bar); the series
    converges like n⁻⁵ (50 odd terms: relative truncation < 1e-9).
    """
    a, c = (a, c) if a >= c else (c, a)
    n = np.arange(1, 2 * terms, 2, dtype=float)
    s = float(np.sum(np.tanh(n * math.pi * a / (2.0 * c)) / n**5))
    return a * c**3 / 3.0 * (1.0 - 192.0 / math.pi**5 * (c / a) * s)


def cowper_shear_coefficient(poisson: float) -> float:
    """Timoshenko shear coefficient κ [-] of a rectangular section, κ = 10(1+ν)/(12+11ν)
    (Cowper, J. Appl. Mech. 33 (1966) 335, table 1)."""
    return 10.0 * (1.0 + poisson) / (12.0 + 11.0 * poisson)


def section_properties(b: float, t: float, d_p: float | None = None) -> dict:
    """Section constants [SI] of a bridge (d_p None: full b × t rectangle) or of a pocket
    (the two side rails of axial width w = (b − d_p)/2 at x = ±(b + d_p)/4).

    Returns A [m²], I_in [m⁴] (= ∫ r'² dA, in-plane bending, axis parallel to x),
    I_out [m⁴] (= ∫ x'² dA, out-of-plane bending, radial axis), J [m⁴] (torsion),
    I_p = I_in + I_out [m⁴] (polar, for the rotary inertia of torsion).  Formulas: module docstring.
    """
    if d_p is None:
        A = b * t
        i_in = b * t**3 / 12.0
        i_out = t * b**3 / 12.0
        J = rect_torsion_constant(b, t)
    else:
        w = 0.5 * (b - d_p)
        e = 0.25 * (b + d_p)
        A = 2.0 * w * t
        i_in = 2.0 * w * t**3 / 12.0
        i_out = 2.0 * (t * w**3 / 12.0 + w * t * e**2)
        J = 2.0 * rect_torsion_constant(w, t)
    return {"A": A, "I_in": i_in, "I_out": i_out, "J": J, "I_p": i_in + i_out}


# ---------------------------------------------------------------------------------------------
# input
# ---------------------------------------------------------------------------------------------
def _positive(name: str, value, example: str) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
        raise InputError(name, f"must be a positive finite number, got {value!r}", example)


#: the most FE elements per pocket pitch (`bearingsim cage-modes 6205`, 9 pockets, this machine: 32 → 1.3 s and
#: 0.28 GB, 64 → 4.3 s and 0.7 GB, 128 → 26 s and 2.4 GB; 100,000 ran out of memory)
MAX_ELEMENTS_PER_PITCH = 64


@dataclass(frozen=True)
class CageRing:
    """A window cage modelled as a ring (all SI).

    Parameters
    ----------
    pitch_radius : float [m]  radius of the pocket centres = the ring's centroid circle R
    axial_width : float [m]  b, along the bearing axis x
    radial_thickness : float [m]  t
    pocket_count : int  Z ≥ 3 (one pocket per ball)
    pocket_diameter : float [m]  d_p < b (two side rails of width (b − d_p)/2 remain beside each
        pocket) and d_p < 2R sin(π/Z) (a bridge remains between pockets on the centroid circle)
    first_pocket_azimuth : float [rad]  φ_0; pocket j at φ_j = φ_0 + 2π j / Z
    young_modulus [Pa], poisson [-], density [kg/m³]  (defaults: ``cage_steel`` of materials.py, 2.06e11, 0.3, 7850)
    elements_per_pitch : int  even ≥ 4 (≥ 2 without pockets); nodes at every pocket centre and
        mid-bridge, and (with pockets) at the pocket edges ±α, α = arcsin(d_p/2R)
    pockets : bool  False: a uniform b × t ring (pocket_diameter then only fixes nothing but
        the pocket nodes' positions; used for the closed-form checks)
    shear_deformation : bool  True: Timoshenko bending (default); False: Euler–Bernoulli
    rotary_inertia : bool  True (default): the mass includes the section's rotary inertia ρI;
        False only to compare with closed forms that neglect it
    """

    pitch_radius: float
    axial_width: float
    radial_thickness: float
    pocket_count: int
    pocket_diameter: float
    first_pocket_azimuth: float = 0.0
    young_modulus: float = _CAGE_STEEL.youngs_modulus
    poisson: float = _CAGE_STEEL.poisson_ratio
    density: float = _CAGE_STEEL.density
    elements_per_pitch: int = 8
    pockets: bool = True
    shear_deformation: bool = True
    rotary_inertia: bool = True

    def __post_init__(self):
        _positive("pitch_radius", self.pitch_radius, 'e.g. "30.5 mm" (half the pitch diameter)')
        _positive("axial_width", self.axial_width, 'e.g. "15 mm"')
        _positive("radial_thickness", self.radial_thickness, 'e.g. "3 mm"')
        _positive("pocket_diameter", self.pocket_diameter, 'e.g. "11.3 mm" (ball diameter + clearance)')
        _positive("young_modulus", self.young_modulus, "e.g. 2.06e11 Pa for steel")
        _positive("density", self.density, "e.g. 7850 kg/m³ for steel")
        z = self.pocket_count
        if isinstance(z, bool) or not isinstance(z, (int, np.integer)) or z < 3:
            raise InputError("pocket_count", f"must be an integer ≥ 3, got {z!r}", "one pocket per ball, e.g. 16")
        if not (isinstance(self.poisson, (int, float)) and -1.0 < self.poisson < 0.5):
            raise InputError("poisson", f"must lie in (−1, 0.5), got {self.poisson!r}", "e.g. 0.3 for steel")
        if not math.isfinite(self.first_pocket_azimuth):
            raise InputError("first_pocket_azimuth", "must be finite", "e.g. 0 rad")
        if self.radial_thickness >= self.pitch_radius:
            raise InputError("radial_thickness", f"{self.radial_thickness:.4g} m must be less than the pitch radius "
                             f"{self.pitch_radius:.4g} m", "a cage is a thin ring")
        epp = self.elements_per_pitch
        if isinstance(epp, bool) or not isinstance(epp, (int, np.integer)) or epp < 2 or epp % 2:
            raise InputError("elements_per_pitch", f"must be an even integer, got {epp!r}", "e.g. 8")
        if epp > MAX_ELEMENTS_PER_PITCH:
            raise InputError("elements_per_pitch", f"{epp} is more than {MAX_ELEMENTS_PER_PITCH}",
                             "the default is 8; e.g. 16 to check convergence")
        if self.pockets:
            if epp < 4:
                raise InputError("elements_per_pitch", f"must be ≥ 4 with pockets, got {epp}",
                                 "2 or more across each pocket and each bridge, e.g. 8")
            if self.pocket_diameter >= self.axial_width:
                raise InputError("pocket_diameter", f"{self.pocket_diameter * 1e3:.4g} mm must be less than the "
                                 f"axial width {self.axial_width * 1e3:.4g} mm",
                                 "side rails must remain beside each pocket: widen the cage or shrink the pocket")
            chord = 2.0 * self.pitch_radius * math.sin(math.pi / z)
            if self.pocket_diameter >= chord:
                raise InputError("pocket_diameter", f"{self.pocket_diameter * 1e3:.4g} mm leaves no bridge: the pocket "
                                 f"pitch on the centroid circle is {chord * 1e3:.4g} mm",
                                 "fewer pockets, a larger pitch radius or a smaller pocket")

    @property
    def shear_modulus(self) -> float:
        """G = E / (2(1 + ν)) [Pa]."""
        return self.young_modulus / (2.0 * (1.0 + self.poisson))

    @property
    def pocket_half_angle(self) -> float:
        """α = arcsin(d_p / 2R) [rad]: the pocket's angular half-span on the centroid circle."""
        return math.asin(min(1.0, self.pocket_diameter / (2.0 * self.pitch_radius)))

    @property
    def pocket_azimuths(self) -> np.ndarray:
        """φ_j [rad], j = 0 … Z − 1."""
        return self.first_pocket_azimuth + 2.0 * math.pi * np.arange(self.pocket_count) / self.pocket_count

    def split(self) -> tuple[int, int]:
        """(n_p, n_b): elements across one pocket span and across one bridge (both even)."""
        epp = int(self.elements_per_pitch)
        if not self.pockets:
            return 0, epp
        frac = 2.0 * self.pocket_half_angle / (2.0 * math.pi / self.pocket_count)
        n_p = 2 * int(round(0.5 * epp * frac))
        n_p = min(max(n_p, 2), epp - 2)
        return n_p, epp - n_p


def default_cage_ring(ball_diameter: float, pitch_diameter: float, ball_count: int, **overrides) -> CageRing:
    """An ASSUMED steel window cage for a catalogue bearing when the user gives no cage data.

    Every number here is an assumption (no source gives the cage of the catalogue bearings):
    pitch radius R = d_m / 2 (the cage centred on the ball pitch circle), axial width
    b = 1.4 D, radial thickness t = 0.3 D, pocket diameter d_p = D + 2 × 0.1 mm (0.1 mm
    clearance each side), Z = ball count, first pocket at ψ = 0, steel E = 2.06e11 Pa,
    ν = 0.3, ρ = 7850 kg/m³, 8 elements per pocket pitch.  Keyword ``overrides`` replace any
    CageRing field.  Note that on the pitch circle the bridges of a tight ball set are thin
    (hub row of [S1]: 0.6 mm), which makes this assumed cage soft there; real cages sit
    off the pitch circle or have shaped pockets — give measured cage data when available.
    """
    _positive("ball_diameter", ball_diameter, 'e.g. "11.1 mm"')
    _positive("pitch_diameter", pitch_diameter, 'e.g. "61 mm"')
    d = float(ball_diameter)
    args = dict(pitch_radius=0.5 * float(pitch_diameter), axial_width=1.4 * d, radial_thickness=0.3 * d,
                pocket_count=int(ball_count), pocket_diameter=d + 2.0e-4)
    args.update(overrides)
    if args["pocket_diameter"] <= d:
        raise InputError("pocket_diameter", f"{args['pocket_diameter'] * 1e3:.4g} mm does not hold the "
                         f"{d * 1e3:.4g} mm ball", f"give more than the ball diameter, e.g. {(d + 2e-4) * 1e3:.4g} mm")
    return CageRing(**args)
