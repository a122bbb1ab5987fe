"""Seed 001 hub unit: quasi-static tilt vs moment (studies/hub_static.py).

Seed 001 gives no tilt values in numbers (its Fig. 6 is a plot); what it states is checked here:
the moment stiffness is the same at 10, 50 and 100 km/h and equals the non-rotating one
(seed 001 section 4), and the tilt range of Fig. 6 (axis ±0.10 deg
at ±0.8 kN·m; the curves stay inside it).  The moment stiffness of the preloaded unit at rest
is checked against a closed form built from the thrust model (independent of the kernel).
"""

import math

import numpy as np

from bearingsim.statics import jones_harris as jh
from bearingsim.statics.axial import solve_thrust
from bearingsim.studies import hub_static as hs


def test_tilt_inside_fig6_range_and_monotonic(hub_study):
    deg = np.degrees(hub_study.tilt)
    assert np.all(np.diff(deg) > 0)
    # seed 001 Fig. 6: inclining angle axis -0.10 ... 0.10 deg for moments -0.8 ... 0.8 kN m
    assert 0.02 < abs(deg[0]) < 0.10, "seed 001 Fig. 6 tilt range at -0.6 kN m"
    assert 0.02 < abs(deg[-1]) < 0.10, "seed 001 Fig. 6 tilt range at +0.6 kN m"
    assert not hub_study.lifted_off.any()


def test_moment_stiffness_independent_of_vehicle_speed(hub, hub_study):
    for v in (10.0, 50.0, 100.0):
        r = hs.run_study(hub, hub_study.moment, speed=hs.vehicle_speed_to_shaft(v))
        ok = r.ring_converged
        assert ok.all()
        slope_v = np.polyfit(r.moment[ok], r.tilt[ok], 1)[0]
        slope_0 = np.polyfit(hub_study.moment[ok], hub_study.tilt[ok], 1)[0]
        np.testing.assert_allclose(slope_v, slope_0, rtol=0.01,
                                   err_msg=f"seed 001 section 4: compliance at {v} km/h equals the non-rotating one")
        np.testing.assert_allclose(r.tilt[ok], hub_study.tilt[ok], rtol=0.01, atol=1e-3 * np.abs(hub_study.tilt).max())


def test_moment_stiffness_at_rest_closed_form(hub):
    """At rest without load every ball carries the thrust-model preload Q0 along the line of groove
    centres; the linearised ball force is dF = k_n (n.dA) n + Q0/L (dA - (n.dA) n) with
    k_n = 1.5 K_n^(2/3) Q0^(1/3) and L = |A| (seed 000 eqs. 3-5; Harris & Kotzalas vol. 2 ch. 3)."""
    res = jh.solve(hub, jh.Loads())
    row = hub.rows[0].bearing
    th = solve_thrust(row, hub.preload)
    _, _, kn_ = row.contact_constants
    k_n = 1.5 * kn_ ** (2 / 3) * th.ball_load ** (1 / 3)
    big_a = row.total_curvature_distance
    length = big_a + th.normal_approach
    ri = (row.inner_conformity - 0.5) * row.ball_diameter
    a0 = row.free_contact_angle
    n = np.array([math.sin(th.contact_angle), math.cos(th.contact_angle)])
    kb = k_n * np.outer(n, n) + th.ball_load / length * (np.eye(2) - np.outer(n, n))
    k = np.zeros((5, 5))
    for r in hub.rows:
        s = r.orientation
        xg = (r.position - hub.load_point) + s * (ri * math.sin(a0) + r.axial_offset)  # groove centre incl. preload offset
        ric = 0.5 * row.pitch_diameter + ri * math.cos(a0)
        for j in range(row.ball_count):
            psi = 2 * math.pi * j / row.ball_count
            t = np.array([[s, 0, 0, s * ric * math.sin(psi), -s * ric * math.cos(psi)],
                          [0, math.cos(psi), math.sin(psi), -xg * math.sin(psi), xg * math.cos(psi)]])
            k += t.T @ kb @ t
    np.testing.assert_allclose(res.stiffness, k, rtol=1e-7, atol=1e-7 * np.abs(k).max(),
                               err_msg="closed-form linearised stiffness of the preloaded unit")
    # moment compliance of the unit at rest (pure moment, other loads free)
    c = np.linalg.inv(res.stiffness)[4, 4]
    np.testing.assert_allclose(c, np.linalg.inv(k)[4, 4], rtol=1e-7)
