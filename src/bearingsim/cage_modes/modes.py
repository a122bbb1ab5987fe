"""Free–free modes of the cage ring (the model: :mod:`bearingsim.cage_modes`)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import ConvergenceError, InputError
from .beam import CageFE, assemble
from .section import CageRing


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
