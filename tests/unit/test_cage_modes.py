"""Elastic cage ring (bearingsim.cage_modes): closed forms and invariants of the FE model.

References (thin uniform ring of radius R, section A, density ρ, moduli E and G):

* in-plane inextensional bending, Hoppe (1871), Blevins (Formulas for Natural Frequency and
  Mode Shape, 1979, ring table), also code_aster V2.03.109:
      ω_n = sqrt(E I_in / (ρ A R⁴)) · n(n² − 1) / sqrt(n² + 1)
* out-of-plane bending–torsion, Love (Treatise on the Mathematical Theory of Elasticity, 4th
  ed., ch. XVIII), Blevins ring table (rotary inertia neglected):
      ω_n = sqrt(E I_out / (ρ A R⁴)) · n(n² − 1) / sqrt(n² + E I_out / (G J))
* uniform twist (n = 0 torsional, "everting") from the strain energy ∫E(β x'/R)² dA:
      ω₀² = E I_out / (ρ I_p R²)
* breathing (n = 0 extensional), Love ch. XVIII: ω₀² = E / (ρ R²)
* two equal and opposite diametral point loads P on a thin ring (Roark's Formulas for Stress
  and Strain, 7th ed., table 9.2 case 1): ΔD = (π/4 − 2/π) P R³ / (E I_in)

The FE ring is built from straight chords; the closed forms above neglect rotary inertia and
shear (the model can switch both off), so the comparisons isolate the discretisation error
(O(h²), shown by the convergence test) from the thin-ring idealisation.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
import scipy.linalg
from numpy.testing import assert_allclose

from bearingsim.cage_modes import (
    CageRing,
    assemble,
    cage_modes,
    cowper_shear_coefficient,
    default_cage_ring,
    rect_torsion_constant,
)
from bearingsim.errors import InputError

E, NU, RHO = 2.06e11, 0.3, 7850.0
G = E / (2 * (1 + NU))
# slender uniform ring: R/t = 25, b/t = 1.5 (so that E I_out / G J = 2.28 matters)
R, B, T = 0.05, 0.003, 0.002
A = B * T
I_IN, I_OUT = B * T**3 / 12, T * B**3 / 12
I_P = I_IN + I_OUT


def hoppe(n):
    return math.sqrt(E * I_IN / (RHO * A * R**4)) * n * (n * n - 1) / math.sqrt(n * n + 1)


def love_out_of_plane(n):
    J = rect_torsion_constant(B, T)
    return math.sqrt(E * I_OUT / (RHO * A * R**4)) * n * (n * n - 1) / math.sqrt(n * n + E * I_OUT / (G * J))


def uniform(epp=8, z=12, **kw):
    return CageRing(R, B, T, z, 0.001, pockets=False, elements_per_pitch=epp, **kw)


def by_kind(modes):
    """kind → first ω [rad/s]."""
    out = {}
    for k, w in zip(modes.kind, modes.omega):
        out.setdefault(k, w)
    return out


@pytest.fixture(scope="module")
def thin_modes():
    """Euler–Bernoulli, no rotary inertia: the thin-ring closed forms' assumptions."""
    return {epp: cage_modes(uniform(epp, shear_deformation=False, rotary_inertia=False), 40) for epp in (4, 8)}


# ---- 1. closed forms ----------------------------------------------------------------------
@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_in_plane_flexural_hoppe(thin_modes, n):
    w8 = by_kind(thin_modes[8])[f"in-plane n={n}"]
    w4 = by_kind(thin_modes[4])[f"in-plane n={n}"]
    ref = hoppe(n)
    # 96 chords: +3.7e-4 (n=2) … +3.0e-4 (n=5); 48 chords: +2.0e-3; 192 chords: −0.5 … −1.1e-4 (the
    # extensibility that Hoppe's inextensional ring neglects, ≈ −t²/12R² order)
    assert_allclose(w8, ref, rtol=5e-4, err_msg=f"Hoppe 1871 / Blevins ring in-plane n={n}")
    assert abs(w8 / ref - 1) < abs(w4 / ref - 1) / 3, "O(h²) convergence to Hoppe 1871 with elements_per_pitch"


@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_out_of_plane_flexural_torsional_love(thin_modes, n):
    w8 = by_kind(thin_modes[8])[f"out-of-plane n={n}"]
    w4 = by_kind(thin_modes[4])[f"out-of-plane n={n}"]
    ref = love_out_of_plane(n)
    # 96 chords: +4.1e-4 … +3.1e-4; 48 chords: +1.7e-3 … +1.3e-3; 192 chords +1.3e-4 … +0.8e-4 (O(h²))
    assert_allclose(w8, ref, rtol=6e-4, err_msg=f"Love ch. XVIII / Blevins ring out-of-plane n={n}")
    assert abs(w8 / ref - 1) < abs(w4 / ref - 1) / 3, "O(h²) convergence to Love ch. XVIII with elements_per_pitch"


