"""The seed 001 hysteresis study (Figs. 7-9): case construction, loop widths, table, bad input."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.io import read_toml
from bearingsim.studies import hub_dynamic as hd

CASE = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"


def _trend_violations(tab):
    v, f = (10, 50, 100), (1, 10, 50)
    n = sum(tab[(s, f[i])] > tab[(s, f[i + 1])] for s in v for i in range(2))
    return n + sum(tab[(v[i], q)] < tab[(v[i + 1], q)] for q in f for i in range(2))


def test_seed_fig9_readings_are_the_two_most_consistent_layouts():
    """Seed 001 §5 / eq. 9: W_H grows with the load frequency and falls with the vehicle speed.  Of the eight
    layouts of the extracted labels (3 groups of 3) on the 3 x 3 grid, our two readings are the ones that break
    this only once."""
    labels = [[3.0, 0.7, 0.3], [4.1, 1.3, 1.3], [6.7, 4.2, 0.9]]
    v, f = (10, 50, 100), (1, 10, 50)
    counts = []
    for by_freq in (True, False):
        for rev_outer in (False, True):
            for rev_inner in (False, True):
                tab = {}
                for gi, grp in enumerate(labels):
                    for ii, val in enumerate(grp):
                        o, i = (2 - gi if rev_outer else gi), (2 - ii if rev_inner else ii)
                        tab[(v[i], f[o]) if by_freq else (v[o], f[i])] = val
                counts.append((_trend_violations(tab), tab))
    counts.sort(key=lambda c: c[0])
    assert [c[0] for c in counts[:3]] == [1, 1, 5]
    assert {tuple(sorted(c[1].items())) for c in counts[:2]} == {tuple(sorted(hd.SEED_FIG9.items())),
                                                                 tuple(sorted(hd.SEED_FIG9_ALT.items()))}


def test_cell_case_changes_speed_frequency_and_duration_only():
    data = read_toml(CASE, "case")
    c = hd.cell_case(data, CASE.parent, 10.0, 10.0, 3)
    assert c.speed.start == pytest.approx(10 / 3.6 / hd.TYRE_RADIUS, rel=1e-12)
    assert c.duration == pytest.approx(0.3, rel=1e-12)
    assert c.output_interval <= 1.0 / 2000 + 1e-15
    # the three load channels now vary at 10 Hz in phase: the moment peaks at t = 1/(4 f) = 25 ms
    np.testing.assert_allclose(c.loads.at(0.025)[[0, 1, 4]], [1890.0, 2785.0 + 965.0, 600.0], rtol=1e-9)
    assert data["loads"]["mz"]["frequency"] == "50 Hz"  # the case file's data are not modified


def test_short_study_runs_and_reports_per_cycle_widths(tmp_path):
    study = hd.run_study(CASE, speeds_kmh=(100.0,), frequencies_hz=(2000.0,), cycles=2)
    (cell,) = study.cells
    assert len(cell.widths) == 1 and np.isfinite(cell.widths).all()
    assert math.isnan(cell.seed())  # not a pair of the seed's Fig. 9
    assert cell.moment.max() == pytest.approx(600.0, rel=1e-3)
    rows = study.rows()
    assert rows[0]["cycles"] == 1 and rows[0]["W_H_mean_mdeg"] == pytest.approx(math.degrees(cell.mean) * 1e3)
    assert study.to_csv(tmp_path / "h.csv").read_text().startswith("speed_kmh,")
    assert study.plot(tmp_path / "h.png").stat().st_size > 0


def test_bad_input(tmp_path):
    with pytest.raises(InputError, match="cycles"):
        hd.run_study(CASE, cycles=1)
    with pytest.raises(InputError, match="speeds"):
        hd.run_study(CASE, speeds_kmh=(-10.0,))
    const = tmp_path / "const.toml"
    const.write_text(CASE.read_text().split("[loads]")[0] + '[loads]\nfr = "2800 N"\n')
    with pytest.raises(InputError, match="loads"):
        hd.run_study(const, cycles=2)


def test_cell_case_output_interval_needs_its_unit():
    data = read_toml(CASE, "case")
    data["output_interval"] = 5e-5  # a bare number in a case file: which unit? (refused as in case_from_dict)
    with pytest.raises(InputError, match="output_interval.*no unit"):
        hd.cell_case(data, CASE.parent, 100.0, 50.0, 3)
    del data["output_interval"]
    with pytest.raises(InputError, match="output_interval"):
        hd.cell_case(data, CASE.parent, 100.0, 50.0, 3)


def test_cli_bad_input_is_one_line_and_exit_2(tmp_path):
    import subprocess
    import sys

    for args, field in ((["--speeds", "fast"], "--speeds"), (["--cycles", "1"], "cycles")):
        r = subprocess.run([sys.executable, "-m", "bearingsim", "reproduce", "hub-hysteresis", str(CASE), *args,
                            "--out", str(tmp_path / "o")], capture_output=True, text=True, timeout=120)
        assert r.returncode == 2, r.stderr
        assert field in (r.stderr + r.stdout)
        assert not list((tmp_path / "o").glob("*.nc"))
