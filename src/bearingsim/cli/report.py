"""The ``report`` command: one operating point of a bearing as an HTML page with its figures
(:func:`bearingsim.report.bearing.bearing_report`)."""

from __future__ import annotations

import shlex
import sys
from pathlib import Path
from typing import Optional

import typer

from . import options
from .console import announce_compilation, make_console
from .options import BearingArg, ControlOpt, FaOpt, FrOpt, FzOpt, MomentOpt, MyOpt, SpeedOpt


def report(
    ctx: typer.Context,
    bearing: BearingArg,
    out: options.out_option("Folder for report.html and its figures (created if missing)") = Path("report"),
    fa: FaOpt = None,
    fr: FrOpt = None,
    fz: FzOpt = None,
    moment: MomentOpt = None,
    my: MyOpt = None,
    speed: SpeedOpt = None,
    lubricant: Optional[str] = typer.Option(None, "--lubricant",
                                            help="Library name or TOML: adds friction torque and heat"),
    temperature: str = typer.Option("60 degC", "--temperature", help='Operating temperature, e.g. "60 degC"'),
    map_file: Optional[Path] = typer.Option(None, "--map", help="A map file (bearingsim map --out) for the "
                                                                "stiffness-vs-speed figure"),
    control: ControlOpt = "outer",
    tilt: str = typer.Option("free", "--tilt", help="Inner-ring tilt: free (moment equilibrium) or fixed (held at "
                             "--misalignment, reaction moment reported)"),
    misalignment: Optional[str] = typer.Option(None, "--misalignment",
                                               help='With --tilt fixed: tilt about z, e.g. "0.5 mrad" (default 0)'),
):
    """Write an HTML report (inputs and sources, results in engineering units, lives, safety, friction, plots)."""
    from ..io import check_path
    from ..report.bearing import bearing_report
    from ..units import parse_quantity
    from .output import output_folder
    from .static import _tilt_options

    b_loads = options.parse_loads(fa, fr, fz, moment, my)
    tilt_mode, gamma = _tilt_options(tilt, misalignment)
    omega = options.parse_speed(speed)
    t = parse_quantity(temperature, "temperature", "--temperature") if lubricant is not None else None
    if map_file is not None:
        check_path(map_file, "--map")
    from ..io import load_bearing

    b = load_bearing(bearing)  # read (and refused) before the output folder is created
    announce_compilation()
    folder = output_folder(out)
    page = bearing_report(b, b_loads, omega, out_dir=folder, lubricant=lubricant, temperature=t, control=control,
                          map_file=map_file, tilt=tilt_mode, misalignment=gamma,
                          command=shlex.join(["bearingsim", *sys.argv[1:]]),  # shown in the report, with the
                          given={p for p in ctx.params if ctx.get_parameter_source(p).name != "DEFAULT"})  # defaults
    make_console().print(f"report written: {page}")


def register(app: typer.Typer) -> None:
    """Add ``report`` to the bearingsim CLI."""
    app.command("report")(report)


__all__ = ["register", "report"]