def test_breathing_and_twist_modes():
    m = cage_modes(uniform(8, shear_deformation=False), 40)
    k = by_kind(m)
    assert_allclose(k["extensional n=0"], math.sqrt(E / (RHO * R**2)), rtol=1e-3,
                    err_msg="Love ch. XVIII breathing mode ω² = E/(ρR²)")
    assert_allclose(k["torsional n=0"], math.sqrt(E * I_OUT / (RHO * I_P * R**2)), rtol=1e-3,
                    err_msg="uniform-twist ring mode ω² = E I_out/(ρ I_p R²)")


@pytest.mark.parametrize("n", [2, 3, 4, 5])
def test_default_model_near_thin_ring(n):
    """Rotary inertia and shear (the default model) lower the thin-ring values.  For a wave number
    k = n/R and a section depth h in the bending plane, the Timoshenko beam correction is
    Δω/ω ≈ −½ k² (h²/12) (1 + E/(κG)) (Timoshenko 1921; Han, Benaroya & Wei, J. Sound Vib. 225
    (1999) 935, long-wave limit): at R/t = 25 that is −0.1 … −0.7 % in-plane (h = t) and
    −0.2 … −1.5 % out-of-plane (h = b = 1.5 t) for n = 2 … 5; the FE lies at 0.5–1.0 × this."""
    m = _default_uniform()
    k = by_kind(m)
    kappa = cowper_shear_coefficient(NU)
    for kind, ref, h, src in ((f"in-plane n={n}", hoppe(n), T, "Hoppe 1871"),
                              (f"out-of-plane n={n}", love_out_of_plane(n), B, "Love ch. XVIII")):
        est = 0.5 * (n * h / R) ** 2 / 12 * (1 + E / (kappa * G))
        r = k[kind] / ref - 1
        assert -1.2 * est - 5e-4 < r < 5e-4, \
            f"{src} with the Timoshenko correction −{est:.2e}: default model {kind} off by {r:+.2e}"


_CACHE = {}


def _default_uniform():
    if "u" not in _CACHE:
        _CACHE["u"] = cage_modes(uniform(8), 40)
    return _CACHE["u"]


# ---- 2. rigid modes, orthonormality ---------------------------------------------------------
@pytest.fixture(scope="module")
def pocketed():
    ring = CageRing(0.03, 0.012, 0.003, 6, 0.008, first_pocket_azimuth=0.3)
    fe = assemble(ring)
    return ring, fe, cage_modes(ring, fe.n_dof - 6, fe=fe)


def test_six_rigid_modes(pocketed):
    ring, fe, m = pocketed
    lam = scipy.linalg.eigh(fe.K, fe.M, eigvals_only=True)
    assert np.sum(np.abs(lam) < 1e-6 * lam[6]) == 6
    assert lam[6] > 0 and np.all(np.abs(lam[:6]) < 1e-9 * lam[6])
    rb = fe.rigid_body_vectors()
    ku = fe.K @ rb
    assert np.max(np.abs(ku)) < 1e-9 * np.max(np.abs(fe.K)) * np.max(np.abs(rb)), "rigid motions must be stress-free"
    assert len(m.rigid_omega) == 6 and np.all(np.abs(m.rigid_omega) < 1e-3 * m.omega[0])


def test_mass_orthonormal_shapes(pocketed):
    ring, fe, m = pocketed
    V = m.vectors
    assert_allclose(V.T @ fe.M @ V, np.eye(V.shape[1]), atol=1e-10)
    assert_allclose(V.T @ fe.K @ V, np.diag(m.omega**2), atol=1e-10 * m.omega[-1] ** 2)
    # shapes are the pocket-node rows of the full vectors, cage frame
    for j, node in enumerate(fe.pocket_nodes):
        assert_allclose(m.shapes[:, j, :], V[6 * node:6 * node + 6, :].T, rtol=0, atol=0)
    assert_allclose(fe.node_xyz[fe.pocket_nodes],
                    np.column_stack([np.zeros(6), 0.03 * np.cos(ring.pocket_azimuths),
                                     0.03 * np.sin(ring.pocket_azimuths)]), atol=1e-15)
    assert np.all(np.diff(m.omega) >= 0)
    # a point 1 mm outward (radially) from pocket 0 at ψ = 0.3: u + θ × r
    r0 = 1e-3 * np.array([0.0, math.cos(0.3), math.sin(0.3)])
    ps = m.point_shapes(np.tile(r0, (6, 1)))
    th = m.shapes[:, 0, 3:]
    assert_allclose(ps[:, 0, 1], m.shapes[:, 0, 1] + th[:, 2] * r0[0] - th[:, 0] * r0[2], rtol=1e-14, atol=1e-18)
    assert_allclose(m.point_shapes(np.zeros(3)), m.shapes[:, :, :3], rtol=0, atol=0)
    # elastic modes carry no rigid-body momentum: Rᵀ M φ = 0
    assert np.max(np.abs(fe.rigid_body_vectors().T @ fe.M @ V)) < 1e-9


