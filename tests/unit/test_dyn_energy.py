"""Dynamic engine invariants: energy conservation without friction and damping; determinism.

Without traction, pocket friction and contact damping the contact forces derive from
the potential Σ (2/5) K δ^(5/2) and the constant axial load from −Fa δx, and the
equations of motion have a constant mass matrix with skew (power-free) gyroscopic
terms, so the total energy is a constant of the motion: its drift must shrink with the
integrator tolerance.
"""

import math

import numpy as np

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import model as md
from bearingsim.dynamics.run import Stepper
from bearingsim.io import load_bearing
from bearingsim.statics import _kernels as kn
from bearingsim.statics import jones_harris as jh


def total_energy(m, st):
    """(total energy, kinetic energy of the rigid bodies, energy of the elastic cages' modes ½ Σ (η̇² + ω² η²)) [J]."""
    y = st.y
    gp = m.gp
    qd = y[ly.R_QD:ly.R_QD + 5]
    e = 0.5 * gp[ly.G_MR] * np.sum(qd[0:3] ** 2) + 0.5 * gp[ly.G_ITR] * np.sum(qd[3:5] ** 2)
    for k in range(m.n_balls):
        ball = y[m.ball_slice(k)]
        par = m.rows[m.ball_row[k]]
        e += 0.5 * par[kn.P_MASS] * np.sum(ball[ly.B_VEL:ly.B_VEL + 3] ** 2) + \
            0.5 * par[kn.P_JB] * np.sum(ball[ly.B_OMEGA:ly.B_OMEGA + 3] ** 2)
    emodal = 0.0
    for c in range(m.n_cages):
        cage = y[m.cage_slice(c)]
        cp = m.cp[c]
        e += 0.5 * cp[ly.C_MASS] * np.sum(cage[ly.K_VEL:ly.K_VEL + 3] ** 2) + \
            0.5 * cp[ly.C_IP] * cage[ly.K_THETA_DOT] ** 2 + \
            0.5 * cp[ly.C_IT] * (cage[ly.K_BETA_Y_DOT] ** 2 + cage[ly.K_BETA_Z_DOT] ** 2)
        _, etad = m.mode_slices(c)
        emodal += 0.5 * np.sum(y[etad] ** 2)
    s = st.sample()
    emodal += s["cage_strain_energy"]
    return e + emodal + s["contact_potential_energy"] - s["applied_load"][0] * y[0], e, emodal


def _setup(tol, **model_kw):
    """Hub row at Fa = 2 kN without traction, damping or pocket friction, balls and ring kicked so that
    they hit their pockets; ``model_kw`` go to build_model (e.g. an elastic cage)."""
    b = load_bearing("hub-seed001-row")
    fa = 2000.0
    res = jh.solve(b, jh.Loads(fa=fa), 0.0)
    m = md.build_model(b, traction="none", damping_alpha=0.0, ring_mass=1.5, cage_mu=0.0,
                       pocket_clearance=2e-5, **model_kw)
    y = md.initial_state(m, res)
    y[ly.R_QD:ly.R_QD + 5] = (2e-3, 1e-3, -1.5e-3, 0.05, -0.04)
    for k in range(m.n_balls):
        ball = y[m.ball_slice(k)]  # a view: writes go to y
        psi = m.ball_psi[k]
        vt = 0.02 * (1 if k % 2 else -1)
        ball[ly.B_VEL + 1] += -vt * math.sin(psi)
        ball[ly.B_VEL + 2] += vt * math.cos(psi)
        ball[ly.B_OMEGA:ly.B_OMEGA + 3] += (3.0 * (k % 3), -2.0, 1.0)
    return m, Stepper(m, fo.constant_loads(fa=fa), y, tol=tol)


def test_energy_conserved_without_friction_and_damping():
    drifts = []
    for tol in (1e-7, 1e-11):
        m, st = _setup(tol)
        e0, ke0, _ = total_energy(m, st)
        worst = 0.0
        cage_hits = 0.0
        for i in range(1, 21):
            st.advance(i * 1e-4)
            e, _, _ = total_energy(m, st)
            worst = max(worst, abs(e - e0))
            cage_hits = max(cage_hits, st.sample()["cage_contact_load"].max())
        assert cage_hits > 0, "the test must exercise the pocket contacts"
        drifts.append(worst / ke0)
    # relative to the initial kinetic energy.  Measured (per-vector error scale): 5.8e-6, 2.3e-6, 8.8e-7, 4.3e-7,
    # 9.1e-8 at tol 1e-7 … 1e-11 (per-component scale: 9.4e-6, 2.7e-6, 1.1e-6, 5.4e-7, 1.9e-7), i.e. convergence
    # as ≈ tol^0.4; contact onsets, where the Hertz force ∝ δ^1.5 is not smooth, are the likely limit (with the
    # earlier point-cloud pocket contact the drift was ≈ 20× larger).  The worst drift over 20 samples is a noisy
    # statistic (± 30 % from one decade to the next as the steps land elsewhere on an impact), so the
    # convergence is asked over four decades: ≈ 40–60× expected, > 10× asked.
    assert drifts[1] < 1e-6, f"energy drift {drifts}"
    assert drifts[0] / drifts[1] > 10, f"drift must shrink with the tolerance: {drifts}"


def test_deterministic_and_restartable():
    """Same input → bitwise the same trajectory, also when restarted from (t, y, h)."""
    m, a = _setup(1e-6)
    _, b = _setup(1e-6)
    a.advance(2e-4)
    a.advance(4e-4)
    b.advance(2e-4)
    c = Stepper(m, fo.constant_loads(fa=2000.0), b.y.copy(), t=b.t, h=b.h, tol=1e-6)
    c.advance(4e-4)
    assert np.array_equal(a.y, c.y)
