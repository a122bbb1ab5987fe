"""Jones–Harris quasi-static equilibrium with inertia: orchestration and results.

The per-ball and ring arithmetic are the numba kernels of :mod:`._kernels` (model and
equations in that module's docstring: Jones 1960; Harris & Kotzalas 2007 vol. 2 ch. 3;
[S0] eqs. 6–16).  This module checks inputs, builds a starting point, calls the
kernels, and packages a :class:`StaticResult`.

Units: forces [N], moments [N·m], speeds [rad/s], displacements [m], tilts [rad].
Loads act on the inner ring at the bearing centre: (Fa, Fr_y, Fr_z, M_y, M_z);
displacements q = (δx, δy, δz, γy, γz) are those of the inner ring from the centred
position (architecture.md: x the bearing axis, ψ = 0 on +y).
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from ..contact import hertz
from ..errors import InputError, InputTypeError
from ..geometry import BallBearing, rotating_ring_of, with_rotating_ring
from ..units import api_quantity
from . import _kernels as kn
from .axial import solve_thrust
from .layout import STATUS, STATUS_PAST_CAPACITY  # the one table of status codes (jones_harris.STATUS stays importable)

CONTROLS = {"outer": kn.CONTROL_OUTER, "inner": kn.CONTROL_INNER, "auto": kn.CONTROL_AUTO}
DOF = ("x", "y", "z", "gamma_y", "gamma_z")
TOL_BALL = 1e-12
TOL_RING = 1e-10
#: a result is called converged only if the ring balance, recomputed with every ball re-solved from its own
#: cold start at the returned displacement (:func:`_kernels.equilibrium_residual`), is within TOL_VERIFY
#: times the load scale (the largest load, moments divided by the pitch radius, at least 1 N) [-]
TOL_VERIFY = 1e-7
MAXIT_BALL = 60
MAXIT_RING = 100
#: p_max = C_p Q^(1/3) of :func:`bearingsim.contact.hertz.max_pressure_from_load` as plain Python (the ball table
#: calls it twice per ball: without the compiled function's dispatch cost)
_max_pressure = hertz.max_pressure_from_load.py_func


def _free_ring(ballout: np.ndarray, rows: np.ndarray, scale: float) -> bool:
    """True when no ball carries more than TOL_VERIFY × scale [N] at the inner raceway (a continuum of
    equilibria: the displacement and stiffness mean nothing)."""
    zs = rows[:, kn.P_Z].astype(int)
    qi = np.concatenate([ballout[r, :z, 2] for r, z in enumerate(zs)])
    return not bool(np.any(qi > TOL_VERIFY * scale))


@njit(cache=True, error_model="numpy")
def _row_loads(rows, qv, ballout, lam, out):
    """out[r] ← the load row r carries (Fa, Fy, Fz, My, Mz) about the kernel origin [N, N·m]: minus the sum of
    its balls' generalized forces on the inner ring, read from the solve's ball table ``ballout`` and control
    state ``lam`` (the terms and order of :func:`._kernels.ring_assemble`: (F_x, F_r) of the inner contact from
    Q_i, α_i and the gyroscopic share λ_i G, ball-model eqs. in that module), without re-solving any ball."""
    for r in range(rows.shape[0]):
        par = rows[r]
        z = int(par[kn.P_Z])
        s = par[kn.P_SIGN]
        ric = par[kn.P_RIC]
        xg = kn.inner_groove_centre_axial(par)
        ta1 = np.zeros(5)
        ta2 = np.zeros(5)
        gw = np.zeros(5)
        for k in range(5):
            out[r, k] = 0.0
        for j in range(z):
            psi = par[kn.P_PSI0] + 2.0 * math.pi * j / z
            kn._groove_offsets(par, s, ric, xg, math.cos(psi), math.sin(psi), qv, ta1, ta2, gw)
            bo = ballout[r, j]
            lam_i, _lam_o = kn.control_weights(lam[r, j])
            qi, g, si, ci = bo[2], bo[6], bo[8], bo[9]
            fx = qi * si + lam_i * g * ci
            fr = qi * ci - lam_i * g * si
            mpsi = lam_i * g * par[kn.P_GRI]
            for k in range(5):
                out[r, k] += fx * ta1[k] + fr * ta2[k] - mpsi * gw[k]


def assemble_at(rows: np.ndarray, q: np.ndarray, omega: float, control: str, ballout: np.ndarray):
    """Every ball of ``rows`` solved at the prescribed inner-ring displacement ``q`` [m, rad] and inner-ring speed
    ``omega`` [rad/s], without a ring equilibrium: fills ``ballout`` (float[nrow, zmax, 12], the ball table of
    :func:`._kernels.ring_assemble`) and returns (Σ ball forces on the inner ring float[5] [N, N·m], the stiffness
    −d(that)/dq at fixed row parameters float[5, 5], the control state int[nrow, zmax]).  The public entry of the
    kernel's per-ball solve for models built on the rigid-ring kernel (:mod:`bearingsim.rings.coupling`)."""
    nrow = rows.shape[0]
    zmax = int(rows[:, kn.P_Z].max())
    lam = np.full((nrow, zmax), 1 if control == "inner" else 0, dtype=np.int64)
    res = np.zeros(5)
    kmat = np.zeros((5, 5))
    kn.ring_assemble(rows, np.asarray(q, dtype=float), float(omega), CONTROLS[control], lam,
                     np.zeros((nrow, zmax, 2)), np.zeros(5), res, kmat, ballout, TOL_BALL, MAXIT_BALL)
    return res, kmat, lam


@dataclass
class ReactionState:
    """The ball unknowns of :func:`bearing_reaction` kept between calls (the warm start of a shaft Newton):
    ``rows`` the row parameters, ``xb`` float[nrow, zmax, 8] ball positions and their tangents dX/dA, ``lam`` the
    raceway control per ball, ``ballout`` the last ball table; ``converged`` every ball's own balance met at
    the last call, ``iterations`` its worst ball's iteration count."""

    rows: np.ndarray
    xb: np.ndarray
    lam: np.ndarray
    ballout: np.ndarray
    converged: bool = True
    iterations: int = 0


