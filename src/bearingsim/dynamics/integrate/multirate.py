"""Multirate refinement of ROS34PW2 steps: the balls that hold the error stepped again on their own.

Why.  On the hub (b) the step is set by a few balls: near the moment's zero crossing the balls of the row being
unloaded rattle between their raceways (inner loads jumping between 0 and ≈ 140 N from one 20 µs sample to the
next) and, resolved at the case's tolerance, hold the whole system at 1.15 µs steps — four of 32 balls carry 96 %
of the error there (``python benchmarks/bench_dynamics.py --steps``).  With
those balls' errors left out, the same 0.8 ms takes 71 steps instead of 695.  Stepping every state at the rate of
the fastest is what multirate methods avoid.

Method (Savcenco, Hundsdorfer & Verwer, "A multirate time stepping strategy for stiff ordinary differential
equations", BIT Numer. Math. 47 (2007) 137–155, their §2: a step of the whole system, then the components whose
local error is too large computed again over the same interval with smaller steps, the others — latent — taken
from an interpolant of the large step):

1. A ROS34PW2 step of size H of the whole system (:func:`.ros34pw2.integrate`), with its error estimate e.
2. Per ball b the sum of its nine scaled squared errors s_b = Σ (e_i / sc_i)²; the balls with s_b > 9 θ
   (the RMS of their own errors above √θ, θ = :data:`HOT`), largest first, up to ``mr`` of them, are *active*.
   The step's error for the controller is that of the others, √((Σ s − Σ_active s_b) / n); above 1 the step is
   rejected.
3. The active balls are integrated again over [t, t + H] (:func:`refine`) by ROS34PW2 steps of their own on their
   nine states each, with the rings and cages on the quadratic through y(t), f(t, y) and the large step's y(t + H)
   (:func:`latent`); their right-hand side is the engine's with the other balls skipped
   (:func:`bearingsim.dynamics.forces.rhs_masked`: 4 active balls cost 8.3 µs against 55 µs for all 32).
   Error control on the active balls' states alone: √(Σ_active (e_i / sc_i)² / (9 n_active)) ≤ 1, which holds each
   of them at least as tightly as the whole system's RMS norm does.  Their W uses the large step's Jacobian blocks
   (turned with the orbit, :mod:`.linalg`), made again by differences of the masked right-hand side after two
   rejections in a row (:func:`micro_jac`).  After :data:`~.common.MICRO_MAX` micro attempts the refinement gives
   up: the large step is rejected and the next :data:`COOL` steps are not refined.
4. The active balls' states at t + H are replaced by the refined ones.

Two groups.  The active balls are dealt to :data:`~.common.GROUPS` = 2 groups in turn
by rank (:func:`split_groups`), each refined on micro steps of its own (its own error control, next micro step and
dense-output nodes; :func:`refine_groups`), so that on a threaded engine the two run on two threads in one parallel
region per refinement (:func:`refine_groups_threaded`) — with the first part of f at the step's end beside them
(the raceway contacts of the balls not refined, which the refinement does not change:
:func:`bearingsim.dynamics.forces.rhs_split`).  The groups are the same whatever the thread count, so one and two
threads give the same trajectory bit for bit.  The masked right-hand sides are not threaded ball by ball: with
≈ 3 balls, ≈ 8 µs of work per call, the parallel region's entry costs what the threads gain.

What it leaves out: the rings and cages feel the active balls' forces of the large step, not of the refined
trajectories (the coupling error of the method).  On the hub (b), the ring displacement's deviation from a
tol-1e-8 run over the first 5 ms is 1.32e-5 / 9.9e-6 / 5.4e-6 of the ranges with the refinement against 8.7e-6 /
6.6e-6 / 3.65e-6 without, within the accuracy bound 1e-4.

Dense output: the refined balls do not follow the large step's Hermite interpolant between its ends, so the last
step of a dense call keeps the micro steps' nodes (states and f) and :func:`.common.dense_state` interpolates the
refined balls on them.
"""

from __future__ import annotations

import numpy as np
from numba import njit, prange

