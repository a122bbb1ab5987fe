"""Inputs of a shaft system: sections, supports, loads, masses, and the finite-element mesh.

Frame and units (architecture.md): x is the shaft axis (positions [m] along it), nodal DOF order
[x, y, z, γy, γz] (the bearing stiffness order) with γz = dy/dx and γy = −dz/dx (right-handed small rotations),
plain SI floats: lengths [m], forces [N], moments [N·m], stiffnesses [N/m, N/rad, N·m/m, N·m/rad],
masses [kg], inertias [kg·m²], speeds [rad/s].  Every class is a frozen dataclass whose ``__post_init__``
refuses impossible input with an :class:`~bearingsim.errors.InputError` naming the field and the fix.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field

import numpy as np

from ..beam import circular_section, cowper_circular
from ..errors import InputError
from ..geometry import ROTATING_RINGS, with_rotating_ring
from ..materials import Material, get_material

#: names of the five nodal DOF, in order
NODE_DOF = ("x", "y", "z", "gamma_y", "gamma_z")
#: two positions closer than this are one point of the mesh [m]
POSITION_TOL = 1e-9


def _real(value, name: str, fix: str = "give a finite number in SI units") -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise InputError(name, f"must be a real number, got {type(value).__name__} {value!r}", fix)
    v = float(value)
    if not math.isfinite(v):
        raise InputError(name, f"must be finite, got {value!r}", fix)
    return v


def _vector(value, n: int, name: str, fix: str) -> np.ndarray:
    try:
        v = np.array(value, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise InputError(name, f"must be {n} numbers, got {value!r}", fix) from None
    if v.shape != (n,) or not np.all(np.isfinite(v)):
        raise InputError(name, f"must be {n} finite numbers, got {value!r}", fix)
    return v


def stiffness_matrix(value, name: str) -> np.ndarray:
    """A 5×5 support stiffness [N/m, N/rad, N·m/m, N·m/rad] from 5 diagonal terms or a full symmetric 5×5;
    InputError naming ``name`` when it is neither, not finite, not symmetric or not positive semi-definite."""
    fix = "give 5 diagonal terms (kx, ky, kz, k_γy, k_γz) or a symmetric 5×5 in SI units"
    try:
        k = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise InputError(name, f"must be numbers, got {value!r}", fix) from None
    if k.shape == (5,):
        k = np.diag(k)
    if k.shape != (5, 5) or not np.all(np.isfinite(k)):
        raise InputError(name, f"must be 5 or 5×5 finite numbers, got shape {k.shape}", fix)
    scale = max(float(np.max(np.abs(k))), 1e-300)
    if np.max(np.abs(k - k.T)) > 1e-9 * scale:
        raise InputError(name, "must be symmetric", fix)
    if np.min(np.linalg.eigvalsh(k)) < -1e-9 * scale:
        raise InputError(name, "must be positive semi-definite (a spring stores energy)", fix)
    return k


def _material(value, name: str) -> Material:
    if isinstance(value, Material):
        return value
    return get_material(value, name)


@dataclass(frozen=True)
class Section:
    """A cylindrical length of the shaft (sections follow each other from :attr:`ShaftSystem.start`).

    length : float  [m] > 0
    outer_diameter : float  [m] > 0
    inner_diameter : float  [m], 0 ≤ d_i < d_o (0: solid)
    material : str or Material  a name of :data:`bearingsim.materials.LIBRARY` (default ``"bearing_steel"``)
    """

    length: float
    outer_diameter: float
    inner_diameter: float = 0.0
    material: object = "bearing_steel"

    def __post_init__(self):
        for key in ("length", "outer_diameter", "inner_diameter"):
            object.__setattr__(self, key, _real(getattr(self, key), f"section.{key}"))
        if self.length <= 0:
            raise InputError("section.length", f"must be positive, got {self.length!r} m", 'e.g. "120 mm"')
        if self.outer_diameter <= 0:
            raise InputError("section.outer_diameter", f"must be positive, got {self.outer_diameter!r} m",
                             'e.g. "55 mm"')
        if not 0.0 <= self.inner_diameter < self.outer_diameter:
            raise InputError("section.inner_diameter", f"must lie in [0, outer_diameter = {self.outer_diameter!r} m),"
                             f" got {self.inner_diameter!r} m", "give 0 for a solid shaft or a bore below the outer"
                             " diameter")
        object.__setattr__(self, "material", _material(self.material, "section.material"))

    @property
    def area(self) -> float:
        """A [m²]."""
        return circular_section(self.outer_diameter, self.inner_diameter)[0]

    @property
    def second_moment(self) -> float:
        """I = I_y = I_z [m⁴]."""
        return circular_section(self.outer_diameter, self.inner_diameter)[1]

    @property
    def shear_coefficient(self) -> float:
        """κ of the solid or hollow circle (Cowper 1966, :func:`bearingsim.beam.cowper_circular`) [-]."""
        return cowper_circular(self.material.poisson_ratio, self.inner_diameter / self.outer_diameter)

    @property
    def shear_modulus(self) -> float:
        """G = E / (2(1 + ν)) [Pa]."""
        return self.material.youngs_modulus / (2.0 * (1.0 + self.material.poisson_ratio))


@dataclass(frozen=True)
class BearingSupport:
    """A ball bearing between the shaft (its inner ring) and the housing (its outer ring).

    name : str
    position : float  [m]  axial position of the bearing's load point (a bearing system's ``load_point``)
    bearing : BallBearing or BearingSystem  anything :func:`bearingsim.load_bearing` returns
    orientation : +1 or −1  +1: the bearing as defined (its contact angle as in its file); −1: mirrored in x
        (x → −x, γy → −γy, γz → −γz: a single angular contact row taking thrust the other way)
    rotating_ring : ``"inner"`` (default: the shaft turns) or ``"outer"`` (the housing turns at the system's
        speed and the shaft stands; the bearing is solved with its outer ring turning)
    control : raceway control of the Jones–Harris model, ``"outer"`` (default), ``"inner"`` or ``"auto"``
    housing_stiffness : None (rigid housing, default) or 5 / 5×5 stiffness of the outer ring's seat to ground
    preload_offset : float  [m]  axial displacement imposed on the outer ring (position preload: spacer or nut)
    preload_force : float or None  [N]  constant axial force on the outer ring along +x, the outer ring free to
        slide axially (spring preload); None (default) holds it at ``preload_offset``
    """

    name: str
    position: float
    bearing: object
    orientation: int = 1
    rotating_ring: str = "inner"
    control: str = "outer"
    housing_stiffness: object = None
    preload_offset: float = 0.0
    preload_force: float | None = None

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise InputError("support.name", f"must be a non-empty string, got {self.name!r}", 'e.g. "front"')
        object.__setattr__(self, "position", _real(self.position, f"{self.name}.position"))
        if not hasattr(self.bearing, "row_vectors"):
            raise InputError(f"{self.name}.bearing", f"expected a bearing, got {type(self.bearing).__name__}",
                             "load one with bearingsim.load_bearing(name)")
        if self.orientation not in (1, -1) or isinstance(self.orientation, bool):
            raise InputError(f"{self.name}.orientation", f"must be +1 or -1, got {self.orientation!r}",
                             "+1: the contact angle as in the bearing file, -1: mirrored")
        if self.rotating_ring not in ROTATING_RINGS:
            raise InputError(f"{self.name}.rotating_ring", f"must be inner or outer, got {self.rotating_ring!r}",
                             'use "inner" (shaft turns) or "outer" (housing turns)')
        # the bearing turns the same ring: its ball speeds, centrifugal and gyroscopic terms follow
        object.__setattr__(self, "bearing", with_rotating_ring(self.bearing, self.rotating_ring))
        if self.control not in ("outer", "inner", "auto"):
            raise InputError(f"{self.name}.control", f"unknown raceway control {self.control!r}",
                             "use outer, inner or auto")
        if self.housing_stiffness is not None:
            object.__setattr__(self, "housing_stiffness",
                               stiffness_matrix(self.housing_stiffness, f"{self.name}.housing_stiffness"))
        object.__setattr__(self, "preload_offset", _real(self.preload_offset, f"{self.name}.preload_offset"))
        if self.preload_force is not None:
            object.__setattr__(self, "preload_force", _real(self.preload_force, f"{self.name}.preload_force"))
            if self.preload_offset != 0.0:
                raise InputError(f"{self.name}.preload_offset", "a spring preload lets the outer ring slide: an "
                                 "offset means nothing there", "give preload_force or preload_offset, not both")

    @property
    def transform(self) -> np.ndarray:
        """T = diag(s, 1, 1, s, s), s = orientation: bearing-frame vector = T · shaft-frame vector."""
        s = float(self.orientation)
        return np.diag([s, 1.0, 1.0, s, s])


@dataclass(frozen=True)
class SpringSupport:
    """A linear support (a plain bearing, a roller bearing's catalogue stiffness, a coupling) to the housing.

    name : str;  position : float [m]
    stiffness : 5 diagonal terms or a symmetric 5×5 [N/m, N/rad, N·m/m, N·m/rad], order [x, y, z, γy, γz]
    housing_stiffness : None (rigid housing) or 5 / 5×5 in series between the spring and ground
    """

    name: str
    position: float
    stiffness: object
    housing_stiffness: object = None

    def __post_init__(self):
        if not isinstance(self.name, str) or not self.name:
            raise InputError("support.name", f"must be a non-empty string, got {self.name!r}", 'e.g. "rear"')
        object.__setattr__(self, "position", _real(self.position, f"{self.name}.position"))
        object.__setattr__(self, "stiffness", stiffness_matrix(self.stiffness, f"{self.name}.stiffness"))
        if self.housing_stiffness is not None:
            object.__setattr__(self, "housing_stiffness",
                               stiffness_matrix(self.housing_stiffness, f"{self.name}.housing_stiffness"))


@dataclass(frozen=True)
class PointLoad:
    """A force and moment on the shaft at ``position`` [m] (a tool-tip force, a coupling force).

    force : (Fx, Fy, Fz) [N];  moment : (My, Mz) [N·m];  name : str
    """

    position: float
    force: object = (0.0, 0.0, 0.0)
    moment: object = (0.0, 0.0)
    name: str = "load"

    def __post_init__(self):
        object.__setattr__(self, "position", _real(self.position, f"{self.name}.position"))
        object.__setattr__(self, "force", _vector(self.force, 3, f"{self.name}.force", "give (Fx, Fy, Fz) [N]"))
        object.__setattr__(self, "moment", _vector(self.moment, 2, f"{self.name}.moment", "give (My, Mz) [N·m]"))

    def vector(self) -> np.ndarray:
        """[Fx, Fy, Fz, My, Mz] [N, N·m]."""
        return np.r_[self.force, self.moment]


@dataclass(frozen=True)
class DistributedLoad:
    """A uniform load per length (qx, qy, qz) [N/m] from ``start`` to ``end`` [m] (consistent nodal loads)."""

    start: float
    end: float
    intensity: object
    name: str = "distributed"

    def __post_init__(self):
        object.__setattr__(self, "start", _real(self.start, f"{self.name}.start"))
        object.__setattr__(self, "end", _real(self.end, f"{self.name}.end"))
        if self.end <= self.start:
            raise InputError(f"{self.name}.end", f"must lie past start = {self.start!r} m, got {self.end!r} m",
                             "give start < end")
        object.__setattr__(self, "intensity", _vector(self.intensity, 3, f"{self.name}.intensity",
                                                      "give (qx, qy, qz) [N/m]"))


@dataclass(frozen=True)
class Gravity:
    """The weight of the shaft and its point masses: acceleration vector (gx, gy, gz) [m/s²] in the shaft frame
    (default (0, −9.80665, 0): gravity along −y)."""

    acceleration: object = (0.0, -9.80665, 0.0)
    name: str = "gravity"

    def __post_init__(self):
        object.__setattr__(self, "acceleration", _vector(self.acceleration, 3, "gravity.acceleration",
                                                         "give (gx, gy, gz) [m/s^2]"))


@dataclass(frozen=True)
class HelicalGear:
    """The mesh force on a helical (or spur, helix 0) gear on the shaft at ``position`` [m].

    torque : float  [N·m]  torque of the mesh force about +x on this gear (nonzero; the sign gives the sense)
    pitch_diameter : float  [m] > 0
    normal_pressure_angle : float  [rad] in (0, 45°)  (default 20°)
    helix_angle : float  [rad] in [0, 45°)
    hand : ``"right"`` or ``"left"`` (of the helix: a right-hand tooth advances along +x turning about +x)
    mesh_angle : float  [rad]  azimuth of the pitch point around the shaft (0 on +y, towards +z)

    Forces (Shigley's Mechanical Engineering Design, 10th ed., eqs. 13-39, 13-40): F_t = 2T/d tangential,
    F_r = F_t tan α_n / cos β towards the shaft axis, F_a = F_t tan β along the axis; at the pitch point
    r = (d/2) e_r the axial force adds the moment r × F_a e_x.  See :meth:`vector`.
    """

    position: float
    torque: float
    pitch_diameter: float
    normal_pressure_angle: float = math.radians(20.0)
    helix_angle: float = 0.0
    hand: str = "right"
    mesh_angle: float = 0.0
    name: str = "gear"

    def __post_init__(self):
        for key in ("position", "torque", "pitch_diameter", "normal_pressure_angle", "helix_angle", "mesh_angle"):
            object.__setattr__(self, key, _real(getattr(self, key), f"{self.name}.{key}"))
        if self.torque == 0.0:
            raise InputError(f"{self.name}.torque", "a gear without torque transmits no force",
                             'give the transmitted torque, e.g. "250 N*m"')
        if self.pitch_diameter <= 0:
            raise InputError(f"{self.name}.pitch_diameter", f"must be positive, got {self.pitch_diameter!r} m",
                             'e.g. "120 mm"')
        if not 0.0 < self.normal_pressure_angle < math.radians(45.0):
            raise InputError(f"{self.name}.normal_pressure_angle", f"must lie in (0, 45°), got "
                             f"{math.degrees(self.normal_pressure_angle):.4g}°", 'e.g. "20 deg"')
        if not 0.0 <= self.helix_angle < math.radians(45.0):
            raise InputError(f"{self.name}.helix_angle", f"must lie in [0, 45°), got "
                             f"{math.degrees(self.helix_angle):.4g}°", 'e.g. "15 deg" (0 for a spur gear)')
        if self.hand not in ("right", "left"):
            raise InputError(f"{self.name}.hand", f"must be right or left, got {self.hand!r}", 'use "right" or "left"')

    def components(self) -> tuple[float, float, float]:
        """(F_t, F_r, F_a) [N]: F_t = 2T/d, F_r = |F_t| tan α_n / cos β, F_a = |F_t| tan β (Shigley eqs.
        13-39, 13-40); F_t carries the sign of the torque."""
        ft = 2.0 * self.torque / self.pitch_diameter
        return (ft, abs(ft) * math.tan(self.normal_pressure_angle) / math.cos(self.helix_angle),
                abs(ft) * math.tan(self.helix_angle))

    def vector(self) -> np.ndarray:
        """[Fx, Fy, Fz, My, Mz] [N, N·m] on the shaft at the gear's node.

        Radial unit e_r = (0, cos θ, sin θ), tangential e_t = e_x × e_r = (0, −sin θ, cos θ), θ = mesh_angle.
        The tooth line of a right-hand helix is cos β e_x + sin β e_t, and the tooth force is normal to it:
        F = F_t e_t − h F_t tan β e_x − F_r e_r (h = +1 right, −1 left hand), so that the torque r × F · e_x = T.
        Its axial part at the pitch radius gives M = (d/2) e_r × F_x e_x = (d/2) F_x (0, sin θ, −cos θ).
        """
        ft, fr, _ = self.components()
        h = 1.0 if self.hand == "right" else -1.0
        c, s = math.cos(self.mesh_angle), math.sin(self.mesh_angle)
        fx = -h * ft * math.tan(self.helix_angle)
        r = 0.5 * self.pitch_diameter
        return np.array([fx, -ft * s - fr * c, ft * c - fr * s, r * fx * s, -r * fx * c])


@dataclass(frozen=True)
class PointMass:
    """A rigid body on the shaft at ``position`` [m] (tool holder, chuck, gear, wheel): mass [kg], polar
    inertia about x ``polar_inertia`` [kg·m²] and diametral inertia ``diametral_inertia`` [kg·m²]."""

    position: float
    mass: float
    polar_inertia: float = 0.0
    diametral_inertia: float = 0.0
    name: str = "mass"

    def __post_init__(self):
        for key in ("position", "mass", "polar_inertia", "diametral_inertia"):
            object.__setattr__(self, key, _real(getattr(self, key), f"{self.name}.{key}"))
        for key in ("mass", "polar_inertia", "diametral_inertia"):
            if getattr(self, key) < 0:
                raise InputError(f"{self.name}.{key}", f"must not be negative, got {getattr(self, key)!r}",
                                 "give a mass [kg] or inertia [kg*m^2] ≥ 0")


LOAD_TYPES = (PointLoad, DistributedLoad, Gravity, HelicalGear)
SUPPORT_TYPES = (BearingSupport, SpringSupport)


@dataclass(frozen=True)
class Mesh:
    """Nodes and elements of a shaft: ``nodes`` float[n] axial positions [m], ``element_section`` int[n − 1] the
    section of each element (element e joins nodes e and e + 1)."""

    nodes: np.ndarray
    element_section: np.ndarray

    @property
    def n_nodes(self) -> int:
        return len(self.nodes)

    @property
    def n_dof(self) -> int:
        return 5 * len(self.nodes)

    def node_at(self, position: float, field_name: str = "position") -> int:
        """Index of the node at ``position`` [m]; InputError naming ``field_name`` when there is none."""
        i = int(np.argmin(np.abs(self.nodes - position)))
        if abs(self.nodes[i] - position) > POSITION_TOL:
            raise InputError(field_name, f"no node at {position!r} m", "give a position of a support, load, mass or "
                             "section end (or add a PointLoad of zero there)")
        return i


@dataclass(frozen=True)
class ShaftSystem:
    """A shaft on its supports, with its loads and masses, at a speed.

    sections : tuple[Section, ...]  from ``start`` [m] along +x, end to end
    supports : tuple[BearingSupport | SpringSupport, ...]  on the shaft, at distinct positions
    loads : tuple[PointLoad | DistributedLoad | Gravity | HelicalGear, ...]
    masses : tuple[PointMass, ...]
    speed : float  [rad/s]  shaft speed (the rotating ring's speed relative to the other)
    elements : int  target number of beam elements (the mesh also has a node at every section end, support,
        point load, gear, mass and distributed-load end)
    shear : bool  Timoshenko (True, default) or Euler–Bernoulli (False) elements
    start : float  [m]  axial position of the shaft's first end
    name : str
    """

    sections: tuple
    supports: tuple
    loads: tuple = ()
    masses: tuple = ()
    speed: float = 0.0
    elements: int = 40
    shear: bool = True
    start: float = 0.0
    name: str = "shaft"
    mesh: Mesh = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        for key in ("sections", "supports", "loads", "masses"):
            v = getattr(self, key)
            if not isinstance(v, list | tuple):
                v = (v,)
            object.__setattr__(self, key, tuple(v))
        if not self.sections:
            raise InputError("sections", "a shaft needs at least one section", "add a Section(length, outer_diameter)")
        for s in self.sections:
            if not isinstance(s, Section):
                raise InputError("sections", f"expected Section, got {type(s).__name__}", "use Section(...)")
        object.__setattr__(self, "speed", _real(self.speed, "speed", "give the shaft speed in rad/s"))
        object.__setattr__(self, "start", _real(self.start, "start"))
        if isinstance(self.elements, bool) or not isinstance(self.elements, numbers.Integral) or self.elements < 1:
            raise InputError("elements", f"must be a positive integer, got {self.elements!r}", "e.g. 40")
        names = set()
        for sup in self.supports:
            if not isinstance(sup, SUPPORT_TYPES):
                raise InputError("supports", f"expected BearingSupport or SpringSupport, got {type(sup).__name__}",
                                 "use BearingSupport(...) or SpringSupport(...)")
            if sup.name in names:
                raise InputError(f"{sup.name}.name", "two supports have this name", "give each support its own name")
            names.add(sup.name)
            self._on_shaft(sup.position, f"{sup.name}.position")
        pos = sorted((s.position, s.name) for s in self.supports)
        for (p0, n0), (p1, n1) in zip(pos, pos[1:], strict=False):
            if p1 - p0 <= POSITION_TOL:
                raise InputError(f"{n1}.position", f"supports {n0!r} and {n1!r} are both at {p1!r} m",
                                 "give each support its own position (a set of rows at one place is one bearing)")
        for ld in self.loads:
            if not isinstance(ld, LOAD_TYPES):
                raise InputError("loads", f"expected a load, got {type(ld).__name__}",
                                 "use PointLoad, DistributedLoad, Gravity or HelicalGear")
            if isinstance(ld, DistributedLoad):
                self._on_shaft(ld.start, f"{ld.name}.start")
                self._on_shaft(ld.end, f"{ld.name}.end")
            elif not isinstance(ld, Gravity):
                self._on_shaft(ld.position, f"{ld.name}.position")
        for m in self.masses:
            if not isinstance(m, PointMass):
                raise InputError("masses", f"expected PointMass, got {type(m).__name__}", "use PointMass(...)")
            self._on_shaft(m.position, f"{m.name}.position")
        self._check_rigid_body()
        object.__setattr__(self, "mesh", build_mesh(self))

    @property
    def span(self) -> tuple[float, float]:
        """(first end, last end) of the shaft [m]."""
        return self.start, self.start + sum(s.length for s in self.sections)

    @property
    def section_ends(self) -> np.ndarray:
        """float[n_sections + 1] axial positions of the section ends [m]."""
        return self.start + np.concatenate([[0.0], np.cumsum([s.length for s in self.sections])])

    def _on_shaft(self, x: float, name: str) -> None:
        lo, hi = self.span
        if not lo - POSITION_TOL <= x <= hi + POSITION_TOL:
            raise InputError(name, f"{x!r} m is off the shaft ({lo:.6g} … {hi:.6g} m)",
                             "give a position between the shaft's ends")

    def _check_rigid_body(self) -> None:
        """InputError when the supports leave a rigid-body motion free: no support holds the shaft axially, or
        the radial supports are fewer than two positions without one that holds the tilt.  A ball bearing holds
        axially and radially; a set or double-row unit (several rows) also holds the tilt; a spring holds the
        directions of its nonzero diagonal terms.  Rotation about x (torsion) is not a DOF of the model."""
        if not self.supports:
            raise InputError("supports", "the shaft has no support", "add a BearingSupport or SpringSupport")
        axial = radial_y = radial_z = 0
        tilt = False
        rad_pos = set()
        for s in self.supports:
            if isinstance(s, BearingSupport):
                axial += 1
                radial_y += 1
                radial_z += 1
                rad_pos.add(s.position)
                tilt = tilt or s.bearing.row_vectors().shape[0] > 1
            else:
                d = np.diag(s.stiffness) > 0
                axial += bool(d[0])
                radial_y += bool(d[1])
                radial_z += bool(d[2])
                if d[1] and d[2]:
                    rad_pos.add(s.position)
                tilt = tilt or bool(d[3] and d[4])
        if axial == 0:
            raise InputError("supports", "no support holds the shaft axially: it can move along x as a rigid body",
                             "add a bearing or give a spring support an axial stiffness")
        if min(radial_y, radial_z) == 0 or (len(rad_pos) < 2 and not tilt):
            raise InputError("supports", "a single radial support lets the shaft tilt as a rigid body",
                             "add a second radial support, a set of rows, or a spring with tilt stiffness")


def build_mesh(system: ShaftSystem) -> Mesh:
    """Nodes at the section ends, supports, point loads, gears, masses and distributed-load ends, the intervals
    between them divided uniformly so that the element count is close to ``system.elements`` (at least one
    element per interval)."""
    keys = list(system.section_ends)
    keys += [s.position for s in system.supports]
    keys += [m.position for m in system.masses]
    for ld in system.loads:
        if isinstance(ld, DistributedLoad):
            keys += [ld.start, ld.end]
        elif not isinstance(ld, Gravity):
            keys.append(ld.position)
    keys = np.sort(np.asarray(keys, dtype=float))
    uniq = [keys[0]]
    for k in keys[1:]:
        if k - uniq[-1] > POSITION_TOL:
            uniq.append(k)
    uniq = np.asarray(uniq)
    lo, hi = system.span
    total = hi - lo
    nodes = [uniq[0]]
    for a, b in zip(uniq[:-1], uniq[1:], strict=True):
        n = max(1, int(round(system.elements * (b - a) / total)))
        nodes += list(a + (b - a) * np.arange(1, n + 1) / n)
    nodes = np.asarray(nodes)
    mids = 0.5 * (nodes[:-1] + nodes[1:])
    sec = np.searchsorted(system.section_ends, mids, side="right") - 1
    sec = np.clip(sec, 0, len(system.sections) - 1)
    return Mesh(nodes=nodes, element_section=sec.astype(int))
