"""Bearing files (TOML with units) and the built-in catalogue → :class:`~bearingsim.geometry.BallBearing`.

Quantities are strings with units (``"11.1 mm"``), parsed once here into SI floats; a bare
number for a dimensional field is refused (:func:`bearingsim.units.file_input`).  A bearing
argument is either a catalogue name (``bearingsim catalog`` lists them) or a path to a TOML file.
A file with ``rows`` or ``arrangement`` is a bearing set or double-row unit, built by
:func:`bearingsim.io.arrangement.arrangement_from_dict` (imported when needed: that module
reads its row bearings through this one).
"""

from __future__ import annotations

import math
import os
from importlib import resources
from pathlib import Path

from ..errors import InputError
from ..geometry import BallBearing
from ..materials import Material, get_material
from ..units import file_input, parse_quantity
from .files import read_toml

_BEARING_KEYS = {
    "name", "type", "ball_diameter", "ball_count", "pitch_diameter", "inner_groove_radius",
    "outer_groove_radius", "inner_conformity", "outer_conformity", "contact_angle",
    "diametral_clearance", "ball_material", "ring_material", "bore", "outside_diameter", "width",
    "dynamic_load_rating", "limiting_speed", "description", "sources",
    "static_load_rating", "geometry_factor_f0", "fatigue_load_limit", "rings",
}
_RINGS_KEYS = {"model", "housing", "shaft"}
_RINGS_UNIT_KEYS = {"outer_ring", "inner_rings"}  # arrangement files (double-row units) only
_SLEEVE_KEYS = {"housing": "outer_diameter", "shaft": "inner_diameter"}



def catalog_names() -> list[str]:
    """Names of the built-in catalogue entries.

    Returns
    -------
    list of str
        The designations :func:`load_bearing` accepts (``"6205"``, ``"skf-7011-cdga-hc"``, ``"hub-seed001"`` …).
    """
    root = resources.files("bearingsim") / "catalog"
    return sorted(p.name[:-5] for p in root.iterdir() if p.name.endswith(".toml"))


def catalog_entries() -> list[dict]:
    """One summary per catalogue entry (for ``bearingsim catalog``), SI units, None where the entry does not say:
    name, type, description, bore_m, outside_diameter_m, width_m, contact_angle_rad, dynamic_load_rating_N,
    static_load_rating_N, ball_count, ball_diameter_m, pitch_diameter_m, estimated (field names whose source
    starts with ESTIMATE or ASSUMED).  Read from the files without building the bearings (fast)."""
    return [catalog_summary(name, _read_catalog(name)) for name in catalog_names()]


_QUICK_UNITS = {"mm": 1e-3, "m": 1.0, "um": 1e-6, "µm": 1e-6, "in": 0.0254, "N": 1.0, "kN": 1e3, "MN": 1e6,
                "deg": math.pi / 180.0, "rad": 1.0}


def _quick(value, dimension: str, field: str):
    """A quantity string as SI float: the plain ``"<number> <unit>"`` forms of the catalogue directly, anything
    else through :func:`bearingsim.units.parse_quantity`; None when absent."""
    if value is None:
        return None
    if isinstance(value, str):
        parts = value.split()
        if len(parts) == 2 and parts[1] in _QUICK_UNITS:
            try:
                return float(parts[0]) * _QUICK_UNITS[parts[1]]
            except ValueError:
                pass
    with file_input():
        return parse_quantity(value, dimension, field)


def catalog_summary(name: str, data: dict) -> dict:
    """The summary of :func:`catalog_entries` for one parsed bearing file ``data`` [SI]."""
    src = data.get("sources", {})
    src = src if isinstance(src, dict) else {}
    estimated = [k for k, v in src.items() if isinstance(v, str)
                 and v.lstrip().upper().startswith(("ESTIMATE", "ASSUMED"))]
    kind = data.get("type", "angular_contact" if "rows" not in data and "arrangement" not in data
                    else "bearing_set")
    z = data.get("ball_count")
    return {
        "name": name, "type": kind, "description": data.get("description", ""),
        "bore_m": _quick(data.get("bore"), "length", "bore"),
        "outside_diameter_m": _quick(data.get("outside_diameter"), "length", "outside_diameter"),
        "width_m": _quick(data.get("width"), "length", "width"),
        "contact_angle_rad": (_quick(data.get("contact_angle"), "angle", "contact_angle")
                              if kind != "deep_groove" else 0.0) if "ball_count" in data else None,
        "dynamic_load_rating_N": _quick(data.get("dynamic_load_rating"), "force", "dynamic_load_rating"),
        "static_load_rating_N": _quick(data.get("static_load_rating"), "force", "static_load_rating"),
        "ball_count": z if isinstance(z, int) and not isinstance(z, bool) else None,
        "ball_diameter_m": _quick(data.get("ball_diameter"), "length", "ball_diameter"),
        "pitch_diameter_m": _quick(data.get("pitch_diameter"), "length", "pitch_diameter"),
        "estimated": estimated,
    }