from .. import threads as _threads  # noqa: F401 - numba's threading layer, chosen and started
from ..layout import PHASE_OTHERS
from .common import DST_NODES, MICRO_MAX, accept_factor, error_scale, node_row, node_time, reject_factor
from .jacobian import perturbed
from .linalg import block_w_inverse

#: a ball is refined when the RMS of its own nine scaled errors exceeds √HOT (hub (b), 20 ms from the start, CPU
#: against the plain step: θ = 1 / 4 / 16: −26 % / −37 % / −20 %)
HOT = 4.0
#: large steps without refinement after a refinement gave up (:data:`~.common.MICRO_MAX` micro attempts)
COOL = 16


@njit(cache=True, _nrt=False)
def turned_block(jb, c, s, out):
    """out = T J_b Tᵀ for one ball's 9 × 9 block, T turning each of its three vectors (r, v, ω) about x by the angle
    whose (cos, sin) is (c, s) (:mod:`.linalg`: the Jacobian turned with the balls' orbit)."""
    for i in range(9):
        for j in range(9):
            out[i, j] = jb[i, j]
    for k in range(3):
        i = 3 * k + 1
        for j in range(9):
            a1 = out[i, j]
            a2 = out[i + 1, j]
            out[i, j] = c * a1 - s * a2
            out[i + 1, j] = s * a1 + c * a2
    for k in range(3):
        j = 3 * k + 1
        for i in range(9):
            a1 = out[i, j]
            a2 = out[i, j + 1]
            out[i, j] = c * a1 - s * a2
            out[i, j + 1] = s * a1 + c * a2


@njit(cache=True, _nrt=False)
def latent(t0, hh, y0, f0, y1, tau, lo, hi, out):
    """out ← the quadratic through y0 and its slope f0 at t0 and y1 at t0 + hh, at tau [s], on the states before lo
    and from hi on (the rings' and the cages'; the balls' states lo … hi − 1 are the caller's: the active balls' it
    sets, the others' the masked right-hand side does not read)."""
    th = (tau - t0) / hh
    for part in range(2):
        for i in range(0 if part == 0 else hi, lo if part == 0 else y0.shape[0]):
            out[i] = y0[i] + th * hh * f0[i] + th * th * (y1[i] - y0[i] - hh * f0[i])


@njit(cache=True, _nrt=False)
def _solve(act, blk, winvb, v, out):
    """out = W_b⁻¹ v on each active ball's nine states."""
    for a in range(act.shape[0]):
        o = blk[act[a]]
        for i in range(9):
            s = 0.0
            for j in range(9):
                s += winvb[a, i, j] * v[o + j]
            out[o + i] = s


@njit
def micro_jac(funm, args, mask, act, blk, tau, ybase, fbase, atol, jt, yt, ft):
    """The active balls' 9 × 9 blocks by forward differences of the masked right-hand side at (tau, ybase), fbase
    being f there: one component of every active ball perturbed at once, the step of
    :func:`.jacobian.block_jac`."""
    na = act.shape[0]
    for j in range(9):
        for i in range(ybase.shape[0]):
            yt[i] = ybase[i]
        for a in range(na):
            o = blk[act[a]] + j
            yt[o] = perturbed(ybase[o], atol[o])
        funm(tau, yt, ft, args, mask)
        for a in range(na):
            o = blk[act[a]]
            e = yt[o + j] - ybase[o + j]
            for i in range(9):
                jt[a, i, j] = (ft[o + i] - fbase[o + i]) / e


@njit(cache=True)
def refine_work(n, nmax):
    """The work arrays of :func:`refine` for n states and up to ``nmax`` active balls (the first, the stages' state,
    zeroed: :func:`latent` does not set the balls' states, and the masked right-hand side reads only the active
    ones)."""
    return (np.zeros(n), np.empty(n), np.empty(n), np.empty((4, n)), np.empty(n), np.empty(n), np.zeros((nmax, 9, 9)),
            np.zeros((nmax, 9, 9)), np.zeros((9, 9)), np.empty(n), np.empty(n), np.empty(n), np.empty(n))


