"""Finite-difference Jacobians of the W-methods: per-ball blocks, the inner ring's columns (by differences, or
derived from the balls' by the invariance of a contact), and the ring's rows by the symmetry of the contact forces.

J ≈ ∂f/∂y is only an approximation in a W-method (the order does not depend on it), so it is
estimated cheaply: forward differences with the step 1e-7 max(|y_j|, 1e4 atol_j), one component of
every ball block perturbed at once (:func:`block_jac`: the balls' derivatives do not depend on each
other's states directly), the ring's 10 columns one at a time (:func:`ring_jac`), and the ring's rows
from the balls' columns (:func:`ring_rows`).  Layout: :mod:`.linalg`.

Each difference is divided by the step actually taken, (y + e) − y in floating point, not by e (Press et al.,
*Numerical Recipes*, 3rd ed. 2007, §5.7): a derivative that is a state itself (a ball's ṙ = v, the ring's
q̇ = q̇) then comes out exactly 1, so the kinematic rows of J are exact and :func:`.linalg.block_w_inverse`
can eliminate them (divided by e they would be 1 ± 1e-9).

The ring's columns cost 10 right-hand sides by differences (:func:`ring_jac`, ≈ 5.8 with the outer-contact memo).
:func:`ring_columns` derives them from the balls' own sweeps instead: a ball's inner contact depends
on the ring's state only through the two bodies' relative position and motion, so moving the ring is moving the
ball the other way, and tilting it is turning the pair about the ring's centre (the contact's forces turn with
it).  The right-hand side records each ball's inner-ring reaction (``memo``, layout ``MEMO_INNER`` of
:mod:`..layout`), :func:`block_jac` differences it in the same sweeps, and the ring's columns follow with no
right-hand side of their own.

How often to refresh (:func:`refresh_interval`, :func:`record_attempt`): a W-method keeps its order with any J, but
the step a lagged J allows depends on the problem — on the 7011 spindle the mean step falls from 5.2 µs one step
after a refresh to 2.8 µs eight steps later (a stability limit that the aging J sets), on the hub at 100 km/h it
does not fall (its steps are set by accuracy).  So the interval is chosen from what the run measures: per age
(steps since the refresh) the right-hand sides spent and the simulated time advanced; the next interval N
minimises (Σ_{k<N} right-hand sides + a refresh's) / Σ_{k<N} time advanced, up to the caller's ``jac_every``.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ..contacts import cross
from ..layout import MEMO_INNER, MEMO_W, MR_GYRO, MR_MOMENT, MR_T, MR_Y, N_RING
from .base import JAC_AGES
from .linalg import NR

#: the refresh interval's controller (:func:`refresh_interval`): the fraction of its record forgotten per interval
#: (the record spans ≈ 32 intervals), the least number of intervals (forgetting-weighted) an age needs before its
#: figures count, and every how many intervals the interval is lengthened (× 2, at least + 5, up to the cap) to
#: measure the ages past the one in use
JAC_FORGET = 1.0 / 32.0
JAC_MIN_VISITS = 3.0
JAC_EXPLORE = 5


@njit(cache=True, _nrt=False, inline="always")
def perturbed(yi, atol_i):
    """y_i moved by the forward-difference step 1e-7 max(|y_i|, 1e4 atol_i) (module docstring)."""
    return yi + 1e-7 * max(abs(yi), 1e4 * atol_i)


@njit(cache=True)
def no_record():
    """The (rec, rbase, drec) arguments of :func:`block_jac` without a record."""
    return np.zeros((0, MEMO_W)), np.zeros((0, 6)), np.zeros((0, 9, 6))


@njit
def block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb, rec, rbase, drec):
    """Finite-difference blocks of ∂f/∂y: one component of every block perturbed at once
    (the blocks' derivatives do not depend on each other's states directly).  With a record (``rec``: the
    right-hand side's memo, filled by every call; :func:`no_record` for none) also drec[b, j] ← ∂(ball b's
    inner-ring reaction)/∂y_j of its own state from the same sweeps, rbase[b] being the reaction at y
    (:func:`ring_columns`).  (The record's arrays are arguments, not defaults: with numba's omitted default arrays
    the sweeps run 1.6× slower, 632 against 395 µs on a hub state.)"""
    n = y.shape[0]
    nb = blk.shape[0]
    for j in range(nbk):
        for i in range(n):
            yt[i] = y[i]
        for b in range(nb):
            o = blk[b] + j
            yt[o] = perturbed(y[o], atol[o])
            epsb[b] = yt[o] - y[o]  # the step actually taken (see the module docstring)
        fun(t, yt, f1, args)
        for b in range(nb):
            o = blk[b]
            for i in range(nbk):
                jac[b, i, j] = (f1[o + i] - f0[o + i]) / epsb[b]
            for i in range(drec.shape[2] if drec.shape[0] > 0 else 0):
                drec[b, j, i] = (rec[b, MEMO_INNER + i] - rbase[b, i]) / epsb[b]


@njit
def ring_jac(fun, args, t, y, f0, atol, blk, nbk, jrr, jbr, yt, f1):
    """Finite-difference ring columns of ∂f/∂y: the ring's own block J_rr (10 × 10) and the balls'
    dependence on the ring J_br (per ball nbk × 10), one ring component perturbed at a time."""
    for j in range(NR):
        for i in range(y.shape[0]):
            yt[i] = y[i]
        yt[j] = perturbed(y[j], atol[j])
        e = yt[j] - y[j]  # the step actually taken (see the module docstring)
        fun(t, yt, f1, args)
        for i in range(NR):
            jrr[i, j] = (f1[i] - f0[i]) / e
        for b in range(blk.shape[0]):
            o = blk[b]
            for i in range(nbk):
                jbr[b, i, j] = (f1[o + i] - f0[o + i]) / e


@njit(cache=True)
def ring_rows(jbr, rmass, bmass, jrb):
    """The ring's dependence on the balls J_rb from J_br by the symmetry of the contact stiffness and
    damping between two bodies (the force of a contact depends on the bodies' relative position and
    sliding velocity, and the ring feels minus the ball's force): M_r ∂a_r/∂(x_b, v_b, ω_b) =
    [M_b ∂a_b/∂(q_r, q̇_r, q̇_r)]ᵀ for the ring's accelerations (rows 5–9); its position rows do not
    depend on the balls.  An approximation (it drops the asymmetric parts: spin, the ring's
    gyroscopic terms, lever-arm changes), which a W-method tolerates without loss of order."""
    for b in range(jbr.shape[0]):
        mb = bmass[b, 0]
        jb = bmass[b, 1]
        for i in range(NR):
            for j in range(9):
                jrb[b, i, j] = 0.0
        for i in range(5):
            mr = rmass[i]
            for j in range(3):
                jrb[b, 5 + i, j] = mb / mr * jbr[b, 3 + j, i]  # positions ↔ ring positions
                jrb[b, 5 + i, 3 + j] = mb / mr * jbr[b, 3 + j, 5 + i]  # velocities ↔ ring rates
                jrb[b, 5 + i, 6 + j] = jb / mr * jbr[b, 6 + j, 5 + i]  # angular velocities ↔ ring rates


@njit(cache=True, _nrt=False)
def record_at(rec, blk, t, y):
    """True when the right-hand side's record (``rec``, :func:`bearingsim.dynamics.forces.record_reactions`) was made
    at exactly (t, y): the time and the ring's states in its ring row, every ball's nine states in its memo row
    (written whenever its outer contact is computed, equal to them on a memo hit), bit for bit."""
    nb = blk.shape[0]
    if rec[nb, MR_T] != t:
        return False
    for i in range(N_RING):
        if rec[nb, MR_Y + i] != y[i]:
            return False
    for b in range(nb):
        if rec[b, 0] != 1.0:
            return False
        for i in range(9):
            if rec[b, 1 + i] != y[blk[b] + i]:
                return False
    return True


@njit(cache=True)
def ring_columns(y, blk, rbase, drec, rmass, bmass, jrr, jbr):
    """The ring's columns J_br (per ball nbk × 10) and J_rr (10 × 10) from the balls' own derivatives, with no
    right-hand side of their own (module docstring).  ``rbase`` (n_balls + 1 rows): each ball's
    inner-ring reaction R = (force, moment about the ring centre) at y, then the record's ring row at y (I_p Ω / I_t
    and the contact moment, layout ``MR_*``); ``drec``: R's derivatives by the ball's nine states (:func:`block_jac`
    with a record); ``rmass``, ``bmass`` as :func:`ring_rows`.  Units (SI): R in [N] and [N·m], its derivatives per
    unit of the ball's state ([m], [m/s], [rad/s]); J's entries are time derivatives of the states per unit of the
    ring's states (e.g. [1/s²] for an acceleration per [m], [1/s] per [m/s]).

    For G either the ball's inner-contact force and moment about its centre, (−F_R, (r − c) × F_R − M_R) by the
    balance of the pair, or R itself, a change dq of the ring's state acts as the ball motion −A dq plus a turn
    φ dq of the pair about c: ∂G/∂q = −(∂G/∂y_b) A + φ × G, column by column —

    * translations of the centre c and its rate ċ: A = the unit motion of the ball's position / velocity;
    * tilt rates (angular velocity change w = e_y for γ̇y, a_z = R_y e_z for γ̇z): the rigid rotation of the
      pair, ball velocity w × (r − c) and angular velocity w;
    * tilts (φ = e_y for γy, a_z for γz: R_y R_z turns by them): the pair turned about c — ball position
      φ × (r − c), velocity φ × (v − ċ) and angular velocity φ × ω — plus what the ring's angular velocity does
      beyond turning with it (wtilt's own change with γy, ∂wtilt/∂γy = γ̇z (cos γy, 0, −sin γy), less φ × wtilt),
      as a rigid rotation of the pair.

    The contact's orbiting reference frame (about the fixed x axis) does not move with the pair, which enters the
    film's entrainment speed only: the columns match the ring's finite differences (:func:`ring_jac`) to
    ≈ 1e-3 of each column on the hub states (tests/unit/test_dyn_ring_columns.py).  The ring's rows: its
    accelerations (ring_equations in :mod:`..forces`) with the sum of the balls' R, the gyroscopic
    terms ∓ I_p Ω / I_t and the explicit ∂(M_x sin γy + M_z cos γy)/∂γy of the contact moment M."""
    nb = blk.shape[0]
    sy = np.sin(y[3])
    cy = np.cos(y[3])
    c = y[0:3]
    cd = y[5:8]
    wt = np.array([y[9] * sy, y[8], y[9] * cy])
    ey = np.array([0.0, 1.0, 0.0])
    az = np.array([sy, 0.0, cy])
    dwt = np.array([y[9] * cy, 0.0, -y[9] * sy])  # ∂wtilt/∂γy
    r = np.empty(3)
    vr = np.empty(3)
    w = np.empty(3)
    tmp = np.empty(3)
    amot = np.zeros((9, NR))  # the ball motion equivalent to each ring column
    dg = np.empty((6, 9))  # ∂G/∂y_b
    g0 = np.empty(6)
    col = np.empty((6, NR))
    mr = rmass[0]
    it = rmass[3]
    for i in range(NR):
        for j in range(NR):
            jrr[i, j] = 0.0
    for i in range(5):
        jrr[i, 5 + i] = 1.0  # q̇ = q̇
    for b in range(nb):
        o = blk[b]
        for i in range(3):
            r[i] = y[o + i] - c[i]
            vr[i] = y[o + 3 + i] - cd[i]
        # the equivalent ball motions A (columns: c, γy, γz, ċ, γ̇y, γ̇z)
        for i in range(9):
            for k in range(NR):
                amot[i, k] = 0.0
        for i in range(3):
            amot[i, i] = 1.0
            amot[3 + i, 5 + i] = 1.0
        for k, phi in ((3, ey), (4, az)):
            cross(phi, r, amot[0:3, k])
            cross(phi, vr, amot[3:6, k])
            cross(phi, y[o + 6:o + 9], amot[6:9, k])
            cross(phi, wt, tmp)
            for i in range(3):
                w[i] = (dwt[i] if k == 3 else 0.0) - tmp[i]
            cross(w, r, tmp)
            for i in range(3):
                amot[3 + i, k] += tmp[i]
                amot[6 + i, k] += w[i]
        for k, wk in ((8, ey), (9, az)):
            cross(wk, r, amot[3:6, k])
            for i in range(3):
                amot[6 + i, k] = wk[i]
        for side in range(2):
            if side == 0:  # the ball: F = −F_R, M = (r − c) × F_R − M_R
                fr = rbase[b, 0:3]
                cross(r, fr, g0[3:6])
                for i in range(3):
                    g0[i] = -fr[i]
                    g0[3 + i] -= rbase[b, 3 + i]
                for j in range(9):
                    d = drec[b, j]
                    cross(r, d[0:3], dg[3:6, j])
                    for i in range(3):
                        dg[i, j] = -d[i]
                        dg[3 + i, j] -= d[3 + i]
                    if j < 3:  # the lever arm r − c itself moves with the ball's position: + e_j × F_R
                        for i in range(3):
                            w[i] = 1.0 if i == j else 0.0
                        cross(w, fr, tmp)
                        for i in range(3):
                            dg[3 + i, j] += tmp[i]
            else:  # the ring's reaction R
                for i in range(6):
                    g0[i] = rbase[b, i]
                    for j in range(9):
                        dg[i, j] = drec[b, j, i]
            for i in range(6):
                for k in range(NR):
                    s = 0.0
                    for j in range(9):
                        s -= dg[i, j] * amot[j, k]
                    col[i, k] = s
            for k, phi in ((3, ey), (4, az)):  # the forces turn with the pair
                cross(phi, g0[0:3], tmp)
                for i in range(3):
                    col[i, k] += tmp[i]
                cross(phi, g0[3:6], tmp)
                for i in range(3):
                    col[3 + i, k] += tmp[i]
            if side == 0:
                mb = bmass[b, 0]
                jb = bmass[b, 1]
                for k in range(NR):
                    for i in range(3):
                        jbr[b, i, k] = 0.0
                        jbr[b, 3 + i, k] = col[i, k] / mb
                        jbr[b, 6 + i, k] = col[3 + i, k] / jb
            else:
                for k in range(NR):
                    for i in range(3):
                        jrr[5 + i, k] += col[i, k] / mr
                    jrr[8, k] += col[4, k] / it
                    jrr[9, k] += (col[3, k] * sy + col[5, k] * cy) / it
    gyro = rbase[nb, MR_GYRO]
    jrr[8, 9] -= gyro
    jrr[9, 8] += gyro
    jrr[9, 3] += (rbase[nb, MR_MOMENT] * cy - rbase[nb, MR_MOMENT + 2] * sy) / it


@njit(cache=True, _nrt=False)
def record_attempt(mem, age, rhs, advanced):
    """Add one step attempt to the refresh interval's record ``mem`` (:data:`.base.JAC_MEMORY` floats, layout in
    :mod:`.base`): the Jacobian's ``age`` [steps since its refresh], the right-hand sides the attempt cost and the
    simulated time it advanced [s] (0 when rejected).  An age's first attempt in an interval counts the interval."""
    k = min(age, JAC_AGES - 1)
    if mem[2] != k:
        mem[3 + 2 * JAC_AGES + k] += 1.0
        mem[2] = k
    mem[3 + k] += rhs
    mem[3 + JAC_AGES + k] += advanced


