"""The sliced contact ellipse: tangential forces of a lubricated ball–raceway contact.

Seed 001 (Sakaguchi & Shibutani, NTN Technical Review 87), section 3.1, eqs. 1–5:

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
   carrying Q_j, multiplied by φ_T φ_s and by the fluid weight w(Λ) (the seed assumes it
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
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..errors import InputError
from . import ehl, traction
from .ehl import hamrock_dowson_central, hamrock_dowson_minimum, regime_code, zhu_cheng_thermal_factor
from .traction import (four_parameter, fluid_shear_stress, mixed_weight, roelands_viscosity,
                       rolling_resistance_ir, rolling_resistance_zh)

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
L_SIZE = 35

MODELS = {"boundary": 0, "fluid": 1, "mixed": 2}
FLUID_MODELS = {"curve": 0, "physical": 1}

#: 4/(3 sqrt(pi)): mean over the transit of the flash temperature of a half-space under a flux
_FLASH = 4.0 / (3.0 * math.sqrt(math.pi))


@njit(cache=True, error_model="numpy")
def slice_fraction(xi0, xi1):
    """Share of the load Q on the strip ξ ∈ [ξ0, ξ1] of the Hertz ellipse (seed eq. 1)."""
    return 0.25 * ((3.0 * xi1 - xi1**3) - (3.0 * xi0 - xi0**3))


@njit(cache=True, error_model="numpy")
def slice_centroid(xi0, xi1):
    """Load centroid ξ̄ = x̄/a of the strip [ξ0, ξ1] (see module docstring)."""
    g = 0.75 * ((0.5 * xi1 * xi1 - 0.25 * xi1**4) - (0.5 * xi0 * xi0 - 0.25 * xi0**4))
    return g / slice_fraction(xi0, xi1)


@njit(cache=True, error_model="numpy")
def slice_area_fraction(xi0, xi1):
    """Area of the strip divided by a b:  [ξ√(1−ξ²) + asin ξ] between ξ0 and ξ1."""
    h1 = xi1 * math.sqrt(max(0.0, 1.0 - xi1 * xi1)) + math.asin(min(1.0, max(-1.0, xi1)))
    h0 = xi0 * math.sqrt(max(0.0, 1.0 - xi0 * xi0)) + math.asin(min(1.0, max(-1.0, xi0)))
    return h1 - h0


@njit(cache=True, error_model="numpy")
def contact_traction(q, a, b, r_dev, centre, normal, major, ball_centre, v_ball, w_ball,
                     race_centre, v_race, w_race, lub, n_slices, out):
    """Tangential forces of one lubricated ball–race contact on n slices (seed 001 eqs. 1–5).

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
    lub float[:] from :func:`pack_lubrication_parameters`; n_slices ≥ 1.

    out float[10] ← force on the ball (3) [N], moment on the ball about ball_centre (3)
    [N m], moment on the race about race_centre (3) [N m], power lost [W] (≥ 0).  The race
    force is minus the ball force.  The normal Hertz force is not included.
    Returns nothing.  See the module docstring for the equations.
    """
    for i in range(10):
        out[i] = 0.0
    if not (q > 0.0 and a > 0.0 and b > 0.0) or n_slices < 1:
        return
    nx, ny, nz = normal[0], normal[1], normal[2]
    mx, my, mz = major[0], major[1], major[2]
    cbx, cby, cbz = ball_centre[0], ball_centre[1], ball_centre[2]
    crx, cry, crz = race_centre[0], race_centre[1], race_centre[2]
    vbx, vby, vbz = v_ball[0], v_ball[1], v_ball[2]
    wbx, wby, wbz = w_ball[0], w_ball[1], w_ball[2]
    vrx, vry, vrz = v_race[0], v_race[1], v_race[2]
    wrx, wry, wrz = w_race[0], w_race[1], w_race[2]
    curv = 0.0
    if math.isfinite(r_dev) and r_dev != 0.0:
        curv = 1.0 / r_dev

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

    # ---- contact-level film (at the ellipse centre) ----
    px, py, pz = centre[0], centre[1], centre[2]
    dbx, dby, dbz = px - cbx, py - cby, pz - cbz
    drx, dry, drz = px - crx, py - cry, pz - crz
    ubx = vbx + wby * dbz - wbz * dby
    uby = vby + wbz * dbx - wbx * dbz
    ubz = vbz + wbx * dby - wby * dbx
    urx = vrx + wry * drz - wrz * dry
    ury = vry + wrz * drx - wrx * drz
    urz = vrz + wrx * dry - wry * drx
    ucx = vbx + oy * dbz - oz * dby
    ucy = vby + oz * dbx - ox * dbz
    ucz = vbz + ox * dby - oy * dbx
    ex = 0.5 * (ubx + urx) - ucx
    ey = 0.5 * (uby + ury) - ucy
    ez = 0.5 * (ubz + urz) - ucz
    en = ex * nx + ey * ny + ez * nz
    ex -= en * nx
    ey -= en * ny
    ez -= en * nz
    u0 = math.sqrt(ex * ex + ey * ey + ez * ez)
    sx, sy, sz = ubx - urx, uby - ury, ubz - urz
    sn = sx * nx + sy * ny + sz * nz
    sx -= sn * nx
    sy -= sn * ny
    sz -= sn * nz
    s0 = math.sqrt(sx * sx + sy * sy + sz * sz)

    phi = lub[L_PHI_S]
    if thermal and u0 > 0.0:
        p_h = 1.5 * q / (math.pi * a * b)
        phi *= zhu_cheng_thermal_factor(p_h, e_eff, lub[L_BETA_ETA], u0, lub[L_KOIL], s0 / u0)
    hc = phi * hamrock_dowson_central(u0, q, eta0, alpha, e_eff, rx, ry)
    hmin = phi * hamrock_dowson_minimum(u0, q, eta0, alpha, e_eff, rx, ry)
    if model == 0:
        wfl = 0.0
    elif model == 1:
        wfl = 1.0
    else:
        if sigma > 0.0:
            wfl = mixed_weight(hmin / sigma, lub[L_LAM1], lub[L_LAM2])
        else:
            wfl = 1.0
    reg = 3
    if u0 > 0.0:
        reg = regime_code(eta0 * u0 / (e_eff * rx), alpha * e_eff, q / (e_eff * rx * rx), rx, ry)
    theta = 0.0
    if thermal:
        theta = hc / (12.0 * lub[L_KOIL])
        if u0 > 0.0:
            theta += 0.5 * _FLASH * math.sqrt(2.0 * b / u0) / lub[L_EFFUS]

    width = 2.0 * a / n_slices
    fx = fy = fz = 0.0
    mbx = mby = mbz = 0.0
    mrx = mry = mrz = 0.0
    power = 0.0
    for j in range(n_slices):
        xi0 = -1.0 + 2.0 * j / n_slices
        xi1 = -1.0 + 2.0 * (j + 1) / n_slices
        frac = slice_fraction(xi0, xi1)
        qj = q * frac
        if qj <= 0.0:
            continue
        x = a * slice_centroid(xi0, xi1)
        cx = curv * x
        root = math.sqrt(max(0.0, 1.0 - cx * cx))
        off = cx * x / (1.0 + root)
        # slice point and local normal
        px = centre[0] + x * mx + off * nx
        py = centre[1] + x * my + off * ny
        pz = centre[2] + x * mz + off * nz
        njx = root * nx - cx * mx
        njy = root * ny - cx * my
        njz = root * nz - cx * mz
        dbx, dby, dbz = px - cbx, py - cby, pz - cbz
        drx, dry, drz = px - crx, py - cry, pz - crz
        ubx = vbx + wby * dbz - wbz * dby
        uby = vby + wbz * dbx - wbx * dbz
        ubz = vbz + wbx * dby - wby * dbx
        urx = vrx + wry * drz - wrz * dry
        ury = vry + wrz * drx - wrx * drz
        urz = vrz + wrx * dry - wry * drx
        # sliding (seed eq. 3), tangential part
        sx, sy, sz = ubx - urx, uby - ury, ubz - urz
        sn = sx * njx + sy * njy + sz * njz
        sx -= sn * njx
        sy -= sn * njy
        sz -= sn * njz
        smag = math.sqrt(sx * sx + sy * sy + sz * sz)
        # entraining velocity relative to the moving contact
        ucx = vbx + oy * dbz - oz * dby
        ucy = vby + oz * dbx - ox * dbz
        ucz = vbz + ox * dby - oy * dbx
        ex = 0.5 * (ubx + urx) - ucx
        ey = 0.5 * (uby + ury) - ucy
        ez = 0.5 * (ubz + urz) - ucz
        en = ex * njx + ey * njy + ez * njz
        ex -= en * njx
        ey -= en * njy
        ez -= en * njz
        uj = math.sqrt(ex * ex + ey * ey + ez * ez)

        if smag > 0.0:
            if uj > 0.0:
                sr = smag / uj
            else:
                sr = 1e300
            mu = 0.0
            if wfl < 1.0:
                mu = four_parameter(sr, lub[L_BA], lub[L_BB], lub[L_BC], lub[L_BD])
            if wfl > 0.0:
                if fluid_kind == 0:
                    muf = four_parameter(sr, lub[L_FA], lub[L_FB], lub[L_FC], lub[L_FD])
                else:
                    pbar = qj / (a * b * slice_area_fraction(xi0, xi1))
                    eta_p = roelands_viscosity(pbar, eta0, lub[L_ROE_LN], lub[L_ROE_Z])
                    tau = fluid_shear_stress(pbar, smag, hc, theta, eta_p, lub[L_TAU0], lub[L_T0C],
                                             lub[L_LSS_R], lub[L_LSS_C1], lub[L_LSS_C2], lub[L_LSS_C3],
                                             lub[L_LSS_C4], lub[L_LSS_FLOOR], lub[L_BETA_V])
                    muf = tau / pbar
                mu = mu + (muf - mu) * wfl
            f = -mu * qj / smag
            tx, ty, tz = f * sx, f * sy, f * sz
            fx += tx
            fy += ty
            fz += tz
            mbx += dby * tz - dbz * ty
            mby += dbz * tx - dbx * tz
            mbz += dbx * ty - dby * tx
            mrx -= dry * tz - drz * ty
            mry -= drz * tx - drx * tz
            mrz -= drx * ty - dry * tx
            power += mu * qj * smag

        if rollres and wfl > 0.0 and uj > 0.0:
            if reg == 0:
                fr = rolling_resistance_ir(eta0, uj, qj / width, width)
            else:
                fr = rolling_resistance_zh(eta0 * uj / (e_eff * rx), alpha * e_eff, qj / (width * e_eff * rx),
                                           rx, alpha, width)
            fr *= phi * wfl
            hx, hy, hz = ex / uj, ey / uj, ez / uj
            r1 = math.sqrt(dbx * dbx + dby * dby + dbz * dbz)
            p1 = 2.0 * fr * rx / r1
            p2 = 2.0 * fr - p1
            # ball: shear -fr at p, pressure p1 through the centre
            gb = p1 - fr
            fx += gb * hx
            fy += gb * hy
            fz += gb * hz
            mbx += -fr * (dby * hz - dbz * hy)
            mby += -fr * (dbz * hx - dbx * hz)
            mbz += -fr * (dbx * hy - dby * hx)
            # race: shear -fr at p, pressure p2 through its centre of curvature p - R2 n_j:
            # (p - cr - R2 n) x (p2 h) = (p - cr) x (p2 h) - 2 fr rx (1/R2 * R2)(n x h)
            gr = p2 - fr
            mrx += gr * (dry * hz - drz * hy)
            mry += gr * (drz * hx - drx * hz)
            mrz += gr * (drx * hy - dry * hx)
            # p2 R2 = 2 fr rx R2 (1/rx - 1/r1) = 2 fr (R2 ... ) -> p2*R2 = 2 fr rx
            c = 2.0 * fr * rx
            mrx -= c * (njy * hz - njz * hy)
            mry -= c * (njz * hx - njx * hz)
            mrz -= c * (njx * hy - njy * hx)
            power += 2.0 * fr * uj
    # race force is -(ball force) exactly
    out[0] = fx
    out[1] = fy
    out[2] = fz
    out[3] = mbx
    out[4] = mby
    out[5] = mbz
    out[6] = mrx
    out[7] = mry
    out[8] = mrz
    out[9] = power


# --------------------------------------------------------------------------- Python side


def pack_lubrication_parameters(lubricant, temperature: float, e_eff: float, rx: float, ry: float,
                                roughness: float = 0.0, boundary_model=(0.0, 0.12, 0.01, 0.10), *,
                                model: str = "mixed", fluid_model: str = "physical", fluid_curve=None,
                                lambda_limits=(1.0, 3.0), thermal: bool = True, starvation_factor: float = 1.0,
                                rolling_resistance: bool = True, solid_effusivity: float = 1.32e4) -> np.ndarray:
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
    return lub


def deformed_surface_radius(ball_diameter: float, groove_radius: float) -> float:
    """Jones (1960) radius of the deformed contact surface, 2 r_g D/(2 r_g + D) [m] (positive, see module doc)."""
    if not (ball_diameter > 0 and groove_radius > 0):
        raise InputError("groove_radius", "ball diameter and groove radius must be positive", "")
    return 2.0 * groove_radius * ball_diameter / (2.0 * groove_radius + ball_diameter)


def check_contact_inputs(q, a, b, vectors: dict, n_slices) -> None:
    """Raise InputError for bad kernel input (NaN velocities, n < 1, negative load); the kernel does not check."""
    if not isinstance(n_slices, (int, np.integer)) or isinstance(n_slices, bool) or n_slices < 1:
        raise InputError("n_slices", f"must be an integer >= 1, got {n_slices!r}", "use e.g. 10 slices")
    for name, v in (("load", q), ("a", a), ("b", b)):
        if not (math.isfinite(v) and v >= 0):
            raise InputError(name, f"must be finite and >= 0, got {v!r}", "")
    for name, vec in vectors.items():
        arr = np.asarray(vec, dtype=float)
        if arr.shape != (3,) or not np.all(np.isfinite(arr)):
            raise InputError(name, f"must be three finite numbers, got {vec!r}", "check the state for NaN/inf")


def contact_traction_checked(q, a, b, r_dev, centre, normal, major, ball_centre, v_ball, w_ball,
                             race_centre, v_race, w_race, lub, n_slices) -> np.ndarray:
    """Python entry: checks the input (typed errors), then calls the kernel; returns out[10]."""
    vecs = dict(centre=centre, normal=normal, major=major, ball_centre=ball_centre, v_ball=v_ball, w_ball=w_ball,
                race_centre=race_centre, v_race=v_race, w_race=w_race)
    check_contact_inputs(q, a, b, vecs, n_slices)
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
    if not (q > 0 and a > 0 and b > 0) or n_slices < 1:
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
    reg = 3
    if u0 > 0:
        U, G, W = eta0 * u0 / (e_eff * rx), alpha * e_eff, q / (e_eff * rx * rx)
        h_ir, h_pr, h_ie, h_pe, _, _ = ehl.regime_films.py_func(U, G, W, rx, ry)
        if h_ir >= h_pr and h_ir >= h_ie:
            reg = 0
        elif h_ie >= h_ir:
            reg = 3 if h_pe >= h_ie else 2
        else:
            reg = 3 if h_pe <= h_pr else 1
    theta = 0.0
    if lub[L_THERMAL] != 0:
        theta = hc / (12 * lub[L_KOIL]) + (0.5 * _FLASH * math.sqrt(2 * b / u0) / lub[L_EFFUS] if u0 > 0 else 0.0)
    width = 2 * a / n_slices
    F = np.zeros(3)
    Mb = np.zeros(3)
    Mr = np.zeros(3)
    power = 0.0
    for j in range(n_slices):
        xi0, xi1 = -1 + 2 * j / n_slices, -1 + 2 * (j + 1) / n_slices
        Fc = lambda z: (3 * z - z**3) / 4  # noqa: E731
        Gc = lambda z: 0.75 * (z * z / 2 - z**4 / 4)  # noqa: E731
        qj = q * (Fc(xi1) - Fc(xi0))
        if qj <= 0:
            continue
        x = a * (Gc(xi1) - Gc(xi0)) / (Fc(xi1) - Fc(xi0))
        root = math.sqrt(max(0.0, 1 - (c * x) ** 2))
        p = p0 + x * m + (c * x * x / (1 + root)) * n
        nj = root * n - c * x * m
        s, e = kin(p, nj)
        smag, uj = float(np.linalg.norm(s)), float(np.linalg.norm(e))
        if smag > 0:
            sr = smag / uj if uj > 0 else 1e300
            mu = 0.0
            if w < 1:
                mu = traction.four_parameter.py_func(sr, *lub[L_BA:L_BD + 1])
            if w > 0:
                if kind == 0:
                    muf = traction.four_parameter.py_func(sr, *lub[L_FA:L_FD + 1])
                else:
                    H = lambda z: z * math.sqrt(max(0.0, 1 - z * z)) + math.asin(min(1.0, max(-1.0, z)))  # noqa
                    pbar = qj / (a * b * (H(xi1) - H(xi0)))
                    eta_p = traction.roelands_viscosity.py_func(pbar, eta0, lub[L_ROE_LN], lub[L_ROE_Z])

                    def stress(dT):
                        eta = eta_p * math.exp(-lub[L_BETA_V] * dT)
                        tl = lub[L_LSS_R] * (lub[L_LSS_C1] * pbar / (lub[L_LSS_C2] + lub[L_LSS_C3] * (lub[L_T0C] + dT))
                                             - lub[L_LSS_C4])
                        tl = max(tl, lub[L_LSS_FLOOR] * pbar)
                        return tl * math.tanh(lub[L_TAU0] * math.asinh(eta * (smag / hc) / lub[L_TAU0]) / tl)

                    if hc <= 0:
                        tau = 0.0
                    else:
                        tau = stress(0.0)
                        if theta > 0:
                            t1 = stress(theta * tau * smag)
                            tau = tau * tau / (2 * tau - t1)
                    muf = tau / pbar
                mu = mu + (muf - mu) * w
            f = -mu * qj * s / smag
            F += f
            Mb += np.cross(p - cb, f)
            Mr += np.cross(p - cr, -f)
            power += mu * qj * smag
        if lub[L_ROLLRES] != 0 and w > 0 and uj > 0:
            if reg == 0:
                fr = traction.MARTIN_ROLLING * width * math.sqrt(eta0 * uj * qj / width)
            else:
                U = eta0 * uj / (e_eff * rx)
                fr = 29.2 * (rx / alpha) * width * (alpha * e_eff * U) ** 0.648 * (qj / (width * e_eff * rx)) ** 0.246
            fr *= phi * w
            h = e / uj
            r1 = float(np.linalg.norm(p - cb))
            inv_r2 = 1 / rx - 1 / r1
            p1 = 2 * fr * rx / r1
            p2 = 2 * fr * rx * inv_r2
            F += (p1 - fr) * h
            Mb += np.cross(p - cb, -fr * h)
            Mr += np.cross(p - cr, (p2 - fr) * h) - 2 * fr * rx * np.cross(nj, h)
            power += 2 * fr * uj
    out[0:3] = F
    out[3:6] = Mb
    out[6:9] = Mr
    out[9] = power


__all__ = ["contact_traction", "contact_traction_reference", "contact_traction_checked",
           "pack_lubrication_parameters", "deformed_surface_radius", "slice_fraction", "slice_centroid",
           "L_SIZE", "MODELS", "FLUID_MODELS"]
