"""Cage stresses recovered from the FE ring (bearingsim.cage_modes.element_end_forces, normal_stress,
stress_shapes, peak_stress): closed forms and invariants.

References (thin ring of centroid radius R, section A, I about the axial axis):

* two equal and opposite diametral loads W pinching a thin ring (Roark's Formulas for Stress and
  Strain, 7th ed., table 9.2 case 1): M_A = W R k2/π at the load points, N_A = 0, and
  M(x) = M_A − W R sin x / 2, N(x) = −(W/2) sin x at x from the load point, k2 = 1 − α, α = I/(A R²)
  (hoop-stress deformation factor); at x = 90°: M_C = W R (k2/π − 1/2), N_C = −W/2.  Roark's positive
  M is the one that stretches the inner fibre (at the load points of a pinched ring the inner surface
  is in tension).  Navier's σ = N/A ± 6 M/(b t²) at the surfaces (Roark §8.1).
* uniform radial pressure p (force per unit length of the centroid circle): hoop force N = p R, no
  bending (Roark table 9.2 / any strength-of-materials text); σ = N/A in every section.
* uniformly distributed twisting couple m per unit length about the centroid tangent (ring
  "everting"): bending moment about the radial axis M = m R in every section, σ = M x/I_out.

In the FE model the centroid circle is a polygon of chords; the nodal loads below are the exact
polygon equivalents of pressure and twist (the membrane / pure-bending states are then exact), and
the diametral case carries the O(h²) chord error shown by the convergence assertion.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearingsim.cage_modes import (
    CageRing,
    assemble,
    cage_modes,
    element_end_forces,
    normal_stress,
    peak_stress,
    peak_stress_location,
    stress_points,
    stress_shapes,
    torsion_shear_stress,
)
from bearingsim.cage_modes.stress import _element_frames
from bearingsim.errors import InputError

E, NU = 2.06e11, 0.3
R, B, T = 0.05, 0.003, 0.002  # slender uniform ring, R/t = 25
A, I_IN, I_OUT = B * T, B * T**3 / 12, T * B**3 / 12


def uniform(epp=8, z=12, **kw):
    return CageRing(R, B, T, z, 0.001, pockets=False, elements_per_pitch=epp, **kw)


def pocketed_ring(**kw):
    return CageRing(0.03, 0.012, 0.003, 8, 0.008, **kw)


def _pinch(fe, z, W, j0=0):
    """Inward radial loads W at pockets j0 and j0 + Z/2 (pinching), static deflection and resultants."""
    f = np.zeros((z, 3))
    for j in (j0, j0 + z // 2):
        psi = fe.ring.pocket_azimuths[j]
        f[j] = -W * np.array([0.0, math.cos(psi), math.sin(psi)])
    u = fe.static_deflection(fe.pocket_load_vector(f))
    return u, element_end_forces(fe, u)


# ---- 1. diametral pinching, Roark table 9.2 case 1 ---------------------------------------------
@pytest.mark.parametrize("shear", [False, True])
def test_diametral_pinching_moments_roark(shear):
    W = 10.0
    k2 = 1 - I_IN / (A * R**2)
    MA, MC = W * R * k2 / math.pi, W * R * (k2 / math.pi - 0.5)
    err = {}
    for epp in (4, 8):
        fe = assemble(uniform(epp, shear_deformation=shear))
        _, F = _pinch(fe, 12, W)
        q = fe.n_nodes // 4  # node at 90° from the load point
        # local M_z' is about the cage axis with the opposite sign to Roark's M (σ = −M_z' y'/I, y' inward)
        m_a = -np.array([F[0, 0, 5], F[-1, 1, 5]])
        m_c = -np.array([F[q, 0, 5], F[q - 1, 1, 5]])
        err[epp] = (m_a / MA - 1, m_c / MC - 1)
        if epp == 8:
            # 96 chords: M_A −2.2e-4, M_C +3.9e-4 (48 chords: −1.3e-3, +2.3e-3); M_A does not depend on
            # the shear deformation (Roark: k2 only)
            assert_allclose(m_a, MA, rtol=5e-4, err_msg="Roark 7th ed. table 9.2 case 1: M_A = W R k2/π")
            assert_allclose(m_c, MC, rtol=1e-3, err_msg="Roark 7th ed. table 9.2 case 1: M_C = W R (k2/π − 1/2)")
            # hoop force at 90°: −W/2 along the tangent (the chord is inclined by half its angle)
            half = math.pi / fe.n_nodes
            assert_allclose(F[q, 0, 0], -W / 2 * math.cos(half), rtol=1e-6,
                            err_msg="Roark table 9.2 case 1: N_C = −W/2")
            # extreme-fibre stresses at the load point (N_A = 0): inner surface +6 M_A/(b t²) (tension)
            s = normal_stress(fe, F)
            pts = stress_points(fe)
            inner, outer = pts[:, 0] < 0, pts[:, 0] > 0
            sig = 6 * MA / (B * T**2)
            assert_allclose(s[0, 0, inner], sig, rtol=1e-3,
                            err_msg="Roark table 9.2 case 1 + Navier, inner fibre at A")
            assert_allclose(s[0, 0, outer], -sig, rtol=1e-3,
                            err_msg="Roark table 9.2 case 1 + Navier, outer fibre at A")
            # at 90°: σ = −W/(2A) ∓ 6 M_C/(b t²) … M_C < 0 stretches the outer fibre
            assert_allclose(s[q, 0, outer], -W / (2 * A) - 6 * MC / (B * T**2), rtol=1e-3,
                            err_msg="Roark table 9.2 case 1 + Navier, outer fibre at 90°")
            assert_allclose(s[q, 0, inner], -W / (2 * A) + 6 * MC / (B * T**2), rtol=1e-3,
                            err_msg="Roark table 9.2 case 1 + Navier, inner fibre at 90°")
            # the largest |σ| sits at a load point (ψ = 0 or π)
            el, end, _ = np.unravel_index(int(np.argmax(np.abs(s))), s.shape)
            assert fe.elements[el, end] in (0, fe.n_nodes // 2)
    for i in range(2):
        assert np.all(np.abs(err[8][i]) < np.abs(err[4][i]) / 3), "O(h²) convergence to Roark table 9.2 case 1"


def test_pinched_pocketed_ring_statics():
    """Pocketed ring (Z = 8, loads on pockets 0 and 4): by the two mirror symmetries the section at
    90° carries the hoop force −W/2 along the cage y axis and the quarter-ring moment balance gives
    M(90°) − M(load point) = W R / 2 exactly, whatever the section stiffnesses (statics of Roark's
    table 9.2 case 1 derivation)."""
    ring = pocketed_ring()
    fe = assemble(ring)
    W = 50.0
    _, F = _pinch(fe, 8, W)
    lam = _element_frames(fe)
    q = int(fe.pocket_nodes[2])  # pocket 2 at 90°
    assert fe.element_pocket[0] and fe.element_pocket[q]
    f_c = lam[q].T @ F[q, 0, :3]  # positive-face force at 90° in the cage frame; x' there is ≈ −y
    # compression N = −W/2 along the tangent −ŷ: the force on the face is +W/2 ŷ, nothing along z
    assert_allclose(f_c, [0.0, W / 2, 0.0], atol=1e-9 * W, err_msg="statics: N(90°) = −W/2")
    assert_allclose(F[q, 0, 5] - F[0, 0, 5], W * ring.pitch_radius / 2, rtol=1e-9,
                    err_msg="statics: M(90°) − M_A = W R/2")
    # mirror symmetry about the section at 90°: the chords on both sides carry the same N and M_z',
    # opposite V_y' (their local frames are mirror images)
    assert_allclose(F[q - 1, 1, [0, 1, 5]] * [1, -1, 1], F[q, 0, [0, 1, 5]], rtol=1e-9)


# ---- 2. breathing (uniform pressure) and everting (uniform twist) ------------------------------
def _polygon_loads(fe, hoop=0.0, twist=0.0):
    """Nodal loads of the polygon that put every element in the membrane state N = hoop [N] or the
    uniform out-of-plane bending M_y' = twist [N·m]: node a of element e receives −N x'_e − M y'_e,
    node b +N x'_e + M y'_e (the loads the element's end resultants balance), i.e. node i receives
    N (x'_i−1 − x'_i) (radially outward, ≈ N Δψ r̂: pressure p = N/R) and M (y'_i−1 − y'_i)
    (≈ M Δψ t̂ as y' is inward and dy'/dψ = −t̂: a couple m = M/R per length about +t̂)."""
    lam = _element_frames(fe)
    F = np.zeros(fe.n_dof)
    for e, (a, b) in enumerate(fe.elements):
        F[6 * a:6 * a + 3] -= hoop * lam[e, 0]
        F[6 * b:6 * b + 3] += hoop * lam[e, 0]
        F[6 * a + 3:6 * a + 6] -= twist * lam[e, 1]
        F[6 * b + 3:6 * b + 6] += twist * lam[e, 1]
    return F


@pytest.mark.parametrize("ring", [uniform(8), pocketed_ring(first_pocket_azimuth=0.3)], ids=["uniform", "pocketed"])
def test_uniform_pressure_hoop_stress(ring):
    """Radial pressure p on the polygon: nodal forces N (x'_e − x'_{e−1}) → N = p R, σ = N/A (rails:
    N/(2 w t)), no bending (thin ring under uniform radial load)."""
    fe = assemble(ring)
    p = 2.0e4  # [N/m]
    N = p * ring.pitch_radius
    F = element_end_forces(fe, fe.static_deflection(_polygon_loads(fe, hoop=N)))
    assert_allclose(F[..., 0], N, rtol=1e-9, err_msg="thin ring under uniform radial load: N = p R")
    assert np.max(np.abs(F[..., 1:3])) < 1e-9 * N and np.max(np.abs(F[..., 3:])) < 1e-9 * N * ring.pitch_radius
    s = normal_stress(fe, F)
    b, t, d = ring.axial_width, ring.radial_thickness, ring.pocket_diameter
    area = np.where(fe.element_pocket, (b - d) * t, b * t)
    assert_allclose(s, np.broadcast_to((N / area)[:, None, None], s.shape), rtol=1e-6,
                    err_msg="σ = N/A, thin ring under uniform radial load")


@pytest.mark.parametrize("ring", [uniform(8), pocketed_ring(first_pocket_azimuth=0.3)], ids=["uniform", "pocketed"])
def test_uniform_twist_bending_stress(ring):
    """Uniform twisting couple m per unit length about the +tangent: the section at axial +x moves
    outward (θ t̂ × x x̂ = θ x r̂), so the +x fibres are stretched; M = m R, σ = M x/I_out."""
    fe = assemble(ring)
    m = 30.0  # [N·m/m]
    M = m * ring.pitch_radius
    F = element_end_forces(fe, fe.static_deflection(_polygon_loads(fe, twist=M)))
    assert_allclose(F[..., 4], M, rtol=1e-9, err_msg="uniformly twisted ring: M = m R")
    s = normal_stress(fe, F)
    x = stress_points(fe)[:, 1]
    iout = np.where(fe.element_pocket, fe.sections["pocket"]["I_out"], fe.sections["bridge"]["I_out"])
    assert_allclose(s, np.broadcast_to(M * x / iout[:, None, None], s.shape), rtol=1e-6,
                    err_msg="uniformly twisted ring: σ = m R x / I_out, +x in tension")
    assert np.all(s[..., 3] > 0) and np.all(s[..., 0] < 0)


@pytest.fixture(scope="module")
def six_pocket_modes():
    """Uniform ring, Euler–Bernoulli, 48 and 96 chords."""
    return {epp: cage_modes(uniform(epp, z=6, shear_deformation=False), 16) for epp in (8, 16)}


@pytest.mark.parametrize("n", [2, 3, 4])
def test_inplane_mode_moment_inextensional_ring(six_pocket_modes, n):
    """Bending moment of the in-plane flexural mode n of a thin uniform ring: for the inextensional
    mode of radial amplitude a the change of curvature is (n² − 1) a / R² (Hoppe 1871; Timoshenko,
    Vibration Problems in Engineering, flexural vibration of a circular ring), M = E I (n² − 1) a/R².
    (The mode also carries a hoop force, ≈ 1 % of the bending stress at R/t = 25, not checked.)"""
    err = {}
    for epp, m in six_pocket_modes.items():
        k = m.kind.index(f"in-plane n={n}")
        psi = m.fe.node_azimuth
        v = m.vectors[:, k].reshape(-1, 6)
        a = np.abs(np.cos(psi) * v[:, 1] + np.sin(psi) * v[:, 2]).max()  # radial amplitude per unit η
        F = element_end_forces(m.fe, m.vectors[:, k])
        err[epp] = np.abs(F[..., 5]).max() / (E * I_IN * (n * n - 1) * a / R**2) - 1
    # quasi-static recovery, 96 chords: +1.7e-3 (n=2), +3.5e-3 (n=3), +6.0e-3 (n=4); 48 chords: +7.6e-3,
    # +1.5e-2, +2.4e-2
    assert abs(err[16]) < 1e-3 * (n * n - 1) / 1.5, \
        f"inextensional ring mode n={n}: M = E I (n²−1) a/R² (Hoppe 1871), off by {err[16]:+.2e}"
    assert abs(err[16]) < abs(err[8]) / 3, "O(h²) convergence of the modal bending moment (Hoppe 1871)"


# ---- 3. invariants -----------------------------------------------------------------------------
@pytest.fixture(scope="module")
def hub():
    """Pocketed ring with a symmetric-breaking first azimuth, 30 modes."""
    ring = pocketed_ring(first_pocket_azimuth=0.3)
    return cage_modes(ring, 30)


def test_element_matrices_reassemble_K(hub):
    """The element stiffness and frames used for the stress recovery reassemble the global K."""
    from bearingsim.cage_modes.stress import _element_stiffness

    fe = hub.fe
    lam, kl = _element_frames(fe), _element_stiffness(fe)
    K = np.zeros_like(fe.K)
    for e, (a, b) in enumerate(fe.elements):
        Tm = np.kron(np.eye(4), lam[e])
        idx = np.r_[6 * a:6 * a + 6, 6 * b:6 * b + 6]
        K[np.ix_(idx, idx)] += Tm.T @ kl[e] @ Tm
    assert_allclose(K, fe.K, rtol=0, atol=1e-12 * np.abs(fe.K).max())


def test_rigid_body_motion_is_stress_free(hub):
    fe = hub.fe
    S = stress_shapes(hub)
    typical = np.abs(S).max(axis=(1, 2, 3))  # per mode [Pa per unit η]
    amp = np.abs(hub.vectors).max()  # displacement of a unit η [m]
    rb = fe.rigid_body_vectors()
    rb = rb / np.abs(rb).max(axis=0) * amp  # the same displacement amplitude
    s = normal_stress(fe, element_end_forces(fe, rb))
    assert np.abs(s).max() < 1e-6 * typical.min(), "rigid-body motion must carry no stress"


def test_nodal_equilibrium_of_resultants(hub):
    """Node i joins end b of element i−1 and end a of element i; the nodal load K u (for a mode
    shape the inertia load ω² M φ) balances the two resultants: K u|_i = R_b(i−1) − R_a(i) in the
    cage frame (the sign convention of element_end_forces: positive-face resultants at both ends)."""
    fe = hub.fe
    v = hub.vectors[:, 5]
    F = element_end_forces(fe, v)
    lam = _element_frames(fe)
    prev = np.roll(np.arange(len(lam)), 1)
    ku = (fe.K @ v).reshape(-1, 6)
    assert np.all(fe.elements[prev, 1] == fe.elements[:, 0])
    for sl in (slice(0, 3), slice(3, 6)):
        glob_b = np.einsum("eji,ej->ei", lam[prev], F[prev, 1, sl])  # end b of element i−1
        glob_a = np.einsum("eji,ej->ei", lam, F[:, 0, sl])  # end a of element i
        assert_allclose(glob_b - glob_a, ku[fe.elements[:, 0], sl], rtol=0, atol=1e-9 * np.abs(glob_a).max())


def test_stress_shapes_superpose(hub):
    fe = hub.fe
    S = stress_shapes(hub)
    assert S.shape == (30, len(fe.elements), 2, 8)
    rng = np.random.default_rng(1)
    eta = rng.normal(size=30) * 1e-4
    direct = normal_stress(fe, element_end_forces(fe, hub.vectors @ eta))
    assert_allclose(np.tensordot(eta, S, axes=(0, 0)), direct, rtol=0, atol=1e-12 * np.abs(direct).max())
    pk = peak_stress(hub, eta, shapes=S)
    assert_allclose(pk, np.abs(direct).max(), rtol=1e-12, err_msg="peak_stress = max |σ(vectors @ η)|")
    assert_allclose(peak_stress(hub, eta), pk, rtol=1e-12)
    etas = rng.normal(size=(5, 30)) * 1e-4
    assert_allclose(peak_stress(hub, etas, shapes=S), [peak_stress(hub, e, shapes=S) for e in etas], rtol=1e-12)
    loc = peak_stress_location(hub, eta, shapes=S)
    assert abs(loc["stress_Pa"]) == pk
    assert direct[loc["element"], loc["end"], loc["point"]] == pytest.approx(loc["stress_Pa"], rel=1e-12)
    assert loc["part"] == ("pocket" if fe.element_pocket[loc["element"]] else "bridge")
    with pytest.raises(InputError):
        peak_stress(hub, np.zeros(29))
    with pytest.raises(InputError):
        element_end_forces(fe, np.zeros(7))


def test_torsion_shear_stress_square_and_strip():
    """τ_max = T/(0.208 a³) for a square (Roark 7th ed. table 10.7 case 4; Timoshenko & Goodier §109)
    and → 3T/(a c²) for a thin strip."""
    from bearingsim.cage_modes.stress import _rect_torsion_stress_factor

    assert_allclose(_rect_torsion_stress_factor(1.0, 1.0), 1 / 0.208, rtol=2e-3,
                    err_msg="Roark table 10.7 case 4 / Timoshenko & Goodier: square τ = T/(0.208 a³)")
    assert_allclose(_rect_torsion_stress_factor(100.0, 1.0), 3 / 100 / (1 - 0.630 / 100), rtol=1e-3,
                    err_msg="Timoshenko & Goodier §109: thin strip τ = 3T/(a c²)")
    fe = assemble(uniform(4))
    F = np.zeros((len(fe.elements), 2, 6))
    F[..., 3] = 2.0
    assert_allclose(torsion_shear_stress(fe, F), 2.0 * _rect_torsion_stress_factor(B, T), rtol=1e-15)
