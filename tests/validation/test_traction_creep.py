"""The small-slip (creep) slope of a lubricated rolling contact: Kalker's linear creep of the solids in series with
the elastic film (issue 13 item 4; bearingsim.contact.traction.creep_slope)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingsim.contact import traction as tr
from bearingsim.errors import InputError

KALKER = "Kalker (1967) linear rolling-contact theory, table of C11 (Kalker 1990, Three-dimensional elastic bodies in " \
         "rolling contact, Table 3.1)"


def test_kalker_c11_reaches_the_strip_limit():
    """a/b → 0 (an ellipse long across the rolling direction) tends to Carter's 2-D strip, C₁₁ = π²/(4(1 − ν)):
    Kalker's a/b = 0.1 row is within 2 % of it for ν = 0, 0.25, 0.5."""
    for nu in (0.0, 0.25, 0.5):
        np.testing.assert_allclose(tr.kalker_c11(0.1, 1.0, nu), math.pi**2 / (4 * (1 - nu)), rtol=0.02,
                                   err_msg=KALKER + ": strip limit pi^2/(4(1-nu))")


@pytest.mark.parametrize("a,b,nu,c11", [
    (1.0, 1.0, 0.25, 4.12),  # circle
    (0.5, 1.0, 0.0, 2.88),
    (0.2, 1.0, 0.5, 4.81),
    (1.0, 0.5, 0.25, 5.10),
    (1.0, 0.2, 0.0, 6.96),
])
def test_kalker_c11_table_points(a, b, nu, c11):
    """Values of Kalker's table (transcribed independently of the module's copy)."""
    np.testing.assert_allclose(tr.kalker_c11(a, b, nu), c11, rtol=1e-12, err_msg=KALKER)


def test_kalker_c11_interpolates_between_rows_and_columns():
    """ν = 0.3 (steel) lies between the ν = 0.25 and 0.5 columns, a/b = 0.125 (a ball-bearing ellipse) between
    the 0.1 and 0.2 rows; the coefficient rises with ν and with a/b."""
    c = tr.kalker_c11(0.125, 1.0, 0.3)
    assert tr.kalker_c11(0.125, 1.0, 0.25) < c < tr.kalker_c11(0.125, 1.0, 0.5)
    assert 3.31 < c < 4.85
    grid = [tr.kalker_c11(g, 1.0, 0.3) for g in np.geomspace(0.2, 1.0, 9)] + \
        [tr.kalker_c11(1.0, g, 0.3) for g in np.geomspace(0.9, 0.1, 9)]
    assert np.all(np.diff(grid) > 0)


def test_series_law_limits():
    """Either compliance → 0 recovers the other; equal compliances halve the slope."""
    q, a, b, g, nu = 800.0, 1.4e-4, 1.2e-3, 79e9, 0.3
    k_s = tr.solid_creep_stiffness(a, b, g, nu)
    assert k_s == pytest.approx(g * a * b * tr.kalker_c11(a, b, nu), rel=1e-14)
    solid_only = tr.creep_slope(q, a, b, g, nu)  # rigid film
    assert solid_only == pytest.approx(k_s / q, rel=1e-14)
    film_only = tr.creep_slope(q, a, b, g, nu, 0.3e9, 0.2e-6, solids=False)
    k_f = tr.film_creep_stiffness(a, b, 0.3e9, 0.2e-6)
    assert film_only == pytest.approx(k_f / q, rel=1e-14)
    assert k_f == pytest.approx(8.0 / 3.0 * 0.3e9 * a * a * b / 0.2e-6, rel=1e-14)
    # a very stiff film (thin) → the solids; a very compliant film (thick) → the film
    assert tr.creep_slope(q, a, b, g, nu, 0.3e9, 1e-12) == pytest.approx(solid_only, rel=1e-4)
    assert tr.creep_slope(q, a, b, g * 1e6, nu, 0.3e9, 0.2e-6) == pytest.approx(film_only, rel=1e-5)
    h_eq = 8.0 / 3.0 * 0.3e9 * a * a * b / k_s  # the film as stiff as the solids
    assert tr.creep_slope(q, a, b, g, nu, 0.3e9, h_eq) == pytest.approx(0.5 * solid_only, rel=1e-12)


def test_film_slope_is_the_point_law_integrated_over_the_ellipse():
    """The film term is the s → 0 limit of elastic_plastic_mean_stress integrated over the Hertz ellipse: a point at
    distance x from the leading edge carries τ = G s x/h (each strip of chord ℓ has the mean τ_e/2 of
    elastic_plastic_mean_stress with τ_e = G s ℓ/h); the double integral is done here by quadrature, independently
    of the closed form (8/3) G a² b/h.  (The former uniform-chord form π G a² b/h, every strip with the longest chord,
    is 3π/8 = 1.18 times larger and fails this.)"""
    from scipy import integrate

    a, b, g_f, h, q = 1.5e-4, 1.3e-3, 0.25e9, 0.1e-6, 600.0
    s = 1e-7
    chord = lambda y: 2 * a * math.sqrt(max(0.0, 1 - (y / b) ** 2))  # noqa: E731
    force, _ = integrate.quad(lambda y: tr.elastic_plastic_mean_stress(1e9, g_f * s * chord(y) / h) * chord(y), -b, b,
                              epsabs=0.0, epsrel=1e-12, limit=200)
    assert force / (q * s) == pytest.approx(tr.creep_slope(q, a, b, 79e9, 0.3, g_f, h, solids=False), rel=1e-9)


def test_bad_input():
    with pytest.raises(InputError, match="poisson"):
        tr.kalker_c11(1.0, 1.0, 0.7)
    with pytest.raises(InputError, match="a_roll/b_lat"):
        tr.kalker_c11(1e-3, 1.0, 0.3)
    with pytest.raises(InputError, match="load"):
        tr.creep_slope(0.0, 1e-4, 1e-3, 79e9, 0.3)
    with pytest.raises(InputError, match="film_thickness"):
        tr.creep_slope(100.0, 1e-4, 1e-3, 79e9, 0.3, 0.3e9, None)
    with pytest.raises(InputError, match="creep_slope"):
        tr.creep_slope(100.0, 1e-4, 1e-3, 79e9, 0.3, solids=False)


def test_series_factor_on_the_film_modulus_gives_the_series_slope():
    """φ G_f in the film law (what a traction kernel needs to include the solids) reproduces creep_slope."""
    q, a, b, g, nu, g_f, h = 700.0, 1.4e-4, 1.25e-3, 79e9, 0.3, 0.28e9, 0.1e-6
    phi = tr.solids_in_series_factor(g_f, 2 * a, h, g, tr.kalker_c11(a, b, nu))
    assert 0 < phi < 1
    assert tr.creep_slope(q, a, b, g, nu, phi * g_f, h, solids=False) == pytest.approx(
        tr.creep_slope(q, a, b, g, nu, g_f, h), rel=1e-12)
