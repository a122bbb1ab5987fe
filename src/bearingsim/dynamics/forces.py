"""Equations of motion of the dynamic model (numba kernels).

Everything here works on the plain arrays of :class:`bearingsim.dynamics.model.Model`, laid out as
documented in :mod:`.layout`.  :func:`rhs` assembles the equations of motion from one helper per
section (:func:`balls_on_raceways`, :func:`cage_pockets` with the elastic modes, :func:`land_guidance`,
:func:`cage_equations`, :func:`ring_equations`, :func:`global_diagnostics`); :func:`evaluate` calls it
from Python.  The contact laws — the Hunt–Crossley Hertz force and traction of a ball–raceway contact
(:func:`~.contacts.race_contact_at`), the Coulomb stand-in (:func:`~.contacts.coulomb_slices`) and the
pocket geometry (:func:`~.contacts.pocket_point`) — are in :mod:`.contacts` (their names stay
importable from here); the load and speed histories are the kernels of :mod:`.loads`.

Ball–cage (Sakaguchi & Shibutani [S1] §3.2, eqs. 6–7): the pocket surface is a set of points in the
pocket frame; the deepest interference of a point with the ball gives a Hertz-type
force Q = K_c δ^1.5 along the line from the point to the ball centre and sliding
friction F = −μ Q v_s/√(|v_s|² + v_ref²) (μ = 0.06 in [S1]; v_ref regularises the
sign at zero sliding).  Cage guidance by a ring land uses the same law on the radial
eccentricity of the cage beyond the land clearance.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from ..contact.slices import TRACTION_OUT
from ..statics import layout as kn  # the row-parameter layout (P_*)
from . import layout as ly
from . import threads as _threads  # noqa: F401 - numba's threading layer, chosen and started (before any parallel kernel)

# the contact laws (re-exported: ``forces.race_contact``, ``forces.coulomb_slices`` ... keep working)
from .contacts import (  # noqa: F401
    coulomb_on_slices,
    coulomb_slices,
    pocket_point,
    race_contact,
    race_contact_at,
    slice_table,
)
from .contacts import cross as _cross

# the load and speed kernels (re-exported: ``forces.loads_at``, ``forces.pack_loads`` ... keep working)
from .loads import constant_loads, load_channel, loads_at, pack_loads, speed_at  # noqa: F401


@njit(cache=True, _nrt=False)
def _rot_yz(gy, gz, rm):
    """R = R_y(γy) R_z(γz) [-]."""
    cy = math.cos(gy)
    sy = math.sin(gy)
    cz = math.cos(gz)
    sz = math.sin(gz)
    rm[0, 0] = cy * cz
    rm[0, 1] = -cy * sz
    rm[0, 2] = sy
    rm[1, 0] = sz
    rm[1, 1] = cz
    rm[1, 2] = 0.0
    rm[2, 0] = -sy * cz
    rm[2, 1] = sy * sz
    rm[2, 2] = cy



A_PIN, A_POUT, A_PCAGE, A_PLAND, A_EPOT, A_ECAGE = range(6)
NACC = 6
#: floats of :func:`_rhs`'s work array before the cage's modal forces (its small arrays, laid out in _rhs)
RHS_WORK = 128


#: work floats per ball in :func:`_one_ball` before race_contact_at's buffer (fb, mb, bp, g, gr, vg, tang, tmp: 3
#: each; fbo, mbo: the outer contact's force and moment on the ball, 3 each)
BALL_WORK = 30
#: per-ball contributions: inner-ring force and moment, outer-ring force and moment (3 each), then the inner and
#: outer power losses and the elastic energy (with diagnostics)
NCONTRIB = 15
#: per-ball row of the outer-contact memo (:func:`outer_memo_hit`): [0] 1 when the row holds a result, [1:10] the
#: ball's position [m], velocity [m/s] and angular velocity [rad/s] it was computed for, [10:22] the result: force
#: [N] and moment [N m] on the ball, force and moment on the outer ring (3 each; the kept copy of the loop body
#: in balls_on_raceways repeats the memo's use, as it repeats the rest of _one_ball: a call per ball cost 7 % here),
#: [22:28] the record of the inner contact's reaction (layout ``MEMO_*``, ``MR_*`` in :mod:`.layout`, with the
#: ring's row after the balls')
MEMO_W = ly.MEMO_W
PHASE_ALL, PHASE_MASKED, PHASE_OTHERS, PHASE_REST = ly.PHASE_ALL, ly.PHASE_MASKED, ly.PHASE_OTHERS, ly.PHASE_REST


@njit(cache=True)
def no_memo():
    """The ``memo`` of :func:`rhs` that holds nothing (every outer contact computed)."""
    return np.zeros((0, MEMO_W))


@njit(cache=True, _nrt=False)
def outer_memo_hit(memo, k, y, o):
    """True when ``memo`` holds ball k's outer-raceway contact for exactly this ball state (its nine states
    y[o:o + 9], bit for bit).

    The outer ring is fixed, so that contact depends on the ball's nine states alone (and on the model's constant
    arrays): a right-hand side whose balls have not moved since the last one — the ten finite-difference sweeps of
    the inner ring's Jacobian columns (:func:`bearingsim.dynamics.integrate.jacobian.ring_jac`) — takes it from the
    memo instead of computing it again, and gets the very same numbers.  NaN never matches."""
    if memo.shape[0] == 0:
        return False
    if memo[k, 0] != 1.0:
        return False
    for i in range(9):
        if memo[k, 1 + i] != y[o + i]:
            return False
    return True


@njit(cache=True, _nrt=False)
def outer_memo_put(memo, k, y, o, fbo, mbo, fo, mo):
    """Store ball k's outer-contact result for its state y[o:o + 9] (nothing without a memo)."""
    if memo.shape[0] == 0:
        return
    for i in range(9):
        memo[k, 1 + i] = y[o + i]
    for i in range(3):
        memo[k, 10 + i] = fbo[i]
        memo[k, 13 + i] = mbo[i]
        memo[k, 16 + i] = fo[i]
        memo[k, 19 + i] = mo[i]
    memo[k, 0] = 1.0


@njit(cache=True, _nrt=False)
def outer_memo_get(memo, k, fbo, mbo, fo, mo):
    """The stored outer-contact result of ball k (after :func:`outer_memo_hit`)."""
    for i in range(3):
        fbo[i] = memo[k, 10 + i]
        mbo[i] = memo[k, 13 + i]
        fo[i] = memo[k, 16 + i]
        mo[i] = memo[k, 19 + i]


