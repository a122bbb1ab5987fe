"""benchmarks/bench_compare.py reads the figure of each benchmark line it compares (no timing here: the figures
depend on the machine)."""

from __future__ import annotations

import pytest


def test_first_figure_of_each_benchmark_line_kind(benchmark_module):
    bc = benchmark_module("bench_compare")
    dyn = ("case (b) traction=slices integrator=ros34w tol=1e-06 n_slices=8 threads=2: 100 ms simulated in 11 s "
           "-> 109.6 wall s per simulated s (217.9 CPU s); 35074 steps (2030 rejected); peak RSS 341 MB")
    assert bc.first_figure(dyn) == 109.6
    assert bc.first_figure("[S0] 8 x 5 grid: 50,500 points/s") == 50500.0
    assert bc.first_figure("case (b) slices  :    82.3 us per right-hand side (32 balls)") == 82.3
    assert bc.first_figure("kernel 1.04 µs per contact") == 1.04
    assert bc.first_figure("no figure on this line") is None


def test_command_needs_the_separator(benchmark_module):
    bc = benchmark_module("bench_compare")
    with pytest.raises(SystemExit):
        bc.main(["HEAD", "bench_dynamics.py"])
