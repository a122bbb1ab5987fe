"""Equal strips cut at the zeros of the rolling slip (``slice_rule = "split"``, the kernel's n_slices = SPLIT_BASE + n;
issue 14, fourteenth pass in docs/development/history.md).

Equal strips evaluate μ(s)·ŝ at each strip's centroid; where a zero of the rolling-direction slip lies inside a strip,
its two sides pull in opposite directions but the strip takes one direction, and as the zero crosses the centroid the
strip's traction turns over: the force is a staircase in the state (kinks the integrator pays for with steps) and
converges only as 1/n.  Cutting the strips that hold a zero there (the zeros are found exactly,
:func:`bearingsim.contact.slices.rolling_slip_zeros`) makes every part one-signed: the force is continuous in the state
and, with 6 strips (≤ 8 evaluations, one pass of the kernel's eight lanes), several times more accurate than 8 equal
strips on the hub states.  The kernel against its independent reference: tests/unit/test_slices.py."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.contact import slices as S

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))  # bench_slices: the bench contact
sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_slice_quadrature import _hub_accelerations  # noqa: E402 - the hub states of test_dyn_options


@settings(max_examples=300, deadline=None)
@given(n=st.integers(1, 16), za=st.floats(-0.999, 0.999), zb=st.floats(-0.999, 0.999), nroot=st.integers(0, 2))
def test_parts_tile_the_major_axis_with_the_zeros_as_edges(n, za, zb, nroot):
    z1, z2 = min(za, zb), max(za, zb)
    if nroot == 2 and z1 == z2:
        nroot = 1
    parts = []
    x, k, ku, iz = -1.0, 0, 1, 0
    for _ in range(n + nroot):  # the kernel's walk along the axis (traction_at)
        x0, k0 = x, k
        x, k, ku, iz = S._next_edge(ku, iz, n, nroot, z1, z2)
        parts.append((x0, x, k0 if k0 >= 0 else (k - 1 if k >= 0 else ku - 1), k0 >= 0 and k >= 0, k0, k))
    edges = [parts[0][0]] + [p[1] for p in parts]
    assert edges[0] == -1.0 and edges[-1] == pytest.approx(1.0, abs=1e-15)
    assert all(parts[p][1] == parts[p + 1][0] for p in range(len(parts) - 1))  # contiguous
    assert all(e1 >= e0 - 1e-15 for e0, e1 in zip(edges, edges[1:]))  # in order (a zero on an edge: to rounding)
    for z in [z1, z2][:nroot]:
        assert z in edges, (z, edges)
    uniform = [-1.0 + 2.0 * k / n for k in range(n + 1)]
    for u in uniform:
        assert min(abs(u - e) for e in edges) <= 1e-15
    for xi0, xi1, k, whole, _, _ in parts:
        # the strip each part belongs to, and whole strips are exactly the uniform ones
        assert -1.0 + 2.0 * k / n <= xi0 + 1e-15 and xi1 <= -1.0 + 2.0 * (k + 1) / n + 1e-15, (xi0, xi1, k)
        if whole:
            assert (xi0, xi1) == (-1.0 + 2.0 * k / n, -1.0 + 2.0 * (k + 1) / n)


def _sweep(n_slices, points=1001):
    """The bench contact (benchmarks/bench_slices.py: mixed physical film, 2 kN, spin) with the ball's rolling
    speed swept from pure rolling to 2 % slip: the zeros of the rolling slip travel across the ellipse."""
    import bench_slices as B

    args = list(B.case())
    wb0 = args[9].copy()
    d = 0.0111
    rows = []
    for k in range(points):
        wb = wb0.copy()
        wb[0] = -2.5 / (d / 2) * (1.0 + 0.02 * k / (points - 1))
        args[9] = wb
        out = np.zeros(S.TRACTION_OUT)
        S.contact_traction(*args, n_slices, out)
        rows.append(out[:10].copy())
    return np.array(rows)


def test_force_is_continuous_as_the_zeros_cross_the_strips():
    """Largest step of the rolling-direction force between neighbouring states over the median step: equal strips
    jump where a zero crosses a centroid (measured 19 with 6 strips), the cut strips do not (2.4)."""
    jump = {}
    for n in (6, S.SPLIT_BASE + 6):
        f = _sweep(n)[:, 1]
        df = np.abs(np.diff(f))
        jump[n] = df.max() / np.median(df)
    assert jump[6] > 8.0, jump  # the staircase the rule removes is there to be removed
    assert jump[S.SPLIT_BASE + 6] < 4.0, jump


def _hub_error(n_slices, scale, ref):
    """(relative error of the ball accelerations, relative error of the power loss) against ref."""
    acc, p = _hub_accelerations(n_slices, scale)
    return np.linalg.norm(acc - ref[0]) / np.linalg.norm(ref[0]), p / ref[1] - 1.0


@pytest.mark.parametrize("scale", [0.99, 1.0, 1.01])
def test_hub_states_six_cut_strips_against_the_strip_limit(scale):
    """The hub states of test_dyn_options (ball spin 1 % below, at and above Jones' value): the ball accelerations
    (traction forces and moments of the 64 contacts) with 6 strips cut at the zeros against 1,024 equal strips, the
    strip model's limit (128 strips differ from it by 0.1–0.3 %).  Measured: 0.96 / 1.39 / 2.19 % (8 equal strips
    8.3 / 2.7 / 14.3 %; 4 Gauss nodes per stretch 0.25 / 2.4 / 0.52 % with 8–12 evaluations), power within 1.1 %."""
    ref = _hub_accelerations(1024, scale)
    err, perr = _hub_error(S.SPLIT_BASE + 6, scale, ref)
    err8, _ = _hub_error(8, scale, ref)
    assert err < 0.025 and err < 0.6 * err8, \
        f"6 cut strips vs 1,024 equal strips (the strip limit of seed eq. 1-2): {err:.4f}, 8 equal strips {err8:.4f}"
    assert abs(perr) < 0.015, f"power loss vs 1,024 equal strips: {perr:+.4f}"


def test_cut_strips_converge_to_the_strip_limit():
    """More strips, cut at the zeros: closer to the limit (6 → 16 strips on the hardest hub state, 2.2 → 1.4 %)."""
    ref = _hub_accelerations(1024, 1.01)
    errs = [_hub_error(S.SPLIT_BASE + n, 1.01, ref)[0] for n in (4, 6, 16)]
    assert errs[2] < errs[1] < errs[0], errs
    assert math.isfinite(errs[2]) and errs[2] < 0.016, errs
