"""Commands of the lubrication module: ``lubrication``, ``lubricants``, ``traction-curve``.

Registered on the app by :func:`register`.  Options take
quantities with units as strings; ``--json`` prints one JSON object in SI; bad input
raises :class:`~bearingsim.errors.InputError` (the main CLI prints it and exits 2).
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
from .output import FIGURE_SUFFIXES, atomic_output, output_file

TractionOut = out_option("Image file to write")


def lubrication(
    bearing: BearingArg,
    fa: FaOpt = None,
    fr: FrOpt = None,
    fz: FzOpt = None,
    moment: MomentOpt = None,
    my: MyOpt = None,
    speed: SpeedOpt = None,
    control: ControlOpt = "outer",
    lubricant: str = typer.Option(None, "--lubricant", help="Library name (bearingsim lubricants) or TOML "
                                  "(not given: iso-vg-68, said so in the output)"),
    temperature: str = typer.Option(None, "--temperature", help='Oil inlet temperature, e.g. "60 degC" (not given: '
                                    '60 degC, said so in the output)'),
    roughness: str = typer.Option("0.1 um", "--roughness", help='Composite rms roughness, e.g. "0.05 um"'),
    slices: int = typer.Option(10, "--slices", help="Slices of each contact ellipse"),
    model: str = typer.Option("mixed", "--model", help="Traction model: mixed, fluid or boundary"),
    lubrication_method: str = typer.Option("oil_bath", "--lubrication-method",
                                           help="Palmgren's f0 column: grease, oil_mist, oil_bath or oil_jet"),
    oil_flow: str = typer.Option(None, "--oil-flow",
                                 help='Jet oil flow for the ball drag (Parker 1984 oil fraction), e.g. "760 cm^3/min"'),
    oil_fraction: float = typer.Option(None, "--oil-fraction",
                                       help="Oil volume fraction of the oil-air mixture for the ball drag, e.g. 0.001"),
    as_json: JsonOpt = False,
):
    """Film thickness, Λ, regime, traction and power loss of every loaded contact (Jones kinematics), and the
    bearing's friction torque and heat (Palmgren and physics-based, bearingsim.friction)."""
    from ..errors import InputError
    from ..friction import METHODS, friction_summary
    from ..io import load_bearing
    from ..lubrication import lubrication_report
    from ..statics.jones_harris import solve
    from ..units import parse_quantity

    announce_compilation()
    b = load_bearing(bearing)
    loads = options.parse_loads(fa, fr, fz, moment, my)
    omega = options.parse_speed(speed)
    if omega == 0.0:
        raise InputError("--speed", "a lubrication report needs a non-zero speed", 'e.g. --speed "3000 rpm"')
    from .static import _operating_lubricant

    lubricant, t, assumed = _operating_lubricant(lubricant, temperature, need_lubricant=True)
    sigma = parse_quantity(roughness, "length", "--roughness")
    if sigma < 0:
        raise InputError("--roughness", "must be >= 0", 'e.g. "0.05 um"')
    from ..contact.slices import STRIPS_MAX  # (larger codes are the kernel's other rules)

    if not 1 <= slices <= STRIPS_MAX:
        raise InputError("--slices", f"must lie in 1..{STRIPS_MAX}, got {slices}", "e.g. 10")
    flow = _parse_flow(oil_flow) if oil_flow is not None else None
    if oil_fraction is not None and not (math.isfinite(oil_fraction) and 0.0 <= oil_fraction <= 1.0):
        raise InputError("--oil-fraction", f"must lie in [0, 1], got {oil_fraction!r}", "e.g. 0.001")
    if lubrication_method not in METHODS:
        raise InputError("--lubrication-method", f"unknown method {lubrication_method!r}",
                         f"use one of {', '.join(METHODS)}")
    res = solve(b, loads, omega, control)
    rep = lubrication_report(res, lubricant, t, sigma, n_slices=slices, model=model)
    rep["friction"] = friction_summary(res, lubricant, t, lubrication_method=lubrication_method, roughness=sigma,
                                       n_slices=slices, traction_model=model, oil_flow=flow,
                                       oil_volume_fraction=oil_fraction)
    # the static solution's limits (contact pressure, contact angle, speed, lift-off), as `static` reports them
    rep["warnings"] = list(getattr(res, "warnings", ()))
    rep["assumed"] = assumed
    if as_json:
        typer.echo(json.dumps(rep))
    else:
        _print_report(rep, getattr(b, "name", bearing))
    if not res.converged:
        raise typer.Exit(1)


