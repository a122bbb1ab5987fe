"""Hub-unit static study (studies/hub_static.py): its inputs and its solver paths.

Not literature validation (that is tests/validation/test_hub_static.py): the study's load path must carry the
ranges of Sakaguchi & Shibutani's Table 2 as the study module defines them, every point must converge, and the
compliance from implicit differentiation must equal the slope of the curve (a consistency check).
"""

import numpy as np

from bearingsim.studies import hub_static as hs


def test_table2_load_ranges_are_reproduced(hub_study):
    np.testing.assert_allclose([hub_study.fa[0], hub_study.fa[-1]], [-1890.0, 1890.0], rtol=1e-12,
                               err_msg="seed 001 Table 2: axial load -1,890 ... 1,890 N")
    np.testing.assert_allclose([hub_study.fr[0], hub_study.fr[-1]], [1820.0, 3750.0], rtol=1e-12,
                               err_msg="seed 001 Table 2: radial load 1,820 ... 3,750 N")
    np.testing.assert_allclose(hub_study.bearing.load_point, 0.0104, rtol=1e-12,
                               err_msg="seed 001 Table 2: load acting point 10.4 mm")
    assert hub_study.converged.all()


def test_all_points_converge_at_vehicle_speeds(hub, hub_study):
    for v in (10.0, 50.0):
        r = hs.run_study(hub, hub_study.moment, speed=hs.vehicle_speed_to_shaft(v))
        assert r.converged.all()


def test_path_compliance_equals_slope_of_curve(hub):
    h = 0.5
    r = hs.run_study(hub, [-h, 0.0, h])
    slope = (r.tilt[2] - r.tilt[0]) / (2 * h)
    np.testing.assert_allclose(r.compliance[1], slope, rtol=1e-5,
                               err_msg="implicit-differentiation compliance vs finite difference of the curve")
