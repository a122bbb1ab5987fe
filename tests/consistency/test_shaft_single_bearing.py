"""The single-bearing limit: one bearing at the middle of a short, very stiff shaft whose tilt is held by stiff
tilt springs at its ends equals the single-bearing solve with the tilt held (``solve(..., tilt="fixed")``)."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

import bearingsim
from bearingsim.shafts.model import BearingSupport, PointLoad, Section, ShaftSystem, SpringSupport
from bearingsim.shafts.solve import solve_shaft
from bearingsim.statics.jones_harris import Loads, solve

TILT = [0.0, 0.0, 0.0, 1e13, 1e13]  # springs holding only the tilt [N·m/rad]


@pytest.mark.parametrize("name, fa, fr, speed", [("6208", 1000.0, 3000.0, 314.16),
                                                 ("6205", 500.0, 2000.0, 157.08),
                                                 ("7011-15", 2000.0, 800.0, 1000.0)])
def test_single_bearing_limit(name, fa, fr, speed):
    b = bearingsim.load_bearing(name)
    L = 0.04
    s = ShaftSystem((Section(L, 0.2),), (SpringSupport("left", 0.0, TILT), BearingSupport("bearing", L / 2, b),
                                         SpringSupport("right", L, TILT)),
                    (PointLoad(L / 2, (fa, fr, 0.0)),), speed=speed, elements=4)
    r = solve_shaft(s)
    sup = r.support("bearing")
    # the shaft bends under the holding moment (M L / 2EI ≈ 1e-8 rad here): the single solve is held at the tilt
    # the shaft imposes; the answer at zero tilt differs by that tilt's effect only
    ref = solve(b, Loads(fa=fa, fr_y=fr), speed, tilt="fixed", misalignment=sup.ring_displacement[3:])
    zero = solve(b, Loads(fa=fa, fr_y=fr), speed, tilt="fixed")
    assert r.converged and ref.converged, (r.status, ref.status)
    assert np.max(np.abs(sup.ring_displacement[3:])) < 1e-7
    assert_allclose(sup.ring_displacement[:3], ref.displacement[:3], rtol=1e-7, atol=1e-12,
                    err_msg="ring translations vs solve(tilt='fixed', misalignment=the shaft's)")
    assert_allclose(sup.ring_displacement[:3], zero.displacement[:3], rtol=1e-4, atol=1e-11,
                    err_msg="ring translations vs solve(tilt='fixed') at zero tilt")
    # the moment the springs apply (through the shaft) is the single solve's reaction moment
    m_springs = r.support("left").reaction[3:] + r.support("right").reaction[3:]
    assert_allclose(m_springs, ref.reaction_moment, rtol=1e-5, atol=1e-6 * max(1.0, np.max(np.abs(ref.reaction_moment))),
                    err_msg="tilt-holding moment vs solve(tilt='fixed').reaction_moment")
    d, dref = sup.bearing_result.to_dict(), ref.to_dict()
    for key in ("basic_rating_life_hours", "reference_rating_life_million_revolutions", "static_safety_factor"):
        if dref.get(key) is not None:
            assert_allclose(d[key], dref[key], rtol=1e-4, err_msg=key)
    qmax = sup.bearing_result.balls["inner_load_N"].max()
    assert_allclose(qmax, ref.balls["inner_load_N"].max(), rtol=1e-5, err_msg="largest ball load")


def test_bearing_reaction_matches_solve():
    """At a converged single-bearing equilibrium the seam's force balances the loads and its tangent is the
    solve's stiffness."""
    b = bearingsim.load_bearing("skf-7011-cdga-hc")
    ref = solve(b, Loads(fa=3000.0, fr_y=500.0, m_z=5.0), 1000.0)
    f, k, st = bearingsim.bearing_reaction(b, ref.displacement, 1000.0)
    assert st.converged
    assert_allclose(f, -ref.loads.as_array(), atol=1e-6 * 3000.0)
    assert_allclose(k, ref.stiffness, rtol=1e-8, atol=1e-8 * np.max(np.abs(k)))
    f2, k2, _ = bearingsim.bearing_reaction(b, ref.displacement * 1.01, 1000.0, state=st)
    f3, k3, _ = bearingsim.bearing_reaction(b, ref.displacement * 1.01, 1000.0)
    assert_allclose(f2, f3, rtol=1e-9, atol=1e-6, err_msg="a warm start finds the same ball equilibrium")
