"""Shaft-system timings (prints figures, no pass/fail): a four-row spindle on 40 beam elements, a 100-speed
stiffness sweep, a 50-speed Campbell diagram, the single-bearing solve for comparison, and the cost against the
element and bearing counts.  Run: ``python benchmarks/bench_shaft.py``."""

from __future__ import annotations

import time

import numpy as np

import bearingsim
from bearingsim.shafts.model import BearingSupport, PointLoad, PointMass, Section, ShaftSystem
from bearingsim.shafts.modes import campbell
from bearingsim.shafts.solve import dof_vector, solve_shaft
from bearingsim.shafts.sweep import shaft_sweep
from bearingsim.statics.jones_harris import Loads, solve

ROW = bearingsim.load_bearing("7011-15")


def spindle(elements: int = 40, n_bearings: int = 4, speed: float = 1000.0) -> ShaftSystem:
    """A milling-spindle-like rotor: tool overhang at x = 0, front rows at 0.08/0.10 m (+1), rear rows at
    0.36/0.38 m (−1) with a spring preload of 400 N each; 1 kN radial + 500 N axial at the tool tip."""
    secs = (Section(0.06, 0.05), Section(0.36, 0.055, 0.02), Section(0.08, 0.045, 0.02))
    places = [(0.08, 1, None), (0.10, 1, None), (0.36, -1, 400.0), (0.38, -1, 400.0)]
    if n_bearings == 2:
        places = [places[0], places[2]]
    sups = tuple(BearingSupport(f"b{i}", x, ROW, orientation=o, preload_force=p)
                 for i, (x, o, p) in enumerate(places))
    return ShaftSystem(secs, sups, (PointLoad(0.0, (500.0, 1000.0, 0.0)),), (PointMass(0.0, 1.5, 1e-3, 2e-3),),
                       speed=speed, elements=elements)


def best(fn, n=5):
    t = []
    for _ in range(n):
        t0 = time.perf_counter()
        fn()
        t.append(time.perf_counter() - t0)
    return min(t)


def main():
    s = spindle()
    r = solve_shaft(s)  # compile and warm
    print(f"spindle: {s.mesh.n_nodes - 1} elements, 4 rows, converged={r.converged} in {r.iterations} iterations, "
          f"tip radial stiffness {r.direct_stiffness_at(0.0)['radial_N_per_m'] / 1e6:.2f} N/um")
    t_full = best(lambda: solve_shaft(s))
    t_bare = best(lambda: solve_shaft(s, bearing_results=False))
    w0 = dof_vector(r)
    t_warm = best(lambda: solve_shaft(s, speed=1010.0, initial=w0, bearing_results=False))
    print(f"solve (4 rows, 40 el.), with bearing results:   {t_full * 1e3:7.2f} ms")
    print(f"solve, reactions and stiffness only:           {t_bare * 1e3:7.2f} ms")
    print(f"solve from the neighbouring speed's solution:  {t_warm * 1e3:7.2f} ms")
    t1 = best(lambda: solve(ROW, Loads(fa=500.0, fr_y=1000.0), 1000.0))
    print(f"single-bearing solve (7011-15, for comparison): {t1 * 1e3:7.2f} ms")
    speeds = np.linspace(0.0, 2000.0, 100)
    t0 = time.perf_counter()
    ds = shaft_sweep(s, speeds, 0.0, lives=False)
    print(f"100-speed stiffness sweep: {time.perf_counter() - t0:6.2f} s (converged {int(ds.converged.sum())}/100)")
    t0 = time.perf_counter()
    ds = shaft_sweep(s, speeds, 0.0, lives=True)
    print(f"100-speed sweep with lives: {time.perf_counter() - t0:6.2f} s")
    t0 = time.perf_counter()
    cd = campbell(s, np.linspace(0.0, 2000.0, 50), 6, gyroscopic=True)
    print(f"50-speed Campbell (gyroscopic, 6 modes): {time.perf_counter() - t0:6.2f} s "
          f"(first mode {cd.frequency.values[0, 0]:.1f} -> {cd.frequency.values[-1, 0]:.1f} Hz)")
    print("cost against elements and bearings (reactions and stiffness only):")
    for nb in (2, 4):
        for ne in (20, 40, 80, 160):
            sy = spindle(ne, nb)
            rr = solve_shaft(sy, bearing_results=False)
            t = best(lambda sy=sy: solve_shaft(sy, bearing_results=False), 3)
            print(f"  {nb} rows, {sy.mesh.n_nodes - 1:4d} elements: {t * 1e3:8.2f} ms, {rr.iterations} iterations")


if __name__ == "__main__":
    main()
