"""Bad input of the thermal model (issue 46, item 5): an InputError naming the field."""

from __future__ import annotations

import math

import pytest

from bearingsim.errors import InputError
from bearingsim.thermal import ThermalNetwork, ThermalSetup, radial_conduction


@pytest.mark.parametrize("field, value", [
    ("oil_flow", -1e-5), ("oil_flow", 0.0), ("ring_conductivity", -43.0), ("shaft_conductivity", 0.0),
    ("housing_conductivity", math.nan), ("oil_specific_heat", -2000.0), ("housing_outside_diameter", -0.1),
    ("housing_width", -0.01), ("shaft_length", 0.0),
    ("oil_inlet_temperature", 900.0), ("ambient_temperature", 100.0), ("reference_temperature", 1000.0),
])
def test_setup_field_named(field, value):
    with pytest.raises(InputError) as e:
        ThermalSetup(**{field: value})
    assert f"thermal.{field}" in str(e.value)


@pytest.mark.parametrize("kwargs, field", [
    (dict(conductivity=-1.0, r_inner=0.01, r_outer=0.02, length=0.01), "conductivity"),
    (dict(conductivity=40.0, r_inner=-0.01, r_outer=0.02, length=0.01), "r_inner"),
    (dict(conductivity=40.0, r_inner=0.02, r_outer=0.01, length=0.01), "r_outer"),
    (dict(conductivity=40.0, r_inner=0.01, r_outer=0.02, length=0.0), "length"),
])
def test_conduction_inputs(kwargs, field):
    with pytest.raises(InputError) as e:
        radial_conduction(**kwargs)
    assert field in str(e.value)


def test_negative_conductance_and_area():
    from bearingsim.thermal import convection

    net = ThermalNetwork()
    net.add_node("a")
    net.add_fixed("amb", 300.0)
    with pytest.raises(InputError, match="thermal.oil_flow"):
        net.connect("a", "amb", -1.0, "thermal.oil_flow")
    with pytest.raises(InputError, match="area"):
        convection(10.0, -1.0)


def test_coolant_above_its_range():
    """An oil inlet above the lubricant's upper temperature (boiling/decomposition) names the field."""
    import bearingsim
    from bearingsim.thermal import thermal_operating_point

    b = bearingsim.load_bearing("skf-7011-cdga-hc")
    with pytest.raises(InputError) as e:
        thermal_operating_point(b, bearingsim.Loads(fa=1000.0), 1000.0, "iso-vg-68",
                                ThermalSetup(oil_inlet_temperature=473.15))
    assert "thermal.oil_inlet_temperature" in str(e.value)
