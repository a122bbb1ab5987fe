"""Influence coefficients of an elastic ring at the ball positions, with the local Hertz part excluded, and
their disk cache.

Quantity.  For a ring carrying Z equally spaced balls, C[m, a, b] [m/N] is the displacement component a
(0: radial r, 1: axial ξ of the row frame) of the raceway at the contact point of ball j + m caused by a unit
force component b acting on the ring at the contact point of ball j, *minus* the part already counted by the
Hertz contact model (for m = 0).  Circulant: the response depends on m only.

Why a subtraction.  The contact model's approach δ = (Q/K)^(2/3) is Hertz's relative displacement of two
half-spaces between points far from the contact.  The ring's displacement field under a concentrated load is
that half-space field plus a smooth correction (the ring's finite size, its seat and its other boundaries).
Only the correction may be added to the groove-centre positions, otherwise the local deformation is counted
twice.  Method (both operations on the same load):

1. The unit force is spread over the raceway by a normalised Gaussian of width σ (along the section and,
   through the harmonic weights ĝ_n = exp(−n²σ_θ²/2), σ_θ = σ/r_p, around the circumference) and solved with
   the harmonic FE of :mod:`.axisymmetric` for n = 0 … n_max (until ĝ_n < 1e-5 or the depth decay
   exp(−n d/r_p) < 1e-6; above n = 48 every 4th harmonic is solved and the others interpolated by a cubic
   spline in n, checked against the dense sum in tests/unit/test_rings.py).
2. The response is read at two points inside the ring on the contact normal, at depths d and 2d (d ≥ 1.5 σ),
   where the FE resolves the field.  The half-space (Boussinesq/Cerruti, Johnson 1985 *Contact Mechanics*
   eqs. 2.18–2.19 for the point force, averaged over the same Gaussian) displacement at those points is
   subtracted from the self term (m = 0).  The remaining correction field is smooth, so its value at the
   contact surface is extrapolated linearly: u_s(0) = 2 u_s(d) − u_s(2d).  The same two-point extrapolation
   is applied to the other balls' terms (whose fields are smooth there).

The groove-centre displacement used by the coupling is taken equal to this raceway displacement at the
contact point (the rotation of the section over the groove radius is neglected: its effect is of the order of
the section rotation × f·D_w).

Cache: coefficients are stored in ``$BEARINGSIM_RING_CACHE`` (default ``~/.cache/bearingsim/rings``) as
``<sha256 of the inputs>.npz``; the key hashes the section, material, ball count, load spread, depths, mesh
settings and :data:`CACHE_VERSION`.

Units: SI (m, N, Pa).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from ..errors import InputError
from .section import RingSection

#: bump when the computation changes (invalidates every cached file)
CACHE_VERSION = 2
CACHE_ENV = "BEARINGSIM_RING_CACHE"


@dataclass(frozen=True)
class InfluenceSettings:
    """Discretisation of the influence computation (all lengths [m]; None → from the section)."""

    sigma: float | None = None  #: Gaussian spread of the unit load; default wall/8
    depth: float | None = None  #: first read-out depth d; default 1.5 σ
    h_contact: float | None = None  #: element size at the contact point; default σ/2
    n_through: int = 10  #: element layers through the wall
    n_axial: int = 20  #: about B / (element size away from the contact)
    ghat_min: float = 1e-5  #: last harmonic: ĝ_n below this
    decay_min: float = 1e-6  #: ... or exp(−n d / r_p) below this
    n_dense: int = 48  #: harmonics solved one by one
    stride: int = 4  #: above n_dense, every stride-th harmonic solved, the others interpolated

    def resolved(self, section: RingSection) -> dict:
        sigma = self.sigma if self.sigma is not None else section.wall / 8.0
        depth = self.depth if self.depth is not None else 1.5 * sigma
        h = self.h_contact if self.h_contact is not None else 0.5 * sigma
        if not (sigma > 0 and depth > 0 and h > 0):
            raise InputError("sigma", "the load spread, read-out depth and element size must be positive",
                             "give lengths in metres or leave them None")
        if 2.0 * depth >= 0.9 * section.wall:
            raise InputError("depth", f"read-out depth 2d = {2e3 * depth:.3g} mm reaches the seat "
                             f"(wall {1e3 * section.wall:.3g} mm)", "use a smaller depth or spread")
        return {"sigma": float(sigma), "depth": float(depth), "h_contact": float(h), "n_through": int(self.n_through),
                "n_axial": int(self.n_axial), "ghat_min": float(self.ghat_min), "decay_min": float(self.decay_min),
                "n_dense": int(self.n_dense), "stride": int(self.stride)}


@dataclass
class RingInfluence:
    """Influence coefficients of one ring (see the module docstring).

    coeffs : float[Z, 2, 2]  C[m, a, b] [m/N], components (r, ξ) of the row frame
    local : float[2, 2]  the half-space part removed from C[0] (surface value, extrapolated as C) [m/N]
    """

    kind: str
    ball_count: int
    coeffs: np.ndarray
    local: np.ndarray
    harmonics: int
    seconds: float
    key: str = ""
    meta: dict = field(default_factory=dict)

    def matrix(self) -> np.ndarray:
        """Full compliance matrix float[2Z, 2Z]: u[2j + a] = Σ_k M[2j + a, 2k + b] F[2k + b] [m/N]."""
        z = self.ball_count
        m = np.zeros((2 * z, 2 * z))
        for j in range(z):
            for k in range(z):
                m[2 * j:2 * j + 2, 2 * k:2 * k + 2] = self.coeffs[(j - k) % z]
        return m


def half_space_on_axis(force_normal: float, force_tangential: float, depth: float, sigma: float,
                       youngs_modulus: float, poisson_ratio: float) -> tuple[float, float]:
    """(u_n, u_t) [m] at depth ``depth`` below the centre of a force on an elastic half-space spread as an
    isotropic Gaussian of width ``sigma`` [m] over the surface: the normal part (Boussinesq) and the tangential
    part (Cerruti) along the force components [N] (Johnson 1985, Contact Mechanics, eqs. 3.?: point-force fields
    u_z = F(1+ν)/(2πE) [z²/ρ³ + 2(1−ν)/ρ] and u_x = Q(1+ν)/(2πE) [1/ρ + x²/ρ³ + (1−2ν)(1/(ρ+z) −
    x²/(ρ(ρ+z)²))], ρ the distance to the load point, averaged over the Gaussian by Gauss–Laguerre quadrature).
    On the axis the cross terms vanish by symmetry."""
    e, nu = youngs_modulus, poisson_ratio
    t, w = np.polynomial.laguerre.laggauss(80)
    s = sigma * np.sqrt(2.0 * t)  # radial distance on the surface; weight exp(−t) dt = Gaussian ring measure
    rho = np.sqrt(s * s + depth * depth)
    z = depth
    un = np.sum(w * (z * z / rho ** 3 + 2.0 * (1.0 - nu) / rho))
    x2 = 0.5 * s * s  # ⟨x²⟩ over the azimuth
    ut = np.sum(w * (1.0 / rho + x2 / rho ** 3 + (1.0 - 2.0 * nu) * (1.0 / (rho + z) - x2 / (rho * (rho + z) ** 2))))
    c = (1.0 + nu) / (2.0 * math.pi * e)
    return float(c * force_normal * un), float(c * force_tangential * ut)


def cache_dir() -> Path:
    """The cache folder (``$BEARINGSIM_RING_CACHE`` or ``~/.cache/bearingsim/rings``)."""
    env = os.environ.get(CACHE_ENV)
    return Path(env) if env else Path.home() / ".cache" / "bearingsim" / "rings"


def cache_key(section: RingSection, youngs_modulus: float, poisson_ratio: float, ball_count: int,
              settings: dict) -> str:
    """sha256 of every input of the computation (section, material, Z, resolved settings, version)."""
    sec = {k: v for k, v in asdict(section).items()
           if not (k in ("sleeve_youngs_modulus", "sleeve_poisson_ratio") and v is None)}  # keys of v2 files kept
    payload = {"version": CACHE_VERSION, "section": sec, "E": float(youngs_modulus),
               "nu": float(poisson_ratio), "Z": int(ball_count), "settings": settings}
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()


def sleeve_material(section, youngs_modulus: float, poisson_ratio: float):
    """The ``second_material`` of :class:`.axisymmetric.HarmonicRing` for a seat sleeve of another material (the
    elements beyond the ring's seat radius: (selector, E [Pa], ν)), or None when the sleeve is of the ring's
    material or there is no sleeve.  Shared by the single-groove and the shared (double-row) sections."""
    if section.sleeve_radius is None or (section.sleeve_youngs_modulus is None
                                         and section.sleeve_poisson_ratio is None):
        return None
    es = section.sleeve_youngs_modulus if section.sleeve_youngs_modulus is not None else youngs_modulus
    nus = section.sleeve_poisson_ratio if section.sleeve_poisson_ratio is not None else poisson_ratio
    seat, sgn = section.seat_radius, section.sign
    return (lambda x: sgn * (x[0] - seat) < 0.0, es, nus)


def compute_influence(section: RingSection, youngs_modulus: float, poisson_ratio: float, ball_count: int,
                      settings: InfluenceSettings | None = None, cache: bool = True) -> RingInfluence:
    """Influence coefficients of ``section`` (a ring on a rigid seat, or bonded to its seat sleeve whose far
    surface follows the shaft's/housing's rigid motion and is otherwise free; axially held at the loaded face) for
    ``ball_count`` balls (see the module docstring); read from / written to the disk cache when ``cache``."""
    from .axisymmetric import HarmonicRing
    from .section import mesh_section

    if not (isinstance(ball_count, (int, np.integer)) and ball_count >= 3):
        raise InputError("ball_count", f"need at least 3 balls, got {ball_count!r}", "give the row's ball count")
    st = (settings or InfluenceSettings()).resolved(section)
    key = cache_key(section, youngs_modulus, poisson_ratio, ball_count, st)
    path = cache_dir() / f"{key}.npz"
    if cache and path.exists():
        try:
            with np.load(path, allow_pickle=False) as f:
                return RingInfluence(section.kind, int(ball_count), f["coeffs"].copy(), f["local"].copy(),
                                     int(f["harmonics"]), float(f["seconds"]), key,
                                     json.loads(str(f["meta"])) | {"cached": True})
        except (OSError, KeyError, ValueError):
            pass  # unreadable file: recompute and overwrite
    t0 = time.perf_counter()
    mesh = mesh_section(section, st["h_contact"], st["n_through"], st["n_axial"])
    face = "face_minus" if section.support_face_z < 0 else "face_plus"
    # a rigid seat holds every harmonic; the far surface of a seat sleeve (a hollow shaft's bore, a housing's
    # outside) only follows the rigid translation and tilt of the shaft/housing (harmonic 1)
    second = sleeve_material(section, youngs_modulus, poisson_ratio)
    ring = HarmonicRing(mesh, youngs_modulus, poisson_ratio, radial_fixed=("seat",), axial_fixed=(face,),
                        radial_harmonics=None if section.sleeve_radius is None else (1,), second_material=second)
    p = section.contact_point
    nin = section.inward_normal
    tan = np.array([-nin[1], nin[0]])
    d = st["depth"]
    pts = np.column_stack([p + d * nin, p + 2.0 * d * nin])  # 2 × 2
    probe = ring.probe(pts)  # rows: U(d), U(2d), W(d), W(2d), V, V
    loads = np.vstack([ring.point_load("raceway", p, (1.0, 0.0), st["sigma"]),
                       ring.point_load("raceway", p, (0.0, 1.0), st["sigma"])])
    sig_t = st["sigma"] / p[0]
    z = int(ball_count)
    psi = 2.0 * math.pi * np.arange(z) / z
    # last harmonic: the spread's weight or the decay of harmonic n over the depth d is negligible
    n_max = int(math.ceil(min(math.sqrt(-2.0 * math.log(st["ghat_min"])) / sig_t,
                              -math.log(st["decay_min"]) * p[0] / d)))
    n_max = max(n_max, 3)
    # harmonics 0 … n_dense solved one by one; above, every ``stride``-th (the response of harmonic n at a fixed
    # point varies smoothly with n there) and the others interpolated by a cubic spline in n
    dense = min(st["n_dense"], n_max)
    sampled = np.unique(np.concatenate([np.arange(dense + 1), np.arange(dense, n_max + 1, st["stride"]), [n_max]]))
    resp = np.empty((len(sampled), 2, 2, 2))  # [n, depth, a, b]
    for i, n in enumerate(sampled):
        x = ring.solve(int(n), loads)  # (2 loads, N)
        v = probe @ x.T  # (6, 2): rows U(d), U(2d), W(d), W(2d), V(d), V(2d); columns the two loads
        resp[i, :, 0, :] = v[0:2, :]
        resp[i, :, 1, :] = v[2:4, :]
        ring._factors.pop(int(n), None)
    all_n = np.arange(n_max + 1)
    if len(sampled) < len(all_n):
        from scipy.interpolate import CubicSpline

        resp = CubicSpline(sampled, resp, axis=0)(all_n)
    ghat = np.exp(-0.5 * (all_n * sig_t) ** 2)
    acc = np.einsum("n,mn,ndab->mdab", ghat, np.cos(np.outer(psi, all_n)), resp)  # [m, depth, a, b]
    n = n_max + 1
    # the half-space part of the self term at both depths, in the (r, ξ) frame
    e, nu = ring.youngs_modulus, ring.poisson_ratio
    hs = np.zeros((2, 2, 2))
    for i, depth in enumerate((d, 2.0 * d)):
        un, ut = half_space_on_axis(1.0, 1.0, depth, st["sigma"], e, nu)
        hs[i] = un * np.outer(nin, nin) + ut * np.outer(tan, tan)
    acc[0] -= hs
    coeffs = 2.0 * acc[:, 0] - acc[:, 1]
    local = 2.0 * hs[0] - hs[1]
    secs = time.perf_counter() - t0
    meta = {"settings": st, "mesh_elements": int(mesh.nelements), "dofs": int(ring.basis.N), "cached": False,
            "harmonics_solved": int(len(sampled))}
    res = RingInfluence(section.kind, z, coeffs, local, n, secs, key, meta)
    if cache:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.tmp.npz")
            np.savez(tmp, coeffs=coeffs, local=local, harmonics=n, seconds=secs, meta=json.dumps(meta))
            os.replace(tmp, path)
        except OSError:
            pass  # a read-only cache is not an error: the coefficients are returned anyway
    return res
