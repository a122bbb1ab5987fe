"""Jones–Harris quasi-static equilibrium with elastic rings.

Model.  The rigid-ring model of :mod:`bearingsim.statics.jones_harris` places the inner groove-curvature centre
of ball j at (A₁, A₂) from the outer one (row frame ξ, r; :mod:`bearingsim.statics._kernels`).  With elastic
rings each groove centre is further displaced by the rings' structural deformation under all ball forces:

    A₁,j ← A₁,j + u_ξ,j(inner) − u_ξ,j(outer),    A₂,j ← A₂,j + u_r,j(inner) − u_r,j(outer),
    u_j(ring) = Σ_k C_ring[j − k] F_k(ring),

with C the ring's influence coefficients (:mod:`.influence`, local Hertz part excluded: the contact model keeps
it) and F_k the force of ball k on that ring in (r, ξ): on the inner ring −(Q_i cos α_i − λ_i G sin α_i,
Q_i sin α_i + λ_i G cos α_i), on the outer ring (Q_o cos α_o − λ_o G sin α_o, Q_o sin α_o + λ_o G cos α_o)
(the contact forces of the ball balance, [S0] eq. 10).  Each row has its own two rings (a set of separate
bearings); rings shared by two rows (a hub unit's common outer ring) are not coupled between the rows.

Solution.  A fixed point on the offsets: solve the ball and ring equilibrium of the rigid-ring kernel with the
current per-ball offsets (every ball is passed to the unchanged kernel as a one-ball row at its own azimuth,
so the kernel needs no change), recompute the offsets from the ball forces, repeat until the largest change of
an offset is below ``tol`` [m].  The contraction factor is the ring compliance times the contact stiffness
(≈ 0.01–0.1 for solid rings), so a few iterations suffice.  The result is called converged only when the last
kernel solve is a verified equilibrium (:func:`bearingsim.statics.jones_harris._attempt`) *and* the offsets
are consistent with its ball forces to ``tol``; otherwise status and both residuals are reported.

Stiffness.  The 5×5 stiffness K = −∂F/∂q with the ring deformation following the ball forces (the rings are
part of the bearing's compliance): central differences of the ring forces at prescribed q, each evaluation
iterating the offsets to ``tol`` at fixed q.

Units: SI (m, N, rad).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..statics import _kernels as kn
from ..statics import jones_harris as jh
from .influence import InfluenceSettings, RingInfluence, compute_influence
from .section import estimate_sections

RING_MODELS = ("rigid", "fe")


@dataclass
class ElasticRings:
    """The influence coefficients of every row's rings: ``rows[r] = (inner, outer)`` :class:`RingInfluence`."""

    rows: list
    description: dict = field(default_factory=dict)
    _matrices: list = field(default=None, repr=False)

    def matrices(self) -> list:
        """Per row (M_inner, M_outer), float[2Z, 2Z] [m/N] (:meth:`RingInfluence.matrix`)."""
        if self._matrices is None:
            self._matrices = [(i.matrix(), o.matrix()) for i, o in self.rows]
        return self._matrices

    def scaled(self, factor: float) -> "ElasticRings":
        """The same rings with every compliance multiplied by ``factor`` (e.g. 1e-6 for a material 10⁶ stiffer)."""
        rows = [tuple(RingInfluence(r.kind, r.ball_count, r.coeffs * factor, r.local * factor, r.harmonics,
                                    r.seconds, r.key, dict(r.meta)) for r in pair) for pair in self.rows]
        return ElasticRings(rows, {**self.description, "compliance_factor": factor})


