"""dynamics.contacts: the contact laws moved out of dynamics.forces (issue 12 item 4).

Mechanism tests: the former names of forces are the contact module's kernels (scripts keep working and
rhs uses the same compiled functions), and one ball–raceway contact obeys the Hunt–Crossley Hertz law it
documents — Q = K δ^1.5 (1 + 3/2 α δ̇) along u = (b − g)/|b − g|, −Q u on the ball, +Q u on the ring with
moment (g − c) × Q u about the ring point c, no moment on the ball without traction.
"""

from __future__ import annotations

import math

import numpy as np

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
