"""Linear algebra of the W-methods: W = I − γ h J with J block diagonal per ball, or the arrowhead
J of the inner ring coupled with its balls.

State layout (:mod:`bearingsim.dynamics.layout`): the inner ring's NR = N_RING = 10 states come
first; ball b's nbk states start at ``blk[b]``; every other state (cages, modes) has J = 0 there, so
W is the identity on them.  Per-ball blocks are inverted explicitly (:func:`invert_small`, 9 × 9);
with the ring coupling,

    W = [[W_rr, W_r1, …, W_rn], [W_1r, W_11, 0 …], …, [W_nr, 0, …, W_nn]]   (an arrowhead),

solved through the ring's Schur complement S = W_rr − Σ_b W_rb W_bb⁻¹ W_br (Golub & Van Loan,
*Matrix Computations*, 4th ed. 2013, §3.2.11 / block elimination): :func:`coupled_w` forms the
ball inverses, Q_b = W_bb⁻¹ W_br and S⁻¹ once per step size, :func:`coupled_apply_w` solves
W x = v with them in O(n_balls) work.

The Jacobian turned with the balls' orbit (:func:`orbit_reference`, :func:`orbit_turn`, :func:`turned_solve`):
the ball states are Cartesian in the inertial frame (x the bearing axis), so a ball's Jacobian block
turns with it as it orbits.  With the outer ring fixed and axisymmetric, turning a ball and everything it touches
about the axis by Δψ turns its forces by Δψ; so where the load does not change along the orbit (an axial load, the
7011 case) J_b(ψ + Δψ) = T J_b(ψ) Tᵀ exactly, T = diag(R, R, R) and R the rotation by Δψ about x (y, z turned),
and the ring's coupling turns as T J_br, J_rb Tᵀ.  J made at the refresh is therefore used turned by each ball's
azimuth change since: J' = P J Pᵀ, P = diag(I_ring, T_1 … T_n, I), and W' = I − γhJ' = P W Pᵀ, so that
W'⁻¹ v = P W⁻¹ (Pᵀ v) — the factorised W serves with two turns of each ball's three vectors per solve (the ring's
Schur complement is invariant: W_rb Tᵀ T W_bb⁻¹ Tᵀ T W_br).  A W-method is of order 3 with any J; what the turn
restores is the stability that an aging J loses as the balls move (7011 (a): the mean step one step after a
refresh 5.2 µs, eight steps later 2.8 µs without the turn).
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from .. import threads as _threads  # noqa: F401 - numba's threading layer, chosen and started
from ..layout import N_BALL, N_RING

NR = N_RING  #: inner-ring states (q, q̇) at the start of the state vector
NB = N_BALL  #: states of a ball block (r, v, ω): the ring–ball coupling's blocks have this size


@njit(cache=True, _nrt=False)
def apply_w(winv, blk, nbk, v, out):
    """out = W⁻¹ v with W block diagonal: W_b on the blocks, identity elsewhere."""
    for i in range(v.shape[0]):
        out[i] = v[i]
    for b in range(blk.shape[0]):
        o = blk[b]
        for i in range(nbk):
            s = 0.0
            for j in range(nbk):
                s += winv[b, i, j] * v[o + j]
            out[o + i] = s


@njit(cache=True, _nrt=False)
def w_solve(winv, blk, nbk, hs, g, cpl, v, out):
    """out = W⁻¹ v: block-diagonal W, or the arrowhead W of the ring–ball coupling when ``cpl`` holds it."""
    jrr, jbr, jrb, q, sinv, z, r = cpl
    if jbr.shape[0] > 0:
        coupled_apply_w(winv, q, sinv, jrb, hs, g, blk, nbk, v, out, z, r)
    else:
        apply_w(winv, blk, nbk, v, out)


@njit(cache=True)
def no_coupling(nbk):
    """The ``cpl`` argument of :func:`w_solve` without the ring–ball coupling: (J_rr,
    J_br, J_rb, Q, S⁻¹, work, work) with no ball rows (the coupled form is built in ROS34PW2)."""
    return (np.zeros((NR, NR)), np.zeros((0, nbk, NR)), np.zeros((0, NR, nbk)), np.zeros((0, nbk, NR)),
            np.zeros((NR, NR)), np.zeros((0, nbk)), np.zeros(NR))


@njit(cache=True, inline="always")
def _gauss_jordan(a, out, n):
    """out = a⁻¹ (n × n) by Gauss–Jordan elimination with partial pivoting (a is overwritten).  Inlined into its
    callers, so that a constant n (:func:`_invert6`) compiles to loops of known length."""
    for i in range(n):
        for j in range(n):
            out[i, j] = 0.0
        out[i, i] = 1.0
    for c in range(n):
        p = c
        big = abs(a[c, c])
        for r in range(c + 1, n):
            if abs(a[r, c]) > big:
                big = abs(a[r, c])
                p = r
        if p != c:
            for j in range(n):
                tmp = a[c, j]
                a[c, j] = a[p, j]
                a[p, j] = tmp
                tmp = out[c, j]
                out[c, j] = out[p, j]
                out[p, j] = tmp
        d = 1.0 / a[c, c]
        for j in range(n):
            a[c, j] *= d
            out[c, j] *= d
        for r in range(n):
            if r != c:
                f = a[r, c]
                if f != 0.0:
                    for j in range(n):
                        a[r, j] -= f * a[c, j]
                        out[r, j] -= f * out[c, j]


@njit(cache=True, _nrt=False)
def invert_small(a, out):
    """out = a⁻¹ by Gauss–Jordan elimination with partial pivoting (a is overwritten);
    for the 9×9 blocks this is ~10× faster than a LAPACK call from numba."""
    _gauss_jordan(a, out, a.shape[0])


@njit(cache=True, _nrt=False)
def _invert6(a, out):
    """:func:`invert_small` for 6 × 6, the loops' length known when compiling (7.8 against 13.6 µs for the 32 ball
    blocks of the hub case)."""
    _gauss_jordan(a, out, 6)


@njit(cache=True, _nrt=False)
def kinematic_rows(jb):
    """True when the block jb (9 × 9, a ball's r, v, ω) has the kinematic rows ṙ = v exactly: rows 0–2 are
    [0 I 0] (so the finite differences give them: the position's derivative is the velocity state itself)."""
    if jb.shape[0] != 9:
        return False
    for i in range(3):
        for j in range(9):
            if jb[i, j] != (1.0 if j == i + 3 else 0.0):
                return False
    return True


@njit(cache=True, _nrt=False)
def block_w_inverse(jb, c, wm, out):
    """out = (I + c J_b)⁻¹ for one block (c = −γh; wm a work array of the block's size, overwritten).

    A ball's block J_b = [[0, I, 0], [G, H]] (rows 0–2 the kinematic ṙ = v, G its 6 × 3 position columns below,
    H its 6 × 6 velocity columns below) is inverted through its velocity part: with k_r = r_r − c k_v from the
    first rows, W k = r reduces to M k_vω = r_vω − c G r_r, M = I + c H − c² G P (P k_vω = k_v), and
    W⁻¹ = [[I + c² N_v G, −c N_v], [−c N G, N]] with N = M⁻¹ and N_v its first three rows (block elimination,
    Golub & Van Loan, *Matrix Computations*, 4th ed. 2013, §3.2.11): a 6 × 6 inversion instead of a 9 × 9 one.
    Any other block: Gauss–Jordan on the whole block (:func:`invert_small`)."""
    n = jb.shape[0]
    if not kinematic_rows(jb):
        for i in range(n):
            for j in range(n):
                wm[i, j] = c * jb[i, j]
            wm[i, i] += 1.0
        invert_small(wm, out)
        return
    m6 = wm[0:6, 0:6]
    ninv = out[3:9, 3:9]  # N = M⁻¹ lands in its place in W⁻¹
    c2 = c * c
    for i in range(6):
        for j in range(6):
            m6[i, j] = c * jb[3 + i, 3 + j]
        for j in range(3):
            m6[i, j] -= c2 * jb[3 + i, j]
        m6[i, i] += 1.0
    _invert6(m6, ninv)
    for i in range(6):
        for j in range(3):
            acc = 0.0
            for k in range(6):
                acc += ninv[i, k] * jb[3 + k, j]
            out[3 + i, j] = -c * acc  # −c N G
    for i in range(3):
        for j in range(3):
            out[i, j] = -c * out[3 + i, j]  # c² N_v G
        out[i, i] += 1.0
        for j in range(6):
            out[i, 3 + j] = -c * ninv[i, j]


@njit(cache=True, _nrt=False)
def w_inverse(jac, hs, g, winv, wm):
    """winv[b] = (I − g hs J_b)⁻¹ for every block b (:func:`block_w_inverse`)."""
    c = -g * hs
    for b in range(jac.shape[0]):
        block_w_inverse(jac[b], c, wm, winv[b])


@njit(cache=True, _nrt=False)
def _coupled_w_ball(b, jac, jbr, jrb, c, winv, wm, q, sb):
    """Ball b's part of :func:`coupled_w` (c = −g hs): winv[b] = W_bb⁻¹, q[b] = Q_b = W_bb⁻¹ W_br and
    sb = W_rb Q_b (its term of the Schur complement), with wm a 9 × 9 work array."""
    block_w_inverse(jac[b], c, wm, winv[b])
    # J_br's rows 0–2 (ṙ = v of the ball) and J_rb's rows 0–4 (the ring's q̇ = q̇) are zero by construction
    # (jacobian.ring_jac, jacobian.ring_rows): their terms are skipped (they added exact zeros: the same numbers)
    # the sums over k run outermost and the rows' ten columns j innermost (contiguous, so the compiler packs them):
    # each element still adds its terms in ascending k from 0.0, the same numbers as a dot product per element
    for i in range(NB):
        for j in range(NR):
            q[b, i, j] = 0.0
        for k in range(3, NB):
            wc = winv[b, i, k] * c
            for j in range(NR):
                q[b, i, j] += wc * jbr[b, k, j]
    for i in range(NR):
        for j in range(NR):
            sb[i, j] = 0.0
    for i in range(NR // 2, NR):
        for k in range(NB):
            cj = c * jrb[b, i, k]
            for j in range(NR):
                sb[i, j] += cj * q[b, k, j]


@njit(cache=True, _nrt=False)
def coupled_w(jac, jrr, jbr, jrb, hs, g, winv, wm, q, sinv, srr, sb):
    """Arrowhead W = I − g hs J with ring block, ball blocks and ring–ball coupling: ball block
    inverses winv, Q_b = W_bb⁻¹ W_br, and the inverse of the ring's Schur complement
    S = W_rr − Σ_b W_rb Q_b (the balls' terms subtracted in ball order).  sb: (n_balls, NR, NR) work.
    J_br's rows 0–2 and J_rb's rows 0–4 must be zero (the kinematic rows ṙ = v, q̇ = q̇: so
    :func:`.jacobian.ring_jac` and :func:`.jacobian.ring_rows` make them); their products are skipped (30.7 against
    36.8 µs on hub-sized blocks).  The ball blocks are inverted through their velocity part (:func:`block_w_inverse`)
    and the loops run to the constant N_BALL = 9 (21 against 30.7 µs)."""
    if jac.shape[1] != NB:
        raise ValueError("coupled_w: the ball blocks must have N_BALL = 9 states")
    nb = jac.shape[0]
    c = -g * hs
    for b in range(nb):
        _coupled_w_ball(b, jac, jbr, jrb, c, winv, wm, q, sb[b])
    _schur_inverse(jrr, c, sb, sinv, srr)


@njit(cache=True, parallel=True)
def coupled_w_threaded(jac, jrr, jbr, jrb, hs, g, winv, wmb, q, sinv, srr, sb):
    """:func:`coupled_w` with the balls on ``numba.get_num_threads()`` threads (wmb: a 9 × 9 work array per
    ball); the Schur complement is summed serially in ball order, so the result is the same bit for bit."""
    if jac.shape[1] != NB:
        raise ValueError("coupled_w_threaded: the ball blocks must have N_BALL = 9 states")
    nb = jac.shape[0]
    c = -g * hs
    for b in prange(nb):
        _coupled_w_ball(b, jac, jbr, jrb, c, winv, wmb[b], q, sb[b])
    _schur_inverse(jrr, c, sb, sinv, srr)


@njit(cache=True, _nrt=False)
def _schur_inverse(jrr, c, sb, sinv, srr):
    """sinv = S⁻¹, S = I + c J_rr − Σ_b sb[b] (subtracted in ball order); srr is overwritten."""
    for i in range(NR):
        for j in range(NR):
            srr[i, j] = c * jrr[i, j]
        srr[i, i] += 1.0
    for b in range(sb.shape[0]):
        for i in range(NR):
            for j in range(NR):
                srr[i, j] -= sb[b, i, j]
    invert_small(srr, sinv)


@njit(cache=True, _nrt=False)
def coupled_apply_w(winv, q, sinv, jrb, hs, g, blk, nbk, v, out, z, r):
    """out = W⁻¹ v for the arrowhead W of :func:`coupled_w` (identity outside ring and balls; ball blocks of
    N_BALL = 9 states, the loops' bounds known when compiling: ``nbk`` is that size)."""
    c = -g * hs
    for i in range(v.shape[0]):
        out[i] = v[i]
    nb = blk.shape[0]
    for i in range(NR):
        r[i] = v[i]
    for b in range(nb):
        o = blk[b]
        for i in range(NB):
            acc = 0.0
            for j in range(NB):
                acc += winv[b, i, j] * v[o + j]
            z[b, i] = acc
        for i in range(NR // 2, NR):  # J_rb's rows 0–4 are zero (coupled_w)
            acc = 0.0
            for j in range(NB):
                acc += c * jrb[b, i, j] * z[b, j]
            r[i] -= acc
    for i in range(NR):
        acc = 0.0
        for j in range(NR):
            acc += sinv[i, j] * r[j]
        out[i] = acc
    for b in range(nb):
        o = blk[b]
        for i in range(NB):
            acc = z[b, i]
            for j in range(NR):
                acc -= q[b, i, j] * out[j]
            out[o + i] = acc


@njit(cache=True, _nrt=False, inline="always")
def _azimuth(y, o):
    """(cos ψ, sin ψ) = (y, z)/√(y² + z²) of the ball centre at y[o:o + 3] ((1, 0) on the axis)."""
    py = y[o + 1]
    pz = y[o + 2]
    r2 = py * py + pz * pz
    if r2 > 0.0:
        rr = 1.0 / np.sqrt(r2)
        return py * rr, pz * rr
    return 1.0, 0.0


@njit(cache=True, _nrt=False)
def orbit_reference(y, blk, jaz):
    """jaz[b] ← ball b's azimuth direction (cos ψ, sin ψ) (at the Jacobian's refresh)."""
    for b in range(blk.shape[0]):
        jaz[b, 0], jaz[b, 1] = _azimuth(y, blk[b])


@njit(cache=True, _nrt=False)
def orbit_turn(y, blk, jaz, turn):
    """turn[b] ← (cos Δψ, sin Δψ) of ball b's azimuth change since :func:`orbit_reference` stored ``jaz``."""
    for b in range(blk.shape[0]):
        c, s = _azimuth(y, blk[b])
        turn[b, 0] = jaz[b, 0] * c + jaz[b, 1] * s
        turn[b, 1] = jaz[b, 0] * s - jaz[b, 1] * c


@njit(cache=True, _nrt=False, inline="always")
def _turn_balls(blk, turn, v, sign):
    """Each ball's three vectors (r, v, ω) in ``v`` turned about x by +Δψ (sign 1) or −Δψ (sign −1)."""
    for b in range(turn.shape[0]):
        c = turn[b, 0]
        s = sign * turn[b, 1]
        o = blk[b]
        for j in range(3):
            i = o + 3 * j + 1
            vy = v[i]
            vz = v[i + 1]
            v[i] = c * vy - s * vz
            v[i + 1] = s * vy + c * vz


@njit(cache=True, _nrt=False)
def turned_solve(winv, blk, nbk, hs, g, cpl, v, out, turn):
    """out = W'⁻¹ v = P W⁻¹ Pᵀ v for the Jacobian turned with the balls' orbit (module docstring; ``turn`` from
    :func:`orbit_turn`, no rows: W⁻¹ v).  ``v`` is overwritten (turned back by −Δψ)."""
    if turn.shape[0] > 0:
        _turn_balls(blk, turn, v, -1.0)
    w_solve(winv, blk, nbk, hs, g, cpl, v, out)
    if turn.shape[0] > 0:
        _turn_balls(blk, turn, out, 1.0)
