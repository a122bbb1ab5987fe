"""Test helper: a ball-like Jacobian block (tests/unit/test_dyn_integrator.py, test_dyn_orbit_turn.py)."""

from __future__ import annotations


def ball_like_block(rng, scale):
    """A 9 × 9 block with a ball's kinematic rows (ṙ = v: rows 0–2 = [0 I 0]) and random dynamics below."""
    jb = rng.normal(size=(9, 9)) * scale
    jb[0:3, :] = 0.0
    jb[0, 3] = jb[1, 4] = jb[2, 5] = 1.0
    return jb


def arrowhead_system(rng, jac, extra=5):
    """A ring–ball coupled Jacobian around the ball blocks ``jac`` [nb, 9, 9] with the engine's structure (J_br's
    position rows zero, J_rb from J_br by reciprocity, :func:`ring_rows`), laid out as the state (ring, balls,
    ``extra`` states with J = 0): (blk, J_rr, J_br, J_rb, the dense J)."""
    import numpy as np

    from bearingsim.dynamics.integrate.jacobian import ring_rows
    from bearingsim.dynamics.integrate.linalg import NR

    nb, nbk = jac.shape[0], jac.shape[1]
    n = NR + nb * nbk + extra
    blk = np.array([NR + nbk * b for b in range(nb)], dtype=np.int64)
    jrr = rng.normal(size=(NR, NR)) * 50
    jbr = rng.normal(size=(nb, nbk, NR)) * 50
    jbr[:, 0:3, :] = 0.0  # a ball's ṙ = v does not depend on the ring (the structure coupled_w relies on)
    jrb = np.zeros((nb, NR, nbk))
    ring_rows(jbr, np.array([3.0, 3.0, 3.0, 0.01, 0.01]), np.tile([5.6e-3, 6.9e-8], (nb, 1)), jrb)
    dense = np.zeros((n, n))
    dense[:NR, :NR] = jrr
    for b, o in enumerate(blk):
        dense[o:o + nbk, o:o + nbk] = jac[b]
        dense[o:o + nbk, :NR] = jbr[b]
        dense[:NR, o:o + nbk] = jrb[b]
    return blk, jrr, jbr, jrb, dense
