"""Shared parts of the integrators: status codes, the error norm, step-size control, step clipping.

Every method of :mod:`bearingsim.dynamics.integrate` reports one of the :class:`Status` codes
(``OK`` … ``MAX_STEPS``, with :data:`STATUS_TEXT` the message), measures its local error with
:func:`error_norm` and lands exactly on the requested time with :func:`clip_step`.  The step-size
factors are those of Hairer, Nørsett & Wanner, *Solving ODEs I*, 2nd ed. 1993, eq. II.4.13
(:func:`accept_factor`, :func:`reject_factor`) and of the PI controller of Gustafsson (1991)
(Hairer & Wanner, *Solving ODEs II*, eq. IV.8.21; :func:`pi_factor`).
"""

from __future__ import annotations

import enum

import numpy as np
from numba import njit


class Status(enum.IntEnum):
    """Outcome of one ``advance`` call (the integer is what the numba kernels return)."""

    OK = 0  #: reached t_end
    STEP_TOO_SMALL = 1  #: the step size fell below h_min (diverging or too stiff)
    NOT_FINITE = 2  #: the state became non-finite
    MAX_STEPS = 3  #: the step limit of the call was reached


OK = int(Status.OK)
STEP_TOO_SMALL = int(Status.STEP_TOO_SMALL)
NOT_FINITE = int(Status.NOT_FINITE)
MAX_STEPS = int(Status.MAX_STEPS)
#: message of every status code
STATUS_TEXT = {OK: "ok", STEP_TOO_SMALL: "step size fell below the minimum (diverging or too stiff)",
               NOT_FINITE: "the state became non-finite", MAX_STEPS: "step limit reached"}


#: no vector groups: every component's relative tolerance is on its own magnitude (:func:`error_scale`)
NO_VECTORS = np.zeros((0, 2), dtype=np.int64)


#: the most micro steps of one multirate refinement (:mod:`.multirate`): the dense output keeps their nodes
MICRO_MAX = 48
#: the groups of refined balls of a step (:mod:`.multirate`), each on micro steps of its own (run on two threads
#: when the engine is threaded; the same groups whatever the thread count)
GROUPS = 2
#: the dense output's state (:func:`dense_arrays`): where the groups' numbers of micro nodes, their times, and the
#: multirate refinement's memory (each group's next micro step [s], the large steps left without refinement) are
DST_NODES = 4
DST_TIMES = DST_NODES + GROUPS
DST_MR = DST_TIMES + GROUPS * (MICRO_MAX + 1)


@njit(cache=True, inline="always")
def node_row(g, j):
    """Row of :func:`dense_arrays`' states holding group g's micro node j (the state; f there in the next row)."""
    return 4 + 2 * (g * (MICRO_MAX + 1) + j)


@njit(cache=True, inline="always")
def node_time(g, j):
    """Index of group g's micro node j's time [s] in :func:`dense_arrays`' dense state."""
    return DST_TIMES + g * (MICRO_MAX + 1) + j


def dense_arrays(n: int) -> tuple[np.ndarray, np.ndarray]:
    """The arrays of a dense-output run of ROS34PW2 (:func:`.ros34pw2.integrate`) for n states: float[4 + 2 G (M + 1),
    n] (y₀ and f(t₀, y₀) at the start of the last step, f at its end, then — when the last step refined some balls
    (:mod:`.multirate`) — the group number + 1 on their states, and per group and node j of its micro steps the
    states and f there, :func:`node_row`) and float[4 + G + G (M + 1) + G + 1] (t₀ [s], the step controller's
    previous error (1 at the start, as in a call without dense output), 1 after a rejected step, 1 when row 2 holds f
    at the current state, per group the number of micro nodes of the last step (0: not refined), the nodes' times
    [s] (:func:`node_time`), the groups' next micro steps [s] and the cool-down count, carried from one call to the
    next); M = :data:`MICRO_MAX`, G = :data:`GROUPS`.  With n = 0: no dense output (:data:`NO_DENSE`)."""
    dst = np.zeros(DST_MR + GROUPS + 1)
    dst[1] = 1.0
    return np.zeros((4 + 2 * GROUPS * (MICRO_MAX + 1) if n else 3, n)), dst


