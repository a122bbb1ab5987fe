"""Defects a new-user trial of the console script found (session 26), each through the installed ``bearingsim``:
internal errors where an input error was due, a study's unbounded size, a filter that answered nothing, lives
rounded to "0 h", and a life note that contradicted the moment load."""

from __future__ import annotations

import os
import shutil
import subprocess

import pytest

SCRIPT = shutil.which("bearingsim")


def run(*args):
    assert SCRIPT is not None, "the console script `bearingsim` is not installed (pip install -e .)"
    env = dict(os.environ)
    env.pop("BEARINGSIM_DEBUG", None)
    return subprocess.run([SCRIPT, *map(str, args)], capture_output=True, text=True, env=env, timeout=600)


def error_lines(p) -> list[str]:
    return [ln for ln in p.stderr.splitlines() if ln.strip() and not ln.startswith(("compiling ", "compiled "))]


@pytest.mark.parametrize("args, field, words", [
    # a single-row bearing given to the double-row hub study was an IndexError ("internal error", exit 1)
    (["reproduce", "hub-static", "--bearing", "6205", "--points", "3"], "--bearing", "double-row"),
    # no bound: 10⁸ moments ran until killed
    (["reproduce", "hub-static", "--points", "100000000"], "--points", "2..10001"),
    # a series the catalogue does not hold printed an empty table, exit 0
    (["catalog", "--series", "99"], "--series", "62"),
    # clearance took a 1 km interference (operating clearance −832 m), 10⁶ rpm (static refuses it), 5000 °C, and a
    # key given twice (the last one won silently)
    (["clearance", "6205", "--shaft-fit", "1e9"], "--shaft-fit", "µm per mm"),
    (["clearance", "6205", "--speed", "1e6 rpm"], "--speed", "n·d_m"),
    (["clearance", "6205", "--temperatures", "inner=5000 degC"], "--temperatures inner", "500 °C"),
    (["clearance", "6205", "--temperatures", "inner=70 degC,inner=80 degC"], "--temperatures", "twice"),
])
def test_an_input_the_command_cannot_take_is_one_line_exit_2(args, field, words, tmp_path):
    p = run(*args, *(["--out", tmp_path / "o"] if args[0] == "reproduce" else []))
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith(f"error: {field}: ") and words in err[0], p.stderr
    assert not (tmp_path / "o").exists()


def test_a_short_life_is_printed_in_significant_digits_not_rounded_to_zero():
    """6205 under 50 kN radial at 1500 rpm: L10 = (C/P)³ = 0.0219 × 10⁶ rev, 10⁶ L10 / (60 n) = 0.244 h (ISO 281) —
    it was printed "L10 = 0 h"; the hours must be the printed revolutions at the printed speed."""
    p = run("static", "6205", "--fr", "50 kN", "--speed", "1500")
    line = next(ln for ln in p.stdout.splitlines() if ln.startswith("basic rating life L10 ="))
    rev = float(line.split("(")[1].split("×")[0])
    hours = float(line.split("=")[1].split("h at")[0])
    assert hours == pytest.approx(rev * 1e6 / (60 * 1500), rel=5e-3), line
    assert hours > 0


def test_a_pure_moment_is_not_called_no_load():
    """Under a moment alone ISO 281's P is 0, but the bearing is loaded (the reference rating life counts the
    moment): the note said "no load: infinite rating life" beside a finite L10r."""
    p = run("static", "6205", "--moment", "20 N*m", "--speed", "1500")
    assert p.returncode == 0, p.stderr
    text = p.stdout + p.stderr
    assert "no load: infinite rating life" not in text
    assert "no radial or axial load (P = 0)" in text and "reference rating life L10r = " in text


def test_lubrication_reports_the_static_solutions_limit_warnings():
    """`lubrication` under a load far past the contact's static limit printed no warning, while `static` on the same
    inputs warns of the contact pressure and s0 < 1: the same warnings now, in the text and the JSON."""
    args = ["skf-7011-cdga-hc", "--fa", "1e6", "--speed", "10000"]
    st = run("static", *args, "--json")
    lu = run("lubrication", *args, "--json")
    import json

    ws, wl = json.loads(st.stdout)["warnings"], json.loads(lu.stdout)["warnings"]
    assert ws and wl == ws, (ws, wl)
    text = run("lubrication", *args).stdout
    assert sum(ln.startswith("warning: ") for ln in text.splitlines()) == len(ws), text


def test_a_tilt_past_a_few_degrees_is_refused_on_both_paths():
    """--tilt fixed --misalignment "90 deg" was solved to "converged" with γz = 1571 mrad and M_z = 3.6e6 N·m; a
    tilt past MAX_MISALIGNMENT (0.1 rad) is now an input error naming the option (CLI) or the argument (library),
    and a tilt of arc minutes still solves."""
    from bearingsim.errors import InputError
    from bearingsim.io import load_bearing
    from bearingsim.statics.jones_harris import MAX_MISALIGNMENT, Loads, solve

    p = run("static", "6205", "--fr", "2000", "--speed", "1500", "--tilt", "fixed", "--misalignment", "90 deg")
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith("error: --misalignment: "), p.stderr
    with pytest.raises(InputError) as e:
        solve(load_bearing("6205"), Loads(fr_y=2000.0), 157.0, tilt="fixed", misalignment=(0.0, 1.01 * MAX_MISALIGNMENT))
    assert e.value.field == "misalignment"
    ok = solve(load_bearing("6205"), Loads(fr_y=2000.0), 157.0, tilt="fixed", misalignment=(0.0, 5.8e-4))
    assert ok.converged


