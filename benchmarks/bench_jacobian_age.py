"""How the Jacobian's age acts on a ROS34PW2 step of the hub case (issue 14, fifteenth pass): stability and error
estimate of one step on the linearisation, with W made of a fresh, an old or a mixed Jacobian.

Usage:  python benchmarks/bench_jacobian_age.py [--vehicle-speed KMH] [--t1 "4 ms"] [--age "80 us"]
         [--steps "1,2,4,8"]

The hub case (b) (examples/hub-moment-50hz.toml; --vehicle-speed as bench_dynamics.py) runs to t1 and on to
t1 + age (dense output, as the runs).  At both states the engine's finite-difference Jacobian is made as the
integrator makes it (`integrate.jacobian`: ball blocks, the ring's columns derived from them, its rows by
symmetry) and assembled dense over the ring's and the balls' states (the cages have no rows in it).  With A the
Jacobian at the later state with every column by finite differences (the ring's too), each step size h [µs] of
--steps gives the amplification matrix R of one ROS34PW2 step on y′ = A y — the integrator's own stages
(`ros34pw2.stages`) and W solves (`linalg.coupled_w`, W = I − γ h J), one step per unit vector — for J the
engine's fresh Jacobian, A itself (the ring's columns by differences), the older Jacobian (old), and the two
mixtures (ball blocks of one state, ring columns and block of the other), and prints its spectral radius
ρ(R) and the largest real part of J's eigenvalues.  With J = A, ρ(R) ≈ exp(h max Re λ(A)) (the method is
L-stable); ρ ≫ 1 means the step is unstable with that J.  Dense linear algebra over ≈ 300 states: seconds.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))


def _jacobian_parts(ws, atol, t, y, derived=True):
    """(ball blocks, J_rr, J_br, J_rb) at (t, y), made as ROS34PW2 makes them at a refresh: the ring's columns
    derived from the balls' sweeps (`jacobian.ring_columns`, the engine's way since the sixteenth pass), or with
    ``derived`` false by the ring's own finite differences (`jacobian.ring_jac`, before)."""
    from bearingsim.dynamics import layout as ly
    from bearingsim.dynamics.integrate import jacobian as jj
    from bearingsim.dynamics.integrate.linalg import NR

    n, nb, nbk = y.size, ws.blk.shape[0], ws.nbk
    f0 = np.zeros(n)
    ws.fun(t, y, f0, ws.args)
    jac, jrr = np.zeros((nb, nbk, nbk)), np.zeros((NR, NR))
    jbr, jrb = np.zeros((nb, nbk, NR)), np.zeros((nb, NR, nbk))
    yt, f1, epsb = np.zeros(n), np.zeros(n), np.zeros(nb)
    rec = ws.args[10]
    if derived:
        rbase = np.zeros((nb + 1, 6))
        rbase[:nb] = rec[:nb, ly.MEMO_INNER:ly.MEMO_INNER + 6]
        rbase[nb] = rec[nb, :6]
        drec = np.zeros((nb, nbk, 6))
        jj.block_jac(ws.fun, ws.args, t, y.copy(), f0, atol, ws.blk, nbk, jac, yt, f1, epsb, rec, rbase, drec)
        jj.ring_columns(y, ws.blk, rbase, drec, ws.rmass, ws.bmass, jrr, jbr)
    else:
        jj.ring_jac(ws.fun, ws.args, t, y.copy(), f0, atol, ws.blk, nbk, jrr, jbr, yt, f1)
        jj.block_jac(ws.fun, ws.args, t, y.copy(), f0, atol, ws.blk, nbk, jac, yt, f1, epsb, *jj.no_record())
    jj.ring_rows(jbr, ws.rmass, ws.bmass, jrb)
    return jac, jrr, jbr, jrb


def dense_jacobian(n, blk, balls, ring):
    """The n × n Jacobian the integrator's blocks stand for, with the ball blocks of ``balls`` and the ring block and
    coupling of ``ring`` (each a tuple of :func:`_jacobian_parts`; ``ring`` None: no ring block nor coupling)."""
    from bearingsim.dynamics.integrate.linalg import NR

    j = np.zeros((n, n))
    nbk = balls[0].shape[1]
    for b, o in enumerate(blk):
        j[o:o + nbk, o:o + nbk] = balls[0][b]
        if ring is not None:
            j[o:o + nbk, :NR] = ring[2][b]
            j[:NR, o:o + nbk] = ring[3][b]
    if ring is not None:
        j[:NR, :NR] = ring[1]
    return j


