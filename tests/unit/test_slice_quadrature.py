"""Gauss quadrature of the contact ellipse between the zeros of the rolling slip (issue 14, lever 1).

The kernel :func:`bearingsim.contact.slices.contact_traction` with n_slices = −k integrates the strip
model's densities (load (3Q/4)(1 − ξ²), seed 001 eq. 1) with k Gauss–Legendre nodes on each sub-interval
of ξ ∈ [−1, 1] cut at the zeros of the rolling-direction sliding speed, nodes graded towards the zeros.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from bearingsim.contact import hertz
from bearingsim.contact import slices as S
from bearingsim.errors import InputError

D = 0.0111
E_EFF = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
RX, RY = hertz.raceway_radii(D, 0.061, 0.52, math.radians(35.0), True)
Q = 2000.0
HC = hertz.point_contact_exact(Q, RX, RY, E_EFF)
R_BALL = D / 2


def _lub(**kw):
    return S.pack_lubrication_parameters("iso-vg-68", 333.15, E_EFF, RX, RY, 0.1e-6, **kw)


def _constant_mu(mu):
    lub = _lub(model="boundary", rolling_resistance=False)
    lub[S.L_BA:S.L_BD + 1] = (0.0, 0.0, 0.0, mu)
    return lub


def _flat(u_ball, u_race, spin, lub, n, r_dev=math.inf, w_side=0.0):
    """Ball above a flat race at z = 0 rolling along y (spin about the normal z, w_side about y)."""
    out = np.zeros(10)
    S.contact_traction(Q, HC.a, HC.b, r_dev, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                       np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u_ball / R_BALL, w_side, spin]),
                       np.array([0.0, 0.0, -1.0]), np.array([0.0, u_race, 0.0]), np.zeros(3), lub, n, out)
    return out


@pytest.mark.parametrize("n", range(1, S.GAUSS_MAX + 1))
def test_gauss_legendre_table_is_exact_for_polynomials_of_degree_2n_minus_1(n):
    x, w = S._GL_X[n, :n], S._GL_W[n, :n]
    for k in range(2 * n):
        exact = (1.0 - (-1.0) ** (k + 1)) / (k + 1)
        assert np.dot(w, x**k) == pytest.approx(exact, abs=1e-14)
    # and not beyond: x^(2n) is integrated with an error (the table is not over-fitted)
    assert abs(np.dot(w, x ** (2 * n)) - 2.0 / (2 * n + 1)) > 1e-6


@pytest.mark.parametrize("k", [4, 6])
def test_pure_spin_constant_mu_is_exact(k):
    """Spin about the normal of a flat contact, constant μ: one zero at ξ = 0, and on each side the graded
    integrand (1 − ξ²)|ξ| with ξ = t² is a polynomial of degree 7 in t: exact from 4 nodes — the moment about
    the normal is 3μQa/8 (the strip docstring's closed form) and the force zero."""
    mu = 0.08
    out = _flat(0.0, 0.0, 50.0, _constant_mu(mu), -k)
    assert out[5] == pytest.approx(-3 * mu * Q * HC.a / 8, rel=1e-12)
    np.testing.assert_allclose(out[0:3], 0.0, atol=1e-12 * mu * Q)


def test_pure_spin_with_three_nodes_is_not_exact():
    """The same case with 3 nodes is not exact (degree 7 > 5): the exactness above is that of the rule."""
    mu = 0.08
    out = _flat(0.0, 0.0, 50.0, _constant_mu(mu), -3)
    assert abs(out[5] / (-3 * mu * Q * HC.a / 8) - 1) > 1e-6


@pytest.mark.parametrize("k", [2, 3])
def test_uniform_sliding_constant_mu_gives_mu_q(k):
    """No zero of the rolling slip: one interval, integrand (1 − ξ²) exact from 2 nodes: F = μQ."""
    mu = 0.07
    out = _flat(1.0, -1.0, 0.0, _constant_mu(mu), -k)
    np.testing.assert_allclose(out[0:3], [0.0, -mu * Q, 0.0], rtol=1e-12, atol=1e-9)
    assert out[9] == pytest.approx(mu * Q * 2.0, rel=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.floats(-1.0, 1.0), st.floats(-2.0, 2.0), st.floats(-50.0, 50.0), st.floats(-300.0, 300.0))
@example(2.373207236475156e-158, 2.373207236475156e-158, 2.373207236475156e-158, -1.0)  # (σ1² underflowed: the CI)
def test_rolling_slip_zeros_are_the_sign_changes(sig0, sig1, sig2, curv):
    """The zeros returned are zeros of g(ξ) = σ0 + σ1 ξ + σ2 δ(aξ), and g keeps its sign between them
    (checked on a dense grid), so each sub-interval has one sign of the rolling slip — whatever the field's scale
    (a field of 1e-158 m/s once lost its zeros to an underflowing σ1²)."""
    a = 1.8e-3
    nr, z1, z2 = S.rolling_slip_zeros(sig0, sig1, sig2, a, curv)

    def g(xi):
        return sig0 + sig1 * xi + sig2 * S.slice_point_offset(a * xi, curv)[0]

    scale = abs(sig0) + abs(sig1) + abs(sig2) * abs(curv) * a * a
    for z in (z1, z2)[:nr]:
        assert abs(g(z)) <= 1e-13 * scale  # (two Halley steps reach ~1e-16; the docstring of rolling_slip_zeros)
    edges = [-1.0] + [z1, z2][:nr] + [1.0]
    for lo, hi in zip(edges, edges[1:]):
        xs = np.linspace(lo, hi, 402)[1:-1]
        vals = np.array([g(x) for x in xs])
        big = np.abs(vals) > 1e-9 * scale
        assert np.all(vals[big] > 0) or np.all(vals[big] < 0), (lo, hi)


def _hub_accelerations(nsl, scale):
    from bearingsim.dynamics import forces as fo
    from bearingsim.dynamics import layout as ly
    from bearingsim.dynamics import model as md
    from bearingsim.io import load_bearing
    from bearingsim.statics import jones_harris as jh

    b = load_bearing("hub-seed001")
    w = 884 * math.pi / 30
    res = jh.solve(b, jh.Loads(fr_y=2800.0, m_z=300.0), w, control="outer")
    m = md.build_model(b, traction="slices", speed=(w, w, 0.0), ring_mass=3.0, damping_alpha=0.05, n_slices=nsl,
                       lubricant="hub-grease-base-oil", temperature=313.15)
    y = md.initial_state(m, res, w)
    idx = []
    for k in range(m.n_balls):
        o = m.ball_slice(k).start
        y[o + ly.B_OMEGA:o + ly.B_OMEGA + 3] *= scale
        idx += list(range(o + ly.B_VEL, o + ly.B_OMEGA + 3))
    dy, _, gd = fo.evaluate(m, 0.0, y, fo.constant_loads(fr_y=2800.0, m_z=300.0))
    return dy[idx], gd[ly.GD_PI] + gd[ly.GD_PO]


@pytest.mark.parametrize("scale", [0.99, 1.01])
def test_hub_states_within_one_percent_of_the_fine_strip_limit(scale):
    """The hub states of test_dyn_options (ball spin 1 % below / above Jones' value): ball accelerations
    (traction forces and moments of the 64 contacts) with 4 graded nodes per sub-interval within 1 % of
    1024 strips (measured 0.25 % and 0.5 %; 8 strips: 8.3 % and 14 %; 128 strips differ from 1024 by
    0.1 % and 0.3 %), and the power loss within 0.5 %."""
    ref, pref = _hub_accelerations(1024, scale)
    acc, p = _hub_accelerations(-4, scale)
    a8, _ = _hub_accelerations(8, scale)
    err = np.linalg.norm(acc - ref) / np.linalg.norm(ref)
    err8 = np.linalg.norm(a8 - ref) / np.linalg.norm(ref)
    assert err < 0.01 and err < err8 / 5, (err, err8)
    assert p == pytest.approx(pref, rel=5e-3)


def test_quadrature_converges_on_the_bench_contact():
    """Mixed physical film, 1 % slip and spin (benchmarks/bench_slices.py): two zeros of the rolling slip;
    the force converges to the 4096-strip limit as nodes are added (measured 3 %, 0.2 %, 0.2 % at 4, 6, 8)."""
    lub = _lub()
    wb = np.array([-2.5 / R_BALL * 1.01, 0.0, 30.0])
    args = (Q, HC.a, HC.b, S.deformed_surface_radius(D, 0.52 * D), np.zeros(3), np.array([0.0, 0.0, 1.0]),
            np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, R_BALL]), np.zeros(3), wb, np.array([0.0, 0.0, -0.025]),
            np.zeros(3), np.array([100.0, 0.0, 0.0]), lub)
    ref = np.zeros(10)
    S.contact_traction(*args, 4096, ref)
    errs = []
    for k in (2, 6, 8):
        out = np.zeros(10)
        S.contact_traction(*args, -k, out)
        errs.append(np.linalg.norm(out[0:9] - ref[0:9]) / np.linalg.norm(ref[0:9]))
    assert errs[2] < errs[0] and errs[1] < errs[0] and errs[2] < 0.01, errs