def catalog_name(name: str) -> str | None:
    """The catalogue designation ``name`` stands for, case-insensitively (``SKF-7011-CDGA-HC`` →
    ``skf-7011-cdga-hc``); None when the catalogue holds none."""
    return {n.lower(): n for n in catalog_names()}.get(str(name).strip().lower())


def _read_catalog(name: str) -> dict:
    return read_toml(resources.files("bearingsim") / "catalog" / f"{name}.toml", "bearing")


def resolve_bearing_data(spec: str | Path) -> dict:
    """The raw TOML table of a bearing given by catalogue name or path."""
    if not isinstance(spec, (str, os.PathLike)):
        raise InputError("bearing", f"expected a catalogue name or a path to a TOML file, got "
                         f"{type(spec).__name__} {spec!r}"[:200], f"use one of {', '.join(catalog_names())} "
                         "or a path to a .toml file")
    spec_s = str(spec)
    if not spec_s.strip():
        raise InputError("bearing", "the name is empty", "give a catalogue designation, e.g. 6205 (bearingsim catalog "
                         "lists them), or a path to a .toml file")
    if spec_s in catalog_names():
        return _read_catalog(spec_s)
    p = Path(spec_s)
    try:
        a_file = p.suffix.lower() == ".toml" or p.exists()
    except OSError:  # e.g. a name longer than the system allows for a path
        a_file = False
    if a_file:
        return read_toml(p, "bearing")
    folded = catalog_name(spec_s)
    if folded is not None:
        return _read_catalog(folded)
    shown = repr(spec_s) if len(spec_s) <= 80 else repr(spec_s[:80]) + f"… ({len(spec_s)} characters)"
    raise InputError("bearing", f"{shown} is neither a catalogue name nor a TOML file", unknown_bearing_fix(spec_s))


def unknown_bearing_fix(name: str) -> str:
    """The fix for a bearing name the catalogue does not hold: its closest designations, else where the list is.

    Case-insensitive, in this order: the designations that start with the name (``7011`` → 7011-15, 7011-25,
    7011-30), those that hold it (skf-7011-cdga-hc), then the closest by edit distance (:mod:`difflib`), then those
    that share its longest start (at least 3 characters); at most six."""
    import difflib

    names = catalog_names()
    key = name.strip().lower()
    lower = {n.lower(): n for n in names}
    close: list[str] = []
    if key and len(key) <= 80:
        close += [n for n in names if n.lower().startswith(key)]
        close += [n for n in names if key in n.lower() and n not in close]
        close += [lower[m] for m in difflib.get_close_matches(key, list(lower), n=6, cutoff=0.6)
                  if lower[m] not in close]
    if not close:  # the designations that share the longest start with it (at least 3 characters)
        common = [(len(os.path.commonprefix([key, n.lower()])), n) for n in names]
        best = max((k for k, _ in common), default=0)
        close = [n for k, n in common if k == best] if best >= 3 else []
    close = close[:6]
    return (f"did you mean {' or '.join(close)}?" if close else
            "bearingsim catalog lists the catalogue; or give a path to a .toml file")


def load_bearing(spec: str | Path):
    """Load a bearing from a catalogue name or a TOML path.

    Parameters
    ----------
    spec : str or Path
        A catalogue designation (case-insensitive, :func:`catalog_names`) or the path of a bearing or bearing-set
        TOML file (quantities as strings with units).

    Returns
    -------
    BallBearing or BearingSystem
        A :class:`~bearingsim.geometry.BallBearing` (or, for arrangement files, the
        :class:`~bearingsim.statics.arrangements.BearingSystem` read by :mod:`bearingsim.io.arrangement`).
    """
    if hasattr(spec, "row_vectors"):  # the rows protocol (bearingsim.geometry)
        return spec  # already a bearing (or bearing system)
    data = resolve_bearing_data(spec)
    return bearing_from_dict(data)