def ring_model(bearing, youngs_modulus: float | None = None, poisson_ratio: float | None = None,
               settings: InfluenceSettings | None = None, shoulder_fraction: float = 0.25,
               shaft_bore_fraction: float | None = 0.5, housing_od_factor: float | None = 1.5,
               cache: bool = True) -> ElasticRings:
    """Influence coefficients of the rings of every row of ``bearing`` (ring material of each row's bearing unless
    ``youngs_modulus`` [Pa] / ``poisson_ratio`` are given; sections from :func:`.section.estimate_sections` with
    the given seat sleeves; coefficients from the disk cache when present)."""
    rows = []
    desc = {"model": "fe", "shoulder_fraction": shoulder_fraction, "shaft_bore_fraction": shaft_bore_fraction,
            "housing_od_factor": housing_od_factor, "rows": []}
    for row in bearing.rows:
        b = row.bearing
        e = float(youngs_modulus) if youngs_modulus is not None else b.ring_material.youngs_modulus
        nu = float(poisson_ratio) if poisson_ratio is not None else b.ring_material.poisson_ratio
        inner, outer = estimate_sections(b, shoulder_fraction, shaft_bore_fraction, housing_od_factor)
        ci = compute_influence(inner, e, nu, b.ball_count, settings, cache)
        co = compute_influence(outer, e, nu, b.ball_count, settings, cache)
        rows.append((ci, co))
        desc["rows"].append({"bearing": b.name, "youngs_modulus_Pa": e, "poisson_ratio": nu,
                             "inner_key": ci.key, "outer_key": co.key,
                             "seconds": ci.seconds + co.seconds, "cached": bool(ci.meta.get("cached")
                                                                                and co.meta.get("cached"))})
    return ElasticRings(rows, desc)


