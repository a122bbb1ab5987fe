"""The sliced contact ellipse: tangential forces of a lubricated ball–raceway contact.

[S1] (Sakaguchi & Shibutani, NTN Technical Review 87), section 3.1, eqs. 1–5:

1. The ellipse (semi-axes a along the transverse major axis, b along rolling) is cut
   into n slices of equal width 2a/n along the major axis.  Slice j, ξ = x/a ∈ [ξ_j, ξ_j+1],
   ξ_j = −1 + 2j/n, carries the Hertz pressure integrated over its area (seed eq. 1):
   the line load across the major axis is w(x) = (3Q/4a)(1 − x²/a²), so
       Q_j = Q [F(ξ_j+1) − F(ξ_j)],   F(ξ) = (3ξ − ξ³)/4,
   which sums to Q exactly.  The slice acts at the load centroid of its strip,
       x̄_j = a [Γ(ξ_j+1) − Γ(ξ_j)] / [F(ξ_j+1) − F(ξ_j)],   Γ(ξ) = (3/4)(ξ²/2 − ξ⁴/4),
   so that moments of the slice loads are exact for fields linear in x (e.g. pure spin
   with a constant μ: Σ μ Q_j |x̄_j| = 3μQa/8 exactly for even n).
2. Jones' method (Jones 1960; seed ref. 9): the points lie on the deformed contact
   surface, a circle of radius r_dev in the plane of the normal and the major axis;
   for a ball of diameter D in a groove of radius r_g, r_dev = 2 r_g D/(2 r_g + D) (the
   harmonic mean of the two radii).  Sign convention: r_dev > 0 when the surface's centre
   of curvature lies on the ball's side of the contact (+normal), as for both inner and
   outer grooves in the transverse plane; r_dev = +inf for a flat contact; r_dev < 0
   curves the other way.  The point of slice j is
       p_j = centre + x̄_j e_major + c x̄_j²/(1 + √(1 − c²x̄_j²)) n,   c = 1/r_dev,
   and its local normal n_j = √(1 − c²x̄_j²) n − c x̄_j e_major.
3. Sliding velocity of the ball surface against the race (seed eq. 3):
       v_s = v_ball + ω_ball × (p − c_ball) − [v_race + ω_race × (p − c_race)],
   projected on the slice's tangent plane.  The entraining (rolling) velocity is the mean
   surface velocity relative to the moving contact: u = ½(v_b + v_r) − v_c, with the
   contact point's velocity v_c = v_ball + Ω × (p − c_ball) and Ω = (r × v_ball)/|r|²,
   r = c_ball − c_race (the ball's orbital angular velocity about the race centre:
   exact when c_race is the point of the bearing axis in the ball's orbit plane; a small
   error of order (axial offset/radius)² × (D/d_m) otherwise).  Slide–roll ratio
   s = |v_s|/|u|.
4. Traction (seed eq. 2): F_j = −μ_j Q_j v_s/|v_s| on the ball, −F_j on the race, with
   μ_j from the boundary / fluid / mixed model chosen in ``lub`` (see
   :mod:`bearingsim.contact.traction`).
5. Rolling viscous resistance and oil-film force (seed eqs. 4–5): F_R,j from Zhou &
   Hoeprich (1991) eq. 17 (or the IR closed form) for a line contact of length 2a/n
   carrying Q_j, multiplied by φ_T φ_s and by the fluid weight w(Λ) (the paper assumes it
   exists only where a film is formed).  It acts on both surfaces against the rolling
   direction û = u/|u|; the pressure-centre shift adds P_1 = 2F_R R_x/R_1 on the ball
   (R_1 = |p − c_ball|, through the ball centre, no moment) and P_2 = 2F_R − P_1 on the
   race (through its centre of curvature, R_2 = 1/(1/R_x − 1/R_1)), in +û.  The four
   forces sum to zero (the film is massless).
6. Power lost [W] = Σ_j (μ_j Q_j |v_s,j| + 2 F_R,j |u_j|) ≥ 0 (the rolling term is the
   work of the pressure-centre moment N e = 2F_R R_x on the relative rolling, Zhou &
   Hoeprich 1991).

The normal (Hertz) force itself is not part of the output: the caller applies Q along
``normal``.  All quantities SI.

Speed (benchmarks/bench_slices.py).  The kernel evaluates the same formulae as the model
functions of :mod:`.ehl` and :mod:`.traction` (and as :func:`contact_traction_reference`, which
calls them; the tests hold the two to 1e-10, they agree to ~1e-14) in cheaper but equal forms:
slice loads, centroids and areas from running differences of their primitives F, G, H (slices
j and n−1−j are mirror images: one table entry per pair); the strips (and the Gauss rule's nodes) go
through the film law eight at a time, one per lane, with the exponentials and logarithms of the film
law and of the contact's film taken on all eight lanes by glibc's vector math library
(:mod:`.vecmath`, :func:`_film_lanes`; results within a few ulp of the scalar functions; the lanes take 20 %
off a hub step and 28 % off the Gauss rule against one slice at a time); the velocity
fields moved from the centre to each slice with constant cross-product matrices; the
Hamrock–Dowson films, regime map and Zhu–Cheng factor from shared logarithms, powers as
exp(c ln x); the Eyring argument x = ηγ̇/τ₀ carried as ln 2x = ln u_s + ln η(p̄) + const only
(:func:`_asinh_l2x`: asinh x = ln 2x for x ≥ 10⁶, error ≤ 2.5e-13 absolute, its asymptotic series in
1/x² for 10 ≤ x < 10⁶, asinh(e^(ln 2x − ln 2)) below; so η = e^(ln η) is never formed and asinh rarely
called), the same for the heat-balance step's
asinh(x e^(−βΔT)) with ln 2x − βΔT; tanh z = (e^(2z) − 1)/(e^(2z) + 1) for
1e-3 ≤ z ≤ 20 (≤ ~1e-13 relative).  No allocation.  Of fastmath only ``contract``: LLVM may fuse a
multiplication and an addition into one FMA instruction (one rounding instead of two; results differ by rounding
only from those of a CPU without FMA, not bit for bit; no reassociation, no approximate functions, NaN and
infinities kept): it takes 5–7 % off the hub right-hand side at the same accuracy.  The heat-balance secant
step stays per slice: solving it once on the central slice would change results by far
more than 1e-10 (each slice has its own pressure and sliding speed).  Strip counts n ≤ 64 take their load
shares, centroids, areas and (load share)^0.246 from tables built at import; the rolling resistance's u^0.648
is u₀^0.648 (u/u₀)^0.648 with the second factor by its binomial series when |u/u₀ − 1| ≤ 1/16 (:func:`_pow_0648`,
< 5e-15); the contact type's film constants (ln αE′, ellipticity terms, the regime map's isoviscous-rigid
film) are stored in ``lub`` by :func:`pack_lubrication_parameters` and used while α E′ and R_y/R_x still match
(:func:`film_constants`); the tables and stored constants take 12 % off the kernel and 10 % off the hub
right-hand side, forces equal to ~1e-15.
The Gauss rule (n_slices < 0) sets up the film law's contact-level constants once per call (ln η₀, 1/h_c,
the limiting-stress denominator, the film-elasticity factors) and integrates the rolling resistance on its own
ROLL_NODES Gauss–Jacobi nodes (its line-load factor (1 − ξ²)^0.246 as the weight, u^0.648 as in the strip
loop); :func:`contact_traction_reference` evaluates the same rule one point at a time with the model functions
(tests at 1e-10); the per-call constants take 21 % off the Gauss kernel.
The log rule (n_slices = LOG_BASE + n, n = 6…8 nodes in all) takes the Gauss rule's path with other nodes
(:func:`_log_node`): generalized Gauss rules exact for the logarithm of the rolling slip's zeros, where μ(s)·ŝ grows
as that logarithm; 7 nodes are within 1 % of the strip limit on the hub states.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..errors import InputError
from . import ehl, traction
from .traction import MARTIN_ROLLING, elastic_plastic_mean_stress, mixed_weight
from .vecmath import LANES, vexp, vlog, vrecip, vsqrt

# ---- layout of the packed parameter vector `lub` -------------------------------------
L_MODEL = 0  # 0 boundary, 1 fluid, 2 mixed
L_FLUID = 1  # fluid model: 0 four-parameter curve, 1 physical (Eyring + limiting shear stress)
L_ETA0 = 2  # inlet viscosity [Pa s]
L_ALPHA = 3  # pressure-viscosity coefficient [1/Pa]
L_EEFF = 4  # E' [Pa]
L_RX = 5  # [m]
L_RY = 6  # [m]
L_SIGMA = 7  # composite roughness [m]
L_BETA_ETA = 8  # -d eta/dT [Pa s/K]
L_KOIL = 9  # lubricant thermal conductivity [W/(m K)]
L_PHI_S = 10  # starvation factor [-]
L_THERMAL = 11  # 1: thermal corrections on
L_FA, L_FB, L_FC, L_FD = 12, 13, 14, 15  # fluid four-parameter curve
L_BA, L_BB, L_BC, L_BD = 16, 17, 18, 19  # boundary four-parameter curve
L_LAM1, L_LAM2 = 20, 21
L_TAU0 = 22  # Eyring stress [Pa]
L_LSS_R, L_LSS_C1, L_LSS_C2, L_LSS_C3, L_LSS_C4, L_LSS_FLOOR = 23, 24, 25, 26, 27, 28
L_BETA_V = 29  # -d ln eta/dT [1/K]
L_ROE_LN = 30  # ln eta0 + 9.67
L_ROE_Z = 31  # Roelands index
L_EFFUS = 32  # effusivity sqrt(k rho c) of the solids [W s^0.5/(m^2 K)]
L_ROLLRES = 33  # 1: rolling resistance and oil-film force on
L_T0C = 34  # inlet temperature [degC]
L_VISCO = 35  # 1: film elasticity (Johnson-Tevaarwerk elastic/plastic mean stress) on
L_GF_SCALE = 36  # factor on the film's elastic shear modulus G_f = tau_L/r_L (1: as the law gives; sensitivity studies)
L_SFLEX = 37  # solids' tangential flexibility 8/(3 C11 G) [1/Pa] (x rolling semi-axis = Kalker's L1; 0: rigid solids)
# constants of the contact type for the film formulae (film_constants), with the two inputs they were made from:
# used by the kernel only while lub[L_C_AE] == alpha E' and lub[L_C_AR] == Ry/Rx (else computed per call)
L_C_AE = 38  # alpha E' the constants were made from [-]
L_C_AR = 39  # Ry/Rx the constants were made from [-]
L_C_LNG = 40  # ln(alpha E')
L_C_K = 41  # ellipticity k = 1.03 (Ry/Rx)^0.64 (Hamrock-Dowson)
L_C_FKMIN = 42  # 1 - exp(-0.68 k) (minimum film)
L_C_FKC = 43  # 1 - 0.61 exp(-0.73 k) (central film)
L_C_HIR = 44  # isoviscous-rigid film parameter of the regime map (ehl.regime_films)
L_C_FKIE = 45  # 1 - 0.85 exp(-0.31 k) (isoviscous-elastic film of the regime map)
L_SIZE = 46

# ---- the strip loop's lanes (traction_at): out[10:] holds these arrays of LANES floats, one lane per strip
(LX, LOFF, LQ, LFRAC, LCHORD, LP, LSX, LSY, LSZ, LSM, LEX, LEY, LEZ, LU, LNX, LNY, LNZ, LSR, LMU, LA, LB, LL2X, LTL,
 LTAU, LZ1, LDEN, LNUM, LARG, LIU, LIS, LRF) = (k * LANES for k in range(31))
#: the contact's logarithms and its film's exponentials (the first two arrays: the strips' lanes come later)
CL_LN, CL_EX = LX, LOFF
#: length of traction_at's ``out``: the 10 results, then the lanes' work space
TRACTION_OUT = 10 + 31 * LANES
#: n_slices = SPLIT_BASE + n: n equal strips, those holding a zero of the rolling slip split there
SPLIT_BASE = 1_000_000
#: n_slices = LOG_BASE + n: n nodes in all, generalized Gauss rules with the logarithm of the slip's zeros
#: (:func:`_log_node`; LOG_MIN ≤ n ≤ LOG_MAX)
LOG_BASE = 2_000_000
LOG_MIN, LOG_MAX = 6, 8
#: most equal strips the checked entry takes (the kernel reads SPLIT_BASE + n and LOG_BASE + n as other rules)
STRIPS_MAX = 100_000

MODELS = {"boundary": 0, "fluid": 1, "mixed": 2}
FLUID_MODELS = {"curve": 0, "physical": 1}

#: 4/(3 sqrt(pi)): mean over the transit of the flash temperature of a half-space under a flux
_FLASH = 4.0 / (3.0 * math.sqrt(math.pi))


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def slice_fraction(xi0, xi1):
    """Share of the load Q on the strip ξ ∈ [ξ0, ξ1] of the Hertz ellipse (seed eq. 1)."""
    return 0.25 * ((3.0 * xi1 - xi1**3) - (3.0 * xi0 - xi0**3))


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def slice_centroid(xi0, xi1):
    """Load centroid ξ̄ = x̄/a of the strip [ξ0, ξ1] (see module docstring)."""
    g = 0.75 * ((0.5 * xi1 * xi1 - 0.25 * xi1**4) - (0.5 * xi0 * xi0 - 0.25 * xi0**4))
    return g / slice_fraction(xi0, xi1)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def surface_curvature(r_dev):
    """Curvature c = 1/r_dev [1/m] of the deformed contact surface across the ellipse (module docstring,
    item 2: r_dev > 0 when its centre of curvature lies on the ball's side); 0 for a flat contact
    (r_dev = ±inf) or r_dev = 0."""
    if math.isfinite(r_dev) and r_dev != 0.0:
        return 1.0 / r_dev
    return 0.0


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def slice_point_offset(x, curv):
    """The slice-point convention (module docstring, item 2): the point at x [m] along the major axis
    lies on the deformed surface, ``offset`` [m] from the tangent plane along the unit normal that points
    from the race towards the ball, offset = c x²/(1 + √(1 − c²x²)) (the circle of curvature c, exact).
    Returns (offset, √(1 − c²x²)); the local normal there is √(1 − c²x²) n − c x e_major."""
    cx = curv * x
    root = math.sqrt(max(0.0, 1.0 - cx * cx))
    return cx * x / (1.0 + root), root


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def slice_area_fraction(xi0, xi1):
    """Area of the strip divided by a b:  [ξ√(1−ξ²) + asin ξ] between ξ0 and ξ1."""
    h1 = xi1 * math.sqrt(max(0.0, 1.0 - xi1 * xi1)) + math.asin(min(1.0, max(-1.0, xi1)))
    h0 = xi0 * math.sqrt(max(0.0, 1.0 - xi0 * xi0)) + math.asin(min(1.0, max(-1.0, xi0)))
    return h1 - h0


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _law_constants(lub):
    """The traction laws' constants from ``lub``: boundary and fluid four-parameter curves (A, B, C, D each), then
    the physical film law's τ₀ [Pa], t₀ [°C], limiting-stress coefficients r_L, c₁…c₄ and floor, β_v [1/K] and
    Roelands' ln η₀ + 9.67 and index z (:func:`pack_lubrication_parameters`)."""
    return (lub[L_BA], lub[L_BB], lub[L_BC], lub[L_BD], lub[L_FA], lub[L_FB], lub[L_FC], lub[L_FD],
            lub[L_TAU0], lub[L_T0C], lub[L_LSS_R], lub[L_LSS_C1], lub[L_LSS_C2], lub[L_LSS_C3], lub[L_LSS_C4],
            lub[L_LSS_FLOOR], lub[L_BETA_V], lub[L_ROE_LN], lub[L_ROE_Z])


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def add_point_traction(out, f, sx, sy, sz, dbx, dby, dbz, drx, dry, drz, power):
    """Add the traction f·(sx, sy, sz) [N] acting at a point (arm d_b from the ball centre, d_r from the race
    centre [m]) to out (module docstring, item 4): force and moment on the ball, moment on the race (whose force
    is minus the ball's), and ``power`` [W] to out[9]."""
    tx, ty, tz = f * sx, f * sy, f * sz
    out[0] += tx
    out[1] += ty
    out[2] += tz
    out[3] += dby * tz - dbz * ty
    out[4] += dbz * tx - dbx * tz
    out[5] += dbx * ty - dby * tx
    out[6] -= dry * tz - drz * ty
    out[7] -= drz * tx - drx * tz
    out[8] -= drx * ty - dry * tx
    out[9] += power


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def add_point_rolling(out, fr, uj, hx, hy, hz, dbx, dby, dbz, drx, dry, drz, njx, njy, njz, two_rx, inv_r1):
    """Add the rolling resistance fr [N] at a point with entraining speed uj [m/s] along the unit vector h to out
    ([S1] eqs. 4–5, module docstring item 5): shear −fr on both surfaces, the pressure-centre shift as P₁ =
    2 fr R_x/R₁ on the ball through its centre (R₁ = |d_b|) and P₂ = 2 fr − P₁ on the race through its centre of
    curvature p − R₂ n_j (P₂ R₂ = 2 fr R_x): the race's moment (p − c_r) × ((P₂ − fr) h) − 2 fr R_x (n_j × h);
    power 2 fr uj [W].  inv_r1 = 1/|d_b| [1/m] (the strips take it for eight points at once)."""
    c = fr * two_rx
    p1 = c * inv_r1
    gb = p1 - fr
    out[0] += gb * hx
    out[1] += gb * hy
    out[2] += gb * hz
    out[3] -= fr * (dby * hz - dbz * hy)
    out[4] -= fr * (dbz * hx - dbx * hz)
    out[5] -= fr * (dbx * hy - dby * hx)
    gr = fr - p1
    out[6] += gr * (dry * hz - drz * hy) - c * (njy * hz - njz * hy)
    out[7] += gr * (drz * hx - drx * hz) - c * (njz * hx - njx * hz)
    out[8] += gr * (drx * hy - dry * hx) - c * (njx * hy - njy * hx)
    out[9] += 2.0 * fr * uj


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def contact_traction(q, a, b, r_dev, centre, normal, major, ball_centre, v_ball, w_ball,
                     race_centre, v_race, w_race, lub, n_slices, out):
    """Tangential forces of one lubricated ball–race contact on n slices ([S1] eqs. 1–5).

    All SI.  q normal load [N] (≥ 0); a, b semi-major (transverse) / semi-minor (rolling)
    axes [m]; r_dev radius of the deformed contact surface in the major-axis plane [m]
    (Jones 1960: 2 r_g D/(2 r_g + D) for a ball of diameter D in a groove of radius r_g,
    positive when its centre of curvature is on the ball's side, as for inner and outer
    grooves; +inf for a flat contact); centre float[3] contact-ellipse centre; normal
    float[3] unit normal from the race towards the ball centre; major float[3] unit vector
    along the major axis; ball_centre, v_ball, w_ball float[3] ball centre position,
    velocity, angular velocity; race_centre, v_race, w_race float[3] the race's centre
    (its point on the bearing axis, in the ball's orbit plane for an exact entraining
    speed), velocity and angular velocity (rigid field v = v_race + w_race × (p − race_centre));
    lub float[:] from :func:`pack_lubrication_parameters`; n_slices ≥ 1: that many equal strips;
    n_slices ≤ −1: Gauss–Legendre quadrature with −n_slices ≤ GAUSS_MAX nodes on each sub-interval between
    the zeros of the rolling slip (:func:`_gauss_quadrature`, the strip model's limit of infinitely many
    strips); n_slices = SPLIT_BASE + n: n equal strips, those that hold a zero of the rolling slip cut there, each
    part a strip of its own width (seed eq. 1's strip formulae; its rolling resistance with its own length:
    Zhou & Hoeprich 1991 eq. 17, or Martin); 0: nothing.

    out float[10] ← force on the ball (3) [N], moment on the ball about ball_centre (3)
    [N m], moment on the race about race_centre (3) [N m], power lost [W] (≥ 0); an out of TRACTION_OUT floats or
    more is also the strips' work space (otherwise one is allocated).  The race
    force is minus the ball force.  The normal Hertz force is not included.
    Returns nothing.  See the module docstring for the equations.
    """
    buf = out if out.shape[0] >= TRACTION_OUT else np.empty(TRACTION_OUT)
    traction_at(q, a, b, r_dev, centre[0], centre[1], centre[2], normal[0], normal[1], normal[2], major[0], major[1],
                major[2], ball_centre[0], ball_centre[1], ball_centre[2], v_ball[0], v_ball[1], v_ball[2], w_ball[0],
                w_ball[1], w_ball[2], race_centre[0], race_centre[1], race_centre[2], v_race[0], v_race[1], v_race[2],
                w_race[0], w_race[1], w_race[2], lub, n_slices, buf)
    for i in range(10):
        out[i] = buf[i]


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def traction_at(q, a, b, r_dev, c0x, c0y, c0z, nx, ny, nz, mx, my, mz, cbx, cby, cbz, vbx, vby, vbz, wbx, wby, wbz,
                crx, cry, crz, vrx, vry, vrz, wrx, wry, wrz, lub, n_slices, out):
    """:func:`contact_traction` with its vectors as their components (the same numbers): the dynamic engine's
    contacts call this form, so that no array is passed nor viewed per contact (numba counts a reference for
    each, with an atomic increment and decrement, which would be 17.5 % of the hub right-hand side's samples).
    out[0:10] ← as :func:`contact_traction`; out needs TRACTION_OUT floats: out[10:] is the work space of the
    lanes (ValueError otherwise)."""
    for i in range(10):
        out[i] = 0.0
    if not (q > 0.0 and a > 0.0 and b > 0.0) or n_slices == 0:
        return
    curv = surface_curvature(r_dev)
    log_rule = n_slices > LOG_BASE
    split = SPLIT_BASE < n_slices < LOG_BASE
    if split:
        n_slices -= SPLIT_BASE
    elif log_rule:  # node rules below, as the Gauss rule's (n_slices < 0)
        n_slices = LOG_BASE - n_slices

    # orbital angular velocity of the ball centre about the race centre
    rbx, rby, rbz = cbx - crx, cby - cry, cbz - crz
    rb2 = rbx * rbx + rby * rby + rbz * rbz
    ox = oy = oz = 0.0
    if rb2 > 0.0:
        ox = (rby * vbz - rbz * vby) / rb2
        oy = (rbz * vbx - rbx * vbz) / rb2
        oz = (rbx * vby - rby * vbx) / rb2

    model = int(lub[L_MODEL])
    fluid_kind = int(lub[L_FLUID])
    eta0 = lub[L_ETA0]
    alpha = lub[L_ALPHA]
    e_eff = lub[L_EEFF]
    rx = lub[L_RX]
    ry = lub[L_RY]
    sigma = lub[L_SIGMA]
    thermal = lub[L_THERMAL] != 0.0
    rollres = lub[L_ROLLRES] != 0.0

    # The velocity fields are affine in the point p: with d_b = p - c_ball, d_r = p - c_race,
    #   sliding  s(p) = v_b + w_b x d_b - v_r - w_r x d_r,
    #   entraining e(p) = ½(v_b + w_b x d_b + v_r + w_r x d_r) - (v_b + Ω x d_b),
    # so they are evaluated at the centre once and moved to each slice point with the
    # constant matrices (w_b - w_r) x . and (½(w_b + w_r) - Ω) x . (same values, fewer operations).
    dbx, dby, dbz = c0x - cbx, c0y - cby, c0z - cbz
    drx, dry, drz = c0x - crx, c0y - cry, c0z - crz
    ubx = vbx + wby * dbz - wbz * dby
    uby = vby + wbz * dbx - wbx * dbz
    ubz = vbz + wbx * dby - wby * dbx
    urx = vrx + wry * drz - wrz * dry
    ury = vry + wrz * drx - wrx * drz
    urz = vrz + wrx * dry - wry * drx
    ucx = vbx + oy * dbz - oz * dby
    ucy = vby + oz * dbx - ox * dbz
    ucz = vbz + ox * dby - oy * dbx
    s0x, s0y, s0z = ubx - urx, uby - ury, ubz - urz
    e0x = 0.5 * (ubx + urx) - ucx
    e0y = 0.5 * (uby + ury) - ucy
    e0z = 0.5 * (ubz + urz) - ucz
    # rates: sliding changes by ws x dp, entraining by we x dp
    wsx, wsy, wsz = wbx - wrx, wby - wry, wbz - wrz
    wex = 0.5 * (wbx + wrx) - ox
    wey = 0.5 * (wby + wry) - oy
    wez = 0.5 * (wbz + wrz) - oz
    # centre values projected on the contact plane
    en = e0x * nx + e0y * ny + e0z * nz
    ex, ey, ez = e0x - en * nx, e0y - en * ny, e0z - en * nz
    u0 = math.sqrt(ex * ex + ey * ey + ez * ez)
    sn = s0x * nx + s0y * ny + s0z * nz
    sx, sy, sz = s0x - sn * nx, s0y - sn * ny, s0z - sn * nz
    s0 = math.sqrt(sx * sx + sy * sy + sz * sz)

    # ---- contact-level film (at the ellipse centre): Hamrock-Dowson with shared logarithms.  The contact's eight
    # logarithms in one vlog and the film's eight exponentials in one vexp (:mod:`.vecmath`): they are
    # taken for every contact and used where the formulae below need them (the unused lanes' values are ignored)
    if out.shape[0] < TRACTION_OUT:
        raise ValueError("traction_at: out needs TRACTION_OUT floats (out[10:] is the lanes' work space)")
    lw = out[10:]
    phi = lub[L_PHI_S]
    hc = 0.0
    hmin = 0.0
    ln_u = ln_g = ln_w = 0.0
    k_hd = 0.0
    fk_min = 0.0
    h_ir = 0.0
    fk_ie = 0.0
    fk_c = 0.0
    beta_eta = lub[L_BETA_ETA]
    width = 2.0 * a * (1.0 / n_slices) if n_slices > 0 else 1.0  # a strip's (as below)
    film = u0 > 0.0 and model != 0  # (the boundary model needs no film)
    if model != 0:  # (nor any of these)
        lw[CL_LN + 0] = beta_eta * u0 * u0 / lub[L_KOIL]  # ln L (Zhu-Cheng)
        lw[CL_LN + 1] = s0 / u0 if u0 > 0.0 else 1.0  # ln (s/u)
        lw[CL_LN + 2] = eta0 * u0 / (e_eff * rx)  # ln U
        lw[CL_LN + 3] = q / (e_eff * rx * rx)  # ln W
        lw[CL_LN + 4] = eta0  # ln η0
        lw[CL_LN + 5] = alpha * e_eff * eta0 / (e_eff * rx)  # ln G U/u (Zhou-Hoeprich)
        lw[CL_LN + 6] = q / (width * e_eff * rx)  # ln W of a strip (Zhou-Hoeprich)
        lw[CL_LN + 7] = u0  # ln u0
        vlog(lw, CL_LN, lw, CL_LN)
        ln_l = lw[CL_LN + 0]
        ln_u = lw[CL_LN + 2]
        ln_w = lw[CL_LN + 3]
        if film:
            if lub[L_C_AE] == alpha * e_eff and lub[L_C_AR] == ry / rx:  # the contact type's constants, made once
                ln_g, k_hd, fk_min, fk_c, h_ir, fk_ie = (lub[L_C_LNG], lub[L_C_K], lub[L_C_FKMIN], lub[L_C_FKC],
                                                         lub[L_C_HIR], lub[L_C_FKIE])
            else:
                ln_g, k_hd, fk_min, fk_c, h_ir, fk_ie = film_constants(alpha, e_eff, rx, ry)
        ln_gv = ln_g + 3.0 * ln_w - 2.0 * ln_u  # the regime map's (regime_code with the shared logarithms,
        ln_ge = (8.0 / 3.0) * ln_w - 2.0 * ln_u  # the same formulae as ehl.regime_films)
        lw[CL_EX + 0] = 0.42 * ln_l
        lw[CL_EX + 1] = 0.83 * lw[CL_LN + 1]
        lw[CL_EX + 2] = 0.64 * ln_l
        lw[CL_EX + 3] = 0.67 * ln_u + 0.53 * ln_g - 0.067 * ln_w
        lw[CL_EX + 4] = 0.68 * ln_u + 0.49 * ln_g - 0.073 * ln_w
        lw[CL_EX + 5] = (2.0 / 3.0) * ln_gv
        lw[CL_EX + 6] = 0.67 * ln_ge
        lw[CL_EX + 7] = 0.49 * ln_gv + 0.17 * ln_ge
        vexp(lw, CL_EX, lw, CL_EX)
    if film:
        if thermal and beta_eta > 0.0:
            # ehl.zhu_cheng_thermal_factor with L^0.42 and L^0.64 from one logarithm
            p_h = 1.5 * q / (math.pi * a * b)
            zc_num = 1.0 - 13.2 * (p_h / e_eff) * lw[CL_EX + 0]
            s83 = lw[CL_EX + 1] if s0 > 0.0 else 0.0  # (s/u)^0.83
            zc_den = 1.0 + 0.213 * (1.0 + 2.23 * s83) * lw[CL_EX + 2]
            phi_t = zc_num / zc_den
            if phi_t < 0.0:
                phi_t = 0.0
            elif phi_t > 1.0:
                phi_t = 1.0
            phi *= phi_t
        hc = phi * rx * 2.69 * lw[CL_EX + 3] * fk_c
        hmin = phi * rx * 3.63 * lw[CL_EX + 4] * fk_min
    if model == 0:
        wfl = 0.0
    elif model == 1:
        wfl = 1.0
    else:
        if sigma > 0.0:
            wfl = mixed_weight(hmin / sigma, lub[L_LAM1], lub[L_LAM2])
        else:
            wfl = 1.0
    do_roll = rollres and wfl > 0.0
    reg = 3
    if do_roll and u0 > 0.0:
        h_pr = 1.66 * lw[CL_EX + 5] * fk_min
        h_ie = 8.70 * lw[CL_EX + 6] * fk_ie
        h_pe = 3.42 * lw[CL_EX + 7] * fk_min
        reg = ehl.select_regime(h_ir, h_pr, h_ie, h_pe)
    theta = 0.0
    if thermal:
        theta = hc / (12.0 * lub[L_KOIL])
        if u0 > 0.0:
            theta += 0.5 * _FLASH * math.sqrt(2.0 * b / u0) / lub[L_EFFUS]

    need_b = wfl < 1.0
    need_f = wfl > 0.0
    fr_scale = phi * wfl
    if n_slices < 0:  # Gauss quadrature: its own constants (the strip ones below are not needed)
        _gauss_quadrature(-n_slices, log_rule, q, a, b, curv, nx, ny, nz, mx, my, mz, c0x - cbx, c0y - cby, c0z - cbz,
                          c0x - crx, c0y - cry, c0z - crz, s0x, s0y, s0z, wsx, wsy, wsz, e0x, e0y, e0z, wex, wey, wez,
                          u0, need_b, need_f, fluid_kind, wfl, hc, theta, do_roll, reg, fr_scale, lub, lw[CL_LN + 4],
                          out)
        return
    inv_n = 1.0 / n_slices
    phys = need_f and fluid_kind != 0
    inv_ab = 1.0 / (a * b)
    half_bn = 0.5 * b * n_slices  # a strip's chord is (its area)/(its width) = b·area·n/2
    ln_eta0 = lw[CL_LN + 4] if phys else 0.0
    # rolling resistance (traction.rolling_resistance_zh / _ir) with the slice-independent factor
    # F_R = k_zh u^0.648 (Q_j/Q)^0.246,  k_zh = 29.2 (Rx/α) L (G η0/(E' Rx))^0.648 (Q/(L E' Rx))^0.246
    # and, where the centre rolls (u0 > 0), k_zh u0^0.648 in the same exponential (the strips need only that product)
    roll_zh = do_roll and reg != 0 and u0 > 0.0
    k_zh = 0.0
    k_zh_u0 = 0.0
    if do_roll and reg != 0:
        ln_zh = 0.648 * lw[CL_LN + 5] + 0.246 * lw[CL_LN + 6]
        if roll_zh:
            k_zh_u0 = 29.2 * (rx / alpha) * width * fr_scale * math.exp(ln_zh + 0.648 * lw[CL_LN + 7])
        else:
            k_zh = 29.2 * (rx / alpha) * width * fr_scale * math.exp(ln_zh)
    k_ir = MARTIN_ROLLING * width * math.sqrt(eta0 * q / width) * fr_scale if do_roll and reg == 0 else 0.0
    two_rx = 2.0 * rx

    # rates of the sliding and entraining velocities along the major axis and the normal
    asx, asy, asz = wsy * mz - wsz * my, wsz * mx - wsx * mz, wsx * my - wsy * mx
    bsx, bsy, bsz = wsy * nz - wsz * ny, wsz * nx - wsx * nz, wsx * ny - wsy * nx
    aex, aey, aez = wey * mz - wez * my, wez * mx - wex * mz, wex * my - wey * mx
    bex, bey, bez = wey * nz - wez * ny, wez * nx - wex * nz, wex * ny - wey * nx
    d0bx, d0by, d0bz = c0x - cbx, c0y - cby, c0z - cbz
    d0rx, d0ry, d0rz = c0x - crx, c0y - cry, c0z - crz
    # The strips go through the film law eight at a time: (A) each strip's load, point and
    # velocities, one lane per strip (strip s of the pair j = min(s, n−1−s): the pair's mirror images share load,
    # area and mean pressure, at ±x̄); (B) the traction coefficient on all eight lanes, with the exponentials and
    # logarithms of the film law taken by vexp / vlog (glibc's vector math library where this CPU has it:
    # :mod:`.vecmath`); (C) each loaded strip's traction and rolling resistance added to out.  Lanes past the last
    # strip or without load carry values that keep the functions finite and are not added.
    n_half = (n_slices + 1) // 2
    tabled = n_slices <= STRIP_TABLE_MAX
    # split strips: the strips that hold a zero of the rolling slip are cut there (rolling_slip_zeros)
    nroot = 0
    z1 = z2 = 0.0
    if split:
        nroot, z1, z2 = slip_zeros_on_major_axis(s0x, s0y, s0z, asx, asy, asz, bsx, bsy, bsz, nx, ny, nz, mx, my, mz,
                                                 a, curv)
    n_parts = n_slices + nroot
    e_x, e_k, e_ku, e_iz = -1.0, 0, 1, 0  # the cut strips' last edge (ξ = −1, uniform edge 0) and the next ones
    hz1 = _area_primitive(z1) if nroot >= 1 and phys else 0.0
    hz2 = _area_primitive(z2) if nroot >= 2 and phys else 0.0
    # rolling resistance (Zhou-Hoeprich) as k_zh u0^0.648 (Q_j/Q)^0.246 (u/u0)^0.648: one exponential per
    # contact (above), the strip's factor from the table, (u/u0)^0.648 by its series near 1 (_pow_0648)
    inv_u0 = 1.0 / u0 if u0 > 0.0 else 0.0
    film = need_f and fluid_kind != 0 and hc > 0.0  # the physical film law on the strips
    for c0 in range(0, n_parts, LANES):
        nl = min(LANES, n_parts - c0)
        # ---- (A) the strips' loads and points, then their velocities (_lane_kinematics)
        for i in range(LANES):
            s = c0 + i
            whole = True
            if split and i < nl:
                # the next part: from the last edge to the next one (uniform or a zero)
                xi0, k0 = e_x, e_k
                e_x, e_k, e_ku, e_iz = _next_edge(e_ku, e_iz, n_slices, nroot, z1, z2)
                xi1, k1 = e_x, e_k
                whole = k0 >= 0 and k1 >= 0
                s = k0 if k0 >= 0 else (k1 - 1 if k1 >= 0 else e_ku - 1)  # the strip the part lies in
            j = s if s < n_half else n_slices - 1 - s
            qj = 0.0
            frac = area = xbar = 0.0
            rf = 0.0
            if i < nl and not whole:
                # a part of a strip cut at a zero: its load share, centroid and area from the strip formulae
                frac = slice_fraction(xi0, xi1) if xi1 > xi0 else 0.0
                if frac > 0.0:
                    if phys:  # H at its edges: a strip edge's from the table, a zero's taken once per contact
                        h0 = _EDGE_H[n_slices, k0] if k0 >= 0 and tabled else (
                            hz1 if k0 == -1 else (hz2 if k0 == -2 else _area_primitive(xi0)))
                        h1 = _EDGE_H[n_slices, k1] if k1 >= 0 and tabled else (
                            hz1 if k1 == -1 else (hz2 if k1 == -2 else _area_primitive(xi1)))
                        area = h1 - h0
                    else:
                        area = 1.0
                    xbar = a * slice_centroid(xi0, xi1)
                    rf = 0.5 * (xi1 - xi0) * n_slices  # (its width over a strip's; the rolling factor below)
                else:
                    frac = 0.0
                qj = q * frac
            elif i < nl:
                if tabled:
                    # strip load share, centroid and area from the tables (the running differences, done once)
                    frac = _STRIP_FRAC[n_slices, j]
                    area = _STRIP_AREA[n_slices, j]
                    xbar = a * _STRIP_XI[n_slices, j]
                else:
                    xi0 = -1.0 + 2.0 * j * inv_n
                    xi1 = -1.0 + 2.0 * (j + 1) * inv_n
                    frac = slice_fraction(xi0, xi1)
                    area = _area_primitive(xi1) - _area_primitive(xi0) if phys else 1.0
                    xbar = a * slice_centroid(xi0, xi1) if frac > 0.0 else 0.0
                qj = q * frac
                rf = 1.0
            x = 0.0
            if qj > 0.0:
                if whole:
                    x = -xbar if s >= n_half else xbar
                    lw[LCHORD + i] = half_bn * area
                else:
                    x = xbar
                    lw[LCHORD + i] = b * area / (xi1 - xi0)
                # the strip's mean pressure and its mean chord (strip area)/(strip width) [m]
                lw[LP + i] = qj * inv_ab / area if phys else 1.0
            else:
                qj = 0.0
            lw[LQ + i] = qj
            lw[LRF + i] = rf
            lw[LFRAC + i] = frac
            lw[LX + i] = x
            if split:  # a whole strip's (Q_j/Q)^0.246 (as the equal strips take it), −1 marking a cut part
                lw[LB + i] = -1.0 if not whole else (_STRIP_Q246[n_slices, j] if tabled else (
                    math.exp(0.246 * math.log(frac)) if frac > 0.0 else 0.0))
        if split and do_roll and reg != 0:
            # Zhou–Hoeprich's factor of a part of width w (a strip's w₀): (w/w₀)^0.754 (Q_j/Q)^0.246 — a whole strip's
            # from the table (above); the cut parts' (at most four: two zeros cut at most two strips, or one strip in
            # three) packed in one vlog (load shares in lanes 0–3, widths in 4–7) and one vexp
            k = 0
            for i in range(LANES):
                if lw[LQ + i] > 0.0 and lw[LB + i] < 0.0 and k < 4:
                    lw[LA + k] = lw[LFRAC + i]
                    lw[LA + 4 + k] = lw[LRF + i]
                    k += 1
            if k > 0:
                for i in range(k, 4):
                    lw[LA + i] = 1.0
                    lw[LA + 4 + i] = 1.0
                vlog(lw, LA, lw, LA)
                for i in range(4):
                    lw[LA + i] = 0.246 * lw[LA + i] + 0.754 * lw[LA + 4 + i]
                vexp(lw, LA, lw, LA)
            k = 0
            for i in range(LANES):
                if lw[LQ + i] > 0.0:
                    if lw[LB + i] >= 0.0:
                        lw[LRF + i] = lw[LB + i]
                    elif k < 4:
                        lw[LRF + i] = lw[LA + k]
                        k += 1
                    else:  # (not reached: no more than four cut parts)
                        lw[LRF + i] = math.exp(0.246 * math.log(lw[LFRAC + i]) + 0.754 * math.log(lw[LRF + i]))
        _lane_kinematics(lw, curv, nx, ny, nz, mx, my, mz, s0x, s0y, s0z, bsx, bsy, bsz, asx, asy, asz, e0x, e0y, e0z,
                         bex, bey, bez, aex, aey, aez)
        # ---- (B) traction coefficients (seed eq. 2) on the eight lanes
        _film_lanes(lw, need_b, need_f, fluid_kind, film, wfl, lub, b, hc, theta, ln_eta0)
        # ---- (C) each loaded strip's traction and rolling resistance (1/|d_b| of the eight points in LA)
        if do_roll:
            for i in range(LANES):
                x = lw[LX + i]
                off = lw[LOFF + i]
                dbx = d0bx + x * mx + off * nx
                dby = d0by + x * my + off * ny
                dbz = d0bz + x * mz + off * nz
                lw[LA + i] = dbx * dbx + dby * dby + dbz * dbz
            vsqrt(lw, LA, lw, LA)
            vrecip(lw, LA, lw, LA)
        for i in range(nl):
            qj = lw[LQ + i]
            if not qj > 0.0:
                continue
            s = c0 + i
            j = s if s < n_half else n_slices - 1 - s
            uj = lw[LU + i]
            fr = 0.0
            if do_roll:
                frac = lw[LFRAC + i]
                if reg == 0:  # (a cut strip's part: Martin's factor √(w Q_j), w its width)
                    fr = k_ir * math.sqrt(frac * lw[LRF + i] if split else frac) * math.sqrt(uj)
                elif roll_zh:
                    if uj > 0.0:
                        rf = lw[LRF + i] if split else (_STRIP_Q246[n_slices, j] if tabled
                                                         else math.exp(0.246 * math.log(frac)))
                        fr = k_zh_u0 * rf * _pow_0648(uj * inv_u0)
                elif uj > 0.0:  # no entraining speed at the centre (u0 = 0): the formula as it stands
                    if split:
                        fr = k_zh * math.exp(0.648 * math.log(uj)) * lw[LRF + i]
                    else:
                        fr = k_zh * math.exp(0.648 * math.log(uj) + 0.246 * math.log(frac))
            dbx, dby, dbz, drx, dry, drz = _add_lane_traction(out, lw, i, mx, my, mz, nx, ny, nz, d0bx, d0by, d0bz,
                                                              d0rx, d0ry, d0rz)
            if do_roll and uj > 0.0:
                inv_u = lw[LIU + i]
                add_point_rolling(out, fr, uj, lw[LEX + i] * inv_u, lw[LEY + i] * inv_u, lw[LEZ + i] * inv_u, dbx, dby,
                                  dbz, drx, dry, drz, lw[LNX + i], lw[LNY + i], lw[LNZ + i], two_rx, lw[LA + i])


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _next_edge(ku, iz, n, nroot, z1, z2):
    """The next edge along ξ = x/a [-] of the n equal strips cut at the zeros z1 < z2 (nroot of them) of the rolling
    slip, the uniform edges −1 + 2k/n and the zeros merged in order (a zero on a uniform edge comes after it: a part of
    no width).  ku: the next uniform edge's index, iz: the next zero's.  Returns (ξ, code, ku, iz) with code the uniform
    edge's index k, or −1 for z1 and −2 for z2."""
    xu = -1.0 + 2.0 * ku / n
    if iz < nroot:
        zz = z1 if iz == 0 else z2
        if zz < xu:
            return zz, -1 - iz, ku, iz + 1
    return xu, ku, ku + 1, iz


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _lane_kinematics(lw, curv, nx, ny, nz, mx, my, mz, s0x, s0y, s0z, bsx, bsy, bsz, asx, asy, asz, e0x, e0y, e0z,
                     bex, bey, bez, aex, aey, aez):
    """The eight lanes' points and velocities from their positions x = lw[LX + i] [m] along the major axis (lanes
    with load lw[LQ + i] = 0 are emptied, :func:`_empty_lane`): the offset from the tangent plane (the formula of
    :func:`slice_point_offset`), sliding and entraining velocities and the local normal (:func:`_slice_velocities`;
    centre values s0, e0 [m/s] and their rates along the normal (bs, be) and the major axis (as, ae) [1/s]), |s|, u,
    1/|s|, 1/u and the slide–roll ratio.  Square roots and reciprocals are taken for all eight lanes in packed
    instructions (:func:`.vecmath.vsqrt`, :func:`.vecmath.vrecip`: exactly the scalar ones): one by one they take
    8 % of a hub step."""
    for i in range(LANES):
        cx = curv * lw[LX + i]
        lw[LA + i] = max(0.0, 1.0 - cx * cx)
    vsqrt(lw, LA, lw, LB)  # slice_point_offset's root √(1 − c²x²)
    for i in range(LANES):
        lw[LA + i] = 1.0 + lw[LB + i]
    vrecip(lw, LA, lw, LA)
    for i in range(LANES):
        x = lw[LX + i]
        root = lw[LB + i]
        off = curv * x * x * lw[LA + i]  # slice_point_offset: c x²/(1 + √(1 − c²x²))
        sx, sy, sz, ex, ey, ez, njx, njy, njz = _slice_velocities(
            x, root, curv, nx, ny, nz, mx, my, mz, s0x + off * bsx, s0y + off * bsy, s0z + off * bsz, asx, asy,
            asz, e0x + off * bex, e0y + off * bey, e0z + off * bez, aex, aey, aez)
        lw[LOFF + i] = off
        lw[LSX + i] = sx
        lw[LSY + i] = sy
        lw[LSZ + i] = sz
        lw[LEX + i] = ex
        lw[LEY + i] = ey
        lw[LEZ + i] = ez
        lw[LNX + i] = njx
        lw[LNY + i] = njy
        lw[LNZ + i] = njz
        lw[LA + i] = sx * sx + sy * sy + sz * sz
        lw[LB + i] = ex * ex + ey * ey + ez * ez
    vsqrt(lw, LA, lw, LSM)
    vsqrt(lw, LB, lw, LU)
    vrecip(lw, LSM, lw, LIS)  # 1/|s| (the traction's direction)
    vrecip(lw, LU, lw, LIU)  # 1/u (slide–roll ratio, the rolling direction)
    for i in range(LANES):
        if lw[LQ + i] > 0.0:
            uj = lw[LU + i]
            lw[LSR + i] = lw[LSM + i] * lw[LIU + i] if uj > 0.0 else 1e300  # (1e300 without rolling)
        else:
            _empty_lane(lw, i)


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _empty_lane(lw, i):
    """Lane i carries no load (past the last strip or node, or none there): values that keep :func:`_film_lanes`'
    functions finite; its result is not used."""
    lw[LQ + i] = 0.0
    lw[LP + i] = 1.0
    lw[LSM + i] = 1.0
    lw[LU + i] = 1.0
    lw[LSR + i] = 1.0
    lw[LCHORD + i] = 0.0


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _add_lane_traction(out, lw, i, mx, my, mz, nx, ny, nz, d0bx, d0by, d0bz, d0rx, d0ry, d0rz):
    """Add lane i's traction −μ Q v_s/|v_s| (seed eq. 2; μ from :func:`_film_lanes`, 1/|v_s| from lw[LIS + i]) at
    its point to out (:func:`add_point_traction`; nothing without sliding).  d0b, d0r: the ellipse centre from the
    ball's and the race's centres [m].  Returns the point's arms (d_b, d_r) [m] (for the rolling resistance)."""
    x = lw[LX + i]
    off = lw[LOFF + i]
    qx = x * mx + off * nx
    qy = x * my + off * ny
    qz = x * mz + off * nz
    dbx, dby, dbz = d0bx + qx, d0by + qy, d0bz + qz
    drx, dry, drz = d0rx + qx, d0ry + qy, d0rz + qz
    smag = lw[LSM + i]
    if smag > 0.0:
        mu = lw[LMU + i]
        qj = lw[LQ + i]
        add_point_traction(out, -mu * qj * lw[LIS + i], lw[LSX + i], lw[LSY + i], lw[LSZ + i], dbx, dby, dbz, drx,
                           dry, drz, mu * qj * smag)
    return dbx, dby, dbz, drx, dry, drz


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _film_lanes(lw, need_b, need_f, fluid_kind, film, wfl, lub, b, hc, theta, ln_eta0):
    """lw[LMU + i] ← the traction coefficient μ on the eight lanes (seed eq. 2): the boundary and fluid models of
    :mod:`.traction` mixed with the fluid weight wfl; ``film``: the physical film law of
    :func:`traction.fluid_shear_stress` (Roelands viscosity at the mean pressure, Eyring stress limited by the
    limiting shear stress, the heat balance's secant step when θ = theta > 0 [K/(Pa m/s)], the elastic–plastic film
    when lub's film elasticity is on) in the fast forms of the module docstring, every exponential and logarithm
    taken on all eight lanes by :func:`.vecmath.vexp` / :func:`.vecmath.vlog`.  Per lane: mean pressure
    LP [Pa], sliding speed LSM [m/s], slide–roll ratio LSR, entraining speed LU [m/s] and the film's chord LCHORD
    [m] (its length along rolling, for the film elasticity); b [m] the ellipse's rolling semi-axis, hc [m] the
    central film, ln_eta0 = ln η0 (η0 [Pa s]).  The strips (:func:`traction_at`) and the Gauss nodes
    (:func:`_gauss_quadrature`) both come here."""
    (ba, bb, bc, bd, fa, fb, fc, fd, tau0, t0c, lss_r, lss_c1, lss_c2, lss_c3, lss_c4, lss_floor, beta_v, roe_ln,
     roe_z) = _law_constants(lub)
    for i in range(LANES):
        lw[LMU + i] = 0.0
    if need_b:
        for i in range(LANES):
            lw[LA + i] = -bc * lw[LSR + i]
        vexp(lw, LA, lw, LB)
        for i in range(LANES):
            lw[LMU + i] = (ba + bb * lw[LSR + i]) * lw[LB + i] + bd
    if need_f and fluid_kind == 0:
        for i in range(LANES):
            lw[LA + i] = -fc * lw[LSR + i]
        vexp(lw, LA, lw, LB)
        for i in range(LANES):
            mu = lw[LMU + i]
            lw[LMU + i] = mu + ((fa + fb * lw[LSR + i]) * lw[LB + i] + fd - mu) * wfl
        return
    if need_f and not film:
        for i in range(LANES):
            lw[LMU + i] -= lw[LMU + i] * wfl
        return
    if not film:
        return
    den0 = lss_c2 + lss_c3 * t0c
    inv_hc = 1.0 / hc
    two_inv_hc_tau0 = 2.0 * (inv_hc * (1.0 / tau0))
    visco = lub[L_VISCO] != 0.0 and lss_r > 0.0
    gf_c = lub[L_GF_SCALE] / lss_r if lss_r > 0.0 else 0.0  # G_f = τ_L/r_L (× scale)
    sol_c = lub[L_SFLEX] * b * inv_hc  # solids in series: L1/h (Kalker), traction.solids_in_series_factor
    # Roelands: ln η(p̄) = ln η0 + (ln η0 + 9.67)((1 + p̄/1.96e8)^z − 1); the logarithm feeds ln 2x directly
    # (x = η γ̇/τ0), η itself is never formed
    for i in range(LANES):
        lw[LA + i] = 1.0 + lw[LP + i] * _INV_ROELANDS_P  # (a product: the divider is the kernel's bottleneck)
    vlog(lw, LA, lw, LB)
    for i in range(LANES):
        lw[LA + i] = roe_z * lw[LB + i]
    vexp(lw, LA, lw, LB)
    for i in range(LANES):
        lw[LL2X + i] = ln_eta0 + roe_ln * (lw[LB + i] - 1.0)  # ln η(p̄), then ln 2x below
        lw[LA + i] = two_inv_hc_tau0 * lw[LSM + i]
    vlog(lw, LA, lw, LB)
    for i in range(LANES):
        l2x = lw[LB + i] + lw[LL2X + i]
        lw[LL2X + i] = l2x
        lw[LA + i] = -2.0 * l2x
    vexp(lw, LA, lw, LB)  # e^(−2 ln 2x) for asinh's series
    c1_den0 = lss_c1 / den0
    for i in range(LANES):
        pbar = lw[LP + i]
        tl = lss_r * (c1_den0 * pbar - lss_c4)
        fl = lss_floor * pbar
        if tl < fl:
            tl = fl
        lw[LTL + i] = tl
    for i in range(LANES):
        z = tau0 / lw[LTL + i] * _asinh_l2x_e(lw[LL2X + i], lw[LB + i])
        lw[LTAU + i] = z  # tanh's argument, then τ below
        lw[LA + i] = 2.0 * min(z, 20.0)
    vexp(lw, LA, lw, LB)
    for i in range(LANES):
        lw[LTAU + i] = lw[LTL + i] * _tanh_pos_e(lw[LTAU + i], lw[LB + i])
    if theta > 0.0:
        # the heat balance's secant step (_heated_stress), its two exponentials on the lanes
        for i in range(LANES):
            dT = theta * lw[LSM + i] * lw[LTAU + i]
            lw[LARG + i] = lw[LL2X + i] - beta_v * dT
            lw[LA + i] = -2.0 * lw[LARG + i]
        vexp(lw, LA, lw, LB)
        for i in range(LANES):
            dT = theta * lw[LSM + i] * lw[LTAU + i]
            den1, num1, z1 = _heated_arg(dT, _asinh_l2x_e(lw[LARG + i], lw[LB + i]), lw[LP + i],
                                         lss_floor * lw[LP + i], tau0, t0c, lss_r, lss_c1, lss_c2, lss_c3, lss_c4)
            lw[LA + i] = 2.0 * min(max(z1, 0.0), 20.0)
            lw[LZ1 + i] = z1
            lw[LDEN + i] = den1
            lw[LNUM + i] = num1
        vexp(lw, LA, lw, LB)
        for i in range(LANES):
            lw[LTAU + i] = _heated_finish(lw[LTAU + i], lw[LDEN + i], lw[LNUM + i], lw[LZ1 + i], lw[LB + i])
    for i in range(LANES):
        tau = lw[LTAU + i]
        if visco and lw[LU + i] > 0.0:
            # traction.elastic_plastic_mean_stress with τ_e = G_f ℓ s/h / (1 + G_f L1/h) (no rolling: τ_e = ∞)
            g = gf_c * lw[LTL + i]
            tau = elastic_plastic_mean_stress(tau, g * lw[LCHORD + i] * inv_hc * lw[LSR + i] / (1.0 + g * sol_c))
        mu = lw[LMU + i]
        lw[LMU + i] = mu + (tau / lw[LP + i] - mu) * wfl

@njit(cache=True, error_model="numpy", fastmath={"contract"})
def film_constants(alpha, e_eff, rx, ry):
    """Constants of a contact type in the Hamrock–Dowson films and the regime map (the same formulae as
    :func:`bearingsim.contact.ehl.hamrock_dowson_central`, ``_minimum`` and ``regime_films``): α [1/Pa],
    E′ [Pa], R_x, R_y [m] → (ln αE′, k = 1.03 (R_y/R_x)^0.64, 1 − e^(−0.68k), 1 − 0.61 e^(−0.73k), the
    isoviscous-rigid film 128 (R_y/R_x) λ_b² (0.131 atan(R_y/2R_x) + 1.683)², λ_b = 1/(1 + 2R_x/3R_y),
    1 − 0.85 e^(−0.31k)) [-].  :func:`pack_lubrication_parameters` stores them in ``lub`` (L_C_*) so that the
    kernel does not recompute them per call."""
    ar = ry / rx
    k_hd = 1.03 * math.exp(0.64 * math.log(ar))
    lam_b = 1.0 / (1.0 + 2.0 / (3.0 * ar))
    h_ir = 128.0 * ar * lam_b**2 * (0.131 * math.atan(ar / 2.0) + 1.683) ** 2
    return (math.log(alpha * e_eff), k_hd, 1.0 - math.exp(-0.68 * k_hd), 1.0 - 0.61 * math.exp(-0.73 * k_hd), h_ir,
            1.0 - 0.85 * math.exp(-0.31 * k_hd))


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _area_primitive(xi):
    """H(ξ) = ξ√(1−ξ²) + asin ξ (clipped to [−1, 1]); strip area / (a b) = H(ξ1) − H(ξ0)."""
    return xi * math.sqrt(max(0.0, 1.0 - xi * xi)) + math.asin(min(1.0, max(-1.0, xi)))


#: strip counts n ≤ STRIP_TABLE_MAX take their strip constants from tables built once here (the same running
#: differences of F, G, H as the loop of :func:`contact_traction` uses above the limit): for the strip pair j
#: (strips j and n−1−j), _STRIP_FRAC[n, j] = F(ξ_j+1) − F(ξ_j) (load share), _STRIP_XI[n, j] = the load centroid
#: x̄/a of strip j (≤ 0; strip n−1−j has −x̄), _STRIP_AREA[n, j] = H(ξ_j+1) − H(ξ_j) (area / ab) and
#: _STRIP_Q246[n, j] = (load share)^0.246 of the Zhou–Hoeprich rolling resistance
STRIP_TABLE_MAX = 64
_STRIP_FRAC = np.zeros((STRIP_TABLE_MAX + 1, (STRIP_TABLE_MAX + 1) // 2))
_STRIP_XI = np.zeros_like(_STRIP_FRAC)
_STRIP_AREA = np.zeros_like(_STRIP_FRAC)
_STRIP_Q246 = np.zeros_like(_STRIP_FRAC)
#: _EDGE_H[n, k] = H(−1 + 2k/n): the area primitive at the edges of n equal strips (the cut strips' parts)
_EDGE_H = np.zeros((STRIP_TABLE_MAX + 1, STRIP_TABLE_MAX + 1))


def _fill_strip_tables():
    for n in range(1, STRIP_TABLE_MAX + 1):
        f_prev, g_prev, h_prev = -0.5, 0.1875, -0.5 * math.pi
        for j in range((n + 1) // 2):
            xi1 = -1.0 + 2.0 * (j + 1) * (1.0 / n)
            f1 = 0.25 * (3.0 * xi1 - xi1 * xi1 * xi1)
            g1 = 0.75 * (0.5 * xi1 * xi1 - 0.25 * (xi1 * xi1) * (xi1 * xi1))
            h1 = _area_primitive.py_func(xi1)
            frac, gfrac = f1 - f_prev, g1 - g_prev
            _STRIP_FRAC[n, j] = frac
            _STRIP_XI[n, j] = gfrac / frac if frac > 0.0 else 0.0
            _STRIP_AREA[n, j] = h1 - h_prev
            _STRIP_Q246[n, j] = math.exp(0.246 * math.log(frac)) if frac > 0.0 else 0.0
            f_prev, g_prev, h_prev = f1, g1, h1


_fill_strip_tables()
for _n in range(1, STRIP_TABLE_MAX + 1):
    for _k in range(_n + 1):
        _EDGE_H[_n, _k] = _area_primitive.py_func(-1.0 + 2.0 * _k / _n)

#: Taylor coefficients of (1 + r)^0.648 (binomial series), r^0 … r^POW_SERIES_ORDER
POW_SERIES_ORDER = 9
#: |r| ≤ POW_SERIES_R: the series' remainder is below 1e-14 relative (|C(0.648, 10)| r^10/(1 − r) < 5e-15)
POW_SERIES_R = 1.0 / 16.0
_POW_C = np.ones(POW_SERIES_ORDER + 1)
for _k in range(1, POW_SERIES_ORDER + 1):
    _POW_C[_k] = _POW_C[_k - 1] * (0.648 - _k + 1) / _k


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _pow_0648(x):
    """x^0.648 for x > 0 [-] (Zhou & Hoeprich 1991's exponent of the rolling speed): the binomial series of
    (1 + r)^0.648, r = x − 1, to r⁹ when |r| ≤ 1/16 (remainder < 5e-15 relative; no logarithm, no
    exponential), exp(0.648 ln x) otherwise."""
    r = x - 1.0
    if abs(r) <= POW_SERIES_R:
        acc = _POW_C[POW_SERIES_ORDER]
        for k in range(POW_SERIES_ORDER - 1, -1, -1):
            acc = acc * r + _POW_C[k]
        return acc
    return math.exp(0.648 * math.log(x))


#: ln(2·10⁶): asinh x = ln 2x within 2.5e-13 for x ≥ 10⁶
_LN_2E6 = math.log(2.0e6)
#: 1/(1.96e8 Pa): Roelands' pressure scale (traction.roelands_viscosity), as a factor
_INV_ROELANDS_P = 1.0 / 1.96e8
_LN_2 = math.log(2.0)
_LN_20 = math.log(20.0)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _tanh_pos(z):
    """tanh z for z ≥ 0 [-]: (e^(2z) − 1)/(e^(2z) + 1) for 1e-3 ≤ z ≤ 20 (e^(2z) − 1 ≥ 2e-3, so at
    most ~500 ulp lost, ~1e-13 relative), exactly 1 above 20 (tanh 20 = 1 − 8e-18), math.tanh below."""
    return _tanh_pos_e(z, math.exp(2.0 * z) if 1e-3 <= z <= 20.0 else 0.0)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _tanh_pos_e(z, e):
    """:func:`_tanh_pos` with e = e^(2z) given (used only where 1e-3 ≤ z ≤ 20; the strip lanes take it from
    :func:`.vecmath.vexp`)."""
    if z > 20.0:
        return 1.0
    if z >= 1e-3:
        return (e - 1.0) / (e + 1.0)
    return math.tanh(z)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _slice_velocities(x, root, curv, nx, ny, nz, mx, my, mz, s1x, s1y, s1z, asx, asy, asz,
                      e1x, e1y, e1z, aex, aey, aez):
    """Tangential sliding and entraining velocities at the slice point x̄ (module docstring, item 3) and the local
    normal there: (s (3), e (3), n_j (3)) [m/s, m/s, -]."""
    cx = curv * x
    njx = root * nx - cx * mx
    njy = root * ny - cx * my
    njz = root * nz - cx * mz
    sx = s1x + x * asx
    sy = s1y + x * asy
    sz = s1z + x * asz
    sn = sx * njx + sy * njy + sz * njz
    sx -= sn * njx
    sy -= sn * njy
    sz -= sn * njz
    ex = e1x + x * aex
    ey = e1y + x * aey
    ez = e1z + x * aez
    en = ex * njx + ey * njy + ez * njz
    ex -= en * njx
    ey -= en * njy
    ez -= en * njz
    return sx, sy, sz, ex, ey, ez, njx, njy, njz


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _slice_kinematics(x, root, curv, nx, ny, nz, mx, my, mz, s1x, s1y, s1z, asx, asy, asz,
                      e1x, e1y, e1z, aex, aey, aez):
    """:func:`_slice_velocities` with the speeds |s| and |e| [m/s]: (s (3), |s|, e (3), |e|, n_j (3))."""
    sx, sy, sz, ex, ey, ez, njx, njy, njz = _slice_velocities(x, root, curv, nx, ny, nz, mx, my, mz, s1x, s1y, s1z,
                                                              asx, asy, asz, e1x, e1y, e1z, aex, aey, aez)
    return (sx, sy, sz, math.sqrt(sx * sx + sy * sy + sz * sz), ex, ey, ez, math.sqrt(ex * ex + ey * ey + ez * ez),
            njx, njy, njz)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _asinh_l2x(l2x):
    """asinh x for x > 0 from l2x = ln 2x alone [-]: ln 2x when x ≥ 1e6 (the dropped term 1/(4x²) ≤ 2.5e-13
    absolute, ≤ 1.8e-14 of the value); for 10 ≤ x < 1e6 the asymptotic series asinh x = ln 2x + Σ_{n≥1}
    (−1)^(n+1) C(2n, n) wⁿ/(4ⁿ 2n), w = 1/x² = 4e^(−2 ln 2x) (Abramowitz & Stegun 4.6.31: w/4 − 3w²/32 + 5w³/96
    − 35w⁴/1024 + …), eight terms (at x = 10 the ninth is 1e-20); below, asinh(e^(ln 2x − ln 2)).  The film law
    never needs x itself, so the viscosity η(p̄) = e^(ln η) is not formed, and no asinh call is made where x ≥ 10
    (the loaded EHL contact's usual range; with the switch at 10 rather than 100 the lanes near the slip's zeros
    between 10 and 100 skip glibc's asinh and the exponential before it, 2–3 % of a hub (b) step)."""
    return _asinh_l2x_e(l2x, math.exp(-2.0 * l2x) if _LN_20 <= l2x < _LN_2E6 else 0.0)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _asinh_l2x_e(l2x, e):
    """:func:`_asinh_l2x` with e = e^(−2 ln 2x) given (used only where 10 ≤ x < 1e6; the strip lanes take it from
    :func:`.vecmath.vexp`).  Below x = 10 the scalar asinh (a vector asinh on all eight lanes costs more than
    the one or two lanes near a zero of the slip that need it)."""
    if l2x >= _LN_2E6:
        return l2x
    if l2x >= _LN_20:
        w = 4.0 * e
        return l2x + w * (1.0 / 4.0 + w * (-3.0 / 32.0 + w * (5.0 / 96.0 + w * (-35.0 / 1024.0 + w * (
            63.0 / 2560.0 + w * (-77.0 / 4096.0 + w * (429.0 / 28672.0 - w * (6435.0 / 524288.0))))))))
    return math.asinh(math.exp(l2x - _LN_2))


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _heated_stress(tau, theta_us, l2x, p, floor_p, tau0, t0c, r_l, c1, c2, c3, c4, beta_v):
    """Secant step of the film heat balance of :func:`traction.fluid_shear_stress` [Pa].

    τ ← τ²/(2τ − τ₁), τ₁ = τ_L(t₀ + ΔT) tanh[τ₀ asinh(x e^(−β ΔT))/τ_L], ΔT = θ u_s τ (theta_us = θ u_s),
    with x given by l2x = ln 2x; asinh by :func:`_asinh_l2x` of ln 2x − β ΔT.
    """
    if not tau > 0.0:
        return 0.0
    dT = theta_us * tau
    den1, num1, z1 = _heated_arg(dT, _asinh_l2x(l2x - beta_v * dT), p, floor_p, tau0, t0c, r_l, c1, c2, c3, c4)
    return _heated_finish(tau, den1, num1, z1, math.exp(2.0 * z1) if 1e-3 <= z1 <= 20.0 else 0.0)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _heated_arg(dT, ash1, p, floor_p, tau0, t0c, r_l, c1, c2, c3, c4):
    """The heated limiting stress τ_L(t₀ + ΔT) = num1/den1 (Dyson via Zhou & Hoeprich, floored) and tanh's argument
    z1 = τ₀ asinh(x e^(−β ΔT))/τ_L of :func:`_heated_stress`, from ΔT [K] and that asinh (ash1).  Returns
    (den1, num1, z1)."""
    den1 = c2 + c3 * (t0c + dT)
    num1 = r_l * (c1 * p - c4 * den1)
    if num1 < floor_p * den1:
        num1 = floor_p * den1
    return den1, num1, tau0 * den1 / num1 * ash1


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _heated_finish(tau, den1, num1, z1, e2):
    """The secant step of :func:`_heated_stress` from :func:`_heated_arg`'s results and e2 = e^(2 z1) (used only
    where 1e-3 ≤ z1 ≤ 20: then τ₁ = (num1/den1)(e2 − 1)/(e2 + 1) with one division for the whole step) [Pa];
    0 when τ ≤ 0."""
    if not tau > 0.0:
        return 0.0
    if 1e-3 <= z1 <= 20.0:
        dp = den1 * (e2 + 1.0)
        return tau * tau * dp / (2.0 * tau * dp - num1 * (e2 - 1.0))
    tau1 = num1 / den1 * _tanh_pos(z1)
    return tau * tau / (2.0 * tau - tau1)


# ---- Gauss quadrature between the zeros of the rolling slip (n_slices < 0) -----------------------------

#: Gauss–Legendre nodes and weights on [−1, 1] for 1..GAUSS_MAX points: _GL_X[n, i], _GL_W[n, i] (i < n)
GAUSS_MAX = 8
_GL_X = np.zeros((GAUSS_MAX + 1, GAUSS_MAX))
_GL_W = np.zeros((GAUSS_MAX + 1, GAUSS_MAX))
for _n in range(1, GAUSS_MAX + 1):
    _GL_X[_n, :_n], _GL_W[_n, :_n] = np.polynomial.legendre.leggauss(_n)


def gauss_jacobi(n: int, a: float) -> tuple[np.ndarray, np.ndarray]:
    """Nodes and weights of the n-point Gauss rule for ∫₋₁¹ f(ξ) (1 − ξ²)^a dξ (Gauss–Jacobi, α = β = a > −1),
    by Golub & Welsch (1969): eigenvalues of the symmetric Jacobi matrix, off-diagonal
    √(4k(k + a)²(k + 2a)/(s²(s² − 1))), s = 2k + 2a; weights μ₀ v₀², μ₀ = √π Γ(a + 1)/Γ(a + 3/2)."""
    k = np.arange(1, n)
    s = 2.0 * k + 2.0 * a
    off = np.sqrt(4.0 * k * (k + a) ** 2 * (k + 2.0 * a) / (s**2 * (s**2 - 1.0)))
    x, v = np.linalg.eigh(np.diag(off, 1) + np.diag(off, -1))
    return x, math.sqrt(math.pi) * math.gamma(a + 1.0) / math.gamma(a + 1.5) * v[0] ** 2


#: rolling resistance of the Gauss rule: ROLL_NODES fixed nodes on ξ ∈ [−1, 1] with the weight of its line-load
#: factor — (1 − ξ²)^0.246 (Zhou–Hoeprich, row 1) or (1 − ξ²)^0.5 (Martin, row 0) — built in (Gauss–Jacobi): the
#: density is smooth times that weight (no zeros of the slip in it), so 4 nodes are exact to degree 7
ROLL_NODES = 4
_RJ_X = np.zeros((2, ROLL_NODES))
_RJ_W = np.zeros((2, ROLL_NODES))
_RJ_X[0], _RJ_W[0] = gauss_jacobi(ROLL_NODES, 0.5)
_RJ_X[1], _RJ_W[1] = gauss_jacobi(ROLL_NODES, 0.246)


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def rolling_slip_zeros(sig0, sig1, sig2, a, curv):
    """Zeros ξ ∈ (−1, 1) of the rolling-direction sliding speed along the major axis [m/s].

    For rigid-body kinematics the sliding velocity is affine in the point p (module docstring,
    item 3), and the rolling direction r = n × e_major is tangent at every point of the deformed
    surface (its normal stays in the plane of n and e_major), so the rolling component at
    x = a ξ is exactly  g(ξ) = σ0 + σ1 ξ + σ2 δ(aξ),  δ(x) = c x²/(1 + √(1 − c²x²)) the offset of
    the circle of curvature c (item 2): σ0 = s(centre)·r, σ1 = a (ω_s × e_major)·r,
    σ2 = (ω_s × n)·r [m/s].  Roots of the quadratic with δ ≈ c x²/2 (the classical two points
    of pure rolling of a conforming groove, Heathcote), polished by two Halley steps on the
    exact g (cubic convergence: |g| ≤ 1.2e-16 of |σ0| + |σ1| + |σ2 c| a² from the quadratic's roots
    over 20,000 random fields with c a ≤ 0.54, as three Newton steps give, for two thirds of their
    square roots and divisions).  Returns (count, ξ1, ξ2) with ξ1 < ξ2 (unused entries 0).
    """
    aa = 0.5 * sig2 * curv * a * a
    scale = abs(aa) + abs(sig1) + abs(sig0)
    r1 = 2.0
    r2 = 2.0
    if scale == 0.0:
        return 0, 0.0, 0.0
    # the zeros do not change with the field's scale: taken on σ/scale, so that σ1² cannot underflow (|σ| ≲ 1e-150)
    inv = 1.0 / scale
    sig0 *= inv
    sig1 *= inv
    sig2 *= inv
    aa *= inv
    scale = 1.0
    if abs(aa) <= 1e-12 * scale:
        if sig1 != 0.0:
            r1 = -sig0 / sig1
    else:
        disc = sig1 * sig1 - 4.0 * aa * sig0
        if disc >= 0.0:
            qq = -0.5 * (sig1 + math.copysign(math.sqrt(disc), sig1))
            r1 = qq / aa
            r2 = sig0 / qq if qq != 0.0 else r1
    nr = 0
    z1 = 0.0
    z2 = 0.0
    for k in range(2):
        z = r1 if k == 0 else r2
        if not abs(z) < 1.5:
            continue
        for _ in range(2):
            x = a * z
            off, root = slice_point_offset(x, curv)
            d1 = sig1
            d2 = 0.0
            if root > 0.0:
                ir = 1.0 / root
                d1 += sig2 * curv * x * ir * a  # g'(ξ): δ'(x) = c x/√(1 − c²x²)
                d2 = sig2 * curv * (ir * ir * ir) * (a * a)  # g''(ξ): δ''(x) = c/(1 − c²x²)^(3/2)
            gv = sig0 + sig1 * z + sig2 * off
            den = 2.0 * d1 * d1 - gv * d2
            if den == 0.0:
                break
            z -= 2.0 * gv * d1 / den  # Halley's step
        if -1.0 + 1e-9 < z < 1.0 - 1e-9:
            if nr == 0:
                z1 = z
                nr = 1
            elif abs(z - z1) > 1e-9:
                if z < z1:
                    z2 = z1
                    z1 = z
                else:
                    z2 = z
                nr = 2
    return nr, z1, z2


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def slip_zeros_on_major_axis(s0x, s0y, s0z, asx, asy, asz, bsx, bsy, bsz, nx, ny, nz, mx, my, mz, a, curv):
    """:func:`rolling_slip_zeros` from the contact's sliding field: the centre's sliding velocity s0 [m/s] and its
    rates along e_major (as = ω_s × e_major) and the normal (bs = ω_s × n) [1/s] projected on the rolling direction
    r = n × e_major (σ0 = s0·r, σ1 = a as·r, σ2 = bs·r).  Returns (count, ξ1, ξ2).  The one place both the Gauss rule
    and the cut strips take their zeros from."""
    sig0, sig1, sig2 = slip_rates_on_major_axis(s0x, s0y, s0z, asx, asy, asz, bsx, bsy, bsz, nx, ny, nz, mx, my, mz, a)
    return rolling_slip_zeros(sig0, sig1, sig2, a, curv)


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def slip_rates_on_major_axis(s0x, s0y, s0z, asx, asy, asz, bsx, bsy, bsz, nx, ny, nz, mx, my, mz, a):
    """(σ0, σ1, σ2) [m/s] of the rolling slip along the major axis, g(ξ) = σ0 + σ1 ξ + σ2 δ(aξ)
    (:func:`rolling_slip_zeros`): the contact's sliding field projected on the rolling direction r = n × e_major."""
    rdx, rdy, rdz = ny * mz - nz * my, nz * mx - nx * mz, nx * my - ny * mx
    sig0 = s0x * rdx + s0y * rdy + s0z * rdz
    sig1 = a * (asx * rdx + asy * rdy + asz * rdz)
    sig2 = bsx * rdx + bsy * rdy + bsz * rdz
    return sig0, sig1, sig2


@njit(cache=True, error_model="numpy", fastmath={"contract"})
def _gauss_node(m, ng, nroot, z1, z2):
    """Node m of :func:`_gauss_quadrature`'s rule: ng Gauss–Legendre nodes on each of the nroot + 1 sub-intervals of
    ξ ∈ [−1, 1] between the zeros z1 < z2 of the rolling slip, node m on sub-interval m // ng.  Returns (ξ, weight).

    The nodes are graded towards the zeros of the rolling slip (t² maps, smoothstep with zeros at both ends): μ(s)
    rises steeply from 0 there (measured: graded 0.25 %, 2.4 %, 0.5 % error at 4 nodes on the hub states against
    plain Gauss 0.64 %, 2.5 %, 1.6 %; grading towards ξ = ±1 gives 1.3 %, 5.8 %, 2.3 %)."""
    k = m // ng
    i = m - k * ng
    lo = -1.0 if k == 0 else (z1 if k == 1 else z2)
    hi = 1.0 if k == nroot else (z1 if k == 0 else z2)
    span = hi - lo
    zlo = k > 0  # the lower end is a zero of the rolling slip (else ξ = −1)
    zhi = k < nroot  # the upper end is a zero (else ξ = +1)
    t = 0.5 + 0.5 * _GL_X[ng, i]
    if zlo and zhi:
        psi = t * t * (3.0 - 2.0 * t)
        dpsi = 6.0 * t * (1.0 - t)
    elif zlo:
        psi = t * t
        dpsi = 2.0 * t
    elif zhi:
        psi = t * (2.0 - t)
        dpsi = 2.0 * (1.0 - t)
    else:
        psi = t
        dpsi = 1.0
    return lo + span * psi, 0.5 * span * dpsi * _GL_W[ng, i]


# ---- generalized Gauss rules with the logarithm of the slip's zeros (n_slices = LOG_BASE + n) -------------------
#
# Next to a zero of the rolling slip, μ(s)·ŝ rises from 0 over a core of width ~1e-3 of the axis (the film's linear
# response), then grows about as the logarithm of the distance to the zero (the Eyring stress, asinh of the shear rate)
# until it levels off (measured on the hub states).  Gauss–Legendre nodes
# converge slowly on such an integrand even graded towards the zero; rules built to integrate the logarithm exactly
# take it with few nodes (the generalized Gaussian quadratures of Ma, Rokhlin & Wandzura 1996, here with one log term):
#   one-sided, t ∈ [0, 1] from the zero: exact for 1, t, …, t^(2n−2) and ln t (n nodes, 2n unknowns);
#   two-sided, symmetric about t = 1/2, zeros at both ends: exact for every polynomial of degree ≤ 2n − 3 and
#   ln t + ln(1 − t) (n ≥ 2).
# The nodes and weights were solved once from these moment equations (∫₀¹ tᵏ dt = 1/(k+1), ∫₀¹ ln t dt = −1, with
# scipy.optimize.least_squares to a residual ≤ 6e-17; n = 1: t = 1/e; two-sided n = 2: t(1 − t) = e⁻²);
# tests/unit/test_log_rule.py checks every moment.  Row n, entries 0..n−1 ascending.
_LOG1_X = np.zeros((7, 6))
_LOG1_W = np.zeros((7, 6))
for _n, _x, _w in (
        (1, (0.36787944117144233,), (1.0,)),
        (2, (0.10948125144610703, 0.7133913765777445), (0.35334955930939316, 0.646650440690607)),
        (3, (0.050353134746613355, 0.3969985049294198, 0.8552246120115472),
         (0.1675406248553914, 0.4809327499596189, 0.35152662518498984)),
        (4, (0.028670570407544154, 0.24159123743099462, 0.6060427719000977, 0.914782440093087),
         (0.09640736620552812, 0.31789621538495505, 0.373615070883663, 0.21208134752585392)),
        (5, (0.018453540464295932, 0.16034712387920436, 0.4306586561404479, 0.7299495255136921, 0.9442991323339215),
         (0.06235400600646219, 0.2186596488904285, 0.30433270420823594, 0.27447069105355276, 0.14018294984132054)),
        (6, (0.012854637567290498, 0.1135732391430297, 0.31637334764266306, 0.5695175583461733, 0.8053802015579017,
             0.9608729079075851),
         (0.04355004147923783, 0.1578098719803966, 0.2386634867084882, 0.2560288270751804, 0.2048820041118846,
          0.09906576864481248))):
    _LOG1_X[_n, :_n], _LOG1_W[_n, :_n] = _x, _w
_LOG2_X = np.zeros((5, 4))
_LOG2_W = np.zeros((5, 4))
for _n, _x, _w in (
        (2, (0.16137820985148146, 0.8386217901485186), (0.5, 0.5)),
        (3, (0.06772448199575876, 0.5, 0.9322755180042412),
         (0.2229808047444392, 0.5540383905111216, 0.2229808047444392)),
        (4, (0.03618329587943532, 0.29707252708404963, 0.7029274729159504, 0.9638167041205646),
         (0.12116887714900373, 0.37883112285099624, 0.37883112285099624, 0.12116887714900373))):
    _LOG2_X[_n, :_n], _LOG2_W[_n, :_n] = _x, _w
#: the smallest distance [-] (in ξ) of the slip's nearest zero that the root-free stretch's sinh map grades towards
LOG_SINH_FLOOR = 0.05


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _log_counts(n, nroot):
    """Nodes (n0, n1, n2) [-] of the log rule (LOG_MIN ≤ n ≤ LOG_MAX, as the entry points check) on the stretches of
    ξ ∈ [−1, 1] between the nroot zeros of the rolling slip: all n on the axis without a zero; n − n // 2 below one
    zero and n // 2 above it; two on each outer stretch and n − 4 between two zeros.  Fixed per count of zeros, so the
    nodes move continuously with the zeros (dealing the nodes by length makes the force jump where a node changes
    stretch: 24 times the steps on the hub).  Unused stretches: 0."""
    if nroot == 0:
        return n, 0, 0
    if nroot == 1:
        return n - n // 2, n // 2, 0
    return 2, n - 4, 2


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def nearest_slip_zero(sig0, sig1, sig2, a, curv):
    """The zero of the rolling slip nearest the ellipse's axis ξ ∈ [−1, 1], off it: (ξ_b, d) [-] with ξ_b the point of
    the axis nearest the zero and d its distance, from the quadratic g(ξ) ≈ σ0 + σ1 ξ + ½ σ2 c a² ξ² of
    :func:`rolling_slip_zeros` (a complex pair x ± iy: ξ_b = clamp(x), d = |x + iy − ξ_b|; real zeros beyond ±1: the
    nearer, the lower ξ_b of two equally near).  d = inf when g has no zero (the rule's map is then affine)."""
    aa = 0.5 * sig2 * curv * a * a
    scale = abs(aa) + abs(sig1) + abs(sig0)
    xb = 0.0
    d = math.inf
    if scale == 0.0:
        return xb, d
    aa /= scale  # (the zeros do not change with the field's scale; σ1² cannot underflow, as in rolling_slip_zeros)
    sig1 /= scale
    sig0 /= scale
    if abs(aa) <= 1e-12:  # (of the normalised coefficients' sum, 1: linear, as rolling_slip_zeros)
        if sig1 != 0.0:
            r = -sig0 / sig1
            xb = min(1.0, max(-1.0, r))
            d = abs(r - xb)
        return xb, d
    disc = sig1 * sig1 - 4.0 * aa * sig0
    if disc < 0.0:
        x = -sig1 / (2.0 * aa)
        y = math.sqrt(-disc) / (2.0 * abs(aa))
        xb = min(1.0, max(-1.0, x))
        return xb, math.sqrt((x - xb) ** 2 + y * y)
    qq = -0.5 * (sig1 + math.copysign(math.sqrt(disc), sig1))
    for k in range(2):
        r = qq / aa if k == 0 else (sig0 / qq if qq != 0.0 else qq / aa)
        rb = min(1.0, max(-1.0, r))
        if abs(r - rb) < d or (abs(r - rb) == d and rb < xb):  # (equally near: the lower end, as the reference)
            xb = rb
            d = abs(r - rb)
    return xb, d


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _log_node(m, nroot, z1, z2, n0, n1, n2, xb, ysh, u0, du):
    """Node m of the log rule (n_slices = LOG_BASE + n): (ξ, weight) [-] for ∫₋₁¹ f(ξ) dξ.

    With zeros of the rolling slip on the axis (nroot ≥ 1), stretch k between them carries n_k nodes
    (:func:`_log_counts`): a stretch with a zero at one end takes the one-sided rule from that end, one between two
    zeros the two-sided rule (tables above).  Without (nroot = 0), n0 Gauss–Legendre nodes in u under the sinh map
    ξ = ξ_b + d sinh u of Johnston & Elliott (2005) towards the slip's nearest zero off the axis
    (:func:`nearest_slip_zero`; ysh = max(d, LOG_SINH_FLOOR), u from u0 = asinh((−1 − ξ_b)/ysh) over du to
    asinh((1 − ξ_b)/ysh), taken once per contact by the caller): μ(s) changes fastest where the slip is smallest, and
    as d grows the map tends to the affine one (plain Gauss–Legendre; ysh > 1e6: that one), so the nodes move
    continuously with the state.  sinh u and cosh u from one exponential."""
    if nroot == 0:
        t = _GL_X[n0, m]
        w = _GL_W[n0, m]
        if ysh > 1e6:  # (the affine limit)
            return t, w
        eu = math.exp(u0 + 0.5 * du * (1.0 + t))
        ie = 1.0 / eu
        return xb + 0.5 * ysh * (eu - ie), 0.25 * du * w * ysh * (eu + ie)
    k = 0
    i = m
    n_k = n0
    if i >= n0:
        k = 1
        i -= n0
        n_k = n1
        if i >= n1:
            k = 2
            i -= n1
            n_k = n2
    lo = -1.0 if k == 0 else (z1 if k == 1 else z2)
    hi = 1.0 if k == nroot else (z1 if k == 0 else z2)
    span = hi - lo
    if k > 0 and k < nroot:  # zeros at both ends
        return lo + span * _LOG2_X[n_k, i], span * _LOG2_W[n_k, i]
    if k > 0:  # the zero at the lower end
        return lo + span * _LOG1_X[n_k, i], span * _LOG1_W[n_k, i]
    return hi - span * _LOG1_X[n_k, i], span * _LOG1_W[n_k, i]  # the zero at the upper end


@njit(cache=True, error_model="numpy", _nrt=False, fastmath={"contract"})
def _gauss_quadrature(ng, log_rule, q, a, b, curv, nx, ny, nz, mx, my, mz, d0bx, d0by, d0bz, d0rx, d0ry, d0rz,
                      s0x, s0y, s0z, wsx, wsy, wsz, e0x, e0y, e0z, wex, wey, wez, u0,
                      need_b, need_f, fluid_kind, wfl, hc, theta, do_roll, reg, fr_scale, lub, ln_eta0, out):
    """The integrals of the strip model in its limit of infinitely many strips, by Gauss–Legendre
    quadrature with ``ng`` nodes on each sub-interval of ξ = x/a ∈ [−1, 1] between the zeros of the
    rolling-direction sliding speed (:func:`rolling_slip_zeros`), where μ(s)·ŝ jumps or turns
    steeply.  Densities per unit ξ (the strip formulae of the module docstring with the strip
    width → 0): load (3Q/4)(1 − ξ²) (seed eq. 1), mean pressure across the chord
    p̄ = 3Q√(1 − ξ²)/(8ab), chord 2b√(1 − ξ²) (film elasticity), rolling resistance per unit
    length from Zhou & Hoeprich (1991) eq. 17 (or Martin's) with the line load (3Q/4a)(1 − ξ²).
    The load density is a polynomial, so each sub-interval is integrated exactly for integrands
    polynomial in ξ of degree ≤ 2 ng − 3 (e.g. constant μ with a linear moment arm).  The rolling
    resistance has no zeros of the slip in it: it is integrated on its own ROLL_NODES fixed
    Gauss–Jacobi nodes whose weight is its line-load factor (1 − ξ²)^0.246 (or ^0.5, Martin), exact for
    the factor and smooth in the rest (u^0.648, the arms).  u0 [m/s] the entraining speed at the
    ellipse centre (u^0.648 is u0^0.648 (u/u0)^0.648 with the second factor by :func:`_pow_0648`, as in
    the strip loop).
    The traction coefficient at a node is the strip loop's film law (seed eq. 2) for one point,
    :func:`_film_lanes` on eight nodes at a time (out[10:] their lanes; ln_eta0 = ln η0).  Writes out[0:10] like
    :func:`contact_traction`.  All SI."""
    # the rates of the velocity fields along e_major and n
    asx, asy, asz = wsy * mz - wsz * my, wsz * mx - wsx * mz, wsx * my - wsy * mx
    bsx, bsy, bsz = wsy * nz - wsz * ny, wsz * nx - wsx * nz, wsx * ny - wsy * nx
    aex, aey, aez = wey * mz - wez * my, wez * mx - wex * mz, wex * my - wey * mx
    bex, bey, bez = wey * nz - wez * ny, wez * nx - wex * nz, wex * ny - wey * nx
    sig0, sig1, sig2 = slip_rates_on_major_axis(s0x, s0y, s0z, asx, asy, asz, bsx, bsy, bsz, nx, ny, nz, mx, my, mz, a)
    nroot, z1, z2 = rolling_slip_zeros(sig0, sig1, sig2, a, curv)
    # log_rule: ng nodes in all (_log_node), dealt to the stretches by _log_counts, or graded towards the slip's
    # nearest zero off the ellipse's axis when none lies on it
    n0 = n1 = n2 = 0
    xb = ysh = u0 = du = 0.0
    if log_rule:
        n0, n1, n2 = _log_counts(ng, nroot)
        if nroot == 0:  # the sinh map's constants (_log_node)
            xb, dz = nearest_slip_zero(sig0, sig1, sig2, a, curv)
            ysh = max(dz, LOG_SINH_FLOOR)
            if ysh <= 1e6:
                u0 = math.asinh((-1.0 - xb) / ysh)
                du = math.asinh((1.0 - xb) / ysh) - u0
    rx = lub[L_RX]
    alpha = lub[L_ALPHA]
    e_eff = lub[L_EEFF]
    eta0 = lub[L_ETA0]
    # rolling resistance: Martin k_ir √(u (1 − ξ²)), or Zhou–Hoeprich k_zh e^ln_zh u^0.648 (1 − ξ²)^0.246 per unit ξ
    k_ir = 0.0
    k_zh = 0.0
    ln_zh = 0.0
    k_zh_u0 = 0.0
    roll_zh = do_roll and reg != 0 and u0 > 0.0
    if do_roll:
        if reg == 0:
            k_ir = MARTIN_ROLLING * a * fr_scale * math.sqrt(0.75 * eta0 * q / a)
        else:
            k_zh = 29.2 * (rx / alpha) * a * fr_scale
            ln_zh = 0.648 * math.log(alpha * eta0 / rx) + 0.246 * math.log(0.75 * q / (a * e_eff * rx))
            if roll_zh:
                k_zh_u0 = k_zh * math.exp(ln_zh + 0.648 * math.log(u0))
    inv_u0 = 1.0 / u0 if u0 > 0.0 else 0.0
    # the nodes go through the film law eight at a time, as the strips do (traction_at): (A) each node's load,
    # point and velocities on a lane, (B) the traction coefficient on the lanes (_film_lanes), (C) the traction of
    # the loaded nodes with a sliding speed
    film = need_f and fluid_kind != 0 and hc > 0.0
    p_c = 0.375 * q / (a * b)  # p̄ = p_c √(1 − ξ²)
    two_rx = 2.0 * rx
    lw = out[10:]
    n_nodes = ng if log_rule else (nroot + 1) * ng
    for c0 in range(0, n_nodes, LANES):
        nl = min(LANES, n_nodes - c0)
        for i in range(LANES):
            om = xi = wgt = 0.0
            if i < nl:
                if log_rule:
                    xi, wgt = _log_node(c0 + i, nroot, z1, z2, n0, n1, n2, xb, ysh, u0, du)
                else:
                    xi, wgt = _gauss_node(c0 + i, ng, nroot, z1, z2)
                om = 1.0 - xi * xi
            qn = 0.0
            if om > 0.0:
                qn = 0.75 * q * om * wgt  # the node's load per unit ξ times its weight
            else:
                xi = om = 0.0
            lw[LQ + i] = qn
            lw[LX + i] = a * xi
            lw[LA + i] = om
        vsqrt(lw, LA, lw, LB)  # √(1 − ξ²)
        for i in range(LANES):
            # mean pressure across the node's chord 2b√(1 − ξ²)
            lw[LP + i] = p_c * lw[LB + i]
            lw[LCHORD + i] = 2.0 * b * lw[LB + i]
        _lane_kinematics(lw, curv, nx, ny, nz, mx, my, mz, s0x, s0y, s0z, bsx, bsy, bsz, asx, asy, asz, e0x, e0y, e0z,
                         bex, bey, bez, aex, aey, aez)
        _film_lanes(lw, need_b, need_f, fluid_kind, film, wfl, lub, b, hc, theta, ln_eta0)
        for i in range(nl):
            if lw[LQ + i] > 0.0:
                _add_lane_traction(out, lw, i, mx, my, mz, nx, ny, nz, d0bx, d0by, d0bz, d0rx, d0ry, d0rz)
    # rolling resistance and oil-film force on the fixed Gauss-Jacobi nodes (the line-load factor in the weight)
    row = 0 if reg == 0 else 1
    for j in range(ROLL_NODES if do_roll else 0):
        x = a * _RJ_X[row, j]
        wgt = _RJ_W[row, j]
        off, root = slice_point_offset(x, curv)
        (sx, sy, sz, smag, ex, ey, ez, uj, njx, njy, njz) = _slice_kinematics(
            x, root, curv, nx, ny, nz, mx, my, mz, s0x + off * bsx, s0y + off * bsy, s0z + off * bsz,
            asx, asy, asz, e0x + off * bex, e0y + off * bey, e0z + off * bez, aex, aey, aez)
        if not uj > 0.0:
            continue
        inv_u = 1.0 / uj
        if reg == 0:
            fr = k_ir * wgt * math.sqrt(uj)
        elif roll_zh:
            fr = k_zh_u0 * wgt * _pow_0648(uj * inv_u0)
        else:  # no entraining speed at the centre (u0 = 0): the formula as it stands
            fr = k_zh * wgt * math.exp(0.648 * math.log(uj) + ln_zh)
        dbx, dby, dbz = d0bx + x * mx + off * nx, d0by + x * my + off * ny, d0bz + x * mz + off * nz
        drx, dry, drz = d0rx + x * mx + off * nx, d0ry + x * my + off * ny, d0rz + x * mz + off * nz
        add_point_rolling(out, fr, uj, ex * inv_u, ey * inv_u, ez * inv_u, dbx, dby, dbz, drx, dry, drz, njx, njy,
                          njz, two_rx, 1.0 / math.sqrt(dbx * dbx + dby * dby + dbz * dbz))


# --------------------------------------------------------------------------- Python side


def pack_lubrication_parameters(lubricant, temperature: float, e_eff: float, rx: float, ry: float,
                                roughness: float = 0.0, boundary_model=(0.0, 0.12, 0.01, 0.10), *,
                                model: str = "mixed", fluid_model: str = "physical", fluid_curve=None,
                                lambda_limits=(1.0, 3.0), thermal: bool = True, starvation_factor: float = 1.0,
                                rolling_resistance: bool = True, solid_effusivity: float = 1.32e4,
                                viscoelastic: bool = True, film_modulus_factor: float = 1.0,
                                solids=None) -> np.ndarray:
    """Build the parameter vector ``lub`` of :func:`contact_traction` for one contact type.

    Parameters
    ----------
    lubricant : Lubricant | str   library name, TOML path or :class:`bearingsim.lubricants.Lubricant`
    temperature : float  [K]   inlet (bulk) temperature
    e_eff : float  [Pa]        E′ of the ball/race pair
    rx, ry : float  [m]        effective radii of the contact (rolling, transverse)
    roughness : float  [m]     composite rms roughness σ = √(σ₁² + σ₂²) (0 = smooth: fully fluid)
    boundary_model : (μ₀, μ_max, s_max, μ_∞) of the boundary curve (default gives
        μ_b = (−0.1 + 22.28 s) e^(−181.5 s) + 0.1, our typical choice)
    model : "boundary" | "fluid" | "mixed"
    fluid_model : "physical" (Eyring + limiting shear stress, thermal) | "curve"
    fluid_curve : (μ₀, μ_max, s_max, μ_∞), required for fluid_model="curve"
    lambda_limits : (Λ₁, Λ₂) of the mixed interpolation
    thermal : apply the Zhu–Cheng inlet factor and the shear heating
    starvation_factor : φ_s ∈ (0, 1]
    rolling_resistance : include rolling viscous resistance and oil-film force
    solid_effusivity : √(kρc) of the ball/race material [W s^0.5/(m² K)]
        (default: 52100 steel, k = 46.6 W/(m K), ρ = 7830 kg/m³, c = 475 J/(kg K), typical values)
    viscoelastic : film elasticity in the physical fluid model (Johnson & Tevaarwerk 1977
        elastic/plastic mean stress, :func:`bearingsim.contact.traction.elastic_plastic_mean_stress`)
    film_modulus_factor : factor [-] on the film's elastic shear modulus G_f = τ_L/r_L (1: the law as is; scales
        the small-slip slope of a film-dominated contact, for sensitivity studies)
    solids : None (rigid solids: the film's compliance alone) or (G [Pa], ν [-]) of the solids: their tangential
        compliance in series with the film's, per point with Kalker's simplified-theory flexibility
        L₁ = 8 a_r/(3 C₁₁ G) (a_r the semi-axis in the rolling direction;
        :func:`bearingsim.contact.traction.solids_in_series_factor`)
    """
    from ..lubricants import get_lubricant

    lub_obj = get_lubricant(lubricant)
    t = lub_obj.check_temperature(temperature)
    for name, v in (("e_eff", e_eff), ("rx", rx), ("ry", ry), ("solid_effusivity", solid_effusivity)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(name, f"must be positive and finite, got {v!r}", "")
    if not (isinstance(roughness, (int, float)) and math.isfinite(roughness) and roughness >= 0):
        raise InputError("roughness", f"must be finite and >= 0, got {roughness!r}", 'e.g. "0.05 um"')
    if model not in MODELS:
        raise InputError("model", f"unknown traction model {model!r}", f"use one of {', '.join(MODELS)}")
    if fluid_model not in FLUID_MODELS:
        raise InputError("fluid_model", f"unknown fluid model {fluid_model!r}", f"use one of {', '.join(FLUID_MODELS)}")
    if not (0.0 < starvation_factor <= 1.0):
        raise InputError("starvation_factor", f"must lie in (0, 1], got {starvation_factor!r}", "1 = fully flooded")
    l1, l2 = lambda_limits
    if not (0.0 <= l1 < l2):
        raise InputError("lambda_limits", f"need 0 <= lambda1 < lambda2, got {lambda_limits!r}", "e.g. (1, 3)")
    lub = np.zeros(L_SIZE)
    lub[L_MODEL] = MODELS[model]
    lub[L_FLUID] = FLUID_MODELS[fluid_model]
    eta0 = lub_obj.dynamic_viscosity(t)
    lub[L_ETA0] = eta0
    lub[L_ALPHA] = lub_obj.pressure_viscosity_coefficient
    lub[L_EEFF] = e_eff
    lub[L_RX] = rx
    lub[L_RY] = ry
    lub[L_SIGMA] = roughness
    beta_v = lub_obj.viscosity_temperature_coefficient(t)
    lub[L_BETA_ETA] = beta_v * eta0
    lub[L_KOIL] = lub_obj.thermal_conductivity
    lub[L_PHI_S] = starvation_factor
    lub[L_THERMAL] = 1.0 if thermal else 0.0
    if fluid_model == "curve":
        if fluid_curve is None:
            raise InputError("fluid_curve", "required with fluid_model='curve'",
                             "give (mu0, mu_max, s_max, mu_inf), e.g. (0, 0.06, 0.01, 0.045)")
        lub[L_FA:L_FD + 1] = traction.fit_four_parameter(*fluid_curve)
    lub[L_BA:L_BD + 1] = traction.fit_four_parameter(*boundary_model)
    lub[L_LAM1] = l1
    lub[L_LAM2] = l2
    lub[L_TAU0] = lub_obj.eyring_stress
    lub[L_LSS_R] = lub_obj.lss_ratio
    lub[L_LSS_C1] = lub_obj.lss_c1
    lub[L_LSS_C2] = lub_obj.lss_c2
    lub[L_LSS_C3] = lub_obj.lss_c3
    lub[L_LSS_C4] = lub_obj.lss_c4
    lub[L_LSS_FLOOR] = lub_obj.lss_floor
    lub[L_BETA_V] = beta_v
    lub[L_ROE_LN] = math.log(eta0) + 9.67
    lub[L_ROE_Z] = lub_obj.roelands_index(t)
    lub[L_EFFUS] = solid_effusivity
    lub[L_ROLLRES] = 1.0 if rolling_resistance else 0.0
    lub[L_T0C] = t - 273.15
    lub[L_VISCO] = 1.0 if viscoelastic else 0.0
    if not (isinstance(film_modulus_factor, (int, float)) and math.isfinite(film_modulus_factor)
            and film_modulus_factor > 0):
        raise InputError("film_modulus_factor", f"must be a positive number, got {film_modulus_factor!r}", "e.g. 1")
    lub[L_GF_SCALE] = film_modulus_factor
    if solids is not None:
        lub[L_SFLEX] = traction.solids_flexibility_coefficient(rx, ry, *solids)
    if lub[L_ALPHA] > 0.0 and rx > 0.0 and ry > 0.0:
        lub[L_C_AE] = lub[L_ALPHA] * lub[L_EEFF]
        lub[L_C_AR] = lub[L_RY] / lub[L_RX]
        lub[L_C_LNG:L_C_FKIE + 1] = film_constants(lub[L_ALPHA], lub[L_EEFF], lub[L_RX], lub[L_RY])
    return lub


def deformed_surface_radius(ball_diameter: float, groove_radius: float) -> float:
    """Jones (1960) radius of the deformed contact surface, 2 r_g D/(2 r_g + D) [m] (positive, see module doc)."""
    if not (ball_diameter > 0 and groove_radius > 0):
        raise InputError("groove_radius", "ball diameter and groove radius must be positive", "")
    return 2.0 * groove_radius * ball_diameter / (2.0 * groove_radius + ball_diameter)


def check_strip_count(n_slices) -> None:
    """Raise InputError unless n_slices [-] is an integer in 1..STRIPS_MAX (the kernel reads larger codes as its
    other rules: SPLIT_BASE + n, LOG_BASE + n)."""
    if not isinstance(n_slices, (int, np.integer)) or isinstance(n_slices, bool) or not 1 <= n_slices <= STRIPS_MAX:
        raise InputError("n_slices", f"must be an integer in 1..{STRIPS_MAX}, got {n_slices!r}", "use e.g. 10 slices")


def check_contact_inputs(q, a, b, vectors: dict, n_slices) -> None:
    """Raise InputError for bad kernel input (NaN velocities, a count outside 1..STRIPS_MAX, negative load); the kernel
    does not check."""
    check_strip_count(n_slices)
    for name, v in (("load", q), ("a", a), ("b", b)):
        if not (math.isfinite(v) and v >= 0):
            raise InputError(name, f"must be finite and >= 0, got {v!r}", "")
    for name, vec in vectors.items():
        arr = np.asarray(vec, dtype=float)
        if arr.shape != (3,) or not np.all(np.isfinite(arr)):
            raise InputError(name, f"must be three finite numbers, got {vec!r}", "check the state for NaN/inf")


def contact_traction_checked(q, a, b, r_dev, centre, normal, major, ball_centre, v_ball, w_ball,
                             race_centre, v_race, w_race, lub, n_slices, quadrature: str = "strips") -> np.ndarray:
    """Python entry: checks the input (typed errors), then calls the kernel; returns out[10].

    quadrature "strips": n_slices equal strips (seed eq. 1); "gauss": n_slices Gauss–Legendre nodes
    (1..GAUSS_MAX) on each sub-interval between the zeros of the rolling slip (the kernel's n_slices < 0); "log":
    n_slices nodes in all (LOG_MIN..LOG_MAX), generalized Gauss rules with the logarithm of the slip's zeros
    (:func:`_log_node`; the kernel's LOG_BASE + n)."""
    vecs = dict(centre=centre, normal=normal, major=major, ball_centre=ball_centre, v_ball=v_ball, w_ball=w_ball,
                race_centre=race_centre, v_race=v_race, w_race=w_race)
    check_contact_inputs(q, a, b, vecs, n_slices)
    if quadrature == "gauss":
        if n_slices > GAUSS_MAX:
            raise InputError("n_slices", f"at most {GAUSS_MAX} Gauss nodes per sub-interval, got {n_slices}",
                             "use 3 or 4 nodes")
        n_slices = -n_slices
    elif quadrature == "log":
        if not LOG_MIN <= n_slices <= LOG_MAX:
            raise InputError("n_slices", f"the log rule takes {LOG_MIN}..{LOG_MAX} nodes in all, got {n_slices}",
                             "use 7 nodes")
        n_slices = LOG_BASE + n_slices
    elif quadrature != "strips":
        raise InputError("quadrature", f"unknown quadrature {quadrature!r}", "use strips, gauss or log")
    lub = np.asarray(lub, dtype=float)
    if lub.shape != (L_SIZE,) or not np.all(np.isfinite(lub)):
        raise InputError("lub", "must be the finite vector built by pack_lubrication_parameters", "")
    args = [np.ascontiguousarray(vecs[k], dtype=float) for k in vecs]
    out = np.zeros(10)
    contact_traction(float(q), float(a), float(b), float(r_dev), *args, lub, int(n_slices), out)
    return out


def contact_traction_reference(q, a, b, r_dev, centre, normal, major, ball_centre, v_ball, w_ball,
                               race_centre, v_race, w_race, lub, n_slices, out):
    """Slow pure-Python/numpy reference of :func:`contact_traction` (same arguments and output).

    Written independently of the kernel with numpy vectors and the pure-Python versions
    (``py_func``) of the model functions; the tests compare the two to 1e-10.
    """
    out[:] = 0.0
    if not (q > 0 and a > 0 and b > 0) or n_slices == 0:
        return
    n = np.asarray(normal, float)
    m = np.asarray(major, float)
    cb = np.asarray(ball_centre, float)
    cr = np.asarray(race_centre, float)
    vb, wb = np.asarray(v_ball, float), np.asarray(w_ball, float)
    vr, wr = np.asarray(v_race, float), np.asarray(w_race, float)
    c = 0.0 if (not math.isfinite(r_dev) or r_dev == 0) else 1.0 / r_dev
    r = cb - cr
    omega = np.cross(r, vb) / (r @ r) if r @ r > 0 else np.zeros(3)

    def kin(p, nn):
        ub = vb + np.cross(wb, p - cb)
        ur = vr + np.cross(wr, p - cr)
        uc = vb + np.cross(omega, p - cb)
        s = ub - ur
        s = s - (s @ nn) * nn
        e = 0.5 * (ub + ur) - uc
        e = e - (e @ nn) * nn
        return s, e

    model, kind = int(lub[L_MODEL]), int(lub[L_FLUID])
    eta0, alpha, e_eff, rx, ry, sigma = (lub[L_ETA0], lub[L_ALPHA], lub[L_EEFF], lub[L_RX], lub[L_RY], lub[L_SIGMA])
    p0 = np.asarray(centre, float)
    s0v, e0v = kin(p0, n)
    u0, s0 = float(np.linalg.norm(e0v)), float(np.linalg.norm(s0v))
    phi = lub[L_PHI_S]
    if lub[L_THERMAL] != 0 and u0 > 0:
        phi *= ehl.zhu_cheng_thermal_factor.py_func(1.5 * q / (math.pi * a * b), e_eff, lub[L_BETA_ETA], u0,
                                                    lub[L_KOIL], s0 / u0)
    hc = phi * ehl.hamrock_dowson_central.py_func(u0, q, eta0, alpha, e_eff, rx, ry)
    hmin = phi * ehl.hamrock_dowson_minimum.py_func(u0, q, eta0, alpha, e_eff, rx, ry)
    if model == 0:
        w = 0.0
    elif model == 1:
        w = 1.0
    else:
        w = traction.mixed_weight.py_func(hmin / sigma, lub[L_LAM1], lub[L_LAM2]) if sigma > 0 else 1.0
    reg = ehl.regime_code.py_func(eta0 * u0 / (e_eff * rx), alpha * e_eff, q / (e_eff * rx * rx), rx, ry)
    theta = 0.0
    if lub[L_THERMAL] != 0:
        theta = hc / (12 * lub[L_KOIL]) + (0.5 * _FLASH * math.sqrt(2 * b / u0) / lub[L_EFFUS] if u0 > 0 else 0.0)
    lss = [lub[k] for k in (L_LSS_R, L_LSS_C1, L_LSS_C2, L_LSS_C3, L_LSS_C4, L_LSS_FLOOR)]

    def point_mu(smag, uj, pbar, chord):
        """μ at one point: sliding speed, entraining speed, mean pressure across the chord, chord length."""
        sr = smag / uj if uj > 0 else 1e300
        mu = 0.0
        if w < 1:
            mu = traction.four_parameter.py_func(sr, *lub[L_BA:L_BD + 1])
        if w > 0:
            if kind == 0:
                muf = traction.four_parameter.py_func(sr, *lub[L_FA:L_FD + 1])
            else:
                eta_p = traction.roelands_viscosity.py_func(pbar, eta0, lub[L_ROE_LN], lub[L_ROE_Z])
                tau = 0.0
                if hc > 0:
                    tau = traction.fluid_shear_stress.py_func(pbar, smag, hc, theta, eta_p, lub[L_TAU0], lub[L_T0C],
                                                              *lss, lub[L_BETA_V])
                    if lub[L_VISCO] != 0 and lss[0] > 0 and uj > 0:
                        # Johnson-Tevaarwerk elastic/plastic film: G = τ_L(p̄, t₀)/r_L over the chord
                        g_mod = (traction.limiting_shear_stress.py_func(pbar, lub[L_T0C], *lss) / lss[0]
                                 * lub[L_GF_SCALE])
                        ser = 1.0 / (1.0 + g_mod * lub[L_SFLEX] * b / hc)  # solids in series (Kalker L1)
                        tau = traction.elastic_plastic_mean_stress.py_func(tau, g_mod * chord * sr / hc * ser)
                muf = tau / pbar
            mu = mu + (muf - mu) * w
        return mu

    F = np.zeros(3)
    Mb = np.zeros(3)
    Mr = np.zeros(3)
    power = 0.0

    def add_point(x, qj, pbar, chord, roll):
        """Traction and rolling resistance of one strip or node at x along the major axis, load qj; ``roll``
        (u, nj) → the rolling-resistance force F_R [N]."""
        nonlocal power
        root = math.sqrt(max(0.0, 1 - (c * x) ** 2))
        p = p0 + x * m + (c * x * x / (1 + root)) * n
        nj = root * n - c * x * m
        s, e = kin(p, nj)
        smag, uj = float(np.linalg.norm(s)), float(np.linalg.norm(e))
        if smag > 0 and qj > 0:
            mu = point_mu(smag, uj, pbar, chord)
            f = -mu * qj * s / smag
            F[:] += f
            Mb[:] += np.cross(p - cb, f)
            Mr[:] += np.cross(p - cr, -f)
            power += mu * qj * smag
        if roll is not None and lub[L_ROLLRES] != 0 and w > 0 and uj > 0:
            fr = roll(uj) * phi * w
            h = e / uj
            r1 = float(np.linalg.norm(p - cb))
            inv_r2 = 1 / rx - 1 / r1
            p1 = 2 * fr * rx / r1
            p2 = 2 * fr * rx * inv_r2
            F[:] += (p1 - fr) * h
            Mb[:] += np.cross(p - cb, -fr * h)
            Mr[:] += np.cross(p - cr, (p2 - fr) * h) - 2 * fr * rx * np.cross(nj, h)
            power += 2 * fr * uj

    def rolling(length, load):
        """Rolling resistance of a line contact of ``length`` [m] carrying ``load`` [N] (Martin or Zhou–Hoeprich)."""
        if reg == 0:
            return lambda u: traction.MARTIN_ROLLING * length * math.sqrt(eta0 * u * load / length)
        return lambda u: traction.rolling_resistance_zh.py_func(eta0 * u / (e_eff * rx), alpha * e_eff,
                                                                 load / (length * e_eff * rx), rx, alpha, length)

    H = lambda z: z * math.sqrt(max(0.0, 1 - z * z)) + math.asin(min(1.0, max(-1.0, z)))  # noqa: E731

    def zeros():
        """The zeros of the rolling slip along the major axis (rolling_slip_zeros on this contact's field)."""
        rdir = np.cross(n, m)
        ws = wb - wr
        sc, _ = kin(p0, n)
        sig = (float(sc @ rdir), a * float(np.cross(ws, m) @ rdir), float(np.cross(ws, n) @ rdir))
        return rolling_slip_zeros.py_func(*sig, a, c)

    def rolling_nodes():
        """The node rules' rolling resistance (the kernel's ROLL_NODES Gauss–Jacobi nodes)."""
        # rolling resistance: Gauss-Jacobi nodes with the line-load factor (1 - ξ²)^0.246 (Zhou-Hoeprich) or
        # (1 - ξ²)^0.5 (Martin) as the weight; per unit ξ the line contact of length a carrying (3Q/4)(1 - ξ²)
        xr, wr_ = gauss_jacobi(ROLL_NODES, 0.5 if reg == 0 else 0.246)
        for xi, wgt in zip(xr, wr_):
            if reg == 0:
                per_xi = lambda u: traction.rolling_resistance_ir.py_func(eta0, u, 0.75 * q / a, a)  # noqa: E731
            else:
                per_xi = lambda u: traction.rolling_resistance_zh.py_func(  # noqa: E731
                    eta0 * u / (e_eff * rx), alpha * e_eff, 0.75 * q / (a * e_eff * rx), rx, alpha, a)
            add_point(a * xi, 0.0, 0.0, 0.0, lambda u, f=per_xi, wgt=wgt: wgt * f(u))

    if 0 < n_slices < LOG_BASE:
        # equal strips; with n_slices = SPLIT_BASE + n the strips that hold a zero of the rolling slip are cut there,
        # each part a strip of its own width
        nst = n_slices - SPLIT_BASE if n_slices > SPLIT_BASE else n_slices
        edges = [-1 + 2 * j / nst for j in range(nst + 1)]
        if n_slices > SPLIT_BASE:
            nroot, z1, z2 = zeros()
            edges = sorted(edges + [z1, z2][:nroot])
        for xi0, xi1 in zip(edges, edges[1:]):
            width = a * (xi1 - xi0)
            Fc = lambda z: (3 * z - z**3) / 4  # noqa: E731
            Gc = lambda z: 0.75 * (z * z / 2 - z**4 / 4)  # noqa: E731
            qj = q * (Fc(xi1) - Fc(xi0))
            if qj <= 0:
                continue
            x = a * (Gc(xi1) - Gc(xi0)) / (Fc(xi1) - Fc(xi0))
            area = a * b * (H(xi1) - H(xi0))
            add_point(x, qj, qj / area, area / width, rolling(width, qj))
    elif n_slices > LOG_BASE:
        # the log rule (the kernel's _log_node): n nodes, n − n // 2 below one zero of the rolling slip and n // 2
        # above it, or two outside two zeros and the rest between them; one-sided tables from a zero, the two-sided
        # one between two;
        # without zeros on the axis, Gauss-Legendre under the sinh map towards the slip's nearest zero off it
        n_nodes = n_slices - LOG_BASE
        nroot, z1, z2 = zeros()
        edges = [-1.0] + [z1, z2][:nroot] + [1.0]
        nodes = []
        if nroot == 0:
            rdir = np.cross(n, m)
            ws = wb - wr
            sc, _ = kin(p0, n)
            s0, s1, s2 = float(sc @ rdir), a * float(np.cross(ws, m) @ rdir), float(np.cross(ws, n) @ rdir)
            coef = [0.5 * s2 * c * a * a, s1, s0]
            while coef and abs(coef[0]) <= 1e-12 * sum(abs(v) for v in coef):
                coef = coef[1:]
            cand = [(abs(root - min(1.0, max(-1.0, root.real))), min(1.0, max(-1.0, root.real)))
                    for root in (np.roots(coef) if len(coef) > 1 else [])]
            d, xb = min(cand) if cand else (math.inf, 0.0)  # the nearest; equally near: the lower end
            y = max(d, LOG_SINH_FLOOR)
            xg, wg = np.polynomial.legendre.leggauss(n_nodes)
            if y > 1e6:
                nodes = list(zip(xg, wg))
            else:
                u0, u1 = math.asinh((-1 - xb) / y), math.asinh((1 - xb) / y)
                us = u0 + 0.5 * (u1 - u0) * (1 + xg)
                nodes = list(zip(xb + y * np.sinh(us), 0.5 * (u1 - u0) * wg * y * np.cosh(us)))
        else:
            counts = [n_nodes - n_nodes // 2, n_nodes // 2] if nroot == 1 else [2, n_nodes - 4, 2]
            for k, (lo, hi) in enumerate(zip(edges, edges[1:])):
                nk = counts[k]
                if 0 < k < nroot:
                    ts, wts = _LOG2_X[nk, :nk], _LOG2_W[nk, :nk]
                    nodes += [(lo + (hi - lo) * t, (hi - lo) * wt) for t, wt in zip(ts, wts)]
                else:
                    ts, wts = _LOG1_X[nk, :nk], _LOG1_W[nk, :nk]
                    nodes += [(lo + (hi - lo) * t if k > 0 else hi - (hi - lo) * t, (hi - lo) * wt)
                              for t, wt in zip(ts, wts)]
        for xi, wgt in nodes:
            om = 1 - xi * xi
            if om > 0:
                add_point(a * xi, 0.75 * q * om * wgt, 3 * q * math.sqrt(om) / (8 * a * b), 2 * b * math.sqrt(om),
                          None)
        rolling_nodes()
    else:
        # Gauss nodes between the zeros of the rolling slip, graded towards the zeros (the kernel's rule,
        # _gauss_quadrature): densities per unit ξ — load (3Q/4)(1 − ξ²), p̄ = 3Q√(1 − ξ²)/(8ab), chord 2b√(1 − ξ²)
        ng = -n_slices
        nroot, z1, z2 = zeros()
        edges = [-1.0] + [z1, z2][:nroot] + [1.0]
        xg, wg = np.polynomial.legendre.leggauss(ng)
        for k in range(nroot + 1):
            lo, hi = edges[k], edges[k + 1]
            zlo, zhi = k > 0, k < nroot
            for t, wt in zip(0.5 + 0.5 * xg, wg):
                psi, dpsi = {(True, True): (3 * t * t - 2 * t**3, 6 * t * (1 - t)), (True, False): (t * t, 2 * t),
                             (False, True): (t * (2 - t), 2 * (1 - t)), (False, False): (t, 1.0)}[(zlo, zhi)]
                xi = lo + (hi - lo) * psi
                wgt = 0.5 * (hi - lo) * dpsi * wt
                om = 1 - xi * xi
                if om <= 0:
                    continue
                add_point(a * xi, 0.75 * q * om * wgt, 3 * q * math.sqrt(om) / (8 * a * b), 2 * b * math.sqrt(om),
                          None)
        rolling_nodes()
    out[0:3] = F
    out[3:6] = Mb
    out[6:9] = Mr
    out[9] = power


__all__ = ["contact_traction", "contact_traction_reference", "contact_traction_checked", "rolling_slip_zeros",
           "GAUSS_MAX",
           "pack_lubrication_parameters", "deformed_surface_radius", "slice_fraction", "slice_centroid",
           "slice_point_offset", "surface_curvature",
           "L_SIZE", "MODELS", "FLUID_MODELS"]
