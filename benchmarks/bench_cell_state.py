"""What a hub-study cell costs from one of its states (issue 14): restart the integrator from a cell's
checkpoint and report the steps and CPU seconds per simulated second over a short stretch.

A study cell (``bearingsim reproduce hub-hysteresis CASE --out DIR``) leaves ``DIR/hub_<V>kmh_<F>Hz.nc.ckpt.npz``
while it runs.  This script rebuilds that cell's case (the study's ``cell_case``; the checkpoint's fingerprint
must match), takes the state, time and step from the checkpoint and integrates ``--duration`` with the chosen
quadrature rule, node count and integrator — the same kernels as the run, without the output.  It answers "what
holds the step here" for states a short benchmark from the clean start never reaches (a 1 Hz cell's moment peak).

Usage:  python benchmarks/bench_cell_state.py CASE CHECKPOINT --speed KMH --frequency HZ --cycles N
            [--duration "0.5 ms"] [--slice-rule strips|gauss] [--n-slices N] [--jac-every 20] [--steps]
``--cycles``: the cell's total cycles (start-up + measured, e.g. 10 for the defaults 2 + 8).  The state is the
checkpoint's; a different rule or node count starts from it as it is (the first microseconds settle the balls).
"""

from __future__ import annotations

import argparse
import dataclasses
import time
from pathlib import Path


def main(argv=None):
    import numpy as np

    from bearingsim.dynamics import run as R
    from bearingsim.io import read_toml
    from bearingsim.studies import hub_dynamic as hd
    from bearingsim.units import parse_quantity

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("case", type=Path)
    ap.add_argument("checkpoint", type=Path)
    ap.add_argument("--speed", type=float, required=True, help="the cell's vehicle speed [km/h]")
    ap.add_argument("--frequency", type=float, required=True, help="the cell's load frequency [Hz]")
    ap.add_argument("--cycles", type=int, required=True, help="the cell's total load cycles (start-up + measured)")
    ap.add_argument("--duration", default="0.5 ms")
    ap.add_argument("--slice-rule", default=None, choices=["strips", "gauss"])
    ap.add_argument("--n-slices", type=int, default=None)
    ap.add_argument("--jac-every", type=int, default=20)
    ap.add_argument("--steps", action="store_true", help="profile what limits the step (bench_dynamics.py --steps)")
    a = ap.parse_args(argv)
    case = hd.cell_case(read_toml(a.case, "case"), a.case.parent, a.speed, a.frequency, a.cycles)
    z = np.load(a.checkpoint)
    if str(z["fingerprint"]) != case.fingerprint():
        raise SystemExit(f"the checkpoint is not this cell's (fingerprint {z['fingerprint']} against "
                         f"{case.fingerprint()}): check --speed, --frequency, --cycles and the case file")
    changes = {k: v for k, v in (("slice_rule", a.slice_rule), ("n_slices", a.n_slices)) if v is not None}
    if changes:
        case = dataclasses.replace(case, **changes)
    m, ls, _, _ = R.build(case)
    st = R.Stepper(m, ls, z["y"].copy(), t=float(z["t"]), h=float(z["h"]), tol=case.tolerance, method=case.method,
                   jac_every=a.jac_every)
    st.advance(st.t + 2e-6)  # compiles
    dur = parse_quantity(a.duration, "time", "--duration")
    if a.steps:
        import sys

        sys.path.insert(0, str(Path(__file__).resolve().parent))
        from bench_dynamics import profile_steps

        profile_steps(st, ls, dur, f"{a.speed:g} km/h, {a.frequency:g} Hz from t = {st.t:.4g} s")
        return
    s0, r0 = st.steps, st.rejected
    c0 = time.process_time()
    st.advance(st.t + dur)
    cpu = time.process_time() - c0
    n = st.steps - s0
    print(f"{a.speed:g} km/h, {a.frequency:g} Hz from t = {float(z['t']):.4g} s, rule {case.slice_rule} "
          f"n_slices {case.n_slices}, {case.method}, jac_every {a.jac_every}: {dur * 1e3:.3g} ms in {n} steps "
          f"({st.rejected - r0} rejected), mean step {dur / max(n, 1) * 1e6:.3g} us, "
          f"{cpu / dur:.0f} CPU s per simulated s")


if __name__ == "__main__":
    main()
