"""Array layouts of the dynamic model: the contract between the model builder, the numba kernels and the outputs.

A leaf module (imports nothing from bearingsim): every index used to address the dynamic model's plain
float arrays is named and documented here once.  The kernels (:mod:`.forces`), the builder
(:mod:`.model`), the elastic cage (:mod:`.cage`), the integrators (:mod:`.integrate`) and the run
(:mod:`.run`) import the names from here.  Frame: inertial, x the bearing axis, ψ = 0 on +y, outer
ring fixed.  All values SI.

Related layouts owned elsewhere: the statics row-parameter vector (``P_*``, one row per ball row:
ball diameter, pitch diameter, contact constants, groove-centre positions ...) of the statics
kernels, and the lubrication-parameter vector (``L_*``) of :mod:`bearingsim.contact.slices`, which
``Model.lubs`` holds per contact (row r: inner 2r, outer 2r + 1).

State vector y (float64)
------------------------
::

    [0:5]                      q   = (δx, δy, δz, γy, γz) of the inner ring       [m, m, m, rad, rad]
    [5:10]                     q̇                                                    [m/s, rad/s]
    [10 + 9k : 10 + 9k + 9]    ball k: r(3) [m], v(3) [m/s], ω(3) [rad/s]
    [OC + 12c : OC + 12c + 12] cage c: r(3) [m], v(3) [m/s], θ, βy, βz [rad], θ̇, β̇y, β̇z [rad/s]
    [M_c : M_c + n_c]          η  of elastic cage c (mass-normalised modal coordinates [kg^½ m])
    [M_c + n_c : M_c + 2 n_c]  η̇ of elastic cage c [kg^½ m/s]

with OC = N_RING + N_BALL n_balls (``Model.cage_offset``), M_0 = OC + N_CAGE n_cages and
M_c = ``cp[c, C_MODE0]``.  The offsets inside each block are the ``R_*``, ``B_*`` and ``K_*``
names below; the inner ring's tilts and the cage's orientation are R_y(γy) R_z(γz) and
R_y(βy) R_z(βz) R_x(θ).
"""

from __future__ import annotations

# ---- state: block sizes -------------------------------------------------------------------
N_RING = 10  #: inner-ring states (q, q̇)
N_BALL = 9  #: states per ball (r, v, ω)
N_CAGE = 12  #: rigid-body states per cage (r, v, θ, βy, βz, θ̇, β̇y, β̇z)

#: names of the inner ring's five degrees of freedom, in the order of q, of the loads
#: (Fa, Fr_y, Fr_z, M_y, M_z) and of the output dimension ``dof``
DOF = ("x", "y", "z", "gamma_y", "gamma_z")

# ---- state: offsets inside the inner-ring block --------------------------------------------
R_Q = 0  #: q = (δx, δy, δz, γy, γz) [m, m, m, rad, rad]
R_QD = 5  #: q̇ [m/s, m/s, m/s, rad/s, rad/s]

# ---- state: offsets inside a ball block ----------------------------------------------------
B_POS = 0  #: centre position (3) [m]
B_VEL = 3  #: centre velocity (3) [m/s]
B_OMEGA = 6  #: angular velocity, inertial frame (3) [rad/s]

# ---- state: offsets inside a cage block ----------------------------------------------------
K_POS = 0  #: centre displacement (3) [m] (the axial pocket-plane position C_XP is added)
K_VEL = 3  #: centre velocity (3) [m/s]
K_THETA = 6  #: rotation angle about the bearing axis θ [rad]
K_BETA_Y = 7  #: tilt βy [rad]
K_BETA_Z = 8  #: tilt βz [rad]
K_THETA_DOT = 9  #: spin rate θ̇ [rad/s]
K_BETA_Y_DOT = 10  #: tilt rate β̇y [rad/s]
K_BETA_Z_DOT = 11  #: tilt rate β̇z [rad/s]

# ---- per-row extra contact constants: Model.rowx[row, X_*] --------------------------------
X_CAI = 0  #: inner contact-ellipse semi-major axis per N^(1/3): a = X_CAI Q^(1/3) [m/N^(1/3)]
X_CBI = 1  #: inner semi-minor axis per N^(1/3) [m/N^(1/3)]
X_CAO = 2  #: outer semi-major axis per N^(1/3) [m/N^(1/3)]
X_CBO = 3  #: outer semi-minor axis per N^(1/3) [m/N^(1/3)]
X_RDI = 4  #: radius of the deformed contact surface across the groove, inner, 2 f D / (2 f + 1) [m]
X_RDO = 5  #: the same, outer [m]
X_XGI = 6  #: global x of the inner groove-centre circle in the ring frame [m]
X_XGO = 7  #: global x of the outer groove-centre circle [m]
X_RGO = 8  #: radius of the outer groove-centre circle [m]
X_EPI = 9  #: effective modulus E' of ball / inner ring [Pa]
X_EPO = 10  #: E' of ball / outer ring [Pa]
X_RXI = 11  #: rolling-direction radius R_x at the free contact angle, inner [m]
X_RXO = 12  #: R_x, outer [m]
X_RYI = 13  #: transverse radius R_y, inner [m]
X_RYO = 14  #: R_y, outer [m]
X_KCI = 15  #: K_i^(1/3), cube root of the inner load–deflection constant (for Q^(1/3)) [N^(1/3)/m^(1/2)]
X_KCO = 16  #: K_o^(1/3), outer [N^(1/3)/m^(1/2)]
NROWX = 17  #: length of a rowx row

