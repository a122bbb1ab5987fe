"""Option types shared by the commands, each declared once (typer ``Annotated`` types).

Quantities are strings with units (``"1000 N"``, ``"11200 rpm"``); bare numbers are in N, N·m and rpm.  The load
and speed options come in two kinds built by one function each: a single operating point (``static``,
``lubrication``, ``export ross``) and a grid ``START:STOP:COUNT`` (inclusive) or a single value (``map``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

BearingArg = Annotated[str, typer.Argument(help="Catalogue name or TOML file")]
ControlOpt = Annotated[str, typer.Option("--control", help="Raceway control: outer, inner or auto")]
JsonOpt = Annotated[bool, typer.Option("--json", help="Print one JSON object in SI units")]

#: the load options: (option name, what it is, example value, example grid, unit of a bare number)
_LOADS = (
    ("--fa", "Axial load along +x", "1000 N", "1000:5000:9", "N"),
    ("--fr", "Radial load along +y", "1000 N", "0:2000:5", "N"),
    ("--fz", "Radial load along +z", "1000 N", "0:2000:5", "N"),
    ("--moment", "Moment about z", "1 N*m", "-50:50:11", "N·m"),
    ("--my", "Moment about y", "1 N*m", "-50:50:11", "N·m"),
)


def _help(what: str, example: str, unit: str, grid: bool) -> str:
    if grid:
        return f'{what} ({unit}): value or grid START:STOP:COUNT, e.g. "{example}"'
    return f'{what} ({unit}), e.g. "{example}"'


def load_options(grid: bool) -> tuple:
    """The five load option types (--fa, --fr, --fz, --moment, --my) as ``Annotated[Optional[str], ...]``; with
    ``grid`` their help says that each also takes a grid ``START:STOP:COUNT``."""
    out = []
    for name, what, example, example_grid, unit in _LOADS:
        help_ = _help(what, example_grid if grid else example, unit, grid)
        out.append(Annotated[Optional[str], typer.Option(name, help=help_)])
    return tuple(out)


def speed_option(grid: bool):
    """The ``--speed`` option type (inner-ring speed); with ``grid`` it also takes ``START:STOP:COUNT``."""
    help_ = _help("Inner-ring speed", "0:11200:41" if grid else "11200 rpm", "rpm", grid)
    return Annotated[Optional[str], typer.Option("--speed", help=help_)]


def out_option(help: str, *aliases: str, optional: bool = False):
    """The ``--out`` option type (a file or a folder, as ``help`` says; the default is the command's; with
    ``optional`` the option may be left out: None)."""
    return Annotated[Optional[Path] if optional else Path, typer.Option("--out", *aliases, help=help)]


FaOpt, FrOpt, FzOpt, MomentOpt, MyOpt = load_options(grid=False)
FaGrid, FrGrid, FzGrid, MomentGrid, MyGrid = load_options(grid=True)
SpeedOpt = speed_option(grid=False)
SpeedGrid = speed_option(grid=True)
OutFolder = out_option("Folder for the CSV and the plot")


def parse_loads(fa, fr, fz, moment, my):
    """The single-point load options (strings with units; bare numbers in N and N·m) → ``Loads`` [N, N·m]."""
    from ..statics.jones_harris import Loads
    from ..units import parse_quantity

    return Loads(
        fa=parse_quantity(fa, "force", "--fa") if fa is not None else 0.0,
        fr_y=parse_quantity(fr, "force", "--fr") if fr is not None else 0.0,
        fr_z=parse_quantity(fz, "force", "--fz") if fz is not None else 0.0,
        m_y=parse_quantity(my, "moment", "--my") if my is not None else 0.0,
        m_z=parse_quantity(moment, "moment", "--moment") if moment is not None else 0.0,
    )


def parse_speed(speed) -> float:
    """The single-point ``--speed`` option → inner-ring angular speed [rad/s] (0 when not given)."""
    from ..units import parse_quantity

    return parse_quantity(speed, "speed", "--speed") if speed is not None else 0.0
