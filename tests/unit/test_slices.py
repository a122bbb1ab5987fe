"""Unit tests of the sliced contact ellipse kernel (seed 001 eqs. 1-5)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from bearingsim.contact import hertz
from bearingsim.contact import slices as S
from bearingsim.errors import InputError

D, DM, F_I = 0.0111, 0.061, 0.52
E_EFF = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
RX, RY = hertz.raceway_radii(D, DM, F_I, math.radians(35.0), True)
Q = 2000.0
HC = hertz.point_contact_exact(Q, RX, RY, E_EFF)
R_BALL = D / 2


def _lub(**kw):
    kw.setdefault("fluid_curve", (0.0, 0.06, 0.01, 0.045))
    return S.pack_lubrication_parameters("iso-vg-68", 333.15, E_EFF, RX, RY, kw.pop("roughness", 0.1e-6), **kw)


def _flat_rolling(u_ball, u_race, spin=0.0, lub=None, n=10, q=Q, r_dev=math.inf):
    """Ball above a flat race at z=0, rolling along y; the race translates along y."""
    lub = _lub() if lub is None else lub
    out = np.zeros(10)
    S.contact_traction(q, HC.a, HC.b, r_dev, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                       np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u_ball / R_BALL, 0.0, spin]),
                       np.array([0.0, 0.0, -1.0]), np.array([0.0, u_race, 0.0]), np.zeros(3), lub, n, out)
    return out


# --------------------------------------------------------------------------- slice loads (seed eq. 1)

@pytest.mark.parametrize("n", [1, 2, 3, 7, 10, 50])
def test_slice_loads_sum_to_q(n):
    fr = [S.slice_fraction(-1 + 2 * j / n, -1 + 2 * (j + 1) / n) for j in range(n)]
    assert math.fsum(fr) == pytest.approx(1.0, abs=1e-15)
    assert min(fr) > 0


@pytest.mark.parametrize("n", [3, 10])
def test_slice_loads_integrate_hertz_pressure(n):
    """Q_j equals the 2-D integral of p0 sqrt(1 - x²/a² - y²/b²) over the strip (numerical quadrature)."""
    a, b = HC.a, HC.b
    p0 = 1.5 * Q / (math.pi * a * b)
    for j in range(n):
        x0, x1 = a * (-1 + 2 * j / n), a * (-1 + 2 * (j + 1) / n)
        val, _ = integrate.dblquad(
            lambda y, x: p0 * math.sqrt(max(0.0, 1 - (x / a) ** 2 - (y / b) ** 2)), x0, x1,
            lambda x: -b * math.sqrt(max(0.0, 1 - (x / a) ** 2)), lambda x: b * math.sqrt(max(0.0, 1 - (x / a) ** 2)),
            epsabs=1e-12, epsrel=1e-10)
        assert Q * S.slice_fraction(x0 / a, x1 / a) == pytest.approx(val, rel=1e-8)
        xm, _ = integrate.quad(lambda x: x * 0.75 * (1 - x * x), x0 / a, x1 / a, epsabs=1e-14)
        w, _ = integrate.quad(lambda x: 0.75 * (1 - x * x), x0 / a, x1 / a, epsabs=1e-14)
        assert S.slice_centroid(x0 / a, x1 / a) == pytest.approx(xm / w, abs=1e-12)
        area, _ = integrate.quad(lambda x: 2 * math.sqrt(max(0.0, 1 - x * x)), x0 / a, x1 / a, epsabs=1e-13)
        assert S.slice_area_fraction(x0 / a, x1 / a) == pytest.approx(area, rel=1e-9)


# --------------------------------------------------------------------------- kernel vs reference

def _random_state(rng):
    n = rng.normal(size=3)
    n /= np.linalg.norm(n)
    m = np.cross(n, rng.normal(size=3))
    m /= np.linalg.norm(m)
    c = rng.normal(size=3) * 0.01
    cb = c + R_BALL * n
    cr = c - 0.02 * n + 0.003 * m
    vb = rng.normal(size=3) * 3
    wb = rng.normal(size=3) * 500
    vr = rng.normal(size=3) * 0.5
    wr = rng.normal(size=3) * 200
    return c, n, m, cb, vb, wb, cr, vr, wr


@pytest.mark.parametrize("kw", [dict(model="boundary"), dict(model="fluid", fluid_model="curve"),
                                dict(model="fluid", fluid_model="physical"), dict(model="mixed", roughness=0.1e-6),
                                dict(model="mixed", roughness=0.02e-6, thermal=False),
                                dict(model="mixed", roughness=0.3e-6, starvation_factor=0.7),
                                dict(model="fluid", fluid_model="physical", viscoelastic=False)])
@pytest.mark.parametrize("n_slices", [1, 4, 11, S.SPLIT_BASE + 1, S.SPLIT_BASE + 6])
def test_kernel_matches_reference(kw, n_slices):
    rng = np.random.default_rng(n_slices)
    lub = _lub(**kw)
    for trial in range(4):
        c, n, m, cb, vb, wb, cr, vr, wr = _random_state(rng)
        r_dev = [math.inf, S.deformed_surface_radius(D, F_I * D), -0.02, 0.004][trial]
        q = [Q, 300.0, 5000.0, 1.0][trial]
        a, b = HC.a * (q / Q) ** (1 / 3), HC.b * (q / Q) ** (1 / 3)
        out, ref = np.zeros(10), np.zeros(10)
        args = (q, a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr, lub, n_slices)
        S.contact_traction(*args, out)
        S.contact_traction_reference(*args, ref)
        scale = np.max(np.abs(ref)) + 1e-300
        np.testing.assert_allclose(out, ref, rtol=1e-10, atol=1e-10 * scale)
        assert out[9] >= 0


def test_zero_load_gives_nothing():
    out = _flat_rolling(2.5, 2.0, q=0.0)
    assert np.all(out == 0.0)


# --------------------------------------------------------------------------- physics invariants

def test_pure_rolling_no_traction_only_rolling_resistance():
    u = 3.0
    out = _flat_rolling(u, u, lub=_lub(model="fluid", rolling_resistance=False))
    np.testing.assert_allclose(out, 0.0, atol=1e-15)
    lub = _lub(model="fluid", thermal=False)
    out = _flat_rolling(u, u, lub=lub)
    # expected: sum over slices of Zhou & Hoeprich eq. 17 on strips of width 2a/n, against the rolling direction
    n = 10
    width = 2 * HC.a / n
    eta0, alpha = lub[S.L_ETA0], lub[S.L_ALPHA]
    fr = force = 0.0
    for j in range(n):
        xi0, xi1 = -1 + 2 * j / n, -1 + 2 * (j + 1) / n
        qj = Q * S.slice_fraction(xi0, xi1)
        U = eta0 * u / (E_EFF * RX)
        frj = 29.2 * (RX / alpha) * width * (alpha * E_EFF * U) ** 0.648 * (qj / (width * E_EFF * RX)) ** 0.246
        fr += frj
        # ball: -F_R + P1, P1 = 2 F_R R_x / R_1, R_1 = distance of the slice point from the ball centre
        r1 = math.hypot(R_BALL, HC.a * S.slice_centroid(xi0, xi1))
        force += frj * (2 * RX / r1 - 1)
    assert out[1] == pytest.approx(force, rel=1e-12)
    assert abs(out[0]) < 1e-12 * fr and abs(out[2]) < 1e-12 * fr
    # moment on the ball about its centre: shear -F_R at the contact, lever R_ball, opposing the rolling
    assert out[3] == pytest.approx(-fr * R_BALL, rel=1e-12)
    assert out[9] == pytest.approx(2 * fr * u, rel=1e-12)


def test_large_sliding_gives_boundary_mu_q():
    lub = _lub(model="boundary")
    mu_inf = lub[S.L_BD]
    out = _flat_rolling(1e3, -1e3, lub=lub)  # sliding +2000 m/s along y, rolling speed 0
    np.testing.assert_allclose(out[0:3], [0.0, -mu_inf * Q, 0.0], rtol=1e-12, atol=1e-9)
    assert out[9] == pytest.approx(mu_inf * Q * 2e3, rel=1e-12)


@pytest.mark.parametrize("n", [2, 10, 40])
def test_pure_spin_constant_mu_even_n_exact(n):
    """Spin ω about the normal, constant μ: the moment about the normal is 3μQa/8 (exact for even n)."""
    mu = 0.08
    lub = _lub(model="boundary", rolling_resistance=False)
    lub[S.L_BA:S.L_BD + 1] = (0.0, 0.0, 0.0, mu)
    out = _flat_rolling(0.0, 0.0, spin=50.0, lub=lub, n=n)
    expected = 3 * mu * Q * HC.a / 8
    assert out[5] == pytest.approx(-expected, rel=1e-12)
    np.testing.assert_allclose(out[0:3], 0.0, atol=1e-12 * mu * Q)


def test_pure_spin_odd_n_converges():
    mu = 0.08
    lub = _lub(model="boundary", rolling_resistance=False)
    lub[S.L_BA:S.L_BD + 1] = (0.0, 0.0, 0.0, mu)
    expected = 3 * mu * Q * HC.a / 8
    errs = [abs(_flat_rolling(0.0, 0.0, spin=50.0, lub=lub, n=n)[5] + expected) / expected for n in (3, 9, 27, 81)]
    assert all(e2 < e1 for e1, e2 in zip(errs, errs[1:]))
    assert errs[-1] < 1e-3


def test_angular_momentum_balance_of_traction():
    """Traction pairs act at the same point: M_b + c_b×F + M_r + c_r×(−F) = 0."""
    rng = np.random.default_rng(7)
    lub = _lub(model="mixed", rolling_resistance=False)
    for _ in range(5):
        c, n, m, cb, vb, wb, cr, vr, wr = _random_state(rng)
        out = np.zeros(10)
        S.contact_traction(Q, HC.a, HC.b, S.deformed_surface_radius(D, F_I * D), c, n, m, cb, vb, wb, cr, vr, wr,
                           lub, 10, out)
        tot = out[3:6] + np.cross(cb, out[0:3]) + out[6:9] + np.cross(cr, -out[0:3])
        assert np.max(np.abs(tot)) < 1e-12 * (np.max(np.abs(out[3:9])) + 1e-300)


def test_jones_points_lie_on_deformed_surface():
    r_dev = S.deformed_surface_radius(D, F_I * D)
    assert r_dev == pytest.approx(2 * F_I * D * D / (2 * F_I * D + D))
    a = HC.a
    for n in (1, 5, 10):
        for j in range(n):
            x = a * S.slice_centroid(-1 + 2 * j / n, -1 + 2 * (j + 1) / n)
            c = 1 / r_dev
            off = c * x * x / (1 + math.sqrt(1 - (c * x) ** 2))
            # distance to the centre of curvature (0, r_dev) in the (major, normal) plane
            assert math.hypot(x, off - r_dev) == pytest.approx(r_dev, rel=1e-14)


def test_traction_opposes_sliding_and_power_positive():
    out = _flat_rolling(3.03, 2.97, lub=_lub(model="fluid", rolling_resistance=False))
    assert out[1] < 0  # ball surface faster than the race along +y -> force on ball along -y
    assert out[9] == pytest.approx(-out[1] * 0.06, rel=1e-12)


# --------------------------------------------------------------------------- bad input

def test_bad_inputs_raise_typed_errors():
    lub = _lub()
    good = dict(centre=np.zeros(3), normal=np.array([0, 0, 1.0]), major=np.array([1.0, 0, 0]),
                ball_centre=np.array([0, 0, R_BALL]), v_ball=np.zeros(3), w_ball=np.zeros(3),
                race_centre=np.array([0, 0, -1.0]), v_race=np.zeros(3), w_race=np.zeros(3))
    args = lambda **kw: [kw.get(k, v) for k, v in good.items()]  # noqa: E731
    with pytest.raises(InputError, match="n_slices"):
        S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *args(), lub, 0)
    with pytest.raises(InputError, match="v_ball"):
        S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *args(v_ball=np.array([np.nan, 0, 0])), lub, 10)
    with pytest.raises(InputError, match="w_race"):
        S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *args(w_race=np.array([0, np.inf, 0])), lub, 10)
    with pytest.raises(InputError, match="load"):
        S.contact_traction_checked(-1.0, HC.a, HC.b, math.inf, *args(), lub, 10)
    out = S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *args(), lub, 10)
    assert out.shape == (10,)
    with pytest.raises(InputError, match="model"):
        S.pack_lubrication_parameters("iso-vg-68", 333.15, E_EFF, RX, RY, 0.0, model="wet")
    with pytest.raises(InputError, match="temperature"):
        S.pack_lubrication_parameters("iso-vg-68", 200.0, E_EFF, RX, RY, 0.0)
    with pytest.raises(InputError, match="roughness"):
        S.pack_lubrication_parameters("iso-vg-68", 333.15, E_EFF, RX, RY, -1e-7)


def test_mixed_model_continuous_in_lambda():
    """Kernel force vs roughness across Λ₁ and Λ₂: no jump (seed 001 mixed interpolation)."""
    lub0 = _lub(model="mixed", rolling_resistance=False, roughness=0.1e-6)
    # Λ = h_min/σ: scanning σ makes Λ cross Λ₂ = 3 and Λ₁ = 1
    forces = []
    sig = np.geomspace(2e-8, 2e-6, 400)
    for s in sig:
        lub = lub0.copy()
        lub[S.L_SIGMA] = s
        forces.append(_flat_rolling(3.03, 2.97, lub=lub)[1])
    forces = np.array(forces)
    jumps = np.abs(np.diff(forces))
    assert forces[0] != pytest.approx(forces[-1], rel=0.05)  # boundary and fluid ends differ
    assert np.max(jumps) < 0.05 * np.max(np.abs(forces))  # smooth: no step at Λ₁ or Λ₂


def test_traction_converges_with_slice_count():
    lub = _lub(model="fluid", fluid_model="curve")
    f = [np.linalg.norm(_flat_rolling(3.0, 3.0, spin=40.0, lub=lub, n=n, r_dev=S.deformed_surface_radius(D, F_I * D))
                        [0:6]) for n in (5, 10, 20, 40, 80, 160)]
    d = np.abs(np.diff(f))
    assert np.all(d[1:] < d[:-1] * 0.9)  # successive differences shrink
    assert d[-1] < 1e-2 * f[-1]


def test_rolling_resistance_force_system_balances():
    """Shear on both surfaces plus the pressure forces (through the ball centre and the race's centre
    of curvature) sum to zero force and zero moment (massless film; Zhou & Hoeprich 1991 N e = P_x,i R_i)."""
    rng = np.random.default_rng(3)
    lub = _lub(model="fluid", thermal=False)
    for _ in range(5):
        c, n, m, cb, vb, wb, cr, vr, wr = _random_state(rng)
        out = np.zeros(10)
        S.contact_traction(Q, HC.a, HC.b, math.inf, c, n, m, cb, vb, wb, cr, vr, wr, lub, 1, out)
        tot = out[3:6] + np.cross(cb, out[0:3]) + out[6:9] + np.cross(cr, -out[0:3])
        assert np.max(np.abs(tot)) < 1e-12 * (np.max(np.abs(out[3:9])) + 1e-300)


# --------------------------------------------------------------------------- fast forms used by the kernel

def test_fast_tanh_and_asinh_forms_match_libm():
    """The kernel's tanh (via exp) and asinh from ln 2x alone (ln 2x for x ≥ 1e6, where the dropped 1/(4x²) is
    ≤ 1.8e-14 of the value; eight terms of the series in 1/x² for 10 ≤ x < 1e6; asinh(e^(ln 2x − ln 2)) below) agree
    with math.tanh/asinh, on both sides of both switches; the series' coefficients are C(2n, n)/(4ⁿ 2n)
    (Abramowitz & Stegun 4.6.31)."""
    for z in np.geomspace(1e-9, 60.0, 400):
        assert S._tanh_pos(z) == pytest.approx(math.tanh(z), rel=2e-13, abs=0.0)
    assert S._tanh_pos(0.0) == 0.0
    for x in np.concatenate([np.geomspace(1e-9, 1e15, 400), np.geomspace(9.9, 10.1, 50),
                        np.geomspace(99.0, 101.0, 50), np.geomspace(9.9e5, 1.01e6, 50)]):
        assert S._asinh_l2x(math.log(2 * x)) == pytest.approx(math.asinh(x), rel=3e-14)


def test_pow_0648_series_matches_libm():
    """The rolling-resistance power x^0.648 by its binomial series near 1 (|x − 1| ≤ 1/16) and exp/log elsewhere
    agrees with x**0.648 to the stated 1e-14 (series remainder < 5e-15 plus rounding), on both sides of the switch."""
    r = S.POW_SERIES_R
    xs = np.concatenate([1.0 + np.linspace(-r, r, 2001), 1.0 + r * (1 + np.geomspace(1e-12, 1e-3, 50)),
                         1.0 - r * (1 + np.geomspace(1e-12, 1e-3, 50)), np.geomspace(1e-6, 1e6, 400)])
    for x in xs:
        assert S._pow_0648(x) == pytest.approx(x**0.648, rel=1e-14, abs=0.0), x
    # the series is the binomial one: its last coefficient is C(0.648, 9)
    c9 = math.prod(0.648 - k for k in range(9)) / math.factorial(9)
    assert S._POW_C[S.POW_SERIES_ORDER] == pytest.approx(c9, rel=1e-14)


def test_strip_tables_equal_the_strip_formulae():
    """The tabulated strip constants (n ≤ STRIP_TABLE_MAX) are the load share, load centroid and area of each
    strip pair (slice_fraction, slice_centroid, slice_area_fraction), and the kernel gives the same forces with
    the table (n = 64) as without it (the same strips with n = 64 evaluated by the running differences is not
    reachable from outside, so the tabled kernel is held to the reference at 1e-10 instead)."""
    for n in (1, 2, 3, 8, 13, 64):
        for j in range((n + 1) // 2):
            x0, x1 = -1.0 + 2.0 * j / n, -1.0 + 2.0 * (j + 1) / n
            assert S._STRIP_FRAC[n, j] == pytest.approx(S.slice_fraction(x0, x1), rel=1e-13)
            assert S._STRIP_XI[n, j] == pytest.approx(S.slice_centroid(x0, x1), rel=1e-12, abs=1e-15)
            assert S._STRIP_AREA[n, j] == pytest.approx(S.slice_area_fraction(x0, x1), rel=1e-12)
            assert S._STRIP_Q246[n, j] == pytest.approx(S.slice_fraction(x0, x1) ** 0.246, rel=1e-14)
        assert 2 * S._STRIP_FRAC[n, :n // 2].sum() + (S._STRIP_FRAC[n, n // 2] if n % 2 else 0.0) == \
            pytest.approx(1.0, rel=1e-14)


@pytest.mark.parametrize("n_slices", [8, 64, 65])
def test_kernel_tabled_and_untabled_strips_match_reference(n_slices):
    """Kernel vs reference at 1e-10 on both sides of the table limit (64 tabled, 65 by running differences), with
    rolling resistance on and entraining speeds near and far from the centre's (both branches of _pow_0648)."""
    rd = S.deformed_surface_radius(D, F_I * D)
    lub = _lub(model="mixed", roughness=0.1e-6, viscoelastic=False)  # (the film elasticity is another test's)
    for u in (0.05, 5.0):
        for spin in (0.0, 40.0, 4000.0):
            args = (2000.0, HC.a, HC.b, rd, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                    np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u * 1.002 / R_BALL, 0.0, spin * u]),
                    np.array([0.0, 0.0, -0.025]), np.zeros(3), np.array([-u / 0.025, 0.0, 0.0]), lub, n_slices)
            out, ref = np.zeros(10), np.zeros(10)
            S.contact_traction(*args, out)
            S.contact_traction_reference(*args, ref)
            scale = np.max(np.abs(ref)) + 1e-300
            np.testing.assert_allclose(out, ref, rtol=1e-10, atol=1e-10 * scale, err_msg=str((u, spin)))


