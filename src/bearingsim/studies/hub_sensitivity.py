"""Dynamic sensitivities of the [S1] hub hysteresis: W_H of ONE cell of the study grid
(:mod:`.hub_dynamic`) when one input of the traction law or of the geometry is changed.

Each variant is the case of the cell (:func:`.hub_dynamic.cell_case`, physical traction) with one change:

* ``creep_x0.5`` / ``creep_x2`` — the film's elastic shear modulus G_f × 0.5 / × 2 (``[lubrication]
  film_modulus_factor``, :func:`bearingsim.contact.slices.pack_lubrication_parameters`): the small-slip slope of
  the film-elastic traction (Johnson & Tevaarwerk 1977) × 0.5 / × 2, the saturated (viscous) stress unchanged;
* ``film+solids`` — the solids' tangential compliance (Kalker's simplified theory) in series with the film's
  (``traction_compliance = "film+solids"``, :func:`bearingsim.contact.traction.solids_in_series_factor`);
* ``mumax_x0.5`` / ``mumax_x2`` — the limiting shear stress τ_L (ratio r_L and floor of the lubricant) × 0.5 / × 2:
  the saturated traction coefficient μ_max ≈ τ_L/p̄ × 0.5 / × 2 with the film's elastic modulus G_f = τ_L/r_L
  unchanged (the case's contacts are smooth, Λ > 3: the boundary law does not enter);
* ``slices4`` / ``slices16`` — the strips per contact ellipse (the case: 8);
* ``fi+0.01`` … ``fo-0.01`` — the inner or the outer groove conformity f = r/D ± 0.01 (the case: 0.52 both).

Results go to a folder: per variant a sub-folder with the run (netCDF, checkpoints; a killed variant resumes)
and the stored cell (:func:`.hub_dynamic.save_cell`), and ``<variant>.json`` with the analysed cell
(:meth:`.hub_dynamic.CellResult.to_dict`), the variant's description and its fingerprint.
:func:`load_sensitivities` reads the folder back for the report (:mod:`.hub_report`).

Command line (one variant after the other in this process; start two processes for two at a time)::

    python -m bearingsim.studies.hub_sensitivity CASE DIR [--speed 100] [--frequency 50] [--cycles 8]
        [--variants base,creep_x0.5,...]
"""

from __future__ import annotations

import copy
import json
import math
import os
import re
import sys
from pathlib import Path

from ..errors import InputError
from .hub_dynamic import STARTUP_CYCLES, analyse_cell, cell_case, run_cell, save_cell

#: variant name → (description, kind, value); kinds: "case" (top-level key = value), "lubrication" (key = value
#: in [lubrication]), "lss" (limiting-shear-stress factor), "conformity" (("inner" | "outer", Δf))
VARIANTS = {
    "base": ("the case as given", "case", {}),
    "creep_x0.5": ("film elastic modulus × 0.5 (small-slip slope × 0.5)", "lubrication",
                   {"film_modulus_factor": 0.5}),
    "creep_x2": ("film elastic modulus × 2 (small-slip slope × 2)", "lubrication", {"film_modulus_factor": 2.0}),
    "film+solids": ("solids' compliance (Kalker) in series with the film's", "case",
                    {"traction_compliance": "film+solids"}),
    "mumax_x0.5": ("limiting shear stress × 0.5 (μ_max × 0.5)", "lss", 0.5),
    "mumax_x2": ("limiting shear stress × 2 (μ_max × 2)", "lss", 2.0),
    "slices4": ("4 strips per contact ellipse", "case", {"n_slices": 4}),
    "slices16": ("16 strips per contact ellipse", "case", {"n_slices": 16}),
    "fi+0.01": ("inner groove conformity + 0.01", "conformity", ("inner", 0.01)),
    "fi-0.01": ("inner groove conformity − 0.01", "conformity", ("inner", -0.01)),
    "fo+0.01": ("outer groove conformity + 0.01", "conformity", ("outer", 0.01)),
    "fo-0.01": ("outer groove conformity − 0.01", "conformity", ("outer", -0.01)),
}


def _library_text(kind: str, name: str) -> str:
    """Text of a library TOML (lubricant or catalogue bearing) or of a TOML path."""
    p = Path(name)
    if p.suffix == ".toml" and p.exists():
        return p.read_text()
    root = Path(__file__).resolve().parents[1]
    cand = root / "data" / f"lubricant-{name}.toml" if kind == "lubricant" else root / "catalog" / f"{name}.toml"
    if not cand.exists():
        raise InputError(kind, f"cannot find the TOML of {name!r} to derive a variant from",
                         "give the case's lubricant or bearing as a library name or a TOML path")
    return cand.read_text()


def _edit_number(text: str, key: str, change) -> str:
    """``text`` (TOML) with the plain number of ``key`` replaced by ``change(value)``."""
    pat = re.compile(rf"^({re.escape(key)}\s*=\s*)([0-9.eE+-]+)\s*$", re.M)
    if pat.search(text) is None:
        raise InputError(key, "not a plain number in the TOML", "give it as a number to derive the variant")
    return pat.sub(lambda mm: f"{mm.group(1)}{change(float(mm.group(2)))!r}", text, count=1)


def _scaled(text: str, key: str, factor: float) -> str:
    return _edit_number(text, key, lambda v: v * factor)


