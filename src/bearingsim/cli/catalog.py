"""``bearingsim catalog``: list and filter the built-in catalogue, or show one entry with the source of every
number (estimates flagged).

Thin: the summaries come from :func:`bearingsim.io.catalog_entries`, one entry from
:func:`bearingsim.io.load_bearing`; trade units on the screen (mm, deg, kN), SI in ``--json``.
"""

from __future__ import annotations

import json
import math
import re
from typing import Annotated, Optional

import typer

from .console import make_console
from .options import JsonOpt

NameArg = Annotated[Optional[str], typer.Argument(help="Show this entry (e.g. 6208, 7205-40) with its sources")]
SeriesOpt = Annotated[Optional[str], typer.Option("--series", help="Only this ISO series, e.g. 62, 63, 70, 72")]
BoreOpt = Annotated[Optional[str], typer.Option("--bore", help='Only this bore (mm), e.g. 40 or "40 mm"')]
TypeOpt = Annotated[Optional[str], typer.Option("--type", help="Only deep_groove, angular_contact or bearing_set")]

#: an ISO designation of the catalogue: series (2 digits), bore code (2 digits), optional "-<contact angle>"
_ISO_NAME = re.compile(r"^(\d{2})(\d{2})(?:-(\d{1,2}))?$")


def series_of(name: str) -> str | None:
    """The ISO series of a catalogue designation (``"6208"`` → ``"62"``, ``"7205-40"`` → ``"72"``), else None."""
    m = _ISO_NAME.match(name)
    return m.group(1) if m else None


def _parse_bore(value: str) -> float:
    """--bore: a bare number in mm, or a length with its unit → [m]."""
    from ..errors import InputError
    from ..units import parse_quantity

    try:
        v = float(value) * 1e-3
    except ValueError:
        v = parse_quantity(value, "length", "--bore")
    if not (math.isfinite(v) and v > 0):
        raise InputError("--bore", f"must be a positive length, got {value!r}", 'e.g. --bore 40 (mm) or "40 mm"')
    return v


def select(entries: list[dict], series: str | None = None, bore: float | None = None,
           kind: str | None = None) -> list[dict]:
    """The catalogue summaries that match every given filter (bore [m] within 1 µm)."""
    from ..errors import InputError

    if series is not None and not re.fullmatch(r"\d{2}", series.strip()):
        raise InputError("--series", f"{series!r} is not an ISO series", "give two digits, e.g. --series 62")
    if kind is not None and kind not in ("deep_groove", "angular_contact", "bearing_set"):
        raise InputError("--type", f"unknown type {kind!r}", "use deep_groove, angular_contact or bearing_set")
    known = sorted({x for x in (series_of(e["name"]) for e in entries) if x is not None})
    if series is not None and series.strip() not in known:
        raise InputError("--series", f"no series {series.strip()} in the catalogue", f"it holds {', '.join(known)}")
    out = []
    for e in entries:
        if series is not None and series_of(e["name"]) != series.strip():
            continue
        if bore is not None and (e["bore_m"] is None or abs(e["bore_m"] - bore) > 1e-6):
            continue
        if kind is not None and e["type"] != kind:
            continue
        out.append(e)
    return out


def _fmt(v, scale: float = 1.0, fmt: str = ".4g") -> str:
    return "—" if v is None else format(v * scale, fmt)