# ---- 3. mass and inertia --------------------------------------------------------------------
def _prism_sums(ring):
    """Independent mass, polar (x) and transverse (y) inertia of the modelled ring: Z pitches of
    n_p pocket chords over 2α and n_b bridge chords over 2π/Z − 2α, each a straight prism."""
    r, b, t, d, z = ring.pitch_radius, ring.axial_width, ring.radial_thickness, ring.pocket_diameter, ring.pocket_count
    alpha = math.asin(d / (2 * r))
    n_p, n_b = ring.split()
    w, e = (b - d) / 2, (b + d) / 4
    secs = {"p": ((b - d) * t, (b - d) * t**3 / 12, 2 * (t * w**3 / 12 + w * t * e**2)),
            "b": (b * t, b * t**3 / 12, t * b**3 / 12)}
    # element spans (start offset, angle) in one pitch, starting at the pocket centre
    spans = [("p", alpha / (n_p / 2))] * (n_p // 2) + [("b", (math.pi / z - alpha) / (n_b / 2))] * n_b \
        + [("p", alpha / (n_p / 2))] * (n_p // 2)
    mass = ip = it = 0.0
    for j in range(z):
        psi = ring.first_pocket_azimuth + 2 * math.pi * j / z
        for kind, dpsi in spans:
            a_, iin, iout = secs[kind]
            L = 2 * r * math.sin(dpsi / 2)
            h = r * math.cos(dpsi / 2)
            pm = psi + dpsi / 2
            mass += RHO * a_ * L
            ip += RHO * L * (a_ * (h * h + L * L / 12) + iin)
            it += RHO * (math.sin(pm) ** 2 * L * (iin + iout) + math.cos(pm) ** 2 * (a_ * L**3 / 12 + L * iout)
                         + a_ * L * h * h * math.sin(pm) ** 2)
            psi += dpsi
    return mass, ip, it


def test_mass_and_inertia(pocketed):
    ring, fe, m = pocketed
    mass, ip, it = _prism_sums(ring)
    assert_allclose(m.mass, mass, rtol=1e-12, err_msg="ρ × volume of the ring as modelled")
    assert_allclose(m.mass, RHO * fe.volume, rtol=1e-12)
    assert_allclose(m.polar_inertia, ip, rtol=1e-12, err_msg="polar inertia of the modelled prisms")
    assert_allclose(m.transverse_inertia, it, rtol=1e-12, err_msg="transverse inertia of the modelled prisms")
    # sanity against the exact solid ring without pockets (chords and rectangular windows aside)
    full = cage_modes(CageRing(0.03, 0.012, 0.003, 6, 0.008, pockets=False), 1)
    assert_allclose(full.mass, RHO * 2 * math.pi * 0.03 * 0.012 * 0.003, rtol=2e-3, err_msg="ring volume 2πR b t")


# ---- 4. degenerate pairs and their splitting ------------------------------------------------
def _singles(m, rtol=1e-6):
    lam = m.omega**2
    single = np.ones(len(lam), dtype=bool)
    for k in range(len(lam) - 1):
        if abs(lam[k + 1] - lam[k]) <= rtol * lam[k + 1]:
            single[k] = single[k + 1] = False
    return single


def test_uniform_ring_pairs(thin_modes):
    m = thin_modes[8]
    single = _singles(m)
    for k, (kind, n) in enumerate(zip(m.kind[:-1], m.wave_number[:-1])):  # the last may be half a pair
        assert single[k] == (n == 0), f"uniform ring: {kind} must be {'single' if n == 0 else 'a cos/sin pair'}"
    # the pair is rotated to cos/sin about the first pocket: radial displacement of the cos member
    # is extreme at pocket 0, the sin member's is zero there
    k = m.kind.index("in-plane n=2")
    ur = m.shapes[k:k + 2, :, 1]  # pocket 0 at ψ = 0: radial = y
    assert abs(ur[1, 0]) < 1e-6 * abs(ur[0, 0]) and ur[0, 0] > 0


@pytest.mark.parametrize("z", [4, 5, 6])
def test_pocketed_ring_pair_splitting(z):
    """Dihedral symmetry D_Z: a harmonic n stays a degenerate pair unless 2n ≡ 0 (mod Z), i.e. n a
    multiple of Z/2 (Z even) or of Z (Z odd), where the pair splits (1-D representations)."""
    m = cage_modes(CageRing(0.03, 0.012, 0.003, z, 0.008), 16)
    single = _singles(m)
    lam = m.omega**2
    split_seen = False
    for k, (kind, n) in enumerate(zip(m.kind[:14], m.wave_number[:14])):
        assert single[k] == ((2 * n) % z == 0), f"Z={z}: {kind} single={single[k]}"
        if single[k] and n > 0:
            split_seen = True
            gaps = np.abs(lam / lam[k] - 1)
            gaps[k] = np.inf
            assert gaps.min() > 1e-3
    assert split_seen or z == 5


# ---- 5. bad input ----------------------------------------------------------------------------
@pytest.mark.parametrize("kw, field", [
    (dict(pitch_radius=-0.03), "pitch_radius"),
    (dict(axial_width=0.0), "axial_width"),
    (dict(radial_thickness=-1e-3), "radial_thickness"),
    (dict(pocket_diameter=0.012), "pocket_diameter"),
    (dict(pocket_diameter=0.02), "pocket_diameter"),
    (dict(pocket_count=2), "pocket_count"),
    (dict(pocket_count=6.0), "pocket_count"),
    (dict(pocket_count=16, pocket_diameter=0.0118), "pocket_diameter"),  # no bridge left
    (dict(elements_per_pitch=7), "elements_per_pitch"),
    (dict(elements_per_pitch=2), "elements_per_pitch"),
    (dict(poisson=0.5), "poisson"),
    (dict(density=float("nan")), "density"),
    (dict(radial_thickness=0.04), "radial_thickness"),
])
def test_bad_ring_input(kw, field):
    args = dict(pitch_radius=0.03, axial_width=0.012, radial_thickness=0.003, pocket_count=6, pocket_diameter=0.008)
    args.update(kw)
    with pytest.raises(InputError) as e:
        CageRing(**args)
    assert e.value.field == field


def test_too_many_modes():
    ring = CageRing(0.03, 0.012, 0.003, 4, 0.008, elements_per_pitch=4)
    nmax = 6 * 16 - 6
    assert len(cage_modes(ring, nmax).omega) == nmax
    with pytest.raises(InputError, match=str(nmax)) as e:
        cage_modes(ring, nmax + 1)
    assert e.value.field == "n_modes"
    with pytest.raises(InputError):
        cage_modes(ring, 0)


def test_default_cage_ring_assumptions():
    ring = default_cage_ring(11.1e-3, 61e-3, 16)  # seed 001 hub row
    assert_allclose([ring.pitch_radius, ring.axial_width, ring.radial_thickness, ring.pocket_diameter],
                    [30.5e-3, 1.4 * 11.1e-3, 0.3 * 11.1e-3, 11.3e-3], rtol=1e-15)
    assert ring.pocket_count == 16
    with pytest.raises(InputError) as e:
        default_cage_ring(12e-3, 61e-3, 16)  # balls touching on the pitch circle: no bridge
    assert e.value.field == "pocket_diameter"


def test_cowper_and_torsion_constants():
    assert_allclose(cowper_shear_coefficient(0.3), 10 * 1.3 / 15.3, rtol=1e-15, err_msg="Cowper 1966 rectangle")
    # square: J = 0.1406 a⁴ (Roark table 10.7 case 4 / Timoshenko & Goodier table 5: 0.141)
    assert_allclose(rect_torsion_constant(1.0, 1.0), 0.14058, rtol=1e-4, err_msg="Timoshenko & Goodier ch. 10 square")
    # thin strip: J → a c³/3 (1 − 0.630 c/a)
    assert_allclose(rect_torsion_constant(10.0, 1.0), 10 / 3 * (1 - 0.630 / 10), rtol=1e-3,
                    err_msg="Timoshenko & Goodier ch. 10 narrow rectangle")


# ---- 6. static check: modal superposition of a self-equilibrated pocket load -----------------
def test_static_deflection_modal_sum():
    ring = CageRing(0.03, 0.012, 0.003, 8, 0.008)
    fe = assemble(ring)
    m = cage_modes(ring, fe.n_dof - 6, fe=fe)
    f = np.zeros((8, 3))
    psi = ring.pocket_azimuths
    for j in (0, 4):  # equal and opposite radial (outward) forces on two opposite pockets
        f[j] = 100.0 * np.array([0.0, math.cos(psi[j]), math.sin(psi[j])])
    F = fe.pocket_load_vector(f)
    u = fe.static_deflection(F)
    # independent: clamp the 6 DOF of one unloaded node (a statically determinate support: the
    # reaction of a self-equilibrated load is zero), solve the reduced K, then remove the
    # rigid-body part M-orthogonally
    rb = fe.rigid_body_vectors()
    free = np.setdiff1d(np.arange(fe.n_dof), np.arange(6 * 3, 6 * 3 + 6))
    uc = np.zeros(fe.n_dof)
    uc[free] = np.linalg.solve(fe.K[np.ix_(free, free)], F[free])
    uc -= rb @ np.linalg.solve(rb.T @ fe.M @ rb, rb.T @ fe.M @ uc)
    u6 = np.abs(u).reshape(-1, 6)
    scale = np.repeat([u6[:, :3].max(), u6[:, 3:].max()], 3)  # translations [m], rotations [rad]
    assert_allclose((u - uc).reshape(-1, 6) / scale, 0.0, atol=1e-9)
    V, w = m.vectors, m.omega
    modal = V @ ((V.T @ F) / w**2)
    assert_allclose((modal - u).reshape(-1, 6) / scale, 0.0, atol=1e-8,
                    err_msg="Σ φ φᵀF/ω² over all elastic modes")
    # with the pocket shapes only (what the dynamics sees): generalized force Σ_j φ(j)·F_j
    gf = np.einsum("kjc,jc->k", m.shapes[:, :, :3], f)
    assert_allclose(gf, V.T @ F, rtol=1e-12, atol=1e-12 * np.max(np.abs(gf)))
    # truncated to 20 modes: the ovalisation Fᵀu (rigid-motion invariant) is within 1.1 % here
    # (printed: 20-mode / full = 0.98996)
    full = F @ u
    ratio = F @ (V[:, :20] @ ((V[:, :20].T @ F) / w[:20] ** 2)) / full
    print(f"20-mode / full static compliance = {ratio:.5f}")
    assert 0.97 < ratio <= 1.0


def test_diametral_loads_roark():
    """Uniform thin ring pulled by two opposite radial point loads P: the loaded diameter grows by
    (π/4 − 2/π) P R³/(E I) (bending only; Roark table 9.2 case 1)."""
    ring = uniform(8, z=12, shear_deformation=False)
    fe = assemble(ring)
    P = 10.0
    f = np.zeros((12, 3))
    f[0] = [0.0, P, 0.0]
    f[6] = [0.0, -P, 0.0]
    u = fe.static_deflection(fe.pocket_load_vector(f))
    dD = u[6 * fe.pocket_nodes[0] + 1] - u[6 * fe.pocket_nodes[6] + 1]
    ref = (math.pi / 4 - 2 / math.pi) * P * R**3 / (E * I_IN)
    # FE (96 chords, bending + membrane) −1.9e-4 relative to the bending-only reference
    assert_allclose(dD, ref, rtol=1e-3, err_msg="Roark 7th ed. table 9.2 case 1")


# ---- CLI ---------------------------------------------------------------------------------------
def test_cli_cage_modes_json_and_bad_input():
    import json

    import typer
    from typer.testing import CliRunner

    from bearingsim.cage_modes import default_cage_ring as dcr
    from bearingsim.cli import cage as cli_cage

    app = typer.Typer()

    @app.callback()
    def _root():  # a group, so that the command keeps its name
        pass

    cli_cage.register(app)
    r = CliRunner().invoke(app, ["cage-modes", "hub-seed001", "--modes", "4", "--json"])
    assert r.exit_code == 0, r.output
    out = json.loads(r.output)
    ref = cage_modes(dcr(11.1e-3, 61e-3, 16), 4)  # first row of the hub unit
    assert_allclose([m["omega_rad_s"] for m in out["modes"]], ref.omega, rtol=1e-9)
    assert_allclose(out["mass_kg"], ref.mass, rtol=1e-12)
    r = CliRunner().invoke(app, ["cage-modes", "hub-seed001-row", "--width", "10 mm"])
    assert isinstance(r.exception, InputError) and r.exception.field == "pocket_diameter"
