"""The Jacobian turned with the balls' orbit (issue 14, seventeenth pass; :mod:`bearingsim.dynamics.integrate.linalg`).

Three kinds of check: the algebra (W'⁻¹ v = P W⁻¹ Pᵀ v against the dense solve of the turned matrix), the premise
(on the axially loaded 7011 a ball's finite-difference Jacobian block later in its orbit is the earlier block turned
by the azimuth change, T J Tᵀ), and the engine (the path the user takes: fewer steps with the turn, the same
trajectory to the tolerance)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from _blocks import arrowhead_system, ball_like_block  # tests/unit/_blocks.py
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import run as R
from bearingsim.dynamics.case import load_case
from bearingsim.dynamics.integrate import linalg as la
from bearingsim.dynamics.integrate.jacobian import block_jac, no_record

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _turn_matrix(blk, nbk, n, turn):
    """P = diag(I_ring, T_1 … T_n, I): T_b turns each of ball b's three vectors about x by its Δψ."""
    p = np.eye(n)
    for b, o in enumerate(blk):
        c, s = turn[b]
        rot = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
        for j in range(3):
            i = o + 3 * j
            p[i:i + 3, i:i + 3] = rot
    return p


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(0, 2**31 - 1), angles=st.lists(st.floats(-3.2, 3.2), min_size=3, max_size=3))
def test_turned_solve_equals_the_dense_solve_of_the_turned_jacobian(seed, angles):
    """The factorised W of J serves the turned J' = P J Pᵀ exactly (the ring's Schur complement is invariant)."""
    rng = np.random.default_rng(seed)
    nb, nbk, extra = 3, 9, 5
    n = la.NR + nb * nbk + extra
    jac = np.array([ball_like_block(rng, 50.0) for _ in range(nb)])
    blk, jrr, jbr, jrb, dense = arrowhead_system(rng, jac, extra)
    hs, g = 1e-3, 0.435866521508459
    winv = np.zeros((nb, nbk, nbk))
    q = np.zeros((nb, nbk, la.NR))
    sinv = np.zeros((la.NR, la.NR))
    la.coupled_w(jac, jrr, jbr, jrb, hs, g, winv, np.zeros((nbk, nbk)), q, sinv, np.zeros((la.NR, la.NR)),
                 np.zeros((nb, la.NR, la.NR)))
    cpl = (jrr, jbr, jrb, q, sinv, np.zeros((nb, nbk)), np.zeros(la.NR))
    turn = np.array([[np.cos(a), np.sin(a)] for a in angles])
    p = _turn_matrix(blk, nbk, n, turn)
    v = rng.normal(size=n)
    out = np.zeros(n)
    la.turned_solve(winv, blk, nbk, hs, g, cpl, v.copy(), out, turn)
    expect = np.linalg.solve(np.eye(n) - g * hs * (p @ dense @ p.T), v)
    np.testing.assert_allclose(out, expect, rtol=1e-10, atol=1e-12)
    # no rows: the plain solve
    out0 = np.zeros(n)
    la.turned_solve(winv, blk, nbk, hs, g, cpl, v.copy(), out0, np.zeros((0, 2)))
    np.testing.assert_allclose(out0, np.linalg.solve(np.eye(n) - g * hs * dense, v), rtol=1e-10, atol=1e-12)


def test_orbit_turn_measures_the_azimuth_change():
    rng = np.random.default_rng(0)
    nb = 4
    blk = np.array([10 + 9 * b for b in range(nb)], dtype=np.int64)
    y = np.zeros(10 + 9 * nb)
    psi0 = rng.uniform(-np.pi, np.pi, nb)
    rad = rng.uniform(0.01, 0.05, nb)
    for b in range(nb):
        y[blk[b] + 1:blk[b] + 3] = rad[b] * np.cos(psi0[b]), rad[b] * np.sin(psi0[b])
    jaz = np.zeros((nb, 2))
    la.orbit_reference(y, blk, jaz)
    dpsi = rng.uniform(-0.5, 0.5, nb)
    for b in range(nb):
        y[blk[b] + 1:blk[b] + 3] = 1.01 * rad[b] * np.cos(psi0[b] + dpsi[b]), 1.01 * rad[b] * np.sin(psi0[b] + dpsi[b])
    turn = np.zeros((nb, 2))
    la.orbit_turn(y, blk, jaz, turn)
    np.testing.assert_allclose(turn[:, 0], np.cos(dpsi), atol=1e-14)
    np.testing.assert_allclose(turn[:, 1], np.sin(dpsi), atol=1e-14)


