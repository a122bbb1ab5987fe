"""Row-parameter layout and solver status codes of the quasi-static model: the contract between the bearing
geometry, the statics kernels, the dynamics and the outputs.

A leaf module (imports nothing): every index of the row-parameter vector and every status code is named and
documented here once.  :meth:`bearingsim.geometry.BallBearing.row_parameters` writes the vector, the numba
kernels of :mod:`bearingsim.statics._kernels` (which re-exports these names) and the dynamic model
(:mod:`bearingsim.dynamics.model`, :mod:`bearingsim.dynamics.forces`) read it.  All values SI.

Why here and not in a top-level ``core`` package: the vector is the statics model's input (Jones 1960;
Harris & Kotzalas 2007 vol. 2 ch. 3), the dynamic state has its own layout in :mod:`bearingsim.dynamics.layout`,
and ``bearingsim/statics/__init__.py`` is empty, so importing this module costs nothing more than the module.

Row-parameter vector (float64, length :data:`NPAR`; one vector per ball row, stacked as ``rows[k, P_*]``)
-------------------------------------------------------------------------------------------------------
Local frame of a row: ξ = s (x − x_row) axial, r radial; s = ±1 the row's orientation.  The groove
curvature centres: outer fixed, inner at (Δx₀ + e, Δr₀) from it in the centred position
(Harris & Kotzalas vol. 2 eqs. 3.22–3.26; [S0] eq. 6).

=============  ====  ==========================================================================  ============
name           idx   meaning                                                                     unit
=============  ====  ==========================================================================  ============
P_Z            0     number of balls Z (an integer stored as float)                              [-]
P_D            1     ball diameter D                                                             [m]
P_DM           2     pitch diameter d_m                                                          [m]
P_RI           3     (f_i − ½) D: distance ball centre – inner groove centre at zero load        [m]
P_RO           4     (f_o − ½) D: the same at the outer groove                                   [m]
P_KI           5     inner load–deflection constant K_i of Q = K δ^1.5 (Hertz)                   [N/m^1.5]
P_KO           6     outer load–deflection constant K_o                                          [N/m^1.5]
P_DX0          7     axial separation Δx₀ of the groove centres, centred position                [m]
P_DR0          8     radial separation Δr₀ of the groove centres (minus half the clearance)      [m]
P_RIC          9     radius of the inner groove-centre locus, d_m/2 + r_i cos α₀                  [m]
P_XIC          10    local axial position of the inner groove centre from the row plane          [m]
P_XROW         11    global axial position x_row of the row plane from the kernel origin         [m]
P_SIGN         12    orientation s = +1 or −1 (−1 mirrors the contact angle)                     [-]
P_MASS         13    ball mass m                                                                 [kg]
P_JB           14    ball polar moment of inertia J                                              [kg m²]
P_GRI          15    inner groove radius f_i D (arm of the friction moment)                      [m]
P_PSI0         16    azimuth ψ₀ of ball 0                                                        [rad]
P_CPI          17    inner p_max per Q^(1/3): p_max = CPI Q^(1/3)                                 [Pa/N^(1/3)]
P_CPO          18    outer p_max per Q^(1/3)                                                     [Pa/N^(1/3)]
P_CAI          19    inner a E(κ) per Q^(1/3) (raceway-control criterion, Jones 1960)             [m/N^(1/3)]
P_CAO          20    outer a E(κ) per Q^(1/3)                                                     [m/N^(1/3)]
P_AXOFF        21    axial preload offset e of the inner groove centres (local, + = interference) [m]
P_OROT         22    1: the outer ring turns at ω, the inner stands; 0: the inner ring turns       [-]
=============  ====  ==========================================================================  ============

Raceway control (argument ``control`` of the ring kernels): :data:`CONTROL_OUTER` (λ_o = 2, λ_i = 0),
:data:`CONTROL_INNER` (λ_o = λ_i = 1), :data:`CONTROL_AUTO` (per ball, Jones' criterion with a E(κ)).

Status codes
------------
:data:`STATUS` is the one table of solver status codes with their messages, used by
:func:`bearingsim.statics.jones_harris.solve` / ``solve_many``, the results' ``status`` text and the map
files' ``status`` variable (:data:`STATUS_SHORT`, its CF ``flag_values``/``flag_meanings``).  Codes 0, 1, 2, 3
and 6 come from the ring kernels; 4, 5, 7, 8 and 9 are added by the callers.
"""

