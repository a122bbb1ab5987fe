"""The ``[rings]`` key of bearing files (issue 16): parsed once in bearingsim.io, honoured by ring_model and by
``static`` through the installed console script."""

import json
from importlib import resources

import numpy as np
import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script

from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.rings.coupling import ring_model, solve
from bearingsim.rings.influence import InfluenceSettings
from bearingsim.rings.spec import RingSpec, Sleeve, model_of, spec_of
from bearingsim.statics.jones_harris import Loads

SRC = (resources.files("bearingsim") / "catalog" / "skf-7011-cdga-hc.toml").read_text()
SLEEVES = '''
[rings]
model = "fe"
[rings.housing]
outer_diameter = "120 mm"
youngs_modulus = "72 GPa"
poisson_ratio = 0.33
[rings.shaft]
inner_diameter = "20 mm"
material = "bearing_steel"
'''


def _coarse(b):
    wall = 0.5 * (b.pitch_diameter - b.ball_diameter - b.bore)
    return InfluenceSettings(sigma=wall / 4, n_through=4, n_axial=8, ghat_min=1e-3, decay_min=1e-3)


def test_file_sleeves_equal_the_api_sleeves(tmp_path, monkeypatch):
    monkeypatch.setenv("BEARINGSIM_RING_CACHE", str(tmp_path / "cache"))
    p = tmp_path / "b.toml"
    p.write_text(SRC + SLEEVES)
    bf = load_bearing(p)
    spec = spec_of(bf)
    assert isinstance(spec, RingSpec) and model_of(bf) == "fe"
    assert spec.housing == Sleeve(0.12, 72e9, 0.33, False, "user input")
    assert spec.shaft.diameter == 0.02 and spec.shaft.youngs_modulus == 208e9
    b = load_bearing("skf-7011-cdga-hc")
    assert spec_of(b) is None and model_of(b) == "rigid"
    st = _coarse(b)
    from_file = ring_model(bf, settings=st)  # computed and written to the cache
    # the same sleeves through the API: the same inputs (hash of section, sleeve material, settings), read back
    api = ring_model(b, settings=st, housing=Sleeve(0.12, 72e9, 0.33), shaft=Sleeve(0.02, 208e9, 0.3))
    assert not from_file.description["rows"][0]["cached"] and api.description["rows"][0]["cached"]
    default = ring_model(b, settings=st, cache=False)
    for (fi, fo), (ai, ao), (di, do) in zip(from_file.rows, api.rows, default.rows):
        assert fi.key == ai.key and fo.key == ao.key and fi.key != di.key and fo.key != do.key
        np.testing.assert_array_equal(fo.coeffs, ao.coeffs)
    # an aluminium housing of OD 120 mm is softer than the default steel housing of 1.5 D = 135 mm: the outer
    # ring's radial self-compliance grows
    assert from_file.rows[0][1].coeffs[0, 0, 0] > 1.1 * default.rows[0][1].coeffs[0, 0, 0]
    loads = Loads(fa=2000.0, fr_y=1000.0)
    rf, ra = solve(bf, loads, rings=from_file), solve(b, loads, rings=api)
    assert rf.converged and ra.converged
    np.testing.assert_array_equal(rf.displacement, ra.displacement)
    np.testing.assert_array_equal(rf.stiffness, ra.stiffness)


def test_rigid_seat_and_solid_shaft(tmp_path):
    p = tmp_path / "b.toml"
    p.write_text(SRC + '[rings]\nmodel = "fe"\n[rings.housing]\nrigid = true\n[rings.shaft]\ninner_diameter = "0 mm"\n')
    spec = spec_of(load_bearing(p))
    assert spec.housing.rigid and spec.shaft.diameter == 0.0
    from bearingsim.rings.section import estimate_sections

    inner, outer = estimate_sections(load_bearing("skf-7011-cdga-hc"), housing=spec.housing, shaft=spec.shaft)
    assert outer.sleeve_radius is None and inner.sleeve_radius == pytest.approx(0.25 * 0.0275)


