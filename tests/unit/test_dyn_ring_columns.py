"""The inner ring's Jacobian columns derived from the balls' own sweeps (issue 14,
:func:`bearingsim.dynamics.integrate.jacobian.ring_columns`): a ball's inner contact sees the ring only through
the pair's relative position and motion, so the ring's columns follow from the balls' derivatives of their
recorded inner-ring reactions.  These are consistency tests against the engine's own finite differences of the
ring's states (:func:`~bearingsim.dynamics.integrate.jacobian.ring_jac`, the path used before), not literature
validation: a W-method's Jacobian is an approximation by design; what it must be is close to ∂f/∂y."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import model as md
from bearingsim.dynamics import run as R
from bearingsim.dynamics.case import load_case
from bearingsim.dynamics.integrate import INFO_SIZE, ros34_workspace, ros34pw2
from bearingsim.dynamics.integrate import jacobian as jc
from bearingsim.dynamics.integrate.linalg import NR
from bearingsim.dynamics.loads import SpeedHistory
from bearingsim.io import load_bearing
from bearingsim.statics import jones_harris as jh
from bearingsim.units import parse_quantity

CASES = {
    "hub 100 km/h": ("examples/hub-moment-50hz.toml", None, 1e-3),
    "hub 10 km/h": ("examples/hub-moment-50hz.toml", "83.55 rpm", 2e-3),
    "7011": ("examples/spindle-7011.toml", None, 1e-3),
}


@pytest.fixture(scope="module")
def states():
    """Each case's model after a short run (loaded balls, moving ring, the film traction on)."""
    out = {}
    for name, (path, speed, t) in CASES.items():
        c = load_case(path)
        if speed:
            c = dataclasses.replace(c, speed=SpeedHistory(parse_quantity(speed, "speed", "speed")))
        m, ls, y, _ = R.build(c)
        s = R.Stepper(m, ls, y.copy(), tol=c.tolerance, method=c.method, threads=1)
        s.advance(t)
        out[name] = (m, ls, s)
    return out


def _both(m, ls, s, y, t):
    """(J_rr, J_br) by the ring's finite differences and by ring_columns, at (t, y)."""
    args = fo.args_of(m, ls)
    ws = s.workspace
    blk, nbk, atol = ws.blk, ws.nbk, ws.atol
    nb, n = blk.size, y.size
    f0 = np.empty(n)
    yt, f1 = np.empty(n), np.empty(n)
    jrr = np.zeros((NR, NR))
    jbr = np.zeros((nb, nbk, NR))
    fo.rhs_args(t, y, f0, args)
    jc.ring_jac(fo.rhs_args, args, t, y, f0, atol, blk, nbk, jrr, jbr, yt, f1)
    fo.rhs_args(t, y, f0, args)  # the record at y
    rec = args[10]
    rbase = np.zeros((nb + 1, 6))
    rbase[:nb] = rec[:nb, ly.MEMO_INNER:ly.MEMO_INNER + 6]
    rbase[nb] = rec[nb, :6]
    assert rec[nb, ly.MR_DERIVE] == 1.0
    drec = np.zeros((nb, nbk, 6))
    jac = np.zeros((nb, nbk, nbk))
    jc.block_jac(fo.rhs_args, args, t, y, f0, atol, blk, nbk, jac, yt, f1, np.empty(nb), rec, rbase, drec)
    jrr2 = np.zeros((NR, NR))
    jbr2 = np.zeros((nb, nbk, NR))
    jc.ring_columns(y, blk, rbase, drec, ws.rmass, ws.bmass, jrr2, jbr2)
    return jrr, jbr, jrr2, jbr2


@settings(max_examples=12, deadline=None)
@given(case=st.sampled_from(sorted(CASES)), tilt=st.tuples(*[st.floats(-1e-3, 1e-3)] * 2),
       cdot=st.tuples(*[st.floats(-1e-2, 1e-2)] * 3), rates=st.tuples(*[st.floats(-5.0, 5.0)] * 2))
