"""Stepping a dynamic model between output times, and sampling the output quantities.

:class:`Stepper` holds the state of one run (t [s], y, the proposed step h [s], step counts) and
advances it with the integrator named by ``method`` through the contract of
:mod:`bearingsim.dynamics.integrate`: ``METHODS[method].advance(workspace, t_end)`` on a
:class:`~bearingsim.dynamics.integrate.Workspace` whose state array is the stepper's ``y`` and whose
Jacobian (ROS34PW2 keeps it from one call to the next, and checkpoints save it) is ``Stepper._ws``.
:meth:`Stepper.sample` evaluates the right-hand side of :mod:`.forces` once at the current state and
packs the output quantities (:func:`sample_from`), named as in :data:`.output.VARIABLES`.

With ``dense=True`` (ROS34PW2 only; :func:`.run.simulate` sets it) the integrator does not stop at the output
times: :meth:`Stepper.state_at` advances to the first step at or past the time asked and interpolates the state
there (:func:`.integrate.common.hermite_one`), so the steps, and the trajectory, do not depend on the output interval.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numba
import numpy as np

from ..errors import BearingSimError, InputError
from ..statics import layout as kn  # the row-parameter layout (P_*)
from . import forces as fo
from . import integrate as ig
from . import layout as ly
from . import model as md
from .integrate.common import dense_arrays, dense_state
from .integrate.specialised import engine_kernel


class SimulationError(BearingSimError):
    """The integration failed (diverging step, separated balls); data so far are saved."""


#: integrator names and what they are (the ``integrator`` attribute of an output file)
INTEGRATOR_TEXT = {
    "dopri5": "Dormand-Prince 5(4) with error control",
    "ros2w": "ROS2 W-method (Verwer et al. 1999), block-diagonal per ball",
    "ros34w": "ROS34PW2 W-method (Rang & Angermann 2005), per-ball blocks coupled with the inner ring",
}


def integrator_text(method: str, model: md.Model | None = None, ring_coupling: bool = True, multirate: int = 0) -> str:
    """What the ``integrator`` attribute of an output file says about ``method``.  ROS34PW2 couples the
    inner ring's block with the balls unless the ring is held fixed (``G_RING_FIXED``) or
    ``ring_coupling`` is off; then its Jacobian is block-diagonal per ball.  With ``multirate`` > 0 its steps refine
    up to that many balls with micro steps of their own (:mod:`.integrate.multirate`)."""
    if method == "ros34w" and (not ring_coupling or (model is not None and model.gp[ly.G_RING_FIXED] > 0.0)):
        text = "ROS34PW2 W-method (Rang & Angermann 2005), block-diagonal per ball"
    else:
        text = INTEGRATOR_TEXT[method]
    if method == "ros34w" and multirate > 0:
        text += (f"; the balls that hold the error (up to {multirate} per step) stepped again on their own "
                 "(multirate refinement, Savcenco, Hundsdorfer & Verwer 2007)")
    return text


@dataclass
class Stepper:
    """State and integrator settings of one run (all SI)."""

    model: md.Model
    loadspec: np.ndarray
    y: np.ndarray
    t: float = 0.0
    h: float = 1e-7
    tol: float = 1e-6
    h_min: float = 1e-13
    method: str = "dopri5"  #: "dopri5" (explicit), "ros2w" or "ros34w" (linearly implicit, for stiff traction)
    #: the most steps between Jacobian refreshes (also after two rejections in a row); with :attr:`jac_adaptive` the
    #: interval is chosen up to it from the run's record (:func:`.integrate.jacobian.refresh_interval`)
    jac_every: int = 20
    #: ROS34PW2: the refresh interval from the run's own cost per simulated time by the Jacobian's age (False: every
    #: :attr:`jac_every` steps).  Alone: 7011 (a) −13.5 %, hub at 10 km/h −13.9 %, hub (b) −1.0 % right-hand sides
    jac_adaptive: bool = True
    #: ROS34PW2: the Jacobian used turned with each ball's azimuth change since its refresh (J' = P J Pᵀ,
    #: :mod:`.integrate.linalg`; False: as made).  7011 (a) ≈ 3× fewer right-hand sides (its J aged by the orbit)
    jac_orbit: bool = True
    ring_coupling: bool = True  #: ROS34PW2: the inner ring's block and its coupling with the balls in the Jacobian
    #: ROS34PW2: the most balls a step refines with micro steps of their own (:mod:`.integrate.multirate`; 0: none).
    #: Hub (b), 20 ms: 37 % less CPU than without, at 10 km/h 36 % less; the 7011 never refines
    multirate: int = 8
    max_steps_per_interval: int = 10_000_000
    #: threads for the ball contacts of the right-hand side (None or 1: serial; up to NUMBA_NUM_THREADS; "auto":
    #: :func:`idle_cores`, the CLI's default).  The result is the same bit for bit
    #: (:func:`.forces.balls_on_raceways`).  The library's default stays serial (a caller running several cases
    #: in processes, as the hub study does, must not oversubscribe the cores); with the OpenMP layer 2 threads run
    #: the hub case at 110 wall s per simulated s against 171 on one on an idle 2-core machine.
    threads: int | str | None = None
    #: dense output (ROS34PW2; ignored by the other methods): the steps run past the output times and
    #: :meth:`state_at` interpolates; then :attr:`t` and :attr:`y` are the integrator's own time and state
    dense: bool = False
    steps: int = 0
    rejected: int = 0
    atol: np.ndarray = field(default=None, repr=False)
    rtol: np.ndarray = field(default=None, repr=False)
    #: (start, stop) of the vector each component's relative tolerance is measured on (:func:`.model.error_vectors`)
    vec: np.ndarray = field(default=None, repr=False)

    def __post_init__(self):
        if self.atol is None or self.rtol is None:
            self.atol, self.rtol = md.tolerance_vectors(self.model, self.tol)
        if self.vec is None:
            self.vec = md.error_vectors(self.model)
        if self.method not in ig.METHODS:
            raise InputError("integrator", f"unknown integrator {self.method!r}", "use dopri5, ros2w or ros34w")
        self._args = fo.args_of(self.model, self.loadspec)
        self._info = np.zeros(ig.INFO_SIZE)
        self._blk = np.array([ly.N_RING + ly.N_BALL * k for k in range(self.model.n_balls)], dtype=np.int64)
        # ROS34PW2 also carries the inner ring's block and its coupling with the balls (a stiff mode at
        # low rolling speed, docs/dynamics.md) unless the ring is held fixed
        m = self.model
        if m.gp[ly.G_RING_FIXED] > 0.0 or not self.ring_coupling:
            self._rmass, self._bmass = np.zeros(0), np.zeros((0, 2))
        else:
            self._rmass = np.array([m.gp[ly.G_MR]] * 3 + [m.gp[ly.G_ITR]] * 2)
            self._bmass = np.array([[m.rows[r, kn.P_MASS], m.rows[r, kn.P_JB]] for r in m.ball_row])
        # the ROS34PW2 Jacobian lives from one call to the next (and in checkpoints)
        self._ws = ig.ros34_workspace(m.n_balls, ly.N_BALL, self._rmass.shape[0] == 5, self.jac_adaptive,
                                      self.jac_orbit)
        self.dense = bool(self.dense) and self.method == "ros34w"
        #: the dense output's arrays (:func:`.integrate.common.dense_arrays`; saved in checkpoints), or None
        self._dense = dense_arrays(self.y.shape[0]) if self.dense else None
        self.threads = resolve_threads(self.threads)
        fun = fo.rhs_args_threaded if self.threads > 1 else fo.rhs_args
        kernel = engine_kernel(ig.METHODS[self.method].__name__.rsplit(".", 1)[1], fun)
        self.workspace = ig.Workspace(fun, self._args, self.y, self.atol, self.rtol, vec=self.vec, blk=self._blk,
                                      kernel=kernel, nbk=ly.N_BALL, rmass=self._rmass, bmass=self._bmass,
                                      jacobian=self._ws, info=self._info, dense=self._dense,
                                      multirate=int(self.multirate) if self.method == "ros34w" else 0)

    def advance(self, t_end: float) -> None:
        """Integrate to t_end [s] with ``METHODS[method].advance(workspace, t_end)`` (with :attr:`dense`: to the
        first step at or past t_end); raises :class:`SimulationError` naming the time and body on failure."""
        ws = self.workspace
        # the stepper's fields are the state (tests and checkpoints set them): the workspace takes them
        ws.y, ws.atol, ws.rtol, ws.vec, ws.jacobian = self.y, self.atol, self.rtol, self.vec, self._ws
        ws.dense = self._dense
        ws.t, ws.h, ws.h_min = self.t, self.h, self.h_min
        ws.max_steps, ws.jac_every = self.max_steps_per_interval, self.jac_every
        ws.multirate = int(self.multirate) if self.method == "ros34w" else 0
        ws.steps, ws.rejected = self.steps, self.rejected
        if self.threads > 1:
            numba.set_num_threads(self.threads)
        status = ig.METHODS[self.method].advance(ws, float(t_end))
        self.steps, self.rejected = ws.steps, ws.rejected
        self.t = ws.t
        if status != ig.OK:
            comp = md.describe_component(self.model, int(self._info[2]))
            raise SimulationError(f"integration failed at t = {ws.t * 1e3:.6g} ms: {ig.STATUS_TEXT[status]}; "
                                  f"largest error in {comp}")
        self.h = ws.h

    def state_at(self, t: float) -> np.ndarray:
        """The state at time t [s] (a new array): integrated to t; with :attr:`dense` to the first step at or past
        t and interpolated in that step (:func:`.integrate.common.dense_state`).  Times must not go back past the
        start of the last step."""
        if t > self.t:
            self.advance(t)
        if not self.dense or t == self.t:
            if t != self.t:
                raise ValueError(f"the stepper is at t = {self.t!r} s, not at {t!r} s (no dense output)")
            return self.y.copy()
        dns, dst = self._dense
        if dst[3] == 0.0 or t < dst[0]:
            raise ValueError(f"t = {t!r} s is before the last step [{dst[0]!r}, {self.t!r}] s of the dense output")
        return dense_state(dns, dst, self.t, self.y, float(t))

    def sample(self, t: float | None = None, y: np.ndarray | None = None) -> dict:
        """Output quantities at the current state, or at (t [s], y) (:meth:`state_at`) (SI)."""
        if t is None:
            t, y = self.t, self.y
        # (on the run's threads: the same numbers bit for bit; the two evaluations of a lubricated sample cost
        # ≈ 110 µs of the hub's, 1.3 wall s per simulated s at 10 kHz output)
        threaded = self.threads > 1
        dy, diag, gd = fo.evaluate(self.model, t, y, self.loadspec, threads=threaded)
        out = sample_from(self.model, t, y, diag, gd)
        out["power_loss_rolling"] = 0.0
        if int(self.model.gp[ly.G_TRAC]) == 2 and self.model.lubs is not None:
            # rolling viscous resistance share: the same state without it (Sakaguchi & Shibutani [S1] eqs. 4-5)
            from ..contact import slices

            if not np.any(self.model.lubs[:, slices.L_ROLLRES] != 0):
                return out
            saved = self.model.lubs.copy()
            try:
                self.model.lubs[:, slices.L_ROLLRES] = 0.0
                _, _, gd2 = fo.evaluate(self.model, t, y, self.loadspec, threads=threaded)
            finally:
                self.model.lubs[:] = saved
            out["power_loss_rolling"] = (gd[ly.GD_PI] + gd[ly.GD_PO]) - (gd2[ly.GD_PI] + gd2[ly.GD_PO])
        return out


def resolve_threads(threads) -> int:
    """The thread count of a run: None → 1 (serial, :attr:`Stepper.threads`); ``"auto"`` → :func:`idle_cores`;
    else an integer in 1..NUMBA_NUM_THREADS (InputError otherwise)."""
    top = numba.config.NUMBA_NUM_THREADS
    if threads is None:
        return 1
    if isinstance(threads, str) and threads.strip().lower() == "auto":
        return idle_cores()
    if isinstance(threads, bool) or not isinstance(threads, (int, np.integer)) or not 1 <= threads <= top:
        raise InputError("threads", f"must be an integer in 1..{top} (NUMBA_NUM_THREADS) or auto, got {threads!r}",
                         "e.g. --threads 1 for one core; set NUMBA_NUM_THREADS for more")
    return int(threads)


def idle_cores(window: float = 0.1) -> int:
    """Threads for ``--threads auto`` (the CLI's default): the cores this process may run on
    (``os.sched_getaffinity``) less the cores the others keep busy now (:func:`busy_cores` over ``window`` [s];
    where /proc/stat is missing, the one-minute load average), rounded to the nearest core, at least 1 and at
    most NUMBA_NUM_THREADS (1 in the test suite, tests/conftest.py).  The OpenMP layer's threads spin between
    right-hand sides: on idle cores that is what makes them pay, on busy ones it costs several times the work
    (:mod:`.forces`), so a loaded machine gets fewer threads.  A present measurement rather than the load
    average, which would still count a run that has just ended for a minute.  The trajectory is the same for
    any count."""
    import os

    try:
        cores = len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # (not on every platform)
        cores = os.cpu_count() or 1
    busy = busy_cores(window)
    if busy is None:
        try:
            busy = os.getloadavg()[0]
        except (AttributeError, OSError):
            busy = 0.0
    free = int(math.floor(cores - busy + 0.5))
    return max(1, min(free, cores, numba.config.NUMBA_NUM_THREADS))


def _cpu_times(path: str = "/proc/stat") -> tuple[float, float] | None:
    """(busy, total) jiffies of all CPUs from the first line of /proc/stat (idle and iowait count as idle; guest
    time is already inside user), or None where it cannot be read."""
    try:
        with open(path, encoding="ascii") as fh:
            fields = fh.readline().split()
        vals = [float(v) for v in fields[1:9]]  # user nice system idle iowait irq softirq steal
    except (OSError, ValueError, IndexError):
        return None
    if len(vals) < 5 or fields[0] != "cpu":
        return None
    total = sum(vals)
    return total - vals[3] - vals[4], total


def busy_cores(window: float = 0.1, read=_cpu_times) -> float | None:
    """Cores busy now [-]: the busy share of all CPUs' time over ``window`` [s] (two reads of /proc/stat) times
    the CPU count; None where /proc/stat is missing or did not advance."""
    import os
    import time

    a = read()
    if a is None:
        return None
    time.sleep(window)
    b = read()
    if b is None or b[1] <= a[1]:
        return None
    return (b[0] - a[0]) / (b[1] - a[1]) * (os.cpu_count() or 1)


def sample_from(model: md.Model, t: float, y: np.ndarray, diag: np.ndarray, gd: np.ndarray) -> dict:
    """Pack one output sample (dictionary of numpy arrays / floats, SI)."""
    oc = model.cage_offset
    nc = model.n_cages
    cage = np.array([y[oc + ly.N_CAGE * c + 9] for c in range(nc)])
    cage_angle = np.array([y[oc + ly.N_CAGE * c + 6] for c in range(nc)])
    cage_pos = np.array([y[oc + ly.N_CAGE * c:oc + ly.N_CAGE * c + 3] for c in range(nc)])
    deform = np.zeros(nc)
    stress = np.zeros(nc)
    for c in range(nc):
        eta, _ = model.mode_slices(c)
        n, z = eta.stop - eta.start, int(model.cp[c, ly.C_Z])
        if n:
            u = np.einsum("k,kjd->jd", y[eta], model.cage_modes[c, :n, 2:2 + 6 * z].reshape(n, z, 6)[:, :, :3])
            deform[c] = np.sqrt((u * u).sum(axis=1)).max()
            stress[c] = np.abs(np.tensordot(y[eta], model.cage_stress[c], (0, 0))).max()
    return {
        "time": t,
        "inner_ring_displacement": y[0:5].copy(),
        "inner_ring_velocity": y[5:10].copy(),
        "applied_load": gd[ly.GD_FA:ly.GD_MZ + 1].copy(),
        "shaft_speed": gd[ly.GD_W],
        "cage_angular_speed": cage,
        "cage_angle": cage_angle,
        "cage_position": cage_pos,
        "ball_orbital_speed": diag[:, ly.D_WM].copy(),
        "ball_spin_speed": diag[:, ly.D_WR].copy(),
        "ball_pitch_angle": diag[:, ly.D_BETA].copy(),
        "inner_contact_load": diag[:, ly.D_QI].copy(),
        "outer_contact_load": diag[:, ly.D_QO].copy(),
        "inner_contact_angle": diag[:, ly.D_AI].copy(),
        "outer_contact_angle": diag[:, ly.D_AO].copy(),
        "inner_approach": diag[:, ly.D_DI].copy(),
        "outer_approach": diag[:, ly.D_DO].copy(),
        "inner_slide_roll_ratio": diag[:, ly.D_SRI].copy(),
        "outer_slide_roll_ratio": diag[:, ly.D_SRO].copy(),
        "inner_power_loss": diag[:, ly.D_PI].copy(),
        "outer_power_loss": diag[:, ly.D_PO].copy(),
        "cage_contact_load": diag[:, ly.D_QC].copy(),
        "cage_power_loss": diag[:, ly.D_PC].copy(),
        "inner_ring_friction_torque": gd[ly.GD_TQI],
        "outer_ring_friction_torque": gd[ly.GD_TQO],
        "power_loss_inner": gd[ly.GD_PI],
        "power_loss_outer": gd[ly.GD_PO],
        "power_loss_cage": gd[ly.GD_PC],
        "power_loss_land": gd[ly.GD_PL],
        "contact_potential_energy": gd[ly.GD_EPOT],
        "cage_strain_energy": gd[ly.GD_ECAGE],
        "cage_pocket_deformation": deform,
        "cage_peak_stress": stress,
    }

