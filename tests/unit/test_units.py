"""Units at the edge (bearingsim.units.parse_quantity): conversions written out by hand."""

from __future__ import annotations

import math

import pytest

from bearingsim.errors import InputError
from bearingsim.units import parse_quantity

# (value, dimension, expected SI value), conversion factors from the SI definitions
CASES = [
    ("11.1 mm", "length", 0.0111),
    ("0.01 mm", "length", 1e-5),
    ("43.5 mm", "length", 0.0435),
    ("1 in", "length", 0.0254),  # international inch, exactly 25.4 mm
    ("11200 rpm", "speed", 11200 * 2 * math.pi / 60),
    ("1 rpm", "speed", 2 * math.pi / 60),
    ("10 rad/s", "speed", 10.0),
    ("15 deg", "angle", 15 * math.pi / 180),
    ("0.5 rad", "angle", 0.5),
    ("1000 N", "force", 1000.0),
    ("2 kN", "force", 2000.0),
    ("1 N*m", "moment", 1.0),
    ("30 N*m", "moment", 30.0),
    ("310 GPa", "pressure", 310e9),
    ("3200 kg/m^3", "density", 3200.0),
    ("3.2 g/cm^3", "density", 3200.0),
    ("2 g", "mass", 0.002),
    ("5 ms", "time", 0.005),
    ("50 Hz", "frequency", 50.0),
    ("60 degC", "temperature", 333.15),
    ("100 N/um", "stiffness", 100e6),
]


@pytest.mark.parametrize("value, dimension, expected", CASES)
def test_quantity_with_unit(value, dimension, expected):
    assert parse_quantity(value, dimension, "f") == pytest.approx(expected, rel=1e-12)


# bare numbers take the field's default unit (issue 2 item 7: N, N·m, rpm; angles in deg)
BARE = [
    (0.0111, "length", 0.0111),
    ("0.0111", "length", 0.0111),
    (1000, "force", 1000.0),
    ("1000", "force", 1000.0),
    (30, "moment", 30.0),
    (11200, "speed", 11200 * 2 * math.pi / 60),
    ("11200", "speed", 11200 * 2 * math.pi / 60),
    (15, "angle", 15 * math.pi / 180),
    (60, "temperature", 333.15),
    (0.3, "dimensionless", 0.3),
]


@pytest.mark.parametrize("value, dimension, expected", BARE)
def test_bare_number_takes_default_unit(value, dimension, expected):
    assert parse_quantity(value, dimension, "f") == pytest.approx(expected, rel=1e-12)


def test_result_is_plain_float():
    v = parse_quantity("11.1 mm", "length", "ball_diameter")
    assert type(v) is float


BAD = [
    ("5 kg", "length", "ball_diameter"),  # wrong dimension
    ("1000 N", "length", "pitch_diameter"),
    ("11.1 mm", "force", "fa"),
    ("3 m", "speed", "speed"),
    ("5 furlongz", "length", "ball_diameter"),  # unknown unit
    ("11.1 parsecs_per_banana", "length", "ball_diameter"),
    ("", "length", "ball_diameter"),  # empty
    ("mm 11.1 +", "length", "ball_diameter"),  # garbage
    (True, "force", "fa"),  # a bool is not a quantity
    (float("nan"), "force", "fa"),
    (float("inf"), "length", "ball_diameter"),
    ("inf mm", "length", "ball_diameter"),
    ([1, 2], "force", "fa"),
]


@pytest.mark.parametrize("value, dimension, field", BAD)
def test_bad_quantity_raises_input_error_naming_field(value, dimension, field):
    with pytest.raises(InputError) as info:
        parse_quantity(value, dimension, field)
    exc = info.value
    assert exc.field == field
    assert str(exc).startswith(field)
    assert exc.fix, "the message must say how to fix the input"
    assert exc.fix in str(exc)


def test_wrong_dimension_message_names_expected_unit():
    with pytest.raises(InputError) as info:
        parse_quantity("5 kg", "length", "ball_diameter")
    # the fix suggests a unit of the right dimension
    assert "m" in info.value.fix


def test_turns_per_second_speed():
    assert parse_quantity("1 turn/s", "speed", "speed") == pytest.approx(2 * math.pi, rel=1e-12)


def test_hertz_as_a_shaft_speed_is_revolutions_per_second():
    try:
        v = parse_quantity("50 Hz", "speed", "speed")
    except InputError as exc:  # rejecting the ambiguous unit is an acceptable fix
        assert exc.field == "speed" and exc.fix
        return
    assert v == pytest.approx(2 * math.pi * 50, rel=1e-12)


