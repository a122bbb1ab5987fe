"""The contact kernels of the right-hand side run without numba's reference counting (issue 14).

numba increments and decrements an atomic reference count for every array argument of a function it does not
inline and for every array view it makes; with 17 arrays per ball–raceway contact and views per ball that was
17 % of the hub right-hand side (`perf`: NRT_incref / NRT_decref).  The contact now takes its vectors as
components (:func:`bearingsim.dynamics.contacts.race_contact_at`, :func:`bearingsim.contact.slices.traction_at`),
and the kernels that only read and write arrays they are given are compiled with ``_nrt=False``.  These tests
keep it so: the option is set on every hot kernel, this numba honours it (a fresh compile of the contact has no
reference counting in its LLVM IR, and has it without the option), and the array and component forms of the
contact give the same numbers bit for bit.
"""

from __future__ import annotations

import re

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from bearingsim.contact import slices as S
from bearingsim.dynamics import contacts as ct
from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics.integrate import common as cm
from bearingsim.dynamics.integrate import linalg as la

HOT = (ct.race_contact_at, S.traction_at, S._gauss_quadrature, S.add_point_traction, S.add_point_rolling,
       S._law_constants, fo.outer_memo_hit, fo.outer_memo_put, fo.outer_memo_get, fo._one_ball,
       # the right-hand side's body and the integrator's per-step kernels (a debugger's count of NRT_incref /
       # NRT_decref by caller put 14 % of a hub step in these: error_scale per component, the ball loop's and
       # the cage loop's views, the W blocks)
       fo._rhs, fo.balls_on_raceways, fo._rot_yz, ct.cross, ct.slice_table, cm.error_scale, cm.error_norm,
       cm.error_norm_parts,
       la.apply_w, la.w_solve, la.invert_small, la._invert6, la.kinematic_rows, la.block_w_inverse, la.w_inverse,
       la._coupled_w_ball, la.coupled_w, la._schur_inverse, la.coupled_apply_w)


def test_hot_kernels_are_compiled_without_reference_counting():
    for fn in HOT:
        assert fn.targetoptions.get("_nrt") is False, fn.py_func.__name__


def _ir_of_fresh_copy(nrt: bool) -> str:
    """The LLVM IR of race_contact_at compiled afresh (not from the cache) with or without reference counting."""
    opts = {k: v for k, v in ct.race_contact_at.targetoptions.items() if k not in ("cache", "_nrt", "nopython")}
    fresh = njit(**opts, _nrt=nrt)(ct.race_contact_at.py_func)
    lub = np.zeros(S.L_SIZE)
    gp = np.zeros(ly.NGP)
    tbuf = np.zeros(60)
    fresh(0.0, 30e-3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 30e-3 - 0.2e-3 - 1e-6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
          0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 8e9, np.cbrt(8e9), 0.2e-3, 6e-3, 0.0, lub, gp, 1e-4, 1e-5, 10e-3, 1.0, 0.0,
          0.0, tbuf)
    (ir,) = fresh.inspect_llvm().values()
    # the function itself, not its Python and C wrappers
    def name(f):
        return re.search(r"@([^\s(]+)\(", f).group(1)

    (own,) = [f for f in ir.split("\ndefine ")[1:] if "race_contact_at" in name(f) and "cpython" not in name(f)
              and not name(f).startswith("cfunc")]
    return own


def test_this_numba_honours_the_option():
    assert "NRT_incref" in _ir_of_fresh_copy(True)  # the check can fail: with counting, the arrays are counted
    assert "NRT_incref" not in _ir_of_fresh_copy(False)


def _contact_inputs(rng):
    kc, rgroove, half_d = 8.0e9, 0.2e-3, 6.0e-3
    u = rng.normal(size=3)
    u /= np.linalg.norm(u)
    g = np.array([1e-3, 30e-3, 2e-3])
    b = g + (rgroove + rng.uniform(1e-7, 2e-5)) * u
    tang = np.cross(u, rng.normal(size=3))
    tang /= np.linalg.norm(tang)
    vecs = [b, rng.normal(scale=0.1, size=3), rng.normal(scale=300.0, size=3), g, rng.normal(scale=0.01, size=3),
            float(rng.normal(scale=100.0)), np.array([0.5e-3, 0.0, 0.0]), rng.normal(scale=0.01, size=3),
            rng.normal(scale=300.0, size=3)]
    return vecs, kc, rgroove, half_d, tang


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 2**32 - 1), mode=st.sampled_from([0, 1, 2]), nsl=st.sampled_from([-4, -2, 1, 8]))
def test_array_and_component_forms_of_the_contact_agree_bit_for_bit(seed, mode, nsl):
    rng = np.random.default_rng(seed)
    vecs, kc, rgroove, half_d, tang = _contact_inputs(rng)
    b, v, w, g, vg, worb, rcen, vrace, wrace = vecs
    gp = np.zeros(ly.NGP)
    gp[ly.G_TRAC] = mode
    gp[ly.G_NSL] = abs(nsl) if mode == 1 else nsl
    gp[ly.G_MU0], gp[ly.G_S0], gp[ly.G_VREF] = 0.1, 0.01, 1e-3
    lub = (S.pack_lubrication_parameters("iso-vg-68", 333.15, 2.3e11, 5e-3, 50e-3, 0.1e-6, model="mixed",
                                         fluid_model="physical") if mode == 2 else np.zeros(S.L_SIZE))
    alpha = 0.05
    a_c, b_c, r_dev = 1e-4, 1e-5, 10e-3
    fb, mb, fr, mr = (np.zeros(3) for _ in range(4))
    res = np.zeros(8)
    tbuf = np.zeros(max(44 + 2 * 8, S.TRACTION_OUT))  # the Coulomb slices at 44:, or the strips' lanes
    ct.slice_table(8, tbuf[44:])
    ct.race_contact(b, v, w, g, vg, worb, rcen, vrace, wrace, kc, rgroove, half_d, alpha, lub, gp, a_c, b_c, r_dev,
                    tang, fb, mb, fr, mr, res, tbuf)
    tb2 = np.zeros_like(tbuf)
    ct.slice_table(8, tb2[44:])
    out = ct.race_contact_at(*b, *v, *w, *g, *vg, worb, *rcen, *vrace, *wrace, kc, np.cbrt(kc), rgroove, half_d,
                             alpha, lub, gp, a_c, b_c, r_dev, *tang, tb2)
    got = np.array(out)
    want = np.concatenate([res[:7], fb, mb, fr, mr])
    np.testing.assert_array_equal(got, want)
    if mode == 2:
        assert np.any(got[10:13] != 0.0)  # traction moments present: the comparison covers the kernel
