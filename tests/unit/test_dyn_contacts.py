"""dynamics.contacts: the contact laws moved out of dynamics.forces (issue 12 item 4).

Mechanism tests: the former names of forces are the contact module's kernels (scripts keep working and
rhs uses the same compiled functions), and one ball–raceway contact obeys the Hunt–Crossley Hertz law it
documents — Q = K δ^1.5 (1 + 3/2 α δ̇) along u = (b − g)/|b − g|, −Q u on the ball, +Q u on the ring with
moment (g − c) × Q u about the ring point c, no moment on the ball without traction.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.contact import slices
from bearingsim.dynamics import contacts as ct
from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly


def test_forces_keeps_the_contact_names():
    for name in ("race_contact", "coulomb_slices", "coulomb_on_slices", "slice_table", "pocket_point"):
        assert getattr(fo, name) is getattr(ct, name), name
    assert fo._cross is ct.cross


def _contact(delta, ddot, alpha):
    kc, rgroove, half_d = 8.0e9, 0.2e-3, 6.0e-3  # [N/m^1.5], (f - 1/2) D [m], D/2 [m]
    u = np.array([0.3, -0.4, np.sqrt(1 - 0.25)])
    g = np.array([1e-3, 30e-3, 2e-3])
    b = g + (rgroove + delta) * u
    v = ddot * u  # approach rate along u (the groove centre at rest)
    c = np.array([0.5e-3, 0.0, 0.0])
    gp = np.zeros(ly.NGP)
    gp[ly.G_TRAC] = 0.0
    fb, mb, fr, mr = (np.zeros(3) for _ in range(4))
    res, tbuf = np.zeros(8), np.zeros(44)
    ct.race_contact(b, v, np.zeros(3), g, np.zeros(3), 0.0, c, np.zeros(3), np.zeros(3), kc, rgroove, half_d,
                    alpha, np.zeros(slices.L_SIZE), gp, 1e-4, 1e-5, 10e-3, np.array([0.0, 0.0, 1.0]), fb, mb, fr,
                    mr, res, tbuf)
    return kc, u, g, c, fb, mb, fr, mr, res


def test_race_contact_is_the_hunt_crossley_hertz_law():
    delta, ddot, alpha = 5e-6, 0.02, 0.1  # [m], [m/s], [s/m]
    kc, u, g, c, fb, mb, fr, mr, res = _contact(delta, ddot, alpha)
    q = kc * delta ** 1.5 * (1 + 1.5 * alpha * ddot)
    assert math.isclose(res[0], q, rel_tol=1e-12)
    assert math.isclose(res[1], delta, rel_tol=1e-9)  # the approach, recovered from |b - g|
    np.testing.assert_allclose(fb, -q * u, rtol=1e-12, atol=1e-12 * q)
    np.testing.assert_allclose(fr, q * u, rtol=1e-12, atol=1e-12 * q)
    np.testing.assert_array_equal(mb, 0.0)  # through the ball centre, no traction model
    np.testing.assert_allclose(mr, np.cross(g - c, q * u), rtol=1e-12, atol=1e-12 * q * 1e-3)
    assert res[6] == 0.0  # no power loss without traction


def test_race_contact_carries_no_tension():
    _, _, _, _, fb, _, _, _, res = _contact(-1e-6, 0.0, 0.1)  # a gap
    assert res[0] == 0.0 and np.all(fb == 0.0)
    _, _, _, _, fb, _, _, _, res = _contact(1e-6, -20.0, 0.1)  # separating fast: 1 + 3/2 α δ̇ < 0
    assert res[0] == 0.0 and np.all(fb == 0.0)


def _decimal_cbrt(x) -> float:
    """x^(1/3) to 40 digits (decimal arithmetic), then rounded to a float: the reference of the tests below."""
    from decimal import Decimal, localcontext

    with localcontext() as ctx:
        ctx.prec = 40
        return float(Decimal(x) ** (Decimal(1) / Decimal(3)))


@settings(max_examples=300, deadline=None)
@given(d=st.one_of(st.floats(-1e-3, 1e-3), st.floats(-0.999, 50.0)))
def test_cube_root_of_the_damping_factor_is_correct_to_rounding(d):
    """contacts._cbrt_1p(d) = (1 + d)^(1/3) (binomial series, Abramowitz & Stegun 3.6.8, where |d| ≤ 1e-3; the cube
    root elsewhere) within 2 ulp of the decimal reference — the series is truncated below rounding."""
    from decimal import Decimal

    want = _decimal_cbrt(Decimal(1) + Decimal(d))
    got = ct._cbrt_1p(d)
    assert abs(got - want) <= 2 * np.spacing(want), (d, got, want)


@settings(max_examples=200, deadline=None)
@given(delta=st.floats(1e-9, 5e-5), ddot=st.floats(-1.0, 1.0), kc=st.floats(1e9, 5e10))
def test_contact_load_cube_root_without_pow(delta, ddot, kc):
    """Q^(1/3) as race_contact_at forms it, K^(1/3) δ^(1/2) (1 + 1.5 α δ̇)^(1/3) with K^(1/3) from Model.rowx, equals
    the cube root of the Hertz–Hunt–Crossley load Q = K δ^1.5 (1 + 1.5 α δ̇) (Hunt & Crossley 1975) to a few ulp
    (the ellipse's semi-axes are a = a_c Q^(1/3): they must not depend on how the root is taken)."""
    from decimal import Decimal

    alpha = 0.05
    damp = 1.5 * alpha * ddot
    q = Decimal(kc) * Decimal(delta) ** Decimal("1.5") * (Decimal(1) + Decimal(damp))
    want = _decimal_cbrt(q)
    got = float(np.cbrt(kc)) * math.sqrt(delta) * ct._cbrt_1p(damp)
    assert abs(got - want) <= 6 * np.spacing(want), (got, want)
