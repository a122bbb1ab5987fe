"""Closed-form checks of the steady thermal network (bearingsim.thermal.network) and of the operating point's
energy balance (issue 46, item 3)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim.thermal.network import ThermalNetwork, axial_conduction, convection, radial_conduction


@given(k=st.floats(1.0, 400.0), r1=st.floats(1e-3, 0.1), ratio=st.floats(1.01, 5.0), length=st.floats(1e-3, 0.2),
       q=st.floats(1.0, 1e4))
@settings(max_examples=60, deadline=None)
def test_ring_radial_conduction_closed_form(k, r1, ratio, length, q):
    """A ring's bore held at 300 K, heat q entering its outside: ΔT = q ln(r2/r1)/(2π k L)."""
    r2 = r1 * ratio
    net = ThermalNetwork()
    net.add_node("outside")
    net.add_fixed("bore", 300.0)
    net.connect("outside", "bore", radial_conduction(k, r1, r2, length))
    net.add_heat("outside", q)
    sol = net.solve()
    expected = 300.0 + q * math.log(r2 / r1) / (2.0 * math.pi * k * length)
    assert sol.temperatures["outside"] == pytest.approx(expected, rel=1e-12)
    assert sol.energy_balance_error < 1e-9


def test_series_network_hand_solution():
    """Source 100 W at A; A -(2 W/K)- B -(5 W/K)- ambient 290 K, B also loses to coolant 300 K through 3 W/K and
    receives 20 W: by hand, T_B from (T_B−290)·5 + (T_B−300)·3 = 120 → T_B = (120 + 1450 + 900)/8 = 308.75 K,
    T_A = T_B + 100/2 = 358.75 K; heat out to ambient 5·18.75 = 93.75 W, to coolant 3·8.75 = 26.25 W."""
    net = ThermalNetwork()
    for n in ("A", "B"):
        net.add_node(n)
    net.add_fixed("ambient", 290.0)
    net.add_fixed("coolant", 300.0)
    net.connect("A", "B", 2.0)
    net.connect("B", "ambient", 5.0)
    net.connect("B", "coolant", 3.0)
    net.add_heat("A", 100.0)
    net.add_heat("B", 20.0)
    sol = net.solve()
    assert sol.temperatures["B"] == pytest.approx(308.75, rel=1e-12)
    assert sol.temperatures["A"] == pytest.approx(358.75, rel=1e-12)
    assert sol.heat_removed["ambient"] == pytest.approx(93.75, rel=1e-12)
    assert sol.heat_removed["coolant"] == pytest.approx(26.25, rel=1e-12)


def test_element_conductances():
    assert axial_conduction(40.0, 2e-4, 0.1) == pytest.approx(0.08, rel=1e-12)
    assert convection(50.0, 0.02) == pytest.approx(1.0, rel=1e-12)


def test_isolated_node_is_an_input_error():
    from bearingsim.errors import InputError

    net = ThermalNetwork()
    net.add_node("A")
    net.add_node("B")
    net.add_fixed("ambient", 290.0)
    net.connect("A", "ambient", 1.0)
    net.add_heat("B", 1.0)
    with pytest.raises(InputError, match="not connected"):
        net.solve()


@pytest.fixture(scope="module")
def op():
    import bearingsim
    from bearingsim.thermal import ThermalSetup, thermal_operating_point

    b = bearingsim.load_bearing("skf-7011-cdga-hc")
    return thermal_operating_point(b, bearingsim.Loads(fa=1000.0), 15000 * math.pi / 30, "iso-vg-68",
                                   ThermalSetup(oil_inlet_temperature=313.15, oil_flow=1.67e-5))


def test_operating_point_energy_balance(op):
    """Heat generated (every source at the fixed point) = heat removed (oil + ambient) to ≤ 0.1 %."""
    assert op.converged, op.status
    generated = sum(v for v in op.heat_sources.values() if v is not None)
    removed = sum(op.heat_removed.values())
    assert removed == pytest.approx(generated, rel=1e-3)
    assert op.energy_balance_error <= 1e-3


def test_operating_point_clearance_is_the_clearance_model(op):
    """The clearance change reported equals the clearance model at the fixed point's temperatures."""
    from bearingsim.statics.clearance import OperatingClearance

    t = op.temperatures
    b = op.result.bearing
    ch = OperatingClearance(inner_ring_temperature=t["inner_ring"], outer_ring_temperature=t["outer_ring"],
                            ball_temperature=t["balls"], shaft_temperature=t["shaft"],
                            housing_temperature=t["housing"], speed=op.result.speed)
    import bearingsim

    base = bearingsim.load_bearing("skf-7011-cdga-hc")
    assert op.clearance_change == pytest.approx(ch.change(base)["diametral_clearance_change_m"], rel=1e-12)
    assert b.diametral_clearance != base.diametral_clearance
    assert all(v > 313.15 for k, v in t.items() if k not in ("shaft", "housing"))


def test_runaway_is_a_status():
    """A bearing cooled by a trickle of oil whose heat grows with temperature has no fixed point within the
    lubricant's range: not converged, the reason in the status."""
    import bearingsim
    from bearingsim.thermal import ThermalSetup, thermal_operating_point

    b = bearingsim.load_bearing("skf-7011-cdga-hc")
    op = thermal_operating_point(b, bearingsim.Loads(fa=1000.0), 15000 * math.pi / 30, "iso-vg-68",
                                 ThermalSetup(oil_inlet_temperature=313.15, oil_flow=1e-8), max_iterations=30)
    assert not op.converged
    assert op.status.startswith("no fixed point (thermal runaway)"), op.status