@njit
def refine(funm, args, mask, act, t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec, hm0, h_min, tab, work, count,
           dns, dst, g, yo):
    """The active balls ``act`` (``mask`` 1 on them) again over [t, t + hh] [s] with ROS34PW2 steps of their own
    (module docstring, step 3), starting with the step hm0; y1's active states ← the result.  ``tab``: ROS34PW2's
    constants (a21, a31, a32, a41, a42, a43, α2, α3, α4, c21, c31, c32, c41, c42, c43, m1…m4, e1…e4, γ); ``count``
    (float[1]) += the masked right-hand sides evaluated.  With ``dns`` rows for the nodes
    (:func:`.common.dense_arrays`; no rows: none kept) the micro steps' nodes are kept for the dense output as group
    g's (its states marked g + 1 in dns[3]: the caller clears that row first).  When done, yo's active states ← the
    result (y0, f0, y1 are only read, so that the groups of a step can run at the same time: :func:`refine_groups`).
    Returns (done, the next micro step proposed)."""
    yf, ff, ya, ks, tv, yn, jt, winvb, wm, ybase, yt2, ft2, fa = work
    amat = np.zeros((4, 3))  # a_sq (stage s from the earlier k_q), c_sq, α_s
    cmat = np.zeros((4, 3))
    alpha = np.zeros(4)
    for q, (s_, r_) in enumerate(((1, 0), (2, 0), (2, 1), (3, 0), (3, 1), (3, 2))):
        amat[s_, r_] = tab[q]
        cmat[s_, r_] = tab[9 + q]
    alpha[1], alpha[2], alpha[3] = tab[6], tab[7], tab[8]
    m1, m2, m3, m4 = tab[15], tab[16], tab[17], tab[18]
    d1, d2, d3, d4 = tab[15] - tab[19], tab[16] - tab[20], tab[17] - tab[21], tab[18] - tab[22]
    gam = tab[23]
    na = act.shape[0]
    n = y0.shape[0]
    lo = blk[0]  # the balls' states: lo … hi − 1 (the rings' before, the cages' after)
    hi = blk[blk.shape[0] - 1] + 9
    keep = dns.shape[0] > 4 and dns.shape[1] == n
    if keep:
        for a in range(na):
            o = blk[act[a]]
            for i in range(9):
                dns[3, o + i] = g + 1.0
    for a in range(na):
        b = act[a]
        if turn.shape[0] > 0:
            turned_block(jac[b], turn[b, 0], turn[b, 1], jt[a])
        else:
            for i in range(9):
                for j in range(9):
                    jt[a, i, j] = jac[b, i, j]
    for i in range(n):
        ya[i] = y0[i]
    tau = t
    te = t + hh
    hm = min(hm0, hh)
    hw = -1.0
    ig = 1.0 / gam
    have_f = False
    prev_rej = False
    attempts = 0
    nodes = 0
    while tau < te:
        if attempts >= MICRO_MAX or hm < h_min:
            return False, hm
        last = tau + hm >= te
        hs = te - tau if last else hm
        if hs != hw:
            for a in range(na):
                block_w_inverse(jt[a], -gam * hs, wm, winvb[a])
            hw = hs
        if not have_f:
            latent(t, hh, y0, f0, y1, tau, lo, hi, yf)
            for a in range(na):
                o = blk[act[a]]
                for i in range(9):
                    yf[o + i] = ya[o + i]
            funm(tau, yf, ff, args, mask)
            count[0] += 1.0
            for a in range(na):
                o = blk[act[a]]
                for i in range(9):
                    fa[o + i] = ff[o + i]
            if prev_rej:  # two rejections in a row: the active blocks made again here
                for i in range(n):
                    ybase[i] = yf[i]
                micro_jac(funm, args, mask, act, blk, tau, ybase, fa, atol, jt, yt2, ft2)
                count[0] += 9.0
                for a in range(na):
                    block_w_inverse(jt[a], -gam * hs, wm, winvb[a])
                prev_rej = False
            have_f = True
            if keep and nodes < MICRO_MAX + 1 and (nodes == 0 or dst[node_time(g, nodes - 1)] < tau):
                dst[node_time(g, nodes)] = tau
                r = node_row(g, nodes)
                for a in range(na):
                    o = blk[act[a]]
                    for i in range(9):
                        dns[r, o + i] = ya[o + i]
                        dns[r + 1, o + i] = fa[o + i]
                nodes += 1
        # stage 1
        for a in range(na):
            o = blk[act[a]]
            for i in range(9):
                tv[o + i] = hs * fa[o + i]
        _solve(act, blk, winvb, tv, ks[0])
        # stages 2–4 (the form of .ros34pw2.stages on the active states): Y_s = y + Σ a_sq k_q,
        # W k_s = h f(Y_s) + Σ c_sq k_q / γ, then k_s −= Σ c_sq k_q / γ
        for st in range(1, 4):
            latent(t, hh, y0, f0, y1, tau + alpha[st] * hs, lo, hi, yf)
            for a in range(na):
                o = blk[act[a]]
                for i in range(9):
                    j = o + i
                    v = ya[j]
                    for q in range(st):
                        v += amat[st, q] * ks[q, j]
                    yf[j] = v
            funm(tau + alpha[st] * hs, yf, ff, args, mask)
            for a in range(na):
                o = blk[act[a]]
                for i in range(9):
                    j = o + i
                    c = cmat[st, 0] * ks[0, j]
                    for q in range(1, st):
                        c += cmat[st, q] * ks[q, j]
                    c *= ig
                    tv[j] = hs * ff[j] + c
                    yn[j] = c
            _solve(act, blk, winvb, tv, ks[st])
            for a in range(na):
                o = blk[act[a]]
                for i in range(9):
                    ks[st, o + i] -= yn[o + i]
        count[0] += 3.0
        # the new state of the active balls and their error
        for a in range(na):
            o = blk[act[a]]
            for i in range(9):
                j = o + i
                yf[j] = ya[j] + m1 * ks[0, j] + m2 * ks[1, j] + m3 * ks[2, j] + m4 * ks[3, j]
        e2 = 0.0
        for a in range(na):
            o = blk[act[a]]
            for i in range(9):
                j = o + i
                r = (d1 * ks[0, j] + d2 * ks[1, j] + d3 * ks[2, j] + d4 * ks[3, j]) / error_scale(j, ya, yf, atol, rtol,
                                                                                        vec)
                e2 += r * r
        err = np.sqrt(e2 / (9.0 * na))
        attempts += 1
        if err <= 1.0:
            for a in range(na):
                o = blk[act[a]]
                for i in range(9):
                    ya[o + i] = yf[o + i]
            tau = te if last else tau + hs
            have_f = False
            prev_rej = False
            fac = accept_factor(err, 1.0 / 3.0, 2.0)
            hm = max(hm, hs * fac) if last else hs * fac
        else:
            if prev_rej:
                have_f = False  # f and the blocks made again at tau
            prev_rej = True
            hm = hs * reject_factor(err, 1.0 / 3.0)
    for a in range(na):
        o = blk[act[a]]
        for i in range(9):
            yo[o + i] = ya[o + i]
    if keep:
        dst[DST_NODES + g] = float(nodes)  # (the end node, f at t + hh, is the caller's: .ros34pw2.integrate)
    return True, hm


