"""Pure thrust load without inertia (bearingsim.statics.axial) — seed 000 section 2.1.

Equations rewritten here by hand (Harris & Kotzalas 2007 vol. 1 ch. 7; seed 000 eqs. 3–6):
A = (f_i + f_o − 1) D;  Fa = Z K_n A^1.5 sin α (cos α₀/cos α − 1)^1.5;
δa = A sin(α − α₀)/cos α = A (tan α cos α₀ − sin α₀), so α(δa) is explicit:
tan α = (δa/A + sin α₀)/cos α₀ — which gives Fa(δa) without any solver, for the finite
difference of Ca = dFa/dδa.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from bearingsim.errors import InputError
from bearingsim.geometry import BallBearing
from bearingsim.materials import LIBRARY
from bearingsim.statics import axial

LOADS = [1.0, 100.0, 1000.0, 2000.0, 3000.0, 4000.0, 5000.0, 20000.0]


def params(b):
    return b.free_contact_angle, b.ball_count, b.contact_constants[2], b.total_curvature_distance


def fa_of_alpha(alpha, a0, z, kn, big_a):
    return z * kn * big_a**1.5 * math.sin(alpha) * (math.cos(a0) / math.cos(alpha) - 1.0) ** 1.5


def fa_of_delta(da, a0, z, kn, big_a):
    alpha = math.atan((da / big_a + math.sin(a0)) / math.cos(a0))
    return fa_of_alpha(alpha, a0, z, kn, big_a)


@pytest.mark.parametrize("fa", LOADS)
def test_fixed_point_and_bracketed_agree(b7011, b218, bhub, fa):
    for b in (b7011, b218, bhub):
        fp = axial.solve_thrust(b, fa, method="fixed_point")
        br = axial.solve_thrust(b, fa, method="bracketed")
        assert fp.converged and br.converged
        assert fp.contact_angle == pytest.approx(br.contact_angle, rel=1e-10, abs=0)
        assert fp.axial_deflection == pytest.approx(br.axial_deflection, rel=1e-9)
        assert fp.axial_stiffness == pytest.approx(br.axial_stiffness, rel=1e-9)


@pytest.mark.parametrize("fa", LOADS)
def test_load_of_angle_round_trip(b7011, fa):
    a0, z, kn, big_a = params(b7011)
    s = axial.solve_thrust(b7011, fa)
    assert s.contact_angle > a0
    assert fa_of_alpha(s.contact_angle, a0, z, kn, big_a) == pytest.approx(fa, rel=1e-11)
    assert axial.thrust_load_of_angle(s.contact_angle, a0, z, kn, big_a) == pytest.approx(fa, rel=1e-11)
    # ball load and normal approach: Q = Fa/(Z sin α) = K_n δn^1.5
    assert s.ball_load == pytest.approx(fa / (z * math.sin(s.contact_angle)), rel=1e-14)
    assert kn * s.normal_approach**1.5 == pytest.approx(s.ball_load, rel=1e-10)


@pytest.mark.parametrize("fa", [500.0, 3000.0])
def test_deflection_geometry(b7011, fa):
    """The inner groove centre moves axially by δa: (A sin α₀ + δa)² + (A cos α₀)² = (A + δn)²."""
    a0, _, _, big_a = params(b7011)
    s = axial.solve_thrust(b7011, fa)
    lhs = math.hypot(big_a * math.sin(a0) + s.axial_deflection, big_a * math.cos(a0))
    assert lhs == pytest.approx(big_a + s.normal_approach, rel=1e-13)
    assert math.atan2(big_a * math.sin(a0) + s.axial_deflection, big_a * math.cos(a0)) == pytest.approx(
        s.contact_angle, rel=1e-13)


@pytest.mark.parametrize("fa", LOADS)
def test_closed_form_stiffness_equals_finite_difference(b7011, b218, fa):
    for b in (b7011, b218):
        a0, z, kn, big_a = params(b)
        s = axial.solve_thrust(b, fa)
        h = 1e-4 * s.axial_deflection
        fd = (fa_of_delta(s.axial_deflection + h, a0, z, kn, big_a)
              - fa_of_delta(s.axial_deflection - h, a0, z, kn, big_a)) / (2 * h)
        assert s.axial_stiffness == pytest.approx(fd, rel=1e-6)


def test_zero_load(b7011):
    s = axial.solve_thrust(b7011, 0.0)
    assert s.contact_angle == b7011.free_contact_angle
    assert s.axial_deflection == 0.0 and s.ball_load == 0.0


def test_stiffness_increases_with_load(b7011):
    ca = [axial.solve_thrust(b7011, fa).axial_stiffness for fa in LOADS]
    assert all(c2 > c1 for c1, c2 in zip(ca, ca[1:]))


@pytest.mark.parametrize("fa, method, field", [(-1.0, "bracketed", "fa"), (float("nan"), "bracketed", "fa"),
                                                (100.0, "newton", "method")])
def test_bad_input(b7011, fa, method, field):
    with pytest.raises(InputError) as info:
        axial.solve_thrust(b7011, fa, method=method)
    assert info.value.field == field and info.value.fix


# ---- Palmgren -------------------------------------------------------------------------------
@pytest.mark.parametrize("fa, z, dw_mm, alpha_deg", [(1000.0, 21, 10.319, 15.0), (5000.0, 21, 10.319, 17.5),
                                                     (2000.0, 16, 22.23, 40.0)])
def test_palmgren_by_hand_in_mm(fa, z, dw_mm, alpha_deg):
    """δa [mm] = 4.4e-4 / sin α · (Q²/D_w)^(1/3), Q = Fa/(Z sin α) [N], D_w [mm] (NSK catalogue form)."""
    s = math.sin(math.radians(alpha_deg))
    q = fa / (z * s)
    da_mm = 4.4e-4 / s * (q * q / dw_mm) ** (1.0 / 3.0)
    got = axial.palmgren_axial_deflection(fa, z, dw_mm * 1e-3, math.radians(alpha_deg))
    assert got == pytest.approx(da_mm * 1e-3, rel=1e-13)
    if (fa, z, dw_mm, alpha_deg) == (1000.0, 21, 10.319, 15.0):
        # Q = 183.99 N, (Q²/Dw)^(1/3) = 14.858, δa = 0.025260 mm (by hand)
        assert got == pytest.approx(2.5260e-5, rel=2e-4)
    # Ca = dFa/dδa at constant α: δa ∝ Fa^(2/3) gives 1.5 Fa/δa; check by central difference
    ca = axial.palmgren_axial_stiffness(fa, z, dw_mm * 1e-3, math.radians(alpha_deg))
    h = 1e-4 * fa
    dd = (axial.palmgren_axial_deflection(fa + h, z, dw_mm * 1e-3, math.radians(alpha_deg))
          - axial.palmgren_axial_deflection(fa - h, z, dw_mm * 1e-3, math.radians(alpha_deg)))
    assert ca == pytest.approx(2 * h / dd, rel=1e-7)


# ---- property tests ---------------------------------------------------------------------------
@st.composite
def bearings(draw):
    d = draw(st.floats(3e-3, 30e-3))
    dm = d * draw(st.floats(3.0, 12.0))
    zmax = int(math.pi / math.asin(d / dm))
    z = draw(st.integers(6, max(6, zmax - 1)))
    if dm * math.sin(math.pi / z) <= d:
        z = zmax - 1
    fi = draw(st.floats(0.505, 0.58))
    fo = draw(st.floats(0.505, 0.60))
    a0 = math.radians(draw(st.floats(5.0, 45.0)))
    ball = draw(st.sampled_from(["bearing_steel", "silicon_nitride"]))
    return BallBearing("prop", "angular_contact", d, z, dm, fi, fo, a0, LIBRARY[ball], LIBRARY["bearing_steel"])


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(b=bearings(), load_factor=st.floats(1e-4, 0.3))
def test_bracketed_always_converges(b, load_factor):
    """Loads up to ~ Z K_n A^1.5 · 0.3 (far beyond any real load): the bracketed solver converges,
    satisfies the load equation, and the fixed point either agrees or says it did not converge."""
    a0, z, kn, big_a = params(b)
    fa = load_factor * z * kn * big_a**1.5
    br = axial.solve_thrust(b, fa, method="bracketed")
    assert br.converged
    assert a0 < br.contact_angle < math.pi / 2
    assert fa_of_alpha(br.contact_angle, a0, z, kn, big_a) == pytest.approx(fa, rel=1e-9)
    assert br.axial_stiffness > 0
    fp = axial.solve_thrust(b, fa, method="fixed_point")
    if fp.converged:
        assert fp.contact_angle == pytest.approx(br.contact_angle, rel=1e-9)


@settings(max_examples=30, deadline=None)
@given(b=bearings(), f1=st.floats(1.0, 5e4), f2=st.floats(1.0, 5e4))
def test_monotonic_in_load(b, f1, f2):
    lo, hi = sorted((f1, f2))
    if hi - lo < 1e-6 * hi:
        return
    s1, s2 = axial.solve_thrust(b, lo), axial.solve_thrust(b, hi)
    assert s2.contact_angle > s1.contact_angle
    assert s2.axial_deflection > s1.axial_deflection
    assert s2.axial_stiffness > s1.axial_stiffness
