"""Benchmark of the elastic-ring model (issue 16 item 5).

(a) Influence coefficients of the SKF 7011 CDGA/HC rings (inner and outer, default settings): first computation
    (an empty cache folder) and the cached read.  Target: ≤ 30 s per ring the first time.
(b) A static solve with FE rings (coefficients cached) against the rigid-ring solve, same loads, alternating
    (the shared machine's load varies), median of ``--repeat`` runs each.  Target: ≤ 10× the rigid solve.
(c) A small map (``bearingsim.sweep.map_grid``, 10 loads × 5 speeds up to 10,000 rpm, in this process) with FE
    rings against the rigid-ring map (batch kernel): the coefficients are read from the cache once and reused
    for every point (warm-started from the previous point).
(f) The [S1] hub unit (one outer ring shared by both rows, two inner rings): coefficients first time and cached,
    a static solve with FE rings against rigid rings, a map over 25 moments.

(d) With ``--solid3d``: the harmonic ring model against the 3-D quarter-ring reference
    (:class:`bearingsim.rings.solid3d.QuarterRing3D`, quadratic hexahedra) for both 7011 rings under four equal
    ball loads of 1 kN along the contact normal (θ = 0, 90, 180, 270°; spread σ = 1.2 mm, σ_θ = 0.2 rad), same
    section grid: (u_r, u_z) at the contact point and at depths 1.8 and 3.6 mm below it, under a ball (θ = 0) and
    between two (θ = 45°).  Issue 16: ≤ 2 %.  Minutes (not in CI).

(e) With ``--shared3d``: the same comparison for the shared outer ring of the [S1] hub unit (two grooves,
    :mod:`bearingsim.rings.shared`, estimated section): four 1 kN ball loads on row 1 only, the displacements
    read at row 1's and at row 2's contact points: the row-to-row coupling against the 3-D reference.

Usage:  python benchmarks/bench_rings.py [--repeat 30] [--skip-first] [--solid3d] [--shared3d] [--n-theta 8]
        [--figure map_fe.png]   (c)'s map: K_xx with rigid and FE rings over load and speed
The numba compilation is excluded (one warm-up solve each).  CPU seconds (process time) are printed next to
the wall seconds: the steadier figure on a shared machine.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time

import numpy as np


def timed(fn):
    t0, c0 = time.perf_counter(), time.process_time()
    out = fn()
    return out, time.perf_counter() - t0, time.process_time() - c0


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=30)
    ap.add_argument("--skip-first", action="store_true", help="skip (a)'s first computation (use the user cache)")
    ap.add_argument("--solid3d", action="store_true", help="only (d): harmonic model vs the 3-D reference")
    ap.add_argument("--n-theta", type=int, default=8, help="(d): hexahedra over the quarter circumference")
    ap.add_argument("--shared3d", action="store_true", help="only (e): the hub's shared outer ring vs 3-D")
    ap.add_argument("--figure", default=None, help="(c): write the map's K_xx with FE / rigid rings to this PNG")
    args = ap.parse_args()
    if args.solid3d:
        solid3d(args.n_theta)
        return
    if args.shared3d:
        shared3d(args.n_theta)
        return

    from bearingsim.io import load_bearing
    from bearingsim.rings import influence as inf
    from bearingsim.rings.coupling import ring_model
    from bearingsim.rings.coupling import solve as solve_fe
    from bearingsim.rings.section import estimate_sections
    from bearingsim.statics.jones_harris import Loads, solve

    b = load_bearing("skf-7011-cdga-hc")
    inner, outer = estimate_sections(b)
    tmp = None
    if not args.skip_first:
        tmp = tempfile.TemporaryDirectory()
        os.environ[inf.CACHE_ENV] = tmp.name
        for sec in (inner, outer):
            r, wall, cpu = timed(lambda sec=sec: inf.compute_influence(
                sec, b.ring_material.youngs_modulus, b.ring_material.poisson_ratio, b.ball_count))
            print(f"(a) {sec.kind} ring coefficients, first time: {wall:6.1f} s wall, {cpu:6.1f} s CPU "
                  f"({r.harmonics} harmonics, {r.meta['harmonics_solved']} solved, {r.meta['dofs']} dofs)")
    rings, wall, cpu = timed(lambda: ring_model(b))
    print(f"(a) both rings from the cache: {1e3 * wall:.1f} ms wall")

    cases = {"Fa 1 kN": Loads(fa=1000.0), "Fa 5 kN": Loads(fa=5000.0),
             "Fa 2 kN + Fr 1.5 kN + M 20 N·m": Loads(fa=2000.0, fr_y=1500.0, m_z=20.0)}
    for name, loads in cases.items():
        solve(b, loads)
        solve_fe(b, loads, rings=rings)
        tr, tf = [], []
        for _ in range(args.repeat):  # alternating
            tr.append(timed(lambda: solve(b, loads))[2])
            tf.append(timed(lambda: solve_fe(b, loads, rings=rings))[2])
        r0 = solve(b, loads)
        r1 = solve_fe(b, loads, rings=rings)
        ratio = np.median(tf) / np.median(tr)
        print(f"(b) {name:32s} rigid {1e3 * np.median(tr):6.2f} ms CPU, FE rings {1e3 * np.median(tf):6.2f} ms CPU, "
              f"ratio {ratio:5.1f}  (K_xx {r0.axial_stiffness / 1e6:6.1f} → {r1.axial_stiffness / 1e6:6.1f} N/µm, "
              f"{r1.ring_iterations} ring iterations)")

    from bearingsim.sweep import map_grid

    grid = dict(fa="500:5000:10", speed="0:10000:5", workers=1)
    map_grid(b, fa=[1000.0, 2000.0], workers=1)  # compiled kernels loaded before timing
    rigid_map, wr, cr = timed(lambda: map_grid(b, **grid))
    fe_map, wf, cf = timed(lambda: map_grid(b, rings="fe", **grid))
    if args.figure:
        _map_figure(rigid_map, fe_map, args.figure)
    print(f"(c) bearingsim.sweep.map_grid 10 loads × 5 speeds, in this process: rigid rings (batch kernel) "
          f"{1e3 * cr / 50:.3f} ms CPU per point, FE rings (coefficients from the cache once, warm-started points) "
          f"{cf:.2f} s CPU "
          f"({1e3 * cf / 50:.1f} ms per point), ratio {cf / max(cr, 1e-9):.0f}")

    # (f) the [S1] hub unit: shared outer ring (two grooves) + two inner rings
    from bearingsim.rings.shared import estimate_unit

    hub = load_bearing("hub-seed001")
    if not args.skip_first:
        _, wh, ch = timed(lambda: ring_model(hub))
        print(f"(f) hub unit, all ring coefficients first time: {wh:.1f} s wall, {ch:.1f} s CPU "
              f"(shared outer ring of {estimate_unit(hub)[1].z_faces} m)")
    hrings, wh, _ = timed(lambda: ring_model(hub))
    print(f"(f) hub rings from the cache: {1e3 * wh:.1f} ms wall; shared ring "
          f"{hrings.description['shared_outer_ring']['dofs']} unknowns, "
          f"{hrings.description['shared_outer_ring']['seconds']:.1f} s when computed")
    hl = Loads(fa=1890.0, fr_y=3750.0, m_z=600.0)
    solve(hub, hl)
    solve_fe(hub, hl, rings=hrings)
    tr, tf = [], []
    for _ in range(args.repeat):
        tr.append(timed(lambda: solve(hub, hl))[2])
        tf.append(timed(lambda: solve_fe(hub, hl, rings=hrings))[2])
    r0, r1 = solve(hub, hl), solve_fe(hub, hl, rings=hrings)
    print(f"(f) hub static (Fa 1890 N, Fr 3750 N, M 600 N·m): rigid {1e3 * np.median(tr):.2f} ms CPU, FE rings "
          f"{1e3 * np.median(tf):.2f} ms CPU, ratio {np.median(tf) / np.median(tr):.1f}; tilt "
          f"{r0.displacement[4] * 1e3:.3f} → {r1.displacement[4] * 1e3:.3f} mrad, K_tilt "
          f"{r0.stiffness[4, 4] / 1e3:.1f} → {r1.stiffness[4, 4] / 1e3:.1f} N·m/mrad")
    hgrid = dict(moment="-600:600:25", fr="2785 N", workers=1)
    map_grid(hub, moment=[0.0, 100.0], workers=1)
    _, wr, cr = timed(lambda: map_grid(hub, **hgrid))
    _, wf, cf = timed(lambda: map_grid(hub, rings="fe", **hgrid))
    print(f"(f) hub map over 25 moments: rigid {1e3 * cr / 25:.3f} ms CPU per point, FE rings {cf:.2f} s CPU "
          f"({1e3 * cf / 25:.1f} ms per "
          f"point), ratio {cf / max(cr, 1e-9):.0f}")
    if tmp is not None:
        tmp.cleanup()


def solid3d(n_theta: int) -> None:
    """(d) of the module docstring."""
    import math

    from bearingsim.io import load_bearing
    from bearingsim.rings.axisymmetric import HarmonicRing
    from bearingsim.rings.section import estimate_sections, mesh_section

    b = load_bearing("skf-7011-cdga-hc")
    e, nu = b.ring_material.youngs_modulus, b.ring_material.poisson_ratio
    sig, sig_t, h, force = 1.2e-3, 0.2, 0.6e-3, 1000.0
    worst = 0.0
    for sec in estimate_sections(b):
        p, nin = sec.contact_point, sec.inward_normal
        pts = np.column_stack([p, p + 1.5 * sig * nin, p + 3.0 * sig * nin])
        (s3, x), wall, cpu = timed(lambda sec=sec, p=p, nin=nin: _solve3d(sec, e, nu, h, n_theta, p, nin, sig, sig_t,
                                                                         force))
        face = "face_minus" if sec.support_face_z < 0 else "face_plus"
        ring = HarmonicRing(mesh_section(sec, h, 5, 10), e, nu, radial_fixed=("seat",), axial_fixed=(face,),
                            radial_harmonics=(1,))
        fl = ring.point_load("raceway", p, -nin, sig)
        probe = ring.probe(pts)
        for th in (0.0, math.pi / 4):
            uh = np.zeros((2, 3))
            for n in range(0, 200, 4):  # four balls 90° apart: harmonics 0, 4, 8, …
                gh = math.exp(-0.5 * (n * sig_t) ** 2)
                if gh < 1e-10:
                    break
                v = probe @ ring.solve(n, force * gh * fl)
                uh += 4.0 * math.cos(n * th) * np.vstack([v[0:3], v[3:6]])
            u3 = s3.cylindrical(x, pts, th)
            dev = (u3 - uh) / np.abs(uh).max()
            worst = max(worst, float(np.abs(dev).max()))
            print(f"(d) {sec.kind} θ = {math.degrees(th):4.0f}°  u_r [nm] 3-D {np.round(u3[0] * 1e9, 1)} harmonic "
                  f"{np.round(uh[0] * 1e9, 1)} | u_z 3-D {np.round(u3[1] * 1e9, 1)} harmonic {np.round(uh[1] * 1e9, 1)}"
                  f" | max dev {np.abs(dev).max():.2%}")
        print(f"(d) {sec.kind}: 3-D {s3.dofs} unknowns, {wall:.0f} s wall, {cpu:.0f} s CPU")
    print(f"(d) largest deviation of the harmonic model from the 3-D reference: {worst:.2%} (issue 16: ≤ 2 %)")


def _map_figure(rigid, fe, path) -> None:
    """K_xx over the (c) map with rigid and FE rings, and their ratio (matplotlib PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fa = rigid["fa"].values / 1e3
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 4))
    for j, w in enumerate(rigid["speed"].values):
        rpm = w * 30.0 / np.pi
        kr = rigid["stiffness"].values[:, j, 0, 0] / 1e6
        kf = fe["stiffness"].values[:, j, 0, 0] / 1e6
        line, = a1.plot(fa, kr, "--", lw=1)
        a1.plot(fa, kf, "-", color=line.get_color(), label=f"{rpm:.0f} rpm")
        a2.plot(fa, kf / kr, "o-", color=line.get_color(), ms=3)
    a1.set_xlabel("Fa [kN]")
    a1.set_ylabel("K_xx [N/µm] (dashed: rigid rings, solid: FE rings)")
    a1.legend(fontsize=8)
    a2.set_xlabel("Fa [kN]")
    a2.set_ylabel("K_xx FE rings / rigid rings")
    fig.suptitle(f"{rigid.attrs.get('bearing', '')}: bearingsim map --rings fe")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"(c) wrote {path}")