def bearing_reaction(bearing, q, speed: float = 0.0, control: str = "outer", state: ReactionState | None = None):
    """The force of ``bearing`` on its inner ring and its tangent stiffness at the prescribed displacement ``q``
    = (δx, δy, δz, γy, γz) [m, rad] of the inner ring relative to the outer (from the centred position), at the
    inner-ring ``speed`` [rad/s] (centrifugal and gyroscopic terms on), without a ring equilibrium: the seam
    between a bearing and the shaft it sits on.

    Returns (f float[5] = Σ ball forces on the inner ring (Fx, Fy, Fz, My, Mz) about the bearing's load point
    [N, N·m] — the force the bearing applies to the shaft; the load the bearing carries is −f —, K float[5, 5] =
    −df/dq [N/m, N/rad, N·m/m, N·m/rad], state :class:`ReactionState`).  Pass the returned ``state`` back to
    warm start every ball from its last solution (first-order predictor, :func:`._kernels.ring_assemble`); the
    answer is the same ball equilibrium, found in fewer iterations.  ``state.converged`` is False when a ball's
    own balance failed (the force is then not an equilibrium of that ball)."""
    _check_bearing(bearing)
    _check_control(control)
    qv = _check_initial(q)
    omega = float(abs(_number(speed, "speed")))
    if state is None:
        rows = bearing.row_vectors()
        nrow, zmax = rows.shape[0], int(rows[:, kn.P_Z].max())
        state = ReactionState(rows, np.zeros((nrow, zmax, 8)),
                              np.full((nrow, zmax), 1 if control == "inner" else 0, dtype=np.int64),
                              np.zeros((nrow, zmax, 12)))
    f = np.zeros(5)
    kmat = np.zeros((5, 5))
    conv, its = kn.ring_assemble(state.rows, qv, omega, CONTROLS[control], state.lam, state.xb, np.zeros(5), f,
                                 kmat, state.ballout, TOL_BALL, MAXIT_BALL)
    state.converged, state.iterations = bool(conv), int(its)
    return f, kmat, state


def result_at(bearing, q, speed: float = 0.0, control: str = "outer") -> StaticResult:
    """The :class:`StaticResult` of ``bearing`` held at the ring displacement ``q`` [m, rad] (inner ring relative
    to the outer) at inner-ring ``speed`` [rad/s]: every ball solved from a cold start (:func:`assemble_at`),
    ``loads`` the loads the bearing carries there (−Σ ball forces on the inner ring, so that the ring is in
    equilibrium under them), then the ball table, row loads, warnings, lives and static safety of :func:`solve`.
    ``converged`` is every ball's own balance; ``residual`` 0 (the ring position is imposed); status 8 when no
    ball carries load at the inner raceway."""
    from ..limits import static_warnings

    _check_bearing(bearing)
    _check_control(control)
    qv = _check_initial(q)
    speed = _number(speed, "speed")
    rows = bearing.row_vectors()
    nrow, zmax = rows.shape[0], int(rows[:, kn.P_Z].max())
    lam = np.full((nrow, zmax), 1 if control == "inner" else 0, dtype=np.int64)
    xb = np.zeros((nrow, zmax, 2))
    ballout = np.zeros((nrow, zmax, 12))
    f = np.zeros(5)
    kmat = np.zeros((5, 5))
    bconv, its = kn.ring_assemble(rows, qv, float(abs(speed)), CONTROLS[control], lam, xb, np.zeros(5), f, kmat,
                                  ballout, TOL_BALL, MAXIT_BALL)
    loads = Loads(*(-f))
    status = 0 if bconv else 4
    if status == 0 and _free_ring(ballout, rows, _scale(loads, rows)):
        status = 8
    res = _packaged(bearing, loads, speed, control, rows, status, STATUS.get(status, f"status {status}"), its, 0.0,
                    qv, kmat, ballout, xb, lam)
    res.warnings = static_warnings(res)
    _report(res)
    return res


def _packaged(bearing, loads, speed, control, rows, status, text, its, rn, q, kmat, ballout, xb, lam) -> StaticResult:
    """The :class:`StaticResult` of a ring displacement ``q`` [m, rad] and its ball solution (``ballout``, ``xb``,
    ``lam``): the ball table and the per-row loads; warnings and ratings are the caller's next steps."""
    res = StaticResult(bearing=bearing, loads=loads, speed=float(speed), control=control, converged=status == 0,
                       status=text, iterations=int(its), residual=float(rn), displacement=q.copy(),
                       stiffness=kmat.copy(), balls=ball_table(rows, ballout, xb, lam, float(speed)),
                       rows_params=rows, status_code=int(status))
    res.row_forces = np.zeros((rows.shape[0], 5))
    _row_loads(rows, q, ballout, lam, res.row_forces)
    return res


