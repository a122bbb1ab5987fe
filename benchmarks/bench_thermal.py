"""Benchmark of one thermal operating point of a single bearing (issue 46, item 4: ≤ 50 ms warm).  Prints
figures; not a test.

SKF 7011 CDGA/HC, Fa = 1 kN, 15,000 rpm, ISO VG 68 at a 40 °C inlet, 1 L/min, estimated cage land.
Best of ``REPEAT`` warm runs (wall and CPU time; the CPU time is the one-core figure when other jobs share
the machine), with the iterations of the fixed point.

Run:  python benchmarks/bench_thermal.py
"""

import math
import time

import bearingsim
from bearingsim.thermal import ThermalSetup, thermal_operating_point

REPEAT = 7


def main():
    b = bearingsim.load_bearing("skf-7011-cdga-hc")
    loads = bearingsim.Loads(fa=1000.0)
    speed = 15000 * math.pi / 30
    setup = ThermalSetup(oil_inlet_temperature=313.15, oil_flow=1e-3 / 60)
    op = thermal_operating_point(b, loads, speed, "iso-vg-68", setup)  # JIT warm-up
    wall = cpu = math.inf
    for _ in range(REPEAT):
        t, c = time.perf_counter(), time.process_time()
        op = thermal_operating_point(b, loads, speed, "iso-vg-68", setup)
        wall = min(wall, time.perf_counter() - t)
        cpu = min(cpu, time.process_time() - c)
    print(f"thermal operating point, single bearing: {1e3 * wall:.1f} ms wall, {1e3 * cpu:.1f} ms CPU "
          f"(best of {REPEAT}, warm; target 50 ms); {op.iterations} iterations, {op.status}, "
          f"residual {op.residual:.2g} K, {1e3 * wall / op.iterations:.1f} ms per iteration")


if __name__ == "__main__":
    main()