def test_film_constants_stored_in_lub_give_the_same_forces_and_never_go_stale():
    """The contact type's film constants that pack_lubrication_parameters stores (L_C_*) give the same forces as
    computing them per call (L_C_AE cleared), and a lub whose α is changed after packing is not served the stale
    constants (its forces equal those of the per-call computation, and differ from the original's)."""
    rd = S.deformed_surface_radius(D, F_I * D)
    lub = _lub(model="mixed", roughness=0.1e-6)
    assert lub[S.L_C_AE] == lub[S.L_ALPHA] * lub[S.L_EEFF] and lub[S.L_C_LNG] == pytest.approx(
        math.log(lub[S.L_ALPHA] * lub[S.L_EEFF]), rel=1e-15)
    fresh = lub.copy()
    fresh[S.L_C_AE] = 0.0  # constants computed per call
    changed = lub.copy()
    changed[S.L_ALPHA] *= 1.1
    changed_fresh = changed.copy()
    changed_fresh[S.L_C_AE] = 0.0

    def forces(lb, u, spin):
        out = np.zeros(10)
        S.contact_traction(2000.0, HC.a, HC.b, rd, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                           np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u * 1.002 / R_BALL, 0.0, spin * u]),
                           np.array([0.0, 0.0, -0.025]), np.zeros(3), np.array([-u / 0.025, 0.0, 0.0]), lb, 8, out)
        return out

    for u in (0.05, 5.0):
        for spin in (0.0, 40.0):
            base = forces(lub, u, spin)
            np.testing.assert_allclose(base, forces(fresh, u, spin), rtol=1e-15, atol=0.0)
            np.testing.assert_allclose(forces(changed, u, spin), forces(changed_fresh, u, spin), rtol=1e-15, atol=0.0)
            if u == 5.0:  # a film-carried contact (at 0.05 m/s the mixed model is boundary friction: α plays no part)
                assert np.max(np.abs(forces(changed, u, spin) - base)) > 1e-6 * np.max(np.abs(base))


