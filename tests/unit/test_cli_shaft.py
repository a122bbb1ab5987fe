"""``bearingsim shaft`` through the installed console script: the spindle's tool-tip stiffness and lives in JSON,
the human tables, the speed sweep to netCDF, the modes, the report, and bad input as one line with exit 2."""

import json
from pathlib import Path

import numpy as np
import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SPINDLE = str(EXAMPLES / "spindle-milling.toml")


@pytest.fixture(scope="module")
def spindle_json():
    return json.loads(run("shaft", SPINDLE, "--json").stdout)


def test_spindle_json_has_tool_tip_stiffness_and_lives(spindle_json):
    d = spindle_json
    assert d["converged"] is True and d["status"] == "converged" and d["residual"] < 1e-3
    n = len(d["nodes"])
    assert len(d["deflection"]) == n and set(d["deflection"][0]) == {"axial_m", "radial_y_m", "radial_z_m",
                                                                   "slope_y_rad", "slope_z_rad"}
    k = np.array(d["stiffness_at"]["stiffness_matrix"])
    assert d["stiffness_at"]["position_m"] == 0.0 and k.shape == (5, 5)
    assert np.allclose(k, k.T, rtol=1e-9, atol=1e-9 * np.abs(k).max())
    assert np.all(np.linalg.eigvalsh(k) > 0)
    # a spindle's radial tool-tip stiffness is of the order of 10-200 N/um
    assert 5e6 < d["stiffness_at"]["radial_N_per_m"] < 5e8
    assert [s["name"] for s in d["supports"]] == ["front TBT set", "rear"]
    for s in d["supports"]:
        assert len(s["reaction"]) == 5 and len(s["misalignment_rad"]) == 2
        assert s["reference_rating_life_hours"] > 0, s["name"]
        assert "balls" in s and "stiffness_matrix" in s and "static_safety_factor_pressure" in s
    assert d["supports"][1]["basic_rating_life_hours"] > 0


def test_reactions_balance_the_tool_force(spindle_json):
    """Equilibrium of the whole shaft: the support reactions balance the tool-tip force (no gravity in the file)."""
    fx = sum(s["reaction"][0] for s in spindle_json["supports"])
    fy = sum(s["reaction"][1] for s in spindle_json["supports"])
    fz = sum(s["reaction"][2] for s in spindle_json["supports"])
    assert (fx, fy, fz) == pytest.approx((150.0, -400.0, -250.0), abs=1e-3)


def test_human_output_shows_trade_units():
    out = run("shaft", SPINDLE).stdout
    assert "converged" in out and "N/µm" in out and "N·m/mrad" in out
    assert "front TBT set" in out and "L10rh" in out and " h " in out


def test_stiffness_at_option_moves_the_point():
    d = json.loads(run("shaft", SPINDLE, "--json", "--stiffness-at", "150 mm").stdout)
    assert d["stiffness_at"]["position_m"] == pytest.approx(0.15)
    assert any(abs(x - 0.15) < 1e-12 for x in d["nodes"])


def test_modes_give_frequencies():
    d = json.loads(run("shaft", SPINDLE, "--json", "--modes", "4").stdout)
    f = d["modes"]["frequency_hz"]
    assert len(f) == 4 and all(b >= a > 0 for a, b in zip(f, f[1:]))
    assert np.array(d["modes"]["shape"]).shape == (4, len(d["nodes"]), 5)


def test_speed_sweep_writes_netcdf(tmp_path):
    import pint
    import xarray as xr

    from bearingsim.io.netcdf import component_units

    nc, png = tmp_path / "k.nc", tmp_path / "k.png"
    run("shaft", SPINDLE, "--speeds", "0:12000:3", "--out", str(nc), "--plot", str(png))
    ureg = pint.UnitRegistry()
    with xr.open_dataset(nc) as ds:
        assert ds.sizes["speed"] == 3 and ds.sizes["support"] == 2
        assert list(ds["support"].values) == ["front TBT set", "rear"]
        assert bool(ds["converged"].all())
        assert ds["speed"].values[-1] == pytest.approx(12000 * np.pi / 30)
        # the library's unit convention: every unit parses with pint, mixed variables per component
        assert ureg.parse_units(ds["speed"].attrs["units"]) == ureg.rad / ureg.s
        assert ureg.parse_units(ds["radial_stiffness"].attrs["units"]) == ureg.N / ureg.m
        assert ureg.parse_units(ds["tilt_stiffness"].attrs["units"]) == ureg.N * ureg.m / ureg.rad
        km = component_units(ds["stiffness_matrix"].attrs, (5, 5))
        assert ureg.parse_units(km[3][4]) == ureg.N * ureg.m / ureg.rad and ureg.parse_units(km[1][1]) == ureg.N / ureg.m
        assert component_units(ds["reaction"].attrs) == ["N", "N", "N", "N m", "N m"]
        k = ds["radial_stiffness"].values
        assert np.all(k > 0) and k[0] != k[-1]  # speed softens the bearings
        # the direct radial stiffness is 1 / compliance of the condensed matrix at the node
        c = np.linalg.inv(ds["stiffness_matrix"].values[0])
        assert k[0] == pytest.approx(1.0 / c[1, 1], rel=1e-9)
        assert np.all(ds["max_contact_pressure"].values > 1e8)
    assert png.stat().st_size > 0


