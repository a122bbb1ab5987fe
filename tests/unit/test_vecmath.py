"""The eight-lane exp, log, square root and reciprocal of the strip kernel (bearingsim.contact.vecmath, issue 14).

glibc's vector math library promises a few units in the last place (glibc manual, "Known Maximum Errors in Math
Functions"); the lanes are held to 4 ulp of the scalar functions over the film law's range and beyond, with every
lane checked (a lane shifted by one, or a wrong function, fails).  The scalar fallback (NUMBA_CPU_NAME set: numba
compiles for another CPU than this one) must give the scalar functions' results bit for bit; it runs in a child
process with a cache of its own, as a user's process would.  The square root and the reciprocal are exactly rounded
(IEEE 754), so every lane must equal ``math.sqrt(x)`` / ``1.0 / x`` bit for bit, on this CPU and on a generic one.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import tempfile

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from bearingsim.contact import vecmath as V


@njit(cache=False)
def _apply(x, kind):
    """kind 0: vexp, 1: vlog, 2: vsqrt, 3: vrecip, eight lanes at a time over x."""
    y = np.empty_like(x)
    for c in range(0, x.shape[0], V.LANES):
        if kind == 0:
            V.vexp(x, c, y, c)
        elif kind == 1:
            V.vlog(x, c, y, c)
        elif kind == 2:
            V.vsqrt(x, c, y, c)
        else:
            V.vrecip(x, c, y, c)
    return y


def _ulps(got, ref):
    return np.abs(got - ref) / np.spacing(np.abs(ref))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-700.0, 700.0), min_size=16, max_size=16))
def test_vexp_within_4_ulp_of_exp_on_every_lane(xs):
    x = np.array(xs)
    ref = np.array([math.exp(v) for v in xs])
    got = _apply(x, 0)
    assert np.all(_ulps(got, ref) <= 4.0), (V.MODE, x, got, ref)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(1e-300, 1e300), min_size=16, max_size=16))
def test_vlog_within_4_ulp_of_log_on_every_lane(xs):
    x = np.array(xs)
    ref = np.array([math.log(v) for v in xs])
    got = _apply(x, 1)
    # near x = 1 the logarithm is tiny: the bound is 4 ulp of the value or 4 ulp of 1 (the argument's rounding)
    tol = 4.0 * np.maximum(np.spacing(np.abs(ref)), np.spacing(1.0))
    assert np.all(np.abs(got - ref) <= tol), (V.MODE, x, got, ref)


def test_lanes_keep_their_order_and_offsets():
    """Each lane gets its own argument, at the offsets given (src and dst offsets differ)."""

    @njit(cache=False)
    def shifted(x, y):
        V.vexp(x, 3, y, 5)

    x = np.arange(16, dtype=float) * 0.1
    y = np.zeros(16)
    shifted(x, y)
    assert np.all(y[:5] == 0.0) and np.all(y[13:] == 0.0)
    assert np.allclose(y[5:13], np.exp(x[3:11]), rtol=1e-15, atol=0.0)


def test_special_values_match_the_scalar_functions():
    """Zeros, infinities, overflow (e^710), underflow (e^−746) and NaN as the scalar functions give them."""
    got = _apply(np.array([0.0, -0.0, np.inf, -np.inf, 710.0, -746.0, np.nan, 1.0]), 0)
    assert np.array_equal(got[:6], [1.0, 1.0, np.inf, 0.0, np.inf, 0.0]) and np.isnan(got[6])
    assert abs(got[7] - math.e) <= 4 * np.spacing(math.e)
    lg = _apply(np.array([1.0, 0.0, np.inf, 2.0, 1e-320, 1e308, -1.0, 10.0]), 1)
    assert lg[0] == 0.0 and lg[1] == -np.inf and lg[2] == np.inf and np.isnan(lg[6])
    assert abs(lg[4] - math.log(1e-320)) <= 4 * np.spacing(abs(math.log(1e-320)))


def test_scalar_fallback_is_the_scalar_functions_bit_for_bit():
    code = (
        "import math, numpy as np\n"
        "from numba import njit\n"
        "from bearingsim.contact import vecmath as V\n"
        "assert V.MODE == 'scalar', V.MODE\n"
        "@njit(cache=True)\n"
        "def f(x, y, z):\n"
        "    V.vexp(x, 0, y, 0)\n"
        "    V.vlog(y, 0, z, 0)\n"

        "x = np.linspace(-30.0, 30.0, 8); x0 = x.copy(); y = np.empty(8); z = np.empty(8)\n"
        "f(x, y, z)\n"

        "assert all(y[i] == math.exp(x0[i]) for i in range(8)), y\n"
        "assert all(z[i] == math.log(y[i]) for i in range(8)), z\n"
        "print('ok')\n")
    _run_on_a_generic_cpu(code, runs=2)  # twice: compiled, then loaded from the cache


def _run_on_a_generic_cpu(code: str, runs: int = 1) -> None:
    """Run ``code`` in a child process compiling for NUMBA_CPU_NAME=generic with a cache of its own, ``runs`` times;
    each run must print "ok"."""
    with tempfile.TemporaryDirectory() as d:
        script = os.path.join(d, "child.py")
        with open(script, "w") as fh:
            fh.write(code)
        env = dict(os.environ, NUMBA_CPU_NAME="generic", NUMBA_CACHE_DIR=os.path.join(d, "cache"))
        for _ in range(runs):
            r = subprocess.run([sys.executable, script], env=env, capture_output=True, text=True, timeout=300)
            assert r.returncode == 0 and r.stdout.strip() == "ok", r.stderr[-2000:]


def test_this_machine_uses_the_vector_library_when_it_can():
    """On an x86-64 Linux machine with AVX2 or AVX-512 and glibc's libmvec the lanes are vector calls (the speed of
    issue 14 depends on it); elsewhere the scalar fallback is the documented choice."""
    import ctypes.util

    import llvmlite.binding as ll

    feats = ll.get_host_cpu_features()
    has_lib = bool(ctypes.util.find_library("mvec"))
    other_cpu = os.environ.get("NUMBA_CPU_NAME") or os.environ.get("NUMBA_CPU_FEATURES")
    if other_cpu or not has_lib or not (feats.get("avx512f") or feats.get("avx2")):
        assert V.MODE == "scalar"
    else:
        assert V.MODE == ("avx512" if feats.get("avx512f") else "avx2")


def _ieee(x, kind):
    """kind 0: vsqrt, 1: vrecip."""
    return _apply(x, 2 + kind)


def _same_bits(got, ref):
    return np.array_equal(np.asarray(got).view(np.int64), np.asarray(ref).view(np.int64))


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(0.0, 1e300) | st.floats(1e-320, 1e-300), min_size=16, max_size=16),
       st.lists(st.floats(allow_nan=False).filter(lambda v: v != 0.0), min_size=16, max_size=16))
def test_vsqrt_and_vrecip_are_the_scalar_operations_bit_for_bit(xs, ds):
    """Every lane (two calls of eight) equals the scalar square root / reciprocal exactly, subnormals included."""
    x = np.array(xs)
    assert _same_bits(_ieee(x, 0), [math.sqrt(v) for v in xs]), (x, _ieee(x, 0))
    d = np.array(ds)
    assert _same_bits(_ieee(d, 1), [1.0 / v for v in ds]), (d, _ieee(d, 1))


def test_vsqrt_and_vrecip_special_values_and_offsets():
    """±0, ±inf, negative arguments and NaN as IEEE 754 gives them; the offsets of source and destination held."""
    x = np.array([0.0, -0.0, np.inf, -1.0, np.nan, 4.0, 2.0, 1e-310])
    r = _ieee(x, 0)
    assert _same_bits(r[:3], [0.0, -0.0, np.inf]) and np.isnan(r[3]) and np.isnan(r[4])
    assert r[5] == 2.0 and r[6] == math.sqrt(2.0) and r[7] == math.sqrt(1e-310)
    q = _ieee(np.array([0.0, -0.0, np.inf, -np.inf, np.nan, 4.0, -2.0, 3.0]), 1)
    assert _same_bits(q[:4], [np.inf, -np.inf, 0.0, -0.0]) and np.isnan(q[4])
    assert q[5] == 0.25 and q[6] == -0.5 and q[7] == 1.0 / 3.0

    @njit(cache=False)
    def shifted(a, b):
        V.vsqrt(a, 3, b, 5)
        V.vrecip(a, 2, b, 13)

    a = np.arange(1.0, 17.0)
    b = np.zeros(21)
    shifted(a, b)
    assert np.all(b[:5] == 0.0)
    assert _same_bits(b[5:13], np.sqrt(a[3:11])) and _same_bits(b[13:21], 1.0 / a[2:10])


def test_vsqrt_and_vrecip_on_a_generic_cpu_bit_for_bit():
    """Compiled for another CPU (NUMBA_CPU_NAME=generic: LLVM splits the eight lanes to that target's registers) the
    lanes are still the scalar operations exactly."""
    code = (
        "import math, numpy as np\n"
        "from numba import njit\n"
        "from bearingsim.contact import vecmath as V\n"
        "@njit(cache=True)\n"
        "def f(x, y, z):\n"
        "    V.vsqrt(x, 0, y, 0)\n"
        "    V.vrecip(x, 0, z, 0)\n"
        "x = np.array([2.0, 3.0, 1e-310, 7.5, 1e300, 0.1, 5.0, 11.0]); y = np.empty(8); z = np.empty(8)\n"
        "f(x, y, z)\n"
        "assert all(y[i] == math.sqrt(x[i]) and z[i] == 1.0 / x[i] for i in range(8)), (y, z)\n"
        "print('ok')\n")
    _run_on_a_generic_cpu(code)
