"""Mechanism tests of bearingsim.friction: Palmgren's formulae, the exact spin/sliding split of the traction
power, the drag model, friction_summary's assembly and inputs, and the lubrication command's output."""

from __future__ import annotations

import json
import math
import subprocess

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim import friction as F
from bearingsim.contact import hertz
from bearingsim.contact import slices as S
from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.lubrication import lubrication_report
from bearingsim.statics.jones_harris import Loads, solve

RPM = math.pi / 30.0


@pytest.fixture(scope="module")
def spindle():
    b = load_bearing("skf-7011-cdga-hc")
    return solve(b, Loads(fa=1000.0), 10000 * RPM)


@pytest.fixture(scope="module")
def hub():
    b = load_bearing("hub-seed001")
    return solve(b, Loads(fa=3000.0, fr_y=4000.0), 1000 * RPM)


# ---------------------------------------------------------------------------------------- Palmgren


def test_palmgren_viscous_scaling_and_branches():
    b = load_bearing("skf-7011-cdga-hc")
    nu = 20e-6
    m1 = F.palmgren_torque(b, 0.0, 1000.0, 3000 * RPM, nu, "oil_bath")
    m2 = F.palmgren_torque(b, 0.0, 1000.0, 6000 * RPM, nu, "oil_bath")
    # M_v ∝ (ν n)^(2/3) above ν n = 2000 mm²/s·rpm
    assert m2["viscous_N_m"] / m1["viscous_N_m"] == pytest.approx(2.0 ** (2.0 / 3.0), rel=1e-12)
    # the two branches nearly meet at ν n = 2000: 1e-7·2000^(2/3) = 158.7e-7 against 160e-7 (0.8 % step)
    n_switch = 2000.0 / (nu * 1e6)
    lo = F.palmgren_torque(b, 0.0, 1000.0, 0.999999 * n_switch * RPM, nu)["viscous_N_m"]
    hi = F.palmgren_torque(b, 0.0, 1000.0, 1.000001 * n_switch * RPM, nu)["viscous_N_m"]
    assert hi / lo == pytest.approx(2000.0 ** (2.0 / 3.0) / 160.0, rel=1e-5)
    # f0: the jet column is twice the oil bath for angular contact (6.6 vs 3.3), and the torque follows f0
    jet = F.palmgren_torque(b, 0.0, 1000.0, 3000 * RPM, nu, "oil_jet")
    assert jet["viscous_N_m"] / m1["viscous_N_m"] == pytest.approx(2.0, rel=1e-12)
    # no rotation, no viscous torque; the load term does not depend on speed
    m0 = F.palmgren_torque(b, 0.0, 1000.0, 0.0, nu)
    assert m0["viscous_N_m"] == 0.0 and m0["load_N_m"] == m1["load_N_m"]


def test_palmgren_load_term():
    b = load_bearing("skf-7011-cdga-hc")
    p = F.palmgren_torque(b, 0.0, 2000.0, 1000 * RPM)
    assert p["viscous_N_m"] is None
    # angular contact: P1 = 0.9 Fa cot α (Fr = 0), f1 = 0.001 (P0/C0)^0.33, M_l = f1 P1 d_m
    assert p["P1_N"] == pytest.approx(0.9 * 2000.0 / math.tan(b.contact_angle), rel=1e-12)
    assert p["f1"] == pytest.approx(0.001 * (p["P0_N"] / p["C0_N"]) ** 0.33, rel=1e-12)
    assert p["load_N_m"] == pytest.approx(p["f1"] * p["P1_N"] * b.pitch_diameter, rel=1e-12)
    # a radial load larger than the axial share takes over P1
    q = F.palmgren_torque(b, 5000.0, 100.0, 1000 * RPM)
    assert q["P1_N"] == 5000.0


@settings(max_examples=60, deadline=None)
@given(fr=st.floats(0.0, 2e4), fa=st.floats(0.0, 2e4), dfa=st.floats(1.0, 5e3), rpm=st.floats(10.0, 3e4),
       nu=st.floats(1e-6, 5e-4), deep=st.booleans())
