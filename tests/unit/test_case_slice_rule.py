"""The case-file key ``slice_rule`` (issue 14): the sliced traction by equal strips (default), by Gauss–Legendre
nodes between the zeros of the rolling slip (``contact.slices``, n_slices < 0 inside the kernel), by strips cut at
those zeros (SPLIT_BASE + n) or by the log rule (LOG_BASE + n)."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script

from bearingsim.contact.slices import GAUSS_MAX, LOG_BASE, LOG_MAX, LOG_MIN, SPLIT_BASE
from bearingsim.dynamics.case import case_from_dict
from bearingsim.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
HUB = ROOT / "examples" / "hub-moment-50hz.toml"


def _data(**kw):
    return {**tomllib.loads(HUB.read_text()), **kw}


def test_default_is_strips_and_gauss_reaches_the_kernel_as_negative_count():
    strips = case_from_dict(_data(), base=HUB.parent)
    gauss = case_from_dict(_data(slice_rule="gauss", n_slices=4), base=HUB.parent)
    assert strips.slice_rule == "strips" and strips.model_options()["n_slices"] == 8
    assert gauss.model_options()["n_slices"] == -4
    assert strips.fingerprint() != gauss.fingerprint()  # a resume never mixes the two rules


@pytest.mark.parametrize("bad, field", [({"slice_rule": "simpson"}, "slice_rule"), ({"slice_rule": 3}, "slice_rule"),
                                        ({"slice_rule": "gauss", "n_slices": GAUSS_MAX + 1}, "n_slices"),
                                        ({"slice_rule": "gauss", "n_slices": 0}, "n_slices"),
                                        ({"slice_rule": "log", "n_slices": LOG_MIN - 1}, "n_slices"),
                                        ({"slice_rule": "log", "n_slices": LOG_MAX + 1}, "n_slices")])
def test_bad_rule_or_node_count_names_the_field(bad, field):
    with pytest.raises(InputError) as e:
        case_from_dict(_data(**bad), base=HUB.parent)
    assert e.value.field == field


@pytest.mark.parametrize("name, rule, lo, hi", [("hub-moment-gauss.toml", "gauss", 1, GAUSS_MAX),
                                                ("hub-moment-log.toml", "log", LOG_MIN, LOG_MAX)])
def test_example_study_cases_differ_from_the_benchmark_case_only_by_the_rule(name, rule, lo, hi):
    """examples/hub-moment-gauss.toml (the hub study's case) and examples/hub-moment-log.toml are benchmark case (b)
    with the Gauss rule and the log rule."""
    case = tomllib.loads((ROOT / "examples" / name).read_text())
    base = tomllib.loads(HUB.read_text())
    assert {k: v for k, v in case.items() if k not in ("slice_rule", "n_slices")} == \
        {k: v for k, v in base.items() if k != "n_slices"}
    assert case["slice_rule"] == rule and lo <= case["n_slices"] <= hi
    case_from_dict(case, base=HUB.parent)  # (a valid case)


def test_console_script_refuses_a_bad_rule_in_one_line(tmp_path):
    text = HUB.read_text().replace("n_slices = 8", 'n_slices = 8\nslice_rule = "trapezoid"')
    case = tmp_path / "case.toml"
    case.write_text(text)
    p = run("simulate", str(case), "--out", str(tmp_path / "o.nc"), check=False)
    assert p.returncode == 2, p.stderr
    lines = [ln for ln in p.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "slice_rule" in lines[0] and "Traceback" not in p.stderr, p.stderr


def test_gauss_case_runs_through_the_console_script_and_says_its_rule(tmp_path):
    """0.2 ms of the hub study's case: the file names the quadrature it was computed with."""
    import xarray as xr

    out = tmp_path / "g.nc"
    run("simulate", str(ROOT / "examples" / "hub-moment-gauss.toml"), "--duration", "0.2 ms", "--out", str(out),
        "--quiet")
    with xr.open_dataset(out) as ds:
        assert ds.attrs["traction_quadrature"].startswith("Gauss-Legendre, 4 nodes"), ds.attrs
        assert ds.sizes["time"] == 3


@pytest.mark.parametrize("rule, n, base, says", [
    ("split", 6, SPLIT_BASE, "6 equal strips, cut at the zeros of the rolling slip"),
    ("log", 7, LOG_BASE, "7 nodes, generalized Gauss rules exact for the logarithm of the zeros of the rolling slip")])
def test_rule_reaches_the_kernel_above_its_base_and_says_its_rule(tmp_path, rule, n, base, says):
    """slice_rule = "split" (n equal strips cut at the zeros of the rolling slip, tests/unit/test_split_strips.py) and
    "log" (n nodes in all, tests/unit/test_log_rule.py): the kernel takes SPLIT_BASE + n or LOG_BASE + n, a resume
    never mixes the rule with the equal strips, and the output file names it."""
    import xarray as xr

    case = case_from_dict(_data(slice_rule=rule, n_slices=n), base=HUB.parent)
    assert case.model_options()["n_slices"] == base + n
    assert case.fingerprint() != case_from_dict(_data(n_slices=n), base=HUB.parent).fingerprint()
    path = tmp_path / f"{rule}.toml"
    path.write_text(HUB.read_text().replace("n_slices = 8", f'n_slices = {n}\nslice_rule = "{rule}"'))
    out = tmp_path / "o.nc"
    run("simulate", str(path), "--duration", "0.2 ms", "--out", str(out), "--quiet")
    with xr.open_dataset(out) as ds:
        assert ds.attrs["traction_quadrature"] == says, ds.attrs
        assert ds.sizes["time"] == 3


@pytest.mark.parametrize("rule, n", [("split", 6), ("gauss", 4), ("log", 7)])
def test_coulomb_stand_in_takes_equal_strips_whatever_the_rule(rule, n):
    """The rules are the lubricated kernel's: the Coulomb stand-in's slice table is built for n equal strips (before
    the fix it was given SPLIT_BASE + n or LOG_BASE + n strips, or −n)."""
    c = case_from_dict(_data(slice_rule=rule, n_slices=n, traction="coulomb"), base=HUB.parent)
    assert c.model_options()["n_slices"] == n
