"""``bearingsim clearance``: the operating clearance of a bearing after mounting fits, temperatures and speed.

Thin: the options become a :class:`bearingsim.statics.clearance.OperatingClearance` (Lamé fits, thermal and
centrifugal expansion; equations in that module), applied to the bearing; µm and MPa on the screen, SI in
``--json``.
"""

from __future__ import annotations

import json
import math
from typing import Annotated, Optional

import typer

from .console import make_console
from .options import BearingArg, JsonOpt, SpeedOpt  # --speed: the inner ring's centrifugal expansion

ShaftFitOpt = Annotated[Optional[str], typer.Option(
    "--shaft-fit", help='Shaft tolerance class (ISO 286, e.g. k5, m6, js6: the mean interference against a '
    'normal-class bore is used) or the diametral interference of the inner ring, e.g. "12 um" (negative: loose; '
    "bare number in µm)")]
HousingFitOpt = Annotated[Optional[str], typer.Option(
    "--housing-fit", help='Housing tolerance class (ISO 286, e.g. H7, J7, K7, N7: mean interference against a '
    'normal-class outside diameter) or the diametral interference of the outer ring, e.g. "5 um" (negative: '
    "loose; bare number in µm)")]
TemperaturesOpt = Annotated[Optional[str], typer.Option(
    "--temperatures", help='Operating temperatures, e.g. "inner=70 degC,outer=55 degC" (also balls=, shaft=, '
    "housing=, reference= (default 20 degC); balls default to the mean of the rings, shaft to inner, housing "
    "to outer)")]
ShaftBoreOpt = Annotated[Optional[str], typer.Option("--shaft-bore", help='Bore of a hollow shaft, e.g. "20 mm"')]
HousingOdOpt = Annotated[Optional[str], typer.Option(
    "--housing-od", help='Outside diameter of the housing, e.g. "120 mm" (default: rigid, infinitely thick)')]
HousingExpOpt = Annotated[Optional[float], typer.Option(
    "--housing-expansion", help="Thermal expansion of the housing in 1/K (default steel 11.5e-6; aluminium "
    "about 23e-6)")]
ShaftExpOpt = Annotated[Optional[float], typer.Option(
    "--shaft-expansion", help="Thermal expansion of the shaft in 1/K (default steel 11.5e-6)")]

#: --temperatures keys → OperatingClearance fields
_TEMPERATURES = {"inner": "inner_ring_temperature", "outer": "outer_ring_temperature", "balls": "ball_temperature",
                 "ball": "ball_temperature", "shaft": "shaft_temperature", "housing": "housing_temperature",
                 "reference": "reference_temperature"}


#: the largest diametral interference a fit option takes: 5 µm per mm of the seat's diameter (the tightest ISO 286
#: classes for bearing seats give ≈ 1 µm/mm), or 1 mm where the file gives no seat diameter [m]
MAX_FIT_PER_DIAMETER = 5e-3
MAX_FIT = 1e-3
#: the temperatures ``--temperatures`` takes [K]: −100 … 500 °C (past every bearing steel's service range)
T_MIN = 173.15
T_MAX = 773.15


def _fit(value: str, option: str, bearing) -> tuple[float, dict | None]:
    """A fit option → (diametral interference [m], the tolerance-class details or None): an ISO 286 class
    (:func:`bearingsim.catalogue.fit_interference`, mean of its limits), a bare number in µm, or a length."""
    import re

    from ..catalogue import fit_interference
    from ..errors import InputError
    from ..units import parse_quantity

    text = value.strip()
    seat = "shaft" if option == "--shaft-fit" else "housing"
    row = bearing.rows[0].bearing
    size = row.bore if seat == "shaft" else row.outside_diameter
    if re.fullmatch(r"[a-zA-Z]{1,2}\d", text):
        if not size > 0:
            what = "bore" if seat == "shaft" else "outside_diameter"
            raise InputError(option, f"a tolerance class needs the bearing's {what}, which the file does not give",
                             f"add {what} to the bearing file, or give the interference, e.g. \"10 um\"")
        lo, mean, hi = fit_interference(text, size, seat)
        return mean, {"class": text, "min_m": lo, "mean_m": mean, "max_m": hi}
    try:
        v = float(text) * 1e-6
    except ValueError:
        v = parse_quantity(text, "length", option)
    limit = MAX_FIT_PER_DIAMETER * size if size and size > 0 else MAX_FIT
    if not abs(v) <= limit:
        raise InputError(option, f"an interference of {v * 1e6:.4g} µm is past any mounting fit (at most "
                         f"{limit * 1e6:.4g} µm here, {MAX_FIT_PER_DIAMETER * 1e3:.0f} µm per mm of the seat)",
                         "give a tolerance class (e.g. k5) or the interference in µm, e.g. 10")
    return v, None


