"""Shaft-system files (``type = "shaft_system"``, TOML with units) → :class:`bearingsim.shafts.ShaftSystem`.

Every quantity is a string with its unit (``"55 mm"``, ``"400 N"``, ``"12000 rpm"``), parsed once here into the
SI floats of :mod:`bearingsim.shafts.model`; a bare number for a dimensional field is refused
(:func:`bearingsim.units.file_input`).  Errors name the field as the file spells it (``sections[1].length``,
``supports[0].position``, ``loads[2].torque``) with the fix.  Format::

    type = "shaft_system"
    name = "milling spindle"
    speed = "12000 rpm"               # shaft speed (the rotating ring's)
    material = "bearing_steel"        # default material of the sections (a name or a table)
    elements = 40                     # target number of beam elements (optional)
    start = "0 mm"                    # axial position of the shaft's first end (optional)
    stiffness_at = "0 mm"             # where the system stiffness is reported (default: the tool tip)

    [[sections]]                      # end to end from `start` along +x
    length = "80 mm"
    outer_diameter = "55 mm"
    inner_diameter = "20 mm"          # optional, 0 = solid
    material = "bearing_steel"        # optional

    [[supports]]                      # a ball bearing (catalogue name, path, or inline [supports.bearing] table)
    name = "front"
    position = "100 mm"               # the bearing's load point on the shaft
    bearing = "7011-15"
    orientation = 1                   # +1 as in the bearing file, -1 mirrored
    rotating_ring = "inner"           # or "outer"
    control = "outer"                 # raceway control: outer, inner or auto
    housing_stiffness = { radial = "300 N/um", axial = "200 N/um" }   # optional (default rigid)
    preload = { method = "spring", force = "300 N" }   # or { method = "position", offset = "5 um" }

    [[supports]]                      # a linear spring (roller or plain bearing, coupling)
    name = "coupling"
    position = "400 mm"
    stiffness = { radial = "50 N/um" }   # keys axial, radial, tilt, x, y, z, gamma_y, gamma_z, or matrix (5×5)

    [[loads]]                         # type: force, distributed, gravity, helical_gear, tool_tip
    type = "tool_tip"
    position = "0 mm"
    fy = "500 N"                      # fx, fy, fz [force], my, mz [moment]

    [[masses]]
    position = "0 mm"
    mass = "1.2 kg"
    polar_inertia = "0.0004 kg*m^2"
    diametral_inertia = "0.0008 kg*m^2"

Preload signs: a spring force or a position offset is given as a positive value that loads the bearing (its
outer ring pushed against the balls in the sense its orientation carries thrust); the reader turns it into the
outer ring's axial force or displacement along +x of :class:`bearingsim.shafts.BearingSupport`.
"""

from __future__ import annotations

import dataclasses
import math
import os
from pathlib import Path

from ..errors import InputError
from ..shafts import (
    BearingSupport,
    DistributedLoad,
    Gravity,
    HelicalGear,
    PointLoad,
    PointMass,
    Section,
    ShaftSystem,
    SpringSupport,
)
from ..units import file_input, parse_quantity
from .bearing import bearing_from_dict, catalog_names, load_bearing, material_from_file
from .files import read_toml

_KEYS = {"type", "name", "description", "speed", "material", "elements", "shear", "start", "stiffness_at",
         "sections", "supports", "loads", "masses", "sources"}
_SECTION_KEYS = {"length", "outer_diameter", "inner_diameter", "material"}
_BEARING_SUPPORT_KEYS = {"name", "position", "bearing", "orientation", "rotating_ring", "control",
                         "housing_stiffness", "preload"}
_SPRING_SUPPORT_KEYS = {"name", "position", "stiffness", "housing_stiffness"}
_STIFFNESS_KEYS = {"axial", "radial", "tilt", "x", "y", "z", "gamma_y", "gamma_z", "matrix"}
_LOAD_KEYS = {
    "force": {"type", "name", "position", "fx", "fy", "fz", "my", "mz"},
    "tool_tip": {"type", "name", "position", "fx", "fy", "fz", "my", "mz"},
    "distributed": {"type", "name", "start", "end", "qx", "qy", "qz"},
    "gravity": {"type", "name", "gx", "gy", "gz"},
    "helical_gear": {"type", "name", "position", "torque", "pitch_diameter", "pressure_angle", "helix_angle",
                     "hand", "mesh_angle"},
}
_MASS_KEYS = {"name", "position", "mass", "polar_inertia", "diametral_inertia"}
_PRELOAD_KEYS = {"method", "force", "offset"}

