"""Ring cross-sections of a ball bearing estimated from its boundary dimensions, and their r–z meshes.

A ring is modelled as a body of revolution: a cross-section in the (r, z) half-plane (z the bearing axis, local
to the row: z = ξ, positive towards the side of the *outer* contact point, the convention of the row frame of
:mod:`bearingsim.statics.layout`) swept around the axis.

Estimate of the section (used when only the catalogue's boundary dimensions d, D, B are known; nothing is fitted
to a stiffness):

* groove bottom radii from the pitch diameter and the ball diameter D_w (zero clearance):
  r_bi = (d_m − D_w)/2 (inner), r_bo = (d_m + D_w)/2 (outer) [m];
* groove = circle of radius f·D_w (f the conformity) whose lowest (inner) / highest (outer) point is the groove
  bottom, at mid-width (z = 0);
* seat surface = bore radius d/2 (inner ring) or outside radius D/2 (outer ring);
* both lands (shoulders) at a height h = ``shoulder_fraction``·D_w above (inner) / below (outer) the groove
  bottom; 0.25 D_w is an engineering estimate of angular-contact spindle-bearing shoulders (the high shoulder of
  such rings is typically 0.2–0.3 D_w, the low one lower; using one height for both sides overstates the low
  shoulder a little, which stiffens the ring slightly).  docs/rings.md gives the sensitivity to this fraction;
* faces at z = ±B/2, square corners (chamfers neglected);
* seat: by default the ring is bonded to a sleeve of the same material and width B that stands for its seat
  (the shaft under the inner ring, the housing around the outer ring), held rigidly at its far radius:
  ``sleeve_radius`` = the shaft's bore (default 0.5 d: a hollow machine-tool spindle) or the housing's outside
  radius (default 0.75 D, i.e. a housing wall of D/4); ``sleeve_radius = None`` puts the ring on a rigid seat.
  A seat matters at first order: a ring on a rigid seat is *stiffer* than the half-spaces of Hertz theory
  (its material ends at the seat), a free ring far softer (hoop and ovalisation compliance); docs/rings.md.

Units: metres throughout.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError


@dataclass(frozen=True)
class RingSection:
    """Cross-section of one ring in its row frame [m].

    kind : ``"inner"`` or ``"outer"``
    seat_radius : bore radius (inner) or outside radius (outer)
    land_radius : radius of the lands beside the groove
    groove_bottom_radius : radius of the groove bottom (at z = 0)
    groove_radius : f·D_w
    half_width : B/2
    contact_angle : nominal contact angle α₀ [rad] (where the unit loads act)
    sleeve_radius : far radius of the seat sleeve (shaft bore or housing outside radius), None for a rigid seat
    sleeve_youngs_modulus [Pa], sleeve_poisson_ratio [-] : the sleeve's material, None: the ring's
    """

    kind: str
    seat_radius: float
    land_radius: float
    groove_bottom_radius: float
    groove_radius: float
    half_width: float
    contact_angle: float
    sleeve_radius: float | None = None
    sleeve_youngs_modulus: float | None = None
    sleeve_poisson_ratio: float | None = None

    def __post_init__(self):
        if self.kind not in ("inner", "outer"):
            raise InputError("kind", f"must be 'inner' or 'outer', got {self.kind!r}", "give the ring kind")
        for name in ("seat_radius", "land_radius", "groove_bottom_radius", "groove_radius", "half_width"):
            v = getattr(self, name)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                raise InputError(name, f"must be a positive length, got {v!r}", "give a length in metres")
        sgn = self.sign
        if self.sleeve_radius is not None:
            v = self.sleeve_radius
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0
                    and sgn * (self.seat_radius - v) > 0):
                raise InputError("sleeve_radius", f"{v!r} m is not beyond the seat ({self.kind} ring seat "
                                 f"radius {self.seat_radius!r} m)", "give the shaft bore radius (inner ring, smaller "
                                 "than the bore) or the housing outside radius (outer ring), or None")
        # inner: seat < groove bottom < land; outer: seat > groove bottom > land
        if not (sgn * (self.groove_bottom_radius - self.seat_radius) > 0
                and sgn * (self.land_radius - self.groove_bottom_radius) > 0):
            raise InputError("seat_radius", "the seat, groove bottom and land radii are not ordered as in a "
                             f"{self.kind} ring", "check bore/outside diameter, pitch and ball diameters")
        if sgn * (self.land_radius - self.groove_bottom_radius) >= self.groove_radius:
            raise InputError("land_radius", "the shoulder is higher than the groove radius",
                             "use a smaller shoulder fraction")
        if self.groove_radius * math.sin(self.contact_angle) >= self.groove_edge_z:
            raise InputError("contact_angle", "the nominal contact point lies beyond the groove edge",
                             "use a higher shoulder or a smaller contact angle")

    @property
    def sign(self) -> float:
        """+1 for the inner ring (material below the raceway), −1 for the outer ring."""
        return 1.0 if self.kind == "inner" else -1.0

    @property
    def groove_centre(self) -> tuple[float, float]:
        """(r, z) of the groove-curvature centre [m]."""
        return self.groove_bottom_radius + self.sign * self.groove_radius, 0.0

    @property
    def groove_edge_z(self) -> float:
        """|z| where the groove meets the lands [m]."""
        h = abs(self.land_radius - self.groove_bottom_radius)
        rg = self.groove_radius
        return math.sqrt(rg * rg - (rg - h) ** 2)

    def surface_radius(self, z: np.ndarray) -> np.ndarray:
        """Radius of the raceway side of the section at axial position z [m]."""
        z = np.asarray(z, dtype=float)
        rc, _ = self.groove_centre
        rg = self.groove_radius
        inside = np.abs(z) < self.groove_edge_z
        groove = rc - self.sign * np.sqrt(np.maximum(rg * rg - z * z, 0.0))
        return np.where(inside, groove, self.land_radius)

    @property
    def contact_point(self) -> np.ndarray:
        """(r, z) of the nominal contact point (angle α₀ from the groove bottom, on the side of the row's load
        path: −z on the inner ring, +z on the outer ring) [m]."""
        rc, _ = self.groove_centre
        a = self.contact_angle
        rg = self.groove_radius
        return np.array([rc - self.sign * rg * math.cos(a), -self.sign * rg * math.sin(a)])

    @property
    def inward_normal(self) -> np.ndarray:
        """Unit vector (r, z) at the contact point pointing into the ring material (the direction in which the
        ball pushes this ring) [-]."""
        a = self.contact_angle
        return -self.sign * np.array([math.cos(a), math.sin(a)])

    @property
    def support_face_z(self) -> float:
        """z of the face that carries the ring's axial reaction: the face on the side the ball load pushes
        (−B/2 for the inner ring, +B/2 for the outer ring) [m]."""
        return -self.sign * self.half_width

    @property
    def wall(self) -> float:
        """Wall thickness between groove bottom and seat [m]."""
        return abs(self.groove_bottom_radius - self.seat_radius)

    # ---- the interface of :func:`section_grid` (shared with the several-groove section of .shared) -----------
    @property
    def z_faces(self) -> tuple[float, float]:
        """(z of face_minus, z of face_plus) [m]."""
        return -self.half_width, self.half_width

    @property
    def contact_zs(self) -> tuple[float, ...]:
        """z of the contact point(s) [m]."""
        return (float(self.contact_point[1]),)

    @property
    def groove_edges(self) -> tuple[float, ...]:
        """z of the groove edges [m]."""
        ze = self.groove_edge_z
        return -ze, ze

    @property
    def depth(self) -> float:
        """Wall plus shoulder height (seat to land) [m]."""
        return self.wall + abs(self.land_radius - self.groove_bottom_radius)


def estimate_sections(bearing, shoulder_fraction: float = 0.25, shaft_bore_fraction: float | None = 0.5,
                      housing_od_factor: float | None = 1.5, housing=None,
                      shaft=None) -> tuple[RingSection, RingSection]:
    """(inner, outer) :class:`RingSection` of a single-row ``bearing`` from its bore, outside diameter and width
    (see the module docstring for the estimate) [m].  ``shaft_bore_fraction`` (shaft bore / d) and
    ``housing_od_factor`` (housing outside diameter / D) size the seat sleeves; None gives a rigid seat.
    ``housing`` / ``shaft`` (:class:`bearingsim.rings.spec.Sleeve`, e.g. from the bearing file's ``[rings]``
    table) replace the fraction of that side: absolute diameter (a shaft bore of 0 is a solid shaft,
    :data:`bearingsim.rings.spec.SOLID_SHAFT_BORE_FRACTION`), material, or a rigid seat.
    InputError when the boundary dimensions are unknown."""
    for name in ("bore", "outside_diameter", "width"):
        if not getattr(bearing, name, 0.0) > 0:
            raise InputError(name, "is needed for the elastic-ring model (the ring sections are estimated from the "
                             "boundary dimensions)", f"give {name} in the bearing file")
    if not 0.05 <= shoulder_fraction <= 0.45:
        raise InputError("shoulder_fraction", f"{shoulder_fraction!r} is not a plausible shoulder height / D_w",
                         "use 0.15–0.35 (default 0.25)")
    dw = bearing.ball_diameter
    dm = bearing.pitch_diameter
    alpha = bearing.contact_angle if bearing.kind == "angular_contact" else 0.0
    h = shoulder_fraction * dw
    rbi = 0.5 * (dm - dw)
    rbo = 0.5 * (dm + dw)
    if shaft_bore_fraction is not None and not 0.05 <= shaft_bore_fraction <= 0.9:
        raise InputError("shaft_bore_fraction", f"{shaft_bore_fraction!r} is not a shaft bore / bearing bore",
                         "use 0.05–0.9, or None for a rigid seat")
    if housing_od_factor is not None and not 1.1 <= housing_od_factor <= 4.0:
        raise InputError("housing_od_factor", f"{housing_od_factor!r} is not a housing / bearing outside diameter",
                         "use 1.1–4, or None for a rigid seat")
    si = None if shaft_bore_fraction is None else 0.5 * bearing.bore * shaft_bore_fraction
    so = None if housing_od_factor is None else 0.5 * bearing.outside_diameter * housing_od_factor
    si, ei, nui = _sleeve(shaft, si, 0.5 * bearing.bore)
    so, eo, nuo = _sleeve(housing, so, 0.5 * bearing.outside_diameter)
    inner = RingSection("inner", 0.5 * bearing.bore, rbi + h, rbi, bearing.inner_conformity * dw,
                        0.5 * bearing.width, alpha, si, ei, nui)
    outer = RingSection("outer", 0.5 * bearing.outside_diameter, rbo - h, rbo, bearing.outer_conformity * dw,
                        0.5 * bearing.width, alpha, so, eo, nuo)
    return inner, outer


def _sleeve(sleeve, radius, seat_radius):
    """(sleeve radius or None, E or None, ν or None) [m, Pa] of a :class:`bearingsim.rings.spec.Sleeve` (None:
    ``radius`` from the fractions, the ring's material)."""
    if sleeve is None:
        return radius, None, None
    if sleeve.rigid:
        return None, None, None
    from .spec import SOLID_SHAFT_BORE_FRACTION

    r = 0.5 * sleeve.diameter if sleeve.diameter > 0 else SOLID_SHAFT_BORE_FRACTION * seat_radius
    return r, sleeve.youngs_modulus, sleeve.poisson_ratio


def _graded(a: float, b: float, focus: float, h_min: float, n: int) -> np.ndarray:
    """n+1 points on [a, b], spacing ≈ h_min at ``focus`` growing geometrically (ratio ≤ 1.35) away from it."""
    pts = [focus]
    for direction, end in ((-1.0, a), (1.0, b)):
        x, h = focus, h_min
        side = []
        while direction * (end - x) > 1.5 * h:
            x += direction * h
            side.append(x)
            h = min(h * 1.35, abs(end - a + b - a) / max(n, 1))
        side.append(end)
        pts = (side[::-1] + pts) if direction < 0 else (pts + side)
    return np.unique(np.round(np.array(pts, dtype=float), 15))


def section_grid(section, h_contact: float, n_through: int = 8, n_axial: int = 16, n_sleeve: int = 6):
    """The structured grid of :func:`mesh_section`: (t values, z values [m], r(t, z) [m]) with t ∈ [0, 1] from the
    seat to the raceway in the ring and t ∈ [−1, 0) in the seat sleeve (if any).  ``section`` is a
    :class:`RingSection` or a several-groove :class:`bearingsim.rings.shared.SharedSection` (anything with
    ``z_faces``, ``contact_zs``, ``groove_edges``, ``depth``, ``wall``, ``surface_radius``, ``seat_radius``,
    ``sleeve_radius``): the axial nodes are graded towards every contact point (one grading per stretch between
    the midpoints of neighbouring contact points)."""
    z0, z1 = section.z_faces
    foci = sorted(section.contact_zs)
    cuts = [z0] + [0.5 * (a + b) for a, b in zip(foci[:-1], foci[1:])] + [z1]
    parts = []
    for k, zc in enumerate(foci):
        a, b = cuts[k], cuts[k + 1]
        n = n_axial if len(foci) == 1 else max(2, int(round(n_axial * (b - a) / (z1 - z0))))
        parts.append(_graded(a, b, zc, h_contact, n))
    zs = np.unique(np.concatenate(parts)) if len(parts) > 1 else parts[0]
    edges = list(section.groove_edges)
    zs = np.unique(np.concatenate([zs, edges]))
    # merge nodes closer than h_contact/3 to a groove edge onto the edge
    keep = np.ones(len(zs), bool)
    for e in edges:
        close = (np.abs(zs - e) < h_contact / 3) & (zs != e)
        keep &= ~close
    zs = zs[keep]
    depth = section.depth
    t = _graded(0.0, 1.0, 1.0, h_contact / depth, n_through)
    if section.sleeve_radius is not None:
        w = abs(section.seat_radius - section.sleeve_radius)
        first = min(2.0 * section.wall / max(n_through, 1), w / n_sleeve)
        ratio = 1.0
        if n_sleeve > 1 and first * n_sleeve < w:  # geometric growth: first layer ≈ the ring's outer layers
            from scipy.optimize import brentq

            ratio = brentq(lambda q: first * (q ** n_sleeve - 1.0) / (q - 1.0) - w, 1.0 + 1e-9, 10.0)
        steps = first * ratio ** np.arange(n_sleeve)
        ts = -np.cumsum(steps[::-1])[::-1] / w  # in [−1, 0)
        ts[0] = -1.0
        t = np.concatenate([ts, t])
    far = section.sleeve_radius if section.sleeve_radius is not None else section.seat_radius

    def radius(tt, zz):
        rsurf = section.surface_radius(zz)
        return np.where(tt >= 0, section.seat_radius + tt * (rsurf - section.seat_radius),
                        section.seat_radius - tt * (far - section.seat_radius))

    return t, zs, radius


def mesh_section(section, h_contact: float, n_through: int = 8, n_axial: int = 16, n_sleeve: int = 6):
    """Structured quadrilateral mesh (skfem ``MeshQuad``) of ``section`` (and its seat sleeve) in (r, z) [m].

    Nodes: axial positions graded from ``h_contact`` at the contact point(s) (and including the groove edges) to
    about B/n_axial; through the wall ``n_through`` layers graded from ``h_contact`` at the raceway; the sleeve
    (if any) ``n_sleeve`` layers growing away from the seat.  Each axial line of nodes runs straight from the
    seat to the raceway surface (the surface is followed at the nodes).  Boundaries named ``seat`` (the
    rigidly held surface: the sleeve's far radius, or the ring's seat without a sleeve), ``raceway``,
    ``face_minus``, ``face_plus``."""
    from skfem import MeshQuad

    t, zs, radius = section_grid(section, h_contact, n_through, n_axial, n_sleeve)
    z0, z1 = section.z_faces
    hw = 0.5 * (z1 - z0)
    far = section.sleeve_radius if section.sleeve_radius is not None else section.seat_radius
    mesh = MeshQuad.init_tensor(t, zs)
    tt, zz = mesh.p
    mesh = MeshQuad(np.vstack([radius(tt, zz), zz]), mesh.t)
    tol = 1e-9 * hw
    return mesh.with_boundaries({
        "seat": lambda x: np.abs(x[0] - far) < tol,
        "face_minus": lambda x: np.abs(x[1] - z0) < tol,
        "face_plus": lambda x: np.abs(x[1] - z1) < tol,
        "raceway": lambda x: (np.abs(x[0] - far) >= tol) & (np.abs(x[1] - z0) >= tol) & (np.abs(x[1] - z1) >= tol),
    })


def mesh_rectangle(r_in: float, r_out: float, half_width: float, n_r: int, n_z: int):
    """Uniform quadrilateral mesh of the rectangle [r_in, r_out] × [−half_width, half_width] with boundaries
    ``inner``, ``outer``, ``face_minus``, ``face_plus`` (thin rings and sleeves of the closed-form checks) [m]."""
    from skfem import MeshQuad

    if not (0 < r_in < r_out and half_width > 0 and n_r >= 1 and n_z >= 1):
        raise InputError("mesh", "need 0 < r_in < r_out, half_width > 0 and at least one element each way",
                         "check the dimensions")
    mesh = MeshQuad.init_tensor(np.linspace(r_in, r_out, n_r + 1), np.linspace(-half_width, half_width, n_z + 1))
    tol = 1e-9 * (r_out - r_in)
    return mesh.with_boundaries({
        "inner": lambda x: np.abs(x[0] - r_in) < tol,
        "outer": lambda x: np.abs(x[0] - r_out) < tol,
        "face_minus": lambda x: np.abs(x[1] + half_width) < tol,
        "face_plus": lambda x: np.abs(x[1] - half_width) < tol,
    })