def parse_temperatures(text: str) -> dict:
    """``"inner=70 degC,outer=55 degC"`` → {OperatingClearance field: temperature [K]}."""
    from ..errors import InputError
    from ..units import parse_quantity

    out = {}
    for part in (p.strip() for p in text.split(",")):
        if not part:
            continue
        key, sep, value = part.partition("=")
        key = key.strip().lower()
        if not sep or key not in _TEMPERATURES:
            raise InputError("--temperatures", f"{part!r} is not KEY=TEMPERATURE with a known key",
                             f"keys: {', '.join(k for k in _TEMPERATURES if k != 'ball')}, e.g. "
                             '"inner=70 degC,outer=55 degC"')
        if _TEMPERATURES[key] in out:
            raise InputError("--temperatures", f"{key} is given twice", 'give each part once, e.g. "inner=70 degC"')
        t = parse_quantity(value.strip(), "temperature", f"--temperatures {key}")
        if not T_MIN <= t <= T_MAX:
            raise InputError(f"--temperatures {key}", f"{t - 273.15:.6g} °C is outside {T_MIN - 273.15:.0f} … "
                             f"{T_MAX - 273.15:.0f} °C (past any bearing steel's service range)", 'e.g. "70 degC"')
        out[_TEMPERATURES[key]] = t
    return out


def operating_conditions(bearing, shaft_fit=None, housing_fit=None, temperatures=None, speed=None, shaft_bore=None,
                         housing_od=None, housing_expansion=None, shaft_expansion=None):
    """The command's options → (:class:`~bearingsim.statics.clearance.OperatingClearance` (SI), the tolerance
    classes used {"shaft_fit": …, "housing_fit": …})."""
    from ..statics.clearance import OperatingClearance
    from ..units import parse_quantity

    kw, classes = {}, {}
    if shaft_fit is not None:
        kw["shaft_interference"], classes["shaft_fit"] = _fit(shaft_fit, "--shaft-fit", bearing)
    if housing_fit is not None:
        kw["housing_interference"], classes["housing_fit"] = _fit(housing_fit, "--housing-fit", bearing)
    if temperatures:
        kw.update(parse_temperatures(temperatures))
    if speed is not None:
        from ..limits import check_speed

        kw["speed"] = parse_quantity(speed, "speed", "--speed")
        check_speed(kw["speed"], bearing.rows[0].bearing.pitch_diameter, "--speed")
    if shaft_bore is not None:
        kw["shaft_bore"] = parse_quantity(shaft_bore, "length", "--shaft-bore", require_unit=True)
    if housing_od is not None:
        kw["housing_outside_diameter"] = parse_quantity(housing_od, "length", "--housing-od", require_unit=True)
    if housing_expansion is not None:
        kw["housing_expansion"] = housing_expansion
    if shaft_expansion is not None:
        kw["shaft_expansion"] = shaft_expansion
    return OperatingClearance(**kw), {k: v for k, v in classes.items() if v is not None}


def _free_angle(bearing, pd: float) -> float:
    """Free contact angle [rad] with diametral clearance ``pd`` [m]: cos α_f = cos α₀ − P_d/(2A) (Harris &
    Kotzalas 2007 vol. 1 eq. 2.10; α₀ = 0 for a deep-groove bearing, which has no contact angle without
    clearance)."""
    if bearing.kind == "deep_groove" and pd <= 0:
        return 0.0
    base = math.cos(bearing.contact_angle) if bearing.kind == "angular_contact" else 1.0
    return math.acos(min(1.0, max(-1.0, base - pd / (2.0 * bearing.total_curvature_distance))))


def _row_result(bearing, change: dict) -> dict:
    """One row: clearance before/after [m], free contact angles [rad] and the contributions [m, Pa]."""
    before = bearing.diametral_clearance
    after = before + change["diametral_clearance_change_m"]
    out = {"bearing": bearing.name, "type": bearing.kind,
           "diametral_clearance_before_m": before, "diametral_clearance_after_m": after,
           "free_contact_angle_before_rad": _free_angle(bearing, before),
           "free_contact_angle_after_rad": _free_angle(bearing, after), "preloaded": after < 0}
    out.update({k: float(v) for k, v in change.items()})
    return out


def clearance_result(bearing, conditions) -> dict:
    """The JSON object of ``bearingsim clearance``: conditions and per-row results [SI]; for a bearing set also
    the preload at rest before and after (:meth:`OperatingClearance.apply`)."""
    import dataclasses

    from ..geometry import BallBearing

    cond = {f.name: getattr(conditions, f.name) for f in dataclasses.fields(conditions)}
    if isinstance(bearing, BallBearing):
        return {"conditions": cond, "rows": [_row_result(bearing, conditions.change(bearing))]}
    applied = conditions.apply(bearing)
    info = applied.notes.get("operating_clearance", {})
    rows = [_row_result(r.bearing, ch) for r, ch in zip(bearing.rows, info.get("details", []), strict=True)]
    return {"conditions": cond, "rows": rows, "axial_offset_change_m": info.get("axial_offset_change_m"),
            "preload_before_N": info.get("preload_before_N"), "preload_after_N": info.get("preload_after_N")}


