"""Dynamic engine: steady state under a constant axial load gives Jones' ball speeds.

Reference: Jones (1960) ball kinematics (outer-raceway control), as computed by the
quasi-static model (:mod:`bearingsim.statics.jones_harris`, seed 000); seed 001 §3.1:
IBDAS's ball rotation and revolution speeds closely match Jones' theory.  Tolerance
2 % (issue 5).  The run starts from speeds perturbed away from Jones' values (ball spin
−10 %, orbit −3 %, cage −5 %) so that the traction must drive the balls back.
"""

import math

import numpy as np
import pytest

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import model as md
from bearingsim.dynamics.run import Stepper
from bearingsim.io import load_bearing
from bearingsim.statics import jones_harris as jh


def _run(traction, t_end, method="dopri5"):
    b = load_bearing("skf-7011-cdga-hc")
    w = 10000 * math.pi / 30
    res = jh.solve(b, jh.Loads(fa=3000.0), w, control="outer")
    m = md.build_model(b, traction=traction, speed=(w, w, 0.0), ring_mass=2.0, damping_alpha=0.05,
                       lubricant="iso-vg-68", temperature=333.15)
    y = md.initial_state(m, res)
    for k in range(m.n_balls):
        o = md.N_RING + md.N_BALL * k
        y[o + 3:o + 6] *= 0.97
        y[o + 6:o + 9] *= 0.9
    y[m.cage_offset + 9] *= 0.95
    st = Stepper(m, fo.constant_loads(fa=3000.0), y, tol=1e-6, method=method)
    samples = []
    n = 12
    for i in range(1, n + 1):
        st.advance(i * t_end / n)
        if i >= n // 3:
            samples.append(st.sample())
    wm = np.mean([s["ball_orbital_speed"] for s in samples])
    wr = np.mean([s["ball_spin_speed"] for s in samples])
    # mean cage speed from its angle over the last 2/3 of the run: the cage rattles in its
    # pocket clearance (free flight between pocket impacts, period ≈ 0.8 ms here)
    wc = float((samples[-1]["cage_angle"] - samples[0]["cage_angle"]).mean() / (samples[-1]["time"] - samples[0]["time"]))
    return res, wm, wr, wc


@pytest.mark.parametrize("traction,t_end,method", [("coulomb", 3e-3, "dopri5"), ("slices", 1e-3, "dopri5"),
                                                   ("slices", 1e-3, "ros34w")])
def test_steady_state_ball_speeds_match_jones(traction, t_end, method):
    res, wm, wr, wc = _run(traction, t_end, method)
    np.testing.assert_allclose(wm, res.balls["orbital_speed_rad_s"].mean(), rtol=0.02,
                               err_msg=f"Jones 1960 orbital speed ({traction}); seed 001 §3.1")
    if traction == "coulomb":  # the lubricated run is too short (CI) to average the cage rattle
        np.testing.assert_allclose(wc, res.cage_speed, rtol=0.02, err_msg=f"Jones 1960 cage speed ({traction})")
    np.testing.assert_allclose(wr, res.balls["spin_speed_rad_s"].mean(), rtol=0.02,
                               err_msg=f"Jones 1960 ball spin speed ({traction})")


@pytest.mark.parametrize("traction,method", [("coulomb", "dopri5"), ("slices", "ros34w")])
def test_hub_unit_both_rows_reach_jones_speeds(traction, method):
    """Double-row hub unit of seed 001 (back-to-back, mirrored rows) at 100 km/h under a radial load
    (the lubricated kernel with the ROS34PW2 W-method is the benchmark (b) configuration)."""
    b = load_bearing("hub-seed001")
    w = 884 * math.pi / 30
    res = jh.solve(b, jh.Loads(fr_y=2800.0), w, control="outer")
    kw = {"lubricant": "hub-grease-base-oil", "temperature": 313.15} if traction == "slices" else {}
    m = md.build_model(b, traction=traction, speed=(w, w, 0.0), ring_mass=3.0, damping_alpha=0.05, **kw)
    y = md.initial_state(m, res, w)
    for k in range(m.n_balls):
        o = md.N_RING + md.N_BALL * k
        y[o + 6:o + 9] *= 0.9
    st = Stepper(m, fo.constant_loads(fr_y=2800.0), y, tol=1e-6, method=method)
    st.advance(1.5e-3)
    s = st.sample()
    for row in (0, 1):
        sel = (m.ball_row == row) & (s["inner_contact_load"] > 0)
        np.testing.assert_allclose(s["ball_spin_speed"][sel].mean(), res.balls["spin_speed_rad_s"][sel].mean(),
                                   rtol=0.02, err_msg=f"Jones 1960 spin speed, hub row {row}")
        np.testing.assert_allclose(s["ball_orbital_speed"][sel].mean(), res.balls["orbital_speed_rad_s"][sel].mean(),
                                   rtol=0.02, err_msg=f"Jones 1960 orbital speed, hub row {row}")
