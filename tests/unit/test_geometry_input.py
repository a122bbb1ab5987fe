"""Bad input (issue 2 item 9): every case raises InputError naming the field and saying how to fix it.

Cases: a negative or zero diameter, a groove radius ≤ ball radius, a pitch diameter that does
not fit the balls, too many balls for the circumference, an unknown unit or a wrong
dimension ("5 kg" for a length), an unknown catalogue name, a malformed TOML; plus the CLI
printing one line and exiting with status 2.
"""

from __future__ import annotations

import dataclasses
import math
import subprocess
import sys

import pytest

from bearingsim.errors import InputError
from bearingsim.geometry import BallBearing
from bearingsim.io import bearing_from_dict, load_bearing
from bearingsim.materials import LIBRARY, Material

GOOD = {
    "name": "test 7011-like",
    "type": "angular_contact",
    "ball_diameter": "10.319 mm",
    "ball_count": 21,
    "pitch_diameter": "72.5 mm",
    "inner_groove_radius": "5.366 mm",
    "outer_groove_radius": "5.469 mm",
    "contact_angle": "15 deg",
    "ball_material": "silicon_nitride",
    "ring_material": {"youngs_modulus": "208 GPa", "poisson_ratio": 0.3, "density": "7850 kg/m^3"},
}


def check(exc: InputError, field: str):
    assert isinstance(exc, InputError)
    assert exc.field == field, f"field {exc.field!r}, expected {field!r}"
    assert exc.fix, "InputError must say how to fix the input"
    msg = str(exc)
    assert msg.startswith(field) and exc.fix in msg
    assert "\n" not in msg, "one line"


def with_(**kw):
    d = dict(GOOD)
    for k, v in kw.items():
        if v is None:
            d.pop(k, None)
        else:
            d[k] = v
    return d


def test_good_dictionary_builds():
    b = bearing_from_dict(GOOD)
    assert b.ball_diameter == pytest.approx(10.319e-3, rel=1e-12)
    assert b.inner_conformity == pytest.approx(5.366 / 10.319, rel=1e-12)
    assert b.contact_angle == pytest.approx(math.radians(15), rel=1e-12)


BAD_DICTS = [
    ("negative diameter", with_(ball_diameter="-10.319 mm"), "ball_diameter"),
    ("zero diameter", with_(ball_diameter="0 mm"), "ball_diameter"),
    ("zero pitch diameter", with_(pitch_diameter="0 mm"), "pitch_diameter"),
    ("negative pitch diameter", with_(pitch_diameter="-72.5 mm"), "pitch_diameter"),
    ("inner groove = ball radius", with_(inner_groove_radius="5.1595 mm"), "inner_groove_radius"),
    ("outer groove < ball radius", with_(outer_groove_radius="5 mm"), "outer_groove_radius"),
    ("inner conformity 0.5", with_(inner_groove_radius=None, inner_conformity=0.5), "inner_conformity"),
    ("outer conformity 0.45", with_(outer_groove_radius=None, outer_conformity=0.45), "outer_conformity"),
    ("pitch diameter smaller than the ball", with_(pitch_diameter="10 mm"), "pitch_diameter"),
    ("too many balls", with_(ball_count=40), "ball_count"),
    ("ball count not an integer", with_(ball_count=20.5), "ball_count"),
    ("wrong dimension", with_(ball_diameter="5 kg"), "ball_diameter"),
    ("wrong dimension for an angle", with_(contact_angle="15 mm"), "contact_angle"),
    ("unknown unit", with_(pitch_diameter="72.5 furlongz"), "pitch_diameter"),
    ("unknown unit in a material", with_(ring_material={"youngs_modulus": "208 GPascals", "poisson_ratio": 0.3,
                                                        "density": "7850 kg/m^3"}), "ring_material.youngs_modulus"),
    ("unknown material", with_(ball_material="unobtainium"), "ball_material"),
    ("missing ball diameter", with_(ball_diameter=None), "ball_diameter"),
    ("missing contact angle (angular contact)", with_(contact_angle=None), "contact_angle"),
    ("unknown key", with_(ball_diametre="10 mm"), "ball_diametre"),
    ("both groove radius and conformity", with_(inner_conformity=0.52), "inner_groove_radius"),
]


