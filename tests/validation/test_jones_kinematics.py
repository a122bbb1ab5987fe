"""Ball speeds at n > 0 against Jones' rolling equations (outer ring fixed, inner ring at ω).

Two independent checks of the reported orbital speed ω_m, spin ω_R and pitch angle β:

1. First principles, in the frame turning with the cage (ω_m about x).  Local axes
   (x, r, t) right-handed, x the bearing axis.  The ball spins relative to the cage with
   Ω = ω_R (cos β, −sin β) in (x, r) (Jones' convention, ω_R < 0).  The outer contact
   point is at (D/2)(sin α_o, cos α_o) from the ball centre, the inner one at
   −(D/2)(sin α_i, cos α_i).  The tangential velocity of a ball point ρ is Ω_x ρ_r − Ω_r ρ_x
   and a raceway point at radius R moves at (Ω_race) R with Ω_outer = −ω_m and
   Ω_inner = ω − ω_m in this frame.  Then
   * rolling without slip at both contact centres (two equations);
   * raceway control: no spin relative to the controlling raceway,
     (Ω + (ω_m − ω_race) e_x) · n = 0 with n the contact normal.
2. The closed forms of Jones (1960) as given in Harris & Kotzalas (2007) vol. 2 ch. 2 and
   physics-notes.md, rewritten here: outer control ω_m/ω = (1 − γ′cos α_i)/(1 + cos(α_i − α_o)),
   tan β = sin α_o/(cos α_o + γ′); inner control ω_m/ω = (cos(α_i − α_o) − γ′cos α_o)/(1 + cos(α_i − α_o)),
   tan β = sin α_i/(cos α_i − γ′); ω_R/ω = −1/{γ′ cos β [(cos α_o + tan β sin α_o)/(1 + γ′ cos α_o)
   + (cos α_i + tan β sin α_i)/(1 − γ′ cos α_i)]}, γ′ = D/d_m.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearingsim.statics.jones_harris import Loads, solve

RPM = math.pi / 30.0
SRC1 = "Jones 1960 rolling kinematics from first principles (no slip at both contact centres)"
SRC2 = "Jones 1960 / Harris & Kotzalas 2007 vol. 2 ch. 2 closed-form ball speeds"

CASES = [
    (Loads(fa=1000.0), 11200.0),
    (Loads(fa=3000.0, fr_y=800.0, m_z=10.0), 9000.0),
    (Loads(fa=5000.0, fr_y=-500.0, fr_z=1500.0), 4000.0),
]


def residuals(b, balls, omega, j):
    d, dm = b.ball_diameter, b.pitch_diameter
    ai, ao = balls["inner_contact_angle_rad"][j], balls["outer_contact_angle_rad"][j]
    wm, wr, beta = balls["orbital_speed_rad_s"][j], balls["spin_speed_rad_s"][j], balls["pitch_angle_rad"][j]
    ox, orr = wr * math.cos(beta), -wr * math.sin(beta)
    so, co, si, ci = math.sin(ao), math.cos(ao), math.sin(ai), math.cos(ai)
    # rolling: ball surface velocity = raceway velocity at each contact centre (tangential)
    v_ball_o = ox * (0.5 * d * co) - orr * (0.5 * d * so)
    v_race_o = -wm * (0.5 * dm + 0.5 * d * co)
    v_ball_i = ox * (-0.5 * d * ci) - orr * (-0.5 * d * si)
    v_race_i = (omega - wm) * (0.5 * dm - 0.5 * d * ci)
    # spin relative to each raceway about its contact normal (outward normals of the ball)
    spin_o = (ox + wm) * so + orr * co
    spin_i = -((ox + wm - omega) * si + orr * ci)
    scale = omega * dm
    return (v_ball_o - v_race_o) / scale, (v_ball_i - v_race_i) / scale, spin_o / omega, spin_i / omega


@pytest.mark.parametrize("control", ["outer", "inner", "auto"])
@pytest.mark.parametrize("loads, n", CASES)
def test_rolling_and_spin_first_principles(b7011, loads, n, control):
    omega = n * RPM
    r = solve(b7011, loads, omega, control=control)
    assert r.converged, r.status
    b = r.balls
    for j in range(b7011.ball_count):
        ro, ri, spo, spi = residuals(b7011, b, omega, j)
        assert_allclose([ro, ri], 0.0, atol=1e-12, err_msg=SRC1 + f" (rolling, ball {j})")
        ctrl = b["inner_control"][j]
        spin_at_control = spi if ctrl == 1 else spo
        spin_other = spo if ctrl == 1 else spi
        assert_allclose(spin_at_control, 0.0, atol=1e-12, err_msg=SRC1 + f" (no spin at the controlling race, ball {j})")
        # the other contact spins (a 15° bearing always has spin at one contact)
        assert abs(spin_other) > 1e-3, SRC1 + f" (the other contact spins, ball {j})"


@pytest.mark.parametrize("loads, n", CASES)
@pytest.mark.parametrize("control", ["outer", "inner"])
def test_closed_form_ball_speeds(b7011, loads, n, control):
    omega = n * RPM
    r = solve(b7011, loads, omega, control=control)
    assert r.converged
    b = r.balls
    g = b7011.ball_diameter / b7011.pitch_diameter
    ai, ao = b["inner_contact_angle_rad"], b["outer_contact_angle_rad"]
    if control == "outer":
        wm = (1 - g * np.cos(ai)) / (1 + np.cos(ai - ao))
        tb = np.sin(ao) / (np.cos(ao) + g)
    else:
        wm = (np.cos(ai - ao) - g * np.cos(ao)) / (1 + np.cos(ai - ao))
        tb = np.sin(ai) / (np.cos(ai) - g)
    cb = 1 / np.sqrt(1 + tb * tb)
    wr = -1 / (g * cb * ((np.cos(ao) + tb * np.sin(ao)) / (1 + g * np.cos(ao))
                         + (np.cos(ai) + tb * np.sin(ai)) / (1 - g * np.cos(ai))))
    assert_allclose(b["orbital_speed_rad_s"] / omega, wm, rtol=1e-12, err_msg=SRC2 + " (omega_m)")
    assert_allclose(np.tan(b["pitch_angle_rad"]), tb, rtol=1e-12, err_msg=SRC2 + " (beta)")
    assert_allclose(b["spin_speed_rad_s"] / omega, wr, rtol=1e-12, err_msg=SRC2 + " (omega_R)")


def test_cage_speed_and_zero_speed(b7011):
    """Cage speed lies among the loaded balls' orbital speeds, near the epicyclic value
    ω(1 − γ cos α)/2 (Harris & Kotzalas 2007 vol. 1 ch. 8); at n = 0 every speed is zero."""
    omega = 6000 * RPM
    r = solve(b7011, Loads(fa=2000.0, fr_y=700.0), omega)
    wm = r.balls["orbital_speed_rad_s"][r.balls["inner_load_N"] > 0]
    assert wm.min() - 1e-12 <= r.cage_speed <= wm.max() + 1e-12, SRC2 + " (cage speed among the balls' omega_m)"
    a = r.balls["inner_contact_angle_rad"].mean()
    epicyclic = 0.5 * omega * (1 - b7011.ball_diameter * math.cos(a) / b7011.pitch_diameter)
    assert_allclose(r.cage_speed, epicyclic, rtol=0.01, err_msg="Harris & Kotzalas 2007 vol. 1 ch. 8 cage speed")
    r0 = solve(b7011, Loads(fa=2000.0, fr_y=700.0), 0.0)
    assert np.all(r0.balls["orbital_speed_rad_s"] == 0) and np.all(r0.balls["spin_speed_rad_s"] == 0), SRC2
    assert r0.cage_speed == 0.0, SRC2


def test_gyroscopic_moment(b7011):
    """M_g = J ω_R ω_m sin β, J = m D²/10 (seed 000 eq. 11), magnitude checked per ball."""
    omega = 11000 * RPM
    r = solve(b7011, Loads(fa=1000.0), omega)
    b = r.balls
    m = b7011.ball_material.density * math.pi * b7011.ball_diameter**3 / 6
    j = m * b7011.ball_diameter**2 / 10
    mg = j * np.abs(b["spin_speed_rad_s"] * b["orbital_speed_rad_s"]) * np.sin(b["pitch_angle_rad"])
    assert_allclose(np.abs(b["gyroscopic_moment_N_m"]), mg, rtol=1e-10, err_msg="seed 000 eq. 11 (Mg)")


@pytest.mark.parametrize("control", ["outer", "inner"])
@pytest.mark.parametrize("loads, n", CASES)
def test_ball_free_body_with_gyroscopic_couple(b7011, loads, n, control):
    """Each ball is in equilibrium under the two contact forces, F_c and the gyroscopic couple.

    Derived here from the free body (not copied from the code): H = J(ω_m e_x + ω_R(cos β e_x −
    sin β e_r)) with e_r turning at ω_m, so dH/dt = −J ω_R ω_m sin β e_t = J|ω_R| ω_m sin β e_t; the
    raceways supply it by friction forces tangent to the contacts, λ M_g/D each (outer control
    λ_o = 2, λ_i = 0; inner control λ_o = λ_i = 1; seed 000 eq. 10).  A tangential force F at the
    outer contact (D/2)(sin α_o, cos α_o) gives the couple +e_t when it points along (−cos α_o, sin α_o);
    at the inner contact −(D/2)(sin α_i, cos α_i) along (cos α_i, −sin α_i).  Normal forces push the
    ball towards each groove centre: +Q_i(sin α_i, cos α_i) and −Q_o(sin α_o, cos α_o); F_c outward.
    """
    omega = n * RPM
    r = solve(b7011, loads, omega, control=control)
    assert r.converged
    b = r.balls
    d = b7011.ball_diameter
    m = b7011.ball_material.density * math.pi * d**3 / 6
    jb = m * d * d / 10
    mg = -jb * b["spin_speed_rad_s"] * b["orbital_speed_rad_s"] * np.sin(b["pitch_angle_rad"])
    assert np.all(mg > 0), "J|w_R| w_m sin(beta) > 0 with w_R < 0 (Jones)"
    g = mg / d
    lam_i = np.where(b["inner_control"] == 1, 1.0, 0.0)
    lam_o = 2.0 - lam_i
    si, ci = np.sin(b["inner_contact_angle_rad"]), np.cos(b["inner_contact_angle_rad"])
    so, co = np.sin(b["outer_contact_angle_rad"]), np.cos(b["outer_contact_angle_rad"])
    qi, qo, fc = b["inner_load_N"], b["outer_load_N"], b["centrifugal_force_N"]
    rx = qi * si - qo * so + lam_i * g * ci - lam_o * g * co
    rr = qi * ci - qo * co - lam_i * g * si + lam_o * g * so + fc
    scale = qo.max()
    src = "ball free body, seed 000 eq. 10 with dH/dt of Jones' ball spin"
    assert_allclose(rx / scale, 0.0, atol=1e-9, err_msg=src + " (axial)")
    assert_allclose(rr / scale, 0.0, atol=1e-9, err_msg=src + " (radial)")
    assert_allclose(np.abs(b["gyroscopic_moment_N_m"]), mg, rtol=1e-10, err_msg=src + " (M_g)")
