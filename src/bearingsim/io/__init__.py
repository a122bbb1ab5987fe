"""Every file format of bearingsim, at the edge: units parsed once into SI floats when reading, and
written as CF/UDUNITS strings when writing.

==========================  ==========================================================================
:mod:`.files`               path checks and the one TOML reader (:func:`read_text`, :func:`read_toml`)
:mod:`.bearing`             bearing files and the built-in catalogue → ``BallBearing`` (sets and
                            double-row units are handed to :mod:`.arrangement`)
:mod:`.arrangement`         bearing sets and double-row units (``rows``/``arrangement``) → ``BearingSystem``
:mod:`.clearance`           the ``[clearance]`` table (fits, temperatures, speed) → ``OperatingClearance``
:mod:`.lubricant`           lubricant files and the built-in library → ``Lubricant``
:mod:`.case`                case files of the dynamic engine → ``Case``
:mod:`.netcdf`              the netCDF writer of maps and dynamic runs (temporary file, atomic rename)
==========================  ==========================================================================

The file readers of the front door (``load_bearing``, ``bearing_from_dict``, ``read_toml`` ...) are importable
from here.  The case, arrangement and clearance readers are forwarded on
first use (they import the dynamics and statics packages).
"""

from __future__ import annotations

from .bearing import bearing_from_dict, catalog_entries, catalog_names, load_bearing, resolve_bearing_data
from .files import MAX_FILE_BYTES, check_path, parse_toml, read_text, read_toml
from .lubricant import get_lubricant, library, library_names, lubricant_from_dict

__all__ = ["MAX_FILE_BYTES", "check_path", "read_text", "parse_toml", "read_toml", "catalog_names",
           "catalog_entries", "resolve_bearing_data", "load_bearing", "bearing_from_dict", "lubricant_from_dict",
           "get_lubricant", "library", "library_names", "case_from_dict", "load_case", "arrangement_from_dict",
           "operating_clearance_from_dict"]


def __getattr__(name: str):
    if name in ("case_from_dict", "load_case"):
        from . import case as _case

        return getattr(_case, name)
    if name == "arrangement_from_dict":
        from . import arrangement as _arrangement

        return _arrangement.arrangement_from_dict
    if name == "operating_clearance_from_dict":
        from . import clearance as _clearance

        return _clearance.operating_clearance_from_dict
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
