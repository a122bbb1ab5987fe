"""Threads in the dynamic right-hand side (issue 14, lever 3): the balls' contacts run in a numba prange and
their reactions on the rings are summed serially in ball order, so any thread count gives the same result
bit for bit.  The suite runs with NUMBA_NUM_THREADS=1 (tests/conftest.py); the two-thread evaluations run
in a subprocess with NUMBA_NUM_THREADS=2 on states of a serial run of this process (the integrator is the
same code for any thread count, and its threaded linear algebra sums in ball order: a 2-thread ROS34PW2 run must
reach the serial run's states bit for bit, the multirate refinement's steps from the hub's moment zero crossing
included)."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from bearingsim.dynamics.stepper import resolve_threads
from bearingsim.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
CASES = (("hub-moment-50hz.toml", "slices"), ("spindle-7011.toml", "coulomb"))

_SCRIPT = textwrap.dedent("""
    import dataclasses, sys, numba, numpy as np
    from bearingsim.dynamics import forces as fo, run as R
    from bearingsim.dynamics.case import load_case
    assert numba.config.NUMBA_NUM_THREADS == 2
    numba.set_num_threads(2)
    d = np.load(sys.argv[1])
    for name, trac in %r:
        m, ls, _, _ = R.build(dataclasses.replace(load_case("examples/" + name), traction=trac))
        for i, y in enumerate(d[name + ":y"]):
            for part, v in zip(("dy", "diag", "gdiag"), fo.evaluate(m, 0.0, y, ls, threads=True)):
                ref = d[f"{name}:{part}{i}"]
                assert np.array_equal(v, ref), (name, i, part, np.abs(v - ref).max())
        if trac == "slices":  # the integrator on 2 threads (W's ball blocks too: linalg.coupled_w_threaded)
            case = load_case("examples/" + name)
            m, ls, y0, _ = R.build(case)
            st = R.Stepper(m, ls, y0.copy(), tol=case.tolerance, method=case.method, threads=2)
            for k, t in ((2, 1e-5), (3, 2e-5)):
                st.advance(t)
                assert np.array_equal(st.y, d[name + ":y"][k]), (name, t, np.abs(st.y - d[name + ":y"][k]).max())
    # the multirate refinement on 2 threads (its two groups of balls: multirate.refine_groups_threaded), from the hub's moment zero crossing
    case = load_case("examples/hub-moment-50hz.toml")
    m, ls, _, _ = R.build(case)
    st = R.Stepper(m, ls, d["zc:y0"].copy(), t=float(d["zc:t0"]), h=float(d["zc:h0"]), tol=case.tolerance,
                   method="ros34w", threads=2, multirate=8, dense=True)
    st.advance(float(d["zc:t_end"]))
    assert st.workspace.work[4] > 2 * st.workspace.work[5] > 0, list(st.workspace.work)  # several balls a step
    assert np.array_equal(st.y, d["zc:y"]), np.abs(st.y - d["zc:y"]).max()
    assert np.array_equal(st.state_at(float(d["zc:t_out"])), d["zc:y_out"])
    # the output sample on the run's threads (Stepper.sample: its two evaluations, the rolling-resistance share)
    out = st.sample(float(d["zc:t_out"]), st.state_at(float(d["zc:t_out"])))
    keys = [k for k in d.files if k.startswith("zs:")]
    assert len(keys) > 10 and d["zs:power_loss_rolling"] != 0.0
    for k in keys:
        assert np.array_equal(np.asarray(out[k[3:]]), d[k]), k
    print("bitwise ok")
