"""A full 3-D finite-element model of a ring (scikit-fem), the reference for the harmonic model of
:mod:`.axisymmetric`.

The ring cross-section grid of :func:`.section.section_grid` is swept around the axis into 27-node quadratic
hexahedra (``ElementHex2`` on a ``MeshHex``: the ring becomes a polygon of 4·``n_theta`` sides).  One quarter of
the ring, θ ∈ [0, π/2], is modelled with symmetry planes (u_y = 0 on y = 0, u_x = 0 on x = 0): it carries loads
symmetric about both planes, e.g. four equal ball loads at θ = 0, π/2, π, 3π/2 (harmonics n = 0, 4, 8, …).
Supports as in :func:`.influence.compute_influence`: the loaded face held axially (a shared ring of
:mod:`.shared`: its far surface held axially); the seat sleeve's far surface
free (harmonic 1, the only one held there, is absent from these loads), or without a sleeve the ring's seat held
radially (only for the radial direction: done here by holding both in-plane components, so compare rigid-seat
cases only at n = 0).  Isotropic linear elasticity (skfem.models.elasticity).

Loads: unit force [N] in the (r, z) direction ``direction`` at the section point ``point`` of every ball, spread
as in the harmonic model: a Gaussian of width σ [m] in the section distance to the point times a Gaussian of
width σ_θ [rad] around the circumference, normalised so that each ball's resultant is 1 N × ``force``.

Units: SI (m, N, Pa).
"""

from __future__ import annotations

import math

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from ..errors import InputError
from .section import RingSection, section_grid