@njit(cache=True, _nrt=False)
def _one_ball(k, y, dy, rows, rowx, ball_row, gp, lubs, rm, ax, c, cd, wtilt, wring, diag, want, memo, wk, ck):
    """Ball k on its two raceways and its Newton–Euler equations (the body of :func:`balls_on_raceways`).

    wk: the ball's work row (fb, mb, bp, g, gr, vg, tang, tmp, fbo, mbo: 3 floats each, then race_contact_at's
    buffer with the Coulomb slice table at 44:); ck ← its contributions (layout of :func:`balls_on_raceways`): the
    reactions on the inner ring (force, moment about c) and on the outer ring, and with diagnostics its inner and
    outer raceway power losses and elastic energy.  The views of wk and ck are made here, where they are not
    reference-counted (``_nrt=False``; made in the parallel loop they would be 16 counted views per ball).
    ``memo``: the outer contacts of the last evaluation (:func:`outer_memo_hit`; not used with diagnostics)."""
    fb, mb, bp, g, gr, vg, tang, tmp = (wk[0:3], wk[3:6], wk[6:9], wk[9:12], wk[12:15], wk[15:18], wk[18:21],
                                        wk[21:24])
    fbo = wk[24:27]
    mbo = wk[27:30]
    tbuf = wk[30:]
    fring, mring, fout, mout, ex = ck[0:3], ck[3:6], ck[6:9], ck[9:12], ck[12:15]
    alpha = gp[ly.G_ALPHA]
    g0 = gp[ly.G_GX]
    g1 = gp[ly.G_GX + 1]
    g2 = gp[ly.G_GX + 2]
    for i in range(3):
        fring[i] = 0.0
        mring[i] = 0.0
        fout[i] = 0.0
        mout[i] = 0.0
        ex[i] = 0.0
    r = ball_row[k]
    o = ly.N_RING + ly.N_BALL * k
    bx = y[o]
    by = y[o + 1]
    bz = y[o + 2]
    vx = y[o + 3]
    vy = y[o + 4]
    vz = y[o + 5]
    wx = y[o + 6]
    wy = y[o + 7]
    wz = y[o + 8]
    half_d = 0.5 * rows[r, kn.P_D]
    worb = (by * vz - bz * vy) / (by * by + bz * bz)
    # ---- inner raceway: ball in the ring frame, groove centre in its meridian plane
    for i in range(3):
        tmp[i] = y[o + i] - c[i]
    for i in range(3):
        bp[i] = rm[0, i] * tmp[0] + rm[1, i] * tmp[1] + rm[2, i] * tmp[2]
    rr = math.sqrt(bp[1] * bp[1] + bp[2] * bp[2])  # (glibc hypot: 1.5 % of a step)
    cps = bp[1] / rr
    sps = bp[2] / rr
    xgi = rowx[r, ly.X_XGI]
    ric = rows[r, kn.P_RIC]
    for i in range(3):
        gr[i] = rm[i, 0] * xgi + rm[i, 1] * ric * cps + rm[i, 2] * ric * sps
        g[i] = c[i] + gr[i]
        tang[i] = -rm[i, 1] * sps + rm[i, 2] * cps
    _cross(wtilt, gr, vg)
    for i in range(3):
        vg[i] += cd[i]
    # (race_contact_at on scalars: an array argument or view per contact costs numba atomic reference counts)
    (qi, di, ux, uy, uz, srr, pw, fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry,
     mrz) = race_contact_at(bx, by, bz, vx, vy, vz, wx, wy, wz, g[0], g[1], g[2], vg[0], vg[1], vg[2], worb,
                            c[0], c[1], c[2], cd[0], cd[1], cd[2], wring[0], wring[1], wring[2],
                            rows[r, kn.P_KI], rowx[r, ly.X_KCI], rows[r, kn.P_RI], half_d, alpha,
                            lubs[2 * r], gp,
                            rowx[r, ly.X_CAI], rowx[r, ly.X_CBI], rowx[r, ly.X_RDI], tang[0], tang[1],
                            tang[2], tbuf)
    fb[0] = fbx
    fb[1] = fby
    fb[2] = fbz
    mb[0] = mbx
    mb[1] = mby
    mb[2] = mbz
    fring[0] += frx
    fring[1] += fry
    fring[2] += frz
    mring[0] += mrx
    mring[1] += mry
    mring[2] += mrz
    if want:
        s = rows[r, kn.P_SIGN]
        ua = ux * ax[0] + uy * ax[1] + uz * ax[2]
        urr = ux * (rm[0, 1] * cps + rm[0, 2] * sps)
        urr += uy * (rm[1, 1] * cps + rm[1, 2] * sps)
        urr += uz * (rm[2, 1] * cps + rm[2, 2] * sps)
        diag[k, ly.D_QI] = qi
        diag[k, ly.D_DI] = di
        diag[k, ly.D_AI] = math.atan2(-s * ua, -urr)
        diag[k, ly.D_SRI] = srr
        diag[k, ly.D_PI] = pw
        ex[0] += pw
        if di > 0.0:
            ex[2] += 0.4 * rows[r, kn.P_KI] * di ** 2.5
    # ---- outer raceway (fixed)
    rr = math.sqrt(by * by + bz * bz)
    cps = by / rr
    sps = bz / rr
    rgo = rowx[r, ly.X_RGO]
    # (the outer contact into fbo, mbo, then added: a memo hit gives the same numbers as computing it)
    if want or not outer_memo_hit(memo, k, y, o):
        (qo, do_, ux, uy, uz, srr, pw, fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry,
         mrz) = race_contact_at(bx, by, bz, vx, vy, vz, wx, wy, wz, rowx[r, ly.X_XGO], rgo * cps, rgo * sps,
                                0.0, 0.0, 0.0, worb, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                                rows[r, kn.P_KO], rowx[r, ly.X_KCO], rows[r, kn.P_RO], half_d, alpha,
                                lubs[2 * r + 1], gp,
                                rowx[r, ly.X_CAO], rowx[r, ly.X_CBO], rowx[r, ly.X_RDO], 0.0, -sps, cps,
                                tbuf)
        fbo[0] = fbx
        fbo[1] = fby
        fbo[2] = fbz
        mbo[0] = mbx
        mbo[1] = mby
        mbo[2] = mbz
        fout[0] += frx
        fout[1] += fry
        fout[2] += frz
        mout[0] += mrx
        mout[1] += mry
        mout[2] += mrz
        outer_memo_put(memo, k, y, o, fbo, mbo, fout, mout)
        if want:
            s = rows[r, kn.P_SIGN]
            diag[k, ly.D_QO] = qo
            diag[k, ly.D_DO] = do_
            diag[k, ly.D_AO] = math.atan2(s * ux, uy * cps + uz * sps)
            diag[k, ly.D_SRO] = srr
            diag[k, ly.D_PO] = pw
            ex[1] += pw
            if do_ > 0.0:
                ex[2] += 0.4 * rows[r, kn.P_KO] * do_ ** 2.5
            # orbital speed and spin relative to the orbiting frame
            r2 = by * by + bz * bz
            wm = (by * vz - bz * vy) / r2
            diag[k, ly.D_WM] = wm
            wxr = wx - wm
            wrad = wy * cps + wz * sps
            wtan = -wy * sps + wz * cps
            mag = math.sqrt(wxr * wxr + wrad * wrad + wtan * wtan)
            sg = 1.0 if wxr >= 0.0 else -1.0
            diag[k, ly.D_WR] = sg * mag
            diag[k, ly.D_BETA] = math.atan2(-s * wrad * sg, wxr * sg)
            diag[k, ly.D_QC] = 0.0
            diag[k, ly.D_PC] = 0.0
    else:
        outer_memo_get(memo, k, fbo, mbo, fout, mout)
    for i in range(3):
        fb[i] += fbo[i]
        mb[i] += mbo[i]
    # ---- the ball: ṙ = v, m v̇ = F + m g, J ω̇ = M
    mass = rows[r, kn.P_MASS]
    jb = rows[r, kn.P_JB]
    dy[o] = vx
    dy[o + 1] = vy
    dy[o + 2] = vz
    dy[o + 3] = fb[0] / mass + g0
    dy[o + 4] = fb[1] / mass + g1
    dy[o + 5] = fb[2] / mass + g2
    dy[o + 6] = mb[0] / jb
    dy[o + 7] = mb[1] / jb
    dy[o + 8] = mb[2] / jb


# the threading layer of _balls_parallel is chosen and started by .threads (imported above)


@njit(cache=True, _nrt=False, inline="always")
def dealt(i, nb):
    """The ball taken by iteration i of :func:`_balls_parallel`'s loop: the balls in four contiguous quarters
    (q = ⌈nb/4⌉ balls each, the last one shorter) visited in the order 0, 2, 1, 3.  (i may come as a parallel
    loop's unsigned index: taken as int64 first, since uint64 − int64 is a float in numba.)"""
    i = np.int64(i)
    q = (nb + 3) // 4
    s1 = min(q, max(nb - q, 0))
    s2 = min(q, max(nb - 2 * q, 0))
    if i < q:
        return i
    if i < q + s2:
        return 2 * q + (i - q)
    if i < q + s2 + s1:
        return q + (i - q - s2)
    return 3 * q + (i - q - s2 - s1)


