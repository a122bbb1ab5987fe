"""The ``shaft`` command: a shaft system file (``type = "shaft_system"``, :mod:`bearingsim.io.shaft_system`) solved
on its bearings (:func:`bearingsim.shafts.solve.solve_shaft`), with the stiffness at the tool tip, the supports'
reactions and lives, a speed sweep to netCDF (:func:`bearingsim.shafts.sweep.shaft_sweep`), the natural frequencies
(:func:`bearingsim.shafts.modes.modes`) and an HTML report (:func:`bearingsim.report.shaft.shaft_report`).

Thin: parse the options, call the API, print (trade units on the terminal, SI in ``--json``).
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Optional

import typer

from .console import announce_compilation, make_console, status_text
from .options import JsonOpt, ShaftSpeedOpt

ShaftArg = typer.Argument(..., help='Shaft-system file (TOML, type = "shaft_system"; docs/user-guide/shafts.md)')


def shaft(
    file: Path = ShaftArg,
    speed: ShaftSpeedOpt = None,
    as_json: JsonOpt = False,
    stiffness_at: Optional[str] = typer.Option(
        None, "--stiffness-at", help='Axial position where the system stiffness is reported, e.g. "0 mm" (default: '
        "the file's stiffness_at, else its tool tip)"),
    report: Optional[Path] = typer.Option(None, "--report", help="Folder for report.html and its figures"),
    speeds: Optional[str] = typer.Option(None, "--speeds", help='Speed sweep START:STOP:COUNT (rpm), e.g. '
                                         '"0:20000:21": stiffness at the tool tip, reactions and lives per speed'),
    out: Optional[Path] = typer.Option(None, "--out", help="With --speeds: netCDF file to write (.nc)"),
    plot: Optional[Path] = typer.Option(None, "--plot", help="With --speeds: figure of the stiffness against speed"),
    preloads: Optional[str] = typer.Option(
        None, "--preloads", help='With --speeds: preload sweep of one bearing support, NAME=START:STOP:COUNT (N for '
        'a spring preload, mm for a position preload), e.g. "rear=100 N:600 N:6"'),
    workers: Optional[int] = typer.Option(None, "--workers", help="With --speeds: local processes (default 1)"),
    scheduler: Optional[str] = typer.Option(None, "--scheduler", help="With --speeds: Dask scheduler address "
                                            "tcp://host:port"),
    n_modes: Optional[int] = typer.Option(None, "--modes", help="Number of natural frequencies and mode shapes"),
    gyroscopic: bool = typer.Option(False, "--gyroscopic", help="With --modes: gyroscopic terms at the speed "
                                    "(forward and backward whirl)"),
):
    """Shaft system: a shaft on its bearings (full Jones–Harris bearings, Timoshenko beam), its deflection, the
    stiffness at the tool tip, each support's reaction and each bearing's lives; speed sweeps and modes."""
    from ..errors import InputError
    from ..io.shaft_system import load_shaft_system, with_probe
    from ..units import parse_quantity
    from .output import output_folder

    for name, given in (("--out", out), ("--plot", plot), ("--preloads", preloads), ("--workers", workers),
                        ("--scheduler", scheduler)):
        if speeds is None and given is not None:
            raise InputError(name, "applies to the speed sweep", 'add --speeds START:STOP:COUNT, e.g. --speeds '
                             '"0:20000:21"')
    if workers is not None and not 1 <= workers <= 1024:
        raise InputError("--workers", f"must be in 1..1024, got {workers}", "e.g. --workers 2")
    if workers is not None and scheduler is not None:
        raise InputError("--workers", "the Dask cluster's workers run the sweep", "give --scheduler or --workers")
    if speeds is not None and (n_modes is not None or report is not None):
        raise InputError("--speeds", "a sweep is a run of its own", "run --modes or --report without --speeds")
    if n_modes is not None and not 1 <= n_modes <= 100:
        raise InputError("--modes", f"must be in 1..100, got {n_modes}", "e.g. --modes 6")
    if gyroscopic and n_modes is None:
        raise InputError("--gyroscopic", "applies to the modes", "add --modes N")
    sf = load_shaft_system(file)
    if stiffness_at is not None:
        sf = with_probe(sf, parse_quantity(stiffness_at, "length", "--stiffness-at"), "--stiffness-at")
    omega = sf.system.speed if speed is None else parse_quantity(speed, "speed", "--speed")
    if speeds is not None:
        return _sweep(sf, speeds, out, plot, as_json, preloads, workers or 1, scheduler)
    folder = None
    if report is not None:
        folder = output_folder(report, "--report")
    from ..shafts.solve import solve_shaft

    announce_compilation()
    res = solve_shaft(sf.system, speed=omega)
    modal = None
    if n_modes is not None and res.converged:
        from ..shafts.modes import modes

        modal = modes(res, n_modes, gyroscopic)
    at = sf.stiffness_at if res.converged else None
    if as_json:
        d = res.to_dict(stiffness_at=at)
        d["name"] = sf.system.name
        d["tool_tip_position_m"] = sf.tool_tip
        if modal is not None:
            d["modes"] = modal.to_dict()
        typer.echo(json.dumps(d))
    else:
        print_shaft(sf, res, modal)
    if folder is not None and res.converged:
        from ..report.shaft import shaft_report

        page = shaft_report(sf, res, folder)
        make_console(stderr=as_json).print(f"report written: {page}")
    if not res.converged:
        raise typer.Exit(1)


def _preload_grid(sf, spec: str):
    """``NAME=START:STOP:COUNT`` → (support name, preload values [N or m])."""
    from ..errors import InputError
    from ..shafts.model import BearingSupport
    from ..shafts.sweep import preload_kind
    from ..sweep import parse_grid

    name, sep, grid = spec.partition("=")
    name = name.strip()
    bearings = [s.name for s in sf.system.supports if isinstance(s, BearingSupport)]
    if not sep or name not in bearings:
        raise InputError("--preloads", f"{spec!r} does not name a bearing support of the file" if sep else
                         f"{spec!r} is not NAME=START:STOP:COUNT", f'e.g. --preloads "{bearings[0]}=100 N:600 N:6" '
                         f"(supports: {', '.join(bearings)})")
    values = parse_grid(grid.strip(), preload_kind(sf.system, name), "--preloads")
    if values.size > 101:
        raise InputError("--preloads", f"{values.size} preloads is more than 101", "use fewer preloads")
    return name, values


def _sweep(sf, speeds: str, out, plot, as_json: bool, preloads: str | None = None, workers: int = 1,
           scheduler: str | None = None):
    """``--speeds``: the stiffness at the tool tip, reactions and lives over the speeds (netCDF with ``--out``),
    and over the preloads of one support with ``--preloads``."""
    from ..errors import InputError
    from ..shafts.sweep import shaft_sweep
    from ..sweep import parse_grid
    from .output import FIGURE_SUFFIXES, NETCDF_SUFFIXES, atomic_output, check_suffix, output_file

    grid = parse_grid(speeds, "speed", "--speeds")
    if grid.size > 2001:
        raise InputError("--speeds", f"{grid.size} speeds is more than 2001", "use fewer speeds")
    support, pl = (None, None) if preloads is None else _preload_grid(sf, preloads)
    if sf.stiffness_at is None:
        raise InputError("--stiffness-at", "the file has no tool tip and no stiffness_at: the sweep needs a position",
                         'give --stiffness-at "0 mm" (or a tool_tip load in the file)')
    if plot is not None:
        check_suffix(plot, "--plot", FIGURE_SUFFIXES)
    if out is not None:
        out = output_file(out, "--out", suffixes=NETCDF_SUFFIXES)
    if plot is not None:
        plot = output_file(plot, "--plot", suffixes=FIGURE_SUFFIXES)
    announce_compilation()
    res = shaft_sweep(sf.system, grid, sf.stiffness_at, support, pl, out=out, workers=workers, scheduler=scheduler,
                      attrs={"source_file": str(sf.path)})
    if out is not None:
        import xarray as xr

        ds = xr.load_dataset(res)
    else:
        ds = res
    if plot is not None:
        from ..report.shaft import plot_sweep

        with atomic_output(plot, "--plot", default_suffix=".png") as tmp:
            plot_sweep(ds, tmp)
    conv = ds["converged"].values.astype(bool)
    keys = (("radial_stiffness", "radial_stiffness_N_per_m"), ("axial_stiffness", "axial_stiffness_N_per_m"),
            ("tilt_stiffness", "tilt_stiffness_N_m_per_rad"))
    if as_json:
        d = {"name": sf.system.name, "position_m": sf.stiffness_at, "speed_rad_s": [float(v) for v in grid]}
        if pl is not None:
            d |= {"preload_support": support, "preload_units": ds["preload"].attrs["units"],
                  "preload": [float(v) for v in pl]}
        d["converged"] = conv.tolist()
        d |= {k: _nums(ds[v].values) for v, k in keys}
        d |= {"out": str(out) if out is not None else None, "plot": str(plot) if plot is not None else None}
        typer.echo(json.dumps(d))
    else:
        from rich.table import Table

        con = make_console()
        t = Table(title=f"{sf.system.name}: stiffness at x = {sf.stiffness_at * 1e3:.4g} mm against speed"
                  + ("" if pl is None else f" and the preload of {support}"))
        cols = ("speed rpm", "radial N/µm", "axial N/µm", "tilt N·m/mrad", "converged")
        punit = None if pl is None else ("N" if ds["preload"].attrs["units"] == "N" else "µm")
        for c in ((f"preload {punit}",) if pl is not None else ()) + cols:
            t.add_column(c, justify="right")
        rows = [((), slice(None))] if pl is None else [((f"{p * (1.0 if punit == 'N' else 1e6):.4g}",), i)
                                                        for i, p in enumerate(pl)]
        for lead, i in rows:
            vals = [ds[v].values if pl is None else ds[v].values[i] for v, _ in keys]
            ok = conv if pl is None else conv[i]
            for j, w in enumerate(grid):
                t.add_row(*lead, f"{w * 30 / math.pi:.0f}", _fmt(vals[0][j], 1e-6), _fmt(vals[1][j], 1e-6),
                          _fmt(vals[2][j], 1e-3), "yes" if ok[j] else "[red]no[/]")
        con.print(t)
        for p in (out, plot):
            if p is not None:
                con.print(f"wrote {p}")
    ds.close()
    if not conv.all():
        raise typer.Exit(1)


def _num(v):
    v = float(v)
    return v if math.isfinite(v) else None


def _nums(a):
    """Finite values as floats, NaN as None, nested as the array."""
    import numpy as np

    a = np.asarray(a)
    return [_num(v) for v in a] if a.ndim == 1 else [_nums(r) for r in a]


def _fmt(v, f: float, spec: str = ".4g") -> str:
    v = float(v)
    return "—" if not math.isfinite(v) else format(v * f, spec)


def print_shaft(sf, res, modal=None) -> None:
    """Readable tables of a :class:`~bearingsim.shafts.solve.ShaftResult` (µm, mrad, N, N·m, N/µm, N·m/mrad,
    hours, MPa; display only)."""
    import numpy as np
    from rich.table import Table

    from ..life import hours_text
    from ..report.shaft import max_pressure

    con = make_console()
    con.print(f"[bold]{sf.system.name}[/]  speed {res.speed * 30 / math.pi:.0f} rpm: "
              f"{status_text(res.converged, res.status, res.iterations, res.residual)}; {len(res.nodes)} nodes, "
              f"{res.nodes[0] * 1e3:.4g} … {res.nodes[-1] * 1e3:.4g} mm")
    u = res.displacement
    radial = np.hypot(u[:, 1], u[:, 2])
    i = int(np.argmax(radial))
    con.print(f"largest radial deflection {radial[i] * 1e6:.4g} µm at x = {res.nodes[i] * 1e3:.4g} mm; "
              f"largest slope {np.max(np.hypot(u[:, 3], u[:, 4])) * 1e3:.4g} mrad")
    if sf.stiffness_at is not None and res.converged:
        k = res.direct_stiffness_at(sf.stiffness_at)
        j = int(np.argmin(np.abs(res.nodes - sf.stiffness_at)))
        what = "tool tip" if sf.tool_tip is not None and abs(sf.tool_tip - sf.stiffness_at) < 1e-9 else "node"
        con.print(f"[bold]stiffness at the {what}[/] (x = {sf.stiffness_at * 1e3:.4g} mm): radial "
                  f"{k['radial_N_per_m'] * 1e-6:.4g} N/µm (y), {k['radial_z_N_per_m'] * 1e-6:.4g} N/µm (z), axial "
                  f"{k['axial_N_per_m'] * 1e-6:.4g} N/µm, tilt {k['tilt_N_m_per_rad'] * 1e-3:.4g} N·m/mrad; "
                  f"deflection there δx = {u[j, 0] * 1e6:.4g} µm, δy = {u[j, 1] * 1e6:.4g} µm, "
                  f"δz = {u[j, 2] * 1e6:.4g} µm, γy = {u[j, 3] * 1e3:.4g} mrad, γz = {u[j, 4] * 1e3:.4g} mrad")
    t = Table(title="supports: reactions on the shaft, misalignment, lives")
    for c in ("support", "x mm", "Fx N", "Fy N", "Fz N", "My N·m", "Mz N·m", "tilt mrad", "L10h", "L10rh",
              "s0", "p_max MPa"):
        t.add_column(c, justify="right")
    for s in res.supports:
        f = s.reaction
        cells = [s.name, f"{s.position * 1e3:.4g}", *(f"{v:.4g}" for v in f),
                 f"{math.hypot(*s.misalignment) * 1e3:.4g}"]
        b = s.bearing_result
        if b is not None:
            d = b.to_dict()
            pm = max_pressure(d)
            s0 = d.get("static_safety_factor")
            cells += [hours_text(d.get("basic_rating_life_hours")), hours_text(d.get("reference_rating_life_hours")),
                      "—" if s0 is None else f"{s0:.3g}", f"{pm * 1e-6:.0f}"]
        else:
            cells += ["spring", "", "", ""]
        t.add_row(*cells)
    con.print(t)
    notes: dict[str, list[str]] = {}
    for s in res.supports:
        if s.bearing_result is not None:
            for n in s.bearing_result.to_dict().get("life_notes", ()):
                notes.setdefault(n, []).append(s.name)
    for n, who in notes.items():
        con.print(f"[dim]note ({', '.join(who)}): {n}[/]")
    for w in res.warnings:
        con.print(f"[yellow]warning:[/] {w}")
    if modal is not None:
        m = Table(title="natural frequencies (bearings linearised at the equilibrium)"
                  + (", gyroscopic" if modal.gyroscopic else ""))
        for c in ("mode", "f Hz", "whirl"):
            m.add_column(c, justify="right")
        for k, fr in enumerate(modal.frequency_hz):
            m.add_row(str(k + 1), f"{fr:.5g}", {1: "forward", -1: "backward"}.get(int(modal.whirl[k]), "—"))
        con.print(m)


def register(app: typer.Typer) -> None:
    """Add ``shaft`` to the bearingsim CLI."""
    app.command("shaft")(shaft)


__all__ = ["print_shaft", "register", "shaft"]
