"""Hertz point contact (bearingsim.contact.hertz): closed forms and invariants.

The reference here is an independent re-implementation in the test with scipy's elliptic
integrals (scipy.special.ellipk / ellipe take the parameter m = k², as A&S 17.2) and
scipy.optimize.brentq for the ellipticity, of the classical Hertz equations
(Harris & Kotzalas 2007 vol. 1 ch. 5; Hamrock & Brewe 1983 eqs. 1–14):

    F(ρ) = (1/Rx − 1/Ry)/(1/Rx + 1/Ry) = [(κ²+1)𝓔 − 2𝓚] / [(κ²−1)𝓔],  m = 1 − 1/κ²
    a = (6κ²𝓔QR/(πE′))^⅓, b = (6𝓔QR/(πκE′))^⅓, δ = 𝓚[(9/(2𝓔R))(Q/(πκE′))²]^⅓, p = 3Q/(2πab)
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from bearingsim.contact import hertz
from bearingsim.errors import InputError

E_STEEL, NU_STEEL = 208e9, 0.30
E_SIN, NU_SIN = 310e9, 0.26


def ref_kappa(rx, ry):
    """κ from the curvature difference, solved with scipy (independent of bearingsim)."""
    fr = (1 / rx - 1 / ry) / (1 / rx + 1 / ry)

    def g(t):
        k = math.exp(t)
        m = 1 - 1 / k**2
        return ((k * k + 1) * ellipe(m) - 2 * ellipk(m)) / ((k * k - 1) * ellipe(m)) - fr

    return math.exp(brentq(g, 1e-4, 15.0, xtol=1e-15, rtol=1e-15))


def ref_contact(q, rx, ry, e_eff):
    k = ref_kappa(rx, ry)
    m = 1 - 1 / k**2
    kk, ee = ellipk(m), ellipe(m)
    r = 1 / (1 / rx + 1 / ry)
    a = (6 * k * k * ee * q * r / (math.pi * e_eff)) ** (1 / 3)
    b = (6 * ee * q * r / (math.pi * k * e_eff)) ** (1 / 3)
    d = kk * ((9 / (2 * ee * r)) * (q / (math.pi * k * e_eff)) ** 2) ** (1 / 3)
    return dict(kappa=k, ell_k=kk, ell_e=ee, a=a, b=b, approach=d, max_pressure=3 * q / (2 * math.pi * a * b))


# --- elliptic integrals ----------------------------------------------------------------------
M_GRID = np.concatenate([np.linspace(0.0, 0.99, 100), 1 - np.logspace(-2, -12, 30)])


def test_elliptic_ke_matches_scipy():
    ks = np.array([hertz.elliptic_ke(float(m))[0] for m in M_GRID])
    es = np.array([hertz.elliptic_ke(float(m))[1] for m in M_GRID])
    assert_allclose(ks, ellipk(M_GRID), rtol=1e-14, atol=0, err_msg="scipy.special.ellipk (parameter m)")
    assert_allclose(es, ellipe(M_GRID), rtol=1e-14, atol=0, err_msg="scipy.special.ellipe (parameter m)")


def test_elliptic_ke_circle():
    k, e = hertz.elliptic_ke(0.0)
    assert k == pytest.approx(math.pi / 2, rel=1e-15)
    assert e == pytest.approx(math.pi / 2, rel=1e-15)


# --- exact ellipticity ------------------------------------------------------------------------
RATIOS = [1.001, 1.01, 1.5, 2.0, 5.0, 10.0, 17.3, 30.0, 60.0, 100.0, 1e3, 1e4]


@pytest.mark.parametrize("ratio", RATIOS)
def test_ellipticity_exact_matches_independent_solution(ratio):
    rx = 2.7e-3
    kappa, kk, ee = hertz.ellipticity_exact(rx, rx * ratio)
    k_ref = ref_kappa(rx, rx * ratio)
    assert kappa == pytest.approx(k_ref, rel=1e-10)
    m = 1 - 1 / kappa**2
    assert kk == pytest.approx(float(ellipk(m)), rel=1e-13)
    assert ee == pytest.approx(float(ellipe(m)), rel=1e-13)


def test_ellipticity_is_one_for_equal_radii():
    kappa, kk, ee = hertz.ellipticity_exact(3e-3, 3e-3)
    assert kappa == 1.0
    assert kk == pytest.approx(math.pi / 2) and ee == pytest.approx(math.pi / 2)


@pytest.mark.parametrize("ratio", [1.2, 5.0, 40.0])
def test_point_contact_matches_reference(ratio):
    q, rx, e_eff = 850.0, 4.1e-3, hertz.effective_modulus(E_SIN, NU_SIN, E_STEEL, NU_STEEL)
    c = hertz.point_contact_exact(q, rx, rx * ratio, e_eff)
    ref = ref_contact(q, rx, rx * ratio, e_eff)
    for key, v in ref.items():
        assert getattr(c, key) == pytest.approx(v, rel=1e-10), key


def test_axes_swapped_when_rx_greater_than_ry():
    """R_x > R_y is the same contact with the ellipse turned: κ ≥ 1 always."""
    e = 2.2e11
    c1 = hertz.point_contact_exact(500.0, 3e-3, 30e-3, e)
    c2 = hertz.point_contact_exact(500.0, 30e-3, 3e-3, e)
    assert c2.kappa >= 1.0
    for key in ("a", "b", "approach", "max_pressure", "kappa", "stiffness_constant"):
        assert getattr(c1, key) == pytest.approx(getattr(c2, key), rel=1e-13)


# --- load-deflection and pressure -----------------------------------------------------------------
@pytest.mark.parametrize("q", [1.0, 37.0, 500.0, 12000.0])
def test_load_deflection_constant(q):
    c = hertz.point_contact_exact(q, 2.9e-3, 0.11, 2.28e11)
    assert c.load == q
    assert c.stiffness_constant * c.approach**1.5 == pytest.approx(q, rel=1e-12)


def test_max_pressure_definition_and_load_scaling():
    c1 = hertz.point_contact_exact(100.0, 2.9e-3, 0.11, 2.28e11)
    c8 = hertz.point_contact_exact(800.0, 2.9e-3, 0.11, 2.28e11)
    assert c1.max_pressure == pytest.approx(3 * 100.0 / (2 * math.pi * c1.a * c1.b), rel=1e-14)
    # Hertz: a, b ∝ Q^(1/3), δ ∝ Q^(2/3), p ∝ Q^(1/3); κ and K independent of Q
    assert c8.a / c1.a == pytest.approx(2.0, rel=1e-12)
    assert c8.b / c1.b == pytest.approx(2.0, rel=1e-12)
    assert c8.approach / c1.approach == pytest.approx(4.0, rel=1e-12)
    assert c8.max_pressure / c1.max_pressure == pytest.approx(2.0, rel=1e-12)
    assert c8.kappa == c1.kappa and c8.stiffness_constant == pytest.approx(c1.stiffness_constant, rel=1e-14)


def test_zero_load_gives_zero_contact_but_finite_constant():
    c = hertz.point_contact_exact(0.0, 2.9e-3, 0.11, 2.28e11)
    assert c.a == 0.0 and c.b == 0.0 and c.approach == 0.0 and c.max_pressure == 0.0
    assert c.stiffness_constant > 0.0


def test_semi_axis_contains_pi_e_term():
    """Trap (physics-notes): a written without the πE′ term.  Doubling E′ shrinks a by 2^(1/3)."""
    c1 = hertz.point_contact_exact(300.0, 3e-3, 40e-3, 1e11)
    c2 = hertz.point_contact_exact(300.0, 3e-3, 40e-3, 2e11)
    assert c1.a / c2.a == pytest.approx(2 ** (1 / 3), rel=1e-13)
    assert c1.b / c2.b == pytest.approx(2 ** (1 / 3), rel=1e-13)
    assert c2.stiffness_constant / c1.stiffness_constant == pytest.approx(2.0, rel=1e-13)


@pytest.mark.parametrize("q, rx, ry, e, field", [
    (-1.0, 3e-3, 4e-2, 2e11, "load"),
    (float("nan"), 3e-3, 4e-2, 2e11, "load"),
    (1.0, 0.0, 4e-2, 2e11, "rx"),
    (1.0, 3e-3, -4e-2, 2e11, "ry"),
    (1.0, 3e-3, 4e-2, 0.0, "effective_modulus"),
])
def test_bad_contact_input(q, rx, ry, e, field):
    with pytest.raises(InputError) as info:
        hertz.point_contact_exact(q, rx, ry, e)
    assert info.value.field == field and info.value.fix


# --- effective modulus and raceway radii (physics-notes traps) -------------------------------------
def test_effective_modulus_definition():
    """E′ = 2/[(1−ν₁²)/E₁ + (1−ν₂²)/E₂] (Hamrock's E′), not E/(1−ν²) of one body."""
    same = hertz.effective_modulus(E_STEEL, NU_STEEL, E_STEEL, NU_STEEL)
    assert same == pytest.approx(E_STEEL / (1 - NU_STEEL**2), rel=1e-15)
    hyb = hertz.effective_modulus(E_SIN, NU_SIN, E_STEEL, NU_STEEL)
    by_hand = 2.0 / ((1 - 0.26**2) / 310e9 + (1 - 0.30**2) / 208e9)
    assert hyb == pytest.approx(by_hand, rel=1e-15)
    assert hyb == pytest.approx(2.7090e11, rel=1e-4)  # 2/(3.00774e-12 + 4.37500e-12)
    # symmetric in the two bodies
    assert hertz.effective_modulus(E_STEEL, NU_STEEL, E_SIN, NU_SIN) == pytest.approx(hyb, rel=1e-15)


def test_hybrid_bearing_uses_both_moduli(b7011):
    """Trap: a hybrid bearing must combine ball (Si₃N₄) and ring (steel) properties."""
    bm, rm = b7011.ball_material, b7011.ring_material
    assert bm.youngs_modulus != rm.youngs_modulus
    expected = 2.0 / ((1 - bm.poisson_ratio**2) / bm.youngs_modulus + (1 - rm.poisson_ratio**2) / rm.youngs_modulus)
    assert b7011.effective_modulus == pytest.approx(expected, rel=1e-15)
    assert b7011.effective_modulus != pytest.approx(rm.youngs_modulus / (1 - rm.poisson_ratio**2), rel=1e-3)
    assert b7011.effective_modulus != pytest.approx(bm.youngs_modulus / (1 - bm.poisson_ratio**2), rel=1e-3)


@pytest.mark.parametrize("alpha_deg", [0.0, 15.0, 40.0])
def test_raceway_radii_by_hand(alpha_deg):
    """Rx = D(1∓γ)/2 (inner −, outer +), Ry = fD/(2f−1), γ = D cos α / d_m (Harris & Kotzalas 2007 ch. 2)."""
    d, dm, fi, fo = 10.319e-3, 72.5e-3, 0.52, 0.53
    a = math.radians(alpha_deg)
    g = d * math.cos(a) / dm
    rxi, ryi = hertz.raceway_radii(d, dm, fi, a, True)
    rxo, ryo = hertz.raceway_radii(d, dm, fo, a, False)
    assert rxi == pytest.approx(d * (1 - g) / 2, rel=1e-13)
    assert rxo == pytest.approx(d * (1 + g) / 2, rel=1e-13)
    assert ryi == pytest.approx(fi * d / (2 * fi - 1), rel=1e-13)
    assert ryo == pytest.approx(fo * d / (2 * fo - 1), rel=1e-13)


def test_outer_race_radii_not_swapped(b7011, b218, bhub):
    """Trap: Rx/Ry swapped in the outer-race branch gives κ < 1.  Both contacts must have κ > 1."""
    for b in (b7011, b218, bhub):
        for inner in (True, False):
            rx, ry = b.raceway_radii(inner)
            assert ry > rx
            c = b.contact(100.0, inner)
            assert c.kappa > 1.0
            assert c.a > c.b


def test_inner_and_outer_contacts_use_their_own_integrals(b7011):
    """Trap: the outer 𝓔 reused for the inner contact.  Each contact is solved for its own radii."""
    ci = b7011.contact(200.0, True)
    co = b7011.contact(200.0, False)
    assert ci.kappa != pytest.approx(co.kappa, rel=1e-3)
    for c, inner in ((ci, True), (co, False)):
        rx, ry = b7011.raceway_radii(inner)
        ref = ref_contact(200.0, rx, ry, b7011.effective_modulus)
        assert c.ell_e == pytest.approx(ref["ell_e"], rel=1e-12)
        assert c.ell_k == pytest.approx(ref["ell_k"], rel=1e-12)
        assert c.approach == pytest.approx(ref["approach"], rel=1e-10)


def test_series_constant():
    """Kn = [(1/Ki)^(2/3) + (1/Ko)^(2/3)]^(−3/2): the approaches of two contacts in series add."""
    ki, ko, q = 9.1e9, 1.07e10, 250.0
    kn = hertz.series_constant(ki, ko)
    d_total = (q / ki) ** (2 / 3) + (q / ko) ** (2 / 3)
    assert kn * d_total**1.5 == pytest.approx(q, rel=1e-13)
    assert hertz.series_constant(ki, ki) == pytest.approx(ki / 2**1.5, rel=1e-14)
