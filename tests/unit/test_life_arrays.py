"""life.basic_rating_life_arrays (the ISO 281 life of a map point) against the single-point rating summary of a
solved operating point (jones_harris.solve -> rating): same P, L10 and L10h, point by point."""

import dataclasses
import math

import numpy as np

from bearingsim import io, life
from bearingsim.statics import arrangements as ar
from bearingsim.statics import jones_harris as jh


def _single_point(bearing, fr, fa, speed):
    r = jh.solve(bearing, jh.Loads(fr_y=fr, fa=fa), speed)
    assert r.converged
    s = r.rating
    return s["basic_rating_life_million_revolutions"], s["basic_rating_life_hours"]


def test_arrays_equal_the_single_point_summary_deep_groove_15deg_and_pair(b7011):
    pair = ar.make_system(dataclasses.replace(b7011, dynamic_load_rating=23.4e3, static_load_rating=17.3e3,
                                              geometry_factor_f0=14.0), "DB", preload=200.0)
    cases = [(io.load_bearing("6205"), [(2000.0, 500.0), (1000.0, 100.0), (500.0, 1500.0), (3000.0, 0.0)]),
             (io.load_bearing("7205-15"), [(2000.0, 2000.0), (1500.0, 300.0), (800.0, 2500.0)]),
             (io.load_bearing("7205-40"), [(2000.0, 2000.0), (2000.0, 500.0)]),
             (pair, [(2000.0, 300.0), (1000.0, 2500.0), (3000.0, 100.0)])]
    speeds = (1500 * math.pi / 30, 6000 * math.pi / 30)
    for brg, loads in cases:
        fr = np.array([f for f, _ in loads] * 2)
        fa = np.array([a for _, a in loads] * 2)
        w = np.repeat(speeds, len(loads))
        l10, l10h = life.basic_rating_life_arrays(brg, fr, fa, w)
        ref = [_single_point(brg, *x) for x in zip(fr, fa, w)]
        np.testing.assert_allclose(l10, [x[0] for x in ref], rtol=1e-12, err_msg=f"{brg.name}: L10")
        np.testing.assert_allclose(l10h, [x[1] for x in ref], rtol=1e-12, err_msg=f"{brg.name}: L10h")


def test_arrays_broadcast_and_edge_values():
    b = io.load_bearing("6208")
    fr = np.array([[0.0], [2000.0]])
    fa = np.array([0.0, 1000.0])
    l10, l10h = life.basic_rating_life_arrays(b, fr, fa, 0.0)
    assert l10.shape == (2, 2)
    assert l10[0, 0] == np.inf  # no load
    assert np.isfinite(l10[1, 1]) and np.all(np.isnan(l10h))  # at rest: no hours
    # no C: no life
    nc = dataclasses.replace(b, dynamic_load_rating=0.0)
    assert np.all(np.isnan(life.basic_rating_life_arrays(nc, fr, fa, 100.0)[0]))
