"""Commands of the quasi-static maps: ``map``, ``export ross`` and ``reproduce hub-static``.

Options take quantities with units as strings; grids are ``START:STOP:COUNT`` (inclusive); bare numbers are in N,
N·m and rpm.  Registered on the app by :func:`register`.
"""

from __future__ import annotations

import contextlib
import json
import math
import time
from pathlib import Path
from typing import Optional

import typer

from . import options
from .console import announce_compilation, make_console
from .options import (
    BearingArg,
    ControlOpt,
    FaGrid,
    FaOpt,
    FrGrid,
    FrOpt,
    FzGrid,
    FzOpt,
    MomentGrid,
    MomentOpt,
    MyGrid,
    MyOpt,
    OutFolder,
    SpeedGrid,
    out_option,
)

MapOut = out_option("netCDF file to write (streamed, atomic)", optional=True)
RossOut = out_option("JSON file (coefficients); a .toml name saves a ross.BearingElement")

def map_cmd(
    bearing: BearingArg,
    fa: FaGrid = None,
    fr: FrGrid = None,
    fz: FzGrid = None,
    moment: MomentGrid = None,
    my: MyGrid = None,
    speed: SpeedGrid = None,
    preload: Optional[str] = typer.Option(None, "--preload", help="Preload per row, value or grid (N); sets only"),
    control: ControlOpt = "outer",
    out: MapOut = None,
    workers: Optional[int] = typer.Option(None, "--workers", help="Local processes (default: all cores)"),
    scheduler: Optional[str] = typer.Option(None, "--scheduler", help="Dask scheduler address tcp://host:port"),
    worker_timeout: float = typer.Option(60.0, "--worker-timeout",
                                         help="With --scheduler: fail after this many seconds without workers"),
    chunk: int = typer.Option(2000, "--chunk", help="Points per block"),
    plot: Optional[Path] = typer.Option(None, "--plot", help="Write a K_xx stiffness map (PNG)"),
    as_json: bool = typer.Option(False, "--json", help="Print a JSON summary in SI"),
    rings: Optional[str] = typer.Option(None, "--rings", help="Ring model: rigid, or fe (elastic rings and seats by "
                                        "finite elements, coefficients computed once and cached on disk; "
                                        "docs/rings.md); default: the bearing file's [rings] model"),
):
    """Quasi-static map over a grid of loads, speeds and preloads (xarray / netCDF)."""
    from ..sweep import map_grid, plot_map
    from .output import FIGURE_SUFFIXES, NETCDF_SUFFIXES, apply_umask, atomic_output, check_suffix, output_file, writing

    def opt(v):
        return 0.0 if v is None else v

    from ..errors import InputError
    from ..io import load_bearing
    from ..rings.spec import RING_MODELS, model_of

    b = load_bearing(bearing)  # a bad bearing file is refused before any output folder is created
    if rings is not None:
        rings = str(rings).strip().lower()
        if rings not in RING_MODELS:
            raise InputError("--rings", f"unknown ring model {rings!r}", "use rigid or fe")
    else:
        rings = model_of(b)
    # both outputs checked (folders created) before the map is computed, both types before either folder
    if plot is not None:
        check_suffix(plot, "--plot", FIGURE_SUFFIXES)
    if out is not None:
        out = output_file(out, "--out", renamed=True, suffixes=NETCDF_SUFFIXES)
    if plot is not None:
        plot = output_file(plot, "--plot", suffixes=FIGURE_SUFFIXES)
    announce_compilation()
    if scheduler is None:
        # kernels compiled (first run) or loaded here, with the note, before local worker processes start:
        # they then load them from the cache instead of each compiling them silently behind the progress bar
        from ..sweep import warm_up

        with contextlib.suppress(Exception):  # a warm-up never stops the map: its errors come from map_grid
            warm_up(bearing)
    t0 = time.perf_counter()
    # a full disk while streaming: map_grid removes its temporary file; one line here
    with writing("--out", out) if out is not None else contextlib.nullcontext():
        ds = map_grid(bearing, fa=opt(fa), fr=opt(fr), fr_z=opt(fz), m_y=opt(my), moment=opt(moment),
                      speed=opt(speed), preload=preload, control=control, out=out, workers=workers,
                      scheduler=scheduler, chunk_points=chunk, progress=not as_json,
                      worker_timeout=worker_timeout, rings=rings, notify=None if as_json else make_console().print)
    if out is not None:
        apply_umask(out)
    dt = time.perf_counter() - t0
    npts = int(ds["converged"].size)
    nconv = int(ds["converged"].sum())
    png = None
    if plot is not None:
        with atomic_output(plot, "--plot", default_suffix=".png") as tmp:
            plot_map(ds, tmp)
        png = plot
    summary = {"bearing": ds.attrs.get("bearing", bearing), "points": npts, "converged": nconv,
               "seconds": dt, "points_per_second": npts / dt if dt > 0 else None, "rings": rings,
               "dims": {d: int(n) for d, n in ds.sizes.items() if d not in ("dof", "dof2")},
               "out": str(out) if out is not None else None, "plot": str(png) if png else None}
    if as_json:
        typer.echo(json.dumps(summary))
    else:
        con = make_console()
        con.print(f"{summary['bearing']}: {npts} points, {nconv} converged, {dt:.2f} s "
                  f"({summary['points_per_second']:.0f} points/s)"
                  + (", elastic rings (finite elements)" if rings == "fe" else ""))
        if out is not None:
            con.print(f"wrote {out}")
        if png:
            con.print(f"wrote {png}")
    ds.close()
    if nconv < npts:
        raise typer.Exit(1)


