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


@settings(max_examples=100, deadline=None)
@given(delta=st.floats(1e-7, 3e-5), ddot=st.floats(-0.5, 0.5), spin=st.floats(-500.0, 500.0))
def test_contact_ellipse_is_sized_by_the_cube_root_of_its_own_load(delta, ddot, spin):
    """race_contact (Coulomb stand-in, spinning ball) sizes its ellipse a = a_c Q^(1/3) with the load Q it returns:
    its traction equals coulomb_on_slices called with a = a_c Q^(1/3), Q^(1/3) taken by pow, within 1e-12 — whatever
    K^(1/3) δ^(1/2) (1 + 1.5 α δ̇)^(1/3) route the contact takes inside (Hertz: a ∝ Q^(1/3), Johnson 1985 §4.2)."""
    kc, rgroove, half_d, alpha = 8.0e9, 0.2e-3, 6.0e-3, 0.05
    a_c, b_c, r_dev, nsl = 1e-4, 1e-5, 10e-3, 8
    u = np.array([0.3, -0.4, np.sqrt(1 - 0.25)])
    g = np.array([1e-3, 30e-3, 2e-3])
    b = g + (rgroove + delta) * u
    tang = np.array([0.0, 0.0, 1.0]) - u[2] * u
    tang /= np.linalg.norm(tang)
    v = ddot * u + 0.3 * tang  # approach and sliding
    w = spin * u + 20.0 * np.cross(u, tang)  # spin about the normal and rolling
    c = np.array([0.5e-3, 0.0, 0.0])
    gp = np.zeros(ly.NGP)
    gp[ly.G_TRAC], gp[ly.G_MU0], gp[ly.G_S0], gp[ly.G_NSL], gp[ly.G_VREF] = 1.0, 0.1, 0.01, nsl, 1e-3
    fb, mb, fr, mr = (np.zeros(3) for _ in range(4))
    res, tbuf = np.zeros(8), np.zeros(44 + 2 * nsl)
    ct.slice_table(nsl, tbuf[44:])
    z3 = np.zeros(3)
    ct.race_contact(b, v, w, g, z3, 0.0, c, z3, z3, kc, rgroove, half_d, alpha, np.zeros(slices.L_SIZE), gp, a_c,
                    b_c, r_dev, tang, fb, mb, fr, mr, res, tbuf)
    q, dl, un = res[0], res[1], res[2:5]
    if not q > 0.0:
        return
    centre = b + (half_d - 0.5 * dl) * un
    table = np.zeros(2 * nsl)
    ct.slice_table(nsl, table)
    want = np.zeros(10)
    ct.coulomb_on_slices(q, a_c * q ** (1.0 / 3.0), r_dev, centre, -un, np.cross(un, tang), b, v, w, c, z3, z3,
                         gp[ly.G_MU0], gp[ly.G_S0], gp[ly.G_VREF], nsl, table, want)
    np.testing.assert_allclose(tbuf[0:10], want, rtol=1e-12, atol=1e-12 * q * half_d,
                               err_msg="ellipse semi-axis a = a_c Q^(1/3) (Hertz, Johnson 1985 §4.2)")
