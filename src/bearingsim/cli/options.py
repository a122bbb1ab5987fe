"""Option types shared by the commands, each declared once (typer ``Annotated`` types).

Quantities are strings with units (``"1000 N"``, ``"11200 rpm"``); bare numbers are in N, N·m and rpm.  The load
and speed options come in two kinds built by one function each: a single operating point (``static``,
``lubrication``, ``export ross``) and a grid ``START:STOP:COUNT`` (inclusive) or a single value (``map``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer
from typer.core import TyperGroup

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
ShaftSpeedOpt = Annotated[Optional[str], typer.Option(
    "--speed", help='Shaft speed instead of the file\'s, e.g. "8000 rpm" (bare number: rpm)')]
SpeedGrid = speed_option(grid=True)
OutFolder = out_option("Folder for the CSV and the plot")


def refuse_repeated_options(command, name: str, parent, args: list[str]) -> None:
    """Raise a usage error (exit 2, one line) when ``args`` give one option of ``command`` more than once
    (``--fr 2000 --fr 3000``): click keeps the last value silently.  Options declared to be repeated
    (``multiple``, ``count``) and eager ones (``--help``) are let through.  ``args`` are parsed a first time here
    with ``resilient_parsing`` (errors are left to the command's own parse)."""
    ctx = command.context_class(command, info_name=name, parent=parent, resilient_parsing=True)
    _, _, order = command.make_parser(ctx).parse_args(list(args))
    seen = set()
    for param in order:
        if getattr(param, "param_type_name", "") != "option" or param.multiple or param.count or param.is_eager:
            continue
        if param.name in seen:
            ctx.fail(f"Option '{param.opts[0]}' is given more than once; give it once.")
        seen.add(param.name)


class SingleUseOptions(TyperGroup):
    """The command group of the app and its sub-groups (``typer.Typer(cls=SingleUseOptions)``): every command
    resolved through it refuses an option given twice (:func:`refuse_repeated_options`)."""

    def resolve_command(self, ctx, args):
        name, cmd, rest = super().resolve_command(ctx, args)
        if cmd is not None and not isinstance(cmd, TyperGroup):  # a sub-group checks its own commands
            refuse_repeated_options(cmd, name, ctx, rest)
        return name, cmd, rest


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
