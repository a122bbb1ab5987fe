"""The same linear rotor in bearingsim and in ROSS (ross-rotordynamics): natural frequencies at standstill and
at speed (gyroscopic), and the export of a rotor on ball bearings."""

import numpy as np
import pytest
from numpy.testing import assert_allclose

import bearingsim
from bearingsim.shafts.model import BearingSupport, PointLoad, PointMass, Section, ShaftSystem, SpringSupport
from bearingsim.shafts.modes import modes
from bearingsim.shafts.ross import to_ross
from bearingsim.shafts.solve import solve_shaft

pytest.importorskip("ross")


def _rotor(speed=0.0):
    return ShaftSystem((Section(0.25, 0.04), Section(0.35, 0.05, 0.02)),
                       (SpringSupport("a", 0.05, [1e8, 5e7, 5e7, 0, 0]), SpringSupport("b", 0.55, [0, 8e7, 8e7, 0, 0])),
                       masses=(PointMass(0.3, 5.0, 0.02, 0.01),), elements=16, speed=speed)


@pytest.mark.parametrize("speed", [0.0, 1500.0])
def test_frequencies_match_ross(speed):
    """Both codes on one model: lateral and axial frequencies within 3e-4 up to 1.2 kHz and 1.5e-3 at the 8th mode
    (ROSS's Timoshenko element carries the shear terms in its mass matrix as well, ours the Φ = 0 consistent mass,
    bearingsim.beam: the difference grows with the mode number)."""
    s = _rotor(speed)
    ours = modes(solve_shaft(s), 8, gyroscopic=speed > 0).frequency_hz
    rotor, _ = to_ross(s, [speed])
    theirs = np.sort(np.asarray(rotor.run_modal(speed=speed, num_modes=24).wn)) / (2 * np.pi)
    theirs = theirs[theirs > 1.0]
    nearest = np.array([theirs[np.argmin(np.abs(theirs - f))] for f in ours])
    assert_allclose(ours[:7], nearest[:7], rtol=3e-4, err_msg="bearingsim vs ROSS natural frequencies")
    assert_allclose(ours, nearest, rtol=1.5e-3, err_msg="bearingsim vs ROSS, up to the 8th mode (1.4 kHz)")


def test_export_of_a_rotor_on_ball_bearings():
    b = bearingsim.load_bearing("7011-15")
    s = ShaftSystem((Section(0.4, 0.055),), (BearingSupport("front", 0.05, b), BearingSupport(
        "rear", 0.3, b, orientation=-1, preload_force=500.0)), (PointLoad(0.0, (0.0, 500.0, 0.0)),))
    speeds = [0.0, 500.0, 1000.0]
    rotor, warnings = to_ross(s, speeds)
    assert any("front" in w and "K[gamma_z,gamma_z]" in w for w in warnings)
    assert any("rear" in w and "sliding outer ring" in w for w in warnings)
    r = solve_shaft(s, speed=500.0)
    front = next(be for be in rotor.bearing_elements if be.tag == "front")
    assert_allclose(front.kxx_interpolated(500.0), r.support("front").stiffness[1, 1], rtol=1e-6)
