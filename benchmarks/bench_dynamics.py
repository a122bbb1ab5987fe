"""Benchmark of the dynamic engine (issue 5): wall seconds per simulated second and peak memory.

Cases: (a) examples/spindle-7011.toml — SKF 7011 at Fa = 3000 N, 10,000 rpm, 20 ms;
(b) examples/hub-moment-50hz.toml — seed-001 hub unit, 2 × 16 balls, 2 cages, 100 km/h,
50 Hz moment, 0.1 s.  Targets (issue 14): (b) ≤ 60 s wall per simulated second on one core, ≤ 35 with 2 threads.

Usage:  python benchmarks/bench_dynamics.py [--case a|b|both] [--duration "2 ms"] [--traction slices|coulomb|none]
         [--integrator auto|dopri5|ros2w|ros34w] [--tolerance 1e-6] [--n-slices 8] [--slice-rule strips|split|gauss|log]
         [--vehicle-speed KMH] [--profile] [--kernel] [--accuracy] [--threads N] [--steps]
         [--timeline WINDOW [--jac-every N] [--jac-fixed] [--jac-unturned]]
--slice-rule gauss integrates the traction with --n-slices Gauss nodes per stretch between the zeros of the rolling
slip (the case key slice_rule); --vehicle-speed runs the hub case (b) at that vehicle speed (10 km/h: 83.55 rpm).
--accuracy compares the ring displacement of the chosen settings with a DOPRI5 run at
tolerance 1e-7 over the same (short) duration and prints the largest deviation of each
ring coordinate relative to its range (issue 14: ≤ 1e-4 for the loaded coordinates over 5 ms).
--kernel times one right-hand side per traction model and runs 0.2 ms with the integrator the case's
runs use (ROS34PW2 with sliced traction, DOPRI5 otherwise), reporting its mean step and right-hand
sides per step.  --threads N: threads for the ball contacts (default 1 here, for comparable figures;
the results are the same bit for bit).
--steps profiles what limits the ROS34PW2 step over --duration (default 1 ms, after 0.05 ms of start-up): per
state class the share of the summed squared scaled error and how often it held the largest component, the
rejected steps, and the balls with the largest error share (loaded or not).
The numba compilation is excluded (a 0.05 ms warm-up run compiles first).  Peak memory
is the process's maximum resident set size.  The CPU seconds (process time) are the steadier
figure on a shared machine, where the wall time also counts the waits for a core.
"""

from __future__ import annotations

import argparse
import dataclasses
import resource
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASES = {"a": ROOT / "examples" / "spindle-7011.toml", "b": ROOT / "examples" / "hub-moment-50hz.toml"}


#: --multirate: the most balls a ROS34PW2 step refines (:mod:`bearingsim.dynamics.integrate.multirate`), or None for
#: the case file's (its default)
MULTIRATE: int | None = None


def load_bench_case(name: str, vehicle_speed: float | None = None, slice_rule: str | None = None):
    """The case file of ``name``, with the hub's shaft speed for a vehicle speed [km/h] (the study's tyre,
    :func:`bearingsim.studies.hub_static.shaft_speed_entry`) and the traction quadrature rule replaced."""
    from bearingsim.dynamics.case import case_from_dict
    from bearingsim.io import read_toml
    from bearingsim.studies.hub_static import shaft_speed_entry

    data = read_toml(CASES[name], "case")
    if MULTIRATE is not None:
        data["multirate"] = MULTIRATE
    if vehicle_speed is not None:
        data["speed"] = shaft_speed_entry(vehicle_speed)
    if slice_rule is not None:
        data["slice_rule"] = slice_rule
    return case_from_dict(data, base=CASES[name].parent)