def test_checked_entry_takes_the_quadrature_by_name():
    lub = _constant_mu(0.08)
    vec = dict(centre=np.zeros(3), normal=[0.0, 0.0, 1.0], major=[1.0, 0.0, 0.0], ball_centre=[0.0, 0.0, R_BALL],
               v_ball=np.zeros(3), w_ball=[0.0, 0.0, 50.0], race_centre=[0.0, 0.0, -1.0], v_race=np.zeros(3),
               w_race=np.zeros(3))
    out = S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *vec.values(), lub, 4, quadrature="gauss")
    assert out[5] == pytest.approx(-3 * 0.08 * Q * HC.a / 8, rel=1e-12)
    with pytest.raises(InputError, match="quadrature"):
        S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *vec.values(), lub, 4, quadrature="simpson")
    with pytest.raises(InputError, match="n_slices"):
        S.contact_traction_checked(Q, HC.a, HC.b, math.inf, *vec.values(), lub, S.GAUSS_MAX + 1, quadrature="gauss")


@pytest.mark.parametrize("a", [0.246, 0.5])
def test_gauss_jacobi_rule_matches_scipy_and_is_exact(a):
    """The rolling resistance's fixed nodes (Golub–Welsch) equal scipy's Gauss–Jacobi rule, and integrate
    ξ^k (1 − ξ²)^a exactly for k ≤ 2n − 1 (moments B((k+1)/2, a+1) for even k, zero for odd k)."""
    from scipy.special import beta, roots_jacobi

    n = S.ROLL_NODES
    x, w = S.gauss_jacobi(n, a)
    xs, ws = roots_jacobi(n, a, a)
    np.testing.assert_allclose(x, xs, atol=1e-14)
    np.testing.assert_allclose(w, ws, rtol=1e-13)
    for k in range(2 * n):
        exact = 0.0 if k % 2 else beta((k + 1) / 2, a + 1)
        assert np.dot(w, x**k) == pytest.approx(exact, abs=1e-14)