""" % (CASES,))


def test_two_threads_give_the_one_thread_result_bit_for_bit(tmp_path):
    import dataclasses

    from bearingsim.dynamics import forces as fo
    from bearingsim.dynamics import run as R
    from bearingsim.dynamics.case import load_case

    data = {}
    for name, trac in CASES:
        case = dataclasses.replace(load_case(ROOT / "examples" / name), traction=trac)
        m, ls, y0, _ = R.build(case)
        states = [y0, y0 * (1.0 + 1e-4 * np.sin(np.arange(y0.size)))]  # the start, and one where all contacts slide
        if trac == "slices":  # and states of a serial ROS34PW2 run (contacts loaded, traction developing)
            st = R.Stepper(m, ls, y0.copy(), tol=case.tolerance, method=case.method, threads=1)
            for t in (1e-5, 2e-5):
                st.advance(t)
                states.append(st.y.copy())
        data[name + ":y"] = np.array(states)
        for i, y in enumerate(states):
            out = fo.evaluate(m, 0.0, y, ls, threads=False)
            assert np.abs(out[0]).max() > 0 and out[1][:, 0].max() > 0
            for part, v in zip(("dy", "diag", "gdiag"), out):
                data[f"{name}:{part}{i}"] = v
    # the multirate refinement (tests/unit/test_dyn_multirate.py): 0.3 ms from the hub's moment zero crossing, where
    # most steps refine several balls; the 2-thread run must reach the same state and dense output bit for bit
    case = load_case(ROOT / "examples" / "hub-moment-50hz.toml")
    m, ls, y0, _ = R.build(case)
    zc = R.Stepper(m, ls, y0.copy(), tol=case.tolerance, method="ros34w", threads=1, multirate=0)
    zc.advance(9.1e-3)
    ser = R.Stepper(m, ls, zc.y.copy(), t=zc.t, h=zc.h, tol=case.tolerance, method="ros34w", threads=1, multirate=8,
                    dense=True)
    ser.advance(zc.t + 0.3e-3)
    assert ser.workspace.work[4] > 2 * ser.workspace.work[5] > 0, list(ser.workspace.work)
    t_out = 0.5 * (ser.t + float(ser._dense[1][0]))  # inside the last step
    data.update({"zc:y0": zc.y, "zc:t0": zc.t, "zc:h0": zc.h, "zc:t_end": zc.t + 0.3e-3, "zc:y": ser.y,
                 "zc:t_out": t_out, "zc:y_out": ser.state_at(t_out)})
    data.update({"zs:" + k: np.asarray(v) for k, v in ser.sample(t_out, ser.state_at(t_out)).items()
                 if np.asarray(v).dtype.kind == "f"})
    np.savez(tmp_path / "ref.npz", **data)
    env = dict(os.environ, NUMBA_NUM_THREADS="2")
    r = subprocess.run([sys.executable, "-c", _SCRIPT, str(tmp_path / "ref.npz")], cwd=ROOT, env=env,
                       capture_output=True, text=True, timeout=900)
    assert r.returncode == 0, r.stderr[-3000:]
    assert "bitwise ok" in r.stdout


def test_thread_count_is_checked():
    assert resolve_threads(1) == 1
    assert resolve_threads(None) == 1  # the library stays serial by default (stepper.Stepper.threads)
    assert resolve_threads("auto") == 1  # the idle cores, capped by NUMBA_NUM_THREADS = 1 in the suite (conftest)
    for bad in (0, -1, 10_000, 1.5, True, "many"):
        with pytest.raises(InputError, match="threads"):
            resolve_threads(bad)


@pytest.mark.parametrize("bad, words", [("0", ("threads",)), ("lots", ("--threads", "auto"))])
def test_cli_rejects_a_bad_thread_count_in_one_line(tmp_path, bad, words):
    r = subprocess.run(["bearingsim", "simulate", str(ROOT / "examples" / "spindle-7011.toml"), "--out",
                        str(tmp_path / "x.nc"), "--threads", bad, "--quiet"], capture_output=True, text=True,
                       timeout=300)
    assert r.returncode == 2, (r.stdout, r.stderr)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and all(w in lines[0] for w in words), r.stderr


def test_serial_loop_is_the_per_ball_function_written_out():
    """The one-thread loop of balls_on_raceways is the body of _one_ball written out (a call per ball cost 13 %
    of the right-hand side): the two texts must stay the same statement for statement, or the one- and
    many-thread results would drift apart."""
    import inspect
    import re
    import textwrap as tw

    from bearingsim.dynamics import forces as fo

    one = inspect.getsource(fo._one_ball.py_func)
    body = one[one.index("    r = ball_row[k]\n"):]
    for old, new in (("fring", "fr"), ("mring", "mr"), ("fout", "fo"), ("mout", "mo")):
        body = re.sub(r"\b%s\b" % old, new, body)
    drv = inspect.getsource(fo.balls_on_raceways.py_func)
    copy = drv[drv.index("# ---- BEGIN copy"):drv.index("# ---- END copy")]
    copy = copy[copy.index("\n") + 1:]

    def norm(text):
        return [ln.strip() for ln in tw.dedent(text).splitlines() if ln.strip()]

    assert norm(copy) == norm(body)
    assert len(norm(body)) > 80


def test_idle_cores_counts_only_cores_the_others_leave(monkeypatch):
    """--threads auto: the cores this process may use less the cores busy now, rounded, within
    1..NUMBA_NUM_THREADS (the OpenMP layer's spinning threads cost several times the work on busy cores:
    forces.py); the one-minute load average only where /proc/stat cannot be read."""
    import os

    import numba

    from bearingsim.dynamics import stepper

    monkeypatch.setattr(numba.config, "NUMBA_NUM_THREADS", 16)
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: set(range(8)))
    for busy, want in ((0.0, 8), (0.4, 8), (0.6, 7), (3.2, 5), (7.9, 1), (40.0, 1)):
        monkeypatch.setattr(stepper, "busy_cores", lambda window, busy=busy: busy)
        assert stepper.idle_cores() == want, (busy, stepper.idle_cores())
    monkeypatch.setattr(stepper, "busy_cores", lambda window: None)  # no /proc/stat: the load average
    monkeypatch.setattr(os, "getloadavg", lambda: (2.2, 0.0, 0.0))
    assert stepper.idle_cores() == 6
    monkeypatch.setattr(numba.config, "NUMBA_NUM_THREADS", 2)
    monkeypatch.setattr(os, "getloadavg", lambda: (0.0, 0.0, 0.0))
    assert stepper.idle_cores() == 2


def test_busy_cores_from_two_reads_of_proc_stat(monkeypatch, tmp_path):
    """The busy share between two reads of /proc/stat's first line, times the CPU count."""
    import os

    from bearingsim.dynamics import stepper

    stat = tmp_path / "stat"
    reads = iter(["cpu  100 0 50 800 50 0 0 0 0 0\n", "cpu  250 0 100 1000 50 0 0 0 0 0\n"])

    def read():
        stat.write_text(next(reads))
        return stepper._cpu_times(str(stat))

    monkeypatch.setattr(os, "cpu_count", lambda: 4)
    # busy 150 + 50 = 200 of 400 jiffies: half of 4 CPUs
    assert stepper.busy_cores(0.0, read) == 2.0
    stat.write_text("not a stat file\n")
    assert stepper._cpu_times(str(stat)) is None
    assert stepper._cpu_times(str(tmp_path / "missing")) is None


