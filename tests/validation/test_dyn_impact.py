"""Dynamic engine: a ball thrown onto the outer raceway gives Hertz's impact duration.

Reference: Hertz impact of a body on a non-linear spring Q = K δ^1.5 (Johnson,
*Contact Mechanics* 1985, §11.4, eqs. 11.20–11.24): the largest approach
δ_max = (5 m v² / (4 K))^(2/5) and the contact duration
t_c = 2 (δ_max / v) ∫₀¹ dx/√(1 − x^(5/2)) = 2.9433 δ_max / v.
"""

import dataclasses

import numpy as np
from scipy.special import beta

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import model as md
from bearingsim.dynamics.run import Stepper
from bearingsim.io import load_bearing
from bearingsim.statics import _kernels as kn


def _impact_duration(v_impact):
    b = dataclasses.replace(load_bearing("hub-seed001-row"), diametral_clearance=1e-4)
    m = md.build_model(b, ring_fixed=True, cage=False, traction="none", damping_alpha=0.0)
    y = md.initial_state(m)
    par = m.rows[0]
    # ball 0 moves along the line outer groove centre -> ball centre, 1 µm before touching
    o = md.N_RING
    g = np.array([m.rowx[0, md.X_XGO], m.rowx[0, md.X_RGO], 0.0])
    u = y[o:o + 3] - g
    u /= np.linalg.norm(u)
    gap = 1e-6
    y[o:o + 3] = g + (par[kn.P_RO] - gap) * u
    y[o + 3:o + 6] = v_impact * u
    mass, k = par[kn.P_MASS], par[kn.P_KO]
    dmax = (5 * mass * v_impact**2 / (4 * k)) ** 0.4
    integral = 0.4 * beta(0.4, 0.5)
    t_ref = 2 * integral * dmax / v_impact
    st = Stepper(m, fo.constant_loads(), y, tol=1e-9)
    t_end = gap / v_impact + 1.3 * t_ref
    n = 2000
    ts, ds = [], []
    for i in range(n + 1):
        st.advance(i * t_end / n)
        ts.append(st.t)
        ds.append(st.sample()["outer_approach"][0])
    ts, ds = np.array(ts), np.array(ds)
    pos = np.nonzero(ds > 0)[0]
    i0, i1 = pos[0], pos[-1]
    t_in = ts[i0 - 1] + (ts[i0] - ts[i0 - 1]) * (-ds[i0 - 1]) / (ds[i0] - ds[i0 - 1])
    t_out = ts[i1] + (ts[i1 + 1] - ts[i1]) * ds[i1] / (ds[i1] - ds[i1 + 1])
    return t_out - t_in, t_ref, ds.max(), dmax, st


def test_hertz_impact_duration_and_peak_approach():
    for v in (0.05, 0.5):
        tc, t_ref, dpk, dmax, st = _impact_duration(v)
        np.testing.assert_allclose(tc, t_ref, rtol=2e-3, err_msg=f"Johnson 1985 eq. 11.24 (Hertz impact time), v = {v}")
        np.testing.assert_allclose(dpk, dmax, rtol=2e-3, err_msg=f"Johnson 1985 eq. 11.22 (max approach), v = {v}")
        # the rebound speed equals the impact speed without damping (elastic impact)
        vout = np.linalg.norm(st.y[md.N_RING + 3:md.N_RING + 6])
        np.testing.assert_allclose(vout, v, rtol=1e-5, err_msg="elastic Hertz impact: restitution 1")
