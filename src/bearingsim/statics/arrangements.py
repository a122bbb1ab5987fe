"""Bearing sets and double-row units on a rigid shaft and a rigid housing.

A :class:`BearingSystem` is a list of single-row angular contact (or deep-groove) rows,
each with its axial position, its orientation and an axial preload offset, sharing one
inner ring (the shaft) and one outer ring (the housing).  The quasi-static model is the
Jones–Harris model of :mod:`bearingsim.statics._kernels` applied to every row at once
(Harris & Kotzalas 2007 vol. 2 ch. 3 "bearing systems"; [S0] eq. 13 summed over rows):

* row plane of row k at axial position x_k, orientation s_k = ±1 (−1 mirrors the contact
  angle; in a back-to-back (DB, "O") pair the row at −L/2 has s = +1 and the row at +L/2
  has s = −1 so that the lines of action diverge outwards; face-to-face (DF, "X") is the
  opposite; tandem (DT) has both rows s = +1),
* axial offset e_k of the inner groove centres in the row's local axial direction
  (positive = interference): a preload applied by clamping the rings of an opposed set
  is an offset e in every row,
* loads (Fa, Fr_y, Fr_z, M_y, M_z) [N, N·m] on the inner ring, acting at the system's
  ``load_point`` (axial position [m] measured from the system centre).  The kernels place
  the origin at the load point, so the displacements and the 5×5 stiffness of a
  :class:`~bearingsim.statics.jones_harris.StaticResult` refer to the load point;
  :func:`row_results` gives the displacements at each row plane.

Preload given as a force F₀ [N] is converted to the offset e by solving, at rest and
without external load, "axial load carried by the rows of orientation +1 = F₀" (brentq on e;
for a symmetric pair this is the single-row thrust relation, [S0] eqs. 3–5).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from scipy.optimize import brentq

from ..contact import hertz
from ..errors import InputError
from ..geometry import BallBearing, Row, row_vectors
from . import _kernels as kn

ARRANGEMENTS = {
    # name: orientation of the row at −L/2, orientation of the row at +L/2
    "DB": (1.0, -1.0),
    "DF": (-1.0, 1.0),
    "DT": (1.0, 1.0),
}
#: maximum contact pressure [Pa] above which a preload is rejected as unrealistic.  ISO 76
#: limits the static pressure of ball bearings to 4.2 GPa; 5 GPa is well beyond any preload.
MAX_PRELOAD_PRESSURE = 5.0e9


@dataclass(frozen=True)
class BearingSystem:
    """Rows of balls on one rigid shaft and one rigid housing (a bearing set or a double-row unit).

    Parameters
    ----------
    name : str
    rows : tuple[Row, ...]
    load_point : float  [m]  axial position where the external loads act, from the system centre
    arrangement : str  ``"DB"``, ``"DF"``, ``"DT"`` or ``"custom"``
    preload : float  [N]  preload force per row the offsets were computed for (0 when given as offsets)
    dynamic_load_rating : float  [N]  basic dynamic load rating C of the whole unit (0 when unknown)
    notes : dict  source of every number
    """

    name: str
    rows: tuple
    load_point: float = 0.0
    arrangement: str = "custom"
    preload: float = 0.0
    dynamic_load_rating: float = 0.0
    notes: dict = field(default_factory=dict, compare=False, hash=False)

    kind = "bearing_system"

    def __post_init__(self):
        rows = tuple(self.rows)
        object.__setattr__(self, "rows", rows)
        if len(rows) < 1:
            raise InputError("rows", "a bearing system needs at least one row", "add [[rows]] tables")
        if not math.isfinite(self.load_point):
            raise InputError("load_point", f"must be finite, got {self.load_point!r}", 'e.g. "10.4 mm"')
        # rows must not overlap: two ball sets closer than the larger ball diameter would intersect
        for i in range(len(rows)):
            for j in range(i + 1, len(rows)):
                gap = abs(rows[i].position - rows[j].position)
                need = max(rows[i].bearing.ball_diameter, rows[j].bearing.ball_diameter)
                if gap < need:
                    raise InputError("rows", f"rows {i} and {j} overlap: their planes are {gap * 1e3:.4g} mm apart, "
                                     f"less than the ball diameter {need * 1e3:.4g} mm",
                                     "give row positions (or row_spacing) at least one ball diameter apart")
        self._check_preload_pressure()

    # ---- attributes shared with BallBearing (used by the CLI and by jones_harris) --------
    @property
    def pitch_diameter(self) -> float:
        return self.rows[0].bearing.pitch_diameter

    @property
    def ball_diameter(self) -> float:
        return self.rows[0].bearing.ball_diameter

    @property
    def ball_count(self) -> int:
        return int(sum(r.bearing.ball_count for r in self.rows))

    @property
    def free_contact_angle(self) -> float:
        return self.rows[0].bearing.free_contact_angle

    def summary(self) -> dict:
        """Main data in SI, for printing and JSON."""
        return {
            "name": self.name, "type": self.kind, "arrangement": self.arrangement,
            "load_point_m": self.load_point, "preload_N": self.preload,
            "dynamic_load_rating_N": self.dynamic_load_rating,
            "rows": [{"bearing": r.bearing.name, "position_m": r.position, "orientation": int(r.orientation),
                      "axial_offset_m": r.axial_offset, **r.bearing.summary()} for r in self.rows],
        }

    # ---- kernel interface ----------------------------------------------------------------
    def row_vectors(self) -> np.ndarray:
        """Kernel parameter vectors float[nrow, NPAR] (the rows protocol, :mod:`bearingsim.geometry`); the
        kernel origin is the load point."""
        return row_vectors(self)

    @cached_property
    def _k0(self) -> np.ndarray:
        """Stiffness at rest without external load (5×5) [SI]."""
        rows = self.row_vectors()
        zmax = int(rows[:, kn.P_Z].max())
        q = np.zeros(5)
        res = np.zeros(5)
        kmat = np.zeros((5, 5))
        kn.ring_assemble(rows, q, 0.0, kn.CONTROL_OUTER, np.zeros((len(rows), zmax), dtype=np.int64),
                         np.zeros((len(rows), zmax, 2)), np.zeros(5), res, kmat,
                         np.zeros((len(rows), zmax, 12)), 1e-12, 60)
        return kmat

    def initial_guess(self, loads) -> np.ndarray:
        """Start of the ring Newton [m, rad]: linear estimate with the unloaded stiffness when the set is
        preloaded, else the thrust-model deflection of the rows that face the axial load."""
        q = np.zeros(5)
        k0 = self._k0
        f = loads.as_array()
        if np.all(np.isfinite(k0)) and np.linalg.cond(k0) < 1e12 and np.all(np.diag(k0) > 0):
            q = np.linalg.solve(k0, f)
            amax = max(r.bearing.total_curvature_distance for r in self.rows)
            dm = self.pitch_diameter
            scale = max(np.max(np.abs(q[:3])), np.max(np.abs(q[3:])) * 0.5 * dm)
            if scale > 0.02 * amax:
                q *= 0.02 * amax / scale
            return q
        from .axial import solve_thrust

        sgn = 1.0 if loads.fa >= 0 else -1.0
        facing = [r for r in self.rows if r.orientation == sgn] or list(self.rows)
        b = facing[0].bearing
        fr = math.hypot(loads.fr_y, loads.fr_z)
        mr = math.hypot(loads.m_y, loads.m_z) / (0.5 * b.pitch_diameter)
        fa_eq = (abs(loads.fa) + 0.5 * (fr + mr) * math.tan(max(b.free_contact_angle, 0.1))) / len(facing) + 1.0
        if b.kind == "angular_contact":
            q[0] = sgn * (solve_thrust(b, fa_eq).axial_deflection - facing[0].axial_offset)
        return q

    # ---- preload ---------------------------------------------------------------------------
    def row_axial_loads(self, q: np.ndarray, speed: float = 0.0) -> np.ndarray:
        """Axial load carried by each row [N] (positive: compressing the row in its own direction)."""
        return np.array([rl[0] * r.orientation for rl, r in zip(_row_forces(self, q, speed), self.rows)])

    def rest_preload(self) -> np.ndarray:
        """Axial load of every row at rest without external load [N] (the preload)."""
        from .jones_harris import Loads, solve

        res = solve(self, Loads(), 0.0)
        if not res.converged:
            return np.full(len(self.rows), np.nan)
        return np.array([rl[0] * r.orientation for rl, r in zip(res.row_forces, self.rows)])

    def _check_preload_pressure(self):
        if not any(r.axial_offset > 0 for r in self.rows):
            return
        # worst case: an offset taken entirely by one row's balls (q = 0 start of the set)
        for i, r in enumerate(self.rows):
            if r.axial_offset <= 0:
                continue
            b = r.bearing
            par = dataclasses.replace(r, position=0.0, orientation=1.0, first_ball_azimuth=0.0).vector()
            a1, a2 = par[kn.P_DX0] + par[kn.P_AXOFF], par[kn.P_DR0]
            dn = math.hypot(a1, a2) - (par[kn.P_RI] + par[kn.P_RO])
            if dn <= 0:
                continue
            ki, ko, kn_ = b.contact_constants
            qball = hertz.load_from_approach(kn_, dn)
            p = hertz.max_pressure_from_load(max(par[kn.P_CPI], par[kn.P_CPO]), qball)
            if p > MAX_PRELOAD_PRESSURE:
                raise InputError("preload", f"row {i}: an axial offset of {r.axial_offset * 1e6:.4g} µm makes the "
                                 f"balls penetrate the raceways by {dn * 1e6:.4g} µm (contact pressure "
                                 f"{p / 1e9:.3g} GPa, beyond any realistic preload; ISO 76 allows 4.2 GPa static)",
                                 "give a smaller preload or preload_offset (typically a few µm to tens of µm)")


def _row_forces(system, q, speed=0.0, result=None):
    """Per row: the load the row carries (Fa, Fy, Fz, My, Mz) about the kernel origin [N, N·m]
    (minus the sum of its ball forces on the inner ring), from one kernel pass over the row's balls at q."""
    rows = system.row_vectors()
    out = []
    for k in range(rows.shape[0]):
        par = rows[k:k + 1]
        z = int(par[0, kn.P_Z])
        lam = np.zeros((1, z), dtype=np.int64)
        xb = np.zeros((1, z, 2))
        if result is not None:
            sel = result.balls["row"] == k
            lam[0, :] = result.balls["inner_control"][sel]
            xb[0, :, 0] = result.balls["x1_m"][sel]
            xb[0, :, 1] = result.balls["x2_m"][sel]
        res = np.zeros(5)
        control = kn.CONTROL_INNER if (result is not None and result.control == "inner") else kn.CONTROL_OUTER
        if result is not None and result.control == "auto":
            control = kn.CONTROL_AUTO
        kn.ring_assemble(par, np.asarray(q, dtype=float), float(abs(speed)), control, lam, xb, np.zeros(5), res,
                         np.zeros((5, 5)), np.zeros((1, z, 12)), 1e-12, 60)
        out.append(-res)
    return out


