"""Robustness of the quasi-static solvers (issue 11 items 1, 5, 6, 10): no exception from a kernel, no
non-equilibrium called converged, API arguments checked at the boundary, signed ball speeds."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from bearingsim.errors import InputError, InputTypeError
from bearingsim.statics import _batch
from bearingsim.statics import _kernels as kn
from bearingsim.statics import jones_harris as jh

RPM = math.pi / 30.0


# ---- division by zero in the ball kinematics (ball_eval, kinematics) --------------------------------
def test_kinematics_without_rolling_solution_is_nan_not_zero_division():
    """po + pi = 0 exactly (outer control, α_o = 0, α_i = 180°: po = 1/(1 + γ'), pi = −1/(1 + γ')): Jones'
    relations divide by it; the kernel returns NaN speeds instead of raising ZeroDivisionError."""
    gam = 0.2
    res = kn.kinematics(0.0, -1.0, 0.0, 1.0, gam)
    assert np.all(np.isnan(res[:3]))
    # the inner-control pitch angle divides by cos α_i − γ' = 0 (3-4-5 triangle: both exactly 3/5)
    res2 = kn.kinematics(4.0 / 5.0, 3.0 / 5.0, 0.0, 1.0, 3.0 / 5.0)
    assert np.all(np.isnan(res2[3:])) and np.all(np.isfinite(res2[:3]))


def test_ball_eval_at_a_zero_divisor_returns_nan_residual():
    """Inner control with cos α_i = γ' exactly (tan β = sin α_i / 0): a NaN residual, not an exception.
    Inner line of centres (p, q) = (4, 3), |.| = 5, γ' = 3/5 (plain numbers: only the arithmetic is tested)."""
    out = np.zeros(10)
    jac = np.zeros((5, 4))
    kn.ball_eval(0.0, 10.0, 4.0, 13.0, 4.9, 9.9, 1e10, 1e10, 3.0 / 5.0, 1.0, 1.0, 1.0, 1.0, 1, out, jac)
    assert out[4] > 0 and math.isnan(out[0]) and math.isnan(out[8])
    out2 = np.zeros(10)
    kn.ball_eval(0.0, 10.0, 4.0, 13.0, 4.9, 9.9, 1e10, 1e10, 0.2, 1.0, 1.0, 1.0, 1.0, 1, out2, jac)
    assert np.all(np.isfinite(out2))


def test_harris_218_point_of_the_issue_does_not_raise(b218):
    """Fa 0, Fr_y −20.4 kN, Fr_z 1.03 kN, 586 rad/s, outer control: raised ZeroDivisionError."""
    for control in ("outer", "inner", "auto"):
        r = jh.solve(b218, jh.Loads(fa=0.0, fr_y=-20.4e3, fr_z=1.03e3), 586.0, control)
        assert isinstance(r.converged, bool) and (r.converged or r.status != "converged")
    m = jh.solve_many(b218, np.array([[0.0, -20.4e3, 1.03e3, 0, 0]]), np.array([586.0]))
    assert m.status.shape == (1,)


def test_nan_residual_is_never_a_small_residual():
    """max(rn, nan) drops the NaN: the norm used for convergence must propagate it."""
    assert math.isnan(kn._scaled_norm(np.array([0.0, math.nan, 0.0, 0.0, 0.0]), 0.07))
    assert kn._scaled_norm(np.array([1.0, -3.0, 0.0, 0.07, 0.0]), 0.07) == 3.0


# ---- initial, types ------------------------------------------------------------------------------------
def test_nan_initial_is_refused(b7011):
    with pytest.raises(InputError, match="initial"):
        jh.solve(b7011, jh.Loads(fa=1000.0), 0.0, initial=np.full(5, np.nan))


@pytest.mark.parametrize("initial", [np.zeros(4), np.zeros(6), np.zeros((5, 1)), [0.0, 1.0]])
def test_initial_of_wrong_shape_is_refused_before_the_kernel(b7011, initial):
    with pytest.raises(InputError, match="initial"):
        jh.solve(b7011, jh.Loads(fa=1000.0), 0.0, initial=initial)


@pytest.mark.parametrize("kwargs,field", [({"fa": "1000"}, "fa"), ({"fa": True}, "fa"), ({"fr_y": None}, "fr_y"),
                                          ({"m_z": [1.0]}, "m_z"), ({"fa": math.inf}, "fa")])
def test_loads_refuse_non_numbers_naming_the_field(kwargs, field):
    with pytest.raises(InputError) as e:
        jh.Loads(**kwargs)
    assert e.value.field == field
    value = list(kwargs.values())[0]
    if isinstance(value, str):  # a string is a quantity: a bare number names the unit to add
        assert "no unit" in str(e.value)
    elif not isinstance(value, float):
        assert isinstance(e.value, TypeError) and isinstance(e.value, InputTypeError)


