"""Load and speed histories: one evaluation — the Python ``.at()`` is the numba kernel of the equations of motion."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import loads as ld

finite = st.floats(-1e4, 1e4, allow_nan=False)


@st.composite
def channels(draw):
    sines = tuple(draw(st.lists(st.tuples(finite, st.floats(0.0, 500.0), st.floats(-3.0, 3.0)), max_size=3)))
    table = None
    if draw(st.booleans()):
        tt = sorted(set(draw(st.lists(st.floats(0.0, 0.05), min_size=2, max_size=8))))
        if len(tt) >= 2:
            table = (tuple(tt), tuple(draw(st.lists(finite, min_size=len(tt), max_size=len(tt)))))
    return ld.LoadChannel(draw(finite), sines, table)


@settings(max_examples=60, deadline=None)
@given(st.lists(channels(), min_size=5, max_size=5), st.lists(st.floats(-0.01, 0.06), min_size=1, max_size=20))
def test_at_is_the_kernel_bitwise(chs, times):
    """LoadHistory.at, LoadChannel(t) and the kernel loads_at that forces.rhs calls give the same bits
    (multi-sine sums and tables included, where the former np.interp path differed in the last bits)."""
    hist = ld.LoadHistory(tuple(chs))
    spec = hist.packed()
    out = np.empty(5)
    for t in times + [tt for c in chs if c.table for tt in c.table[0]]:
        fo.loads_at(t, spec, out)
        assert np.array_equal(hist.at(t), out)
        assert [c(t) for c in chs] == list(out)


def test_kernel_matches_the_closed_form():
    """offset + Σ A sin(2π f t + φ) + linear interpolation held constant outside the table."""
    ch = ld.sine(600.0, 50.0, 0.3, offset=100.0) + ld.sine(20.0, 130.0)
    ch = ch + ld.table([0.0, 0.01, 0.02], [0.0, 2000.0, 500.0])
    for t in (-0.001, 0.0, 0.0037, 0.01, 0.015, 0.03):
        ref = (100 + 600 * math.sin(2 * math.pi * 50 * t + 0.3) + 20 * math.sin(2 * math.pi * 130 * t)
               + np.interp(t, [0, 0.01, 0.02], [0, 2000, 500]))
        assert math.isclose(ch(t), ref, rel_tol=1e-14, abs_tol=1e-11)


def test_speed_history_is_the_kernel():
    sp = ld.SpeedHistory(100.0, 2000.0, 0.005)
    gp = np.zeros(ly.NGP)
    gp[ly.G_W0], gp[ly.G_W1], gp[ly.G_TRAMP] = sp.as_tuple()
    for t in np.linspace(-1e-3, 1e-2, 57):
        assert sp.at(t) == fo.speed_at(t, gp)
    assert sp.at(0.0025) == 100.0 + 1900.0 * 0.5 and sp.at(0.02) == 2000.0
    assert ld.SpeedHistory(300.0).at(1.0) == 300.0