def _parse_flow(text: str) -> float:
    """A volume flow with its unit ("760 cm^3/min", "1.2 l/min") as m³/s (pint for the unit only)."""
    import re

    from ..errors import InputError
    from ..units import registry

    m = re.fullmatch(r"\s*([-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(\S.*?)\s*", str(text))
    fix = 'e.g. --oil-flow "760 cm^3/min"'
    if not m:
        raise InputError("--oil-flow", f"expected a number with a volume-flow unit, got {text!r}", fix)
    from pint.errors import PintError

    try:
        unit = registry().Unit(m.group(2))
    except (PintError, ValueError, TypeError, AttributeError, SyntaxError):
        raise InputError("--oil-flow", f"unknown unit {m.group(2)!r}", fix) from None
    if unit.dimensionality != registry().Unit("m^3/s").dimensionality:
        raise InputError("--oil-flow", f"{m.group(2)!r} is not a volume flow", fix)
    value = float((float(m.group(1)) * unit).to("m^3/s").magnitude)
    if not (math.isfinite(value) and value > 0):
        raise InputError("--oil-flow", f"must be positive, got {text!r}", fix)
    return value


def _print_friction(con, f: dict) -> None:
    """Friction torque and heat per source (trade units: mN·m, W)."""
    from rich.table import Table

    from ..friction import METHOD_LABELS, MODEL_LABELS

    t = Table(title=f"friction torque and heat (rotating ring, {METHOD_LABELS[f['lubrication_method']]} for "
                    "Palmgren's f0)")
    for c in ("model", "source", "M mN·m", "P W"):
        t.add_column(c, justify="right")

    def row(model, src, key):
        m = f.get(f"{key}_N_m")
        if m is None:
            return
        p = f.get(f"{key}_W")  # the physical sources carry their power; Palmgren's is M |ω|
        if p is None:
            p = m * abs(f["speed_rad_s"])
        t.add_row(model, src, f"{m * 1e3:.2f}", f"{p:.2f}")

    row("Palmgren", "load M_l", "palmgren_load")
    row("Palmgren", "viscous M_v", "palmgren_viscous")
    row("Palmgren", "total", "palmgren_torque")
    for src in ("rolling", "spin", "sliding", "drag"):
        row("physics-based", src, src)
    row("physics-based", "total", "physical_torque")
    con.print(t)
    con.print(f"friction torque {f['friction_torque_N_m'] * 1e3:.2f} mN·m, heat {f['power_loss_W']:.1f} W "
              f"({MODEL_LABELS[f['headline_model']]})")
    for n in f["notes"]:
        con.print(f"[yellow]note:[/] {n}")


def _print_report(rep: dict, name: str) -> None:
    from rich.table import Table

    con = make_console()
    con.print(f"[bold]{name}[/]  {rep['lubricant']} at {rep['temperature_K'] - 273.15:.1f} °C "
              f"(η₀ = {rep['dynamic_viscosity_Pa_s'] * 1e3:.2f} mPa·s), "
              f"speed {rep['speed_rad_s'] * 30 / math.pi:.0f} rpm, "
              f"σ = {rep['roughness_m'] * 1e6:.3f} µm, model {rep['model']}"
              + ("" if rep["converged"] else "  [red]static solution NOT CONVERGED[/]"))
    t = Table(title="loaded contacts (traction and power at Jones' kinematics)")
    for c in ("ball", "contact", "Q N", "a mm", "b mm", "p_max MPa", "u m/s", "Rx mm", "Ry mm", "h_c µm",
              "h_min µm", "Λ", "regime", "μ", "P W"):
        t.add_column(c, justify="right")
    for bl in rep["balls"]:
        for c in ("inner", "outer"):
            e = bl[c]
            if not e:
                continue
            lam = e["film_parameter"]
            t.add_row(str(bl["index"]), c, f"{e['load_N']:.1f}", f"{e['semi_major_m'] * 1e3:.3f}",
                      f"{e['semi_minor_m'] * 1e3:.3f}", f"{e['max_pressure_Pa'] / 1e6:.0f}",
                      f"{e['entrainment_speed_m_s']:.3f}", f"{e['rx_m'] * 1e3:.3f}", f"{e['ry_m'] * 1e3:.2f}",
                      f"{e['central_film_m'] * 1e6:.4f}", f"{e['minimum_film_m'] * 1e6:.4f}",
                      "∞" if lam is None else f"{lam:.2f}", str(e["regime"]), f"{e['traction_coefficient']:.4f}",
                      f"{e['power_loss_W']:.3f}")
    con.print(t)
    con.print(f"total power loss {rep['total_power_loss_W']:.2f} W")
    if rep.get("friction"):
        _print_friction(con, rep["friction"])
    for w in rep.get("warnings", ()):
        con.print(f"[yellow]warning:[/] {w}")
    from ..lubrication import assumed_phrases

    for line in assumed_phrases(rep.get("assumed") or {}):
        con.print(f"[yellow]note:[/] {line}")