@njit(cache=True, parallel=True)
def _balls_parallel(y, dy, rows, rowx, ball_row, gp, lubs, rm, ax, c, cd, wtilt, wring, diag, want, memo, work,
                    contrib, active):
    """:func:`_one_ball` for every ball in a numba ``prange`` (threads: ``numba.set_num_threads``), each with
    its own work row; contrib[k] ← its reactions and diagnostics (layout of :func:`balls_on_raceways`).

    The balls are dealt to the threads in contiguous quarters (:func:`dealt`: iterations take quarters 0, 2, 1, 3 of
    the ball numbering; numba's static schedule hands each of 2 threads a contiguous half of the iterations, so one
    thread takes quarters 0 and 2, the other 1 and 3).  The balls are numbered row by row and along each row, so a
    thread holds opposite halves of the rows (under a moment load one row's load zone is opposite the other's: the
    loaded balls split about evenly), and its balls are neighbours in memory, so the cache lines that neighbours
    share in ``dy`` (9 floats per ball) stay on one core.  Hub (b), 2 threads, right-hand side at three states of a
    run (4 / 6 / 9.2 ms, each call on a state other than the last one's): 29–31 / 27–28 / 32–34 µs in quarters
    against 38–42 / 35–41 / 43–48 dealt even/odd, 30–32 / 30–31 / 39–40 in contiguous halves (a row per thread:
    unbalanced near the moment's zero crossing) and 44–46 / 44 / 53 on one thread; loops of calls on one repeated
    state overstate the even/odd dealing (31 µs at 4 ms against 40 with two alternating states).  Which thread
    computes a ball does not change its numbers.  ``active`` (no entries: every ball): the balls with active[k] = 0 are
    skipped, their contributions zero (:func:`rhs_masked`)."""
    nb = ball_row.shape[0]
    for i in prange(nb):
        k = dealt(i, nb)
        if active.shape[0] > 0 and active[k] == 0:
            for j in range(contrib.shape[1]):
                contrib[k, j] = 0.0
            continue
        _one_ball(k, y, dy, rows, rowx, ball_row, gp, lubs, rm, ax, c, cd, wtilt, wring, diag, want, memo, work[k],
                  contrib[k])


@njit(cache=True, _nrt=False)
def balls_on_raceways(y, dy, rows, rowx, ball_row, gp, lubs, rm, ax, c, cd, wtilt, wring, fring, mring, fout, mout,
                      diag, acc, memo, threads, work, active, phase=PHASE_ALL):
    """Every ball on its two raceways, and Newton–Euler for every ball.

    Inner raceway: the groove-curvature centre g in the ball's meridian plane of the tilted, displaced
    ring, g = c + R (ξ_g e_x + r_ic (cos ψ e_y + sin ψ e_z)) with ψ the ball's azimuth in the ring
    frame, moving with ċ + ω_tilt × (g − c); outer raceway (fixed): g = (x_go, r_go cos ψ, r_go sin ψ)
    at rest.  Each contact is :func:`race_contact_at` (Hunt–Crossley Hertz normal force and traction);
    the ring's reactions accumulate in (fring, mring) about c and (fout, mout).  Ball (isotropic
    inertia: J ω̇ = M in the inertial frame, centrifugal and gyroscopic effects arise from the motion
    itself): ṙ = v, m v̇ = F + m g, J ω̇ = M.  ``rm``, ``ax``, ``c``, ``cd``, ``wtilt``, ``wring``: the
    inner ring's rotation R_y R_z, axis, centre, centre velocity, tilt rate and total angular velocity.
    With diagnostics (diag has rows): loads, approaches, contact angles (inner atan2(−s u·e_ax, −u·e_r),
    outer atan2(s u_x, u·e_r)), slide-roll ratios, power losses, the orbital speed ω_m = (r × v)_x/r²,
    the spin ω_R relative to the orbiting frame (Jones sign: positive along +x) and pitch angle
    β = atan2(−s ω_rad, ω_x) (Jones 1960); acc ← raceway power losses and elastic energies (2/5) K δ^2.5.

    Threads: the balls are independent given the rings' state, so they run in a numba
    ``prange`` when ``threads`` is true (:func:`_one_ball`, each with its own work row; the count is
    ``numba.set_num_threads``) and write their reactions on the rings into a per-ball array, which is
    then summed serially in ball order: the result does not depend on the number of threads nor on
    ``threads``, bit for bit.

    work: float[:func:`ball_work_size`] (the per-ball contributions, the balls' work rows and one contribution row),
    so that nothing is allocated and no view is reference-counted here (``_nrt=False``).
    """
    nb = ball_row.shape[0]
    want = diag.shape[0] > 0
    # work rows of race_contact_at, followed by the slices of the Coulomb stand-in (the same for every contact)
    nsl = int(gp[ly.G_NSL]) if int(gp[ly.G_TRAC]) == 1 else 0
    nbw = ball_row_work(nsl)
    o1 = nb * NCONTRIB
    contrib = work[0:o1].reshape((nb, NCONTRIB))
    if threads:
        work = work[o1:o1 + nb * nbw].reshape((nb, nbw))
        slice_table(nsl, work[0, BALL_WORK + 44:])
        for k in range(1, nb):
            for i in range(2 * nsl):
                work[k, BALL_WORK + 44 + i] = work[0, BALL_WORK + 44 + i]
        _balls_parallel(y, dy, rows, rowx, ball_row, gp, lubs, rm, ax, c, cd, wtilt, wring, diag, want, memo, work,
                        contrib, active)
    else:
        # one thread: the body of _one_ball written out in the loop (one set of work arrays, no parallel region,
        # no call per ball: a call per ball costs 13 % of a hub right-hand side, the body written out 1 %, in one
        # process over 40 paired repetitions).  The same statements, so bitwise the same result as the threaded path
        # (tests/unit/test_dyn_threads.py compares the two texts and the results).
        wk = work[o1:o1 + nbw]
        slice_table(nsl, wk[BALL_WORK + 44:])
        ck = work[o1 + nbw:o1 + nbw + NCONTRIB]
        fb, mb, bp, g, gr, vg, tang, tmp = (wk[0:3], wk[3:6], wk[6:9], wk[9:12], wk[12:15], wk[15:18], wk[18:21],
                                            wk[21:24])
        fbo = wk[24:27]
        mbo = wk[27:30]
        tbuf = wk[30:]
        fr, mr, fo, mo, ex = ck[0:3], ck[3:6], ck[6:9], ck[9:12], ck[12:15]
        alpha = gp[ly.G_ALPHA]
        g0 = gp[ly.G_GX]
        g1 = gp[ly.G_GX + 1]
        g2 = gp[ly.G_GX + 2]
        for k in range(nb):
            if phase != PHASE_ALL and (active[k] == 0) != (phase == PHASE_OTHERS):
                if phase == PHASE_MASKED:
                    for i in range(NCONTRIB):
                        contrib[k, i] = 0.0
                continue  # (PHASE_REST: its contribution is the PHASE_OTHERS call's, kept in the work array)
            for i in range(NCONTRIB):
                ck[i] = 0.0
            # ---- BEGIN copy of the body of _one_ball (kept identical: bitwise the same as the threaded path)
            r = ball_row[k]
            o = ly.N_RING + ly.N_BALL * k
            bx = y[o]
            by = y[o + 1]
            bz = y[o + 2]
            vx = y[o + 3]
            vy = y[o + 4]
            vz = y[o + 5]
            wx = y[o + 6]
            wy = y[o + 7]
            wz = y[o + 8]
            half_d = 0.5 * rows[r, kn.P_D]
            worb = (by * vz - bz * vy) / (by * by + bz * bz)
            # ---- inner raceway: ball in the ring frame, groove centre in its meridian plane
            for i in range(3):
                tmp[i] = y[o + i] - c[i]
            for i in range(3):
                bp[i] = rm[0, i] * tmp[0] + rm[1, i] * tmp[1] + rm[2, i] * tmp[2]
            rr = math.sqrt(bp[1] * bp[1] + bp[2] * bp[2])  # (glibc hypot: 1.5 % of a step)
            cps = bp[1] / rr
            sps = bp[2] / rr
            xgi = rowx[r, ly.X_XGI]
            ric = rows[r, kn.P_RIC]
            for i in range(3):
                gr[i] = rm[i, 0] * xgi + rm[i, 1] * ric * cps + rm[i, 2] * ric * sps
                g[i] = c[i] + gr[i]
                tang[i] = -rm[i, 1] * sps + rm[i, 2] * cps
            _cross(wtilt, gr, vg)
            for i in range(3):
                vg[i] += cd[i]
            # (race_contact_at on scalars: an array argument or view per contact costs numba atomic reference counts)
            (qi, di, ux, uy, uz, srr, pw, fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry,
             mrz) = race_contact_at(bx, by, bz, vx, vy, vz, wx, wy, wz, g[0], g[1], g[2], vg[0], vg[1], vg[2], worb,
                                    c[0], c[1], c[2], cd[0], cd[1], cd[2], wring[0], wring[1], wring[2],
                                    rows[r, kn.P_KI], rowx[r, ly.X_KCI], rows[r, kn.P_RI], half_d, alpha,
                                    lubs[2 * r], gp,
                                    rowx[r, ly.X_CAI], rowx[r, ly.X_CBI], rowx[r, ly.X_RDI], tang[0], tang[1],
                                    tang[2], tbuf)
            fb[0] = fbx
            fb[1] = fby
            fb[2] = fbz
            mb[0] = mbx
            mb[1] = mby
            mb[2] = mbz
            fr[0] += frx
            fr[1] += fry
            fr[2] += frz
            mr[0] += mrx
            mr[1] += mry
            mr[2] += mrz
            if want:
                s = rows[r, kn.P_SIGN]
                ua = ux * ax[0] + uy * ax[1] + uz * ax[2]
                urr = ux * (rm[0, 1] * cps + rm[0, 2] * sps)
                urr += uy * (rm[1, 1] * cps + rm[1, 2] * sps)
                urr += uz * (rm[2, 1] * cps + rm[2, 2] * sps)
                diag[k, ly.D_QI] = qi
                diag[k, ly.D_DI] = di
                diag[k, ly.D_AI] = math.atan2(-s * ua, -urr)
                diag[k, ly.D_SRI] = srr
                diag[k, ly.D_PI] = pw
                ex[0] += pw
                if di > 0.0:
                    ex[2] += 0.4 * rows[r, kn.P_KI] * di ** 2.5
            # ---- outer raceway (fixed)
            rr = math.sqrt(by * by + bz * bz)
            cps = by / rr
            sps = bz / rr
            rgo = rowx[r, ly.X_RGO]
            # (the outer contact into fbo, mbo, then added: a memo hit gives the same numbers as computing it)
            if want or not outer_memo_hit(memo, k, y, o):
                (qo, do_, ux, uy, uz, srr, pw, fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry,
                 mrz) = race_contact_at(bx, by, bz, vx, vy, vz, wx, wy, wz, rowx[r, ly.X_XGO], rgo * cps, rgo * sps,
                                        0.0, 0.0, 0.0, worb, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
                                        rows[r, kn.P_KO], rowx[r, ly.X_KCO], rows[r, kn.P_RO], half_d, alpha,
                                        lubs[2 * r + 1], gp,
                                        rowx[r, ly.X_CAO], rowx[r, ly.X_CBO], rowx[r, ly.X_RDO], 0.0, -sps, cps,
                                        tbuf)
                fbo[0] = fbx
                fbo[1] = fby
                fbo[2] = fbz
                mbo[0] = mbx
                mbo[1] = mby
                mbo[2] = mbz
                fo[0] += frx
                fo[1] += fry
                fo[2] += frz
                mo[0] += mrx
                mo[1] += mry
                mo[2] += mrz
                outer_memo_put(memo, k, y, o, fbo, mbo, fo, mo)
                if want:
                    s = rows[r, kn.P_SIGN]
                    diag[k, ly.D_QO] = qo
                    diag[k, ly.D_DO] = do_
                    diag[k, ly.D_AO] = math.atan2(s * ux, uy * cps + uz * sps)
                    diag[k, ly.D_SRO] = srr
                    diag[k, ly.D_PO] = pw
                    ex[1] += pw
                    if do_ > 0.0:
                        ex[2] += 0.4 * rows[r, kn.P_KO] * do_ ** 2.5
                    # orbital speed and spin relative to the orbiting frame
                    r2 = by * by + bz * bz
                    wm = (by * vz - bz * vy) / r2
                    diag[k, ly.D_WM] = wm
                    wxr = wx - wm
                    wrad = wy * cps + wz * sps
                    wtan = -wy * sps + wz * cps
                    mag = math.sqrt(wxr * wxr + wrad * wrad + wtan * wtan)
                    sg = 1.0 if wxr >= 0.0 else -1.0
                    diag[k, ly.D_WR] = sg * mag
                    diag[k, ly.D_BETA] = math.atan2(-s * wrad * sg, wxr * sg)
                    diag[k, ly.D_QC] = 0.0
                    diag[k, ly.D_PC] = 0.0
            else:
                outer_memo_get(memo, k, fbo, mbo, fo, mo)
            for i in range(3):
                fb[i] += fbo[i]
                mb[i] += mbo[i]
            # ---- the ball: ṙ = v, m v̇ = F + m g, J ω̇ = M
            mass = rows[r, kn.P_MASS]
            jb = rows[r, kn.P_JB]
            dy[o] = vx
            dy[o + 1] = vy
            dy[o + 2] = vz
            dy[o + 3] = fb[0] / mass + g0
            dy[o + 4] = fb[1] / mass + g1
            dy[o + 5] = fb[2] / mass + g2
            dy[o + 6] = mb[0] / jb
            dy[o + 7] = mb[1] / jb
            dy[o + 8] = mb[2] / jb
            # ---- END copy
            for i in range(NCONTRIB):
                contrib[k, i] = ck[i]
    if phase == PHASE_MASKED or phase == PHASE_OTHERS:
        return  # (the rings' reactions are not read, or summed by the PHASE_REST call)
    # the reduction, serially in ball order (independent of the thread count)
    for k in range(nb):
        for i in range(3):
            fring[i] += contrib[k, i]
            mring[i] += contrib[k, 3 + i]
            fout[i] += contrib[k, 6 + i]
            mout[i] += contrib[k, 9 + i]
        if want:
            acc[A_PIN] += contrib[k, 12]
            acc[A_POUT] += contrib[k, 13]
            acc[A_EPOT] += contrib[k, 14]


