"""Benchmark of the batch solver and the maps (issue 3 item 7).  Prints figures; not a test.

    python benchmarks/bench_sweep.py            # all
    python benchmarks/bench_sweep.py --quick    # skip the 1,000,000-point map

Figures: operating points per second on one core (batch kernel, warm starts) for the SKF 7011 grid
with inertia (41 speeds x 9 axial loads), a 10,000-point random combined-load set, and the hub unit;
map_grid with 1 and 2 Dask workers on a 10,000-point grid; peak memory of a 1,000,000-point map
streamed to netCDF.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time

import numpy as np


def rate(fn, npts, repeat=3):
    """Best wall-clock rate [points/s] over ``repeat`` runs; the CPU-time rate of the same runs is
    kept in CPU_RATE (equal on an idle machine; the CPU figure is the one-core speed when other jobs
    share the cores)."""
    fn()  # compile / warm
    best = np.inf
    best_cpu = np.inf
    for _ in range(repeat):
        t = time.perf_counter()
        c = time.process_time()
        out = fn()
        best = min(best, time.perf_counter() - t)
        best_cpu = min(best_cpu, time.process_time() - c)
    CPU_RATE[0] = npts / best_cpu
    return npts / best, out


CPU_RATE = [0.0]


def cpu():
    return f"[CPU time: {CPU_RATE[0]:,.0f} points/s]"


def _spin(n):
    s = 0
    for i in range(n):
        s += i * i
    return s


def machine_parallel_efficiency() -> float:
    """Control: speed-up of two pure-Python tasks in two processes (2.0 on two idle cores)."""
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(2) as ex:
        list(ex.map(_spin, [10, 10]))
        t = time.perf_counter()
        list(ex.map(_spin, [4_000_000]))
        t1 = time.perf_counter() - t
        t = time.perf_counter()
        list(ex.map(_spin, [4_000_000, 4_000_000]))
        t2 = time.perf_counter() - t
    return 2 * t1 / t2


def main(quick=False):  # noqa: C901
    from bearingsim.io import load_bearing
    from bearingsim.statics._batch import run_batch

    b7011 = load_bearing("skf-7011-cdga-hc")
    hub = load_bearing("hub-seed001")
    rpm = np.pi / 30

    # 1. 7011 grid: 9 axial loads x 41 speeds, serpentine over speed
    fa = np.linspace(1000, 5000, 9)
    sp = np.linspace(0, 11200, 41) * rpm
    loads, om = [], []
    for i, f in enumerate(fa):
        for w in (sp if i % 2 == 0 else sp[::-1]):
            loads.append([f, 0, 0, 0, 0])
            om.append(w)
    loads, om = np.array(loads), np.array(om)
    r, out = rate(lambda: run_batch(b7011, loads, om), len(om))
    print(f"7011 grid 41 speeds x 9 loads, inertia, 1 core: {r:,.0f} points/s "
          f"(converged {out['converged'].mean():.1%}, mean iterations {out['iterations'].mean():.2f}) {cpu()}")

    # 2. 10,000 random combined loads and speeds
    rng = np.random.default_rng(0)
    n = 10_000
    L = np.column_stack([rng.uniform(500, 5000, n), rng.uniform(-2000, 2000, n), rng.uniform(-2000, 2000, n),
                         rng.uniform(-50, 50, n), rng.uniform(-50, 50, n)])
    W = rng.uniform(0, 11200, n) * rpm
    r, out = rate(lambda: run_batch(b7011, L, W, reorder=True), n, repeat=1)
    st = np.bincount(out["status"], minlength=4)
    print(f"7011 random combined-load set, 10,000 points, Z-order, 1 core: {r:,.0f} points/s "
          f"(converged {out['converged'].mean():.1%}; status counts {st.tolist()}; "
          f"mean iterations {out['iterations'].mean():.2f}) {cpu()}")
    r, out = rate(lambda: run_batch(b7011, L, W, reorder=False), n, repeat=1)
    print(f"   same set in random order: {r:,.0f} points/s (converged {out['converged'].mean():.1%}) {cpu()}")

    # 3. hub unit: moment x speed (tied seed 001 loads)
    m = np.linspace(-600, 600, 121)
    spd = np.linspace(0, 100 / 3.6 / 0.3175, 11)
    loads, om = [], []
    for i, w in enumerate(spd):
        for mm in (m if i % 2 == 0 else m[::-1]):
            loads.append([1890 * mm / 600, 2785 + 965 * mm / 600, 0, 0, mm])
            om.append(w)
    loads, om = np.array(loads), np.array(om)
    r, out = rate(lambda: run_batch(hub, loads, om), len(om))
    print(f"hub unit (2 x 16 balls) 121 moments x 11 speeds (0-100 km/h), 1 core: {r:,.0f} points/s "
          f"(converged {out['converged'].mean():.1%}, ring converged {np.isin(out['status'], (0, 4)).mean():.1%}, "
          f"mean iterations {out['iterations'].mean():.2f}) {cpu()}")
    sel = om == 0
    r, out = rate(lambda: run_batch(hub, loads[sel], om[sel]), int(sel.sum()))
    print(f"hub unit at rest, 121 moments, 1 core: {r:,.0f} points/s (converged {out['converged'].mean():.1%}) {cpu()}")

    # 4. map_grid: in-process vs Dask LocalCluster with 1 and 2 workers, 10,000-point grid
    from distributed import Client, LocalCluster

    from bearingsim.sweep import map_grid, warm_up

    print(f"control: two pure-Python tasks on two processes run {machine_parallel_efficiency():.2f} x faster "
          "than one (2.0 on two idle cores; less when other jobs share the machine)")
    # 10,000 combined-load points (25 Fa x 20 Fr x 20 M at 3000 rpm), 25 blocks of 400
    kw = dict(fa="500:5000:25", fr="0:2000:20", moment="-20:20:20", speed="3000", chunk_points=400)
    t = time.perf_counter()
    ser = map_grid(b7011, workers=1, **kw)
    t_ser = time.perf_counter() - t
    print(f"map_grid 10,000 combined-load points in-process: {10000 / t_ser:,.0f} points/s "
          f"(converged {float(ser.converged.mean()):.1%})")
    for nw in (1, 2):
        with LocalCluster(n_workers=nw, threads_per_worker=1, processes=True, dashboard_address=None) as cl, \
                Client(cl) as client:
            client.run(warm_up)  # load the compiled kernels on every worker before timing
            t = time.perf_counter()
            ds = map_grid(b7011, scheduler=client, **kw)
            dt = time.perf_counter() - t
            same = all(np.array_equal(ser[v].values, ds[v].values) for v in ser.data_vars)
            print(f"map_grid 10,000 combined-load points, Dask {nw} worker(s): {10000 / dt:,.0f} points/s "
                  f"(identical to serial: {same})")
            if nw == 1:
                t1 = dt
            else:
                print(f"   speed-up 2 workers / 1 worker: {t1 / dt:.2f} x  (machine has {os.cpu_count()} cores)")

    if quick:
        return
    # 5. 1,000,000-point map streamed to disk, peak RSS measured in a child process
    with tempfile.TemporaryDirectory() as d:
        code = (
            "import resource, time\n"
            "from bearingsim.sweep import map_grid\n"
            "t = time.perf_counter()\n"
            f"ds = map_grid('skf-7011-cdga-hc', fa='500:5000:100', fr='0:2000:100', speed='0:11200:100', "
            f"out=r'{d}/big.nc', workers=2, chunk_points=2000)\n"
            "dt = time.perf_counter() - t\n"
            "print(int(ds['converged'].sum()), dt, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss, "
            "resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)\n"
        )
        t = time.perf_counter()
        res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
        if res.returncode != 0:
            print("1,000,000-point map failed:", res.stderr[-2000:])
            return
        conv, dt, rss_self, rss_child = res.stdout.split()[-4:]
        size = os.path.getsize(f"{d}/big.nc") if os.path.exists(f"{d}/big.nc") else 0
        print(f"1,000,000-point map (7011, 100 fa x 100 fr x 100 speeds) streamed to netCDF, 2 local workers: "
              f"{float(dt):.1f} s ({1e6 / float(dt):,.0f} points/s), converged {int(conv):,}; "
              f"peak RSS parent {int(rss_self) / 1024:.0f} MB, largest worker {int(rss_child) / 1024:.0f} MB; "
              f"file {size / 1e6:.0f} MB")


if __name__ == "__main__":
    main(quick="--quick" in sys.argv)
