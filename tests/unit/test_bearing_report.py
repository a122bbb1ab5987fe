"""The bearing report (issue 15 item 4): structure of the page, its figures, numbers in the units of the trade,
estimate flags, through the API and the installed console script."""

import html
import json
import re
import subprocess

import numpy as np
import pytest

from bearingsim.io import load_bearing
from bearingsim.report.bearing import bearing_report
from bearingsim.statics.jones_harris import Loads, solve


def _text(page: str) -> str:
    page = re.sub(r"<style>.*?</style>", "", page, flags=re.S)
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


def _figures(page: str) -> list[str]:
    return re.findall(r'<img src="([^"]+)"', page)


@pytest.fixture(scope="module")
def spindle_report(tmp_path_factory):
    out = tmp_path_factory.mktemp("rep")
    loads = Loads(fa=2000.0, fr_y=1000.0)
    page = bearing_report("skf-7011-cdga-hc", loads, 628.3185307179587, out_dir=out, lubricant="iso-vg-68",
                          temperature=323.15)
    res = solve(load_bearing("skf-7011-cdga-hc"), loads, 628.3185307179587)
    return page, res.to_dict()


def test_page_has_sections_figures_and_tables(spindle_report):
    page, _ = spindle_report
    s = page.read_text()
    assert s.startswith("<!DOCTYPE html>") and s.rstrip().endswith("</html>")
    for ident in ("inputs", "results", "figures"):
        assert f'id="{ident}"' in s
    figs = _figures(s)
    assert len(figs) == 4  # load distribution, angles and pressure, ellipse vs shoulder, stiffness vs speed
    for f in figs:
        assert "/" not in f, "figures are linked by a relative name beside the page"
        assert (page.parent / f).stat().st_size > 5000
    assert s.count("<table") >= 4  # operating point, inputs, results, stiffness, friction


def test_numbers_are_the_results_in_trade_units(spindle_report):
    page, d = spindle_report
    t = _text(page.read_text())
    assert f"{d['axial_stiffness_N_per_m'] * 1e-6:.4g} N/µm" in t
    assert f"{d['displacement']['axial_m'] * 1e6:.4g} µm" in t
    assert f"{d['displacement']['tilt_rad'] * 1e3:.4g} mrad" in t
    assert "6000 rpm" in t
    assert f"{d['static_safety_factor']:.3g}" in t
    k = np.asarray(d["stiffness_matrix"])
    assert f"{k[4, 4] * 1e-3:.4g} N·m/mrad" in t and f"{k[0, 4] * 1e-3:.4g} N/mrad" in t
    assert "friction torque" in t and " W" in t


def test_estimates_are_flagged_with_their_source(spindle_report):
    page, _ = spindle_report
    t = _text(page.read_text())
    # the 7011's ball set is an estimate in its catalogue file: flagged, with the file's source text
    assert re.search(r"ball diameter D\s+10\.319 mm\s+ESTIMATE\s+ESTIMATE: design rule", t)
    assert re.search(r"bore\s+55 mm\s+SKF super-precision", t)


def test_a_unit_gets_one_polar_panel_per_row(tmp_path):
    page = bearing_report("hub-seed001", Loads(fa=1890.0, fr_y=3750.0, m_z=600.0), 87.5, out_dir=tmp_path)
    s = page.read_text()
    assert len(_figures(s)) == 4
    assert re.search(r"\b1\s+ball diameter D", _text(s)), "the second row's inputs are listed"


def test_cli_report_and_its_errors(tmp_path):
    out = tmp_path / "a" / "b"
    r = subprocess.run(["bearingsim", "report", "skf-7011-cdga-hc", "--fa", "1 kN", "--speed", "3000 rpm",
                        "--out", str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    assert (out / "report.html").is_file() and len(list(out.glob("*.png"))) == 4
    # a map file that is not one: one line, exit 2, nothing written
    bad = tmp_path / "notamap.nc"
    bad.write_bytes(b"\x00\x01binary")
    out2 = tmp_path / "c"
    r = subprocess.run(["bearingsim", "report", "skf-7011-cdga-hc", "--fa", "1 kN", "--map", str(bad),
                        "--out", str(out2)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "map" in r.stderr, r.stderr
    r = subprocess.run(["bearingsim", "report", "no-such-bearing", "--out", str(tmp_path / "d")],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "d").exists(), "a refused report creates no folder"


def test_report_with_a_map_plots_stiffness_against_speed(tmp_path):
    m = tmp_path / "m.nc"
    r = subprocess.run(["bearingsim", "map", "skf-7011-cdga-hc", "--fa", "500:1500:3", "--speed", "0:12000:4",
                        "--out", str(m), "--json"], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    json.loads(r.stdout)
    page = bearing_report("skf-7011-cdga-hc", Loads(fa=1000.0), 500.0, out_dir=tmp_path / "r", map_file=m)
    figs = _figures(page.read_text())
    assert len(figs) == 4 and figs[-1].endswith("_map_stiffness.png")  # the map replaces the speed sweep
