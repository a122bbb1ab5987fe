"""Plausibility of inputs (issue 11 item 5, input side): impossible values are refused, file fields need units.

Before: bare numbers in a bearing file were read as metres or pascals (all lengths bare gave a 72.5 m
bearing, exit 0); E = 1 Pa, 0.03-nm balls, a 1.9 km pitch circle, negative bore/width/dynamic_load_rating
were accepted; an angular-contact file with 5 mm clearance was accepted and then failed to converge;
ball_count 10¹² and a grid COUNT of 10¹¹ were not refused before allocating.  The bounds are the table in
bearingsim.geometry's docstring.
"""

from __future__ import annotations

import json
import math
import shutil
import subprocess
import time
import tracemalloc

import pytest

from bearingsim import geometry, io, materials
from bearingsim.errors import InputError
from bearingsim.sweep import MAX_GRID_POINTS, check_grid_size, parse_grid

BASE = {
    "name": "7011-like", "type": "angular_contact", "ball_diameter": "10.319 mm", "ball_count": 21,
    "pitch_diameter": "72.5 mm", "inner_conformity": 0.52, "outer_conformity": 0.53, "contact_angle": "15 deg",
    "ball_material": "silicon_nitride", "ring_material": "bearing_steel", "bore": "55 mm",
    "outside_diameter": "90 mm", "width": "18 mm", "dynamic_load_rating": "20 kN",
}


def build(**kw):
    d = dict(BASE)
    for k, v in kw.items():
        if v is None:
            d.pop(k, None)
        else:
            d[k] = v
    return io.bearing_from_dict(d)


def refused(field: str, **kw) -> InputError:
    with pytest.raises(InputError) as info:
        build(**kw)
    exc = info.value
    assert exc.field == field, str(exc)
    assert exc.fix and "\n" not in str(exc)
    return exc


def test_base_builds():
    b = build()
    assert b.pitch_diameter == pytest.approx(72.5e-3, rel=1e-12) and b.ball_count == 21


# ---- units required on every dimensional field of a file ---------------------------------------
BARE = [("ball_diameter", 10.319, "mm"), ("pitch_diameter", 72.5, "mm"), ("bore", 55, "mm"),
        ("outside_diameter", 90.0, "mm"), ("width", 18, "mm"), ("dynamic_load_rating", 20000, "N"),
        ("contact_angle", 15, "deg"), ("diametral_clearance", 0.01, "mm")]


@pytest.mark.parametrize("key, value, unit", BARE)
def test_bare_number_in_a_file_names_the_unit_to_add(key, value, unit):
    exc = refused(key, **{key: value})
    assert "no unit" in exc.problem and f'"{value} {unit}"' in exc.fix


def test_all_lengths_bare_is_refused_not_a_72_m_bearing(write_toml):
    text = "\n".join([
        'name = "bare"', 'type = "angular_contact"', "ball_diameter = 10.319", "ball_count = 21",
        "pitch_diameter = 72.5", "inner_conformity = 0.52", "outer_conformity = 0.53", 'contact_angle = "15 deg"',
        'ball_material = "silicon_nitride"', 'ring_material = "bearing_steel"'])
    with pytest.raises(InputError) as info:
        io.load_bearing(write_toml(text))
    assert info.value.field == "ball_diameter" and "mm" in info.value.fix


def test_bare_modulus_and_density_in_a_material_table():
    with pytest.raises(InputError) as info:
        build(ring_material={"youngs_modulus": 208e9, "poisson_ratio": 0.3, "density": "7850 kg/m^3"})
    assert info.value.field == "ring_material.youngs_modulus" and "GPa" in info.value.fix
    with pytest.raises(InputError) as info:
        build(ring_material={"youngs_modulus": "208 GPa", "poisson_ratio": 0.3, "density": 7850})
    assert info.value.field == "ring_material.density"


def test_dimensionless_fields_stay_bare_and_zero_needs_no_unit():
    b = build(inner_conformity=0.52, ball_count=21, diametral_clearance=0,
              ring_material={"youngs_modulus": "208 GPa", "poisson_ratio": 0.3, "density": "7850 kg/m^3"})
    assert b.ring_material.poisson_ratio == 0.3 and b.diametral_clearance == 0.0


def test_bundled_catalogue_and_examples_load():
    for name in io.catalog_names():
        io.load_bearing(name)


