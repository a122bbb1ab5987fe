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

from ..beam import element_matrices
from .beam import CageFE, assemble
from .modes import CageModes, cage_modes
from .section import (
    NODE_DOF,
    CageRing,
    cowper_shear_coefficient,
    default_cage_ring,
    rect_torsion_constant,
    section_properties,
)
from .stress import (
    RESULTANTS,
    element_end_forces,
    normal_stress,
    peak_stress,
    peak_stress_location,
    stress_points,
    stress_shapes,
    torsion_shear_stress,
)

__all__ = ["CageRing", "CageFE", "CageModes", "default_cage_ring", "assemble", "cage_modes",
           "rect_torsion_constant", "cowper_shear_coefficient", "section_properties", "RESULTANTS",
           "element_end_forces", "stress_points", "normal_stress", "torsion_shear_stress", "stress_shapes",
           "peak_stress", "peak_stress_location", "element_matrices", "NODE_DOF"]
