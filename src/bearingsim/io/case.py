"""Case files of the dynamic engine (TOML with units) → :class:`~bearingsim.dynamics.case.Case`.

The layout of a case file is documented in :mod:`bearingsim.dynamics.case` (with the :class:`Case`
dataclass and its checks); this module only reads: units are parsed here, once, into SI floats.
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

from ..dynamics.case import MULTIRATE_DEFAULT, Case
from ..dynamics.loads import parse_loads, parse_speed
from ..errors import InputError
from ..units import file_input, parse_quantity
from .bearing import load_bearing
from .files import read_toml

_KEYS = {"bearing", "lubricant", "temperature", "speed", "duration", "output_interval", "traction", "n_slices",
         "tolerance", "contact_damping", "gravity", "load_point", "chunk", "control", "loads", "inner_ring", "cage",
         "lubrication", "name", "description", "checkpoint_every", "integrator", "start", "ramp_in",
         "traction_compliance", "ball_orbit", "slice_rule", "multirate"}

#: elastic-cage ring data in [cage] (bearingsim.cage_modes.CageRing fields) and their dimensions
_CAGE_RING = {"axial_width": "length", "radial_thickness": "length", "pocket_diameter": "length",
              "young_modulus": "pressure", "poisson": "dimensionless", "density": "density"}


def _inertia(value, fname: str) -> float:
    v = parse_quantity(value, "inertia", fname)
    if not (math.isfinite(v) and v > 0):
        raise InputError(fname, f"must be positive, got {value!r}", 'e.g. "0.01 kg*m^2"')
    return v


def case_from_dict(data: dict, base: Path | None = None) -> Case:
    """Build a :class:`Case` from a parsed TOML table (units parsed here).

    Every dimensional value needs its unit (``duration = "20 ms"``; a bare number is an
    :class:`InputError` naming the unit to add, :func:`bearingsim.units.file_input`); ``tolerance``,
    ``contact_damping`` [s/m] (or ``"ehl"``), ``n_slices``, ``chunk`` and ``cage.friction`` are bare numbers.
    """
    if not isinstance(data, dict):
        raise InputError("case", f"expected a table, got {type(data).__name__}", "give the parsed TOML table (a dict)")
    if base is not None and not isinstance(base, (str, Path)):
        raise InputError("base", f"expected a folder path, got {type(base).__name__}", "give a pathlib.Path or None")
    with file_input():
        return _case_from_dict(data, None if base is None else Path(base))


def _case_from_dict(data: dict, base: Path | None) -> Case:
    unknown = sorted(set(data) - _KEYS)
    if unknown:
        raise InputError(unknown[0], "unknown key in the case file", f"known keys: {', '.join(sorted(_KEYS))}")
    for key in ("bearing", "speed", "duration", "output_interval"):
        if key not in data:
            raise InputError(key, "missing", f"add {key} to the case file")
    bspec = data["bearing"]
    if base is not None and isinstance(bspec, str) and bspec.endswith(".toml") and not Path(bspec).is_absolute():
        bspec = str(base / bspec)
    bearing = load_bearing(bspec)
    lub = data.get("lubricant")
    if lub is not None and not isinstance(lub, str):
        raise InputError("lubricant", f"expected a library name or a TOML path, got {lub!r}"[:160],
                         'e.g. lubricant = "iso-vg-68"')
    if isinstance(lub, str) and base is not None and lub.endswith(".toml") and not Path(lub).is_absolute():
        lub = str(base / lub)
    traction = data.get("traction", "slices" if lub is not None else "none")
    ring = data.get("inner_ring", {})
    if not isinstance(ring, dict):
        raise InputError("inner_ring", "expected a table", "write an [inner_ring] table")
    unknown = set(ring) - {"mass", "transverse_inertia", "polar_inertia"}
    if unknown:
        raise InputError(f"inner_ring.{sorted(unknown)[0]}", "unknown key",
                         "use mass, transverse_inertia, polar_inertia")
    ring_mass = parse_quantity(ring.get("mass", "2 kg"), "mass", "inner_ring.mass")
    inertia = None
    if "transverse_inertia" in ring or "polar_inertia" in ring:
        if not ("transverse_inertia" in ring and "polar_inertia" in ring):
            raise InputError("inner_ring.polar_inertia", "give both transverse_inertia and polar_inertia",
                             'e.g. transverse_inertia = "0.002 kg*m^2", polar_inertia = "0.004 kg*m^2"')
        inertia = (_inertia(ring["transverse_inertia"], "inner_ring.transverse_inertia"),
                   _inertia(ring["polar_inertia"], "inner_ring.polar_inertia"))
    cage_in = data.get("cage", {})
    if not isinstance(cage_in, dict):
        raise InputError("cage", "expected a table", "write a [cage] table")
    unknown = set(cage_in) - {"mass", "pocket_clearance", "friction", "guidance", "land_clearance", "pocket_shape",
                              "enabled", "n_modes", "modal_damping"} - set(_CAGE_RING)
    if unknown:
        raise InputError(f"cage.{sorted(unknown)[0]}", "unknown key",
                         "use mass, pocket_clearance, friction, guidance, land_clearance, pocket_shape, enabled, "
                         "n_modes, modal_damping, " + ", ".join(_CAGE_RING))
    cage = {}
    if "mass" in cage_in:
        cage["mass"] = parse_quantity(cage_in["mass"], "mass", "cage.mass")
    if "pocket_clearance" in cage_in:
        cage["pocket_clearance"] = parse_quantity(cage_in["pocket_clearance"], "length", "cage.pocket_clearance")
        if not cage["pocket_clearance"] > 0:
            raise InputError("cage.pocket_clearance", "must be positive", 'e.g. "0.2 mm"')
    if "land_clearance" in cage_in:
        cage["land_clearance"] = parse_quantity(cage_in["land_clearance"], "length", "cage.land_clearance")
    if "friction" in cage_in:
        cage["friction"] = parse_quantity(cage_in["friction"], "dimensionless", "cage.friction")
    for k in ("guidance", "pocket_shape", "enabled", "n_modes"):
        if k in cage_in:
            cage[k] = cage_in[k]
    if "modal_damping" in cage_in:
        cage["modal_damping"] = parse_quantity(cage_in["modal_damping"], "dimensionless", "cage.modal_damping")
    ring = {k: parse_quantity(cage_in[k], dim, f"cage.{k}") for k, dim in _CAGE_RING.items() if k in cage_in}
    if ring:
        cage["ring"] = ring
    grav = data.get("gravity", (0.0, 0.0, 0.0))
    if not (isinstance(grav, (list, tuple)) and len(grav) == 3):
        raise InputError("gravity", "expected three components", 'e.g. ["0 m/s^2", "0 m/s^2", "-9.81 m/s^2"]')
    gvec = [parse_quantity(g, "acceleration", f"gravity[{i}]") for i, g in enumerate(grav)]
    if not isinstance(data.get("loads", {}), dict):
        raise InputError("loads", f"expected a [loads] table, got {data['loads']!r}"[:160],
                         'write [loads] with fa = "3000 N" etc. (fa, fr, fz, my, mz)')
    sys_lp = bearing.load_point
    load_point = 0.0
    if "load_point" in data:
        load_point = parse_quantity(data["load_point"], "length", "load_point") - sys_lp
    temperature = parse_quantity(data.get("temperature", "60 degC"), "temperature", "temperature")
    tol = data.get("tolerance", 1e-6)
    damping = data.get("contact_damping", 0.05)
    for k, v in (("tolerance", tol), ("contact_damping", damping)):
        if k == "contact_damping" and isinstance(v, str):
            if v != "ehl":
                raise InputError(k, f"unknown contact damping model {v!r}"[:160],
                                 'give a Hunt–Crossley alpha in s/m (e.g. 0.05) or "ehl"')
            continue
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            raise InputError(k, f"expected a number, got {v!r}", "e.g. 1e-6" if k == "tolerance" else
                             'e.g. 0.05 (Hunt–Crossley alpha, s/m) or "ehl"')
    start = data.get("start", "consistent")
    if not isinstance(start, str):
        raise InputError("start", f"expected a name, got {start!r}"[:160], 'use start = "consistent" or "rest"')
    loads = parse_loads(data.get("loads"))
    if "ramp_in" in data:
        ramp = parse_quantity(data["ramp_in"], "time", "ramp_in")
        if not (math.isfinite(ramp) and ramp >= 0):
            raise InputError("ramp_in", f"must be a finite time ≥ 0, got {data['ramp_in']!r}"[:160],
                             'e.g. ramp_in = "5 ms"')
        loads = replace(loads, ramp_in=ramp)
    every = data.get("checkpoint_every", 1)  # chunks, or a wall-clock time such as "30 s"
    interval = None
    if isinstance(every, str):
        interval, every = parse_quantity(every, "time", "checkpoint_every"), 1
    return Case(bearing=bearing, loads=loads, speed=parse_speed(data["speed"]),
                duration=parse_quantity(data["duration"], "time", "duration"),
                output_interval=parse_quantity(data["output_interval"], "time", "output_interval"),
                lubricant=lub, temperature=temperature, traction=traction, n_slices=data.get("n_slices", 8),
                slice_rule=data.get("slice_rule", "strips"),
                tolerance=float(tol), contact_damping=damping if isinstance(damping, str) else float(damping),
                gravity=tuple(gvec), load_point=load_point,
                ring_mass=ring_mass, ring_inertia=inertia, cage=cage, lubrication=data.get("lubrication", {}),
                chunk=data.get("chunk", 200), control=data.get("control", "outer"),
                checkpoint_every=every, checkpoint_interval=interval, integrator=data.get("integrator", "auto"),
                start=start, traction_compliance=data.get("traction_compliance", "film"),
                ball_orbit=data.get("ball_orbit", "free"), multirate=data.get("multirate", MULTIRATE_DEFAULT),
                source=data)


def load_case(path) -> Case:
    """Read a case TOML file.

    Parameters
    ----------
    path : str or Path
        A dynamic case file (``examples/*.toml``): bearing, loads and speed histories, lubricant, integrator.

    Returns
    -------
    Case
        The case for :func:`bearingsim.simulate`; relative paths in the file resolve from its folder.
    """
    p = Path(path)
    return case_from_dict(read_toml(p, "case"), base=p.parent)


__all__ = ["case_from_dict", "load_case"]
