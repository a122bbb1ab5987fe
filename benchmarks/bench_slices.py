"""Benchmark of the sliced-contact kernel bearingsim.contact.slices.contact_traction.

Prints µs per call after warm-up, called from a numba loop (as the dynamics engine does)
for 10 slices and a few other counts (best and median of repeated runs), and for the Gauss quadrature between the
zeros of the rolling slip (n_slices = −k: k nodes per sub-interval; the case has two zeros, so 3k μ evaluations), for
equal strips cut at those zeros ("split": n strips, n + 2 evaluations here), for the log rule (n_slices =
LOG_BASE + n: n nodes in all, generalized Gauss rules exact for the logarithm of the zeros; n − 4 + 4 = n here), for
the physical fluid model, the four-parameter curve and the boundary model.  Run:  python benchmarks/bench_slices.py
Not a test: figures depend on the machine.
"""

from __future__ import annotations

import math
import time

import numpy as np
from numba import njit

from bearingsim.contact import hertz
from bearingsim.contact import slices as S


@njit(cache=False)  # no cache: numba does not invalidate it when the called kernel changes
def _loop(n_calls, q, a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr, lub, n_slices, out):
    acc = 0.0
    for i in range(n_calls):
        S.contact_traction(q * (1.0 + 1e-9 * i), a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr, lub, n_slices, out)
        acc += out[0]
    return acc


def case(model="mixed", fluid_model="physical"):
    d, dm, f, alpha = 0.0111, 0.061, 0.52, math.radians(35.0)
    e = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
    rx, ry = hertz.raceway_radii(d, dm, f, alpha, True)
    hc = hertz.point_contact_exact(2000.0, rx, ry, e)
    lub = S.pack_lubrication_parameters("iso-vg-68", 333.15, e, rx, ry, 0.1e-6, model=model,
                                        fluid_model=fluid_model, fluid_curve=(0.0, 0.06, 0.01, 0.045))
    n = np.array([0.0, 0.0, 1.0])
    m = np.array([1.0, 0.0, 0.0])
    c = np.zeros(3)
    cb = np.array([0.0, 0.0, d / 2])
    cr = np.array([0.0, 0.0, -0.025])
    wr = np.array([100.0, 0.0, 0.0])
    wb = np.array([-2.5 / (d / 2) * 1.01, 0.0, 30.0])  # 1 % slip and some spin
    return (2000.0, hc.a, hc.b, S.deformed_surface_radius(d, f * d), c, n, m, cb, np.zeros(3), wb, cr,
            np.zeros(3), wr, lub)


def against(src: str, pairs: int = 60, n_calls: int = 4000) -> None:
    """Interleaved timing of this tree's kernel and the one under ``src`` (module docstring)."""
    import importlib
    import shutil
    import sys
    import tempfile
    from pathlib import Path

    tmp = tempfile.mkdtemp()
    shutil.copytree(Path(src) / "bearingsim", Path(tmp) / "bearingsim_other",
                    ignore=shutil.ignore_patterns("*.nbi", "*.nbc"))
    sys.path.insert(0, tmp)
    other = importlib.import_module("bearingsim_other.contact.slices")

    def looper(mod):
        @njit
        def loop(n, q, a, b, r_dev, c, nn, m, cb, vb, wb, cr, vr, wr, lub, n_slices, out):
            acc = 0.0
            for i in range(n):
                mod.contact_traction(q * (1.0 + 1e-9 * i), a, b, r_dev, c, nn, m, cb, vb, wb, cr, vr, wr, lub,
                                     n_slices, out)
                acc += out[0]
            return acc
        return loop

    args = case("mixed", "physical")
    lub_other = np.zeros(other.L_SIZE)
    k = min(other.L_SIZE, S.L_SIZE)
    lub_other[:k] = args[-1][:k]  # the older layout is a prefix of this one (entries appended over time)
    runs = ((looper(other), args[:-1] + (lub_other,), []), (looper(S), args, []))
    out = np.zeros(10)
    for loop, a, _ in runs:
        loop(10, *a, 8, out)
    for _ in range(pairs):
        for loop, a, ts in runs:
            t0 = time.process_time()
            loop(n_calls, *a, 8, out)
            ts.append((time.process_time() - t0) / n_calls * 1e6)
    (_, _, t_old), (_, _, t_new) = runs
    print(f"contact_traction, physical fluid, 8 strips, CPU µs per call: {src}: best {min(t_old):.3f} median "
          f"{np.median(t_old):.3f}; this tree: best {min(t_new):.3f} median {np.median(t_new):.3f}; median of "
          f"{pairs} paired ratios this/other {np.median(np.array(t_new) / np.array(t_old)):.3f}")
    shutil.rmtree(tmp, ignore_errors=True)


def main(repeats: int = 25, n_calls: int = 10_000):
    print(f"contact_traction: µs per call after warm-up (numba loop of {n_calls} calls, best and median of "
          f"{repeats} repeats; the best is the figure least disturbed by other load on the machine)")
    for model, fluid in (("mixed", "physical"), ("fluid", "curve"), ("boundary", "physical")):
        args = case(model, fluid)
        for n_slices in (1, 5, 8, 10, 20, S.SPLIT_BASE + 6, S.SPLIT_BASE + 8, -2, -3, -4, S.LOG_BASE + 7,
                         S.LOG_BASE + 8):
            out = np.zeros(10)
            _loop(10, *args, n_slices, out)
            times = []
            for _ in range(repeats):
                t0 = time.perf_counter()
                _loop(n_calls, *args, n_slices, out)
                times.append((time.perf_counter() - t0) / n_calls * 1e6)
            label = (f"log   ={n_slices - S.LOG_BASE:3d}" if n_slices > S.LOG_BASE
                     else f"split ={n_slices - S.SPLIT_BASE:3d}" if n_slices > S.SPLIT_BASE
                     else f"slices={n_slices:3d}" if n_slices > 0 else f"gauss ={-n_slices:3d}")
            print(f"  model={model:8s} fluid={fluid:8s} {label}: best {min(times):6.3f}  "
                  f"median {float(np.median(times)):6.3f} µs/call")


if __name__ == "__main__":
    import sys

    if len(sys.argv) == 3 and sys.argv[1] == "--against":
        against(sys.argv[2])
    else:
        main()
