"""The ``[clearance]`` table of bearing and arrangement files →
:class:`~bearingsim.statics.clearance.OperatingClearance`.

The physics (Lamé fits, thermal and centrifugal expansion) stays in :mod:`bearingsim.statics.clearance`;
this module only reads: quantities with their units are parsed into SI floats here.
"""

from __future__ import annotations

from ..errors import InputError
from ..statics.clearance import OperatingClearance
from ..units import parse_quantity

#: key → dimension of :data:`bearingsim.units.DIMENSIONS` (None: a bare number, an expansion coefficient [1/K]
#: or a Poisson ratio [-])
_KEYS = {
    "shaft_interference": "length", "housing_interference": "length", "shaft_bore": "length",
    "housing_outside_diameter": "length", "shaft_modulus": "pressure", "housing_modulus": "pressure",
    "shaft_poisson": None, "housing_poisson": None, "reference_temperature": "temperature",
    "inner_ring_temperature": "temperature", "outer_ring_temperature": "temperature",
    "ball_temperature": "temperature", "shaft_temperature": "temperature", "housing_temperature": "temperature",
    "ring_expansion": None, "ball_expansion": None, "shaft_expansion": None, "housing_expansion": None,
    "speed": "speed",
}


def operating_clearance_from_dict(data: dict, field: str = "clearance") -> OperatingClearance:
    """Build :class:`OperatingClearance` from a TOML table (quantities with units; expansion
    coefficients in 1/K as numbers, e.g. ``housing_expansion = 23e-6`` for aluminium)."""
    if not isinstance(data, dict):
        raise InputError(field, "expected a table", "write a [clearance] table")
    kw = {}
    for k, v in data.items():
        if k not in _KEYS:
            raise InputError(f"{field}.{k}", "unknown key", f"known keys: {', '.join(sorted(_KEYS))}")
        dim = _KEYS[k]
        if dim is None:
            if isinstance(v, bool) or not isinstance(v, int | float):
                raise InputError(f"{field}.{k}", f"expected a number, got {v!r}", "e.g. 11.5e-6")
            kw[k] = float(v)
        else:
            kw[k] = parse_quantity(v, dim, f"{field}.{k}")
    return OperatingClearance(**kw)
