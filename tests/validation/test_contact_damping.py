"""Normal damping of a lubricated ball–raceway contact (issue 13 item 3; bearingsim.contact.damping).

The squeeze-film model is derived from Reynolds' equation (module docstring); its rigid limits are checked here
against Reynolds' closed form and a numerical solution of the Reynolds equation.  The fitted EHL damping
expressions of the literature (Wijnant 1998; Nonato & Cavalca 2014) could not be retrieved, so no comparison with
their published values is made.  The last test measures the damping ratio of the hub's tilt mode in a free decay
of the dynamic model and compares it with the modal estimate from the contacts."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as spla

from bearingsim.contact import damping as dm
from bearingsim.dynamics import loads as ld
from bearingsim.dynamics import run
from bearingsim.dynamics.case import load_case
from bearingsim.dynamics.stepper import Stepper
from bearingsim.errors import InputError

CASE = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"
REYNOLDS = "Reynolds (1886) squeeze film of a sphere approaching a plane, F = 6 pi eta R^2 (-dh/dt)/h " \
           "(Hamrock, Schmid & Jacobson 2004, Fundamentals of Fluid Film Lubrication, squeeze-film chapter)"


def test_rigid_sphere_is_reynolds_squeeze():
    eta, r0, h = 0.04, 6e-3, 0.3e-6
    np.testing.assert_allclose(dm.squeeze_rigid_ellipsoid(eta, r0, r0, h), 6 * math.pi * eta * r0**2 / h,
                               rtol=1e-12, err_msg=REYNOLDS)
    # the quadrature of the flattened model with a = 0 is the same problem
    np.testing.assert_allclose(dm.squeeze_flattened_circle(eta, r0, 0.0, h), 6 * math.pi * eta * r0**2 / h,
                               rtol=2e-4, err_msg=REYNOLDS + " (quadrature, a = 0)")


def _reynolds_fd_force(eta, rx, ry, h0, n=241, span=10.0):
    """Squeeze force per unit approach rate of a rigid elliptic paraboloid: finite-volume solution of
    ∇·(h³∇p) = 12 η ḣ₀ (ḣ₀ = −1) with p = 0 on the edge of |u|, |v| ≤ span (u = x/√(2R_x h₀), v = y/√(2R_y h₀))."""
    sx, sy = math.sqrt(2 * rx * h0), math.sqrt(2 * ry * h0)
    u = np.linspace(-span, span, n)
    du = u[1] - u[0]
    hh = lambda uu, vv: h0 * (1 + uu * uu + vv * vv)  # noqa: E731
    idx = -np.ones((n, n), dtype=int)
    inner = [(i, j) for i in range(1, n - 1) for j in range(1, n - 1)]
    for m, (i, j) in enumerate(inner):
        idx[i, j] = m
    rows, cols, vals = [], [], []
    rhs = np.full(len(inner), -12 * eta * (-1.0) * (sx * du) * (sy * du))
    for m, (i, j) in enumerate(inner):
        diag = 0.0
        for di, dj, s_len, s_face in ((1, 0, sx, sy), (-1, 0, sx, sy), (0, 1, sy, sx), (0, -1, sy, sx)):
            hf = hh(u[i] + 0.5 * di * du, u[j] + 0.5 * dj * du) ** 3
            g = hf * (s_face * du) / (s_len * du)
            diag += g
            k = idx[i + di, j + dj]
            if k >= 0:
                rows.append(m)
                cols.append(k)
                vals.append(-g)
        rows.append(m)
        cols.append(m)
        vals.append(diag)
    a = sp.csr_matrix((vals, (rows, cols)), shape=(len(inner), len(inner)))
    p = spla.spsolve(a, rhs)
    return p.sum() * (sx * du) * (sy * du)


def test_rigid_ellipsoid_matches_a_numerical_reynolds_solution():
    """The closed form c = 12 π η R √(R_x R_y)/h (derived in the module) against a finite-volume solution of the
    Reynolds equation for R_y/R_x = 9 (a ball-bearing-like ellipse); the numerical solution's truncation (|u| ≤ 10,
    p ∝ 1/h²: force tail ≈ 1 %) and grid error bound the tolerance."""
    eta, rx, ry, h = 0.05, 4.5e-3, 40.5e-3, 0.2e-6
    c_fd = _reynolds_fd_force(eta, rx, ry, h)
    np.testing.assert_allclose(c_fd, dm.squeeze_rigid_ellipsoid(eta, rx, ry, h), rtol=0.03,
                               err_msg="finite-volume solution of Reynolds' equation for the elliptic paraboloid")


def test_flattened_circle_limits_and_convergence():
    eta, r, h = 0.05, 5e-3, 0.2e-6
    rigid = 6 * math.pi * eta * r * r / h
    ell = math.sqrt(2 * r * h)
    # a → 0 recovers the rigid paraboloid; a growing Hertz zone, whose edge does not squeeze, damps less
    assert dm.squeeze_flattened_circle(eta, r, 0.01 * ell, h) == pytest.approx(rigid, rel=0.02)
    cs = [dm.squeeze_flattened_circle(eta, r, f * ell, h) for f in (0.1, 0.5, 1, 2, 5, 20)]
    assert np.all(np.diff(cs) < 0) and cs[-1] < 0.15 * rigid
    # grid convergence of the quadrature
    assert dm.squeeze_flattened_circle(eta, r, 5 * ell, h, n=24000) == pytest.approx(cs[4], rel=1e-3)
    # the ellipse model reduces to the flattened circle for R_x = R_y
    np.testing.assert_allclose(dm.ehl_contact_damping(eta, r, r, 3 * ell, 3 * ell, h),
                               dm.squeeze_flattened_circle(eta, r, 3 * ell, h), rtol=1e-12)


def test_bad_input():
    with pytest.raises(InputError, match="viscosity"):
        dm.squeeze_rigid_ellipsoid(-1.0, 1e-3, 1e-3, 1e-7)
    with pytest.raises(InputError, match="contact_radius"):
        dm.squeeze_flattened_circle(0.05, 1e-3, -1e-4, 1e-7)
    with pytest.raises(InputError, match="contact_damping"):
        dm.hunt_crossley_coefficient(-0.1, 100.0)
    with pytest.raises(InputError, match="x"):
        dm.free_decay_damping_ratio(np.linspace(0, 1, 100), np.ones(100))


def test_free_decay_fit_recovers_a_known_damping_ratio():
    t = np.linspace(0, 5e-3, 501)
    w, z = 2 * math.pi * 1250.0, 0.012
    x = 1e-5 + 3e-4 * t + 2e-5 * np.exp(-z * w * t) * np.cos(w * math.sqrt(1 - z * z) * t + 0.4)
    zf, f = dm.free_decay_damping_ratio(t, x)
    assert zf == pytest.approx(z, rel=1e-3) and f == pytest.approx(1250.0 * math.sqrt(1 - z * z), rel=1e-4)


def _free_tilt_decay(alpha):
    """ζ and frequency of the hub ring's tilt vibration after a 0.3 rad/s tilt-rate kick, constant loads (the hub
    case's loads at t = 0: Fr = 2785 N), 100 km/h, frictionless (to isolate the normal damping), 5 ms."""
    c = load_case(CASE)
    const = ld.LoadHistory((ld.constant(0.0), ld.constant(2785.0), ld.LoadChannel(), ld.LoadChannel(),
                            ld.LoadChannel()))
    cc = dataclasses.replace(c, loads=const, contact_damping=alpha, traction="none", duration=0.005,
                             output_interval=1e-5)
    model, spec, y0, res = run.build(cc)
    y0[9] += 0.3
    st = Stepper(model, spec, y0, tol=cc.tolerance, h=1e-7, method=cc.method)
    d = run.run_stepper(st, cc.duration, cc.output_interval).data
    return dm.free_decay_damping_ratio(d["time"], d["inner_ring_displacement"][:, 4]), res, cc


