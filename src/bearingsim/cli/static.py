"""Commands of the quasi-static model: ``static`` and ``reproduce spindle-axial-stiffness``.

Thin: parse the options (:mod:`.options`), call the API (:func:`bearingsim.statics.jones_harris.solve`), print.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Optional

import typer

from ..errors import InputError
from . import options
from .console import announce_compilation, make_console, status_text
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


def static(
    bearing: BearingArg,
    fa: FaOpt = None,
    fr: FrOpt = None,
    fz: FzOpt = None,
    moment: MomentOpt = None,
    my: MyOpt = None,
    speed: SpeedOpt = None,
    control: ControlOpt = "outer",
    lubricant: Optional[str] = typer.Option(
        None, "--lubricant", help="Library name (bearingsim lubricants) or TOML: modified rating life (ISO 281 a_ISO) "
        "and friction torque"),
    temperature: Optional[str] = typer.Option(None, "--temperature",
                                              help='Operating (oil) temperature with --lubricant, e.g. "70 degC"'),
    contamination: str = typer.Option(
        "normal", "--contamination", help="Cleanliness level of ISO 281 table 11 (extreme, high, normal, slight, "
        "typical, severe, very_severe) or the factor e_C (0-1)"),
    reliability: float = typer.Option(90.0, "--reliability", help="Reliability in % for the modified life "
                                      "(ISO 281 reliability table: 90, 95, 96, 97, 98, 99 ... 99.95)"),
    rings: Optional[str] = typer.Option(None, "--rings", help="Ring model: rigid, or fe (elastic rings and seats by "
                                        "finite elements, coefficients cached on disk; docs/rings.md); default: "
                                        "the bearing file's [rings] model (rigid without one)"),
    tilt: str = typer.Option("free", "--tilt", help="Inner-ring tilt: free (moment equilibrium: the ring tilts under "
                             "Fr + Fa, the moment loads are the only moments) or fixed (tilt held at --misalignment, "
                             "a stiff shaft in a stiff housing; the reaction moment is reported; docs/life.md)"),
    misalignment: Optional[str] = typer.Option(
        None, "--misalignment", help='With --tilt fixed: tilt of the inner ring about z (the axis of --moment), '
        'e.g. "0.5 mrad" (default 0)'),
    thermal: bool = typer.Option(
        False, "--thermal", help="Thermal operating point (bearingsim.thermal): ring, ball and oil temperatures, the "
        "operating clearance and the lives at them; oil jet at --temperature (default 40 degC) of --lubricant "
        "(default iso-vg-68), 0.6 L/min, estimated cage land"),
    as_json: JsonOpt = False,
):
    """Quasi-static equilibrium (Jones–Harris with centrifugal force and gyroscopic moment), with the ISO 281
    rating lives (hours at the speed), the ISO/TS 16281 reference rating life and the ISO 76 static safety."""
    from ..io import load_bearing
    from ..life import apply_rating, reliability_factor
    from ..statics.jones_harris import solve

    announce_compilation()
    b = load_bearing(bearing)
    loads = options.parse_loads(fa, fr, fz, moment, my)
    omega = options.parse_speed(speed)
    lub, t, assumed = _operating_lubricant(lubricant, temperature, inlet=thermal)
    ec = _contamination(contamination)
    reliability_factor(reliability, "--reliability")
    rings = _ring_model(rings, b)
    tilt, gamma = _tilt_options(tilt, misalignment)
    op = None
    if thermal:
        if rings == "fe" or tilt != "free" or len(b.rows) != 1:
            raise InputError("--thermal", "the thermal operating point takes one row with rigid rings and a free tilt",
                             "drop --rings fe / --tilt fixed, or give a single-row bearing")
        from ..thermal import ThermalSetup, thermal_operating_point

        op = thermal_operating_point(b, loads, omega, lub, ThermalSetup(oil_inlet_temperature=t), control=control)
        res, t = op.result, op.temperatures["oil"]
        res.converged = bool(res.converged and op.converged)
    elif rings == "fe":
        if tilt != "free":
            raise InputError("--tilt", "a held tilt is not available with --rings fe", "use --rings rigid")
        from ..rings.coupling import solve as solve_fe

        res = solve_fe(b, loads, omega, control, rings="fe")
    else:
        res = solve(b, loads, omega, control, tilt=tilt, misalignment=gamma)
    friction = None
    if res.converged:
        apply_rating(res, lub, t, ec, reliability)
        if lub is not None:
            friction = _friction(res, lub, t)
    if as_json:
        from ..rings.coupling import result_dict

        d = result_dict(res)  # the static schema plus "rings": the ring model (and its iterations for fe)
        if friction is not None:
            d["friction"] = friction
            d["friction_torque_N_m"] = friction.get("friction_torque_N_m")
            d["power_loss_W"] = friction.get("power_loss_W")
        if op is not None:
            d["thermal"] = op.to_dict()
        d["assumed"] = assumed
        typer.echo(json.dumps(d))
    else:
        if rings == "fe":
            make_console().print(f"rings: elastic (finite elements, docs/rings.md): {res.ring_iterations} offset "
                                 f"iterations, last change {res.ring_residual * 1e9:.2g} nm")
        print_static(res, friction, assumed)
        if op is not None:
            temps = ", ".join(f"{k.replace('_', ' ')} {v - 273.15:.1f} degC" for k, v in op.temperatures.items())
            make_console().print(f"thermal operating point: {op.status} ({op.iterations} iterations, residual "
                                 f"{op.residual:.2g} K)\n  {temps}\n  operating diametral clearance change "
                                 f"{op.clearance_change * 1e6:+.2f} um; heat {sum(op.heat_removed.values()):.0f} W "
                                 f"(to the oil {op.heat_removed.get('oil_inlet', 0):.0f} W, ambient "
                                 f"{op.heat_removed.get('ambient', 0):.0f} W)" + "".join(f"\n  warning: {w}"
                                                                                    for w in op.warnings))
    if not res.converged:
        raise typer.Exit(1)


def _tilt_options(tilt, misalignment) -> tuple[str, tuple[float, float]]:
    """``--tilt`` free|fixed and ``--misalignment`` (an angle about z, only with fixed) → (mode, (γy, γz) [rad])."""
    from ..units import parse_quantity

    t = str(tilt).strip().lower()
    if t not in ("free", "fixed"):
        raise InputError("--tilt", f"unknown tilt control {tilt!r}", "use free or fixed")
    if misalignment is None:
        return t, (0.0, 0.0)
    if t != "fixed":
        raise InputError("--misalignment", "a misalignment needs the tilt held", "add --tilt fixed")
    gamma = (0.0, parse_quantity(misalignment, "angle", "--misalignment"))
    from ..statics.jones_harris import check_misalignment

    check_misalignment(gamma, "--misalignment")
    return t, gamma


def _ring_model(value, bearing=None) -> str:
    """``--rings``: ``rigid`` or ``fe``; anything else is one line naming the option.  None: the model of the
    bearing file's ``[rings]`` table (:func:`bearingsim.rings.spec.model_of`; rigid without one)."""
    if value is None:
        from ..rings.spec import model_of

        return model_of(bearing)
    v = str(value).strip().lower()
    if v not in ("rigid", "fe"):
        raise InputError("--rings", f"unknown ring model {value!r}", "use rigid or fe")
    return v


