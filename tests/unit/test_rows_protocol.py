"""The rows protocol (bearingsim.geometry module docstring): every bearing answers ``rows``, ``load_point``
and ``row_vectors()``, and downstream code asks nothing else about its rows."""

import dataclasses
import re
from pathlib import Path

import numpy as np
import pytest

import bearingsim
from bearingsim.contact import hertz
from bearingsim.dynamics.model import build_model
from bearingsim.errors import InputError
from bearingsim.geometry import BallBearing, Row, row_vectors
from bearingsim.io import load_bearing
from bearingsim.lubrication import lubrication_report
from bearingsim.statics import _kernels as kn
from bearingsim.statics import arrangements as ar
from bearingsim.statics import jones_harris as jh
from bearingsim.statics import layout as rl

SRC = Path(bearingsim.__file__).parent


@pytest.fixture(scope="module")
def b7011():
    return load_bearing("skf-7011-cdga-hc")


@pytest.fixture(scope="module")
def mixed_pair(b7011):
    """A DB pair whose second row has other conformities and a steel ball: per-row physics must come from the
    row's own bearing, not from row 0."""
    other = dataclasses.replace(b7011, name="other", inner_conformity=0.515, outer_conformity=0.54,
                                ball_material=b7011.ring_material)
    rows = (Row(b7011, -0.009, 1.0, 2e-6), Row(other, 0.009, -1.0, 2e-6, 0.1))
    return ar.BearingSystem("mixed", rows, load_point=0.003)


def test_single_row_is_one_row_at_the_origin(b7011):
    assert b7011.rows == (Row(b7011),)
    assert b7011.load_point == 0.0
    v = b7011.row_vectors()
    assert v.shape == (1, rl.NPAR)
    # bitwise the vector the kernels always had
    assert np.array_equal(v[0], b7011.row_parameters())


def test_set_vectors_are_the_rows_about_the_load_point(mixed_pair):
    v = mixed_pair.row_vectors()
    assert np.array_equal(v, row_vectors(mixed_pair))
    for k, r in enumerate(mixed_pair.rows):
        assert v[k, rl.P_XROW] == r.position - mixed_pair.load_point
        assert v[k, rl.P_SIGN] == r.orientation
        assert v[k, rl.P_AXOFF] == r.axial_offset
        assert v[k, rl.P_PSI0] == r.first_ball_azimuth
        assert v[k, rl.P_RI] == (r.bearing.inner_conformity - 0.5) * r.bearing.ball_diameter


def test_row_checks_name_the_field(b7011):
    with pytest.raises(InputError, match="rows.orientation"):
        Row(b7011, orientation=0.5)
    with pytest.raises(InputError, match="rows.bearing"):
        Row("skf-7011-cdga-hc")
    with pytest.raises(InputError, match="rows.position"):
        Row(b7011, position=float("nan"))
    with pytest.raises(InputError, match="rows.axial_offset"):
        Row(b7011, axial_offset="2 um")  # a string is refused by name (was a TypeError from math.isfinite)
    assert Row(b7011, orientation=-1).orientation == -1.0 and isinstance(Row(b7011, position=1).position, float)


def test_dynamic_row_extras_read_each_rows_bearing(mixed_pair):
    from bearingsim.dynamics import layout as ly

    m = build_model(mixed_pair, ring_mass=1.0)
    for k, r in enumerate(mixed_pair.rows):
        b, par = r.bearing, m.rows[k]
        assert m.rowx[k, ly.X_EPI] == b.effective_modulus
        assert m.rowx[k, ly.X_RXO] == b.raceway_radii(False)[0]
        # groove-centre circles: the one spelling of bearingsim.statics.layout
        assert m.rowx[k, ly.X_XGI] == rl.inner_groove_centre_axial(par)
        assert m.rowx[k, ly.X_XGO] == rl.outer_groove_centre_axial(par)
        assert m.rowx[k, ly.X_RGO] == rl.outer_groove_centre_radius(par)
    assert m.rowx[0, ly.X_EPI] != m.rowx[1, ly.X_EPI], "the rows' materials differ"


def test_lubrication_reads_each_rows_conformity_and_materials(mixed_pair):
    res = jh.solve(mixed_pair, jh.Loads(fa=2000.0, fr_y=1000.0), speed=500.0)
    assert res.converged
    rep = lubrication_report(res, "iso-vg-68", 333.15)
    rows_seen = set()
    for ball in rep["balls"]:
        b = mixed_pair.rows[ball["row"]].bearing
        for inner, name in ((True, "inner"), (False, "outer")):
            c = ball[name]
            if c is None:
                continue
            rx, ry = hertz.raceway_radii(b.ball_diameter, b.pitch_diameter,
                                         b.inner_conformity if inner else b.outer_conformity,
                                         c["contact_angle_rad"], inner)
            assert (c["rx_m"], c["ry_m"]) == (rx, ry)
            hz = hertz.point_contact_exact(c["load_N"], rx, ry, b.effective_modulus)
            assert c["max_pressure_Pa"] == hz.max_pressure
            rows_seen.add(ball["row"])
    assert rows_seen == {0, 1}


def test_one_series_constant():
    assert kn.series_constant is hertz.series_constant
    ki, ko = 3.1e10, 4.7e10
    np.testing.assert_allclose(hertz.series_constant(ki, ko), (ki ** (-2 / 3) + ko ** (-2 / 3)) ** -1.5, rtol=1e-15,
                               err_msg="Harris & Kotzalas 2007 vol. 1 eq. 7.4")


def test_no_module_asks_for_rows_another_way():
    """Outside geometry.py nobody builds a kernel vector from a bearing by hand or duck-types a bearing for its
    rows: the former spellings (row_parameters, rows_parameters, rows_of, bearing_rows, _effective_modulus) are
    gone from the package."""
    banned = re.compile(r"\.row_parameters\(|rows_parameters|\brows_of\(|\bbearing_rows\(|_effective_modulus\(|"
                        r"getattr\((bearing|brg|b|system|spec), \"rows\"")
    offenders = []
    for p in SRC.rglob("*.py"):
        if p.name == "geometry.py":
            continue
        for i, line in enumerate(p.read_text().splitlines(), 1):
            if banned.search(line):
                offenders.append(f"{p.relative_to(SRC)}:{i}: {line.strip()}")
    assert not offenders, "\n".join(offenders)


def test_any_bearing_type_is_accepted_only_through_the_protocol():
    with pytest.raises(Exception, match="bearing"):
        jh.solve(object(), jh.Loads(fa=100.0))
    assert isinstance(load_bearing("skf-7011-cdga-hc"), BallBearing)
