"""Finite-difference Jacobians of the W-methods: per-ball blocks, the inner ring's columns, and the
ring's rows by the symmetry of the contact forces.

J ≈ ∂f/∂y is only an approximation in a W-method (the order does not depend on it), so it is
estimated cheaply: forward differences with the step 1e-7 max(|y_j|, 1e4 atol_j), one component of
every ball block perturbed at once (:func:`block_jac`: the balls' derivatives do not depend on each
other's states directly), the ring's 10 columns one at a time (:func:`ring_jac`), and the ring's rows
from the balls' columns (:func:`ring_rows`).  Layout: :mod:`.linalg`.

Each difference is divided by the step actually taken, (y + e) − y in floating point, not by e (Press et al.,
*Numerical Recipes*, 3rd ed. 2007, §5.7): a derivative that is a state itself (a ball's ṙ = v, the ring's
q̇ = q̇) then comes out exactly 1, so the kinematic rows of J are exact and :func:`.linalg.block_w_inverse`
can eliminate them (issue 14); before, they were 1 ± 1e-9.
"""

from __future__ import annotations

from numba import njit

from .linalg import NR


@njit
def block_jac(fun, args, t, y, f0, atol, blk, nbk, jac, yt, f1, epsb):
    """Finite-difference blocks of ∂f/∂y: one component of every block perturbed at once
    (the blocks' derivatives do not depend on each other's states directly)."""
    n = y.shape[0]
    nb = blk.shape[0]
    for j in range(nbk):
        for i in range(n):
            yt[i] = y[i]
        for b in range(nb):
            o = blk[b] + j
            yt[o] = y[o] + 1e-7 * max(abs(y[o]), 1e4 * atol[o])
            epsb[b] = yt[o] - y[o]  # the step actually taken (see the module docstring)
        fun(t, yt, f1, args)
        for b in range(nb):
            o = blk[b]
            for i in range(nbk):
                jac[b, i, j] = (f1[o + i] - f0[o + i]) / epsb[b]


@njit
def ring_jac(fun, args, t, y, f0, atol, blk, nbk, jrr, jbr, yt, f1):
    """Finite-difference ring columns of ∂f/∂y: the ring's own block J_rr (10 × 10) and the balls'
    dependence on the ring J_br (per ball nbk × 10), one ring component perturbed at a time."""
    for j in range(NR):
        for i in range(y.shape[0]):
            yt[i] = y[i]
        yt[j] = y[j] + 1e-7 * max(abs(y[j]), 1e4 * atol[j])
        e = yt[j] - y[j]  # the step actually taken (see the module docstring)
        fun(t, yt, f1, args)
        for i in range(NR):
            jrr[i, j] = (f1[i] - f0[i]) / e
        for b in range(blk.shape[0]):
            o = blk[b]
            for i in range(nbk):
                jbr[b, i, j] = (f1[o + i] - f0[o + i]) / e


@njit(cache=True)
def ring_rows(jbr, rmass, bmass, jrb):
    """The ring's dependence on the balls J_rb from J_br by the symmetry of the contact stiffness and
    damping between two bodies (the force of a contact depends on the bodies' relative position and
    sliding velocity, and the ring feels minus the ball's force): M_r ∂a_r/∂(x_b, v_b, ω_b) =
    [M_b ∂a_b/∂(q_r, q̇_r, q̇_r)]ᵀ for the ring's accelerations (rows 5–9); its position rows do not
    depend on the balls.  An approximation (it drops the asymmetric parts: spin, the ring's
    gyroscopic terms, lever-arm changes), which a W-method tolerates without loss of order."""
    for b in range(jbr.shape[0]):
        mb = bmass[b, 0]
        jb = bmass[b, 1]
        for i in range(NR):
            for j in range(9):
                jrb[b, i, j] = 0.0
        for i in range(5):
            mr = rmass[i]
            for j in range(3):
                jrb[b, 5 + i, j] = mb / mr * jbr[b, 3 + j, i]  # positions ↔ ring positions
                jrb[b, 5 + i, 3 + j] = mb / mr * jbr[b, 3 + j, 5 + i]  # velocities ↔ ring rates
                jrb[b, 5 + i, 6 + j] = jb / mr * jbr[b, 6 + j, 5 + i]  # angular velocities ↔ ring rates