def run(name: str, duration: float | None, traction: str | None, profile: bool, integrator: str | None = None,
        tolerance: float | None = None, n_slices: int | None = None, keep=None, cage_modes: int = 0,
        threads: int = 1, vehicle_speed: float | None = None, slice_rule: str | None = None) -> dict:
    from bearingsim.dynamics.run import simulate

    case = load_bench_case(name, vehicle_speed, slice_rule)
    if traction:
        case = dataclasses.replace(case, traction=traction)
    if integrator:
        case = dataclasses.replace(case, integrator=integrator)
    if tolerance:
        case = dataclasses.replace(case, tolerance=tolerance)
    if n_slices:
        case = dataclasses.replace(case, n_slices=n_slices)
    if cage_modes:
        cage = {k: v for k, v in case.cage.items() if k != "mass"}  # an elastic cage's mass is its ring's
        case = dataclasses.replace(case, cage={**cage, "n_modes": cage_modes})
    with tempfile.TemporaryDirectory() as d:
        warm = dataclasses.replace(case, duration=max(case.output_interval, 5e-5), output_interval=min(
            case.output_interval, 5e-5))
        simulate(warm, out=Path(d) / "warm.nc", threads=threads)
        full = dataclasses.replace(case, duration=duration or case.duration)
        t0 = time.perf_counter()
        c0 = time.process_time()
        if profile:
            import cProfile
            import pstats

            pr = cProfile.Profile()
            pr.enable()
        res = simulate(full, out=Path(d) / "run.nc", threads=threads)
        if profile:
            pr.disable()
            pstats.Stats(pr).sort_stats("cumulative").print_stats(12)
        wall = time.perf_counter() - t0
        cpu = time.process_time() - c0
        if keep is not None:
            ds = res.to_xarray()
            keep.append(ds["inner_ring_displacement"].values.copy())
            ds.close()
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    out = {"case": name, "traction": full.traction, "integrator": full.method, "tolerance": full.tolerance,
           "n_slices": full.n_slices, "slice_rule": full.slice_rule, "cage_modes": cage_modes, "threads": threads, "simulated_s": full.duration, "wall_s": wall,
           "wall_per_simulated_s": wall / full.duration, "cpu_per_simulated_s": cpu / full.duration,
           "steps": res.summary["steps"],
           "rejected": res.summary["rejected_steps"], "peak_rss_MB": peak}
    return out


def kernel_profile(name: str, threads: int = 1, vehicle_speed: float | None = None, slice_rule: str | None = None,
                   n_slices: int | None = None) -> None:
    """Cost of one right-hand-side evaluation per traction model, and the step of the integrator the case's
    runs use (``case.method``: ROS34PW2 with sliced traction under "auto", else DOPRI5) and what limits it;
    the case as the runs take it (--vehicle-speed, --slice-rule, --n-slices)."""
    import collections

    import numpy as np

    from bearingsim.dynamics import forces as fo
    from bearingsim.dynamics import model as md
    from bearingsim.dynamics import run as R

    case = load_bench_case(name, vehicle_speed, slice_rule)
    if n_slices:
        case = dataclasses.replace(case, n_slices=n_slices)
    for trac in ("none", "coulomb", "slices"):
        c = dataclasses.replace(case, traction=trac)
        m, ls, y, _ = R.build(c)
        # memo off: the same state called again would take the outer contacts from the memo (forces.outer_memo_hit),
        # which a stage never does (each stage is a new state): with it the figure was half the cost in a run
        args = fo.args_of(m, ls, memo=False)
        dy = np.zeros_like(y)
        fun = fo.rhs_args_threaded if threads > 1 else fo.rhs_args
        fun(0.0, y, dy, args)
        n = 2000
        t0 = time.perf_counter()
        for _ in range(n):
            fun(0.0, y, dy, args)
        us = (time.perf_counter() - t0) / n * 1e6
        st = R.Stepper(m, ls, y.copy(), tol=c.tolerance, method=c.method, threads=threads)
        st.advance(2e-6)  # compiles the integrator
        s0 = st.steps
        calls = _count_rhs(st)
        cnt = collections.Counter()
        for i in range(2, 101):
            st.advance(i * 2e-6)
            cnt[md.describe_component(m, int(st._info[2])).split(":")[0]] += 1
        nst = max(st.steps - s0, 1)
        print(f"case ({name}) {trac:8s}: {us:7.1f} us per right-hand side ({m.n_balls} balls); integrator "
              f"{c.method}: mean step over 0.2 ms {0.198e-3 / nst * 1e6:.3g} us, {nst} steps, "
              f"≈{calls(st) / nst:.2f} right-hand sides per step; largest error most often in "
              f"{cnt.most_common(1)[0][0]}")


def step_profile(name: str, duration: float, tolerance: float | None = None) -> None:
    """Where the steps go (issue 14): runs ``duration`` of the case with ROS34PW2 after 0.05 ms of start-up and
    reports, per state class (ring, ball positions, velocities, angular velocities by axis, cage), the share of
    the summed squared scaled error over all attempted steps and how often the class held the largest
    component, the rejected steps, and the ten balls with the largest error share (with their inner contact
    load at the end: loaded or not)."""

    from bearingsim.dynamics import run as R
    from bearingsim.dynamics.case import load_case

    case = load_case(CASES[name])
    if tolerance:
        case = dataclasses.replace(case, tolerance=tolerance)
    m, ls, y, _ = R.build(case)
    st = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method="ros34w")
    st.advance(5e-5)
    profile_steps(st, ls, duration, f"case ({name})")


