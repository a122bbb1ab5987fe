"""Kalker's longitudinal creep coefficient C₁₁ (bearingsim.contact.traction.KALKER_C11_*, kalker_c11) against the
published table (issue 13 item 4 / brief HC item 3a).

Source: J.J. Kalker (1990), *Three-dimensional elastic bodies in rolling contact*, Kluwer, Table E.3 (the linear
theory's coefficients C_ij for elliptic contacts), as reproduced in the CONTACT program of E.A.H. Vollebregt and
J.J. Kalker (Apache-2.0, github.com/eve70a/CONTACT, src/m_hertz.f90, subroutine ``linrol``, data array ``cij``,
first coefficient = C₁₁).  The values below were typed from that listing into this test, separately from the
module's copy (which predates the check and was typed from memory; no entry differed).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingsim.contact import traction as tr

SOURCE = ("Kalker 1990, Three-dimensional elastic bodies in rolling contact, Table E.3, as listed in the CONTACT "
          "code (Vollebregt & Kalker), github.com/eve70a/CONTACT src/m_hertz.f90 linrol")

#: g = a/b ≤ 1 (a along the rolling direction): C₁₁ at ν = 0, 0.25, 0.5
TABLE_E3_A_LE_B = {0.1: (2.51, 3.31, 4.85), 0.2: (2.59, 3.37, 4.81), 0.3: (2.68, 3.44, 4.80), 0.4: (2.78, 3.53, 4.82),
                   0.5: (2.88, 3.62, 4.83), 0.6: (2.98, 3.72, 4.91), 0.7: (3.09, 3.81, 4.97), 0.8: (3.19, 3.91, 5.05),
                   0.9: (3.29, 4.01, 5.12), 1.0: (3.40, 4.12, 5.20)}
#: g = b/a < 1
TABLE_E3_A_GT_B = {0.1: (10.7, 11.7, 12.9), 0.2: (6.96, 7.78, 8.82), 0.3: (5.57, 6.34, 7.34), 0.4: (4.84, 5.57, 6.57),
                   0.5: (4.37, 5.10, 6.11), 0.6: (4.06, 4.78, 5.80), 0.7: (3.82, 4.54, 5.58), 0.8: (3.65, 4.36, 5.42),
                   0.9: (3.51, 4.22, 5.30)}


@pytest.mark.parametrize("g", sorted(TABLE_E3_A_LE_B))
def test_c11_rows_a_le_b(g):
    np.testing.assert_allclose(tr.KALKER_C11_A_OVER_B[g], TABLE_E3_A_LE_B[g], rtol=0, atol=0, err_msg=SOURCE)
    for nu, c in zip((0.0, 0.25, 0.5), TABLE_E3_A_LE_B[g]):
        np.testing.assert_allclose(tr.kalker_c11(g, 1.0, nu), c, rtol=1e-12, err_msg=SOURCE)


@pytest.mark.parametrize("g", sorted(TABLE_E3_A_GT_B))
def test_c11_rows_a_gt_b(g):
    np.testing.assert_allclose(tr.KALKER_C11_B_OVER_A[g], TABLE_E3_A_GT_B[g], rtol=0, atol=0, err_msg=SOURCE)
    for nu, c in zip((0.0, 0.25, 0.5), TABLE_E3_A_GT_B[g]):
        np.testing.assert_allclose(tr.kalker_c11(1.0, g, nu), c, rtol=1e-12, err_msg=SOURCE)


@pytest.mark.parametrize("nu", [0.1, 0.2, 0.3, 0.35, 0.45])
def test_poisson_interpolation_keeps_the_strip_limit(nu):
    """Between the table's ν columns: near the strip (a/b = 0.1 is within 2 % of it at the three columns) C₁₁ must
    follow Carter's strip π²/(4(1 − ν)), whose inverse is linear in ν.  The module interpolates 1/C₁₁ quadratically
    in ν (as CONTACT's linrol does); interpolating C₁₁ linearly would be 2.6 % high at ν = 0.3 and fail this."""
    ref = [math.pi**2 / (4 * (1 - n)) for n in (0.0, 0.25, 0.5)]
    ratio = [c / r for c, r in zip(TABLE_E3_A_LE_B[0.1], ref)]  # the table's own distance from the strip, per ν
    want = math.pi**2 / (4 * (1 - nu)) * float(np.interp(nu, (0.0, 0.25, 0.5), ratio))
    np.testing.assert_allclose(tr.kalker_c11(0.1, 1.0, nu), want, rtol=0.005, err_msg=SOURCE + " (strip limit)")