@njit(cache=True)
def dense_state(dns: np.ndarray, dst: np.ndarray, t1: float, y1: np.ndarray, t: float) -> np.ndarray:
    """The state at t [s] in the last step [dst[0], t1] of a dense-output run (ending at y1): :func:`hermite_one` on
    the step's ends, and on the refined balls' states (:mod:`.multirate`) the same interpolant on their group's micro
    step that holds t.  (Compiled: 1.8 µs a sample on the hub case, against 16.5 µs in numpy.)"""
    n = y1.shape[0]
    y = np.empty(n)
    js = np.zeros(GROUPS, np.int64)  # per group the last node at or before t (the first one before them all)
    nodes = np.zeros(GROUPS, np.int64)
    for g in range(GROUPS):
        nodes[g] = int(dst[DST_NODES + g]) if dst.shape[0] > DST_NODES + g else 0
        while js[g] < nodes[g] - 2 and dst[node_time(g, js[g] + 1)] <= t:
            js[g] += 1
    for i in range(n):
        g = int(dns[3, i]) - 1 if dns.shape[0] > 3 else -1
        if g >= 0 and nodes[g] >= 2:
            j = js[g]
            r = node_row(g, j)
            y[i] = hermite_one(dst[node_time(g, j)], dns[r, i], dns[r + 1, i], dst[node_time(g, j + 1)],
                               dns[r + 2, i], dns[r + 3, i], t)
        else:
            y[i] = hermite_one(dst[0], dns[0, i], dns[1, i], t1, y1[i], dns[2, i], t)
    return y


@njit(cache=True)
def no_masked(t, y, dy, args, active):
    """The masked right-hand side of a problem without one (:mod:`.multirate` is off there): nothing."""
    return


@njit(cache=True)
def no_split(t, y, dy, args, active, phase, work):
    """The two-part right-hand side of a problem without one (the integrator then evaluates f whole): nothing."""
    return


#: no dense output (:func:`dense_arrays` for no states): the calls stop exactly at t_end
NO_DENSE, NO_DENSE_STATE = dense_arrays(0)


@njit(cache=True, inline="always")
def hermite_one(t0, y0, f0, t1, y1, f1, t):
    """The cubic Hermite interpolant of one step at t ∈ [t0, t1] [s] from the values y and derivatives f at both
    ends, for one component (Hairer, Nørsett & Wanner, *Solving ODEs I*, 2nd ed. 1993, §II.6, eq. 6.7): with
    h = t1 − t0 and θ = (t − t0)/h, u(θ) = (1 − θ) y0 + θ y1 + θ(θ − 1)[(1 − 2θ)(y1 − y0) + (θ − 1) h f0 + θ h f1].
    Exact for cubics; its error is O(h⁴), the order of ROS34PW2's local error (order 3), and it is continuous with
    a continuous derivative from one step to the next.  t ≥ t1 (or no step) returns y1 bit for bit."""
    h = t1 - t0
    if t >= t1 or h <= 0.0:
        return y1
    th = (t - t0) / h
    return (1.0 - th) * y0 + th * y1 + th * (th - 1.0) * ((1.0 - 2.0 * th) * (y1 - y0) + (th - 1.0) * h * f0
                                                          + th * h * f1)


@njit(cache=True, _nrt=False)
def error_scale(i, y, ynew, atol, rtol, vec):
    """Error scale of component i: atol_i + rtol_i max(|y|, |ynew|) (Hairer, Nørsett & Wanner, *Solving
    ODEs I*, 1993, eq. II.4.11), where |·| is the component's own magnitude, or, when ``vec`` (int64[n, 2])
    holds rows (start, stop), the Euclidean norm of y[start:stop], the vector the component belongs to.

    With vectors, a velocity's three components share one scale, the same in every frame; per component, one
    that passes through zero in the ball's orbit would be held several times tighter than its neighbours.
    ``vec`` with no rows: per component.
    """
    if vec.shape[0] == 0:
        return atol[i] + rtol[i] * max(abs(y[i]), abs(ynew[i]))
    a = 0.0
    b = 0.0
    for j in range(vec[i, 0], vec[i, 1]):
        a += y[j] * y[j]
        b += ynew[j] * ynew[j]
    return atol[i] + rtol[i] * np.sqrt(max(a, b))


