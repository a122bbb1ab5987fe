"""Consistency (not literature validation): the dynamic engine against our quasi-static Jones–Harris model.

* symmetry: a centred axial load on a single row keeps the inner ring centred and every
  ball loaded alike (Jones 1960; Harris & Kotzalas 2007 vol. 2 ch. 3, pure thrust);
* a load varied slowly (well below the ring's natural frequency) gives the
  quasi-static displacements of :func:`bearingsim.statics.jones_harris.solve` (≤ 2 %,
  issue 5), for the axial deflection of the 7011 and the tilt of the seed-001 hub unit
  under a moment (seed 001 Fig. 6: the dynamic tilt–moment slope equals the static one).
"""

import math

import numpy as np

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import model as md
from bearingsim.dynamics.run import Stepper
from bearingsim.io import load_bearing
from bearingsim.statics import jones_harris as jh


def test_centred_axial_load_keeps_ring_centred():
    b = load_bearing("skf-7011-cdga-hc")
    w = 10000 * math.pi / 30
    res = jh.solve(b, jh.Loads(fa=3000.0), w)
    m = md.build_model(b, traction="coulomb", speed=(w, w, 0.0), ring_mass=2.0, damping_alpha=0.05)
    st = Stepper(m, fo.constant_loads(fa=3000.0), md.initial_state(m, res), tol=1e-6)
    st.advance(5e-4)
    s = st.sample()
    q = s["inner_ring_displacement"]
    assert abs(q[1]) < 1e-9 * q[0] / 1e-5 * 1e-3 and abs(q[2]) < 1e-12, q
    assert abs(q[3]) < 1e-10 and abs(q[4]) < 1e-10, q
    qi = s["inner_contact_load"]
    np.testing.assert_allclose(qi, qi.mean(), rtol=1e-8, err_msg="Jones 1960: pure thrust loads all balls alike")


def _slow_run(bearing, channels, t_ramp, n_check, ring_mass, static_loads):
    """Run a smooth half-cosine load ramp and return (dynamic q, static q) at check times."""
    ls = fo.pack_loads(channels)
    l0 = static_loads(0.0)
    res0 = jh.solve(bearing, l0, 0.0)
    assert res0.converged
    m = md.build_model(bearing, traction="none", damping_alpha=0.5, ring_mass=ring_mass)
    st = Stepper(m, ls, md.initial_state(m, res0), tol=1e-7)
    out = []
    for i in range(1, n_check + 1):
        t = i * t_ramp / n_check
        st.advance(t)
        s = st.sample()
        qs = jh.solve(bearing, static_loads(t), 0.0, initial=res0.displacement)
        assert qs.converged
        out.append((t, s["inner_ring_displacement"], qs.displacement, s["applied_load"]))
    return out


def test_slow_axial_load_matches_statics():
    b = load_bearing("skf-7011-cdga-hc")
    t_ramp = 0.02
    f = 1.0 / (2 * t_ramp)
    fa = lambda t: 1750.0 - 1250.0 * math.cos(math.pi * t / t_ramp)  # noqa: E731
    channels = [{"offset": 1750.0, "sines": [(1250.0, f, -math.pi / 2)]}, {}, {}, {}, {}]
    out = _slow_run(b, channels, t_ramp, 4, 2.0, lambda t: jh.Loads(fa=fa(t)))
    for t, qd, qs, load in out:
        # the load channel (offset + sine with a phase) must apply the intended Fa(t) of the static comparison
        np.testing.assert_allclose(load[0], fa(t), rtol=1e-12, err_msg="load history vs its closed form")
        np.testing.assert_allclose(qd[0], qs[0], rtol=0.02,
                                   err_msg=f"Jones–Harris statics (seed 000 eqs. 6–16) at Fa = {fa(t):.0f} N")


def test_slow_moment_on_hub_unit_matches_statics():
    b = load_bearing("hub-seed001")
    t_ramp = 0.02
    f = 1.0 / (2 * t_ramp)
    mz = lambda t: 300.0 - 300.0 * math.cos(math.pi * t / t_ramp)  # noqa: E731
    channels = [{}, {"offset": 2000.0}, {}, {}, {"offset": 300.0, "sines": [(300.0, f, -math.pi / 2)]}]
    out = _slow_run(b, channels, t_ramp, 4, 3.0, lambda t: jh.Loads(fr_y=2000.0, m_z=mz(t)))
    for t, qd, qs, load in out:
        np.testing.assert_allclose(load[4], mz(t), rtol=1e-12, err_msg="load history vs its closed form")
        np.testing.assert_allclose(qd[4], qs[4], rtol=0.02,
                                   err_msg=f"Jones–Harris statics, hub tilt at M_z = {load[4]:.0f} N·m (seed 001 Fig. 6)")
        np.testing.assert_allclose(qd[1], qs[1], rtol=0.02, err_msg="Jones–Harris statics, hub radial displacement")
