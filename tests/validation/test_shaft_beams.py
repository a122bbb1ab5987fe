"""Shaft beam model against closed forms: static deflections (Roark; Timoshenko & Gere) and natural frequencies
(Blevins; the Rayleigh beam)."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearingsim.shafts.model import PointLoad, Section, ShaftSystem, SpringSupport
from bearingsim.shafts.modes import modes
from bearingsim.shafts.solve import solve_shaft

E, NU, RHO = 208e9, 0.30, 7900.0  # bearing_steel (materials.LIBRARY)
G = E / (2 * (1 + NU))
CLAMP = [1e16] * 5  # a clamp: stiffer than the beam by ≥ 1e9


def _props(d_o, d_i=0.0):
    s = Section(1.0, d_o, d_i)
    return s.area, s.second_moment, s.shear_coefficient


@pytest.mark.parametrize("shear", [False, True])
@pytest.mark.parametrize("d_i", [0.0, 0.03])
def test_cantilever_tip(shear, d_i):
    """Tip deflection and slope of a cantilever under a tip force: δ = PL³/3EI (+ PL/κGA with shear), θ = PL²/2EI
    (Roark's Formulas 7th ed. table 8.1 case 1a; Timoshenko & Gere, Mechanics of Materials, shear deflection)."""
    L, d, P = 0.3, 0.05, 2000.0
    s = ShaftSystem((Section(L, d, d_i),), (SpringSupport("clamp", 0.0, CLAMP),), (PointLoad(L, (0.0, P, P)),),
                    elements=7, shear=shear)
    r = solve_shaft(s)
    A, I, k = _props(d, d_i)
    delta = P * L**3 / (3 * E * I) + (P * L / (k * G * A) if shear else 0.0)
    assert r.converged
    src = "Roark 7th ed. table 8.1 case 1a" + (" + shear term PL/(kGA), Cowper k" if shear else "")
    assert_allclose(r.displacement[-1, [1, 2]], [delta, delta], rtol=1e-8, err_msg=src)
    assert_allclose(r.displacement[-1, 4], P * L**2 / (2 * E * I), rtol=1e-8, err_msg="Roark: slope PL²/2EI")
    assert_allclose(r.displacement[-1, 3], -P * L**2 / (2 * E * I), rtol=1e-8,
                    err_msg="Roark: slope about y, γy = −dz/dx")


def test_cantilever_axial():
    """Axial tip deflection PL/EA of a bar (Timoshenko & Gere)."""
    L, d, P = 0.3, 0.05, 5e4
    s = ShaftSystem((Section(L, d),), (SpringSupport("clamp", 0.0, CLAMP),), (PointLoad(L, (P, 0.0, 0.0)),))
    A, _, _ = _props(d)
    ref = P * L / (E * A) + P / CLAMP[0]  # the bar and the clamp's spring in series
    assert_allclose(solve_shaft(s).displacement[-1, 0], ref, rtol=1e-9, err_msg="Timoshenko & Gere PL/EA")


def test_overhung_beam_tip():
    """Simply supported beam with an overhang c loaded at its free end: tip deflection P c² (a + c) / 3EI
    (Roark 7th ed. table 8.1, end support with overhang; Euler–Bernoulli) and the reactions P c/a, P(a + c)/a."""
    a, c, d, P = 0.4, 0.15, 0.04, 1000.0
    pin = [1e15, 1e15, 1e15, 0.0, 0.0]
    roller = [0.0, 1e15, 1e15, 0.0, 0.0]
    s = ShaftSystem((Section(a + c, d),), (SpringSupport("A", 0.0, pin), SpringSupport("B", a, roller)),
                    (PointLoad(a + c, (0.0, P, 0.0)),), elements=22, shear=False)
    r = solve_shaft(s)
    _, I, _ = _props(d)
    assert_allclose(r.displacement[-1, 1], P * c**2 * (a + c) / (3 * E * I), rtol=1e-6, err_msg="Roark overhang")
    assert_allclose(r.support("A").reaction[1], P * c / a, rtol=1e-9, err_msg="statics: R_A = Pc/a")
    assert_allclose(r.support("B").reaction[1], -P * (a + c) / a, rtol=1e-9, err_msg="statics: R_B = −P(a+c)/a")


@pytest.mark.parametrize("shear", [False, True])
def test_shaft_on_two_springs(shear):
    """Uniform shaft on two linear radial springs k1, k2 at its ends, force P at b: y(b) = (R1/k1)(L−b)/L +
    (R2/k2) b/L + P b²(L−b)²/(3EIL) [+ P b(L−b)/(κGAL)], R1 = P(L−b)/L, R2 = P b/L (superposition of the rigid
    motion on the springs and the simply supported beam, Roark 7th ed. table 8.1 case 1e)."""
    L, b, d, P, k1, k2 = 0.5, 0.2, 0.045, 3000.0, 2e8, 5e8
    s = ShaftSystem((Section(L, d),), (SpringSupport("1", 0.0, [1e9, k1, k1, 0, 0]),
                                       SpringSupport("2", L, [0.0, k2, k2, 0, 0])),
                    (PointLoad(b, (0.0, 0.0, P)),), elements=20, shear=shear)
    r = solve_shaft(s)
    A, I, k = _props(d)
    r1, r2 = P * (L - b) / L, P * b / L
    y = r1 / k1 * (L - b) / L + r2 / k2 * b / L + P * b**2 * (L - b) ** 2 / (3 * E * I * L)
    y += P * b * (L - b) / (k * G * A * L) if shear else 0.0
    i = int(np.argmin(abs(r.nodes - b)))
    assert_allclose(r.displacement[i, 2], y, rtol=1e-8, err_msg="closed form: springs + Roark table 8.1 case 1e")


def _frequencies(system, n):
    return modes(solve_shaft(system), n).frequency_hz


def test_free_free_frequencies():
    """Free–free uniform shaft: f_n = (β_n L)² / (2π L²) √(EI/ρA), β_n L = 4.73004, 7.85320, 10.99561 (Blevins,
    Formulas for Natural Frequency and Mode Shape, table 8-1).  The shaft is slender (L/d = 200) so that rotary
    inertia, which the element includes, lowers f_n by (β_n r_g)² / 2 < 2e-4; soft springs (1e-3 N/m) hold it."""
    L, d = 2.0, 0.01
    soft = [1e-3] * 5
    s = ShaftSystem((Section(L, d),), (SpringSupport("a", 0.0, soft), SpringSupport("b", L, soft)), elements=60,
                    shear=False)
    f = _frequencies(s, 11)
    A, I, _ = _props(d)
    beta = np.array([4.730040745, 7.853204624, 10.99560784])
    ref = beta**2 / (2 * math.pi * L**2) * math.sqrt(E * I / (RHO * A))
    assert np.all(f[:5] < 0.05), "five rigid-body modes on the soft springs"
    assert_allclose(f[5:11:2], ref, rtol=5e-4, err_msg="Blevins table 8-1 free-free beam")
    assert_allclose(f[5:11:2], f[6:11:2], rtol=1e-10, err_msg="axisymmetric shaft: equal y and z frequencies")


@pytest.mark.parametrize("shear", [False, True])
def test_simply_supported_frequencies(shear):
    """Simply supported shaft, L/d = 25.  Rayleigh beam (rotary inertia, no shear): f_n = (nπ/L)² √(EI/ρA) /
    (2π √(1 + (nπ r_g/L)²)), r_g² = I/A; Timoshenko beam: the lower root of
    (ρ²I/κG) ω⁴ − [ρA + ρIα²(1 + E/κG)] ω² + EIα⁴ = 0, α = nπ/L (Han, Benaroya & Wei, J. Sound Vib. 225 (1999)
    935, simply supported case; Blevins table 8-1 for the Euler–Bernoulli limit).  The element's mass is the
    Φ = 0 consistent mass, so that the ω⁴ term is approximated: within 3e-4 up to n = 3 here."""
    L, d = 1.0, 0.04
    pin = [1e14, 1e14, 1e14, 0.0, 0.0]
    roller = [0.0, 1e14, 1e14, 0.0, 0.0]
    s = ShaftSystem((Section(L, d),), (SpringSupport("a", 0.0, pin), SpringSupport("b", L, roller)), elements=60,
                    shear=shear)
    f = _frequencies(s, 6)[::2]
    A, I, k = _props(d)
    ref = []
    for n in (1, 2, 3):
        a = n * math.pi / L
        if shear:
            w2 = min(np.roots([RHO**2 * I / (k * G), -(RHO * A + RHO * I * a**2 * (1 + E / (k * G))),
                               E * I * a**4]).real)
        else:
            w2 = E * I * a**4 / (RHO * A * (1 + a**2 * I / A))
        ref.append(math.sqrt(w2) / (2 * math.pi))
    src = "Han, Benaroya & Wei 1999: simply supported " + ("Timoshenko" if shear else "Rayleigh") + " beam"
    assert_allclose(f, ref, rtol=3e-4 if shear else 2e-5, err_msg=src)


def test_spinning_simply_supported_whirl():
    """Spinning simply supported Rayleigh shaft: (ρA + ρIα²) ω² ∓ 2ρIα²Ω ω − EIα⁴ = 0, α = nπ/L, forward (−)
    above and backward (+) below the standstill frequency (Lalanne & Ferraris, Rotordynamics Prediction in
    Engineering, 2nd ed. 1998, ch. 3, simply supported uniform rotor; polar I_p = 2I)."""
    L, d, spin = 1.0, 0.02, 3000.0
    pin = [1e12, 1e12, 1e12, 0.0, 0.0]
    roller = [0.0, 1e12, 1e12, 0.0, 0.0]
    s = ShaftSystem((Section(L, d),), (SpringSupport("a", 0.0, pin), SpringSupport("b", L, roller)), elements=40,
                    shear=False, speed=spin)
    m = modes(solve_shaft(s), 6, gyroscopic=True)
    A, I, _ = _props(d)
    ref, whirl = [], []
    for n in (1, 2, 3):
        a = n * math.pi / L
        for sgn in (-1, 1):
            c = [RHO * A + RHO * I * a * a, -sgn * 2 * RHO * I * a * a * spin, -E * I * a**4]
            ref.append(max(np.roots(c).real) / (2 * math.pi))
            whirl.append(sgn)
    assert_allclose(m.frequency_hz, ref, rtol=1e-5, err_msg="Lalanne & Ferraris: spinning simply supported shaft")
    assert list(m.whirl) == whirl, "backward whirl below, forward above"