_SEQUENCE = textwrap.dedent("""
    import sys, numpy as np
    from bearingsim.dynamics import run as R, forces as fo
    from bearingsim.dynamics.case import load_case
    m, ls, y, _ = R.build(load_case("examples/hub-moment-50hz.toml"))
    if sys.argv[1] == "threaded":
        fo.rhs_args_threaded(0.0, y, np.zeros_like(y), fo.args_of(m, ls))
    else:
        dy = fo.evaluate(m, 0.0, y, ls, threads=True)[0]
        assert np.isfinite(dy).all() and np.abs(dy).max() > 0
    print("ok")
""")


def test_a_cached_kernel_calling_the_parallel_one_loads_in_a_fresh_process():
    """The sequence that killed a hub-study worker: a fresh process loads from the cache a kernel compiled without
    ``parallel`` that calls the parallel ball loop, and runs it.  Process 1 compiles and caches the threaded
    right-hand side (``rhs_args_threaded`` → ``rhs`` → ``_rhs`` → ``balls_on_raceways``, none parallel, calling
    ``_balls_parallel``); processes 2 and 3 load it and run it (``evaluate(threads=True)``).  Before forces.py
    started the threading layer at import, such a process died (segmentation fault, or "LLVM ERROR: Symbol not
    found: allocate_sched"), since numba registers the layer's symbols only when the layer starts.  (``evaluate``
    compiled a kernel of its own before, threads a run-time flag; it now calls the engine's: forces._rhs.)"""
    env = dict(os.environ, NUMBA_NUM_THREADS="2")
    # (the suite's own kernel cache: the kernel is there already when the bitwise test above ran, which changes
    # nothing for processes 2 and 3; a cache of its own before, 71 s of compilation in the CI)
    for step in ("threaded", "evaluate", "evaluate"):
        r = subprocess.run([sys.executable, "-c", _SEQUENCE, step], cwd=ROOT, env=env, capture_output=True,
                           text=True, timeout=900)
        assert r.returncode == 0 and "ok" in r.stdout, (step, r.returncode, r.stderr[-2000:])


def test_balls_are_dealt_in_contiguous_quarters():
    """forces.dealt: every ball once for any count; on 2 threads (numba's static schedule: a contiguous half of the
    iterations each) each thread's balls are two contiguous runs, a quarter of the row numbering apart."""
    from bearingsim.dynamics.forces import dealt

    for nb in range(1, 70):
        ks = [dealt(i, nb) for i in range(nb)]
        assert sorted(ks) == list(range(nb)), (nb, ks)
    ks = [dealt(i, 32) for i in range(32)]
    assert ks[:16] == list(range(0, 8)) + list(range(16, 24)) and ks[16:] == list(range(8, 16)) + list(range(24, 32))