@pytest.fixture(scope="module")
def spindle():
    case = load_case(EXAMPLES / "spindle-7011.toml")
    m, ls, y, _ = R.build(case)
    st_ = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, dense=True)
    st_.advance(2e-3)
    return case, m, ls, st_


def _ball_blocks(m, ls, st_, y, t):
    args = fo.args_of(m, ls)
    ws = st_.workspace
    nb, nbk = ws.blk.shape[0], ws.nbk
    n = y.shape[0]
    f0 = np.empty(n)
    fo.rhs_args(t, y, f0, args)
    jac = np.zeros((nb, nbk, nbk))
    e1, e2, e3 = no_record()
    block_jac(fo.rhs_args, args, t, y, f0, ws.atol, ws.blk, nbk, jac, np.empty(n), np.empty(n), np.empty(nb),
              e1, e2, e3)
    return jac


def test_a_balls_jacobian_block_turns_with_its_orbit(spindle):
    """The premise, on the 7011 under its axial load: ball b's finite-difference block 40 µs later (≈ 1° of orbit)
    is T J_b Tᵀ of the earlier one within 0.3 % (relative Frobenius norm; measured ≤ 0.11 %, the finite differences'
    own scatter), while the block as made is off by ≥ 1.4 % — the Jacobian's aging that the turn removes."""
    case, m, ls, st_ = spindle
    y1, t1 = st_.y.copy(), st_.t
    j1 = _ball_blocks(m, ls, st_, y1, t1)
    st_.advance(st_.t + 4e-5)
    y2, t2 = st_.y.copy(), st_.t
    j2 = _ball_blocks(m, ls, st_, y2, t2)
    blk = st_.workspace.blk
    jaz = np.zeros((blk.shape[0], 2))
    la.orbit_reference(y1, blk, jaz)
    turn = np.zeros_like(jaz)
    la.orbit_turn(y2, blk, jaz, turn)
    assert np.all(np.abs(np.arctan2(turn[:, 1], turn[:, 0])) > 5e-3)  # the balls moved on their orbit
    turned, plain = [], []
    for b in range(blk.shape[0]):
        c, s = turn[b]
        rot = np.kron(np.eye(3), np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]]))
        nrm = np.linalg.norm(j2[b])
        turned.append(np.linalg.norm(j2[b] - rot @ j1[b] @ rot.T) / nrm)
        plain.append(np.linalg.norm(j2[b] - j1[b]) / nrm)
    assert max(turned) < 3e-3, max(turned)
    assert min(plain) > 5 * max(turned), (min(plain), max(turned))


def test_engine_steps_with_the_turned_jacobian(spindle):
    """The path the user takes (Stepper, the cached kernel), 7011 (a) over 1 ms from its state at 2 ms: the turned
    Jacobian takes fewer steps than the Jacobian as made, and both runs end within 1e-8 m of a run at tolerance
    1e-8 (the ring's displacement; the position tolerance is 1e-9 m per step at 1e-6; measured 1.3e-9 turned in 114
    steps, 5.2e-9 as made in 299)."""
    case, m, ls, st_ = spindle
    out = {}
    for orbit, tol in ((True, case.tolerance), (False, case.tolerance), (True, 1e-8)):
        s2 = R.Stepper(m, ls, st_.y.copy(), t=st_.t, h=st_.h, tol=tol, method=case.method, threads=1,
                       jac_orbit=orbit)
        s2.advance(st_.t + 1e-3)
        out[orbit, tol] = (s2.steps, s2.y.copy(), s2._ws[6].shape)
    turned, plain, ref = out[True, case.tolerance], out[False, case.tolerance], out[True, 1e-8]
    assert turned[2] == (m.n_balls, 2) and plain[2] == (0, 2)
    assert turned[0] < 0.7 * plain[0], (turned[0], plain[0])
    ring = slice(ly.R_Q, ly.R_Q + 3)
    for run in (turned, plain):
        dev = np.abs(run[1][ring] - ref[1][ring]).max()
        assert dev < 1e-8, dev  # [m]
