"""Command of the elastic cage model: ``cage-modes``.

Registered on the app by :func:`register`.  Lengths are strings with units
("15 mm"; a bare number is in m, as everywhere in units.py); ``--json`` prints one JSON object in SI; bad input raises
:class:`~bearingsim.errors.InputError` (the main CLI prints it and exits 2).
"""

from __future__ import annotations

import json
from typing import Optional

import typer

from .console import make_console
from .options import BearingArg, JsonOpt


def cage_modes_cmd(
    bearing: BearingArg,
    modes: int = typer.Option(56, "--modes", help="Number of elastic modes (Sakaguchi & Shibutani use 56 per cage)"),
    width: Optional[str] = typer.Option(None, "--width", help='Cage axial width, e.g. "15 mm" (default 1.4 D)'),
    thickness: Optional[str] = typer.Option(None, "--thickness",
                                            help='Cage radial thickness, e.g. "3 mm" (default 0.3 D)'),
    pocket: Optional[str] = typer.Option(None, "--pocket-diameter",
                                         help='Pocket diameter, e.g. "11.3 mm" (default D + 0.2 mm)'),
    elements: int = typer.Option(8, "--elements-per-pitch", help="FE elements per pocket pitch (even, ≥ 4)"),
    as_json: JsonOpt = False,
):
    """Free–free elastic modes of the cage (FE ring model) for mode synthesis in the dynamics.

    Without cage data an ASSUMED steel window cage is used (bearingsim.cage_modes.default_cage_ring:
    on the pitch circle, width 1.4 D, thickness 0.3 D, pockets D + 0.2 mm); a bearing system
    (double row, arrangement) uses its first row's geometry.
    """
    from ..cage_modes import cage_modes, default_cage_ring
    from ..io import load_bearing
    from ..units import parse_quantity

    b = load_bearing(bearing)
    row = b.rows[0].bearing
    over = {}
    for opt, val, key in (("--width", width, "axial_width"), ("--thickness", thickness, "radial_thickness"),
                          ("--pocket-diameter", pocket, "pocket_diameter")):
        if val is not None:
            over[key] = parse_quantity(val, "length", opt)
    ring = default_cage_ring(row.ball_diameter, row.pitch_diameter, row.ball_count, elements_per_pitch=elements,
                             **over)
    res = cage_modes(ring, modes)
    name = getattr(b, "name", bearing)
    if as_json:
        out = {"bearing": name, "cage_assumed": sorted({"axial_width", "radial_thickness", "pocket_diameter"}
                                                        - set(over)),
               **res.summary()}
        typer.echo(json.dumps(out))
        return
    from rich.table import Table

    con = make_console()
    r = ring
    con.print(f"[bold]{name}[/]: cage ring R = {r.pitch_radius * 1e3:.3f} mm, b = {r.axial_width * 1e3:.3f} mm, "
              f"t = {r.radial_thickness * 1e3:.3f} mm, {r.pocket_count} pockets of {r.pocket_diameter * 1e3:.3f} mm, "
              f"steel; {res.fe.n_nodes} nodes ({res.fe.n_dof} DOF)"
              + ("" if over.keys() >= {"axial_width", "radial_thickness", "pocket_diameter"}
                 else "  [yellow](ASSUMED cage dimensions)[/]"))
    t = Table(title=f"{len(res.omega)} free–free elastic modes")
    t.add_column("mode", justify="right")
    t.add_column("f Hz", justify="right")
    t.add_column("kind")
    for i, (f, k) in enumerate(zip(res.frequency_hz, res.kind)):
        t.add_row(str(i + 1), f"{f:.1f}", k)
    con.print(t)
    con.print(f"cage mass {res.mass * 1e3:.2f} g, polar inertia {res.polar_inertia:.4e} kg·m², "
              f"transverse inertia {res.transverse_inertia:.4e} kg·m²")


def register(app: typer.Typer) -> None:
    """Add ``cage-modes`` to the bearingsim CLI."""
    app.command("cage-modes")(cage_modes_cmd)


__all__ = ["register", "cage_modes_cmd"]
