"""`bearingsim static --thermal` through the console script (issue 46: the Done-when command)."""

from __future__ import annotations

import json

from _cli import run  # tests/unit/_cli.py: the installed console script


def test_static_thermal_json():
    p = run("static", "skf-7011-cdga-hc", "--fa", "1 kN", "--speed", "15000 rpm", "--thermal", "--json")
    d = json.loads(p.stdout)
    th = d["thermal"]
    assert th["converged"] and th["status"] == "converged"
    t = th["temperatures_K"]
    assert set(t) >= {"inner_ring", "outer_ring", "balls", "oil"}
    assert all(v > 313.15 for k, v in t.items() if k in ("inner_ring", "outer_ring", "balls", "oil"))
    assert abs(th["diametral_clearance_change_m"]) > 0
    assert abs(sum(th["heat_removed_W"].values()) - sum(v for v in th["heat_sources_W"].values() if v)) <= \
        1e-3 * sum(v for v in th["heat_sources_W"].values() if v)


def test_static_thermal_refuses_fe_rings():
    p = run("static", "skf-7011-cdga-hc", "--fa", "1 kN", "--speed", "15000 rpm", "--thermal", "--rings", "fe",
            check=False)
    assert p.returncode == 2, p.stderr
    assert "--thermal" in p.stderr and len(p.stderr.strip().splitlines()) == 1, p.stderr


def test_static_thermal_no_fixed_point_is_exit_1():
    """An inlet at the top of the oil's range: the oil node passes the range, no fixed point: exit 1, the reason
    printed (not an internal error)."""
    p = run("static", "skf-7011-cdga-hc", "--fa", "1 kN", "--speed", "15000 rpm", "--thermal", "--lubricant",
            "iso-vg-68", "--temperature", "149 degC", check=False)
    assert p.returncode == 1, p.stderr
    assert "thermal operating point: no fixed point" in p.stdout, p.stdout[-500:]


def test_static_thermal_coolant_above_range_is_one_line():
    p = run("static", "skf-7011-cdga-hc", "--fa", "1 kN", "--speed", "15000 rpm", "--thermal", "--lubricant",
            "iso-vg-68", "--temperature", "160 degC", check=False)
    assert p.returncode == 2 and len(p.stderr.strip().splitlines()) == 1, p.stderr
