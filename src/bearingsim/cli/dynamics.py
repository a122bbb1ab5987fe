"""Commands of the dynamic engine: ``bearingsim simulate CASE.toml --out run.nc [--resume]``
(``reproduce hub-hysteresis`` is in :mod:`.hysteresis`).  Registered on the app by :func:`register`.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Annotated, Optional

import typer

from .console import announce_compilation, make_console
from .options import out_option

CaseArg = Annotated[Path, typer.Argument(help="case TOML file (see examples/spindle-7011.toml)")]
SimulateOut = out_option("output netCDF file (streamed in chunks)", "-o")


def simulate(case: CaseArg,
             out: SimulateOut,
             resume: bool = typer.Option(False, "--resume", help="continue from the checkpoint OUT.ckpt.npz "
                                         "(none: start from the beginning, with a note)"),
             checkpoint_every: Optional[str] = typer.Option(
                 None, "--checkpoint-every",
                 help="wall-clock time between checkpoints, e.g. '10 s' (default: the case's, else 30 s)"),
             duration: Optional[str] = typer.Option(None, "--duration",
                                                    help="override the case duration, e.g. '2 ms'"),
             json_out: bool = typer.Option(False, "--json", help="print a JSON summary (SI)"),
             quiet: bool = typer.Option(False, "--quiet", help="no progress bar"),
             threads: str = typer.Option(
                 "auto", "--threads", help="threads for the ball contacts: a count (at most NUMBA_NUM_THREADS) or "
                 "auto, the idle cores (default); the result is the same bit for bit")):
    """Run a dynamic simulation of rings, balls and cage in time."""
    import dataclasses

    from ..dynamics.case import load_case
    from ..dynamics.run import simulate as run_sim
    from ..units import parse_quantity
    from .output import NETCDF_SUFFIXES, output_file, writing

    _check_case_path(case)
    c = load_case(case)
    out = output_file(out, "--out", renamed=True, suffixes=NETCDF_SUFFIXES)
    if duration is not None:
        c = dataclasses.replace(c, duration=parse_quantity(duration, "time", "--duration"))
    con = make_console(stderr=True)
    every = None
    if checkpoint_every is not None:
        from ..errors import InputError

        every = parse_quantity(checkpoint_every, "time", "--checkpoint-every")
        if not every > 0:
            raise InputError("--checkpoint-every", f"must be a positive time, got {checkpoint_every!r}",
                             "e.g. '30 s'")
    announce_compilation()
    with writing("--out", out):  # a full disk while streaming: one line; the checkpoint (if any) allows --resume
        res = run_sim(c, out=out, resume=resume, progress=not (quiet or json_out), console=con,
                      checkpoint_seconds=every, threads=_thread_count(threads))
    summary = dict(res.summary)
    summary["output"] = str(out)
    try:
        summary["steady_state"] = res.steady_state()
    except Exception:  # noqa: BLE001 - a summary must not hide the saved output
        pass
    if json_out:
        typer.echo(json.dumps(summary))
    else:
        con.print(_run_line(out, summary))
        ss = summary.get("steady_state")
        if ss:
            con.print(f"last half of the run: heat {ss['heat_generation_total_W']:.4g} W (ball-inner "
                      f"{ss['power_loss_inner']:.4g}, ball-outer {ss['power_loss_outer']:.4g}, ball-cage "
                      f"{ss['power_loss_cage']:.4g}, land {ss['power_loss_land']:.4g}; rolling resistance "
                      f"{ss['power_loss_rolling']:.4g} of the raceway terms); inner-ring friction torque "
                      f"{ss['inner_ring_friction_torque']:.4g} N·m; cage {ss['cage_angular_speed']:.5g} rad/s")
            if ss.get("cage_pocket_deformation_max", 0.0) > 0:
                con.print("elastic cage: largest pocket displacement "
                          f"{ss['cage_pocket_deformation_max'] * 1e6:.3g} µm, largest normal stress "
                          f"{ss['cage_peak_stress_max'] / 1e6:.3g} MPa")


def _run_line(out: Path, summary: dict) -> str:
    """The one-line summary of a run (:func:`bearingsim.dynamics.run.simulate`'s ``summary``): this call's
    simulated time, wall time and steps, and for a resumed run the point it resumed at and the whole run's."""
    threads = f"{summary['threads']} " + ("thread" if summary["threads"] == 1 else "threads")
    rate = f"{summary['wall_per_simulated_second']:.4g} wall s per simulated s"
    seg = (f"{summary['simulated_seconds'] * 1e3:.4g} ms simulated in {summary['wall_seconds']:.3g} s "
           f"({rate}, {summary['steps']} steps, {threads})")
    at = summary.get("resumed_at_seconds")
    if at is None:
        return f"wrote {out}: {seg}"
    return (f"wrote {out}: resumed at {at * 1e3:.4g} ms, this run {seg}; whole run "
            f"{summary['run_simulated_seconds'] * 1e3:.4g} ms simulated, {summary['run_steps']} steps")


#: how to write a case file, for the message on a case that is not one
CASE_HOWTO = ("simulate takes a case file: copy examples/spindle-7011.toml, set bearing = {bearing} and the "
              "loads, speed and duration; every key is in the docstring of bearingsim.dynamics.case and "
              "docs/dynamics.md")


def _check_case_path(case: Path) -> None:
    """Refuse a case argument that is not an existing file with the fix for ``simulate``: a bearing name
    (``bearingsim simulate 6205``) is told that the command takes a case file and how to write one."""
    from ..errors import InputError
    from ..io.bearing import catalog_name

    if case.exists():
        return
    name = catalog_name(str(case))
    if name is not None:
        raise InputError("case", f"{str(case)!r} is a bearing of the catalogue, not a case file",
                         CASE_HOWTO.format(bearing=f'"{name}"') + f"; a quasi-static point: bearingsim static {name}")
    raise InputError("case", f"{str(case)!r} does not exist", CASE_HOWTO.format(bearing="the bearing's name or file"))


def register(app: typer.Typer, reproduce_app: typer.Typer | None = None) -> None:
    """Add ``simulate`` to the typer app (``reproduce_app`` is accepted and unused: ``reproduce hub-hysteresis``
    is registered by :mod:`.hysteresis`)."""
    app.command("simulate")(simulate)


__all__ = ["register", "simulate"]


def _thread_count(text: str):
    """``--threads``: "auto" or a whole number in 1..NUMBA_NUM_THREADS (:func:`.stepper.resolve_threads`), with
    the option's own name in the message."""
    from ..dynamics.stepper import resolve_threads
    from ..errors import InputError

    t = text.strip()
    try:
        return resolve_threads(t if t.lower() == "auto" else int(t))
    except ValueError as e:  # int() of a word, or InputError (a ValueError) of a count out of range
        problem = e.problem if isinstance(e, InputError) else f"must be a whole number or auto, got {text!r}"
        raise InputError("--threads", problem, "e.g. --threads 1 for one core; set NUMBA_NUM_THREADS for more") \
            from None
