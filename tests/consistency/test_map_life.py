"""Maps carry the ISO 281 basic rating life of every point (issue 15): the map's L10 and L10h equal the static
result's at the same operating point (consistency, not validation: the life itself is validated against the
standards' examples in tests/validation/test_iso281*.py)."""

import math

import numpy as np
import pytest

from bearingsim.io import load_bearing
from bearingsim.statics import jones_harris as jh
from bearingsim.sweep import map_grid


@pytest.fixture(scope="module")
def ds():
    return map_grid("6208", fa=[0.0, 1000.0], fr=[1000.0, 3000.0], speed=[0.0, 3000 * math.pi / 30], workers=1)


@pytest.mark.parametrize("fa, fr", [(0.0, 1000.0), (1000.0, 1000.0), (1000.0, 3000.0)])
def test_map_life_equals_static_life(ds, fa, fr):
    w = 3000 * math.pi / 30
    res = jh.solve(load_bearing("6208"), jh.Loads(fa=fa, fr_y=fr), w).to_dict()
    pt = ds.sel(fa=fa, fr=fr, speed=w)
    np.testing.assert_allclose(float(pt.basic_rating_life) / 1e6, res["basic_rating_life_million_revolutions"],
                               rtol=1e-12, err_msg="map L10 vs static L10")
    np.testing.assert_allclose(float(pt.basic_rating_life_time) / 3600, res["basic_rating_life_hours"],
                               rtol=1e-12, err_msg="map L10h vs static L10h")


def test_map_life_units_and_zero_speed(ds):
    assert ds.basic_rating_life.attrs["units"] == "1" and ds.basic_rating_life_time.attrs["units"] == "s"
    assert ds.basic_rating_life_time.attrs["units_display"] == "h"
    assert np.all(np.isnan(ds.basic_rating_life_time.sel(speed=0.0)))
    assert np.all(np.isfinite(ds.basic_rating_life.sel(speed=0.0)))  # revolutions need no speed


def test_bearing_without_rating_gives_nan_not_a_number():
    d = map_grid("skf-7011-cdga-hc", fa=[1000.0, 2000.0], speed=600.0, workers=1)
    assert np.all(np.isnan(d.basic_rating_life.values))


def test_life_is_plotted_in_hours_and_millions_of_revolutions(ds, tmp_path):
    from bearingsim.sweep import plot_map, plot_unit

    assert plot_unit(ds, "basic_rating_life_time") == ("h", 1.0 / 3600.0)
    assert plot_unit(ds, "basic_rating_life") == ("1e6 rev", 1e-6)
    assert plot_unit(ds, "stiffness", 0, 0)[0] == "N/µm"
    assert plot_map(ds.sel(speed=3000 * math.pi / 30), tmp_path / "life.png", var="basic_rating_life_time").exists()