def test_heated_stress_matches_fluid_shear_stress():
    """First Eyring/limiting-stress evaluation + the kernel's secant step equal traction.fluid_shear_stress."""
    from bearingsim.contact import traction as T

    rng = np.random.default_rng(11)
    lub = _lub()
    tau0, t0c, beta_v = lub[S.L_TAU0], lub[S.L_T0C], lub[S.L_BETA_V]
    lss = lub[S.L_LSS_R:S.L_LSS_FLOOR + 1]
    for _ in range(3000):
        p = 10 ** rng.uniform(6, 9.7)
        u_s = 10 ** rng.uniform(-7, 2)
        h = 10 ** rng.uniform(-9, -5)
        eta_p = 10 ** rng.uniform(-3, 8)
        theta = 10 ** rng.uniform(-12, -5)
        ref = T.fluid_shear_stress.py_func(p, u_s, h, theta, eta_p, tau0, t0c, *lss, beta_v)
        x = eta_p * (u_s / h) / tau0
        fl = lss[5] * p
        tl = max(lss[0] * (lss[1] * p / (lss[2] + lss[3] * t0c) - lss[4]), fl)
        l2x = math.log(2 * x)
        tau = tl * S._tanh_pos(tau0 / tl * S._asinh_l2x(l2x))
        tau = S._heated_stress(tau, theta * u_s, l2x, p, fl, tau0, t0c, *lss[:5], beta_v)
        assert tau == pytest.approx(ref, rel=1e-12), (p, u_s, h, eta_p, theta)