@pytest.mark.parametrize("case, data, field", BAD_DICTS, ids=[c[0] for c in BAD_DICTS])
def test_bad_bearing_data(case, data, field):
    with pytest.raises(InputError) as info:
        bearing_from_dict(data)
    check(info.value, field)


def _direct():
    return dict(name="t", kind="angular_contact", ball_diameter=10e-3, ball_count=20, pitch_diameter=70e-3,
                inner_conformity=0.52, outer_conformity=0.53, contact_angle=math.radians(15),
                ball_material=LIBRARY["silicon_nitride"], ring_material=LIBRARY["bearing_steel"])


@pytest.mark.parametrize("key, value, field", [
    ("ball_diameter", -1e-3, "ball_diameter"),
    ("ball_diameter", 0.0, "ball_diameter"),
    ("ball_diameter", float("nan"), "ball_diameter"),
    ("pitch_diameter", 0.0, "pitch_diameter"),
    ("pitch_diameter", 10.2e-3, "pitch_diameter"),
    ("inner_conformity", 0.5, "inner_conformity"),
    ("outer_conformity", 0.49, "outer_conformity"),
    ("ball_count", 22, "ball_count"),  # pi*70/10 = 21.99 balls at most touching; 22 overlap
    ("ball_count", 2, "ball_count"),
    ("contact_angle", math.radians(-5), "contact_angle"),
    ("kind", "tapered_roller", "type"),
])
def test_dataclass_checks(key, value, field):
    kw = _direct()
    kw[key] = value
    with pytest.raises(InputError) as info:
        BallBearing(**kw)
    check(info.value, field)


def test_ball_count_limit_is_the_circumference():
    """Z balls fit when d_m sin(π/Z) > D (neighbours do not overlap)."""
    kw = _direct()
    zmax = max(z for z in range(3, 100) if 70e-3 * math.sin(math.pi / z) > 10e-3)
    kw["ball_count"] = zmax
    BallBearing(**kw)
    kw["ball_count"] = zmax + 1
    with pytest.raises(InputError) as info:
        BallBearing(**kw)
    check(info.value, "ball_count")
    assert str(zmax) in info.value.fix


def test_bearing_is_frozen(b7011):
    with pytest.raises(dataclasses.FrozenInstanceError):
        b7011.ball_count = 3


@pytest.mark.parametrize("kw, field", [
    (dict(youngs_modulus=-1.0), "steel.youngs_modulus"),
    (dict(poisson_ratio=0.5), "steel.poisson_ratio"),
    (dict(density=0.0), "steel.density"),
])
def test_bad_material(kw, field):
    base = dict(name="steel", youngs_modulus=208e9, poisson_ratio=0.3, density=7850.0)
    base.update(kw)
    with pytest.raises(InputError) as info:
        Material(**base)
    check(info.value, field)


def test_unknown_catalogue_name():
    with pytest.raises(InputError) as info:
        load_bearing("skf-7011-no-such-bearing")
    check(info.value, "bearing")
    assert "skf-7011-cdga-hc" in info.value.fix  # lists the choices


def test_missing_toml_file(tmp_path):
    with pytest.raises(InputError) as info:
        load_bearing(tmp_path / "nothing_here.toml")
    check(info.value, "bearing")


@pytest.mark.parametrize("text", [
    'name = "x"\nball_diameter = "10 mm\n',  # unterminated string
    "ball_count = = 3\n",
    "[ring_material\nyoungs_modulus = 1\n",
])
def test_malformed_toml(write_toml, text):
    with pytest.raises(InputError) as info:
        load_bearing(write_toml(text))
    check(info.value, "bearing")


def test_toml_with_bad_value(write_toml):
    text = "\n".join(f"{k} = {v!r}" if not isinstance(v, dict) else "" for k, v in with_(ball_diameter="5 kg").items()
                     if not isinstance(v, dict))
    text = text.replace("'", '"') + '\n[ring_material]\nyoungs_modulus = "208 GPa"\npoisson_ratio = 0.3\n' \
        'density = "7850 kg/m^3"\n'
    with pytest.raises(InputError) as info:
        load_bearing(write_toml(text))
    check(info.value, "ball_diameter")