def test_palmgren_monotone(fr, fa, dfa, rpm, nu, deep):
    """More axial load never lowers the load torque (P1 and P0 grow with Fa); more speed or viscosity never
    lowers the viscous torque; both are finite and ≥ 0."""
    b = load_bearing("skf-7011-cdga-hc")
    if deep:
        import dataclasses

        b = dataclasses.replace(b, kind="deep_groove", contact_angle=0.0, diametral_clearance=10e-6)
    p = F.palmgren_torque(b, fr, fa, rpm * RPM, nu)
    q = F.palmgren_torque(b, fr, fa + dfa, rpm * RPM, nu)
    assert 0.0 <= p["load_N_m"] <= q["load_N_m"] and math.isfinite(q["load_N_m"])
    faster = F.palmgren_torque(b, fr, fa, 1.5 * rpm * RPM, nu)["viscous_N_m"]
    thicker = F.palmgren_torque(b, fr, fa, rpm * RPM, 1.5 * nu)["viscous_N_m"]
    assert 0.0 < p["viscous_N_m"] <= min(faster, thicker)


def test_palmgren_uses_the_project_iso76_figures():
    """P0 and the C0 estimate are the ones of safety.py / life.py (one formula each); a C0 in the file wins."""
    import dataclasses

    from bearingsim.life import static_rating_estimate
    from bearingsim.safety import equivalent_static_load

    b = load_bearing("skf-7011-cdga-hc")
    p = F.palmgren_torque(b, 800.0, 2000.0, 1000 * RPM)
    assert p["C0_estimated"] and p["C0_N"] == static_rating_estimate(b)[0]
    assert p["P0_N"] == equivalent_static_load(800.0, 2000.0, b.contact_angle, 1, "angular_contact")
    given = dataclasses.replace(b, static_load_rating=20e3)
    q = F.palmgren_torque(given, 800.0, 2000.0, 1000 * RPM)
    assert not q["C0_estimated"] and q["C0_N"] == 20e3
    assert q["load_N_m"] / p["load_N_m"] == pytest.approx((p["C0_N"] / 20e3) ** 0.33, rel=1e-12)
    # an angle beyond ISO 76's table is clamped to 45°
    steep = dataclasses.replace(b, contact_angle=math.radians(60.0))
    r = F.palmgren_torque(steep, 0.0, 2000.0, 1000 * RPM)
    assert r["P0_N"] == pytest.approx(equivalent_static_load(0.0, 2000.0, math.radians(45.0)), rel=1e-12)


# ---------------------------------------------------------------------------------------- physics


def test_traction_power_splits_exactly_into_spin_and_sliding():
    """P_traction = −F·s₀ − ω_rel·M_c for any kinematics (the identity the split rests on), here with centre
    sliding, spin and a curved contact surface; M_c from the kernel's moment about the ball centre."""
    e = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
    rx, ry = hertz.raceway_radii(0.01, 0.06, 0.52, math.radians(25), True)
    q = 1500.0
    hz = hertz.point_contact_exact(q, rx, ry, e)
    lub = S.pack_lubrication_parameters("iso-vg-68", 333.15, e, rx, ry, 0.1e-6, rolling_resistance=False)
    r_dev = S.deformed_surface_radius(0.01, 0.0052)
    n = np.array([0.0, 0.0, 1.0])
    major = np.array([1.0, 0.0, 0.0])
    cb = np.array([0.0, 0.0, 0.005])
    cr = np.array([0.0, 0.0, -0.03])
    wb = np.array([-3.0, 2000.0, 40.0])  # spin about n and a tilt of the rolling axis
    vb = np.array([0.0, 0.0, 0.0])
    wr = np.array([0.0, -1.0 / 0.03 * 10.0 * 0.99, 0.0])  # ≈ 1 % centre sliding against the ball's rolling
    out = np.zeros(10)
    centre = np.zeros(3)
    S.contact_traction(q, hz.a, hz.b, r_dev, centre, n, major, cb, vb, wb, cr, np.zeros(3), wr, lub, 10, out)
    f, mb, power = out[0:3], out[3:6], out[9]
    s0 = (vb + np.cross(wb, centre - cb)) - np.cross(wr, centre - cr)
    s0 -= (s0 @ n) * n
    mc = mb - np.cross(centre - cb, f)
    w_rel = wb - wr
    assert power > 0 and abs(f @ s0) > 1e-3 * power  # both parts present
    assert -(f @ s0) - (w_rel @ mc) == pytest.approx(power, rel=1e-9)
    # the spin part uses n·M_b = n·M_c (the contact centre lies on the normal through the ball centre)
    assert n @ mb == pytest.approx(n @ mc, rel=1e-12)