def offset_for_preload(bearing_rows, force: float) -> float:
    """Offset e [m] (equal in every row) giving the preload ``force`` [N] at rest (brentq on e)."""
    if not (math.isfinite(force) and force > 0):
        raise InputError("preload", f"must be a positive force, got {force!r} N", 'e.g. preload = "5400 N"')
    orient = {r.orientation for r in bearing_rows}
    if len(orient) < 2:
        raise InputError("preload", "all rows face the same way (tandem): they cannot be preloaded against "
                         "each other", "preload an opposed set (DB or DF) or give axial offsets per row")
    from .jones_harris import Loads, solve

    def carried(e):
        sys_ = BearingSystem("preload", tuple(dataclasses.replace(r, axial_offset=e) for r in bearing_rows))
        res = solve(sys_, Loads(), 0.0)
        if res.status_code == 8:
            return 0.0  # the rows just touch (or not at all): no ball loaded, no preload
        if not res.converged:
            raise InputError("preload", f"no equilibrium at rest with an offset of {e * 1e6:.4g} µm",
                             "check the row geometry and the preload")
        # the row loads the solve summed from its own balls (row_axial_loads at res.displacement, no re-run)
        fa = [rl[0] * r.orientation for rl, r in zip(res.row_forces, sys_.rows)]
        return float(sum(f for f, r in zip(fa, bearing_rows) if r.orientation > 0))

    # bracket: from contact at the clearance upwards, doubling from the single-row thrust deflection at
    # the preload, up to the offset that reaches MAX_PRELOAD_PRESSURE in one row
    from .axial import solve_thrust

    lo, hi = 0.0, math.inf
    for r in bearing_rows:
        lo_r, hi_r = _offset_limits(r.bearing)
        lo = max(lo, lo_r)
        hi = min(hi, hi_r)
    hi *= 1.0 - 1e-9
    b0 = bearing_rows[0].bearing
    step = solve_thrust(b0, force).axial_deflection if b0.kind == "angular_contact" else 1e-6
    e = min(lo + max(step, 1e-9), hi)
    while True:
        try:
            f_e = carried(e)
        except InputError:
            f_e = math.inf  # no equilibrium: beyond a sensible offset, keep it as the upper bracket
        if f_e >= force:
            break
        if e >= hi:
            raise InputError("preload", f"{force:.4g} N is beyond any realistic preload for this row geometry "
                             f"(it would exceed {MAX_PRELOAD_PRESSURE / 1e9:.3g} GPa contact pressure; "
                             f"the limit is about {f_e:.4g} N)", "give a smaller preload")
        lo = e
        step *= 2.0
        e = min(lo + max(step, 1e-9), hi)
    hi = e

    def g(x):
        try:
            return carried(x) - force
        except InputError:
            return math.inf

    if lo >= hi:
        return hi
    return brentq(g, lo, hi, xtol=1e-15, rtol=1e-12)


