"""Issue 42, solver side: what a new user hit in the statics (items 3, 4, 8, 12 and 15).

* item 3: a load past what the bearing carries in equilibrium ends with that reason (status 9) and the largest
  fraction of the load that converges, never a NaN state shown as numbers (a 180° contact angle);
* item 4: lift-off is told from a partial load zone: balls unloaded at speed count as lifted off only beyond the
  balls unloaded at rest under the same loads (bearingsim.limits.lift_off_count);
* item 8: the public functions take quantities with units (strings, pint) and convert them at the edge;
* item 12: inputs out of the domain end in an InputError naming the field (or a warning when possible);
* item 15: raceway control "auto" converges where the fixed controls do, with their verdicts.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from _cli import run
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearingsim import limits
from bearingsim.errors import InputError
from bearingsim.io import catalog_names, load_bearing
from bearingsim.statics import jones_harris as jh
from bearingsim.statics.axial import solve_thrust
from bearingsim.statics.layout import STATUS_PAST_CAPACITY

RPM = math.pi / 30.0


# ---- item 3: a load past capacity ---------------------------------------------------------------------------

def test_load_past_capacity_is_named_with_the_load_that_is_carried():
    b = load_bearing("6205")
    r = jh.solve(b, jh.Loads(fr_y=200e3), 1500 * RPM)
    assert not r.converged and r.status_code == STATUS_PAST_CAPACITY
    assert "load past what the bearing can carry in equilibrium" in r.status
    assert "iteration limit" not in r.status
    # no number of the non-equilibrium state: NaN (JSON null), never a 180° contact angle
    assert np.all(np.isnan(r.balls["inner_contact_angle_rad"])) and np.all(np.isnan(r.displacement))
    # the fraction named in the status converges, 1.05 × it does not (the ramp's resolution is 0.04 %)
    frac = float(r.status.split("about ")[1].split(" ×")[0])
    assert 0.0 < frac < 1.0
    assert jh.solve(b, jh.Loads(fr_y=0.99 * frac * 200e3), 1500 * RPM).converged
    assert not jh.solve(b, jh.Loads(fr_y=1.05 * frac * 200e3), 1500 * RPM).converged


def test_cli_load_past_capacity_message():
    p = run("static", "6205", "--fr", "200 kN", "--speed", "1500", check=False)
    assert p.returncode == 1
    assert "load past what the bearing can carry in equilibrium" in p.stdout
    assert "180.0" not in p.stdout and "iteration limit" not in p.stdout


# ---- item 4: lift-off against a partial load zone ------------------------------------------------------------

def test_partial_load_zone_at_speed_is_not_lift_off():
    """6205 under 2 kN radial: 3 of 9 balls loaded at rest and at 1500 rpm alike — a load zone, not lift-off."""
    b = load_bearing("6205")
    rest = jh.solve(b, jh.Loads(fr_y=2000.0), 0.0)
    run_ = jh.solve(b, jh.Loads(fr_y=2000.0), 1500 * RPM)
    assert rest.converged and run_.converged
    n_rest = int(np.sum(rest.balls["inner_load_N"] > 0))
    n_run = int(np.sum(run_.balls["inner_load_N"] > 0))
    assert n_rest < 9 and n_run == n_rest
    assert not any("lift" in w for w in run_.warnings + rest.warnings)


def test_hub_row_load_zone_is_not_lift_off():
    b = load_bearing("hub-seed001")
    r = jh.solve(b, jh.Loads(fa=1890.0, fr_y=3750.0, m_z=1800.0), 1000 * RPM)  # 3 of 32 balls unloaded (12 at rest)
    assert r.converged and np.any(~(r.balls["inner_load_N"] > 0))
    assert not any("lift" in w for w in r.warnings)


def test_lift_off_rule_counts_balls_beyond_the_rest_load_zone():
    assert limits.lift_off_count(6, 6) == 0
    assert limits.lift_off_count(6, 2) == 4
    assert limits.lift_off_count(2, 6) == 0
    np.testing.assert_array_equal(limits.lift_off_count(np.array([3, 5]), np.array([3, 1])), [0, 4])
    # a result at speed with 6 of 9 balls unloaded whose rest equilibrium has all 9 loaded is warned
    b = load_bearing("6205")
    r = jh.solve(b, jh.Loads(fr_y=2000.0), 1500 * RPM)
    w = limits.static_warnings(r, np.full(9, 100.0))
    assert any("6 of 9 balls lifted off the inner raceway" in x for x in w)
    assert not any("lifted off" in x for x in limits.static_warnings(r, r.balls["inner_load_N"]))


def test_map_flags_no_lift_off_for_a_load_zone():
    b = load_bearing("6205")
    out = jh.solve_many(b, np.array([[0.0, 2000.0, 0, 0, 0]] * 3), np.array([0.0, 1500.0, 3000.0]) * RPM)
    assert out.converged.all()
    assert not np.any(out.warning_flags & limits.FLAG_LIFT_OFF)


def test_cli_radial_load_zone_at_speed_has_no_lift_off_warning():
    p = run("static", "6205", "--fr", "2000", "--speed", "1500")
    assert "lift" not in p.stdout


# ---- item 8: quantities with units in the API ----------------------------------------------------------------

def test_solve_takes_strings_and_pint_quantities():
    import pint

    u = pint.UnitRegistry()
    b = load_bearing("6205")
    si = jh.solve(b, jh.Loads(fr_y=2000.0, fa=500.0), speed=1500 * RPM)
    s = jh.solve(b, jh.Loads(fr_y="2 kN", fa="0.5 kN"), speed="1500 rpm")
    q = jh.solve(b, jh.Loads(fr_y=2 * u.kN, fa=500 * u.N), speed=1500 * u.rpm)
    for r in (s, q):
        assert r.converged and r.speed == pytest.approx(157.07963267948966, rel=1e-15)
        np.testing.assert_allclose(r.displacement, si.displacement, rtol=1e-12, atol=1e-18)
    assert jh.Loads(m_z="5 N*m").m_z == 5.0 and jh.Loads(m_y=2 * u.N * u.m).m_y == 2.0
    th = solve_thrust(b, "0.5 kN")
    assert th.axial_stiffness == solve_thrust(b, 500.0).axial_stiffness


@pytest.mark.parametrize("call, field", [
    (lambda b: jh.Loads(fr_y="2 mm"), "fr_y"),
    (lambda b: jh.Loads(m_z="5 N"), "m_z"),
    (lambda b: jh.solve(b, jh.Loads(), speed="2 kN"), "speed"),
    (lambda b: jh.solve(b, jh.Loads(), speed="1500"), "speed"),  # a bare string: the unit is named
    (lambda b: solve_thrust(b, "3 mm"), "fa"),
    (lambda b: jh.solve_many(b, np.zeros((2, 5)), ["1 kN", "2 kN"]), "speeds"),
])
def test_wrong_dimension_names_the_field(call, field):
    with pytest.raises(InputError) as e:
        call(load_bearing("6205"))
    assert e.value.field == field


def test_solve_many_takes_speeds_with_units():
    b = load_bearing("6205")
    ld = np.array([[500.0, 2000.0, 0, 0, 0]] * 2)
    a = jh.solve_many(b, ld, ["1500 rpm", "3000 rpm"])
    c = jh.solve_many(b, ld, np.array([1500.0, 3000.0]) * RPM)
    np.testing.assert_allclose(a.displacement, c.displacement, rtol=1e-12, atol=1e-18)


# ---- item 15: raceway control auto ---------------------------------------------------------------------------

@pytest.mark.parametrize("name, fr, fa, rpm", [
    ("7012-25", 5070.0, 4050.0, 6310.0), ("7217-40", 2080.0, 1950.0, 4054.0),
    ("7212-15", 16500.0, 6300.0, 8451.0), ("7007-15", 540.0, 570.0, 17700.0)])
def test_auto_control_converges_where_the_fixed_controls_do(name, fr, fa, rpm):
    b = load_bearing(name)
    loads = jh.Loads(fa=fa, fr_y=fr)
    fixed = [jh.solve(b, loads, rpm * RPM, c) for c in ("outer", "inner")]
    assert all(r.converged for r in fixed)
    auto = jh.solve(b, loads, rpm * RPM, "auto")
    assert auto.converged, auto.status
    # converged means verified: the balls re-solved from a cold start (their control decided afresh) balance the ring
    assert auto.residual <= jh.TOL_VERIFY * max(fa, fr)


@pytest.mark.parametrize("name, fr, fa, rpm", [("harris-218", 3000.0, 660.0, 4496.0), ("7204-40", 3500.0, 17.0, 6000.0)])
def test_forty_degree_rows_without_axial_load_give_the_reason(name, fr, fa, rpm):
    r = jh.solve(load_bearing(name), jh.Loads(fa=fa, fr_y=fr), rpm * RPM, "auto")
    assert not r.converged and r.status_code == 3, r.status
    assert "add axial load" in r.status


_ANGULAR = [n for n in catalog_names() if n.startswith("7") and "-" in n]


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(_ANGULAR), fr=st.floats(0.02, 0.3), fa=st.floats(0.0, 0.15), v=st.floats(0.05, 0.9))
def test_auto_has_the_verdicts_of_the_fixed_controls(name, fr, fa, v):
    """Over catalogue angular contact rows (radial 2–30 % of C, axial 0–15 %, speed to 0.9 of the limiting speed):
    when both fixed controls converge, auto converges; when neither does, auto does not either."""
    b = load_bearing(name)
    c = b.dynamic_load_rating
    speed = v * (b.limiting_speed or 1000.0)
    loads = jh.Loads(fa=fa * c, fr_y=fr * c)
    outer, inner = (jh.solve(b, loads, speed, k) for k in ("outer", "inner"))
    auto = jh.solve(b, loads, speed, "auto")
    if outer.converged and inner.converged:
        assert auto.converged, (name, auto.status)
    if not outer.converged and not inner.converged:
        assert not auto.converged
        if 3 in (outer.status_code, inner.status_code):
            assert auto.status_code == 3, auto.status


# ---- item 12: inputs out of the domain -----------------------------------------------------------------------

_ROW = """name = "t"
type = "angular_contact"
ball_diameter = "11.5 mm"
ball_count = 17
pitch_diameter = "72.5 mm"
inner_conformity = 0.52
outer_conformity = 0.53
contact_angle = "15 deg"
dynamic_load_rating = "23.4 kN"
ball_material = "bearing_steel"
ring_material = "bearing_steel"
"""


def _file(tmp_path, text, name="b.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


@pytest.mark.parametrize("old, new, field", [
    ('"23.4 kN"', '"1e300 kN"', "dynamic_load_rating"),
    ('ring_material = "bearing_steel"', 'ring_material = "bearing_steel"\nstatic_load_rating = "1e12 kN"',
     "static_load_rating"),
    ('"11.5 mm"', '"11.5 km"', "ball_diameter"),
])
def test_implausible_row_numbers_name_the_field(tmp_path, old, new, field):
    with pytest.raises(InputError) as e:
        load_bearing(str(_file(tmp_path, _ROW.replace(old, new))))
    assert e.value.field == field


@pytest.mark.parametrize("extra, field", [('row_spacing = "5 mm"', "row_spacing"),
                                          ('row_spacing = "1e30 mm"', "row_spacing"),
                                          ('row_spacing = "18 mm"\nload_point = "1e30 mm"', "load_point")])
def test_implausible_set_numbers_name_the_field(tmp_path, extra, field):
    row = _file(tmp_path, _ROW, "row.toml")
    text = f'name = "s"\ntype = "bearing_set"\narrangement = "DB"\nrow = "{row}"\npreload = "100 N"\n{extra}\n'
    with pytest.raises(InputError) as e:
        load_bearing(str(_file(tmp_path, text, "set.toml")))
    assert e.value.field == field


def test_possible_but_implausible_inputs_are_warned(tmp_path):
    wide = load_bearing(str(_file(tmp_path, _ROW + 'diametral_clearance = "0.5 mm"\n')))
    r = jh.solve(wide, jh.Loads(fa=1000.0))
    assert any("diametral clearance 500 µm" in w and "free contact angle" in w for w in r.warnings)
    steep = load_bearing(str(_file(tmp_path, _ROW.replace('"15 deg"', '"88.9 deg"'), "s.toml")))
    r = jh.solve(steep, jh.Loads(fa=1000.0))
    assert any("contact angle" in w and "past 80°" in w for w in r.warnings)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(d=st.floats(1e-3, 1e6), c=st.floats(1e-3, 1e300), c0=st.floats(1e-3, 1e300),
       pd=st.floats(-1e3, 1e3), angle=st.floats(0.0, 89.5))
def test_bearing_file_domain_loads_or_names_a_field(tmp_path, d, c, c0, pd, angle):
    """Over the numbers of a bearing file (ball diameter [mm], C and C0 [kN], clearance [µm], angle [deg]): the
    file either loads and solves, or ends in an InputError naming a field — never another exception."""
    text = (_ROW.replace('"11.5 mm"', f'"{d!r} mm"').replace('"23.4 kN"', f'"{c!r} kN"')
            .replace('"15 deg"', f'"{angle!r} deg"')
            + f'static_load_rating = "{c0!r} kN"\ndiametral_clearance = "{pd!r} um"\n')
    try:
        b = load_bearing(str(_file(tmp_path, text)))
    except InputError as e:
        assert e.field
        return
    r = jh.solve(b, jh.Loads(fa=100.0, fr_y=100.0))
    assert isinstance(r.status, str)
