"""exp and log on eight lanes at once, for the strip kernel's film law.

The strip kernel (:func:`bearingsim.contact.slices.traction_at`) evaluates the film law's transcendental functions
strip by strip: ≈ 36 exponentials and 12 logarithms per contact with 8 strips, a quarter of a hub step's time in
glibc's scalar ``exp`` and ``log`` (``perf``).  numba calls the scalar functions only
(its LLVM has no vector math library configured), so :func:`vexp` and :func:`vlog`
are numba intrinsics that call glibc's vector math library ``libmvec`` directly (the x86-64 vector function ABI,
``_ZGVeN8v_exp``: eight doubles in one AVX-512 register; ``_ZGVdN4v_exp``: four in an AVX2 register, called twice).
Measured alone: 4.1 ns per eight exponentials against 24 ns for eight scalar calls.

:data:`MODE` is chosen once, at import: ``"avx512"`` or ``"avx2"`` when numba compiles for this machine's CPU
(``NUMBA_CPU_NAME`` and ``NUMBA_CPU_FEATURES`` unset), the CPU has the instructions and libmvec (glibc ≥ 2.22)
loads; ``"scalar"`` otherwise (eight calls of the scalar functions: the same results as ``math.exp`` bit for bit).
libmvec's functions are accurate to a few units in the last place (glibc manual, "Known Maximum Errors in Math
Functions"; 2 ulp against the scalar exp measured here), so results differ from the scalar path's by rounding.
numba's cache of a kernel is specific to the CPU it was compiled for, so a cache made with one mode is not loaded on
a machine of another.

Both intrinsics take (src, i0, dst, j0) with src and dst contiguous float64 arrays: dst[j0:j0 + 8] ←
f(src[i0:i0 + 8]); the caller guarantees the eight elements on both sides (no bounds check).

:func:`vsqrt` and :func:`vrecip` (√x and 1/x on eight lanes) are LLVM's vector square
root and division, whatever :data:`MODE` is: IEEE-754 rounds both exactly, so every lane is bit for bit the scalar
``math.sqrt(x)`` / ``1.0 / x``.  They exist because the strip kernel's square roots and divisions share one
execution unit that takes 4–6 cycles for each scalar one (``perf``: 8 % of a hub step waited on them); a packed
instruction does eight in about the time of three.  numba's LLVM does not pack them by itself (its SLP vectoriser
is off).
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os

from llvmlite import ir
from numba import types
from numba.core import cgutils
from numba.extending import intrinsic

#: lanes of one call of :func:`vexp` / :func:`vlog`
LANES = 8


def _choose_mode() -> str:
    """"avx512", "avx2" or "scalar" (module docstring); the vector exp and log are registered with llvmlite."""
    from numba import config

    other_cpu = any(os.environ.get(v) for v in ("NUMBA_CPU_NAME", "NUMBA_CPU_FEATURES"))
    if other_cpu or config.CPU_NAME or config.CPU_FEATURES:
        return "scalar"  # numba compiles for another CPU than this one: the vector ABI may not hold
    try:
        import llvmlite.binding as ll

        feats = ll.get_host_cpu_features()
        lib = ctypes.CDLL(ctypes.util.find_library("mvec") or "libmvec.so.1")
        for mode, feat, tag in (("avx512", "avx512f", "_ZGVeN8v_"), ("avx2", "avx2", "_ZGVdN4v_")):
            if feats.get(feat, False):
                addrs = {tag + f: ctypes.cast(getattr(lib, tag + f), ctypes.c_void_p).value for f in ("exp", "log")}
                for name, addr in addrs.items():
                    ll.add_symbol(name, addr)
                return mode
    except (OSError, AttributeError, RuntimeError, KeyError):
        pass
    return "scalar"


#: "avx512", "avx2" or "scalar": how :func:`vexp` and :func:`vlog` are compiled in this process
MODE = _choose_mode()


def _lane_pointers(context, builder, sig, args):
    """Pointers to src[i0] and dst[j0] of an intrinsic called as (src, i0, dst, j0)."""
    src, i0, dst, j0 = args
    a = context.make_array(sig.args[0])(context, builder, src)
    b = context.make_array(sig.args[2])(context, builder, dst)
    return builder.gep(a.data, [i0]), builder.gep(b.data, [j0])


def _lanes_codegen(fname: str):
    """The intrinsic's code: load eight doubles, apply ``fname`` ("exp" or "log"), store eight."""

    def codegen(context, builder, sig, args):
        pa, pb = _lane_pointers(context, builder, sig, args)
        dbl = ir.DoubleType()
        if MODE == "scalar":
            fn = builder.module.declare_intrinsic("llvm." + fname, [dbl])
            for k in range(LANES):
                off = ir.Constant(ir.IntType(64), k)
                builder.store(builder.call(fn, [builder.load(builder.gep(pa, [off]))]), builder.gep(pb, [off]))
            return context.get_dummy_value()
        width, tag = (8, "_ZGVeN8v_") if MODE == "avx512" else (4, "_ZGVdN4v_")
        vt = ir.VectorType(dbl, width)
        fn = cgutils.get_or_insert_function(builder.module, ir.FunctionType(vt, [vt]), tag + fname)
        for k in range(0, LANES, width):
            off = ir.Constant(ir.IntType(64), k)
            v = builder.load(builder.bitcast(builder.gep(pa, [off]), vt.as_pointer()), align=8)
            builder.store(builder.call(fn, [v]), builder.bitcast(builder.gep(pb, [off]), vt.as_pointer()), align=8)
        return context.get_dummy_value()

    return codegen


@intrinsic
def vexp(typingctx, src, i0, dst, j0):
    """dst[j0:j0 + 8] ← exp(src[i0:i0 + 8]) (module docstring)."""
    return types.void(src, types.intp, dst, types.intp), _lanes_codegen("exp")


@intrinsic
def vlog(typingctx, src, i0, dst, j0):
    """dst[j0:j0 + 8] ← log(src[i0:i0 + 8]) (module docstring)."""
    return types.void(src, types.intp, dst, types.intp), _lanes_codegen("log")


def _lanes_ieee(op: str):
    """Code of an exactly rounded operation on eight lanes: "sqrt" (llvm.sqrt on <8 x double>) or "recip" (1/x by
    ``fdiv``); LLVM splits the vector to the target's register width."""

    def codegen(context, builder, sig, args):
        pa, pb = _lane_pointers(context, builder, sig, args)
        vt = ir.VectorType(ir.DoubleType(), LANES)
        v = builder.load(builder.bitcast(pa, vt.as_pointer()), align=8)
        if op == "sqrt":
            fn = cgutils.get_or_insert_function(builder.module, ir.FunctionType(vt, [vt]), f"llvm.sqrt.v{LANES}f64")
            r = builder.call(fn, [v])
        else:
            r = builder.fdiv(ir.Constant(vt, [1.0] * LANES), v)
        builder.store(r, builder.bitcast(pb, vt.as_pointer()), align=8)
        return context.get_dummy_value()

    return codegen


@intrinsic
def vsqrt(typingctx, src, i0, dst, j0):
    """dst[j0:j0 + 8] ← √src[i0:i0 + 8], each lane exactly ``math.sqrt`` (module docstring)."""
    return types.void(src, types.intp, dst, types.intp), _lanes_ieee("sqrt")


@intrinsic
def vrecip(typingctx, src, i0, dst, j0):
    """dst[j0:j0 + 8] ← 1/src[i0:i0 + 8], each lane exactly ``1.0 / x`` (module docstring)."""
    return types.void(src, types.intp, dst, types.intp), _lanes_ieee("recip")