def test_hub_tilt_mode_damping_ratio():
    """The tilt mode of the hub (≈ 1.24 kHz) decays in the dynamic model at the damping ratio the contacts predict:
    with the squeeze-film ("ehl") α the free decay and the modal estimate ω Σc/(2Σk) agree within 30 % (the
    estimate weights every contact alike, the mode does not); without damping the fit gives a floor ≪ that."""
    c = load_case(CASE)
    c = dataclasses.replace(c, loads=ld.LoadHistory((ld.constant(0.0), ld.constant(2785.0), ld.LoadChannel(),
                                                      ld.LoadChannel(), ld.LoadChannel())), contact_damping="ehl")
    alpha = c.damping_alpha()
    (z_ehl, f), res, cc = _free_tilt_decay(alpha)
    tab = dm.contact_damping_table(res, cc.lubricant, cc.temperature, alpha=alpha)
    k = [t["stiffness_N_m"] for t in tab]
    z_est_hc = dm.modal_damping_ratio(2 * math.pi * f, [t["c_hunt_crossley_N_s_m"] for t in tab], k)
    z_est_ehl = dm.modal_damping_ratio(2 * math.pi * f, [t["c_ehl_N_s_m"] for t in tab], k)
    assert 1100 < f < 1400
    assert z_ehl == pytest.approx(z_est_hc, rel=0.3)
    assert z_est_ehl == pytest.approx(z_est_hc, rel=1e-9)  # equivalent_alpha matches Σc of HC and squeeze
    (z0, _), _, _ = _free_tilt_decay(0.0)
    assert z0 < 0.25 * z_ehl


