"""Elastic cage: a finite-element ring model and its free–free modes (for mode synthesis).

[S1] (Sakaguchi & Shibutani, NTN Technical Review 87, 2019, §2–3 and Table 3): IBDAS models
the elastic deformation of each cage by mode synthesis (56 modes per cage).  This module builds
the structural side: the cage as a closed ring of straight 3-D frame elements, its free–free
modes, and the mass-normalised mode shapes at the pocket centres, which the dynamic model uses
as modal coordinates η (cage displacement u = Σ_k φ_k η_k, generalized force f_k = φ_kᵀ F).

Frames and units (plain SI floats)
----------------------------------
Cage frame: x = bearing axis, azimuth ψ measured from +y towards +z (ψ = 0 on +y).  Node i
sits on the centroid circle of radius R at (0, R cos ψ_i, R sin ψ_i); pocket j's centre is
the node at φ_j = first_pocket_azimuth + 2π j / Z.  Every node has 6 DOF in the cage frame:
(ux, uy, uz) [m] and the small-rotation vector (θx, θy, θz) [rad]; global DOF index
``6 * node + component``.

Model
-----
* Section: bridges between pockets carry the full b × t rectangle (b axial, t radial); the
  elements inside a pocket's angular span carry the two side rails of axial width
  w = (b − d_p)/2 each, centred at x = ±e, e = (b + d_p)/4 (a window cage).  The pocket's
  angular span on the centroid circle is ±α, α = arcsin(d_p / 2R): the model removes a square
  window, d_p (tangential, chord 2R sin α) × d_p (axial), through the radial thickness, where a
  drilled cylindrical pocket removes π d_p²/4 — the model's mass is therefore lower than the
  drilled cage's (the modelled volume is :attr:`CageFE.volume`).
* Section constants (Roark's Formulas for Stress and Strain, 7th ed., Table A.1 and Table 10.7
  case 4; Timoshenko & Goodier, Theory of Elasticity, 3rd ed., ch. 10, rectangular bar, for the
  series): A = b t, I_inplane = b t³/12 (bending in the ring plane, about an axis parallel to
  x), I_outplane = t b³/12 (bending out of the plane, about the radial axis), torsion
  J = (a c³/3) [1 − (192/π⁵)(c/a) Σ_{n odd} tanh(nπa/2c)/n⁵] for an a × c rectangle (a ≥ c);
  pocket section: A = 2 w t, I_inplane = 2 w t³/12, I_outplane = 2 (t w³/12 + w t e²),
  J = 2 J(w, t) (Saint-Venant torsion of the two rails; the stiffening of twist by opposite
  bending of the two rails over the short pocket length is neglected — a lower bound).
  Shear coefficient of a rectangle κ = 10(1 + ν)/(12 + 11ν) (Cowper 1966, J. Appl. Mech. 33).
* Element: straight two-node 3-D frame, 12 DOF (Przemieniecki, Theory of Matrix Structural
  Analysis, 1968: ch. 5, beam element with shear deformation; ch. 11, consistent mass): axial
  and Saint-Venant torsion with linear interpolation; bending in each principal plane with the
  shear-deformable (Timoshenko) stiffness, Φ = 12 E I / (κ G A L²), which reduces exactly to
  Euler–Bernoulli when Φ = 0 (``shear_deformation=False``).  Timoshenko by default because the
  cage's bridges and pocket rails are short compared to their section (L/t ≈ 0.1 … 2), where
  shear flexibility is not negligible; the thin-ring closed forms are checked with Φ = 0.
  Consistent mass: cubic Hermite translational mass plus rotary inertia ρI (Przemieniecki
  ch. 11), torsional rotary inertia ρ I_p, I_p = I_inplane + I_outplane.  The mass is the
  Euler–Bernoulli (Φ = 0) consistent mass also when the stiffness includes shear: it
  reproduces rigid-body motion (and the rigid-body inertia of the prisms) exactly and
  converges under mesh refinement.
* The curved centroid circle is approximated by straight chords (error O(h²) in frequency).

Not modelled: the cage's rotation (centrifugal stiffening, Coriolis splitting of the pairs,
O(Ω_cage/ω) small), the guiding lands, and pocket shapes other than the square window.

Stresses (quasi-static recovery from the nodal displacements, :func:`element_end_forces`,
:func:`normal_stress`, :func:`stress_shapes`, :func:`peak_stress`): the element end forces
k_l T u_e (Przemieniecki ch. 5–6) give the stress resultants (N, V_y', V_z', T, M_y', M_z') at
both ends of every element; Navier's σ = N/A + M_y' z'/I_y' − M_z' y'/I_z' (Roark 7th ed. §8.1,
with the stiffness's section constants) at eight section points (:func:`stress_points`: the
corners of the two rails of a pocket element; the corners and four surface points of a bridge).
Element inertia between the nodes, shear stresses and the curved-beam correction O(t/R) are
neglected (Saint-Venant torsion shear separately: :func:`torsion_shear_stress`).  Closed-form
checks in tests/unit/test_cage_stress.py (Roark table 9.2 case 1 diametral loads, uniform
pressure and twist, the inextensional ring modes).

Free–free modes: K φ = ω² M φ (scipy.linalg.eigh); the six rigid-body modes (zero ω) are found,
checked and excluded.  Closed-form checks (tests/unit/test_cage_modes.py): Hoppe (1871) in-plane
and Love (Treatise, 4th ed., ch. XVIII, vibrations of a circular ring) / Blevins (Formulas for
Natural Frequency and Mode Shape, 1979, ring table) out-of-plane flexural frequencies of a thin
uniform ring, its breathing and uniform-twist modes, and Roark's diametral-load deflection
(static_deflection).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .errors import ConvergenceError, InputError
from .materials import LIBRARY as _MATERIALS

_CAGE_STEEL = _MATERIALS["cage_steel"]  #: default cage material (assumed; materials.py)

__all__ = ["CageRing", "CageFE", "CageModes", "default_cage_ring", "assemble", "cage_modes",
           "rect_torsion_constant", "cowper_shear_coefficient", "section_properties", "RESULTANTS",
           "element_end_forces", "stress_points", "normal_stress", "torsion_shear_stress", "stress_shapes",
           "peak_stress", "peak_stress_location"]

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
    return CageRing(**args)


# ---------------------------------------------------------------------------------------------
# element matrices (local frame: x' along the element, y' in the ring plane, z' = cage x)
# ---------------------------------------------------------------------------------------------
# local DOF order per node: u, v, w, θx', θy', θz'; element DOFs 0-5 node a, 6-11 node b
_BEND_XY = (1, 5, 7, 11)  # v1, θz1, v2, θz2 (bending in the x'-y' plane, about z')
_BEND_XZ = (2, 4, 8, 10)  # w1, θy1, w2, θy2 (bending in the x'-z' plane, about y')
_FLIP = np.diag([1.0, -1.0, 1.0, -1.0])  # θy' = −dw/dx' : x'-z' matrices from the x'-y' ones


def _bend_k(ei: float, L: float, phi: float) -> np.ndarray:
    """Shear-deformable bending stiffness (v1, θ1, v2, θ2), θ = dv/dx (Przemieniecki 1968, ch. 5)."""
    c = ei / ((1.0 + phi) * L**3)
    return c * np.array([[12.0, 6 * L, -12.0, 6 * L],
                         [6 * L, (4 + phi) * L**2, -6 * L, (2 - phi) * L**2],
                         [-12.0, -6 * L, 12.0, -6 * L],
                         [6 * L, (2 - phi) * L**2, -6 * L, (4 + phi) * L**2]])


def _bend_m(rho_a: float, rho_i: float, L: float) -> np.ndarray:
    """Consistent bending mass (v1, θ1, v2, θ2): Hermite translational + rotary inertia
    (Przemieniecki 1968, ch. 11, with Φ = 0)."""
    mt = rho_a * L / 420.0 * np.array([[156.0, 22 * L, 54.0, -13 * L],
                                       [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                                       [54.0, 13 * L, 156.0, -22 * L],
                                       [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    mr = rho_i / (30.0 * L) * np.array([[36.0, 3 * L, -36.0, 3 * L],
                                        [3 * L, 4 * L**2, -3 * L, -L**2],
                                        [-36.0, -3 * L, 36.0, -3 * L],
                                        [3 * L, -L**2, -3 * L, 4 * L**2]])
    return mt + mr


def element_matrices(L: float, sec: dict, E: float, G: float, rho: float, kappa: float,
                     shear: bool, rotary: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Local 12 × 12 stiffness and consistent mass of a straight frame element [SI].

    Local axes: x' element axis, y' in the ring plane (radial), z' parallel to the cage axis;
    I_z' = sec["I_in"] (in-plane bending), I_y' = sec["I_out"] (out-of-plane bending).
    """
    A, i_in, i_out, J, ip = sec["A"], sec["I_in"], sec["I_out"], sec["J"], sec["I_p"]
    r = 1.0 if rotary else 0.0
    k = np.zeros((12, 12))
    m = np.zeros((12, 12))
    bar = np.array([[1.0, -1.0], [-1.0, 1.0]])
    lin = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
    ax, tw = [0, 6], [3, 9]
    k[np.ix_(ax, ax)] = E * A / L * bar
    k[np.ix_(tw, tw)] = G * J / L * bar
    m[np.ix_(ax, ax)] = rho * A * L * lin
    m[np.ix_(tw, tw)] = r * rho * ip * L * lin
    phi_y = 12.0 * E * i_in / (kappa * G * A * L**2) if shear else 0.0
    phi_z = 12.0 * E * i_out / (kappa * G * A * L**2) if shear else 0.0
    ixy, ixz = list(_BEND_XY), list(_BEND_XZ)
    k[np.ix_(ixy, ixy)] = _bend_k(E * i_in, L, phi_y)
    k[np.ix_(ixz, ixz)] = _FLIP @ _bend_k(E * i_out, L, phi_z) @ _FLIP
    m[np.ix_(ixy, ixy)] = _bend_m(rho * A, r * rho * i_in, L)
    m[np.ix_(ixz, ixz)] = _FLIP @ _bend_m(rho * A, r * rho * i_out, L) @ _FLIP
    return k, m


