"""benchmarks/bench_jacobian_age.py (issue 14, fifteenth pass): the amplification matrix of one ROS34PW2 step is the
method's stability function R(z) on each eigenvalue — R(z) = e^z + O(z⁴) (order 3) and R(−∞) = 0 (L-stable, Rang &
Angermann 2005) — and with W made of another matrix it is the W-method's (the integrator's own stages and W solves); the script runs
on the hub case."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def _step_matrix(bj, lam, jdiag):
    """R of one step on y′ = diag(lam) y with W made of diag(jdiag) (one block, no ring)."""
    blk = np.array([0], dtype=np.int64)
    a = np.diag(lam)
    balls = (np.diag(jdiag)[None, :, :],)
    return bj.amplification(a, blk, balls, None, 1.0)


def test_amplification_is_the_stability_function(benchmark_module):
    """The integrator's own step (its stages and W solves) on a diagonal problem: R(z) = e^z + O(z⁴) — order 3,
    Rang & Angermann's ROS34PW2 — and R(−∞) = 0 (L-stable); with W = I (J = 0) the stiff mode blows up."""
    bj = benchmark_module("bench_jacobian_age")
    lam = np.array([-1e-3, -1e-2, -0.1, 0.05, -1e9])
    r = _step_matrix(bj, lam, lam)
    assert np.allclose(r, np.diag(np.diag(r)), rtol=0, atol=1e-14)  # no coupling between the modes
    r = np.diag(r)
    small = np.abs(lam) <= 0.1
    err = np.abs(r[small] - np.exp(lam[small]))
    assert np.all(err <= 0.05 * np.abs(lam[small]) ** 4 + 1e-15), (err, lam[small])
    assert np.any(err > 1e-6 * np.abs(lam[small]) ** 4)  # (the bound is not met trivially: the error is there)
    assert abs(r[-1]) < 1e-6, r[-1]
    assert abs(np.diag(_step_matrix(bj, lam, lam * 1.05))[-1]) < 1.0  # J close to A: still stable
    assert abs(np.diag(_step_matrix(bj, lam, 0.0 * lam))[-1]) > 1e6  # J = 0: explicit on the stiff mode


def test_jacobian_age_on_the_hub_from_the_command_line():
    out = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "bench_jacobian_age.py"), "--t1", "0.2 ms", "--age",
                          "20 us", "--steps", "2"], capture_output=True, text=True, timeout=600)
    assert out.returncode == 0, out.stderr
    fresh = [ln for ln in out.stdout.splitlines() if ln.strip().startswith("fresh")]
    assert len(fresh) == 2, out.stdout  # the engine's (ring columns derived) and the ring's finite differences
    for line in fresh:
        rho = float(line.rsplit(" ", 1)[-1])
        assert 0.99 < rho < 1.01, out.stdout  # the fresh Jacobian's step is stable (the spectrum's growth is slow)
