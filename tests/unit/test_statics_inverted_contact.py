"""A heavy radial load at speed: the unloaded balls opposite the load zone had their inner groove centre carried past
them (open contact, cos α_i < 0), where Jones' rolling relations divide by zero — 6205 under ≥ 35 kN radial did not
converge at any speed above 0 (residual NaN) while it did at rest (new-user trial, session 26).  Such a contact now
takes the other contact's angle in the rolling relations (``_kernels.rolling_angles``)."""

from __future__ import annotations

import math
import os
import shutil
import subprocess

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.io import load_bearing
from bearingsim.statics.jones_harris import Loads, solve, solve_many


@pytest.fixture(scope="module")
def b6205():
    return load_bearing("6205")


def test_at_a_crawl_the_heavy_radial_solution_is_the_one_at_rest(b6205):
    """Zero reference: at 0.1 rad/s the inertial terms are ~10⁻⁷ N, so the ring's displacement must be the one at
    rest (which never used the rolling relations) — it was NaN."""
    rest = solve(b6205, Loads(fr_y=50e3), 0.0)
    crawl = solve(b6205, Loads(fr_y=50e3), 0.1)
    assert rest.converged and crawl.converged, crawl.status
    np.testing.assert_allclose(crawl.displacement, rest.displacement, rtol=0, atol=1e-12,
                               err_msg="displacement at 0.1 rad/s against the one at rest (inertia ~1e-7 N)")
    assert np.all(np.isfinite(crawl.balls["orbital_speed_rad_s"])), crawl.balls["orbital_speed_rad_s"]


@settings(max_examples=40, deadline=None)
@given(fr=st.floats(1e3, 60e3), rpm=st.floats(1.0, 6000.0))
def test_heavy_radial_loads_converge_at_any_speed_on_both_paths(b6205, fr, rpm):
    """Over radial loads to 60 kN (≈ 8 C0) and speeds to 6,000 rpm: the single and the batch solver both converge,
    with every ball's speeds finite, and agree on the displacement."""
    w = rpm * math.pi / 30
    r = solve(b6205, Loads(fr_y=fr), w)
    assert r.converged, (fr, rpm, r.status, r.residual)
    assert np.all(np.isfinite(r.balls["orbital_speed_rad_s"])) and np.all(np.isfinite(r.balls["pitch_angle_rad"]))
    br = solve_many(b6205, np.array([[0.0, fr, 0.0, 0.0, 0.0]]), np.array([w]))
    assert bool(br.converged[0]), (fr, rpm)
    np.testing.assert_allclose(br.displacement[0], r.displacement, rtol=1e-6, atol=1e-12,
                               err_msg="batch against single solve")


def test_the_console_script_converges_where_it_gave_nan():
    script = shutil.which("bearingsim")
    assert script is not None
    env = {k: v for k, v in os.environ.items() if k != "BEARINGSIM_DEBUG"}
    p = subprocess.run([script, "static", "6205", "--fr", "50 kN", "--speed", "1500"], capture_output=True, text=True,
                       env=env, timeout=600)
    assert p.returncode == 0, p.stdout + p.stderr
    assert "converged" in p.stdout.splitlines()[0] and "nan" not in p.stdout.lower(), p.stdout
