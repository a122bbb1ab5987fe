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
