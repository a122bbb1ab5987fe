"""The integrator contract: one ``advance(workspace, t_end) -> status`` for every method.

A :class:`Workspace` holds everything an integration needs between two output times: the
right-hand side ``fun(t, y, dy, args)`` (a numba function, :func:`bearingsim.dynamics.forces.rhs_args`
for the bearing), its argument tuple, the time t [s], the state y (updated in place), the proposed
next step h [s], the per-component tolerances, the step limits, the ball blocks of the W-methods'
Jacobian and the Jacobian itself, which ROS34PW2 keeps from one call to the next (and which a
checkpoint saves).  Each method module (:mod:`.dopri5`, :mod:`.ros2`, :mod:`.ros34pw2`) provides

* ``integrate(fun, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, ...)`` — the numba
  kernel: integrates y in place from t to exactly t_end with error control and returns
  (status, t reached, proposed next step); info[0:4] ← steps accepted, steps rejected, index of the
  component with the largest error at the last step, that scaled error; ROS34PW2 also info[4:7] ← the
  right-hand sides evaluated, the W factorisations and the Jacobian refreshes, info[7:10] ← the refined balls'
  right-hand sides, the balls refined and the steps refined (:mod:`.multirate`) (:attr:`Workspace.work`);
* ``advance(ws, t_end) -> Status`` — the same on a :class:`Workspace`: on success ws.t = t_end and
  ws.h the proposed step; on failure ws.t is the time reached and ws.h unchanged; ws.steps and
  ws.rejected count the steps.  With ``ws.dense`` (ROS34PW2's dense output) the call instead stops at the
  first step that reaches or passes t_end (ws.t ≥ t_end) and leaves that step for the interpolant
  (:func:`.common.hermite_one`).

When ``ws.kernel`` holds the method's kernel specialised for ``ws.fun`` (:mod:`.specialised`, cached on disk;
the stepper sets it for the engine's own right-hand sides with :func:`.specialised.engine_kernel`), ``advance``
calls it instead of the generic ``integrate``: the same code, the same results bit for bit, without compiling it
again in every process.

Status codes and messages: :mod:`.common`.  Determinism: no randomness, a fixed arithmetic order,
and every call stops exactly at t_end and returns the proposed next step, so a run restarted from
(t, y, h) — and for ROS34PW2 its Jacobian and, with dense output, its last step and controller memory — repeats
the same steps bit for bit.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ..layout import N_BALL
from .common import NO_VECTORS, OK, Status

#: entries of a workspace's ``info`` (module docstring)
INFO_SIZE = 10


#: ages (steps since the Jacobian's refresh) the refresh interval's controller keeps a record of
#: (:func:`.jacobian.refresh_interval`); its memory: [interval in use, intervals seen, age of the last attempt,
#: then per age: right-hand sides, simulated time advanced, intervals that reached it]
JAC_AGES = 64
JAC_MEMORY = 3 + 3 * JAC_AGES


def ros34_workspace(nb: int, nbk: int, coupled: bool, adaptive: bool = True, orbit: bool = True) -> tuple:
    """The Jacobian that ROS34PW2 keeps from one call to the next: (jac [nb, nbk, nbk],
    J_rr [10, 10], J_br [nc, nbk, 10], J_rb [nc, 10, nbk], state int64[2] = (steps since the refresh,
    1 when the arrays hold a Jacobian), the refresh interval's memory float[JAC_MEMORY] — float[0] with
    ``adaptive`` False: a fixed interval —, the balls' azimuth directions at the refresh float[nb, 2] — float[0, 2]
    with ``orbit`` False or blocks that are not the balls' (nbk ≠ N_BALL): J used as made, not turned with the
    balls' orbit, :mod:`.linalg`), nc = nb when the ring is coupled, else 0.  A run restarted from a checkpoint
    repeats the same steps when the checkpoint holds this workspace too."""
    nr = 10
    nc = nb if coupled else 0
    return (np.zeros((nb, nbk, nbk)), np.zeros((nr, nr)), np.zeros((nc, nbk, nr)), np.zeros((nc, nr, nbk)),
            np.zeros(2, dtype=np.int64), np.zeros(JAC_MEMORY if adaptive else 0),
            np.zeros((nb if orbit and nbk == N_BALL else 0, 2)))


@dataclass
class Workspace:
    """What every integrator's ``advance(ws, t_end)`` reads and updates (all SI).

    ``blk``/``nbk``: start index and size of the per-ball Jacobian blocks (W-methods); ``rmass`` =
    (m, m, m, I_t, I_t) of the inner ring and ``bmass`` (m, J) per ball switch on ROS34PW2's ring–ball
    coupling (empty arrays: per-ball blocks only); ``jacobian`` is :func:`ros34_workspace`.
    """

    fun: object  #: numba right-hand side fun(t, y, dy, args)
    args: tuple  #: its argument tuple
    y: np.ndarray  #: state (integrated in place)
    atol: np.ndarray  #: absolute tolerance per component
    rtol: np.ndarray  #: relative tolerance per component
    #: int64[n, 2]: (start, stop) of the vector each component's relative tolerance is measured on
    #: (:func:`.common.error_scale`); no rows: each component on its own
    vec: np.ndarray = field(default_factory=lambda: NO_VECTORS)
    t: float = 0.0  #: time [s]
    h: float = 1e-7  #: proposed next step [s]
    h_min: float = 1e-13  #: smallest step allowed [s]
    max_steps: int = 10_000_000  #: step limit per call
    blk: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    nbk: int = 0
    jac_every: int = 20  #: steps between Jacobian refreshes of the W-methods
    rmass: np.ndarray = field(default_factory=lambda: np.zeros(0))
    bmass: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    jacobian: tuple | None = None  #: ROS34PW2's Jacobian (:func:`ros34_workspace`), made on first use
    info: np.ndarray = field(default_factory=lambda: np.zeros(INFO_SIZE))  #: see the module docstring
    steps: int = 0  #: accepted steps so far
    rejected: int = 0  #: rejected steps so far
    #: ROS34PW2's work so far: right-hand sides evaluated, W factorisations, Jacobian refreshes, and of the multirate
    #: refinement (:mod:`.multirate`) the right-hand sides of the refined balls alone, the balls refined (summed over
    #: the steps) and the steps refined (zeros for the other methods)
    work: np.ndarray = field(default_factory=lambda: np.zeros(6, dtype=np.int64))
    #: ROS34PW2 on the engine's right-hand side: the most balls one step refines (:mod:`.multirate`; 0: none)
    multirate: int = 0
    #: the method's kernel specialised for ``fun`` (:func:`.specialised.engine_kernel`), or None: the generic one
    kernel: object = None
    #: ROS34PW2's dense output (:func:`.common.dense_arrays`): the calls stop at the first step at or past t_end
    #: (ws.t ≥ t_end) and leave that step's ends for :func:`.common.hermite_one`; None: every call lands on t_end
    dense: tuple | None = None

    def finish(self, status: int, t: float, h: float) -> Status:
        """Book the result of one kernel call (see the module docstring) and return its status."""
        self.steps += int(self.info[0])
        self.rejected += int(self.info[1])
        if self.info.shape[0] >= INFO_SIZE:
            self.work += self.info[4:10].astype(np.int64)
            self.info[4:10] = 0.0
        self.t = t
        if status == OK:
            self.h = h
        return Status(status)
