"""State layout and bodies of the dynamic bearing model (Sakaguchi & Shibutani [S1], Table 3).

Bodies (inertial frame, x the bearing axis, ψ = 0 on +y, outer ring fixed):

* inner ring: translations (x, y, z) and tilts (γy, γz) about y and z, spin about its
  own axis prescribed, Ω(t) [rad/s]; orientation R = R_y(γy) R_z(γz) (small tilts are
  those of the statics, :mod:`bearingsim.statics._kernels`, to first order);
* every ball: centre position (3) and velocity (3) and angular velocity (3) in the
  inertial frame (a sphere's orientation does not enter the forces);
* one rigid cage per row: centre position (3), velocity (3), orientation
  R_y(βy) R_z(βz) R_x(θ) (θ, βy, βz), spin rate θ̇ and tilt rates (β̇y, β̇z).
  An elastic cage adds n_c modal coordinates η and their rates η̇ (mode synthesis, see
  :mod:`.cage`), stored after all bodies so that every other offset stays fixed.

The state vector and every parameter array are laid out as documented in :mod:`.layout` (the
names ``N_*``, ``X_*``, ``G_*``, ``C_*`` are re-exported here).  Geometry comes from the kernel row
parameters of the statics (layout ``P_*`` of the statics kernels): per row the inner groove
curvature centres lie on a circle of radius P_RIC at local axial position
ξ = P_XIC + P_AXOFF in the inner-ring frame, the outer ones on a fixed circle of radius
P_RIC − P_DR0 at ξ = P_XIC − P_DX0 (global x = P_XROW + P_SIGN ξ).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..contact.slices import deformed_surface_radius
from ..errors import InputError
from ..statics import layout as kn  # the row-parameter layout (P_*)
from . import layout as ly


@dataclass
class Model:
    """Arrays describing one bearing system for the kernels (all SI)."""

    rows: np.ndarray  #: float[nrow, NPAR] statics row parameters
    rowx: np.ndarray  #: float[nrow, NROWX]
    ball_row: np.ndarray  #: int[nb] row of every ball
    ball_psi: np.ndarray  #: float[nb] nominal azimuth [rad]
    gp: np.ndarray  #: float[NGP]
    cp: np.ndarray  #: float[ncage, NCP]
    names: dict = field(default_factory=dict)
    lubs: np.ndarray | None = None  #: float[2 nrow, L_SIZE] lubrication parameters (inner, outer per row)
    #: float[ncage, n_max_modes, 2 + 6 Z] modal data of elastic cages (see :func:`.forces.rhs`); None: rigid
    cage_modes: np.ndarray | None = None
    #: per cage the :class:`bearingsim.cage_modes.CageModes` behind ``cage_modes`` (None: rigid)
    cage_fe: list | None = None
    #: per cage its normal-stress shapes float[n_modes, E, 2, 8] [Pa per unit η] (None: rigid)
    cage_stress: list | None = None

    def __post_init__(self):
        if self.cage_modes is None:
            self.cage_modes = np.zeros((self.cp.shape[0], 0, 2))

    def lub_array(self) -> np.ndarray:
        if self.lubs is None:
            from ..contact import slices

            self.lubs = np.zeros((2 * self.rows.shape[0], slices.L_SIZE))
        return self.lubs

    @property
    def n_balls(self) -> int:
        return int(self.ball_row.shape[0])

    @property
    def n_cages(self) -> int:
        return int(self.cp.shape[0])

    @property
    def n_modes(self) -> int:
        """Modal coordinates of all elastic cages."""
        return int(self.cp[:, ly.C_NMODES].sum()) if self.n_cages else 0

    @property
    def n_state(self) -> int:
        return ly.N_RING + ly.N_BALL * self.n_balls + ly.N_CAGE * self.n_cages + 2 * self.n_modes

    @property
    def cage_offset(self) -> int:
        return ly.N_RING + ly.N_BALL * self.n_balls

    def ball_slice(self, k: int) -> slice:
        o = ly.N_RING + ly.N_BALL * k
        return slice(o, o + ly.N_BALL)

    def cage_slice(self, c: int) -> slice:
        o = self.cage_offset + ly.N_CAGE * c
        return slice(o, o + ly.N_CAGE)

    def mode_slices(self, c: int) -> tuple[slice, slice]:
        """(η, η̇) of cage c in the state (empty for a rigid cage)."""
        o, n = int(self.cp[c, ly.C_MODE0]), int(self.cp[c, ly.C_NMODES])
        return slice(o, o + n), slice(o + n, o + 2 * n)


def pocket_geometry(ball_diameter: float, shape: str = "sphere", opening_deg: float = 20.0) -> tuple[int, float]:
    """(shape code, shape parameter) of the pocket surface ([S1] §3.2), for ``cp[C_SHAPE]``, ``cp[C_POCKET]``.

    ``shape="sphere"`` (default): a spherical pocket of radius D/2 + clearance, open toward the
    raceways within ``opening_deg`` of the cage's radial axis; it locates a ball-guided cage radially
    and axially; parameter = the opening half-angle [rad].  ``shape="cylinder"``: a cylindrical pocket
    of radius D/2 + clearance with a radial axis and a half-length 0.2 D; it does not locate the cage
    radially (use land guidance); parameter = the half-length [m].  The contact routine finds the
    surface point nearest the ball centre in closed form (:func:`bearingsim.dynamics.forces.pocket_point`).
    """
    if shape == "sphere":
        return ly.POCKET_SHAPES[shape], math.radians(opening_deg)
    if shape == "cylinder":
        return ly.POCKET_SHAPES[shape], 0.2 * ball_diameter
    raise InputError("cage.pocket_shape", f"unknown pocket shape {shape!r}", "use sphere or cylinder")


def row_extras(bearing, rows: np.ndarray) -> np.ndarray:
    """Per-row contact constants (ellipse size, conformal radius, groove-centre circles) float[nrow, NROWX]
    (layout :mod:`.layout`), from the rows of the bearing (the rows protocol, :mod:`bearingsim.geometry`) and
    their kernel vectors ``rows`` (the groove-centre positions of :mod:`bearingsim.statics.layout`)."""
    bearings = [r.bearing for r in bearing.rows]
    if len(bearings) != rows.shape[0]:
        raise InputError("bearing", f"{len(bearings)} rows but {rows.shape[0]} kernel vectors",
                         "build the kernel vectors with bearing.row_vectors()")
    rx = np.zeros((rows.shape[0], ly.NROWX))
    for r, b in enumerate(bearings):
        par = rows[r]
        ci = b.contact(1.0, True)
        co = b.contact(1.0, False)
        d = b.ball_diameter
        rx[r, ly.X_CAI] = ci.a
        rx[r, ly.X_CBI] = ci.b
        rx[r, ly.X_CAO] = co.a
        rx[r, ly.X_CBO] = co.b
        fi, fo = b.inner_conformity, b.outer_conformity
        rx[r, ly.X_RDI] = deformed_surface_radius(d, fi * d)
        rx[r, ly.X_RDO] = deformed_surface_radius(d, fo * d)
        rx[r, ly.X_XGI] = kn.inner_groove_centre_axial(par)
        rx[r, ly.X_XGO] = kn.outer_groove_centre_axial(par)
        rx[r, ly.X_RGO] = kn.outer_groove_centre_radius(par)
        rx[r, ly.X_EPI] = b.effective_modulus
        rx[r, ly.X_EPO] = b.effective_modulus
        rxi, ryi = b.raceway_radii(True)
        rxo, ryo = b.raceway_radii(False)
        rx[r, ly.X_RXI], rx[r, ly.X_RYI], rx[r, ly.X_RXO], rx[r, ly.X_RYO] = rxi, ryi, rxo, ryo
        rx[r, ly.X_KCI] = np.cbrt(par[kn.P_KI])
        rx[r, ly.X_KCO] = np.cbrt(par[kn.P_KO])
    return rx


def cage_contact_constant(ball_diameter: float, ball_material, cage_modulus: float | None = None,
                          cage_poisson: float | None = None) -> float:
    """Hertz constant K [N/m^1.5] of a ball on a flat cage surface, Q = K δ^1.5; cage modulus [Pa] and
    Poisson ratio default to ``cage_steel`` of :mod:`bearingsim.materials`.

    Sphere on a flat (Johnson 1985 eq. 4.22): Q = (4/3) E* R^½ δ^(3/2) with R = D/2 and
    1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂, i.e. Q = (2/3) E′ R^½ δ^(3/2) with the effective modulus E′ = 2 E* of
    :func:`bearingsim.contact.hertz.effective_modulus`.  The conformal cylindrical pocket is stiffer; this
    is a lower bound chosen so that the pocket contact is not the stiffest time scale.
    """
    from ..contact.hertz import effective_modulus
    from ..materials import LIBRARY

    steel = LIBRARY["cage_steel"]
    cage_modulus = steel.youngs_modulus if cage_modulus is None else cage_modulus
    cage_poisson = steel.poisson_ratio if cage_poisson is None else cage_poisson
    e_eff = effective_modulus(ball_material.youngs_modulus, ball_material.poisson_ratio, cage_modulus, cage_poisson)
    return 2.0 / 3.0 * e_eff * math.sqrt(0.5 * ball_diameter)


def build_model(bearing, *, ring_mass: float = 1.0, ring_inertia: tuple[float, float] | None = None,
                gravity=(0.0, 0.0, 0.0), damping_alpha: float = 0.0, traction: str = "none",
                mu0: float = 0.06, s0: float = 0.005, n_slices: int = 8, load_point: float = 0.0,
                speed: tuple[float, float, float] = (0.0, 0.0, 0.0), ring_fixed: bool = False,
                cage: bool = True, cage_mass: float | None = None, pocket_clearance: float | None = None,
                cage_mu: float = 0.06, guidance: str = "balls", land_clearance: float = 2e-4,
                cage_stiffness: float | None = None, v_ref: float = 1e-3, pocket_shape: str = "sphere",
                lubricant=None, temperature: float = 333.15, lubrication: dict | None = None,
                cage_modes: int = 0, cage_ring: dict | None = None, modal_damping: float | None = None,
                ball_orbit: str = "free") -> Model:
    """Build the kernel arrays of a bearing (the rows protocol of :mod:`bearingsim.geometry`: one row, a set or a unit).

    Parameters (SI): ring_mass [kg]; ring_inertia (transverse, polar) [kg m²] (default:
    a thin ring of the inner-race radius); gravity [m/s²]; damping_alpha Hunt–Crossley α
    [s/m]; traction "none" | "coulomb" | "slices"; mu0, s0 of the Coulomb stand-in;
    lubricant (library name, path or Lubricant) and temperature [K] with ``lubrication``
    keyword options of :func:`bearingsim.contact.slices.pack_lubrication_parameters`
    for traction "slices"; load_point axial position of the load point [m]; speed (Ω₀, Ω₁, ramp) [rad/s, s];
    cage options: mass [kg] (default 10 % of the ball set), pocket clearance [m]
    (default 2 % of D), friction μ = 0.06 ([S1] §3.2), guidance "balls",
    "outer-land" or "inner-land" with a radial land clearance [m]; cage_modes: elastic modes per
    cage (0: rigid), with ``cage_ring`` overrides of the assumed ring [SI] and ``modal_damping`` ζ
    (:func:`.cage.attach_elastic_cages`).  ball_orbit "free" | "held": "held" holds every ball at its
    azimuth by a frictionless constraint (a zero reference: no orbital motion, :func:`.forces.rhs`).
    """
    if ball_orbit not in ("free", "held"):
        raise InputError("ball_orbit", f"unknown option {ball_orbit!r}", "use free or held")
    if traction not in ly.TRACTION_MODELS:
        raise InputError("traction", f"unknown traction model {traction!r}", "use none, coulomb or slices")
    if guidance not in ly.GUIDANCE:
        raise InputError("cage.guidance", f"unknown guidance {guidance!r}", "use balls, outer-land or inner-land")
    if not ring_mass > 0:
        raise InputError("inner_ring.mass", f"must be positive, got {ring_mass!r} kg", 'e.g. "3 kg"')
    rows = np.ascontiguousarray(bearing.row_vectors(), dtype=float)
    nrow = rows.shape[0]
    rowx = row_extras(bearing, rows)
    brs = [r.bearing for r in bearing.rows]
    ball_row, ball_psi = [], []
    for r in range(nrow):
        z = int(rows[r, kn.P_Z])
        for j in range(z):
            ball_row.append(r)
            ball_psi.append(rows[r, kn.P_PSI0] + 2 * math.pi * j / z)
    ball_row = np.array(ball_row, dtype=np.int64)
    gp = np.zeros(ly.NGP)
    gp[ly.G_MR] = ring_mass
    rin = 0.5 * (rows[0, kn.P_DM] - rows[0, kn.P_D])
    if ring_inertia is None:
        it, ip = 0.5 * ring_mass * rin**2, ring_mass * rin**2
    else:
        it, ip = ring_inertia
    if not (it > 0 and ip > 0):
        raise InputError("inner_ring.inertia", "moments of inertia must be positive", 'e.g. "0.01 kg*m^2"')
    gp[ly.G_ITR], gp[ly.G_IPR] = it, ip
    gp[ly.G_GX:ly.G_GX + 3] = gravity
    gp[ly.G_ALPHA] = damping_alpha
    gp[ly.G_TRAC] = ly.TRACTION_MODELS[traction]
    gp[ly.G_MU0], gp[ly.G_S0], gp[ly.G_NSL] = mu0, s0, n_slices
    gp[ly.G_XL] = load_point
    gp[ly.G_W0], gp[ly.G_W1], gp[ly.G_TRAMP] = speed
    gp[ly.G_RING_FIXED] = 1.0 if ring_fixed else 0.0
    gp[ly.G_VREF] = v_ref
    gp[ly.G_CAGE_ON] = 1.0 if cage else 0.0
    gp[ly.G_ORBIT_HELD] = 1.0 if ball_orbit == "held" else 0.0
    cp = np.zeros((nrow, ly.NCP))
    b0 = 0
    d0 = brs[0].ball_diameter
    clr = 0.02 * d0 if pocket_clearance is None else pocket_clearance
    for r in range(nrow):
        b = brs[r]
        par = rows[r]
        z = int(par[kn.P_Z])
        d = par[kn.P_D]
        mball = par[kn.P_MASS]
        mc = 0.1 * z * mball if cage_mass is None else cage_mass
        rp = 0.5 * par[kn.P_DM]
        cp[r, ly.C_MASS] = mc
        cp[r, ly.C_IP] = mc * rp**2
        cp[r, ly.C_IT] = 0.5 * mc * rp**2
        # pocket centres at the axial position of the ball centres in the centred position
        s = par[kn.P_SIGN]
        lo = par[kn.P_RO]
        a0 = math.atan2(par[kn.P_DX0], par[kn.P_DR0]) if (par[kn.P_DX0] != 0 or par[kn.P_DR0] != 0) else 0.0
        cp[r, ly.C_XP] = rowx[r, ly.X_XGO] + s * lo * math.sin(a0)
        cp[r, ly.C_RP] = rowx[r, ly.X_RGO] + lo * math.cos(a0)
        cp[r, ly.C_CLR] = clr
        cp[r, ly.C_KC] = cage_contact_constant(d, b.ball_material) if cage_stiffness is None else cage_stiffness
        cp[r, ly.C_MU] = cage_mu
        cp[r, ly.C_GUIDE] = ly.GUIDANCE[guidance]
        if guidance == "outer-land":
            cp[r, ly.C_RLAND] = rp + 0.3 * d
        elif guidance == "inner-land":
            cp[r, ly.C_RLAND] = rp - 0.3 * d
        cp[r, ly.C_CLAND] = land_clearance
        cp[r, ly.C_KLAND] = cp[r, ly.C_KC]
        cp[r, ly.C_MULAND] = cage_mu
        cp[r, ly.C_PSI0] = par[kn.P_PSI0]
        cp[r, ly.C_Z] = z
        cp[r, ly.C_BALL0] = b0
        cp[r, ly.C_SHAPE], cp[r, ly.C_POCKET] = pocket_geometry(d, pocket_shape)
        b0 += z
    lubs = None
    if traction == "slices":
        from ..contact import slices

        if lubricant is None:
            raise InputError("lubricant", "the sliced-ellipse traction needs a lubricant",
                             'e.g. lubricant = "iso-vg-68"')
        lubs = np.zeros((2 * nrow, slices.L_SIZE))
        for r in range(nrow):
            lubs[2 * r] = slices.pack_lubrication_parameters(lubricant, temperature, rowx[r, ly.X_EPI],
                                                             rowx[r, ly.X_RXI], rowx[r, ly.X_RYI],
                                                             **(lubrication or {}))
            lubs[2 * r + 1] = slices.pack_lubrication_parameters(lubricant, temperature, rowx[r, ly.X_EPO],
                                                                 rowx[r, ly.X_RXO], rowx[r, ly.X_RYO],
                                                                 **(lubrication or {}))
    model = Model(rows=rows, rowx=rowx, ball_row=ball_row, ball_psi=np.array(ball_psi), gp=gp, cp=cp,
                  names={"bearing": getattr(bearing, "name", "bearing")}, lubs=lubs)
    if cage_modes or cage_ring or modal_damping is not None:
        from .cage import DEFAULT_MODAL_DAMPING, attach_elastic_cages

        if not cage_modes:
            raise InputError("cage.n_modes", "cage ring data or modal damping given for a rigid cage",
                             "set n_modes (e.g. 20) or drop the elastic-cage keys")
        attach_elastic_cages(model, cage_modes, cage_ring,
                             DEFAULT_MODAL_DAMPING if modal_damping is None else modal_damping,
                             cage_mass_given=cage_mass is not None)
        if cage_stiffness is None:  # the pockets touch the ring's material (e.g. a polymer cage), not steel
            for r in range(nrow):
                ring = model.cage_fe[r].fe.ring
                cp[r, ly.C_KC] = cp[r, ly.C_KLAND] = cage_contact_constant(rows[r, kn.P_D], brs[r].ball_material,
                                                                     ring.young_modulus, ring.poisson)
    return model


def initial_state(model: Model, static=None, speed: float | None = None, rates: np.ndarray | None = None) -> np.ndarray:
    """State vector near steady state from a quasi-static solution.

    ``rates`` (optional, float[n_state], from :func:`quasi_static_rates`): the time derivative of the
    quasi-static positions (inner ring q, ball centres) at t = 0; it is added to the velocities, so that the
    start moves with the quasi-static solution of time-varying loads (a clean start, docs/dynamics.md).
    Without it the ring starts at rest (and the balls with their orbital velocity only).

    ``static`` is a :class:`bearingsim.statics.jones_harris.StaticResult` of the same
    bearing: ring displacement q, per-ball centres (x1_m, x2_m from the outer groove
    centre in the ball's axial–radial plane), Jones orbital speed ω_m, spin speed ω_R
    and pitch angle β.  The ball's absolute angular velocity is ω_m e_x plus the Jones
    spin ω_R (cos β e_x − s sin β e_r) (Jones 1960; statics kernel docstring: spin
    vector ω_R (cos β, −sin β) in the local (ξ, r) plane of a row with s = +1, relative
    to the cage; a mirrored row, s = −1, mirrors this pseudo-vector).  The
    cage is centred and turns at the mean orbital speed.  Without ``static`` the balls sit
    on the line of the groove centres of the centred position, at rest.
    """
    y = np.zeros(model.n_state)
    rows = model.rows
    omega = model.gp[ly.G_W0] if speed is None else speed
    if static is not None:
        y[0:5] = static.displacement
    for k in range(model.n_balls):
        r = model.ball_row[k]
        par = rows[r]
        s = par[kn.P_SIGN]
        psi = model.ball_psi[k]
        if static is not None:
            bt = static.balls
            x1, x2 = bt["x1_m"][k], bt["x2_m"][k]
            wm = bt["orbital_speed_rad_s"][k] * (1.0 if omega >= 0 else -1.0)
            wr = bt["spin_speed_rad_s"][k] * (1.0 if omega >= 0 else -1.0)
            beta = bt["pitch_angle_rad"][k]
            psi = bt["azimuth_rad"][k]
        else:
            a0 = math.atan2(par[kn.P_DX0], par[kn.P_DR0])
            x1, x2 = par[kn.P_RO] * math.sin(a0), par[kn.P_RO] * math.cos(a0)
            wm = wr = beta = 0.0
        xg = model.rowx[r, ly.X_XGO]
        rg = model.rowx[r, ly.X_RGO]
        xb = xg + s * x1
        rb = rg + x2
        cps, sps = math.cos(psi), math.sin(psi)
        o = ly.N_RING + ly.N_BALL * k
        y[o:o + 3] = (xb, rb * cps, rb * sps)
        y[o + 3:o + 6] = (0.0, -wm * rb * sps, wm * rb * cps)
        # angular velocity is a pseudo-vector: mirroring the row (s = -1) keeps its axial
        # component and reverses the radial one
        y[o + 6] = wm + wr * math.cos(beta)
        y[o + 7] = -s * wr * math.sin(beta) * cps
        y[o + 8] = -s * wr * math.sin(beta) * sps
    for c in range(model.n_cages):
        o = model.cage_offset + ly.N_CAGE * c
        cp = model.cp[c]
        b0, z = int(cp[ly.C_BALL0]), int(cp[ly.C_Z])
        wm = 0.0
        if static is not None:
            wm = float(np.mean(static.balls["orbital_speed_rad_s"][b0:b0 + z])) * (1.0 if omega >= 0 else -1.0)
        y[o + 9] = wm
    if rates is not None:
        rates = np.asarray(rates, dtype=float)
        if rates.shape != y.shape or not np.all(np.isfinite(rates)):
            raise InputError("rates", f"need {y.shape[0]} finite values, got shape {rates.shape}",
                             "pass the result of quasi_static_rates(model, ...)")
        y[ly.R_QD:ly.R_QD + 5] += rates[0:5]
        for k in range(model.n_balls):
            o = ly.N_RING + ly.N_BALL * k
            y[o + ly.B_VEL:o + ly.B_VEL + 3] += rates[o + ly.B_POS:o + ly.B_POS + 3]
    if model.gp[ly.G_ORBIT_HELD] > 0.0:  # balls held in azimuth: no orbital velocity, the cage at rest
        for k in range(model.n_balls):
            o = ly.N_RING + ly.N_BALL * k
            rb = math.hypot(y[o + 1], y[o + 2])
            ey, ez = -y[o + 2] / rb, y[o + 1] / rb
            vt = y[o + 4] * ey + y[o + 5] * ez
            y[o + 4] -= vt * ey
            y[o + 5] -= vt * ez
        for c in range(model.n_cages):
            y[model.cage_offset + ly.N_CAGE * c + 9] = 0.0
    return y


def _static_loads(loads, t: float, load_point: float):
    """:class:`bearingsim.statics.jones_harris.Loads` of a load history at t, the moments moved from the load
    point (axial position ``load_point`` [m]) to the origin of the bearing's kernel rows (as in
    :func:`bearingsim.dynamics.run.build`)."""
    from ..statics import jones_harris as jh

    f = loads.at(t)
    return jh.Loads(fa=f[0], fr_y=f[1], fr_z=f[2], m_y=f[3] - load_point * f[2], m_z=f[4] + load_point * f[1])


def quasi_static_rates(model: Model, bearing, loads, static, speed: float, load_point: float = 0.0,
                       control: str = "outer", t0: float = 0.0, h: float | None = None) -> np.ndarray:
    """d/dt of the quasi-static positions at t0 (inner ring q, ball centres), float[n_state] [m/s, rad/s].

    The quasi-static solution q_s(t) of the loads F(t) (Jones–Harris statics, ``static`` = q_s(t0)) moves
    with the loads; a start at q_s(t0) at rest is not on that trajectory: with q = q_s + e the ring's
    equation M ë + K e = −M q̈_s starts with e = 0, ė = −q̇_s and rings with amplitude |q̇_s|/ω_n in every
    mode ω_n (a kick that leaves the lightly damped tilt mode ringing).  Starting with q̇ = q̇_s(t0) removes it to
    first order (what remains is forced by q̈_s, amplitude |q̈_s|/ω_n², smaller by ω_load/ω_n).  To first order
    q̇_s = K⁻¹ dF/dt with K the static stiffness; here it is the one-sided three-point difference of converged solves,
    q̇_s ≈ (−3 q_s(t0) + 4 q_s(t0 + h) − q_s(t0 + 2h)) / 2h with h = ``loads.rate_step()`` (O(h²) error; only
    t ≥ t0, so a load table that starts rising at t0 gives its right-hand rate; the solves start from
    q_s(t0), tolerance far below the change of q over h), which also gives the balls' centre velocities in the
    groove (their positions x1, x2 follow the contact angles).  Ball spins and the cage are left at their
    quasi-static values at t0.  Returns zeros when the loads do not change at t0 (e.g. a ramp-in).
    """
    from ..statics import jones_harris as jh

    if h is None:
        h = loads.rate_step()
    if not (h > 0 and math.isfinite(h)):
        raise InputError("h", f"must be a positive time step, got {h!r} s", "omit it (default from the loads)")
    rates = np.zeros(model.n_state)
    if not np.any(loads.at(t0 + h) - loads.at(t0)) and not np.any(loads.at(t0 + 2 * h) - loads.at(t0)):
        return rates
    w = abs(speed)
    states = []
    for tt in (t0, t0 + h, t0 + 2 * h):
        res = jh.solve(bearing, _static_loads(loads, tt, load_point), w, control=control,
                       initial=np.asarray(static.displacement, dtype=float))
        if not res.converged:
            raise InputError("loads", f"no quasi-static equilibrium at t = {tt:.6g} s ({res.status}) for the "
                             "consistent start", 'set start = "rest" or give loads the bearing can carry')
        states.append(initial_state(model, res, speed))
    dy = (-3.0 * states[0] + 4.0 * states[1] - states[2]) / (2.0 * h)
    rates[0:5] = dy[0:5]
    for k in range(model.n_balls):
        o = ly.N_RING + ly.N_BALL * k
        rates[o:o + 3] = dy[o:o + 3]
    return rates


def tolerance_vectors(model: Model, tol: float = 1e-6, length_scale: float = 1e-3,
                      speed_scale: float = 1.0, rate_scale: float = 100.0) -> tuple[np.ndarray, np.ndarray]:
    """Per-component (atol, rtol) of the state for the integrator's error control.

    Positions and angles get an absolute tolerance only (tol × length_scale [m], tol ×
    length_scale / pitch radius [rad]): contact approaches of ~10 µm sit on ball
    coordinates of ~30 mm, so a relative tolerance on positions would be meaningless.
    Velocities get tol × speed_scale [m/s] absolute plus tol relative; angular
    velocities tol × rate_scale [rad/s] plus tol relative.  The relative part of a ball's or a
    cage's velocity or angular velocity is taken of the whole vector's magnitude
    (:func:`error_vectors`), that of the ring's rates of each component.
    """
    n = model.n_state
    atol = np.empty(n)
    rtol = np.zeros(n)
    rpitch = 0.5 * float(model.rows[0, kn.P_DM])
    alen = tol * length_scale
    aang = alen / rpitch
    atol[0:3] = alen
    atol[3:5] = aang
    atol[5:8] = tol * speed_scale
    atol[8:10] = tol * speed_scale / rpitch
    rtol[5:10] = tol
    for k in range(model.n_balls):
        o = ly.N_RING + ly.N_BALL * k
        atol[o:o + 3] = alen
        atol[o + 3:o + 6] = tol * speed_scale
        atol[o + 6:o + 9] = tol * rate_scale
        rtol[o + 3:o + 9] = tol
    for c in range(model.n_cages):
        o = model.cage_offset + ly.N_CAGE * c
        atol[o:o + 3] = alen
        atol[o + 3:o + 6] = tol * speed_scale
        atol[o + 6:o + 9] = aang
        atol[o + 9:o + 12] = tol * rate_scale
        rtol[o + 3:o + 6] = tol
        rtol[o + 9:o + 12] = tol
        # modal coordinates (mass-normalised: a pocket moves by ≈ η / √m_cage)
        eta, etad = model.mode_slices(c)
        sm = math.sqrt(model.cp[c, ly.C_MASS])
        atol[eta] = alen * sm
        atol[etad] = tol * speed_scale * sm
        rtol[etad] = tol
    return atol, rtol


def error_vectors(model: Model) -> np.ndarray:
    """int64[n_state, 2]: (start, stop) of the vector whose Euclidean norm each state component's relative
    tolerance is measured on (:func:`bearingsim.dynamics.integrate.common.error_scale`).

    The velocity [m/s] and the angular velocity [rad/s] of every ball and cage are vectors (the cage's rates
    (θ̇, β̇y, β̇z), its angular velocity to first order in the tilt): their three components share one error
    scale, tol × (scale + |v|), the same in any frame.  Per component, a ball's
    velocity or spin component that passes through zero as the ball orbits would be held to tol × scale, several
    times tighter than its neighbours for no physical reason, and in the slow cells of the hub study such a
    component would hold the step.  Every other component (positions,
    the ring's rates, the cage's modal coordinates) is its own vector (i, i + 1).
    """
    n = model.n_state
    vec = np.empty((n, 2), dtype=np.int64)
    vec[:, 0] = np.arange(n)
    vec[:, 1] = np.arange(1, n + 1)

    def group(start):
        vec[start:start + 3, 0] = start
        vec[start:start + 3, 1] = start + 3

    for k in range(model.n_balls):
        o = ly.N_RING + ly.N_BALL * k
        group(o + ly.B_VEL)
        group(o + ly.B_OMEGA)
    for c in range(model.n_cages):
        o = model.cage_offset + ly.N_CAGE * c
        group(o + ly.K_VEL)
        group(o + ly.K_THETA_DOT)
    return vec


def describe_component(model: Model, i: int) -> str:
    """Name of state component i (for error messages: the body involved)."""
    if i < 10:
        return f"inner ring {ly.DOF[i % 5]}{' rate' if i >= 5 else ''}"
    if i < model.cage_offset:
        k = (i - ly.N_RING) // ly.N_BALL
        part = ("position", "velocity", "angular velocity")[((i - ly.N_RING) % ly.N_BALL) // 3]
        return f"ball {k} (row {int(model.ball_row[k])}) {part}: its raceway or pocket contacts"
    if i < model.cage_offset + ly.N_CAGE * model.n_cages:
        c = (i - model.cage_offset) // ly.N_CAGE
        return f"cage {c}: its pocket or land contacts"
    for c in range(model.n_cages):
        eta, etad = model.mode_slices(c)
        if eta.start <= i < etad.stop:
            return f"cage {c} elastic mode {(i - eta.start) % max(1, eta.stop - eta.start)}: its pocket contacts"
    return f"state component {i}"


def __getattr__(name: str):
    """The layout names (``model.N_RING``, ``model.C_MASS`` ...) are those of :mod:`.layout` (kept importable
    from here)."""
    if hasattr(ly, name) and name[:1].isupper():
        return getattr(ly, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
