"""Contact laws of the dynamic model (numba kernels on plain floats and arrays, SI).

* :func:`race_contact_at` — one ball–raceway contact: the Hunt–Crossley Hertz normal force and the
  traction of the chosen model (the glue between the contact geometry and the traction kernels), on the
  vectors' components (the engine's form); :func:`race_contact` the same on arrays;
* :func:`coulomb_slices` / :func:`coulomb_on_slices` with :func:`slice_table` — the regularised
  Coulomb stand-in on the slices of the contact ellipse;
* :func:`pocket_point` — the geometry of the ball–pocket contact: the point of a spherical or
  cylindrical pocket nearest the ball centre;
* :func:`cross` — the vector product the kernels share.

The equations of motion that use them are :func:`bearingsim.dynamics.forces.rhs` and its section
helpers.  Array layouts (``gp``, ``cp``, the lubricant rows): :mod:`.layout`.

Ball–raceway normal force (Sakaguchi & Shibutani [S1] §3.1; Harris & Kotzalas 2007 vol. 1 eq. 7.4):
the ball centre b and the groove-curvature centre g of the raceway in the ball's
meridian plane (the closest point of the groove-centre circle) give the approach
δ = |b − g| − (f − ½)D; along u = (b − g)/|b − g|

    Q = K δ^1.5 (1 + (3/2) α δ̇),   δ̇ = u·(v_b − v_g),   Q ≥ 0,

the Hunt–Crossley contact law (Hunt & Crossley, J. Appl. Mech. 42 (1975) 440, eq. 12
with n = 3/2; restitution e ≈ 1 − α v_impact).  It is chosen because the damping force
vanishes with δ (no jump at first touch, no tensile force at separation, unlike a
linear dashpot) and the dissipated energy per impact is a fixed fraction of the
impact energy, as measured for steel impacts.  K is the statics constant K_i or K_o
(evaluated at the free contact angle, :meth:`BallBearing.contact_constants`), so the
model reduces exactly to the Jones–Harris statics.  The force acts on the ball as −Q u
and on the ring as +Q u through g: it has no moment about the ball centre and derives
from the potential (2/5) K δ^2.5 (energy is conserved without damping and friction).

Tangential ball–raceway forces: model 0 none; model 1 a *regularised Coulomb stand-in
for tests* (not a lubricant model): on the n slices of the contact ellipse of
:mod:`bearingsim.contact.slices` (load share and load centroid of each strip, [S1] eq. 1,
points on the deformed surface) the force opposes the slice's sliding velocity ([S1] eqs. 2–3),
μ = μ₀ s/√(s² + s₀²) with s = |v_s|/u_roll the slide-roll ratio; model 2 the
lubricated sliced-ellipse kernel :func:`bearingsim.contact.slices.contact_traction`.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..contact import slices as _sl
from . import layout as ly


@njit(cache=True, _nrt=False)
def cross(a, b, out):
    """out ← a × b (3-vectors)."""
    out[0] = a[1] * b[2] - a[2] * b[1]
    out[1] = a[2] * b[0] - a[0] * b[2]
    out[2] = a[0] * b[1] - a[1] * b[0]



@njit(cache=True, _nrt=False)
def slice_table(nsl, table):
    """table[k], table[nsl + k] ← load share and load centroid ξ̄ of slice k of n = nsl
    (:func:`bearingsim.contact.slices.slice_fraction`, :func:`~bearingsim.contact.slices.slice_centroid`),
    evaluated once per right-hand side for :func:`coulomb_on_slices`."""
    for k in range(nsl):
        e1 = -1.0 + 2.0 * k / nsl
        e2 = -1.0 + 2.0 * (k + 1) / nsl
        table[k] = _sl.slice_fraction(e1, e2)
        table[nsl + k] = _sl.slice_centroid(e1, e2)


@njit(cache=True)
def coulomb_slices(q, a, r_dev, centre, normal, major, bc, vb, wb, rc, vr, wr, mu0, s0, vref, nsl, out):
    """Regularised Coulomb traction on slices of the contact ellipse (TEST STAND-IN, not a lubricant model).

    The slices of :mod:`bearingsim.contact.slices` ([S1] eq. 1): slice k spans ξ = x/a ∈ [ξ_k, ξ_k+1],
    ξ_k = −1 + 2k/n, of the major axis (length 2a); its load is the Hertz pressure integrated over the
    strip, Q_k = Q·``slice_fraction``(ξ_k, ξ_k+1), and it acts at the strip's load centroid
    x̄_k = a·``slice_centroid``(ξ_k, ξ_k+1) on the deformed surface, p = centre + x̄_k major +
    ``slice_point_offset``(x̄_k, 1/r_dev)·normal, with ``normal`` the unit normal from the race towards
    the ball (the convention of :func:`bearingsim.contact.slices.contact_traction`).
    Sliding velocity v_s = (v_b + ω_b × (p − b)) − (v_r + ω_r × (p − c_r)), projected on
    the tangent plane ([S1] eq. 3); force on the ball −μ Q_k v_s/|v_s| (eq. 2) with
    μ = μ₀ s/√(s² + s₀² + (v_ref/u)²), s = |v_s|/u the slide-roll ratio, u the mean
    rolling speed.

    out[10] ← force on ball (3) [N], moment on ball about b (3) [N·m], moment on the
    race about c_r (3) [N·m], power loss [W].  Returns the slide-roll ratio at the
    centre slice.
    """
    table = np.empty(2 * nsl)
    slice_table(nsl, table)
    return coulomb_on_slices(q, a, r_dev, centre, normal, major, bc, vb, wb, rc, vr, wr, mu0, s0, vref, nsl, table,
                             out)


@njit(cache=True)
def coulomb_on_slices(q, a, r_dev, centre, normal, major, bc, vb, wb, rc, vr, wr, mu0, s0, vref, nsl, table, out):
    """:func:`coulomb_slices` with the slices' load shares and centroids given (:func:`slice_table`)."""
    for k in range(10):
        out[k] = 0.0
    if q <= 0.0:
        return 0.0
    srr_c = 0.0
    n0, n1, n2 = normal[0], normal[1], normal[2]
    curv = _sl.surface_curvature(r_dev)
    for k in range(nsl):
        qk = q * table[k]
        eta = a * table[nsl + k]
        dn, _ = _sl.slice_point_offset(eta, curv)
        p0 = centre[0] + eta * major[0] + dn * n0
        p1 = centre[1] + eta * major[1] + dn * n1
        p2 = centre[2] + eta * major[2] + dn * n2
        rb0, rb1, rb2 = p0 - bc[0], p1 - bc[1], p2 - bc[2]
        rr0, rr1, rr2 = p0 - rc[0], p1 - rc[1], p2 - rc[2]
        # surface velocities of ball and race at the slice point
        sb0 = vb[0] + wb[1] * rb2 - wb[2] * rb1
        sb1 = vb[1] + wb[2] * rb0 - wb[0] * rb2
        sb2 = vb[2] + wb[0] * rb1 - wb[1] * rb0
        sr0 = vr[0] + wr[1] * rr2 - wr[2] * rr1
        sr1 = vr[1] + wr[2] * rr0 - wr[0] * rr2
        sr2 = vr[2] + wr[0] * rr1 - wr[1] * rr0
        nb = sb0 * n0 + sb1 * n1 + sb2 * n2
        nr = sr0 * n0 + sr1 * n1 + sr2 * n2
        sb0 -= nb * n0
        sb1 -= nb * n1
        sb2 -= nb * n2
        sr0 -= nr * n0
        sr1 -= nr * n1
        sr2 -= nr * n2
        vs0 = sb0 - sr0
        vs1 = sb1 - sr1
        vs2 = sb2 - sr2
        ur0 = 0.5 * (sb0 + sr0)
        ur1 = 0.5 * (sb1 + sr1)
        ur2 = 0.5 * (sb2 + sr2)
        vs = math.sqrt(vs0 * vs0 + vs1 * vs1 + vs2 * vs2)
        u = math.sqrt(ur0 * ur0 + ur1 * ur1 + ur2 * ur2)
        den = math.sqrt(vs * vs + (s0 * u) ** 2 + vref * vref)
        c = -mu0 * qk / den
        if k == nsl // 2:
            srr_c = vs / max(u, 1e-12)
        _sl.add_point_traction(out, c, vs0, vs1, vs2, rb0, rb1, rb2, rr0, rr1, rr2, -c * vs * vs)
    return srr_c



