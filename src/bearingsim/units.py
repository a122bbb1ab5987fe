"""Quantities with units at the edge of the program.

Everything inside bearingsim is a plain SI float.  Strings such as ``"11.1 mm"``,
``"11200 rpm"`` or ``"310 GPa"`` from TOML files and the command line are parsed
here once and checked for dimension.

Grammar (a quantity is never evaluated as arithmetic)::

    quantity := number [unit]
    number   := [+|-] digits [. digits] [(e|E) [+|-] digits]        (one number, decimal point)
    unit     := term { ("*" | "/" | "·" | "." | " ") term }
    term     := (name | "(" unit ")" | "1") [("^" | "**") [+|-] digits]   (|exponent| ≤ 12)

The number is read by Python's ``float`` (never by an expression evaluator); unit names are
looked up one at a time in pint's registry and combined here, so neither ``"9**9**9 N"`` nor
``"m**9**9**9"`` nor ``"1/0 N"`` is ever evaluated.  A decimal comma (``"3000,5 N"``) is refused
with a hint; strings longer than :data:`MAX_LENGTH` characters are refused before parsing; the
value must be finite in SI.  What users type is accepted: ``"10000 RPM"``, ``"10 krpm"``,
``"3kN"``, ``"1/min"``, ``"rev/min"``, ``"N*m"``, ``"N·m"``, ``"N m"``, ``"Nm"``, ``"µm"``/``"um"``,
``"degC"``/``"°C"``, ``"mm²/s"``.

A bare number (``3000`` or ``"3000"``) is taken in the dimension's default unit (N for forces,
N·m for moments, rpm for speeds, deg for angles: the command-line convention of the README) —
except inside :func:`file_input` (or with ``require_unit=True``), where the file readers parse:
a bare number for a dimensional field of a bearing, lubricant or case file is an error naming
the unit to add (``all lengths bare`` once read a 72.5 m bearing).  Dimensionless fields
(ball_count, conformities, Poisson's ratio) stay bare numbers.
"""

from __future__ import annotations

import contextlib
import contextvars
import math
import numbers
import re
from functools import lru_cache

from .errors import InputError

#: longest quantity string accepted [characters]
MAX_LENGTH = 100
#: largest |exponent| of a unit factor ("m^3", "s^-2"); bounds what a unit string can ask of pint
MAX_UNIT_EXPONENT = 12

# dimension name -> (pint dimensionality string, SI unit used inside, default unit for bare numbers)
DIMENSIONS: dict[str, tuple[str, str, str]] = {
    "length": ("[length]", "m", "m"),
    "angle": ("", "rad", "deg"),
    "force": ("[mass] * [length] / [time] ** 2", "N", "N"),
    "moment": ("[mass] * [length] ** 2 / [time] ** 2", "N*m", "N*m"),
    "speed": ("1 / [time]", "rad/s", "rpm"),
    "pressure": ("[mass] / [length] / [time] ** 2", "Pa", "Pa"),
    "density": ("[mass] / [length] ** 3", "kg/m^3", "kg/m^3"),
    "mass": ("[mass]", "kg", "kg"),
    "time": ("[time]", "s", "s"),
    "frequency": ("1 / [time]", "Hz", "Hz"),
    "temperature": ("[temperature]", "K", "degC"),
    "dimensionless": ("", "", ""),
    "stiffness": ("[mass] / [time] ** 2", "N/m", "N/m"),
    "kinematic_viscosity": ("[length] ** 2 / [time]", "m^2/s", "mm^2/s"),
    "inverse_temperature": ("1 / [temperature]", "1/K", "1/K"),
    "inverse_pressure": ("[length] * [time] ** 2 / [mass]", "1/Pa", "1/Pa"),
    "thermal_conductivity": ("[mass] * [length] / [time] ** 3 / [temperature]", "W/(m*K)", "W/(m*K)"),
    "velocity": ("[length] / [time]", "m/s", "m/s"),
    "acceleration": ("[length] / [time] ** 2", "m/s^2", "m/s^2"),
    "inertia": ("[mass] * [length] ** 2", "kg*m^2", "kg*m^2"),
}

