"""Jones–Harris quasi-static equilibrium with inertia: orchestration and results.

The per-ball and ring arithmetic are the numba kernels of :mod:`._kernels` (model and
equations in that module's docstring: Jones 1960; Harris & Kotzalas 2007 vol. 2 ch. 3;
seed 000 eqs. 6–16).  This module checks inputs, builds a starting point, calls the
kernels, and packages a :class:`StaticResult`.

Units: forces [N], moments [N·m], speeds [rad/s], displacements [m], tilts [rad].
Loads act on the inner ring at the bearing centre: (Fa, Fr_y, Fr_z, M_y, M_z);
displacements q = (δx, δy, δz, γy, γz) are those of the inner ring from the centred
position (architecture.md: x the bearing axis, ψ = 0 on +y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from . import _kernels as kn
from .axial import solve_thrust

CONTROLS = {"outer": kn.CONTROL_OUTER, "inner": kn.CONTROL_INNER, "auto": kn.CONTROL_AUTO}
DOF = ("x", "y", "z", "gamma_y", "gamma_z")
TOL_BALL = 1e-12
TOL_RING = 1e-10
MAXIT_BALL = 60
MAXIT_RING = 100


@dataclass(frozen=True)
class Loads:
    """External loads on the inner ring [N, N·m]; M about y and z at the bearing centre."""

    fa: float = 0.0
    fr_y: float = 0.0
    fr_z: float = 0.0
    m_y: float = 0.0
    m_z: float = 0.0

    def __post_init__(self):
        for name in ("fa", "fr_y", "fr_z", "m_y", "m_z"):
            v = getattr(self, name)
            if not math.isfinite(v):
                raise InputError(name, f"must be finite, got {v!r}", "give a finite load")

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
        b = self.balls
        balls = []
        for j in range(len(b["azimuth_rad"])):
            balls.append({k: (int(v[j]) if k in ("row", "inner_control") else float(v[j])) for k, v in b.items()})
        out = {
            "bearing": getattr(self.bearing, "name", str(self.bearing)),
            "converged": bool(self.converged),
            "status": self.status,
            "iterations": int(self.iterations),
            "residual_N": float(self.residual),
            "speed_rad_s": float(self.speed),
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
            "balls": balls,
        }
        from ..life import iso281_life, reference_rating_life

        out["basic_rating_life_million_revolutions"] = iso281_life(self)
        out["reference_rating_life_million_revolutions"] = reference_rating_life(self)
        if hasattr(self.bearing, "rows"):
            from .arrangements import row_results

            out["rows"] = row_results(self)
        return out

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


def rows_of(bearing) -> np.ndarray:
    """Kernel row parameters of a bearing or bearing system."""
    if hasattr(bearing, "rows_parameters"):
        return bearing.rows_parameters()
    return bearing.row_parameters()[None, :]


def initial_guess(bearing, loads: Loads) -> np.ndarray:
    """A start for the ring Newton: the thrust-model axial deflection under an equivalent load."""
    if hasattr(bearing, "initial_guess"):
        return bearing.initial_guess(loads)
    q0 = np.zeros(5)
    if bearing.kind == "angular_contact":
        fr = math.hypot(loads.fr_y, loads.fr_z)
        mr = math.hypot(loads.m_y, loads.m_z) / (0.5 * bearing.pitch_diameter)
        fa_eq = max(loads.fa, 0.0) + 0.5 * (fr + mr) * math.tan(max(bearing.free_contact_angle, 0.1)) + 1.0
        # the seed's fixed point is cheap; Brent's method (imports scipy.optimize) only if it fails
        th = solve_thrust(bearing, fa_eq, method="fixed_point")
        if not th.converged:
            th = solve_thrust(bearing, fa_eq)
        q0[0] = th.axial_deflection + 0.5 * bearing.diametral_clearance * \
            math.cos(bearing.free_contact_angle) / max(math.sin(bearing.free_contact_angle), 1e-3)
    else:
        # deep groove: take up the clearance in the load direction
        fr = math.hypot(loads.fr_y, loads.fr_z)
        c = 0.5 * bearing.diametral_clearance
        if fr > 0:
            q0[1] = loads.fr_y / fr * (c + 1e-6)
            q0[2] = loads.fr_z / fr * (c + 1e-6)
        if loads.fa != 0:
            q0[0] = math.copysign(math.sqrt(max(bearing.total_curvature_distance * c * 2, 0)) + 1e-6, loads.fa)
    return q0


def _scale(loads: Loads, rows: np.ndarray) -> float:
    dm = rows[0, kn.P_DM]
    return max(abs(loads.fa), abs(loads.fr_y), abs(loads.fr_z), 2 * abs(loads.m_y) / dm, 2 * abs(loads.m_z) / dm,
               1.0)


def solve(bearing, loads: Loads | None = None, speed: float = 0.0, control: str = "outer",
          initial: np.ndarray | None = None) -> StaticResult:
    """Quasi-static equilibrium of ``bearing`` under ``loads`` at inner-ring ``speed`` [rad/s].

    Parameters
    ----------
    bearing : BallBearing or a bearing system with ``rows_parameters()``
    loads : Loads  [N, N·m]
    speed : float  [rad/s]  inner-ring speed (outer ring fixed)
    control : ``"outer"``, ``"inner"`` or ``"auto"`` raceway control (auto: Jones' criterion per ball)
    initial : optional start for (δx, δy, δz, γy, γz)

    Returns a :class:`StaticResult`; ``converged`` is False (with ``status`` and ``residual``)
    when no equilibrium was found — never a silently wrong number.
    """
    loads = loads or Loads()
    if control not in CONTROLS:
        raise InputError("control", f"unknown raceway control {control!r}", "use outer, inner or auto")
    if not math.isfinite(speed):
        raise InputError("speed", f"must be finite, got {speed!r}", 'e.g. "11200 rpm"')
    rows = rows_of(bearing)
    zmax = int(rows[:, kn.P_Z].max())
    nrow = rows.shape[0]
    q = np.array(initial if initial is not None else initial_guess(bearing, loads), dtype=float)
    lam = np.full((nrow, zmax), 1 if control == "inner" else 0, dtype=np.int64)
    xb = np.zeros((nrow, zmax, 2))
    kmat = np.zeros((5, 5))
    ballout = np.zeros((nrow, zmax, 12))
    status, its, rn, bconv = kn.solve_ring(rows, loads.as_array(), float(abs(speed)), CONTROLS[control], q, lam, xb,
                                           kmat, ballout, TOL_BALL, TOL_RING, MAXIT_BALL, MAXIT_RING,
                                           _scale(loads, rows))
    messages = {0: "converged", 1: "no equilibrium found within the iteration limit",
                2: "singular stiffness: no ball carries load in some direction, the bearing cannot carry "
                   "this load (e.g. an axial load that pulls a single angular contact row apart)",
                3: "the only equilibrium puts a loaded contact past the groove bottom of an angular contact "
                   "row (negative contact angle, where the ring has its low shoulder): add axial load or a "
                   "second row"}
    msg = messages[int(status)]
    if status == 0 and not bconv:
        msg = "ring converged but a ball's equilibrium did not"
    converged = status == 0 and bool(bconv)
    balls = ball_table(rows, ballout, xb, lam, float(abs(speed)))
    return StaticResult(bearing=bearing, loads=loads, speed=float(speed), control=control, converged=converged,
                        status=msg, iterations=int(its), residual=float(rn), displacement=q.copy(),
                        stiffness=kmat.copy(), balls=balls, rows_params=rows)


def ball_table(rows: np.ndarray, ballout: np.ndarray, xb: np.ndarray, lam: np.ndarray, omega: float) -> dict:
    """Per-ball quantities from the kernel's output arrays (SI), including Jones' ball speeds."""
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
            kin = kn.kinematics(si, ci, so, co, gam)
            ctrl = int(lam[r, j])
            wm, wr, beta = kin[3 * ctrl] * omega, kin[3 * ctrl + 1] * omega, kin[3 * ctrl + 2]
            cols["row"].append(r)
            cols["azimuth_rad"].append(par[kn.P_PSI0] + 2 * math.pi * j / z)
            cols["inner_contact_angle_rad"].append(math.atan2(si, ci))
            cols["outer_contact_angle_rad"].append(math.atan2(so, co))
            cols["inner_load_N"].append(bo[2])
            cols["outer_load_N"].append(bo[3])
            cols["inner_max_pressure_Pa"].append(par[kn.P_CPI] * bo[2] ** (1 / 3))
            cols["outer_max_pressure_Pa"].append(par[kn.P_CPO] * bo[3] ** (1 / 3))
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
    converged: np.ndarray  #: (n,) bool
    iterations: np.ndarray  #: (n,) int
    residual: np.ndarray  #: (n,) [N]


def solve_many(bearing, loads: np.ndarray, speeds: np.ndarray, control: str = "outer") -> BatchResult:
    """Solve many operating points, each started from the previous solution (warm start).

    Parameters
    ----------
    loads : float[n, 5]  (Fa, Fr_y, Fr_z, M_y, M_z) [N, N·m] per point
    speeds : float[n]  inner-ring speeds [rad/s]
    control : raceway control as in :func:`solve`

    Neighbouring points in the order given share their solutions as starting points (the
    compiled loop of :func:`bearingsim.statics._batch.run_batch`, with a tangent predictor and a
    cold restart when a warm start fails), so order the points along a path through the grid
    (e.g. speed fastest) for best speed.
    """
    from ._batch import run_batch

    loads = np.ascontiguousarray(loads, dtype=float)
    speeds = np.ascontiguousarray(speeds, dtype=float)
    if loads.ndim != 2 or loads.shape[1] != 5 or speeds.shape != (loads.shape[0],):
        raise InputError("loads", f"expected loads (n, 5) and speeds (n,), got {loads.shape} and {speeds.shape}",
                         "give one (Fa, Fr_y, Fr_z, M_y, M_z) row and one speed per point")
    if not (np.isfinite(loads).all() and np.isfinite(speeds).all()):
        raise InputError("loads", "non-finite load or speed", "give finite values")
    if control not in CONTROLS:
        raise InputError("control", f"unknown raceway control {control!r}", "use outer, inner or auto")
    out = run_batch(bearing, loads, speeds, control)
    return BatchResult(out["q"], out["k"], out["converged"], out["iterations"], out["residual"])
