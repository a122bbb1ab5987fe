"""Rating life (life.py): Lundberg-Palmgren integrals, calibration to C, scaling laws, ISO 281."""

import dataclasses
import math
from types import SimpleNamespace

import numpy as np
import pytest
from scipy.special import gamma

from bearingsim import life
from bearingsim.io import load_bearing
from bearingsim.statics import arrangements as ar
from bearingsim.statics import jones_harris as jh


def _wallis(n):
    """int_0^(pi/2) cos^n = (sqrt(pi)/2) Gamma((n+1)/2) / Gamma(n/2 + 1)."""
    return math.sqrt(math.pi) / 2 * gamma((n + 1) / 2) / gamma(n / 2 + 1)


def test_lp_integrals_closed_forms():
    jr, j1, j2 = life.lp_integrals(0.5)
    # eps = 0.5: Q/Qmax = cos^1.5(psi) on |psi| < pi/2 (Stribeck); Wallis integrals
    np.testing.assert_allclose(jr, _wallis(2.5) / math.pi, rtol=1e-9)
    np.testing.assert_allclose(j1**3, _wallis(4.5) / math.pi, rtol=1e-9)
    np.testing.assert_allclose(j2 ** (10 / 3), _wallis(5.0) / math.pi, rtol=1e-9)
    np.testing.assert_allclose([jr, j1], [0.2288, 0.5625], atol=6e-5,
                               err_msg="Harris & Kotzalas 2007 vol. 2 ch. 8, Lundberg-Palmgren integrals, eps = 0.5")
    # eps = 1: Q/Qmax = cos^3(psi/2) over the full circle
    np.testing.assert_allclose(life.lp_integrals(1.0)[0], 0.8 / math.pi, rtol=1e-9)


def _stribeck_result(bearing, c, scale=1.0, z_rows=1):
    """A fake result whose balls carry the eps = 0.5 Stribeck distribution at radial load scale*C."""
    z = bearing.ball_count
    jr = life.lp_integrals(0.5)[0]
    qmax = scale * c / (z * jr * math.cos(bearing.free_contact_angle))
    psi = 2 * math.pi * np.arange(z) / z
    q = qmax * np.maximum(np.cos(psi), 0.0) ** 1.5
    balls = {"row": np.repeat(np.arange(z_rows), z), "inner_load_N": np.tile(q, z_rows),
             "outer_load_N": np.tile(q, z_rows)}
    return balls


def test_calibration_gives_one_million_revolutions_at_c():
    b = dataclasses.replace(load_bearing("harris-218"), dynamic_load_rating=100e3)
    res = SimpleNamespace(bearing=b, balls=_stribeck_result(b, 100e3))
    # the discrete sum over Z = 16 balls replaces the L-P integral: agreement to the quadrature error
    np.testing.assert_allclose(life.reference_rating_life(res), 1.0, rtol=0.02,
                               err_msg="ISO 281 definition of C: L10 = 1e6 rev at P = C")


def test_life_scales_with_inverse_cube_of_load_and_system_combination():
    b = dataclasses.replace(load_bearing("harris-218"), dynamic_load_rating=100e3)
    l1 = life.reference_rating_life(SimpleNamespace(bearing=b, balls=_stribeck_result(b, 100e3, 0.5)))
    l2 = life.reference_rating_life(SimpleNamespace(bearing=b, balls=_stribeck_result(b, 100e3, 0.25)))
    np.testing.assert_allclose(l2 / l1, 8.0, rtol=1e-12)
    # two identical rows each with the same loads: L_sys = 2^(-9/10) L_row (Weibull e = 10/9)
    sys_ = ar.BearingSystem("pair", (ar.Row(b, -0.03, 1.0), ar.Row(b, 0.03, -1.0)))
    sys_ = dataclasses.replace(sys_, dynamic_load_rating=2**0.7 * 100e3)
    l_sys = life.reference_rating_life(SimpleNamespace(bearing=sys_, balls=_stribeck_result(b, 100e3, 0.5, 2)))
    np.testing.assert_allclose(l_sys, 2 ** (-0.9) * l1, rtol=1e-12)


def test_no_rating_gives_none_and_real_solution_gives_finite_life():
    b = load_bearing("skf-7011-cdga-hc")
    r = jh.solve(b, jh.Loads(fa=1000.0))
    assert life.reference_rating_life(r) is None
    b2 = dataclasses.replace(b, dynamic_load_rating=23.4e3)
    r2 = jh.solve(b2, jh.Loads(fa=1000.0), speed=1000.0)
    l = life.reference_rating_life(r2)
    assert l is not None and 0 < l < math.inf
    # doubling the load shortens life by more than 2^3 / 1.5 (load exponent 3)
    r3 = jh.solve(b2, jh.Loads(fa=2000.0), speed=1000.0)
    assert life.reference_rating_life(r3) < l / 5


@pytest.mark.parametrize("deg, fr, fa, rows, p", [
    (40, 1000.0, 500.0, 1, 1000.0),                 # Fa/Fr = 0.5 <= e = 1.14: P = Fr
    (40, 1000.0, 2000.0, 1, 0.35 * 1000 + 0.57 * 2000),
    (35, 1000.0, 500.0, 2, 1000 + 0.66 * 500),
    (35, 1000.0, 2000.0, 2, 0.6 * 1000 + 1.07 * 2000),
])
def test_iso281_equivalent_load(deg, fr, fa, rows, p):
    np.testing.assert_allclose(life.equivalent_dynamic_load(fr, fa, math.radians(deg), rows), p, rtol=1e-12,
                               err_msg="ISO 281:2007 table 3, angular contact ball bearings")
    assert life.equivalent_dynamic_load(fr, fa, math.radians(15), rows) is None
    np.testing.assert_allclose(life.basic_rating_life(10e3, p), (10e3 / p) ** 3)


def test_iso281_life_without_load_is_none_not_infinity(b218):
    """No load: P = 0 and L10 = ∞, which ``json.dumps`` writes as the non-JSON token Infinity; the result
    dictionary gives None (null) instead."""
    import dataclasses
    import json

    from bearingsim.life import iso281_life
    from bearingsim.statics import jones_harris as jh

    b = dataclasses.replace(b218, dynamic_load_rating=100e3)
    r = jh.solve(b, jh.Loads(), 0.0)
    assert iso281_life(r) is None
    assert "Infinity" not in json.dumps(r.to_dict())
    assert iso281_life(jh.solve(b, jh.Loads(fa=3000.0), 0.0)) > 0
