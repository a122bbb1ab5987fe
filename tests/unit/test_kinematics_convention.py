"""The sign convention of Jones' ball speeds, pinned once and used as stated.

Convention (:func:`bearingsim.statics._kernels.kinematics`, keys of
:func:`bearingsim.statics.jones_harris.ball_table`): in the row frame (ξ axial = s (x − x_row),
r radial, t = ξ × r) turning with the cage at ω_m about x, the ball's angular velocity relative
to the cage is Ω = ω_R (cos β, −sin β, 0); the outer contact centre is at +(D/2)(sin α_o, cos α_o)
from the ball centre, the inner one at −(D/2)(sin α_i, cos α_i); ω_m and ω_R are proportional to the
signed shaft speed ω, β does not depend on its sign.

Mechanism checked here: with exactly this Ω (no choice of signs) the sliding speed at both contact
centres is zero (pure rolling, Jones 1960) and the spin about the normal of the controlling raceway
is zero, for outer and inner control, ± shaft speed, rows of both orientations (the DB pair and the
double-row hub unit have mirrored rows), a deep-groove bearing; and
:func:`bearingsim.lubrication.contact_at_jones_kinematics`, which builds Ω from the convention,
reports zero centre sliding.  A negative shaft speed gives the same lubrication figures as a
positive one (the bearing is symmetric under reversing the sense of rotation).
"""

from __future__ import annotations

import json
import math
import subprocess

import numpy as np
import pytest

from bearingsim.io import load_bearing
from bearingsim.lubrication import _contact_geometry, contact_at_jones_kinematics, lubrication_report
from bearingsim.statics import layout as rl
from bearingsim.statics.jones_harris import Loads, solve

RPM = math.pi / 30.0

CASES = {
    "skf-7011-cdga-hc": (Loads(fa=3000.0, fr_y=500.0), 10000.0),
    "skf-7011-cdga-hc-db": (Loads(fa=1000.0, fr_y=500.0, m_z=10.0), 8000.0),
    "hub-seed001": (Loads(fa=945.0, fr_y=3268.0, m_z=300.0), 1000.0),
    "harris-218": (Loads(fa=2000.0, fr_y=8000.0), 3000.0),
}


@pytest.fixture(scope="module")
def results():
    out = {}
    for name, (loads, n) in CASES.items():
        b = load_bearing(name)
        for control in ("outer", "inner"):
            for sign in (1.0, -1.0):
                r = solve(b, loads, sign * n * RPM, control=control)
                assert r.converged, (name, control, sign, r.status)
                out[name, control, sign] = r
    return out


def _frame_residuals(r, j):
    """Centre sliding at (outer, inner) over ω d_m, spin about the (outer, inner) normal over ω."""
    par = r.rows_params[int(r.balls["row"][j])]
    d, dm = par[rl.P_D], par[rl.P_DM]
    b = r.balls
    w, wm, wr, beta = r.speed, b["orbital_speed_rad_s"][j], b["spin_speed_rad_s"][j], b["pitch_angle_rad"][j]
    ai, ao = b["inner_contact_angle_rad"][j], b["outer_contact_angle_rad"][j]
    omega_ball = wr * np.array([math.cos(beta), -math.sin(beta), 0.0])
    centre = np.array([0.0, 0.5 * dm, 0.0])
    slide, spin = [], []
    for inner, alpha, w_race in ((False, ao, -wm), (True, ai, w - wm)):
        off, n = _contact_geometry(d, alpha, inner)
        p = centre + off
        v = np.cross(omega_ball, off) - np.cross([w_race, 0.0, 0.0], p)
        slide.append(np.linalg.norm(v - (v @ n) * n) / abs(w * dm))
        spin.append((omega_ball - np.array([w_race, 0.0, 0.0])) @ n / abs(w))
    return slide, spin


def test_frame_geometry_matches_the_kernel_contact_angles():
    # outer contact at +(D/2)(sin α, cos α), inner at −(D/2)(sin α, cos α), normals race → ball
    d, a = 0.01, 0.4
    off_o, n_o = _contact_geometry(d, a, False)
    off_i, n_i = _contact_geometry(d, a, True)
    np.testing.assert_allclose(off_o, [0.5 * d * math.sin(a), 0.5 * d * math.cos(a), 0.0], rtol=0, atol=1e-18)
    np.testing.assert_allclose(off_i, [-0.5 * d * math.sin(a), -0.5 * d * math.cos(a), 0.0], rtol=0, atol=1e-18)
    np.testing.assert_allclose(n_o, -off_o / (0.5 * d), atol=1e-15)
    np.testing.assert_allclose(n_i, -off_i / (0.5 * d), atol=1e-15)