def test_derived_ring_columns_match_the_ring_differences(states, case, tilt, cdot, rates):
    """Over tilts up to 1 mrad, centre velocities up to 10 mm/s and tilt rates up to 5 rad/s added to a running
    state, each of the ten ring columns of J_rr (the ring's acceleration rows) and of J_br (all balls' rows
    stacked) is within 1 % of the finite differences (measured ≤ 4.5e-3: the one-sided differences' own error and
    the film's entrainment speed, which the contact takes in a frame orbiting about the fixed axis and so does
    not move with the pair — both of the order of the slide-roll ratio).  Leaving out the turn of the forces with
    a tilt, the lever e_j × F of the ball's moment, or the tilt rate's ∂wtilt/∂γy puts a column off by O(1)."""
    m, ls, s = states[case]
    y = s.y.copy()
    y[3:5] += tilt
    y[5:8] += cdot
    y[8:10] += rates
    jrr, jbr, jrr2, jbr2 = _both(m, ls, s, y, s.t)
    err_rr = np.linalg.norm(jrr2[5:] - jrr[5:], axis=0) / np.linalg.norm(jrr[5:], axis=0)
    a, b = jbr.reshape(-1, NR), jbr2.reshape(-1, NR)
    err_br = np.linalg.norm(b - a, axis=0) / np.linalg.norm(a, axis=0)
    assert np.all(np.isfinite(err_rr)) and np.all(np.isfinite(err_br))
    assert err_rr.max() < 1e-2, f"{case}: J_rr columns off the ring's finite differences by {err_rr}"
    assert err_br.max() < 1e-2, f"{case}: J_br columns off the ring's finite differences by {err_br}"
    np.testing.assert_array_equal(jrr2[0:5], jrr[0:5], err_msg="kinematic rows q' = q̇ (exact in both)")


def test_record_sums_to_the_ring_contact_force(states):
    """The record's inner-ring reactions are the ring's contact force: m_r (c̈ − g) − F_applied = Σ_k F_R,k
    (ring_equations), and its ring row holds I_p Ω / I_t."""
    m, ls, s = states["hub 100 km/h"]
    args = fo.args_of(m, ls)
    dy = np.zeros_like(s.y)
    fo.rhs_args(s.t, s.y, dy, args)
    nb = m.n_balls
    rec = args[10]
    loads = np.zeros(5)
    fo.loads_at(s.t, ls, loads)
    mr = m.gp[ly.G_MR]
    g = m.gp[ly.G_GX:ly.G_GX + 3]
    contact = mr * (dy[5:8] - g) - loads[0:3]
    total = rec[:nb, ly.MEMO_INNER:ly.MEMO_INNER + 3].sum(axis=0)
    np.testing.assert_allclose(total, contact, rtol=1e-9, atol=1e-9 * np.abs(contact).max())
    omega = fo.speed_at(s.t, m.gp)
    assert rec[nb, ly.MR_GYRO] == pytest.approx(m.gp[ly.G_IPR] * omega / m.gp[ly.G_ITR], rel=1e-15)
    assert abs(rec[nb, ly.MR_GYRO]) > 0


def _one_step_work(m, ls, y, t, args, h=1e-7):
    """Right-hand sides of one ROS34PW2 step that starts with a Jacobian refresh: f(t, y), the refresh, three
    stages."""
    blk = np.array([m.ball_slice(k).start for k in range(m.n_balls)], dtype=np.int64)
    atol, rtol = md.tolerance_vectors(m, 1e-6)
    rmass = np.array([m.gp[ly.G_MR]] * 3 + [m.gp[ly.G_ITR]] * 2)
    from bearingsim.statics import layout as kn

    bmass = np.array([[m.rows[r, kn.P_MASS], m.rows[r, kn.P_JB]] for r in m.ball_row])
    info = np.zeros(INFO_SIZE)
    ws = ros34_workspace(m.n_balls, ly.N_BALL, True)
    ros34pw2.integrate(fo.rhs_args, args, t, t + 10.0, y.copy(), h, atol, rtol, 1e-14, 1, info, blk, ly.N_BALL,
                       20, ws, rmass, bmass, rec=args[10])
    return int(info[0] + info[1]), int(info[4])