# ---- global parameters: Model.gp[G_*] ------------------------------------------------------
G_MR = 0  #: inner ring (hub) mass [kg]
G_ITR = 1  #: inner ring transverse moment of inertia [kg m²]
G_IPR = 2  #: inner ring polar moment of inertia [kg m²]
G_GX = 3  #: gravity vector (3 values, G_GX..G_GX + 2) [m/s²]
G_ALPHA = 6  #: Hunt–Crossley damping constant α [s/m]
G_TRAC = 7  #: traction model code (TRACTION_MODELS): 0 none, 1 regularised Coulomb (test stand-in), 2 sliced kernel
G_MU0 = 8  #: Coulomb coefficient of the stand-in model [-]
G_S0 = 9  #: slide-roll ratio of the stand-in's regularisation [-]
G_NSL = 10  #: slices per contact ellipse [-]
G_XL = 11  #: axial position of the load point [m]
G_W0 = 12  #: shaft speed at t = 0 [rad/s]
G_W1 = 13  #: shaft speed after the ramp [rad/s]
G_TRAMP = 14  #: ramp duration [s] (0: constant speed G_W0)
G_RING_FIXED = 15  #: 1: inner ring held at its initial position (tests), 0: free
G_VREF = 16  #: speed regularising friction directions at zero sliding [m/s]
G_CAGE_ON = 17  #: 1: ball–cage contacts on, 0: off
G_ORBIT_HELD = 18  #: 1: every ball's azimuth held fixed (frictionless constraint, zero reference), 0: free
NGP = 19  #: length of gp

#: traction model name → code in gp[G_TRAC]
TRACTION_MODELS = {"none": 0, "coulomb": 1, "slices": 2}

# ---- per-cage parameters: Model.cp[cage, C_*] ----------------------------------------------
C_MASS = 0  #: cage mass [kg]
C_IP = 1  #: polar moment of inertia [kg m²]
C_IT = 2  #: transverse moment of inertia [kg m²]
C_XP = 3  #: axial position of the pocket centres (cage frame) [m]
C_RP = 4  #: radius of the pocket centres [m]
C_CLR = 5  #: pocket clearance (pocket radius − ball radius) [m]
C_KC = 6  #: ball–pocket Hertz constant K_c, Q = K_c δ^1.5 [N/m^1.5]
C_MU = 7  #: ball–pocket friction coefficient [-]
C_GUIDE = 8  #: guidance code (GUIDANCE): 0 ball-guided, 1 outer-ring land, 2 inner-ring land
C_RLAND = 9  #: land radius [m]
C_CLAND = 10  #: radial land clearance [m]
C_KLAND = 11  #: land contact constant [N/m^1.5]
C_MULAND = 12  #: land friction coefficient [-]
C_PSI0 = 13  #: azimuth of pocket 0 [rad]
C_Z = 14  #: number of pockets [-]
C_BALL0 = 15  #: index of the first ball of this cage [-]
C_NMODES = 16  #: modal coordinates n_c (0: rigid cage) [-]
C_SHAPE = 17  #: pocket shape code (POCKET_SHAPES): 0 sphere, 1 cylinder
C_POCKET = 18  #: sphere: half-angle of the opening about the radial axis [rad]; cylinder: half-length [m]
C_MODE0 = 19  #: index in the state of the cage's first modal coordinate M_c [-]
NCP = 20  #: length of a cp row

#: pocket shape name → code in cp[C_SHAPE]
POCKET_SHAPES = {"sphere": 0, "cylinder": 1}
#: cage guidance name → code in cp[C_GUIDE]
GUIDANCE = {"balls": 0, "outer-land": 1, "inner-land": 2}
GUIDANCE_INNER_LAND = GUIDANCE["inner-land"]