# ---- command line: one line and exit status 2, never a traceback ----------------------------------
CLI = "import sys; from bearingsim.cli import main; sys.argv = ['bearingsim'] + sys.argv[1:]; main()"


@pytest.mark.parametrize("args", [
    ["static", "no-such-bearing"],
    ["static", "skf-7011-cdga-hc", "--fa", "5 kg"],
    ["static", "skf-7011-cdga-hc", "--speed", "100 furlongz"],
])
def test_cli_bad_input_exits_2_with_one_line(args):
    p = subprocess.run([sys.executable, "-c", CLI, *args], capture_output=True, text=True, timeout=120)
    out = (p.stdout + p.stderr).strip()
    assert p.returncode == 2, out
    assert "Traceback" not in out
    assert len(out.splitlines()) == 1, out


def test_catalogue_218_matches_issue_2(b218):
    """Issue 2: harris-218 is D = 22.23 mm, Z = 16, d_m = 125.3 mm, f_i = f_o = 0.5232, α₀ = 40°, steel."""
    assert b218.ball_diameter == pytest.approx(22.23e-3, rel=1e-12)
    assert b218.ball_count == 16
    assert b218.pitch_diameter == pytest.approx(125.3e-3, rel=1e-12)
    assert b218.inner_conformity == pytest.approx(0.5232) and b218.outer_conformity == pytest.approx(0.5232)
    assert b218.contact_angle == pytest.approx(math.radians(40.0), rel=1e-12)
    assert b218.ball_material.youngs_modulus == b218.ring_material.youngs_modulus
    # Harris's A = B D = (0.5232 + 0.5232 − 1) · 22.23 mm = 1.0314 mm
    assert b218.total_curvature_distance == pytest.approx(1.0314e-3, rel=1e-4)


def test_catalogue_7011_boundary_dimensions_fit(b7011):
    """SKF 7011: d = 55 mm, D = 90 mm, B = 18 mm, 15°, Si₃N₄ balls; the estimated ball set fits inside."""
    assert b7011.bore == pytest.approx(55e-3) and b7011.outside_diameter == pytest.approx(90e-3)
    assert b7011.contact_angle == pytest.approx(math.radians(15.0), rel=1e-12)
    assert b7011.bore < b7011.pitch_diameter - b7011.ball_diameter
    assert b7011.pitch_diameter + b7011.ball_diameter < b7011.outside_diameter
    assert b7011.ball_material.youngs_modulus > b7011.ring_material.youngs_modulus  # ceramic balls
    assert any("ESTIMATE" in str(v) for v in b7011.notes.values()), "the estimate must say it is one"


# ---- issue 11 item 10: wrong types at the public API name the argument -----------------------------
@pytest.mark.parametrize("spec", [None, 7, 2.5, ["skf-7011-cdga-hc"], {"name": "x"}])
def test_load_bearing_wrong_type(spec):
    with pytest.raises(InputError) as info:
        load_bearing(spec)
    check(info.value, "bearing")


def test_load_bearing_passes_a_bearing_through(b7011):
    assert load_bearing(b7011) is b7011


@pytest.mark.parametrize("data", [None, "ball_diameter = 1", ["a"], 3])
def test_bearing_from_dict_wrong_type(data):
    with pytest.raises(InputError) as info:
        bearing_from_dict(data)
    check(info.value, "bearing")


@pytest.mark.parametrize("key, value, field", [
    ("ball_diameter", None, "ball_diameter"),
    ("ball_diameter", "10 mm", "ball_diameter"),  # the dataclass is SI floats; units are read by io
    ("pitch_diameter", [70e-3], "pitch_diameter"),
    ("contact_angle", True, "contact_angle"),
    ("diametral_clearance", None, "diametral_clearance"),
    ("bore", "55 mm", "bore"),
    ("ball_count", 20.0, "ball_count"),
    ("ball_count", "20", "ball_count"),
    ("ball_count", True, "ball_count"),
    ("ball_count", 10**12, "ball_count"),
    ("ball_material", "silicon_nitride", "ball_material"),
    ("ring_material", None, "ring_material"),
    ("name", None, "name"),
    ("kind", None, "type"),
    ("notes", None, "notes"),
])
def test_ball_bearing_wrong_types(key, value, field):
    kw = _direct()
    kw[key] = value
    with pytest.raises(InputError) as info:
        BallBearing(**kw)
    check(info.value, field)


