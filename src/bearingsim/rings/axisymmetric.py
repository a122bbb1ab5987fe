"""Axisymmetric finite elements with circumferential Fourier harmonics (scikit-fem).

A body of revolution (the ring cross-section in the (r, z) half-plane swept around the z axis) under loads that
vary around the circumference is solved one Fourier harmonic at a time (the classic semi-analytical method:
Wilson 1965, AIAA J. 3(12) 2269–2274; Zienkiewicz & Taylor, *The Finite Element Method* vol. 1, 5th ed.,
ch. 9 "axisymmetric solids under non-symmetric load").  For harmonic n the displacement is

    u_r = U(r, z) cos nθ,   u_z = W(r, z) cos nθ,   u_θ = V(r, z) sin nθ

(the family symmetric about θ = 0: loads in the r–z plane at θ = 0), and the strains are

    ε_rr = U_r,  ε_zz = W_z,  ε_θθ = (U + nV)/r,  γ_rz = U_z + W_r        (× cos nθ)
    γ_rθ = V_r − V/r − nU/r,  γ_zθ = V_z − nW/r                             (× sin nθ)

i.e. ε = E₀(u) + n E₁(u) with E₁(u) = (0, 0, V/r, 0, −U/r, −W/r).  With the isotropic elasticity matrix D
the stiffness of harmonic n is π_n (A₀₀ + n A₀₁ + n² A₁₁), A_ab = ∫ E_a(u)ᵀ D E_b(v) r dr dz (A₀₁ symmetrised),
π_0 = 2π and π_n = π for n ≥ 1 (∫ cos² nθ dθ); the three matrices are assembled once.  For n = 0 the
circumferential unknown V (torsion) is decoupled and unloaded and is removed.  Elements: 9-node quadratic
quadrilaterals (``ElementQuad2``) on the (r, z) mesh of :mod:`.section`.

Units: SI (m, Pa, N).  A load is a force [N] acting at a point of the section's boundary, spread over the
boundary along the section (a normalised Gaussian of width σ [m]) and around the circumference (a normalised
Gaussian in θ of width σ/r_p: harmonic weight ĝ_n = exp(−n² σ_θ²/2)), or a pressure [Pa] on a boundary.
"""

from __future__ import annotations

import math

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ..errors import InputError


def _strains(u, r, which: int):
    """The six strain components (ε_rr, ε_zz, ε_θθ, γ_rz, γ_rθ, γ_zθ) of E₀ (which = 0) or E₁ (which = 1)."""
    U, W, V = u[0], u[1], u[2]
    g = u.grad
    zero = 0.0 * U
    if which == 0:
        return (g[0][0], g[1][1], U / r, g[0][1] + g[1][0], g[2][0] - V / r, g[2][1])
    return (zero, zero, V / r, zero, -U / r, -W / r)


def _energy(e, f, lam, mu):
    """eᵀ D f for the isotropic D (engineering shear strains)."""
    tr_e = e[0] + e[1] + e[2]
    tr_f = f[0] + f[1] + f[2]
    return (lam * tr_e * tr_f + 2.0 * mu * (e[0] * f[0] + e[1] * f[1] + e[2] * f[2])
            + mu * (e[3] * f[3] + e[4] * f[4] + e[5] * f[5]))