#: standard gravity [m/s²] (the default of a ``gravity`` load: along −y)
STANDARD_GRAVITY = 9.80665

#: dimension of each term of a 5×5 support stiffness: K[i, j] = dF_i/dq_j, F = (Fx, Fy, Fz, My, Mz),
#: q = (x, y, z, γy, γz): N/m, N/rad (= N), N·m/m (= N), N·m/rad (= N·m)
_K_DIMENSION = (("stiffness",) * 3 + ("force",) * 2,) * 3 + (("force",) * 3 + ("moment",) * 2,) * 2
_K_EXAMPLE = {"stiffness": "N/um", "force": "N/mrad", "moment": "N*m/mrad"}


@dataclasses.dataclass(frozen=True)
class ShaftFile:
    """A shaft-system file read into the model: ``system`` (:class:`bearingsim.shafts.ShaftSystem`, SI),
    ``stiffness_at`` [m] where the system stiffness is reported (the file's ``stiffness_at``, else the tool
    tip's position, else None), ``tool_tip`` [m] the tool tip's position or None, ``path`` the file."""

    system: object
    stiffness_at: float | None
    tool_tip: float | None
    path: str | None = None
    description: str = ""


def _table(value, field: str, example: str) -> dict:
    if not isinstance(value, dict):
        raise InputError(field, f"expected a table, got {type(value).__name__} {value!r}"[:160], example)
    return value


def _check_keys(t: dict, known: set, field: str) -> None:
    bad = sorted(set(t) - known)
    if bad:
        raise InputError(f"{field}.{bad[0]}" if field else bad[0], "unknown key",
                         f"known keys: {', '.join(sorted(known))}")


def _require(t: dict, key: str, field: str, example: str):
    if key not in t:
        raise InputError(f"{field}.{key}", "missing", f"give {key}, e.g. {key} = {example}")
    return t[key]


def _q(t: dict, key: str, dim: str, field: str, default=None):
    """``t[key]`` parsed as ``dim`` [SI], ``default`` when absent."""
    if key not in t:
        return default
    return parse_quantity(t[key], dim, f"{field}.{key}" if field else key)


def _positive(value: float, field: str, example: str) -> float:
    if not (math.isfinite(value) and value > 0):
        raise InputError(field, f"must be positive, got {value!r} (SI)", f"e.g. {example}")
    return value


def _relabel(exc: InputError, names: dict) -> InputError:
    """``exc`` with its field's first part (a support, load or mass name of the model) replaced by the file's
    spelling (``supports[0]``)."""
    head, _, rest = str(exc.field).partition(".")
    if head in names:
        return InputError(names[head] + (f".{rest}" if rest else ""), exc.problem, exc.fix)
    return exc


def _stiffness(value, field: str):
    """A support stiffness table → 5×5 [SI] (``matrix`` of 25 quantities, or diagonal keys)."""
    import numpy as np

    t = _table(value, field, '{ radial = "300 N/um", axial = "100 N/um" } or { matrix = [[...], ...] }')
    _check_keys(t, _STIFFNESS_KEYS, field)
    if "matrix" in t:
        if len(t) > 1:
            raise InputError(f"{field}.matrix", "a matrix and diagonal keys together", "give one or the other")
        m = t["matrix"]
        if not (isinstance(m, list) and len(m) == 5 and all(isinstance(r, list) and len(r) == 5 for r in m)):
            raise InputError(f"{field}.matrix", "must be 5 rows of 5 quantities (order x, y, z, gamma_y, gamma_z)",
                             'e.g. [["100 N/um", "0 N/um", ...], ...]')
        k = np.zeros((5, 5))
        for i in range(5):
            for j in range(5):
                dim = _K_DIMENSION[i][j]
                v = m[i][j]
                k[i, j] = 0.0 if v == 0 else parse_quantity(v, dim, f"{field}.matrix[{i}][{j}]")
        return k
    diag = np.zeros(5)
    for key, idx, dim in (("axial", (0,), "stiffness"), ("radial", (1, 2), "stiffness"), ("tilt", (3, 4), "moment"),
                          ("x", (0,), "stiffness"), ("y", (1,), "stiffness"), ("z", (2,), "stiffness"),
                          ("gamma_y", (3,), "moment"), ("gamma_z", (4,), "moment")):
        if key in t:
            v = parse_quantity(t[key], dim, f"{field}.{key}")
            if not (math.isfinite(v) and v >= 0):
                raise InputError(f"{field}.{key}", f"must not be negative, got {t[key]!r}",
                                 f'e.g. "{"200 N/um" if dim == "stiffness" else "500 N*m/mrad"}"')
            diag[list(idx)] = v
    if not diag.any():
        raise InputError(field, "no stiffness given", 'give e.g. radial = "300 N/um" (axial, radial, tilt, ...)')
    return np.diag(diag)