def _operating_lubricant(lubricant, temperature, inlet=False, need_lubricant=False):
    """(Lubricant or None, temperature [K] or None, assumed) from the options by the rule of
    :func:`bearingsim.lubrication.operating_conditions`: either option alone makes the command use a lubricant,
    and the one not given is assumed (and said so in the output).  With ``inlet`` (``--thermal``) a lubricant is
    always used and ``--temperature`` is the oil inlet temperature, whose default is the thermal model's
    (:class:`bearingsim.thermal.ThermalSetup`)."""
    from ..lubrication import operating_conditions
    from ..units import parse_quantity

    t = parse_quantity(temperature, "temperature", "--temperature") if temperature is not None else None
    if inlet and t is None:
        from ..thermal import ThermalSetup

        lub, t, assumed = operating_conditions(lubricant, ThermalSetup().oil_inlet_temperature, need_lubricant=True,
                                               lubricant_field="--lubricant", temperature_field="--temperature")
        return lub, t, {**assumed, "oil_inlet_temperature_K": t}
    return operating_conditions(lubricant, t, need_lubricant=inlet or need_lubricant, lubricant_field="--lubricant",
                                temperature_field="--temperature")


def _contamination(value: str):
    """The --contamination option: a level name of ISO 281 table 11 or a factor e_C in [0, 1]."""
    from ..errors import InputError
    from ..life import CONTAMINATION

    try:
        v = float(value)
    except ValueError:
        key = value.strip().lower().replace("-", "_").replace(" ", "_")
        if key not in CONTAMINATION:
            raise InputError("--contamination", f"unknown cleanliness level {value!r}",
                             "use one of " + ", ".join(CONTAMINATION) + " (ISO 281:2007 table 11) or a factor 0-1") \
                from None
        return key
    if not 0.0 <= v <= 1.0:
        raise InputError("--contamination", f"e_C must lie in [0, 1], got {value}", "e.g. --contamination 0.5")
    return v