def test_loads_accept_numpy_and_int_and_store_floats():
    ld = jh.Loads(fa=np.float32(1000.0), fr_y=3)
    assert type(ld.fa) is float and ld.fa == 1000.0 and type(ld.fr_y) is float


@pytest.mark.parametrize("speed", ["1000 N", None, [1.0], True])
def test_solve_refuses_non_number_speed(b7011, speed):
    # a string with a speed unit is a quantity (tests/unit/test_new_user_physics.py); one of another dimension is not
    with pytest.raises(InputTypeError if not isinstance(speed, str) else InputError) as e:
        jh.solve(b7011, jh.Loads(fa=1000.0), speed)
    assert e.value.field == "speed"


def test_solve_refuses_wrong_loads_control_and_bearing(b7011):
    with pytest.raises(InputTypeError, match="loads"):
        jh.solve(b7011, (1000.0, 0, 0, 0, 0))
    with pytest.raises(InputError, match="control"):
        jh.solve(b7011, jh.Loads(fa=1.0), 0.0, control=1)
    with pytest.raises(InputTypeError, match="bearing"):
        jh.solve("skf-7011-cdga-hc", jh.Loads(fa=1.0))


@pytest.mark.parametrize("loads,speeds,field", [("1000", np.zeros(1), "loads"), (None, np.zeros(1), "loads"),
                                                (np.zeros((1, 5)), "0", "speeds"),
                                                ([[1, 2, 3, 4, "x"]], np.zeros(1), "loads")])
def test_solve_many_refuses_non_numbers(b7011, loads, speeds, field):
    with pytest.raises(InputError) as e:
        jh.solve_many(b7011, loads, speeds)
    assert e.value.field == field


def test_solve_thrust_refuses_non_numbers(b7011):
    from bearingsim.statics.axial import solve_thrust

    for bad in ("1000", None, True, [1000.0]):
        with pytest.raises(InputError) as e:
            solve_thrust(b7011, bad)
        assert e.value.field == "fa"


# ---- speed: sign, absurd values --------------------------------------------------------------------
def test_negative_speed_turns_balls_and_cage_the_other_way(b7011):
    """−1047 rad/s gave a cage speed of +453 rad/s; Jones' speeds are linear in ω."""
    rp = jh.solve(b7011, jh.Loads(fa=3000.0), 1047.0)
    rn = jh.solve(b7011, jh.Loads(fa=3000.0), -1047.0)
    assert rp.converged and rn.converged
    np.testing.assert_array_equal(rn.displacement, rp.displacement)
    assert rn.cage_speed == -rp.cage_speed and rp.cage_speed > 0
    np.testing.assert_array_equal(rn.balls["orbital_speed_rad_s"], -rp.balls["orbital_speed_rad_s"])
    np.testing.assert_array_equal(rn.balls["spin_speed_rad_s"], -rp.balls["spin_speed_rad_s"])
    assert rn.to_dict()["cage_speed_rad_s"] < 0


def test_absurd_speed_is_an_input_error_with_the_limit(b7011):
    with pytest.raises(InputError, match="n·d_m") as e:
        jh.solve(b7011, jh.Loads(fa=3000.0), 1e7 * RPM)
    assert e.value.field == "speed" and "rpm" in e.value.fix
    with pytest.raises(InputError, match="n·d_m"):
        jh.solve_many(b7011, np.array([[3000.0, 0, 0, 0, 0]]), np.array([1e7 * RPM]))
    assert jh.solve(b7011, jh.Loads(fa=3000.0), 60000 * RPM).status != ""  # below the limit: an answer


# ---- zero load at speed, free ring ---------------------------------------------------------------------
def test_zero_load_at_speed_is_fast_and_reports_a_free_ring(b7011):
    """Took 14 s and reported a 468 N residual; every ball is lifted off the inner raceway by F_c, so the
    inner ring position is undetermined: status 8, not converged, in milliseconds."""
    jh.solve(b7011, jh.Loads(), 100.0)  # compiled
    t = time.perf_counter()
    r = jh.solve(b7011, jh.Loads(), 11200 * RPM)
    assert time.perf_counter() - t < 1.0
    assert not r.converged and r.status_code == 8 and "lifted off" in r.status
    m = jh.solve_many(b7011, np.zeros((2, 5)), np.array([11200 * RPM, 0.0]))
    assert list(m.status) == [8, 8]


# ---- open inner contact under inner/auto control ------------------------------------------------------
@pytest.mark.parametrize("control", ["inner", "auto"])
def test_balls_with_open_inner_contact_are_outer_controlled(deep_groove, control):
    """A ball that does not touch the inner raceway cannot transmit the friction that holds its gyroscopic
    moment to the inner ring: it runs under outer control (λ_i = 0)."""
    r = jh.solve(deep_groove, jh.Loads(fa=50.0, fr_y=8000.0), 3000.0, control)
    assert r.converged, r.status
    open_ = ~(r.balls["inner_load_N"] > 0)
    assert open_.any() and (~open_).any()
    assert np.all(r.balls["inner_control"][open_] == 0)
    if control == "inner":
        assert np.all(r.balls["inner_control"][~open_] == 1)


