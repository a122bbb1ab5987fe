"""What a new user hit (issue 42, command-line half), each through the installed console script."""

from __future__ import annotations

import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script


@pytest.mark.parametrize("argv, option", [
    (("static", "6205", "--fr", "2000", "--fr", "3000"), "--fr"),
    (("static", "6205", "--fr=2000", "--speed", "1500", "--fr", "3000"), "--fr"),
    (("lubrication", "6205", "--fa", "1000", "--fa", "2000"), "--fa"),
    (("map", "6205", "--speed", "0:10:3", "--speed", "5"), "--speed"),
    (("reproduce", "hub-hysteresis", "case.toml", "--speeds", "10", "--speeds", "50"), "--speeds"),
    (("static", "6205", "--json", "--json"), "--json"),
])
def test_a_repeated_option_is_a_usage_error(argv, option):
    """`--fr 2000 --fr 3000` is refused (exit 2, one line naming the option), for every command alike."""
    p = run(*argv, check=False)
    assert p.returncode == 2, p.stderr
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0] and "more than once" in lines[0], p.stderr
    assert p.stdout == ""


def test_designations_are_case_insensitive():
    """`SKF-7011-CDGA-HC` is the catalogue's skf-7011-cdga-hc, for a command and for `catalog NAME` alike."""
    upper = run("clearance", "SKF-7011-CDGA-HC", "--json", check=False)
    lower = run("clearance", "skf-7011-cdga-hc", "--json")
    assert upper.returncode == 0, upper.stderr
    assert upper.stdout == lower.stdout
    shown = run("catalog", "SKF-7011-CDGA-HC", "--json", check=False)
    assert shown.returncode == 0, shown.stderr
    assert '"skf-7011-cdga-hc"' in shown.stdout


@pytest.mark.parametrize("name, expected", [
    ("7011", ["7011-15", "7011-25", "7011-30"]),
    ("7011-1", ["7011-15"]),
    ("SKF-7011", ["skf-7011-cdga-hc"]),
])
def test_suggestions_put_the_series_first(name, expected):
    """A designation without its contact-angle suffix is answered with the series it starts (prefix matches
    before edit distance): `7011` suggests 7011-15/-25/-30, first."""
    p = run("clearance", name, check=False)
    assert p.returncode == 2
    line = p.stderr.strip()
    assert "did you mean" in line, line
    suggested = line.split("did you mean", 1)[1].strip(" ?)").split(" or ")
    assert suggested[:len(expected)] == expected, line


def test_a_typo_is_still_answered_by_edit_distance():
    line = run("clearance", "62o5", check=False).stderr
    assert "6205" in line.split("did you mean", 1)[1], line


def test_simulate_given_a_bearing_name_says_it_takes_a_case_file(tmp_path):
    """`bearingsim simulate 6205` names 6205 as a catalogue bearing and says how to write a case file."""
    p = run("simulate", "6205", "--out", str(tmp_path / "x.nc"), check=False)
    assert p.returncode == 2
    line = p.stderr.strip()
    assert len(line.splitlines()) == 1
    assert "'6205' is a bearing of the catalogue, not a case file" in line, line
    assert "examples/spindle-7011.toml" in line and 'bearing = "6205"' in line, line
    assert "catalogue name" not in line.split("(", 1)[1]  # no longer offered as what simulate takes
    assert not (tmp_path / "x.nc").exists()