def _friction(res, lub, t):
    """Friction torque and power loss of the operating point (:func:`bearingsim.friction.friction_summary`),
    None at rest or when the friction model is not available."""
    if res.speed == 0:
        return None
    try:
        from ..friction import friction_summary
    except ImportError:  # pragma: no cover - the friction module is part of the package
        return None
    return friction_summary(res, lub, t)


def _kn(v) -> str:
    return "—" if v is None else f"{v / 1e3:.4g} kN"


def print_rating(con, res, friction=None) -> None:
    """The ratings, lives (hours), static safety and friction of a result, estimates flagged (trade units)."""
    from ..life import hours_text  # (here, not at the top: `bearingsim --help` loads no numerics)

    r = getattr(res, "rating", None)
    if not r:
        return
    est = set(r.get("estimated", ()))

    def flag(key):
        return " [yellow](estimated)[/]" if key in est else ""

    rpm = abs(res.speed) * 30 / math.pi
    con.print(f"ratings: C = {_kn(r['dynamic_load_rating_N'])}{flag('dynamic_load_rating_N')}, "
              f"C0 = {_kn(r['static_load_rating_N'])}{flag('static_load_rating_N')}, "
              f"f0 = {r['geometry_factor_f0']:.3g}{flag('geometry_factor_f0')}, "
              f"Pu = {_kn(r['fatigue_load_limit_N'])}{flag('fatigue_load_limit_N')}")
    con.print(f"equivalent loads: P = {_kn(r['equivalent_dynamic_load_N'])} (ISO 281), "
              f"P0 = {_kn(r['equivalent_static_load_N'])} (ISO 76)")
    l10, l10r = r["basic_rating_life_million_revolutions"], r["reference_rating_life_million_revolutions"]
    at = f" at {rpm:.0f} rpm" if rpm > 0 else ""
    for name, rev, hours, std in (("basic rating life L10", l10, r["basic_rating_life_hours"], "ISO 281"),
                                  ("reference rating life L10r", l10r, r["reference_rating_life_hours"],
                                   "ISO/TS 16281")):
        if rev is not None:
            head = f"{hours_text(hours)}{at} ({rev:.4g} × 10⁶ rev" if hours is not None else f"{rev:.4g} × 10⁶ rev ("
            con.print(f"{name} = {head}, {std})".replace("(, ", "("))
    f = r.get("life_factors", {})
    if r.get("modified_rating_life_hours") is not None or r.get("modified_reference_rating_life_hours") is not None:
        con.print(f"modified rating life (reliability {f['reliability_percent']:g} %, a1 = {f['a1']:.3g}, "
                  f"κ = {f['kappa']:.3g} (ν = {f['viscosity_m2_s'] * 1e6:.3g} mm²/s, ν1 = "
                  f"{f['rated_viscosity_m2_s'] * 1e6:.3g} mm²/s), e_C = {f['e_C']:.2g}): "
                  f"L_nm = {hours_text(r['modified_rating_life_hours'])}"
                  + (f" (a_ISO = {f['a_ISO']:.3g})" if "a_ISO" in f else "")
                  + f", L_nmr = {hours_text(r['modified_reference_rating_life_hours'])}"
                  + (f" (a_ISO = {f['a_ISO_reference']:.3g})" if "a_ISO_reference" in f else ""))
    s0, s0p = r.get("static_safety_factor"), r.get("static_safety_factor_pressure")
    c0_est = "; C0 estimated" if "static_load_rating_N" in est else ""
    con.print("static safety: s0 = C0/P0 = " + ("—" if s0 is None else f"{s0:.3g}") + f" (ISO 76{c0_est})"
              + "; from the maximum contact pressure, (4200 MPa / p_max)³ = "
              + ("—" if s0p is None else f"{s0p:.3g}"))
    for row in r.get("row_ratings") or ():
        lr, s0r = row["reference_rating_life_million_revolutions"], row["static_safety_factor_pressure"]
        lh = row["reference_rating_life_hours"]
        con.print(f"  row {row['row']}: L10r = " + ("—" if lr is None else f"{lr:.4g} × 10⁶ rev")
                  + ("" if lh is None else f" = {hours_text(lh)}") + ", s0 from p_max = "
                  + ("—" if s0r is None else f"{s0r:.3g}"))
    if friction is not None:
        tq, pw = friction.get("friction_torque_N_m"), friction.get("power_loss_W")
        if tq is not None:
            from ..friction import MODEL_LABELS

            con.print(f"friction torque {tq * 1e3:.4g} N·mm, power loss {pw:.4g} W "
                      f"({MODEL_LABELS[friction.get('headline_model', 'palmgren')]})")
    for n in r.get("life_notes", ()):
        con.print(f"[dim]note:[/] {n}")


