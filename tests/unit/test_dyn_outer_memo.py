"""The outer-contact memo of the right-hand side (issue 14): the outer ring is fixed, so a ball's outer-raceway
contact depends on the ball's nine states alone; a right-hand side whose balls have not moved since the last one
(the ten finite-difference sweeps of the inner ring's Jacobian columns) takes it from the memo.  These tests hold
that a memo hit gives the numbers of a full evaluation bit for bit, whatever moves, that the memo is really used
(a planted value shows through) and never used where it must not be (a moved ball, diagnostics)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import run as R
from bearingsim.dynamics.case import load_case
from bearingsim.dynamics.integrate import jacobian as jc
from bearingsim.dynamics.integrate.linalg import NR
from bearingsim.statics import layout as kn


@pytest.fixture(scope="module")
def hub():
    """The hub unit of seed 001 with the lubricated sliced traction, in its initial (loaded) state."""
    m, ls, y, _ = R.build(load_case("examples/hub-moment-50hz.toml"))
    assert int(m.gp[ly.G_TRAC]) != 0  # traction on: the outer contacts carry the film law
    return m, ls, y


def _f(y, args):
    dy = np.zeros_like(y)
    fo.rhs_args(0.0, y, dy, args)
    return dy


@settings(max_examples=30, deadline=None)
@given(j=st.integers(0, NR - 1), rel=st.floats(-1e-3, 1e-3), ball=st.integers(-1, 31), bj=st.integers(0, 8),
       brel=st.floats(-1e-4, 1e-4))
def test_memo_hit_is_the_full_evaluation_bit_for_bit(hub, j, rel, ball, bj, brel):
    """After an evaluation at y, move the inner ring (any of its 10 states, by up to 1e-3 of its scale) and
    optionally one ball: the memo's right-hand side equals a memo-free one exactly."""
    m, ls, y = hub
    args = fo.args_of(m, ls)
    _f(y, args)  # fills the memo
    yt = y.copy()
    scale = (1e-4, 1e-4, 1e-4, 1e-3, 1e-3, 1e-2, 1e-2, 1e-2, 1.0, 1.0)[j]  # m, rad, m/s, rad/s
    yt[j] += rel * scale
    if ball >= 0:
        o = ly.N_RING + ly.N_BALL * ball
        yt[o + bj] += brel * max(abs(yt[o + bj]), 1e-3)
    with_memo = _f(yt, args)
    without = _f(yt, fo.args_of(m, ls, memo=False))
    assert np.array_equal(with_memo, without), np.abs(with_memo - without).max()


def test_memo_is_used_for_unmoved_balls_only(hub):
    """A value planted in the memo shows in the ball's acceleration while the ball has not moved (so the
    memo path really runs), and is ignored once the ball moves or with diagnostics on."""
    m, ls, y = hub
    args = fo.args_of(m, ls)
    ref = _f(y, args)
    memo = args[10]
    k = 3
    o = ly.N_RING + ly.N_BALL * k
    assert memo[k, 0] == 1.0 and np.array_equal(memo[k, 1:10], y[o:o + 9])
    mass = m.rows[m.ball_row[k], kn.P_MASS]
    memo[k, 10] += 1.0  # 1 N more outer-contact force along x on ball k
    planted = _f(y, args)
    assert planted[o + 3] - ref[o + 3] == pytest.approx(1.0 / mass, rel=1e-9)
    others = np.ones(y.shape, bool)
    others[o + 3] = False
    assert np.array_equal(planted[others], ref[others])
    # the ball moves: the memo row no longer matches, the contact is computed (and the memo refilled)
    yt = y.copy()
    yt[o + 4] += 1e-9
    assert np.array_equal(_f(yt, args), _f(yt, fo.args_of(m, ls, memo=False)))
    # diagnostics: always computed (the memo holds no diagnostics)
    args_d = fo.args_of(m, ls, diag=np.zeros((m.n_balls, ly.NDB)), gdiag=np.zeros(ly.NDG))
    _f(y, args_d)
    args_d[10][k, 10] += 1.0
    assert np.array_equal(_f(y, args_d), ref)


def test_ring_columns_with_the_memo_are_those_without(hub):
    """The inner ring's finite-difference Jacobian columns (where the memo pays: ten sweeps with the balls
    unmoved) are bit for bit those of memo-free sweeps."""
    m, ls, y = hub
    blk = np.array([m.ball_slice(k).start for k in range(m.n_balls)], dtype=np.int64)
    atol = np.full(y.shape, 1e-9)
    out = []
    for memo in (True, False):
        args = fo.args_of(m, ls, memo=memo)
        f0 = _f(y, args)
        jrr = np.zeros((NR, NR))
        jbr = np.zeros((m.n_balls, ly.N_BALL, NR))
        jc.ring_jac(fo.rhs_args, args, 0.0, y, f0, atol, blk, ly.N_BALL, jrr, jbr, np.empty_like(y),
                    np.empty_like(y))
        out.append((jrr, jbr))
    assert np.abs(out[0][1]).max() > 0
    assert np.array_equal(out[0][0], out[1][0]) and np.array_equal(out[0][1], out[1][1])