#: former private name (the readers in bearingsim.io and the map used it)
_preload_offset = offset_for_preload


def _offset_limits(b: BallBearing) -> tuple[float, float]:
    """(offset at first contact, offset reaching MAX_PRELOAD_PRESSURE) of one row at q = 0 [m]."""
    par = b.row_vectors()[0]
    rsum = par[kn.P_RI] + par[kn.P_RO]
    dx0, dr0 = par[kn.P_DX0], par[kn.P_DR0]
    _, _, kn_ = b.contact_constants
    qmax = (MAX_PRELOAD_PRESSURE / max(par[kn.P_CPI], par[kn.P_CPO])) ** 3
    dn = hertz.approach_from_load(kn_, qmax)
    lo = math.sqrt(max(rsum**2 - dr0**2, 0.0)) - dx0
    hi = math.sqrt((rsum + dn) ** 2 - dr0**2) - dx0
    return max(lo, 0.0), hi


#: the largest row spacing or load-point distance of a bearing set, in pitch diameters of its rows [-]: beyond it
#: the rows are two supports of a shaft, not one set (the ring equilibrium of a set then is ill-conditioned:
#: moments of 1e30 mm arms)
MAX_SPAN_PER_PITCH = 100.0


def make_system(row_bearing: BallBearing, arrangement: str = "DB", row_spacing: float | None = None,
                preload: float | None = None, preload_offset: float | None = None, load_point: float = 0.0,
                name: str | None = None, dynamic_load_rating: float | None = None,
                notes: dict | None = None) -> BearingSystem:
    """Two identical rows in a DB, DF or DT arrangement (a spindle pair or a double-row unit).

    Parameters
    ----------
    row_bearing : BallBearing  geometry of one row
    arrangement : ``"DB"`` (back-to-back, O), ``"DF"`` (face-to-face, X), ``"DT"`` (tandem)
    row_spacing : float  [m]  distance between the row planes (default: the bearing width, as for a
        pair of single bearings mounted side by side)
    preload : float  [N]  preload force per row at rest, or
    preload_offset : float  [m]  total axial interference of the set, shared equally by the two rows
    load_point : float  [m]  axial position of the load from the centre between the rows
    dynamic_load_rating : float  [N]  of the unit; default 2^0.7 C of one row (ISO 281:2007 eq. for a
        bearing with i = 2 rows, C = i^0.7 C₁) when the row has a rating
    """
    arr = str(arrangement).upper()
    if arr not in ARRANGEMENTS:
        raise InputError("arrangement", f"unknown arrangement {arrangement!r}", "use DB, DF or DT (or [[rows]])")
    if row_spacing is None:
        row_spacing = row_bearing.width
    if not (math.isfinite(row_spacing) and row_spacing > 0):
        raise InputError("row_spacing", f"must be positive, got {row_spacing!r} m",
                         'e.g. row_spacing = "18.2 mm" (needed when the row has no width)')
    if row_spacing < row_bearing.ball_diameter:
        raise InputError("row_spacing", f"{row_spacing * 1e3:.4g} mm is less than the ball diameter "
                         f"{row_bearing.ball_diameter * 1e3:.4g} mm: the two rows of balls would overlap",
                         "give the distance between the row planes (at least the ball diameter; the bearing width "
                         "for two separate bearings)")
    if row_spacing > MAX_SPAN_PER_PITCH * row_bearing.pitch_diameter:
        raise InputError("row_spacing", f"{row_spacing * 1e3:.4g} mm is more than {MAX_SPAN_PER_PITCH:g} pitch "
                         "diameters: not one bearing set (model two supports of a shaft instead)",
                         "check the value and its unit, e.g. row_spacing = \"18.2 mm\"")
    if preload is not None and preload_offset is not None:
        raise InputError("preload", "both preload and preload_offset are given", "give only one of them")
    s1, s2 = ARRANGEMENTS[arr]
    rows = [Row(row_bearing, -0.5 * row_spacing, s1), Row(row_bearing, 0.5 * row_spacing, s2)]
    e = 0.0
    if preload_offset is not None:
        if not math.isfinite(preload_offset):
            raise InputError("preload_offset", f"must be finite, got {preload_offset!r}", 'e.g. "10 um"')
        if arr == "DT" and preload_offset != 0:
            raise InputError("preload_offset", "a tandem pair cannot be preloaded against itself",
                             "use DB or DF, or give [[rows]] with axial offsets")
        e = 0.5 * preload_offset
    rows = [dataclasses.replace(r, axial_offset=e) for r in rows]
    pl = 0.0
    if preload is not None and preload != 0:
        if arr == "DT":
            raise InputError("preload", "a tandem pair cannot be preloaded against itself",
                             "use DB or DF, or give [[rows]] with axial offsets")
        e = offset_for_preload(rows, preload)
        rows = [dataclasses.replace(r, axial_offset=e) for r in rows]
        pl = preload
    if dynamic_load_rating is None:
        dynamic_load_rating = 2.0**0.7 * row_bearing.dynamic_load_rating
    return BearingSystem(name=name or f"{row_bearing.name} {arr}", rows=tuple(rows), load_point=load_point,
                         arrangement=arr, preload=pl, dynamic_load_rating=dynamic_load_rating, notes=notes or {})