@pytest.mark.parametrize("spin", [0.0, 40.0])
def test_gauss_rule_rolling_resistance_converges_to_the_strip_limit(spin):
    """Traction off (μ ≡ 0), rolling resistance and oil-film force only (Zhou & Hoeprich 1991 per unit
    length, seed eqs. 4–5): the Gauss rule's 4 fixed Gauss–Jacobi nodes give the strip model's limit — 4096
    strips, whose own error falls as n^−1.25 (the (1 − ξ²)^0.246 edge factor) — within 1e-4 of the largest
    entry, forces, moments and power, with and without spin (the entraining speed varies across the ellipse),
    and closer to it than 1024 strips are (measured 5.0e-6 against 2.3e-5; the 4096-strip reference's own error,
    from that n^−1.25 convergence, is ≈ 7e-6)."""
    lub = _lub(model="fluid", fluid_model="curve", fluid_curve=(0.0, 0.06, 0.01, 0.045))
    lub[S.L_FA:S.L_FD + 1] = 0.0  # the curve μ(s) = (A + B s)e^(−C s) + D with A = B = D = 0: no traction
    wb = np.array([-2.5 / R_BALL, 0.0, spin])
    args = (Q, HC.a, HC.b, S.deformed_surface_radius(D, 0.52 * D), np.zeros(3), np.array([0.0, 0.0, 1.0]),
            np.array([1.0, 0.0, 0.0]), np.array([0.0, 0.0, R_BALL]), np.zeros(3), wb, np.array([0.0, 0.0, -0.025]),
            np.zeros(3), np.array([100.0, 0.0, 0.0]), lub)
    ref, ref2, out = np.zeros(10), np.zeros(10), np.zeros(10)
    S.contact_traction(*args, 4096, ref)
    S.contact_traction(*args, 1024, ref2)
    S.contact_traction(*args, -4, out)
    scale = np.max(np.abs(ref))
    assert scale > 0 and ref[9] > 0
    strip_err = np.max(np.abs(ref2 - ref)) / scale  # the strips' own convergence: 1024 against 4096
    assert np.max(np.abs(out - ref)) / scale < min(1e-4, strip_err), (out, ref, strip_err)
