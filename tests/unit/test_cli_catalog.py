"""``bearingsim catalog`` through the installed console script: list, filters, one entry with its sources and
estimate flags, --json against the API, unknown names with 'did you mean'."""

import json

import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script

from bearingsim import io


def test_list_shows_every_entry_with_its_columns():
    out = run("catalog").stdout
    for name in ("6205", "6208", "7014-15", "7205-40", "harris-218", "skf-7011-cdga-hc", "hub-seed001-row"):
        assert f"│ {name} " in out
    for col in ("designation", "C kN", "C0 kN", "Z × D_w", "estimated"):
        assert col in out
    assert f"({len(io.catalog_names())} entries)" in out


def test_filters_and_json_agree_with_the_api():
    rows = json.loads(run("catalog", "--series", "72", "--bore", "40 mm", "--json").stdout)
    assert [r["name"] for r in rows] == ["7208-15", "7208-30", "7208-40"]
    b = io.load_bearing("7208-40")
    r = rows[2]
    assert r["bore_m"] == pytest.approx(b.bore, rel=1e-12)
    assert r["contact_angle_rad"] == pytest.approx(b.contact_angle, rel=1e-12)
    assert r["dynamic_load_rating_N"] == pytest.approx(b.dynamic_load_rating, rel=1e-12)
    assert r["static_load_rating_N"] == pytest.approx(b.static_load_rating, rel=1e-12)
    assert (r["ball_count"], r["ball_diameter_m"]) == (b.ball_count, pytest.approx(b.ball_diameter, rel=1e-12))
    assert r["estimated"] == list(b.estimated)
    deep = json.loads(run("catalog", "--series", "62", "--json").stdout)
    assert len(deep) == 21 and all(r["type"] == "deep_groove" and r["name"].startswith("62") for r in deep)
    bare = json.loads(run("catalog", "--bore", "40", "--type", "deep_groove", "--json").stdout)
    assert sorted(r["name"] for r in bare) == ["6008", "6208", "6308"]


def test_one_entry_shows_sources_and_flags_estimates():
    out = run("catalog", "6208").stdout
    assert "NSK Rolling Bearings" in out and "ISO 15" in out
    assert "ESTIMATE" in out and "estimated or assumed" in out
    d = json.loads(run("catalog", "6208", "--json").stdout)
    b = io.load_bearing("6208")
    assert d["static_load_rating_N"] == pytest.approx(17900.0) and d["geometry_factor_f0"] == 14.0
    assert d["fatigue_load_limit_N"] == 0.0  # not given by the source: unknown
    assert d["ball_count"] == b.ball_count and set(d["estimated"]) == set(b.estimated)
    assert d["sources"]["dynamic_load_rating"].startswith("NSK")


def test_unknown_name_is_one_line_with_did_you_mean():
    p = run("catalog", "6280", check=False)
    assert p.returncode == 2 and p.stdout == ""
    line = p.stderr.strip()
    assert "\n" not in line and "'6280' is not in the catalogue" in line and "did you mean" in line
    assert "6208" in line or "6220" in line
    p = run("catalog", "--series", "6x", check=False)
    assert p.returncode == 2 and "--series" in p.stderr
