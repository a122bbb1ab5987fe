"""Benchmark of the batch solver and the maps (issue 3 item 7).  Prints figures; not a test.

    python benchmarks/bench_sweep.py            # all
    python benchmarks/bench_sweep.py --quick    # skip the 1,000,000-point map

Figures: operating points per second on one core (batch kernel, warm starts) for the SKF 7011 grid
with inertia (41 speeds x 9 axial loads), a 10,000-point random combined-load set, and the hub unit
(wall and CPU-time rates); map_grid in-process and with 1 and 2 pre-warmed Dask workers on two
10,000-point grids (the 7011 combined-load grid at 3000 rpm, and the same number of dearer points of
the 7011 DB pair over speed), with a control of the machine's parallel efficiency; time and peak memory
of a 1,000,000-point map streamed to netCDF.
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

    from bearingsim.sweep import _blocks, map_grid, warm_up

    print(f"control: two pure-Python tasks on two processes run {machine_parallel_efficiency():.2f} x faster "
          "than one (2.0 on two idle cores; less when other jobs share the machine)")
    # 10,000 combined-load points (25 Fa x 20 Fr x 20 M at 3000 rpm) in 5 blocks (4 x 2,400 + 400 points,
    # 35-55 ms each): few tasks, because the ~5 ms of scheduler/client CPU per task on the main process is
    # taken from the workers on a 2-core machine, and about even shares for 2 workers (the dearest block,
    # low Fa with many status-3 points, first; the small one last)
    chunk = 2400
    kw = dict(fa="500:5000:25", fr="0:2000:20", moment="-20:20:20", speed="3000", chunk_points=chunk)
    nblk = len(_blocks((25, 20, 20), chunk))
    map_grid(b7011, workers=1, **kw)  # imports (xarray) and kernels loaded before timing
    t = time.perf_counter()
    c = time.process_time()
    ser = map_grid(b7011, workers=1, **kw)
    t_ser = time.perf_counter() - t
    c_ser = time.process_time() - c
    print(f"map_grid 10,000 combined-load points in-process ({nblk} blocks): {10000 / t_ser:,.0f} points/s "
          f"[CPU time: {10000 / c_ser:,.0f} points/s] (converged {float(ser.converged.mean()):.1%})")
    print("Dask: wall time of map_grid(scheduler=client) on LocalClusters of 1 and 2 single-threaded worker "
          "processes, started and pre-warmed before timing (client.run(warm_up) loads the compiled kernels in "
          "every worker); results gathered into the in-memory Dataset by the main process (which also hosts the "
          "scheduler); runs alternate between the two clusters, 5 runs each")

    def _cpu():
        return time.process_time()

    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cl1, \
            Client(cl1) as c1, \
            LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cl2, \
            Client(cl2) as c2:
        for client in (c1, c2):
            client.run(warm_up)
        db = load_bearing("skf-7011-cdga-hc-db")
        cases = [("7011, 25 Fa x 20 Fr x 20 M at 3000 rpm", b7011, kw, ser),
                 # the same number of points, each dearer (a preloaded pair, 2 x 21 balls, speeds to 11,200 rpm)
                 ("7011 DB pair, 25 Fa x 20 Fr x 20 speeds", db,
                  dict(fa="500:5000:25", fr="0:2000:20", speed="1000:11200:20", chunk_points=chunk), None)]
        for label, brg, kwc, ref in cases:
            if ref is None:
                ref = map_grid(brg, workers=1, **kwc)
            walls = {1: [], 2: []}
            cpus = {1: [], 2: []}
            same = True
            for client in (c1, c2):
                map_grid(brg, scheduler=client, **kwc)  # first map: connections and imports
            for _ in range(5):
                for nw, client in ((1, c1), (2, c2)):
                    w0 = client.run(_cpu)
                    m0 = time.process_time()
                    t = time.perf_counter()
                    ds = map_grid(brg, scheduler=client, **kwc)
                    walls[nw].append(time.perf_counter() - t)
                    m1 = time.process_time()
                    w1 = client.run(_cpu)
                    cpus[nw].append((sum(w1[k] - w0[k] for k in w0), m1 - m0))
                    same = same and all(np.array_equal(ref[v].values, ds[v].values) for v in ref.data_vars)
            print(f"map_grid {label} (10,000 points, {nblk} blocks of <= {chunk}):")
            for nw in (1, 2):
                wc = np.median([x[0] for x in cpus[nw]])
                mc = np.median([x[1] for x in cpus[nw]])
                print(f"   Dask {nw} worker(s): best {10000 / min(walls[nw]):,.0f} points/s, median "
                      f"{10000 / np.median(walls[nw]):,.0f} points/s; CPU per map: workers {wc:.3f} s, main process "
                      f"{mc:.3f} s")
            print(f"   speed-up 2 workers / 1 worker: {min(walls[1]) / min(walls[2]):.2f} x (best of 5), "
                  f"{np.median(walls[1]) / np.median(walls[2]):.2f} x (median); identical to serial: {same} "
                  f"(machine has {os.cpu_count()} cores)")

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
