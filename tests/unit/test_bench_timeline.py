"""benchmarks/bench_dynamics.py --timeline (issue 14, fifteenth pass): the per-window counts are the integrator's own
and add up to the steps of one uninterrupted run (the dense-output stepper's trajectory does not depend on where the
windows stop it); the console path gives the table and the summary line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def test_timeline_windows_add_up_to_one_run(benchmark_module):
    from bearingsim.dynamics import run as R

    bd = benchmark_module("bench_dynamics")
    tl = bd.step_timeline("a", 0.3e-3, 0.1e-3)
    case = bd.load_bench_case("a")
    m, ls, y, _ = R.build(case)
    st = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, dense=True)
    st.advance(0.3e-3)
    assert tl["steps"].shape == (3,) and tl["steps"].min() > 0
    assert int(tl["steps"].sum()) == st.steps and int(tl["rejected"].sum()) == st.rejected
    assert tl["jacobians"][0] >= 1  # the first window refreshes the Jacobian at its first step
    assert int(tl["jacobians"].sum()) == int(st.workspace.work[2])
    assert tl["rhs"] == int(st.workspace.work[0]) > 4 * st.steps  # ≥ 4 per step: f(t, y) and three stages
    assert (tl["q_max"] > 0).all() and (tl["q_min"] <= tl["q_max"]).all()


def test_timeline_from_the_command_line():
    out = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_dynamics.py"), "--case", "a", "--timeline",
                          "0.1 ms", "--duration", "0.2 ms"], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    lines = out.stdout.splitlines()
    assert any("steps per 100 us window" in ln for ln in lines), out.stdout
    assert any("windows step faster than twice the median" in ln for ln in lines), out.stdout
    assert any(ln.strip().startswith("work: ") and "right-hand sides" in ln for ln in lines), out.stdout