# ---------------------------------------------------------------------------------------------
# assembly
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class CageFE:
    """Assembled FE model of a cage ring (cage frame, SI).

    Attributes
    ----------
    ring : CageRing
    K, M : float[6N, 6N]  stiffness [N/m, N, N·m] and consistent mass [kg, kg·m, kg·m²]
    node_azimuth : float[N] [rad];  node_xyz : float[N, 3] [m] (0, R cos ψ, R sin ψ)
    pocket_nodes : int[Z]  node of pocket centre j;  elements : int[E, 2] (node a, node b)
    element_pocket : bool[E]  True for the elements inside a pocket span (side-rail section)
    element_length : float[E] [m] (chords);  sections : {"bridge": dict, "pocket": dict}
    """

    ring: CageRing
    K: np.ndarray
    M: np.ndarray
    node_azimuth: np.ndarray
    node_xyz: np.ndarray
    pocket_nodes: np.ndarray
    elements: np.ndarray
    element_pocket: np.ndarray
    element_length: np.ndarray
    sections: dict = field(compare=False)

    @property
    def n_nodes(self) -> int:
        return len(self.node_azimuth)

    @property
    def n_dof(self) -> int:
        return 6 * self.n_nodes

    @staticmethod
    def dof(node, component) -> np.ndarray:
        """Global DOF index of (node, component), component 0..5 = ux, uy, uz, θx, θy, θz."""
        return 6 * np.asarray(node) + np.asarray(component)

    @property
    def volume(self) -> float:
        """Σ A_e L_e [m³]: the volume of the ring as modelled (chords, square pocket windows)."""
        a = np.where(self.element_pocket, self.sections["pocket"]["A"], self.sections["bridge"]["A"])
        return float(np.sum(a * self.element_length))

    def rigid_body_vectors(self) -> np.ndarray:
        """float[6N, 6]: translations along x, y, z, then rotations about x, y, z through the
        cage centre (u = e × r, θ = e), unit amplitude [m, rad]."""
        r = np.zeros((self.n_dof, 6))
        for i in range(3):
            e = np.zeros(3)
            e[i] = 1.0
            r[self.dof(np.arange(self.n_nodes), i), i] = 1.0
            rot = np.cross(e, self.node_xyz)  # (N, 3)
            for c in range(3):
                r[self.dof(np.arange(self.n_nodes), c), 3 + i] = rot[:, c]
            r[self.dof(np.arange(self.n_nodes), 3 + i), 3 + i] = 1.0
        return r

    def pocket_load_vector(self, forces, moments=None) -> np.ndarray:
        """float[6N]: nodal load vector of forces [N] float[Z, 3] (and moments [N·m] float[Z, 3])
        applied at the pocket centres, cage-frame components."""
        z = len(self.pocket_nodes)
        f = np.asarray(forces, dtype=float)
        if f.shape != (z, 3):
            raise InputError("forces", f"expected shape ({z}, 3), got {f.shape}", "one (Fx, Fy, Fz) per pocket")
        out = np.zeros(self.n_dof)
        for c in range(3):
            out[self.dof(self.pocket_nodes, c)] = f[:, c]
        if moments is not None:
            mo = np.asarray(moments, dtype=float)
            if mo.shape != (z, 3):
                raise InputError("moments", f"expected shape ({z}, 3), got {mo.shape}", "one (Mx, My, Mz) per pocket")
            for c in range(3):
                out[self.dof(self.pocket_nodes, 3 + c)] = mo[:, c]
        return out

    def static_deflection(self, load: np.ndarray) -> np.ndarray:
        """Static deflection u [m, rad] float[6N] of the free ring under a nodal load [N, N·m].

        Solves [[K, M R], [Rᵀ M, 0]] [u; λ] = [F; 0] (R = rigid-body vectors): u is the elastic
        deflection M-orthogonal to the rigid-body modes — the sum Σ_k φ_k φ_kᵀ F / ω_k² over all
        elastic modes.  For a self-equilibrated load λ = 0; any resultant force or moment is
        balanced by the rigid-body inertia term M R λ (inertia relief).
        """
        F = np.asarray(load, dtype=float)
        if F.shape != (self.n_dof,):
            raise InputError("load", f"expected shape ({self.n_dof},), got {F.shape}", "use pocket_load_vector")
        R = self.rigid_body_vectors()
        MR = self.M @ R
        n = self.n_dof
        A = np.zeros((n + 6, n + 6))
        A[:n, :n] = self.K
        A[:n, n:] = MR
        A[n:, :n] = MR.T
        rhs = np.concatenate([F, np.zeros(6)])
        # scale the constraint rows/columns to the stiffness level for conditioning
        s = math.sqrt(np.max(np.abs(np.diag(self.K))) / max(np.max(np.abs(MR)), 1e-300))
        A[:n, n:] *= s
        A[n:, :n] *= s
        return np.linalg.solve(A, rhs)[:n]