@njit(cache=True)
def ball_work_size(nb, nsl, threads):
    """Length of :func:`balls_on_raceways`' work array for nb balls and nsl Coulomb slices (0: sliced traction)."""
    return nb * NCONTRIB + (nb if threads else 1) * ball_row_work(nsl) + NCONTRIB


@njit(cache=True)
def ball_row_work(nsl):
    """Floats of one ball's work row: BALL_WORK, then race_contact_at's buffer (the traction's out with its strip
    lanes, TRACTION_OUT; the Coulomb stand-in's vectors at 10:44 and its nsl slices at 44:)."""
    return BALL_WORK + max(44 + 2 * nsl, TRACTION_OUT)


@njit(cache=True, inline="always")
def cage_kinematics(y, o, cpar, rm, rcm, occ, wc):
    """Cage frame: rm ← R_y(βy) R_z(βz), rcm ← R_c = R_y R_z R_x(θ), occ ← the pocket-plane centre
    (C_XP + r), wc ← angular velocity θ̇ R_y R_z e_x + β̇y e_y + β̇z R_y e_z.  Returns (sin βy, cos βy)."""
    th = y[o + ly.K_THETA]
    by_ = y[o + ly.K_BETA_Y]
    bz_ = y[o + ly.K_BETA_Z]
    thd = y[o + ly.K_THETA_DOT]
    byd = y[o + ly.K_BETA_Y_DOT]
    bzd = y[o + ly.K_BETA_Z_DOT]
    _rot_yz(by_, bz_, rm)
    ct = math.cos(th)
    st = math.sin(th)
    # Rc = R_y R_z R_x(θ)
    for i in range(3):
        rcm[i, 0] = rm[i, 0]
        rcm[i, 1] = rm[i, 1] * ct + rm[i, 2] * st
        rcm[i, 2] = -rm[i, 1] * st + rm[i, 2] * ct
    occ[0] = cpar[ly.C_XP] + y[o]
    occ[1] = y[o + 1]
    occ[2] = y[o + 2]
    cyb = math.cos(by_)
    syb = math.sin(by_)
    wc[0] = bzd * syb + thd * rm[0, 0]
    wc[1] = byd + thd * rm[1, 0]
    wc[2] = bzd * cyb + thd * rm[2, 0]
    return syb, cyb


