"""benchmarks/bench_jacobian_age.py (issue 14, fifteenth pass): the amplification matrix of one ROS34PW2 step is the
method's stability function R(z) on each eigenvalue — R(z) = e^z + O(z⁴) (order 3) and R(−∞) = 0 (L-stable, Rang &
Angermann 2005) — and with W made of another matrix it is the W-method's; the script runs on the hub case."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def test_amplification_is_the_stability_function(benchmark_module):
    bj = benchmark_module("bench_jacobian_age")
    lam = np.array([-1e-3, -1e-2, -0.1, 0.05, -1e9])
    a = np.diag(lam)
    r = np.diag(bj.amplification(a, a, 1.0))
    small = np.abs(lam) <= 0.1
    # order 3: the error of R(z) against e^z falls as z⁴ (the ratio to z⁴ bounded and not growing as z → 0)
    err = np.abs(r[small] - np.exp(lam[small]))
    assert np.all(err <= 0.05 * np.abs(lam[small]) ** 4 + 1e-15), (err, lam[small])
    assert abs(r[-1]) < 1e-6, r[-1]  # L-stable: R(z) → 0 as z → −∞
    # a W matrix other than the problem's own: still a stable step on a stiff mode with J close to it, not with J = 0
    j_close = np.diag(lam * 1.05)
    assert abs(np.diag(bj.amplification(a, j_close, 1.0))[-1]) < 1.0
    assert abs(np.diag(bj.amplification(a, np.zeros_like(a), 1.0))[-1]) > 1e6


def test_jacobian_age_on_the_hub_from_the_command_line():
    out = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_jacobian_age.py"), "--t1", "0.2 ms", "--age",
                          "20 us", "--steps", "2"], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    fresh = [ln for ln in out.stdout.splitlines() if ln.strip().startswith("fresh")]
    assert fresh, out.stdout
    rho = float(fresh[0].rsplit(" ", 1)[-1])
    assert 0.99 < rho < 1.01, out.stdout  # the fresh Jacobian's step is stable (the spectrum's growth is slow)
