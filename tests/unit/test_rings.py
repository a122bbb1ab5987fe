"""Mechanisms of the elastic-ring model (bearingsim.rings): section estimate, mesh, half-space part, exclusion of
the local Hertz deformation, harmonic interpolation, disk cache, coupling offsets, bad input."""

import math

import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.rings import influence as inf
from bearingsim.rings.coupling import ElasticRings, offsets_from_forces, ring_forces, ring_model, solve
from bearingsim.rings.influence import InfluenceSettings, compute_influence, half_space_on_axis
from bearingsim.rings.section import RingSection, estimate_sections, mesh_section
from bearingsim.statics import layout as kn
from bearingsim.statics.jones_harris import Loads

E, NU = 208e9, 0.3


@pytest.fixture(scope="module")
def b7011():
    return load_bearing("skf-7011-cdga-hc")


def coarse(section, **kw):
    """Coarse discretisation for the tests (a few seconds per ring)."""
    opts = dict(sigma=section.wall / 4, n_through=5, n_axial=10, ghat_min=1e-4, decay_min=1e-4)
    opts.update(kw)
    return InfluenceSettings(**opts)


@pytest.fixture(scope="module")
def inner_coeffs(b7011):
    inner, _ = estimate_sections(b7011)
    return inner, compute_influence(inner, E, NU, b7011.ball_count, coarse(inner), cache=False)


def test_section_estimate_from_boundary_dimensions(b7011):
    inner, outer = estimate_sections(b7011)
    dw, dm = b7011.ball_diameter, b7011.pitch_diameter
    assert inner.wall == pytest.approx(0.5 * (dm - dw - b7011.bore), rel=1e-12)
    assert outer.wall == pytest.approx(0.5 * (b7011.outside_diameter - dm - dw), rel=1e-12)
    assert inner.land_radius - inner.groove_bottom_radius == pytest.approx(0.25 * dw, rel=1e-12)
    assert inner.sleeve_radius == pytest.approx(0.25 * b7011.bore) and outer.sleeve_radius == pytest.approx(
        0.75 * b7011.outside_diameter)
    for s in (inner, outer):  # the contact point lies on the groove circle, at α₀ from the groove bottom
        rc, zc = s.groove_centre
        p = s.contact_point
        assert math.hypot(p[0] - rc, p[1] - zc) == pytest.approx(s.groove_radius, rel=1e-12)
        assert math.atan2(abs(p[1]), abs(p[0] - rc)) == pytest.approx(b7011.contact_angle, rel=1e-12)
        assert s.surface_radius(np.array([p[1]]))[0] == pytest.approx(p[0], rel=1e-12)
    # the ball pushes the inner ring towards −r, −ξ and the outer ring towards +r, +ξ
    assert np.all(inner.inward_normal < 0) and np.all(outer.inward_normal > 0)


def test_section_needs_boundary_dimensions(b7011):
    import dataclasses

    with pytest.raises(InputError, match="bore"):
        estimate_sections(dataclasses.replace(b7011, bore=0.0))
    with pytest.raises(InputError, match="sleeve_radius"):
        RingSection("inner", 0.02, 0.03, 0.028, 0.005, 0.01, 0.26, sleeve_radius=0.025)


def test_mesh_follows_the_raceway(b7011):
    for s in estimate_sections(b7011):
        m = mesh_section(s, s.wall / 8, 5, 10)
        assert set(m.boundaries) == {"seat", "raceway", "face_minus", "face_plus"}
        ends = np.unique(m.facets[:, m.boundaries["raceway"]])
        r, z = m.p[:, ends]
        np.testing.assert_allclose(r, s.surface_radius(z), rtol=1e-12)
        assert np.all(m.p[0] > 0)


def test_half_space_point_limit():
    """A narrow spread gives the point-force values on the axis: u_n = F(1+ν)(3−2ν)/(2πEd) (Boussinesq),
    u_t = F(1+ν)(3−2ν)/(4πEd) (Cerruti), Johnson 1985 eqs. 3.19, 3.86a."""
    d = 1e-3
    un, ut = half_space_on_axis(1.0, 1.0, d, 1e-7, E, NU)
    assert un == pytest.approx((1 + NU) * (3 - 2 * NU) / (2 * math.pi * E * d), rel=1e-6)
    assert ut == pytest.approx((1 + NU) * (3 - 2 * NU) / (4 * math.pi * E * d), rel=1e-6)
    # a wider spread lowers the value at the same depth
    assert half_space_on_axis(1.0, 1.0, d, 0.5 * d, E, NU)[0] < un


def test_local_hertz_part_is_excluded(b7011, inner_coeffs):
    """No double counting: in a massive block (the half-space limit of Hertz theory) the self term left after the
    subtraction is a small fraction of the subtracted half-space part (what remains is the curvature of the
    groove, a correction of the order of Hertz theory's own error for conforming contacts); without the
    subtraction it would be the whole local part.  The 7011 inner ring on its hollow-shaft sleeve yields more
    than a half-space (positive self term) but far less than the local part."""
    inner, c = inner_coeffs
    block = RingSection("inner", 0.004, inner.land_radius, inner.groove_bottom_radius, inner.groove_radius, 0.03,
                        inner.contact_angle)
    cb = compute_influence(block, E, NU, b7011.ball_count, coarse(inner, n_through=12, n_axial=14), cache=False)
    n = block.inward_normal
    local = n @ cb.local @ n
    assert local > 0
    assert abs(n @ cb.coeffs[0] @ n) < 0.1 * local
    assert 0 < n @ c.coeffs[0] @ n < 0.3 * local