from __future__ import annotations

# ---- row parameter layout (table in the module docstring) -------------------------------------------------
P_Z = 0  #: number of balls [-]
P_D = 1  #: ball diameter [m]
P_DM = 2  #: pitch diameter [m]
P_RI = 3  #: (f_i − 1/2) D [m]
P_RO = 4  #: (f_o − 1/2) D [m]
P_KI = 5  #: inner contact load–deflection constant [N/m^1.5]
P_KO = 6  #: outer contact load–deflection constant [N/m^1.5]
P_DX0 = 7  #: axial separation of the groove centres in the centred position [m]
P_DR0 = 8  #: radial separation of the groove centres in the centred position [m]
P_RIC = 9  #: radius of the inner groove-centre locus [m]
P_XIC = 10  #: local axial position of the inner groove centre from the row plane [m]
P_XROW = 11  #: global axial position of the row plane [m]
P_SIGN = 12  #: +1 or −1: orientation of the row [-]
P_MASS = 13  #: ball mass [kg]
P_JB = 14  #: ball polar moment of inertia [kg m²]
P_GRI = 15  #: inner groove radius f_i D (arm of the friction moment) [m]
P_PSI0 = 16  #: azimuth of ball 0 [rad]
P_CPI = 17  #: p_max = CPI Q^(1/3), inner [Pa/N^(1/3)]
P_CPO = 18  #: p_max = CPO Q^(1/3), outer [Pa/N^(1/3)]
P_CAI = 19  #: a E(κ) = CAI Q^(1/3), inner [m/N^(1/3)] (raceway-control criterion)
P_CAO = 20  #: a E(κ) = CAO Q^(1/3), outer [m/N^(1/3)]
P_AXOFF = 21  #: axial preload offset e of the inner groove centres (local) [m]
P_OROT = 22  #: 1 when the outer ring turns (inner ring standing), 0 when the inner ring turns [-]
NPAR = 23  #: length of the row-parameter vector

# ---- raceway control ----------------------------------------------------------------------------------------
CONTROL_OUTER = 0  #: outer-raceway control: λ_o = 2, λ_i = 0
CONTROL_INNER = 1  #: inner-raceway control: λ_o = λ_i = 1
CONTROL_AUTO = 2  #: per ball, the raceway with the larger friction moment controls (Jones 1960)

# ---- solver status codes ------------------------------------------------------------------------------------
STATUS_CONVERGED = 0
STATUS_ITERATION_LIMIT = 1
STATUS_SINGULAR = 2
STATUS_PAST_GROOVE_BOTTOM = 3
STATUS_BALL_NOT_CONVERGED = 4
STATUS_NOT_CONFIRMED = 5
STATUS_PAST_GROOVE_EDGE = 6
STATUS_INTERNAL_ERROR = 7
STATUS_FREE_RING = 8
STATUS_PAST_CAPACITY = 9

#: status code → message (results' ``status`` text, CLI output)
STATUS = {
    STATUS_CONVERGED: "converged",
    STATUS_ITERATION_LIMIT: "no equilibrium found within the iteration limit",
    STATUS_SINGULAR: "singular stiffness: no ball carries load in some direction, the bearing cannot carry "
                     "this load (e.g. an axial load that pulls a single angular contact row apart)",
    STATUS_PAST_GROOVE_BOTTOM: "the only equilibrium puts a loaded contact past the groove bottom of an angular "
                               "contact row (negative contact angle, where the ring has its low shoulder): add "
                               "axial load or a second row",
    STATUS_BALL_NOT_CONVERGED: "ring converged but a ball's equilibrium did not",
    STATUS_NOT_CONFIRMED: "the ring balance is not met when the balls are re-solved from scratch at the returned "
                          "displacement (the ball equilibrium is not unique here): not an equilibrium to report",
    STATUS_PAST_GROOVE_EDGE: "the only equilibrium found puts a loaded contact at a contact angle of 90° or more, "
                             "beyond the groove edge of the ring (outside the model): the load is beyond what the "
                             "bearing can carry",
    STATUS_INTERNAL_ERROR: "the solver failed on this point (internal error); see the log",
    STATUS_FREE_RING: "no ball carries load at the inner raceway (no load, or every ball lifted off by its "
                      "centrifugal force): the inner ring is free and its position is not determined",
    STATUS_PAST_CAPACITY: "load past what the bearing can carry in equilibrium: the ring displacement it calls "
                          "for carries a ball past the groove-curvature centres, where the contact and rolling "
                          "relations have no solution (residual NaN)",
}