@njit(cache=True, inline="always")
def cage_pockets(ci, y, dy, rows, ball_row, gp, cpar, cm, alpha, rcm, occ, vc, wc, fc, mc, fm, diag, want, acc, work,
                 active):
    """The ball–pocket contacts of cage ci ([S1] §3.2, eqs. 6–7; module docstring).

    Per pocket j at azimuth φ_j = ψ₀ + 2πj/Z: the ball centre in the pocket frame (elastic cage: in the
    pocket displaced by u_j and turned by ρ_j), the nearest pocket-surface point (:func:`pocket_point`),
    the Hunt–Crossley force Q = K_c δ^1.5 (1 + (3/2) α δ̇) along the normal and the regularised sliding
    friction −μ Q v_t/√(|v_t|² + v_ref²).  Accumulates the ball's accelerations in dy, the cage's force
    fc and moment mc about its centre, the modal forces fm = Σ_j φ_k^u·F_j + φ_k^ρ·(r_j × F_j) (cage
    frame), and with ``want`` the diagnostics, power loss and elastic energy (2/5) K_c δ^2.5.
    work: tuple of float[3] work arrays (:func:`rhs`).
    """
    tmp, bp, wpk, ud, rho, udd, rhod, nlc, rpk, fcl, mcl, nvec, pc, pw, half, vbp, vcp, ff, ftot = work
    if gp[ly.G_CAGE_ON] <= 0.0:
        return
    nm = int(cpar[ly.C_NMODES])
    om0 = int(cpar[ly.C_MODE0])
    z = int(cpar[ly.C_Z])
    b0 = int(cpar[ly.C_BALL0])
    rp = cpar[ly.C_RP]
    clr = cpar[ly.C_CLR]
    kcg = cpar[ly.C_KC]
    mu = cpar[ly.C_MU]
    vref = gp[ly.G_VREF]
    # cos φ_j, sin φ_j by turning pocket 0's by 2π/Z from pocket to pocket (two sincos per cage instead of one per
    # pocket, a serial part of the threaded right-hand side; the rounding grows by ≤ 1 ulp per pocket)
    dphi = 2.0 * math.pi / z if z > 0 else 0.0
    cdp = math.cos(dphi)
    sdp = math.sin(dphi)
    cph = math.cos(cpar[ly.C_PSI0])
    sph = math.sin(cpar[ly.C_PSI0])
    for j in range(z):
        if j > 0:
            cph, sph = cph * cdp - sph * sdp, sph * cdp + cph * sdp
        k = b0 + j
        if active.shape[0] > 0 and active[k] == 0:
            continue
        ob = ly.N_RING + ly.N_BALL * k
        half_d = 0.5 * rows[ball_row[k], kn.P_D]
        for i in range(3):
            tmp[i] = y[ob + i] - occ[i]
        for i in range(3):
            bp[i] = rcm[0, i] * tmp[0] + rcm[1, i] * tmp[1] + rcm[2, i] * tmp[2]
        # ball centre from the pocket centre, cage frame
        wpk[0] = bp[0]
        wpk[1] = bp[1] - rp * cph
        wpk[2] = bp[2] - rp * sph
        if nm > 0:
            # the pocket's elastic displacement and small rotation (cage frame), and their rates
            for i in range(3):
                ud[i] = 0.0
                rho[i] = 0.0
                udd[i] = 0.0
                rhod[i] = 0.0
            sb = ly.CM_SHAPE0 + 6 * j
            for kk in range(nm):
                et = y[om0 + kk]
                ed = y[om0 + nm + kk]
                for i in range(3):
                    s1 = cm[ci, kk, sb + i]
                    s2 = cm[ci, kk, sb + 3 + i]
                    ud[i] += et * s1
                    rho[i] += et * s2
                    udd[i] += ed * s1
                    rhod[i] += ed * s2
            # ball centre in the displaced and turned pocket frame: R(ρ)ᵀ (w − u) ≈ (w − u) − ρ × (w − u)
            for i in range(3):
                wpk[i] -= ud[i]
            _cross(rho, wpk, tmp)
            for i in range(3):
                wpk[i] -= tmp[i]
        # no point of a pocket of radius D/2 + clr can touch a ball this close to its centre
        if math.sqrt(wpk[0] * wpk[0] + wpk[1] * wpk[1] + wpk[2] * wpk[2]) <= clr:
            continue
        # ball centre in the pocket frame (t, r, x)
        ut = -wpk[1] * sph + wpk[2] * cph
        ur = wpk[1] * cph + wpk[2] * sph
        ux = wpk[0]
        # nearest point of the pocket surface to the ball centre (closed form) and the penetration
        qt, qr, qx = pocket_point(int(cpar[ly.C_SHAPE]), cpar[ly.C_POCKET], half_d + clr, ut, ur, ux)
        e0 = ut - qt
        e1 = ur - qr
        e2 = ux - qx
        dd = math.sqrt(e0 * e0 + e1 * e1 + e2 * e2)
        best = half_d - dd
        if not (best > 0.0 and dd > 0.0):
            continue
        # normal (point → ball centre) and contact point from the pocket centre, cage frame
        nlc[0] = e2 / dd
        nlc[1] = (e1 * cph - e0 * sph) / dd
        nlc[2] = (e1 * sph + e0 * cph) / dd
        rpk[0] = qx
        rpk[1] = qr * cph - qt * sph
        rpk[2] = qr * sph + qt * cph
        if nm > 0:
            # turned with the pocket; the point's elastic velocity u̇ + ρ̇ × r (cage frame) in fcl
            _cross(rho, nlc, tmp)
            for i in range(3):
                nlc[i] += tmp[i]
            _cross(rho, rpk, tmp)
            for i in range(3):
                rpk[i] += tmp[i]
            _cross(rhod, rpk, fcl)
            for i in range(3):
                fcl[i] += udd[i]
            pl0 = rpk[0] + ud[0]
            pl1 = rp * cph + rpk[1] + ud[1]
            pl2 = rp * sph + rpk[2] + ud[2]
        else:
            pl0 = rpk[0]
            pl1 = rp * cph + rpk[1]
            pl2 = rp * sph + rpk[2]
        for i in range(3):
            nvec[i] = rcm[i, 0] * nlc[0] + rcm[i, 1] * nlc[1] + rcm[i, 2] * nlc[2]
            pc[i] = occ[i] + rcm[i, 0] * pl0 + rcm[i, 1] * pl1 + rcm[i, 2] * pl2
            pw[i] = pc[i] - y[ob + i]
            half[i] = pc[i] - occ[i]
        # ω_b × (p − b) (the ball's states read in place: an array view per pocket costs numba a reference count)
        vbp[0] = y[ob + 7] * pw[2] - y[ob + 8] * pw[1]
        vbp[1] = y[ob + 8] * pw[0] - y[ob + 6] * pw[2]
        vbp[2] = y[ob + 6] * pw[1] - y[ob + 7] * pw[0]
        _cross(wc, half, vcp)
        for i in range(3):
            vbp[i] += y[ob + 3 + i]
            vcp[i] += vc[i]
        if nm > 0:
            for i in range(3):
                vcp[i] += rcm[i, 0] * fcl[0] + rcm[i, 1] * fcl[1] + rcm[i, 2] * fcl[2]
        ddot = -(nvec[0] * (y[ob + 3] - vcp[0]) + nvec[1] * (y[ob + 4] - vcp[1]) + nvec[2] * (y[ob + 5] - vcp[2]))
        qn = kcg * best * math.sqrt(best) * (1.0 + 1.5 * alpha * ddot)
        if qn <= 0.0:
            continue
        vn = (vbp[0] - vcp[0]) * nvec[0] + (vbp[1] - vcp[1]) * nvec[1] + (vbp[2] - vcp[2]) * nvec[2]
        vt2 = 0.0
        for i in range(3):
            ff[i] = (vbp[i] - vcp[i]) - vn * nvec[i]
            vt2 += ff[i] * ff[i]
        cf = -mu * qn / math.sqrt(vt2 + vref * vref)
        ploss = 0.0
        for i in range(3):
            ploss -= cf * ff[i] * ff[i]
            ff[i] *= cf
            ftot[i] = qn * nvec[i] + ff[i]
        dy[ob + 3] += ftot[0] / rows[ball_row[k], kn.P_MASS]
        dy[ob + 4] += ftot[1] / rows[ball_row[k], kn.P_MASS]
        dy[ob + 5] += ftot[2] / rows[ball_row[k], kn.P_MASS]
        _cross(pw, ff, tmp)
        jb = rows[ball_row[k], kn.P_JB]
        dy[ob + 6] += tmp[0] / jb
        dy[ob + 7] += tmp[1] / jb
        dy[ob + 8] += tmp[2] / jb
        _cross(half, ftot, tmp)
        for i in range(3):
            fc[i] -= ftot[i]
            mc[i] -= tmp[i]
        if nm > 0:
            # generalized modal forces of the pocket force on the cage (cage frame) and of its
            # moment about the deformed pocket centre
            for i in range(3):
                fcl[i] = -(rcm[0, i] * ftot[0] + rcm[1, i] * ftot[1] + rcm[2, i] * ftot[2])
            _cross(rpk, fcl, mcl)
            sb = ly.CM_SHAPE0 + 6 * j
            for kk in range(nm):
                acm = 0.0
                for i in range(3):
                    acm += cm[ci, kk, sb + i] * fcl[i] + cm[ci, kk, sb + 3 + i] * mcl[i]
                fm[kk] += acm
        if want:
            diag[k, ly.D_QC] = qn
            diag[k, ly.D_PC] = ploss
            acc[A_PCAGE] += ploss
            acc[A_EPOT] += 0.4 * kcg * best ** 2.5