def test_case_option_ehl():
    from bearingsim.io import read_toml
    from bearingsim.io.case import case_from_dict

    data = read_toml(CASE, "case")
    c = case_from_dict(dict(data, contact_damping="ehl"), CASE.parent)
    assert c.contact_damping == "ehl"
    alpha = c.damping_alpha()
    assert c.model_options()["damping_alpha"] == alpha and alpha > 0.05  # the squeeze film damps more than HC
    assert case_from_dict(data, CASE.parent).damping_alpha() == 0.05
    with pytest.raises(InputError, match="contact_damping"):
        case_from_dict(dict(data, contact_damping="viscous"), CASE.parent)
    with pytest.raises(InputError, match="contact_damping"):
        case_from_dict(dict(data, contact_damping=-0.1), CASE.parent)
    no_lub = {k: v for k, v in data.items() if k != "lubricant"}
    with pytest.raises(InputError, match="contact_damping"):
        case_from_dict(dict(no_lub, contact_damping="ehl", traction="none"), CASE.parent)


def test_squeeze_rate_is_the_derivative_of_the_hertz_gap():
    """The model's squeeze rate outside the contact, −(1 − (2/π) asin(a/r)) per unit approach (an incremental
    flat punch), is d/dδ of the Hertz separation (a² = R δ); and the separation tends to the point-load
    displacement of the same force far away (Johnson 1985, ch. 3)."""
    r_c, a = 5e-3, 3e-4
    d = a * a / r_c
    r = np.array([1.01, 1.2, 2.0, 5.0, 20.0]) * a
    dd = 1e-6 * d
    num = (dm.hertz_separation(r, math.sqrt(r_c * (d + dd)), r_c)
           - dm.hertz_separation(r, math.sqrt(r_c * (d - dd)), r_c)) / (2 * dd)
    np.testing.assert_allclose(num, -(1 - (2 / np.pi) * np.arcsin(a / r)), rtol=1e-4, atol=1e-7)
    assert dm.hertz_separation(0.5 * a, a, r_c) == 0.0 and dm.hertz_separation(a, a, r_c) == pytest.approx(0, abs=1e-15)
    far = 200 * a
    assert dm.hertz_separation(far, a, r_c) == pytest.approx(far**2 / (2 * r_c) - d + 4 * a**3 / (3 * math.pi * r_c * far),
                                                               rel=1e-9)
