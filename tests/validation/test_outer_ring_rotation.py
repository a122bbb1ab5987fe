"""A bearing whose outer ring turns (the inner ring standing): ball speeds, centrifugal force and gyroscopic moment
against the closed forms of ball-bearing kinematics, the kernel's tangent against finite differences, and a shaft
support with ``rotating_ring = "outer"``.

References: Harris & Kotzalas, *Essential Concepts of Bearing Technology* (2007), ch. 8 (cage speed of a ball
bearing with both rings turning: ω_c = ½[ω_i (1 − γ) + ω_o (1 + γ)], γ = D cos α / d_m, pure rolling) and
*Advanced Concepts* ch. 2–3 (centrifugal force F_c = ½ m d_m ω_m², gyroscopic moment M_g = J ω_R ω_m sin β).
"""

import math

import numpy as np
import pytest

from bearingsim.geometry import with_rotating_ring
from bearingsim.io import load_bearing
from bearingsim.statics import _kernels as kn
from bearingsim.statics import jones_harris as jh

RPM = math.pi / 30.0
KIN = "Harris & Kotzalas 2007, Essential Concepts ch. 8: cage speed ½[ω_i(1 − γ) + ω_o(1 + γ)]"
INERTIA = "Harris & Kotzalas 2007, Advanced Concepts ch. 3: F_c = ½ m d_m ω_m², M_g = J ω_R ω_m sin β"


@pytest.fixture(scope="module")
def b7011():
    return load_bearing("7011-15")


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_cage_speed_at_low_speed_is_the_pure_rolling_closed_form(b7011, ring):
    """At 10 rpm under a pure axial load both contact angles are equal (to ~1e-9: the centrifugal term is
    negligible), so Jones' speeds reduce to the textbook cage speed of the ring that turns."""
    w = 10 * RPM
    r = jh.solve(b7011, jh.Loads(fa=1000.0), w, rotating_ring=ring)
    assert r.converged, r.status
    a = r.balls["inner_contact_angle_rad"]
    np.testing.assert_allclose(a, r.balls["outer_contact_angle_rad"], atol=1e-7)
    g = b7011.ball_diameter * np.cos(a) / b7011.pitch_diameter
    want = w * (1 - g) / 2 if ring == "inner" else w * (1 + g) / 2
    np.testing.assert_allclose(r.balls["orbital_speed_rad_s"], want, rtol=1e-6, err_msg=KIN)
    assert r.to_dict()["rotating_ring"] == ring


@pytest.mark.parametrize("ring", ["inner", "outer"])
def test_centrifugal_force_and_gyroscopic_moment_follow_the_orbit_of_the_turning_ring(b7011, ring):
    """At 15,000 rpm: the kernel's ball forces equal the closed forms evaluated with the ball table's speeds."""
    r = jh.solve(b7011, jh.Loads(fa=1000.0), 15000 * RPM, rotating_ring=ring)
    assert r.converged, r.status
    m, dm, j = b7011.ball_mass, b7011.pitch_diameter, b7011.ball_inertia
    wm, wr, beta = (r.balls[k] for k in ("orbital_speed_rad_s", "spin_speed_rad_s", "pitch_angle_rad"))
    np.testing.assert_allclose(r.balls["centrifugal_force_N"], 0.5 * m * dm * wm ** 2, rtol=1e-9, err_msg=INERTIA)
    # the kernel's moment is the one the raceways apply to the ball, −J ω_R ω_m sin β
    np.testing.assert_allclose(r.balls["gyroscopic_moment_N_m"], -j * wr * wm * np.sin(beta), rtol=1e-9,
                               err_msg=INERTIA)


def test_outer_ring_turning_loads_the_balls_harder(b7011):
    """The cage of a turning outer ring orbits faster, ((1 + γ)/(1 − γ))² more centrifugal force (1.6–1.8 for
    γ ≈ 0.13), and the ball's spin relative to the cage reverses, so the gyroscopic moment changes sign."""
    ri = jh.solve(b7011, jh.Loads(fa=1000.0), 15000 * RPM, rotating_ring="inner")
    ro = jh.solve(b7011, jh.Loads(fa=1000.0), 15000 * RPM, rotating_ring="outer")
    g = b7011.ball_diameter * math.cos(b7011.contact_angle) / b7011.pitch_diameter
    ratio = ro.balls["centrifugal_force_N"].mean() / ri.balls["centrifugal_force_N"].mean()
    assert abs(ratio / ((1 + g) / (1 - g)) ** 2 - 1) < 0.05, ratio
    assert np.all(np.sign(ro.balls["gyroscopic_moment_N_m"]) == -np.sign(ri.balls["gyroscopic_moment_N_m"]))
    assert ro.balls["outer_load_N"].mean() > ri.balls["outer_load_N"].mean()