#: the unit suggested when a file gives a bare number for a dimensional field
FILE_UNIT: dict[str, str] = {
    "length": "mm", "angle": "deg", "force": "N", "moment": "N*m", "speed": "rpm", "pressure": "GPa",
    "density": "kg/m^3", "mass": "kg", "time": "s", "frequency": "Hz", "temperature": "degC",
    "stiffness": "N/um", "kinematic_viscosity": "mm^2/s", "inverse_temperature": "1/K",
    "inverse_pressure": "1/GPa", "thermal_conductivity": "W/(m*K)", "velocity": "m/s",
    "acceleration": "m/s^2", "inertia": "kg*m^2",
}

#: spellings people type that pint does not know (or reads as something else: pint's "Nm" is a
#: "number_meter"); each maps to a unit expression of the grammar above
_ALIASES = {
    "RPM": "rpm", "Rpm": "rpm", "rpms": "rpm", "kRPM": "krpm", "rev": "revolution", "revs": "revolution",
    "Nm": "N*m", "kNm": "kN*m", "Nmm": "N*mm", "mNm": "mN*m", "sec": "s", "secs": "s",
    "micron": "um", "microns": "um", "%": "percent",
}

#: set while a file (bearing, lubricant, case) is being read: dimensional fields need a unit
_FILE_INPUT: contextvars.ContextVar[bool] = contextvars.ContextVar("bearingsim_file_input", default=False)


@contextlib.contextmanager
def file_input():
    """Inside this block :func:`parse_quantity` refuses a bare number for a dimensional field
    (unless the caller says otherwise): the file readers (:func:`bearingsim.io.bearing_from_dict`,
    :func:`bearingsim.lubricants.lubricant_from_dict`, :func:`bearingsim.dynamics.case.case_from_dict`)
    wrap their parsing in it, so every quantity of a file — also those parsed by the modules they
    call (arrangements, load histories) — carries its unit.  An exact zero needs none (0 mm = 0 m),
    except a temperature."""
    token = _FILE_INPUT.set(True)
    try:
        yield
    finally:
        _FILE_INPUT.reset(token)

_NUMBER = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")
_DECIMAL_COMMA = re.compile(r"[+-]?\d*,\d")
_TOKEN = re.compile(r"\s*(?:(?P<name>%|[A-Za-z_µμ°Ωå][A-Za-z_µμ°Ωå0-9]*)|(?P<pow>\*\*|\^)|(?P<op>[*/·⋅.()])"
                    r"|(?P<int>[+-]?\d+))")
_SUPERSCRIPTS = str.maketrans({"²": "^2", "³": "^3", "⁻": "^-", "¹": "1"})


#: Units typed most often (catalogue files, the command line's defaults) converted without pint, whose import
#: costs ~0.2 s of every command's start-up: dimension -> {unit text: (factor, offset)}; the SI
#: value is ``number * factor + offset``, the same floating-point operations pint performs for these units
#: (tests/unit/test_startup.py::test_fast_units_equal_pint checks every entry bitwise against pint).  Anything
#: else goes through pint.
_FAST_UNITS: dict[str, dict[str, tuple[float, float]]] = {
    "length": {"m": (1.0, 0.0), "mm": (1e-3, 0.0), "um": (1e-6, 0.0), "µm": (1e-6, 0.0)},
    "angle": {"rad": (1.0, 0.0), "deg": (math.pi / 180.0, 0.0)},
    "force": {"N": (1.0, 0.0), "kN": (1e3, 0.0)},
    "moment": {"N*m": (1.0, 0.0)},
    "speed": {"rpm": (2.0 * math.pi / 60.0, 0.0), "rad/s": (1.0, 0.0)},
    "pressure": {"Pa": (1.0, 0.0), "MPa": (1e6, 0.0), "GPa": (1e9, 0.0)},
    "time": {"s": (1.0, 0.0), "ms": (1e-3, 0.0)},
    "temperature": {"K": (1.0, 0.0), "degC": (1.0, 273.15)},
}