@pytest.mark.parametrize("kw, field", [
    (dict(youngs_modulus="208 GPa"), "steel.youngs_modulus"),
    (dict(poisson_ratio=None), "steel.poisson_ratio"),
    (dict(density=[7850.0]), "steel.density"),
    (dict(name=None), "material.name"),
])
def test_material_wrong_types(kw, field):
    base = dict(name="steel", youngs_modulus=208e9, poisson_ratio=0.3, density=7850.0)
    base.update(kw)
    with pytest.raises(InputError) as info:
        Material(**base)
    check(info.value, field)


@pytest.mark.parametrize("name", [None, 3, ["bearing_steel"]])
def test_get_material_wrong_type(name):
    from bearingsim.materials import get_material

    with pytest.raises(InputError) as info:
        get_material(name, "ball_material")
    check(info.value, "ball_material")


@pytest.mark.parametrize("spec", [None, 68, ["iso-vg-68"], {"name": "x"}])
def test_get_lubricant_wrong_type(spec):
    from bearingsim.lubricants import get_lubricant

    with pytest.raises(InputError) as info:
        get_lubricant(spec)
    check(info.value, "lubricant")


@pytest.mark.parametrize("data, field", [
    (None, "lubricant"),
    ([1, 2], "lubricant"),
    ({"viscosity": [[40, "68 mm^2/s"], ["100 degC", "8.7 mm^2/s"]], "density_15C": "875 kg/m^3",
      "pressure_viscosity_coefficient": "21 1/GPa", "thermal_conductivity": "0.13 W/(m*K)"},
     "lubricant.viscosity[0].temperature"),  # a bare temperature in a file needs its unit
    ({"viscosity": [["40 degC", 68], ["100 degC", "8.7 mm^2/s"]], "density_15C": "875 kg/m^3",
      "pressure_viscosity_coefficient": "21 1/GPa", "thermal_conductivity": "0.13 W/(m*K)"},
     "lubricant.viscosity[0].kinematic_viscosity"),
])
def test_lubricant_from_dict_wrong_types_and_bare_numbers(data, field):
    from bearingsim.lubricants import lubricant_from_dict

    with pytest.raises(InputError) as info:
        lubricant_from_dict(data)
    check(info.value, field)


def test_lubricant_dataclass_wrong_type():
    from bearingsim.lubricants import Lubricant

    with pytest.raises(InputError) as info:
        Lubricant("oil", 313.15, 68e-6, 373.15, 8.7e-6, 875.0, 21e-9, 0.13, density_temperature_coefficient="6e-4")
    check(info.value, "oil.density_temperature_coefficient")


@pytest.mark.parametrize("call, field", [
    (lambda b: b.contact("1000", True), "load"),
    (lambda b: b.contact(None, True), "load"),
    (lambda b: b.contact(-5.0, True), "load"),
    (lambda b: b.contact(100.0, True, contact_angle="15 deg"), "contact_angle"),
    (lambda b: b.raceway_radii(True, float("nan")), "contact_angle"),
    (lambda b: b.row_parameters(x_row="0 mm"), "x_row"),
    (lambda b: b.row_parameters(sign=0.5), "sign"),
    (lambda b: b.row_parameters(axial_offset=[1e-6]), "axial_offset"),
])
def test_bearing_methods_check_their_arguments(b7011, call, field):
    with pytest.raises(InputError) as info:
        call(b7011)
    check(info.value, field)


def test_parse_toml_wrong_type():
    from bearingsim.io import parse_toml

    with pytest.raises(InputError) as info:
        parse_toml(b"a = 1", "x.toml", "bearing")
    check(info.value, "bearing")
