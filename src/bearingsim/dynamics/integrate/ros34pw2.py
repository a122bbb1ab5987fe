"""ROS34PW2: the third-order linearly implicit W-method of Rang & Angermann (BIT 45 (2005) 761,
Table 3), the default integrator with the lubricated traction kernel (``integrator = "auto"`` and
traction "slices"; DOPRI5 otherwise).

Four stages, order 3 as a W-method (any approximation of the Jacobian), embedded order 2, L-stable
for the exact Jacobian.  Hairer form: (I − γhJ) k_i = h f(t + α_i h, y + Σ_j a_ij k_j) + hJ Σ_j c_ij k_j, each stage
solved without a product with J (:func:`stages`).
J holds the per-ball blocks of ∂f/∂y (:func:`.jacobian.block_jac`) and — unless the inner ring is
held fixed or the coupling is switched off — the inner ring's own block and the ring–ball coupling
(:func:`.jacobian.ring_columns` from the balls' sweeps when the right-hand side records the balls' inner-ring
reactions, else :func:`.jacobian.ring_jac`; :func:`.jacobian.ring_rows`): the inner ring sliding against all its
balls is a stiff mode at low rolling speed (docs/dynamics.md).  W is then an arrowhead matrix solved
through the ring's Schur complement (:mod:`.linalg`).  The Jacobian is kept from one call to the next
(:func:`.base.ros34_workspace`, saved in checkpoints) and refreshed after two rejections in a row and every
``jac_every`` steps — or, with the workspace's record (the default), at the interval up to ``jac_every`` that the
run's cost per simulated time by the Jacobian's age says is cheapest (:func:`.jacobian.refresh_interval`): a
W-method keeps its order with a lagged Jacobian, but how far the step falls as J ages depends on the problem.
Step size: PI controller (Gustafsson 1991) with exponents 0.7/3 and 0.4/3 and growth ≤ 2 after an accepted step —
a growth by at most 1.2 keeps the step and W instead (RADAU5's rule, ``R34_HOLD``) — and h·max(0.2, 0.9 err^(−1/3))
after a rejected one.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ..layout import MEMO_INNER, MEMO_W, MR_DERIVE, N_BALL, PHASE_REST
from .base import INFO_SIZE, Workspace, ros34_workspace
from .common import (
    DST_MR,
    DST_NODES,
    GROUPS,
    MAX_STEPS,
    NO_DENSE,
    NO_DENSE_STATE,
    NO_VECTORS,
    NOT_FINITE,
    OK,
    STEP_TOO_SMALL,
    Status,
    clip_step,
    error_norm_parts,
    error_scale,
    no_masked,
    no_split,
    node_row,
    node_time,
    pi_factor,
    reject_factor,
)
from .jacobian import (
    block_jac,
    no_record,
    record_at,
    record_attempt,
    refresh_interval,
    ring_columns,
    ring_jac,
    ring_rows,
)
from .linalg import NR, coupled_w, coupled_w_threaded, no_coupling, orbit_reference, orbit_turn, turned_solve, w_inverse
from .multirate import COOL, refine_groups, refine_work, select, split_groups

# ROS34PW2 (Rang & Angermann, BIT 45 (2005) 761, Table 3)
R34_G = 0.435866521508459
R34_A21 = 0.87173304301691801
R34_A31, R34_A32 = 0.84457060015369423, -0.11299064236484185
R34_A41, R34_A42, R34_A43 = 0.0, 0.0, 1.0
R34_C21 = -0.87173304301691801
R34_C31, R34_C32 = -0.90338057013044082, 0.054180672388095326
R34_C41, R34_C42, R34_C43 = 0.24212380706095346, -1.2232505839045147, 0.54526025533510214
R34_M = (0.24212380706095346, -1.2232505839045147, 1.5452602553351020, 0.43586652150845900)
R34_E = (0.37810903145819369, -0.096042292212423178, 0.5, 0.21793326075422950)
R34_ALPHA2 = R34_A21
R34_ALPHA3 = R34_A31 + R34_A32
R34_ALPHA4 = R34_A41 + R34_A42 + R34_A43
R34_GROW = 2.0  # largest step growth factor (fewer rejections than 5 on the contact problems)
R34_KI = 0.7 / 3.0  # PI controller exponents (Gustafsson: 0.7/(p+1), 0.4/(p+1), p = 2 the embedded order)
R34_KP = 0.4 / 3.0
R34_REJECT_EXPONENT = 1.0 / 3.0
#: a proposed growth of the step by a factor in [1, R34_HOLD] keeps the step instead, so that W = I − γhJ is not
#: formed again (RADAU5's quot1 = 1, quot2 = 1.2: Hairer & Wanner, *Solving ODEs II*, 2nd ed. 1996, §IV.8 and the
#: code's documentation).  Hub (b) 0.1 s, five tolerances: W factorisations −36 %, rejections −27 %, steps +1.5 %,
#: CPU −2.8 %; at 10 km/h (17 tolerances) right-hand sides −12 %, CPU −13 %, and no run in the heavy tail of
#: 54,000+ steps (6 of 17 without); 1.3 and 1.5 do worse
R34_HOLD = 1.2


@njit
def stages(fun, args, t, y, hs, f0, winv, blk, nbk, k1, k2, k3, k4, yt, ft, tv, cpl, turn):
    """The four stages of ROS34PW2 (k_i include the factor h); f0 = f(t, y); ``cpl`` = (J_rr, J_br,
    J_rb, Q, S⁻¹, work, work) of the ring–ball coupling (:func:`.linalg.coupled_w`) or
    :func:`.linalg.no_coupling`; ``turn`` the balls' azimuth changes since the Jacobian's refresh
    (:func:`.linalg.orbit_turn`; no rows: J as made), with which W is used turned (:func:`.linalg.turned_solve`).

    The stage equation W k_i = h f(Y_i) + hJ s_i, s_i = Σ_j c_ij k_j, is solved without the product J s_i:
    hJ = (I − W)/γ for the same J that W = I − γhJ is made of, so k_i = W⁻¹(h f(Y_i) + s_i/γ) − s_i/γ (the form
    of Hairer & Wanner, *Solving ODEs II*, §IV.7 — its implementation with u_i = Σ_j γ_ij k_j — written for the
    untransformed k_i; three products with the coupled J per step saved; W must be made of the Jacobian
    the step uses, as :func:`integrate` makes it after every refresh)."""
    n = y.shape[0]
    ig = 1.0 / R34_G
    for i in range(n):
        ft[i] = hs * f0[i]
    turned_solve(winv, blk, nbk, hs, R34_G, cpl, ft, k1, turn)
    # stage 2
    for i in range(n):
        yt[i] = y[i] + R34_A21 * k1[i]
        tv[i] = ig * (R34_C21 * k1[i])
    fun(t + R34_ALPHA2 * hs, yt, ft, args)
    for i in range(n):
        ft[i] = hs * ft[i] + tv[i]
    turned_solve(winv, blk, nbk, hs, R34_G, cpl, ft, k2, turn)
    for i in range(n):
        k2[i] -= tv[i]
    # stage 3
    for i in range(n):
        yt[i] = y[i] + R34_A31 * k1[i] + R34_A32 * k2[i]
        tv[i] = ig * (R34_C31 * k1[i] + R34_C32 * k2[i])
    fun(t + R34_ALPHA3 * hs, yt, ft, args)
    for i in range(n):
        ft[i] = hs * ft[i] + tv[i]
    turned_solve(winv, blk, nbk, hs, R34_G, cpl, ft, k3, turn)
    for i in range(n):
        k3[i] -= tv[i]
    # stage 4
    for i in range(n):
        yt[i] = y[i] + R34_A41 * k1[i] + R34_A42 * k2[i] + R34_A43 * k3[i]
        tv[i] = ig * (R34_C41 * k1[i] + R34_C42 * k2[i] + R34_C43 * k3[i])
    fun(t + R34_ALPHA4 * hs, yt, ft, args)
    for i in range(n):
        ft[i] = hs * ft[i] + tv[i]
    turned_solve(winv, blk, nbk, hs, R34_G, cpl, ft, k4, turn)
    for i in range(n):
        k4[i] -= tv[i]


@njit
def integrate(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, ws,
              rmass=np.zeros(0), bmass=np.zeros((0, 2)), stats=np.zeros(0), threaded=False, vec=NO_VECTORS,
              dns=NO_DENSE, dst=NO_DENSE_STATE, rec=np.zeros((0, MEMO_W)), funm=no_masked, mr=0, funs=no_split,
              swork=np.zeros(0), fung=refine_groups):
    """ROS34PW2 from t to t_end in place (module docstring).

    ``blk``, ``nbk``: the per-ball Jacobian blocks (start indices, states each); ``ws``
    (:func:`.base.ros34_workspace`) carries the Jacobian and the steps since its refresh from one call
    to the next; with ``rmass`` = (m, m, m, I_t, I_t) of the inner ring (the first 10 states) and
    ``bmass`` (m, J) per ball block, J also holds the ring's block and the ring–ball coupling.
    4 right-hand sides per step.  Same other arguments and return values as :func:`.dopri5.integrate`; when
    ``info`` has INFO_SIZE = 7 entries, info[4:7] ← the right-hand sides evaluated, the W factorisations and the
    Jacobian refreshes of the call (exact counts: the cost model of ``benchmarks/bench_dynamics.py --kernel``).
    ``stats`` (profiling: ``benchmarks/bench_dynamics.py --steps``): when it holds 2n floats, every attempted
    step adds each component's squared scaled error to stats[i] and 1 to stats[n + i] of its largest component
    (the results do not change).  ``threaded``: W's ball blocks formed on ``numba.get_num_threads()`` threads
    (:func:`.linalg.coupled_w_threaded`, the same result bit for bit; 33 µs per step size serially on the hub
    case).  ``vec``: the vectors the relative tolerances are measured on (:func:`.common.error_scale`).

    Dense output (``dns`` float[3, n], ``dst`` float[4]; :func:`.common.dense_arrays`): the steps are not clipped at
    t_end; the call returns at the first step that reaches or passes it, with t ≥ t_end, and leaves the last step's
    start (t₀ in dst[0], y₀ and f(t₀, y₀) in dns[0], dns[1]) and f at the state reached (dns[2]) for the Hermite
    interpolant of :func:`.common.hermite_one`.  The controller's memory (err_prev, a rejection just before) and f at
    the state reached are carried from one call to the next in ``dst``, so that the steps do not depend on where the
    calls stop: the trajectory is the same for any output interval (a checkpoint saves these arrays too).
    Without them (no columns): every call stops exactly at t_end and starts its controller afresh.

    ``rec``: the memo that ``fun`` fills (``args``' own array, :func:`bearingsim.dynamics.forces.record_reactions`)
    with n_balls + 1 rows: the ring's Jacobian columns are then derived from the balls' sweeps
    (:func:`.jacobian.ring_columns`: a refresh costs 9 right-hand sides, 10 when the last evaluation was not at
    (t, y) and the record must be made there first, :func:`.jacobian.record_at`; instead of 9 + 10 with ≈ 0.58
    each), unless the record's ring row says the model does not allow it.

    ``funs`` and ``swork`` (the engine's :func:`bearingsim.dynamics.forces.rhs_split` and its
    :func:`~bearingsim.dynamics.forces.split_work`; none: f is evaluated whole): at a refined step (``mr`` > 0) f at
    its end is made in two parts, the raceway contacts of the balls not refined beside the refinement's groups
    (``fung``: :func:`.multirate.refine_groups`, or :func:`.multirate.refine_groups_threaded` from the threaded
    engine's kernel), the rest once the step is accepted — the same f bit for bit.

    ``funm``, ``mr``: the multirate refinement (:mod:`.multirate`): with mr > 0 and the balls' layout
    (nbk = 9) each step refines up to mr balls whose own errors are too large with micro steps of their own, ``funm``
    being the right-hand side of those balls alone (:func:`bearingsim.dynamics.forces.rhs_masked`, signature
    (t, y, dy, args, active)); the step's error for the controller is then that of the other states.  info[7:10] ←
    the masked right-hand sides, the balls refined and the steps refined.  mr = 0 (the default, and
    :func:`.common.no_masked`): the plain method.
    """
    n = y.shape[0]
    nb = blk.shape[0]
    jac, jrr, jbr, jrb, jst, jmem, jaz = ws
    winv = np.zeros((nb, nbk, nbk))
    wm = np.zeros((nbk, nbk))
    f0 = np.empty(n)
    f1 = np.empty(n)
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    yt = np.empty(n)
    ft = np.empty(n)
    tv = np.empty(n)
    ynew = np.empty(n)
    evec = np.empty(n)
    epsb = np.empty(nb)
    coupled = rmass.shape[0] == 5
    nc = nb if coupled else 0
    qm = np.zeros((nc, nbk, NR))
    sinv = np.zeros((NR, NR))
    srr = np.zeros((NR, NR))
    sb = np.zeros((nc, NR, NR))
    wmb = np.zeros((nc if threaded else 0, nbk, nbk))
    zb = np.zeros((nc, nbk))
    rr = np.zeros(NR)
    # the coupling's arrays, or empty ones (then W and J are the per-ball blocks alone)
    cpl = (jrr, jbr, jrb, qm, sinv, zb, rr) if coupled else no_coupling(nbk)
    # the turn needs the balls' layout (r, v, ω from blk[b]): other blocks use J as made
    turn = np.zeros((jaz.shape[0] if jaz.shape[0] == nb and nbk == N_BALL else 0, 2))
    rbase = np.zeros((nb + 1, 6))  # the record at y (:func:`.jacobian.ring_columns`)
    drec = np.zeros((nb, nbk, 6))
    # the multirate refinement (:mod:`.multirate`): up to mr balls per step, on the balls' layout
    mr_on = mr > 0 and nbk == N_BALL
    nmr = mr if mr_on else 0
    mrw = (refine_work(n if mr_on else 0, nmr), refine_work(n if mr_on else 0, nmr))  # (one per group)
    r2 = np.empty(n if mr_on else 0)
    sbl = np.empty(nb if mr_on else 0)
    mask = np.zeros(nb if mr_on else 0, np.int8)
    rank = np.zeros(nmr, np.int64)
    gmask = np.zeros((GROUPS, nb if mr_on else 0), np.int8)
    gact = np.zeros((GROUPS, nmr), np.int64)
    gn = np.zeros(GROUPS, np.int64)
    gdone = np.zeros(GROUPS, np.int64)
    yo = np.empty(n if mr_on else 0)
    counts = np.zeros(GROUPS)  # masked right-hand sides per group (:func:`.multirate.refine`)
    # f at a refined step's end in two parts, the first beside the refinement (``funs``: forces.rhs_split)
    over = mr_on and swork.shape[0] > 0
    fnext = np.empty(n if over else 0)
    tab = np.array([R34_A21, R34_A31, R34_A32, R34_A41, R34_A42, R34_A43, R34_ALPHA2, R34_ALPHA3, R34_ALPHA4,
                    R34_C21, R34_C31, R34_C32, R34_C41, R34_C42, R34_C43, R34_M[0], R34_M[1], R34_M[2], R34_M[3],
                    R34_E[0], R34_E[1], R34_E[2], R34_E[3], R34_G])
    no_nodes = np.zeros((0, n))
    hmg = np.full(GROUPS, h)  # each group's next micro step
    cool = 0
    nref = 0
    nball = 0
    if dns.shape[1] == n and dst.shape[0] > DST_MR + GROUPS and dst[DST_MR] > 0.0:
        for g in range(GROUPS):
            hmg[g] = dst[DST_MR + g]
        cool = int(dst[DST_MR + GROUPS])
    need_jac = jst[1] == 0
    since = jst[0]
    adaptive = jmem.shape[0] > 0  # the refresh interval from the run's record (:func:`.jacobian.refresh_interval`)
    interval = jac_every
    if adaptive and jmem[0] > 0.0:
        interval = min(int(jmem[0]), jac_every)
    h_w = -1.0
    nacc = 0
    nrej = 0
    nfun = 0  # right-hand sides evaluated, W factorisations, Jacobian refreshes (info[4:7])
    nfac = 0
    njac = 0
    status = OK
    have_f0 = False
    prev_rej = False
    err_prev = 1.0
    dense = dns.shape[1] == n
    if dense:
        # the controller's memory and f at the current state, carried from the previous call
        err_prev = dst[1]
        prev_rej = dst[2] > 0.0
        if dst[3] > 0.0:
            for i in range(n):
                f0[i] = dns[2, i]
            have_f0 = True
    while t < t_end:
        if nacc + nrej >= max_steps:
            status = MAX_STEPS
            break
        if dense:
            hs, last = h, False
        else:
            hs, last = clip_step(t, h, t_end)
        if not have_f0:
            fun(t, y, f0, args)
            nfun += 1
            have_f0 = True
        if need_jac or since >= interval:
            derive = False
            if coupled and rec.shape[0] > nb:
                if not record_at(rec, blk, t, y):  # e.g. after a rejection (the stages evaluated since f(t, y))
                    fun(t, y, f1, args)
                    nfun += 1
                derive = rec[nb, MR_DERIVE] == 1.0
            if derive:
                for b in range(nb + 1):
                    for i in range(6):
                        rbase[b, i] = rec[b, MEMO_INNER + i] if b < nb else rec[nb, i]
                block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb, rec, rbase, drec)
                ring_columns(y, blk, rbase, drec, rmass, bmass, jrr, jbr)
                ring_rows(jbr, rmass, bmass, jrb)
            else:
                # the ring's columns first: their sweeps leave the balls where f0 put them, so the engine's
                # right-hand side takes every outer contact from its memo (forces.outer_memo_hit) — after the ball
                # sweeps the memo would hold perturbed balls and the first ring sweep would miss
                if coupled:
                    ring_jac(fun, args, t, y, f0, atol, blk, nbk, jrr, jbr, yt, f1)
                    ring_rows(jbr, rmass, bmass, jrb)
                    nfun += NR
                e1, e2, e3 = no_record()
                block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb, e1, e2, e3)
            nfun += nbk
            njac += 1
            need_jac = False
            since = 0
            h_w = -1.0
            if adaptive:
                interval = refresh_interval(jmem, jac_every, nbk if derive else nbk + NR)
            if turn.shape[0] > 0:
                orbit_reference(y, blk, jaz)
        if turn.shape[0] > 0:
            orbit_turn(y, blk, jaz, turn)
        if hs != h_w:
            if coupled:
                if threaded:
                    coupled_w_threaded(jac, jrr, jbr, jrb, hs, R34_G, winv, wmb, qm, sinv, srr, sb)
                else:
                    coupled_w(jac, jrr, jbr, jrb, hs, R34_G, winv, wm, qm, sinv, srr, sb)
            else:
                w_inverse(jac, hs, R34_G, winv, wm)
            h_w = hs
            nfac += 1
        stages(fun, args, t, y, hs, f0, winv, blk, nbk, k1, k2, k3, k4, yt, ft, tv, cpl, turn)
        nfun += 3
        for i in range(n):
            ynew[i] = y[i] + R34_M[0] * k1[i] + R34_M[1] * k2[i] + R34_M[2] * k3[i] + R34_M[3] * k4[i]
            evec[i] = ((R34_M[0] - R34_E[0]) * k1[i] + (R34_M[1] - R34_E[1]) * k2[i]
                       + (R34_M[2] - R34_E[2]) * k3[i] + (R34_M[3] - R34_E[3]) * k4[i])
        err, finite = error_norm_parts(evec, y, ynew, atol, rtol, info, vec, r2)
        masked0 = counts.sum()
        nact = 0
        part = False  # f at the step's end begun beside the refinement (its PHASE_OTHERS part in fnext)
        if dense and dst.shape[0] > DST_NODES + GROUPS:
            for g in range(GROUPS):
                dst[DST_NODES + g] = 0.0
        if mr_on and finite:
            if cool > 0:
                cool -= 1
            else:
                nact, rem = select(r2, blk, nbk, nmr, sbl, mask, rank)
                err_l = np.sqrt(rem / n)
                if nact > 0 and err_l <= 1.0:
                    tn = t_end if last else t + hs
                    split_groups(rank, nact, nb, gmask, gact, gn)
                    keep = dense and t + hs >= t_end
                    dkeep = dns if keep else no_nodes
                    if keep:
                        for i in range(n):
                            dns[3, i] = 0.0
                    # the groups one after the other, or on two threads (fung: multirate.refine_groups_threaded from
                    # the threaded engine's kernel; bit for bit the same: they read y, f0, ynew and write disjoint
                    # parts of yo, dns, dst)
                    fung(funm, args, gmask, gact, gn, t, hs, y, f0, ynew, blk, jac, turn, atol, rtol, vec, hmg,
                         h_min, tab, mrw, counts, dkeep, dst, yo, gdone, funs, over, tn, fnext, swork, mask)
                    part = over
                    if gdone.min() == 1:
                        for a in range(nact):
                            o = blk[rank[a]]
                            for i in range(nbk):
                                ynew[o + i] = yo[o + i]
                        err = err_l
                        nref += 1
                        nball += nact
                    else:  # given up: the large step as it is (accepted if its own error allows), no refinement
                        cool = COOL
                        nact = 0
                        if dense and dst.shape[0] > DST_NODES + GROUPS:
                            for g in range(GROUPS):
                                dst[DST_NODES + g] = 0.0
                elif nact > 0:
                    err = err_l  # rejected: the next step is sized for the other states
        if stats.shape[0] == 2 * n:
            for i in range(n):
                r = evec[i] / error_scale(i, y, ynew, atol, rtol, vec)
                stats[i] += r * r
            stats[n + int(info[2])] += 1.0
        if adaptive:  # (an accepted step also pays the next f(t, y))
            record_attempt(jmem, since, (4.0 if err <= 1.0 else 3.0) + (counts.sum() - masked0) * (nact + 1.0) / nb,
                           hs if err <= 1.0 else 0.0)
        if err <= 1.0:
            if dense:
                dst[0] = t  # the step's start for the interpolant
                for i in range(n):
                    dns[0, i] = y[i]
                    dns[1, i] = f0[i]
            have_f0 = False
            if part:  # f at the new state: the part not begun beside the refinement (its balls, cages, rings)
                funs(t_end if last else t + hs, ynew, fnext, args, mask, PHASE_REST, swork)
                nfun += 1
                for i in range(n):
                    f0[i] = fnext[i]
                have_f0 = True
            for i in range(n):
                y[i] = ynew[i]
            t = t_end if last else t + hs
            prev_rej = False
            nacc += 1
            since += 1
            fac, err_prev = pi_factor(err, err_prev, R34_KI, R34_KP, R34_GROW)
            if 1.0 <= fac <= R34_HOLD:
                fac = 1.0  # keep the step and W (R34_HOLD)
            if not (last and hs < h):
                h = hs * fac
        else:
            nrej += 1
            # a W-method keeps its order with a lagged Jacobian: refresh it only when a
            # step is rejected twice in a row (the Jacobian may then limit stability)
            if prev_rej:
                need_jac = True
            prev_rej = True
            h = hs * reject_factor(err, R34_REJECT_EXPONENT)
            if h < h_min:
                status = STEP_TOO_SMALL if finite else NOT_FINITE
                break
    jst[0] = since
    jst[1] = 0 if need_jac else 1
    if dense:
        if status == OK and not have_f0:
            fun(t, y, f0, args)  # (the next step's f0: computed once, carried in dns[2])
            nfun += 1
            have_f0 = True
        if have_f0:
            for i in range(n):
                dns[2, i] = f0[i]
        if dst.shape[0] > DST_MR + GROUPS:
            for g in range(GROUPS):
                nodes = int(dst[DST_NODES + g])
                if nodes > 0 and have_f0 and nacc > 0:  # the group's end node: the state reached and f there
                    dst[node_time(g, nodes)] = t
                    r = node_row(g, nodes)
                    for i in range(n):
                        dns[r, i] = y[i]
                        dns[r + 1, i] = f0[i]
                    dst[DST_NODES + g] = nodes + 1.0
                dst[DST_MR + g] = hmg[g]
            dst[DST_MR + GROUPS] = float(cool)
        dst[1] = err_prev
        dst[2] = 1.0 if prev_rej else 0.0
        dst[3] = 1.0 if have_f0 else 0.0
    info[0] = nacc
    info[1] = nrej
    if info.shape[0] >= INFO_SIZE:
        info[4] = nfun
        info[5] = nfac
        info[6] = njac
        info[7] = counts.sum()
        info[8] = nball
        info[9] = nref
    return status, t, h


@njit
def fixed_steps(fun, args, t, y, h, nsteps, blk, nbk):
    """``nsteps`` ROS34PW2 steps of constant size h with the block Jacobian refreshed every
    step (no error control) — for order tests.  ``nbk`` = 0 gives J = 0 (the W-method then
    is an explicit 4-stage Runge–Kutta method of order 3)."""
    n = y.shape[0]
    nb = blk.shape[0] if nbk > 0 else 0
    nk = max(nbk, 1)
    jac = np.zeros((nb, nk, nk))
    winv = np.zeros((nb, nk, nk))
    wm = np.zeros((nk, nk))
    bl = blk[:nb]
    cpl = no_coupling(nk)
    f0 = np.empty(n)
    f1 = np.empty(n)
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    yt = np.empty(n)
    ft = np.empty(n)
    tv = np.empty(n)
    epsb = np.empty(max(nb, 1))
    atol = np.full(n, 1e-12)
    for _ in range(nsteps):
        fun(t, y, f0, args)
        if nb > 0:
            e1, e2, e3 = no_record()
            block_jac(fun, args, t, y, f0, atol, bl, nk, jac, yt, f1, epsb, e1, e2, e3)
            w_inverse(jac, h, R34_G, winv, wm)
        stages(fun, args, t, y, h, f0, winv, bl, nk, k1, k2, k3, k4, yt, ft, tv, cpl, np.zeros((0, 2)))
        for i in range(n):
            y[i] = y[i] + R34_M[0] * k1[i] + R34_M[1] * k2[i] + R34_M[2] * k3[i] + R34_M[3] * k4[i]
        t += h
    return t


def advance(ws: Workspace, t_end: float) -> Status:
    """Integrate the workspace to t_end [s] with ROS34PW2 (the contract of :mod:`.base`); the Jacobian
    lives in ``ws.jacobian`` (made here on first use).  The engine's right-hand sides run the cached kernel of
    :mod:`.specialised` (the same code).  With ``ws.dense`` (:func:`.common.dense_arrays`) the call stops at the
    first step at or past t_end (dense output, :func:`integrate`)."""
    if ws.jacobian is None:
        ws.jacobian = ros34_workspace(ws.blk.shape[0], ws.nbk, ws.rmass.shape[0] == 5)
    dns, dst = ws.dense if ws.dense is not None else (NO_DENSE, NO_DENSE_STATE)
    kernel = ws.kernel
    if kernel is not None:
        status, t, h = kernel(ws.args, ws.t, float(t_end), ws.y, ws.h, ws.atol, ws.rtol, ws.h_min, ws.max_steps,
                              ws.info, ws.blk, ws.nbk, ws.jac_every, ws.jacobian, ws.rmass, ws.bmass, ws.vec, dns, dst,
                              ws.multirate)
    else:
        status, t, h = integrate(ws.fun, ws.args, ws.t, float(t_end), ws.y, ws.h, ws.atol, ws.rtol, ws.h_min,
                                 ws.max_steps, ws.info, ws.blk, ws.nbk, ws.jac_every, ws.jacobian, ws.rmass,
                                 ws.bmass, vec=ws.vec, dns=dns, dst=dst)
    return ws.finish(status, t, h)
