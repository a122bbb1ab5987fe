"""A ring shared by several rows of balls (the common outer ring of a double-row unit such as a wheel hub):
one axisymmetric section carrying one groove per row, and the influence coefficients between every contact
point of every row.

Section (:class:`SharedSection`).  Global axial coordinate z of the unit (the rows' ``position``, from the
system centre); groove g of row g is a circle of radius f·D_w whose bottom (radius r_b) lies in the row plane
z = x_g; lands at ``land_radius`` between and beside the grooves; seat at ``seat_radius`` (the outside of an
outer ring); faces at ``z_faces``.  Row g's local frame is ξ = s_g (z − x_g) (:mod:`bearingsim.statics.layout`),
so its contact point is the single-row one of :class:`.section.RingSection` mirrored by s_g, and a load or
displacement component ξ in row g's frame is s_g times the global z component.  The mesh is
:func:`.section.mesh_section` (the axial nodes graded towards every contact point).

Influence coefficients (:func:`compute_shared_influence`).  The harmonic FE of :mod:`.axisymmetric` is loaded
at every groove by the unit force spread of :mod:`.influence` (σ along the section, σ_θ around), both
directions (r, ξ) of the row's frame; per harmonic n the responses are kept for every pair (row h read, row g
loaded):

* h = g (the row's own groove): read at depths d and 2d on the contact normal, the half-space part of the
  same-ball term removed and the surface value extrapolated, exactly as :func:`.influence.compute_influence`
  does for a single-groove ring (with one groove this module reproduces it to round-off:
  tests/unit/test_rings_shared.py);
* h ≠ g (another row's groove, where the field of the load at g is smooth): the work-conjugate read-out, the
  displacement averaged with the same spread as a unit load at h, u_hg = ĝ_n(h) f_hᵀ K_n⁻¹ f_g ĝ_n(g).  K_n is
  symmetric, so C_hg = C_ghᵀ holds to round-off (Maxwell–Betti reciprocity); the averaging over the spread
  (σ ≈ 0.5 mm) of a field that varies over the groove distance (≈ 18 mm) differs from the point value by
  O((σ/L)²) ≈ 1e-3 of a term that is itself small.

Supports (the shared outer ring of a unit): bonded to a housing sleeve (the knuckle) whose far surface follows
the housing's rigid translation and tilt (radial and axial held in harmonic 1) and is held axially in every
harmonic (the unit's flange bolted to the knuckle carries the axial load of both rows, which push the ring in
opposite directions); without a sleeve the seat is held (radially and axially).  ``axial_support`` may name a
face instead (the single-ring convention: the face on the loaded side).

Units: SI (m, N, Pa).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
import time
from dataclasses import asdict, dataclass, field

import numpy as np

from ..errors import InputError
from .influence import InfluenceSettings, cache_dir, half_space_on_axis, sleeve_material

#: bump when the computation changes (invalidates cached shared-ring files)
SHARED_CACHE_VERSION = 1


@dataclass(frozen=True)
class Groove:
    """One row's groove in a shared ring: row plane ``position`` [m] (global z), ``orientation`` s = ±1,
    ``bottom_radius`` [m], ``radius`` f·D_w [m], nominal ``contact_angle`` α₀ [rad]."""

    position: float
    orientation: float
    bottom_radius: float
    radius: float
    contact_angle: float


@dataclass(frozen=True)
class SharedSection:
    """Cross-section of a ring with one groove per row (module docstring) [m]."""

    kind: str
    seat_radius: float
    land_radius: float
    grooves: tuple
    z_min: float
    z_max: float
    sleeve_radius: float | None = None
    sleeve_youngs_modulus: float | None = None
    sleeve_poisson_ratio: float | None = None
    axial_support: str = "seat"

    def __post_init__(self):
        object.__setattr__(self, "grooves", tuple(self.grooves))
        if self.kind not in ("inner", "outer"):
            raise InputError("kind", f"must be 'inner' or 'outer', got {self.kind!r}", "give the ring kind")
        if self.axial_support not in ("seat", "face_minus", "face_plus"):
            raise InputError("axial_support", f"unknown support {self.axial_support!r}",
                             "use seat, face_minus or face_plus")
        if not self.grooves:
            raise InputError("grooves", "a shared ring needs at least one groove", "give the rows' grooves")
        sgn = self.sign
        for g in self.grooves:
            if not (sgn * (g.bottom_radius - self.seat_radius) > 0 and sgn * (self.land_radius - g.bottom_radius) > 0):
                raise InputError("seat_radius", f"the seat, groove bottom and land radii are not ordered as in an "
                                 f"{self.kind} ring", "check the unit's outside diameter / bore and the rows")
            h = abs(self.land_radius - g.bottom_radius)
            if h >= g.radius:
                raise InputError("land_radius", "the shoulder is higher than the groove radius",
                                 "use a smaller shoulder fraction")
        edges = sorted((g.position - self._edge(g), g.position + self._edge(g)) for g in self.grooves)
        if edges[0][0] <= self.z_min or edges[-1][1] >= self.z_max:
            raise InputError("width", f"a groove reaches a face of the {self.kind} ring "
                             f"({1e3 * self.z_min:.4g} … {1e3 * self.z_max:.4g} mm)", "give a wider ring")
        for (a0, a1), (b0, b1) in zip(edges[:-1], edges[1:]):
            if a1 >= b0:
                raise InputError("rows", "two grooves of the shared ring overlap", "check the row spacing")
        if self.sleeve_radius is not None and not sgn * (self.seat_radius - self.sleeve_radius) > 0:
            raise InputError("sleeve_radius", f"{self.sleeve_radius!r} m is not beyond the seat", "check the sleeve")

    @property
    def sign(self) -> float:
        """+1 for an inner ring (material below the raceway), −1 for an outer ring."""
        return 1.0 if self.kind == "inner" else -1.0

    def _edge(self, g) -> float:
        h = abs(self.land_radius - g.bottom_radius)
        return math.sqrt(g.radius ** 2 - (g.radius - h) ** 2)

    def groove_centre(self, g) -> float:
        """Radius of the groove-curvature centre of groove g [m]."""
        return g.bottom_radius + self.sign * g.radius

    def contact_point(self, k: int) -> np.ndarray:
        """(r, z) of row k's nominal contact point (the single-row point mirrored by s_k) [m]."""
        g = self.grooves[k]
        a = g.contact_angle
        return np.array([self.groove_centre(g) - self.sign * g.radius * math.cos(a),
                         g.position + g.orientation * (-self.sign * g.radius * math.sin(a))])

    def local_normal(self, k: int) -> np.ndarray:
        """Unit vector (r, ξ) in row k's frame at its contact point pointing into the material [-]."""
        a = self.grooves[k].contact_angle
        return -self.sign * np.array([math.cos(a), math.sin(a)])

    def to_global(self, k: int) -> np.ndarray:
        """Matrix (r, ξ of row k) → (r, z): diag(1, s_k)."""
        return np.diag([1.0, self.grooves[k].orientation])

    # ---- the interface of .section.section_grid -----------------------------------------------------------
    @property
    def z_faces(self) -> tuple[float, float]:
        return self.z_min, self.z_max

    @property
    def contact_zs(self) -> tuple[float, ...]:
        return tuple(float(self.contact_point(k)[1]) for k in range(len(self.grooves)))

    @property
    def groove_edges(self) -> tuple[float, ...]:
        out = []
        for g in self.grooves:
            e = self._edge(g)
            out += [g.position - e, g.position + e]
        return tuple(out)

    @property
    def wall(self) -> float:
        """Thinnest wall between a groove bottom and the seat [m]."""
        return min(abs(g.bottom_radius - self.seat_radius) for g in self.grooves)

    @property
    def depth(self) -> float:
        return max(abs(self.land_radius - self.seat_radius), self.wall)

    def surface_radius(self, z) -> np.ndarray:
        """Radius of the raceway side at axial position z [m]."""
        z = np.asarray(z, dtype=float)
        out = np.full(z.shape, self.land_radius)
        for g in self.grooves:
            dz = z - g.position
            inside = np.abs(dz) < self._edge(g)
            groove = self.groove_centre(g) - self.sign * np.sqrt(np.maximum(g.radius ** 2 - dz * dz, 0.0))
            out = np.where(inside, groove, out)
        return out