def test_simulate_says_when_its_start_is_past_a_physical_limit(tmp_path):
    """A case under 10¹² N ran to exit 0 with nothing said (ring displacement −5 m in the file): the warnings of its
    quasi-static start (contact pressure, contact angle, s0) are now printed and in the JSON summary."""
    import json
    from pathlib import Path

    case = Path(__file__).resolve().parents[2] / "examples" / "spindle-7011.toml"
    text = case.read_text(encoding="utf-8")
    assert '\nfa = "' in text
    lines = [('fa = "1e12 N"' if ln.startswith("fa = ") else ln) for ln in text.splitlines()]
    huge = tmp_path / "huge.toml"
    huge.write_text("\n".join(lines) + "\n", encoding="utf-8")
    p = run("simulate", huge, "--out", tmp_path / "h.nc", "--duration", "0.05 ms", "--json")
    summary = json.loads(p.stdout)
    ws = summary["initial_static_warnings"]
    assert any("contact pressure" in w for w in ws), ws
    said = [ln for ln in error_lines(p) if ln.startswith("warning: the quasi-static start at t = 0: ")]
    assert len(said) == len(ws), p.stderr


@pytest.mark.parametrize("args, start", [
    # the library's argument names had reached the user instead of the options typed
    (["map", "6205", "--fr", "abc"], "error: --fr: "),
    (["map", "6205", "--fr", "1000:2000:2", "--chunk", "0"], "error: --chunk: "),
    (["static", "6205", "--fr", "1000", "--control", "bogus"], "error: --control: "),
    (["export", "ross", "6205", "--fr", "1000", "--speed", "0:100:2", "--node", "-1", "--out", "{d}/x.toml"],
     "error: --node: "),
    # an empty name was "'.' is a directory"
    (["static", ""], "error: bearing: the name is empty"),
])
def test_errors_name_the_option_the_user_typed(args, start, tmp_path):
    p = run(*[a.replace("{d}", str(tmp_path)) for a in args])
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith(start), p.stderr


def test_a_pasted_value_is_shortened_not_the_fix():
    """A 5,000-character bearing name: the line was cut at 400 characters, the fix lost (and an OSError 'file name
    too long' underneath); now the value is shortened and the fix kept; an unknown designation gets its neighbours
    (the full catalogue list had been cut mid-list)."""
    p = run("static", "x" * 5000)
    err = error_lines(p)
    assert p.returncode == 2 and len(err) == 1 and len(err[0]) < 400, p.stderr
    assert "(5000 characters)" in err[0] and err[0].endswith("or give a path to a .toml file)"), err[0]
    p = run("static", "6299")
    assert error_lines(p) == ["error: bearing: '6299' is neither a catalogue name nor a TOML file (did you mean 6219 "
                              "or 6209?)"], p.stderr


def test_a_report_refuses_another_bearings_map(tmp_path):
    """`report 6205 --map M` with M made for the 7011 drew the 7011's stiffness under the 6205's name (exit 0): now
    one line naming --map, exit 2, before anything is written; the same map with its own bearing still works."""
    m = tmp_path / "m7011.nc"
    assert run("map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--speed", "0:6000:3", "--out", m).returncode == 0
    p = run("report", "6205", "--fr", "1000", "--map", m, "--out", tmp_path / "rep")
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith("error: --map: m7011.nc is a map of SKF 7011"), p.stderr
    assert not (tmp_path / "rep" / "report.html").exists()
    ok = run("report", "skf-7011-cdga-hc", "--fa", "1000", "--map", m, "--out", tmp_path / "rep2")
    assert ok.returncode == 0 and (tmp_path / "rep2" / "report.html").is_file(), ok.stderr


def test_the_spindle_study_says_when_it_compares_two_bearings(tmp_path):
    """`reproduce spindle-axial-stiffness --bearing 6205` printed "deviation" columns against the paper's 7011
    values without a word; now a note says so (and none for the paper's own bearing)."""
    other = run("reproduce", "spindle-axial-stiffness", "--bearing", "6205", "--out", tmp_path / "a")
    own = run("reproduce", "spindle-axial-stiffness", "--out", tmp_path / "b")
    assert other.returncode == 0 and own.returncode == 0, other.stderr + own.stderr
    assert "they compare two bearings" in other.stdout and "they compare two bearings" not in own.stdout


@pytest.mark.parametrize("args, field", [
    # 100,000 elements per pitch ran out of memory ("error: out of memory", exit 1)
    (["cage-modes", "6205", "--elements-per-pitch", "100000"], "--elements-per-pitch"),
    # a 1 mm pocket for a 7.9 mm ball gave modes, exit 0
    (["cage-modes", "6205", "--pocket-diameter", "1 mm"], "--pocket-diameter"),
])
def test_cage_inputs_past_sense_are_refused(args, field):
    p = run(*args)
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith(f"error: {field}: "), p.stderr


@pytest.mark.parametrize("args", [["static", "6205", "--fr", "1000", "--speed", "1500"],
                                  ["static", "6205", "--fr", "1000", "--speed", "1500", "--json"],
                                  ["catalog"]])
def test_a_closed_stdout_ends_with_141_not_the_status_of_not_converged(args):
    """`bearingsim static … | head -1` ended with status 1 (rich's handling of a broken pipe), which the command
    line reserves for "not converged": now 141 (128 + SIGPIPE, as shell tools), nothing on stderr.  The reader
    here closes the pipe before the command writes, so every write meets the broken pipe."""
    env = {k: v for k, v in os.environ.items() if k != "BEARINGSIM_DEBUG"}
    p = subprocess.Popen([SCRIPT, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env)
    p.stdout.close()
    err = p.stderr.read().decode()
    assert p.wait(timeout=600) == 141, err
    assert [ln for ln in err.splitlines() if ln.strip() and not ln.startswith(("compiling ", "compiled "))] == [], err