def amplification(a, blk, balls, ring, h):
    """R = ∂y₁/∂y₀ of one ROS34PW2 step of size h [s] on y′ = A y, with W = I − γ h J made of ``balls`` and ``ring``
    (as :func:`dense_jacobian`) the way the integrator makes it (:func:`.linalg.coupled_w` or
    :func:`.linalg.w_inverse`), the stages by :func:`.ros34pw2.stages` itself: column j is the step from y₀ = e_j."""
    from bearingsim.dynamics.integrate import ros34pw2 as rp
    from bearingsim.dynamics.integrate.common import linear_rhs
    from bearingsim.dynamics.integrate.linalg import NR, coupled_w, no_coupling, w_inverse

    n = a.shape[0]
    jac = balls[0]
    nb, nbk = jac.shape[0], jac.shape[1]
    winv = np.zeros((nb, nbk, nbk))
    wm = np.zeros((nbk, nbk))
    if ring is None:
        w_inverse(jac, h, rp.R34_G, winv, wm)
        cpl = no_coupling(nbk)
    else:
        qm, sinv, srr, sb = np.zeros((nb, nbk, NR)), np.zeros((NR, NR)), np.zeros((NR, NR)), np.zeros((nb, NR, NR))
        coupled_w(jac, ring[1], ring[2], ring[3], h, rp.R34_G, winv, wm, qm, sinv, srr, sb)
        cpl = (ring[1], ring[2], ring[3], qm, sinv, np.zeros((nb, nbk)), np.zeros(NR))
    k1, k2, k3, k4, yt, ft, tv = (np.zeros(n) for _ in range(7))
    out = np.zeros((n, n))
    for j in range(n):
        y = np.zeros(n)
        y[j] = 1.0
        rp.stages(linear_rhs, (a,), 0.0, y, h, a[:, j].copy(), winv, blk, nbk, k1, k2, k3, k4, yt, ft, tv, cpl,
                  np.zeros((0, 2)))
        out[:, j] = y + rp.R34_M[0] * k1 + rp.R34_M[1] * k2 + rp.R34_M[2] * k3 + rp.R34_M[3] * k4
    return out


def jacobian_age(vehicle_speed: float | None, t1: float, age: float, steps: list[float]) -> dict:
    """The report of the module docstring; returns {variant: (max Re λ(J), [ρ(R) per step])} and "drift", the
    relative change of the Jacobian over ``age`` (Frobenius)."""
    from bearingsim.dynamics import run as R
    from bearingsim.dynamics.integrate.linalg import NR
    from bench_dynamics import load_bench_case

    case = load_bench_case("b", vehicle_speed)
    m, ls, y, _ = R.build(case)
    st = R.Stepper(m, ls, y.copy(), tol=case.tolerance, method=case.method, threads=1, dense=True)
    ws = st.workspace
    st.advance(t1)
    t_old, p_old = st.t, _jacobian_parts(ws, st.atol, st.t, st.y.copy())
    st.advance(t1 + age)
    t_new, p_new = st.t, _jacobian_parts(ws, st.atol, st.t, st.y.copy())
    p_fd = _jacobian_parts(ws, st.atol, st.t, st.y.copy(), derived=False)
    n = st.y.size
    # the ring's and the balls' states (the cages have no rows in J: W is the identity there)
    idx = np.r_[np.arange(NR), np.concatenate([np.arange(o, o + ws.nbk) for o in ws.blk])]
    variants = {"fresh": (p_new, p_new), "fresh, ring by differences": (p_fd, p_fd), "old": (p_old, p_old),
                "balls fresh, ring old": (p_new, p_old), "balls old, ring fresh": (p_old, p_new)}
    a = dense_jacobian(n, ws.blk, p_fd, p_fd)  # the linearisation: the finite differences of every column
    drift = float(np.linalg.norm(dense_jacobian(n, ws.blk, p_old, p_old) - a) / np.linalg.norm(a))
    lam = np.linalg.eigvals(a[np.ix_(idx, idx)])
    print(f"hub (b){f' at {vehicle_speed:g} km/h' if vehicle_speed is not None else ''}: Jacobians at t = "
          f"{t_old * 1e3:.4g} and {t_new * 1e3:.4g} ms; change {drift:.3f} (Frobenius, relative); fresh: largest "
          f"|λ| {np.abs(lam).max():.3g} 1/s")
    out = {"drift": drift}
    for name, (balls, ring) in variants.items():
        re = float(np.linalg.eigvals(dense_jacobian(n, ws.blk, balls, ring)[np.ix_(idx, idx)]).real.max())
        rho = [float(np.abs(np.linalg.eigvals(amplification(a, ws.blk, balls, ring, h)[np.ix_(idx, idx)])).max())
               for h in steps]
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