class QuarterRing3D:
    """3-D quarter-ring model (module docstring); ``solve_ball_loads`` → displacement field."""

    def __init__(self, section: RingSection, youngs_modulus: float, poisson_ratio: float, h_contact: float,
                 n_theta: int = 16, n_through: int = 5, n_axial: int = 10, n_sleeve: int = 6):
        from skfem import Basis, ElementHex2, ElementVector, MeshHex, asm
        from skfem.models.elasticity import lame_parameters, linear_elasticity

        if n_theta < 2:
            raise InputError("n_theta", f"need at least 2 elements over the quarter, got {n_theta!r}",
                             "e.g. 16")
        self.section = section
        t, zs, radius = section_grid(section, h_contact, n_through, n_axial, n_sleeve)
        phi = np.linspace(0.0, 0.5 * math.pi, n_theta + 1)
        m = MeshHex.init_tensor(t, phi, zs)
        tt, ph, zz = m.p
        # inner ring: r grows with t, (t, θ, z) → (r, θ, z) is right-handed; outer ring: r falls with t, so θ is
        # mirrored to keep positive element volumes
        th = ph if section.kind == "inner" else 0.5 * math.pi - ph
        r = radius(tt, zz)
        self.mesh = MeshHex(np.vstack([r * np.cos(th), r * np.sin(th), zz]), m.t)
        self.basis = Basis(self.mesh, ElementVector(ElementHex2()), intorder=4)
        self.scalar_basis = Basis(self.mesh, ElementHex2(), intorder=4)
        lam, mu = lame_parameters(float(youngs_modulus), float(poisson_ratio))
        self.k = asm(linear_elasticity(lam, mu), self.basis).tocsr()
        z0, z1 = section.z_faces
        hw = 0.5 * (z1 - z0)
        tol = 1e-9 * hw
        d = self.basis.get_dofs
        fixed = [d(lambda x: np.abs(x[1]) < tol).all("u^2"), d(lambda x: np.abs(x[0]) < tol).all("u^1")]
        far = section.sleeve_radius if section.sleeve_radius is not None else section.seat_radius
        support = getattr(section, "axial_support", None)
        if support == "seat":  # a shared ring (.shared): held axially at the far surface (every harmonic)
            # the far surface is a polygon of chords: its facet points lie up to far (1 − cos(Δφ/2)) inside
            sag = far * (1.0 - math.cos(0.25 * math.pi / n_theta)) * 1.01 + 1e-6 * hw
            fixed.append(d(lambda x: np.abs(np.hypot(x[0], x[1]) - far) < sag).all("u^3"))
        else:
            zface = section.support_face_z if support is None else (z0 if support == "face_minus" else z1)
            fixed.append(d(lambda x: np.abs(x[2] - zface) < tol).all("u^3"))
        if section.sleeve_radius is None:  # a rigid seat
            seat = lambda x: np.abs(np.hypot(x[0], x[1]) - section.seat_radius) < 1e-6 * hw  # noqa: E731
            fixed += [d(seat).all("u^1"), d(seat).all("u^2")]
        self.fixed = np.unique(np.concatenate(fixed))
        self.free = np.setdiff1d(np.arange(self.basis.N), self.fixed)
        self.comp = self.basis.split_indices()
        self._lu = None

    def _raceway_facets(self) -> np.ndarray:
        s = self.section
        far = s.sleeve_radius if s.sleeve_radius is not None else s.seat_radius
        mid = self.mesh.p[:, self.mesh.facets].mean(axis=1)
        bnd = self.mesh.boundary_facets()
        r = np.hypot(mid[0, bnd], mid[1, bnd])
        tol = 1e-7
        z0, z1 = s.z_faces
        keep = (np.abs(mid[0, bnd]) > tol) & (np.abs(mid[1, bnd]) > tol) & (np.abs(mid[2, bnd] - z0) > tol) & \
            (np.abs(mid[2, bnd] - z1) > tol) & (np.abs(r - far) > 1e-6 * (z1 - z0))
        return bnd[keep]

    def ball_load_vector(self, point, direction, sigma: float, sigma_theta: float, thetas, force: float = 1.0):
        """Generalized forces [N] of a force ``force`` at every ball azimuth in ``thetas`` (all four quadrant
        images must be listed, e.g. (−π/2, 0, π/2, π)), spread as in the module docstring."""
        from skfem import FacetBasis, LinearForm, asm

        p = np.asarray(point, dtype=float)
        e = np.asarray(direction, dtype=float)
        e = e / np.linalg.norm(e)
        facets = self._raceway_facets()
        fb = FacetBasis(self.mesh, self.basis.elem, facets=facets, intorder=6)
        fbs = FacetBasis(self.mesh, self.scalar_basis.elem, facets=facets, intorder=6)
        thetas = np.asarray(thetas, dtype=float)

        def density(x):
            r = np.sqrt(x[0] ** 2 + x[1] ** 2)
            th = np.arctan2(x[1], x[0])
            h = np.exp(-0.5 * ((r - p[0]) ** 2 + (x[2] - p[1]) ** 2) / sigma ** 2)
            g = sum(np.exp(-0.5 * ((th - tk) / sigma_theta) ** 2) for tk in thetas)
            return h * g, th

        @LinearForm
        def total(v, w):
            dens, _ = density(w.x)
            return dens * v

        @LinearForm
        def lf(v, w):
            dens, th = density(w.x)
            return dens * (e[0] * np.cos(th) * v[0] + e[0] * np.sin(th) * v[1] + e[1] * v[2])

        # resultant over the quarter: one ball (two halves on the symmetry planes, or one inside) per quarter
        per_quarter = len(thetas) / 4.0
        norm = float(np.sum(asm(total, fbs))) / per_quarter
        return force * asm(lf, fb) / norm

    def solve(self, load: np.ndarray) -> np.ndarray:
        """Nodal displacements [m] (components interleaved as in ``basis``)."""
        if self._lu is None:
            self._lu = splu(self.k[self.free][:, self.free].tocsc(), permc_spec="MMD_AT_PLUS_A")
        x = np.zeros(self.basis.N)
        x[self.free] = self._lu.solve(np.asarray(load, dtype=float)[self.free])
        return x

    def cylindrical(self, x: np.ndarray, points_rz, theta: float) -> np.ndarray:
        """(u_r, u_z) [m] at the section points ``points_rz`` (2 × m) on the azimuth ``theta`` [rad]."""
        pts = np.atleast_2d(np.asarray(points_rz, dtype=float))
        xyz = np.vstack([pts[0] * math.cos(theta), pts[0] * math.sin(theta), pts[1]])
        pr = self.scalar_basis.probes(xyz)
        ux, uy, uz = (pr @ x[c] for c in self.comp)
        return np.vstack([ux * math.cos(theta) + uy * math.sin(theta), uz])

    @property
    def dofs(self) -> int:
        return int(self.basis.N)


__all__ = ["QuarterRing3D", "sp"]