@njit(cache=True, _nrt=False)
def select(r2, blk, nbk, nmax, sb, mask, rank):
    """The active balls of a step (module docstring, step 2) from the scaled squared errors ``r2`` of its states:
    mask[b] ← 1 on them, rank[0:number] ← them, largest error first, sb[b] ← each ball's sum; returns (their number,
    the sum over the other states)."""
    nb = blk.shape[0]
    tot = 0.0
    for i in range(r2.shape[0]):
        tot += r2[i]
    for b in range(nb):
        s = 0.0
        o = blk[b]
        for i in range(nbk):
            s += r2[o + i]
        sb[b] = s
        mask[b] = 0
    nact = 0
    rem = tot
    while nact < nmax:
        bb = -1
        best = HOT * nbk
        for b in range(nb):
            if mask[b] == 0 and sb[b] > best:
                best = sb[b]
                bb = b
        if bb < 0:
            break
        mask[bb] = 1
        rank[nact] = bb
        rem -= sb[bb]
        nact += 1
    return nact, max(rem, 0.0)


@njit(cache=True, _nrt=False)
def split_groups(rank, nact, nb, gmask, gact, gn):
    """The active balls ``rank[0:nact]`` (largest error first) dealt to the :data:`~.common.GROUPS` groups in turn
    (rank r to group r mod G, so that the groups carry similar errors): gmask[g, b] ← 1 on group g's balls,
    gact[g, 0:gn[g]] ← them in ball order (the order :func:`refine` and the masked right-hand side visit them)."""
    ng = gmask.shape[0]
    for g in range(ng):
        gn[g] = 0
        for b in range(nb):
            gmask[g, b] = 0
    for r in range(nact):
        gmask[r % ng, rank[r]] = 1
    for g in range(ng):
        for b in range(nb):
            if gmask[g, b] == 1:
                gact[g, gn[g]] = b
                gn[g] += 1