def profile_steps(st, ls, duration: float, label: str) -> None:
    """The report of :func:`step_profile` for ``duration`` [s] from a ROS34PW2 stepper's present state (also used
    by bench_cell_state.py --steps on a study cell's checkpoint)."""
    import numpy as np

    from bearingsim.dynamics import forces as fo
    from bearingsim.dynamics import model as md
    from bearingsim.dynamics.integrate import INFO_SIZE, ros34pw2

    m = st.model
    ws = st.workspace
    n = st.y.shape[0]
    stats = np.zeros(2 * n)
    info = np.zeros(INFO_SIZE)  # (the integrator writes its work counts past the first four)
    t0 = time.perf_counter()
    status, t, h = ros34pw2.integrate(ws.fun, ws.args, st.t, st.t + duration, st.y, st.h, st.atol, st.rtol,
                                      st.h_min, 10**8, info, ws.blk, ws.nbk, st.jac_every, st._ws, ws.rmass,
                                      ws.bmass, stats, False, st.vec, rec=ws.args[10])
    wall = time.perf_counter() - t0
    acc, rej = int(info[0]), int(info[1])
    e2, worst = stats[:n], stats[n:]
    oc = m.cage_offset
    classes = {"ring position": np.arange(0, 5), "ring velocity": np.arange(5, 10)}
    bidx = np.arange(m.n_balls) * md.N_BALL + md.N_RING
    for lab, off in (("ball position", 0), ("ball velocity", 3), ("ball ang. velocity", 6)):
        for ax, k in zip("xyz", range(3)):
            classes[f"{lab} {ax}"] = bidx + off + k
    classes["cage (all states)"] = np.arange(oc, n)
    tot, wtot = e2.sum(), worst.sum()
    print(f"{label} ROS34PW2 tol {st.tol:g}: "
          f"{duration * 1e3:.3g} ms in {wall:.3g} s, {acc} steps ({rej} rejected), mean step "
          f"{duration / max(acc, 1) * 1e6:.3g} us, status {status}")
    print("  class: share of summed squared scaled error | share of attempts where it held the largest component")
    for lab, idx in classes.items():
        print(f"  {lab:24s} {e2[idx].sum() / tot:7.3f} | {worst[idx].sum() / wtot:7.3f}")
    _, diag, _ = fo.evaluate(m, st.t, st.y, ls)
    per_ball = np.array([e2[o:o + md.N_BALL].sum() for o in bidx]) / tot
    top = np.argsort(per_ball)[::-1][:10]
    print("  balls with the largest error share (ball: share, inner contact load N at the end): "
          + ", ".join(f"{k}: {per_ball[k]:.3f} ({diag[k, fo.D_QI]:.0f})" for k in top))
    qi = diag[:, fo.D_QI]
    print(f"  inner contact load range {qi.min():.0f}..{qi.max():.0f} N; balls below 20 % of the largest carry "
          f"{per_ball[qi < 0.2 * qi.max()].sum():.3f} of the error")