def test_physical_losses_sum_to_lubrication_report(spindle, hub):
    for res, lub, t in ((spindle, "iso-vg-68", 333.15), (hub, "hub-grease-base-oil", 333.15)):
        rep = lubrication_report(res, lub, t, 0.1e-6)
        c = F.contact_losses(res, lub, t, 0.1e-6)
        assert c["rolling_W"] + c["spin_W"] + c["sliding_W"] == pytest.approx(rep["total_power_loss_W"], rel=1e-9)
        assert c["rolling_W"] > 0 and c["spin_W"] > 0 and c["sliding_W"] >= -1e-9 * rep["total_power_loss_W"]
        # EHL rolling alone: the kernel's losses without rolling resistance are the traction part
        no_rr = sum(_traction_only(res, lub, t))
        assert c["spin_W"] + c["sliding_W"] == pytest.approx(no_rr, rel=1e-9)


def _traction_only(res, lub, t):
    """Per contact power of the kernel without rolling resistance, built independently of friction.py."""
    from bearingsim.lubrication import contact_at_jones_kinematics

    bl = res.balls
    rows = [getattr(r, "bearing", r) for r in getattr(res.bearing, "rows", [res.bearing])]
    for j in range(len(bl["row"])):
        rb = rows[int(bl["row"][j])]
        for inner in (True, False):
            q = bl["inner_load_N" if inner else "outer_load_N"][j]
            if not q > 0:
                continue
            a = bl["inner_contact_angle_rad" if inner else "outer_contact_angle_rad"][j]
            f = rb.inner_conformity if inner else rb.outer_conformity
            rx, ry = hertz.raceway_radii(rb.ball_diameter, rb.pitch_diameter, f, a, inner)
            hz = hertz.point_contact_exact(q, rx, ry, rb.effective_modulus)
            lp = S.pack_lubrication_parameters(lub, t, rb.effective_modulus, rx, ry, 0.1e-6, rolling_resistance=False)
            k, _, _ = contact_at_jones_kinematics(
                lp, q, hz.a, hz.b, S.deformed_surface_radius(rb.ball_diameter, f * rb.ball_diameter),
                rb.ball_diameter, rb.pitch_diameter, bl["inner_contact_angle_rad"][j], bl["outer_contact_angle_rad"][j],
                res.speed, bl["orbital_speed_rad_s"][j], bl["spin_speed_rad_s"][j], bl["pitch_angle_rad"][j], inner, 10)
            yield k[9]


def test_drag_model():
    # Schiller–Naumann meets the Newton value 0.44 at Re = 1000 within 0.4 %
    assert F.sphere_drag_coefficient(999.999) == pytest.approx(0.44, rel=4e-3)
    assert F.sphere_drag_coefficient(1e-4) == pytest.approx(24.0 / 1e-4, rel=1e-3)  # Stokes
    # Newton regime: power ∝ v³
    p1 = F.ball_drag_power(0.01, 0.06, 2000.0, 0.01, 850.0, 0.01, 333.15)
    p2 = F.ball_drag_power(0.01, 0.06, 4000.0, 0.01, 850.0, 0.01, 333.15)
    assert p2 / p1 == pytest.approx(8.0, rel=1e-12)
    # Parker's oil fraction: X ∝ w^0.37 / (n d_m^1.7)
    x1 = F.parker_oil_fraction(760e-6 / 60, 28000 * RPM, 0.0465)
    assert F.parker_oil_fraction(2 * 760e-6 / 60, 28000 * RPM, 0.0465) / x1 == pytest.approx(2**0.37, rel=1e-12)
    assert F.parker_oil_fraction(760e-6 / 60, 56000 * RPM, 0.0465) / x1 == pytest.approx(0.5, rel=1e-12)
    with pytest.raises(InputError, match="oil_flow"):
        F.parker_oil_fraction(-1.0, 100.0, 0.05)


# ---------------------------------------------------------------------------------------- summary