def test_rpm_as_a_frequency_is_revolutions_per_second():
    try:
        v = parse_quantity("600 rpm", "frequency", "frequency")
    except InputError as exc:
        assert exc.field == "frequency" and exc.fix
        return
    assert v == pytest.approx(10.0, rel=1e-12)


# ---- issue 11 item 3: one number and a unit, never arithmetic ------------------------------------
import time  # noqa: E402

from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from bearingsim.units import DIMENSIONS, MAX_LENGTH, file_input, format_quantity, registry  # noqa: E402


@pytest.fixture(autouse=True, scope="module")
def _pint_loaded():
    """Timing assertions below measure parsing, not the one-time creation of pint's registry (~0.5 s)."""
    registry()

HOSTILE = [
    ("9**9**9 N", "force"),  # hung the process (pint evaluated the power tower)
    ("10**400 N", "force"),  # OverflowError
    ("1/0 N", "force"),  # ZeroDivisionError
    ("1 m**9**9**9", "length"),  # the same power tower in the unit part
    ("1 m^9^9^9", "length"),
    ("1 (m**99)**99", "length"),
    ("1 m^13", "length"),  # exponents are bounded to ±12
    ("2*3 N", "force"),
    ("(1+2) N", "force"),
    ("1e400 N", "force"),  # beyond the float range
    ("1e308 km", "length"),  # finite as written, infinite in SI
    ("-1e308 kN", "force"),
    ("1" * 400 + " N", "force"),  # longer than MAX_LENGTH
    ("1 " + "(" * 60 + "m" + ")" * 60, "length"),  # past the length bound
    ("__import__('os') N", "force"),
    ("1 N; 2 N", "force"),
]


@pytest.mark.parametrize("text, dimension", HOSTILE)
def test_hostile_strings_are_refused_quickly(text, dimension):
    t0 = time.perf_counter()
    with pytest.raises(InputError) as info:
        parse_quantity(text, dimension, "--fa")
    assert time.perf_counter() - t0 < 0.5, "parsing must not evaluate anything expensive"
    assert info.value.field == "--fa" and info.value.fix
    assert "\n" not in str(info.value)


@pytest.mark.parametrize("text, fixed", [("3000,5 N", "3000.5 N"), ("72,5 mm", "72.5 mm"), ("23,4 kN", "23.4 kN"),
                                         ("-0,5 N*m", "-0.5 N*m")])
def test_decimal_comma_is_refused_with_a_hint(text, fixed):
    """Issue 11: "3000,5 N" was read as 30005 N and "72,5 mm" as 0.725 m."""
    with pytest.raises(InputError) as info:
        parse_quantity(text, "length" if "mm" in text else ("moment" if "N*m" in text else "force"), "--fa")
    assert "decimal" in str(info.value) and fixed in info.value.fix


RPM = 2 * math.pi / 60
TYPED = [
    ("10000 RPM", "speed", 10000 * RPM),
    ("10 krpm", "speed", 10000 * RPM),
    ("3000 rev/min", "speed", 3000 * RPM),
    ("3000 r/min", "speed", None),  # not a pint unit: refused (None) rather than guessed
    ("1/min", "speed", RPM),
    ("600 1/min", "speed", 600 * RPM),
    ("600 min^-1", "speed", 600 * RPM),
    ("3kN", "force", 3000.0),
    ("3e3N", "force", 3000.0),
    ("+2.5E-1 kN", "force", 250.0),
    ("12 N*m", "moment", 12.0),
    ("12 N·m", "moment", 12.0),
    ("12 N m", "moment", 12.0),
    ("12 Nm", "moment", 12.0),  # pint alone reads "Nm" as a number-metre
    ("1.5 kNm", "moment", 1500.0),
    ("5 µm", "length", 5e-6),
    ("5 μm", "length", 5e-6),  # Greek mu
    ("5 um", "length", 5e-6),
    ("60 degC", "temperature", 333.15),
    ("60 °C", "temperature", 333.15),
    ("68 mm²/s", "kinematic_viscosity", 68e-6),
    ("20 1/GPa", "inverse_pressure", 20e-9),
    ("0.13 W/(m*K)", "thermal_conductivity", 0.13),
    ("-9.81 m/s^2", "acceleration", -9.81),
    ("0.002 kg*m^2", "inertia", 0.002),
    (".5 mm", "length", 0.5e-3),
    ("  11.1   mm  ", "length", 11.1e-3),
]


@pytest.mark.parametrize("text, dimension, expected", TYPED)
def test_what_users_type(text, dimension, expected):
    if expected is None:
        with pytest.raises(InputError):
            parse_quantity(text, dimension, "f")
        return
    assert parse_quantity(text, dimension, "f") == pytest.approx(expected, rel=1e-12)