# ---- impossible values --------------------------------------------------------------------------
IMPOSSIBLE = [
    ("ball_diameter", dict(ball_diameter="0.03 nm")),
    ("ball_diameter", dict(ball_diameter="0.4 mm", pitch_diameter="3 mm", bore=None, outside_diameter=None,
                           width=None, ball_count=8)),
    ("ball_diameter", dict(ball_diameter="210 mm", pitch_diameter="2 m", bore=None, outside_diameter=None,
                           width=None)),
    ("pitch_diameter", dict(pitch_diameter="1.9 km", bore=None, outside_diameter=None)),
    ("bore", dict(bore="-55 mm")),
    ("width", dict(width="-18 mm")),
    ("width", dict(width="5 mm")),  # narrower than the balls
    ("outside_diameter", dict(outside_diameter="-90 mm")),
    ("dynamic_load_rating", dict(dynamic_load_rating="-20 kN")),
    ("ring_material.youngs_modulus", dict(ring_material={"youngs_modulus": "1 Pa", "poisson_ratio": 0.3,
                                                         "density": "7850 kg/m^3"})),
    ("ring_material.youngs_modulus", dict(ring_material={"youngs_modulus": "2000 GPa", "poisson_ratio": 0.3,
                                                         "density": "7850 kg/m^3"})),
    ("ring_material.poisson_ratio", dict(ring_material={"youngs_modulus": "208 GPa", "poisson_ratio": -0.1,
                                                        "density": "7850 kg/m^3"})),
    ("ring_material.density", dict(ring_material={"youngs_modulus": "208 GPa", "poisson_ratio": 0.3,
                                                  "density": "7.85 kg/m^3"})),  # g/cm³ slip
    ("ball_count", dict(ball_count=2)),
    ("ball_count", dict(ball_count=10**12)),
    ("diametral_clearance", dict(diametral_clearance="5 mm")),
]


@pytest.mark.parametrize("field, kw", IMPOSSIBLE, ids=[f"{f}-{i}" for i, (f, _) in enumerate(IMPOSSIBLE)])
def test_impossible_value_is_refused(field, kw):
    refused(field, **kw)


def test_ball_count_of_a_trillion_is_refused_before_allocating():
    tracemalloc.start()
    t0 = time.perf_counter()
    try:
        with pytest.raises(InputError) as info:
            build(ball_count=10**12)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert info.value.field == "ball_count"
    assert time.perf_counter() - t0 < 1.0 and peak < 5e6, f"peak {peak} bytes"


def test_material_bounds_at_the_edges():
    lo, hi = materials.LIMITS["youngs_modulus"]
    materials.Material("m", lo, 0.3, 7850.0)
    materials.Material("m", hi, 0.3, 7850.0)
    with pytest.raises(InputError):
        materials.Material("m", lo * 0.999, 0.3, 7850.0)
    with pytest.raises(InputError):
        materials.Material("m", hi * 1.001, 0.3, 7850.0)


# ---- clearance bound from the groove geometry ------------------------------------------------------
@pytest.mark.parametrize("alpha0_deg", [0.0, 15.0, 25.0, 40.0])
def test_clearance_bound_is_the_80_degree_free_contact_angle(alpha0_deg):
    """P_d,max = 2A(cos α₀ − cos 80°): with that clearance taken up, cos α_f = cos α₀ − P_d/(2A) = cos 80°."""
    d, fi, fo = 10.319e-3, 0.52, 0.53
    big_a = (fi + fo - 1.0) * d
    pd_max = 2.0 * big_a * (math.cos(math.radians(alpha0_deg)) - math.cos(math.radians(80.0)))
    kind = "deep_groove" if alpha0_deg == 0.0 else "angular_contact"
    extra = {"type": kind, "contact_angle": None if kind == "deep_groove" else f"{alpha0_deg} deg"}
    b = build(diametral_clearance=f"{pd_max * 0.999 * 1e6} um", **extra)
    alpha_f = math.acos(math.cos(b.contact_angle) - b.diametral_clearance / (2 * b.total_curvature_distance))
    assert math.degrees(alpha_f) == pytest.approx(80.0, abs=0.1) and alpha_f < math.radians(80.0)
    exc = refused("diametral_clearance", diametral_clearance=f"{pd_max * 1.001 * 1e6} um", **extra)
    assert "80" in exc.problem


def test_deep_groove_contact_angle_and_clearance_share_the_bound():
    build(type="deep_groove", contact_angle="79.9 deg")
    refused("diametral_clearance", type="deep_groove", contact_angle="80.1 deg")


# ---- grids ----------------------------------------------------------------------------------------
def test_grid_count_is_bounded_before_allocation():
    t0 = time.perf_counter()
    with pytest.raises(InputError) as info:
        parse_grid("0:1000:100000000000", "force", "--fa")
    assert info.value.field == "--fa" and time.perf_counter() - t0 < 0.5
    for bad in ("0:1000:1e3", "0:1000:10**11", "0:1000:-5", "0:1000:2.5"):
        with pytest.raises(InputError):
            parse_grid(bad, "force", "--fa")
    assert parse_grid("0:1000:3", "force", "--fa").tolist() == [0.0, 500.0, 1000.0]