@dataclass
class SharedInfluence:
    """Harmonic responses of a shared ring (module docstring) and their assembly into compliance matrices.

    resp : float[G, G, N, 2, 2, 2]  [h, g, n, depth, a, b]: component a (r, ξ of row h) at row h's groove for a
        unit force component b (r, ξ of row g) at row g's groove, harmonic n, the spread weights included (ĝ_n of
        g for h = g, ĝ_n of both for h ≠ g) [m/N]
    half_space : float[G, 2, 2, 2]  [g, depth, a, b] the half-space part of the same-ball term [m/N]
    ghat : float[G, N]  the circumferential spread weights of the loads
    """

    resp: np.ndarray
    half_space: np.ndarray
    ghat: np.ndarray
    harmonics: int
    seconds: float
    key: str = ""
    meta: dict = field(default_factory=dict)

    def matrix(self, azimuths: list) -> np.ndarray:
        """Compliance float[2n, 2n] over the balls of all rows (row by row, ball-major, components (r, ξ) of each
        ball's row frame): u[2i + a] = Σ M[2i + a, 2k + b] F[2k + b] [m/N], ``azimuths[g]`` the ball azimuths of
        row g [rad]; the same-ball terms without the local (half-space) part, the surface value extrapolated
        from the depths d and 2d as in :func:`.influence.compute_influence`."""
        zs = [len(a) for a in azimuths]
        off = np.concatenate([[0], np.cumsum(zs)])
        n = np.arange(self.resp.shape[2])
        m = np.zeros((2 * off[-1], 2 * off[-1]))
        for h, ph in enumerate(azimuths):
            for g, pg in enumerate(azimuths):
                dpsi = np.subtract.outer(np.asarray(ph, float), np.asarray(pg, float))  # [j, k]
                acc = np.einsum("jkn,ndab->jkdab", np.cos(dpsi[..., None] * n), self.resp[h, g])
                if h == g:  # the same ball: its local (half-space) part is the contact model's
                    idx = np.arange(zs[h])
                    acc[idx, idx] -= self.half_space[g]
                c = 2.0 * acc[:, :, 0] - acc[:, :, 1]  # [j, k, a, b]
                m[2 * off[h]:2 * off[h + 1], 2 * off[g]:2 * off[g + 1]] = \
                    c.transpose(0, 2, 1, 3).reshape(2 * zs[h], 2 * zs[g])
        return m

    def scaled(self, factor: float) -> "SharedInfluence":
        return SharedInfluence(self.resp * factor, self.half_space * factor, self.ghat, self.harmonics,
                               self.seconds, self.key, dict(self.meta) | {"compliance_factor": factor})