def _node_offsets(ring: CageRing) -> np.ndarray:
    """Azimuths of the nodes of one pocket pitch, relative to the pocket centre, in [0, 2π/Z)."""
    pitch = 2.0 * math.pi / ring.pocket_count
    n_p, n_b = ring.split()
    if not ring.pockets:
        return pitch * np.arange(n_b) / n_b
    a = ring.pocket_half_angle
    half = [a * k / (n_p // 2) for k in range(n_p // 2 + 1)]  # 0 … α
    half += [a + (0.5 * pitch - a) * k / (n_b // 2) for k in range(1, n_b // 2 + 1)]  # … mid-bridge
    first = np.array(half)  # 0 … pitch/2
    second = pitch - first[-2:0:-1]  # mirrored, pitch/2 < ψ < pitch
    return np.concatenate([first, second])


def assemble(ring: CageRing) -> CageFE:
    """Assemble K and M of the ring (see the module docstring for the element and sections).

    Element e joins node e and node e+1 (mod N); its local axes: x' along the chord from a to
    b, z' = cage x, y' = z' × x' (radially inward).  Global matrices K_g = Tᵀ K_l T with
    T = blockdiag(λ, λ, λ, λ), λ the rows x', y', z' in the cage frame.
    """
    z = ring.pocket_count
    pitch = 2.0 * math.pi / z
    offs = _node_offsets(ring)
    epp = len(offs)
    psi = (ring.first_pocket_azimuth + (np.arange(z)[:, None] * pitch + offs[None, :])).ravel()
    n = len(psi)
    R = ring.pitch_radius
    xyz = np.column_stack([np.zeros(n), R * np.cos(psi), R * np.sin(psi)])
    elems = np.column_stack([np.arange(n), (np.arange(n) + 1) % n])
    # pocket elements: both ends within ±α of the pocket centre (offsets ≤ α or ≥ pitch − α)
    a = ring.pocket_half_angle
    tol = 1e-12 * pitch
    off_a = np.tile(offs, z)
    off_b = np.roll(off_a, -1)
    off_b = np.where(off_b == 0.0, pitch, off_b)

    def inside(o):
        return (o <= a + tol) | (o >= pitch - a - tol)

    in_pocket = inside(off_a) & inside(off_b) if ring.pockets else np.zeros(n, dtype=bool)
    sec_b = section_properties(ring.axial_width, ring.radial_thickness)
    sec_p = section_properties(ring.axial_width, ring.radial_thickness, ring.pocket_diameter)
    E, G, rho = ring.young_modulus, ring.shear_modulus, ring.density
    kappa = cowper_shear_coefficient(ring.poisson)
    K = np.zeros((6 * n, 6 * n))
    M = np.zeros((6 * n, 6 * n))
    lengths = np.empty(n)
    ez = np.array([1.0, 0.0, 0.0])
    cache = {}
    for e, (ia, ib) in enumerate(elems):
        d = xyz[ib] - xyz[ia]
        L = float(np.linalg.norm(d))
        lengths[e] = L
        ex = d / L
        ey = np.cross(ez, ex)
        lam = np.vstack([ex, ey, ez])
        key = (round(L / R, 13), bool(in_pocket[e]))
        if key not in cache:
            cache[key] = element_matrices(L, sec_p if in_pocket[e] else sec_b, E, G, rho, kappa,
                                          ring.shear_deformation, ring.rotary_inertia)
        kl, ml = cache[key]
        T = np.zeros((12, 12))
        for blk in range(4):
            T[3 * blk:3 * blk + 3, 3 * blk:3 * blk + 3] = lam
        idx = np.concatenate([np.arange(6 * ia, 6 * ia + 6), np.arange(6 * ib, 6 * ib + 6)])
        K[np.ix_(idx, idx)] += T.T @ kl @ T
        M[np.ix_(idx, idx)] += T.T @ ml @ T
    K = 0.5 * (K + K.T)
    M = 0.5 * (M + M.T)
    return CageFE(ring=ring, K=K, M=M, node_azimuth=psi, node_xyz=xyz, pocket_nodes=np.arange(z) * epp,
                  elements=elems, element_pocket=in_pocket, element_length=lengths,
                  sections={"bridge": sec_b, "pocket": sec_p})


# ---------------------------------------------------------------------------------------------
# modes
# ---------------------------------------------------------------------------------------------
@dataclass(frozen=True, eq=False)
class CageModes:
    """Free–free elastic modes of a cage ring (cage frame, SI).

    omega : float[n] [rad/s]  the n lowest elastic natural frequencies, ascending
    shapes : float[n, Z, 6]  mass-normalised mode shapes at the pocket centres, components
        (ux, uy, uz) [m] and small rotations (θx, θy, θz) [rad] per unit modal coordinate η
        (φᵀ M φ = 1: η carries the unit √kg·m, so the shape values are in 1/√kg); the cage's
        elastic displacement is u = Σ_k φ_k η_k and the generalized force f_k = Σ_j φ_k(j) · F_j
    vectors : float[6N, n]  the full FE mode vectors (same normalisation)
    kind : list[str]  e.g. "in-plane n=2", "out-of-plane n=3", "extensional n=0", "torsional n=0"
    wave_number : int[n]  circumferential wave number n of each mode
    mass [kg], polar_inertia (about x) [kg m²], transverse_inertia (about y) [kg m²] of the FE model
    rigid_omega : float[6] [rad/s]  sign(ω²)·sqrt|ω²| of the six rigid-body eigenvalues as computed
        (numerical noise, ≈ 0)
    fe : CageFE  the assembled model (K, M, node and DOF maps)

    Sign and pair conventions: a degenerate pair (cos/sin) is rotated so that the first member's
    dominant field (radial displacement in-plane, axial out-of-plane) varies as cos n(ψ − φ_0)
    and the second as sin n(ψ − φ_0); every mode's leading harmonic coefficient is positive.
    """

    omega: np.ndarray
    shapes: np.ndarray
    vectors: np.ndarray
    kind: list
    wave_number: np.ndarray
    mass: float
    polar_inertia: float
    transverse_inertia: float
    rigid_omega: np.ndarray
    fe: CageFE = field(repr=False, compare=False)

    @property
    def frequency_hz(self) -> np.ndarray:
        """ω / 2π [Hz]."""
        return self.omega / (2.0 * math.pi)

    def point_shapes(self, offsets) -> np.ndarray:
        """Mode shapes float[n, Z, 3] [displacement per unit η] at points rigidly attached to the
        pocket-centre sections, u + θ × r, with r = offsets float[Z, 3] (or [3], the same for every
        pocket) [m] from each pocket centre, cage-frame components (small rotations; the section is
        rigid in the beam model)."""
        r = np.broadcast_to(np.asarray(offsets, dtype=float), (self.shapes.shape[1], 3))
        return self.shapes[:, :, :3] + np.cross(self.shapes[:, :, 3:], r[None, :, :])

    def summary(self) -> dict:
        """JSON-ready dict (SI)."""
        r = self.fe.ring
        return {
            "mass_kg": self.mass, "polar_inertia_kg_m2": self.polar_inertia,
            "transverse_inertia_kg_m2": self.transverse_inertia,
            "ring": {"pitch_radius_m": r.pitch_radius, "axial_width_m": r.axial_width,
                     "radial_thickness_m": r.radial_thickness, "pocket_count": r.pocket_count,
                     "pocket_diameter_m": r.pocket_diameter, "young_modulus_Pa": r.young_modulus,
                     "poisson": r.poisson, "density_kg_m3": r.density,
                     "elements_per_pitch": r.elements_per_pitch, "pockets": r.pockets,
                     "shear_deformation": r.shear_deformation, "rotary_inertia": r.rotary_inertia},
            "modes": [{"index": i, "omega_rad_s": float(w), "frequency_Hz": float(w / (2 * math.pi)),
                       "kind": k} for i, (w, k) in enumerate(zip(self.omega, self.kind))],
        }


def _cyl_fields(fe: CageFE, v: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(in-plane fields (u_r, u_t, R θ_x), out-of-plane fields (u_x, R θ_r, R θ_t)) of the
    mode vectors v float[6N, m], each float[3, N, m]."""
    psi = fe.node_azimuth
    R = fe.ring.pitch_radius
    c, s = np.cos(psi)[:, None], np.sin(psi)[:, None]
    nn = fe.n_nodes
    u = v.reshape(nn, 6, -1)
    ur = c * u[:, 1] + s * u[:, 2]
    ut = -s * u[:, 1] + c * u[:, 2]
    tr = c * u[:, 4] + s * u[:, 5]
    tt = -s * u[:, 4] + c * u[:, 5]
    return np.stack([ur, ut, R * u[:, 3]]), np.stack([u[:, 0], R * tr, R * tt])


def _node_weights(fe: CageFE) -> np.ndarray:
    """Trapezoid weights of the nodes on the circle [rad] (sum 2π)."""
    dpsi = np.diff(np.append(fe.node_azimuth, fe.node_azimuth[0] + 2.0 * math.pi))
    return 0.5 * (dpsi + np.roll(dpsi, 1))


def _harmonics(fe: CageFE, f: np.ndarray) -> np.ndarray:
    """Complex Fourier coefficients c_n = Σ_i w_i f_i e^{−i n (ψ_i − φ_0)}, n = 0 … N/2,
    of fields f float[..., N, m] → complex[..., N/2 + 1, m]."""
    w = _node_weights(fe)
    nmax = fe.n_nodes // 2
    ph = np.exp(-1j * np.outer(np.arange(nmax + 1), fe.node_azimuth - fe.ring.first_pocket_azimuth))  # (n, N)
    return np.einsum("kn,n,...nm->...km", ph, w, f)


def _classify(fe: CageFE, v: np.ndarray):
    """Plane, wave number, kind and dominant harmonic coefficient of each mode vector."""
    inp, outp = _cyl_fields(fe, v)
    w = _node_weights(fe)[:, None]
    e_in = np.sum(w * np.sum(inp**2, axis=0), axis=0)
    e_out = np.sum(w * np.sum(outp**2, axis=0), axis=0)
    c_in = _harmonics(fe, inp)  # (3, n, m)
    c_out = _harmonics(fe, outp)
    kinds, nums, lead = [], [], []
    for k in range(v.shape[1]):
        if e_in[k] >= e_out[k]:
            p = np.sum(np.abs(c_in[:, :, k]) ** 2, axis=0)
            n = int(np.argmax(p))
            # branch by the phase of u_t relative to u_r: flexural (inextensional, u_r = −∂u_t/∂ψ)
            # Re(c_r · conj(i c_t)) < 0; the extensional branch has the opposite sign
            if n <= 1:  # n = 0 breathing; elastic n = 1 (the flexural n = 1 pair is rigid translation)
                kind = f"extensional n={n}"
            else:
                flex = (c_in[0, n, k] * np.conj(1j * c_in[1, n, k])).real < 0.0
                kind = f"in-plane n={n}" if flex else f"extensional n={n}"
            coef = c_in[0, n, k] if abs(c_in[0, n, k]) > 1e-9 * math.sqrt(p[n]) else c_in[1, n, k]
        else:
            p = np.sum(np.abs(c_out[:, :, k]) ** 2, axis=0)
            n = int(np.argmax(p))
            # branch by the phase of the twist R θ_t relative to u_x: the lower (flexural–torsional)
            # branch has Re(c_x · conj(c_θt)) < 0, the torsional branch the opposite sign
            if n <= 1:  # n = 0 twist (ring everting); elastic n = 1 (the flexural n = 1 pair is rigid tilt)
                kind = f"torsional n={n}"
            else:
                flex = (c_out[0, n, k] * np.conj(c_out[2, n, k])).real < 0.0
                kind = f"out-of-plane n={n}" if flex else f"torsional n={n}"
            coef = c_out[0, n, k] if abs(c_out[0, n, k]) > 1e-9 * math.sqrt(p[n]) else c_out[2, n, k]
        kinds.append(kind)
        nums.append(n)
        lead.append((e_in[k] >= e_out[k], n, coef))
    return kinds, np.array(nums, dtype=int), lead


def _orient(fe: CageFE, lam: np.ndarray, vec: np.ndarray) -> None:
    """Rotate degenerate pairs to cos/sin form and fix the signs of the mode vectors (in place).

    A pair (relative eigenvalue gap ≤ 1e-7) is rotated so that the first member's dominant field
    (u_r in-plane, u_x out-of-plane) has a real harmonic coefficient c_n (cos n(ψ − φ_0)-like)
    and the second a purely imaginary one (sin-like); then every mode's leading coefficient is
    made positive: Re c > 0 when |Re c| ≥ |Im c|, else Im c < 0 (a positive sin n(ψ − φ_0) term).
    """
    m = vec.shape[1]
    k = 0
    while k + 1 < m:
        if abs(lam[k + 1] - lam[k]) <= 1e-7 * abs(lam[k + 1]):
            _, _, lead = _classify(fe, vec[:, k:k + 2])
            ca, cb = lead[0][2], lead[1][2]
            if lead[0][:2] == lead[1][:2] and abs(ca.imag) + abs(cb.imag) > 0:
                g = math.atan2(-ca.imag, cb.imag)
                a_new = vec[:, k] * math.cos(g) + vec[:, k + 1] * math.sin(g)
                b_new = -vec[:, k] * math.sin(g) + vec[:, k + 1] * math.cos(g)
                vec[:, k], vec[:, k + 1] = a_new, b_new
            k += 2
        else:
            k += 1
    _, _, lead = _classify(fe, vec)
    for j, (_, _, c) in enumerate(lead):
        flip = (c.real < 0) if abs(c.real) >= abs(c.imag) else (c.imag > 0)
        if flip:
            vec[:, j] *= -1.0


def cage_modes(ring: CageRing, n_modes: int, fe: CageFE | None = None) -> CageModes:
    """The ``n_modes`` lowest free–free elastic modes of the cage ring.

    Solves K φ = ω² M φ (scipy.linalg.eigh, generalized symmetric-definite) for the lowest
    6 + n_modes (+ 1, to complete a degenerate pair) eigenpairs; the first six are the rigid-body
    modes: they must satisfy |ω²| < 1e-6 ω₇² (or lie below the solver's noise level, 1e-12 of the
    largest eigenvalue; else ConvergenceError: the model is not a single free ring).
    Returns :class:`CageModes`; ``fe`` reuses an assembled model of the same ring.

    Cost: dense eigh of 6 N DOF (N = Z × elements_per_pitch nodes); seed-001 hub row (Z = 16,
    768 DOF, 56 modes) ≈ 0.4–1 s CPU.
    """
    from scipy.linalg import eigh

    if fe is None:
        fe = assemble(ring)
    nmax = fe.n_dof - 6
    if isinstance(n_modes, bool) or not isinstance(n_modes, (int, np.integer)) or n_modes < 1:
        raise InputError("n_modes", f"must be a positive integer, got {n_modes!r}", "e.g. 56 ([S1])")
    if n_modes > nmax:
        raise InputError("n_modes", f"{n_modes} exceeds the {nmax} elastic modes of this FE model",
                         f"ask for at most {nmax} modes or raise elements_per_pitch")
    top = min(fe.n_dof - 1, 6 + n_modes)
    # Jacobi scaling (unit mass diagonal) for conditioning; eigenvalues unchanged, φ = D φ̃
    d = 1.0 / np.sqrt(np.diag(fe.M))
    lam, vec = eigh(fe.K * np.outer(d, d), fe.M * np.outer(d, d), subset_by_index=[0, top])
    vec *= d[:, None]
    # zero level: eigh's absolute accuracy ~ eps × λ_max, λ_max ≈ max(diag K̃) (≤ its Gershgorin bound)
    noise = 1e-12 * float(np.max(np.diag(fe.K) * d * d))
    lam_el = lam[6]
    if not (lam_el > noise and np.all(np.abs(lam[:6]) < max(1e-6 * lam_el, noise))):
        raise ConvergenceError(f"expected 6 rigid-body modes (|ω²| < 1e-6 ω₇²), found eigenvalues "
                               f"{np.array2string(lam[:7], precision=3)}")
    rigid = np.sign(lam[:6]) * np.sqrt(np.abs(lam[:6]))
    lam, vec = lam[6:], vec[:, 6:]
    _orient(fe, lam, vec)
    lam, vec = lam[:n_modes], vec[:, :n_modes]
    kinds, nums, _ = _classify(fe, vec)
    rb = fe.rigid_body_vectors()
    shapes = vec.reshape(fe.n_nodes, 6, n_modes)[fe.pocket_nodes].transpose(2, 0, 1).copy()
    return CageModes(omega=np.sqrt(lam), shapes=shapes, vectors=vec, kind=kinds, wave_number=nums,
                     mass=float(rb[:, 0] @ fe.M @ rb[:, 0]), polar_inertia=float(rb[:, 3] @ fe.M @ rb[:, 3]),
                     transverse_inertia=float(rb[:, 4] @ fe.M @ rb[:, 4]), rigid_omega=rigid, fe=fe)


# ---------------------------------------------------------------------------------------------
# stress recovery (quasi-static, from the nodal displacements)
# ---------------------------------------------------------------------------------------------
#: names of the 6 stress resultants returned by :func:`element_end_forces`, in order
RESULTANTS = ("N", "V_y", "V_z", "T", "M_y", "M_z")


def _element_frames(fe: CageFE) -> np.ndarray:
    """float[E, 3, 3]: rows x', y', z' of each element's local frame in the cage frame, built
    exactly as in :func:`assemble` (x' along the chord a → b, z' = cage x, y' = z' × x', radially
    inward at the chord's midpoint)."""
    xyz = fe.node_xyz
    d = xyz[fe.elements[:, 1]] - xyz[fe.elements[:, 0]]
    ex = d / np.linalg.norm(d, axis=1)[:, None]
    ez = np.broadcast_to(np.array([1.0, 0.0, 0.0]), ex.shape)
    ey = np.cross(ez, ex)
    return np.stack([ex, ey, ez], axis=1)


def _element_stiffness(fe: CageFE) -> np.ndarray:
    """float[E, 12, 12]: the local element stiffness matrices used by :func:`assemble`."""
    ring = fe.ring
    kappa = cowper_shear_coefficient(ring.poisson)
    out = np.empty((len(fe.elements), 12, 12))
    cache = {}
    for e, L in enumerate(fe.element_length):
        key = (round(L / ring.pitch_radius, 13), bool(fe.element_pocket[e]))
        if key not in cache:
            sec = fe.sections["pocket" if fe.element_pocket[e] else "bridge"]
            cache[key] = element_matrices(float(L), sec, ring.young_modulus, ring.shear_modulus, ring.density,
                                          kappa, ring.shear_deformation, ring.rotary_inertia)[0]
        out[e] = cache[key]
    return out


def element_end_forces(fe: CageFE, u) -> np.ndarray:
    """Stress resultants at both ends of every element [N, N·m] from the nodal displacements u.

    u : float[6N] (or float[6N, m], m displacement vectors as columns, e.g. ``CageModes.vectors``)
        [m, rad], cage frame, global DOF order of :class:`CageFE`.
    Returns float[E, 2, 6] (or float[m, E, 2, 6]): for element e, end 0 = node a =
    ``fe.elements[e, 0]``, end 1 = node b, the resultants (N, V_y', V_z', T, M_y', M_z') in the
    element's local frame (x' along the chord a → b, y' radially inward, z' = cage axis x; see
    :func:`assemble`): axial force N [N], shear forces V_y', V_z' [N], torque T [N·m] and bending
    moments M_y' (out-of-plane bending, about the radial axis) and M_z' (in-plane bending, about
    the axial axis) [N·m].

    Sign convention (beam stress resultants): the force and moment that the material on the +x'
    side of a cut exerts on the face whose outward normal is +x', components along the local
    axes.  Hence N > 0 is tension, and the normal stress at a section point (y', z') is
    σ = N/A + M_y' z'/I_y' − M_z' y'/I_z' (M_y' = ∫ z'σ dA, M_z' = −∫ y'σ dA).  With the element
    end forces f = k_l T u_e (Przemieniecki, Theory of Matrix Structural Analysis, 1968, ch. 5–6:
    the forces the nodes exert on the element), the resultants are −f_a at end a and +f_b
    at end b; at a node without external load the resultants of two adjacent elements agree once
    both are expressed in the cage frame (equilibrium).

    Quasi-static stress recovery: the element's inertia (and any load between the nodes) is not
    included — the resultants are those of the element deformed statically into the same nodal
    displacements (exact for the beam element under end loads).  For a vibrating mode the
    element's own inertia, −ω² m_l u_l, is left out: on the assumed seed-001 hub cage (8 elements
    per pocket pitch) including it changes the peak stress of the 12 lowest modes by −0.06 …
    −0.22 % (16 elements: −0.01 … −0.04 %), i.e. O(h²) and below the recovery's own discretisation
    error (tests/unit/test_cage_stress.py, inextensional ring modes).
    """
    u = np.asarray(u, dtype=float)
    single = u.ndim == 1
    uu = u[:, None] if single else u
    if uu.ndim != 2 or uu.shape[0] != fe.n_dof:
        raise InputError("u", f"expected shape ({fe.n_dof},) or ({fe.n_dof}, m), got {u.shape}",
                         "a full FE displacement vector, e.g. modes.vectors @ eta")
    lam = _element_frames(fe)  # (E, 3, 3)
    kl = _element_stiffness(fe)  # (E, 12, 12)
    nodes = uu.reshape(fe.n_nodes, 6, -1)
    ue = np.concatenate([nodes[fe.elements[:, 0]], nodes[fe.elements[:, 1]]], axis=1)  # (E, 12, m)
    ul = np.einsum("eij,ebjm->ebim", lam, ue.reshape(len(lam), 4, 3, -1)).reshape(ue.shape)
    f = np.einsum("eij,ejm->eim", kl, ul)  # (E, 12, m): local end forces on the element
    res = np.stack([-f[:, :6], f[:, 6:]], axis=1)  # (E, 2, 6, m)
    if single:
        return res[..., 0]
    return np.moveaxis(res, -1, 0)


def stress_points(fe: CageFE) -> np.ndarray:
    """float[P = 8, 2]: the section points where the normal stress is evaluated, as offsets from
    the section's centroid [m]: column 0 the radial offset r (outward), column 1 the axial offset
    x (cage x = local z').  Point p = 4 i_r + i_x with r = (+t/2, −t/2)[i_r] (outer, inner
    surface) and x = (−b/2, −d_p/2, +d_p/2, +b/2)[i_x].

    For a pocket element these are the eight corners of the two side rails (rails of width
    w = (b − d_p)/2 centred at x = ±(b + d_p)/4, corners at ±(b + d_p)/4 ± (b − d_p)/4); for a
    bridge (full b × t rectangle) the points at ±b/2 are its four corners and the points at
    ±d_p/2 interior points of the outer and inner surfaces (Navier's stress is linear over the
    section, so its extremes are at corners: the maximum over the eight points is the section's)."""
    r = fe.ring
    t, b, d = r.radial_thickness, r.axial_width, r.pocket_diameter
    rad = np.repeat([0.5 * t, -0.5 * t], 4)
    ax = np.tile([-0.5 * b, -0.5 * d, 0.5 * d, 0.5 * b], 2)
    return np.column_stack([rad, ax])


def _section_arrays(fe: CageFE) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(A, I_y' = I_out, I_z' = I_in), each float[E], of the element sections (the stiffness's)."""
    sb, sp = fe.sections["bridge"], fe.sections["pocket"]
    pk = fe.element_pocket
    return (np.where(pk, sp["A"], sb["A"]), np.where(pk, sp["I_out"], sb["I_out"]),
            np.where(pk, sp["I_in"], sb["I_in"]))


def normal_stress(fe: CageFE, forces) -> np.ndarray:
    """Normal (hoop) stress σ [Pa] at the :func:`stress_points` of both ends of every element,
    float[..., E, 2, P], from the resultants ``forces`` float[..., E, 2, 6] of
    :func:`element_end_forces`.

    Navier (Roark's Formulas for Stress and Strain, 7th ed., §8.1; straight-beam formula, the
    ring's curvature correction O(t/R) neglected): σ = N/A + M_y' z'/I_y' − M_z' y'/I_z', with the
    section constants of the stiffness model (pocket: the two rails as one section, plane sections
    remaining plane across them; bridge: b × t rectangle), y' = −r (inward), z' = x.  Positive =
    tension.  Shear stresses (transverse shear, Saint-Venant torsion) are neglected here; see
    :func:`torsion_shear_stress`.
    """
    F = np.asarray(forces, dtype=float)
    A, iy, iz = _section_arrays(fe)
    pts = stress_points(fe)
    yl, zl = -pts[:, 0], pts[:, 1]  # local y' (inward), z' (axial)
    return (F[..., 0, None] / A[:, None, None] + F[..., 4, None] * zl / iy[:, None, None]
            - F[..., 5, None] * yl / iz[:, None, None])


def _rect_torsion_stress_factor(a: float, c: float, terms: int = 50) -> float:
    """c·k/J [1/m³] with τ_max = T c k / J for a solid a × c rectangle (a ≥ c): the maximum
    Saint-Venant shear stress, at the middle of the long sides, k = 1 − (8/π²) Σ_{n odd}
    1/(n² cosh(nπa/(2c))) (Timoshenko & Goodier, Theory of Elasticity, 3rd ed., §109; a square
    gives τ_max = T/(0.208 a³), Roark 7th ed. table 10.7 case 4)."""
    a, c = (a, c) if a >= c else (c, a)
    n = np.arange(1, 2 * terms, 2, dtype=float)
    k = 1.0 - 8.0 / math.pi**2 * float(np.sum(1.0 / (n**2 * np.cosh(np.minimum(n * math.pi * a / (2 * c), 700.0)))))
    return c * k / rect_torsion_constant(a, c)


def torsion_shear_stress(fe: CageFE, forces) -> np.ndarray:
    """Largest Saint-Venant torsion shear stress |τ| [Pa] of each element end, float[..., E, 2],
    from the resultants float[..., E, 2, 6]: τ = |T| c k / J of the b × t rectangle (bridge), or
    of one rail (w × t) carrying T/2 (pocket; the stiffness's J = 2 J_rail).  Formula:
    :func:`_rect_torsion_stress_factor` (Timoshenko & Goodier §109).  Not added to the normal
    stress (different points and components); transverse shear stress (≈ 1.5 V/A) is not given."""
    F = np.asarray(forces, dtype=float)
    r = fe.ring
    t, b, d = r.radial_thickness, r.axial_width, r.pocket_diameter
    fb = _rect_torsion_stress_factor(b, t)
    fp = 0.5 * _rect_torsion_stress_factor(0.5 * (b - d), t) if r.pockets else fb
    fac = np.where(fe.element_pocket, fp, fb)
    return np.abs(F[..., 3]) * fac[:, None]


def stress_shapes(modes: CageModes) -> np.ndarray:
    """Normal stress per unit modal coordinate, float[n_modes, E, 2, P] [Pa per unit η]:
    S_k = σ(φ_k) at the :func:`stress_points` of both ends of every element (quasi-static
    recovery, :func:`element_end_forces` and :func:`normal_stress`).  The stress of the elastic
    cage is σ(t) = Σ_k η_k(t) S_k (linear in u = Σ_k η_k φ_k; the rigid-body motion carries no
    stress).  Memory: n_modes × E × 2 × 8 floats (seed-001 hub row, 56 modes, 128 elements:
    0.9 MB)."""
    return normal_stress(modes.fe, element_end_forces(modes.fe, modes.vectors))


def _eta_2d(modes: CageModes, eta) -> tuple[np.ndarray, bool]:
    e = np.asarray(eta, dtype=float)
    n = len(modes.omega)
    if e.shape[-1:] != (n,) or e.ndim > 2:
        raise InputError("eta", f"expected shape ({n},) or (n_t, {n}), got {e.shape}", "one modal coordinate per mode")
    return np.atleast_2d(e), e.ndim == 1


def peak_stress(modes: CageModes, eta, shapes: np.ndarray | None = None):
    """max |σ| [Pa] over all elements, ends and stress points of the stress σ = Σ_k η_k S_k
    (:func:`stress_shapes`, normal stress only).  eta float[n_modes] → float; float[n_t, n_modes]
    → float[n_t].  Pass precomputed ``shapes`` to avoid recomputing them."""
    S = stress_shapes(modes) if shapes is None else shapes
    e, single = _eta_2d(modes, eta)
    flat = S.reshape(S.shape[0], -1)
    out = np.empty(len(e))
    chunk = max(1, int(4e6 // max(flat.shape[1], 1)))
    for i in range(0, len(e), chunk):
        out[i:i + chunk] = np.max(np.abs(e[i:i + chunk] @ flat), axis=1)
    return float(out[0]) if single else out


def peak_stress_location(modes: CageModes, eta, shapes: np.ndarray | None = None) -> dict:
    """Where the peak of :func:`peak_stress` occurs for one η float[n_modes]: dict with
    stress_Pa (signed, tension > 0), element, end (0 = node a, 1 = node b), node, azimuth_rad (of
    that node), point (index into :func:`stress_points`), radial_offset_m, axial_offset_m, and
    part ("pocket" rail or "bridge")."""
    S = stress_shapes(modes) if shapes is None else shapes
    e, single = _eta_2d(modes, eta)
    if not single:
        raise InputError("eta", "expected one vector of modal coordinates", "call it per output sample")
    s = np.tensordot(e[0], S, axes=(0, 0))  # (E, 2, P)
    el, end, p = np.unravel_index(int(np.argmax(np.abs(s))), s.shape)
    fe = modes.fe
    node = int(fe.elements[el, end])
    pts = stress_points(fe)
    return {"stress_Pa": float(s[el, end, p]), "element": int(el), "end": int(end), "node": node,
            "azimuth_rad": float(fe.node_azimuth[node]), "point": int(p), "radial_offset_m": float(pts[p, 0]),
            "axial_offset_m": float(pts[p, 1]), "part": "pocket" if fe.element_pocket[el] else "bridge"}
