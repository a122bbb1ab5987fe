"""The log rule of the sliced contact ellipse (the kernel's n_slices = LOG_BASE + n, LOG_MIN ≤ n ≤ LOG_MAX nodes).

What this file proves about :mod:`bearingsim.contact.slices`:

1. The tables ``_LOG1_*`` (one-sided rules on t ∈ [0, 1], the slip's zero at t = 0) and ``_LOG2_*`` (two-sided,
   zeros at both ends) integrate the moments they claim — 1, t, …, t^(2n−2) and ln t; every polynomial of degree
   ≤ 2n − 3 and ln t + ln(1 − t) — to 1e-14, and no more (the next moment is missed), with the closed forms of the
   smallest rows (t = 1/e; t(1 − t) = e⁻²).
2. :func:`_log_counts` deals the counts its docstring fixes per number of zeros (n; n − n // 2 and n // 2 about one zero;
   2, n − 4, 2 for two), whatever the zeros' positions, at least two to every stretch, within the rows the tables
   have; every one of the n nodes is used (with one zero and odd n, the lower stretch takes the odd one).
3. :func:`nearest_slip_zero` is the zero of the quadratic g(ξ) ≈ σ0 + σ1 ξ + ½ σ2 c a² ξ² nearest the axis [−1, 1]
   (checked against ``numpy.roots``).
4. The kernel :func:`contact_traction` agrees with its independently written pure-Python reference
   :func:`contact_traction_reference` to 1e-10 with 0 (affine and sinh-mapped), 1 and 2 zeros of the rolling slip,
   except where rounding decides between them: two zeros off the axis equally near (the sinh map may grade towards
   either; what that changes is bounded separately), zeros moved by rounding (a double zero; a zero of a tiny σ1),
   slip within rounding of the surfaces' speeds.
5. Constant μ on a flat contact: the closed forms of seed 001 eq. 1's load density (pure spin −3μQa/8, uniform
   sliding μQ, and a zero off the centre) are integrated exactly (≥ 3 nodes each side of the zero); node by node,
   each stretch is integrated to its rule's degree and the logarithm of its zeros, and not beyond that degree.
6. On the hub states (test_dyn_options) the rule with 7 nodes is within 1 % of 1,024 equal strips (the strip limit
   of seed 001 eqs. 1–2) and several times closer to it than 8 equal strips.
7. :func:`_log_node` puts every node on its stretch with a positive weight, the weights integrating a constant
   exactly (the sinh map without zeros: within the Gauss–Legendre remainder of ∫ y cosh u du; plain Gauss–Legendre
   in its affine limit).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, event, given, settings
from hypothesis import strategies as st

from bearingsim.contact import hertz
from bearingsim.contact import slices as S

sys.path.insert(0, str(Path(__file__).resolve().parent))
from test_slice_quadrature import _hub_accelerations  # noqa: E402 - the hub states of test_dyn_options

D, F_I = 0.0111, 0.52
E_EFF = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
RX, RY = hertz.raceway_radii(D, 0.061, F_I, math.radians(35.0), True)
Q = 2000.0
HC = hertz.point_contact_exact(Q, RX, RY, E_EFF)
R_BALL = D / 2
R_DEV = S.deformed_surface_radius(D, F_I * D)  # the groove's deformed surface (Jones 1960)
NODES = range(S.LOG_MIN, S.LOG_MAX + 1)


def _lub(**kw):
    kw.setdefault("fluid_curve", (0.0, 0.06, 0.01, 0.045))
    return S.pack_lubrication_parameters("iso-vg-68", 333.15, E_EFF, RX, RY, kw.pop("roughness", 0.1e-6), **kw)


def _constant_mu(mu):
    """Boundary model with the four-parameter curve μ(s) = (A + B s)e^(−C s) + D at A = B = C = 0: μ ≡ D."""
    lub = _lub(model="boundary", rolling_resistance=False)
    lub[S.L_BA:S.L_BD + 1] = (0.0, 0.0, 0.0, mu)
    return lub


def _flat(u_ball, u_race, spin, lub, n_slices):
    """Ball above a flat race at z = 0 rolling along y, spinning about the normal z: the rolling slip at x = aξ is
    s_y = spin·aξ + u_ball − u_race (one zero at ξ = (u_race − u_ball)/(spin a), none without spin)."""
    out = np.zeros(10)
    S.contact_traction(Q, HC.a, HC.b, math.inf, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                       np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u_ball / R_BALL, 0.0, spin]),
                       np.array([0.0, 0.0, -1.0]), np.array([0.0, u_race, 0.0]), np.zeros(3), lub, n_slices, out)
    return out


def _groove_args(u, slip, spin, q, r_dev, lub, n_slices):
    """The operating-range contact of test_slices (ball on a race of radius 0.025 m, entraining speed u [m/s], slip
    of the ball's rolling speed, spin about the normal [rad/s]) as the arguments of contact_traction."""
    a, b = HC.a * (q / Q) ** (1 / 3), HC.b * (q / Q) ** (1 / 3)
    return (q, a, b, r_dev, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
            np.array([0.0, 0.0, R_BALL]), np.zeros(3), np.array([u * (1 + slip) / R_BALL, 0.0, spin]),
            np.array([0.0, 0.0, -0.025]), np.zeros(3), np.array([-u / 0.025, 0.0, 0.0]), lub, n_slices)


def _slip_field(args):
    """(σ0, σ1, σ2, a, c) of the rolling slip along the major axis (rolling_slip_zeros' arguments) of a contact,
    from its vectors with numpy (as contact_traction_reference takes them)."""
    q, a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr = args[:13]
    ub = vb + np.cross(wb, c - cb)
    ur = vr + np.cross(wr, c - cr)
    rdir = np.cross(n, m)
    ws = wb - wr
    curv = 0.0 if not math.isfinite(r_dev) else 1.0 / r_dev
    return float((ub - ur) @ rdir), a * float(np.cross(ws, m) @ rdir), float(np.cross(ws, n) @ rdir), a, curv


def _node(f, m, nroot, z1, z2, counts, xb=0.0, dz=math.inf):
    """Node m of the log rule from _log_node (f: its py_func or the compiled function) with the sinh map's constants
    as the caller (_gauss_quadrature) takes them once per contact: y = max(d, LOG_SINH_FLOOR), u0 = asinh((−1 − ξ_b)/y),
    du = asinh((1 − ξ_b)/y) − u0 (none beyond y = 1e6)."""
    y = max(dz, S.LOG_SINH_FLOOR)
    u0 = du = 0.0
    if y <= 1e6:
        u0 = math.asinh((-1.0 - xb) / y)
        du = math.asinh((1.0 - xb) / y) - u0
    return f(m, nroot, z1, z2, *counts, xb, y, u0, du)


# --------------------------------------------------------------------------- 1. the tables


@pytest.mark.parametrize("n", range(1, 7))
def test_one_sided_table_integrates_its_moments(n):
    """Row n of _LOG1_*: ∫₀¹ tᵏ dt = 1/(k+1) for k ≤ 2n − 2 and ∫₀¹ ln t dt = −1 to 1e-14 (the moment equations the
    comment block above the tables says they were solved from), nodes ascending inside (0, 1), weights positive
    summing to 1; and t^(2n−1) is missed by more than 1e-8 (measured 3.2e-7 at n = 6): the rule is the one
    claimed, not one of higher degree."""
    x, w = S._LOG1_X[n, :n], S._LOG1_W[n, :n]
    assert np.all(x > 0.0) and np.all(x < 1.0) and np.all(np.diff(x) > 0.0), x
    assert np.all(w > 0.0), w
    assert math.fsum(w) == pytest.approx(1.0, abs=1e-14)
    for k in range(2 * n - 1):
        assert np.dot(w, x**k) == pytest.approx(1.0 / (k + 1), abs=1e-14), f"∫₀¹ t^{k} dt = 1/{k + 1}, row {n}"
    assert np.dot(w, np.log(x)) == pytest.approx(-1.0, abs=1e-14), f"∫₀¹ ln t dt = −1, row {n}"
    k = 2 * n - 1
    assert abs(np.dot(w, x**k) - 1.0 / (k + 1)) > 1e-8, f"row {n} is exact for t^{k} too: not the rule claimed"


@pytest.mark.parametrize("n", range(2, 5))
def test_two_sided_table_is_symmetric_and_integrates_its_moments(n):
    """Row n of _LOG2_*: symmetric about t = 1/2 (x_i = 1 − x_(n−1−i), mirrored weights equal; so every odd power
    of t − 1/2 integrates to 0), exact for (t − 1/2)^(2j) (moment 2^(−2j)/(2j + 1)) for 2j ≤ 2n − 3 and for
    ln t + ln(1 − t) (moment −2) to 1e-14; the next even power (t − 1/2)^(2n−2) is missed by more than 1e-8
    (measured 2.3e-4 at n = 4)."""
    x, w = S._LOG2_X[n, :n], S._LOG2_W[n, :n]
    assert np.all(x > 0.0) and np.all(x < 1.0) and np.all(np.diff(x) > 0.0), x
    assert np.all(w > 0.0), w
    np.testing.assert_array_equal(x + x[::-1], np.ones(n), err_msg="nodes symmetric about 1/2")
    np.testing.assert_array_equal(w, w[::-1], err_msg="mirrored weights equal")
    for j in range(n - 1):
        exact = 0.5 ** (2 * j) / (2 * j + 1)
        assert np.dot(w, (x - 0.5) ** (2 * j)) == pytest.approx(exact, abs=1e-14), f"(t − 1/2)^{2 * j}, row {n}"
    assert np.dot(w, np.log(x) + np.log(1.0 - x)) == pytest.approx(-2.0, abs=1e-14), \
        f"∫₀¹ ln t + ln(1 − t) dt = −2, row {n}"
    j = n - 1
    assert abs(np.dot(w, (x - 0.5) ** (2 * j)) - 0.5 ** (2 * j) / (2 * j + 1)) > 1e-8, \
        f"row {n} is exact for (t − 1/2)^{2 * j} too: not the rule claimed"


def test_smallest_rows_have_their_closed_forms():
    """One node, exact for 1 and ln t: weight 1 and ln t₁ = −1, t₁ = 1/e; two symmetric nodes, exact for
    ln t + ln(1 − t): 2·½ ln(t(1 − t)) = −2, t(1 − t) = e⁻² (the comment block of the tables); the table's 1/e is
    the rounded 1/e."""
    assert S._LOG1_X[1, 0] == math.exp(-1.0)
    assert S._LOG1_W[1, 0] == 1.0
    for t in S._LOG2_X[2, :2]:
        assert t * (1.0 - t) == pytest.approx(math.exp(-2.0), abs=1e-16)
    assert S._LOG2_X[2, 0] == pytest.approx(0.5 - math.sqrt(0.25 - math.exp(-2.0)), abs=1e-16)


# --------------------------------------------------------------------------- 2. dealing the nodes


_zero = st.floats(-1.0, 1.0, exclude_min=True, exclude_max=True)


def _counts_of(n, nroot):
    """The counts _log_counts' docstring states: all n on the axis without a zero, n − n // 2 below one zero and
    n // 2 above it, two on each outer stretch and n − 4 between two zeros."""
    return {0: (n, 0, 0), 1: (n - n // 2, n // 2, 0), 2: (2, n - 4, 2)}[nroot]


@settings(max_examples=300, deadline=None)
@given(n=st.integers(S.LOG_MIN, S.LOG_MAX), nroot=st.integers(0, 2), za=_zero, zb=_zero)
def test_log_counts_are_fixed_per_count_of_zeros(n, nroot, za, zb):
    """The counts are those of the docstring whatever the zeros' positions (so the nodes move continuously with the
    zeros), nroot = 0 giving (n, 0, 0); every used stretch has at least two nodes, the unused ones none, no count
    goes beyond the rows the tables have (one-sided 1..6, two-sided 2..4; Gauss–Legendre 1..GAUSS_MAX), and all n
    are dealt."""
    z1, z2 = min(za, zb), max(za, zb)
    assume(nroot < 2 or z1 < z2)
    counts = tuple(S._log_counts(n, nroot))
    assert counts == _counts_of(n, nroot), counts
    if nroot == 0:
        assert counts[0] <= S.GAUSS_MAX
        return
    used = counts[:nroot + 1]
    assert all(c >= 2 for c in used) and all(c == 0 for c in counts[nroot + 1:]), counts
    assert used[0] <= 6 and used[-1] <= 6, counts  # _LOG1_X has rows 1..6
    if nroot == 2:
        assert 2 <= used[1] <= 4, counts  # _LOG2_X has rows 2..4
    assert sum(counts) == n, counts


@pytest.mark.parametrize("n", [n for n in NODES if n % 2])
def test_every_node_is_used_with_one_zero(n):
    """LOG_BASE + n: "n nodes in all" (slices.py) — with one zero of the rolling slip, too."""
    counts = S._log_counts(n, 1)
    assert sum(counts) == n, counts
    assert all(_node(S._log_node.py_func, m, 1, 0.2, 0.0, counts)[1] > 0.0 for m in range(n))


# --------------------------------------------------------------------------- 3. the nearest zero off the axis


def _zeros_numpy(sig0, sig1, sig2, a, curv):
    """[(ξ_b, d, |root|)] of the roots of σ0 + σ1 ξ + ½ σ2 c a² ξ² by numpy.roots, nearest the interval [−1, 1] first
    (the quadratic taken as linear where its leading coefficient is below 1e-12 of the sum of the coefficients'
    moduli, as nearest_slip_zero and contact_traction_reference do); [] without roots."""
    coef = [0.5 * sig2 * curv * a * a, sig1, sig0]
    if abs(coef[0]) <= 1e-12 * sum(abs(v) for v in coef):
        roots = [-sig0 / sig1] if sig1 != 0.0 else []  # (may be ±inf: no zero within reach)
    else:
        roots = np.roots(np.array(coef) / max(abs(v) for v in coef))  # (scaled: no overflow in the companion matrix)
    found = []
    for r in roots:
        xb = min(1.0, max(-1.0, r.real))
        found.append((xb, abs(r - xb), abs(r)))
    return sorted(found, key=lambda f: f[1])


def _tied(zeros):
    """Two real zeros at the same distance from the axis (to 1e-9, far above rounding) at different points of it:
    either is "the nearest" (e.g. the symmetric field of a groove without spin, σ1 = 0, its zeros beyond both ends,
    or both on the axis), and which one the sinh map grades towards is up to rounding — nearest_slip_zero takes the
    root qq/aa unless the other is strictly nearer, contact_traction_reference takes numpy.roots' order."""
    return (len(zeros) == 2 and zeros[0][0] != zeros[1][0]
            and zeros[1][1] - zeros[0][1] <= 1e-9 * max(1.0, zeros[0][2], zeros[1][2]))


#: σ [m/s] in [−1, 1], none below 1e-100 in modulus but 0: nearest_slip_zero squares them unscaled (the discriminant
#: σ1² − 4 aa σ0 underflows below ~1e-154; sliding speeds are never that small)
_sig = st.floats(-1.0, 1.0).map(lambda v: 0.0 if abs(v) < 1e-100 else v)


@settings(max_examples=500, deadline=None)
@given(s0=_sig, s1=_sig, s2=_sig, sig_scale=st.sampled_from([1e-3, 1.0, 30.0]), a=st.floats(1e-4, 2e-3),
       r=st.floats(2e-3, 1e-2))
def test_nearest_slip_zero_is_numpys_nearest_root(s0, s1, s2, sig_scale, a, r):
    """(ξ_b, d) against numpy.roots of the quadratic [½ σ2 c a², σ1, σ0] (σ2 drawn as s2·2/(c a²) so that the
    quadratic term is as large as the others): ξ_b to 1e-9 of max(1, |root|), d to 1e-9 relative with the same
    absolute floor (d = |root − clamp(root)| cancels where the root lies near ±1); at a tie of two real zeros beyond
    the two ends (_tied) either end.  Near-double roots are left out (|disc| < 1e-6 of σ1² + |4 aa σ0|: there the
    roots themselves move by √ε; the double root at 0 is checked below)."""
    curv = 1.0 / r
    sig0, sig1, sig2 = sig_scale * s0, sig_scale * s1, sig_scale * s2 * 2.0 / (curv * a * a)
    aa = 0.5 * sig2 * curv * a * a
    disc = sig1 * sig1 - 4.0 * aa * sig0
    assume(abs(disc) >= 1e-6 * (sig1 * sig1 + abs(4.0 * aa * sig0)))
    xb, d = S.nearest_slip_zero(sig0, sig1, sig2, a, curv)
    zeros = _zeros_numpy(sig0, sig1, sig2, a, curv)
    src = f"numpy.roots([{aa!r}, {sig1!r}, {sig0!r}])"
    if not zeros:
        assert math.isinf(d), (xb, d, src)
        return
    xr, dr, rmod = zeros[0]
    tol = 1e-9 * max(1.0, rmod)
    assert abs(d - dr) <= max(tol, 1e-9 * dr), (d, dr, src)
    ends = [z[0] for z in zeros] if _tied(zeros) else [xr]
    assert min(abs(xb - e) for e in ends) <= tol, (xb, ends, src)
    assert -1.0 <= xb <= 1.0 and d >= 0.0


def test_nearest_slip_zero_special_cases():
    """No slip at all: no zero, d = inf (the rule's affine limit); a constant slip (σ1 = σ2 = 0): likewise; a double
    root at ξ = 0 (pure rolling of a groove, σ0 = σ1 = 0): on the axis, d = 0; a complex pair x ± iy with x inside
    the axis: (x, y); the linear field σ0 + σ1 ξ: its root −σ0/σ1, clamped."""
    a, curv = 1e-3, 1.0 / 5e-3
    assert S.nearest_slip_zero(0.0, 0.0, 0.0, a, curv) == (0.0, math.inf)
    assert math.isinf(S.nearest_slip_zero(0.7, 0.0, 0.0, a, curv)[1])
    assert S.nearest_slip_zero(0.0, 0.0, 3.0, a, curv) == (0.0, 0.0)
    # aa (ξ − 0.3)² + aa·0.4² = aa ξ² − 0.6 aa ξ + 0.25 aa: roots 0.3 ± 0.4i
    sig2 = 2.0 / (curv * a * a)  # aa = 1
    xb, d = S.nearest_slip_zero(0.25, -0.6, sig2, a, curv)
    assert xb == pytest.approx(0.3, abs=1e-14) and d == pytest.approx(0.4, rel=1e-13)
    xb, d = S.nearest_slip_zero(1.5, 1.0, 0.0, a, curv)  # root −1.5 (the field scaled first: to rounding)
    assert xb == -1.0 and d == pytest.approx(0.5, rel=1e-15)
    # the same fields 1e-160 times weaker (σ1² would underflow unscaled): the same zeros
    assert S.nearest_slip_zero(1.5e-160, 1e-160, 0.0, a, curv) == pytest.approx((xb, d), rel=1e-15)
    assert S.nearest_slip_zero(0.25e-160, -0.6e-160, sig2 * 1e-160, a, curv) == pytest.approx((0.3, 0.4), rel=1e-13)


# --------------------------------------------------------------------------- 4. kernel against its reference


def _kernel_and_reference(args):
    out, ref = np.zeros(10), np.zeros(10)
    S.contact_traction(*args, out)
    S.contact_traction_reference(*args, ref)
    return out, ref


def _max_sliding(args):
    """(largest tangential sliding speed on the axis [m/s] — module docstring items 2–3, on 2,001 points, +1 % for
    what lies between them —, the sum of the surfaces' speeds at the centre [m/s])."""
    q, a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr = args[:13]
    ub, ur = vb + np.cross(wb, c - cb), vr + np.cross(wr, c - cr)
    curv = 0.0 if not math.isfinite(r_dev) else 1.0 / r_dev
    x = a * np.linspace(-1.0, 1.0, 2001)
    root = np.sqrt(np.maximum(0.0, 1.0 - (curv * x) ** 2))
    d = x[:, None] * m + (curv * x * x / (1.0 + root))[:, None] * n  # the points' offsets from the centre
    nj = root[:, None] * n - (curv * x)[:, None] * m  # their normals
    sv = (ub - ur) + np.cross(wb - wr, d)
    sv -= np.sum(sv * nj, axis=1)[:, None] * nj
    return 1.01 * np.max(np.linalg.norm(sv, axis=1)), np.linalg.norm(ub) + np.linalg.norm(ur)


def _rounding_slip(args):
    """The slip on the axis is below 1e-5 of the surfaces' speeds: the sliding speeds are differences of speeds
    rounded to ~2e-16 of them, the traction (μ rising from 0 with the slip) inherits that rounding over their size,
    and two implementations agree to 1e-10 only from there up (test_slices' operating range starts at 1e-5 slip)."""
    s_max, speeds = _max_sliding(args)
    return s_max < 1e-5 * speeds


def _rounding_moves_zeros(args):
    """The zeros of the rolling slip are ill-conditioned here: σ0 moved by 1e-14 of the surfaces' speeds (~50 times
    its rounding, which differs between the kernel's scalar and the reference's numpy arithmetic) changes their count
    (a double zero: pure rolling in a groove; a zero at an end of the axis) or moves one by more than 1e-10 (a zero of
    a small σ1, moved by rounding/σ1).  The two implementations may then integrate on different stretches, and agree
    only to that."""
    sig0, sig1, sig2, a, curv = _slip_field(args)
    delta = 1e-14 * _max_sliding(args)[1]
    nr, z1, z2 = S.rolling_slip_zeros(sig0, sig1, sig2, a, curv)
    for d in (-delta, delta):
        nr_d, z1_d, z2_d = S.rolling_slip_zeros(sig0 + d, sig1, sig2, a, curv)
        if nr_d != nr or max(abs(z1_d - z1), abs(z2_d - z2)) > 1e-10:
            return True
    return False


def _gross_scales(args):
    """Lower bounds of the sums of the moduli of the nodes' contributions to out[0:10] (the scale of the two
    implementations' rounding): the traction's Σ μ_j q_j ≥ P_t / max|s| with P_t the kernel's power with the rolling
    resistance off and max|s| the largest tangential sliding speed on the axis (_max_sliding); moments with the lever
    arms' lower bounds |centre − c| − 2a (the points lie within √2·a of the centre).  Where the net result cancels
    (pure spin: the net force is 1e-4 of the two sides' tractions) max|out| alone would ask for far less than
    rounding."""
    q, a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr, lub, n_slices = args
    lub_t = lub.copy()
    lub_t[S.L_ROLLRES] = 0.0
    out_t = np.zeros(10)
    S.contact_traction(q, a, b, r_dev, c, n, m, cb, vb, wb, cr, vr, wr, lub_t, n_slices, out_t)
    s_max = _max_sliding(args)[0]
    gross = out_t[9] / s_max if s_max > 0.0 else 0.0
    lever_b = max(0.0, np.linalg.norm(c - cb) - 2.0 * a)
    lever_r = max(0.0, np.linalg.norm(c - cr) - 2.0 * a)
    return np.array([gross] * 3 + [gross * lever_b] * 3 + [gross * lever_r] * 3 + [0.0])


def _assert_agree(out, ref, what, args):
    """Kernel and reference to 1e-10 (as test_slices holds the other rules): relative, and absolute 1e-10 of the
    largest entry, or of the entry's gross sum (_gross_scales) where that is larger."""
    scale = np.maximum(np.max(np.abs(ref)) + 1e-300, _gross_scales(args))
    err = np.abs(out - ref)
    bad = err > 1e-10 * np.maximum(np.abs(ref), scale)
    assert not np.any(bad), (f"contact_traction vs contact_traction_reference (its log rule), {what}: entries "
                             f"{np.nonzero(bad)[0]}, kernel {out[bad]}, reference {ref[bad]}, scale {scale[bad]}")
    assert out[9] >= 0.0


#: (u [m/s], slip, spin / u [rad/m], r_dev, the zeros of the rolling slip it has: "affine", "sinh" (d above the
#: floor), "floor" (d below LOG_SINH_FLOOR), 1 or 2)
_ZERO_CASES = [
    (1.0, 0.1, 0.0, math.inf, "affine"),  # constant slip across the axis: no zero anywhere
    (1.0, 0.1, 40.0, math.inf, "sinh"),  # the zero at ξ ≈ −1.36, d ≈ 0.36
    (1.0, 0.1, 53.0, math.inf, "floor"),  # the zero at ξ ≈ −1.02, d ≈ 0.023 < 0.05
    (2.0, 0.1, 10.0, R_DEV, "sinh"),  # the groove's quadratic: nearest zero at d ≈ 0.06
    (1.0, 0.01, 40.0, math.inf, 1),
    (1.0, 0.0, 1.0, math.inf, 1),  # spin without slip: the zero at ξ = 0, the net force 1e-4 of each side's
    (5.0, 0.001, 40.0, R_DEV, 1),
    (0.5, 0.01, 200.0, R_DEV, 1),
    (1.0, 0.01, 10.0, R_DEV, 2),  # Heathcote's two points of pure rolling, off-centre
    (1.0, 0.001, 0.0, R_DEV, 2),  # ... symmetric
    (20.0, 0.01, 0.0, R_DEV, 2),
]


def _zero_kind(args):
    sig = _slip_field(args)
    nroot, _, _ = S.rolling_slip_zeros(*sig)
    if nroot:
        return nroot
    d = S.nearest_slip_zero(*sig)[1]
    return "affine" if d > 1e6 else ("floor" if d < S.LOG_SINH_FLOOR else "sinh")


def _contact_tied(args):
    """The contact's rolling slip has no zero on the axis and two tied ones off it (_tied)."""
    sig = _slip_field(args)
    return S.rolling_slip_zeros(*sig)[0] == 0 and _tied(_zeros_numpy(*sig))


def test_explicit_cases_have_the_zero_configurations_they_name():
    """Each case of _ZERO_CASES has the zeros it is listed with (rolling_slip_zeros, nearest_slip_zero), so the
    kernel-vs-reference tests below cover 0 zeros (affine, sinh map above and at its floor), 1 and 2 zeros."""
    lub = _lub()
    kinds = [_zero_kind(_groove_args(u, slip, sr * u, Q, rd, lub, 0)) for u, slip, sr, rd, _ in _ZERO_CASES]
    assert kinds == [c[-1] for c in _ZERO_CASES]
    assert {"affine", "sinh", "floor", 1, 2} <= set(kinds)


@pytest.mark.parametrize("kw", [dict(model="boundary"), dict(model="fluid", fluid_model="curve"),
                                dict(model="fluid", fluid_model="physical"), dict(model="mixed", roughness=0.1e-6),
                                dict(model="mixed", roughness=0.3e-6, thermal=False)])
@pytest.mark.parametrize("n", NODES)
def test_kernel_matches_reference_with_each_zero_configuration(kw, n):
    """The cases of _ZERO_CASES at three loads: kernel and reference to 1e-10 (as test_slices holds the other
    rules); the tied states (_tied: at 20 N the groove's symmetric cases have their zeros beyond both ends) are
    test_tied_zeros_off_the_axis_grade_towards_either_end's."""
    lub = _lub(**kw)
    tied = []
    for u, slip, sr, rd, kind in _ZERO_CASES:
        for q in (20.0, 2000.0, 20000.0):
            args = _groove_args(u, slip, sr * u, q, rd, lub, S.LOG_BASE + n)
            if _contact_tied(args):
                tied.append((u, slip, sr, q))
                continue
            _assert_agree(*_kernel_and_reference(args), f"{kind} zeros, {kw}, u {u}, slip {slip}, Q {q}", args)
    assert tied == [(20.0, 0.01, 0.0, 20.0)], tied


_MODELS = [dict(model="boundary"), dict(model="fluid", fluid_model="curve"), dict(model="fluid"),
           dict(model="mixed", roughness=0.1e-6), dict(model="mixed", roughness=0.3e-6, starvation_factor=0.7),
           dict(model="fluid", viscoelastic=False)]
_LUBS = [_lub(**kw) for kw in _MODELS]


@settings(max_examples=150, deadline=None)
@given(n=st.integers(S.LOG_MIN, S.LOG_MAX), model=st.integers(0, len(_MODELS) - 1),
       log_u=st.floats(math.log(0.01), math.log(50.0)), slip=st.floats(-0.5, 0.5),
       spin_ratio=st.floats(-200.0, 200.0), log_q=st.floats(math.log(20.0), math.log(20000.0)),
       rd=st.sampled_from([math.inf, R_DEV, -0.02, 0.004]))
def test_kernel_matches_reference_over_the_operating_range(n, model, log_u, slip, spin_ratio, log_q, rd):
    """Speeds, slips, spins, loads and curvatures of ball bearings drawn by hypothesis: kernel and reference to
    1e-10."""
    u = math.exp(log_u)
    args = _groove_args(u, slip, spin_ratio * u, math.exp(log_q), rd, _LUBS[model], S.LOG_BASE + n)
    assume(not _contact_tied(args))  # (test_tied_zeros_off_the_axis_grade_towards_either_end)
    assume(not _rounding_slip(args) and not _rounding_moves_zeros(args))
    event(f"zeros: {_zero_kind(args)}")
    _assert_agree(*_kernel_and_reference(args), f"{_MODELS[model]}, zeros: {_zero_kind(args)}", args)


@settings(max_examples=100, deadline=None)
@given(n=st.integers(S.LOG_MIN, S.LOG_MAX), model=st.integers(0, len(_MODELS) - 1), seed=st.integers(0, 2**32 - 1),
       trial=st.integers(0, 3))
def test_kernel_matches_reference_in_random_geometry(n, model, seed, trial):
    """The random contact states of test_slices.test_kernel_matches_reference (any normal, major axis, velocities
    and angular velocities; four curvatures and loads): kernel and reference to 1e-10."""
    rng = np.random.default_rng(seed)
    nv = rng.normal(size=3)
    nv /= np.linalg.norm(nv)
    m = np.cross(nv, rng.normal(size=3))
    m /= np.linalg.norm(m)
    c = rng.normal(size=3) * 0.01
    cb, cr = c + R_BALL * nv, c - 0.02 * nv + 0.003 * m
    vb, wb = rng.normal(size=3) * 3, rng.normal(size=3) * 500
    vr, wr = rng.normal(size=3) * 0.5, rng.normal(size=3) * 200
    r_dev = [math.inf, R_DEV, -0.02, 0.004][trial]
    q = [Q, 300.0, 5000.0, 1.0][trial]
    a, b = HC.a * (q / Q) ** (1 / 3), HC.b * (q / Q) ** (1 / 3)
    args = (q, a, b, r_dev, c, nv, m, cb, vb, wb, cr, vr, wr, _LUBS[model], S.LOG_BASE + n)
    assume(not _contact_tied(args))  # (test_tied_zeros_off_the_axis_grade_towards_either_end)
    assume(not _rounding_slip(args) and not _rounding_moves_zeros(args))
    event(f"zeros: {_zero_kind(args)}")
    _assert_agree(*_kernel_and_reference(args), f"{_MODELS[model]}, zeros: {_zero_kind(args)}", args)


@pytest.mark.parametrize("n", NODES)
def test_tied_zeros_off_the_axis_grade_towards_either_end(n):
    """A groove without spin, sliding 1 % at 20 N: the rolling slip σ0 + σ2 δ(aξ) is even in ξ, its zeros lie beyond
    both ends at the same distance (_tied), and the kernel and the reference may grade the sinh map towards opposite
    ends (mirror-image nodes).  Then what the mirror ξ → −ξ keeps (force along the rolling direction, moments about
    the major axis, power) agrees to 1e-10 all the same, and the moments about the normal — zero for the even field —
    are the rule's asymmetry only: below 1e-6 of the largest entry either way (measured 2.4e-8); the jump of the
    whole result when a small spin of either sign breaks the tie stays below 1e-5 of |F, M| (measured ≤ 1.2e-6 at
    2 kN, 10 % slip, where the rule is within 5e-5 of 4,096 strips)."""
    lub = _lub(model="mixed", roughness=0.1e-6)
    args = _groove_args(20.0, 0.01, 0.0, 20.0, R_DEV, lub, S.LOG_BASE + n)
    assert _contact_tied(args)
    out, ref = _kernel_and_reference(args)
    scale = np.max(np.abs(ref))
    even = [1, 3, 6, 9]
    np.testing.assert_allclose(out[even], ref[even], rtol=1e-10, atol=1e-10 * scale,
                               err_msg="contact_traction vs contact_traction_reference at a tie, mirror-even entries")
    for r in (out, ref):
        assert np.all(np.abs(r[[0, 2, 4, 7]]) <= 1e-10 * scale), r  # (zero by symmetry in any rule)
        assert np.all(np.abs(r[[5, 8]]) <= 1e-6 * scale), r
    side = []
    for spin in (-1e-9, 1e-9):
        o = np.zeros(10)
        S.contact_traction(*_groove_args(1.0, 0.1, spin, 2000.0, R_DEV, lub, S.LOG_BASE + n), o)
        side.append(o)
    assert np.linalg.norm(side[0][:9] - side[1][:9]) <= 1e-5 * np.linalg.norm(side[0][:9]), side


# --------------------------------------------------------------------------- 5. closed forms, constant μ


@pytest.mark.parametrize("n", NODES)
def test_pure_spin_constant_mu_is_exact(n):
    """Spin about the normal of a flat contact, constant μ: one zero at ξ = 0, at least 3 nodes on each of the
    stretches [−1, 0] and [0, 1] (_log_counts), and on each the integrand (1 − ξ²)|ξ| of degree 3 ≤ 2·3 − 2 is
    integrated exactly by the one-sided rule: the moment about the normal is −3μQa/8 (the closed form of the strip
    model's docstring, seed 001 eq. 1 with constant μ), the force zero."""
    assert min(S._log_counts(n, 1)[:2]) >= 3
    mu = 0.08
    out = _flat(0.0, 0.0, 50.0, _constant_mu(mu), S.LOG_BASE + n)
    assert out[5] == pytest.approx(-3 * mu * Q * HC.a / 8, rel=1e-12), "pure spin: −3μQa/8 (seed 001 eq. 1)"
    np.testing.assert_allclose(out[0:3], 0.0, atol=1e-12 * mu * Q, err_msg="pure spin: no net force")


@pytest.mark.parametrize("z", [0.3, 0.6, -0.45, -0.9])
@pytest.mark.parametrize("n", NODES)
def test_off_centre_zero_constant_mu_is_exact(n, z):
    """Spin and sliding on a flat contact, constant μ, the rolling slip spin·a(ξ − z) with its zero at ξ = z: with
    ≥ 3 nodes on each stretch the closed forms of seed 001 eq. 1's load density (3Q/4)(1 − ξ²) are exact to 1e-12:
        F_y = μQ(3z − z³)/2,  M_z = −(3μQa/8)(1 − z²)²,  power = (3μQ/4)|spin| a (1/2 + z² − z⁴/6)."""
    assert min(S._log_counts(n, 1)[:2]) >= 3
    mu, spin = 0.08, 50.0
    out = _flat(0.0, z * spin * HC.a, spin, _constant_mu(mu), S.LOG_BASE + n)
    assert out[1] == pytest.approx(mu * Q * (3 * z - z**3) / 2, rel=1e-12), "F_y = μQ(3z − z³)/2 (seed 001 eq. 1)"
    assert out[5] == pytest.approx(-3 * mu * Q * HC.a / 8 * (1 - z * z) ** 2, rel=1e-12), \
        "M_z = −(3μQa/8)(1 − z²)² (seed 001 eq. 1)"
    assert out[9] == pytest.approx(0.75 * mu * Q * spin * HC.a * (0.5 + z * z - z**4 / 6), rel=1e-12), \
        "power = (3μQ/4)|ω|a(1/2 + z² − z⁴/6) (seed 001 eq. 1)"


@pytest.mark.parametrize("n", NODES)
def test_uniform_sliding_constant_mu_gives_mu_q(n):
    """No zero anywhere (d = inf): n Gauss–Legendre nodes on [−1, 1], the load density (1 − ξ²) exact: F = μQ
    against the sliding, power μQ|s| (seed 001 eq. 2 with constant μ)."""
    mu = 0.07
    out = _flat(1.0, -1.0, 0.0, _constant_mu(mu), S.LOG_BASE + n)
    np.testing.assert_allclose(out[0:3], [0.0, -mu * Q, 0.0], rtol=1e-12, atol=1e-12 * mu * Q,
                               err_msg="uniform sliding: F = μQ (seed 001 eq. 2)")
    assert out[9] == pytest.approx(mu * Q * 2.0, rel=1e-12)


# --------------------------------------------------------------------------- 6. the hub states


@pytest.mark.parametrize("scale", [0.99, 1.0, 1.01])
def test_hub_states_seven_nodes_against_the_strip_limit(scale):
    """The hub states of test_dyn_options (ball spin 1 % below, at and above Jones' value): the ball accelerations
    (traction forces and moments of the 64 contacts) with the log rule's 7 nodes against 1,024 equal strips (the
    strip limit of seed 001 eqs. 1–2; 128 strips differ from it by 0.1–0.3 %).  Measured: 0.20 / 0.32 / 0.72 % (8
    equal strips 8.3 / 2.7 / 14.3 %: 0.02 / 0.12 / 0.05 of theirs), power −0.19 / −0.23 / +0.37 %; 6 nodes reach
    5.5 % at 1.01, hence 7."""
    ref, pref = _hub_accelerations(1024, scale)
    acc, p = _hub_accelerations(S.LOG_BASE + 7, scale)
    a8, _ = _hub_accelerations(8, scale)
    err = np.linalg.norm(acc - ref) / np.linalg.norm(ref)
    err8 = np.linalg.norm(a8 - ref) / np.linalg.norm(ref)
    assert err < 0.01, f"7 log-rule nodes vs 1,024 equal strips (the strip limit of seed 001 eqs. 1–2): {err:.4%}"
    assert err < 0.3 * err8, \
        f"7 log-rule nodes {err:.4%} vs 8 equal strips {err8:.4%} against 1,024 equal strips (the strip limit of " \
        f"seed 001 eqs. 1–2)"
    assert p == pytest.approx(pref, rel=0.01), \
        f"power loss vs 1,024 equal strips (the strip limit of seed 001 eqs. 1–2): {p / pref - 1:+.4%}"


# --------------------------------------------------------------------------- 7. the nodes


def test_the_rule_takes_one_pass_of_the_lanes():
    """At most LOG_MAX nodes, one pass of the kernel's eight lanes; the tables cover the node counts."""
    assert S.LOG_MAX <= S.LANES
    assert S.LOG_MAX <= S.GAUSS_MAX  # the root-free stretch takes Gauss–Legendre row n


def _stretches(n, nroot, z1, z2):
    """[(lo, hi, zero_lo, zero_hi, [(ξ, w), …])] of the log rule's nodes (_log_node.py_func) on each stretch between
    the zeros, in the kernel's order m = 0, 1, …; and the nodes m past the dealt ones."""
    counts = S._log_counts(n, nroot)
    edges = [-1.0] + [z1, z2][:nroot] + [1.0]
    out, m = [], 0
    for k, nk in enumerate(counts[:nroot + 1]):
        nodes = [_node(S._log_node.py_func, m + i, nroot, z1, z2, counts) for i in range(nk)]
        out.append((edges[k], edges[k + 1], k > 0, k < nroot, nodes))
        m += nk
    rest = [_node(S._log_node.py_func, i, nroot, z1, z2, counts) for i in range(m, n)]
    return out, rest


#: zeros as rolling_slip_zeros returns them: inside (−1 + 1e-9, 1 − 1e-9), two of them at least 1e-9 apart
_kernel_zero = st.floats(-1.0 + 1e-9, 1.0 - 1e-9, exclude_min=True, exclude_max=True)


@settings(max_examples=300, deadline=None)
@given(n=st.integers(S.LOG_MIN, S.LOG_MAX), nroot=st.integers(1, 2), za=_kernel_zero, zb=_kernel_zero)
def test_log_nodes_with_zeros_integrate_each_stretch_to_the_rules_degree(n, nroot, za, zb):
    """With zeros on the axis, the nodes of _log_node (py_func; the compiled function to rounding) on each stretch
    [lo, hi] of length L lie on it with positive weights, and integrate, to 1e-13 of L(1 + |ln L|) + 1e-14:
    ((ξ − lo)/L)^k → L/(k + 1) up to the rule's degree (one-sided 2n_k − 2, two-sided 2n_k − 3), and the logarithm
    of the distance to the stretch's zero(s): ln(ξ − lo) or ln(hi − ξ) → L(ln L − 1) (one-sided, from the end the
    zero is at: the table's orientation), ln(ξ − lo) + ln(hi − ξ) → 2L(ln L − 1) (two-sided); all weights sum to
    2 = ∫₋₁¹ dξ to 1e-12.  Nodes past the dealt ones (one zero, odd n: test_every_node_is_used_with_one_zero) carry
    weight 0 exactly and add nothing."""
    z1, z2 = min(za, zb), max(za, zb)
    assume(nroot < 2 or z2 - z1 > 1e-9)
    stretches, rest = _stretches(n, nroot, z1, z2)
    counts = S._log_counts(n, nroot)
    total = []
    for m in range(n):
        xi, w = _node(S._log_node.py_func, m, nroot, z1, z2, counts)
        xc, wc = _node(S._log_node, m, nroot, z1, z2, counts)
        assert xc == pytest.approx(xi, abs=1e-15) and wc == pytest.approx(w, rel=1e-14, abs=1e-300), m
    for lo, hi, zlo, zhi, nodes in stretches:
        span = hi - lo
        xs = np.array([p[0] for p in nodes])
        ws = np.array([p[1] for p in nodes])
        assert np.all((xs >= lo) & (xs <= hi)), (xs, lo, hi)
        assert np.all(ws > 0.0), ws
        total += list(ws)
        # (plus 1e-14: the nodes are rounded to the grid of ξ, ~1e-16, which moves t = (ξ − lo)/L by ~1e-16/L and
        # the moments, whose weights sum to L, by ~k·1e-16; the logarithm's smallest node by ~3e-16)
        tol = 1e-13 * span * (1.0 + abs(math.log(span))) + 1e-14
        nk = len(nodes)
        degree = 2 * nk - 3 if (zlo and zhi) else 2 * nk - 2
        t = np.clip((xs - lo) / span, 0.0, 1.0)
        for k in range(degree + 1):
            assert abs(np.dot(ws, t**k) - span / (k + 1)) <= tol, (k, lo, hi, nk)
        exact_log = span * (math.log(span) - 1.0)
        if zlo and zhi:
            got = np.dot(ws, np.log(xs - lo) + np.log(hi - xs))
            assert abs(got - 2.0 * exact_log) <= 2.0 * tol, ("ln(ξ − lo) + ln(hi − ξ)", lo, hi, nk)
        elif zlo:
            assert abs(np.dot(ws, np.log(xs - lo)) - exact_log) <= tol, ("ln(ξ − lo)", lo, hi, nk)
        else:
            assert abs(np.dot(ws, np.log(hi - xs)) - exact_log) <= tol, ("ln(hi − ξ)", lo, hi, nk)
    assert math.fsum(total) == pytest.approx(2.0, abs=1e-12), "∫₋₁¹ dξ = 2"
    assert all(w == 0.0 for _, w in rest), rest


@pytest.mark.parametrize("n", NODES)
def test_log_nodes_do_not_exceed_the_rules_degree(n):
    """Two zeros at ±0.5: the outer stretches take the one-sided 2-node rule (exact to degree 2, not 3), the middle
    the two-sided (n − 4)-node rule (exact to degree 2n − 11, not one more): the degrees that the exactness above
    relies on are the rules', not an accident of this configuration."""
    stretches, _ = _stretches(n, 2, -0.5, 0.5)
    for lo, hi, zlo, zhi, nodes in stretches:
        nk = len(nodes)
        k = (2 * nk - 2 if (zlo and zhi) else 2 * nk - 1)
        xs, ws = np.array([p[0] for p in nodes]), np.array([p[1] for p in nodes])
        t = (xs - lo) / (hi - lo)
        assert abs(np.dot(ws, t**k) - (hi - lo) / (k + 1)) > 1e-8, (lo, hi, nk, k)


def _gauss_remainder_bound(n, u0, u1, y):
    """The Gauss–Legendre remainder of ∫ y cosh u du over [u0, u1] with n nodes:
    L^(2n+1) (n!)⁴ / ((2n+1) ((2n)!)³) · max f^(2n), L = u1 − u0, f^(2n) = y cosh u (Abramowitz & Stegun 25.4.30),
    and it is positive (the rule underestimates) since f^(2n) > 0."""
    span = u1 - u0
    c = span ** (2 * n + 1) * math.factorial(n) ** 4 / ((2 * n + 1) * math.factorial(2 * n) ** 3)
    return c * y * math.cosh(max(abs(u0), abs(u1)))


@settings(max_examples=300, deadline=None)
@given(n=st.integers(S.LOG_MIN, S.LOG_MAX), xb=st.floats(-1.0, 1.0), dz=st.floats(0.0, 1e7))
def test_log_nodes_without_zeros_follow_the_sinh_map(n, xb, dz):
    """No zero on the axis: n Gauss–Legendre nodes in u under ξ = ξ_b + y sinh u, y = max(d, LOG_SINH_FLOOR): nodes
    inside [−1, 1] ascending, weights positive, their sum ∫ y cosh u du = 2 up to the Gauss–Legendre remainder of
    that integral (positive, at most its bound; measured 2.3e-6 at n = 6, ξ_b = 0, d at the floor); beyond
    d = 1e6 exactly numpy's Gauss–Legendre rule (the affine limit)."""
    nodes = [_node(S._log_node.py_func, m, 0, 0.0, 0.0, (n, 0, 0), xb, dz) for m in range(n)]
    xs, ws = np.array([p[0] for p in nodes]), np.array([p[1] for p in nodes])
    assert np.all(xs >= -1.0) and np.all(xs <= 1.0) and np.all(np.diff(xs) > 0.0), xs
    assert np.all(ws > 0.0), ws
    y = max(dz, S.LOG_SINH_FLOOR)
    if y > 1e6:
        xg, wg = np.polynomial.legendre.leggauss(n)
        np.testing.assert_allclose(xs, xg, rtol=0, atol=1e-15, err_msg="numpy.polynomial.legendre.leggauss")
        np.testing.assert_allclose(ws, wg, rtol=1e-15, err_msg="numpy.polynomial.legendre.leggauss")
        return
    u0, u1 = math.asinh((-1.0 - xb) / y), math.asinh((1.0 - xb) / y)
    deficit = 2.0 - math.fsum(ws)
    bound = _gauss_remainder_bound(n, u0, u1, y)
    assert -1e-14 <= deficit <= bound + 1e-14, (deficit, bound)


def test_log_nodes_without_zeros_at_infinite_distance_are_gauss_legendre():
    """d = inf (no zero at all): the nodes are exactly numpy's Gauss–Legendre nodes and weights (the affine map)."""
    for n in NODES:
        xg, wg = np.polynomial.legendre.leggauss(n)
        for f in (S._log_node.py_func, S._log_node):
            nodes = [_node(f, m, 0, 0.0, 0.0, (n, 0, 0), 0.3, math.inf) for m in range(n)]
            np.testing.assert_allclose([p[0] for p in nodes], xg, rtol=0, atol=1e-15,
                                       err_msg="numpy.polynomial.legendre.leggauss")
            np.testing.assert_allclose([p[1] for p in nodes], wg, rtol=1e-15,
                                       err_msg="numpy.polynomial.legendre.leggauss")
