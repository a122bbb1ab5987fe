"""Benchmark of the quasi-static core (issue 2, item 10).  Prints figures; not a test.

(a) the seed-000 8 x 5 speed-load grid on the SKF 7011 CDGA/HC with inertia;
(b) 10,000 random combined loads (Fa 1-5 kN, Fr_y, Fr_z +-500 N, M_y, M_z +-20 N m, 0-11,200 rpm)
    on the same bearing with inertia;
(c) wall time of a warm `bearingsim static skf-7011-cdga-hc --fa 1000 --speed 11200 --json`.

Run:  python benchmarks/bench_static.py
"""

import math
import subprocess
import sys
import time

import numpy as np

from bearingsim.io import load_bearing
from bearingsim.statics.jones_harris import solve_many


def rate(bearing, loads, speeds, repeat=3):
    """Best wall-clock rate [points/s]; the best CPU-time rate (time.process_time, the one-core speed when
    other jobs share the machine) is kept in CPU_RATE[0]."""
    solve_many(bearing, loads[:5], speeds[:5])  # JIT warm-up (and on-disk cache load)
    best = math.inf
    best_cpu = math.inf
    for _ in range(repeat):
        t = time.perf_counter()
        c = time.process_time()
        res = solve_many(bearing, loads, speeds)
        best = min(best, time.perf_counter() - t)
        best_cpu = min(best_cpu, time.process_time() - c)
    CPU_RATE[0] = len(speeds) / best_cpu
    return len(speeds) / best, res


CPU_RATE = [0.0]


def main():
    b = load_bearing("skf-7011-cdga-hc")
    speeds_rpm = np.array([0, 2800, 3550, 4000, 5000, 6000, 7000, 9000, 11000], float)[1:]
    fa = np.array([1000, 2000, 3000, 4000, 5000], float)
    grid_f, grid_n = np.meshgrid(fa, speeds_rpm, indexing="ij")  # speed varies fastest
    loads = np.zeros((grid_f.size, 5))
    loads[:, 0] = grid_f.ravel()
    r, res = rate(b, loads, grid_n.ravel() * math.pi / 30)
    print(f"(a) seed 8x5 speed-load grid: {r:,.0f} points/s on one core "
          f"({res.converged.sum()}/{len(res.converged)} converged) [CPU time: {CPU_RATE[0]:,.0f} points/s]")

    rng = np.random.default_rng(2026)
    n = 10_000
    loads = np.column_stack([rng.uniform(1000, 5000, n), rng.uniform(-500, 500, n), rng.uniform(-500, 500, n),
                             rng.uniform(-20, 20, n), rng.uniform(-20, 20, n)])
    speeds = rng.uniform(0, 11200, n) * math.pi / 30
    r, res = rate(b, loads, speeds, repeat=2)
    print(f"(b) 10,000 random combined loads with inertia: {r:,.0f} points/s on one core "
          f"({res.converged.sum()}/{n} converged, mean {res.iterations.mean():.1f} ring iterations) "
          f"[CPU time: {CPU_RATE[0]:,.0f} points/s]")

    cmd = [sys.executable, "-m", "bearingsim", "static", "skf-7011-cdga-hc", "--fa", "1000", "--speed", "11200 rpm",
           "--json"]
    subprocess.run(cmd, capture_output=True, check=True)  # warm the numba on-disk cache
    walls = []
    for _ in range(3):
        t = time.perf_counter()
        subprocess.run(cmd, capture_output=True, check=True)
        walls.append(time.perf_counter() - t)
    print(f"(c) warm `bearingsim static ... --json`: {min(walls):.2f} s wall (best of 3)")


if __name__ == "__main__":
    main()
