"""Stress recovery of the cage ring from nodal displacements (the model: :mod:`bearingsim.cage_modes`)."""

from __future__ import annotations

import math

import numpy as np

from ..beam import element_matrices
from ..errors import InputError
from .beam import CageFE
from .modes import CageModes
from .section import cowper_shear_coefficient, rect_torsion_constant

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