def print_static(res, friction=None, assumed=None) -> None:
    """Readable tables of a :class:`StaticResult` (engineering units for display only); ``assumed``: the inputs
    :func:`bearingsim.lubrication.operating_conditions` filled in, one line each."""
    from rich.table import Table

    con = make_console()
    d = res.displacement
    con.print(f"[bold]{getattr(res.bearing, 'name', '')}[/]  speed {res.speed * 30 / math.pi:.0f} rpm, "
              f"control {res.control}: {status_text(res.converged, res.status, res.iterations, res.residual)}")
    if assumed:
        from ..lubrication import assumed_phrases

        for line in assumed_phrases(assumed):
            con.print(f"[yellow]note:[/] {line}")
    con.print(f"displacement: δx = {d[0] * 1e6:.4f} µm, δy = {d[1] * 1e6:.4f} µm, δz = {d[2] * 1e6:.4f} µm, "
              f"γy = {d[3] * 1e3:.5f} mrad, γz = {d[4] * 1e3:.5f} mrad")
    if getattr(res, "tilt_mode", "free") == "fixed" and res.reaction_moment is not None:
        m = res.reaction_moment
        con.print(f"tilt held at γy = {res.misalignment[0] * 1e3:.4g} mrad, γz = {res.misalignment[1] * 1e3:.4g} mrad "
                  f"(--tilt fixed): reaction moment M_y = {m[0]:.4g} N·m, M_z = {m[1]:.4g} N·m")
    con.print(f"axial stiffness K_xx = {res.axial_stiffness / 1e6:.2f} N/µm;  cage speed "
              f"{res.cage_speed * 30 / math.pi:.1f} rpm")
    c = getattr(res, "clearance", {})
    if c:
        con.print(f"internal clearance: radial {c['radial_internal_clearance_m'] * 1e6:.2f} µm, axial "
                  f"{c['axial_internal_clearance_m'] * 1e6:.2f} µm; axial play {c['axial_play_m'] * 1e6:.2f} µm")
    print_rating(con, res, friction)
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


#: the bearing of [S0] (the reference values of ``reproduce spindle-axial-stiffness``)
PAPER_BEARING = "skf-7011-cdga-hc"


def reproduce_spindle(
    out: SpindleOut = Path("out"),
    bearing: str = typer.Option(PAPER_BEARING, "--bearing", help="Bearing to use (catalogue or TOML)"),
    rings: str = typer.Option("rigid", "--rings", help="rigid, or fe: adds the axial stiffness with elastic (FE) "
                              "rings next to the paper's FEM column (T3)"),
):
    """Axial stiffness of the SKF 7011 spindle bearing vs load and speed ([S0] in docs/references.md): tables
    T1–T3 side by side with the paper, its Fig. 5 as a plot, and a CSV."""
    from ..io import load_bearing
    from ..studies.spindle import run_study
    from .output import output_folder, write_study

    rings = _ring_model(rings)
    announce_compilation()
    out = output_folder(out, "--out")
    study = run_study(load_bearing(bearing), rings=rings)
    con = make_console()
    study.print_tables(con)
    if bearing != PAPER_BEARING:
        con.print(f"[yellow]note:[/] the paper's columns and the deviations are [S0]'s values for its SKF 7011 CDGA/HC "
                  f"({PAPER_BEARING}), not for {bearing}: they compare two bearings")
    csv, png = write_study(study, out, "spindle_axial_stiffness.csv", "spindle_axial_stiffness_fig5.png")
    con.print(f"wrote {csv} and {png}")


def register(app: typer.Typer, reproduce_app: typer.Typer | None = None) -> None:
    """Add ``static`` and (with ``reproduce_app``) ``reproduce spindle-axial-stiffness``."""
    app.command("static")(static)
    if reproduce_app is not None:
        reproduce_app.command("spindle-axial-stiffness")(reproduce_spindle)


__all__ = ["print_static", "register", "reproduce_spindle", "static"]
