"""dynamics.analysis: loop widths on plain arrays, and Results delegating to it (file and memory)."""

import math

import numpy as np
import pytest

from bearingsim.dynamics import analysis


def _loop(n=20001, lag=0.3e-3):
    w, m0, c = 2 * math.pi * 50, 600.0, 1.7e-6
    t = np.linspace(0.0, 0.05, n)
    return t, m0 * np.sin(w * t), c * m0 * np.sin(w * (t - lag)), math.sqrt(3) * c * m0 * math.sin(w * lag)


def test_loop_widths_on_arrays_match_the_closed_form_and_results():
    """Sakaguchi & Shibutani Fig. 8 definition at M = M0/2 of a lagging tilt: √3 c M0 sin(w lag) per cycle;
    Results.loop_widths returns the same array, bit for bit."""
    from bearingsim.dynamics.run import Results

    t, m, g, expected = _loop()
    widths = analysis.loop_widths(m, g, 300.0)
    assert len(widths) == 3
    np.testing.assert_allclose(widths, expected, rtol=1e-5)
    assert analysis.fluctuation_range(m, g, 300.0) == widths[-1]
    load = np.zeros((t.size, 5))
    disp = np.zeros((t.size, 5))
    load[:, 3], disp[:, 2] = m, g
    res = Results(data={"time": t, "applied_load": load, "inner_ring_displacement": disp}, attrs={})
    assert np.array_equal(res.loop_widths(300.0, dof=2, load=3), widths)
    assert res.fluctuation_range(300.0, dof=2, load=3) == widths[-1]


def test_no_complete_cycle_gives_no_width():
    t, m, g, _ = _loop()
    assert analysis.loop_widths(m, g, 700.0).size == 0  # the load never reaches the level
    assert math.isnan(analysis.fluctuation_range(m, g, 700.0))
    half = t <= 0.005  # a quarter period: rising crossing only
    assert analysis.loop_widths(m[half], g[half], 300.0).size == 0


@pytest.mark.parametrize("lag", [-0.2e-3, 0.5e-3])
def test_width_sign_follows_the_lag(lag):
    _, m, g, expected = _loop(lag=lag)
    assert np.sign(analysis.fluctuation_range(m, g, 300.0)) == np.sign(lag)
    assert analysis.fluctuation_range(m, g, 300.0) == pytest.approx(expected, rel=1e-5)