@njit(cache=True, inline="always")
def land_guidance(cpar, occ, vc, wc, c, ax, wring, cd, fc, mc, fring, mring, vref, want, acc, work):
    """Cage guided by a ring land (module docstring): the radial eccentricity e of the cage centre
    (outer land: from the bearing axis; inner land: from the inner ring's axis) beyond the land
    clearance c_L gives Q = K_L (|e| − c_L)^1.5 at the land radius r_L along ±e/|e|, and sliding friction
    −μ_L Q v_t/√(|v_t|² + v_ref²) against the land (at rest, or moving with the inner ring).  Accumulates
    the cage's force fc and moment mc, for an inner land the reaction on the ring (fring, mring), the
    land power loss and elastic energy (2/5) K_L (|e| − c_L)^2.5.  work: as :func:`cage_pockets`."""
    guide = int(cpar[ly.C_GUIDE])
    if guide <= 0:
        return
    tmp, _, _, _, _, _, _, _, _, _, _, nvec, _, pw, half, vbp, vcp, ff, ftot = work
    if guide == 1:
        e0 = 0.0
        e1 = occ[1]
        e2 = occ[2]
    else:
        for i in range(3):
            tmp[i] = occ[i] - c[i]
        pr = tmp[0] * ax[0] + tmp[1] * ax[1] + tmp[2] * ax[2]
        e0 = tmp[0] - pr * ax[0]
        e1 = tmp[1] - pr * ax[1]
        e2 = tmp[2] - pr * ax[2]
    ecc = math.sqrt(e0 * e0 + e1 * e1 + e2 * e2)
    pen = ecc - cpar[ly.C_CLAND]
    if pen > 0.0:
        qn = cpar[ly.C_KLAND] * pen * math.sqrt(pen)
        nvec[0] = e0 / ecc
        nvec[1] = e1 / ecc
        nvec[2] = e2 / ecc
        sgn = 1.0 if guide == 1 else -1.0
        for i in range(3):
            half[i] = sgn * nvec[i] * cpar[ly.C_RLAND]
        _cross(wc, half, vcp)
        for i in range(3):
            vcp[i] += vc[i]
        if guide == 2:
            for i in range(3):
                tmp[i] = occ[i] + half[i] - c[i]
            _cross(wring, tmp, vbp)
            for i in range(3):
                vbp[i] += cd[i]
        else:
            for i in range(3):
                vbp[i] = 0.0
        vn = 0.0
        for i in range(3):
            vn += (vcp[i] - vbp[i]) * nvec[i]
        vt2 = 0.0
        for i in range(3):
            ff[i] = (vcp[i] - vbp[i]) - vn * nvec[i]
            vt2 += ff[i] * ff[i]
        cf = -cpar[ly.C_MULAND] * qn / math.sqrt(vt2 + vref * vref)
        for i in range(3):
            acc[A_PLAND] -= cf * ff[i] * ff[i]
            ftot[i] = -qn * nvec[i] + cf * ff[i]
            fc[i] += ftot[i]
        _cross(half, ftot, tmp)
        for i in range(3):
            mc[i] += tmp[i]
        if guide == 2:
            for i in range(3):
                fring[i] -= ftot[i]
                tmp[i] = occ[i] + half[i] - c[i]
            _cross(tmp, ftot, pw)
            for i in range(3):
                mring[i] -= pw[i]
        if want:
            acc[A_EPOT] += 0.4 * cpar[ly.C_KLAND] * pen ** 2.5


@njit(cache=True, inline="always")
def cage_equations(ci, o, y, dy, cpar, cm, rm, syb, cyb, fc, mc, fm, g0, g1, g2, acc):
    """Rigid cage: ṙ = v, m v̇ = F + m g; I_p θ̈ = M·(R_y R_z e_x); I_t β̈y = M·e_y − I_p θ̇ β̇z;
    I_t β̈z = M·R_y e_z + I_p θ̇ β̇y.  Elastic modes (Craig 1981 ch. 17): η̈_k + 2ζ_k ω_k η̇_k + ω_k² η_k
    = fm_k; strain energy Σ ½ ω_k² η_k² [J] into acc."""
    thd = y[o + ly.K_THETA_DOT]
    byd = y[o + ly.K_BETA_Y_DOT]
    bzd = y[o + ly.K_BETA_Z_DOT]
    mcg = cpar[ly.C_MASS]
    ip = cpar[ly.C_IP]
    itc = cpar[ly.C_IT]
    dy[o] = y[o + 3]
    dy[o + 1] = y[o + 4]
    dy[o + 2] = y[o + 5]
    dy[o + 3] = fc[0] / mcg + g0
    dy[o + 4] = fc[1] / mcg + g1
    dy[o + 5] = fc[2] / mcg + g2
    dy[o + 6] = thd
    dy[o + 7] = byd
    dy[o + 8] = bzd
    dy[o + 9] = (mc[0] * rm[0, 0] + mc[1] * rm[1, 0] + mc[2] * rm[2, 0]) / ip
    dy[o + 10] = (mc[1] - ip * thd * bzd) / itc
    dy[o + 11] = (mc[0] * syb + mc[2] * cyb + ip * thd * byd) / itc
    # modal coordinates of an elastic cage
    nm = int(cpar[ly.C_NMODES])
    om0 = int(cpar[ly.C_MODE0])
    for kk in range(nm):
        et = y[om0 + kk]
        ed = y[om0 + nm + kk]
        wk = cm[ci, kk, ly.CM_OMEGA]
        dy[om0 + kk] = ed
        dy[om0 + nm + kk] = fm[kk] - cm[ci, kk, ly.CM_DAMP] * ed - wk * wk * et
        acc[A_ECAGE] += 0.5 * wk * wk * et * et


@njit(cache=True, inline="always")
def ring_equations(y, dy, gp, fring, mring, loads, omega, sy, cy, g0, g1, g2):
    """Inner ring ([S1] Table 3; Lagrange with a constant mass matrix): m c̈ = F + F_applied + m g;
    I_t γ̈y = Q_γy − I_p Ω γ̇z; I_t γ̈z = Q_γz + I_p Ω γ̇y with Q_γy = M·e_y + M_y − x_L F_z and
    Q_γz = M·R_y e_z + M_z + x_L F_y (applied loads at the load point x_L).  Held fixed: ẏ = 0."""
    xl = gp[ly.G_XL]
    if gp[ly.G_RING_FIXED] > 0.0:
        for i in range(10):
            dy[i] = 0.0
        return
    mr = gp[ly.G_MR]
    itr = gp[ly.G_ITR]
    ipr = gp[ly.G_IPR]
    dy[0] = y[5]
    dy[1] = y[6]
    dy[2] = y[7]
    dy[3] = y[8]
    dy[4] = y[9]
    dy[5] = (fring[0] + loads[0]) / mr + g0
    dy[6] = (fring[1] + loads[1]) / mr + g1
    dy[7] = (fring[2] + loads[2]) / mr + g2
    qgy = mring[1] + loads[3] - xl * loads[2]
    qgz = mring[0] * sy + mring[2] * cy + loads[4] + xl * loads[1]
    dy[8] = (qgy - ipr * omega * y[9]) / itr
    dy[9] = (qgz + ipr * omega * y[8]) / itr


@njit(cache=True, inline="always")
def global_diagnostics(gdiag, loads, mring, ax, mout, acc, omega):
    """gdiag ← applied loads, friction torques on both rings about their axes, power losses, shaft speed,
    elastic energies (layout GD_* in :mod:`.layout`)."""
    gdiag[ly.GD_FA] = loads[0]
    gdiag[ly.GD_FRY] = loads[1]
    gdiag[ly.GD_FRZ] = loads[2]
    gdiag[ly.GD_MY] = loads[3]
    gdiag[ly.GD_MZ] = loads[4]
    gdiag[ly.GD_TQI] = mring[0] * ax[0] + mring[1] * ax[1] + mring[2] * ax[2]
    gdiag[ly.GD_TQO] = mout[0]
    gdiag[ly.GD_PI] = acc[A_PIN]
    gdiag[ly.GD_PO] = acc[A_POUT]
    gdiag[ly.GD_PC] = acc[A_PCAGE]
    gdiag[ly.GD_PL] = acc[A_PLAND]
    gdiag[ly.GD_W] = omega
    gdiag[ly.GD_EPOT] = acc[A_EPOT]
    gdiag[ly.GD_ECAGE] = acc[A_ECAGE]