def shared_cache_key(section: SharedSection, youngs_modulus: float, poisson_ratio: float, settings: dict) -> str:
    payload = {"version": SHARED_CACHE_VERSION, "section": asdict(section), "E": float(youngs_modulus),
               "nu": float(poisson_ratio), "settings": settings}
    return hashlib.sha256(json.dumps(payload, sort_keys=True).encode()).hexdigest()


def compute_shared_influence(section: SharedSection, youngs_modulus: float, poisson_ratio: float,
                             settings: InfluenceSettings | None = None, cache: bool = True) -> SharedInfluence:
    """Harmonic responses of a shared ring between all its grooves (module docstring); read from / written to
    the disk cache of :mod:`.influence` when ``cache``."""
    from .axisymmetric import HarmonicRing
    from .section import mesh_section

    st = (settings or InfluenceSettings()).resolved(section)
    key = "shared-" + shared_cache_key(section, youngs_modulus, poisson_ratio, st)
    path = cache_dir() / f"{key}.npz"
    if cache and path.exists():
        try:
            with np.load(path, allow_pickle=False) as f:
                return SharedInfluence(f["resp"].copy(), f["half_space"].copy(), f["ghat"].copy(),
                                       int(f["harmonics"]), float(f["seconds"]), key,
                                       json.loads(str(f["meta"])) | {"cached": True})
        except (OSError, KeyError, ValueError):
            pass  # unreadable file: recompute and overwrite
    t0 = time.perf_counter()
    mesh = mesh_section(section, st["h_contact"], st["n_through"], st["n_axial"])
    second = sleeve_material(section, youngs_modulus, poisson_ratio)
    ring = HarmonicRing(mesh, youngs_modulus, poisson_ratio, radial_fixed=("seat",),
                        axial_fixed=(section.axial_support,),
                        radial_harmonics=None if section.sleeve_radius is None else (1,), second_material=second)
    ng = len(section.grooves)
    d = st["depth"]
    sigma = st["sigma"]
    loads, probes, pts_r = [], [], []
    for k in range(ng):
        p = section.contact_point(k)
        rot = section.to_global(k)
        nin = rot @ section.local_normal(k)  # global (r, z)
        for b in range(2):
            loads.append(ring.point_load("raceway", p, rot[:, b], sigma))
        probes.append(ring.probe(np.column_stack([p + d * nin, p + 2.0 * d * nin])))
        pts_r.append(p[0])
    loads = np.vstack(loads)  # [2 ng, N]: (groove k, direction b) → 2k + b
    r_min = min(pts_r)
    sig_t = np.array([sigma / r for r in pts_r])
    n_max = int(math.ceil(min(math.sqrt(-2.0 * math.log(st["ghat_min"])) / float(sig_t.min()),
                              -math.log(st["decay_min"]) * max(pts_r) / d)))
    n_max = max(n_max, 3)
    dense = min(st["n_dense"], n_max)
    sampled = np.unique(np.concatenate([np.arange(dense + 1), np.arange(dense, n_max + 1, st["stride"]), [n_max]]))
    all_n = np.arange(n_max + 1)
    ghat_all = np.exp(-0.5 * np.outer(sig_t, all_n) ** 2)  # [g, n]
    raw = np.empty((len(sampled), ng, ng, 2, 2, 2))  # [n, h, g, depth, a, b] before the spread weights
    for i, n in enumerate(sampled):
        x = ring.solve(int(n), loads)  # (2 ng, N)
        for h in range(ng):
            s_h = section.grooves[h].orientation
            v = probes[h] @ x.T  # rows U(d), U(2d), W(d), W(2d), V, V; columns the loads
            conj = loads[2 * h:2 * h + 2] @ x.T  # [a, load]: the work-conjugate read-out at groove h
            for g in range(ng):
                cols = slice(2 * g, 2 * g + 2)
                if h == g:
                    raw[i, h, g, :, 0, :] = v[0:2, cols]
                    raw[i, h, g, :, 1, :] = s_h * v[2:4, cols]
                else:
                    raw[i, h, g, 0] = raw[i, h, g, 1] = conj[:, cols]
        ring._factors.pop(int(n), None)
    if len(sampled) < len(all_n):
        from scipy.interpolate import CubicSpline

        raw = CubicSpline(sampled, raw, axis=0)(all_n)
    resp = np.empty((ng, ng, n_max + 1, 2, 2, 2))
    for h in range(ng):
        for g in range(ng):
            w = ghat_all[g] if h == g else ghat_all[g] * ghat_all[h]
            resp[h, g] = w[:, None, None, None] * raw[:, h, g]
    e, nu = ring.youngs_modulus, ring.poisson_ratio
    hs = np.zeros((ng, 2, 2, 2))
    for k in range(ng):
        nl = section.local_normal(k)
        tl = np.array([-nl[1], nl[0]])
        for i, depth in enumerate((d, 2.0 * d)):
            un, ut = half_space_on_axis(1.0, 1.0, depth, sigma, e, nu)
            hs[k, i] = un * np.outer(nl, nl) + ut * np.outer(tl, tl)
    secs = time.perf_counter() - t0
    meta = {"settings": st, "mesh_elements": int(mesh.nelements), "dofs": int(ring.basis.N), "cached": False,
            "harmonics_solved": int(len(sampled)), "grooves": ng, "min_contact_radius_m": r_min}
    res = SharedInfluence(resp, hs, ghat_all, n_max + 1, secs, key, meta)
    if cache:
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.tmp.npz")
            np.savez(tmp, resp=resp, half_space=hs, ghat=ghat_all, harmonics=n_max + 1, seconds=secs,
                     meta=json.dumps(meta))
            os.replace(tmp, path)
        except OSError:
            pass
    return res