#: double-row unit: the same object as a set of two rows
DoubleRow = make_system


# ---- results ---------------------------------------------------------------------------------
def row_results(result) -> list[dict]:
    """Per-row results of a solved system (SI): loads carried, displacements at the row plane, balls.

    Each dict: ``row``, ``bearing``, ``position_m`` (from the system centre), ``orientation``,
    ``axial_offset_m``, ``loads`` (fa_N, fr_y_N, fr_z_N, m_y_N_m, m_z_N_m: the load the row carries,
    moments about the row plane; fa positive along +x), ``axial_load_N`` (positive when the row is
    compressed in its own direction), ``displacement`` (axial, y, z at the row plane, tilts),
    ``loaded_balls``, ``lifted_off`` (True when no ball of the row carries load), and ``balls``.
    The row figures are those :func:`~bearingsim.statics.jones_harris.solve` stored on the result
    (``result.rows``); this adds each row's ball table.
    """
    from .jones_harris import ball_dicts

    rows = result.rows if getattr(result, "rows", None) is not None else row_summaries(result)
    b = result.balls
    return [{**d, "balls": ball_dicts(b, np.nonzero(b["row"] == d["row"])[0])} for d in rows]


def row_summaries(result) -> list[dict]:
    """The figures of :func:`row_results` without the per-row ball tables (the report step of
    :func:`~bearingsim.statics.jones_harris.solve`): the row loads are ``result.row_forces``, summed in the
    solve from its own ball forces (re-computed with one kernel pass per row only for a result without them)."""
    system = result.bearing
    rows, x0 = system.rows, system.load_point
    q = np.asarray(result.displacement, dtype=float)
    forces = result.row_forces if getattr(result, "row_forces", None) is not None \
        else _row_forces(system, q, result.speed, result)
    out = []
    b = result.balls
    rowof, pi, po = b["row"], b["inner_max_pressure_Pa"], b["outer_max_pressure_Pa"]
    # at speed the outer contacts stay loaded by the centrifugal force: a row lifts off when no ball touches
    # the inner raceway
    nball = np.bincount(rowof, minlength=len(rows)).tolist()
    nload = np.bincount(rowof[b["inner_load_N"] > 0], minlength=len(rows)).tolist()
    q = q.tolist()  # Python floats (the same doubles: the arithmetic below gives the same bits, faster)
    for k, (row, f) in enumerate(zip(rows, np.asarray(forces, dtype=float).tolist())):
        xk = row.position - x0  # row plane from the kernel origin (the load point)
        has_balls = nball[k] > 0
        sel = rowof == k if has_balls else None
        nloaded = nload[k]
        out.append({
            "row": k,
            "bearing": row.bearing.name,
            "position_m": float(row.position),
            "orientation": int(row.orientation),
            "axial_offset_m": float(row.axial_offset),
            "loads": {"fa_N": float(f[0]), "fr_y_N": float(f[1]), "fr_z_N": float(f[2]),
                      "m_y_N_m": float(f[3] + xk * f[2]), "m_z_N_m": float(f[4] - xk * f[1])},
            "axial_load_N": float(f[0] * row.orientation),
            "radial_load_N": float(math.hypot(f[1], f[2])),
            "displacement": {"axial_m": float(q[0]), "y_m": float(q[1] + q[4] * xk), "z_m": float(q[2] - q[3] * xk),
                             "gamma_y_rad": float(q[3]), "gamma_z_rad": float(q[4])},
            "loaded_balls": nloaded,
            "lifted_off": nloaded == 0,
            "max_inner_pressure_Pa": float(pi[sel].max()) if has_balls else 0.0,
            "max_outer_pressure_Pa": float(po[sel].max()) if has_balls else 0.0,
        })
    return out


# ---- TOML ------------------------------------------------------------------------------------
#: the TOML reader moved to :mod:`bearingsim.io.arrangement` (files are read at the edge); its names are
#: forwarded on first use (a module-level import would be a cycle: io.arrangement imports this module)
_FORWARDED = ("_KEYS", "_ROW_KEYS", "_row_bearing", "arrangement_from_dict")


def __getattr__(name: str):
    if name in _FORWARDED:
        from ..io import arrangement as _reader

        return getattr(_reader, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
