"""The load distribution of ISO/TS 16281:2008 for one row of balls, and the basic reference rating life L10r
computed on it, as the standard defines them.

:func:`bearingsim.statics.jones_harris.solve` gives every result its ``reference_rating_life`` from the
Jones–Harris load distribution (speed, sets, elastic rings included).  This module gives L10r from the
standard's own, simpler load distribution, the number a program that follows ISO/TS 16281 prints.  At rest
both give the same ball loads for a deep-groove row without a moment (the same Hertz constant, and the tilt
radius drops out, below); under a moment they differ by the moment arm (below), and for an angular-contact row
whose ring tilts by the radial shift of its axially offset groove centres, which the standard's approach
omits (−0.46 % on L10r for a 7011 at 25° under F_a = 1 kN, F_r = 0.5 kN).

Model (rigid rings, no centrifugal force or gyroscopic moment; ball j at azimuth ψ_j = 2πj/Z, ring
displacement q = (δ_x, δ_y, δ_z, γ_y, γ_z) [m, m, m, rad, rad] as in a
:class:`~bearingsim.statics.jones_harris.StaticResult`):

    radial distance of the groove-curvature centres   d_r,j = d_r0 + δ_y cos ψ_j + δ_z sin ψ_j
    axial distance                                    d_a,j = d_a0 + δ_x + (D_pw/2)(γ_y sin ψ_j − γ_z cos ψ_j)
    (deep groove: d_r0 = A − P_d/2, d_a0 = 0; angular contact: d_r0 = A cos α₀ − P_d/2, d_a0 = A sin α₀)
    approach  δ_j = max(√(d_r,j² + d_a,j²) − A, 0),   contact angle  α_j = atan2(d_a,j, d_r,j)
    ball load  Q_j = K_n δ_j^1.5   (K_n of two Hertz contacts in series, :attr:`BallBearing.contact_constants`)
    equilibrium  F_a = Σ Q_j sin α_j,   F_r = Σ Q_j cos α_j (cos ψ_j, sin ψ_j),
                 (M_y, M_z) = (D_pw/2) Σ Q_j sin α_j (sin ψ_j, −cos ψ_j)

with A = (f_i + f_o − 1) D_w (the deep-groove ring measured from its centred position, so that either
shoulder can carry a ball) and small rotations (the standard's (D_pw/2) sin ψ with sin ψ = ψ: 2e-6 of the
tilt at 4 mrad).  The moment of a ball's axial force is taken about the pitch radius D_pw/2 (the
standard's moment equation, as the open implementation minzhun/ISO16281 BallBearing.py transcribes it,
"equation 16-18"); the Jones–Harris model rotates the rigid inner ring about its groove-curvature centres at
R_i = D_pw/2 + (f_i − ½) D_w cos α₀ (1.06 % farther out for the 6305-like bearing of the validation), so
under a moment its ball loads are smaller and its L10r longer (+2.4 % for that bearing under 1 N·m,
tests/validation/test_iso16281_moment.py).
The tilt enters the approach about D_pw/2 too: the loads, and L10r, do not depend on that radius for a
load given as forces and moments (only the product radius × tilt appears in the approach); the reported tilt
does: the tilts of the commercial program of the validation (MASTA, examples 5–7 of
tests/validation/test_iso16281*.py) are those about D_pw/2, to 5e-5 (about R_i, which minzhun's transcription
writes in its approach, "equation 12", they come out 1.04 % smaller).  The
radial force balance is solved in both radial directions: under a moment the loads of an odd number of
balls have a resultant along the tilt axis, which a model restricted to the plane of the tilt (minzhun's)
leaves unbalanced (+0.88 % on L10r there).

L10r: :func:`bearingsim.life.row_reference_life` on the loads (inner ring rotating).

Units: SI inside and out (N, N·m, m, rad); L10r in 10⁶ revolutions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import life
from .errors import InputError
from .geometry import BallBearing
from .statics import jones_harris as jh
from .statics import layout as rl


@dataclass
class Iso16281Result:
    """Load distribution of ISO/TS 16281:2008 (module docstring) and the reference rating life on it (SI)."""

    bearing: BallBearing
    loads: jh.Loads
    converged: bool
    residual: float  #: max |residual| [N] (moments divided by D_pw/2)
    displacement: np.ndarray  #: (δx, δy, δz, γy, γz) [m, m, m, rad, rad]
    balls: dict = field(repr=False)  #: azimuth_rad, load_N, contact_angle_rad, approach_m: arrays over the Z balls
    reference_rating_life: float | None  #: L10r [10⁶ rev]; None without a dynamic load rating or convergence

    @property
    def tilt(self) -> float:
        """Total tilt of the inner ring [rad] (about D_pw/2, module docstring)."""
        return float(math.hypot(self.displacement[3], self.displacement[4]))


class _Row:
    """Fixed quantities of the row: groove-centre offsets in the unloaded position, A, R = D_pw/2, K_n, azimuths."""

    def __init__(self, bearing: BallBearing):
        p = bearing.row_vectors()[0]
        self.dx0, self.dr0 = float(p[rl.P_DX0]), float(p[rl.P_DR0])
        self.big_a = bearing.total_curvature_distance
        self.radius = 0.5 * bearing.pitch_diameter
        self.k = float(bearing.contact_constants[2])
        self.psi = 2.0 * math.pi * np.arange(bearing.ball_count) / bearing.ball_count
        c, s = np.cos(self.psi), np.sin(self.psi)
        # (d_r, d_a) = (dr0, dx0) + B q: B is 2 × 5 per ball
        self.b = np.zeros((bearing.ball_count, 2, 5))
        self.b[:, 0, 1], self.b[:, 0, 2] = c, s
        self.b[:, 1, 0] = 1.0
        self.b[:, 1, 3], self.b[:, 1, 4] = self.radius * s, -self.radius * c

    def balls(self, q):
        """(Q, α, approach, ρ, u): ball loads [N], contact angles [rad], approaches [m], centre distances [m] and
        the unit vectors (cos α, sin α) for the displacement q."""
        v = np.array([self.dr0, self.dx0]) + self.b @ q
        rho = np.hypot(v[:, 0], v[:, 1])
        u = v / rho[:, None]
        approach = np.maximum(rho - self.big_a, 0.0)
        return self.k * approach ** 1.5, np.arctan2(v[:, 1], v[:, 0]), approach, rho, u

    def forces(self, q):
        """(G, dG/dq): the generalised force of the balls on the ring, Σ Q_j ∂ρ_j/∂q [N, N·m], and its Jacobian."""
        qb, _, approach, rho, u = self.balls(q)
        n = np.einsum("jk,jkm->jm", u, self.b)  # ∂ρ_j/∂q
        g = qb @ n
        dq = 1.5 * self.k * np.sqrt(approach)
        proj = np.eye(2)[None] - np.einsum("jk,jl->jkl", u, u)
        curv = np.einsum("jkm,jkl,jln->jmn", self.b, proj, self.b) / rho[:, None, None]
        jac = np.einsum("j,jm,jn->mn", dq, n, n) + np.einsum("j,jmn->mn", qb, curv)
        return g, jac


def _check(bearing, loads):
    if not isinstance(bearing, BallBearing):
        raise InputError("bearing", f"ISO/TS 16281 load distribution of one row of balls, got {type(bearing).__name__}",
                         "give one BallBearing; for a bearing set use the reference_rating_life of bearingsim.solve")
    if loads is None:
        loads = jh.Loads()
    if not isinstance(loads, jh.Loads):
        raise InputError("loads", f"expected bearingsim.Loads, got {type(loads).__name__}",
                         'e.g. bearingsim.Loads(fa="1 kN", m_y="1 N*m")')
    return loads


def load_distribution(bearing: BallBearing, loads: jh.Loads | None = None, tol: float = 1e-10,
                      maxit: int = 60) -> Iso16281Result:
    """The ISO/TS 16281:2008 load distribution of ``bearing`` under ``loads`` (forces and moments on the inner
    ring, at rest) and L10r on it (module docstring).  Newton's method on the five ring displacements with the
    analytic Jacobian, started from the Jones–Harris solution at rest (:func:`bearingsim.solve`) and halved
    while a step does not reduce the residual; converged when the largest residual is below ``tol`` of the
    load scale (moments divided by D_pw/2) [N]."""
    loads = _check(bearing, loads)
    row = _Row(bearing)
    la = loads.as_array()
    scale = np.array([1.0, 1.0, 1.0, row.radius, row.radius])
    ref = max(float(np.max(np.abs(la / scale))), 1e-12)

    def res(q):
        g, jac = row.forces(q)
        return (la - g) / scale, jac

    if not np.any(la):
        q, converged, rnorm = np.zeros(5), True, 0.0
    else:
        start = jh.solve(bearing, loads)
        q = np.array(start.displacement, dtype=float)
        # the Jones–Harris tilt is about R_i; the same axial shift of the balls about D_pw/2
        ric = float(bearing.row_vectors()[0, rl.P_RIC])
        q[3:] *= ric / row.radius
        r, jac = res(q)
        rnorm = float(np.max(np.abs(r)))
        converged = rnorm <= tol * ref
        for _ in range(maxit):
            if converged:
                break
            try:
                step = np.linalg.solve(jac, r * scale)
            except np.linalg.LinAlgError:
                step = np.linalg.lstsq(jac, r * scale, rcond=None)[0]
            t = 1.0
            while t > 1e-6:
                trial = q + t * step
                r_t, jac_t = res(trial)
                n_t = float(np.max(np.abs(r_t)))
                if np.isfinite(n_t) and n_t < rnorm:
                    break
                t *= 0.5
            else:
                break
            q, r, jac, rnorm = trial, r_t, jac_t, n_t
            converged = rnorm <= tol * ref
    qb, alpha, approach, _, _ = row.balls(q)
    balls = {"azimuth_rad": row.psi, "load_N": qb, "contact_angle_rad": alpha, "approach_m": approach}
    l10r = None
    c = float(bearing.dynamic_load_rating or 0.0)
    if converged and c > 0:
        l10r = life.row_reference_life(bearing, c, qb, qb)
    return Iso16281Result(bearing, loads, bool(converged), rnorm, q, balls, l10r)


def reference_rating_life(bearing: BallBearing, loads: jh.Loads | None = None) -> float | None:
    """Basic reference rating life L10r [10⁶ revolutions] of ISO/TS 16281:2008 on the standard's own load
    distribution (:func:`load_distribution`); ``None`` without a dynamic load rating or if the equilibrium
    was not found."""
    return load_distribution(bearing, loads).reference_rating_life