def step_timeline(name: str, duration: float, window: float, vehicle_speed: float | None = None,
                  slice_rule: str | None = None, n_slices: int | None = None, tolerance: float | None = None,
                  jac_every: int = 20, jac_fixed: bool = False, jac_unturned: bool = False) -> dict:
    """Where in time the steps go (issue 14, fifteenth pass): the case's integrator stepping from t = 0 over
    ``duration`` [s], reported per ``window`` [s]: accepted and rejected steps, Jacobian refreshes and the inner
    contacts' load range at the window's end; then the share of all steps taken in windows that step faster than
    twice the median window, and the steps the run would take if every window stepped at the median rate.
    Exact counts (the integrator's own; they do not depend on the machine).  Returns the per-window arrays."""
    import numpy as np

    from bearingsim.dynamics import forces as fo
    from bearingsim.dynamics import run as R

    case = load_bench_case(name, vehicle_speed, slice_rule)
    if n_slices:
        case = dataclasses.replace(case, n_slices=n_slices)
    if tolerance:
        case = dataclasses.replace(case, tolerance=tolerance)
    m, ls, y, _ = R.build(case)
    # dense output, as simulate() runs: the steps do not stop at the windows' ends, so the trajectory is the run's
    st = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, jac_every=jac_every,
                   jac_adaptive=not jac_fixed, jac_orbit=not jac_unturned, dense=True, multirate=case.multirate)
    nw = max(1, int(round(duration / window)))
    steps = np.zeros(nw, dtype=int)
    rej = np.zeros(nw, dtype=int)
    jacs = np.zeros(nw, dtype=int)
    qlo = np.zeros(nw)
    qhi = np.zeros(nw)
    work = st.workspace.work if case.method == "ros34w" else None
    for k in range(nw):
        s0, r0 = st.steps, st.rejected
        j0 = int(work[2]) if work is not None else 0
        st.advance((k + 1) * window)
        steps[k], rej[k] = st.steps - s0, st.rejected - r0
        jacs[k] = (int(work[2]) - j0) if work is not None else 0
        _, diag, _ = fo.evaluate(m, st.t, st.y, ls)
        qlo[k], qhi[k] = diag[:, fo.D_QI].min(), diag[:, fo.D_QI].max()
    print(f"case ({name}) {case.method} tol {case.tolerance:g} slice_rule={case.slice_rule} n_slices={case.n_slices}"
          + (f" vehicle_speed={vehicle_speed:g} km/h" if vehicle_speed is not None else "")
          + f": steps per {window * 1e6:.4g} us window")
    print("   t_end [ms]  steps  rejected  mean step [us]  Jacobians  inner loads [N]")
    for k in range(nw):
        print(f"  {(k + 1) * window * 1e3:10.3f} {steps[k]:6d} {rej[k]:9d} {window / max(steps[k], 1) * 1e6:15.3g}"
              f" {jacs[k]:10d}  {qlo[k]:6.0f}..{qhi[k]:.0f}")
    med = float(np.median(steps))
    fast = steps > 2.0 * med
    total = int(steps.sum())
    print(f"  {total} steps ({int(rej.sum())} rejected) in {nw} windows; median {med:g} per window; "
          f"{fast.sum()} windows step faster than twice the median and hold {steps[fast].sum() / max(total, 1):.3f} "
          f"of the steps; at the median rate throughout: {med * nw:.0f} steps")
    nfun = int(work[0]) if work is not None else 0
    if work is not None:
        print(f"  work: {nfun} right-hand sides ({nfun / max(total, 1):.3f} per step), {int(work[2])} Jacobian "
              f"refreshes, {int(work[1])} W factorisations"
              + (f"; multirate: {int(work[5])} steps refined, {int(work[4])} balls in all, {int(work[3])} right-hand "
                 f"sides of the refined balls alone" if len(work) > 5 else ""))
    return {"steps": steps, "rejected": rej, "jacobians": jacs, "q_min": qlo, "q_max": qhi, "rhs": nfun}