@pytest.mark.parametrize("n_slices", [9, 10, -3, -4, S.SPLIT_BASE + 6, S.SPLIT_BASE + 9])
def test_kernel_matches_reference_operating_range(n_slices):
    """Kernel vs reference at 1e-10 over speeds, slips and loads of ball bearings (all branches of the fast forms);
    n_slices < 0: the Gauss rule between the zeros of the rolling slip (the spin of 40 u rad/s puts two zeros in
    the ellipse), whose nodes the reference evaluates with the model functions one point at a time;
    SPLIT_BASE + n: n strips cut at those zeros (the reference sorts the zeros into the strips' edges and takes
    every part as a strip of its own width; 9 strips and two cuts need two passes of the eight lanes)."""
    rd = S.deformed_surface_radius(D, F_I * D)
    for kw in (dict(model="mixed", roughness=0.1e-6), dict(model="fluid"), dict(model="mixed", roughness=0.3e-6)):
        lub = _lub(**kw)
        for u in (0.01, 0.5, 5.0, 50.0):
            for slip in (1e-5, 1e-3, 3e-2, 0.5):
                for q in (20.0, 2000.0, 20000.0):
                    a, b = HC.a * (q / Q) ** (1 / 3), HC.b * (q / Q) ** (1 / 3)
                    args = (q, a, b, rd, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                            np.array([0.0, 0.0, R_BALL]), np.zeros(3),
                            np.array([u * (1 + slip) / R_BALL, 0.0, 40.0 * u]),
                            np.array([0.0, 0.0, -0.025]), np.zeros(3), np.array([-u / 0.025, 0.0, 0.0]), lub,
                            n_slices)
                    out, ref = np.zeros(10), np.zeros(10)
                    S.contact_traction(*args, out)
                    S.contact_traction_reference(*args, ref)
                    scale = np.max(np.abs(ref)) + 1e-300
                    np.testing.assert_allclose(out, ref, rtol=1e-10, atol=1e-10 * scale, err_msg=str((kw, u, slip, q)))


