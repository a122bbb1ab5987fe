"""Zero reference of the hub hysteresis (issue 13 item 6) that holds: the [S1] hub case
(examples/hub-moment-50hz.toml, 100 km/h, Table 2 loads) with every ball held at its azimuth by a frictionless
constraint (``ball_orbit = "held"``), loads at 100 Hz.

Why W_H = 0 exactly there: without traction, cage friction and contact damping, every force left is a
contact normal force that depends on positions only (Hertz), plus the inner ring's gyroscopic moment
I_p Ω × γ̇, which does no work.  The balls' only motion left is in their own radial plane (their spin does not
enter frictionless forces).  Such a system is conservative and is invariant under time reversal combined with
the mirror z → −z (the mirror in the load plane x–y reverses the spin Ω about x, time reversal reverses it back;
the ball set, ψ_j = 2πj/16 in both rows, is symmetric about ψ = 0).  The loads lie in that plane (F_a, F_r along y,
M about z) and are even about the peak, M(T/2 − t) = M(t), so the periodic response that continues the
quasi-static one is even too: γz(T/2 − t) = γz(t).  The rising and falling crossings of M = 0.3 kN·m are mirror
instants, so W_H = 0 and the loop area ∮ M dγz = 0.  (A linearised check: the in-plane response to in-plane
sine loads of M q̈ + G q̇ + K q = F with G skew and a mirror symmetry is (K − ω²M + B K_oo⁻¹ B)⁻¹ F, real: in phase.)

What is NOT a zero reference (tests/consistency/test_hub_zero_reference.py): the same frictionless case with the
balls free to orbit.  Nothing holds them along the groove; the tilting ring pushes them along it and against the
cage pockets, the loads do 6–22 mJ of work per cycle on that motion and the response never becomes periodic.

What this zero reference resolves (measured 2026-11-27, the per-vector error scale of issue 14 and the commit
before it): over 18 cycles (20 run) W_H = 0.021 [0.002, 0.041]·10⁻³ ° (per-component error scale) and 0.018
[0.003, 0.033] (per-vector); over the test's 6 cycles 0.012 [−0.036, 0.060] and 0.024 [0.001, 0.046]; at tol
1e-7 0.017 / 0.022, at 3e-6 0.030 [0.009, 0.051] / 0.026.  So the chain (model, DOPRI5, estimator) leaves a
residual of ≈ 0.02·10⁻³ ° that does not shrink with the tolerance — not the integrator's — and that a 6-cycle
interval contains or not as the rounding moves the trajectory.  The test therefore asks for what holds: the
mean within 0.05·10⁻³ ° and the whole interval within ±0.06·10⁻³ °, less than half the lower end of the
interval the traction gives in the same setup (0.125 below).  The residual's source is an open item
(docs/development/history.md, sixth pass); not the start's ringing: with a 10 or 30 ms ramp-in of the load variation 20
cycles give 0.013 [−0.004, 0.030] and 0.026 [−0.001, 0.053]·10⁻³ °, the same per-cycle scatter (±0.05); nor
the held-ball constraint's work (with held balls the energy test's row conserves energy as with free ones).

Why 100 Hz and not 200 Hz: the hub's tilt mode (≈ 1.15 kHz here) is undamped in this run; at 200 Hz it is close
to the 6th load harmonic (5.75 f) and the fifth harmonic was resonantly amplified (2.6·10⁻³ °), the start left a
0.4–0.6·10⁻³ ° ringing and W_H scattered 0.6…−0.07 per cycle with positive loop areas (measured).  At 100 Hz
(11.5 f) eight cycles gave W_H per cycle −0.028 … +0.058·10⁻³ °, mean 0.006, interval [−0.035, 0.047]·10⁻³ °.

The same held case WITH the lubricated traction (the case's sliced kernel; the balls then slide at the ring's
surface speed, and the major-axis traction resists their motion in the radial plane, [S1] §5) lags:
0.152, 0.164, 0.145, 0.126, 0.144, 0.119, 0.128·10⁻³ °, mean 0.140 [0.125, 0.154] over 7 cycles — so the test
of the zero can fail: a dissipative mechanism in the same setup gives an interval far from 0.

Measured wall times (shared 2-core machine, load ≈ 4): frictionless 8 cycles 31 s; with traction 8 cycles 109 s, so
≈ 55 s for the 4 the test runs.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"
FREQ = 100.0


def _case(cycles: int, **changes):
    from bearingsim.dynamics.case import case_from_dict
    from bearingsim.io import read_toml

    d = read_toml(EXAMPLE, "case")
    d["duration"] = f"{cycles / FREQ!r} s"
    d["output_interval"] = f"{1.0 / (200.0 * FREQ)!r} s"
    for spec in d["loads"].values():
        if isinstance(spec, dict) and "frequency" in spec:
            spec["frequency"] = f"{FREQ!r} Hz"
    cage = changes.pop("cage", None)
    if cage is not None:
        d["cage"] = {**d.get("cage", {}), **cage}
    d.update(changes)
    if d.get("traction") != "slices":
        d.pop("n_slices", None)
    return case_from_dict(d, base=EXAMPLE.parent)


def _mdeg(x):
    return math.degrees(x) * 1e3


@pytest.fixture(scope="module")
def held_frictionless():
    """No traction, cage friction 0, contact damping 0, balls held: 8 load cycles at 100 Hz (80 ms)."""
    from bearingsim.dynamics.run import simulate

    return simulate(_case(8, traction="none", contact_damping=0.0, cage={"friction": 0.0}, ball_orbit="held"))


def test_held_balls_do_not_orbit(held_frictionless):
    """The constraint holds: every ball's orbital speed is zero at every sample (to rounding of the velocity
    projection, ≪ the 36 rad/s the balls orbit at when free)."""
    (wm,) = held_frictionless.read("ball_orbital_speed")
    assert wm.shape[1] == 32
    assert np.max(np.abs(wm)) < 1e-9, np.max(np.abs(wm))


def test_frictionless_undamped_held_run_has_no_loop(held_frictionless):
    """The zero reference: the estimator's own periodicity criterion holds, the 95 % interval of the loop area
    contains 0, that of W_H lies within ±0.06·10⁻³ ° and its mean within 0.05·10⁻³ ° (a third of the lag the
    traction gives below; the module docstring says why not "the interval contains 0")."""
    e = held_frictionless.hysteresis(300.0, frequency=FREQ)
    assert e.cycles_total == 8
    assert e.cycles_used >= 5, (e.status, e.change)
    lo, hi = e.ci95
    assert -0.06 < _mdeg(lo) and _mdeg(hi) < 0.06, (_mdeg(e.mean), _mdeg(lo), _mdeg(hi))
    assert abs(_mdeg(e.mean)) < 0.05, _mdeg(e.mean)
    alo, ahi = e.loop_area_ci95
    assert alo < 0.0 < ahi, (e.loop_area, alo, ahi)
    # the compliance is the hub's (statics 0.102 °/kN·m; undamped dynamic amplification below 1 % at f/f_n ≈ 0.09)
    assert math.degrees(e.compliance) * 1e3 == pytest.approx(0.102, rel=0.02)


def test_same_held_run_with_traction_lags():
    """The same held case with the case's lubricated traction, 4 cycles: the periodicity criterion holds from cycle 1
    (changes 1.2–8.4·10⁻⁴ over 8 cycles), so 3 are used; their widths (0.152, 0.164, 0.145 in the 8-cycle run) put
    even the 3-cycle t-interval near [0.13, 0.18]·10⁻³ °, far above the 0.05 asserted."""
    from bearingsim.dynamics.run import simulate

    res = simulate(_case(4, contact_damping=0.0, cage={"friction": 0.0}, ball_orbit="held"))
    e = res.hysteresis(300.0, frequency=FREQ, min_cycles=3)
    assert e.cycles_used >= 3, (e.status, e.change)
    assert e.ci95[0] > 0.05e-3 * math.pi / 180.0, (_mdeg(e.mean), [_mdeg(x) for x in e.ci95])
    assert e.phase_lag > 0 and e.loop_area > 0


def test_ball_orbit_option_is_checked():
    from bearingsim.errors import InputError

    with pytest.raises(InputError, match="ball_orbit"):
        _case(1, ball_orbit="locked")
