"""``bearingsim clearance`` through the installed console script: the options reach
statics.clearance.OperatingClearance unchanged (JSON vs API), two closed forms of the model, one-line errors."""

import json

import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script

from bearingsim import io
from bearingsim.statics.clearance import OperatingClearance


def test_json_equals_the_api_and_the_screen_shows_um():
    args = ("6208", "--shaft-fit", "15 um", "--housing-fit", "-4", "--temperatures",
            "inner=70 degC, outer=55 degC, reference=20 degC", "--speed", "3000 rpm", "--housing-od", "120 mm")
    d = json.loads(run("clearance", *args, "--json").stdout)
    b = io.load_bearing("6208")
    cond = OperatingClearance(shaft_interference=15e-6, housing_interference=-4e-6, inner_ring_temperature=343.15,
                              outer_ring_temperature=328.15, reference_temperature=293.15, speed=3000 * 3.141592653589793
                              / 30, housing_outside_diameter=0.12)
    ch = cond.change(b)
    row = d["rows"][0]
    for k, v in ch.items():
        assert row[k] == pytest.approx(v, rel=1e-9, abs=1e-15), k
    assert row["diametral_clearance_after_m"] == pytest.approx(b.diametral_clearance
                                                               + ch["diametral_clearance_change_m"], rel=1e-12)
    out = run("clearance", *args).stdout
    assert "operating clearance" in out and f"{row['diametral_clearance_after_m'] * 1e6:.2f}" in out


def test_closed_forms_shaft_fit_and_uniform_temperature():
    """Equal steel, solid shaft: the inner raceway grows by I d / D_i (Harris & Kotzalas 2007 vol. 1 ch. 4); a
    uniform temperature rise of steel rings and balls leaves the clearance unchanged (D_o - D_i - 2 D_w = 0)."""
    b = io.load_bearing("6205")
    d = json.loads(run("clearance", "6205", "--shaft-fit", "20 um", "--json").stdout)["rows"][0]
    di = b.pitch_diameter - b.ball_diameter
    assert d["inner_raceway_fit_m"] == pytest.approx(20e-6 * b.bore / di, rel=1e-9)
    assert d["diametral_clearance_change_m"] == pytest.approx(-20e-6 * b.bore / di, rel=1e-9)
    u = json.loads(run("clearance", "6205", "--temperatures", "inner=80 degC,outer=80 degC,balls=80 degC",
                       "--json").stdout)["rows"][0]
    assert u["inner_raceway_thermal_m"] > 1e-6  # the raceways did grow ...
    assert abs(u["diametral_clearance_change_m"]) < 1e-12  # ... and the clearance did not change


def test_bearing_set_reports_the_preload_change():
    d = json.loads(run("clearance", "skf-7011-cdga-hc-db", "--temperatures", "inner=40 degC,outer=30 degC",
                       "--json").stdout)
    assert len(d["rows"]) == 2 and d["preload_before_N"] is not None
    assert min(d["preload_after_N"]) > max(d["preload_before_N"])  # warmer inner rings: more preload


@pytest.mark.parametrize("args, field", [
    (("--temperatures", "core=70 degC"), "--temperatures"),
    (("--temperatures", "inner=70 kg"), "--temperatures inner"),
    (("--shaft-fit", "15 kN"), "--shaft-fit"),
])
def test_bad_options_are_one_line_exit_2(args, field):
    p = run("clearance", "6208", *args, check=False)
    assert p.returncode == 2 and p.stdout == ""
    assert p.stderr.strip().startswith(f"error: {field}") and "\n" not in p.stderr.strip()


def test_tolerance_classes_use_the_mean_interference():
    from bearingsim.catalogue import fit_interference

    d = json.loads(run("clearance", "6208", "--shaft-fit", "k5", "--housing-fit", "J7", "--json").stdout)
    lo, mean, hi = fit_interference("k5", 0.040, "shaft")
    assert d["conditions"]["shaft_interference"] == pytest.approx(mean, rel=1e-12)
    assert d["tolerance_classes"]["shaft_fit"] == {"class": "k5", "min_m": pytest.approx(lo),
                                                   "mean_m": pytest.approx(mean), "max_m": pytest.approx(hi)}
    assert d["conditions"]["housing_interference"] == pytest.approx(fit_interference("J7", 0.080, "housing")[1])
    p = run("clearance", "6208", "--shaft-fit", "K5", check=False)
    assert p.returncode == 2 and p.stderr.startswith("error: --shaft-fit")