@pytest.mark.parametrize("n_slices", [4, 10, -3, S.SPLIT_BASE + 6])
def test_kernel_matches_reference_without_rolling_at_the_centre(n_slices):
    """The rolling resistance where the ellipse centre does not roll (u0 = 0: the kernel's k_zh branch, which the
    strips' and Gauss nodes' u0-scaled forms do not cover): the race spinning about the normal through the centre
    (ball at rest) entrains the strips off the centre only; kernel vs the one-point-at-a-time reference at 1e-10.
    Even strip counts: with an odd count the middle strip's centroid sits on the spin pole, where slip and rolling
    speed both vanish and μ(s/u) has no limit (the kernel's tabled centroid is 0 exactly and gives no traction there,
    the reference's running difference leaves ~1e-20 m and takes the limit along the spin field)."""
    rd = S.deformed_surface_radius(D, F_I * D)
    lub = _lub(model="mixed", roughness=0.1e-6)
    for spin in (50.0, 800.0):
        for q in (200.0, 5000.0):
            a, b = HC.a * (q / Q) ** (1 / 3), HC.b * (q / Q) ** (1 / 3)
            args = (q, a, b, rd, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                    np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.zeros(3), np.array([0.0, 0.0, -0.025]), np.zeros(3),
                    np.array([0.0, 0.0, spin]), lub, n_slices)
            out, ref = np.zeros(10), np.zeros(10)
            S.contact_traction(*args, out)
            S.contact_traction_reference(*args, ref)
            assert out[9] > 0.0  # the strips roll: rolling resistance and its power
            scale = np.max(np.abs(ref))
            np.testing.assert_allclose(out, ref, rtol=1e-10, atol=1e-10 * scale,
                                       err_msg=f"contact_traction_reference, u0 = 0, spin {spin}, Q {q}")


