"""Static equilibrium of a shaft system: assembly of the beam, supports and loads, Newton with the bearings'
analytic tangents, the verified result, and the linearised stiffness at a node.

Unknowns: the shaft's nodal DOF u (5 per node, order [x, y, z, γy, γz]) and, per support, the five DOF of its
outer ring (housing side) o — held at their prescribed values (rigid housing, position preload) or free where a
housing spring or a spring preload lets them move.  A bearing at node n with orientation transform T
(:attr:`~.model.BearingSupport.transform`) sees the ring displacement q = T (u_n − o) (inner relative to outer,
its own frame) and applies f_s = T f(q) to the shaft and −f_s to its outer ring, f and its stiffness
K_b = −df/dq from :func:`bearingsim.statics.jones_harris.bearing_reaction` (shaft frame: T K_b T).  Equilibrium

    R(u, o) = F_ext − K_beam u + Σ_supports (f_s on n, −f_s on o) − K_h o + F_preload = 0,

solved by Newton's method on the free DOF with the tangent K_t = −dR/d(u, o) (beam + bearing tangents +
springs), a Levenberg–Marquardt shift μ·D where K_t is singular (a bearing inside its clearance; D the
bearings' tangents at their single-bearing starts, :func:`_seed_stiffness`), and a backtracking line search
on the scaled residual.  A result is called converged only when the residual, recomputed with every bearing
re-solved from a cold start at the returned ring positions, is within :data:`TOL_VERIFY` times
the load scale.  Units: SI (module :mod:`.model`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy.sparse import csc_matrix
from scipy.sparse.linalg import splu

from ..beam import shaft_element_matrices
from ..errors import InputError
from ..statics.jones_harris import Loads, bearing_reaction, initial_guess, result_at
from .model import NODE_DOF, BearingSupport, DistributedLoad, Gravity, HelicalGear, PointLoad, ShaftSystem

#: Newton tolerance on the scaled residual (forces [N], moments divided by the reference length), relative to
#: the load scale [-]
TOL = 1e-9
#: the re-check with cold-started bearings (:func:`solve_shaft`) [-]
TOL_VERIFY = 1e-7
MAXIT = 200
#: the largest change of a bearing's ring displacement per Newton step (δx, δy, δz [m], γy, γz [rad]): ball
#: contacts stiffen over microns, so that a full step from inside a clearance would overshoot
CAP = np.array([2e-5, 2e-5, 2e-5, 5e-4, 5e-4])


@dataclass(frozen=True, eq=False)
class LinearModel:
    """The linear parts of a shaft system (free of the bearings): beam stiffness K [N/m …], consistent mass M
    [kg …] including the point masses, gyroscopic matrix per unit spin G1 [kg·m² …] (beam + point polar
    inertias), external load vector F [N, N·m], over the shaft DOF (5 per node) followed by 5 outer-ring DOF
    per support; ``fixed`` bool mask of the DOF held at ``prescribed`` values; ``support_node`` the shaft node
    of each support; ``length_scale`` [m] the length that turns moments into forces in residual norms."""

    system: ShaftSystem
    K: np.ndarray
    M: np.ndarray
    G1: np.ndarray
    F: np.ndarray
    fixed: np.ndarray
    prescribed: np.ndarray
    support_node: tuple
    length_scale: float

    @property
    def n_shaft(self) -> int:
        return self.system.mesh.n_dof

    def node_dofs(self, node: int) -> np.ndarray:
        return 5 * node + np.arange(5)

    def outer_dofs(self, k: int) -> np.ndarray:
        return self.n_shaft + 5 * k + np.arange(5)


def _element_load(L: float, q: np.ndarray) -> np.ndarray:
    """Consistent nodal loads of a uniform load q = (qx, qy, qz) [N/m] on an element of length L [m]
    (Przemieniecki 1968, ch. 5: qL/2 at each end and ±qL²/12 end moments), element DOF order of
    :func:`bearingsim.beam.shaft_element_matrices`."""
    f = np.zeros(10)
    f[[0, 5]] = 0.5 * q[0] * L
    f[[1, 6]] = 0.5 * q[1] * L
    f[4], f[9] = q[1] * L**2 / 12.0, -q[1] * L**2 / 12.0  # γz = dy/dx
    f[[2, 7]] = 0.5 * q[2] * L
    f[3], f[8] = -q[2] * L**2 / 12.0, q[2] * L**2 / 12.0  # γy = −dz/dx
    return f


def linear_model(system: ShaftSystem) -> LinearModel:
    """Assemble the beam matrices (:func:`bearingsim.beam.shaft_element_matrices`), the point masses and the
    external loads of ``system``, and the outer-ring DOF of its supports."""
    mesh = system.mesh
    ns = mesh.n_dof
    nsup = len(system.supports)
    n = ns + 5 * nsup
    K = np.zeros((n, n))
    M = np.zeros((n, n))
    G1 = np.zeros((n, n))
    F = np.zeros(n)
    x = mesh.nodes
    g = next((ld.acceleration for ld in system.loads if isinstance(ld, Gravity)), None)
    dist = [ld for ld in system.loads if isinstance(ld, DistributedLoad)]
    cache = {}
    for e in range(mesh.n_nodes - 1):
        sec = system.sections[mesh.element_section[e]]
        L = float(x[e + 1] - x[e])
        mat = sec.material
        key = (int(mesh.element_section[e]), round(L, 15))
        if key not in cache:  # equal elements of one section share their matrices
            cache[key] = shaft_element_matrices(L, mat.youngs_modulus, sec.shear_modulus, mat.density, sec.area,
                                                sec.second_moment, sec.shear_coefficient, system.shear)
        ke, me, ge = cache[key]
        idx = slice(5 * e, 5 * e + 10)
        K[idx, idx] += ke
        M[idx, idx] += me
        G1[idx, idx] += ge
        mid = 0.5 * (x[e] + x[e + 1])
        if g is not None:
            F[idx] += _element_load(L, mat.density * sec.area * g)
        for ld in dist:
            if ld.start - 1e-12 <= mid <= ld.end + 1e-12:
                F[idx] += _element_load(L, ld.intensity)
    for m in system.masses:
        i = mesh.node_at(m.position)
        d = 5 * i
        M[d, d] += m.mass
        M[d + 1, d + 1] += m.mass
        M[d + 2, d + 2] += m.mass
        M[d + 3, d + 3] += m.diametral_inertia
        M[d + 4, d + 4] += m.diametral_inertia
        G1[d + 3, d + 4] += m.polar_inertia
        G1[d + 4, d + 3] -= m.polar_inertia
        if g is not None:
            F[d:d + 3] += m.mass * g
    for ld in system.loads:
        if isinstance(ld, PointLoad | HelicalGear):
            i = mesh.node_at(ld.position)
            F[5 * i:5 * i + 5] += ld.vector()
    fixed = np.zeros(n, dtype=bool)
    fixed[ns:] = True
    pres = np.zeros(n)
    nodes = []
    for k, s in enumerate(system.supports):
        nodes.append(mesh.node_at(s.position))
        o = ns + 5 * k + np.arange(5)
        if s.housing_stiffness is not None:
            K[np.ix_(o, o)] += s.housing_stiffness
            fixed[o] = np.diag(s.housing_stiffness) <= 0
        if isinstance(s, BearingSupport):
            pres[o[0]] = s.preload_offset
            if s.preload_force is not None:
                fixed[o[0]] = False
                F[o[0]] += s.preload_force
                if s.housing_stiffness is not None:
                    K[o[0], o] = 0.0  # the outer ring slides: no housing spring acts axially
                    K[o, o[0]] = 0.0
    lo, hi = system.span
    return LinearModel(system, 0.5 * (K + K.T), 0.5 * (M + M.T), G1, F, fixed, pres, tuple(nodes),
                       max(0.1 * (hi - lo), 1e-3))


@dataclass
class SupportResult:
    """One support at the solution: ``reaction`` [Fx, Fy, Fz, My, Mz] [N, N·m] the support applies to the shaft
    (shaft frame), ``misalignment`` (γy, γz) [rad] of the shaft relative to the outer ring there (shaft frame),
    ``ring_displacement`` (δx, δy, δz, γy, γz) [m, rad] of the inner ring relative to the outer in the bearing's
    own frame, ``stiffness`` 5×5 the support's tangent in the shaft frame, ``bearing_result`` the bearing's
    :class:`~bearingsim.statics.jones_harris.StaticResult` at that ring displacement (None for a spring)."""

    name: str
    position: float
    reaction: np.ndarray
    misalignment: np.ndarray
    ring_displacement: np.ndarray
    stiffness: np.ndarray
    bearing_result: object = None

    def to_dict(self) -> dict:
        d = {"name": self.name, "position_m": float(self.position),
             "reaction": [float(v) for v in self.reaction],
             "misalignment_rad": [float(v) for v in self.misalignment],
             "ring_displacement": [float(v) for v in self.ring_displacement],
             "stiffness_matrix": [[float(v) for v in r] for r in self.stiffness]}
        if self.bearing_result is not None:
            d["kind"] = "bearing"
            d.update(self.bearing_result.to_dict())
        else:
            d["kind"] = "spring"
        return d


@dataclass
class ShaftResult:
    """The static equilibrium of a shaft system (SI).

    ``nodes`` float[n] [m]; ``displacement`` float[n, 5] per node (x, y, z, γy, γz) [m, rad]; ``supports``
    list[:class:`SupportResult`]; ``outer_ring`` float[n_supports, 5] the outer rings' displacements [m, rad];
    ``tangent`` the tangent stiffness over the free DOF at the solution and ``free`` their indices;
    ``converged``, ``status``, ``iterations``, ``residual`` (scaled [N], moments over ``length_scale``) and
    ``warnings`` as every result of the library.
    """

    system: ShaftSystem
    speed: float
    converged: bool
    status: str
    iterations: int
    residual: float
    nodes: np.ndarray
    displacement: np.ndarray
    outer_ring: np.ndarray
    supports: list
    tangent: np.ndarray = field(repr=False)
    free: np.ndarray = field(repr=False)
    length_scale: float = 1.0
    warnings: list = field(default_factory=list)

    def support(self, name: str) -> SupportResult:
        for s in self.supports:
            if s.name == name:
                return s
        raise KeyError(name)

    def compliance_at(self, position: float) -> np.ndarray:
        """The 5×5 block of the linearised compliance K_t⁻¹ at the node at ``position`` [m] (order [x, y, z, γy,
        γz]; [m/N, rad/N, m/(N·m), rad/(N·m)]): the node's displacement per unit force or moment there, every
        other DOF free, the bearings on their tangents at the solution.  1/C_yy is the tool-tip radial
        stiffness [N/m], 1/C_xx the axial, 1/C_γzγz the tilt stiffness [N·m/rad]."""

        i = self.system.mesh.node_at(float(position), "stiffness_at")
        idx = np.searchsorted(self.free, 5 * i + np.arange(5))
        e = np.zeros((len(self.free), 5))
        e[idx, np.arange(5)] = 1.0
        try:
            c = np.linalg.solve(self.tangent, e)[idx]
        except np.linalg.LinAlgError:
            raise InputError("stiffness_at", "the system's tangent stiffness is singular at this equilibrium",
                             "add support stiffness (preload, or a bearing that carries load)") from None
        return 0.5 * (c + c.T)

    def stiffness_at(self, position: float) -> np.ndarray:
        """The 5×5 linearised stiffness of the whole system at the node at ``position`` [m], order
        [x, y, z, γy, γz] [N/m, N/rad, N·m/m, N·m/rad]: the inverse of :meth:`compliance_at` (static condensation
        of every other DOF; each entry holds the node's other four DOF at zero — the direct stiffness of one
        DOF with the others free is 1 / compliance_at[i, i])."""
        k = np.linalg.inv(self.compliance_at(position))
        return 0.5 * (k + k.T)

    def direct_stiffness_at(self, position: float) -> dict:
        """{"radial_N_per_m": 1/C_yy, "radial_z_N_per_m": 1/C_zz, "axial_N_per_m": 1/C_xx,
        "tilt_N_m_per_rad": 1/C_γzγz} at ``position`` [m] (:meth:`compliance_at`; the tool-tip figures)."""
        c = np.diag(self.compliance_at(position))
        return {"radial_N_per_m": float(1 / c[1]), "radial_z_N_per_m": float(1 / c[2]),
                "axial_N_per_m": float(1 / c[0]), "tilt_N_m_per_rad": float(1 / c[4])}

    def to_dict(self, stiffness_at: float | None = None) -> dict:
        """JSON-ready dictionary (SI): converged, status, residual, nodes, deflection per node, supports (each
        bearing with the keys of ``static --json``), and ``stiffness_at`` when a position is given."""
        d = self.displacement
        out = {"converged": bool(self.converged), "status": self.status, "iterations": int(self.iterations),
               "residual": float(self.residual), "speed_rad_s": float(self.speed),
               "nodes": [float(v) for v in self.nodes],
               "deflection": [{"axial_m": float(r[0]), "radial_y_m": float(r[1]), "radial_z_m": float(r[2]),
                               "slope_y_rad": float(r[3]), "slope_z_rad": float(r[4])} for r in d],
               "supports": [s.to_dict() for s in self.supports],
               "dof_order": list(NODE_DOF), "warnings": list(self.warnings)}
        if stiffness_at is not None:
            k = self.stiffness_at(stiffness_at)
            out["stiffness_at"] = {"position_m": float(stiffness_at),
                                   "stiffness_matrix": [[float(v) for v in r] for r in k],
                                   **self.direct_stiffness_at(stiffness_at)}
        return out


class _Supports:
    """Reactions and tangents of every support for a full DOF vector (warm-started bearing states)."""

    def __init__(self, lm: LinearModel, speed: float):
        self.lm = lm
        self.speed = speed
        self.states = [None] * len(lm.system.supports)

    def evaluate(self, w: np.ndarray, cold: bool = False):
        """(forces on the DOF float[n], tangent contributions float[n, n], per-support list of
        (f_shaft[5], K_shaft[5×5], q_local[5]), every bearing ball converged)."""
        lm = self.lm
        n = len(w)
        f = np.zeros(n)
        kt = np.zeros((n, n))
        per = []
        ok = True
        for k, s in enumerate(lm.system.supports):
            a = lm.node_dofs(lm.support_node[k])
            b = lm.outer_dofs(k)
            rel = w[a] - w[b]
            if isinstance(s, BearingSupport):
                t = s.transform
                q = t @ rel
                fb, kb, st = bearing_reaction(s.bearing, q, self.speed, s.control,
                                              None if cold else self.states[k])
                if not cold:
                    self.states[k] = st
                ok = ok and st.converged
                fs = t @ fb
                ks = t @ kb @ t
            else:
                q = rel
                ks = s.stiffness
                fs = -ks @ rel
            f[a] += fs
            f[b] -= fs
            a0, b0 = a[0], b[0]
            kt[a0:a0 + 5, a0:a0 + 5] += ks
            kt[a0:a0 + 5, b0:b0 + 5] -= ks
            kt[b0:b0 + 5, a0:a0 + 5] -= ks
            kt[b0:b0 + 5, b0:b0 + 5] += ks
            per.append((fs, ks, q))
        return f, kt, per, ok


def _scaled_norm(r: np.ndarray, lm: LinearModel) -> float:
    """max |r| with moments (γy, γz rows) divided by the length scale [N]."""
    w = np.ones(len(r))
    w[3::5] = w[4::5] = 1.0 / lm.length_scale
    return float(np.max(np.abs(r * w))) if len(r) else 0.0


def _load_scale(lm: LinearModel) -> float:
    """The largest external or preload force, moments over the length scale, at least 1 N [N]."""
    s = _scaled_norm(lm.F, lm)
    for sup in lm.system.supports:
        if isinstance(sup, BearingSupport):
            s = max(s, abs(sup.preload_force or 0.0), float(getattr(sup.bearing, "preload", 0.0) or 0.0))
    return max(s, 1.0)


def _sparse_solve(a: np.ndarray, r: np.ndarray) -> np.ndarray | None:
    """a⁻¹ r by sparse LU (the tangent is banded along the shaft plus the support couplings); None when a is
    singular."""
    import warnings


    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return splu(csc_matrix(a)).solve(r)
    except RuntimeError:  # "Factor is exactly singular"
        return None


def _seed_stiffness(lm: LinearModel, speed: float, scale: float) -> np.ndarray:
    """The regularising matrix of the Levenberg–Marquardt shift: each bearing's tangent at the start the
    single-bearing solver uses under an axial and a radial load of the load scale
    (:func:`bearingsim.statics.jones_harris.initial_guess`) plus that at its axial mirror, in
    the support's place (shaft frame), plus 1e-6 of
    the beam's diagonal — a matrix of the physical scale of the contacts, so that μ = 1 is the linear problem
    with bearings as springs (a start inside a clearance, where the tangents vanish)."""
    n = len(lm.F)
    d = np.zeros((n, n))
    kd = np.diag(lm.K)
    base = 1e-6 * np.where(kd > 0, kd, np.max(kd))
    for k, s in enumerate(lm.system.supports):
        if not isinstance(s, BearingSupport):
            continue
        q0 = np.asarray(initial_guess(s.bearing, Loads(fa=scale, fr_y=scale)), dtype=float)
        kb = np.zeros((5, 5))
        for sign in (1.0, -1.0):  # the start's axial sense depends on the row's orientation: both senses
            _, kq, _ = bearing_reaction(s.bearing, q0 * np.array([sign, 1.0, 1.0, 1.0, 1.0]), speed, s.control)
            kb += 0.5 * (kq + kq.T)
        kb += np.diag(np.maximum(np.abs(np.diag(kb)), 1e-3 * np.max(np.abs(np.diag(kb))) + 1.0)) * 1e-3
        ks = s.transform @ kb @ s.transform
        a, b = lm.node_dofs(lm.support_node[k]), lm.outer_dofs(k)
        d[np.ix_(a, a)] += ks
        d[np.ix_(a, b)] -= ks
        d[np.ix_(b, a)] -= ks
        d[np.ix_(b, b)] += ks
    return d + np.diag(base)


def solve_shaft(system: ShaftSystem, speed: float | None = None, initial: np.ndarray | None = None,
                tol: float = TOL, maxiter: int = MAXIT, bearing_results: bool = True) -> ShaftResult:
    """Static equilibrium of ``system`` at ``speed`` [rad/s] (default ``system.speed``).

    ``initial``: optional start, float[n_dof] over all DOF (a previous result's :func:`dof_vector`).
    ``bearing_results``: attach each bearing's full StaticResult (lives, ball table; :func:`result_at`) — off
    for sweeps that need only reactions and stiffness.  Returns a :class:`ShaftResult`; ``converged`` False
    with the reason in ``status`` when no equilibrium was found (e.g. a load past the bearings' capacity).
    """

    speed = system.speed if speed is None else float(speed)
    if not math.isfinite(speed):
        raise InputError("speed", f"must be finite, got {speed!r}", "give the shaft speed in rad/s")
    lm = linear_model(system)
    n = len(lm.F)
    free = np.nonzero(~lm.fixed)[0]
    w = lm.prescribed.copy() if initial is None else np.array(initial, dtype=float)
    if w.shape != (n,):
        raise InputError("initial", f"must have shape ({n},), got {w.shape}", "pass a ShaftResult's dof_vector")
    w[lm.fixed] = lm.prescribed[lm.fixed]
    sup = _Supports(lm, speed)
    scale = _load_scale(lm)
    dreg = _seed_stiffness(lm, speed, scale)[np.ix_(free, free)]

    def residual(wv):
        fs, kt, per, ok = sup.evaluate(wv)
        r = lm.F - lm.K @ wv + fs
        return r[free], (lm.K + kt)[np.ix_(free, free)], per, ok

    r, kt, per, ok = residual(w)
    nr = _scaled_norm(r, lm) if np.all(np.isfinite(r)) else math.inf
    mu = 0.0
    its = 0
    status = "iteration limit reached"
    conv = False
    bearings = [k for k, sp in enumerate(system.supports) if isinstance(sp, BearingSupport)]
    while its < maxiter:
        if nr <= tol * scale and ok:
            conv = True
            break
        its += 1
        accepted = False
        for _ in range(40):
            a = kt + mu * dreg
            dw = _sparse_solve(a, r)
            if dw is None or not np.all(np.isfinite(dw)):
                mu = max(0.1, 10.0 * mu)
                continue
            full = np.zeros(n)
            full[free] = dw
            big = max((float(np.max(np.abs(full[lm.node_dofs(lm.support_node[k])] - full[lm.outer_dofs(k)])
                                    / CAP)) for k in bearings), default=0.0)
            if big > 1.0:
                dw /= big
            step = 1.0
            for _ls in range(8):
                w1 = w.copy()
                w1[free] += step * dw
                r1, kt1, per1, ok1 = residual(w1)
                n1 = _scaled_norm(r1, lm) if np.all(np.isfinite(r1)) else math.inf
                if n1 < (1.0 - 1e-4 * step) * nr:
                    accepted = True
                    break
                step *= 0.5
            if accepted:
                w, r, kt, per, ok, nr = w1, r1, kt1, per1, ok1, n1
                mu = 0.0 if step == 1.0 else mu * 0.3
                break
            mu = max(0.1, 10.0 * mu)
            if mu > 1e6:
                break
        if not accepted:
            status = (f"no equilibrium found: the residual stalls at {nr:.3g} N (load scale {scale:.3g} N) — a load "
                      "past the bearings' capacity, or a bearing that cannot carry it in that direction")
            break
    residual_n = nr
    warnings = []
    if conv:
        # the re-check: every bearing re-solved from a cold start at the returned ring positions
        fs, _, _, okc = sup.evaluate(w, cold=True)
        rv = _scaled_norm((lm.F - lm.K @ w + fs)[free], lm)
        residual_n = max(nr, rv)
        if not okc or rv > TOL_VERIFY * scale:
            conv = False
            status = f"the re-check with every bearing cold-started leaves a residual of {rv:.3g} N"
        else:
            status = "converged"
    elif its >= maxiter:
        status = f"iteration limit reached ({maxiter}) with residual {nr:.3g} N"
    supports = []
    for k, s in enumerate(system.supports):
        fs_k, ks_k, q_k = per[k]
        br = None
        if isinstance(s, BearingSupport):
            if bearing_results:
                br = result_at(s.bearing, q_k, speed, s.control)
                for wmsg in br.warnings:
                    warnings.append(f"{s.name}: {wmsg}")
        a = lm.node_dofs(lm.support_node[k])
        b = lm.outer_dofs(k)
        supports.append(SupportResult(s.name, s.position, fs_k.copy(), (w[a] - w[b])[3:].copy(), q_k.copy(),
                                      ks_k.copy(), br))
    ns = lm.n_shaft
    res = ShaftResult(system=system, speed=speed, converged=conv, status=status, iterations=its,
                      residual=float(residual_n), nodes=system.mesh.nodes.copy(),
                      displacement=w[:ns].reshape(-1, 5).copy(), outer_ring=w[ns:].reshape(-1, 5).copy(),
                      supports=supports, tangent=kt, free=free, length_scale=lm.length_scale, warnings=warnings)
    return res


def dof_vector(result: ShaftResult) -> np.ndarray:
    """All DOF of a result (shaft nodes then outer rings) as one float vector [m, rad]: a start for
    :func:`solve_shaft` (``initial``)."""
    return np.concatenate([result.displacement.ravel(), result.outer_ring.ravel()])