@njit(cache=True, _nrt=False)
def refresh_interval(mem, cap, refresh_cost):
    """The number of steps the Jacobian made now serves (1 … ``cap``): the N that minimises the cost per simulated
    time (Σ_{k<N} r_k + refresh_cost) / Σ_{k<N} τ_k, r_k and τ_k the mean right-hand sides and time advanced at age
    k over the intervals that reached it (module docstring), over the ages with enough record; every
    :data:`JAC_EXPLORE`-th interval longer, to measure the ages past N.  Forgets :data:`JAC_FORGET` of the record
    first and starts the next interval's (ages from 0).  Without a record yet: ``cap``."""
    for i in range(3, mem.shape[0]):
        mem[i] *= 1.0 - JAC_FORGET
    mem[1] += 1.0
    mem[2] = -1.0
    best = np.inf
    n = int(mem[0]) if mem[0] > 0.0 else cap
    rhs = refresh_cost
    adv = 0.0
    for k in range(min(cap, JAC_AGES)):
        visits = mem[3 + 2 * JAC_AGES + k]
        if visits < JAC_MIN_VISITS:
            break
        rhs += mem[3 + k] / visits
        adv += mem[3 + JAC_AGES + k] / visits
        if adv > 0.0 and rhs / adv < best:
            best = rhs / adv
            n = k + 1
    if int(mem[1]) % JAC_EXPLORE == 0:
        n = max(2 * n, n + 5)
    n = max(1, min(n, cap))
    mem[0] = float(n)
    return n