def material_from_file(value, field: str) -> Material:
    """A material of a file: a name of the materials table, or a table with ``youngs_modulus`` [Pa or a
    quantity], ``poisson_ratio`` [-], ``density`` [kg/m³ or a quantity] (and ``name``, ``source``); errors name
    ``field``."""
    if isinstance(value, str):
        return get_material(value, field)
    if isinstance(value, dict):
        unknown = set(value) - {"name", "youngs_modulus", "poisson_ratio", "density", "source"}
        if unknown:
            raise InputError(f"{field}.{sorted(unknown)[0]}", "unknown key",
                             "a material table takes youngs_modulus, poisson_ratio, density, name, source")
        for key in ("youngs_modulus", "poisson_ratio", "density"):
            if key not in value:
                raise InputError(f"{field}.{key}", "missing", f"add {key} to [{field}]")
        pr = value["poisson_ratio"]
        if isinstance(pr, bool) or not isinstance(pr, (int, float)):
            raise InputError(f"{field}.poisson_ratio", f"expected a number, got {pr!r}", "e.g. 0.3")
        return Material(
            name=str(value.get("name", field)),
            youngs_modulus=parse_quantity(value["youngs_modulus"], "pressure", f"{field}.youngs_modulus"),
            poisson_ratio=float(pr),
            density=parse_quantity(value["density"], "density", f"{field}.density"),
            source=str(value.get("source", "user input")),
        )
    raise InputError(field, f"expected a material name or table, got {value!r}",
                     'write ball_material = "silicon_nitride" or a [ball_material] table')


def _sleeve(value, field: str):
    """``[rings.housing]`` / ``[rings.shaft]`` → :class:`bearingsim.rings.spec.Sleeve` (SI)."""
    from ..rings.spec import Sleeve

    key = _SLEEVE_KEYS[field.rsplit(".", 1)[1]]
    if not isinstance(value, dict):
        raise InputError(field, f"expected a table, got {value!r}"[:120],
                         f'write [{field}] with {key} = "... mm" (and optionally material)')
    known = {key, "material", "youngs_modulus", "poisson_ratio", "rigid"}
    unknown = sorted(set(value) - known)
    if unknown:
        raise InputError(f"{field}.{unknown[0]}", "unknown key", f"[{field}] takes {', '.join(sorted(known))}")
    rigid = value.get("rigid", False)
    if not isinstance(rigid, bool):
        raise InputError(f"{field}.rigid", f"expected true or false, got {rigid!r}", "rigid = true (a rigid seat)")
    if rigid:
        extra = sorted(set(value) - {"rigid"})
        if extra:
            raise InputError(f"{field}.{extra[0]}", "a rigid seat has no sleeve dimensions or material",
                             f"remove {extra[0]} or rigid = true")
        return Sleeve(rigid=True)
    if key not in value:
        raise InputError(f"{field}.{key}", "missing", f'give {key} = "... mm"'
                         + (' ("0 mm" for a solid shaft)' if key == "inner_diameter" else "") + " or rigid = true")
    dia = parse_quantity(value[key], "length", f"{field}.{key}")
    if not (math.isfinite(dia) and dia >= 0 and (dia > 0 or key == "inner_diameter")):
        raise InputError(f"{field}.{key}", f"must be a positive length, got {value[key]!r}", 'e.g. "120 mm"')
    e = nu = None
    name = ""
    if "material" in value:
        mat = get_material(value["material"], f"{field}.material")
        e, nu, name = mat.youngs_modulus, mat.poisson_ratio, mat.name
    if "youngs_modulus" in value:
        e = parse_quantity(value["youngs_modulus"], "pressure", f"{field}.youngs_modulus")
        if not (math.isfinite(e) and e > 0):
            raise InputError(f"{field}.youngs_modulus", f"must be positive, got {value['youngs_modulus']!r}",
                             'e.g. "208 GPa"')
        name = name or "user input"
    if "poisson_ratio" in value:
        pr = value["poisson_ratio"]
        if isinstance(pr, bool) or not isinstance(pr, (int, float)) or not 0.0 <= pr < 0.5:
            raise InputError(f"{field}.poisson_ratio", f"expected a number in [0, 0.5), got {pr!r}", "e.g. 0.3")
        nu = float(pr)
    return Sleeve(float(dia), e, nu, False, name)


