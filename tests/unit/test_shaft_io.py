"""The shaft-system file reader (bearingsim.io.shaft_system): units parsed into the model, errors naming the
file's fields, preload signs, and the three examples."""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.errors import InputError
from bearingsim.io.shaft_system import load_shaft_system, shaft_system_from_dict, with_probe
from bearingsim.shafts import BearingSupport, HelicalGear, PointLoad, SpringSupport

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _base(**over):
    d = {"type": "shaft_system", "speed": "3000 rpm",
         "sections": [{"length": "100 mm", "outer_diameter": "40 mm"},
                      {"length": "150 mm", "outer_diameter": "50 mm", "inner_diameter": "10 mm"}],
         "supports": [{"name": "a", "position": "20 mm", "bearing": "6208"},
                      {"name": "b", "position": "230 mm", "bearing": "6206"}],
         "loads": [{"type": "force", "position": "120 mm", "fy": "2 kN"}]}
    d.update(over)
    return d


def test_units_parsed_into_the_model():
    sf = shaft_system_from_dict(_base())
    s = sf.system
    assert s.speed == pytest.approx(3000 * math.pi / 30)
    assert s.sections[1].inner_diameter == pytest.approx(0.010)
    assert s.span == pytest.approx((0.0, 0.25))
    assert [sp.position for sp in s.supports] == pytest.approx([0.020, 0.230])
    assert isinstance(s.loads[0], PointLoad) and s.loads[0].force[1] == pytest.approx(2000.0)
    assert sf.stiffness_at is None and sf.tool_tip is None


@settings(max_examples=25, deadline=None)
@given(t=st.floats(-2000.0, 2000.0).filter(lambda v: abs(v) > 1e-3), d=st.floats(20.0, 400.0),
       helix=st.floats(0.0, 40.0))
def test_gear_quantities_reach_the_model(t, d, helix):
    data = _base(loads=[{"type": "helical_gear", "position": "120 mm", "torque": f"{t!r} N*m",
                         "pitch_diameter": f"{d!r} mm", "helix_angle": f"{helix!r} deg"}])
    g = shaft_system_from_dict(data).system.loads[0]
    assert isinstance(g, HelicalGear)
    ft, fr, fa = g.components()
    assert ft == pytest.approx(2 * t / (d * 1e-3))
    assert fa == pytest.approx(abs(ft) * math.tan(math.radians(helix)), abs=1e-9)


def test_spring_support_and_stiffness_keys():
    sups = [{"name": "a", "position": "20 mm", "bearing": "6208"},
            {"name": "s", "position": "230 mm", "stiffness": {"radial": "50 N/um", "tilt": "2 N*m/mrad"}}]
    s = shaft_system_from_dict(_base(supports=sups)).system.supports[1]
    assert isinstance(s, SpringSupport)
    assert s.stiffness[1, 1] == pytest.approx(50e6) and s.stiffness[2, 2] == pytest.approx(50e6)
    assert s.stiffness[3, 3] == pytest.approx(2e3) and s.stiffness[0, 0] == 0.0


@pytest.mark.parametrize("orientation", [1, -1])
def test_preload_sign_follows_orientation(orientation):
    sups = [{"name": "a", "position": "20 mm", "bearing": "7010-15", "orientation": orientation,
             "preload": {"method": "spring", "force": "300 N"}},
            {"name": "b", "position": "230 mm", "bearing": "7010-15", "orientation": -orientation,
             "preload": {"method": "position", "offset": "5 um"}}]
    a, b = shaft_system_from_dict(_base(supports=sups)).system.supports
    assert a.preload_force == pytest.approx(-orientation * 300.0)
    assert b.preload_offset == pytest.approx(orientation * 5e-6)


def test_spring_preload_loads_the_bearing():
    """The spring force given as a positive value is carried by the bearing as its own thrust (a loaded row)."""
    from bearingsim.shafts.solve import solve_shaft

    sups = [{"name": "front", "position": "20 mm", "bearing": "7010-15", "orientation": 1},
            {"name": "rear", "position": "230 mm", "bearing": "7010-15", "orientation": -1,
             "preload": {"method": "spring", "force": "400 N"}}]
    r = solve_shaft(shaft_system_from_dict(_base(supports=sups, loads=[])).system)
    assert r.converged, r.status
    for s in r.supports:
        assert s.bearing_result.loads.fa == pytest.approx(400.0, rel=1e-6), s.name


@pytest.mark.parametrize("change, field", [
    ({"supports": [{"name": "a", "position": "300 mm", "bearing": "6208"},
                   {"name": "b", "position": "230 mm", "bearing": "6206"}]}, "supports[0].position"),
    ({"supports": [{"name": "a", "position": "230 mm", "bearing": "6208"},
                   {"name": "b", "position": "230 mm", "bearing": "6206"}]}, "supports[1].position"),
    ({"supports": [{"name": "a", "position": "20 mm", "bearing": "6208"}]}, "supports"),
    ({"sections": [{"length": "0 mm", "outer_diameter": "40 mm"}]}, "sections[0].length"),
    ({"sections": [{"length": "250 mm", "outer_diameter": "-40 mm"}]}, "sections[0].outer_diameter"),
    ({"loads": [{"type": "helical_gear", "position": "120 mm", "pitch_diameter": "100 mm"}]}, "loads[0].torque"),
    ({"loads": [{"type": "helical_gear", "position": "120 mm", "torque": "0 N*m", "pitch_diameter": "100 mm"}]},
     "loads[0].torque"),
    ({"loads": [{"type": "force", "position": "120 mm", "fy": 2000}]}, "loads[0].fy"),
    ({"loads": [{"type": "torque", "position": "120 mm"}]}, "loads[0].type"),
    ({"speed": "3000 N"}, "speed"),
    ({"colour": "red"}, "colour"),
])
def test_bad_input_names_the_field(change, field):
    with pytest.raises(InputError) as e:
        shaft_system_from_dict(_base(**change))
    assert e.value.field == field, str(e.value)
    assert e.value.fix


def test_probe_adds_a_node_and_refuses_off_the_shaft():
    sf = shaft_system_from_dict(_base())
    p = with_probe(sf, 0.2)
    assert p.stiffness_at == 0.2 and abs(p.system.mesh.nodes - 0.2).min() < 1e-12
    with pytest.raises(InputError) as e:
        with_probe(sf, 0.5)
    assert e.value.field == "--stiffness-at"


@pytest.mark.parametrize("name", ["spindle-milling.toml", "hub-wheel.toml", "gearbox-helical.toml"])
def test_examples_read(name):
    sf = load_shaft_system(EXAMPLES / name)
    assert any(isinstance(s, BearingSupport) for s in sf.system.supports)
    assert sf.stiffness_at is not None


def test_spindle_front_set_has_four_rows():
    sf = load_shaft_system(EXAMPLES / "spindle-milling.toml")
    front = sf.system.supports[0].bearing
    assert [r.orientation for r in front.rows] == [1, 1, -1, -1]
    assert sf.tool_tip == 0.0
