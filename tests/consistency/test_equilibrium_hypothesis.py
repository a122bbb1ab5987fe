"""Every result called converged is an equilibrium, and the single and batch paths agree (issue 11 item 6).

Operating points are drawn over the whole domain: the three catalogue single rows (SKF 7011 CDGA/HC,
Harris' 218, the seed 001 hub row) and 6205/6208-like deep-groove bearings with clearance; axial loads
from pulling (−30 %) to past capacity, radial loads and moments in any direction from 0.1 % to 200 % of
a capacity scale; speeds from rest to 1.5× a limiting speed (n·d_m = 1e6 mm·rpm, an oil-lubricated
ball-bearing speed factor); outer, inner and auto raceway control.  Each draw is a short path of points
solved by ``solve_many`` (warm starts along the path, as a map does) and one by one by ``solve``.

Check (independent of the library's ring assembly and of its own check, :mod:`._recompute`): every ball
re-solved from a cold start at the returned displacement, the ring forces summed by hand; the balance
must hold to the stated tolerance ``TOL_VERIFY`` × load scale.  Both paths must agree on convergence.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

sys.path.insert(0, str(Path(__file__).parent))
from _recompute import load_scale, ring_residual  # noqa: E402

from bearingsim.io import bearing_from_dict, load_bearing  # noqa: E402
from bearingsim.statics import jones_harris as jh  # noqa: E402

NDM_LIMIT = 1.0e6  #: reference speed factor n·d_m [mm·rpm]


def _deep_groove(name, d_mm, z, dm_mm, pd_um):
    return bearing_from_dict({"name": name, "type": "deep_groove", "ball_diameter": f"{d_mm} mm", "ball_count": z,
                              "pitch_diameter": f"{dm_mm} mm", "inner_conformity": 0.52, "outer_conformity": 0.53,
                              "diametral_clearance": f"{pd_um} um", "ball_material": "bearing_steel",
                              "ring_material": "bearing_steel"})


@pytest.fixture(scope="module")
def bearings():
    return {"7011": load_bearing("skf-7011-cdga-hc"), "218": load_bearing("harris-218"),
            "hub": load_bearing("hub-seed001-row"), "6205": _deep_groove("6205-like", 7.938, 9, 38.5, 15),
            "6208": _deep_groove("6208-like", 11.906, 9, 60.0, 20)}


def _capacity(b) -> float:
    """A load scale [N] of the order of the static rating: Z D² × 10 N/mm² (ISO 76 f0 ≈ 12–14 for balls)."""
    return b.ball_count * (b.ball_diameter * 1e3) ** 2 * 10.0


point = st.tuples(st.floats(-0.3, 1.0), st.floats(-3.0, 0.3),  # axial: sign/fraction, log10 magnitude
                  st.floats(-1.0, 1.0), st.floats(-1.0, 1.0), st.floats(-3.0, 0.3),  # radial direction, log10
                  st.floats(-1.0, 1.0), st.floats(-1.0, 1.0), st.floats(-3.0, -0.5),  # moment direction, log10
                  st.floats(0.0, 1.5))  # speed / limiting speed


@settings(max_examples=50, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(name=st.sampled_from(["7011", "218", "hub", "6205", "6208"]),
       control=st.sampled_from(["outer", "inner", "auto"]), path=st.lists(point, min_size=2, max_size=5),
       at_rest=st.lists(st.booleans(), min_size=5, max_size=5))
def test_converged_results_are_equilibria_and_paths_agree(bearings, name, control, path, at_rest):
    b = bearings[name]
    cap = _capacity(b)
    dm = b.pitch_diameter
    wlim = NDM_LIMIT / (dm * 1e3) * math.pi / 30
    loads = np.array([[fa * cap * 10**la, ry * cap * 10**lr, rz * cap * 10**lr, my * cap * dm * 10**lm,
                       mz * cap * dm * 10**lm] for fa, la, ry, rz, lr, my, mz, lm, _ in path])
    speeds = np.array([0.0 if rest else p[-1] * wlim for p, rest in zip(path, at_rest)])
    batch = jh.solve_many(b, loads, speeds, control)
    rows = b.row_vectors()
    for i in range(len(path)):
        single = jh.solve(b, jh.Loads(*loads[i]), float(speeds[i]), control)
        sc = load_scale(loads[i], dm)
        for tag, conv, q in (("single", single.converged, single.displacement),
                             ("batch", batch.converged[i], batch.displacement[i])):
            if conv:
                rv, balls_ok = ring_residual(rows, loads[i], float(speeds[i]), control, q)
                assert balls_ok and rv <= jh.TOL_VERIFY * sc, \
                    f"{tag} called converged but the recomputed ring balance is off by {rv:.3g} N " \
                    f"({rv / sc:.3g} of the load scale) at loads {loads[i].tolist()}, speed {speeds[i]}"
        assert bool(single.converged) == bool(batch.converged[i]), \
            f"single {single.status_code} vs batch {batch.status[i]} at loads {loads[i].tolist()}, speed {speeds[i]}"


def test_recomputation_detects_a_non_equilibrium(bearings):
    """The checker can fail: the converged displacement moved by 0.1 % of its size is not an equilibrium."""
    b = bearings["7011"]
    r = jh.solve(b, jh.Loads(fa=3000.0, fr_y=500.0), 1000.0, "outer")
    assert r.converged
    rows = b.row_vectors()
    la = r.loads.as_array()
    rv, ok = ring_residual(rows, la, 1000.0, "outer", r.displacement)
    assert ok and rv <= jh.TOL_VERIFY * 3000.0
    q = r.displacement.copy()
    q[0] *= 1.001
    assert ring_residual(rows, la, 1000.0, "outer", q)[0] > 100 * jh.TOL_VERIFY * 3000.0