def _fast_si(number: float, unit_text: str, dimension: str, text: str, field: str) -> float | None:
    """SI value of ``number unit_text`` from :data:`_FAST_UNITS` (finite, checked), or None (ask pint)."""
    entry = _FAST_UNITS.get(dimension, {}).get(unit_text)
    if entry is None:
        return None
    out = number * entry[0] if entry[1] == 0.0 else number * entry[0] + entry[1]  # keeps the sign of -0.0
    if not math.isfinite(out):
        raise InputError(field, f"{text!r} is beyond the floating-point range in SI", "give a finite value")
    return out


@lru_cache(maxsize=1)
def registry():
    """The shared pint UnitRegistry (created lazily on first use: importing pint costs ~0.3 s)."""
    import pint

    try:  # parsed definitions cached on disk: 0.02 s instead of 0.5 s per start
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except (OSError, ImportError):  # pragma: no cover - read-only home or no platformdirs
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


def _example(dimension: str) -> str:
    dim = DIMENSIONS[dimension]
    return FILE_UNIT.get(dimension) or dim[2] or dim[1] or "%"


def parse_quantity(value, dimension: str, field: str, *, require_unit: bool | None = None) -> float:
    """Convert ``value`` to a plain SI float of the given dimension.

    Parameters
    ----------
    value : str | int | float
        ``"11.1 mm"``, ``"11200 rpm"``, ``"60 degC"`` or a bare number, which is
        taken in the dimension's default unit (see :data:`DIMENSIONS`).
    dimension : str
        One of the keys of :data:`DIMENSIONS`.
    field : str
        Name of the input field, used in error messages.
    require_unit : bool | None
        Refuse a bare number for a dimensional field (file readers: a bare ``72.5`` must not
        silently become metres).  None (default): refuse inside :func:`file_input`, else accept.

    Returns
    -------
    float
        The value in SI units [m, rad, N, N·m, rad/s, Pa, kg/m³, kg, s, Hz, K, ...].

    Raises
    ------
    InputError
        Unknown unit, wrong dimension, arithmetic or a decimal comma, a string longer than
        :data:`MAX_LENGTH`, a bare number where a unit is required, or a value that is not a
        finite number in SI.
    """
    if dimension not in DIMENSIONS:
        raise InputError(field, f"unknown dimension {dimension!r}", f"use one of {', '.join(DIMENSIONS)}")
    dim, si, default = DIMENSIONS[dimension]
    example = _example(dimension)
    if require_unit is None:
        require_unit = _FILE_INPUT.get()
    if isinstance(value, bool) or type(value).__name__ == "bool_":
        raise InputError(field, f"expected a quantity, got {value!r}", f'write e.g. "1 {example}"'.rstrip())
    if isinstance(value, numbers.Real):
        try:
            number = float(value)
        except (OverflowError, ValueError, TypeError):
            raise InputError(field, f"{value!r} is not a finite number", "give a finite value") from None
        return _bare(number, repr(value), dimension, field, require_unit)
    if not isinstance(value, str):
        raise InputError(field, f"expected a quantity string such as '1 {example}', got {type(value).__name__}",
                         "write the value as a string with its unit")
    if len(value) > MAX_LENGTH:
        raise InputError(field, f"the value is {len(value)} characters long (at most {MAX_LENGTH})",
                         f'write one number and a unit, e.g. "1 {example}"'.rstrip())
    text = value.strip()
    if not text:
        raise InputError(field, "empty value", f'write e.g. "1 {example}"'.rstrip())
    m = _NUMBER.match(text)
    if m is None:
        raise InputError(field, f"{text!r} does not start with a number",
                         f'write a number then a unit, e.g. "1 {example}"'.rstrip())
    rest = text[m.end():]
    if _DECIMAL_COMMA.match(text) and rest.startswith(","):
        fixed = text.replace(",", ".", 1)
        raise InputError(field, f"{text!r} has a decimal comma (or a thousands separator)",
                         f'use a decimal point and no separators: "{fixed}"')
    try:
        number = float(m.group(0))
    except ValueError:  # pragma: no cover - the pattern admits only float syntax
        raise InputError(field, f"cannot read the number in {text!r}", "write e.g. 1.5e3") from None
    if not math.isfinite(number):
        raise InputError(field, f"{m.group(0)!r} is beyond the floating-point range", "give a finite value")
    unit_text = rest.strip()
    if not unit_text:
        return _bare(number, m.group(0), dimension, field, require_unit)
    fast = _fast_si(number, unit_text, dimension, text, field)
    if fast is not None:
        return fast
    return _to_si(number, _parse_unit(unit_text, text, field, example), text, dimension, field)