@njit(cache=True, _nrt=False)
def error_norm(e, y, ynew, atol, rtol, info, vec=NO_VECTORS):
    """Scaled RMS norm of the local error estimate e (Hairer, Nørsett & Wanner, *Solving ODEs I*,
    1993, eq. II.4.11): √(Σ (e_i / s_i)² / n), s_i = :func:`error_scale` (``vec``: its vector groups).

    info[2], info[3] ← index and scaled error of the worst component.  Returns (err, finite);
    a non-finite component gives err = 1e10 and finite = False.
    """
    return error_norm_parts(e, y, ynew, atol, rtol, info, vec, e[:0])  # (an empty view: no parts kept)


@njit(cache=True, _nrt=False)
def error_norm_parts(e, y, ynew, atol, rtol, info, vec, r2):
    """:func:`error_norm`, and when ``r2`` has n entries each component's (e_i / s_i)² in it (the multirate
    refinement's choice of balls, :mod:`.multirate`)."""
    keep = r2.shape[0] == y.shape[0]
    n = y.shape[0]
    err = 0.0
    imax = 0
    emax = -1.0
    finite = True
    for i in range(n):
        r = e[i] / error_scale(i, y, ynew, atol, rtol, vec)
        ri2 = r * r
        if keep:
            r2[i] = ri2
        if not np.isfinite(ri2):
            finite = False
            imax = i
            break
        if ri2 > emax:
            emax = ri2
            imax = i
        err += ri2
    info[2] = imax
    info[3] = np.sqrt(emax) if finite else np.inf
    return (np.sqrt(err / n) if finite else 1e10), finite


@njit(cache=True)
def clip_step(t, h, t_end):
    """(step [s], last) with the step shortened to land exactly on t_end [s]; last is True when it does."""
    if t + h >= t_end:
        return t_end - t, True
    return h, False


@njit(cache=True)
def accept_factor(err, expo, grow):
    """Step growth after an accepted step, h ← h·min(grow, max(0.2, 0.9 err^(−expo))) (Hairer et al.
    eq. II.4.13; expo = 1/(q + 1) with q the lower of the embedded orders); ``grow`` when err = 0."""
    return grow if err == 0.0 else min(grow, max(0.2, 0.9 * err ** -expo))


@njit(cache=True)
def reject_factor(err, expo):
    """Step reduction after a rejected step, max(0.2, 0.9 err^(−expo))."""
    return max(0.2, 0.9 * err ** -expo)


@njit(cache=True)
def pi_factor(err, err_prev, ki, kp, grow):
    """PI step-size factor 0.9 e^(−ki) (e_prev/e)^kp limited to [0.2, grow], e = max(err, 1e-10)
    (Gustafsson 1991; Hairer & Wanner, *Solving ODEs II*, eq. IV.8.21).  Returns (factor, the
    e_prev of the next step = max(e, 1e-4))."""
    e_now = max(err, 1e-10)
    fac = 0.9 * e_now ** (-ki) * (err_prev / e_now) ** kp
    fac = min(grow, max(0.2, fac))
    return fac, max(e_now, 1e-4)


@njit(cache=True)
def linear_rhs(t, y, dy, args):
    """dy ← A y with A = args[0] (n × n): the linear right-hand side y′ = A y on which the methods' order and
    stability are checked (tests/unit/test_dyn_integrator.py, benchmarks/bench_jacobian_age.py)."""
    a = args[0]
    for i in range(y.shape[0]):
        acc = 0.0
        for k in range(y.shape[0]):
            acc += a[i, k] * y[k]
        dy[i] = acc
