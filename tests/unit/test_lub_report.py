"""Tests of the lubrication report (orchestration), the traction-curve function and the CLI commands."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from bearingsim.cli.lubrication import register
from bearingsim.contact import ehl, hertz
from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.lubricants import get_lubricant
from bearingsim.lubrication import lubrication_report, traction_vs_slide_roll
from bearingsim.statics.jones_harris import Loads, solve


@pytest.fixture(scope="module")
def hub_result():
    b = load_bearing("hub-seed001-row")
    return solve(b, Loads(fa=3000.0, fr_y=1000.0), 1000 * math.pi / 30)


def test_report_entrainment_and_film(hub_result):
    rep = lubrication_report(hub_result, "hub-grease-base-oil", 333.15, 0.1e-6)
    b = hub_result.bearing
    lub = get_lubricant("hub-grease-base-oil")
    eta0 = lub.dynamic_viscosity(333.15)
    omega = hub_result.speed
    assert rep["balls"], "some balls are loaded"
    for bl in rep["balls"]:
        j = bl["index"]
        wm = hub_result.balls["orbital_speed_rad_s"][j]
        for name, inner in (("inner", True), ("outer", False)):
            e = bl[name]
            alpha = e["contact_angle_rad"]
            # Jones kinematics: pure rolling at the contact centre, race speed relative to the cage
            r = 0.5 * (b.pitch_diameter - b.ball_diameter * math.cos(alpha)) if inner else \
                0.5 * (b.pitch_diameter + b.ball_diameter * math.cos(alpha))
            u = abs(omega - wm) * r if inner else abs(wm) * r
            assert e["entrainment_speed_m_s"] == pytest.approx(u, rel=1e-9)
            assert e["centre_sliding_speed_m_s"] < 1e-9 * u or not (hub_result.balls["inner_control"][j] == inner)
            rx, ry = hertz.raceway_radii(b.ball_diameter, b.pitch_diameter,
                                         b.inner_conformity if inner else b.outer_conformity, alpha, inner)
            assert (e["rx_m"], e["ry_m"]) == (pytest.approx(rx, rel=1e-12), pytest.approx(ry, rel=1e-12))
            hc, hm = ehl.film_thickness(u, e["load_N"], eta0, lub.pressure_viscosity_coefficient, b.effective_modulus,
                                        rx, ry, thermal_factor=e["thermal_factor"])
            assert e["central_film_m"] == pytest.approx(hc, rel=1e-9)
            assert e["film_parameter"] == pytest.approx(hm / 0.1e-6, rel=1e-9)
            assert e["power_loss_W"] >= 0 and e["traction_coefficient"] >= 0
    assert rep["total_power_loss_W"] > 0


def test_report_bad_input(hub_result):
    with pytest.raises(InputError, match="temperature"):
        lubrication_report(hub_result, "iso-vg-68", 200.0)
    with pytest.raises(InputError, match="roughness"):
        lubrication_report(hub_result, "iso-vg-68", 333.15, -1e-7)
    with pytest.raises(InputError, match="n_slices"):
        lubrication_report(hub_result, "iso-vg-68", 333.15, n_slices=0)


def test_traction_curve_shapes():
    e = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
    rx, ry = hertz.raceway_radii(0.0111, 0.061, 0.52, math.radians(35), True)
    s = np.linspace(0, 0.05, 51)
    mu = traction_vs_slide_roll("iso-vg-68", 333.15, 2000.0, rx, ry, e, 5.0, s)
    assert mu[0] == 0.0
    assert 0.02 < mu.max() < 0.08  # typical EHL traction of mineral oil
    # the four-parameter curve option reproduces its defining points (seed 001 Fig. 4 shape)
    mu_c = traction_vs_slide_roll("iso-vg-68", 333.15, 2000.0, rx, ry, e, 5.0, [0.0, 0.01, 10.0],
                                  fluid_model="curve", fluid_curve=(0.0, 0.06, 0.01, 0.045))
    np.testing.assert_allclose(mu_c, [0.0, 0.06, 0.045], atol=1e-12)
    # boundary model: depends on s only, not on speed
    m1 = traction_vs_slide_roll("iso-vg-68", 333.15, 2000.0, rx, ry, e, 1.0, s, model="boundary")
    m2 = traction_vs_slide_roll("iso-vg-68", 333.15, 500.0, rx, ry, e, 20.0, s, model="boundary")
    np.testing.assert_allclose(m1, m2, rtol=1e-12, atol=1e-15)


def test_physical_fluid_curve_has_the_seed_fig4_shape():
    """Seed 001 Fig. 4 (shape only; its conditions are not given): μ rises from 0 over s ~ 1e-4 - 1e-3, peaks near
    s = 0.005 - 0.015 and falls slowly.  The rise comes from the film's elasticity (Johnson & Tevaarwerk 1977), the
    fall from shear heating; at 20 m/s both lie in the seed's range."""
    e = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
    rx, ry = hertz.raceway_radii(0.0111, 0.061, 0.52, math.radians(35), True)
    s = np.geomspace(1e-5, 0.1, 121)
    for lub, q in (("iso-vg-68", 2000.0), ("hub-grease-base-oil", 5000.0)):
        mu = traction_vs_slide_roll(lub, 333.15, q, rx, ry, e, 20.0, s)
        i = int(np.argmax(mu))
        assert 0.005 <= s[i] <= 0.02, (lub, s[i])
        assert mu[-1] < 0.95 * mu[i]
        assert mu[0] < 0.05 * mu[i]  # no Coulomb-like jump at s -> 0
        assert np.all(np.diff(mu[: i + 1]) > 0)


