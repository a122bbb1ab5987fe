"""Shaft model: input checks, gear forces, the beam element's invariants, the solver's statuses."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

import bearingsim
from bearingsim.beam import cowper_circular, shaft_element_matrices
from bearingsim.errors import InputError
from bearingsim.shafts.model import (
    BearingSupport,
    DistributedLoad,
    HelicalGear,
    PointLoad,
    PointMass,
    Section,
    ShaftSystem,
    SpringSupport,
)
from bearingsim.shafts.solve import linear_model, solve_shaft

B6208 = bearingsim.load_bearing("6208")


def _two_bearings(**kw):
    return ShaftSystem((Section(0.3, 0.04),), (BearingSupport("a", 0.05, B6208), BearingSupport("b", 0.25, B6208)),
                       **kw)


@pytest.mark.parametrize("make, field", [
    (lambda: Section(0.0, 0.04), "section.length"),
    (lambda: Section(0.1, -0.04), "section.outer_diameter"),
    (lambda: Section(0.1, 0.04, 0.05), "section.inner_diameter"),
    (lambda: HelicalGear(0.1, 0.0, 0.1), "gear.torque"),
    (lambda: ShaftSystem((Section(0.3, 0.04),), (BearingSupport("a", 0.35, B6208),
                                                 BearingSupport("b", 0.25, B6208))), "a.position"),
    (lambda: ShaftSystem((Section(0.3, 0.04),), (BearingSupport("a", 0.25, B6208),
                                                 BearingSupport("b", 0.25, B6208))), "b.position"),
    (lambda: ShaftSystem((Section(0.3, 0.04),), (BearingSupport("a", 0.05, B6208),)), "supports"),
    (lambda: ShaftSystem((Section(0.3, 0.04),), (SpringSupport("a", 0.0, [0, 1e8, 1e8, 0, 0]),
                                                 SpringSupport("b", 0.3, [0, 1e8, 1e8, 0, 0]))), "supports"),
    (lambda: SpringSupport("s", 0.0, [[1, 2], [3, 4]]), "s.stiffness"),
    (lambda: BearingSupport("a", 0.0, B6208, orientation=2), "a.orientation"),
    (lambda: PointMass(0.0, -1.0), "mass.mass"),
    (lambda: _two_bearings(loads=(PointLoad(0.5, (0, 1, 0)),)), "load.position"),
])
def test_bad_input_names_the_field(make, field):
    with pytest.raises(InputError) as e:
        make()
    assert e.value.field == field
    assert e.value.fix


def test_mesh_has_key_nodes():
    s = _two_bearings(loads=(PointLoad(0.123, (0, 1, 0)), DistributedLoad(0.06, 0.2, (0, -10, 0))),
                      masses=(PointMass(0.3, 2.0),), elements=30)
    for x in (0.0, 0.05, 0.06, 0.123, 0.2, 0.25, 0.3):
        assert np.min(np.abs(s.mesh.nodes - x)) < 1e-12
    assert np.all(np.diff(s.mesh.nodes) > 0)
    assert 28 <= s.mesh.n_nodes - 1 <= 36


@given(torque=st.floats(-5e3, 5e3).filter(lambda t: abs(t) > 1e-3), d=st.floats(0.02, 0.5),
       an=st.floats(0.1, 0.6), beta=st.floats(0.0, 0.6), theta=st.floats(-math.pi, math.pi),
       hand=st.sampled_from(["right", "left"]))
@settings(max_examples=60, deadline=None)
def test_gear_force_is_the_tooth_normal_force(torque, d, an, beta, theta, hand):
    """The mesh force transmits the torque (r × F · e_x = T), is normal to the tooth line and has the Shigley
    components F_t = 2T/d, F_r = F_t tan α_n / cos β, F_a = F_t tan β (eqs. 13-39, 13-40)."""
    g = HelicalGear(0.0, torque, d, an, beta, hand, theta)
    v = g.vector()
    er = np.array([0.0, math.cos(theta), math.sin(theta)])
    et = np.cross([1.0, 0.0, 0.0], er)
    f = v[:3]
    r = 0.5 * d * er
    assert_allclose(np.cross(r, f)[0], torque, rtol=1e-9)
    h = 1.0 if hand == "right" else -1.0
    line = math.cos(beta) * np.array([1.0, 0.0, 0.0]) + h * math.sin(beta) * et
    assert abs(f @ line) <= 1e-9 * np.linalg.norm(f)
    ft = 2 * torque / d
    assert_allclose(-f @ er, abs(ft) * math.tan(an) / math.cos(beta), rtol=1e-9)
    assert_allclose(abs(f[0]), abs(ft) * math.tan(beta), rtol=1e-9, atol=1e-12)
    assert_allclose(v[3:], (np.cross(r, [f[0], 0.0, 0.0]))[1:], rtol=1e-9, atol=1e-12 * abs(ft) * d)


def test_cowper_circle():
    """Cowper 1966 table 1: solid circle 6(1+ν)/(7+6ν); a thin tube (m → 1) 2(1+ν)/(4+3ν)."""
    assert_allclose(cowper_circular(0.3), 6 * 1.3 / 8.8, rtol=1e-15)
    assert_allclose(cowper_circular(0.3, 1.0), 2 * 1.3 / 4.9, rtol=1e-12)


@pytest.mark.parametrize("shear", [False, True])
def test_element_invariants(shear):
    L, E, G, rho, A, i = 0.05, 2e11, 8e10, 7800.0, 1e-3, 8e-8
    k, m, g = shaft_element_matrices(L, E, G, rho, A, i, 0.88, shear)
    # rigid motions: translations and the two rigid rotations (γz: y = γ x; γy: z = −γ x) cost nothing
    rig = []
    for c in range(3):
        v = np.zeros(10)
        v[[c, 5 + c]] = 1.0
        rig.append(v)
    rig.append(np.array([0, 0, 0, 0, 1, 0, L, 0, 0, 1.0]))
    rig.append(np.array([0, 0, 0, 1, 0, 0, 0, -L, 1, 0.0]))
    for v in rig:
        assert np.max(np.abs(k @ v)) < 1e-6 * np.max(np.abs(k))
    assert_allclose(rig[0] @ m @ rig[0], rho * A * L, rtol=1e-12)
    assert_allclose(k, k.T, atol=0)
    assert_allclose(m, m.T, atol=0)
    assert_allclose(g, -g.T, atol=0)
    # rigid rotation about z: the polar inertia of the rod couples it to the y-rotation, ∫ρ I_p = ρ 2I L
    assert_allclose(rig[4] @ g @ rig[3], rho * 2 * i * L, rtol=1e-12)


def test_gravity_and_distributed_loads_sum_to_the_weight():
    s = _two_bearings(loads=(bearingsim.Gravity(), DistributedLoad(0.0, 0.3, (0.0, 0.0, 100.0))),
                      masses=(PointMass(0.3, 2.0),))
    lm = linear_model(s)
    w = Section(0.3, 0.04).area * 0.3 * 7900.0 + 2.0
    assert_allclose(lm.F[1:lm.n_shaft:5].sum(), -9.80665 * w, rtol=1e-12)
    assert_allclose(lm.F[2:lm.n_shaft:5].sum(), 30.0, rtol=1e-12)


def test_equilibrium_and_load_past_capacity():
    r = solve_shaft(_two_bearings(loads=(PointLoad(0.15, (1000.0, 4000.0, 0.0)),), speed=300.0))
    assert r.converged, r.status
    total = sum(s.reaction for s in r.supports)
    assert_allclose(total[:3], [-1000.0, -4000.0, 0.0], atol=1e-5)
    # moments about the origin: Σ (x_s e_x × F_s) + M_s + load = 0
    mz = sum(s.reaction[4] + s.position * s.reaction[1] for s in r.supports) + 0.15 * 4000.0
    assert abs(mz) < 1e-4
    heavy = solve_shaft(_two_bearings(loads=(PointLoad(0.15, (0.0, 2e5, 0.0)),)))
    assert any("ISO 76" in w for w in heavy.warnings), heavy.warnings  # the bearings' warnings reach the shaft
    # two angular contact rows facing the same way cannot carry a thrust against their contact angle
    a = bearingsim.load_bearing("7011-15")
    s = ShaftSystem((Section(0.3, 0.055),), (BearingSupport("a", 0.05, a), BearingSupport("b", 0.25, a)),
                    (PointLoad(0.15, (-2000.0, 500.0, 0.0)),))
    bad = solve_shaft(s)
    assert not bad.converged and "no equilibrium" in bad.status


def test_stiffness_at_is_the_compliance_inverse():
    r = solve_shaft(_two_bearings(loads=(PointLoad(0.3, (500.0, 2000.0, 0.0)),), speed=300.0))
    k = r.stiffness_at(0.3)
    c = r.compliance_at(0.3)
    assert_allclose(k @ c, np.eye(5), atol=1e-8)
    d = r.to_dict(stiffness_at=0.3)
    assert_allclose(d["stiffness_at"]["radial_N_per_m"], 1 / c[1, 1])
    assert d["supports"][0]["basic_rating_life_hours"] > 0
    with pytest.raises(InputError):
        r.stiffness_at(0.1234)