def estimate_unit(system, spec=None, shoulder_fraction: float = 0.25, shaft_bore_fraction: float | None = 0.5,
                  housing_od_factor: float | None = 1.5, housing=None, shaft=None):
    """Ring sections of a double-row unit (``system``: a :class:`bearingsim.statics.arrangements.BearingSystem`)
    → (list of the rows' inner :class:`.section.RingSection`, the shared outer :class:`SharedSection`, notes).

    Boundary dimensions from ``spec`` (the file's ``[rings.outer_ring]`` / ``[rings.inner_rings]``,
    :class:`.spec.RingSpec`), else ESTIMATE (listed in ``notes["estimated"]``; nothing fitted to a stiffness):

    * outside diameter of the outer ring d_m + 2 D_w (a wall of D_w/2 between groove bottom and outside: the
      flanged outer ring of a hub is thicker than a single bearing's, 0.35 D_w for the SKF 7011);
    * inner-ring bore d_m − 2 D_w (the same wall under the inner groove);
    * outer-ring width: the span of the row planes + 2 D_w (each outer face D_w beyond the outermost row);
    * inner rings: one per row (separate rings), centred on the row's groove, of width the row spacing (the
      rings meet midway between the rows) or 2 D_w for a single row;

    the grooves, lands (``shoulder_fraction``·D_w) and contact points per row as in
    :func:`.section.estimate_sections`; the seat sleeves as there (``housing`` / ``shaft`` a
    :class:`.spec.Sleeve`, else the fractions)."""
    import dataclasses

    from .section import _sleeve, estimate_sections

    rows = list(system.rows)
    spec_o = spec.outer_ring if spec is not None else (0.0, 0.0)
    spec_i = spec.inner_rings if spec is not None else (0.0, 0.0)
    dws = [r.bearing.ball_diameter for r in rows]
    dms = [r.bearing.pitch_diameter for r in rows]
    pos = [float(r.position) for r in rows]
    est = []
    od = spec_o[0] or max(dm + 2.0 * dw for dm, dw in zip(dms, dws))
    if not spec_o[0]:
        est.append(f"outer ring outside diameter {od * 1e3:.4g} mm: ESTIMATE d_m + 2 D_w")
    width = spec_o[1] or (max(pos) - min(pos) + 2.0 * max(dws))
    if not spec_o[1]:
        est.append(f"outer ring width {width * 1e3:.4g} mm: ESTIMATE span of the rows + 2 D_w")
    bore = spec_i[0] or min(dm - 2.0 * dw for dm, dw in zip(dms, dws))
    if not spec_i[0]:
        est.append(f"inner ring bore {bore * 1e3:.4g} mm: ESTIMATE d_m - 2 D_w")
    gaps = [abs(b - a) for a, b in zip(sorted(pos)[:-1], sorted(pos)[1:])]
    wi = spec_i[1] or (min(gaps) if gaps else 2.0 * max(dws))
    if not spec_i[1]:
        est.append(f"inner ring width {wi * 1e3:.4g} mm: ESTIMATE the row spacing (separate inner rings meeting "
                   "midway)")
    if housing is not None and not housing.rigid and not housing.diameter > od:
        raise InputError("rings.housing.outer_diameter", f"{housing.diameter * 1e3:.4g} mm is not larger than the "
                         f"unit's outer ring ({od * 1e3:.4g} mm{', estimated' if not spec_o[0] else ''})",
                         "give the housing's outside diameter, or the ring's in [rings.outer_ring]")
    if shaft is not None and not shaft.rigid and not shaft.diameter < bore:
        raise InputError("rings.shaft.inner_diameter", f"{shaft.diameter * 1e3:.4g} mm is not smaller than the "
                         f"inner rings' bore ({bore * 1e3:.4g} mm{', estimated' if not spec_i[0] else ''})",
                         "give the shaft's bore, or the rings' in [rings.inner_rings]")
    inners, grooves = [], []
    land = math.inf
    for r in rows:
        b = r.bearing
        bb = dataclasses.replace(b, bore=bore, outside_diameter=od, width=wi)
        inner, outer = estimate_sections(bb, shoulder_fraction, shaft_bore_fraction, housing_od_factor,
                                         shaft=shaft)
        inners.append(inner)
        grooves.append(Groove(float(r.position), float(r.orientation), outer.groove_bottom_radius,
                              outer.groove_radius, outer.contact_angle))
        land = min(land, outer.land_radius)
    so = None if housing_od_factor is None else 0.5 * od * housing_od_factor
    so, eo, nuo = _sleeve(housing, so, 0.5 * od)
    mid = 0.5 * (max(pos) + min(pos))
    outer = SharedSection("outer", 0.5 * od, land, tuple(grooves), mid - 0.5 * width, mid + 0.5 * width, so, eo, nuo)
    notes = {"outer_ring_outside_diameter_m": od, "outer_ring_width_m": width, "inner_ring_bore_m": bore,
             "inner_ring_width_m": wi, "estimated": est}
    return inners, outer, notes


def is_unit(bearing, spec=None) -> bool:
    """True for a bearing system whose rows share one outer ring (module docstring of :mod:`.coupling`): the
    file gives the shared outer ring (``[rings.outer_ring]``) or its row bearings have no boundary dimensions
    (a double-row unit such as a hub, read from a row entry without bore / outside diameter / width)."""
    if getattr(bearing, "kind", None) != "bearing_system":
        return False
    if spec is not None and (spec.outer_ring[0] > 0 or spec.outer_ring[1] > 0):
        return True
    return any(not (r.bearing.bore > 0 and r.bearing.outside_diameter > 0 and r.bearing.width > 0)
               for r in bearing.rows)


__all__ = ["Groove", "SharedInfluence", "SharedSection", "compute_shared_influence", "estimate_unit", "is_unit",
           "shared_cache_key"]
