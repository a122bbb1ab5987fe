"""Commands of the quasi-static model: ``catalog``, ``static`` and ``reproduce spindle-axial-stiffness``.

Thin: parse the options (:mod:`.options`), call the API (:func:`bearingsim.statics.jones_harris.solve`), print.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import typer

from . import options
from .console import announce_compilation, make_console
from .options import (
    BearingArg,
    ControlOpt,
    FaOpt,
    FrOpt,
    FzOpt,
    JsonOpt,
    MomentOpt,
    MyOpt,
    SpeedOpt,
    out_option,
)


def catalog():
    """List the built-in bearing catalogue."""
    from rich.table import Table

    from ..io import catalog_entries

    t = Table(title="bearingsim catalogue")
    t.add_column("name")
    t.add_column("type")
    t.add_column("description")
    for e in catalog_entries():
        t.add_row(e["name"], e["type"], e["description"])
    make_console().print(t)


def static(
    bearing: BearingArg,
    fa: FaOpt = None,
    fr: FrOpt = None,
    fz: FzOpt = None,
    moment: MomentOpt = None,
    my: MyOpt = None,
    speed: SpeedOpt = None,
    control: ControlOpt = "outer",
    as_json: JsonOpt = False,
):
    """Quasi-static equilibrium (Jones–Harris with centrifugal force and gyroscopic moment)."""
    from ..io import load_bearing
    from ..statics.jones_harris import solve

    announce_compilation()
    b = load_bearing(bearing)
    loads = options.parse_loads(fa, fr, fz, moment, my)
    omega = options.parse_speed(speed)
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

    con = make_console()
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


SpindleOut = out_option("Folder for the CSV and the Fig. 5 plot")


def reproduce_spindle(
    out: SpindleOut = Path("out"),
    bearing: str = typer.Option("skf-7011-cdga-hc", "--bearing", help="Bearing to use (catalogue or TOML)"),
):
    """Axial stiffness of the SKF 7011 spindle bearing vs load and speed ([S0] in docs/references.md): tables
    T1–T3 side by side with the paper, its Fig. 5 as a plot, and a CSV."""
    from ..io import load_bearing
    from ..studies.spindle import run_study
    from .output import output_folder, write_study

    announce_compilation()
    out = output_folder(out, "--out")
    study = run_study(load_bearing(bearing))
    con = make_console()
    study.print_tables(con)
    csv, png = write_study(study, out, "spindle_axial_stiffness.csv", "spindle_axial_stiffness_fig5.png")
    con.print(f"wrote {csv} and {png}")


def register(app: typer.Typer, reproduce_app: typer.Typer | None = None) -> None:
    """Add ``catalog``, ``static`` and (with ``reproduce_app``) ``reproduce spindle-axial-stiffness``."""
    app.command("catalog")(catalog)
    app.command("static")(static)
    if reproduce_app is not None:
        reproduce_app.command("spindle-axial-stiffness")(reproduce_spindle)


__all__ = ["catalog", "print_static", "register", "reproduce_spindle", "static"]
