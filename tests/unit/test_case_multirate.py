"""The case-file key ``multirate`` (issue 14, eighteenth pass): the most balls a ROS34PW2 step refines with micro steps
of their own (:mod:`bearingsim.dynamics.integrate.multirate`); 0 is the plain method."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest
from _cli import run  # tests/unit/_cli.py: the installed console script

from bearingsim.dynamics.case import MULTIRATE_DEFAULT, case_from_dict
from bearingsim.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
HUB = ROOT / "examples" / "hub-moment-50hz.toml"


def _data(**kw):
    return {**tomllib.loads(HUB.read_text()), **kw}


def test_default_and_zero_reach_the_stepper_and_the_fingerprint():
    from bearingsim.dynamics.run import Stepper, build

    on = case_from_dict(_data(), base=HUB.parent)
    off = case_from_dict(_data(multirate=0), base=HUB.parent)
    assert on.multirate == MULTIRATE_DEFAULT == 8 and off.multirate == 0
    assert on.fingerprint() != off.fingerprint()  # a resume never mixes the two
    m, ls, y, _ = build(off)
    assert Stepper(m, ls, y, method="ros34w").multirate == MULTIRATE_DEFAULT  # (the library's default too)


@pytest.mark.parametrize("bad", [True, -1, 2.5, "eight", 10**6, [8]])
def test_bad_value_names_the_field(bad):
    with pytest.raises(InputError) as e:
        case_from_dict(_data(multirate=bad), base=HUB.parent)
    assert e.value.field == "multirate" and e.value.fix


def test_console_script_refuses_a_bad_value_in_one_line(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(HUB.read_text().replace("n_slices = 8", 'n_slices = 8\nmultirate = "lots"'))
    p = run("simulate", str(case), "--out", str(tmp_path / "o.nc"), check=False)
    assert p.returncode == 2, p.stderr
    lines = [ln for ln in p.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and "multirate" in lines[0] and "Traceback" not in p.stderr, p.stderr


def test_output_file_says_whether_the_steps_refine(tmp_path):
    """0.2 ms of the hub case through the console script, with and without the refinement: the output's
    ``integrator`` attribute names it only when it is on."""
    import xarray as xr

    texts = {}
    for mr in (8, 0):
        case = tmp_path / f"mr{mr}.toml"
        case.write_text(HUB.read_text().replace("n_slices = 8", f"n_slices = 8\nmultirate = {mr}"))
        out = tmp_path / f"mr{mr}.nc"
        run("simulate", str(case), "--duration", "0.2 ms", "--out", str(out), "--quiet")
        with xr.open_dataset(out) as ds:
            texts[mr] = ds.attrs["integrator"]
            assert ds.sizes["time"] == 3
    assert "up to 8 per step" in texts[8] and "multirate" not in texts[0], texts