def _list_table(rows: list[dict]):
    from rich.table import Table

    t = Table(title=f"bearingsim catalogue ({len(rows)} entries)")
    for col, just in (("designation", "left"), ("type", "left"), ("d mm", "right"), ("D mm", "right"),
                      ("B mm", "right"), ("α deg", "right"), ("C kN", "right"), ("C0 kN", "right"),
                      ("Z × D_w mm", "right"), ("estimated", "left")):
        t.add_column(col, justify=just)
    for e in rows:
        zd = (f"{e['ball_count']} × {e['ball_diameter_m'] * 1e3:.4g}"
              if e["ball_count"] is not None and e["ball_diameter_m"] is not None else "—")
        est = "ball set" if {"ball_count", "ball_diameter"} & set(e["estimated"]) else (
            ", ".join(e["estimated"]) if e["estimated"] else "no")
        alpha = None if e["contact_angle_rad"] is None else math.degrees(e["contact_angle_rad"])
        t.add_row(e["name"], e["type"], _fmt(e["bore_m"], 1e3), _fmt(e["outside_diameter_m"], 1e3),
                  _fmt(e["width_m"], 1e3), _fmt(alpha, 1.0, ".3g"), _fmt(e["dynamic_load_rating_N"], 1e-3),
                  _fmt(e["static_load_rating_N"], 1e-3), zd, est)
    return t


def entry_details(name: str) -> dict:
    """One catalogue entry (or bearing file) in SI with its sources: the ``--json`` object of
    ``bearingsim catalog NAME``."""
    from ..geometry import BallBearing
    from ..io import catalog_names, load_bearing, resolve_bearing_data

    data = resolve_bearing_data(name)
    b = load_bearing(name)
    if not isinstance(b, BallBearing):  # a bearing set or double-row unit
        rows = [{"bearing": r.bearing.name, "position_m": r.position, "orientation": r.orientation,
                 "axial_offset_m": r.axial_offset} for r in b.rows]
        src = data.get("sources", {})
        return {"name": name, "type": data.get("type", "bearing_set"), "description": data.get("description", ""),
                "rows": rows, "sources": dict(src) if isinstance(src, dict) else {},
                "estimated": [k for k, v in (src.items() if isinstance(src, dict) else ())
                              if isinstance(v, str) and v.lstrip().upper().startswith(("ESTIMATE", "ASSUMED"))]}
    return {
        "name": name if name in catalog_names() else b.name, "type": b.kind,
        "description": data.get("description", ""),
        "bore_m": b.bore, "outside_diameter_m": b.outside_diameter, "width_m": b.width,
        "contact_angle_rad": b.contact_angle, "free_contact_angle_rad": b.free_contact_angle,
        "ball_count": b.ball_count, "ball_diameter_m": b.ball_diameter, "pitch_diameter_m": b.pitch_diameter,
        "inner_conformity": b.inner_conformity, "outer_conformity": b.outer_conformity,
        "diametral_clearance_m": b.diametral_clearance,
        "dynamic_load_rating_N": b.dynamic_load_rating, "static_load_rating_N": b.static_load_rating,
        "geometry_factor_f0": b.geometry_factor_f0, "fatigue_load_limit_N": b.fatigue_load_limit,
        "limiting_speed_rad_s": b.limiting_speed,
        "ball_material": b.ball_material.name, "ring_material": b.ring_material.name,
        "sources": b.sources, "estimated": list(b.estimated),
    }


#: how each field of :func:`entry_details` is shown: (key, label, scale, unit, source keys)
_SHOW = (
    ("bore_m", "bore d", 1e3, "mm", ("bore", "boundary")),
    ("outside_diameter_m", "outside diameter D", 1e3, "mm", ("outside_diameter", "bore", "boundary")),
    ("width_m", "width B", 1e3, "mm", ("width", "bore", "boundary")),
    ("free_contact_angle_rad", "free contact angle α₀", 180.0 / math.pi, "deg", ("contact_angle",
                                                                                 "diametral_clearance")),
    ("dynamic_load_rating_N", "dynamic load rating C", 1e-3, "kN", ("dynamic_load_rating",)),
    ("static_load_rating_N", "static load rating C₀", 1e-3, "kN", ("static_load_rating",)),
    ("geometry_factor_f0", "factor f₀", 1.0, "", ("geometry_factor_f0",)),
    ("fatigue_load_limit_N", "fatigue load limit P_u", 1e-3, "kN", ("fatigue_load_limit",)),
    ("limiting_speed_rad_s", "limiting speed", 30.0 / math.pi, "rpm", ("limiting_speed",)),
    ("ball_count", "ball count Z", 1.0, "", ("ball_count",)),
    ("ball_diameter_m", "ball diameter D_w", 1e3, "mm", ("ball_diameter", "geometry")),
    ("pitch_diameter_m", "pitch diameter d_m", 1e3, "mm", ("pitch_diameter", "geometry")),
    ("inner_conformity", "inner conformity f_i", 1.0, "", ("inner_conformity", "conformity", "geometry")),
    ("outer_conformity", "outer conformity f_o", 1.0, "", ("outer_conformity", "conformity", "geometry")),
    ("diametral_clearance_m", "diametral clearance P_d", 1e6, "µm", ("diametral_clearance",)),
    ("ball_material", "ball material", None, "", ("ball_material", "materials", "material")),
    ("ring_material", "ring material", None, "", ("ring_material", "materials", "material")),
)


