"""Work against precision of the dynamic engine (issue 14): steps and CPU time against the error, per tolerance.

A lever that takes fewer steps at the same tolerance may only be less accurate — a looser tolerance in
disguise.  This script runs one case at several tolerances and at a tight reference tolerance (the same
integrator), samples the state at ``--samples`` equal times over ``--duration`` and prints, per tolerance, the
steps, the CPU seconds per simulated second and the largest errors against the reference: the inner ring's
loaded coordinates (displacements and tilts whose range over the run exceeds 1 % of the largest of their kind)
relative to their range, and the balls' angular velocity relative to its magnitude.  Two trees compared with
``bench_compare.py REV -- bench_precision.py ...`` give two work-precision curves: a lever pays only if its
curve lies below the other (fewer steps at equal error), not if it moves along it.

Usage:  python benchmarks/bench_precision.py [--case a|b] [--duration "5 ms"] [--tolerances 5e-7,1e-6,2e-6,4e-6]
            [--reference 1e-8] [--samples 20] [--slice-rule strips|gauss] [--n-slices N] [--vehicle-speed KMH]
            [--multirate N]
Not a test: the figures depend on the machine (the step counts and errors do not).
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from pathlib import Path


def main(argv=None):
    import numpy as np

    sys.path.insert(0, str(Path(__file__).resolve().parent))
    from bearingsim.dynamics import layout as ly
    from bearingsim.dynamics import run as R
    from bearingsim.units import parse_quantity
    from bench_dynamics import load_bench_case

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default="b", choices=["a", "b"])
    ap.add_argument("--duration", default="5 ms")
    ap.add_argument("--tolerances", default="5e-7,1e-6,2e-6,4e-6")
    ap.add_argument("--reference", type=float, default=1e-8, help="tolerance of the reference run")
    ap.add_argument("--samples", type=int, default=20)
    ap.add_argument("--slice-rule", default=None, choices=["strips", "gauss"])
    ap.add_argument("--n-slices", type=int, default=None)
    ap.add_argument("--vehicle-speed", type=float, default=None, help="hub case (b) at this vehicle speed [km/h]")
    ap.add_argument("--multirate", type=int, default=None,
                    help="most balls a step refines (0: none; default: the engine's); the reference never refines")
    a = ap.parse_args(argv)
    case = load_bench_case(a.case, a.vehicle_speed if a.case == "b" else None, a.slice_rule)
    if a.n_slices:
        case = dataclasses.replace(case, n_slices=a.n_slices)
    duration = parse_quantity(a.duration, "time", "--duration")
    tols = [float(x) for x in a.tolerances.split(",")]
    m, ls, y0, _ = R.build(case)
    R.Stepper(m, ls, y0.copy(), tol=case.tolerance, method=case.method).advance(2e-6)  # compiles
    times = np.linspace(0.0, duration, a.samples + 1)[1:]
    balls = np.array([ly.N_RING + ly.N_BALL * k for k in range(m.n_balls)])[:, None] + np.arange(6, 9)

    def run(tol, multirate=a.multirate):
        st = R.Stepper(m, ls, y0.copy(), tol=tol, method=case.method)
        if multirate is not None and hasattr(st, "multirate"):  # (a tree before the refinement has none)
            st.multirate = multirate
        ys = []
        c0 = time.process_time()
        for t in times:
            st.advance(float(t))
            ys.append(st.y.copy())
        return np.array(ys), st.steps, st.rejected, time.process_time() - c0

    ref = run(a.reference, 0)[0]
    span = np.ptp(ref[:, 0:5], axis=0)
    loaded = np.zeros(5, bool)
    for kind in (slice(0, 3), slice(3, 5)):  # displacements, tilts
        loaded[kind] = span[kind] > 0.01 * span[kind].max()
    names = np.array(["dx", "dy", "dz", "gy", "gz"])
    w_ref = np.linalg.norm(ref[:, balls], axis=2)
    print(f"case ({a.case}) rule {case.slice_rule} n_slices {case.n_slices} {case.method}, {duration * 1e3:g} ms, "
          f"reference tol {a.reference:g}; ring coordinates loaded: {', '.join(names[loaded])}")
    for tol in tols:
        ys, steps, rej, cpu = run(tol)
        ring = (np.abs(ys[:, 0:5] - ref[:, 0:5]).max(axis=0) / np.where(span > 0, span, 1.0))[loaded].max()
        w_err = (np.linalg.norm(ys[:, balls] - ref[:, balls], axis=2) / w_ref).max()
        print(f"tol {tol:g}: {steps} steps ({rej} rejected), {cpu / duration:.0f} CPU s per simulated s; "
              f"ring error {ring:.2e} of range, ball angular velocity error {w_err:.2e} of magnitude")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