@njit
def _refine_group(g, funm, args, gmask, gact, gn, t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec, hmg, h_min,
                  tab, work, counts, dns, dst, yo, done):
    """Group g of :func:`refine_groups` (nothing when it has no ball)."""
    if gn[g] == 0:
        done[g] = 1
        return
    ok, hm = refine(funm, args, gmask[g], gact[g, 0:gn[g]], t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec,
                    min(hmg[g], hh), h_min, tab, work, counts[g:g + 1], dns, dst, g, yo)
    done[g] = 1 if ok else 0
    hmg[g] = hm


@njit
def refine_groups(funm, args, gmask, gact, gn, t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec, hmg, h_min, tab,
                  works, counts, dns, dst, yo, done, funs, over, t1, fnext, swork, mask):
    """:func:`refine` for each group of :func:`split_groups` in turn, each on micro steps of its own (its own error
    control, micro step hmg[g] and nodes), into yo; done[g] ← whether it finished; then, with ``over``, the first part
    of f at the step's end, ``funs(t1, y1, fnext, args, mask, PHASE_OTHERS, swork)`` (the raceway contacts of the
    balls not refined, which the refinement does not change).  The groups read y0, f0, y1 and write disjoint parts of
    yo, dns and dst, so :func:`refine_groups_threaded` gives the same numbers bit for bit."""
    for g in range(gmask.shape[0]):
        _refine_group(g, funm, args, gmask, gact, gn, t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec, hmg, h_min,
                      tab, works[g], counts, dns, dst, yo, done)
    if over:
        funs(t1, y1, fnext, args, mask, PHASE_OTHERS, swork)


@njit(parallel=True)
def refine_groups_threaded(funm, args, gmask, gact, gn, t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec, hmg,
                           h_min, tab, works, counts, dns, dst, yo, done, funs, over, t1, fnext, swork, mask):
    """:func:`refine_groups` on two threads, one parallel region per refinement: group 0 on one, group 1 and then
    the first part of f on the other; the same numbers bit for bit.  ``funm`` and ``funs`` must be serial: the groups
    are the parallel work.  For the engine's right-hand sides only (``args`` of 11 arrays,
    :func:`bearingsim.dynamics.forces.args_of`; the threaded kernel of :mod:`.specialised` passes it to
    :func:`.ros34pw2.integrate`): the tuples are unpacked outside the loop, since a parallel loop's body takes
    arrays, not tuples of them, as arguments."""
    a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10 = args
    w00, w01, w02, w03, w04, w05, w06, w07, w08, w09, w010, w011, w012 = works[0]
    w10, w11, w12, w13, w14, w15, w16, w17, w18, w19, w110, w111, w112 = works[1]
    for g in prange(2):
        ag = (a0, a1, a2, a3, a4, a5, a6, a7, a8, a9, a10)
        # (one call site: the work tuple chosen by the index, so that the parallel region holds one copy of refine)
        wg = ((w00, w01, w02, w03, w04, w05, w06, w07, w08, w09, w010, w011, w012) if g == 0 else
              (w10, w11, w12, w13, w14, w15, w16, w17, w18, w19, w110, w111, w112))
        _refine_group(g, funm, ag, gmask, gact, gn, t, hh, y0, f0, y1, blk, jac, turn, atol, rtol, vec, hmg, h_min,
                      tab, wg, counts, dns, dst, yo, done)
        if g == 1 and over:
            funs(t1, y1, fnext, ag, mask, PHASE_OTHERS, swork)