def test_readout_depth_does_not_matter(b7011, inner_coeffs):
    """The corrected coefficients do not depend on where the smooth field is read (depths d, 2d vs 1.07 d,
    2.13 d): within 2 % of the self term and of the whole row's sum."""
    inner, c = inner_coeffs
    c2 = compute_influence(inner, E, NU, b7011.ball_count, coarse(inner, depth=0.4 * inner.wall), cache=False)
    n = inner.inward_normal
    assert n @ c2.coeffs[0] @ n == pytest.approx(n @ c.coeffs[0] @ n, rel=0.02)
    np.testing.assert_allclose(c2.coeffs[1:], c.coeffs[1:], rtol=0.02, atol=0.02 * np.abs(c.coeffs[1:]).max())


def test_harmonic_interpolation_matches_dense_sum(b7011, inner_coeffs):
    inner, c = inner_coeffs
    dense = compute_influence(inner, E, NU, b7011.ball_count, coarse(inner, stride=1), cache=False)
    assert dense.meta["harmonics_solved"] > c.meta["harmonics_solved"]
    np.testing.assert_allclose(c.coeffs, dense.coeffs, rtol=0, atol=1e-5 * np.abs(dense.coeffs).max())


def test_coefficients_scale_with_compliance(b7011, inner_coeffs):
    """Linear elasticity: C ∝ 1/E (same key inputs otherwise)."""
    inner, c = inner_coeffs
    c10 = compute_influence(inner, 10 * E, NU, b7011.ball_count, coarse(inner), cache=False)
    np.testing.assert_allclose(c10.coeffs, c.coeffs / 10, rtol=1e-9, atol=1e-9 * np.abs(c.coeffs).max())


def test_disk_cache(tmp_path, monkeypatch, b7011):
    monkeypatch.setenv(inf.CACHE_ENV, str(tmp_path))
    inner, _ = estimate_sections(b7011)
    st = coarse(inner, ghat_min=1e-2, decay_min=1e-2, n_through=3, n_axial=6)
    first = compute_influence(inner, E, NU, b7011.ball_count, st)
    files = list(tmp_path.glob("*.npz"))
    assert [f.name for f in files] == [f"{first.key}.npz"] and not first.meta["cached"]
    again = compute_influence(inner, E, NU, b7011.ball_count, st)
    assert again.meta["cached"] and np.array_equal(again.coeffs, first.coeffs)
    other = compute_influence(inner, 1.01 * E, NU, b7011.ball_count, st)  # another material: another key
    assert other.key != first.key and len(list(tmp_path.glob("*.npz"))) == 2
    files[0].write_bytes(b"not an npz")  # a damaged file is recomputed and replaced
    fixed = compute_influence(inner, E, NU, b7011.ball_count, st)
    assert not fixed.meta["cached"] and np.allclose(fixed.coeffs, first.coeffs, rtol=1e-12, atol=0)
    assert inf.cache_dir() == tmp_path


def test_offsets_of_uniform_axial_load(b7011):
    """Pure axial load: all balls carry the same forces, so every ball gets the same offsets, equal to the
    row sum Σ_m C_m F of each ring (computed here by hand from the circulant coefficients)."""
    rng = np.random.default_rng(1)
    z = b7011.ball_count
    ci = rng.normal(size=(z, 2, 2)) * 1e-10
    co = rng.normal(size=(z, 2, 2)) * 1e-10
    mk = lambda c, kind: inf.RingInfluence(kind, z, c, np.zeros((2, 2)), 1, 0.0)  # noqa: E731
    rings = ElasticRings([(mk(ci, "inner"), mk(co, "outer"))])
    rows0 = b7011.row_vectors()
    fi = np.tile([-900.0, -250.0], (z, 1))
    fo = np.tile([950.0, 240.0], (z, 1))
    off = offsets_from_forces(rows0, rings, fi, fo)
    ui = ci.sum(axis=0) @ fi[0]
    uo = co.sum(axis=0) @ fo[0]
    np.testing.assert_allclose(off, np.tile([ui[1] - uo[1], ui[0] - uo[0]], (z, 1)), rtol=1e-12)


def test_ring_forces_balance_the_ball_at_rest():
    """At rest (no gyroscopic moment, no centrifugal force) the forces of a ball on its two rings are equal
    and opposite."""
    bo = np.zeros((1, 1, 12))
    a_i, a_o = 0.3, 0.3
    bo[0, 0, [2, 3, 8, 9, 10, 11]] = [500.0, 500.0, math.sin(a_i), math.cos(a_i), math.sin(a_o), math.cos(a_o)]
    fi, fo = ring_forces(bo, np.zeros((1, 1), dtype=np.int64))
    np.testing.assert_allclose(fi + fo, 0.0, atol=1e-12)
    assert fi[0, 0] < 0 and fi[0, 1] < 0


def test_bad_ring_input(b7011):
    with pytest.raises(InputError, match="rings"):
        solve(b7011, Loads(fa=1000.0), rings="elastic")
    with pytest.raises(InputError, match="rings"):
        solve(b7011, Loads(fa=1000.0), rings=ElasticRings([]))
    with pytest.raises(InputError, match="ball_count"):
        compute_influence(estimate_sections(b7011)[0], E, NU, 2)
    with pytest.raises(InputError, match="depth"):
        compute_influence(estimate_sections(b7011)[0], E, NU, 21, InfluenceSettings(depth=0.01), cache=False)
    assert kn.P_Z == 0  # the one-ball rows rely on the layout's ball-count slot
    assert callable(ring_model)