def api_quantity(value, dimension: str, field: str):
    """A value given to a public function → SI: a Python or numpy number (or array) is already SI and is returned
    as it is (the caller checks it); a string with a unit (``"1500 rpm"``, ``"2 kN"``) goes through
    :func:`parse_quantity` with the unit required (a bare ``"1500"`` names the unit to add: in the API a bare
    number is SI, on the command line it is the default unit); a pint ``Quantity`` (any registry: read through
    the name of its unit) is converted by the factor of one of its units, its magnitude may be an array.
    A wrong dimension raises :class:`InputError` naming ``field``."""
    if isinstance(value, str):
        return parse_quantity(value, dimension, field, require_unit=True)
    units = getattr(value, "units", None)
    if units is not None and hasattr(value, "magnitude"):
        factor = parse_quantity(f"1 {units}", dimension, field, require_unit=True)
        if dimension == "temperature":
            zero = parse_quantity(f"0 {units}", dimension, field, require_unit=True)
            return zero + (factor - zero) * value.magnitude
        mag = value.magnitude
        return float(mag) * factor if isinstance(mag, numbers.Real) else mag * factor
    return value


def _bare(number: float, shown: str, dimension: str, field: str, require_unit: bool) -> float:
    """A number without a unit: an error where a unit is required, else the default unit."""
    dim, si, default = DIMENSIONS[dimension]
    if not math.isfinite(number):
        raise InputError(field, f"{shown} is not a finite number", "give a finite value")
    if not default and not si:  # dimensionless
        return number
    if require_unit and not (number == 0.0 and dimension != "temperature"):
        raise InputError(field, f"the number {shown} has no unit",
                         f'write it as a string with its unit, e.g. "{shown} {FILE_UNIT.get(dimension, si)}"')
    if default == si:
        return number
    fast = _fast_si(number, default, dimension, f"{shown} {default}", field)
    if fast is not None:
        return fast
    return _to_si(number, registry().Unit(default), f"{shown} {default}", dimension, field)


