"""The several-groove (shared) ring of bearingsim.rings.shared (issue 16, hub units): with one groove it is the
single-groove model of bearingsim.rings.influence to round-off (same mesh, same read-out), and its section
estimate for the [S1] hub follows the documented rule."""

import math

import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.rings.influence import InfluenceSettings, compute_influence
from bearingsim.rings.section import estimate_sections
from bearingsim.rings.shared import Groove, SharedSection, compute_shared_influence, estimate_unit, is_unit


def _one_groove(outer, support="face_plus"):
    return SharedSection("outer", outer.seat_radius, outer.land_radius,
                         (Groove(0.0, 1.0, outer.groove_bottom_radius, outer.groove_radius, outer.contact_angle),),
                         -outer.half_width, outer.half_width, outer.sleeve_radius, axial_support=support)


def test_one_groove_is_the_single_groove_model():
    """The shared-ring code with one groove (the second groove 'absent') against compute_influence on the same
    section: the same coefficients to round-off (very coarse settings: the identity holds at any mesh)."""
    _, outer = estimate_sections(load_bearing("skf-7011-cdga-hc"))
    st = InfluenceSettings(sigma=outer.wall / 4, n_through=3, n_axial=6, ghat_min=1e-3, decay_min=1e-3)
    single = compute_influence(outer, 208e9, 0.3, 21, st, cache=False)
    shared = compute_shared_influence(_one_groove(outer), 208e9, 0.3, st, cache=False)
    m1 = single.matrix()
    m2 = shared.matrix([2 * math.pi * np.arange(21) / 21])
    assert shared.harmonics == single.harmonics
    np.testing.assert_allclose(m2, m1, rtol=0, atol=1e-12 * np.abs(m1).max())


def test_hub_unit_estimate():
    hub = load_bearing("hub-seed001")
    assert is_unit(hub) and not is_unit(load_bearing("skf-7011-cdga-hc-db"))
    inners, outer, notes = estimate_unit(hub)
    dw, dm = 11.1e-3, 61e-3
    assert notes["outer_ring_outside_diameter_m"] == pytest.approx(dm + 2 * dw)
    assert notes["inner_ring_bore_m"] == pytest.approx(dm - 2 * dw)
    assert notes["outer_ring_width_m"] == pytest.approx(18.2e-3 + 2 * dw)
    assert len(notes["estimated"]) == 4 and all("ESTIMATE" in t for t in notes["estimated"])
    assert [g.position for g in outer.grooves] == pytest.approx([-9.1e-3, 9.1e-3])
    assert [g.orientation for g in outer.grooves] == [1.0, -1.0]  # DB: mirrored second row
    # back-to-back: both outer contact points lie between the rows (lines of action diverge outwards)
    z = outer.contact_zs
    assert -9.1e-3 < z[0] < 0 < z[1] < 9.1e-3 and z[0] == pytest.approx(-z[1])
    assert all(i.half_width == pytest.approx(9.1e-3) for i in inners)


def test_shared_section_refuses_overlapping_grooves():
    _, outer = estimate_sections(load_bearing("skf-7011-cdga-hc"))
    g = Groove(0.0, 1.0, outer.groove_bottom_radius, outer.groove_radius, outer.contact_angle)
    with pytest.raises(InputError, match="overlap"):
        SharedSection("outer", outer.seat_radius, outer.land_radius, (g, Groove(1e-3, -1.0, *[
            getattr(g, k) for k in ("bottom_radius", "radius", "contact_angle")])), -0.02, 0.02)
    with pytest.raises(InputError, match="face"):
        SharedSection("outer", outer.seat_radius, outer.land_radius, (g,), -0.002, 0.002)


def test_hub_sleeve_inside_the_estimated_ring_is_refused_by_field():
    from bearingsim.rings.spec import Sleeve

    hub = load_bearing("hub-seed001")
    with pytest.raises(InputError) as e:
        estimate_unit(hub, housing=Sleeve(0.08))  # inside the estimated 83.2 mm outer ring
    assert e.value.field == "rings.housing.outer_diameter"
    with pytest.raises(InputError) as e:
        estimate_unit(hub, shaft=Sleeve(0.039))  # not inside the estimated 38.8 mm bore
    assert e.value.field == "rings.shaft.inner_diameter"