def export_ross(
    bearing: BearingArg,
    speed: SpeedGrid = "0:10000:11",
    fa: FaOpt = None,
    fr: FrOpt = None,
    fz: FzOpt = None,
    moment: MomentOpt = None,
    my: MyOpt = None,
    control: ControlOpt = "outer",
    out: RossOut = Path("bearing_ross.json"),
    node: int = typer.Option(0, "--node", help="Shaft node for the ROSS element (.toml output)"),
):
    """Speed-dependent stiffness for ross.BearingElement (kxx, kyy, kxy, kyx, kzz)."""
    from ..export import export_json, to_ross_bearing
    from ..io import load_bearing
    from ..sweep import parse_grid
    from .output import ROSS_SUFFIXES, atomic_output, output_file

    loads = options.parse_loads(fa, fr, fz, moment, my)
    speeds = parse_grid(speed, "speed", "--speed")
    out = output_file(out, "--out", suffixes=ROSS_SUFFIXES)
    announce_compilation()
    b = load_bearing(bearing)
    if out.suffix.lower() == ".toml":
        el = to_ross_bearing(b, node, speeds, loads, control)
        with atomic_output(out, "--out") as tmp:
            if out.is_file() and tmp != out:  # ROSS adds the element to an existing file's elements
                import shutil

                shutil.copyfile(out, tmp)
            el.save(tmp)
    else:
        with atomic_output(out, "--out") as tmp:
            export_json(b, speeds, tmp, loads, control)
    make_console().print(f"wrote {out} ({speeds.size} speeds, {speeds[0] * 30 / math.pi:.0f}–"
                     f"{speeds[-1] * 30 / math.pi:.0f} rpm); ROSS takes kxx, kyy, kxy, kyx, kzz — tilt and "
                     "translation–tilt terms are dropped (listed in the JSON)")


#: the most moments ``reproduce hub-static`` takes (401 moments took 2.1 s wall with the start-up)
MAX_HUB_POINTS = 10_001


def reproduce_hub_static(
    out: OutFolder = Path("out"),
    bearing: str = typer.Option("hub-seed001", "--bearing", help="Hub unit (catalogue or TOML)"),
    vehicle_speed: Optional[str] = typer.Option(None, "--vehicle-speed",
                                                help="Vehicle speed in km/h (default: at rest)"),
    points: int = typer.Option(25, "--points", help="Number of moments from -600 to +600 N·m"),
):
    """Hub unit of Sakaguchi & Shibutani [S1]: tilt of the hub unit's inner ring vs moment (quasi-static reference)."""
    import numpy as np

    from ..errors import InputError
    from ..io import load_bearing
    from ..studies import hub_static as hs
    from .output import output_folder, write_study

    if not 2 <= points <= MAX_HUB_POINTS:
        raise InputError("--points", f"must be in 2..{MAX_HUB_POINTS}, got {points}", "e.g. --points 25")
    b = load_bearing(bearing)
    hs.check_hub(b, "--bearing")
    w = 0.0
    if vehicle_speed is not None:
        try:
            v = float(str(vehicle_speed).replace("km/h", "").strip())
        except ValueError:
            raise InputError("--vehicle-speed", f"not a number of km/h: {vehicle_speed!r}", "e.g. 50") from None
        w = hs.vehicle_speed_to_shaft(v)
    out = output_folder(out, "--out")
    announce_compilation()
    res = hs.run_study(b, np.linspace(-hs.M_MAX, hs.M_MAX, points), speed=w)
    typer.echo(res.table())
    csv, png = write_study(res, out, "hub_static.csv", "hub_static.png")
    make_console().print(f"wrote {csv} and {png}")
    if not res.converged.all():
        raise typer.Exit(1)


def register(app: typer.Typer, reproduce_app: typer.Typer | None = None) -> None:
    """Add ``map``, ``export ross`` and (when ``reproduce_app`` is given) ``reproduce hub-static``."""
    app.command("map")(map_cmd)
    export_app = typer.Typer(no_args_is_help=True, help="Export bearing coefficients to other codes.")
    export_app.command("ross")(export_ross)
    app.add_typer(export_app, name="export")
    if reproduce_app is not None:
        reproduce_app.command("hub-static")(reproduce_hub_static)


__all__ = ["export_ross", "map_cmd", "register", "reproduce_hub_static"]