@njit(cache=True)
def rhs(t, y, dy, rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo, threads=False):
    """Time derivative of the state (equations of motion, inertial frame).

    The equations, one helper each: balls on the raceways (:func:`ball_inner_raceway`,
    :func:`ball_outer_raceway`) and Newton–Euler for every ball (:func:`ball_equations`); per cage its
    frame (:func:`cage_kinematics`), the ball–pocket contacts with the elastic modes
    (:func:`cage_pockets`), land guidance (:func:`land_guidance`) and its rigid and modal equations
    (:func:`cage_equations`); the inner ring (:func:`ring_equations`).

    Inner ring ([S1] Table 3; Lagrange with constant mass matrix):
    m c̈ = F + m g;  I_t γ̈y = Q_γy − I_p Ω γ̇z;  I_t γ̈z = Q_γz + I_p Ω γ̇y, with the
    generalized moments Q_γy = M·e_y and Q_γz = M·R_y e_z of the contact moment M about
    the ring centre, plus the applied loads (moments about the bearing centre of the
    forces applied at the load point x_L: M_y − x_L F_z, M_z + x_L F_y).
    Balls (Newton and Euler; a sphere's inertia is isotropic so Euler's equations in
    the inertial frame reduce to J ω̇ = M, centrifugal and gyroscopic effects arise
    from the motion itself): m v̇ = F + m g, J ω̇ = M.
    Cage: m v̇ = F + m g; I_p θ̈ = M·(R_y R_z e_x); I_t β̈y = M·e_y − I_p θ̇ β̇z;
    I_t β̈z = M·R_y e_z + I_p θ̇ β̇y.
    Elastic cage (mode synthesis, [S1] Table 3; Craig 1981 ch. 17): the pockets move in the cage
    frame by u_j = Σ η_k φ_k^u(j) and turn by ρ_j = Σ η_k φ_k^ρ(j) (free–free mass-normalised modes,
    :mod:`bearingsim.cage_modes`); η̈_k + 2 ζ_k ω_k η̇_k + ω_k² η_k = Σ_j (φ_k^u(j)·F_j + φ_k^ρ(j)·(r_j × F_j))
    with F_j the pocket force on the cage (cage frame) and r_j its point from the deformed pocket
    centre.  The modes are orthogonal to the rigid motions, so the rigid and elastic inertias decouple
    to first order; the cage's spin couples them only through centrifugal and Coriolis terms of
    relative size (θ̇/ω_1)², neglected (docs/dynamics.md).

    cm (n_cages × n_max_modes × (2 + 6 Z)): per mode ω_k [rad/s], 2 ζ_k ω_k [1/s], then the six
    shape components (u_x, u_y, u_z [m], ρ_x, ρ_y, ρ_z [rad] per unit η, cage frame) of every pocket
    (layout CM_* in :mod:`.layout`).

    lubs (2 n_rows × L_SIZE): lubrication parameters of the inner (2r) and outer (2r+1)
    contacts of row r for the sliced-ellipse kernel.
    diag (n_balls × NDB) and gdiag (NDG) receive output quantities when diag has rows.
    memo (n_balls × MEMO_W, or no rows: :func:`no_memo`): the outer-raceway contacts of the last evaluation, reused
    for a ball whose state has not changed since (:func:`outer_memo_hit`; the same result bit for bit); with a row
    more (n_balls + 1 rows, :func:`args_of`) it also records each ball's inner-ring reaction and the ring's
    gyroscopic coefficient of this evaluation (:func:`record_reactions`), from which ROS34PW2 derives the ring's
    Jacobian columns.
    threads: the balls in parallel (:func:`balls_on_raceways`; same result bit for bit).

    One work array is allocated here; the equations are :func:`_rhs`, compiled without numba's reference counting
    (counted, its ~60 small arrays and views would each take an atomic increment and decrement).
    """
    nsl = int(gp[ly.G_NSL]) if int(gp[ly.G_TRAC]) == 1 else 0
    nw = RHS_WORK + cm.shape[1] + ball_work_size(ball_row.shape[0], nsl, threads)
    _rhs(t, y, dy, rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo, threads, np.empty(nw),
         np.zeros(0, np.int8), int(PHASE_ALL))


@njit(cache=True, _nrt=False)
def _rhs(t, y, dy, rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo, threads, work, active,
         phase):
    """The body of :func:`rhs`; work: float[RHS_WORK + cm.shape[1] + ball_work_size(...)] (every small array of the
    equations is a view of it); ``phase`` (:data:`PHASE_ALL` …) and ``active`` say which part is computed.

    Compiled twice, ``threads`` a literal False or True: numba compiles a called function once per literal
    argument, so its callers pass ``phase`` as a run-time value (``int(…)``): as literals the phase constants
    would compile four copies of the serial body (and of :func:`balls_on_raceways`), ≈ 18 s of compilation each
    from an empty cache.  ``threads`` stays a literal: the serial right-hand side without the threaded branch is
    1–2 % faster (hub (b), 45.2–45.5 against 45.7–46.4 µs, alternated processes)."""
    nb = ball_row.shape[0]
    want = diag.shape[0] > 0
    omega = speed_at(t, gp)
    alpha = gp[ly.G_ALPHA]
    g0 = gp[ly.G_GX]
    g1 = gp[ly.G_GX + 1]
    g2 = gp[ly.G_GX + 2]
    # ---- inner ring: orientation, axis, angular velocity (tilt rates plus the spin Ω about its axis)
    rm = work[0:9].reshape((3, 3))
    _rot_yz(y[3], y[4], rm)
    cy = math.cos(y[3])
    sy = math.sin(y[3])
    c = y[0:3]
    cd = y[5:8]
    ax = work[9:12]
    ax[0] = rm[0, 0]
    ax[1] = rm[1, 0]
    ax[2] = rm[2, 0]
    wtilt = work[12:15]
    wtilt[0] = y[9] * sy
    wtilt[1] = y[8]
    wtilt[2] = y[9] * cy
    wring = work[15:18]
    for i in range(3):
        wring[i] = wtilt[i] + omega * ax[i]
    fring = work[18:21]
    mring = work[21:24]
    fout = work[24:27]
    mout = work[27:30]
    acc = work[30:30 + NACC]
    for i in range(18, 30 + NACC):  # fring, mring, fout, mout, acc start at zero
        work[i] = 0.0
    loads = work[36:41]
    masked = phase == PHASE_MASKED  # (the active balls' derivatives alone, nothing of the rings' and cages')
    if not masked:
        loads_at(t, loadspec, loads)
    # ---- balls on the raceways
    balls_on_raceways(y, dy, rows, rowx, ball_row, gp, lubs, rm, ax, c, cd, wtilt, wring, fring, mring, fout, mout,
                      diag, acc, memo, threads, work[RHS_WORK + cm.shape[1]:], active, phase)
    if phase == PHASE_OTHERS:
        return
    # ---- cages: pockets (with elastic modes), land guidance, equations
    oc0 = ly.N_RING + ly.N_BALL * nb
    rmc = work[41:50].reshape((3, 3))
    rcm = work[50:59].reshape((3, 3))
    occ = work[59:62]
    wc = work[62:65]
    fc = work[65:68]
    mc = work[68:71]
    tmp = work[71:74]
    bp = work[74:77]
    wpk = work[77:80]
    ud = work[80:83]
    rho = work[83:86]
    udd = work[86:89]
    rhod = work[89:92]
    nlc = work[92:95]
    rpk = work[95:98]
    fcl = work[98:101]
    mcl = work[101:104]
    nvec = work[104:107]
    pc = work[107:110]
    pw = work[110:113]
    half = work[113:116]
    vbp = work[116:119]
    vcp = work[119:122]
    ff = work[122:125]
    ftot = work[125:128]
    fm = work[RHS_WORK:RHS_WORK + cm.shape[1]]
    for i in range(3):
        ud[i] = 0.0
        rho[i] = 0.0
        udd[i] = 0.0
        rhod[i] = 0.0
    cwork = (tmp, bp, wpk, ud, rho, udd, rhod, nlc, rpk, fcl, mcl, nvec, pc, pw, half, vbp, vcp, ff, ftot)
    for ci in range(cp.shape[0]):
        o = oc0 + ly.N_CAGE * ci
        cpar = cp[ci]
        if masked and not any_active(active, int(cpar[ly.C_BALL0]), int(cpar[ly.C_Z])):
            continue
        for kk in range(int(cpar[ly.C_NMODES])):
            fm[kk] = 0.0
        syb, cyb = cage_kinematics(y, o, cpar, rmc, rcm, occ, wc)
        vc = y[o + ly.K_VEL:o + ly.K_VEL + 3]
        for i in range(3):
            fc[i] = 0.0
            mc[i] = 0.0
        cage_pockets(ci, y, dy, rows, ball_row, gp, cpar, cm, alpha, rcm, occ, vc, wc, fc, mc, fm, diag, want, acc,
                     cwork, active if masked else active[:0])
        if masked:
            continue
        land_guidance(cpar, occ, vc, wc, c, ax, wring, cd, fc, mc, fring, mring, gp[ly.G_VREF], want, acc, cwork)
        cage_equations(ci, o, y, dy, cpar, cm, rmc, syb, cyb, fc, mc, fm, g0, g1, g2, acc)
    if gp[ly.G_ORBIT_HELD] > 0.0:
        # balls held in azimuth by a frictionless constraint (the fixed half-plane of each ball, a linear
        # constraint e_psi . r = 0): the azimuthal components of velocity and acceleration are removed
        for k in range(nb):
            if masked and active[k] == 0:
                continue  # (rhs_masked: the other balls' states are not set)
            o = ly.N_RING + ly.N_BALL * k
            rb = math.hypot(y[o + 1], y[o + 2])
            ey = -y[o + 2] / rb
            ez = y[o + 1] / rb
            vt = dy[o + 1] * ey + dy[o + 2] * ez
            dy[o + 1] -= vt * ey
            dy[o + 2] -= vt * ez
            at = dy[o + 4] * ey + dy[o + 5] * ez
            dy[o + 4] -= at * ey
            dy[o + 5] -= at * ez
    if masked:
        return
    # ---- inner ring
    ring_equations(y, dy, gp, fring, mring, loads, omega, sy, cy, g0, g1, g2)
    if memo.shape[0] > nb:
        record_reactions(memo, work[RHS_WORK + cm.shape[1]:], nb, gp, cp, omega, mring, t, y)
    if want:
        global_diagnostics(gdiag, loads, mring, ax, mout, acc, omega)