@njit(cache=True)
def race_contact(b, v, w, g, vg_lin, worb, rcen, vrace, wrace, kc, rgroove, half_d, alpha, lub, gp, a_c, b_c,
                 r_dev, tang, fb, mb, fr, mr, res, tbuf):
    """Normal (Hunt–Crossley Hertz) and tangential force of one ball–raceway contact.

    b, v, w: ball centre, velocity, angular velocity; g: groove-curvature centre;
    vg_lin: velocity of g as a point of the ring (rigid-body, without spin);
    worb: ball orbital speed [rad/s]: the traction kernel sees all velocities in the
    frame turning at ω_m about the bearing axis, where the contact is quasi-stationary
    (sliding velocities do not depend on the frame; rolling speeds do);
    rcen, vrace, wrace: ring reference point, its velocity and the ring angular
    velocity (with spin) for the surface velocity; kc [N/m^1.5]; rgroove = (f − ½)D;
    a_c, b_c: ellipse semi-axes per N^(1/3); tang: unit tangent of the groove circle
    (rolling direction).  Accumulates the force/moment on the ball (fb, mb) and on the
    ring (fr, mr about rcen).  res ← Q, δ, u(3), slide-roll ratio, power loss.  tbuf: work array of
    ``forces.ball_row_work(nsl) − BALL_WORK`` floats (the sliced traction's out with its lanes,
    ``contact.slices.TRACTION_OUT``); for the Coulomb stand-in tbuf[44:] holds its slices (:func:`slice_table`).
    """
    (q, delta, u0, u1, u2, srr, power, fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry, mrz) = race_contact_at(
        b[0], b[1], b[2], v[0], v[1], v[2], w[0], w[1], w[2], g[0], g[1], g[2], vg_lin[0], vg_lin[1], vg_lin[2], worb,
        rcen[0], rcen[1], rcen[2], vrace[0], vrace[1], vrace[2], wrace[0], wrace[1], wrace[2], kc, np.cbrt(kc), rgroove,
        half_d, alpha, lub, gp, a_c, b_c, r_dev, tang[0], tang[1], tang[2], tbuf)
    res[0] = q
    res[1] = delta
    res[2] = u0
    res[3] = u1
    res[4] = u2
    res[5] = srr
    res[6] = power
    fb[0] += fbx
    fb[1] += fby
    fb[2] += fbz
    mb[0] += mbx
    mb[1] += mby
    mb[2] += mbz
    fr[0] += frx
    fr[1] += fry
    fr[2] += frz
    mr[0] += mrx
    mr[1] += mry
    mr[2] += mrz


