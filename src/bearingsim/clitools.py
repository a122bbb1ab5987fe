"""Small helpers shared by the command-line modules."""

from __future__ import annotations

from typing import Annotated, Optional

import typer

# Options shared by the commands that take one operating point (static, lubrication); strings with units,
# bare numbers in N, N·m and rpm (parse_loads).
BearingArg = Annotated[str, typer.Argument(help="Catalogue name or TOML file")]
FaOpt = Annotated[Optional[str], typer.Option("--fa", help='Axial load along +x, e.g. "1000 N"')]
FrOpt = Annotated[Optional[str], typer.Option("--fr", help="Radial load along +y")]
FzOpt = Annotated[Optional[str], typer.Option("--fz", help="Radial load along +z")]
MomentOpt = Annotated[Optional[str], typer.Option("--moment", help='Moment about z, e.g. "1 N*m"')]
MyOpt = Annotated[Optional[str], typer.Option("--my", help="Moment about y")]
SpeedOpt = Annotated[Optional[str], typer.Option("--speed", help='Inner-ring speed, e.g. "11200 rpm"')]
ControlOpt = Annotated[str, typer.Option("--control", help="Raceway control: outer, inner or auto")]


def make_console(stderr: bool = False):
    """A rich Console; 160 columns wide when the output is not a terminal (pipes, files, CI logs),
    so that tables are not truncated to 80 columns."""
    from rich.console import Console

    con = Console(stderr=stderr)
    if not con.is_terminal:
        con = Console(stderr=stderr, width=160)
    return con


def parse_loads(fa, fr, fz, moment, my):
    """CLI load options (strings with units; bare numbers in N and N·m) → Loads."""
    from .statics.jones_harris import Loads
    from .units import parse_quantity

    return Loads(
        fa=parse_quantity(fa, "force", "--fa") if fa is not None else 0.0,
        fr_y=parse_quantity(fr, "force", "--fr") if fr is not None else 0.0,
        fr_z=parse_quantity(fz, "force", "--fz") if fz is not None else 0.0,
        m_y=parse_quantity(my, "moment", "--my") if my is not None else 0.0,
        m_z=parse_quantity(moment, "moment", "--moment") if moment is not None else 0.0,
    )