def _parse_unit(unit_text: str, text: str, field: str, example: str):
    """A pint Unit from a unit expression (grammar in the module docstring), never evaluating numbers."""
    src = unit_text.translate(_SUPERSCRIPTS)
    tokens = []
    pos = 0
    while pos < len(src):
        if src[pos:].strip() == "":
            break
        t = _TOKEN.match(src, pos)
        if t is None:
            raise InputError(field, f"cannot read the unit in {text!r} (at {src[pos:].strip()[:10]!r})",
                             f'write one number then a unit, e.g. "1 {example}" (no arithmetic)')
        kind = t.lastgroup
        gap = t.start(kind) > pos
        tokens.append((kind, t.group(kind), gap))
        pos = t.end()
    ureg = registry()
    state = {"i": 0}

    def bad(why: str):
        return InputError(field, f"cannot read the unit in {text!r} ({why})",
                          f'write one number then a unit, e.g. "1 {example}" (no arithmetic)')

    def peek():
        return tokens[state["i"]] if state["i"] < len(tokens) else (None, None, False)

    def take():
        tok = peek()
        state["i"] += 1
        return tok

    def factor():
        kind, tx, _ = take()
        if kind == "name":
            return lookup(tx)
        if kind == "op" and tx == "(":
            u = expr()
            k2, t2, _ = take()
            if (k2, t2) != ("op", ")"):
                raise bad("unbalanced parenthesis")
            return u
        if kind == "int" and tx == "1" and peek()[:2] == ("op", "/"):
            return ureg.Unit("dimensionless")
        raise bad(f"unexpected {tx!r}" if tx is not None else "it ends too early")

    def term():
        u = factor()
        if peek()[0] == "pow":
            take()
            k2, t2, _ = take()
            if k2 != "int":
                raise bad("an exponent must be a whole number")
            n = int(t2)
            if abs(n) > MAX_UNIT_EXPONENT:
                raise bad(f"exponent {n} is beyond ±{MAX_UNIT_EXPONENT}")
            u = u ** n
            if peek()[0] == "pow":
                raise bad("repeated exponent")
        return u

    def expr():
        u = term()
        while True:
            kind, tx, gap = peek()
            if kind == "op" and tx in "*·⋅.":
                take()
                u = u * term()
            elif kind == "op" and tx == "/":
                take()
                u = u / term()
            elif kind == "name" or (kind == "op" and tx == "("):
                if not gap and kind == "op":
                    raise bad("missing operator before '('")
                u = u * term()  # "N m": a space multiplies
            else:
                return u

    def lookup(name: str):
        alias = _ALIASES.get(name)
        if alias is not None:
            return _parse_unit(alias, text, field, example)
        try:
            return ureg.Unit(name)
        except Exception:  # noqa: BLE001 - pint raises several kinds for an unknown name
            raise InputError(field, f"unknown unit {name!r} in {text!r}",
                             f'write a unit such as "{example}"') from None

    if not tokens:
        raise bad("no unit")
    if tokens[0][:2] == ("op", "/"):  # "1/min" is read as the number 1 and the unit "/min"
        tokens.insert(0, ("int", "1", False))
    try:
        unit = expr()
    except InputError:
        raise
    except Exception as exc:  # noqa: BLE001 - pint's unit algebra (offset units, ...) on validated tokens
        raise bad(f"{exc.__class__.__name__}: {exc}") from None
    if state["i"] != len(tokens):
        raise bad(f"unexpected {tokens[state['i']][1]!r}")
    if any(abs(p) > MAX_UNIT_EXPONENT for p in unit._units.values()):
        raise bad(f"an exponent beyond ±{MAX_UNIT_EXPONENT}")
    return unit


def _to_si(number: float, unit, text: str, dimension: str, field: str) -> float:
    """``number`` × ``unit`` in the SI unit of ``dimension`` (checked), as a finite float."""
    import pint

    dim, si, default = DIMENSIONS[dimension]
    ureg = registry()
    try:
        q = ureg.Quantity(number, unit)
        if si == "":
            mag = q.to("dimensionless").magnitude
        elif si == "rad" and q.dimensionless:
            mag = q.to("rad").magnitude
        elif si in ("rad/s", "Hz"):
            # pint treats the radian as dimensionless, so it cannot tell "50 Hz" (cycles per second)
            # from "50 rad/s".  A rate written with an angle unit (rpm, rad/s, deg/s) converts as an
            # angular speed; a bare reciprocal time (Hz, 1/s, 1/min) counts cycles.
            if q.dimensionality != ureg.Quantity(1, "Hz").dimensionality:
                raise pint.errors.DimensionalityError(q.units, si)
            cycles = all(name.endswith("hertz") or ureg.Quantity(1, name).dimensionality == {"[time]": 1}
                         for name, _ in q.unit_items())
            w = q.to("rad/s").magnitude if not cycles else 2.0 * math.pi * q.to("Hz").magnitude
            mag = w if si == "rad/s" else w / (2.0 * math.pi)
        else:
            mag = q.to(si).magnitude
        out = float(mag)
    except pint.errors.DimensionalityError:
        raise InputError(field, f"{text!r} has dimension {_dimensionality(unit)}, expected {dimension}",
                         f'give it in a unit such as "{_example(dimension) or si}"') from None
    except (OverflowError, ZeroDivisionError):
        raise InputError(field, f"{text!r} is beyond the floating-point range in SI", "give a finite value") from None
    except Exception as exc:  # noqa: BLE001 - pint's offset-unit and conversion errors
        raise InputError(field, f"cannot convert {text!r} to {si or 'a number'} ({exc.__class__.__name__})",
                         f'give it in a unit such as "{_example(dimension) or si}"') from None
    if not math.isfinite(out):
        raise InputError(field, f"{text!r} is beyond the floating-point range in SI", "give a finite value")
    return out