def _number(value, field: str) -> float:
    """A real number (not bool, not str) → float; InputTypeError/InputError naming ``field`` otherwise."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        hint = "pass a float in SI units, a string with its unit or a pint Quantity"
        raise InputTypeError(field, f"must be a real number, got {type(value).__name__} {value!r}", hint)
    v = float(value)
    if not math.isfinite(v):
        raise InputError(field, f"must be finite, got {value!r}", "give a finite value")
    return v


@dataclass(frozen=True)
class Loads:
    """External loads on the inner ring [N, N·m]; M about y and z at the bearing centre.

    Each load is a float in SI units [N, N·m], a string with its unit (``"2 kN"``, ``"5 N*m"``) or a pint
    ``Quantity`` (:func:`bearingsim.units.api_quantity`); it is stored as a float [N, N·m]."""

    fa: float = 0.0
    fr_y: float = 0.0
    fr_z: float = 0.0
    m_y: float = 0.0
    m_z: float = 0.0

    def __post_init__(self):
        for name in ("fa", "fr_y", "fr_z", "m_y", "m_z"):
            # quantities converted to SI, then numbers only (a bool, None or list is refused naming the field)
            dim = "moment" if name.startswith("m_") else "force"
            object.__setattr__(self, name, _number(api_quantity(getattr(self, name), dim, name), name))

    def as_array(self) -> np.ndarray:
        return np.array([self.fa, self.fr_y, self.fr_z, self.m_y, self.m_z], dtype=float)


@dataclass
class StaticResult:
    """Quasi-static solution of a bearing (or bearing system) under load at speed.

    Attributes are SI.  ``balls`` holds one array per quantity, shape (n_balls,), over all
    rows in order; ``row`` says which row each ball belongs to.
    """

    bearing: object
    loads: Loads
    speed: float  #: inner-ring speed [rad/s]
    control: str
    converged: bool
    status: str
    iterations: int
    residual: float  #: max |residual| [N] (moments divided by the pitch radius)
    displacement: np.ndarray  #: (δx, δy, δz, γy, γz) [m, m, m, rad, rad]
    stiffness: np.ndarray  #: 5×5, order (x, y, z, γy, γz) [N/m, N/rad, N·m/m, N·m/rad]
    balls: dict = field(repr=False)
    rows_params: np.ndarray = field(repr=False, default=None)
    #: plausibility warnings (:func:`bearingsim.limits.static_warnings`), empty when none
    warnings: list = field(default_factory=list)
    status_code: int = 0  #: kernel status (keys of :data:`STATUS`)
    #: per row: the load it carries (Fa, Fy, Fz, My, Mz) about the kernel origin [N, N·m], shape (n_rows, 5),
    #: summed from the solve's own ball forces (:func:`_row_loads`)
    row_forces: np.ndarray = field(repr=False, default=None)
    #: ISO 281 basic rating life L10 [10⁶ rev] (:func:`bearingsim.life.iso281_life`), None when not applicable
    basic_rating_life: float | None = None
    #: ISO/TS 16281 reference rating life L10r [10⁶ rev] (:func:`bearingsim.life.reference_rating_life`)
    reference_rating_life: float | None = None
    #: ISO 281 / ISO 76 / ISO/TS 16281 figures (:func:`bearingsim.life.rating_summary`: ratings, equivalent
    #: loads, lives in 10⁶ rev and hours, static safety factors, estimate flags and notes), JSON-ready
    rating: dict | None = field(repr=False, default=None)
    #: per-row figures of a bearing system (:func:`bearingsim.statics.arrangements.row_summaries`: loads,
    #: displacements at the row plane, loaded balls, peak pressures; :func:`~.arrangements.row_results` and
    #: :meth:`to_dict` add each row's ball table), else None
    rows: list | None = field(repr=False, default=None)
    #: control of the inner ring's tilt (γy, γz): "free" (moment equilibrium, the default) or "fixed" (tilt held at
    #: ``misalignment``, the moment that holds it reported in ``reaction_moment``) — :func:`solve`
    tilt_mode: str = "free"
    #: prescribed tilt (γy, γz) of the inner ring for tilt_mode "fixed" [rad]
    misalignment: np.ndarray | None = field(repr=False, default=None)
    #: tilt_mode "fixed": the moment (M_y, M_z) [N·m] that the shaft (the constraint) applies to the inner ring, in
    #: addition to ``loads``, to hold the tilt — the bearing's moment reaction; solving with tilt "free" under
    #: ``loads`` plus this moment gives the same equilibrium
    reaction_moment: np.ndarray | None = field(repr=False, default=None)

    @property
    def clearance(self) -> dict:
        """Internal clearances of the bearing [m] (:func:`internal_clearance`)."""
        return internal_clearance(self.bearing)

    @property
    def axial_displacement(self) -> float:
        return float(self.displacement[0])

    @property
    def radial_displacement(self) -> float:
        return float(math.hypot(self.displacement[1], self.displacement[2]))

    @property
    def tilt(self) -> float:
        return float(math.hypot(self.displacement[3], self.displacement[4]))

    @property
    def axial_stiffness(self) -> float:
        """K_xx = ∂Fa/∂δx with the other displacements held [N/m]."""
        return float(self.stiffness[0, 0])

    def to_dict(self) -> dict:
        """JSON-ready dictionary in SI units (the ``static --json`` schema)."""
        balls = ball_dicts(self.balls)
        out = {
            "bearing": getattr(self.bearing, "name", str(self.bearing)),
            "converged": bool(self.converged),
            "status": self.status,
            "iterations": int(self.iterations),
            "residual_N": float(self.residual),
            "speed_rad_s": float(self.speed),
            "rotating_ring": rotating_ring_of(self.bearing),
            "control": self.control,
            "loads": {"fa_N": self.loads.fa, "fr_y_N": self.loads.fr_y, "fr_z_N": self.loads.fr_z,
                      "m_y_N_m": self.loads.m_y, "m_z_N_m": self.loads.m_z},
            "displacement": {
                "axial_m": self.axial_displacement, "radial_m": self.radial_displacement, "tilt_rad": self.tilt,
                "vector": [float(v) for v in self.displacement],
            },
            "axial_stiffness_N_per_m": self.axial_stiffness,
            "stiffness_matrix": [[float(v) for v in row] for row in self.stiffness],
            "stiffness_order": list(DOF),
            "cage_speed_rad_s": self.cage_speed,
            "clearance": self.clearance,
            "warnings": list(self.warnings),
            "balls": balls,
        }
        out["basic_rating_life_million_revolutions"] = self.basic_rating_life
        out["reference_rating_life_million_revolutions"] = self.reference_rating_life
        if self.rating is not None:
            out.update(self.rating)
        out["tilt"] = {"mode": self.tilt_mode}
        if self.tilt_mode == "fixed":
            out["tilt"].update(
                misalignment_rad=[float(v) for v in self.misalignment],
                reaction_moment_N_m=[float(v) for v in self.reaction_moment] if self.reaction_moment is not None
                else None)
        if self.rows is not None:
            rowof = self.balls["row"]
            out["rows"] = [{**d, "balls": [balls[j] for j in np.nonzero(rowof == d["row"])[0]]} for d in self.rows]
        return _json_safe(out)

    @property
    def cage_speed(self) -> float:
        """Cage speed [rad/s]: the mean of Jones' orbital speeds over the balls in contact.

        With a rigid cage all balls orbit together; under a non-uniform load the quasi-static
        model gives each ball its own ω_m, and the cage runs at their mean (balls that carry
        no load are pushed by the cage and do not count).
        """
        w = self.balls["orbital_speed_rad_s"]
        loaded = self.balls["inner_load_N"] > 0
        if not loaded.any():
            return float(np.mean(w)) if len(w) else 0.0
        return float(np.mean(w[loaded]))


def ball_dicts(balls: dict, index=None) -> list[dict]:
    """The ball table ``balls`` (one array per quantity) as one dict per ball (JSON-ready floats and ints),
    for all balls or those at the positions ``index``."""
    if index is None:
        index = range(len(balls["azimuth_rad"]))
    return [{k: (int(v[j]) if k in ("row", "inner_control") else float(v[j])) for k, v in balls.items()}
            for j in index]


def _json_safe(v):
    """Non-finite floats (NaN ball speeds of a state outside the rolling relations, an infinite life) → None,
    so that ``json.dumps`` writes valid JSON (null) instead of the tokens NaN/Infinity."""
    if isinstance(v, dict):
        return {k: _json_safe(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_json_safe(x) for x in v]
    if isinstance(v, float) and not math.isfinite(v):
        return None
    return v


def internal_clearance(bearing) -> dict:
    """Internal clearances of a single-row bearing [m] (empty for a bearing system; see its rows).

    radial_internal_clearance_m : P_d, the diametral (radial) clearance: total radial free movement of one
        ring from one extreme to the other (ISO 5593; Harris & Kotzalas 2007 vol. 1 §2.2)
    axial_internal_clearance_m : P_e, total axial free movement.  Deep groove: P_e = 2 A sin α₀ with
        cos α₀ = 1 − P_d/(2A) (Harris & Kotzalas 2007 vol. 1 eqs. 2.10, 2.13).  Angular contact (a single
        row is open on one side): the axial shift from the centred position to first contact,
        √(A² − (A cos α₀ − P_d/2)²) − A sin α₀ (0 without extra clearance).
    axial_play_m : the axial movement from the centred position to first contact on each side
        (P_e/2 for a deep-groove bearing; as above for an angular contact row).
    """
    if not hasattr(bearing, "total_curvature_distance"):
        return {}
    big_a = bearing.total_curvature_distance
    pd = bearing.diametral_clearance
    a0 = bearing.free_contact_angle
    if bearing.kind == "deep_groove":
        pe = 2.0 * big_a * math.sin(a0) if pd > 0 else 0.0
        play = 0.5 * pe
    else:
        c = big_a * math.cos(a0) - 0.5 * pd
        play = math.sqrt(max(big_a * big_a - c * c, 0.0)) - big_a * math.sin(a0) if pd > 0 else 0.0
        pe = play
    return {"radial_internal_clearance_m": float(pd), "axial_internal_clearance_m": float(pe),
            "axial_play_m": float(play)}


def initial_guess(bearing, loads: Loads) -> np.ndarray:
    """A start for the ring Newton: the thrust-model axial deflection under an equivalent load."""
    if hasattr(bearing, "initial_guess"):
        return bearing.initial_guess(loads)
    q0 = np.zeros(5)
    if bearing.kind == "angular_contact":
        fr = math.hypot(loads.fr_y, loads.fr_z)
        mr = math.hypot(loads.m_y, loads.m_z) / (0.5 * bearing.pitch_diameter)
        fa_eq = max(loads.fa, 0.0) + 0.5 * (fr + mr) * math.tan(max(bearing.free_contact_angle, 0.1)) + 1.0
        # the fixed point of [S0] eq. 4 is cheap; Brent's method (imports scipy.optimize) only if it fails
        th = solve_thrust(bearing, fa_eq, method="fixed_point")
        if not th.converged:
            th = solve_thrust(bearing, fa_eq)
        q0[0] = th.axial_deflection + 0.5 * bearing.diametral_clearance * \
            math.cos(bearing.free_contact_angle) / max(math.sin(bearing.free_contact_angle), 1e-3)
    else:
        fr = math.hypot(loads.fr_y, loads.fr_z)
        if fr > 0 and loads.fa == 0:
            # pure radial load: the planar rigid-ring solution (Harris & Kotzalas vol. 1 §7.3), so that the
            # balls of the load zone are in contact from the first iterate.  A start just past the
            # clearance loads a single ball (or none, when the load points between balls), whose axial and
            # tilt rows are proportional: a singular Jacobian.
            q1 = q0.copy()
            if kn.planar_radial_start(bearing.row_vectors(), loads.as_array(), q1):
                return q1
        # deep groove: take up the clearance in the load direction
        c = 0.5 * bearing.diametral_clearance
        if fr > 0:
            q0[1] = loads.fr_y / fr * (c + 1e-6)
            q0[2] = loads.fr_z / fr * (c + 1e-6)
        if loads.fa != 0:
            q0[0] = math.copysign(math.sqrt(max(bearing.total_curvature_distance * c * 2, 0)) + 1e-6, loads.fa)
        m = math.hypot(loads.m_y, loads.m_z)
        if m > 0 and fr == 0 and loads.fa == 0:
            q0[3:] = _moment_tilt(bearing, loads)
    return q0


def _moment_tilt(bearing, loads: Loads) -> np.ndarray:
    """(γy, γz) [rad] that take up the axial play of a deep-groove row in the sense of the moment."""
    m = math.hypot(loads.m_y, loads.m_z)
    if m == 0:
        return np.zeros(2)
    # tilt the inner ring until the ball farthest from the tilt axis has taken up the
    # axial play A sin α₀ plus the Hertz approach of a ball carrying 2M/(Z r) (r the groove-centre
    # radius); from the centred position inside the clearance no ball is loaded and the Jacobian is zero
    par = bearing.row_vectors()[0]
    big_a = bearing.total_curvature_distance
    ric = par[kn.P_RIC]
    z = bearing.ball_count
    psi = par[kn.P_PSI0] + 2 * math.pi * np.arange(z) / z
    reach = float(np.max(np.abs(np.sin(psi) * loads.m_y - np.cos(psi) * loads.m_z))) / m
    q_ball = 2.0 * m / (z * ric)
    approach = hertz.approach_from_load(bearing.contact_constants[2], q_ball)
    tilt = (big_a * math.sin(bearing.free_contact_angle) + approach) / (ric * max(reach, 1e-3))
    return np.array([loads.m_y / m * tilt, loads.m_z / m * tilt])


def _deep_groove_starts(bearing, loads: Loads) -> list:
    """Starts of a single deep-groove row that take up the clearance in the directions the loads act: every
    combination of the planar radial displacement, the axial play shift (sense of Fa) and the tilt through
    the axial play (sense of the moment) that the loads call for (cheap at rest, closed-form balls)."""
    if getattr(bearing, "kind", None) != "deep_groove":
        return []
    la = loads.as_array()
    radial = np.zeros(5)
    kn.planar_radial_start(bearing.row_vectors(), la, radial)
    axial = np.zeros(5)
    if loads.fa != 0:
        big_a = bearing.total_curvature_distance
        axial[0] = math.copysign(big_a * math.sin(bearing.free_contact_angle) + 1e-7, loads.fa)
    tilt = np.zeros(5)
    tilt[3:] = _moment_tilt(bearing, loads)
    parts = [p for p in (radial, axial, tilt) if np.any(p)]
    out = []
    for mask in range(1, 2 ** len(parts)):
        out.append(sum(p for k, p in enumerate(parts) if mask >> k & 1))
    return out


def _scale(loads: Loads, rows: np.ndarray) -> float:
    dm = rows[0, kn.P_DM]
    return max(abs(loads.fa), abs(loads.fr_y), abs(loads.fr_z), 2 * abs(loads.m_y) / dm, 2 * abs(loads.m_z) / dm,
               1.0)


def _check_control(control) -> str:
    if not isinstance(control, str) or control not in CONTROLS:
        raise InputError("control", f"unknown raceway control {control!r}", "use outer, inner or auto")
    return control


def _check_initial(initial) -> np.ndarray:
    """``initial`` → float[5] copy; refused (InputError naming it) before any compiled kernel sees it."""
    try:
        q = np.array(initial, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError("initial", f"must be 5 numbers (δx, δy, δz, γy, γz), got {initial!r}",
                             "pass a float array of shape (5,) [m, rad]") from None
    if q.shape != (5,):
        raise InputError("initial", f"must have shape (5,), got {q.shape}", "pass (δx, δy, δz, γy, γz) [m, rad]")
    if not np.all(np.isfinite(q)):
        raise InputError("initial", f"must be finite, got {q.tolist()}", "pass finite displacements or None")
    return q


def _check_bearing(bearing):
    if not hasattr(bearing, "row_vectors"):
        raise InputTypeError("bearing", f"expected a BallBearing or bearing system, got {type(bearing).__name__}",
                             "load one with bearingsim.io.load_bearing")


def _solve_kernel(rows, loads_arr, omega, control, q, scale):
    """One kernel solve from q (modified) with fresh ball and control states → (status, its, rn, bconv, ...)."""
    nrow = rows.shape[0]
    zmax = int(rows[:, kn.P_Z].max())
    lam = np.full((nrow, zmax), 1 if control == "inner" else 0, dtype=np.int64)
    xb = np.zeros((nrow, zmax, 2))
    kmat = np.zeros((5, 5))
    ballout = np.zeros((nrow, zmax, 12))
    status, its, rn, bconv = kn.solve_ring(rows, loads_arr, omega, CONTROLS[control], q, lam, xb, kmat, ballout,
                                           TOL_BALL, TOL_RING, MAXIT_BALL, MAXIT_RING, scale)
    return int(status), int(its), float(rn), bool(bconv), lam, xb, kmat, ballout


def _verified(rows, loads_arr, omega, control, q, scale) -> tuple[bool, float]:
    """Independent recomputation (:func:`_kernels.equilibrium_residual`) within TOL_VERIFY → (ok, residual)."""
    rv, bc = kn.equilibrium_residual(rows, loads_arr, omega, CONTROLS[control], q, TOL_BALL, MAXIT_BALL)
    return bool(bc) and bool(rv <= TOL_VERIFY * scale), float(rv)


def _attempt(rows, la, omega, control, q, scale) -> list:
    """One solve from q (a copy is taken) plus the independent check → [status, q, its, rn, lam, xb, kmat,
    ballout]; status 0 only for a verified equilibrium (a failed check gets one restart with fresh balls from
    the same displacement, then status 5); 4 when a ball's own balance failed."""
    q = np.array(q, dtype=float)
    status, its, rn, bconv, lam, xb, kmat, ballout = _solve_kernel(rows, la, omega, control, q, scale)
    if status == 0 and bconv:
        ok, rv = _verified(rows, la, omega, control, q, scale)
        if not ok:
            # the balls were carried into another branch by their warm starts: continue from the fresh state
            status, its2, rn, bconv, lam, xb, kmat, ballout = _solve_kernel(rows, la, omega, control, q, scale)
            its += its2
            if status == 0 and bconv:
                ok, rv = _verified(rows, la, omega, control, q, scale)
                if not ok:
                    status, rn = 5, max(rn, rv)
    if status == 0 and not bconv:
        status = 4
    return [status, q, its, rn, lam, xb, kmat, ballout]