def _print(res: dict, name: str) -> None:
    from rich.table import Table

    con = make_console()
    cond = res["conditions"]
    t_ref = cond["reference_temperature"] - 273.15
    temps = ", ".join(f"{lbl} {cond[f] - 273.15:.1f} °C" for lbl, f in (
        ("inner ring", "inner_ring_temperature"), ("outer ring", "outer_ring_temperature"),
        ("balls", "ball_temperature"), ("shaft", "shaft_temperature"), ("housing", "housing_temperature"))
        if cond[f] is not None)
    cls = res.get("tolerance_classes", {})

    def fit_text(key, what):
        c = cls.get(key)
        text = f"{what} {cond[key.replace('_fit', '_interference')] * 1e6:+.1f} µm"
        if c:
            text += f" ({c['class']}: mean of {c['min_m'] * 1e6:+.1f} … {c['max_m'] * 1e6:+.1f} µm)"
        return text

    con.print(f"[bold]{name}[/]: {fit_text('shaft_fit', 'shaft fit')}, {fit_text('housing_fit', 'housing fit')} "
              f"(positive = interference), reference {t_ref:.1f} °C"
              + (f"; {temps}" if temps else "") + f"; speed {cond['speed'] * 30 / math.pi:.0f} rpm")
    t = Table(title="diametral clearance (µm; negative = less clearance / preload)")
    t.add_column("")
    for i, r in enumerate(res["rows"]):
        t.add_column(r["bearing"] if len(res["rows"]) == 1 else f"row {i + 1}", justify="right")
    lines = (("clearance before (mounted free)", "diametral_clearance_before_m", 1e6, ".2f"),
             ("inner raceway: shaft fit", "inner_raceway_fit_m", -1e6, "+.2f"),
             ("outer raceway: housing fit", "outer_raceway_fit_m", 1e6, "+.2f"),
             ("inner raceway: temperature", "inner_raceway_thermal_m", -1e6, "+.2f"),
             ("outer raceway: temperature", "outer_raceway_thermal_m", 1e6, "+.2f"),
             ("balls: temperature (×2)", "ball_thermal_m", -2e6, "+.2f"),
             ("inner raceway: centrifugal", "inner_raceway_centrifugal_m", -1e6, "+.2f"),
             ("change", "diametral_clearance_change_m", 1e6, "+.2f"),
             ("operating clearance", "diametral_clearance_after_m", 1e6, ".2f"),
             ("shaft fit pressure (MPa)", "shaft_fit_pressure_Pa", 1e-6, ".1f"),
             ("housing fit pressure (MPa)", "housing_fit_pressure_Pa", 1e-6, ".1f"),
             ("free contact angle before (deg)", "free_contact_angle_before_rad", 180 / math.pi, ".2f"),
             ("free contact angle after (deg)", "free_contact_angle_after_rad", 180 / math.pi, ".2f"))
    for label, key, scale, fmt in lines:
        t.add_row(label, *[format(r[key] * scale, fmt) for r in res["rows"]])
    con.print(t)
    for r in res["rows"]:
        if r["preloaded"] and r["type"] == "deep_groove":
            con.print(f"[yellow]note:[/] {r['bearing']}: the operating clearance is negative "
                      f"({r['diametral_clearance_after_m'] * 1e6:.2f} µm): the row runs preloaded")
    if res.get("preload_after_N") is not None:
        before = res.get("preload_before_N")
        con.print("preload at rest: " + (f"before {', '.join(f'{v:.0f}' for v in before)} N, " if before else "")
                  + f"after {', '.join(f'{v:.0f}' for v in res['preload_after_N'])} N (axial offset change "
                  f"{res['axial_offset_change_m'] * 1e6:+.2f} µm per row)")


def clearance(
    bearing: BearingArg,
    shaft_fit: ShaftFitOpt = None,
    housing_fit: HousingFitOpt = None,
    temperatures: TemperaturesOpt = None,
    speed: SpeedOpt = None,
    shaft_bore: ShaftBoreOpt = None,
    housing_od: HousingOdOpt = None,
    housing_expansion: HousingExpOpt = None,
    shaft_expansion: ShaftExpOpt = None,
    as_json: JsonOpt = False,
):
    """Operating clearance after interference fits, ring and ball temperatures and speed (Lamé fits, thermal and
    centrifugal expansion; bearingsim.statics.clearance)."""
    from ..io import load_bearing

    b = load_bearing(bearing)
    cond, classes = operating_conditions(b, shaft_fit, housing_fit, temperatures, speed, shaft_bore, housing_od,
                                         housing_expansion, shaft_expansion)
    res = clearance_result(b, cond)
    res["tolerance_classes"] = classes
    if as_json:
        typer.echo(json.dumps({"bearing": getattr(b, "name", str(bearing)), **res}))
    else:
        _print(res, getattr(b, "name", str(bearing)))


def register(app: typer.Typer) -> None:
    """Add ``clearance``."""
    app.command("clearance")(clearance)


__all__ = ["clearance", "clearance_result", "operating_conditions", "parse_temperatures", "register"]