@pytest.mark.parametrize("n_slices", [1, 10])
def test_viscoelastic_film_linear_limit_closed_form(n_slices):
    """Small slide-roll ratio at 2 GPa: the film shears elastically (Johnson & Tevaarwerk 1977 linear elastic
    regime), F = Σ_j G(p̄_j) ℓ_j A_j s/(2 h_c) with ℓ_j the strip's mean chord and A_j its area; without film
    elasticity the same contact is Coulomb-like (μ near its plateau already at s = 1e-7)."""
    from bearingsim.contact import ehl
    from bearingsim.contact import traction as T

    lub = _lub(model="fluid", fluid_model="physical", thermal=False, rolling_resistance=False)
    q = 8000.0  # p_max ≈ 2 GPa on the hub inner raceway
    hc = hertz.point_contact_exact(q, RX, RY, E_EFF)
    u, s = 3.0, 1e-7
    out = np.zeros(10)
    args = (q, hc.a, hc.b, math.inf, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
            np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u * (1 + s / 2) / R_BALL, 0.0, 0.0]),
            np.array([0.0, 0.0, -1.0]), np.array([0.0, u * (1 - s / 2), 0.0]), np.zeros(3))
    S.contact_traction(*args, lub, n_slices, out)
    h = ehl.hamrock_dowson_central(u, q, lub[S.L_ETA0], lub[S.L_ALPHA], E_EFF, RX, RY)
    expected = 0.0
    for j in range(n_slices):
        xi0, xi1 = -1 + 2 * j / n_slices, -1 + 2 * (j + 1) / n_slices
        area = hc.a * hc.b * S.slice_area_fraction(xi0, xi1)
        pbar = q * S.slice_fraction(xi0, xi1) / area
        g = T.limiting_shear_stress(pbar, 60.0, 0.25, 1.2, 2.52, 0.024, 1e8, 0.02) / 0.25
        chord = area / (2 * hc.a / n_slices)
        expected += g * chord * area * s / (2 * h)
    np.testing.assert_allclose(-out[1], expected, rtol=1e-9,
                               err_msg="Johnson & Tevaarwerk (1977) linear elastic film traction G s l / (2 h)")
    assert abs(out[0]) < 1e-12 * expected
    stiff = np.zeros(10)
    S.contact_traction(*args, _lub(model="fluid", fluid_model="physical", thermal=False, rolling_resistance=False,
                                   viscoelastic=False), n_slices, stiff)
    assert -stiff[1] / q > 0.01 and -out[1] / q < 1e-4


