"""Cage land, cage pocket and jet momentum losses (bearingsim.friction, module docstring item 3) and the thermal
correlations (bearingsim.thermal.correlations): closed forms and bad input."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim import friction as F
from bearingsim.errors import InputError
from bearingsim.thermal import correlations as C


@given(eta=st.floats(1e-4, 1.0), w=st.floats(1.0, 5000.0), d=st.floats(0.01, 0.3), c=st.floats(1e-5, 1e-3))
@settings(max_examples=50, deadline=None)
def test_land_torque_is_petroff(eta, w, d, c):
    """Couette shear τ = η ω r / c over the area π d w_L, lever r: M = τ π d w_L d/2."""
    land = F.CageLand(diameter=d, width=0.1 * d, clearance=c)
    tau = eta * w * (d / 2) / c
    assert F.cage_land_torque(land, w, eta) == pytest.approx(tau * math.pi * d * 0.1 * d * d / 2, rel=1e-12)


def test_pocket_power_from_cage_balance():
    """Z balls carry the land torque at d_m/2: Σ Q_p d_m/2 = M_L; power μ Σ Q_p |ω_R| D/2."""
    m_l, z, dm, dw, wr = 0.02, 16, 0.0465, 0.00714, 9000.0
    p = F.cage_pocket_power(m_l, z, dm, dw, wr, friction=0.06)
    assert p == pytest.approx(0.06 * (2 * m_l / dm) * wr * dw / 2, rel=1e-12)


def test_jet_momentum_power():
    assert F.jet_momentum_power(1e-5, 900.0, 3000.0, 0.05) == pytest.approx(900 * 1e-5 * (3000 * 0.025) ** 2,
                                                                         rel=1e-12)
    with pytest.raises(InputError, match="oil_flow"):
        F.jet_momentum_power(-1e-5, 900.0, 3000.0, 0.05)


@pytest.mark.parametrize("kw, field", [(dict(diameter=-0.05, width=0.01, clearance=1e-4), "cage.diameter"),
                                       (dict(diameter=0.05, width=0.0, clearance=1e-4), "cage.width"),
                                       (dict(diameter=0.05, width=0.01, clearance=1e-4, guidance="x"),
                                        "cage.guidance")])
def test_cage_land_bad_input(kw, field):
    with pytest.raises(InputError, match=field):
        F.CageLand(**kw)


def test_contact_conductance_closed_form():
    """Two half-spaces of k₁, k₂ on a circle of radius a: G = 4a / (1/k₁ + 1/k₂) (Holm)."""
    a = 2e-4
    assert C.contact_conductance(a, a, 43.0, 30.0) == pytest.approx(4 * a / (1 / 43 + 1 / 30), rel=1e-12)


def test_flat_plate_laminar_and_mixed():
    rho, mu, k, cp = 1.16, 1.85e-5, 0.0263, 1007.0  # air at 300 K (Incropera table A.4)
    pr = cp * mu / k
    h = C.flat_plate_convection(10.0, 0.1, rho, mu, k, cp)
    re = rho * 10 * 0.1 / mu
    assert h == pytest.approx(0.664 * re**0.5 * pr ** (1 / 3) * k / 0.1, rel=1e-12)
    h2 = C.flat_plate_convection(100.0, 1.0, rho, mu, k, cp)
    re2 = rho * 100.0 / mu
    assert h2 == pytest.approx((0.037 * re2**0.8 - 871) * pr ** (1 / 3) * k, rel=1e-12)


def test_natural_convection_cylinder_limits():
    """Churchill & Chu: Nu → 0.60² = 0.36 as Ra → 0 (conduction limit); h grows with ΔT (Ra^(1/6) term)."""
    d = 0.1
    _, _, k, _ = C.air_properties(300.0)
    small = 1e-4
    assert C.natural_convection_cylinder(small, 300.0 + 1e-9, 300.0 - 1e-9) == pytest.approx(0.36 * k / small,
                                                                                        rel=1e-2)
    hs = [C.natural_convection_cylinder(d, 300.0 + dt, 300.0) for dt in (1.0, 10.0, 100.0)]
    assert hs[0] < hs[1] < hs[2]