def _alternative_starts(bearing, loads, speed, control, initial, q_first, rows, la, omega, scale, reasons):
    """Callables giving further starts of :func:`solve` (see there), cheapest first; a fixed-control solve that
    ends with status 3 or 6 is noted in ``reasons`` (status code → control)."""
    if initial is not None:
        yield lambda: np.array(initial_guess(bearing, loads), dtype=float)
    for q_dg in _deep_groove_starts(bearing, loads):
        yield lambda q_dg=q_dg: q_dg
    if control != "outer" and omega > 0:
        def fixed_solution(fixed):
            r = solve(bearing, loads, speed, fixed)
            if r.status_code in (3, 6):
                reasons.setdefault(r.status_code, fixed)
            return r.displacement if r.converged else None
        yield lambda: fixed_solution("outer")
        if control == "auto":
            yield lambda: fixed_solution("inner")

    def continuation():
        q1 = np.array(q_first, dtype=float)
        z = rows.shape[0], int(rows[:, kn.P_Z].max())
        for f in (0.1, 0.25, 0.5, 0.75):
            kn.solve_ring(rows, f * la, omega, CONTROLS[control], q1,
                          np.full(z, 1 if control == "inner" else 0, dtype=np.int64), np.zeros(z + (2,)),
                          np.zeros((5, 5)), np.zeros(z + (12,)), TOL_BALL, TOL_RING, MAXIT_BALL, MAXIT_RING,
                          max(f * scale, 1.0))
        return q1
    yield continuation

    def batch_ramp():
        from ._batch import run_batch

        ramp = np.array([0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0])
        out = run_batch(bearing, ramp[:, None] * la[None, :], np.full(len(ramp), omega), control, fallback=False)
        return out["q"][-1].copy() if out["status"][-1] == 0 else None
    yield batch_ramp


