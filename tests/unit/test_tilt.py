"""The tilt control of the quasi-static solve (jones_harris.solve(tilt="fixed", misalignment=...)): a held tilt is
an equilibrium under the external loads plus the reported reaction moment, the tilt is the prescribed one, and the
CLI exposes it (--tilt fixed, --misalignment) through the installed console script."""

import json
import math
import subprocess

import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.statics import _kernels as kn
from bearingsim.statics import jones_harris as jh

W = 1500 * math.pi / 30


@pytest.mark.parametrize("name, loads, gamma", [
    ("6205", dict(fr_y=2000.0, fa=500.0), (0.0, 0.0)),
    ("6208", dict(fr_y=5000.0, fa=2000.0, m_y=3.0), (0.0, 0.0)),
    ("6205", dict(fr_y=2000.0), (0.0, 5e-4)),
    ("7205-30", dict(fr_y=2000.0, fa=1500.0), (2e-4, -1e-4)),
])
def test_fixed_tilt_is_an_equilibrium_with_the_reaction_moment(name, loads, gamma):
    b = load_bearing(name)
    r = jh.solve(b, jh.Loads(**loads), W, tilt="fixed", misalignment=gamma)
    assert r.converged and r.tilt_mode == "fixed"
    np.testing.assert_allclose(r.displacement[3:], gamma, rtol=0, atol=1e-8, err_msg="the tilt is held")
    assert r.loads == jh.Loads(**loads), "the result keeps the external loads; the constraint is reaction_moment"
    # independent check: every ball re-solved from a cold start at the returned displacement balances the external
    # loads plus the reaction moment (the solver's own acceptance test, TOL_VERIFY of the load scale)
    la = jh.Loads(**loads).as_array() + np.r_[0.0, 0.0, 0.0, r.reaction_moment]
    rows = b.row_vectors()
    rv, bc = kn.equilibrium_residual(rows, la, W, jh.CONTROLS["outer"], r.displacement.copy(), jh.TOL_BALL,
                                     jh.MAXIT_BALL)
    assert bc and rv <= jh.TOL_VERIFY * jh._scale(jh.Loads(*la), rows)
    # the free solve under loads + reaction moment lands on the same equilibrium
    free = jh.solve(b, jh.Loads(*la), W)
    np.testing.assert_allclose(free.displacement, r.displacement, rtol=0, atol=1e-10)


def test_held_tilt_needs_a_moment_that_grows_with_the_misalignment():
    b = load_bearing("6205")
    m = [jh.solve(b, jh.Loads(fr_y=2000.0), W, tilt="fixed", misalignment=(0.0, g)).reaction_moment[1]
         for g in (0.0, 2e-4, 5e-4)]
    assert m[0] == 0.0  # pure radial load: no moment at zero tilt (symmetry)
    assert 0.0 < m[1] < m[2], m  # a positive tilt about z needs a positive moment about z (stiffening)


def test_free_tilt_under_combined_load_tilts_and_fixed_tilt_carries_the_moment():
    b = load_bearing("6205")
    free = jh.solve(b, jh.Loads(fr_y=2000.0, fa=500.0), W)
    fixed = jh.solve(b, jh.Loads(fr_y=2000.0, fa=500.0), W, tilt="fixed")
    assert free.tilt_mode == "free" and free.reaction_moment is None
    assert abs(free.displacement[4]) > 1e-3  # the unconstrained deep-groove ring tilts by mrad under Fr + Fa
    # held at zero tilt the load zone is wider and the reference rating life longer
    assert fixed.reference_rating_life > 1.2 * free.reference_rating_life
    assert fixed.basic_rating_life == free.basic_rating_life  # ISO 281 P is the same formula of the loads


@pytest.mark.parametrize("kw, field", [(dict(tilt="wobbly"), "tilt"),
                                       (dict(tilt="free", misalignment=(0.0, 1e-3)), "misalignment"),
                                       (dict(tilt="fixed", misalignment=(1e-3,)), "misalignment"),
                                       (dict(tilt="fixed", misalignment=(0.0, math.nan)), "misalignment")])
def test_bad_tilt_input_names_the_field(kw, field):
    with pytest.raises(InputError) as e:
        jh.solve(load_bearing("6205"), jh.Loads(fr_y=1000.0), W, **kw)
    assert e.value.field == field


def test_cli_tilt_fixed_json_and_errors():
    out = subprocess.run(["bearingsim", "static", "6205", "--fr", "2 kN", "--fa", "0.5 kN", "--speed", "1500 rpm",
                          "--tilt", "fixed", "--misalignment", "0.2 mrad", "--json"],
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    d = json.loads(out.stdout)
    assert d["tilt"]["mode"] == "fixed"
    np.testing.assert_allclose(d["tilt"]["misalignment_rad"], [0.0, 2e-4], rtol=0, atol=1e-15)
    np.testing.assert_allclose(d["displacement"]["vector"][3:], [0.0, 2e-4], rtol=0, atol=1e-8)
    # the API gives the same reaction moment
    r = jh.solve(load_bearing("6205"), jh.Loads(fr_y=2000.0, fa=500.0), W, tilt="fixed", misalignment=(0.0, 2e-4))
    np.testing.assert_allclose(d["tilt"]["reaction_moment_N_m"], r.reaction_moment, rtol=1e-9, atol=1e-12)
    free = json.loads(subprocess.run(["bearingsim", "static", "6205", "--fr", "2 kN", "--json"],
                                     capture_output=True, text=True, timeout=120).stdout)
    assert free["tilt"] == {"mode": "free"}
    bad = subprocess.run(["bearingsim", "static", "6205", "--fr", "2 kN", "--misalignment", "1 mrad"],
                         capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and "--misalignment" in bad.stderr and len(bad.stderr.strip().splitlines()) == 1


def test_cli_report_shows_the_held_tilt_and_its_reaction_moment(tmp_path):
    out = subprocess.run(["bearingsim", "report", "6205", "--fr", "2 kN", "--fa", "0.5 kN", "--speed", "1500 rpm",
                          "--tilt", "fixed", "--out", str(tmp_path / "rep")], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    html = (tmp_path / "rep" / "report.html").read_text()
    r = jh.solve(load_bearing("6205"), jh.Loads(fr_y=2000.0, fa=500.0), W, tilt="fixed")
    assert "held at γy = 0 mrad, γz = 0 mrad" in html
    assert f"{r.reaction_moment[1]:.4g} N·m" in html and "reaction moment (tilt held)" in html


@pytest.mark.parametrize("name, loads", [("6208", dict(fr_y=3000.0, fa=800.0, m_z=6.0, m_y=-2.0)),
                                         ("7205-30", dict(fr_y=1500.0, fa=2000.0, m_z=-4.0)),
                                         ("6305", dict(fr_y=2000.0, m_y=3.0))])
def test_holding_the_free_tilt_needs_no_reaction(name, loads):
    """The inverse check: hold the tilt at the free equilibrium's own tilt under the same loads (moments included):
    the constraint has nothing to do, reaction moment ≈ 0 and the same displacement."""
    b = load_bearing(name)
    free = jh.solve(b, jh.Loads(**loads), W)
    held = jh.solve(b, jh.Loads(**loads), W, tilt="fixed", misalignment=free.displacement[3:])
    assert free.converged and held.converged
    scale = max(abs(v) for v in loads.values())
    np.testing.assert_allclose(held.reaction_moment, 0.0, atol=1e-6 * scale * 0.5 * b.pitch_diameter)
    np.testing.assert_allclose(held.displacement, free.displacement, rtol=0, atol=1e-10)
