"""Lubricant files (TOML with units) and the built-in library → :class:`~bearingsim.lubricants.Lubricant`.

Library files are ``bearingsim/data/lubricant-<name>.toml``.  The physics (viscosity, density,
pressure–viscosity and traction laws) stays in :mod:`bearingsim.lubricants`; this module only reads.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

from ..errors import InputError
from ..lubricants import Lubricant
from ..units import file_input, parse_quantity
from .files import read_toml

_QUANTITIES = {
    # key: (dimension in units.DIMENSIONS, dataclass field)
    "density_15C": ("density", "density_15"),
    "density_temperature_coefficient": ("inverse_temperature", "density_temperature_coefficient"),
    "pressure_viscosity_coefficient": ("inverse_pressure", "pressure_viscosity_coefficient"),
    "thermal_conductivity": ("thermal_conductivity", "thermal_conductivity"),
    "eyring_stress": ("pressure", "eyring_stress"),
    "lss_c4": ("pressure", "lss_c4"),
}
_NUMBERS = {"lss_ratio": "lss_ratio", "lss_c1": "lss_c1", "lss_c2": "lss_c2", "lss_c3": "lss_c3",
            "lss_floor": "lss_floor"}


def lubricant_from_dict(data: dict, fname: str = "lubricant") -> Lubricant:
    """Build a :class:`Lubricant` from a TOML table (see the library files for the layout).

    Dimensional values need their unit (``"68 mm^2/s"``, ``"40 degC"``; a bare number is an
    :class:`InputError` naming the unit to add); ``lss_*`` are bare numbers.
    """
    if not isinstance(data, dict):
        raise InputError(fname, f"expected a table, got {type(data).__name__}", "give the parsed TOML table (a dict)")
    with file_input():
        return _lubricant_from_dict(data, fname)


def _lubricant_from_dict(data: dict, fname: str) -> Lubricant:
    name = str(data.get("name", "user-lubricant"))
    visc = data.get("viscosity")
    if not isinstance(visc, list) or len(visc) != 2 or not all(isinstance(p, list) and len(p) == 2 for p in visc):
        raise InputError(f"{fname}.viscosity", "expected two [temperature, kinematic viscosity] pairs",
                         'e.g. viscosity = [["40 degC", "68 mm^2/s"], ["100 degC", "8.7 mm^2/s"]]')
    kw: dict = {}
    for i, (t, nu) in enumerate(visc, start=1):
        kw[f"temperature_{i}"] = parse_quantity(t, "temperature", f"{fname}.viscosity[{i - 1}].temperature")
        nu_si = parse_quantity(nu, "kinematic_viscosity", f"{fname}.viscosity[{i - 1}].kinematic_viscosity")
        if not nu_si > 0:
            raise InputError(f"{fname}.viscosity[{i - 1}]", f"viscosity must be positive, got {nu!r}",
                             'e.g. "68 mm^2/s"')
        kw[f"kinematic_viscosity_{i}"] = nu_si
    for key, (dim, attr) in _QUANTITIES.items():
        if key in data:
            kw[attr] = parse_quantity(data[key], dim, f"{fname}.{key}")
    for key, attr in _NUMBERS.items():
        if key in data:
            v = data[key]
            if isinstance(v, bool) or not isinstance(v, (int, float)):
                raise InputError(f"{fname}.{key}", f"expected a number, got {v!r}", "write a bare number, e.g. 0.25")
            kw[attr] = float(v)
    rng = data.get("temperature_range")
    if rng is not None:
        if not (isinstance(rng, list) and len(rng) == 2):
            raise InputError(f"{fname}.temperature_range", "expected [min, max]", 'e.g. ["-20 degC", "150 degC"]')
        kw["min_temperature"] = parse_quantity(rng[0], "temperature", f"{fname}.temperature_range[0]")
        kw["max_temperature"] = parse_quantity(rng[1], "temperature", f"{fname}.temperature_range[1]")
    for req in ("density_15", "pressure_viscosity_coefficient", "thermal_conductivity"):
        if req not in kw:
            key = {"density_15": "density_15C"}.get(req, req)
            raise InputError(f"{fname}.{key}", "missing", "add it to the lubricant table")
    src = data.get("sources", {})
    return Lubricant(name=name, description=str(data.get("description", "")),
                     sources=dict(src) if isinstance(src, dict) else {"all": str(src)}, **kw)


def _data_dir():
    return resources.files("bearingsim") / "data"


def library_names() -> list[str]:
    """Names of the built-in lubricants."""
    out = []
    for entry in _data_dir().iterdir():
        n = entry.name
        if n.startswith("lubricant-") and n.endswith(".toml"):
            out.append(n[len("lubricant-"):-len(".toml")])
    return sorted(out)


def library() -> dict[str, Lubricant]:
    """All built-in lubricants by name."""
    return {n: get_lubricant(n) for n in library_names()}


def get_lubricant(spec: str | Path | Lubricant, fname: str = "lubricant") -> Lubricant:
    """A lubricant from the library by name, or from a TOML file path.

    Parameters
    ----------
    spec : str, Path or Lubricant
        A library name (``bearingsim lubricants`` lists them, e.g. ``"iso-vg-68"``), the path of a lubricant TOML
        file, or a Lubricant (returned as it is).
    fname : str
        The field named in the error message when ``spec`` is not a lubricant.

    Returns
    -------
    Lubricant
        Viscosity–temperature (ASTM D341), pressure–viscosity (Roelands) and density data, SI.
    """
    if isinstance(spec, Lubricant):
        return spec
    if not isinstance(spec, (str, Path)):
        raise InputError(fname, f"expected a lubricant name, a path to a TOML file or a Lubricant, got "
                         f"{type(spec).__name__} {spec!r}"[:200],
                         f"use one of {', '.join(library_names())} or a path to a .toml file")
    s = str(spec)
    if s in library_names():
        return lubricant_from_dict(read_toml(_data_dir() / f"lubricant-{s}.toml", fname), fname)
    p = Path(s)
    if p.suffix.lower() == ".toml" or p.exists():
        return lubricant_from_dict(read_toml(p, fname), fname)
    raise InputError(fname, f"{s!r} is neither a library lubricant nor a TOML file",
                     f"use one of {', '.join(library_names())} or a path to a .toml file")


__all__ = ["lubricant_from_dict", "get_lubricant", "library", "library_names"]