TILT_MODES = ("free", "fixed")


def _check_tilt(tilt, misalignment) -> tuple[str, np.ndarray]:
    if not isinstance(tilt, str) or tilt not in TILT_MODES:
        raise InputError("tilt", f"unknown tilt control {tilt!r}", "use free or fixed")
    try:
        g = np.array(misalignment if misalignment is not None else (0.0, 0.0), dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise InputTypeError("misalignment", f"must be two numbers (γy, γz) [rad], got {misalignment!r}",
                             "pass e.g. (0.0, 0.0005)") from None
    if g.shape != (2,) or not np.all(np.isfinite(g)):
        raise InputError("misalignment", f"must be two finite numbers (γy, γz) [rad], got {misalignment!r}",
                         "pass e.g. (0.0, 0.0005)")
    if tilt == "free" and np.any(g != 0):
        raise InputError("misalignment", "a misalignment needs the tilt held (tilt='fixed')",
                         "pass tilt='fixed' (CLI: --tilt fixed)")
    check_misalignment(g, "misalignment")
    return tilt, g


#: the largest tilt :func:`solve` holds [rad] (5.7°): ball bearings run misaligned by arc minutes, and the contact
#: geometry of rigid rings is meant for such tilts (without the limit a 90° tilt solves to "converged" with
#: M = 3.6e6 N·m)
MAX_MISALIGNMENT = 0.1


def check_misalignment(g, field: str) -> None:
    """An :class:`InputError` naming ``field`` when a tilt (γy, γz) [rad] exceeds :data:`MAX_MISALIGNMENT`."""
    m = float(np.hypot(*np.asarray(g, dtype=float)))
    if m > MAX_MISALIGNMENT:
        raise InputError(field, f"a tilt of {math.degrees(m):.4g}° is past {math.degrees(MAX_MISALIGNMENT):.3g}° "
                         "(ball bearings run misaligned by arc minutes)", 'give e.g. "2 arcmin" or "0.5 mrad"')


def _translations_at_tilt(rows, la, omega, control, t, gamma, scale, maxit: int = 60):
    """Newton's method with backtracking on the translations t = (δx, δy, δz) [m] of the inner ring at the held
    tilt ``gamma`` [rad]: the force balance la[:3] + Σ ball forces (:func:`assemble_at`) = 0, Jacobian −K_tt of
    the kernel's tangent stiffness → (t, converged, iterations)."""
    nrow, zmax = rows.shape[0], int(rows[:, kn.P_Z].max())
    ballout = np.zeros((nrow, zmax, 12))

    def resid(tv):
        f, k, _ = assemble_at(rows, np.r_[tv, gamma], omega, control, ballout)
        return la[:3] + f[:3], k[:3, :3]

    t = np.array(t, dtype=float)
    r, k = resid(t)
    nr = float(np.max(np.abs(r)))
    for it in range(maxit):
        if nr <= TOL_RING * scale:
            return t, True, it
        dt = np.linalg.lstsq(k, r, rcond=None)[0]
        step = 1.0
        for _ in range(30):
            r1, k1 = resid(t + step * dt)
            n1 = float(np.max(np.abs(r1)))
            if np.isfinite(n1) and n1 < (1.0 - 1e-4 * step) * nr:
                break
            step *= 0.5
        else:
            return t, False, it
        t, r, k, nr = t + step * dt, r1, k1, n1
    return t, nr <= TOL_RING * scale, maxit


def _solve_fixed_tilt(bearing, loads: Loads, speed: float, control: str, initial, gamma: np.ndarray) -> StaticResult:
    """The equilibrium of the translations (δx, δy, δz) with the inner ring's tilt held at ``gamma`` [rad]
    (displacement control of γy, γz).  Path: from the free equilibrium (its tilt γ_f, or the default start) the
    tilt is moved to ``gamma`` in steps of at most 0.25 mrad, the translations re-balanced at each step by
    :func:`_translations_at_tilt` (tangent predictor −K_tt⁻¹ K_tγ Δγ; a failed step is halved).  Displacement
    control follows the moment–tilt curve through its unstable part (a deep-groove ring under F_a snaps between
    tilted states under a prescribed moment).  The moment M that holds the tilt, −(M_ext + Σ ball moments), is
    ``reaction_moment``; the point is then handed to :func:`solve` under loads + M (a verified equilibrium: every
    ball re-solved from a cold start, TOL_VERIFY) for the ball table and checks, so that ``converged`` keeps its
    meaning.  Not converged (status 1) when the path stalls or the verified solve leaves the held tilt."""
    rows = bearing.row_vectors()
    scale = _scale(loads, rows)
    la = loads.as_array()
    omega = float(abs(speed))
    if initial is not None:
        q = _check_initial(initial).copy()
    else:
        free = solve(bearing, loads, speed, control)
        q = free.displacement.copy() if free.converged else np.array(initial_guess(bearing, loads), dtype=float)
    nrow, zmax = rows.shape[0], int(rows[:, kn.P_Z].max())
    ballout = np.zeros((nrow, zmax, 12))
    its = 0
    g0, t = q[3:].copy(), q[:3].copy()
    s, ds = 0.0, min(1.0, 2.5e-4 / max(float(np.max(np.abs(gamma - g0))), 1e-12))
    ok = True
    while s < 1.0 and ok:
        s1 = min(1.0, s + ds)
        g_prev, g_new = g0 + s * (gamma - g0), g0 + s1 * (gamma - g0)
        _, k, _ = assemble_at(rows, np.r_[t, g_prev], omega, control, ballout)
        pred = t - np.linalg.lstsq(k[:3, :3], k[:3, 3:] @ (g_new - g_prev), rcond=None)[0]
        t1, conv, n = _translations_at_tilt(rows, la, omega, control, pred, g_new, scale)
        its += n
        if conv:
            s, t = s1, t1
        elif ds > 1e-4:
            ds *= 0.5
        else:
            ok = False
    m = np.zeros(2)
    if ok:
        f, _, _ = assemble_at(rows, np.r_[t, gamma], omega, control, ballout)
        m = -(la[3:] + f[3:])
        m[np.abs(m) <= 1e-12 * scale * float(rows[0, kn.P_DM])] = 0.0  # round-off of a symmetric case, not a moment
        res = solve(bearing, Loads(*(la + np.r_[0.0, 0.0, 0.0, m])), speed, control, np.r_[t, gamma])
        its += res.iterations
        miss = float(np.max(np.abs(res.displacement[3:] - gamma)))
        ok = res.converged and miss <= 1e-6 * max(float(np.max(np.abs(gamma))), 1e-3)
        why = f"the verified solve left the held tilt by {miss:.3g} rad"
    else:
        res = solve(bearing, loads, speed, control)
        why = f"the translations could not be balanced at the held tilt (reached {s:.3g} of the tilt path)"
    res.iterations = its
    res.tilt_mode = "fixed"
    res.misalignment = gamma.copy()
    res.reaction_moment = m.copy() if ok else None
    res.loads = loads  # the external loads; the constraint moment is reaction_moment
    if not ok:
        res.converged = False
        res.status_code = 1
        res.status = "tilt not held: " + why
    _report(res)  # the lives and safety of the constrained equilibrium (external loads only)
    return res


def solve(bearing, loads: Loads | None = None, speed: float = 0.0, control: str = "outer",
          initial: np.ndarray | None = None, tilt: str = "free", misalignment=None,
          rotating_ring: str | None = None) -> StaticResult:
    """Quasi-static equilibrium of ``bearing`` under ``loads`` at inner-ring ``speed`` [rad/s].

    Parameters
    ----------
    bearing : BallBearing or BearingSystem (the rows protocol, :mod:`bearingsim.geometry`)
    loads : Loads  [N, N·m] (each load a float in SI, a string with its unit or a pint Quantity)
    speed : float  [rad/s]  speed of the turning ring (the inner one unless ``rotating_ring`` or the bearing's
        own ``rotating_ring`` says outer; the other ring stands); the sign gives the sense of rotation of
        the balls and cage (the equilibrium depends on |speed| only).  A bare number is rad/s (157.08 is
        1500 rpm); ``"1500 rpm"`` or a pint Quantity is converted (:func:`bearingsim.units.api_quantity`)
    control : ``"outer"``, ``"inner"`` or ``"auto"`` raceway control (auto: Jones' criterion per ball, evaluated at
        the ball's outer-control solution at the current displacement — inner control when it says so and the inner
        contact stays closed — so that the ring forces depend on the displacement alone: ``_kernels.ring_assemble``)
    initial : optional start for (δx, δy, δz, γy, γz) [m, rad], float[5], finite
    tilt : ``"free"`` (default: the inner ring tilts until the moments balance — a single bearing carries no
        moment beyond ``loads``) or ``"fixed"``: the tilt (γy, γz) is held at ``misalignment`` (default 0: a
        single bearing on a stiff shaft in a stiff housing; ISO/TS 16281 takes the tilt or the moment as an
        input, docs/life.md) and the moment that holds it is returned as ``reaction_moment``
    misalignment : (γy, γz) [rad] of the inner ring relative to the outer for ``tilt="fixed"`` (floats in rad,
        or strings with a unit such as ``"2 arcmin"``)
    rotating_ring : ``"inner"`` or ``"outer"``: the ring that turns at ``speed`` (None: the bearing's own,
        :attr:`bearingsim.geometry.BallBearing.rotating_ring`)

    Returns a :class:`StaticResult`; ``converged`` is False (with ``status`` and ``residual``)
    when no equilibrium was found — never a silently wrong number.  A result is called converged
    only when the ring balance recomputed independently (every ball re-solved from its own cold start
    at the returned displacement) is within :data:`TOL_VERIFY`; results past the plausibility limits
    of :mod:`bearingsim.limits` carry ``warnings``.
    """
    from ..limits import check_speed, static_warnings

    _check_bearing(bearing)
    if rotating_ring is not None:
        bearing = with_rotating_ring(bearing, rotating_ring)
    if loads is None:
        loads = Loads()
    elif not isinstance(loads, Loads):
        raise InputTypeError("loads", f"expected a Loads, got {type(loads).__name__}",
                             "e.g. Loads(fa=1000.0, fr_y=500.0) [N, N·m]")
    _check_control(control)
    speed = _number(api_quantity(speed, "speed", "speed"), "speed")
    if misalignment is not None and not isinstance(misalignment, np.ndarray):
        misalignment = [api_quantity(g, "angle", "misalignment") for g in misalignment] \
            if isinstance(misalignment, list | tuple) else api_quantity(misalignment, "angle", "misalignment")
    tilt, gamma = _check_tilt(tilt, misalignment)
    if tilt == "fixed":
        return _solve_fixed_tilt(bearing, loads, speed, control, initial, gamma)
    rows = bearing.row_vectors()
    check_speed(speed, float(rows[0, kn.P_DM]))
    q = _check_initial(initial) if initial is not None else np.array(initial_guess(bearing, loads), dtype=float)
    la = loads.as_array()
    omega = float(abs(speed))
    scale = _scale(loads, rows)
    state = _attempt(rows, la, omega, control, q, scale)
    reasons = {}  # fixed-control answers met on the way (status code → control), for the reason of a failure
    if state[0] not in (0, 8):
        # other starts before giving up (the first answer's status is kept when none converges): the default
        # start (when the caller gave one); for inner/auto control at speed the outer-control equilibrium (a
        # ball switches to outer control where its inner contact opens, a kink that can stall the line
        # search), and for auto the inner-control one; a continuation in the load from a tenth of it; the batch
        # loop along a load ramp (tangent predictor, coupled ring–ball Newton), so that a point the batch path
        # converges is not refused here
        for make in _alternative_starts(bearing, loads, speed, control, initial, q, rows, la, omega, scale,
                                        reasons):
            q1 = make()
            if q1 is None or not np.all(np.isfinite(q1)):
                continue
            st1 = _attempt(rows, la, omega, control, q1, scale)
            if st1[0] == 0:
                st1[2] += state[2]
                state = st1
                break
            if st1[0] in (3, 6):
                reasons.setdefault(st1[0], control)
            state[2] += st1[2]
    status, q, its, rn, lam, xb, kmat, ballout = state
    if status in (0, 3, 6) and _free_ring(ballout, rows, scale):
        status = 8
    text = STATUS.get(status, f"status {status}")
    if status not in (0, 3, 6, 8):
        status, text, its = _failure_reason(bearing, loads, control, rows, la, omega, scale, state, reasons)
    if status == STATUS_PAST_CAPACITY:
        # no state to report: the last iterate is outside the model (balls past the groove-curvature centres)
        q, kmat, ballout, xb = (np.full_like(a, np.nan) for a in (q, kmat, ballout, xb))
    res = _packaged(bearing, loads, speed, control, rows, status, text, its, rn, q, kmat, ballout, xb, lam)
    res.warnings = static_warnings(res, _rest_inner_loads(bearing, loads, res, rows, la, control, scale))
    _report(res)
    return res


def _rest_inner_loads(bearing, loads, res, rows, la, control, scale):
    """The inner-raceway ball loads [N] of the equilibrium at rest under the same loads, when ``res`` (at speed)
    has balls without inner load while others carry load — the reference of the lift-off rule of
    :func:`bearingsim.limits.static_warnings`; None otherwise (or when the rest equilibrium is not found)."""
    qi = res.balls["inner_load_N"]
    if res.speed == 0 or not res.converged or np.all(qi > 0) or not np.any(qi > 0):
        return None
    rest = _attempt(rows, la, 0.0, control, res.displacement, scale)
    if rest[0] != 0:
        rest = _attempt(rows, la, 0.0, control, np.array(initial_guess(bearing, loads), dtype=float), scale)
    if rest[0] != 0:
        return None
    ballout = rest[7]
    return np.concatenate([ballout[r, :int(z), 2] for r, z in enumerate(rows[:, kn.P_Z])])


def _failure_reason(bearing, loads, control, rows, la, omega, scale, state, reasons):
    """(status code, status text, iterations) of a point no start converged, from what was met on the way:

    * a NaN residual: the load is past what the bearing carries in equilibrium at this speed (status 9); the
      largest fraction of the loads that converges is estimated by :func:`_carried_fraction` and named;
    * an angular contact row whose fixed-control solve (or, at speed, whose equilibrium at rest under the same
      loads) puts a loaded contact past the groove bottom: the reason of status 3 (not enough axial load);
    * else the kernel's status."""
    status, its, rn = state[0], state[2], state[3]
    text = STATUS.get(status, f"status {status}")
    if not math.isfinite(rn):
        frac = _carried_fraction(bearing, rows, la, omega, control)
        text = STATUS[STATUS_PAST_CAPACITY]
        if frac > 0:
            carried = ", ".join(f"{n} {frac * v:.4g} {u}" for n, v, u in
                                zip(("Fa", "Fr_y", "Fr_z", "M_y", "M_z"), la, ("N",) * 3 + ("N·m",) * 2) if v)
            text += (f"; at this speed about {frac:.3g} × these loads ({carried}) is the most carried (the largest "
                     "fraction of them that converges along a load ramp)")
        return STATUS_PAST_CAPACITY, text, its
    if not np.any(rows[:, kn.P_DX0] > 0):
        return status, text, its
    for code in (3, 6):
        if code in reasons:
            return code, f"{STATUS[code]} (found with {reasons[code]} control)", its
    if omega > 0:
        rest = _attempt(rows, la, 0.0, control, np.array(initial_guess(bearing, loads), dtype=float), scale)
        its += rest[2]
        if rest[0] == 3:
            return 3, f"{STATUS[3]} (found at rest under the same loads; at speed no equilibrium was found)", its
    return status, text, its


def _carried_fraction(bearing, rows, la, omega, control) -> float:
    """The largest factor f ≤ 1 [-] for which f × ``la`` converges at ``omega`` along a load ramp of the batch
    loop (:func:`._batch.run_batch`, warm starts, no single-point fallback): 50 factors 0.02 … 1, then 50
    between the last one that converges and the next (f to 0.04 %) → f; 0 when 0.02 × ``la`` fails."""
    from ._batch import run_batch

    lo, hi = 0.0, 1.0
    for ramp in (np.linspace(0.02, 1.0, 50), None):
        if ramp is None:
            ramp = np.linspace(lo, hi, 51)[1:]
        st = run_batch(bearing, ramp[:, None] * la[None, :], np.full(len(ramp), omega), control,
                       fallback=False)["status"]
        bad = np.flatnonzero(st != 0)
        k = int(bad[0]) if bad.size else len(ramp)
        if k == 0:
            return lo
        lo = float(ramp[k - 1])
        if k == len(ramp):
            return lo
        hi = float(ramp[k])
    return lo


def _report(res: StaticResult) -> None:
    """The report step of :func:`solve`: the lives and static safety (:func:`bearingsim.life.apply_rating`, without
    lubricant: the CLI adds one) and (for a bearing system) the per-row results, computed once from the solution
    so that :meth:`StaticResult.to_dict` only serialises."""
    from ..life import apply_rating

    apply_rating(res)
    if not isinstance(res.bearing, BallBearing):  # a set or a unit: the per-row results
        from .arrangements import row_summaries

        res.rows = row_summaries(res)


def ball_table(rows: np.ndarray, ballout: np.ndarray, xb: np.ndarray, lam: np.ndarray, omega: float) -> dict:
    """Per-ball quantities from the kernel's output arrays (SI), including Jones' ball speeds.

    ``omega`` is the signed speed of the turning ring [rad/s] (the inner ring, or the outer one where the row's
    ``P_OROT`` is 1): the ball speeds are proportional to it (Jones' relations are linear in ω), so a negative
    speed gives negative orbital speeds (the cage turns with the turning ring) and the spin reverses with it.
    With the outer ring turning, the orbit is ω − ω_m(inner ring at ω) and the spin relative to the cage that of
    the inner ring at −ω (kinematic inversion).  ``orbital_speed_rad_s`` ω_m, ``spin_speed_rad_s`` ω_R and
    ``pitch_angle_rad`` β follow the sign convention stated in :func:`._kernels.kinematics`: relative
    to the cage, the ball turns at ω_R (cos β, −sin β) in the row's (axial ξ, radial r) frame."""
    cols = {k: [] for k in ("row", "azimuth_rad", "inner_contact_angle_rad", "outer_contact_angle_rad",
                            "inner_load_N", "outer_load_N", "inner_max_pressure_Pa", "outer_max_pressure_Pa",
                            "inner_approach_m", "outer_approach_m", "x1_m", "x2_m", "centrifugal_force_N",
                            "gyroscopic_moment_N_m", "orbital_speed_rad_s", "spin_speed_rad_s", "pitch_angle_rad",
                            "inner_control")}
    for r in range(rows.shape[0]):
        par = rows[r]
        z = int(par[kn.P_Z])
        gam = par[kn.P_D] / par[kn.P_DM]
        for j in range(z):
            bo = ballout[r, j]
            si, ci, so, co = bo[8], bo[9], bo[10], bo[11]
            ksi, kci, kso, kco, _, _ = kn.rolling_angles(si, ci, so, co, bo[4], bo[5])
            kin = kn.kinematics(ksi, kci, kso, kco, gam)
            ctrl = int(lam[r, j])
            wm, wr, beta = kin[3 * ctrl] * omega, kin[3 * ctrl + 1] * omega, kin[3 * ctrl + 2]
            if par[kn.P_OROT]:  # the outer ring turns at ω: the same relative speeds as the inner ring at −ω
                wm, wr = omega - wm, -wr
            cols["row"].append(r)
            cols["azimuth_rad"].append(par[kn.P_PSI0] + 2 * math.pi * j / z)
            cols["inner_contact_angle_rad"].append(math.atan2(si, ci))
            cols["outer_contact_angle_rad"].append(math.atan2(so, co))
            cols["inner_load_N"].append(bo[2])
            cols["outer_load_N"].append(bo[3])
            cols["inner_max_pressure_Pa"].append(_max_pressure(par[kn.P_CPI], bo[2]))
            cols["outer_max_pressure_Pa"].append(_max_pressure(par[kn.P_CPO], bo[3]))
            cols["inner_approach_m"].append(bo[4])
            cols["outer_approach_m"].append(bo[5])
            cols["x1_m"].append(xb[r, j, 0])
            cols["x2_m"].append(xb[r, j, 1])
            cols["centrifugal_force_N"].append(bo[7])
            cols["gyroscopic_moment_N_m"].append(bo[6] * par[kn.P_D])
            cols["orbital_speed_rad_s"].append(wm)
            cols["spin_speed_rad_s"].append(wr)
            cols["pitch_angle_rad"].append(beta)
            cols["inner_control"].append(ctrl)
    return {k: np.asarray(v) for k, v in cols.items()}


@dataclass
class BatchResult:
    """Equilibria of many operating points (arrays over points, SI)."""

    displacement: np.ndarray  #: (n, 5)
    stiffness: np.ndarray  #: (n, 5, 5)
    converged: np.ndarray  #: (n,) bool: verified equilibria (status 0)
    iterations: np.ndarray  #: (n,) int
    residual: np.ndarray  #: (n,) [N]
    status: np.ndarray = None  #: (n,) int, keys of :data:`STATUS`
    warning_flags: np.ndarray = None  #: (n,) int32 bitmask of :mod:`bearingsim.limits`

    def status_message(self, i: int) -> str:
        """Readable status of point i."""
        return STATUS.get(int(self.status[i]), f"status {int(self.status[i])}")


def solve_many(bearing, loads: np.ndarray, speeds: np.ndarray, control: str = "outer") -> BatchResult:
    """Solve many operating points, each started from the previous solution (warm start).

    Parameters
    ----------
    loads : float[n, 5]  (Fa, Fr_y, Fr_z, M_y, M_z) [N, N·m] per point
    speeds : float[n]  inner-ring speeds [rad/s] (bare numbers), or a pint Quantity array / strings with units
    control : raceway control as in :func:`solve`

    Neighbouring points in the order given share their solutions as starting points (the
    compiled loop of :func:`bearingsim.statics._batch.run_batch`, with a tangent predictor and a
    cold restart when a warm start fails), so order the points along a path through the grid
    (e.g. speed fastest) for best speed.  Every point reported converged passed the same independent
    recomputation as :func:`solve` (:data:`TOL_VERIFY`); a point the loop does not converge is solved
    again by :func:`solve`, so both paths agree on convergence; a point that fails in any other way gets
    its own status (7) and the other points keep their results.
    """
    from ..limits import check_speed
    from ._batch import run_batch

    _check_bearing(bearing)
    _check_control(control)
    if isinstance(speeds, list | tuple) and any(isinstance(v, str) for v in speeds):
        speeds = [api_quantity(v, "speed", "speeds") for v in speeds]
    elif not isinstance(speeds, str):
        speeds = api_quantity(speeds, "speed", "speeds")
    for name, v in (("loads", loads), ("speeds", speeds)):
        if v is None or isinstance(v, str | bytes | bool):
            raise InputTypeError(name, f"expected an array of numbers, got {type(v).__name__}",
                                 "loads float[n, 5] [N, N·m], speeds float[n] [rad/s]")
    try:
        loads = np.ascontiguousarray(loads, dtype=float)
        speeds = np.ascontiguousarray(speeds, dtype=float)
    except (TypeError, ValueError):
        raise InputTypeError("loads", "loads and speeds must be arrays of numbers",
                             "loads float[n, 5] [N, N·m], speeds float[n] [rad/s]") from None
    if loads.ndim != 2 or loads.shape[1] != 5 or speeds.shape != (loads.shape[0],):
        raise InputError("loads", f"expected loads (n, 5) and speeds (n,), got {loads.shape} and {speeds.shape}",
                         "give one (Fa, Fr_y, Fr_z, M_y, M_z) row and one speed per point")
    if not (np.isfinite(loads).all() and np.isfinite(speeds).all()):
        raise InputError("loads", "non-finite load or speed", "give finite values")
    if speeds.size:
        check_speed(float(np.max(np.abs(speeds))), float(bearing.row_vectors()[0, kn.P_DM]), "speeds")
    out = run_batch(bearing, loads, speeds, control)
    return BatchResult(out["q"], out["k"], out["converged"], out["iterations"], out["residual"], out["status"],
                       out["warning_flags"])