def _bearing(spec, field: str, folder: Path | None):
    """A support's bearing: catalogue name, path (relative to the shaft file's folder) or an inline table."""

    try:
        if isinstance(spec, dict):
            return bearing_from_dict(spec)
        if isinstance(spec, str):
            if spec not in catalog_names() and folder is not None and not os.path.isabs(spec):
                local = folder / spec
                if local.exists():
                    return load_bearing(str(local))
            return load_bearing(spec)
    except InputError as exc:
        f = exc.field if str(exc.field).startswith(field) else f"{field}.{exc.field}" if isinstance(spec, dict) \
            else field
        raise InputError(f, exc.problem, exc.fix) from None
    raise InputError(field, f"expected a catalogue name, a path or a table, got {spec!r}"[:160],
                     'e.g. bearing = "7011-15" or a [supports.bearing] table')


def _preload(value, field: str, orientation: int) -> tuple[float, float | None]:
    """``preload = { method = "spring", force = ... }`` or ``{ method = "position", offset = ... }`` →
    (preload_offset [m], preload_force [N] or None) of the outer ring along +x of the shaft."""
    t = _table(value, field, '{ method = "spring", force = "300 N" } or { method = "position", offset = "5 um" }')
    _check_keys(t, _PRELOAD_KEYS, field)
    method = t.get("method")
    if method not in ("spring", "position"):
        raise InputError(f"{field}.method", f"must be spring or position, got {method!r}",
                         'method = "spring" (constant force) or "position" (axial offset)')
    if method == "spring":
        if "offset" in t:
            raise InputError(f"{field}.offset", "a spring preload has a force, not an offset",
                             'remove offset or use method = "position"')
        f = parse_quantity(_require(t, "force", field, '"300 N"'), "force", f"{field}.force")
        _positive(f, f"{field}.force", '"300 N"')
        return 0.0, -orientation * f
    if "force" in t:
        raise InputError(f"{field}.force", "a position preload has an offset, not a force",
                         'remove force or use method = "spring"')
    e = parse_quantity(_require(t, "offset", field, '"5 um"'), "length", f"{field}.offset")
    if not math.isfinite(e):
        raise InputError(f"{field}.offset", f"must be finite, got {e!r}", 'e.g. "5 um"')
    return -orientation * e, None


def _orientation(t: dict, field: str) -> int:
    o = t.get("orientation", 1)
    if isinstance(o, str):
        o = {"+1": 1, "1": 1, "-1": -1}.get(o.strip(), o)
    if isinstance(o, bool) or o not in (1, -1):
        raise InputError(f"{field}.orientation", f"must be 1 or -1, got {o!r}",
                         "orientation = 1 (as in the bearing file) or -1 (mirrored)")
    return int(o)


def _support(t, i: int, folder: Path | None):

    field = f"supports[{i}]"
    t = _table(t, field, "write [[supports]] tables")
    name = t.get("name", f"support {i + 1}")
    if not isinstance(name, str) or not name.strip():
        raise InputError(f"{field}.name", f"must be a non-empty string, got {name!r}", 'e.g. name = "front"')
    if "bearing" in t and "stiffness" in t:
        raise InputError(f"{field}.stiffness", "a support is a bearing or a spring, not both",
                         "remove bearing or stiffness")
    pos = parse_quantity(_require(t, "position", field, '"100 mm"'), "length", f"{field}.position")
    hk = _stiffness(t["housing_stiffness"], f"{field}.housing_stiffness") if "housing_stiffness" in t else None
    if "stiffness" in t:
        _check_keys(t, _SPRING_SUPPORT_KEYS, field)
        return SpringSupport(name, pos, _stiffness(t["stiffness"], f"{field}.stiffness"), hk)
    if "bearing" not in t:
        raise InputError(f"{field}.bearing", "missing", 'give bearing = "7011-15" (or a path), or a spring with '
                         'stiffness = { radial = "100 N/um" }')
    _check_keys(t, _BEARING_SUPPORT_KEYS, field)
    o = _orientation(t, field)
    offset, force = _preload(t["preload"], f"{field}.preload", o) if "preload" in t else (0.0, None)
    ring = t.get("rotating_ring", "inner")
    if ring not in ("inner", "outer"):
        raise InputError(f"{field}.rotating_ring", f"must be inner or outer, got {ring!r}",
                         'rotating_ring = "inner" (the shaft turns) or "outer" (the housing turns)')
    return BearingSupport(name, pos, _bearing(t["bearing"], f"{field}.bearing", folder), o, ring,
                          str(t.get("control", "outer")), hk, offset, force)