def _count_rhs(st):
    """A counter of right-hand-side calls of a stepper's integrator; returns a function of the stepper giving the
    calls since now.  ROS34PW2 counts its own (``Workspace.work``, exact); for the others the count is estimated from
    the integrator's known costs (stages per step)."""
    s0, r0 = st.steps, st.rejected
    w0 = int(st.workspace.work[0])

    def calls(s):
        acc, rej = s.steps - s0, s.rejected - r0
        if s.method == "dopri5":
            return 6 * (acc + rej) + 1  # 7 stages, the last reused as the next first (FSAL)
        if s.method == "ros34w":
            return int(s.workspace.work[0]) - w0  # (f per accepted step, 3 per attempt, the Jacobian's sweeps)
        return 2 * (acc + rej) + acc
    return calls


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--case", default="both", choices=["a", "b", "both"])
    ap.add_argument("--duration", default=None, help='simulated time, e.g. "2 ms" (default: the case file)')
    ap.add_argument("--traction", default=None, choices=["slices", "coulomb", "none"])
    ap.add_argument("--integrator", default=None, choices=["auto", "dopri5", "ros2w", "ros34w"])
    ap.add_argument("--tolerance", type=float, default=None, help="integrator tolerance (default: the case file)")
    ap.add_argument("--n-slices", type=int, default=None, help="slices per contact ellipse, Gauss nodes per "
                    "stretch with --slice-rule gauss, nodes in all with --slice-rule log (default: the case file)")
    ap.add_argument("--slice-rule", default=None, choices=["strips", "split", "gauss", "log"],
                    help="traction quadrature (default: the case file's, strips)")
    ap.add_argument("--vehicle-speed", type=float, default=None, help="hub case (b) at this vehicle speed [km/h] "
                    "(default: the case file's 100 km/h)")
    ap.add_argument("--accuracy", action="store_true", help="compare with a DOPRI5 run at tolerance 1e-7")
    ap.add_argument("--cage-modes", type=int, default=0, help="elastic cages with this many modes each (default rigid)")
    ap.add_argument("--profile", action="store_true", help="cProfile the run")
    ap.add_argument("--threads", type=int, default=1, help="threads for the ball contacts (default 1)")
    ap.add_argument("--kernel", action="store_true", help="time one right-hand side per traction model and "
                    "report what limits the step (numba profiling)")
    ap.add_argument("--steps", action="store_true", help="profile what limits the ROS34PW2 step (error share per "
                    "state class, rejected steps) over --duration (default 1 ms)")
    ap.add_argument("--timeline", default=None, metavar="WINDOW", help='where in time the steps go: steps, '
                    'rejections, Jacobian refreshes and inner loads per WINDOW (e.g. "0.2 ms") over --duration '
                    '(default 20 ms) from t = 0')
    ap.add_argument("--jac-every", type=int, default=20, help="with --timeline: the most steps between Jacobian "
                    "refreshes (default 20, the engine's)")
    ap.add_argument("--jac-fixed", action="store_true", help="with --timeline: refresh every --jac-every steps "
                    "(the engine before the adaptive interval; default: the interval from the run's record)")
    ap.add_argument("--jac-unturned", action="store_true", help="with --timeline: the Jacobian used as made, not "
                    "turned with the balls' orbit (the engine before the seventeenth pass)")
    ap.add_argument("--multirate", type=int, default=None, help="the most balls a ROS34PW2 step refines with micro "
                    "steps of their own (0: none, the engine before the eighteenth pass; default: the case's, 8)")
    a = ap.parse_args(argv)
    global MULTIRATE
    MULTIRATE = a.multirate
    if a.timeline:
        from bearingsim.units import parse_quantity

        dur = parse_quantity(a.duration, "time", "--duration") if a.duration else 20e-3
        win = parse_quantity(a.timeline, "time", "--timeline")
        for name in (["a", "b"] if a.case == "both" else [a.case]):
            step_timeline(name, dur, win, a.vehicle_speed if name == "b" else None, a.slice_rule, a.n_slices,
                          a.tolerance, a.jac_every, a.jac_fixed, a.jac_unturned)
        return
    if a.steps:
        from bearingsim.units import parse_quantity

        dur = parse_quantity(a.duration, "time", "--duration") if a.duration else 1e-3
        for name in (["a", "b"] if a.case == "both" else [a.case]):
            step_profile(name, dur, a.tolerance)
        return
    if a.kernel:
        for name in (["a", "b"] if a.case == "both" else [a.case]):
            kernel_profile(name, a.threads, a.vehicle_speed if name == "b" else None, a.slice_rule, a.n_slices)
        return
    from bearingsim.units import parse_quantity

    dur = parse_quantity(a.duration, "time", "--duration") if a.duration else None
    for name in (["a", "b"] if a.case == "both" else [a.case]):
        keep = [] if a.accuracy else None
        vs = a.vehicle_speed if name == "b" else None
        r = run(name, dur, a.traction, a.profile, a.integrator, a.tolerance, a.n_slices, keep, a.cage_modes,
                a.threads, vs, a.slice_rule)
        print(f"case ({r['case']}) traction={r['traction']} integrator={r['integrator']} tol={r['tolerance']:g} "
              f"n_slices={r['n_slices']} slice_rule={r['slice_rule']} "
              + (f"vehicle_speed={vs:g} km/h " if vs is not None else "")
              + f"cage_modes={r['cage_modes']} threads={r['threads']}: "
              f"{r['simulated_s'] * 1e3:.4g} ms simulated in "
              f"{r['wall_s']:.3g} s -> {r['wall_per_simulated_s']:.4g} wall s per simulated s "
              f"({r['cpu_per_simulated_s']:.4g} CPU s); "
              f"{r['steps']} steps ({r['rejected']} rejected); peak RSS {r['peak_rss_MB']:.0f} MB")
        sys.stdout.flush()
        if a.accuracy:
            import numpy as np

            run(name, dur, a.traction, False, "dopri5", 1e-7, None, keep, a.cage_modes, a.threads, vs,
                a.slice_rule)
            test, ref = keep
            span = np.ptp(ref, axis=0) + 1e-30
            dev = np.abs(test - ref).max(axis=0) / span
            print("  largest deviation from DOPRI5 tol 1e-7 / range of the coordinate: "
                  + ", ".join(f"{k} {v:.2e}" for k, v in zip(("dx", "dy", "dz", "gy", "gz"), dev)))


if __name__ == "__main__":
    main()
