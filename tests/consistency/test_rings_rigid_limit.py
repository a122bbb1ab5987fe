"""Elastic rings (bearingsim.rings.coupling) against the rigid-ring Jones–Harris model.

* zero ring compliance: the one-ball-per-row path reproduces the rigid-ring solve (same kernel, same ball
  order) to round-off, for a single row and for a DB pair;
* a ring material 10⁶ times stiffer than steel: displacement, ball loads and the 5×5 stiffness of the rigid
  model to 1e-6 (the ring compliance itself changes them by ~1e-8 relative at this stiffness; the stiffness is
  a central difference with a 1 nm step, truncation ~(1 nm/δ)² ≈ 1e-7);
* steel rings: a converged result is an equilibrium (the ring forces recomputed at the returned displacement
  with the offsets iterated at fixed q balance the load) and differs from the rigid model (the rings do
  something), while the fixed point converges in a few iterations.
"""

import numpy as np
import pytest

from bearingsim.io import load_bearing
from bearingsim.rings.coupling import forces_at, result_dict, ring_model, solve
from bearingsim.rings.influence import InfluenceSettings
from bearingsim.statics import jones_harris as jh
from bearingsim.statics.arrangements import make_system

LOADS = [jh.Loads(fa=3000.0), jh.Loads(fa=2000.0, fr_y=1500.0, m_z=20.0)]


@pytest.fixture(scope="module")
def b7011():
    return load_bearing("skf-7011-cdga-hc")


@pytest.fixture(scope="module")
def steel_rings(b7011, tmp_path_factory):
    import os

    old = os.environ.get("BEARINGSIM_RING_CACHE")
    os.environ["BEARINGSIM_RING_CACHE"] = str(tmp_path_factory.mktemp("ringcache"))
    try:
        wall = 0.5 * (b7011.pitch_diameter - b7011.ball_diameter - b7011.bore)
        st = InfluenceSettings(sigma=wall / 4, n_through=5, n_axial=10, ghat_min=1e-4, decay_min=1e-4)
        yield ring_model(b7011, settings=st)
    finally:
        if old is None:
            os.environ.pop("BEARINGSIM_RING_CACHE")
        else:
            os.environ["BEARINGSIM_RING_CACHE"] = old


@pytest.mark.parametrize("loads", LOADS)
def test_zero_compliance_is_the_rigid_solve(b7011, steel_rings, loads):
    rigid = jh.solve(b7011, loads)
    el = solve(b7011, loads, rings=steel_rings.scaled(0.0))
    assert el.converged and el.ring_iterations == 1
    np.testing.assert_allclose(el.displacement, rigid.displacement, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(el.balls["inner_load_N"], rigid.balls["inner_load_N"], rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(el.row_forces, rigid.row_forces, rtol=1e-10, atol=1e-8)


def test_zero_compliance_pair(b7011, steel_rings):
    pair = make_system(b7011, "DB")
    rings = type(steel_rings)([steel_rings.rows[0]] * 2).scaled(0.0)
    loads = jh.Loads(fa=1500.0, fr_y=800.0)
    rigid = jh.solve(pair, loads)
    el = solve(pair, loads, rings=rings)
    assert rigid.converged and el.converged
    np.testing.assert_allclose(el.displacement, rigid.displacement, rtol=1e-12, atol=1e-18)
    np.testing.assert_allclose(el.row_forces, rigid.row_forces, rtol=1e-10, atol=1e-8)


@pytest.mark.parametrize("loads", LOADS)
def test_very_stiff_rings_reproduce_rigid_rings(b7011, steel_rings, loads):
    rigid = jh.solve(b7011, loads)
    el = solve(b7011, loads, rings=steel_rings.scaled(1e-6))
    assert el.converged, el.status
    scale = np.abs(rigid.displacement).max()
    np.testing.assert_allclose(el.displacement, rigid.displacement, rtol=0, atol=1e-6 * scale)
    np.testing.assert_allclose(el.balls["inner_load_N"], rigid.balls["inner_load_N"], rtol=0,
                               atol=1e-6 * rigid.balls["inner_load_N"].max())
    k = rigid.stiffness
    np.testing.assert_allclose(el.stiffness, k, rtol=0, atol=1e-6 * np.abs(np.diag(k)).max())
    for i in range(5):
        assert el.stiffness[i, i] == pytest.approx(k[i, i], rel=1e-6)


@pytest.mark.parametrize("loads", LOADS)
def test_steel_rings_equilibrium(b7011, steel_rings, loads):
    el = solve(b7011, loads, rings=steel_rings)
    assert el.converged, el.status
    assert el.ring_iterations <= 6 and el.ring_residual <= 1e-12
    f, off, _, _ = forces_at(b7011, el.displacement, 0.0, "outer", steel_rings, el.ring_offsets)
    scale = jh._scale(loads, b7011.row_vectors())
    np.testing.assert_allclose(f - loads.as_array(), 0.0, atol=jh.TOL_VERIFY * scale * 10)
    np.testing.assert_allclose(off, el.ring_offsets, rtol=0, atol=1e-11)
    rigid = jh.solve(b7011, loads)
    assert np.max(np.abs(el.ring_offsets)) > 1e-8  # tens of nm: the rings deform
    d = result_dict(el)  # the JSON names the ring model
    assert d["rings"]["model"] == "fe" and d["rings"]["iterations"] == el.ring_iterations
    assert d["rings"]["max_axial_offset_m"] == pytest.approx(np.max(np.abs(el.ring_offsets[:, 0])))
    assert result_dict(solve(b7011, loads, rings="rigid"))["rings"] == {"model": "rigid"}
    assert not np.allclose(el.displacement, rigid.displacement, rtol=1e-4, atol=0)


@pytest.mark.parametrize(("loads", "speed", "control"), [(LOADS[1], 0.0, "outer"), (LOADS[0], 1200.0, "inner")])
def test_stiffness_matches_central_differences(b7011, steel_rings, loads, speed, control):
    """The linearised 5×5 stiffness with elastic rings against central differences (1 nm, 1 nm/(d_m/2)) of the
    load recomputed at prescribed displacements with the ring offsets re-solved there (forces_at): 1e-6 of the
    largest diagonal term (observed 5e-10 … 2e-8; the difference truncation is ~1e-7)."""
    el = solve(b7011, loads, speed, control, rings=steel_rings)
    assert el.converged, el.status
    q = el.displacement
    k = np.zeros((5, 5))
    for c in range(5):
        h = 1e-9 if c < 3 else 1e-9 / (0.5 * b7011.pitch_diameter)
        qp, qm = q.copy(), q.copy()
        qp[c] += h
        qm[c] -= h
        fp = forces_at(b7011, qp, speed, control, steel_rings, el.ring_offsets)[0]
        fm = forces_at(b7011, qm, speed, control, steel_rings, el.ring_offsets)[0]
        k[:, c] = (fp - fm) / (2 * h)
    np.testing.assert_allclose(el.stiffness, k, rtol=0, atol=1e-6 * np.abs(np.diag(k)).max())
