"""Operating clearance (statics/clearance.py): Lamé closed forms, thermal and centrifugal limits."""

import dataclasses
import math

import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.io import bearing_from_dict, load_bearing
from bearingsim.statics import arrangements as ar
from bearingsim.statics import clearance as cl


def test_inner_ring_on_solid_shaft_equal_materials():
    # equal materials, solid shaft: raceway expansion = I d / D_i (Harris & Kotzalas vol. 1 ch. 4)
    e, nu = 208e9, 0.3
    i, d, di = 20e-6, 0.055, 0.0622
    p = cl.fit_pressure_shaft(i, d, 0.0, di, e, nu, e, nu)
    np.testing.assert_allclose(cl.inner_raceway_expansion(p, d, di, e), i * d / di, rtol=1e-12)
    # Lamé pressure for equal materials and a solid shaft: p = E I (D_i^2 - d^2) / (2 d D_i^2)
    np.testing.assert_allclose(p, e * i * (di**2 - d**2) / (2 * d * di**2), rtol=1e-12)


def test_outer_ring_in_housing_equal_materials():
    e, nu = 208e9, 0.3
    i, dout, dh, do = 15e-6, 0.09, 0.14, 0.0828
    p = cl.fit_pressure_housing(i, dout, dh, do, e, nu, e, nu)
    expect = i * (do / dout) * (1 - (dout / dh) ** 2) / (1 - (do / dh) ** 2)
    np.testing.assert_allclose(cl.outer_raceway_contraction(p, dout, do, e), expect, rtol=1e-12,
                               err_msg="Harris & Kotzalas vol. 1 ch. 4, outer ring in a housing")


def test_centrifugal_expansion_thin_ring_limit_and_scaling():
    rho, e, nu = 7850.0, 208e9, 0.3
    b = 0.03
    w = 1000.0
    thin = cl.centrifugal_expansion(w, 2 * b * (1 - 1e-6), 2 * b, rho, e, nu)
    np.testing.assert_allclose(thin, 2 * rho * w**2 * b**3 / e, rtol=1e-5, err_msg="thin ring: u = rho w^2 r^3 / E")
    np.testing.assert_allclose(cl.centrifugal_expansion(2 * w, 0.04, 0.06, rho, e, nu),
                               4 * cl.centrifugal_expansion(w, 0.04, 0.06, rho, e, nu), rtol=1e-12)


def test_uniform_heating_scales_clearance():
    b = load_bearing("skf-7011-cdga-hc")
    a = 11.5e-6
    oc = cl.OperatingClearance(inner_ring_temperature=353.15, outer_ring_temperature=353.15,
                               ball_temperature=353.15, ring_expansion=a, ball_expansion=a)
    ch = oc.change(b)
    dw, dm = b.ball_diameter, b.pitch_diameter
    np.testing.assert_allclose(ch["diametral_clearance_change_m"], a * 60 * ((dm + dw) - (dm - dw) - 2 * dw),
                               atol=1e-18)
    assert ch["shaft_fit_pressure_Pa"] == 0 and ch["housing_fit_pressure_Pa"] == 0


def test_hot_inner_ring_and_fits_reduce_clearance_and_raise_preload():
    db = load_bearing("skf-7011-cdga-hc-db")
    before = db.rest_preload()
    oc = cl.OperatingClearance(shaft_interference=5e-6, inner_ring_temperature=313.15, outer_ring_temperature=303.15)
    ch = oc.change(db.rows[0].bearing)
    assert ch["diametral_clearance_change_m"] < 0
    after = oc.apply(db).rest_preload()
    assert np.all(after > before)


def test_axial_thermal_growth_db_loses_df_gains_preload():
    row = load_bearing("skf-7011-cdga-hc")
    oc = cl.OperatingClearance(shaft_temperature=323.15, housing_temperature=293.15,
                               inner_ring_temperature=293.15, outer_ring_temperature=293.15)
    dp = {}
    for arr, sign in (("DB", -1), ("DF", 1)):
        s = ar.make_system(row, arr, 0.018, preload=300.0)
        new = oc.apply(s)
        dp[arr] = new.rest_preload()[0] - 300.0
        np.testing.assert_allclose(new.rows[0].axial_offset - s.rows[0].axial_offset,
                                   sign * 0.5 * 11.5e-6 * 30 * 0.018, rtol=1e-12)
    # the radial effects (hot shaft tightens the fit) are the same for both; the axial growth of the
    # shaft relieves the DB pair and loads the DF pair
    assert dp["DB"] < dp["DF"]
    rep = new.notes["operating_clearance"]
    assert rep["preload_before_N"][0] == pytest.approx(300.0, rel=1e-9)


def test_toml_clearance_table_and_bad_input():
    data = {"arrangement": "DB", "row": "skf-7011-cdga-hc", "preload": "150 N",
            "clearance": {"shaft_interference": "4 um", "inner_ring_temperature": "45 degC",
                          "outer_ring_temperature": "35 degC", "speed": "12000 rpm"}}
    s = bearing_from_dict(data)
    rep = s.notes["operating_clearance"]
    assert rep["preload_after_N"][0] > rep["preload_before_N"][0]
    bad = dict(data, clearance={"shaft_inteference": "4 um"})
    with pytest.raises(InputError) as exc:
        bearing_from_dict(bad)
    assert exc.value.field == "clearance.shaft_inteference"
    with pytest.raises(InputError) as exc:
        cl.OperatingClearance(shaft_poisson=0.7)
    assert exc.value.field == "clearance.shaft_poisson"
    nob = dataclasses.replace(load_bearing("hub-seed001-row"))
    with pytest.raises(InputError) as exc:
        cl.OperatingClearance(shaft_interference=1e-5).change(nob)
    assert exc.value.field == "bore"


def test_single_bearing_apply_changes_clearance():
    b = load_bearing("skf-7011-cdga-hc")
    oc = cl.OperatingClearance(speed=12000 * math.pi / 30)
    nb = oc.apply(b)
    assert nb.diametral_clearance < 0


def test_clearance_reader_lives_in_io_and_old_names_forward():
    """The [clearance] reader moved to bearingsim.io.clearance; the old statics names are the same objects."""
    from bearingsim.io import clearance as reader
    from bearingsim.statics import clearance as cl_mod

    assert cl_mod.operating_clearance_from_dict is reader.operating_clearance_from_dict
    assert cl_mod._KEYS is reader._KEYS
    with pytest.raises(AttributeError):
        cl_mod.no_such_name  # noqa: B018