@pytest.mark.parametrize(("text", "field"), [
    ('[rings]\nmodel = "fem"\n', "rings.model"),
    ('[rings]\nmodels = "fe"\n', "rings.models"),
    ('[rings]\nmodel = "fe"\n[rings.housing]\nouter_diameter = "120"\n', "rings.housing.outer_diameter"),
    ('[rings]\nmodel = "fe"\n[rings.housing]\nouter_diameter = "12 N"\n', "rings.housing.outer_diameter"),
    ('[rings]\nmodel = "fe"\n[rings.housing]\nouter_diameter = "80 mm"\n', "rings.housing.outer_diameter"),
    ('[rings]\nmodel = "fe"\n[rings.shaft]\ninner_diameter = "60 mm"\n', "rings.shaft.inner_diameter"),
    ('[rings]\nmodel = "fe"\n[rings.shaft]\nouter_diameter = "10 mm"\n', "rings.shaft.outer_diameter"),
    ('[rings]\nmodel = "fe"\n[rings.shaft]\ninner_diameter = "10 mm"\nmaterial = "cheese"\n',
     "rings.shaft.material"),
    ('[rings]\nmodel = "fe"\n[rings.shaft]\ninner_diameter = "10 mm"\npoisson_ratio = 0.6\n',
     "rings.shaft.poisson_ratio"),
    ('[rings]\nmodel = "fe"\n[rings.outer_ring]\noutside_diameter = "100 mm"\n', "rings.outer_ring"),
])
def test_bad_rings_table(tmp_path, text, field):
    p = tmp_path / "b.toml"
    p.write_text(SRC + text)
    with pytest.raises(InputError) as e:
        load_bearing(p)
    assert e.value.field == field


def test_static_takes_the_file_model_and_the_option_overrides_it(tmp_path):
    p = tmp_path / "fe.toml"
    p.write_text(SRC + '[rings]\nmodel = "fe"\n')  # default seats: the coefficients of `static --rings fe`
    from_file = json.loads(run("static", str(p), "--fa", "3 kN", "--json").stdout)
    option = json.loads(run("static", "skf-7011-cdga-hc", "--fa", "3 kN", "--rings", "fe", "--json").stdout)
    rigid = json.loads(run("static", str(p), "--fa", "3 kN", "--rings", "rigid", "--json").stdout)
    assert from_file["rings"]["model"] == "fe" and rigid["rings"]["model"] == "rigid"
    assert from_file["axial_stiffness_N_per_m"] == option["axial_stiffness_N_per_m"]
    assert rigid["axial_stiffness_N_per_m"] > 1.05 * from_file["axial_stiffness_N_per_m"]


def test_bad_rings_key_is_one_line(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text(SRC + '[rings]\nmodel = "fe"\n[rings.housing]\nouter_diameter = "120"\n')
    r = run("static", str(p), "--fa", "3 kN", check=False)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert "rings.housing.outer_diameter" in r.stderr


def test_hub_file_gives_the_shared_ring_dimensions():
    """examples/hub-rings.toml: the [rings] table of an arrangement file (unit dimensions, knuckle, solid shaft)
    reaches the sections of the shared outer ring and of the inner rings; nothing is then estimated."""
    from pathlib import Path

    from bearingsim.rings.shared import estimate_unit

    hub = load_bearing(Path(__file__).parents[2] / "examples" / "hub-rings.toml")
    spec = spec_of(hub)
    assert model_of(hub) == "fe" and spec.outer_ring == (0.084, 0.042) and spec.inner_rings == (0.04, 0.0182)
    inners, outer, notes = estimate_unit(hub, spec, housing=spec.housing, shaft=spec.shaft)
    assert notes["estimated"] == []
    assert outer.seat_radius == 0.042 and outer.z_faces == pytest.approx((-0.021, 0.021))
    assert outer.sleeve_radius == 0.06 and outer.sleeve_youngs_modulus == 70e9 and outer.sleeve_poisson_ratio == 0.33
    for i in inners:
        assert i.seat_radius == 0.02 and i.half_width == pytest.approx(0.0091)
        assert i.sleeve_radius == pytest.approx(0.25 * 0.02)  # solid shaft: the rigid-core stand-in
    with pytest.raises(InputError) as e:  # a hub's housing inside its outer ring
        from bearingsim.io.bearing import bearing_from_dict, resolve_bearing_data

        data = resolve_bearing_data(Path(__file__).parents[2] / "examples" / "hub-rings.toml")
        data["rings"]["housing"]["outer_diameter"] = "80 mm"
        bearing_from_dict(data)
    assert e.value.field == "rings.housing.outer_diameter"


def test_map_bad_ring_model_is_one_line(tmp_path):
    r = run("map", "skf-7011-cdga-hc", "--fa", "1 kN:2 kN:2", "--rings", "soft", "--out", str(tmp_path / "m.nc"),
            check=False)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "--rings" in r.stderr
    assert not (tmp_path / "m.nc").exists()