# ---- contact angles beyond the ring ----------------------------------------------------------------
def test_contact_at_90_degrees_or_more_is_not_reported_as_converged(b218):
    """harris-218 returned converged equilibria with inner contact angles up to 104° (only the low-shoulder
    side was checked); a loaded contact at |α| ≥ 90° is outside either ring: never converged, single or
    batch, over heavy combined loads at speed."""
    rng = np.random.default_rng(11)
    n = 40
    loads = np.column_stack([rng.uniform(1e4, 6e4, n), rng.uniform(-6e4, 6e4, n), rng.uniform(-2e4, 2e4, n),
                             rng.uniform(-2e3, 2e3, n), rng.uniform(-2e3, 2e3, n)])
    speeds = rng.uniform(0, 900, n)
    out = _batch.run_batch(b218, loads, speeds)
    conv = out["converged"]
    assert conv.any() and (out["status"] == 6).any()  # the domain reaches past the groove edge
    for key in ("alpha_inner_min", "alpha_inner_max", "alpha_outer_min", "alpha_outer_max"):
        assert np.all(np.abs(out[key][conv]) < math.pi / 2)
    for i in range(0, n, 5):
        r = jh.solve(b218, jh.Loads(*loads[i]), speeds[i])
        assert r.converged == bool(conv[i])
        if r.converged:
            for key, ld in (("inner_contact_angle_rad", "inner_load_N"), ("outer_contact_angle_rad", "outer_load_N")):
                assert np.all(np.abs(r.balls[key][r.balls[ld] > 0]) < math.pi / 2)


def test_contact_past_groove_edge_kernel_check():
    rows = np.zeros((1, kn.NPAR))
    rows[0, kn.P_Z] = 2
    bo = np.zeros((1, 2, 12))
    bo[0, :, 2] = 10.0
    bo[0, :, 3] = 10.0
    bo[0, :, 9] = 0.5
    bo[0, :, 11] = 0.5
    assert not kn.contact_past_groove_edge(rows, bo)
    bo[0, 1, 9] = -0.01  # inner contact at 90.6°
    assert kn.contact_past_groove_edge(rows, bo)
    bo[0, 1, 2] = 0.0  # ... but unloaded
    assert not kn.contact_past_groove_edge(rows, bo)


# ---- batch isolation -----------------------------------------------------------------------------------
def test_one_failing_point_does_not_lose_the_batch(b7011, monkeypatch):
    """An exception inside the compiled loop: every point is redone by the single path; a point whose
    single solve raises gets status 7 and the others keep their results."""
    loads = np.array([[1000.0, 0, 0, 0, 0], [2000.0, 0, 0, 0, 0], [3000.0, 0, 0, 0, 0]])
    speeds = np.array([0.0, 500.0, 1000.0])
    ref = jh.solve_many(b7011, loads, speeds)

    def boom(*a, **k):
        raise ZeroDivisionError("simulated kernel failure")

    monkeypatch.setattr(_batch, "solve_batch", boom)
    real_solve = jh.solve

    def flaky(bearing, loads_, speed=0.0, control="outer", initial=None):
        if loads_.fa == 2000.0:
            raise FloatingPointError("simulated point failure")
        return real_solve(bearing, loads_, speed, control, initial)

    monkeypatch.setattr(jh, "solve", flaky)
    m = jh.solve_many(b7011, loads, speeds)
    assert list(m.status) == [0, 7, 0]
    assert list(m.converged) == [True, False, True]
    for i in (0, 2):
        np.testing.assert_allclose(m.displacement[i], ref.displacement[i], rtol=1e-7, atol=1e-13)
    assert np.all(np.isnan(m.displacement[1]))


def test_result_dictionary_is_valid_json_with_non_finite_values(b7011):
    """NaN ball speeds (a state outside the rolling relations) and infinite values become null: json.dumps
    with allow_nan=False (strict JSON) accepts the dictionary."""
    import json

    r = jh.solve(b7011, jh.Loads(fa=3000.0), 1000.0)
    r.balls["orbital_speed_rad_s"][0] = math.nan
    r.balls["spin_speed_rad_s"][1] = math.inf
    d = r.to_dict()
    json.dumps(d, allow_nan=False)
    assert d["balls"][0]["orbital_speed_rad_s"] is None and d["balls"][1]["spin_speed_rad_s"] is None
    assert d["balls"][2]["orbital_speed_rad_s"] == pytest.approx(float(r.balls["orbital_speed_rad_s"][2]))