def _show_entry(d: dict) -> None:
    from rich.table import Table

    con = make_console()
    con.print(f"[bold]{d['name']}[/]  {d['type']}: {d['description']}")
    src, est = d.get("sources", {}), set(d.get("estimated", ()))
    if "rows" in d:
        for r in d["rows"]:
            con.print(f"  row {r['bearing']}: position {r['position_m'] * 1e3:.4g} mm, orientation "
                      f"{r['orientation']:+.0f}, preload offset {r['axial_offset_m'] * 1e6:.4g} µm")
        for k, v in src.items():
            con.print(f"  {k}: {'[yellow]' if k in est else ''}{v}{'[/]' if k in est else ''}")
        return
    t = Table(title="data and sources (estimates in yellow)")
    for col in ("quantity", "value", "unit", "estimated", "source"):
        t.add_column(col, overflow="fold")
    for key, label, scale, unit, keys in _SHOW:
        v = d.get(key)
        if isinstance(v, float) and v == 0.0 and key in ("fatigue_load_limit_N", "geometry_factor_f0",
                                                          "dynamic_load_rating_N", "static_load_rating_N",
                                                          "limiting_speed_rad_s", "bore_m",
                                                          "outside_diameter_m", "width_m"):
            shown = "unknown"
        elif scale is None or isinstance(v, str):
            shown = str(v)
        else:
            shown = f"{v * scale:.6g}"
        skey = next((k for k in keys if k in src), None)
        flag = "yes" if skey is not None and skey in est else ""
        text = src.get(skey, "") if skey else ""
        style = "yellow" if flag else None
        t.add_row(label, shown, unit, flag, text, style=style)
    con.print(t)
    if est:
        con.print(f"[yellow]estimated or assumed:[/] {', '.join(sorted(est))}")


def catalog(
    name: NameArg = None,
    series: SeriesOpt = None,
    bore: BoreOpt = None,
    kind: TypeOpt = None,
    as_json: JsonOpt = False,
):
    """List the built-in bearing catalogue (filters --series, --bore, --type), or show one entry with its sources."""

    from ..errors import InputError
    from ..io import catalog_entries
    from ..io.bearing import catalog_name, unknown_bearing_fix

    if name is not None:
        if not name.lower().endswith(".toml"):
            found = catalog_name(name)
            if found is None:
                raise InputError("bearing", f"{name!r} is not in the catalogue", unknown_bearing_fix(name))
            name = found
        d = entry_details(name)
        if as_json:
            typer.echo(json.dumps(d))
        else:
            _show_entry(d)
        return
    rows = select(catalog_entries(), series, _parse_bore(bore) if bore is not None else None, kind)
    if as_json:
        typer.echo(json.dumps(rows))
        return
    make_console().print(_list_table(rows))


def register(app: typer.Typer) -> None:
    """Add ``catalog``."""
    app.command("catalog")(catalog)


__all__ = ["catalog", "entry_details", "register", "select", "series_of"]
