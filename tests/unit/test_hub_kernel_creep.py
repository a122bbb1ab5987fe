"""Spin-softened transverse creep of the hub's ball contacts (studies.hub_reduced.kernel_creep_slope).

Mechanism tests, not literature validation: the slope is measured on our own traction kernel.  The claim they
guard (docs/dynamics.md, [S1] section): with the spin of an angular-contact ball, the contact's resistance to a
small transverse (major-axis) slip is set by the saturated traction turning, κ_eff ≈ ∫ p μ(|s|)/|s| dA / Q,
which depends on the spin-to-roll ratio (kinematics), not on the film — so κ_eff is far below the film-elastic
slope and nearly the same at 10 and 100 km/h, while the film slope falls ≈ 4.7× over that range."""

from pathlib import Path

import numpy as np
import pytest

from bearingsim.dynamics.case import load_case
from bearingsim.errors import InputError
from bearingsim.studies.hub_reduced import kernel_creep_slope, reduced_wh

CASE = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"


@pytest.fixture(scope="module")
def case():
    return load_case(CASE)


@pytest.fixture(scope="module")
def slopes(case):
    return {v: kernel_creep_slope(case, v) for v in (10.0, 100.0)}


def test_spin_softened_slope_is_far_below_the_film_slope(slopes):
    for v, r in slopes.items():
        k, film = r["kappa"], r["film"]
        ok = np.isfinite(k)
        assert ok.sum() >= 16, f"{v} km/h: loaded balls {ok.sum()}"
        assert np.all(k[ok] > 0), f"{v} km/h: a transverse slip must be resisted, kappa {k[ok]}"
        # measured 10 km/h: 7.2-8.3 vs film 210-580; 100 km/h: 7.7-9.1 vs 46-123
        assert np.all(k[ok] < film[ok] / 4), f"{v} km/h: kappa_eff {k[ok]} vs film {film[ok]}"


def test_spin_softened_slope_is_kinematic_not_film(slopes):
    """The film slope falls with speed (thicker film); the spin-softened slope barely moves."""
    film_ratio = np.nanmedian(slopes[10.0]["film"]) / np.nanmedian(slopes[100.0]["film"])
    kernel_ratio = slopes[10.0]["median"] / slopes[100.0]["median"]
    assert film_ratio > 3.0, film_ratio  # measured 4.7
    assert abs(kernel_ratio - 1.0) < 0.2, kernel_ratio  # measured 0.93


def test_slope_does_not_depend_on_the_probe_step(case):
    a = kernel_creep_slope(case, 50.0, step=1e-6)["kappa"]
    b = kernel_creep_slope(case, 50.0, step=1e-5)["kappa"]
    ok = np.isfinite(a)
    np.testing.assert_allclose(a[ok], b[ok], rtol=2e-2)


def test_reduced_model_with_kernel_slope_lags_and_follows_the_seed_trends(case):
    """With the kernel's slope the reduced model lags (W_H > 0), falls with speed at 50 Hz and rises with the
    load frequency at 10 km/h — the trends of the dynamic runs (docs/dynamics.md grid table), which the
    film slope (τ ≈ 0.3 s at 10 km/h: ωτ ≫ 1) reversed at 10 km/h."""
    w = {(v, f): reduced_wh(case, v, f, creep_slope="kernel")["wh"] for v, f in ((10, 50), (100, 50), (10, 10))}
    assert all(x > 0 for x in w.values()), w
    assert w[(10, 50)] > w[(100, 50)], w
    assert w[(10, 50)] > w[(10, 10)], w
    film = {f: reduced_wh(case, 10, f)["wh"] for f in (10, 50)}
    assert film[50] < film[10], film  # the film slope's reversed frequency trend at 10 km/h


@pytest.mark.parametrize("bad", ["film", 0.0, -3.0, float("nan")])
def test_bad_creep_slope_is_an_input_error(case, bad):
    with pytest.raises(InputError, match="creep_slope"):
        reduced_wh(case, 50, 50, creep_slope=bad)
