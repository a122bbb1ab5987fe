"""A solid shaft ("0 mm") under FE rings is an approximation with a first-order sensitivity (a rigid core of a
quarter of the bore, docs/rings.md §7): the result says so, in the JSON and on the screen (console script)."""

import json
from pathlib import Path

from _cli import run

HUB = Path(__file__).resolve().parents[2] / "examples" / "hub-rings.toml"
LOADS = ["--fa", "1890 N", "--fr", "3750 N", "--moment", "600 N*m"]


def test_solid_shaft_is_flagged_and_a_hollow_one_is_not(tmp_path):
    src = HUB.read_text()
    assert 'inner_diameter = "0 mm"' in src
    hollow = tmp_path / "hub-hollow.toml"
    hollow.write_text(src.replace('inner_diameter = "0 mm"', 'inner_diameter = "20 mm"'))
    solid = json.loads(run("static", str(HUB), *LOADS, "--json").stdout)
    held = json.loads(run("static", str(hollow), *LOADS, "--json").stdout)
    assert any("solid shaft" in w for w in solid["warnings"]), solid["warnings"]
    assert not any("solid shaft" in w for w in held["warnings"]), held["warnings"]
    screen = run("static", str(HUB), *LOADS)
    assert "solid shaft" in screen.stdout + screen.stderr