def rings_from_dict(value, field: str = "rings", unit: bool = False):
    """The ``[rings]`` table of a bearing file (``unit``: of an arrangement file, which may also give the shared
    ring dimensions ``[rings.outer_ring]`` and ``[rings.inner_rings]``) → :class:`bearingsim.rings.spec.RingSpec`
    (SI).  Format: :mod:`bearingsim.rings.spec`; unknown keys and wrong units are an :class:`InputError` naming
    the field."""
    from ..rings.spec import RING_MODELS, RingSpec

    if not isinstance(value, dict):
        raise InputError(field, f"expected a table, got {value!r}"[:120], '[rings] with model = "fe" or "rigid"')
    known = _RINGS_KEYS | (_RINGS_UNIT_KEYS if unit else set())
    unknown = sorted(set(value) - known)
    if unknown:
        fix = f"[{field}] takes {', '.join(sorted(known))}"
        if unknown[0] in _RINGS_UNIT_KEYS:
            fix = f"{unknown[0]} belongs in an arrangement file (double-row unit); " + fix
        raise InputError(f"{field}.{unknown[0]}", "unknown key", fix)
    model = value.get("model", "rigid")
    if model not in RING_MODELS:
        raise InputError(f"{field}.model", f"unknown ring model {model!r}", 'use model = "rigid" or "fe"')
    housing = _sleeve(value["housing"], f"{field}.housing") if "housing" in value else None
    shaft = _sleeve(value["shaft"], f"{field}.shaft") if "shaft" in value else None
    dims = {}
    for key, names in (("outer_ring", ("outside_diameter", "width")), ("inner_rings", ("bore", "width"))):
        t = value.get(key, {})
        f = f"{field}.{key}"
        if not isinstance(t, dict):
            raise InputError(f, f"expected a table, got {t!r}"[:120], f"write [{f}] with {' and '.join(names)}")
        bad = sorted(set(t) - set(names))
        if bad:
            raise InputError(f"{f}.{bad[0]}", "unknown key", f"[{f}] takes {', '.join(names)}")
        vals = []
        for n in names:
            v = parse_quantity(t[n], "length", f"{f}.{n}") if n in t else 0.0
            if not (math.isfinite(v) and v >= 0 and (v > 0 or n not in t)):
                raise InputError(f"{f}.{n}", f"must be a positive length, got {t[n]!r}", 'e.g. "40 mm"')
            vals.append(float(v))
        dims[key] = tuple(vals)
    return RingSpec(model, housing, shaft, dims["outer_ring"], dims["inner_rings"])


def check_sleeves(spec, bore: float, outside_diameter: float, field: str = "rings") -> None:
    """The sleeves of ``spec`` lie beyond the ring seats (housing outside diameter > D, shaft bore < d) [m]."""
    h, s = spec.housing, spec.shaft
    if h is not None and not h.rigid and outside_diameter > 0 and not h.diameter > outside_diameter:
        raise InputError(f"{field}.housing.outer_diameter", f"{h.diameter * 1e3:.4g} mm is not larger than the "
                         f"bearing's outside diameter {outside_diameter * 1e3:.4g} mm",
                         "give the housing's outside diameter (larger than the bearing's)")
    if s is not None and not s.rigid and bore > 0 and not s.diameter < bore:
        raise InputError(f"{field}.shaft.inner_diameter", f"{s.diameter * 1e3:.4g} mm is not smaller than the "
                         f"bearing's bore {bore * 1e3:.4g} mm", 'give the shaft\'s bore ("0 mm": solid shaft)')


def _conformity(data: dict, side: str, ball_diameter: float) -> float:
    kr, kc = f"{side}_groove_radius", f"{side}_conformity"
    if kr in data and kc in data:
        raise InputError(kr, f"both {kr} and {kc} are given", "give only one of them")
    if kr in data:
        r = parse_quantity(data[kr], "length", kr)
        if not r > 0:
            raise InputError(kr, f"must be positive, got {r!r} m", 'e.g. "5.98 mm"')
        if r <= 0.5 * ball_diameter:
            raise InputError(kr, f"groove radius {r * 1e3:.4g} mm is not larger than the ball radius "
                             f"{0.5 * ball_diameter * 1e3:.4g} mm", "the groove radius must exceed D/2 (f > 0.5)")
        return r / ball_diameter
    if kc in data:
        v = data[kc]
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise InputError(kc, f"expected a number, got {v!r}", "e.g. 0.52")
        return float(v)
    raise InputError(kr, "missing", f"give {kr} (with a unit) or {kc} (groove radius / ball diameter)")


def bearing_from_dict(data: dict) -> BallBearing:
    """Build a :class:`BallBearing` from a parsed TOML table (units parsed here).

    Every dimensional field needs its unit (``ball_diameter = "11.1 mm"``; a bare number is an
    :class:`InputError` naming the unit to add); ``ball_count``, the conformities and Poisson's
    ratio are bare numbers.  The plausibility bounds of the values are those of
    :mod:`bearingsim.geometry` (table in its docstring).
    """
    if not isinstance(data, dict):
        raise InputError("bearing", f"expected a table of bearing data, got {type(data).__name__}",
                         "give the parsed TOML table (a dict) of a bearing file")
    with file_input():
        return _bearing_from_dict(data)