def test_length_bound_is_exact():
    ok = "1" + " " * (MAX_LENGTH - 3) + "mm"
    assert len(ok) == MAX_LENGTH and parse_quantity(ok, "length", "f") == pytest.approx(1e-3, rel=1e-12)
    with pytest.raises(InputError, match="characters"):
        parse_quantity(ok + " ", "length", "f")


def test_huge_python_int_is_an_input_error():
    with pytest.raises(InputError):
        parse_quantity(10**400, "force", "fa")


def test_file_fields_need_units_and_cli_numbers_do_not():
    """Bare numbers: N / N·m / rpm on the command line (README), an error inside a file."""
    assert parse_quantity("3000", "force", "--fa") == 3000.0
    assert parse_quantity("11200", "speed", "--speed") == pytest.approx(11200 * RPM, rel=1e-12)
    with file_input():
        with pytest.raises(InputError) as info:
            parse_quantity(72.5, "length", "pitch_diameter")
        assert info.value.field == "pitch_diameter" and "72.5 mm" in info.value.fix
        with pytest.raises(InputError):
            parse_quantity("208e9", "pressure", "youngs_modulus")
        with pytest.raises(InputError):  # a temperature zero is 0 K or 0 degC: it needs a unit
            parse_quantity(0, "temperature", "temperature")
        assert parse_quantity(0.0, "length", "axial_offset") == 0.0  # zero is zero in every length unit
        assert parse_quantity(0.52, "dimensionless", "inner_conformity") == 0.52
        assert parse_quantity("11.1 mm", "length", "ball_diameter") == pytest.approx(11.1e-3, rel=1e-12)
    assert parse_quantity(0.0725, "length", "pitch_diameter") == 0.0725  # outside a file: SI, as before


# arbitrary text: only InputError, quickly.  The alphabet is weighted to what a parser might choke on.
_ALPHABET = st.sampled_from(list("0123456789.,eE+-*/^()· %°µ") + ["**", "m", "N", "k", "rpm", "deg", "C", "Pa",
                                                                      "inf", "nan", " ", "1e308", "9**9"])


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(parts=st.lists(_ALPHABET, max_size=40), other=st.text(max_size=120),
       dimension=st.sampled_from(sorted(DIMENSIONS)))
def test_arbitrary_text_raises_only_input_error_in_bounded_time(parts, other, dimension):
    for text in ("".join(parts), other):
        t0 = time.perf_counter()
        try:
            v = parse_quantity(text, dimension, "f")
        except InputError:
            pass
        else:
            assert type(v) is float and math.isfinite(v)
        assert time.perf_counter() - t0 < 0.5


# format then parse: the value comes back, for each dimension and in several units
_UNITS = {
    "length": ["m", "mm", "um", "in"], "angle": ["rad", "deg"], "force": ["N", "kN"], "moment": ["N*m", "kN*m"],
    "speed": ["rad/s", "rpm", "krpm", "1/min"], "pressure": ["Pa", "MPa", "GPa"], "density": ["kg/m^3", "g/cm^3"],
    "mass": ["kg", "g"], "time": ["s", "ms"], "frequency": ["Hz", "rpm"], "temperature": ["K", "degC", "degF"],
    "dimensionless": [None], "stiffness": ["N/m", "N/um"], "kinematic_viscosity": ["m^2/s", "mm^2/s"],
    "inverse_temperature": ["1/K"], "inverse_pressure": ["1/Pa", "1/GPa"], "thermal_conductivity": ["W/(m*K)"],
    "velocity": ["m/s", "km/h"], "acceleration": ["m/s^2"], "inertia": ["kg*m^2", "g*mm^2"],
}


def test_every_dimension_has_round_trip_units():
    assert set(_UNITS) == set(DIMENSIONS)


@settings(max_examples=300, deadline=None)
@given(dimension=st.sampled_from(sorted(_UNITS)), data=st.data(),
       value=st.floats(min_value=-1e12, max_value=1e12, allow_nan=False, allow_infinity=False))
def test_format_then_parse_round_trips(dimension, data, value):
    unit = data.draw(st.sampled_from(_UNITS[dimension]))
    if dimension == "temperature":
        value = abs(value) % 5000.0  # thermodynamic temperatures [K]
    text = format_quantity(value, dimension, unit)
    assert len(text) <= MAX_LENGTH
    back = parse_quantity(text, dimension, "f")
    # offset units (degC, degF) add ~273/460 K: a few ulps of that offset (~1e-13 K) is the resolution
    assert back == pytest.approx(value, rel=1e-12, abs=1e-11 if dimension == "temperature" else 0.0), text


def test_deep_but_short_parentheses_are_a_valid_unit():
    t0 = time.perf_counter()
    assert parse_quantity("1 " + "(" * 45 + "m" + ")" * 45, "length", "f") == 1.0
    assert time.perf_counter() - t0 < 0.5