@pytest.mark.parametrize("name", list(CASES))
@pytest.mark.parametrize("control", ["outer", "inner"])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_pinned_convention_rolls_and_does_not_spin_at_the_controlling_race(results, name, control, sign):
    r = results[name, control, sign]
    b = r.balls
    assert np.all(b["inner_control"] == (1 if control == "inner" else 0))
    # the speeds follow the sign of the shaft speed, β does not
    r_pos = results[name, control, 1.0]
    np.testing.assert_array_equal(np.sign(b["orbital_speed_rad_s"]), sign * np.sign(r_pos.balls["orbital_speed_rad_s"]))
    np.testing.assert_allclose(b["pitch_angle_rad"], r_pos.balls["pitch_angle_rad"], rtol=1e-9, atol=1e-12)
    assert np.all(b["spin_speed_rad_s"] * sign < 0), "Jones: ω_R/ω < 0"
    other_spin = []
    for j in range(len(b["row"])):
        if not (b["inner_load_N"][j] > 0 and b["outer_load_N"][j] > 0):
            continue
        slide, spin = _frame_residuals(r, j)
        np.testing.assert_allclose(slide, 0.0, atol=1e-13, err_msg=f"{name} ball {j}: sliding at the contact centres")
        k = 1 if control == "inner" else 0
        np.testing.assert_allclose(spin[k], 0.0, atol=1e-12, err_msg=f"{name} ball {j}: spin at the {control} race")
        other_spin.append(abs(spin[1 - k]))
    assert other_spin, "some balls are loaded at both contacts"
    if name != "harris-218":
        # angular contact: the other raceway spins, so a wrong β would show
        assert min(other_spin) > 1e-3


def test_sets_cover_both_row_orientations():
    for name in ("skf-7011-cdga-hc-db", "hub-seed001"):
        r = solve(load_bearing(name), CASES[name][0], CASES[name][1] * RPM)
        rows = r.rows_params
        assert sorted(set(rows[:, rl.P_SIGN])) == [-1.0, 1.0], name


@pytest.mark.parametrize("name", ["skf-7011-cdga-hc-db", "hub-seed001"])
@pytest.mark.parametrize("control", ["outer", "inner"])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_lubrication_contact_has_zero_centre_sliding(results, name, control, sign):
    r = results[name, control, sign]
    b = r.balls
    lub = np.zeros(64)  # contact_traction is not reached for q = 0; only the kinematics are used
    n_checked = 0
    for j in range(len(b["row"])):
        par = r.rows_params[int(b["row"][j])]
        for inner in (True, False):
            _, u, s_c = contact_at_jones_kinematics(
                lub, 0.0, 1e-4, 1e-5, 1e-3, par[rl.P_D], par[rl.P_DM], b["inner_contact_angle_rad"][j],
                b["outer_contact_angle_rad"][j], r.speed, b["orbital_speed_rad_s"][j], b["spin_speed_rad_s"][j],
                b["pitch_angle_rad"][j], inner)
            assert u > 0
            assert s_c < 1e-12 * u, f"{name} ball {j} {'inner' if inner else 'outer'}: sliding {s_c} at u = {u}"
            n_checked += 1
    assert n_checked == 2 * len(b["row"])


def test_negative_speed_gives_the_same_lubrication_report():
    b = load_bearing("skf-7011-cdga-hc")
    pos = lubrication_report(solve(b, Loads(fa=3000.0), 10000 * RPM), "iso-vg-68", 333.15)
    neg = lubrication_report(solve(b, Loads(fa=3000.0), -10000 * RPM), "iso-vg-68", 333.15)
    assert pos["balls"] and len(pos["balls"]) == len(neg["balls"])
    for bp, bn in zip(pos["balls"], neg["balls"]):
        for name in ("inner", "outer"):
            for key in ("entrainment_speed_m_s", "central_film_m", "tangential_force_N", "power_loss_W",
                        "spin_moment_N_m"):
                assert bn[name][key] == pytest.approx(bp[name][key], rel=1e-9, abs=1e-12), (name, key)
            assert bn[name]["centre_sliding_speed_m_s"] < 1e-12 * bn[name]["entrainment_speed_m_s"]
    assert neg["total_power_loss_W"] == pytest.approx(pos["total_power_loss_W"], rel=1e-9)


def test_cli_negative_speed_gives_the_same_power_loss():
    # installed console script: the same contacts and losses at ±10000 rpm (before the fix −10000 rpm gave
    # 62 m/s of centre sliding at the inner contacts and a total loss of 35.7 kW instead of 350 W)
    out = {}
    for speed in ("10000 rpm", "-10000 rpm"):
        p = subprocess.run(["bearingsim", "lubrication", "skf-7011-cdga-hc", "--fa", "3000", "--speed", speed,
                            "--lubricant", "iso-vg-68", "--temperature", "60 degC", "--json"],
                           capture_output=True, text=True, timeout=300)
        assert p.returncode == 0, p.stderr
        out[speed] = json.loads(p.stdout)
    pos, neg = out["10000 rpm"], out["-10000 rpm"]
    assert neg["speed_rad_s"] == pytest.approx(-pos["speed_rad_s"], rel=1e-12)
    assert neg["total_power_loss_W"] == pytest.approx(pos["total_power_loss_W"], rel=1e-9)
    assert max(b["inner"]["centre_sliding_speed_m_s"] for b in neg["balls"]) < 1e-9