def _load(t, i: int):

    field = f"loads[{i}]"
    t = _table(t, field, "write [[loads]] tables")
    kind = _require(t, "type", field, '"force" (force, tool_tip, distributed, gravity, helical_gear)')
    if kind not in _LOAD_KEYS:
        raise InputError(f"{field}.type", f"unknown load type {kind!r}", f"use one of {', '.join(_LOAD_KEYS)}")
    _check_keys(t, _LOAD_KEYS[kind], field)
    name = str(t.get("name", kind.replace("_", " ")))
    if kind in ("force", "tool_tip"):
        pos = parse_quantity(_require(t, "position", field, '"0 mm"'), "length", f"{field}.position")
        force = [_q(t, k, "force", field, 0.0) for k in ("fx", "fy", "fz")]
        moment = [_q(t, k, "moment", field, 0.0) for k in ("my", "mz")]
        return PointLoad(pos, force, moment, name)
    if kind == "distributed":
        start = parse_quantity(_require(t, "start", field, '"20 mm"'), "length", f"{field}.start")
        end = parse_quantity(_require(t, "end", field, '"80 mm"'), "length", f"{field}.end")
        q = [_q(t, k, "stiffness", field, 0.0) for k in ("qx", "qy", "qz")]  # N/m: the dimension of a stiffness
        return DistributedLoad(start, end, q, name)
    if kind == "gravity":
        g = [_q(t, k, "acceleration", field, 0.0) for k in ("gx", "gy", "gz")]
        if not any(k in t for k in ("gx", "gy", "gz")):
            g = [0.0, -STANDARD_GRAVITY, 0.0]
        return Gravity(g, name)
    # helical gear: the transmitted torque is required (a gear without torque carries no force)
    torque = parse_quantity(_require(t, "torque", field, '"250 N*m" (the torque the gear transmits)'), "moment",
                            f"{field}.torque")
    if torque == 0.0:
        raise InputError(f"{field}.torque", "a gear without torque transmits no force",
                         'give the transmitted torque, e.g. torque = "250 N*m"')
    hand = t.get("hand", "right")
    return HelicalGear(parse_quantity(_require(t, "position", field, '"150 mm"'), "length", f"{field}.position"),
                       torque,
                       parse_quantity(_require(t, "pitch_diameter", field, '"120 mm"'), "length",
                                      f"{field}.pitch_diameter"),
                       _q(t, "pressure_angle", "angle", field, math.radians(20.0)),
                       _q(t, "helix_angle", "angle", field, 0.0), hand,
                       _q(t, "mesh_angle", "angle", field, 0.0), name)


def _mass(t, i: int):

    field = f"masses[{i}]"
    t = _table(t, field, "write [[masses]] tables")
    _check_keys(t, _MASS_KEYS, field)
    return PointMass(parse_quantity(_require(t, "position", field, '"0 mm"'), "length", f"{field}.position"),
                     parse_quantity(_require(t, "mass", field, '"1.5 kg"'), "mass", f"{field}.mass"),
                     _q(t, "polar_inertia", "inertia", field, 0.0), _q(t, "diametral_inertia", "inertia", field, 0.0),
                     str(t.get("name", f"mass {i + 1}")))


def _section(t, i: int, default_material):

    field = f"sections[{i}]"
    t = _table(t, field, "write [[sections]] tables with length and outer_diameter")
    _check_keys(t, _SECTION_KEYS, field)
    length = parse_quantity(_require(t, "length", field, '"80 mm"'), "length", f"{field}.length")
    od = parse_quantity(_require(t, "outer_diameter", field, '"55 mm"'), "length", f"{field}.outer_diameter")
    idia = _q(t, "inner_diameter", "length", field, 0.0)
    mat = material_from_file(t["material"], f"{field}.material") if "material" in t else default_material
    try:
        return Section(length, od, idia, mat)
    except InputError as exc:  # the model's checks (positive sizes, bore below the outside) in the file's names
        raise InputError(str(exc.field).replace("section", field, 1), exc.problem, exc.fix) from None