#: status code → (short description for the map file's long_name, CF flag meaning)
STATUS_SHORT = {
    STATUS_CONVERGED: ("converged", "converged"),
    STATUS_ITERATION_LIMIT: ("iteration limit", "iteration_limit"),
    STATUS_SINGULAR: ("singular", "singular"),
    STATUS_PAST_GROOVE_BOTTOM: ("contact past groove bottom", "contact_past_groove_bottom"),
    STATUS_BALL_NOT_CONVERGED: ("a ball not converged", "ball_not_converged"),
    STATUS_NOT_CONFIRMED: ("not confirmed by the independent recomputation", "not_confirmed"),
    STATUS_PAST_GROOVE_EDGE: ("contact angle of 90 deg or more", "contact_past_groove_edge"),
    STATUS_INTERNAL_ERROR: ("internal error at this point", "internal_error"),
    STATUS_FREE_RING: ("free inner ring (no ball loaded)", "free_inner_ring"),
    STATUS_PAST_CAPACITY: ("load past capacity", "load_past_capacity"),
}

#: ``long_name`` of a map file's ``status`` variable
STATUS_LONG_NAME = ", ".join(f"{code} {short}" for code, (short, _) in STATUS_SHORT.items())


def status_cf_attributes() -> dict:
    """CF attributes of an integer ``status`` variable (CF conventions §3.5: flag_values, flag_meanings); the
    writer gives ``flag_values`` the variable's integer type."""
    return {"flag_values": list(STATUS_SHORT), "flag_meanings": " ".join(m for _, m in STATUS_SHORT.values())}


# ---- formulas on the row vector, written once ------------------------------------------------------------
# Plain Python on the vector (this module stays a leaf, without numba); :mod:`bearingsim.statics._kernels`
# compiles the same functions with numba for the ring assemblers, and Python callers (the dynamic model's
# builder) call them as they are: the same floating-point operations in the same order, so the same bits.


def inner_groove_centre_axial(par):
    """Global axial position of the inner groove-curvature centres of a row, ring centred [m].

    x_gi = x_row + s (ξ_ic + e): the inner groove centre lies at local axial position ξ_ic = r_i sin α₀ from
    the row plane, moved by the preload offset e (Harris & Kotzalas 2007 vol. 2 eqs. 3.22–3.26; [S0]
    eq. 6).  ``par``: a row-parameter vector (indices :data:`P_XROW`, :data:`P_SIGN`, :data:`P_XIC`,
    :data:`P_AXOFF`)."""
    return par[P_XROW] + par[P_SIGN] * (par[P_XIC] + par[P_AXOFF])


def outer_groove_centre_axial(par):
    """Global axial position of the (fixed) outer groove-curvature centres of a row [m].

    x_go = x_row + s (ξ_ic − Δx₀): Δx₀ axially from the inner ones in the centred position, without offset
    (Harris & Kotzalas 2007 vol. 2 eqs. 3.22–3.26)."""
    return par[P_XROW] + par[P_SIGN] * (par[P_XIC] - par[P_DX0])


def outer_groove_centre_radius(par):
    """Radius of the circle of the outer groove-curvature centres [m]: r_go = r_ic − Δr₀."""
    return par[P_RIC] - par[P_DR0]


def ball_speed_constants(par, omega_squared):
    """Gyroscopic and centrifugal constants of a row's balls at ring speed ω (omega_squared = ω² [rad²/s²]).

    Returns (c_g, c_f) [N, N]: c_g = J ω² d_m / D² and c_f = ½ m d_m ω², the force scales of the gyroscopic
    term G = M_g / D, M_g = J ω_R ω_m sin β, and of the centrifugal force F_c = ½ m d_m ω_m², which the ball
    kernel (:func:`bearingsim.statics._kernels.ball_eval`) multiplies by functions of Jones' speed ratios
    (Jones 1960; Harris & Kotzalas 2007 vol. 2 ch. 3; [S0] eqs. 11–12)."""
    d = par[P_D]
    dm = par[P_DM]
    return par[P_JB] * omega_squared * dm / (d * d), 0.5 * par[P_MASS] * dm * omega_squared
