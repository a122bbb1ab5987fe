"""How the Jacobian's age acts on a ROS34PW2 step of the hub case (issue 14, fifteenth pass): stability and error
estimate of one step on the linearisation, with W made of a fresh, an old or a mixed Jacobian.

Usage:  python benchmarks/bench_jacobian_age.py [--vehicle-speed KMH] [--t1 "4 ms"] [--age "80 us"]
         [--steps "1,2,4,8"]

The hub case (b) (examples/hub-moment-50hz.toml; --vehicle-speed as bench_dynamics.py) runs to t1 and on to
t1 + age (dense output, as the runs).  At both states the engine's finite-difference Jacobian is made as the
integrator makes it (`integrate.jacobian`: ball blocks, the ring's columns, its rows by symmetry) and assembled
dense over the ring's and the balls' states (the cages have no rows in it).  With A the Jacobian at the later
state, each step size h [µs] of --steps gives the amplification matrix R = I + Σ mᵢ Kᵢ of one ROS34PW2 step on
y′ = A y (the stage formulas of `ros34pw2.stages`, W = I − γ h J) for J = A (fresh), the older Jacobian (old), and
the two mixtures (ball blocks of one state, ring columns and block of the other), and prints its spectral radius
ρ(R) and the largest real part of J's eigenvalues.  With J = A, ρ(R) ≈ exp(h max Re λ(A)) (the method is
L-stable); ρ ≫ 1 means the step is unstable with that J.  Dense linear algebra over ≈ 300 states: seconds.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))


def _jacobian_parts(ws, atol, t, y):
    """(ball blocks, J_rr, J_br, J_rb) at (t, y), made as ROS34PW2 makes them at a refresh."""
    from bearingsim.dynamics.integrate import jacobian as jj

    n, nb, nbk = y.size, ws.blk.shape[0], ws.nbk
    f0 = np.zeros(n)
    ws.fun(t, y, f0, ws.args)
    jac, jrr = np.zeros((nb, nbk, nbk)), np.zeros((10, 10))
    jbr, jrb = np.zeros((nb, nbk, 10)), np.zeros((nb, 10, nbk))
    yt, f1, epsb = np.zeros(n), np.zeros(n), np.zeros(nb)
    jj.ring_jac(ws.fun, ws.args, t, y.copy(), f0, atol, ws.blk, nbk, jrr, jbr, yt, f1)
    jj.ring_rows(jbr, ws.rmass, ws.bmass, jrb)
    jj.block_jac(ws.fun, ws.args, t, y.copy(), f0, atol, ws.blk, nbk, jac, yt, f1, epsb)
    return jac, jrr, jbr, jrb


def dense_jacobian(blk, balls, ring, idx):
    """The Jacobian over the states ``idx`` (ring first, then each ball's block) with the ball blocks of ``balls``
    and the ring block and coupling of ``ring`` (each a tuple of :func:`_jacobian_parts`)."""
    n = int(idx.max()) + 1
    j = np.zeros((n, n))
    jac = balls[0]
    jrr, jbr, jrb = ring[1], ring[2], ring[3]
    j[:10, :10] = jrr
    for b, o in enumerate(blk):
        j[o:o + 9, o:o + 9] = jac[b]
        j[o:o + 9, :10] = jbr[b]
        j[:10, o:o + 9] = jrb[b]
    return j[np.ix_(idx, idx)]


def amplification(a, j, h):
    """R = I + Σ mᵢ Kᵢ of one ROS34PW2 step of size h [s] on y′ = A y with W = I − γ h J (``ros34pw2.stages``)."""
    from bearingsim.dynamics.integrate import ros34pw2 as rp

    g = rp.R34_G
    alpha = {(2, 1): rp.R34_A21, (3, 1): rp.R34_A31, (3, 2): rp.R34_A32, (4, 1): rp.R34_A41, (4, 2): rp.R34_A42,
             (4, 3): rp.R34_A43}
    gam = {(2, 1): rp.R34_C21, (3, 1): rp.R34_C31, (3, 2): rp.R34_C32, (4, 1): rp.R34_C41, (4, 2): rp.R34_C42,
           (4, 3): rp.R34_C43}
    eye = np.eye(a.shape[0])
    winv = np.linalg.inv(eye - g * h * j)
    k = {}
    for i in (1, 2, 3, 4):
        y = eye.copy()
        tv = np.zeros_like(eye)
        for m in range(1, i):
            y += alpha[(i, m)] * k[m]
            tv += gam[(i, m)] / g * k[m]
        k[i] = winv @ (h * a @ y + tv) - tv
    return eye + sum(mi * k[i + 1] for i, mi in enumerate(rp.R34_M))


def jacobian_age(vehicle_speed: float | None, t1: float, age: float, steps: list[float]) -> dict:
    """The report of the module docstring; returns {variant: (max Re λ(J), [ρ(R) per step])} and "drift", the
    relative change of the Jacobian over ``age`` (Frobenius)."""
    from bearingsim.dynamics import run as R
    from bench_dynamics import load_bench_case

    case = load_bench_case("b", vehicle_speed)
    m, ls, y, _ = R.build(case)
    st = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, dense=True)
    ws = st.workspace
    st.advance(t1)
    t_old, p_old = st.t, _jacobian_parts(ws, st.atol, st.t, st.y.copy())
    st.advance(t1 + age)
    t_new, p_new = st.t, _jacobian_parts(ws, st.atol, st.t, st.y.copy())
    idx = np.r_[np.arange(10), np.concatenate([np.arange(o, o + 9) for o in ws.blk])]
    a = dense_jacobian(ws.blk, p_new, p_new, idx)
    variants = {"fresh": a, "old": dense_jacobian(ws.blk, p_old, p_old, idx),
                "balls fresh, ring old": dense_jacobian(ws.blk, p_new, p_old, idx),
                "balls old, ring fresh": dense_jacobian(ws.blk, p_old, p_new, idx)}
    drift = float(np.linalg.norm(variants["old"] - a) / np.linalg.norm(a))
    lam = np.linalg.eigvals(a)
    print(f"hub (b){f' at {vehicle_speed:g} km/h' if vehicle_speed is not None else ''}: Jacobians at t = "
          f"{t_old * 1e3:.4g} and {t_new * 1e3:.4g} ms; change {drift:.3f} (Frobenius, relative); fresh: largest "
          f"|λ| {np.abs(lam).max():.3g} 1/s")
    out = {"drift": drift}
    for name, j in variants.items():
        re = float(np.linalg.eigvals(j).real.max())
        rho = [float(np.abs(np.linalg.eigvals(amplification(a, j, h))).max()) for h in steps]
        out[name] = (re, rho)
        print(f"  {name:22s} max Re λ(J) {re:10.4g} 1/s; ρ(R) at "
              + ", ".join(f"{h * 1e6:g} µs {r:.4g}" for h, r in zip(steps, rho)))
    return out


def main(argv=None):
    from bearingsim.units import parse_quantity

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--vehicle-speed", type=float, default=None, help="km/h (default: the case's 100 km/h)")
    ap.add_argument("--t1", default="4 ms", help='the older state\'s time (default "4 ms")')
    ap.add_argument("--age", default="80 us", help='the older Jacobian\'s age (default "80 us", ≈ 20 steps)')
    ap.add_argument("--steps", default="1,2,4,8", help="step sizes [µs] (default 1,2,4,8)")
    a = ap.parse_args(argv)
    steps = [float(s) * 1e-6 for s in a.steps.split(",")]
    jacobian_age(a.vehicle_speed, parse_quantity(a.t1, "time", "--t1"), parse_quantity(a.age, "time", "--age"), steps)


if __name__ == "__main__":
    main()