def test_slice_point_offset_is_the_circle_of_the_deformed_surface():
    """The one slice-point convention: a point at x along the major axis lies on the circle of radius
    r_dev tangent to the plane at the centre, offset towards the ball (+normal); flat when r_dev = ±inf."""
    for r_dev, x in ((7e-3, 1e-3), (7e-3, -2.5e-3), (-4e-3, 1.5e-3)):
        off, root = S.slice_point_offset(x, S.surface_curvature(r_dev))
        # the circle's centre at r_dev along +normal: (x, off) lies at distance |r_dev| from it
        assert math.isclose(math.hypot(x, off - r_dev), abs(r_dev), rel_tol=1e-14)
        assert math.isclose(root, math.sqrt(1 - (x / r_dev) ** 2), rel_tol=1e-14)
        assert math.copysign(1.0, off) == math.copysign(1.0, r_dev)
    assert S.slice_point_offset(1e-3, S.surface_curvature(math.inf)) == (0.0, 1.0)
    assert S.surface_curvature(0.0) == 0.0


@pytest.mark.parametrize("n_slices", [4, 8, 10])
def test_coulomb_stand_in_uses_the_same_slices(n_slices):
    """dynamics.forces.coulomb_slices places its slices as contact_traction does (load share and load
    centroid of each strip): a pure spin ω about the normal with a constant μ (s₀ = v_ref = 0) gives the
    spin moment Σ μ Q_j |x̄_j| = 3 μ Q a / 8 exactly for an even slice count (module docstring, item 1);
    slice midpoints instead of centroids miss it by ~1/n²."""
    from bearingsim.dynamics.forces import coulomb_slices

    q, a, mu, spin = 1500.0, 1.2e-3, 0.07, 40.0
    out = np.zeros(10)
    coulomb_slices(q, a, math.inf, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                   np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([0.0, 0.0, spin]), np.array([0.0, 0.0, -0.03]),
                   np.zeros(3), np.zeros(3), mu, 0.0, 0.0, n_slices, out)
    assert math.isclose(-out[5], 3 * mu * q * a / 8, rel_tol=1e-12)
    assert abs(out[0]) < 1e-12 * mu * q and abs(out[1]) < 1e-12 * mu * q  # the slices' forces cancel
