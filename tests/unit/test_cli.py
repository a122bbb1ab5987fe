"""Command-line interface through the installed console script: JSON schema, units at the edge, one-line errors
with exit status 2."""

import json
import math

import numpy as np
import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script


@pytest.fixture(scope="module")
def static_json():
    p = run("static", "skf-7011-cdga-hc", "--fa", "1000 N", "--fr", "200", "--moment", "1 N*m",
            "--speed", "11200 rpm", "--json")
    return json.loads(p.stdout)


def test_static_json_schema(static_json):
    d = static_json
    assert d["converged"] is True
    assert isinstance(d["iterations"], int)
    disp = d["displacement"]
    assert set(disp) >= {"axial_m", "radial_m", "tilt_rad", "vector"}
    v = disp["vector"]
    assert len(v) == 5
    assert disp["radial_m"] == pytest.approx(math.hypot(v[1], v[2]))
    assert disp["tilt_rad"] == pytest.approx(math.hypot(v[3], v[4]))
    k = np.array(d["stiffness_matrix"])
    assert k.shape == (5, 5)
    assert d["axial_stiffness_N_per_m"] == pytest.approx(k[0, 0])
    assert len(d["balls"]) == 21
    keys = {"azimuth_rad", "inner_contact_angle_rad", "outer_contact_angle_rad", "inner_load_N", "outer_load_N",
            "inner_max_pressure_Pa", "outer_max_pressure_Pa", "orbital_speed_rad_s", "spin_speed_rad_s"}
    assert keys <= set(d["balls"][0])
    assert d["speed_rad_s"] == pytest.approx(11200 * math.pi / 30)


def test_static_units_at_the_edge(static_json):
    """Bare numbers are N, N·m and rpm; "1 kN" equals "1000"."""
    p = run("static", "skf-7011-cdga-hc", "--fa", "1 kN", "--fr", "0.2 kN", "--moment", "1000 N*mm",
            "--speed", "11200", "--json")
    d = json.loads(p.stdout)
    np.testing.assert_allclose(d["displacement"]["vector"], static_json["displacement"]["vector"], rtol=1e-9,
                               atol=1e-15)


def test_static_table_output():
    p = run("static", "harris-218", "--fa", "20 kN", "--speed", "3000 rpm")
    assert "converged" in p.stdout and "stiffness matrix" in p.stdout


@pytest.mark.parametrize("args, field", [
    (("static", "no-such-bearing", "--fa", "1000"), "bearing"),
    (("static", "skf-7011-cdga-hc", "--fa", "5 kg"), "--fa"),
    (("static", "skf-7011-cdga-hc", "--speed", "3 furlongs"), "--speed"),
    (("static", "skf-7011-cdga-hc", "--control", "sideways"), "control"),
])
def test_bad_input_one_line_exit_2(args, field):
    p = run(*args, check=False)
    assert p.returncode == 2, p.stderr
    lines = [ln for ln in p.stderr.strip().splitlines() if ln.strip()]
    assert len(lines) == 1, p.stderr
    assert field in lines[0] and "Traceback" not in p.stderr


def test_malformed_toml(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text('ball_diameter = "11 mm\nball_count = 16\n')
    p = run("static", str(f), "--fa", "1000", check=False)
    assert p.returncode == 2
    assert "TOML" in p.stderr and len(p.stderr.strip().splitlines()) == 1


def test_bad_geometry_file(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text('type = "angular_contact"\nball_diameter = "0 mm"\nball_count = 16\npitch_diameter = "61 mm"\n'
                 'inner_conformity = 0.52\nouter_conformity = 0.52\ncontact_angle = "35 deg"\n'
                 'ball_material = "bearing_steel"\nring_material = "bearing_steel"\n')
    p = run("static", str(f), "--fa", "1000", check=False)
    assert p.returncode == 2 and "ball_diameter" in p.stderr


def test_not_converged_is_reported():
    """An axial load pulling one angular contact row apart cannot be carried: converged false, exit 1."""
    p = run("static", "skf-7011-cdga-hc", "--fa", "-1000", "--json", check=False)
    assert p.returncode == 1
    d = json.loads(p.stdout)
    assert d["converged"] is False and d["status"] != "converged"


def test_catalog_lists_entries():
    p = run("catalog")
    for name in ("skf-7011-cdga-hc", "harris-218", "hub-seed001-row"):
        assert name in p.stdout


def test_reproduce_spindle(tmp_path):
    p = run("reproduce", "spindle-axial-stiffness", "--out", str(tmp_path))
    assert (tmp_path / "spindle_axial_stiffness.csv").stat().st_size > 0
    assert (tmp_path / "spindle_axial_stiffness_fig5.png").stat().st_size > 0
    assert "T2" in p.stdout

