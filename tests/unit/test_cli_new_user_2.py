"""What a new user hit (issue 42, command-line half), each through the installed console script."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import time

import numpy as np
import pytest
from _cli import SCRIPT, run  # tests/unit/_cli.py: the installed console script


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


_RESUME_CASE = """
bearing = "skf-7011-cdga-hc"
speed = "10000 rpm"
duration = "16 ms"
output_interval = "0.05 ms"
traction = "coulomb"
chunk = 1000
[loads]
fa = "3000 N"
mz = { offset = "0 N*m", amplitude = "20 N*m", frequency = "500 Hz" }
"""


def test_a_resumed_run_reports_its_segment_and_the_whole_run_apart(tmp_path):
    """The summary of `simulate --resume` gives the resumed segment's time and steps together, and the whole run's
    time and steps labelled as such (the segment's time was printed with the whole run's step count)."""
    case = tmp_path / "case.toml"
    case.write_text(_RESUME_CASE)
    out = tmp_path / "run.nc"
    ckpt = tmp_path / "run.nc.ckpt.npz"
    p = subprocess.Popen([SCRIPT, "simulate", str(case), "--out", str(out), "--checkpoint-every", "0.2 s",
                          "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    t0, saved = time.monotonic(), None
    while saved is None and time.monotonic() - t0 < 120:
        assert p.poll() is None, f"the run ended before its first checkpoint: {p.stderr.read().decode()[-300:]}"
        try:
            with np.load(ckpt) as c:
                saved = (int(c["index"]), int(c["steps"])) if int(c["index"]) > 0 else None
        except (OSError, ValueError, EOFError, KeyError):
            pass
        time.sleep(0.01)
    os.killpg(p.pid, signal.SIGKILL)
    p.wait(timeout=10)
    assert saved is not None, "no checkpoint within 120 s"
    with np.load(ckpt) as c:  # the checkpoint the resumed run starts from (a later one may have replaced it)
        index, steps_before = int(c["index"]), int(c["steps"])
    r = run("simulate", str(case), "--out", str(out), "--resume", "--quiet")
    line = " ".join(r.stderr.split())  # the summary goes to stderr, wrapped at the console's width
    m = re.search(r"resumed at ([\d.]+) ms, this run ([\d.]+) ms simulated in .*?, (\d+) steps, .*; whole run "
                  r"([\d.]+) ms simulated, (\d+) steps", line)
    assert m, line
    at, seg, seg_steps, total, total_steps = (float(m[1]), float(m[2]), int(m[3]), float(m[4]), int(m[5]))
    assert at == pytest.approx((index - 1) * 0.05, abs=1e-3), line
    assert total == pytest.approx(16.0, abs=1e-3), line
    assert at + seg == pytest.approx(total, abs=2e-3), line
    assert total_steps == steps_before + seg_steps and seg_steps > 0, line