def test_refresh_takes_the_balls_sweeps_only_where_the_model_allows(states):
    """One step with a refresh: 1 + 9 + 3 right-hand sides with the record (the ring's columns derived), 1 + (10 +
    9) + 3 without it (memo off) or where the balls' sweeps do not see everything the ring feels (a cage guided on
    the inner ring's land) — the integrator takes the differences there."""
    m, ls, s = states["hub 100 km/h"]
    assert _one_step_work(m, ls, s.y, s.t, fo.args_of(m, ls)) == (1, 1 + ly.N_BALL + 3)
    assert _one_step_work(m, ls, s.y, s.t, fo.args_of(m, ls, memo=False)) == (1, 1 + NR + ly.N_BALL + 3)
    b = load_bearing("skf-7011-cdga-hc")
    w = 6000 * math.pi / 30
    res = jh.solve(b, jh.Loads(fa=2000.0), w)
    for guidance, derived in (("balls", True), ("outer-land", True), ("inner-land", False)):
        mg = md.build_model(b, ring_mass=2.0, damping_alpha=0.05, traction="coulomb", speed=(w, w, 0.0),
                            guidance=guidance)
        yg = md.initial_state(mg, res, w)
        lg = fo.constant_loads(fa=2000.0)
        args = fo.args_of(mg, lg)
        steps, nfun = _one_step_work(mg, lg, yg, 0.0, args)
        assert args[10][mg.n_balls, ly.MR_DERIVE] == (1.0 if derived else 0.0), guidance
        assert (steps, nfun) == (1, 1 + ly.N_BALL + 3 + (0 if derived else NR)), guidance


def test_derived_and_differenced_ring_columns_give_the_same_trajectory(states):
    """Consistency: ROS34PW2 with the derived ring columns and with the differenced ones (memo off) follow the same
    hub trajectory to the tolerance over 1 ms (the W-method's result does not depend on its Jacobian beyond the
    error it controls), and the derived one evaluates fewer right-hand sides per step."""
    m, ls, s = states["hub 100 km/h"]
    ws = s.workspace
    out = {}
    for memo in (True, False):
        args = fo.args_of(m, ls, memo=memo)
        y = s.y.copy()
        info = np.zeros(INFO_SIZE)
        ros34pw2.integrate(fo.rhs_args, args, s.t, s.t + 1e-3, y, s.h, ws.atol, ws.rtol, s.h_min, 10**7, info,
                           ws.blk, ws.nbk, 20, ros34_workspace(m.n_balls, ly.N_BALL, True), ws.rmass, ws.bmass,
                           rec=args[10])
        out[memo] = (y, int(info[0]), int(info[4]))
    span = np.abs(out[True][0][0:5] - s.y[0:5]).max()
    assert span > 0
    dev = np.abs(out[True][0][0:5] - out[False][0][0:5]).max() / span
    print(f"ring: derived vs differenced columns {dev:.2e} of the ring's travel; steps, right-hand sides "
          f"{out[True][1:]} vs {out[False][1:]}")
    # a W-method's solution does not depend on J beyond the error it controls: within the tolerance 1e-6 of the travel
    assert dev < 1e-6, dev  # (measured 1.8e-9)
    assert out[True][2] / out[True][1] < out[False][2] / out[False][1], (out[True][1:], out[False][1:])


def test_engine_kernel_derives_the_ring_columns(states):
    """The path the user takes (Stepper → the cached ROS34PW2 kernel): a refresh costs at most the 9 ball sweeps and
    one right-hand side for the record, not 9 + 10 (work counts of the run: 3 per attempted step, 1 per accepted
    step, the refreshes).  The threaded kernel passes the same record: tests/unit/test_dyn_threads.py holds its
    trajectory bit for bit to this one's."""
    m, ls, s = states["hub 100 km/h"]
    for threads in (1,):
        st_ = R.Stepper(m, ls, s.y.copy(), t=s.t, h=s.h, tol=1e-6, method="ros34w", threads=threads, jac_every=5)
        st_.advance(s.t + 2e-4)
        acc, rej = st_.steps, st_.rejected
        nfun, _, njac = (int(v) for v in st_.workspace.work[:3])
        assert njac >= 3, (acc, rej, njac)
        per_refresh = (nfun - 3 * (acc + rej) - acc - 2) / njac
        assert per_refresh <= ly.N_BALL + 1, (threads, acc, rej, nfun, njac)
