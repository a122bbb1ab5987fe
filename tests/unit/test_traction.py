"""Unit tests of the traction models (four-parameter curve, mixed interpolation, fluid model, rolling resistance)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, optimize

from bearingsim.contact import traction as T
from bearingsim.errors import InputError


@pytest.mark.parametrize("mu0, mu_max, s_max, mu_inf", [(0.0, 0.12, 0.01, 0.10), (0.0, 0.06, 0.005, 0.04),
                                                         (0.05, 0.12, 0.02, 0.08), (0.02, 0.07, 0.01, 0.02),
                                                         (0.09, 0.1, 0.015, 0.03)])
def test_four_parameter_fit_reproduces_its_data(mu0, mu_max, s_max, mu_inf):
    c = T.fit_four_parameter(mu0, mu_max, s_max, mu_inf)
    assert T.four_parameter(0.0, *c) == pytest.approx(mu0, abs=1e-12)
    assert T.four_parameter(s_max, *c) == pytest.approx(mu_max, abs=1e-12)
    assert T.four_parameter(1e6, *c) == pytest.approx(mu_inf, abs=1e-12)
    # s_max is the maximum: the derivative vanishes there and neighbours are lower
    h = 1e-7
    d = (T.four_parameter(s_max + h, *c) - T.four_parameter(s_max - h, *c)) / (2 * h)
    assert abs(d) < 1e-6
    s = np.linspace(0, 20 * s_max, 20001)
    assert np.max(T.traction_curve(s, c)) <= mu_max + 1e-12


def test_default_boundary_curve_coefficients():
    """The default boundary curve (0, 0.12 at 0.01, 0.10) is μ = (−0.1 + 22.28 s)e^(−181.46 s) + 0.1."""
    A, B, C, D = T.fit_four_parameter(0.0, 0.12, 0.01, 0.10)
    assert (A, D) == (pytest.approx(-0.1), pytest.approx(0.1))
    assert B == pytest.approx(22.2767, rel=1e-5)
    assert C == pytest.approx(181.455, rel=1e-5)


def test_four_parameter_fit_rejects_curves_without_peak():
    with pytest.raises(InputError):
        T.fit_four_parameter(0.0, 0.05, 0.01, 0.06)
    with pytest.raises(InputError):
        T.fit_four_parameter(0.0, 0.05, 0.0, 0.04)
    with pytest.raises(InputError):
        T.fit_four_parameter(float("nan"), 0.05, 0.01, 0.04)


def test_mixed_interpolation_continuous_in_lambda():
    mb, mf = 0.1, 0.04
    for l1, l2 in ((1.0, 3.0), (0.5, 1.5)):
        for lam in (l1, l2):
            lo = T.mixed_coefficient(mb, mf, lam - 1e-9, l1, l2)
            hi = T.mixed_coefficient(mb, mf, lam + 1e-9, l1, l2)
            assert abs(hi - lo) < 1e-9
        assert T.mixed_coefficient(mb, mf, 0.0, l1, l2) == mb
        assert T.mixed_coefficient(mb, mf, 100.0, l1, l2) == mf
        lam = np.linspace(0, 5, 501)
        mu = np.array([T.mixed_coefficient(mb, mf, x, l1, l2) for x in lam])
        assert np.all(np.diff(mu) <= 1e-15)  # monotone from boundary to fluid
        assert np.max(np.abs(np.diff(mu))) <= (mb - mf) / (l2 - l1) * 0.01 + 1e-12  # Lipschitz: no jump
    with pytest.raises(InputError):
        T.mixed_coefficient(mb, mf, float("nan"))


def test_martin_rolling_resistance_against_numerical_reynolds():
    """IR rolling resistance closed form vs a numerical rigid isoviscous Reynolds solution (Martin problem).

    Dimensionless: h = h0(1+ξ²), x = √(2Rh0) ξ, dp/dξ ∝ (ξ² − ξe²)/(1+ξ²)³, p(−∞) = p(ξe) = 0.
    """
    def p_of(xi, xe):
        val, _ = integrate.quad(lambda t: (t * t - xe * xe) / (1 + t * t) ** 3, -np.inf, xi, epsabs=1e-14)
        return val

    xe = optimize.brentq(lambda z: p_of(z, z), 0.2, 0.8, xtol=1e-14)
    assert xe == pytest.approx(T.MARTIN_XI_EXIT, abs=1e-6)
    # with eta = u = R = h0 = 1 (u mean speed): dp/dξ = 12 √2 (ξ²−ξe²)/(1+ξ²)³, dx = √2 dξ
    k = 12 * math.sqrt(2.0)
    load, _ = integrate.quad(lambda z: k * p_of(z, xe) * math.sqrt(2.0), -np.inf, xe, epsabs=1e-12, limit=200)
    assert load == pytest.approx(T.MARTIN_LOAD, rel=1e-4)
    # Crook: F_r0 = 1/2 ∫ h dp/dx dx = 1/2 ∫ h dp/dξ dξ
    fr, _ = integrate.quad(lambda z: 0.5 * (1 + z * z) * k * (z * z - xe * xe) / (1 + z * z) ** 3, -np.inf, xe,
                           epsabs=1e-13)
    assert fr / math.sqrt(load) == pytest.approx(T.MARTIN_ROLLING, rel=1e-4)


def test_rolling_resistance_scaling_and_regimes():
    kw = dict(eta0=0.03, alpha=2e-8, e_eff=2.3e11, rx=0.004, length=1e-4)
    f1 = T.rolling_resistance("PE", u=2.0, load=100.0, **kw)
    f2 = T.rolling_resistance("PE", u=4.0, load=100.0, **kw)
    f3 = T.rolling_resistance("PE", u=2.0, load=200.0, **kw)
    assert f2 / f1 == pytest.approx(2**0.648, rel=1e-12)
    assert f3 / f1 == pytest.approx(2**0.246, rel=1e-12)
    assert T.rolling_resistance("PE", u=2.0, load=100.0, thermal_factor=0.8, starvation_factor=0.5, **kw) == \
        pytest.approx(0.4 * f1, rel=1e-12)
    g1 = T.rolling_resistance("IR", u=2.0, load=100.0, **kw)
    assert T.rolling_resistance("IR", u=8.0, load=100.0, **kw) == pytest.approx(2 * g1, rel=1e-12)
    with pytest.raises(InputError):
        T.rolling_resistance("XX", u=2.0, load=100.0, **kw)
    with pytest.raises(InputError):
        T.rolling_resistance("PE", u=-1.0, load=100.0, **kw)
    with pytest.raises(InputError, match="viscosity"):
        T.rolling_resistance("PE", u=1.0, load=100.0, **{**kw, "eta0": -0.01})


def _tau(s, u=5.0, p=1.2e9, h=2e-7, theta=3e-7, t0c=60.0):
    eta_p = T.roelands_viscosity(p, 0.024, math.log(0.024) + 9.67, 0.69)
    return T.fluid_shear_stress(p, s * u, h, theta, eta_p, 5e6, t0c, 0.25, 1.2, 2.52, 0.024, 1e8, 0.02, 0.038)


def test_fluid_model_limits():
    p = 1.2e9
    assert _tau(0.0) == 0.0
    tl = T.limiting_shear_stress(p, 60.0, 0.25, 1.2, 2.52, 0.024, 1e8, 0.02)
    assert tl == pytest.approx(0.25 * (1.2 * p / (2.52 + 0.024 * 60) - 1e8))  # Dyson, Zhou & Hoeprich eqs. 36-37
    s = np.array([1e-6, 1e-5, 1e-4, 1e-3, 1e-2])
    iso = np.array([_tau(x, theta=0.0) for x in s])
    assert np.all(np.diff(iso) > 0) and np.all(iso < tl)
    # heating lowers the stress, more at larger sliding
    hot = np.array([_tau(x) for x in s])
    assert np.all(hot <= iso)
    assert (iso[-1] - hot[-1]) / iso[-1] > (iso[0] - hot[0]) / iso[0]
    # low pressure floor
    assert T.limiting_shear_stress(1e7, 60.0, 0.25, 1.2, 2.52, 0.024, 1e8, 0.02) == pytest.approx(0.02 * 1e7)


def test_roelands_matches_barus_slope_at_zero_pressure():
    eta0, z = 0.024, 0.69
    ln = math.log(eta0) + 9.67
    dp = 1e3
    slope = (math.log(T.roelands_viscosity(dp, eta0, ln, z)) - math.log(eta0)) / dp
    assert slope == pytest.approx(ln * z / 1.96e8, rel=1e-4)


@pytest.mark.parametrize("ratio", [0.01, 0.5, 0.999, 1.0, 1.001, 2.0, 30.0, 1e4])
def test_elastic_plastic_mean_stress_is_the_transit_mean(ratio):
    """Johnson & Tevaarwerk (1977) elastic/plastic film: mean over the transit of min(τ_e t/t_c, τ_y)."""
    tau_y = 3.0e7
    tau_e = ratio * tau_y
    ref, _ = integrate.quad(lambda x: min(tau_e * x, tau_y), 0.0, 1.0, points=[min(1.0, 1.0 / ratio)],
                            epsabs=1e-6, epsrel=1e-13)
    assert T.elastic_plastic_mean_stress(tau_y, tau_e) == pytest.approx(ref, rel=1e-12), "transit mean (closed form)"


def test_elastic_plastic_mean_stress_limits_and_smoothness():
    tau_y = 2.0e7
    # linear elastic limit τ_e/2 and viscous (plastic) limit τ_y
    assert T.elastic_plastic_mean_stress(tau_y, 1e3) == 0.5e3
    assert T.elastic_plastic_mean_stress(tau_y, 1e6 * tau_y) == pytest.approx(tau_y, rel=1e-6)
    # value and slope continuous at τ_e = τ_y (slope 1/2 on both sides)
    h = 1e-6 * tau_y
    f = lambda x: T.elastic_plastic_mean_stress(tau_y, x)  # noqa: E731
    assert (f(tau_y + h) - f(tau_y)) / h == pytest.approx(0.5, rel=1e-5)
    assert (f(tau_y) - f(tau_y - h)) / h == pytest.approx(0.5, rel=1e-12)
    # monotone in τ_e and never above τ_y
    x = np.geomspace(1e-3, 1e3, 200) * tau_y
    y = np.array([f(v) for v in x])
    assert np.all(np.diff(y) > 0) and np.all(y < tau_y)
