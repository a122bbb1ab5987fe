"""HTML report of the hub hysteresis study (studies/hub_report.py): structure (figures present and on disk, one
table row per cell, one verdict per claim), the verdict rules on synthetic grids, and the display fit.

The cells are synthetic (analytic lagging loops with estimates set by hand); the report is tested for what it
shows, not for the physics, which is tested with the estimator and the dynamic runs.
"""

from __future__ import annotations

import math
import types
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest

from bearingsim.studies import hub_dynamic as hd
from bearingsim.studies import hub_report as hr

CASE = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"
C = 1.7e-6  # compliance [rad/(N m)]


def _record(v, f, lag, cycles=4, per_cycle=200):
    t = np.arange(cycles * per_cycle + 1) / (per_cycle * f)
    w = 2 * math.pi * f
    m = 600.0 * np.sin(w * t)
    return {"speed_kmh": v, "frequency_hz": f, "time": t, "moment": m, "fa": 1890 / 600 * m, "fr": 2785 + 965 / 600 * m,
            "tilt": 1e-4 + C * 600.0 * np.sin(w * (t - lag)), "wall_seconds": 1.0, "simulated_seconds": t[-1],
            "steps": 10}


def _cell(v, f, wh_mdeg, half_mdeg=0.05, comp=C, static=C):
    """A cell whose estimate says W_H = wh_mdeg ± half_mdeg [1e-3 deg]; its loop lags accordingly."""
    wh = math.radians(wh_mdeg * 1e-3)
    half = math.radians(half_mdeg * 1e-3)
    lag = math.asin(max(min(wh / (math.sqrt(3) * C * 600.0), 1.0), -1.0)) / (2 * math.pi * f)
    est = types.SimpleNamespace(widths=np.full(6, wh), cycles_used=6, first_cycle=1, mean=wh,
                                ci95=(wh - half, wh + half), loop_area=1e-4, loop_area_ci95=(0.9e-4, 1.1e-4),
                                phase_lag=2 * math.pi * f * lag, compliance=comp, two_point=np.full(6, wh),
                                periodic_from=1, criterion="hand-set")
    return hd.CellResult(float(v), float(f), _record(float(v), float(f), lag), estimate=est, static_compliance=static)


def _grid(value):
    return [_cell(v, f, value(v, f)) for v in (10, 50, 100) for f in (10, 50)]


class _Parser(HTMLParser):
    def __init__(self):
        super().__init__()
        self.imgs, self.ids, self.stack, self.rows = [], set(), [], {}
        self.table = None
        self.in_body = False

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.add(a["id"])
        if tag == "img":
            self.imgs.append(a["src"])
        if tag == "table":
            self.table = a.get("id")
            self.rows[self.table] = 0
        if tag == "tbody":
            self.in_body = True
        if tag == "tr" and self.in_body:
            self.rows[self.table] += 1

    def handle_endtag(self, tag):
        if tag == "tbody":
            self.in_body = False


def test_report_structure(tmp_path):
    cells = _grid(lambda v, f: 0.1 + 0.002 * f - 0.001 * v)
    study = hd.HysteresisStudy(cells, case=str(CASE), wall_seconds=12.0, notes=["a note"])
    page = hr.write_report(study, tmp_path / "rep")
    text = page.read_text()
    p = _Parser()
    p.feed(text)
    assert p.imgs == ["fig6_loops_50Hz.png", "fig7_loops_10kmh.png", "fig8_wh_definition.png", "fig9_bubbles.png"]
    for name in p.imgs:  # beside the page, real PNG files
        data = (page.parent / name).read_bytes()
        assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 5000, name
    assert p.rows["cells"] == len(cells)
    assert p.rows["verdicts"] == 5
    assert {"figures", "cells-section", "sensitivity", "assumptions", "notes", "verdicts-section"} <= p.ids
    assert "<style>" in text and "http" not in text.split("<body>")[1]  # opens from disk: nothing fetched
    assert "hub inertia" in text and "317.5 mm" in text  # assumptions from the case file and the tyre radius
    assert "not run" in text  # the dynamic sensitivities are said to be missing


def test_report_without_cells_at_50hz_or_10kmh_says_so(tmp_path):
    study = hd.HysteresisStudy([_cell(100, 20, 0.2)], case=str(CASE))
    text = hr.write_report(study, tmp_path).read_text()
    assert "no analysed cell at 50 Hz" in text and "no analysed cell at 10 km/h" in text
    p = _Parser()
    p.feed(text)
    assert p.imgs == ["fig8_wh_definition.png", "fig9_bubbles.png"] and p.rows["cells"] == 1


def _verdict(study, word):
    (v,) = [v for v in hr.verdicts(study) if word in v["claim"]]
    return v["verdict"]