# ---- the right-hand side's per-ball memo and record (``memo`` of forces.rhs; one row per ball, then the ring's)
#: columns per row: [0] 1 when the row holds an outer contact, [1:10] the ball's nine states it was computed for,
#: [10:22] its result (force and moment on the ball, force and moment on the outer ring), then the record
MEMO_W = 28
#: columns MEMO_INNER : MEMO_INNER + 6 of a ball's row: its inner contact's reaction on the inner ring at the last
#: evaluation, force [N] and moment about the ring centre [N·m] (the ring's Jacobian columns are derived from
#: their differences in the balls' sweeps: integrate.jacobian.ring_columns)
MEMO_INNER = 22
#: the ring's row (index n_balls), columns: I_p Ω / I_t [1/s] (the tilts' gyroscopic coupling), the inner ring's
#: contact moment about its centre (3) [N·m], 1 when the ring's columns may be derived from the balls' (no
#: inner-land cage, azimuths free) else 0, then the time [s] and the ring's ten states of the evaluation (with the
#: balls' states in their rows' columns 1:10, what the record was made at) — all of the last evaluation
MR_GYRO, MR_MOMENT, MR_DERIVE, MR_T, MR_Y = 0, 1, 4, 5, 6

# ---- elastic cage modes: Model.cage_modes[cage, mode, CM_*] --------------------------------
CM_OMEGA = 0  #: natural angular frequency ω_k [rad/s]
CM_DAMP = 1  #: 2 ζ_k ω_k [1/s]
CM_SHAPE0 = 2  #: start of the pocket shapes: pocket j at CM_SHAPE0 + 6 j: u_x, u_y, u_z [m], ρ_x, ρ_y, ρ_z [rad]
#: per unit η, cage frame

# ---- per-ball diagnostics: diag[ball, D_*] (outputs of forces.rhs when diag has rows) -----
D_QI = 0  #: ball–inner raceway normal load [N]
D_QO = 1  #: ball–outer raceway normal load [N]
D_AI = 2  #: inner contact angle [rad]
D_AO = 3  #: outer contact angle [rad]
D_DI = 4  #: inner approach (negative: gap) [m]
D_DO = 5  #: outer approach [m]
D_WM = 6  #: orbital speed [rad/s]
D_WR = 7  #: spin speed relative to the orbiting frame (Jones sign) [rad/s]
D_SRI = 8  #: slide-roll ratio at the inner contact centre [-]
D_SRO = 9  #: slide-roll ratio at the outer contact centre [-]
D_PI = 10  #: power loss of the inner contact [W]
D_PO = 11  #: power loss of the outer contact [W]
D_QC = 12  #: ball–pocket normal load [N]
D_PC = 13  #: power loss of the ball–pocket contact [W]
D_BETA = 14  #: spin-axis pitch angle β [rad]
NDB = 15  #: columns of diag

# ---- global diagnostics: gdiag[GD_*] -------------------------------------------------------
GD_FA = 0  #: applied axial load Fa [N]
GD_FRY = 1  #: applied radial load Fr_y [N]
GD_FRZ = 2  #: applied radial load Fr_z [N]
GD_MY = 3  #: applied moment M_y at the load point [N m]
GD_MZ = 4  #: applied moment M_z at the load point [N m]
GD_TQI = 5  #: moment of the contact forces on the inner ring about its axis [N m]
GD_TQO = 6  #: moment of the contact forces on the outer ring about x [N m]
GD_PI = 7  #: total power loss at the ball–inner raceway contacts [W]
GD_PO = 8  #: total power loss at the ball–outer raceway contacts [W]
GD_PC = 9  #: total power loss at the ball–pocket contacts [W]
GD_PL = 10  #: power loss at the cage guiding lands [W]
GD_W = 11  #: shaft speed [rad/s]
GD_EPOT = 12  #: elastic energy stored in all contacts [J]
GD_ECAGE = 13  #: elastic strain energy of the cages' modes [J]
NDG = 14  #: length of gdiag


def ball_offset(k: int) -> int:
    """Index in the state of ball k's first value."""
    return N_RING + N_BALL * k


def cage_offset(n_balls: int, c: int = 0) -> int:
    """Index in the state of cage c's first value (``Model.cage_offset`` for c = 0)."""
    return N_RING + N_BALL * n_balls + N_CAGE * c


# ---- the parts of one evaluation of the right-hand side (``phase`` of ``forces._rhs``)
#: everything; the balls with active[k] ≠ 0 only (the multirate refinement's masked right-hand side,
#: ``forces.rhs_masked``); the raceway contacts of the balls with active[k] = 0 only, into a work array kept for the
#: next phase; the rest of the evaluation after that (the other balls, the cages, the rings, the reduction) — the
#: last two make f in two parts (``forces.rhs_split``, run beside the refinement: ``integrate.multirate``)
PHASE_ALL = 0
PHASE_MASKED = 1
PHASE_OTHERS = 2
PHASE_REST = 3
