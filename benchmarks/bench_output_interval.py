"""Benchmark: the cost of the output interval (issue 14, dense output).

Runs the hub case (b) (examples/hub-moment-50hz.toml, 100 km/h, 50 Hz moment, tol 1e-6) over ``--duration``
(default 20 ms) in memory with samples every 100, 10 and 5 µs (``--intervals`` in µs) and prints, per interval, the
wall seconds per simulated second, the accepted and rejected steps and the samples taken.  With ROS34PW2's dense
output (``simulate(dense=True)``, the default since it exists) the steps do not stop at the output times, so the
step count does not depend on the interval and only the samples themselves cost more; without it (``--no-dense``,
or a tree from before it: ``bench_compare.py`` runs this script there too) every output time ends a step.

Usage:  python benchmarks/bench_output_interval.py [--duration "20 ms"] [--intervals 100,10,5] [--no-dense]
The numba compilation is excluded (a short warm-up run first).  Not a test: figures depend on the machine.
"""

from __future__ import annotations

import argparse
import dataclasses
import inspect

from bench_dynamics import load_bench_case


def main() -> None:
    from bearingsim.dynamics.run import simulate
    from bearingsim.units import parse_quantity

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--duration", default="20 ms")
    ap.add_argument("--intervals", default="100,10,5", help="output intervals [µs], comma-separated")
    ap.add_argument("--no-dense", action="store_true", help="every output time a step's end (the former way)")
    a = ap.parse_args()
    duration = parse_quantity(a.duration, "time", "--duration")
    case = load_bench_case("b")
    kw = {}
    if "dense" in inspect.signature(simulate).parameters:
        kw["dense"] = not a.no_dense
    mode = "dense output" if kw.get("dense") else "steps end at the output times"
    simulate(dataclasses.replace(case, duration=1e-4, output_interval=5e-5), **kw)  # compile / load the kernels
    for us in (float(v) for v in a.intervals.split(",")):
        run = dataclasses.replace(case, duration=duration, output_interval=us * 1e-6)
        res = simulate(run, **kw)
        s = res.summary
        wall = s["wall_seconds"]  # (the quasi-static start excluded)
        print(f"case (b), output every {us * 1e-3:g} ms ({mode}): {s['simulated_seconds'] * 1e3:.4g} ms in {wall:.3g} s -> "
              f"{wall / s['simulated_seconds']:.4g} wall s per simulated s; {s['steps']} steps "
              f"({s['rejected_steps']} rejected); {run.n_samples + 1} samples", flush=True)


if __name__ == "__main__":
    main()
