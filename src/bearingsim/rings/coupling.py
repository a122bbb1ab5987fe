"""Jones–Harris quasi-static equilibrium with elastic rings.

Model.  The rigid-ring model of :mod:`bearingsim.statics.jones_harris` places the inner groove-curvature centre
of ball j at (A₁, A₂) from the outer one (row frame ξ, r; :mod:`bearingsim.statics.layout`).  With elastic
rings each groove centre is further displaced by the rings' structural deformation under all ball forces:

    A₁,j ← A₁,j + u_ξ,j(inner) − u_ξ,j(outer),    A₂,j ← A₂,j + u_r,j(inner) − u_r,j(outer),
    u_j(ring) = Σ_k C_ring[j − k] F_k(ring),

with C the ring's influence coefficients (:mod:`.influence`, local Hertz part excluded: the contact model keeps
it) and F_k the force of ball k on that ring in (r, ξ): on the inner ring −(Q_i cos α_i − λ_i G sin α_i,
Q_i sin α_i + λ_i G cos α_i), on the outer ring (Q_o cos α_o − λ_o G sin α_o, Q_o sin α_o + λ_o G cos α_o)
(the contact forces of the ball balance, [S0] eq. 10).  Each row has its own two rings (a set of separate
bearings), except in a double-row unit (:func:`.shared.is_unit`: the file gives the unit's outer ring in
``[rings.outer_ring]``, or the rows' bearings have no boundary dimensions, as the [S1] hub): there one outer ring
carries the grooves of all rows (:mod:`.shared`), so u_j(outer) sums the forces of the balls of *every* row
(the offset map P_o is full, not block-diagonal), and each row keeps its own inner ring.

Solution.  Iteration on the offsets: solve the ball and ring equilibrium of the rigid-ring kernel with the
current per-ball offsets (every ball is passed to the unchanged kernel as a one-ball row at its own azimuth,
so the kernel needs no change), recompute the offsets from the ball forces T(off), and update the offsets by
Newton's method on T(off) − off (Jacobian from :func:`linearisation` at the rigid-ring start, kept for the
later steps: a chord method, linear convergence with a small factor; it includes the shift of the equilibrium
q with the offsets), until the largest change of an offset is below ``tol`` [m] (3–6 iterations).  The result
is called converged only when the last kernel solve is a verified equilibrium
(:func:`bearingsim.statics.jones_harris._attempt`) *and* the offsets are consistent with its ball forces to
``tol``; otherwise status and both residuals are reported.

Stiffness.  The 5×5 stiffness K = dF/dq with the ring deformation following the ball forces (the rings are
part of the bearing's compliance), from the linearisation of :func:`linearisation` (agrees with central
differences of :func:`forces_at` to ~1e-8).

Units: SI (m, N, rad).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..statics import jones_harris as jh
from ..statics import layout as kn
from .influence import InfluenceSettings, RingInfluence, compute_influence
from .section import estimate_sections
from .spec import RING_MODELS  # ("rigid", "fe")


@dataclass
class ElasticRings:
    """The influence coefficients of every row's rings: ``rows[r] = (inner, outer)`` :class:`RingInfluence`;
    with ``shared`` (a :class:`.shared.SharedInfluence`: the one outer ring of a double-row unit) the rows'
    outer entries are None and the outer ring couples the rows."""

    rows: list
    description: dict = field(default_factory=dict)
    _matrices: list = field(default=None, repr=False)
    shared: object = None

    def matrices(self) -> list:
        """Per row (M_inner, M_outer), float[2Z, 2Z] [m/N] (:meth:`RingInfluence.matrix`; M_outer None for a
        shared outer ring)."""
        if self._matrices is None:
            self._matrices = [(i.matrix(), None if o is None else o.matrix()) for i, o in self.rows]
        return self._matrices

    def scaled(self, factor: float) -> "ElasticRings":
        """The same rings with every compliance multiplied by ``factor`` (e.g. 1e-6 for a material 10⁶ stiffer)."""
        rows = [tuple(None if r is None else
                      RingInfluence(r.kind, r.ball_count, r.coeffs * factor, r.local * factor, r.harmonics,
                                    r.seconds, r.key, dict(r.meta)) for r in pair) for pair in self.rows]
        shared = None if self.shared is None else self.shared.scaled(factor)
        return ElasticRings(rows, {**self.description, "compliance_factor": factor}, shared=shared)


def ring_model(bearing, youngs_modulus: float | None = None, poisson_ratio: float | None = None,
               settings: InfluenceSettings | None = None, shoulder_fraction: float = 0.25,
               shaft_bore_fraction: float | None = 0.5, housing_od_factor: float | None = 1.5,
               cache: bool = True, housing="file", shaft="file") -> ElasticRings:
    """Influence coefficients of the rings of every row of ``bearing`` (ring material of each row's bearing unless
    ``youngs_modulus`` [Pa] / ``poisson_ratio`` are given; sections from :func:`.section.estimate_sections` with
    the given seat sleeves; coefficients from the disk cache when present).

    Seats: ``housing`` / ``shaft`` are a :class:`.spec.Sleeve`, None (the sleeve from ``housing_od_factor`` /
    ``shaft_bore_fraction``; None there: a rigid seat) or ``"file"`` (default): the sleeve of the bearing file's
    ``[rings]`` table (:func:`.spec.spec_of`) when it gives one, else the fraction."""
    from .spec import spec_of

    spec = spec_of(bearing)
    if housing == "file":
        housing = spec.housing if spec is not None else None
    if shaft == "file":
        shaft = spec.shaft if spec is not None else None
    rows = []
    desc = {"model": "fe", "shoulder_fraction": shoulder_fraction, "shaft_bore_fraction": shaft_bore_fraction,
            "housing_od_factor": housing_od_factor, "rows": []}
    if housing is not None or shaft is not None:
        desc["housing"] = None if housing is None else _sleeve_desc(housing)
        desc["shaft"] = None if shaft is None else _sleeve_desc(shaft)
    if shaft is not None and not shaft.rigid and shaft.diameter == 0.0:
        from .spec import SOLID_SHAFT_BORE_FRACTION

        # an approximation of the model, stated with every result that uses it (solve adds it to the warnings)
        desc["warnings"] = [
            f"solid shaft modelled as a rigid core of {SOLID_SHAFT_BORE_FRACTION:g} of the bore: the inner ring's "
            "compliance depends at first order on that choice (docs/rings.md §7); give the shaft's bore "
            "(inner_diameter) or rigid = true for a defined seat"]
    from .shared import is_unit

    if is_unit(bearing, spec):
        return _unit_model(bearing, spec, youngs_modulus, poisson_ratio, settings, shoulder_fraction,
                           shaft_bore_fraction, housing_od_factor, cache, housing, shaft, desc)
    for row in bearing.rows:
        b = row.bearing
        e = float(youngs_modulus) if youngs_modulus is not None else b.ring_material.youngs_modulus
        nu = float(poisson_ratio) if poisson_ratio is not None else b.ring_material.poisson_ratio
        inner, outer = estimate_sections(b, shoulder_fraction, shaft_bore_fraction, housing_od_factor,
                                         housing=housing, shaft=shaft)
        ci = compute_influence(inner, e, nu, b.ball_count, settings, cache)
        co = compute_influence(outer, e, nu, b.ball_count, settings, cache)
        rows.append((ci, co))
        desc["rows"].append({"bearing": b.name, "youngs_modulus_Pa": e, "poisson_ratio": nu,
                             "inner_key": ci.key, "outer_key": co.key,
                             "seconds": ci.seconds + co.seconds, "cached": bool(ci.meta.get("cached")
                                                                                and co.meta.get("cached"))})
    return ElasticRings(rows, desc)


def _unit_model(bearing, spec, youngs_modulus, poisson_ratio, settings, shoulder_fraction, shaft_bore_fraction,
                housing_od_factor, cache, housing, shaft, desc) -> ElasticRings:
    """:func:`ring_model` of a double-row unit: one outer ring shared by the rows (:mod:`.shared`), separate inner
    rings (one per row)."""
    from .shared import compute_shared_influence, estimate_unit

    inners, outer, notes = estimate_unit(bearing, spec, shoulder_fraction, shaft_bore_fraction, housing_od_factor,
                                         housing, shaft)
    mats = [r.bearing.ring_material for r in bearing.rows]
    e = float(youngs_modulus) if youngs_modulus is not None else mats[0].youngs_modulus
    nu = float(poisson_ratio) if poisson_ratio is not None else mats[0].poisson_ratio
    if youngs_modulus is None and any(m.youngs_modulus != e or m.poisson_ratio != nu for m in mats):
        raise InputError("ring_material", "the rows of a unit with one outer ring have different ring materials",
                         "give the rows the same ring material, or youngs_modulus/poisson_ratio")
    sh = compute_shared_influence(outer, e, nu, settings, cache)
    rows = []
    for row, inner in zip(bearing.rows, inners):
        ci = compute_influence(inner, e, nu, row.bearing.ball_count, settings, cache)
        rows.append((ci, None))
        desc["rows"].append({"bearing": row.bearing.name, "youngs_modulus_Pa": e, "poisson_ratio": nu,
                             "inner_key": ci.key, "outer_key": sh.key, "seconds": ci.seconds,
                             "cached": bool(ci.meta.get("cached"))})
    desc["shared_outer_ring"] = {"grooves": len(outer.grooves), "key": sh.key, "seconds": sh.seconds,
                                 "cached": bool(sh.meta.get("cached")), "dofs": sh.meta.get("dofs")} | notes
    return ElasticRings(rows, desc, shared=sh)


def _sleeve_desc(s) -> dict:
    return {"rigid": bool(s.rigid), "diameter_m": float(s.diameter), "youngs_modulus_Pa": s.youngs_modulus,
            "poisson_ratio": s.poisson_ratio, "material": s.material}


def expand_rows(rows0: np.ndarray, offsets: np.ndarray) -> np.ndarray:
    """One kernel row per ball (P_Z = 1 at the ball's azimuth ψ₀ + 2πj/Z) with the per-ball groove-centre offsets
    ``offsets[b] = (ΔA₁, ΔA₂)`` [m] added to P_AXOFF and P_DR0."""
    zs = rows0[:, kn.P_Z].astype(int)
    out = np.repeat(rows0, zs, axis=0)
    j = np.concatenate([np.arange(z) for z in zs]) if len(zs) else np.zeros(0)
    zrep = np.repeat(zs, zs).astype(float)
    out[:, kn.P_PSI0] = out[:, kn.P_PSI0] + 2.0 * math.pi * j / zrep
    out[:, kn.P_Z] = 1.0
    out[:, kn.P_AXOFF] += offsets[:, 0]
    out[:, kn.P_DR0] += offsets[:, 1]
    return out


def ring_forces(ballout: np.ndarray, lam: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per ball (expanded rows), the forces (F_r, F_ξ) [N] of the ball on the inner and on the outer ring
    (control weights λ_i, λ_o = (1, 1) for inner control, (0, 2) for outer: Harris, as in the kernel)."""
    bo = ballout[:, 0, :]
    inner = lam[:, 0] == 1
    li = np.where(inner, 1.0, 0.0)
    lo = np.where(inner, 1.0, 2.0)
    qi, qo, g, si, ci, so, co = (bo[:, k] for k in (2, 3, 6, 8, 9, 10, 11))
    fi = -np.column_stack([qi * ci - li * g * si, qi * si + li * g * ci])
    fo = np.column_stack([qo * co - lo * g * so, qo * so + lo * g * co])
    return fi, fo


def offset_maps(rows0: np.ndarray, rings: ElasticRings) -> tuple[np.ndarray, np.ndarray]:
    """Matrices (P_i, P_o), float[2n, 2n] over all balls (ball-major): offsets (ΔA₁, ΔA₂) = P_i F_i − P_o F_o
    with F = (F_r, F_ξ) per ball [m/N] (the ring matrices with each ball's output components swapped)."""
    zs = rows0[:, kn.P_Z].astype(int)
    cache = rings.__dict__.setdefault("_maps_cache", {})
    if tuple(zs) in cache:
        return cache[tuple(zs)]
    nb = int(zs.sum())
    pi = np.zeros((2 * nb, 2 * nb))
    po = np.zeros((2 * nb, 2 * nb))
    b = 0
    for r, (mi, mo) in enumerate(rings.matrices()):
        z = int(zs[r])
        perm = np.arange(2 * z).reshape(z, 2)[:, ::-1].ravel()  # output (r, ξ) → (ξ, r)
        pi[2 * b:2 * (b + z), 2 * b:2 * (b + z)] = mi[perm]
        if mo is not None:
            po[2 * b:2 * (b + z), 2 * b:2 * (b + z)] = mo[perm]
        b += z
    if rings.shared is not None:  # one outer ring for all rows: every ball's offset from every row's forces
        az = [rows0[r, kn.P_PSI0] + 2.0 * math.pi * np.arange(int(zs[r])) / int(zs[r]) for r in range(len(zs))]
        perm = np.arange(2 * nb).reshape(nb, 2)[:, ::-1].ravel()
        po = rings.shared.matrix(az)[perm]
    cache[tuple(zs)] = (pi, po)
    return pi, po


def offsets_from_forces(rows0: np.ndarray, rings: ElasticRings, fi: np.ndarray, fo: np.ndarray,
                        maps=None) -> np.ndarray:
    """Groove-centre offsets (ΔA₁, ΔA₂) [m] per ball from the ball forces on the rings (module docstring)."""
    pi, po = maps if maps is not None else offset_maps(rows0, rings)
    return (pi @ fi.ravel() - po @ fo.ravel()).reshape(-1, 2)


def _check_rings(bearing, rings, rows0=None) -> None:
    if not isinstance(rings, ElasticRings):
        raise InputError("rings", f"expected ElasticRings (bearingsim.rings.coupling.ring_model), got "
                         f"{type(rings).__name__}", "build them with ring_model(bearing)")
    rows0 = bearing.row_vectors() if rows0 is None else rows0
    if len(rings.rows) != rows0.shape[0] or any(int(rows0[r, kn.P_Z]) != pair[0].ball_count
                                                for r, pair in enumerate(rings.rows)):
        raise InputError("rings", "the ring coefficients do not match the bearing's rows and ball counts",
                         "compute them for this bearing with ring_model(bearing)")


def _assemble(rows_e, qv, omega, control):
    """At fixed q for the one-ball rows ``rows_e``: ball forces on the rings (F_i, F_o) [N], the load each ball
    carries (generalized, float[n, 5], :func:`bearingsim.statics.jones_harris._row_loads`) and the ring forces."""
    nb = rows_e.shape[0]
    ballout = np.zeros((nb, 1, 12))
    res, kmat, lam = jh.assemble_at(rows_e, qv, omega, control, ballout)
    carried = np.zeros((nb, 5))
    jh._row_loads(rows_e, qv, ballout, lam, carried)
    fi, fo = ring_forces(ballout, lam)
    return fi, fo, carried, res, kmat


def _groove_gradients(rows_e, qv) -> np.ndarray:
    """Per one-ball row: d(A₁, A₂)/dq, float[n, 2, 5] (the small-rotation gradients of
    :func:`bearingsim.statics.layout` row frame, the kernel's small-rotation gradients, vectorised)."""
    psi = rows_e[:, kn.P_PSI0]
    cp, sp = np.cos(psi), np.sin(psi)
    s = rows_e[:, kn.P_SIGN]
    ric = rows_e[:, kn.P_RIC]
    # inner groove-centre axial position x_row + s (ξ_ic + e) (bearingsim.statics.layout.inner_groove_centre_axial)
    xg = rows_e[:, kn.P_XROW] + s * (rows_e[:, kn.P_XIC] + rows_e[:, kn.P_AXOFF])
    out = np.zeros((rows_e.shape[0], 2, 5))
    out[:, 0, 0] = s
    out[:, 0, 3] = s * ric * sp
    out[:, 0, 4] = -s * ric * cp
    out[:, 1, 1] = cp
    out[:, 1, 2] = sp
    out[:, 1, 3] = -xg * sp
    out[:, 1, 4] = xg * cp
    return out


def linearisation(bearing, q, speed: float, control: str, rings: ElasticRings, offsets, step: float = 1e-10,
                  rows0=None):
    """Derivatives at a solution with elastic rings → dict with ``stiffness`` (K = dF_carried/dq with the ring
    deformation following the loads), ``jacobian_offsets`` (∂T/∂off of the offset map T at fixed q, whose
    spectral radius is the contraction factor of a fixed point at fixed q) and ``forces`` (the carried load).

    K = K_A + Σ_j (∂G_j/∂A_j) (d off_j/dq),  d off/dq = (I − ∂T/∂off)⁻¹ ∂T/∂q,
    where K_A is the kernel's analytic stiffness at fixed offsets, G_j the load ball j carries and A_j its
    groove-centre separation (the offsets add to A_j).  Each ball depends on its own A_j only, so central
    differences perturbing A₁ (then A₂) of all balls at once (step ``step`` [m]) give every per-ball
    derivative from four kernel evaluations."""
    rows0 = bearing.row_vectors() if rows0 is None else rows0
    off = np.asarray(offsets, dtype=float)
    nb = off.shape[0]
    qv = np.asarray(q, dtype=float)
    omega = abs(float(speed))
    rows_e = expand_rows(rows0, off)
    _, _, carried, _, k_a = _assemble(rows_e, qv, omega, control)
    dfi = np.zeros((nb, 2, 2))  # [ball, (r, ξ), (A1, A2)]
    dfo = np.zeros((nb, 2, 2))
    dg = np.zeros((nb, 5, 2))
    for a in range(2):
        dp = np.zeros((nb, 2))
        dp[:, a] = step
        fip, fop, gp, _, _ = _assemble(expand_rows(rows0, off + dp), qv, omega, control)
        fim, fom, gm, _, _ = _assemble(expand_rows(rows0, off - dp), qv, omega, control)
        dfi[:, :, a] = (fip - fim) / (2 * step)
        dfo[:, :, a] = (fop - fom) / (2 * step)
        dg[:, :, a] = (gp - gm) / (2 * step)
    pi, po = offset_maps(rows0, rings)
    bdi = np.zeros((2 * nb, 2 * nb))
    bdo = np.zeros((2 * nb, 2 * nb))
    for j in range(nb):
        bdi[2 * j:2 * j + 2, 2 * j:2 * j + 2] = dfi[j]
        bdo[2 * j:2 * j + 2, 2 * j:2 * j + 2] = dfo[j]
    t_off = pi @ bdi - po @ bdo
    ta = _groove_gradients(rows_e, qv)  # [ball, (A1, A2), q]
    # the axial offset sits in P_AXOFF, which also moves the tilt arm of A₂: ∂A/∂off = [[1, 0], [c, 1]] with
    # c = s (−sin ψ γ_y + cos ψ γ_z); ∂F/∂A = ∂F/∂off (∂A/∂off)⁻¹ for the q-path
    psi = rows_e[:, kn.P_PSI0]
    c = rows_e[:, kn.P_SIGN] * (-np.sin(psi) * qv[3] + np.cos(psi) * qv[4])
    inv = np.zeros((nb, 2, 2))
    inv[:, 0, 0] = 1.0
    inv[:, 1, 1] = 1.0
    inv[:, 1, 0] = -c
    t_q = pi @ np.matmul(np.matmul(dfi, inv), ta).reshape(2 * nb, 5) \
        - po @ np.matmul(np.matmul(dfo, inv), ta).reshape(2 * nb, 5)
    doff_dq = np.linalg.solve(np.eye(2 * nb) - t_off, t_q).reshape(nb, 2, 5)
    k = k_a + np.matmul(dg, doff_dq).sum(axis=0)
    return {"stiffness": k, "jacobian_offsets": t_off, "jacobian_q": t_q, "load_offsets": dg, "stiffness_fixed": k_a,
            "forces": carried.sum(axis=0)}


def stiffness(bearing, q, speed: float, control: str, rings: ElasticRings, offsets, rows0=None) -> np.ndarray:
    """K [N/m, N/rad, N·m/m, N·m/rad] with the ring deformation following the loads (:func:`linearisation`)."""
    return linearisation(bearing, q, speed, control, rings, offsets, rows0=rows0)["stiffness"]


def forces_at(bearing, q, speed: float, control: str, rings: ElasticRings, offsets=None, tol: float = 1e-12,
              maxit: int = 30):
    """Load carried by the bearing float[5] [N, N·m] at the prescribed inner-ring displacement q with the offsets
    solved to ``tol`` [m] at that q → (load, offsets, iterations, last change [m]); NaN load when no consistent
    ring state was found.  Newton's method on g(off) = T(off) − off with ∂T/∂off of :func:`linearisation`
    (a plain fixed point at fixed q contracts only while ring compliance × contact stiffness < 1)."""
    rows0 = bearing.row_vectors()
    nb = int(rows0[:, kn.P_Z].sum())
    off = np.zeros((nb, 2)) if offsets is None else np.array(offsets, dtype=float)
    qv = np.asarray(q, dtype=float)
    maps = offset_maps(rows0, rings)
    change = math.inf
    carried = np.zeros((nb, 5))
    it = 0
    for it in range(1, maxit + 1):
        fi, fo, carried, _, _ = _assemble(expand_rows(rows0, off), qv, abs(float(speed)), control)
        g = offsets_from_forces(rows0, rings, fi, fo, maps) - off
        change = float(np.max(np.abs(g))) if nb else 0.0
        if change <= tol or not np.isfinite(change):
            break
        jac = linearisation(bearing, qv, speed, control, rings, off)["jacobian_offsets"]
        off = off + np.linalg.solve(np.eye(2 * nb) - jac, g.ravel()).reshape(nb, 2)
    load = carried.sum(axis=0) if change <= tol else np.full(5, np.nan)
    return load, off, it, change


def _newton_matrix(bearing, q, speed, control, rings, off, rows0):
    """I − J of the load-controlled fixed point off = T(q(off), off), J = ∂T/∂off − ∂T/∂q K_A⁻¹ D (D the
    per-ball ∂G_j/∂A_j: a change of offsets moves the equilibrium q by −K_A⁻¹ D Δoff), from
    :func:`linearisation`; None when K_A is singular."""
    lin = linearisation(bearing, q, speed, control, rings, off, rows0=rows0)
    nb = off.shape[0]
    d = np.transpose(lin["load_offsets"], (1, 0, 2)).reshape(5, 2 * nb)
    try:
        dq = -np.linalg.solve(lin["stiffness_fixed"], d)
    except np.linalg.LinAlgError:
        return None
    m = np.eye(2 * nb) - (lin["jacobian_offsets"] + lin["jacobian_q"] @ dq)
    return m if np.all(np.isfinite(m)) else None


def _newton_update(matrix, off, new):
    """off + (I − J)⁻¹ (T(off) − off); the plain fixed-point step ``new`` without a usable matrix."""
    if matrix is None:
        return new
    try:
        step = np.linalg.solve(matrix, (new - off).ravel())
    except np.linalg.LinAlgError:
        return new
    return off + step.reshape(off.shape) if np.all(np.isfinite(step)) else new


def solve(bearing, loads: "jh.Loads | None" = None, speed: float = 0.0, control: str = "outer",
          rings: "ElasticRings | str | None" = "fe", initial=None, tol: float = 1e-12, maxit: int = 50,
          initial_offsets=None):
    """Quasi-static equilibrium of ``bearing`` with elastic rings (module docstring).

    Parameters
    ----------
    bearing : BallBearing or BearingSystem
        The bearing (single rows, sets and double-row units with a shared outer ring).
    loads : Loads or None
        Loads on the inner ring at the load point [N, N·m]; None: no load.
    speed : float
        Inner-ring speed [rad/s].
    control : str
        Raceway control, ``"outer"``, ``"inner"`` or ``"auto"`` (as :func:`bearingsim.solve`).
    rings : str or ElasticRings
        ``"rigid"`` (the rigid-ring :func:`bearingsim.statics.jones_harris.solve`, unchanged), ``"fe"``
        (coefficients from :func:`ring_model` with its defaults, cached on disk) or an :class:`ElasticRings`.
    initial : float[5] or None
        Start of the ring displacement (δx, δy, δz, γy, γz) [m, rad]; None: the Jones–Harris initial guess.
    tol : float
        Largest change of a groove-centre offset accepted as the fixed point [m].
    maxit : int
        Cap on the fixed-point iterations between the ring offsets and the Jones–Harris solve.
    initial_offsets : float[n_balls, 2] or None
        Start of the offsets [m] (e.g. a neighbouring point's; default zero).

    Returns
    -------
    StaticResult
        A :class:`bearingsim.statics.jones_harris.StaticResult` with, in addition, ``ring_model``
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
    rows0 = bearing.row_vectors()
    _check_rings(bearing, rings, rows0)
    if loads is None:
        loads = jh.Loads()
    elif not isinstance(loads, jh.Loads):
        raise InputError("loads", f"expected a Loads, got {type(loads).__name__}", "e.g. Loads(fa=1000.0)")
    jh._check_control(control)
    speed = jh._number(speed, "speed")
    if not (tol > 0 and math.isfinite(tol)):
        raise InputError("tol", f"must be a positive length, got {tol!r}", "e.g. 1e-12 m")
    nb = int(rows0[:, kn.P_Z].sum())
    la = loads.as_array()
    omega = float(abs(speed))
    scale = jh._scale(loads, rows0)
    q = jh._check_initial(initial) if initial is not None else np.array(jh.initial_guess(bearing, loads), dtype=float)
    # the rigid-ring equilibrium (the zero-compliance limit) is the start; jh.solve's other starts if needed
    st0 = jh._attempt(rows0, la, omega, control, q, scale)
    if st0[0] != 0:
        r0 = jh.solve(bearing, loads, speed, control, initial)
        if r0.converged:
            st0 = jh._attempt(rows0, la, omega, control, r0.displacement, scale)
    q = st0[1].copy()
    maps = offset_maps(rows0, rings)
    off = np.zeros((nb, 2))
    if initial_offsets is not None:
        o = np.asarray(initial_offsets, dtype=float)
        if o.shape != (nb, 2) or not np.all(np.isfinite(o)):
            raise InputError("initial_offsets", f"expected finite float[{nb}, 2] offsets [m], got shape {o.shape}",
                             "pass ring_offsets of a result of this bearing, or None")
        off = o.copy()
    change = math.inf
    its_total = st0[2]
    it = 0
    state = st0
    newton = None
    if st0[0] == 0:
        # fixed point: kernel solves (warm q) with the current offsets until the offsets stop changing; the
        # last one is then re-done with the independent check of jh._attempt
        for it in range(1, maxit + 1):
            rows_e = expand_rows(rows0, off)
            status, its, rn, bconv, lam, xb, kmat, ballout = jh._solve_kernel(rows_e, la, omega, control, q, scale)
            its_total += its
            if status != 0 or not bconv:
                break
            new = offsets_from_forces(rows0, rings, *ring_forces(ballout, lam), maps)
            change = float(np.max(np.abs(new - off))) if nb else 0.0
            if change <= tol:
                break  # the offsets used are consistent with this solution's ball forces to tol
            if newton is None:  # the Jacobian of the first iterate is kept (chord method: the offsets are small)
                newton = _newton_matrix(bearing, q, speed, control, rings, off, rows0)
            off = _newton_update(newton, off, new)
        state = jh._attempt(expand_rows(rows0, off), la, omega, control, q, scale)
        its_total += state[2]
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
    kel = stiffness(bearing, q, speed, control, rings, off, rows0) if converged else kmat.copy()
    if converged and not np.all(np.isfinite(kel)):
        converged = False
        text = "stiffness with elastic rings failed: no consistent ring state next to the solution"
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
    res.warnings = list(res.warnings) + list((rings.description or {}).get("warnings", ()))
    return res


def summary_of(res) -> np.ndarray:
    """The map summary of one result (the columns of :data:`bearingsim.statics.batch.SUMMARY_FIELDS`): largest
    inner/outer contact pressure [Pa], extremes of the inner and outer contact angles of the balls loaded at that
    contact [rad] (NaN when none is), balls without inner load while others carry load."""
    b = res.balls
    out = np.full(7, np.nan)
    qi, qo = np.asarray(b["inner_load_N"]), np.asarray(b["outer_load_N"])
    out[0] = float(np.max(b["inner_max_pressure_Pa"], initial=0.0))
    out[1] = float(np.max(b["outer_max_pressure_Pa"], initial=0.0))
    for k, (q, a) in enumerate(((qi, b["inner_contact_angle_rad"]), (qo, b["outer_contact_angle_rad"]))):
        a = np.asarray(a)[q > 0]
        if a.size:
            out[2 + 2 * k], out[3 + 2 * k] = float(a.min()), float(a.max())
    nload = int(np.sum(qi > 0))
    out[6] = float(qi.size - nload) if nload else 0.0
    return out


def solve_points(bearing, loads, speeds, control: str = "outer", rings: "ElasticRings | None" = None,
                 warm: bool = True) -> dict:
    """Many operating points with elastic rings, in the given order (a map block's serpentine order): the dict of
    :func:`bearingsim.statics.batch.run_batch` (q, k, status, iterations, residual, summary, warning_flags;
    converged points have status 0, a point whose offsets did not converge has status 1, a point that raised
    status 7).  Each point starts from the previous converged point's displacement and ring offsets when
    ``warm`` (the offsets change little between neighbours), else from the rigid-ring start.
    loads float[n, 5] [N, N·m], speeds float[n] [rad/s]."""
    from ..limits import flags_from_summary, limiting_speed

    loads = np.asarray(loads, dtype=float).reshape(-1, 5)
    n = loads.shape[0]
    speeds = np.broadcast_to(np.asarray(speeds, dtype=float), (n,))
    rings = ring_model(bearing) if rings is None else rings
    out = {"q": np.zeros((n, 5)), "k": np.zeros((n, 5, 5)), "status": np.zeros(n, dtype=np.int64),
           "iterations": np.zeros(n, dtype=np.int64), "residual": np.zeros(n), "summary": np.zeros((n, 7))}
    q0 = off0 = None
    for i in range(n):
        try:
            res = solve(bearing, jh.Loads(*loads[i]), float(speeds[i]), control, rings=rings,
                        initial=q0 if warm else None, initial_offsets=off0 if warm else None)
        except InputError:
            raise
        except Exception:  # noqa: BLE001  (isolate the point; the others keep their results)
            out["status"][i] = 7
            for key in ("q", "k", "residual", "summary"):
                out[key][i] = np.nan
            continue
        code = res.status_code if not (res.status_code == 0 and not res.converged) else 1
        out["status"][i] = code
        out["q"][i] = res.displacement
        out["k"][i] = res.stiffness
        out["iterations"][i] = res.iterations
        out["residual"][i] = res.residual
        out["summary"][i] = summary_of(res)
        if res.converged:
            q0, off0 = res.displacement, res.ring_offsets
    conv = out["status"] == 0
    s = out["summary"]
    lift = (s[:, 6] > 0) & (speeds != 0)
    out["warning_flags"] = flags_from_summary(s[:, 0], s[:, 1], [s[:, k] for k in range(2, 6)], speeds, lift, conv,
                                              limiting_speed(bearing))
    out["converged"] = conv
    return out


def result_dict(res) -> dict:
    """``res.to_dict()`` (the ``static --json`` schema) plus ``rings``: the ring model ("rigid" or "fe") and, for
    FE rings, the offset iterations, the last offset change [m], the largest offsets [m] and the model's
    description (sections' assumptions, material, cache keys)."""
    d = res.to_dict()
    model = getattr(res, "ring_model", "rigid")
    info = {"model": model}
    if model == "fe":
        off = res.ring_offsets
        info.update({"iterations": int(res.ring_iterations), "residual_m": float(res.ring_residual),
                     "max_axial_offset_m": float(np.max(np.abs(off[:, 0]))) if len(off) else 0.0,
                     "max_radial_offset_m": float(np.max(np.abs(off[:, 1]))) if len(off) else 0.0,
                     "description": res.ring_description})
    d["rings"] = info
    return d
