"""The reduced traction-lag model of the [S1] hub hysteresis (studies/hub_reduced.py): limits, the first-order
lag's frequency response, energy consistency with the loop estimator, and the mechanism's bounds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.studies import hub_reduced as hr

N_TABLE = 13  # statics points along the load path (faster than the default 25; enough for these checks)


def run(hub, speed=100.0, f=50.0, **kw):
    kw.setdefault("n_table", N_TABLE)
    return hr.reduced_wh(hub, speed, f, **kw)


def test_lag_vanishes_when_the_balls_follow_or_stay_put(hub):
    """τ → 0 (creep slope → 0: the ball follows its quasi-static position) and τ → ∞ (the ball does not move)
    both give W_H → 0: the loop ∝ ωτ/(1 + (ωτ)²)."""
    ref = run(hub, creep_slope=15.0)
    fast = run(hub, creep_slope=1e-7)
    slow = run(hub, creep_slope=1e9, max_cycles=2, orbit=False)  # orbiting balls that never relax drift (no cap hit)
    assert ref["wh"] > 0 and ref["phase_lag"] > 0 and ref["loop_area"] > 0  # a lag, the paper's sign
    assert fast["omega_tau"] < 1e-6 and abs(fast["wh"]) < 1e-5 * ref["wh"]
    assert slow["omega_tau"] > 1e6 and abs(slow["wh"]) < 1e-4 * ref["wh"]


def test_loop_is_largest_at_omega_tau_one(hub):
    """With τ fixed (creep slope given) the loop width of a first-order lag follows g(x) = x/(1 + x²), x = ωτ,
    largest at x = 1: W(x)/W(1) = 2x/(1 + x²).  Tolerance 4 %: τ differs between balls by the spread of their
    rolling speeds (contact angles 23–49°, ± 1.5 %) and the balls orbit by up to 0.45 rad per cycle at x = 4."""
    tau = run(hub, creep_slope=15.0)["tau"]
    xs = np.array([0.25, 0.5, 1.0, 2.0, 4.0])
    w = np.array([run(hub, f=x / (2 * math.pi * tau), creep_slope=15.0)["wh"] for x in xs])
    assert int(np.argmax(w)) == 2
    np.testing.assert_allclose(w / w[2], 2 * xs / (1 + xs**2), rtol=0.04)


def test_loop_area_is_the_work_of_the_tilt_on_the_tractions(hub):
    """The estimator's loop area ∮ M dγ (exact Fourier formula on the model's tilt) equals the work the tilt does
    on the tractions, ∮ −Σ T_j v_j dt, computed independently inside the model (midpoint rule, 360 steps; the
    curves' harmonics above 5 are cut by the fit): rel. 3·10⁻³.  The sliding dissipation also contains the
    exchange with the varying normal loads and is larger (docstring)."""
    for kw in ({"creep_slope": 15.0}, {"creep_slope": 100.0}):
        r = run(hub, **kw)
        assert r["loop_area"] == pytest.approx(r["tilt_work"], rel=3e-3)
        assert r["dissipated"] >= r["tilt_work"] * (1 - 3e-3)


@pytest.mark.parametrize("kappa", [3.0, 15.0, 100.0, 1000.0])
def test_bounds_exceed_the_model(hub, kappa):
    """Force and energy bounds (every ball sliding at μ_max, arm f·D, twice the model's) ≥ the model's W_H."""
    r = run(hub, creep_slope=kappa)
    assert 0 < r["wh"] <= r["bound_force"] and r["wh"] <= r["bound_energy"]
    # the bounds are the mechanism's, not the creep law's: the same for every κ
    ref = run(hub, creep_slope=15.0)
    assert r["bound_force"] == pytest.approx(ref["bound_force"], rel=1e-12)


def test_sliding_cap_keeps_the_loop_within_the_force_bound(hub):
    """μ_max so small that the balls slide most of the cycle: W_H stays ≤ the force bound, which scales with μ_max."""
    r = run(hub, creep_slope=15.0, mu_max=1e-4)
    free = run(hub, creep_slope=15.0)
    assert r["saturated_fraction"] > 0.5 and free["saturated_fraction"] == 0.0
    assert 0 < r["wh"] <= r["bound_force"]
    assert r["bound_force"] == pytest.approx(free["bound_force"] * 1e-4 / hr.MU_MAX, rel=1e-9)


def test_film_elastic_creep_slope_and_the_case_path(hub):
    """Default κ from the film-elastic law: of the order of 10²  (Johnson–Tevaarwerk elastic branch, the hub's
    contacts at 100 km/h), falling with speed as h⁻¹ ∝ u^−0.67; a case file with the same load tie gives the
    same answer as the bearing with the hub tie of hub_static."""
    from pathlib import Path

    from bearingsim.dynamics.case import case_from_dict
    from bearingsim.io import read_toml

    fast = run(hub, 100.0, 50.0, lubricant="hub-grease-base-oil", temperature=313.15)
    slow = run(hub, 50.0, 50.0, lubricant="hub-grease-base-oil", temperature=313.15)
    assert 30 < fast["creep_slope"] < 1000
    ratio = slow["creep_slope"] / fast["creep_slope"]
    assert ratio == pytest.approx(2 ** 0.67, rel=0.05)  # h ∝ u^0.67 (Hamrock–Dowson); b, p̄, G do not change
    assert fast["wh"] <= fast["bound_force"] and fast["static_converged"]
    p = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"
    case = case_from_dict(read_toml(p, "case"), base=p.parent)
    viacase = hr.reduced_wh(case, 100.0, 50.0, creep_slope=15.0, n_table=N_TABLE)
    assert viacase["wh"] == pytest.approx(run(hub, creep_slope=15.0)["wh"], rel=1e-6)


def test_bad_input(hub):
    with pytest.raises(InputError, match="level"):
        run(hub, level=700.0, creep_slope=15.0)
    with pytest.raises(InputError, match="creep_slope"):
        run(hub, creep_slope=-1.0)
    with pytest.raises(InputError, match="creep_slope"):
        run(hub)  # a bare bearing has no lubricant to take the film slope from
    with pytest.raises(InputError, match="frequency_hz"):
        run(hub, f=0.0, creep_slope=15.0)