def _dimensionality(unit) -> str:
    try:
        d = str(unit.dimensionality)
    except Exception:  # noqa: BLE001  # pragma: no cover
        return "?"
    return d if d != "dimensionless" else "none (a pure number or an angle)"


#: the unit of the trade for each SI unit string of our files and results (UDUNITS spelling, as in
#: :mod:`bearingsim.io.netcdf`), with the factor: shown value = factor × SI value.  Speeds in rpm, stiffness
#: in N/µm and N·m/mrad (cross terms N/mrad, N·m/µm), displacements in µm and mrad, pressures in MPa.
DISPLAY_UNITS: dict[str, tuple[str, float]] = {
    "rad/s": ("rpm", 30.0 / math.pi),
    "N/m": ("N/µm", 1e-6),
    "N/rad": ("N/mrad", 1e-3),
    "N m/m": ("N·m/µm", 1e-6),
    "N m/rad": ("N·m/mrad", 1e-3),
    "m": ("µm", 1e6),
    "rad": ("mrad", 1e3),
    "Pa": ("MPa", 1e-6),
    "N m": ("N·m", 1.0),
    "N": ("N", 1.0),
    "s": ("s", 1.0),
    "K": ("K", 1.0),
}


def display_unit(si_unit: str) -> tuple[str, float]:
    """(unit people read, factor) for an SI unit string of our outputs (:data:`DISPLAY_UNITS`); an unknown
    unit is shown as it is (factor 1)."""
    return DISPLAY_UNITS.get(str(si_unit).strip(), (str(si_unit), 1.0))


def format_quantity(value: float, dimension: str, unit: str | None = None) -> str:
    """``value`` [SI] written in ``unit`` (default: the dimension's default unit) so that
    :func:`parse_quantity` reads it back: ``format_quantity(0.0111, "length", "mm") == "11.1 mm"``."""
    dim, si, default = DIMENSIONS[dimension]
    unit = unit or default or si
    if not unit:
        return repr(float(value))
    if unit == si:
        return f"{float(value)!r} {unit}"
    if dimension in ("speed", "frequency") or dimension == "temperature":
        # the same angular/cycle rule as parse_quantity: convert through its own inverse
        one = parse_quantity(f"1 {unit}", dimension, "unit")
        zero = parse_quantity(f"0 {unit}", dimension, "unit") if dimension == "temperature" else 0.0
        return f"{(float(value) - zero) / (one - zero)!r} {unit}"
    q = registry().Quantity(float(value), registry().Unit(si))
    return f"{float(q.to(unit).magnitude)!r} {unit}"


def _convert(text: str, si: str, field: str, dim: str | None = None, default: str = "") -> float:
    """Compatibility wrapper (``cli.lubrication`` reads ``--speeds`` with it): ``text`` with its unit in
    the dimension whose SI unit is ``si``, through :func:`parse_quantity` (no expression evaluation)."""
    for name, (_, si_name, _) in DIMENSIONS.items():
        if si_name == si and name not in ("frequency", "angle"):
            return parse_quantity(text, name, field)
    raise InputError(field, f"no dimension with SI unit {si!r}", "")  # pragma: no cover