def lubricants(as_json: JsonOpt = False):
    """List the built-in lubricants."""
    from ..lubricants import library

    lib = library()
    if as_json:
        typer.echo(json.dumps({n: lub.summary(333.15) for n, lub in lib.items()}))
        return
    from rich.table import Table

    t = Table(title="bearingsim lubricants (η at 60 °C)")
    t.add_column("name", no_wrap=True)
    for c in ("ν40 cSt", "ν100 cSt", "η mPa·s", "α 1/GPa", "ρ15", "k W/mK", "°C range"):
        t.add_column(c, justify="right")
    for n, lub in lib.items():
        t.add_row(n, f"{lub.kinematic_viscosity(313.15) * 1e6:.1f}", f"{lub.kinematic_viscosity(373.15) * 1e6:.2f}",
                  f"{lub.dynamic_viscosity(333.15) * 1e3:.1f}", f"{lub.pressure_viscosity_coefficient * 1e9:.1f}",
                  f"{lub.density_15:.0f}", f"{lub.thermal_conductivity:.3f}",
                  f"{lub.min_temperature - 273.15:.0f}..{lub.max_temperature - 273.15:.0f}")
    con = make_console()
    con.print(t)
    for n, lub in lib.items():
        con.print(f"{n}: {lub.description}")


def traction_curve(
    out: TractionOut = Path("traction_curve.png"),
    lubricant: str = typer.Option("hub-grease-base-oil", "--lubricant", help="Library name or TOML"),
    temperature: str = typer.Option("60 degC", "--temperature", help="Oil temperature"),
    loads: str = typer.Option("500 N,2000 N,5000 N", "--loads", help="Comma-separated contact loads"),
    speeds: str = typer.Option("1 m/s,5 m/s,20 m/s", "--speeds", help="Comma-separated rolling speeds"),
    s_max: float = typer.Option(0.05, "--s-max", help="Largest slide-roll ratio plotted"),
):
    """Plot the traction coefficient vs slide-roll ratio (as in Sakaguchi & Shibutani [S1], Fig. 4) for one ball
    contact."""
    from ..errors import InputError
    from ..lubrication import plot_traction_curves
    from ..units import _convert, parse_quantity

    t = parse_quantity(temperature, "temperature", "--temperature")
    qs = [parse_quantity(x.strip(), "force", "--loads") for x in loads.split(",") if x.strip()]
    us = [_convert(x.strip() if not x.strip().replace(".", "", 1).isdigit() else x.strip() + " m/s", "m/s", "--speeds")
          for x in speeds.split(",") if x.strip()]
    if not qs or not us or min(qs) <= 0 or min(us) <= 0:
        raise InputError("--loads/--speeds", "give positive loads and speeds", 'e.g. --loads "500 N,2000 N"')
    if not (0 < s_max <= 1):
        raise InputError("--s-max", f"must lie in (0, 1], got {s_max}", "e.g. 0.05")
    out = output_file(out, "--out", suffixes=FIGURE_SUFFIXES)
    announce_compilation()
    fig = plot_traction_curves(lubricant, t, qs, us, s_max=s_max)
    with atomic_output(out, "--out", default_suffix=".png") as tmp:
        fig.savefig(tmp, dpi=120)
    typer.echo(str(out))


def register(app: typer.Typer) -> None:
    """Add ``lubrication``, ``lubricants`` and ``traction-curve`` to the bearingsim CLI."""
    app.command("lubrication")(lubrication)
    app.command("lubricants")(lubricants)
    app.command("traction-curve")(traction_curve)


__all__ = ["register", "lubrication", "lubricants", "traction_curve"]