def test_summary_torque_is_power_over_speed(spindle):
    s = F.friction_summary(spindle, "iso-vg-68", 333.15, oil_volume_fraction=0.01)
    w = abs(spindle.speed)
    for src in ("rolling", "spin", "sliding", "drag"):
        assert s[f"{src}_N_m"] * w == pytest.approx(s[f"{src}_W"], rel=1e-12)
    assert s["physical_power_W"] == pytest.approx(sum(s[f"{k}_W"] for k in ("rolling", "spin", "sliding", "drag")),
                                                  rel=1e-12)
    assert s["palmgren_torque_N_m"] == pytest.approx(s["palmgren_load_N_m"] + s["palmgren_viscous_N_m"], rel=1e-12)
    assert (s["friction_torque_N_m"], s["power_loss_W"]) == (s["palmgren_torque_N_m"], s["palmgren_power_W"])
    p = F.friction_summary(spindle, "iso-vg-68", 333.15, model="physical")
    assert p["headline_model"] == "physical" and p["palmgren_torque_N_m"] is None
    assert p["drag_W"] is None and any("drag" in n for n in p["notes"])
    assert p["friction_torque_N_m"] == pytest.approx(s["physical_torque_N_m"] - s["drag_N_m"], rel=1e-12)
    json.dumps(s)  # JSON-ready


def test_summary_without_lubricant(spindle):
    s = F.friction_summary(spindle)
    assert s["palmgren_viscous_N_m"] is None and s["rolling_N_m"] is None
    assert s["friction_torque_N_m"] == s["palmgren_load_N_m"] > 0
    assert any("no lubricant" in n for n in s["notes"])


def test_summary_rows_of_a_system(hub):
    s = F.friction_summary(hub, "hub-grease-base-oil", 333.15, lubrication_method="grease")
    assert len(s["palmgren_rows"]) == 2
    assert s["palmgren_load_N_m"] == pytest.approx(sum(r["load_N_m"] for r in s["palmgren_rows"]), rel=1e-12)
    # the rows' loads are the solve's row forces: the axial ones balance the external 3 kN
    fa = [r[0] for r in hub.row_forces]
    assert sum(fa) == pytest.approx(3000.0, rel=1e-6)


def test_summary_speed_sign(spindle):
    b = spindle.bearing
    neg = solve(b, Loads(fa=1000.0), -spindle.speed)
    a = F.friction_summary(spindle, "iso-vg-68", 333.15)
    c = F.friction_summary(neg, "iso-vg-68", 333.15)
    for k in ("palmgren_torque_N_m", "rolling_W", "spin_W", "sliding_W"):
        assert c[k] == pytest.approx(a[k], rel=1e-6), k


def test_summary_bad_input(spindle):
    with pytest.raises(InputError, match="model"):
        F.friction_summary(spindle, model="palmgrn")
    with pytest.raises(InputError, match="lubrication_method"):
        F.friction_summary(spindle, lubrication_method="splash")
    with pytest.raises(InputError, match="temperature"):
        F.friction_summary(spindle, "iso-vg-68")
    with pytest.raises(InputError, match="oil_volume_fraction"):
        F.friction_summary(spindle, "iso-vg-68", 333.15, oil_volume_fraction=1.5)


# ---------------------------------------------------------------------------------------- CLI


def test_cli_lubrication_friction_matches_api(spindle):
    cmd = ["bearingsim", "lubrication", "skf-7011-cdga-hc", "--fa", "1 kN", "--speed", "10000 rpm",
           "--temperature", "60 degC", "--oil-flow", "1 l/min", "--json"]
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert p.returncode == 0, p.stderr
    fr = json.loads(p.stdout)["friction"]
    api = F.friction_summary(spindle, "iso-vg-68", 333.15, oil_flow=1e-3 / 60)
    for k in ("friction_torque_N_m", "power_loss_W", "palmgren_viscous_N_m", "rolling_N_m", "spin_N_m", "drag_N_m"):
        assert fr[k] == pytest.approx(api[k], rel=1e-9), k
    bad = subprocess.run(cmd[:-3] + ["--oil-flow", "3 kg"], capture_output=True, text=True, timeout=300)
    assert bad.returncode == 2 and "--oil-flow" in bad.stderr + bad.stdout