def test_at_rest_the_turning_ring_does_not_matter(b7011):
    ri = jh.solve(b7011, jh.Loads(fa=800.0, fr_y=500.0), 0.0)
    ro = jh.solve(b7011, jh.Loads(fa=800.0, fr_y=500.0), 0.0, rotating_ring="outer")
    np.testing.assert_array_equal(ro.displacement, ri.displacement)


@pytest.mark.parametrize("inner_ctrl", [0, 1])
def test_ball_tangent_with_the_outer_ring_turning_matches_finite_differences(b7011, inner_ctrl):
    """Consistency: the analytic ball Jacobian of ``ball_eval`` with ``orot = 1`` against central differences."""
    par = with_rotating_ring(b7011, "outer").row_vectors()[0]
    assert par[kn.P_OROT] == 1.0
    cg, cf = kn.ball_speed_constants(par, (15000 * RPM) ** 2)
    lam_i, lam_o = kn.control_weights(inner_ctrl)
    ri, ro, ki, ko = par[kn.P_RI], par[kn.P_RO], par[kn.P_KI], par[kn.P_KO]
    gam = par[kn.P_D] / par[kn.P_DM]
    a = np.array([par[kn.P_DX0] + 8e-6, par[kn.P_DR0] + 2e-6])
    x = np.array([0.0, 0.0])
    out, jac = np.zeros(10), np.zeros((5, 4))
    kn.ball_solve(a[0], a[1], par, cg, cf, lam_i, lam_o, inner_ctrl, x, out, jac, 1e-12, 60)
    p0 = np.array([x[0] + 1e-7, x[1] - 1e-7, a[0], a[1]])

    def f(p):
        o, jj = np.zeros(10), np.zeros((5, 4))
        kn.ball_eval(p[0], p[1], p[2], p[3], ri, ro, ki, ko, gam, cg, cf, lam_i, lam_o, inner_ctrl, o, jj, 1.0)
        return np.array([o[0], o[1], o[2], o[3], o[8]]), jj

    _, jac0 = f(p0)
    h = 1e-10
    fd = np.column_stack([(f(p0 + h * e)[0] - f(p0 - h * e)[0]) / (2 * h) for e in np.eye(4)])
    np.testing.assert_allclose(jac0, fd, rtol=2e-5, atol=2e-5 * np.abs(fd).max())


def test_shaft_support_with_the_outer_ring_turning_solves_the_bearing_so(b7011):
    """A support with ``rotating_ring = "outer"`` carries a bearing whose outer ring turns (no warning that it
    does not), and its result equals the single bearing solved with the outer ring turning at the same ring
    displacement."""
    from bearingsim.shafts import BearingSupport, PointLoad, Section, ShaftSystem, SpringSupport

    sup = BearingSupport("hub", 0.05, b7011, rotating_ring="outer")
    assert sup.bearing.rotating_ring == "outer"
    sysm = ShaftSystem((Section(0.1, 0.04),), (sup, SpringSupport("s2", 0.1, np.full(5, 1e9))), name="s",
                       loads=(PointLoad(0.1, (-800.0, 300.0, 0.0)),))
    from bearingsim.shafts.solve import solve_shaft

    r = solve_shaft(sysm, speed=8000 * RPM)
    assert r.converged, r.status
    assert not any("outer ring rotates" in w for w in r.warnings)
    br = r.supports[0].bearing_result
    assert br.to_dict()["rotating_ring"] == "outer"
    ref = jh.result_at(with_rotating_ring(b7011, "outer"), r.supports[0].ring_displacement, 8000 * RPM)
    np.testing.assert_allclose(br.balls["centrifugal_force_N"], ref.balls["centrifugal_force_N"], rtol=1e-12)