def _bearing_from_dict(data: dict) -> BallBearing:
    if "rows" in data or "arrangement" in data:
        from .arrangement import arrangement_from_dict  # sets and double-row units (imports the statics)

        return arrangement_from_dict(data)
    unknown = sorted(set(data) - _BEARING_KEYS)
    if unknown:
        raise InputError(unknown[0], "unknown key in bearing file",
                         f"known keys: {', '.join(sorted(_BEARING_KEYS))}")
    for key in ("ball_diameter", "ball_count", "pitch_diameter", "ball_material", "ring_material"):
        if key not in data:
            raise InputError(key, "missing", f"add {key} to the bearing file")
    kind = data.get("type", "angular_contact")
    if not isinstance(kind, str):
        raise InputError("type", f"expected a string, got {kind!r}", 'type = "angular_contact" or "deep_groove"')
    z = data["ball_count"]
    if isinstance(z, bool) or not isinstance(z, int):
        raise InputError("ball_count", f"must be an integer, got {z!r}", "e.g. ball_count = 16")
    from ..geometry import LIMITS

    if not LIMITS["ball_count"][0] <= z <= LIMITS["ball_count"][1]:  # before anything is sized by it
        raise InputError("ball_count", f"{z} balls is outside {LIMITS['ball_count'][0]}–{LIMITS['ball_count'][1]}",
                         "give the number of balls in one row, e.g. ball_count = 16")
    d = parse_quantity(data["ball_diameter"], "length", "ball_diameter")
    if not d > 0:
        raise InputError("ball_diameter", f"must be positive, got {data['ball_diameter']!r}", 'e.g. "11.1 mm"')
    dm = parse_quantity(data["pitch_diameter"], "length", "pitch_diameter")
    fi = _conformity(data, "inner", d)
    fo = _conformity(data, "outer", d)
    pd = parse_quantity(data["diametral_clearance"], "length", "diametral_clearance") \
        if "diametral_clearance" in data else 0.0
    if "contact_angle" in data:
        alpha = parse_quantity(data["contact_angle"], "angle", "contact_angle")
        if kind == "deep_groove":
            if "diametral_clearance" in data:
                raise InputError("contact_angle", "a deep-groove bearing takes contact_angle or "
                                 "diametral_clearance, not both", "remove one of them")
            pd = 2.0 * (fi + fo - 1.0) * d * (1.0 - math.cos(alpha))
    elif kind == "angular_contact":
        raise InputError("contact_angle", "missing for an angular contact bearing", 'add contact_angle = "15 deg"')
    else:
        alpha = 0.0

    def opt(key, dim):
        return parse_quantity(data[key], dim, key) if key in data else 0.0

    f0 = data.get("geometry_factor_f0", 0.0)
    if isinstance(f0, bool) or not isinstance(f0, (int, float)):
        raise InputError("geometry_factor_f0", f"expected a number, got {f0!r}", "e.g. geometry_factor_f0 = 14")
    src = data.get("sources", {})
    notes = dict(src) if isinstance(src, dict) else {"sources": str(src)}
    if "description" in data:
        notes["description"] = str(data["description"])
    if "rings" in data:
        notes["rings"] = rings_from_dict(data["rings"])
        check_sleeves(notes["rings"], opt("bore", "length"), opt("outside_diameter", "length"))
    return BallBearing(
        name=str(data.get("name", "bearing")), kind=kind, ball_diameter=d, ball_count=z, pitch_diameter=dm,
        inner_conformity=fi, outer_conformity=fo, contact_angle=alpha,
        ball_material=material_from_file(data["ball_material"], "ball_material"),
        ring_material=material_from_file(data["ring_material"], "ring_material"),
        diametral_clearance=pd, bore=opt("bore", "length"), outside_diameter=opt("outside_diameter", "length"),
        width=opt("width", "length"), dynamic_load_rating=opt("dynamic_load_rating", "force"),
        limiting_speed=opt("limiting_speed", "speed"), static_load_rating=opt("static_load_rating", "force"),
        geometry_factor_f0=float(f0), fatigue_load_limit=opt("fatigue_load_limit", "force"), notes=notes,
    )


__all__ = ["catalog_names", "catalog_entries", "catalog_summary", "resolve_bearing_data", "load_bearing",
           "bearing_from_dict", "rings_from_dict", "check_sleeves", "material_from_file"]