def _list(data: dict, key: str, required: bool) -> list:
    v = data.get(key, [])
    if not isinstance(v, list) or (required and not v):
        raise InputError(key, "expected a list of tables" if v else "missing",
                         f"add [[{key}]] tables" + (" (at least one)" if required else ""))
    return v


def shaft_system_from_dict(data: dict, folder: Path | str | None = None) -> ShaftFile:
    """Build a :class:`ShaftFile` from the parsed TOML table of a shaft-system file (format in the module
    docstring); ``folder``: where relative bearing paths are looked up (the file's folder)."""
    if not isinstance(data, dict):
        raise InputError("shaft_system", f"expected a table, got {type(data).__name__}",
                         "give the parsed TOML table of a shaft-system file")
    with file_input():
        return _from_dict(data, Path(folder) if folder is not None else None)


def _from_dict(data: dict, folder: Path | None) -> ShaftFile:

    if data.get("type") != "shaft_system":
        raise InputError("type", f"expected type = \"shaft_system\", got {data.get('type')!r}",
                         'a shaft-system file starts with type = "shaft_system"')
    _check_keys(data, _KEYS, "")
    default_material = material_from_file(data.get("material", "bearing_steel"), "material")
    sections = tuple(_section(t, i, default_material) for i, t in enumerate(_list(data, "sections", True)))
    supports = tuple(_support(t, i, folder) for i, t in enumerate(_list(data, "supports", True)))
    loads_raw = _list(data, "loads", False)
    loads = tuple(_load(t, i) for i, t in enumerate(loads_raw))
    masses = tuple(_mass(t, i) for i, t in enumerate(_list(data, "masses", False)))
    names = {}
    for key, items in (("masses", masses), ("loads", loads), ("supports", supports)):
        for i, it in enumerate(items):
            names[it.name] = f"{key}[{i}]"
    tips = [i for i, t in enumerate(loads_raw) if t.get("type") == "tool_tip"]
    if len(tips) > 1:
        raise InputError(f"loads[{tips[1]}].type", "a second tool tip", "give one tool_tip load (others as force)")
    tool = loads[tips[0]].position if tips else None
    at = _q(data, "stiffness_at", "length", "", None)
    if at is not None:
        loads = loads + (PointLoad(at, name="stiffness_at"),)  # a node where the stiffness is reported
        names["stiffness_at"] = "stiffness_at"
    elements = data.get("elements", 40)
    if isinstance(elements, bool) or not isinstance(elements, int) or not 1 <= elements <= 2000:
        raise InputError("elements", f"must be a whole number in 1..2000, got {elements!r}", "e.g. elements = 40")
    shear = data.get("shear", True)
    if not isinstance(shear, bool):
        raise InputError("shear", f"expected true or false, got {shear!r}", "shear = true (Timoshenko) or false")
    try:
        system = ShaftSystem(sections, supports, loads, masses, _q(data, "speed", "speed", "", 0.0), elements,
                             shear, _q(data, "start", "length", "", 0.0), str(data.get("name", "shaft system")))
    except InputError as exc:
        raise _relabel(exc, names) from None
    return ShaftFile(system, at if at is not None else tool, tool, description=str(data.get("description", "")))


def load_shaft_system(path) -> ShaftFile:
    """Read a shaft-system file (TOML, :func:`bearingsim.io.files.read_toml`) → :class:`ShaftFile`; relative
    bearing paths are looked up beside the file."""
    data = read_toml(path, "file")
    out = shaft_system_from_dict(data, Path(str(path)).parent)
    return dataclasses.replace(out, path=str(path))


def with_probe(shaft: ShaftFile, position: float, field: str = "--stiffness-at") -> ShaftFile:
    """``shaft`` with a node at ``position`` [m] (a zero point load) where the stiffness is reported; an
    :class:`InputError` naming ``field`` when the position is off the shaft."""

    lo, hi = shaft.system.span
    if not lo - 1e-9 <= position <= hi + 1e-9:
        raise InputError(field, f"{position * 1e3:.6g} mm is off the shaft ({lo * 1e3:.6g} … {hi * 1e3:.6g} mm)",
                         "give a position between the shaft's ends")
    loads = shaft.system.loads + (PointLoad(position, name="stiffness_at"),)
    return dataclasses.replace(shaft, system=dataclasses.replace(shaft.system, loads=loads), stiffness_at=position)


__all__ = ["STANDARD_GRAVITY", "ShaftFile", "load_shaft_system", "shaft_system_from_dict", "with_probe"]