@njit(cache=True, error_model="numpy")
def _cbrt_1p(d):
    """(1 + d)^(1/3) [-] for d > −1: the binomial series 1 + d/3 − d²/9 + 5d³/81 − 10d⁴/243 (Abramowitz & Stegun
    3.6.8) where |d| ≤ 1e-3 (the next term, 22d⁵/729, is below 3.1e-17: the series is the cube root to rounding),
    else the cube root itself.  For the Hertz load's Hunt–Crossley factor 1 + 1.5 α δ̇ (small but for impacts), so
    that Q^(1/3) = K^(1/3) δ^(1/2) (1 + 1.5 α δ̇)^(1/3) needs no pow per contact (a pow costs 2.7 % of a hub step)."""
    if abs(d) <= 1e-3:
        return 1.0 + d * (1.0 / 3.0 + d * (-1.0 / 9.0 + d * (5.0 / 81.0 - d * (10.0 / 243.0))))
    return np.cbrt(1.0 + d)


@njit(cache=True, _nrt=False)
def race_contact_at(bx, by, bz, vx, vy, vz, wx, wy, wz, gx, gy, gz, vgx, vgy, vgz, worb, rcx, rcy, rcz, vrx0, vry0,
                    vrz0, wrx0, wry0, wrz0, kc, kc13, rgroove, half_d, alpha, lub, gp, a_c, b_c, r_dev, tx, ty, tz,
                    tbuf):
    """:func:`race_contact` on the vectors' components, returning (Q [N], δ [m], u (3), slide-roll ratio at the
    centre, power loss [W], force on the ball (3) [N], moment on the ball (3) [N·m], force on the ring (3) [N],
    moment on the ring about rcen (3) [N·m]).  kc13 = kc^(1/3) [N^(1/3)/m^(1/2)] (``Model.rowx``: the ellipse's
    size a = a_c Q^(1/3) from K^(1/3) δ^(1/2) without a pow, :func:`_cbrt_1p`).  The engine calls this form:
    numba increments and decrements an atomic reference count for every array argument of a function it does not
    inline and for every array view, and the array form's 17 arguments and 12 views per contact cost ≈ 12 % of the
    hub right-hand side (compiled without counting, ``_nrt=False``, as it allocates nothing); here only
    ``lub``, ``gp`` and ``tbuf`` (the traction's work array: tbuf[0:10] its out, the Coulomb stand-in's vectors at
    10:31 and its slice table at 44:) are arrays."""
    d0 = bx - gx
    d1 = by - gy
    d2 = bz - gz
    ll = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
    delta = ll - rgroove
    z = 0.0
    if delta <= 0.0:
        return 0.0, delta, d0 / ll, d1 / ll, d2 / ll, 0.0, 0.0, z, z, z, z, z, z, z, z, z, z, z, z
    u0 = d0 / ll
    u1 = d1 / ll
    u2 = d2 / ll
    ddot = u0 * (vx - vgx) + u1 * (vy - vgy) + u2 * (vz - vgz)
    sqrt_delta = math.sqrt(delta)
    damp = 1.5 * alpha * ddot
    q = kc * delta * sqrt_delta * (1.0 + damp)
    if q <= 0.0:
        return 0.0, delta, u0, u1, u2, 0.0, 0.0, z, z, z, z, z, z, z, z, z, z, z, z
    fbx = 0.0
    fby = 0.0
    fbz = 0.0
    fbx -= q * u0
    fby -= q * u1
    fbz -= q * u2
    frx = 0.0
    fry = 0.0
    frz = 0.0
    frx += q * u0
    fry += q * u1
    frz += q * u2
    gr0 = gx - rcx
    gr1 = gy - rcy
    gr2 = gz - rcz
    mrx = 0.0
    mry = 0.0
    mrz = 0.0
    mrx += gr1 * q * u2 - gr2 * q * u1
    mry += gr2 * q * u0 - gr0 * q * u2
    mrz += gr0 * q * u1 - gr1 * q * u0
    mode = int(gp[ly.G_TRAC])
    # contact-ellipse centre, major axis n × t, and the velocities relative to the frame orbiting with the ball
    # at worb about the x axis
    r_c = half_d - 0.5 * delta
    cx = bx + r_c * u0
    cy = by + r_c * u1
    cz = bz + r_c * u2
    mjx = u1 * tz - u2 * ty
    mjy = u2 * tx - u0 * tz
    mjz = u0 * ty - u1 * tx
    vbx = vx
    vby = vy + worb * bz
    vbz = vz - worb * by
    wbx = wx - worb
    wby = wy
    wbz = wz
    vrx = vrx0
    vry = vry0 + worb * rcz
    vrz = vrz0 - worb * rcy
    wrx = wrx0 - worb
    wry = wry0
    wrz = wrz0
    # slide-roll ratio at the contact centre (output): v_s / u in the orbiting frame
    rbx = cx - bx
    rby = cy - by
    rbz = cz - bz
    rrx = cx - rcx
    rry = cy - rcy
    rrz = cz - rcz
    sbx = vbx + (wby * rbz - wbz * rby)
    sby = vby + (wbz * rbx - wbx * rbz)
    sbz = vbz + (wbx * rby - wby * rbx)
    srx = vrx + (wry * rrz - wrz * rry)
    sry = vry + (wrz * rrx - wrx * rrz)
    srz = vrz + (wrx * rry - wry * rrx)
    vs2 = 0.0
    uu2 = 0.0
    vs2 += (sbx - srx) ** 2
    uu2 += (0.5 * (sbx + srx)) ** 2
    vs2 += (sby - sry) ** 2
    uu2 += (0.5 * (sby + sry)) ** 2
    vs2 += (sbz - srz) ** 2
    uu2 += (0.5 * (sbz + srz)) ** 2
    srr = math.sqrt(vs2) / max(math.sqrt(uu2), 1e-12)
    mbx = 0.0
    mby = 0.0
    mbz = 0.0
    if mode == 0:
        return q, delta, u0, u1, u2, srr, 0.0, fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry, mrz
    q13 = kc13 * sqrt_delta * _cbrt_1p(damp)  # Q^(1/3) without a pow
    # both traction models take the normal from the race towards the ball; tbuf[0:10] ← their out
    if mode == 1:
        vec = tbuf[10:44]
        for i, x in enumerate((cx, cy, cz, -u0, -u1, -u2, mjx, mjy, mjz, vbx, vby, vbz, wbx, wby, wbz, vrx, vry, vrz,
                               wrx, wry, wrz, bx, by, bz, rcx, rcy, rcz)):
            vec[i] = x
        coulomb_on_slices(q, a_c * q13, r_dev, vec[0:3], vec[3:6], vec[6:9], vec[21:24], vec[9:12], vec[12:15],
                          vec[24:27], vec[15:18], vec[18:21], gp[ly.G_MU0], gp[ly.G_S0], gp[ly.G_VREF],
                          int(gp[ly.G_NSL]), tbuf[44:], tbuf)
    else:
        _sl.traction_at(q, a_c * q13, b_c * q13, r_dev, cx, cy, cz, -u0, -u1, -u2, mjx, mjy, mjz, bx, by, bz,
                        vbx, vby, vbz, wbx, wby, wbz, rcx, rcy, rcz, vrx, vry, vrz, wrx, wry, wrz, lub,
                        int(gp[ly.G_NSL]), tbuf)
    fbx += tbuf[0]
    fby += tbuf[1]
    fbz += tbuf[2]
    mbx += tbuf[3]
    mby += tbuf[4]
    mbz += tbuf[5]
    frx -= tbuf[0]
    fry -= tbuf[1]
    frz -= tbuf[2]
    mrx += tbuf[6]
    mry += tbuf[7]
    mrz += tbuf[8]
    return q, delta, u0, u1, u2, srr, tbuf[9], fbx, fby, fbz, mbx, mby, mbz, frx, fry, frz, mrx, mry, mrz