def expand_rows(rows0: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """One kernel row per ball (P_Z = 1 at the ball's azimuth) with the per-ball groove-centre offsets
    ``offsets[b] = (ΔA₁, ΔA₂)`` [m] added to P_AXOFF and P_DR0."""
    out = []
    b = 0
    for par in rows0:
        z = int(par[kn.P_Z])
        for j in range(z):
            p = par.copy()
            p[kn.P_Z] = 1.0
            p[kn.P_PSI0] = par[kn.P_PSI0] + 2.0 * math.pi * j / z
            p[kn.P_AXOFF] = par[kn.P_AXOFF] + offsets[b, 0]
            p[kn.P_DR0] = par[kn.P_DR0] + offsets[b, 1]
            out.append(p)
            b += 1
    return np.array(out)


def ring_forces(ballout: np.ndarray, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per ball (expanded rows), the forces (F_r, F_ξ) [N] of the ball on the inner and on the outer ring."""
    n = ballout.shape[0]
    fi = np.zeros((n, 2))
    fo = np.zeros((n, 2))
    for e in range(n):
        bo = ballout[e, 0]
        li, lo = kn.control_weights(lam[e, 0])
        qi, qo, g, si, ci, so, co = bo[2], bo[3], bo[6], bo[8], bo[9], bo[10], bo[11]
        fi[e] = (-(qi * ci - li * g * si), -(qi * si + li * g * ci))
        fo[e] = (qo * co - lo * g * so, qo * so + lo * g * co)
    return fi, fo


def offsets_from_forces(rows0: np.ndarray, rings: ElasticRings, fi: np.ndarray, fo: np.ndarray) -> np.ndarray:
    """Groove-centre offsets (ΔA₁, ΔA₂) [m] per ball from the ring forces (module docstring)."""
    out = np.zeros((fi.shape[0], 2))
    b = 0
    for r, (mi, mo) in enumerate(rings.matrices()):
        z = int(rows0[r, kn.P_Z])
        ui = (mi @ fi[b:b + z].ravel()).reshape(z, 2)  # (u_r, u_ξ) of the inner groove centre
        uo = (mo @ fo[b:b + z].ravel()).reshape(z, 2)
        out[b:b + z, 0] = ui[:, 1] - uo[:, 1]
        out[b:b + z, 1] = ui[:, 0] - uo[:, 0]
        b += z
    return out


def _check_rings(bearing, rings) -> None:
    if not isinstance(rings, ElasticRings):
        raise InputError("rings", f"expected ElasticRings (bearingsim.rings.coupling.ring_model), got "
                         f"{type(rings).__name__}", "build them with ring_model(bearing)")
    rows0 = bearing.row_vectors()
    if len(rings.rows) != rows0.shape[0] or any(int(rows0[r, kn.P_Z]) != pair[0].ball_count
                                                for r, pair in enumerate(rings.rows)):
        raise InputError("rings", "the ring coefficients do not match the bearing's rows and ball counts",
                         "compute them for this bearing with ring_model(bearing)")


def forces_at(bearing, q, speed: float, control: str, rings: ElasticRings, offsets=None, tol: float = 1e-12,
              maxit: int = 50):
    """Ring forces (−carried load) float[5] at the prescribed inner-ring displacement q, the offsets iterated to
    ``tol`` at that q → (forces, offsets, iterations, last change [m])."""
    rows0 = bearing.row_vectors()
    nb = int(rows0[:, kn.P_Z].sum())
    off = np.zeros((nb, 2)) if offsets is None else np.array(offsets, dtype=float)
    qv = np.asarray(q, dtype=float)
    res = np.zeros(5)
    change = math.inf
    for it in range(1, maxit + 1):
        rows_e = expand_rows(rows0, off)
        lam = np.full((nb, 1), 1 if control == "inner" else 0, dtype=np.int64)
        xb = np.zeros((nb, 1, 2))
        kmat = np.zeros((5, 5))
        ballout = np.zeros((nb, 1, 12))
        kn.ring_assemble(rows_e, qv, abs(float(speed)), jh.CONTROLS[control], lam, xb, np.zeros(5), res, kmat,
                         ballout, jh.TOL_BALL, jh.MAXIT_BALL)
        new = offsets_from_forces(rows0, rings, *ring_forces(ballout, lam))
        change = float(np.max(np.abs(new - off))) if nb else 0.0
        off = new
        if change <= tol:
            break
    return res.copy(), off, it, change


def stiffness(bearing, q, speed: float, control: str, rings: ElasticRings, offsets, tol: float = 1e-13,
              step: float = 1e-9) -> np.ndarray:
    """K = −∂F/∂q [N/m, N/rad, N·m/m, N·m/rad] with the ring deformation following the loads: central
    differences of :func:`forces_at` (step ``step`` [m] for translations, step/(d_m/2) for tilts)."""
    dm = float(bearing.row_vectors()[0, kn.P_DM])
    k = np.zeros((5, 5))
    for c in range(5):
        h = step if c < 3 else step / (0.5 * dm)
        qp = np.array(q, dtype=float)
        qm = qp.copy()
        qp[c] += h
        qm[c] -= h
        fp = forces_at(bearing, qp, speed, control, rings, offsets, tol)[0]
        fm = forces_at(bearing, qm, speed, control, rings, offsets, tol)[0]
        k[:, c] = -(fp - fm) / (2.0 * h)
    return k


def solve(bearing, loads: "jh.Loads | None" = None, speed: float = 0.0, control: str = "outer",
          rings: "ElasticRings | str | None" = "fe", initial=None, tol: float = 1e-12, maxit: int = 50):
    """Quasi-static equilibrium of ``bearing`` with elastic rings (module docstring).

    rings : ``"rigid"`` (the rigid-ring :func:`bearingsim.statics.jones_harris.solve`, unchanged), ``"fe"``
        (coefficients from :func:`ring_model` with its defaults, cached on disk) or an :class:`ElasticRings`
    tol : largest change of a groove-centre offset accepted as the fixed point [m]

    Returns a :class:`bearingsim.statics.jones_harris.StaticResult` with, in addition, ``ring_model``
    ("rigid" or "fe"), ``ring_offsets`` float[n_balls, 2] (ΔA₁, ΔA₂) [m], ``ring_iterations`` and
    ``ring_residual`` (the last offset change [m]); ``stiffness`` includes the rings' compliance.
    """
    if isinstance(rings, str):
        if rings not in RING_MODELS:
            raise InputError("rings", f"unknown ring model {rings!r}", "use rigid or fe")
        if rings == "rigid":
            res = jh.solve(bearing, loads, speed, control, initial)
            res.ring_model, res.ring_offsets, res.ring_iterations, res.ring_residual = "rigid", None, 0, 0.0
            return res
        rings = ring_model(bearing)
    jh._check_bearing(bearing)
    _check_rings(bearing, rings)
    if loads is None:
        loads = jh.Loads()
    elif not isinstance(loads, jh.Loads):
        raise InputError("loads", f"expected a Loads, got {type(loads).__name__}", "e.g. Loads(fa=1000.0)")
    jh._check_control(control)
    speed = jh._number(speed, "speed")
    if not (tol > 0 and math.isfinite(tol)):
        raise InputError("tol", f"must be a positive length, got {tol!r}", "e.g. 1e-12 m")
    rows0 = bearing.row_vectors()
    nb = int(rows0[:, kn.P_Z].sum())
    la = loads.as_array()
    omega = float(abs(speed))
    scale = jh._scale(loads, rows0)
    if initial is not None:
        q = jh._check_initial(initial)
    else:  # the rigid-ring equilibrium is the natural start (it is the zero-compliance limit)
        r0 = jh.solve(bearing, loads, speed, control)
        q = r0.displacement.copy() if r0.converged else np.array(jh.initial_guess(bearing, loads), dtype=float)
    off = np.zeros((nb, 2))
    change = math.inf
    state = None
    its_total = 0
    it = 0
    for it in range(1, maxit + 1):
        rows_e = expand_rows(rows0, off)
        state = jh._attempt(rows_e, la, omega, control, q, scale)
        its_total += state[2]
        if state[0] != 0:
            break
        q = state[1]
        new = offsets_from_forces(rows0, rings, *ring_forces(state[7], state[4]))
        change = float(np.max(np.abs(new - off))) if nb else 0.0
        if change <= tol:
            break  # the offsets used are consistent with the solution's ball forces to tol
        off = new
    status, q, its, rn, lam, xb, kmat, ballout = state
    rows_e = expand_rows(rows0, off)
    ring_ok = change <= tol
    if status in (0, 3, 6) and jh._free_ring(ballout, rows_e, scale):
        status = 8
    converged = status == 0 and ring_ok
    if status == 0 and not ring_ok:
        text = f"ring deformation not converged: offset change {change:.3g} m after {it} iterations (tol {tol:.3g})"
    else:
        text = jh.STATUS.get(status, f"status {status}")
    kel = stiffness(bearing, q, speed, control, rings, off, min(tol, 1e-13)) if converged else kmat.copy()
    balls = jh.ball_table(rows_e, ballout, xb, lam, float(speed))
    zs = rows0[:, kn.P_Z].astype(int)
    balls["row"] = np.repeat(np.arange(rows0.shape[0]), zs)
    res = jh.StaticResult(bearing=bearing, loads=loads, speed=float(speed), control=control, converged=converged,
                          status=text, iterations=int(its_total), residual=float(rn), displacement=q.copy(),
                          stiffness=kel, balls=balls, rows_params=rows0, status_code=int(status))
    res.row_forces = np.zeros((rows0.shape[0], 5))
    rf = np.zeros((rows_e.shape[0], 5))
    jh._row_loads(rows_e, q, ballout, lam, rf)
    np.add.at(res.row_forces, np.repeat(np.arange(rows0.shape[0]), zs), rf)
    from ..limits import static_warnings

    res.warnings = static_warnings(res)
    res.ring_model, res.ring_offsets, res.ring_iterations, res.ring_residual = "fe", off, it, change
    res.ring_description = rings.description
    return res


def result_dict(res) -> dict:
    """``res.to_dict()`` plus the ring model: ``rings`` = {model, iterations, residual_m, max_offset_m, ...}."""
    d = res.to_dict() if getattr(res, "ring_model", "rigid") == "rigid" or res.rows is None else res.to_dict()
    model = getattr(res, "ring_model", "rigid")
    info = {"model": model}
    if model == "fe":
        off = res.ring_offsets
        info.update({"iterations": int(res.ring_iterations), "residual_m": float(res.ring_residual),
                     "max_radial_offset_m": float(np.max(np.abs(off[:, 1]))) if len(off) else 0.0,
                     "max_axial_offset_m": float(np.max(np.abs(off[:, 0]))) if len(off) else 0.0,
                     "description": res.ring_description})
    d["rings"] = info
    return d