def shared3d(n_theta: int) -> None:
    """(e) of the module docstring: the shared outer ring of the [S1] hub (two grooves), four 1 kN ball loads on
    row 1 only; (u_r, u_z) at both rows' contact points (and 1.8, 3.6 mm below), harmonic vs 3-D."""
    import math

    from bearingsim.io import load_bearing
    from bearingsim.rings.axisymmetric import HarmonicRing
    from bearingsim.rings.section import mesh_section
    from bearingsim.rings.shared import estimate_unit
    from bearingsim.rings.solid3d import QuarterRing3D

    hub = load_bearing("hub-seed001")
    b = hub.rows[0].bearing
    e, nu = b.ring_material.youngs_modulus, b.ring_material.poisson_ratio
    _, sec, _ = estimate_unit(hub)
    sig, sig_t, h, force = 1.2e-3, 0.2, 0.6e-3, 1000.0
    p1 = sec.contact_point(0)
    n1 = sec.to_global(0) @ sec.local_normal(0)
    t0 = time.perf_counter()
    s3 = QuarterRing3D(sec, e, nu, h, n_theta=n_theta, n_through=5, n_axial=10)
    print(f"(e) 3-D shared ring: {s3.dofs} unknowns", flush=True)
    x = s3.solve(s3.ball_load_vector(p1, -n1, sig, sig_t, (-math.pi / 2, 0.0, math.pi / 2, math.pi), force=force))
    wall3 = time.perf_counter() - t0
    ring = HarmonicRing(mesh_section(sec, h, 5, 10), e, nu, radial_fixed=("seat",), axial_fixed=("seat",),
                        radial_harmonics=(1,))
    fl = ring.point_load("raceway", p1, -n1, sig)
    worst = 0.0
    for k in (0, 1):
        p, nk = sec.contact_point(k), sec.to_global(k) @ sec.local_normal(k)
        pts = np.column_stack([p, p + 1.5 * sig * nk, p + 3.0 * sig * nk])
        probe = ring.probe(pts)
        for th in (0.0, math.pi / 4):
            uh = np.zeros((2, 3))
            for n in range(0, 200, 4):
                gh = math.exp(-0.5 * (n * sig_t) ** 2)
                if gh < 1e-10:
                    break
                v = probe @ ring.solve(n, force * gh * fl)
                uh += 4.0 * math.cos(n * th) * np.vstack([v[0:3], v[3:6]])
            u3 = s3.cylindrical(x, pts, th)
            dev = (u3 - uh) / np.abs(uh).max()
            worst = max(worst, float(np.abs(dev).max()))
            print(f"(e) groove of row {k + 1}, θ = {math.degrees(th):3.0f}°  u_r [nm] 3-D {np.round(u3[0] * 1e9, 1)} "
                  f"harmonic {np.round(uh[0] * 1e9, 1)} | u_z 3-D {np.round(u3[1] * 1e9, 1)} harmonic "
                  f"{np.round(uh[1] * 1e9, 1)} | max dev {np.abs(dev).max():.2%} of the largest", flush=True)
    print(f"(e) 3-D {s3.dofs} unknowns, {wall3:.0f} s wall; largest deviation {worst:.2%}")


def _solve3d(sec, e, nu, h, n_theta, p, nin, sig, sig_t, force):
    import math

    from bearingsim.rings.solid3d import QuarterRing3D

    s3 = QuarterRing3D(sec, e, nu, h, n_theta=n_theta, n_through=5, n_axial=10)
    f = s3.ball_load_vector(p, -nin, sig, sig_t, (-math.pi / 2, 0.0, math.pi / 2, math.pi), force=force)
    return s3, s3.solve(f)


if __name__ == "__main__":
    main()
