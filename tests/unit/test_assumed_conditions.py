"""One rule for an operating temperature / lubricant the user does not give
(:func:`bearingsim.lubrication.operating_conditions`): assumed, and said so in the text and in the JSON
(``assumed``), by ``static`` and ``lubrication`` alike; and the labels of those outputs (issue 42, items 7, 11)."""

import json

from _cli import run

from bearingsim.lubrication import ASSUMED_LUBRICANT, ASSUMED_TEMPERATURE, assumed_phrases, operating_conditions


def test_rule_fills_only_what_is_missing():
    assert operating_conditions(None, None) == (None, None, {})
    lub, t, assumed = operating_conditions("mil-prf-23699", None)
    assert (lub.name, t, assumed) == ("mil-prf-23699", ASSUMED_TEMPERATURE, {"temperature_K": ASSUMED_TEMPERATURE})
    lub, t, assumed = operating_conditions(None, 343.15, need_lubricant=True)
    assert (lub.name, t, assumed) == (ASSUMED_LUBRICANT, 343.15, {"lubricant": ASSUMED_LUBRICANT})
    assert assumed_phrases({"temperature_K": 333.15}) == ["operating temperature 60 °C assumed — give --temperature"]


def test_static_lubricant_without_temperature_assumes_and_says_so():
    p = run("static", "6205", "--fr", "2 kN", "--speed", "1500 rpm", "--lubricant", "iso-vg-68")
    assert "operating temperature 60 °C assumed — give --temperature" in p.stdout, p.stdout
    assert "L_nm = " in p.stdout, p.stdout
    d = json.loads(run("static", "6205", "--fr", "2 kN", "--speed", "1500 rpm", "--lubricant", "iso-vg-68",
                       "--json").stdout)
    assert d["assumed"] == {"temperature_K": 333.15}
    assert d["modified_rating_life_hours"] is not None


def test_static_all_given_assumes_nothing():
    d = json.loads(run("static", "6205", "--fr", "2 kN", "--speed", "1500 rpm", "--lubricant", "iso-vg-68",
                       "--temperature", "70 degC", "--json").stdout)
    assert d["assumed"] == {}
    p = run("static", "6205", "--fr", "2 kN", "--speed", "1500 rpm")
    assert "assumed" not in p.stdout


def test_lubrication_states_its_assumptions():
    p = run("lubrication", "6205", "--fr", "2000", "--speed", "3000")
    assert "lubricant iso-vg-68 assumed — give --lubricant" in p.stdout, p.stdout[-800:]
    assert "operating temperature 60 °C assumed — give --temperature" in p.stdout, p.stdout[-800:]
    assert "(palmgren)" not in p.stdout and "oil_bath" not in p.stdout and "(Palmgren)" in p.stdout
    d = json.loads(run("lubrication", "6205", "--fr", "2000", "--speed", "3000", "--temperature", "70 degC",
                       "--json").stdout)
    assert d["assumed"] == {"lubricant": "iso-vg-68"} and d["temperature_K"] == 343.15


def test_static_status_line_says_converged_once():
    p = run("static", "6205", "--fr", "2 kN", "--fa", "0.5 kN", "--speed", "1500 rpm")
    first = p.stdout.splitlines()[0]
    assert "converged (residual " in first and first.count("converged") == 1, first
    assert "(estimated) (ISO 76)" not in p.stdout