def test_total_grid_size_is_bounded():
    assert check_grid_size((10_000, 10_000)) == MAX_GRID_POINTS
    with pytest.raises(InputError, match="points"):
        check_grid_size((10_000, 10_000, 2))


# ---- the command line keeps its bare-number convention; files do not ------------------------------
BIN = shutil.which("bearingsim")


def _cli(*args, timeout=180):
    p = subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, timeout=timeout)
    return p.returncode, p.stdout, p.stderr


def test_cli_bare_numbers_are_newtons_and_rpm():
    """README: "bare numbers: N, N·m, rpm" for the load/speed options."""
    c1, out1, err1 = _cli("static", "skf-7011-cdga-hc", "--fa", "3000", "--speed", "11200", "--json")
    c2, out2, err2 = _cli("static", "skf-7011-cdga-hc", "--fa", "3 kN", "--speed", "11200 rpm", "--json")
    assert c1 == 0 and c2 == 0, err1 + err2
    d1, d2 = json.loads(out1), json.loads(out2)
    assert d1["displacement"] == d2["displacement"]


@pytest.mark.parametrize("args", [["--fa", "9**9**9 N"]])  # the other hostile strings: test_units.py
def test_cli_hostile_quantity_is_one_line_exit_2(args):
    t0 = time.perf_counter()
    code, out, err = _cli("static", "skf-7011-cdga-hc", *args, timeout=60)
    text = (out + err).strip()
    assert code == 2 and len(text.splitlines()) == 1 and "Traceback" not in text, text
    assert time.perf_counter() - t0 < 30


def test_cli_bare_file_and_huge_grid(tmp_path):
    bad = tmp_path / "bare.toml"
    bad.write_text('name = "b"\nball_diameter = 10.319\nball_count = 21\npitch_diameter = 72.5\n'
                   'inner_conformity = 0.52\nouter_conformity = 0.53\ncontact_angle = "15 deg"\n'
                   'ball_material = "silicon_nitride"\nring_material = "bearing_steel"\n')
    code, out, err = _cli("static", bad, "--fa", "1000")
    text = (out + err).strip()
    assert code == 2 and len(text.splitlines()) == 1 and "ball_diameter" in text and "mm" in text, text
    code, out, err = _cli("map", "skf-7011-cdga-hc", "--fa", "0:1000:100000000000", "--out", tmp_path / "m.nc")
    text = (out + err).strip()
    assert code == 2 and len(text.splitlines()) == 1 and "COUNT" in text, text
    assert not (tmp_path / "m.nc").exists()


def test_geometry_limits_table_matches_the_code():
    doc = geometry.__doc__
    assert "0.5 mm – 200 mm" in doc and geometry.LIMITS["ball_diameter"] == (0.5e-3, 0.2)
    assert "3 – 1000" in doc and geometry.LIMITS["ball_count"] == (3, 1000)
    assert "1.5 mm – 10 m" in doc and geometry.LIMITS["pitch_diameter"] == (1.5e-3, 10.0)
    assert "1 GPa – 1000 GPa" in doc and materials.LIMITS["youngs_modulus"] == (1e9, 1e12)


# ---- case files: sizes that would allocate or run without end ----------------------------------------
CASE = {"bearing": "skf-7011-cdga-hc", "speed": "1000 rpm", "duration": "1 ms", "output_interval": "0.1 ms",
        "traction": "none"}


@pytest.mark.parametrize("upd, field", [
    (dict(duration="1e300 s", output_interval="1e-300 s"), "output_interval"),  # int(round(inf)) raised
    (dict(duration="1000 s", output_interval="1 us"), "output_interval"),  # 10⁹ samples
    (dict(chunk=10**12), "chunk"),
    (dict(chunk=True), "chunk"),
    (dict(n_slices=True), "n_slices"),
    (dict(duration=0.02), "duration"),  # bare number in a case file
    (dict(loads={"fa": 3000}), "loads.fa"),  # also inside the [loads] table (parsed by dynamics.loads)
    (dict(gravity=[0, 0, -9.81]), "gravity[2]"),
    (dict(inner_ring={"mass": 2}), "inner_ring.mass"),
])
def test_case_file_limits_and_units(upd, field):
    from bearingsim.dynamics.case import case_from_dict

    with pytest.raises(InputError) as info:
        case_from_dict(CASE | upd)
    assert info.value.field == field and info.value.fix


def test_case_file_at_the_sample_limit_builds():
    from bearingsim.dynamics.case import MAX_SAMPLES, case_from_dict

    c = case_from_dict(CASE | dict(duration=f"{MAX_SAMPLES * 1e-6} s", output_interval="1 us"))
    assert c.n_samples == MAX_SAMPLES