@njit(cache=True, inline="always")
def any_active(active, b0, z):
    """Whether one of the balls b0 … b0 + z − 1 is active (a cage with pockets to evaluate in :func:`rhs_masked`)."""
    for k in range(b0, b0 + z):
        if active[k] != 0:
            return True
    return False


@njit(cache=True, inline="always")
def record_reactions(memo, bwork, nb, gp, cp, omega, mring, t, y):
    """The memo's record of this evaluation (layout ``MEMO_INNER``, ``MR_*`` in :mod:`.layout`): each ball's
    inner-ring reaction (the first six of its contributions in ``bwork``, :func:`balls_on_raceways`), and in the
    ring's row I_p Ω / I_t, the ring's contact moment and whether the ring's Jacobian columns may be derived from
    the balls' (:func:`bearingsim.dynamics.integrate.jacobian.ring_columns`: not with a cage guided on the inner
    ring's land, whose force on the ring the balls' sweeps do not see, nor with the azimuths held, which projects the
    balls' rows), with t and the ring's states it was made at (the balls' are in their memo rows:
    :func:`bearingsim.dynamics.integrate.jacobian.record_at`)."""
    for k in range(nb):
        for i in range(6):
            memo[k, ly.MEMO_INNER + i] = bwork[k * NCONTRIB + i]
    memo[nb, ly.MR_GYRO] = gp[ly.G_IPR] * omega / gp[ly.G_ITR]
    for i in range(3):
        memo[nb, ly.MR_MOMENT + i] = mring[i]
    ok = gp[ly.G_ORBIT_HELD] == 0.0
    for ci in range(cp.shape[0]):
        if int(cp[ci, ly.C_GUIDE]) == ly.GUIDANCE_INNER_LAND:
            ok = False
    memo[nb, ly.MR_DERIVE] = 1.0 if ok else 0.0
    memo[nb, ly.MR_T] = t
    for i in range(ly.N_RING):
        memo[nb, ly.MR_Y + i] = y[i]


def evaluate(model, t, y, loadspec, want_diag=True, threads=False):
    """Python helper: (dy, diag, gdiag) at (t, y) (threads: :func:`rhs`)."""
    dy = np.zeros_like(y)
    diag = np.zeros((model.n_balls if want_diag else 0, ly.NDB))
    gdiag = np.zeros(ly.NDG)
    # (the engine's two kernels, threads a literal in each: :func:`_rhs`)
    (rhs_args_threaded if threads else rhs_args)(t, y, dy, args_of(model, loadspec, diag, gdiag, memo=False))
    return dy, diag, gdiag


@njit(cache=True)
def rhs_args(t, y, dy, a):
    """:func:`rhs` with its arrays in one tuple (the integrator's calling convention)."""
    rhs(t, y, dy, a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10])


@njit(cache=True)
def rhs_masked(t, y, dy, a, active):
    """:func:`rhs_args` for the balls with active[k] ≠ 0 only (their raceway and pocket contacts): the other
    balls' derivatives and those of the rings and cages are not computed (the multirate refinement's right-hand side,
    :mod:`.integrate.multirate`; on the hub case 0.6 µs and 1.9 µs per active ball, against 55 µs for all 32).
    Serial: on a threaded engine the refinement's groups of balls are the parallel work
    (:func:`.integrate.multirate.refine_groups_threaded`)."""
    rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo = a
    _rhs(t, y, dy, rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, no_memo(), False,
         split_work(a), active, int(PHASE_MASKED))


@njit(cache=True)
def split_work(a):
    """A work array of the one-thread right-hand side (as :func:`rhs` allocates it): the one :func:`rhs_split`'s two
    calls share, and :func:`rhs_masked`'s own."""
    rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo = a
    nsl = int(gp[ly.G_NSL]) if int(gp[ly.G_TRAC]) == 1 else 0
    return np.empty(RHS_WORK + cm.shape[1] + ball_work_size(ball_row.shape[0], nsl, False))


@njit(cache=True)
def rhs_split(t, y, dy, a, active, phase, work):
    """:func:`rhs_args` in two calls on the same ``work`` (:func:`split_work`): ``phase`` = :data:`PHASE_OTHERS`
    the raceway contacts of the balls with active[k] = 0, then :data:`PHASE_REST` everything else.  Between the
    two, the active balls' states may still change (the multirate refinement runs beside the first call,
    :mod:`.integrate.multirate`); the two give f bit for bit as :func:`rhs_args` does at the final state (the same
    statements per ball, the reduction in ball order)."""
    rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo = a
    _rhs(t, y, dy, rows, rowx, ball_row, gp, cp, cm, lubs, loadspec, diag, gdiag, memo, False, work, active,
         int(phase))


@njit(cache=True)
def rhs_args_threaded(t, y, dy, a):
    """:func:`rhs_args` with the balls on ``numba.get_num_threads()`` threads (the same result, bit for bit)."""
    rhs(t, y, dy, a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8], a[9], a[10], True)


def args_of(model, loadspec, diag=None, gdiag=None, memo=True):
    """The argument tuple of :func:`rhs_args` (diagnostics off unless arrays are given; with ``memo`` an
    outer-contact memo of its own, :func:`outer_memo_hit`: it keys on the balls' states alone, so build a new tuple
    when the model's arrays change between calls; its ring row holds the record of :func:`record_reactions`)."""
    if diag is None:
        diag = np.zeros((0, ly.NDB))
    if gdiag is None:
        gdiag = np.zeros(ly.NDG)
    return (model.rows, model.rowx, model.ball_row, model.gp, model.cp, model.cage_modes, model.lub_array(), loadspec,
            diag, gdiag, np.zeros((model.n_balls + 1, MEMO_W)) if memo else no_memo())


def __getattr__(name: str):
    """The diagnostics columns (``forces.D_QI``, ``forces.GD_PI`` ...) are those of :mod:`.layout` (kept
    importable from here)."""
    if name.startswith(("D_", "GD_")) or name in ("NDB", "NDG"):
        return getattr(ly, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
