"""Assembly of the cage ring from the frame elements of :mod:`bearingsim.beam` (the model:
:mod:`bearingsim.cage_modes`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..beam import element_matrices
from ..errors import InputError
from .section import CageRing, cowper_shear_coefficient, section_properties


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