@njit(cache=True)
def pocket_point(shape, par, radius, ut, ur, ux):
    """Point of the pocket surface nearest the ball centre (ut, ur, ux), pocket frame (t, r, x) [m].

    shape 0: sphere of ``radius`` about the pocket centre, open within the half-angle ``par``
    [rad] of the radial axis r: the point is radius·û when û = u/|u| lies on the surface, else
    the nearest point of the opening's rim at the same azimuth.  shape 1: cylinder of ``radius``
    about the radial axis, half-length ``par`` [m]: the point at the ball centre's height
    (clamped to ±par) in the direction of its offset in the t–x plane.  Exact closest points
    ([S1] §3.2 discretises the surface into nodes; the closed form is what those nodes
    converge to, without the jumps of the deepest node as the ball moves).
    """
    if shape == 0:
        d = math.sqrt(ut * ut + ur * ur + ux * ux)
        if d == 0.0:
            return radius, 0.0, 0.0
        c = ur / d
        cmax = math.cos(par)
        if abs(c) <= cmax:
            f = radius / d
            return ut * f, ur * f, ux * f
        rho = math.sqrt(ut * ut + ux * ux)
        sp = math.sin(par) * radius
        cr = cmax * radius if ur > 0.0 else -cmax * radius
        if rho == 0.0:
            return sp, cr, 0.0
        return sp * ut / rho, cr, sp * ux / rho
    rho = math.sqrt(ut * ut + ux * ux)
    h = min(par, max(-par, ur))
    if rho == 0.0:
        return radius, h, 0.0
    return radius * ut / rho, h, radius * ux / rho


# accumulators of rhs (one float array, summed in the same order as the equations are written)
