"""ISO 76:2006 static load rating and static safety against published figures.

* Equivalent static load of deep-groove ball bearings as a bearing maker publishes it: SKF, "Single row deep
  groove ball bearings — loads" (skf.com, deep-groove-ball-bearings/loads): P₀ = 0.6 F_r + 0.5 F_a, and P₀ = F_r
  when that is larger (ISO 76 table 4, X₀ = 0.6, Y₀ = 0.5).
* The static-rating estimate (ISO 76's derivation: 4 200 MPa at the most heavily loaded contact under
  Q_max = 5 C₀/(Z cos α)) for a 6205 whose ball set is public — Case Western Reserve University Bearing Data
  Center, drive-end bearing "6205-2RS JEM SKF": 9 balls of 0.3126 in (7.94 mm) on a 1.537 in (39.04 mm) pitch
  circle — against the SKF catalogue's C₀ = 7.8 kN and f₀ = 14 for the 6205.  Conformities are those ISO 76
  assumes for its f₀ table (r_i ≤ 0.52 D_w, r_e ≤ 0.53 D_w), steel E = 207 GPa, ν = 0.3 (Harris & Kotzalas'
  bearing steel; ISO/TR 10657 derives f₀ for steel of this modulus).  Tolerance 3 %: the catalogue rounds C₀
  to 0.1 kN (1.3 %) and f₀ to an integer (3.6 %).
"""

import numpy as np
import pytest

from bearingsim import life, safety
from bearingsim.geometry import BallBearing
from bearingsim.materials import Material

SKF_LOADS = "SKF deep groove ball bearings, loads: P0 = 0.6 Fr + 0.5 Fa; P0 < Fr -> P0 = Fr"


@pytest.mark.parametrize("fr, fa, p0", [
    (1000.0, 1000.0, 0.6 * 1000 + 0.5 * 1000),  # 1100 N > Fr
    (1000.0, 200.0, 1000.0),  # 0.6 Fr + 0.5 Fa = 700 N < Fr: P0 = Fr
    (0.0, 800.0, 400.0),
])
def test_deep_groove_static_equivalent_load(fr, fa, p0):
    np.testing.assert_allclose(safety.equivalent_static_load(fr, fa, 0.0, 1, "deep_groove"), p0, rtol=1e-12,
                               err_msg=SKF_LOADS)


def test_static_rating_estimate_of_the_6205():
    steel = Material("steel", 207e9, 0.3, 7850.0, "Harris & Kotzalas 2007 bearing steel")
    b = BallBearing(name="6205 (CWRU ball set)", kind="deep_groove", ball_diameter=7.94e-3, ball_count=9,
                    pitch_diameter=39.04e-3, inner_conformity=0.52, outer_conformity=0.53, contact_angle=0.0,
                    ball_material=steel, ring_material=steel)
    c0, f0 = life.static_rating_estimate(b)
    np.testing.assert_allclose(c0, 7.8e3, rtol=0.03,
                               err_msg="SKF catalogue 6205: C0 = 7.8 kN (ball set: CWRU Bearing Data Center)")
    np.testing.assert_allclose(f0, 14.0, rtol=0.03, err_msg="SKF catalogue 6205: f0 = 14")


LYC = "LYC bearing, 'Equivalent static load - angular contact ball bearings', table 4 (ISO 76 table 4 values)"


@pytest.mark.parametrize("deg, y0_single, y0_pair", [(15, 0.46, 0.92), (25, 0.38, 0.76), (40, 0.26, 0.52)])
def test_angular_contact_static_equivalent_load(deg, y0_single, y0_pair):
    a = np.radians(deg)
    fr, fa = 1000.0, 3000.0
    np.testing.assert_allclose(safety.equivalent_static_load(fr, fa, a, 1), 0.5 * fr + y0_single * fa, rtol=1e-12,
                               err_msg=f"{LYC}: {deg} deg single / tandem")
    np.testing.assert_allclose(safety.equivalent_static_load(fr, fa, a, 2), fr + y0_pair * fa, rtol=1e-12,
                               err_msg=f"{LYC}: {deg} deg back-to-back / face-to-face")
    # a small axial load: 0.5 Fr + Y0 Fa < Fr, so P0 = Fr (single row)
    assert safety.equivalent_static_load(fr, 100.0, a, 1) == fr, LYC


def test_static_safety_of_a_pair_through_the_solver():
    """A 7205-40 DB pair (catalogue) under F_r = 3 kN, F_a = 2 kN: P0 = F_r + 0.52 F_a (LYC / ISO 76 table 4) and
    s0 = C0 of the pair (2 C0 of one bearing) / P0; as a tandem pair, P0 = 0.5 F_r + 0.26 F_a."""
    from bearingsim.io import load_bearing
    from bearingsim.statics import arrangements as ar
    from bearingsim.statics import jones_harris as jh

    b = load_bearing("7205-40")
    for arr, p0 in (("DB", 3000.0 + 0.52 * 2000.0), ("DT", max(0.5 * 3000.0 + 0.26 * 2000.0, 3000.0))):
        pair = ar.make_system(b, arr, preload=100.0 if arr == "DB" else None)
        r = jh.solve(pair, jh.Loads(fr_y=3000.0, fa=2000.0))
        assert r.converged
        np.testing.assert_allclose(r.rating["equivalent_static_load_N"], p0, rtol=1e-12, err_msg=f"{LYC}: {arr}")
        np.testing.assert_allclose(r.rating["static_safety_factor"], 2 * b.static_load_rating / p0, rtol=1e-12)
