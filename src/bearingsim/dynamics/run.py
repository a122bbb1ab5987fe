"""Running a dynamic simulation: :func:`simulate` runs a case from start to end.

:func:`simulate` builds the model and its quasi-static start (:func:`build`), advances a
:class:`~.stepper.Stepper` from one output time to the next with a progress bar, streams the samples
to a netCDF file in chunks (memory bounded by the chunk; :mod:`.output`), writes checkpoints at a
wall-clock interval and resumes from them, and returns :class:`~.results.Results`.

The jobs live in their own modules: stepping in :mod:`.stepper`, the output schema, the writer and
the checkpoints in :mod:`.output`, the results in :mod:`.results`.  Their names stay importable from
here (``bearingsim.dynamics.run.simulate``, ``Stepper``, ``Results``, ``SimulationError``,
``VARIABLES`` ...).
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from ..errors import InputError
from . import model as md
from .output import (  # noqa: F401  (re-exported: the former names of this module)
    CHECKPOINT_SECONDS,
    VARIABLES,
    _checkpoint_path,
    _checkpoint_tmp,
    _read_checkpoint,
    _restore_checkpoint,
    _save_checkpoint,
    _variables,
    _Writer,
    stack_samples,
    to_dataset,
)
from .results import Results
from .stepper import SimulationError, Stepper, integrator_text, sample_from  # noqa: F401

__all__ = ["CHECKPOINT_SECONDS", "VARIABLES", "Results", "SimulationError", "Stepper", "build", "run_stepper",
           "sample_from", "simulate", "stack_samples", "to_dataset"]


def run_stepper(stepper: Stepper, duration: float, output_interval: float, progress=None) -> Results:
    """Run in memory (tests and the API without a file): samples at every output interval (interpolated when the
    stepper has dense output, :meth:`Stepper.state_at`)."""
    n = int(round(duration / output_interval))
    samples = [stepper.sample()]
    t0 = stepper.t
    for i in range(1, n + 1):
        t = t0 + i * output_interval
        samples.append(stepper.sample(t, stepper.state_at(t)))
    return Results(data=stack_samples(samples), attrs={})


# ---- the case runner ---------------------------------------------------------------------
def build(case):
    """(model, loadspec, initial state) of a case; the start is the quasi-static solution."""
    from ..statics import jones_harris as jh

    model = md.build_model(case.bearing, **case.model_options())
    loadspec = case.loads.packed()
    l0 = case.loads.at(0.0)
    xl = case.load_point
    static_loads = jh.Loads(fa=l0[0], fr_y=l0[1], fr_z=l0[2], m_y=l0[3] - xl * l0[2], m_z=l0[4] + xl * l0[1])
    w0 = case.speed.at(0.0)
    res = jh.solve(case.bearing, static_loads, abs(w0), control=case.control)
    if not res.converged:
        res = jh.solve(case.bearing, static_loads, 0.0, control=case.control)
    if not res.converged:
        raise InputError("loads", f"no quasi-static equilibrium for the loads at t = 0 ({res.status})",
                         "the initial loads must be carried by the bearing (e.g. an axial load on an angular "
                         "contact row)")
    rates = None  # the clean start: velocities of the quasi-static solution at t = 0
    if getattr(case, "start", "rest") == "consistent":
        rates = md.quasi_static_rates(model, case.bearing, case.loads, res, w0, xl, case.control)
    y0 = md.initial_state(model, res, w0, rates)
    return model, loadspec, y0, res



def _note(console, text: str) -> None:
    """One line for the user: on ``console`` (the CLI's stderr) or as a Python warning (the API)."""
    if console is not None:
        console.print(text, markup=False, highlight=False, soft_wrap=True)
    else:
        import warnings

        warnings.warn(text, stacklevel=3)



def simulate(case, out: str | Path | None = None, resume: bool = False, progress: bool = False,
             console=None, checkpoint_seconds: float | None = None, threads: int | None = None,
             dense: bool = True) -> Results:
    """Run a dynamic case.

    Parameters
    ----------
    case : :class:`~.case.Case` or a path to a case TOML file
    out : netCDF file for the output (streamed in chunks); None keeps the samples in memory.  A
        checkpoint ``OUT.ckpt.npz`` is written after every ``checkpoint_every`` chunks and at the first
        output time after ``checkpoint_seconds`` of wall-clock time since the last one (so a long run
        killed at any time can be resumed); it is removed when the run completes
    resume : continue from the checkpoint of ``out`` (same case required); the trajectory
        is bitwise the same as an uninterrupted run (the integrator restarts from the
        checkpointed t, y, step size and Jacobian, and every output time is hit exactly).
        Without a checkpoint (the run was killed before its first one, or it had completed) the run
        starts from the beginning with a one-line note (on ``console``, else a Python warning)
    progress : show a progress bar (simulated time, rate, ETA)
    console : a ``rich`` console for the progress bar and notes
    checkpoint_seconds : wall-clock interval between checkpoints [s] (default: the case's
        ``checkpoint_every = "… s"``, else :data:`CHECKPOINT_SECONDS`)
    threads : threads for the ball contacts of the right-hand side (None: 1; ``"auto"``: the idle cores,
        :func:`.stepper.idle_cores`; at most NUMBA_NUM_THREADS; the trajectory is the same bit for bit for any
        count; serial by default so that runs in parallel processes do not oversubscribe, :attr:`Stepper.threads`)
    dense : with ROS34PW2, dense output (:attr:`Stepper.dense`): the steps do not stop at the output times, the
        samples are interpolated in the steps, and the trajectory does not depend on the output interval (False:
        every output time is a step's end, as with the other integrators)

    Returns
    -------
    Results
        Its ``summary`` holds this call's segment — ``simulated_seconds`` [s], ``steps``,
        ``rejected_steps``, ``wall_seconds`` [s] and ``wall_per_simulated_second`` (a resumed call: from the
        checkpoint at ``resumed_at_seconds`` [s], else None) — and the whole run's ``run_simulated_seconds`` [s],
        ``run_steps`` and ``run_rejected_steps``.  On a diverging step or when every ball has separated
        the data so far are saved and :class:`SimulationError` is raised.
    """
    from .case import Case, load_case

    if not isinstance(case, Case):
        case = load_case(case)
    if checkpoint_seconds is None:
        checkpoint_seconds = getattr(case, "checkpoint_interval", None) or CHECKPOINT_SECONDS
    if isinstance(checkpoint_seconds, bool) or not isinstance(checkpoint_seconds, int | float) or \
            not (0 < checkpoint_seconds < math.inf):
        raise InputError("checkpoint_every", f"must be a positive wall-clock time, got {checkpoint_seconds!r} s",
                         'e.g. "30 s"')
    from .stepper import resolve_threads

    threads = resolve_threads(threads)  # (bad input fails before the start is solved)
    model, loadspec, y0, static = build(case)
    for w in getattr(static, "warnings", ()):  # the start past a physical limit (contact pressure, angle, s0 < 1)
        _note(console, f"warning: the quasi-static start at t = 0: {w}")
    fp = case.fingerprint()
    stepper = Stepper(model, loadspec, y0, tol=case.tolerance, h=min(1e-7, case.output_interval),
                      method=case.method, threads=threads, dense=dense, multirate=case.multirate)
    attrs = {"title": "bearingsim dynamic simulation", "bearing": model.names.get("bearing", ""),
             "traction": case.traction, "tolerance": case.tolerance, "case_fingerprint": fp,
             "conventions": "x bearing axis, outer ring fixed, psi = 0 on +y, SI units",
             "integrator": integrator_text(case.method, model, stepper.ring_coupling, stepper.multirate)}
    attrs["output_sampling"] = ("dense output: each sample from the cubic Hermite interpolant of the integrator's step "
                                "that holds its time (the steps do not stop at the output times)" if stepper.dense
                                else "every output time ends an integrator step")
    if case.traction == "slices":
        gauss = f"Gauss-Legendre, {case.n_slices} nodes per stretch between the zeros of the rolling slip"
        attrs["traction_quadrature"] = {"gauss": gauss, "split": f"{case.n_slices} equal strips, cut at the zeros of "
                                        "the rolling slip", "log": f"{case.n_slices} nodes, generalized Gauss rules "
                                        "exact for the logarithm of the zeros of the rolling slip"}.get(
                                            case.slice_rule, f"{case.n_slices} equal strips")
    n_total = case.n_samples
    start = 0
    writer = None
    ckpt = None
    out_path = Path(out) if out is not None else None
    samples_mem: list[dict] = []
    if out_path is not None:
        ckpt = _checkpoint_path(out_path)
        c = None
        if resume:
            c, why = _read_checkpoint(ckpt, out_path, fp)
            if c is None:
                _note(console, f"--resume: {why}; starting from the beginning")
        if c is not None:
            _restore_checkpoint(c, stepper)
            start = int(c["index"])
            writer = _Writer(out_path, model, attrs, start)
            if len(writer.ds.dimensions["time"]) < start:
                writer.close()
                raise InputError("--resume", f"{out_path.name} holds fewer samples than its checkpoint counts (was "
                                 "the file replaced?)", "run without --resume to start again")
        else:
            ckpt.unlink(missing_ok=True)  # a stale checkpoint must never meet the new file
            writer = _Writer(out_path, model, attrs, None)
    buf: list[dict] = []
    if start == 0:
        buf.append(stepper.sample())
    t_wall0 = time.perf_counter()
    steps0, rejected0 = stepper.steps, stepper.rejected  # the counts a resumed run starts from (checkpoint)
    first = start if start > 0 else 1
    prog = None
    task = None
    if progress:
        from rich.progress import BarColumn, Progress, TextColumn, TimeRemainingColumn

        prog = Progress(TextColumn("[bold]simulate"), BarColumn(),
                        TextColumn("{task.fields[simt]:.3f} / {task.fields[tot]:.3f} ms"),
                        TextColumn("{task.fields[rate]:.3g} wall s per sim s"), TimeRemainingColumn(),
                        console=console, transient=False)
        prog.start()
        task = prog.add_task("sim", total=n_total, completed=max(start - 1, 0), simt=(first - 1) * case.output_interval
                             * 1e3, tot=case.duration * 1e3, rate=0.0)
    chunks = 0
    error = None
    completed = False
    # the last output time (the stepper's own time may be past it with dense output)
    t_out = t_sim0 = (first - 1) * case.output_interval
    last_ckpt = time.monotonic()

    def flush(final=False, checkpoint=False):
        """Write the buffered samples; then a checkpoint after every ``checkpoint_every`` full chunks, when
        asked (wall-clock interval) and at the end of an incomplete run.  The samples are synced before
        the checkpoint that counts them is renamed into place."""
        nonlocal buf, chunks, last_ckpt
        if writer is not None:
            full = len(buf) >= case.chunk
            writer.write(buf)
            chunks += full
            if checkpoint or (final and not completed) or (full and chunks % max(case.checkpoint_every, 1) == 0):
                _save_checkpoint(ckpt, stepper, writer.index, fp)
                last_ckpt = time.monotonic()
        else:
            samples_mem.extend(buf)
        buf = []

    n_free = 0
    try:
        for i in range(first, n_total + 1):
            try:
                y_out = stepper.state_at(i * case.output_interval)
            except SimulationError as exc:
                error = exc
                break
            t_out = i * case.output_interval
            s = stepper.sample(t_out, y_out)
            buf.append(s)
            # the inner ring has left every ball for three output samples in a row
            n_free = n_free + 1 if not np.any(s["inner_contact_load"] > 0) else 0
            if n_free >= 3:
                error = SimulationError(f"every ball has separated from the inner raceway at t = "
                                        f"{t_out * 1e3:.6g} ms (the loads lift the inner ring off the balls); "
                                        "data so far saved")
                break
            if len(buf) >= case.chunk:
                flush()
            elif writer is not None and time.monotonic() - last_ckpt >= checkpoint_seconds:
                flush(checkpoint=True)  # the run can be resumed from here, chunk or not
            if prog is not None:
                el = time.perf_counter() - t_wall0
                prog.update(task, completed=i, simt=t_out * 1e3,
                            rate=el / max(t_out - t_sim0, 1e-30))
        else:
            completed = True
    finally:
        flush(final=True)
        if prog is not None:
            prog.stop()
        if writer is not None:
            writer.close()
    if completed and ckpt is not None:
        ckpt.unlink(missing_ok=True)  # a completed run leaves no checkpoint behind
        _checkpoint_tmp(ckpt).unlink(missing_ok=True)  # (nor one half-saved when an earlier run was killed)
    wall = time.perf_counter() - t_wall0
    # this call's segment (from the checkpoint when resumed) and the whole run, each labelled: the segment's
    # time, steps and wall time belong together; the run's totals count every segment
    summary = {"wall_seconds": wall, "simulated_seconds": t_out - t_sim0, "steps": stepper.steps - steps0,
               "threads": stepper.threads,
               "rejected_steps": stepper.rejected - rejected0,
               "wall_per_simulated_second": wall / max(t_out - t_sim0, 1e-30),
               "resumed_at_seconds": t_sim0 if start > 0 else None,
               "run_simulated_seconds": t_out, "run_steps": stepper.steps, "run_rejected_steps": stepper.rejected,
               "initial_static_converged": bool(static.converged),
               "initial_static_warnings": list(getattr(static, "warnings", ()))}
    res = Results(data=stack_samples(samples_mem) if writer is None else None, attrs=attrs,
                  path=str(out_path) if out_path else None, summary=summary)
    if error is not None:
        raise error
    return res