def test_verdicts_follow_the_data():
    as_paper = hd.HysteresisStudy(_grid(lambda v, f: 0.5 + 0.05 * f - 0.004 * v))
    assert _verdict(as_paper, "lags") == "confirmed"
    assert _verdict(as_paper, "grows with") == "confirmed"
    assert _verdict(as_paper, "falls as") == "confirmed"
    assert _verdict(as_paper, "stiffness") == "confirmed"
    reverse = hd.HysteresisStudy(_grid(lambda v, f: -(0.5 + 0.05 * f - 0.004 * v) + 3.0))  # opposite trends, > 0
    assert _verdict(reverse, "grows with") == "contradicted" and _verdict(reverse, "falls as") == "contradicted"
    flat = hd.HysteresisStudy(_grid(lambda v, f: 0.0))  # intervals contain 0, no trend beyond them
    assert _verdict(flat, "lags") == "not resolved" and _verdict(flat, "grows with") == "not resolved"
    leads = hd.HysteresisStudy(_grid(lambda v, f: -1.0))
    assert _verdict(leads, "lags") == "contradicted"
    # magnitudes: ours 10x below the paper everywhere -> not confirmed, with the ratio in the evidence
    small = hd.HysteresisStudy([_cell(v, f, hd.SEED_FIG9[(v, f)] / 10) for v in (10, 50, 100) for f in (10, 50)])
    (m,) = [v for v in hr.verdicts(small) if "Magnitudes" in v["claim"]]
    assert m["verdict"] == "not confirmed" and "0.1 … 0.1" in m["evidence"]
    same = hd.HysteresisStudy([_cell(v, f, hd.SEED_FIG9[(v, f)]) for v in (10, 50, 100) for f in (10, 50)])
    assert _verdict(same, "Magnitudes") == "confirmed"
    # compliance spread above 2 %: not confirmed
    stiff = hd.HysteresisStudy([_cell(10, 50, 0.5, comp=C), _cell(100, 50, 0.4, comp=1.05 * C)])
    assert _verdict(stiff, "stiffness") == "not confirmed"


def test_mean_loop_recovers_an_analytic_loop():
    """Display fit of a pure lag: the fitted loop's width at M0/2 is √3 c M0 sin(ω lag) (exact for a sine)."""
    f, lag = 50.0, 0.2e-3
    rec = _record(10.0, f, lag)
    m, g = hr.mean_loop(rec, first_cycle=1, points=4000)
    up = (np.diff(m, append=m[0]) > 0)
    i_r = np.argmin(np.where(up, abs(m - 300.0), np.inf))
    i_f = np.argmin(np.where(~up, abs(m - 300.0), np.inf))
    # nearest phase samples (4000 per cycle): the tilt moves by at most c dM per sample
    tol = C * 600.0 * 2 * math.pi / 4000
    assert g[i_f] - g[i_r] == pytest.approx(math.sqrt(3) * C * 600.0 * math.sin(2 * math.pi * f * lag), abs=tol)


def _variant(folder, name, v, f, wh_mdeg, half=0.01):
    import json

    w = wh_mdeg * 1e-3
    d = {"variant": name, "description": f"change {name}", "speed_kmh": v, "frequency_hz": f, "cycles": 8,
         "startup": 2, "fingerprint": name, "case": str(CASE),
         "cell": {"wh_deg": w, "wh_ci95_deg": [w - half * 1e-3, w + half * 1e-3], "cycles_used": 8, "first_cycle": 1,
                  "wh_cycles_deg": [w + (k % 2 - 0.5) * 2e-6 for k in range(8)],
                  "phase_lag_deg": 0.06, "compliance_deg_per_kNm": 0.102, "wall_seconds": 60.0}}
    (folder / f"{name}_{v:g}_{f:g}.json").write_text(json.dumps(d))


def test_report_shows_the_dynamic_sensitivity_runs(tmp_path):
    """With a folder of hub_sensitivity runs: the figure and one table row per variant (two cells here), the
    ratio to the cell's base run; without one, the report says they were not run (test_report_structure)."""
    src = tmp_path / "sens"
    src.mkdir()
    for name, wh in (("base", 0.145), ("creep_x2", 0.150), ("slices4", 0.128)):
        _variant(src, name, 100.0, 50.0, wh)
    for name, wh in (("base", 0.24), ("mumax_x2", 0.30)):
        _variant(src, name, 10.0, 50.0, wh)
    (src / "not_a_variant.json").write_text('{"cells": []}')  # other JSON in the folder is ignored
    study = hd.HysteresisStudy(_grid(lambda v, f: 0.1), case=str(CASE))
    page = hr.write_report(study, tmp_path / "rep", sensitivity=src)
    text = page.read_text()
    p = _Parser()
    p.feed(text)
    assert "sensitivity_dynamic.png" in p.imgs
    assert (page.parent / "sensitivity_dynamic.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert p.rows["sensitivity-dynamic"] == 5
    assert "not run for this report" not in text
    assert "1.034" in text and "0.883" in text and "1.250" in text  # creep_x2, slices4, mumax_x2 ÷ their base
    # paired differences over the same cycles: equal alternation in every run, so the difference has no scatter
    assert "+0.0050 [+0.0050, +0.0050]" in text and "-0.0170 [-0.0170, -0.0170]" in text


def test_cli_sensitivity_needs_the_report(tmp_path):
    from _cli import run

    p = run("reproduce", "hub-hysteresis", str(CASE), "--sensitivity", str(tmp_path), "--out", str(tmp_path / "o"),
            check=False)
    assert p.returncode == 2 and "--sensitivity" in p.stderr and "--report" in p.stderr