def _app():
    app = typer.Typer()
    register(app)
    return app


def test_cli_lubrication_json_and_errors():
    runner = CliRunner()
    r = runner.invoke(_app(), ["lubrication", "hub-seed001-row", "--fa", "3000 N", "--fr", "1000", "--speed",
                               "1000 rpm", "--lubricant", "hub-grease-base-oil", "--temperature", "60 degC",
                               "--roughness", "0.05 um", "--json"])
    assert r.exit_code == 0, r.output
    d = json.loads(r.output)
    e = d["balls"][0]["inner"]
    for key in ("load_N", "entrainment_speed_m_s", "rx_m", "ry_m", "central_film_m", "minimum_film_m",
                "film_parameter", "regime", "traction_coefficient", "power_loss_W"):
        assert key in e
    assert d["roughness_m"] == pytest.approx(0.05e-6)
    r = runner.invoke(_app(), ["lubrication", "hub-seed001-row", "--fa", "3000 N", "--speed", "1000 rpm",
                               "--temperature", "-60 degC"])
    assert isinstance(r.exception, InputError)
    r = runner.invoke(_app(), ["lubrication", "hub-seed001-row", "--fa", "3000 N", "--speed", "1000 rpm",
                               "--slices", "0"])
    assert isinstance(r.exception, InputError)


def test_cli_lubricants_lists_library():
    r = CliRunner().invoke(_app(), ["lubricants", "--json"])
    assert r.exit_code == 0, r.output
    d = json.loads(r.output)
    assert {"iso-vg-68", "hub-grease-base-oil", "mil-prf-23699"} <= set(d)
    r = CliRunner().invoke(_app(), ["lubricants"])
    assert r.exit_code == 0 and "iso-vg-68" in r.output


def test_physical_fluid_curve_fast_path():
    from bearingsim.lubrication import physical_fluid_curve

    e = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
    rx, ry = hertz.raceway_radii(0.0111, 0.061, 0.52, math.radians(35), True)
    mu0, mu_max, s_max, mu_inf = physical_fluid_curve("iso-vg-68", 333.15, 2000.0, rx, ry, e, 20.0)
    assert mu0 == 0.0 and 0 < mu_inf < mu_max and 0 < s_max < 0.3
    phys = traction_vs_slide_roll("iso-vg-68", 333.15, 2000.0, rx, ry, e, 20.0, [s_max, 0.3])
    fit = traction_vs_slide_roll("iso-vg-68", 333.15, 2000.0, rx, ry, e, 20.0, [s_max, 1e3], fluid_model="curve",
                                 fluid_curve=(mu0, mu_max, s_max, mu_inf))
    assert fit[0] == pytest.approx(phys[0], rel=1e-9)  # the peak is reproduced
    assert fit[1] == pytest.approx(mu_inf, rel=1e-9)


@pytest.mark.parametrize("slices", ["1000006", "2000007"])
def test_console_script_refuses_strip_counts_that_are_other_rules_codes(slices):
    """The kernel reads SPLIT_BASE + n and LOG_BASE + n as its other quadrature rules: a strip count there would
    silently change the rule, so the installed console script refuses it in one line naming the option (exit 2)."""
    from _cli import run

    p = run("lubrication", "hub-seed001-row", "--fa", "3000 N", "--speed", "1000 rpm", "--slices", slices, check=False)
    assert p.returncode == 2, p.stderr
    lines = [ln for ln in p.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "--slices" in lines[0] and "Traceback" not in p.stderr, p.stderr


def test_library_entries_refuse_strip_counts_that_are_other_rules_codes():
    from bearingsim.contact.slices import LOG_BASE, SPLIT_BASE, STRIPS_MAX

    b = load_bearing("hub-seed001-row")
    res = solve(b, Loads(fa=3000.0), 1000 * math.pi / 30)
    for n in (SPLIT_BASE + 6, LOG_BASE + 7, STRIPS_MAX + 1):
        with pytest.raises(InputError) as e:
            lubrication_report(res, "hub-grease-base-oil", 333.15, n_slices=n)
        assert e.value.field == "n_slices"
    with pytest.raises(InputError) as e:
        traction_vs_slide_roll("iso-vg-68", 333.15, 1000.0, 0.005, 0.05, 2.3e11, 2.0, [0.01], n_slices=LOG_BASE + 7)
    assert e.value.field == "n_slices"