def test_preload_sweep_stiffens_the_spindle():
    """The rear bearing's spring preload swept with the speeds: a table (preload, speed); more preload, stiffer tip
    at every speed (the bearings' contact stiffness rises with their load)."""
    d = json.loads(run("shaft", SPINDLE, "--speeds", "0:12000:2", "--preloads", "rear=100 N:600 N:3",
                       "--json").stdout)
    assert d["preload_support"] == "rear" and d["preload_units"] == "N"
    assert d["preload"] == pytest.approx([100.0, 350.0, 600.0])
    k = np.array(d["radial_stiffness_N_per_m"])
    assert k.shape == (3, 2) and np.all(np.array(d["converged"]))
    assert np.all(np.diff(k, axis=0) > 0), k


def test_sweep_over_workers_equals_the_serial_sweep():
    """Consistency: a sweep split into chains over two processes (each chain starts cold) gives the serial,
    warm-started sweep's equilibria to the solver's tolerance."""
    from bearingsim.io.shaft_system import load_shaft_system
    from bearingsim.shafts.sweep import shaft_sweep

    sf = load_shaft_system(SPINDLE)
    sp = np.linspace(0.0, 1200.0, 8)
    a = shaft_sweep(sf.system, sp, sf.stiffness_at)
    b = shaft_sweep(sf.system, sp, sf.stiffness_at, workers=2)
    for v in ("radial_stiffness", "axial_stiffness", "tilt_stiffness", "reaction", "reference_rating_life_hours"):
        np.testing.assert_allclose(b[v].values, a[v].values, rtol=1e-7, err_msg=v)


def test_report(tmp_path):
    run("shaft", str(EXAMPLES / "gearbox-helical.toml"), "--report", str(tmp_path / "rep"))
    page = (tmp_path / "rep" / "report.html").read_text()
    for name in ("shaft_layout.png", "shaft_deflection.png", "shaft_lives.png", "shaft_modes.png",
                 "shaft_stiffness_speed.png"):
        assert name in page and (tmp_path / "rep" / name).stat().st_size > 0


def _bad(tmp_path, text):
    p = tmp_path / "bad.toml"
    p.write_text(text, encoding="utf-8")
    r = run("shaft", str(p), check=False)
    return r


_HEAD = 'type = "shaft_system"\n[[sections]]\nlength = "200 mm"\nouter_diameter = "{od}"\n'
_SUP = '[[supports]]\nname = "{n}"\nposition = "{x}"\nbearing = "6208"\n'
_GEAR = '[[loads]]\ntype = "helical_gear"\nposition = "100 mm"\npitch_diameter = "100 mm"\n'


@pytest.mark.parametrize("text, field", [
    (_HEAD.format(od="40 mm") + _SUP.format(n="a", x="20 mm") + _SUP.format(n="b", x="250 mm"),
     "supports[1].position"),
    (_HEAD.format(od="40 mm") + _SUP.format(n="a", x="20 mm") + _SUP.format(n="b", x="20 mm"),
     "supports[1].position"),
    (_HEAD.format(od="40 mm") + _SUP.format(n="a", x="20 mm"), "supports"),
    (_HEAD.format(od="0 mm") + _SUP.format(n="a", x="20 mm") + _SUP.format(n="b", x="180 mm"),
     "sections[0].outer_diameter"),
    (_HEAD.format(od="40 mm") + _SUP.format(n="a", x="20 mm") + _SUP.format(n="b", x="180 mm") + _GEAR,
     "loads[0].torque"),
])
def test_bad_input_is_one_line_exit_2(tmp_path, text, field):
    r = _bad(tmp_path, text)
    assert r.returncode == 2, r.stderr
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {field}:"), r.stderr
    assert "(" in lines[0]  # the fix
    assert r.stdout == ""


def test_options_that_need_a_sweep(tmp_path):
    r = run("shaft", SPINDLE, "--out", str(tmp_path / "k.nc"), check=False)
    assert r.returncode == 2 and r.stderr.startswith("error: --out:")
    r = run("shaft", SPINDLE, "--speeds", "0:1000:2", "--out", str(tmp_path / "k.csv"), check=False)
    assert r.returncode == 2 and r.stderr.startswith("error: --out:")
    r = run("shaft", SPINDLE, "--stiffness-at", "2 m", check=False)
    assert r.returncode == 2 and r.stderr.startswith("error: --stiffness-at:")
    for opt in (("--workers", "2"), ("--preloads", "rear=100:200:2"), ("--scheduler", "tcp://127.0.0.1:1")):
        r = run("shaft", SPINDLE, *opt, check=False)
        assert r.returncode == 2 and r.stderr.startswith(f"error: {opt[0]}:"), r.stderr
    r = run("shaft", SPINDLE, "--speeds", "0:1000:2", "--preloads", "tail=100 N:200 N:2", check=False)
    assert r.returncode == 2 and r.stderr.startswith("error: --preloads:") and "rear" in r.stderr, r.stderr
    assert len(r.stderr.strip().splitlines()) == 1
