"""Command-line interface (typer + rich).  Thin: parse, call the API, print.

Bad input raises :class:`~bearingsim.errors.InputError`; :func:`main` turns every exception that ends a command
into one line on stderr and an exit status of :class:`~bearingsim.errors.ExitCode` (usage errors and bad input 2,
failures 1; the table is :func:`bearingsim.clitools.error_message`) — never a traceback, unless
``BEARINGSIM_DEBUG=1``.
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import typer

from .clitools import (  # noqa: F401
    BearingArg,
    ControlOpt,
    FaOpt,
    FrOpt,
    FzOpt,
    MomentOpt,
    MyOpt,
    SpeedOpt,
    announce_compilation,
    parse_loads,
)

app = typer.Typer(add_completion=False, no_args_is_help=True,
                  help="bearingsim: ball bearing statics, stiffness, lubrication and dynamics.")
reproduce_app = typer.Typer(no_args_is_help=True, help="Reproduce the published studies (seed papers).")
app.add_typer(reproduce_app, name="reproduce")


def _print_version(value: bool) -> None:
    if value:
        from . import __version__

        typer.echo(f"bearingsim {__version__}")
        raise typer.Exit(0)


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                 help="Print the version and exit"),
):
    """bearingsim: ball bearing statics, stiffness, lubrication and dynamics."""


def _console():
    from .clitools import make_console

    return make_console()


@app.command()
def catalog():
    """List the built-in bearing catalogue."""
    from rich.table import Table

    from .io import catalog_entries

    t = Table(title="bearingsim catalogue")
    t.add_column("name")
    t.add_column("type")
    t.add_column("description")
    for e in catalog_entries():
        t.add_row(e["name"], e["type"], e["description"])
    _console().print(t)


@app.command()
def static(
    bearing: BearingArg,
    fa: FaOpt = None,
    fr: FrOpt = None,
    fz: FzOpt = None,
    moment: MomentOpt = None,
    my: MyOpt = None,
    speed: SpeedOpt = None,
    control: ControlOpt = "outer",
    as_json: bool = typer.Option(False, "--json", help="Print one JSON object in SI units"),
):
    """Quasi-static equilibrium (Jones–Harris with centrifugal force and gyroscopic moment)."""
    from .io import load_bearing
    from .statics.jones_harris import solve
    from .units import parse_quantity

    announce_compilation()
    b = load_bearing(bearing)
    loads = parse_loads(fa, fr, fz, moment, my)
    omega = parse_quantity(speed, "speed", "--speed") if speed is not None else 0.0
    res = solve(b, loads, omega, control)
    if as_json:
        typer.echo(json.dumps(res.to_dict()))
    else:
        print_static(res)
    if not res.converged:
        raise typer.Exit(1)


def print_static(res) -> None:
    """Readable tables of a :class:`StaticResult` (engineering units for display only)."""
    from rich.table import Table

    con = _console()
    d = res.displacement
    con.print(f"[bold]{getattr(res.bearing, 'name', '')}[/]  speed {res.speed * 30 / math.pi:.0f} rpm, "
              f"control {res.control}: {'converged' if res.converged else '[red]NOT CONVERGED[/]'} "
              f"({res.status}; {res.iterations} iterations, residual {res.residual:.2e} N)")
    con.print(f"displacement: δx = {d[0] * 1e6:.4f} µm, δy = {d[1] * 1e6:.4f} µm, δz = {d[2] * 1e6:.4f} µm, "
              f"γy = {d[3] * 1e3:.5f} mrad, γz = {d[4] * 1e3:.5f} mrad")
    con.print(f"axial stiffness K_xx = {res.axial_stiffness / 1e6:.2f} N/µm;  cage speed "
              f"{res.cage_speed * 30 / math.pi:.1f} rpm")
    c = getattr(res, "clearance", {})
    if c:
        con.print(f"internal clearance: radial {c['radial_internal_clearance_m'] * 1e6:.2f} µm, axial "
                  f"{c['axial_internal_clearance_m'] * 1e6:.2f} µm; axial play {c['axial_play_m'] * 1e6:.2f} µm")
    for w in getattr(res, "warnings", ()):
        con.print(f"[yellow]warning:[/] {w}")
    k = Table(title="stiffness matrix (N/µm, N/mrad, N·m/µm, N·m/mrad)")
    k.add_column("")
    names = ("x", "y", "z", "γy", "γz")
    for n in names:
        k.add_column(n, justify="right")
    for i in range(5):
        k.add_row(names[i], *[f"{res.stiffness[i, j] * (1e-6 if j < 3 else 1e-3):.4g}" for j in range(5)])
    con.print(k)
    t = Table(title="balls")
    for c in ("row", "ψ deg", "αi deg", "αo deg", "Qi N", "Qo N", "p_i MPa", "p_o MPa", "ωm rpm", "ωR rpm", "ctrl"):
        t.add_column(c, justify="right")
    b = res.balls
    for j in range(len(b["azimuth_rad"])):
        t.add_row(str(int(b["row"][j])), f"{math.degrees(b['azimuth_rad'][j]):.1f}",
                  f"{math.degrees(b['inner_contact_angle_rad'][j]):.3f}",
                  f"{math.degrees(b['outer_contact_angle_rad'][j]):.3f}",
                  f"{b['inner_load_N'][j]:.1f}", f"{b['outer_load_N'][j]:.1f}",
                  f"{b['inner_max_pressure_Pa'][j] / 1e6:.0f}", f"{b['outer_max_pressure_Pa'][j] / 1e6:.0f}",
                  f"{b['orbital_speed_rad_s'][j] * 30 / math.pi:.1f}", f"{b['spin_speed_rad_s'][j] * 30 / math.pi:.1f}",
                  "inner" if b["inner_control"][j] else "outer")
    con.print(t)


@reproduce_app.command("spindle-axial-stiffness")
def reproduce_spindle(
    out: Path = typer.Option(Path("out"), "--out", help="Folder for the CSV and the Fig. 5 plot"),
    bearing: str = typer.Option("skf-7011-cdga-hc", "--bearing", help="Bearing to use (catalogue or TOML)"),
):
    """Seed 000: tables T1–T3 side by side with the paper, Fig. 5 plot and CSV."""
    from .clitools import atomic_output, output_folder
    from .io import load_bearing
    from .studies.spindle import run_study

    announce_compilation()
    out = output_folder(out, "--out")
    study = run_study(load_bearing(bearing))
    study.print_tables(_console())
    csv, png = out / "spindle_axial_stiffness.csv", out / "spindle_axial_stiffness_fig5.png"
    with atomic_output(csv, "--out") as tmp:
        study.to_csv(tmp)
    with atomic_output(png, "--out") as tmp:
        study.plot(tmp)
    _console().print(f"wrote {csv} and {png}")


from . import cli_cage, cli_dynamics, cli_lubrication, cli_sweep  # noqa: E402  (commands of the topic modules)

cli_cage.register(app)
cli_lubrication.register(app)
cli_sweep.register(app, reproduce_app)
cli_dynamics.register(app, reproduce_app)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``bearingsim`` script: every error ends in one line on stderr and the exit status of
    :class:`~bearingsim.errors.ExitCode` (:func:`bearingsim.clitools.report_error`)."""
    from .clitools import finish_compilation_note, report_error
    from .errors import ExitCode

    try:
        rc = app(args=argv, prog_name="bearingsim", standalone_mode=False)
    except SystemExit:
        finish_compilation_note()
        raise
    except BaseException as exc:  # noqa: BLE001 - the one place where an error becomes a line and a status
        finish_compilation_note()
        sys.exit(report_error(exc))
    finish_compilation_note()
    if isinstance(rc, int) and rc != 0:  # typer.Exit(code) comes back as a return value
        if rc == ExitCode.INTERRUPTED:  # typer turns Ctrl-C into Exit(130)
            typer.echo("aborted", err=True)
        sys.exit(rc)


if __name__ == "__main__":  # pragma: no cover
    main()
