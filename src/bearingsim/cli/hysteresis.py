"""``bearingsim reproduce hub-hysteresis CASE.toml``: the hub unit's tilt–moment hysteresis W_H of Sakaguchi &
Shibutani [S1] (Figs. 6–9) over a grid of vehicle speeds and load frequencies (:mod:`bearingsim.studies.hub_dynamic`),
with an optional HTML report (:mod:`bearingsim.studies.hub_report`).  Registered on the app by :func:`register`.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Optional

import typer

from .console import announce_compilation, make_console
from .options import out_option

HysteresisOut = out_option("folder for the cells' runs (resume), the table, JSON and loop plot")


def _numbers(text: str, field: str) -> list[float]:
    from ..errors import InputError

    try:
        vals = [float(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise InputError(field, f"cannot read {text!r}", "give comma-separated numbers, e.g. 10,50,100") from None
    if not vals:
        raise InputError(field, "no value given", "give comma-separated numbers, e.g. 10,50,100")
    return vals


def reproduce_hub_hysteresis(
    case: Path = typer.Argument(..., help="hub case TOML (e.g. examples/hub-moment-50hz.toml)"),
    speeds: str = typer.Option("100", "--speeds", help="vehicle speeds in km/h, comma-separated (seed: 10,50,100)"),
    frequencies: str = typer.Option("50", "--frequencies", help="load frequencies in Hz (seed: 1,10,50)"),
    cycles: int = typer.Option(8, "--cycles", help="load cycles per cell after the start-up cycles"),
    startup: int = typer.Option(2, "--startup-cycles", help="load cycles simulated before them (not periodic yet)"),
    traction: Optional[str] = typer.Option(None, "--traction",
                                           help="physical (lubricated film), curve (fluid law of the paper's "
                                                "Fig. 4 shape), none (default: the case's)"),
    workers: Optional[int] = typer.Option(None, "--workers",
                                          help="local processes (default: one per cell up to the cores)"),
    scheduler: Optional[str] = typer.Option(None, "--scheduler",
                                            help="Dask scheduler address tcp://host:port (one task per cell)"),
    worker_timeout: float = typer.Option(600.0, "--worker-timeout",
                                         help="with --scheduler: fail after this many seconds without workers"),
    finished_only: bool = typer.Option(False, "--finished-only",
                                       help="run nothing: analyse and report the cells already finished in --out"),
    json_out: bool = typer.Option(False, "--json", help="print the cells as JSON (SI except the *_deg fields)"),
    report: Optional[Path] = typer.Option(None, "--report", help="write an HTML report (report.html + figures) here"),
    sensitivity: Optional[Path] = typer.Option(None, "--sensitivity",
                                               help="folder of dynamic sensitivity runs to show in the report "
                                                    "(python -m bearingsim.studies.hub_sensitivity CASE DIR)"),
    out: HysteresisOut = Path("out"),
):
    """Hub-bearing hysteresis (Sakaguchi & Shibutani [S1], Figs. 6–9): loop width W_H of the tilt at 0.3 kN·m per
    vehicle speed and load frequency, with its 95 % interval, loop area, phase lag, compliance against statics,
    the reduced model and the mechanism's bound (long runs; a killed study continues from its --out folder)."""
    from ..errors import InputError
    from ..studies.hub_dynamic import run_study, traction_model
    from .output import atomic_output, output_folder, write_study, writing

    v = _numbers(speeds, "--speeds")
    f = _numbers(frequencies, "--frequencies")
    if workers is not None and workers < 1:
        raise InputError("--workers", f"must be a positive integer, got {workers}", "e.g. --workers 2")
    traction_model(traction)
    if not case.is_file():
        raise InputError("CASE", f"no case file {case}", "give a case TOML, e.g. examples/hub-moment-50hz.toml")
    out = output_folder(out, "--out")
    if sensitivity is not None:
        if report is None:
            raise InputError("--sensitivity", "is shown in the report only", "give --report DIR as well")
        if not sensitivity.is_dir():
            raise InputError("--sensitivity", f"no folder {sensitivity}",
                             "give the folder of python -m bearingsim.studies.hub_sensitivity CASE DIR")
    if report is not None:
        report = output_folder(report, "--report")
    con = make_console()
    err = make_console(stderr=True)
    announce_compilation()
    with writing("--out", out):
        study = run_study(case, v, f, cycles, startup, traction, out_dir=out, workers=workers, scheduler=scheduler,
                          worker_timeout=worker_timeout, progress=not json_out, console=err,
                          finished_only=finished_only)
    csv, png = write_study(study, out, "hub_hysteresis.csv", "hub_hysteresis_loops.png")
    data = study.to_dict()
    with atomic_output(out / "hub_hysteresis.json", "--out") as tmp:
        tmp.write_text(json.dumps(data, indent=1, allow_nan=False))
    html = None
    if report is not None:
        from ..studies.hub_report import write_report

        with writing("--report", report):
            html = write_report(study, report, sensitivity)
    if json_out:
        if html is not None:
            data["report"] = str(html)
        typer.echo(json.dumps(data, allow_nan=False))
        return
    study.print_table(con)
    con.print(f"wrote {csv}, {png} and {out / 'hub_hysteresis.json'}" + (f"; report {html}" if html else ""))


def register(app: typer.Typer, reproduce_app: typer.Typer) -> None:
    """Add ``reproduce hub-hysteresis`` to the ``reproduce`` group."""
    reproduce_app.command("hub-hysteresis")(reproduce_hub_hysteresis)


__all__ = ["register", "reproduce_hub_hysteresis"]
