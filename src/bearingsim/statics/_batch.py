"""Batch quasi-static solver over many operating points (numba), with warm starts.

The model is the Jones–Harris ring equilibrium of :func:`bearingsim.statics._kernels.solve_ring`
(equations in that module's docstring).  This module only loops over operating points inside
one compiled function: each point starts from the previous point's ring displacement, ball
positions and raceway-control state (a continuation along the grid), and falls back to a cold
start when the warm one fails.  It returns summaries per point, not per-ball tables.

Summary arrays (n = number of points):
    q [n, 5]  displacement (δx, δy, δz, γy, γz) [m, rad]
    k [n, 5, 5]  stiffness [N/m, N/rad, N·m/m, N·m/rad]
    status [n]  status code (:data:`bearingsim.statics.layout.STATUS`, the one table of codes)
    iterations [n], residual [n] [N]
    p_inner, p_outer [n]  maximum contact pressure [Pa]
    alpha_inner_min/max, alpha_outer_min/max [n]  contact angles of the loaded balls [rad]
    n_lift_off [n]  balls without load at the inner raceway while others carry load
    warning_flags [n]  int32 bitmask of :mod:`bearingsim.limits` (pressure, contact angle, speed, lift-off
                at speed, not converged)
Status codes: the keys of :data:`bearingsim.statics.layout.STATUS` (0 converged; 1 iteration limit; 2 singular;
3 contact past the groove bottom; 4 a ball's own balance failed; 5 not confirmed by the independent
recomputation; 6 contact at 90° or more; 7 internal error of this point; 8 free ring).  Public entry:
:mod:`bearingsim.statics.batch`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..contact.hertz import max_pressure_from_load
from . import _kernels as kn

SUMMARY_FIELDS = ("p_inner", "p_outer", "alpha_inner_min", "alpha_inner_max", "alpha_outer_min", "alpha_outer_max",
                  "n_lift_off")
NSUMMARY = len(SUMMARY_FIELDS)


@njit(cache=True, error_model="numpy")
def _scale(loads, dm):
    s = 1.0
    for k in range(3):
        s = max(s, abs(loads[k]))
    for k in range(3, 5):
        s = max(s, 2.0 * abs(loads[k]) / dm)
    return s


@njit(cache=True, error_model="numpy")
def _contact_extremes(ballout, r, z, iq, isin, icos, acc):
    """Largest load and contact-angle extremes of one contact type of row r, merged into acc.

    acc float[3] = (largest load [N], smallest angle [rad], largest angle [rad]); columns iq, isin, icos
    of ``ballout`` hold the load and sin α, cos α.  The angles atan2(sin α, cos α) are taken only at the
    balls of extreme tan α when cos α > 0 (atan2 of the ball otherwise): a few atan2 per row, the same numbers.
    """
    j_lo = -1
    j_hi = -1
    t_lo = 0.0
    t_hi = 0.0
    for j in range(z):
        bo = ballout[r, j]
        if not bo[iq] > 0.0:
            continue
        acc[0] = max(acc[0], bo[iq])
        if bo[icos] > 0.0:
            t = bo[isin] / bo[icos]
            if j_lo < 0 or t < t_lo:
                t_lo = t
                j_lo = j
            if j_hi < 0 or t > t_hi:
                t_hi = t
                j_hi = j
        else:
            a = math.atan2(bo[isin], bo[icos])
            acc[1] = min(acc[1], a)
            acc[2] = max(acc[2], a)
    if j_lo >= 0:
        acc[1] = min(acc[1], math.atan2(ballout[r, j_lo, isin], ballout[r, j_lo, icos]))
        acc[2] = max(acc[2], math.atan2(ballout[r, j_hi, isin], ballout[r, j_hi, icos]))


@njit(cache=True, error_model="numpy")
def _free_ring(rows, ballout, tol):
    """True when no ball carries more than tol [N] at the inner raceway."""
    for r in range(rows.shape[0]):
        for j in range(int(rows[r, kn.P_Z])):
            if ballout[r, j, 2] > tol:
                return False
    return True


@njit(cache=True, error_model="numpy")
def _summarise(rows, ballout, out):
    """Max pressures and contact-angle extremes of the loaded balls → out[0:6] (p_max = C_p Q^(1/3) at the
    largest load of each row; angles by :func:`_contact_extremes`), out[6] ← number of balls without load
    at the inner raceway while others carry load (0 when none carries load)."""
    inner = np.empty(3)
    outer = np.empty(3)
    pi_max = 0.0
    po_max = 0.0
    inner[1] = outer[1] = 1e9
    inner[2] = outer[2] = -1e9
    for r in range(rows.shape[0]):
        par = rows[r]
        z = int(par[kn.P_Z])
        inner[0] = 0.0
        outer[0] = 0.0
        _contact_extremes(ballout, r, z, 2, 8, 9, inner)
        _contact_extremes(ballout, r, z, 3, 10, 11, outer)
        if inner[0] > 0.0:
            pi_max = max(pi_max, max_pressure_from_load(par[kn.P_CPI], inner[0]))
        if outer[0] > 0.0:
            po_max = max(po_max, max_pressure_from_load(par[kn.P_CPO], outer[0]))
    out[0] = pi_max
    out[1] = po_max
    out[2], out[3] = (inner[1], inner[2]) if inner[1] <= inner[2] else (math.nan, math.nan)
    out[4], out[5] = (outer[1], outer[2]) if outer[1] <= outer[2] else (math.nan, math.nan)
    # balls without load at the inner raceway while others carry load (lift-off count)
    nfree = 0
    nload = 0
    for r in range(rows.shape[0]):
        for j in range(int(rows[r, kn.P_Z])):
            if ballout[r, j, 2] > 0.0:
                nload += 1
            else:
                nfree += 1
    out[6] = nfree if nload > 0 else 0.0


@njit(cache=True, nogil=True, error_model="numpy")
def solve_batch(rows, loads, omega, control, q_cold, q_out, k_out, status, iters, resid, summ,
                tol_ball, tol_ring, maxit_ball, maxit_ring, predictor, tol_verify):
    """Solve every operating point i (loads[i], omega[i]) in order, warm-starting from point i−1;
    a point that hits the iteration limit or a singular stiffness is retried from ``q_cold``.

    Start of point i (``predictor``): q_{i−1} + K_{i−1}⁻¹ ΔF (tangent step, used when it moves the ring
    by less than 0.2 of the groove-centre distance), plus, when the step (ΔF, Δω) repeats the previous
    one (grid rows), the previous point's deviation from its own tangent prediction.  Ball positions
    start from X + dX/dA ΔA (tangents kept in ``xb``, see :func:`_kernels.ring_assemble`).  Points with
    status 3 (a converged equilibrium outside the model) are valid starts for the next point.  The
    start only changes the path: every point is converged to the same tolerances.  Each point is solved
    by :func:`_kernels.solve_ring_coupled` (Newton on the ring and ball unknowns together, one ball
    evaluation per iteration, :func:`_kernels.solve_ring` as its safeguard); ``iters`` counts the
    iterations of both.

    rows : float[nrow, NPAR]; loads : float[n, 5] [N, N·m]; omega : float[n] [rad/s]
    control : kernel control code; q_cold : float[5] cold start [m, rad]
    tol_verify : a converged point must pass :func:`_kernels.equilibrium_residual` within tol_verify × load
    scale (else one restart with fresh balls, then status 5); a converged point where no ball carries load
    at the inner raceway gets status 8 (the ring is free); a deep-groove point whose warm and cold starts
    fail is tried from the planar rigid-ring start (:func:`_kernels.planar_radial_start`).
    Outputs (filled): q_out[n, 5], k_out[n, 5, 5], status[n], iters[n], resid[n], summ[n, NSUMMARY].
    """
    n = loads.shape[0]
    nrow = rows.shape[0]
    zmax = 0
    for r in range(nrow):
        zmax = max(zmax, int(rows[r, kn.P_Z]))
    dm = rows[0, kn.P_DM]
    lam0 = 1 if control == kn.CONTROL_INNER else 0
    lam = np.full((nrow, zmax), lam0, dtype=np.int64)
    xb = np.zeros((nrow, zmax, 8))  # positions and their tangents (ring_assemble's warm start)
    xs = np.zeros((nrow, zmax, 8))  # workspaces of solve_ring_coupled (no allocation per point)
    wk = np.zeros(64)
    wk2 = np.zeros(96)
    trig = np.zeros((nrow, zmax, 2))  # ball azimuths, once per batch
    kn.azimuth_table(rows, trig)
    kmat = np.zeros((5, 5))
    ballout = np.zeros((nrow, zmax, 12))
    q = q_cold.copy()
    qtry = np.empty(5)
    sm = np.empty(summ.shape[1])
    kprev = np.zeros((5, 5))
    lprev = np.zeros(5)
    have_prev = False
    dl = np.empty(5)
    dlnow = np.empty(5)
    dlprev = np.empty(5)
    qtan = np.empty(5)
    errprev = np.zeros(5)
    have_err = False
    wprev = -1.0
    dwprev = 0.0
    dq = np.empty(5)
    wsol = np.empty((5, 6))
    amax = 0.0
    for r in range(nrow):
        amax = max(amax, rows[r, kn.P_RI] + rows[r, kn.P_RO])
    for i in range(n):
        ld = loads[i]
        sc = _scale(ld, dm)
        for k in range(5):
            qtry[k] = q[k]
        tangent = False
        if predictor and have_prev:
            # tangent predictor: q + K⁻¹ ΔF from the previous converged point (continuation)
            ok = True
            for k in range(5):
                if not (kprev[k, k] > 0.0):
                    ok = False
            if ok:
                for k in range(5):
                    dl[k] = ld[k] - lprev[k]
                if not kn.solve_small(kprev, dl, dq, wsol):
                    ok = False  # singular tangent: start from the previous solution itself
            if ok:
                smax = 0.0
                for k in range(5):
                    v = abs(dq[k]) * (1.0 if k < 3 else 0.5 * dm)
                    if v > smax or v != v:
                        smax = v  # NaN-propagating max: a NaN tangent step is never taken
                if smax < 0.2 * amax:
                    # correction on a uniform path (grid rows): when the step in (F, ω) repeats,
                    # the last point's deviation from its tangent prediction (the speed effect,
                    # O(Δω), and the curvature, O(h²)) repeats too
                    dw = omega[i] - wprev
                    same = have_err and abs(dw - dwprev) <= 1e-9 * abs(dw)
                    if same:
                        dd = 0.0
                        dn = 0.0
                        for k in range(5):
                            dd = max(dd, abs(dl[k] - dlprev[k]))
                            dn = max(dn, abs(dl[k]))
                        same = dd <= 1e-9 * dn
                    for k in range(5):
                        qtry[k] += dq[k]
                        qtan[k] = qtry[k]
                        if same:
                            qtry[k] += errprev[k]
                    tangent = True
                    for k in range(5):
                        dlnow[k] = dl[k]
        st, it, rn, bconv = kn.solve_ring_coupled(rows, ld, omega[i], control, qtry, lam, xb, kmat, ballout,
                                          tol_ball, tol_ring, maxit_ball, maxit_ring, sc, xs, wk, wk2, trig)
        tot = it
        if st == 1 or st == 2:
            # cold start
            for k in range(5):
                qtry[k] = q_cold[k]
            lam[:, :] = lam0
            xb[:, :, :] = 0.0
            st, it, rn, bconv = kn.solve_ring_coupled(rows, ld, omega[i], control, qtry, lam, xb, kmat, ballout,
                                              tol_ball, tol_ring, maxit_ball, maxit_ring, sc, xs, wk, wk2, trig)
            tot += it
        if (st == 1 or st == 2) and ld[0] == 0.0:
            # a deep-groove row under radial load: the planar rigid-ring start of this point (the cold start
            # of another point may sit inside the clearance, where no ball is loaded)
            for k in range(5):
                qtry[k] = 0.0
            if kn.planar_radial_start(rows, ld, qtry):
                lam[:, :] = lam0
                xb[:, :, :] = 0.0
                st, it, rn, bconv = kn.solve_ring_coupled(rows, ld, omega[i], control, qtry, lam, xb, kmat, ballout,
                                                  tol_ball, tol_ring, maxit_ball, maxit_ring, sc, xs, wk, wk2,
                                                  trig)
                tot += it
        if st == 0 and bconv:
            # independent check: every ball re-solved from its own cold start at the returned displacement
            # (the warm-start chain can carry a ball into another branch of its own equilibrium)
            rv, vb = kn.equilibrium_residual(rows, ld, omega[i], control, qtry, tol_ball, maxit_ball)
            if not (vb and rv <= tol_verify * sc):
                lam[:, :] = lam0
                xb[:, :, :] = 0.0
                st, it, rn, bconv = kn.solve_ring(rows, ld, omega[i], control, qtry, lam, xb, kmat, ballout,
                                                  tol_ball, tol_ring, maxit_ball, maxit_ring, sc)
                tot += it
                if st == 0 and bconv:
                    rv, vb = kn.equilibrium_residual(rows, ld, omega[i], control, qtry, tol_ball, maxit_ball)
                    if not (vb and rv <= tol_verify * sc):
                        st = 5
                        rn = max(rn, rv)
        if st == 0 and not bconv:
            st = 4
        if (st == 0 or st == 3 or st == 6) and _free_ring(rows, ballout, tol_verify * sc):
            st = 8
        status[i] = st
        iters[i] = tot
        resid[i] = rn
        for k in range(5):
            q_out[i, k] = qtry[k]
            for m in range(5):
                k_out[i, k, m] = kmat[k, m]
        _summarise(rows, ballout, sm)
        for k in range(summ.shape[1]):
            summ[i, k] = sm[k]
        if st == 0 or st == 4 or st == 3 or st == 6:
            # the ring equilibrium is good (status 4: only an unloaded ball's own balance failed;
            # status 3 and 6: a converged equilibrium outside the model's validity, still a good start)
            for k in range(5):
                q[k] = qtry[k]
                lprev[k] = ld[k]
                for m in range(5):
                    kprev[k, m] = kmat[k, m]
            have_prev = True
            # error of the pure tangent prediction at this point (used by the next one)
            have_err = tangent and it == tot
            if have_err:
                for k in range(5):
                    errprev[k] = qtry[k] - qtan[k]
                    dlprev[k] = dlnow[k]
                dwprev = omega[i] - wprev
            wprev = omega[i]
        else:
            # do not continue from a failed point
            lam[:, :] = lam0
            xb[:, :, :] = 0.0
            have_prev = False
            have_err = False
    return 0


def order_points(loads: np.ndarray, omega: np.ndarray, bits: int = 5) -> np.ndarray:
    """A visiting order of scattered operating points that keeps neighbours close (Morton / Z-order
    curve over the normalised (loads, speed) space, ``bits`` per axis) → permutation indices."""
    x = np.column_stack([np.asarray(loads, dtype=float).reshape(-1, 5), np.asarray(omega, dtype=float)])
    lo = x.min(axis=0)
    span = x.max(axis=0) - lo
    z = ((x - lo) / np.where(span > 0, span, 1.0) * (2**bits - 1)).astype(np.int64)
    code = np.zeros(len(x), dtype=np.int64)
    for bit in range(bits - 1, -1, -1):
        for j in range(x.shape[1]):
            code = (code << 1) | ((z[:, j] >> bit) & 1)
    return np.argsort(code, kind="stable")


def run_batch(bearing, loads: np.ndarray, omega: np.ndarray, control: str = "outer",
              q_start: np.ndarray | None = None, reorder: bool = False, predictor: bool = True,
              fallback: bool = True) -> dict:
    """Solve many operating points of one bearing (or bearing system) in one compiled loop.

    Parameters
    ----------
    bearing : BallBearing or BearingSystem
    loads : float[n, 5]  (Fa, Fr_y, Fr_z, M_y, M_z) [N, N·m]; order the points so that neighbours are
        close (grid order) to profit from the warm starts
    omega : float[n]  inner-ring speed [rad/s]
    control : ``"outer"``, ``"inner"`` or ``"auto"``
    q_start : cold start [m, rad] (default: the bearing's initial guess for the first point)
    predictor : start each point from the previous solution plus the tangent step K⁻¹ ΔF
    reorder : visit scattered points along a Z-order curve (:func:`order_points`); results are
        returned in the caller's order
    fallback : points the loop does not converge are solved again by the single-point path
        (:func:`_fallback_points`)

    Returns a dict of arrays (see the module docstring).
    """
    from .jones_harris import (
        CONTROLS,
        MAXIT_BALL,
        MAXIT_RING,
        TOL_BALL,
        TOL_RING,
        TOL_VERIFY,
        Loads,
        initial_guess,
    )

    loads = np.ascontiguousarray(np.asarray(loads, dtype=float).reshape(-1, 5))
    n = loads.shape[0]
    loads_in = loads
    speeds = np.broadcast_to(np.asarray(omega, dtype=float), (n,)).copy()
    omega = np.ascontiguousarray(np.abs(speeds))
    rows = np.ascontiguousarray(bearing.row_vectors())
    perm = None
    if reorder and n > 1:
        perm = order_points(loads, omega)
        loads = np.ascontiguousarray(loads[perm])
        omega = np.ascontiguousarray(omega[perm])
    if q_start is None:
        q_start = initial_guess(bearing, Loads(*loads[0])) if n else np.zeros(5)
    out = {
        "q": np.zeros((n, 5)), "k": np.zeros((n, 5, 5)), "status": np.zeros(n, dtype=np.int64),
        "iterations": np.zeros(n, dtype=np.int64), "residual": np.zeros(n), "summary": np.zeros((n, NSUMMARY)),
    }
    if n:
        try:
            solve_batch(rows, loads, omega, CONTROLS[control], np.asarray(q_start, dtype=float), out["q"], out["k"],
                        out["status"], out["iterations"], out["residual"], out["summary"], TOL_BALL, TOL_RING,
                        MAXIT_BALL, MAXIT_RING, predictor, TOL_VERIFY)
        except Exception:  # noqa: BLE001  (one bad point must not lose the call: redo it point by point)
            out["status"][:] = -1 if fallback else 7
        if fallback:
            _fallback_points(bearing, rows, loads, omega, control, out)
    if perm is not None:
        for key in list(out):
            v = np.empty_like(out[key])
            v[perm] = out[key]
            out[key] = v
    out["converged"] = out["status"] == 0
    for j, name in enumerate(SUMMARY_FIELDS):
        out[name] = out["summary"][:, j]
    from ..limits import flags_from_summary, lift_off_count, limiting_speed

    lift = (out["n_lift_off"] > 0) & (speeds != 0)
    if lift.any():
        # lift-off only beyond the load zone of the same loads at rest (limits.lift_off_count; a partial load zone
        # at rest is no lift-off); a point whose rest equilibrium is not found is not flagged, as in solve
        idx = np.flatnonzero(lift)
        rest = run_batch(bearing, loads_in[idx], np.zeros(idx.size), control, fallback=False)
        lift[idx] = (lift_off_count(out["n_lift_off"][idx], rest["n_lift_off"]) > 0) & rest["converged"]
    out["warning_flags"] = flags_from_summary(out["p_inner"], out["p_outer"],
                                              [out[k] for k in SUMMARY_FIELDS[2:6]], speeds, lift, out["converged"],
                                              limiting_speed(bearing))
    return out


def _fallback_points(bearing, rows, loads, omega, control, out) -> None:
    """Points the compiled loop did not converge (any status but 0 and 8; or lost to an exception, status −1)
    are solved again by the single-point path :func:`bearingsim.statics.jones_harris.solve` (its own start and
    load continuation), so that the batch and the single path agree on convergence; a point that raises gets
    status 7."""
    from .jones_harris import Loads, solve

    bad = np.flatnonzero((out["status"] != 0) & (out["status"] != 8))
    summ = np.empty(NSUMMARY)
    for i in bad:
        try:
            r = solve(bearing, Loads(*loads[i]), float(omega[i]), control)
        except Exception:  # noqa: BLE001  (isolate the point; the others keep their results)
            out["status"][i] = 7
            out["q"][i] = np.nan
            out["k"][i] = np.nan
            out["residual"][i] = np.nan
            out["summary"][i] = np.nan
            continue
        if not r.converged and r.status_code in (3, 6, 9) and out["status"][i] >= 0:
            out["status"][i] = r.status_code  # the single path's reason (not enough axial load, past capacity)
        if r.converged or out["status"][i] < 0:
            out["status"][i] = r.status_code
            out["q"][i] = r.displacement
            out["k"][i] = r.stiffness
            out["iterations"][i] += r.iterations
            out["residual"][i] = r.residual
            zmax = int(rows[:, kn.P_Z].max())
            bo = np.zeros((rows.shape[0], zmax, 12))
            b = r.balls
            rr = b["row"].astype(int)
            jj = np.concatenate([np.arange(int(z)) for z in rows[:, kn.P_Z]])
            bo[rr, jj, 2] = b["inner_load_N"]
            bo[rr, jj, 3] = b["outer_load_N"]
            bo[rr, jj, 8] = np.sin(b["inner_contact_angle_rad"])
            bo[rr, jj, 9] = np.cos(b["inner_contact_angle_rad"])
            bo[rr, jj, 10] = np.sin(b["outer_contact_angle_rad"])
            bo[rr, jj, 11] = np.cos(b["outer_contact_angle_rad"])
            _summarise(rows, bo, summ)
            out["summary"][i] = summ