def variant_case_data(case_data: dict, base: Path, variant: str, folder: Path) -> dict:
    """The case data of ``variant`` (files it needs are written into ``folder``)."""
    if variant not in VARIANTS:
        raise InputError("--variants", f"unknown variant {variant!r}", "use one of " + ", ".join(VARIANTS))
    _, kind, value = VARIANTS[variant]
    d = copy.deepcopy(case_data)
    folder.mkdir(parents=True, exist_ok=True)
    if kind == "case":
        d.update(value)
    elif kind == "lubrication":
        d["lubrication"] = {**(d.get("lubrication") or {}), **value}
    elif kind == "lss":
        lub = str(d["lubricant"])
        lub = str((base / lub).resolve()) if lub.endswith(".toml") and not Path(lub).is_absolute() else lub
        text = _scaled(_scaled(_library_text("lubricant", lub), "lss_ratio", value), "lss_floor", value)
        text = re.sub(r'^name\s*=\s*"([^"]*)"', rf'name = "\1 (tau_L x {value:g})"', text, count=1, flags=re.M)
        path = folder / f"lubricant_{variant}.toml"
        path.write_text(text)
        d["lubricant"] = str(path)
    elif kind == "conformity":
        which, df = value
        text = _library_text("bearing", str(d["bearing"]))
        m = re.search(r'^row\s*=\s*"([^"]*)"', text, re.M)
        key = f"{which}_conformity"
        if m is None:  # a single-row bearing
            path = folder / f"bearing_{variant}.toml"
            path.write_text(_shift(text, key, df))
        else:
            row = folder / f"row_{variant}.toml"
            row.write_text(_shift(_library_text("bearing", m.group(1)), key, df))
            path = folder / f"bearing_{variant}.toml"
            path.write_text(text[:m.start(1)] + str(row) + text[m.end(1):])
        d["bearing"] = str(path)
    return d


def _shift(text: str, key: str, df: float) -> str:
    return _edit_number(text, key, lambda v: round(v + df, 10))


def run_variant(case_path, folder, variant: str, speed_kmh: float = 100.0, frequency_hz: float = 50.0,
                cycles: int = 8, startup: int = STARTUP_CYCLES) -> dict:
    """Run (or resume, or take from the folder) one variant of one cell; returns the JSON written to
    ``folder/<variant>.json``: {variant, description, speed_kmh, frequency_hz, cycles, startup, fingerprint,
    cell: CellResult.to_dict()}."""
    from ..io import read_toml

    p = Path(case_path)
    folder = Path(folder)
    sub = folder / variant
    data = variant_case_data(read_toml(p, "case"), p.parent, variant, sub)
    total = startup + cycles
    case = cell_case(data, p.parent, speed_kmh, frequency_hz, total, "physical")
    fp = case.fingerprint()
    out = folder / f"{variant}.json"
    if out.exists():
        try:
            old = json.loads(out.read_text())
        except (OSError, ValueError):
            old = None
        if old is not None and old.get("fingerprint") == fp:
            return old
    rec = run_cell(data, str(p.parent.resolve()), speed_kmh, frequency_hz, total, "physical", str(sub.resolve()))
    save_cell(sub, rec)
    cell = analyse_cell(rec, case)
    from .hub_dynamic import _finite

    res = _finite({"variant": variant, "description": VARIANTS[variant][0], "speed_kmh": float(speed_kmh),
                   "frequency_hz": float(frequency_hz), "cycles": cycles, "startup": startup, "fingerprint": fp,
                   "case": str(p), "cell": cell.to_dict()})
    tmp = folder / f".{variant}.json.part"
    tmp.write_text(json.dumps(res, indent=1))
    os.replace(tmp, out)
    return res


def load_sensitivities(folder) -> list[dict]:
    """The variants stored in ``folder`` (``<variant>.json``, also in sub-folders: one per cell), sorted by cell and
    in :data:`VARIANTS` order (unknown names last)."""
    folder = Path(folder)
    if not folder.is_dir():
        raise InputError("--sensitivity", f"{str(folder)!r} is not a folder", "give the folder of the variant runs")
    out = []
    for js in sorted(folder.rglob("*.json")):
        try:
            d = json.loads(js.read_text())
        except (OSError, ValueError):
            continue
        if isinstance(d, dict) and "variant" in d and isinstance(d.get("cell"), dict):
            out.append(d)
    order = {v: i for i, v in enumerate(VARIANTS)}
    return sorted(out, key=lambda d: (d["speed_kmh"], d["frequency_hz"], order.get(d["variant"], len(order))))


def main(argv=None) -> int:
    import argparse

    ap = argparse.ArgumentParser(prog="python -m bearingsim.studies.hub_sensitivity",
                                 description=__doc__.split("\n")[0])
    ap.add_argument("case")
    ap.add_argument("folder")
    ap.add_argument("--speed", type=float, default=100.0, help="vehicle speed [km/h]")
    ap.add_argument("--frequency", type=float, default=50.0, help="load frequency [Hz]")
    ap.add_argument("--cycles", type=int, default=8)
    ap.add_argument("--variants", default=",".join(VARIANTS))
    a = ap.parse_args(argv)
    for v in [x for x in a.variants.split(",") if x]:
        try:
            r = run_variant(a.case, a.folder, v, a.speed, a.frequency, a.cycles)
        except InputError as exc:
            print(f"error: {exc}", file=sys.stderr)
            return 2
        c = r["cell"]
        wh = c.get("wh_deg")
        ci = c.get("wh_ci95_deg") or [None, None]
        fmt = (lambda x: "—" if x is None or not math.isfinite(x) else f"{x * 1e3:.4f}")  # noqa: E731
        print(f"{v}: W_H {fmt(wh)} [{fmt(ci[0])}, {fmt(ci[1])}] 1e-3 deg, cycles {c.get('cycles_used')}, "
              f"wall {c.get('wall_seconds'):.0f} s", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