class HarmonicRing:
    """Fourier-harmonic axisymmetric FE model of one body of revolution.

    Parameters
    ----------
    mesh : skfem ``MeshQuad`` of the (r, z) section (r > 0), with named boundaries
    youngs_modulus : E [Pa];  poisson_ratio : ν [-]
    radial_fixed : names of boundaries where U = 0 for every harmonic (a rigid cylindrical seat), or ()
    axial_fixed : names of boundaries where W = 0 for every harmonic (a rigid axial abutment), or ()
    free : True for a free body: only the rigid modes are removed (W at one node for n = 0; harmonic 1,
        which holds the rigid translation and tilt, is refused — give self-equilibrated loads without it)
    radial_harmonics : None (the radial seat holds every harmonic) or the harmonics it holds, e.g. (1,): the
        far surface of a seat sleeve follows the shaft's rigid translation and tilt (harmonic 1, where U and W
        are held there) and is free for the other harmonics
    second_material : None, or (mask, E₂ [Pa], ν₂): the points x (2 × n, [m]) where ``mask(x)`` is true have the
        second material (a seat sleeve of another material; element boundaries must follow the interface)
    """

    def __init__(self, mesh, youngs_modulus: float, poisson_ratio: float, radial_fixed=(), axial_fixed=(),
                 free: bool = False, radial_harmonics=None, second_material=None):
        from skfem import Basis, BilinearForm, ElementQuad2, ElementVector, asm

        e, nu = float(youngs_modulus), float(poisson_ratio)
        if not (math.isfinite(e) and e > 0):
            raise InputError("youngs_modulus", f"must be positive, got {youngs_modulus!r} Pa", "e.g. 208e9")
        if not 0.0 <= nu < 0.5:
            raise InputError("poisson_ratio", f"must be in [0, 0.5), got {poisson_ratio!r}", "e.g. 0.3")
        if np.min(mesh.p[0]) <= 0:
            raise InputError("mesh", "the section must lie at r > 0", "a ring does not contain the axis")
        if free and (radial_fixed or axial_fixed):
            raise InputError("free", "a free body has no fixed boundaries", "give free=True or supports, not both")
        if not free and not (radial_fixed and axial_fixed):
            raise InputError("radial_fixed", "a supported ring needs a radial seat and an axial abutment",
                             "name both boundaries, or use free=True with self-equilibrated loads")
        self.mesh = mesh
        self.youngs_modulus, self.poisson_ratio = e, nu
        self.free = bool(free)
        lam = e * nu / ((1 + nu) * (1 - 2 * nu))
        mu = e / (2 * (1 + nu))
        if second_material is not None:
            mask, e2, nu2 = second_material
            e2, nu2 = float(e2), float(nu2)
            if not (math.isfinite(e2) and e2 > 0 and 0.0 <= nu2 < 0.5):
                raise InputError("second_material", f"E = {e2!r} Pa, ν = {nu2!r} is not an elastic material",
                                 "give E > 0 and 0 ≤ ν < 0.5")
            lam1, mu1 = lam, mu
            lam2, mu2 = e2 * nu2 / ((1 + nu2) * (1 - 2 * nu2)), e2 / (2 * (1 + nu2))

            def lam(x):
                return np.where(mask(x), lam2, lam1)

            def mu(x):
                return np.where(mask(x), mu2, mu1)
        else:
            lam_c, mu_c = lam, mu

            def lam(x):
                return lam_c

            def mu(x):
                return mu_c
        self.basis = Basis(mesh, ElementVector(ElementQuad2(), 3), intorder=5)
        self.scalar_basis = Basis(mesh, ElementQuad2(), intorder=5)

        @BilinearForm
        def a00(u, v, w):
            r = w.x[0]
            return _energy(_strains(u, r, 0), _strains(v, r, 0), lam(w.x), mu(w.x)) * r

        @BilinearForm
        def a01(u, v, w):
            r = w.x[0]
            la, m = lam(w.x), mu(w.x)
            return (_energy(_strains(u, r, 0), _strains(v, r, 1), la, m)
                    + _energy(_strains(u, r, 1), _strains(v, r, 0), la, m)) * r

        @BilinearForm
        def a11(u, v, w):
            r = w.x[0]
            return _energy(_strains(u, r, 1), _strains(v, r, 1), lam(w.x), mu(w.x)) * r

        self.a00, self.a01, self.a11 = (asm(f, self.basis).tocsr() for f in (a00, a01, a11))
        comp = self.basis.split_indices()  # dofs of U, W, V; index k of each = scalar dof k
        self.comp = comp
        fixed, radial = [], []
        for name in radial_fixed:
            radial.append(comp[0][self._boundary_scalar_dofs(name)])
            if radial_harmonics is not None:  # the sleeve's far surface: U and W held in harmonic 1
                radial.append(comp[1][self._boundary_scalar_dofs(name)])
        for name in axial_fixed:
            fixed.append(comp[1][self._boundary_scalar_dofs(name)])
        self._radial_harmonics = None if radial_harmonics is None else frozenset(int(n) for n in radial_harmonics)
        self._fixed_radial = np.unique(np.concatenate(radial)) if radial else np.zeros(0, dtype=int)
        self._fixed_all = np.unique(np.concatenate(fixed)) if fixed else np.zeros(0, dtype=int)
        self._factors: dict[int, object] = {}
        self._sliced: dict[int, tuple] = {}  # free dofs and sliced A00, A01, A11 per family (n = 0, n ≥ 1)

    def _boundary_scalar_dofs(self, name: str) -> np.ndarray:
        if name not in self.mesh.boundaries:
            raise InputError("boundary", f"no boundary named {name!r}", f"use one of {sorted(self.mesh.boundaries)}")
        return np.asarray(self.scalar_basis.get_dofs(name).all(), dtype=int)

    # ---- per-harmonic systems ---------------------------------------------------------------------------------
    def _family(self, n: int):
        """Harmonics sharing one set of fixed dofs."""
        if n == 0:
            return (0, self._radial_harmonics is None or 0 in self._radial_harmonics)
        return (1, self._radial_harmonics is None or n in self._radial_harmonics)

    def _free_dofs(self, n: int) -> np.ndarray:
        fixed = [self._fixed_all]
        if self._family(n)[1]:
            fixed.append(self._fixed_radial)
        if n == 0:
            fixed.append(self.comp[2])  # torsion: decoupled, unloaded
            if self.free:
                fixed.append(self.comp[1][:1])  # axial rigid translation
        elif n == 1 and self.free:
            raise InputError("harmonic", "harmonic 1 of a free ring holds its rigid translation and tilt",
                             "use self-equilibrated loads (no n = 1 content) or support the ring")
        fixed = np.unique(np.concatenate(fixed))
        return np.setdiff1d(np.arange(self.basis.N), fixed)

    def stiffness(self, n: int) -> sp.csr_matrix:
        """Global stiffness of harmonic n [N/m] (including ∫cos² nθ dθ)."""
        pin = 2.0 * math.pi if n == 0 else math.pi
        return (pin * (self.a00 + n * self.a01 + (n * n) * self.a11)).tocsr()

    def solve(self, n: int, load: np.ndarray) -> np.ndarray:
        """Nodal amplitudes (U, W, V interleaved as in ``basis``) of harmonic n under the load vector ``load``
        (the harmonic's generalized forces [N], e.g. :meth:`point_load` × ĝ_n); the factorisation is kept."""
        load = np.asarray(load, dtype=float)
        if n not in self._factors:
            fam = self._family(n)
            if fam not in self._sliced:
                free = self._free_dofs(n)
                self._sliced[fam] = (free, self.a00[free][:, free].tocsc(), self.a01[free][:, free].tocsc(),
                                     self.a11[free][:, free].tocsc())
            elif n == 1 and self.free:
                self._free_dofs(1)  # refuses harmonic 1 of a free ring
            free, b0, b1, b2 = self._sliced[fam]
            pin = 2.0 * math.pi if n == 0 else math.pi
            k = (pin * (b0 + n * b1 + (n * n) * b2)).tocsc()
            self._factors[n] = (free, splu(k, permc_spec="MMD_AT_PLUS_A"))
        free, lu = self._factors[n]
        x = np.zeros(self.basis.N)
        rhs = load if load.ndim == 1 else load.T
        sol = lu.solve(np.ascontiguousarray(rhs[free]))
        if load.ndim == 1:
            x[free] = sol
            return x
        out = np.zeros((load.shape[0], self.basis.N))
        out[:, free] = sol.T
        return out

    def clear(self) -> None:
        """Drop the kept factorisations (memory)."""
        self._factors.clear()

    # ---- loads ------------------------------------------------------------------------------------------------
    def point_load(self, boundary: str, point, direction, sigma: float) -> np.ndarray:
        """Generalized forces (harmonic weight ĝ_n not included) of a unit force [N] in the (r, z) ``direction``
        acting at ``point`` of ``boundary``: spread over the boundary with a Gaussian of width ``sigma`` [m] in
        the distance to the point, normalised so that its resultant is exactly 1 N (∫ h r/r_p ds = 1)."""
        from skfem import FacetBasis, LinearForm, asm

        p = np.asarray(point, dtype=float)
        d = np.asarray(direction, dtype=float)
        d = d / np.linalg.norm(d)
        if not sigma > 0:
            raise InputError("sigma", f"must be positive, got {sigma!r}", "give the load's spread in metres")
        fb = FacetBasis(self.mesh, self.basis.elem, facets=self.mesh.boundaries[boundary], intorder=8)
        fbs = FacetBasis(self.mesh, self.scalar_basis.elem, facets=self.mesh.boundaries[boundary], intorder=8)

        def h(x):
            dist2 = (x[0] - p[0]) ** 2 + (x[1] - p[1]) ** 2
            return np.exp(-0.5 * dist2 / sigma ** 2) * x[0] / p[0]

        @LinearForm
        def total(v, w):
            return h(w.x) * v

        @LinearForm
        def lf(v, w):
            return h(w.x) * (d[0] * v[0] + d[1] * v[1])

        norm = float(np.sum(asm(total, fbs)))
        return asm(lf, fb) / norm

    def pressure_load(self, boundary: str, pressure: float) -> np.ndarray:
        """Generalized forces of harmonic 0 of a uniform pressure [Pa] on ``boundary`` (pushing into the body:
        along the inward normal), including the 2π of the circumference."""
        from skfem import FacetBasis, LinearForm, asm

        fb = FacetBasis(self.mesh, self.basis.elem, facets=self.mesh.boundaries[boundary], intorder=6)

        @LinearForm
        def lf(v, w):
            nr, nz = w.n[0], w.n[1]
            return -pressure * (nr * v[0] + nz * v[1]) * w.x[0]

        return 2.0 * math.pi * asm(lf, fb)

    # ---- output -----------------------------------------------------------------------------------------------
    def probe(self, points) -> np.ndarray:
        """Sparse matrix P (3·m × N) with (P x) = (U, W, V) at the m ``points`` (2 × m, [m]) stacked by component:
        rows [0:m] U, [m:2m] W, [2m:3m] V."""
        pts = np.atleast_2d(np.asarray(points, dtype=float))
        if pts.shape[0] != 2:
            pts = pts.T
        ps = self.scalar_basis.probes(pts).tocoo()
        m = pts.shape[1]
        rows, cols, vals = [], [], []
        for c in range(3):
            rows.append(ps.row + c * m)
            cols.append(self.comp[c][ps.col])
            vals.append(ps.data)
        return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                             shape=(3 * m, self.basis.N))
