"""Unit tests of the EHL film functions, the regime map and the lubricants."""

from __future__ import annotations

import math

import pytest

from bearingsim import lubricants as L
from bearingsim.contact import ehl
from bearingsim.errors import InputError

SPEED = 1e-4  # slow enough to pass IR -> IE -> PE on the load sweep
ARGS = dict(eta0=0.03, alpha=2.1e-8, e_eff=2.286e11, rx=4.7e-3, ry=0.144)


def test_film_scaling_exponents():
    hc1, hm1 = ehl.film_thickness(2.0, 1000.0, **ARGS)
    hc2, hm2 = ehl.film_thickness(4.0, 1000.0, **ARGS)
    hc3, hm3 = ehl.film_thickness(2.0, 2000.0, **ARGS)
    assert hc2 / hc1 == pytest.approx(2**0.67, rel=1e-12)
    assert hm2 / hm1 == pytest.approx(2**0.68, rel=1e-12)
    assert hc3 / hc1 == pytest.approx(2**-0.067, rel=1e-12)
    assert hm3 / hm1 == pytest.approx(2**-0.073, rel=1e-12)
    hc4, hm4 = ehl.film_thickness(2.0, 1000.0, **{**ARGS, "eta0": 0.06})
    assert hm4 / hm1 == pytest.approx(2**0.68, rel=1e-12)
    assert 0 < hm1 < hc1


def test_film_closed_form_value():
    u, q = 2.0, 1000.0
    U = ARGS["eta0"] * u / (ARGS["e_eff"] * ARGS["rx"])
    G = ARGS["alpha"] * ARGS["e_eff"]
    W = q / (ARGS["e_eff"] * ARGS["rx"] ** 2)
    k = 1.03 * (ARGS["ry"] / ARGS["rx"]) ** 0.64
    hm = ARGS["rx"] * 3.63 * U**0.68 * G**0.49 * W**-0.073 * (1 - math.exp(-0.68 * k))
    hc = ARGS["rx"] * 2.69 * U**0.67 * G**0.53 * W**-0.067 * (1 - 0.61 * math.exp(-0.73 * k))
    assert ehl.film_thickness(u, q, **ARGS) == (pytest.approx(hc, rel=1e-13), pytest.approx(hm, rel=1e-13))
    f = ehl.film_thickness(u, q, thermal_factor=0.8, starvation_factor=0.5, **ARGS)
    assert f[1] == pytest.approx(0.4 * hm, rel=1e-13)


def test_thermal_factor_properties():
    assert ehl.zhu_cheng_thermal_factor(1.5e9, 2.3e11, 1e-3, 0.0, 0.13, 0.0) == 1.0
    prev = 1.0
    for u in (0.5, 2.0, 10.0, 40.0):
        phi = ehl.zhu_cheng_thermal_factor(1.5e9, 2.3e11, 1e-3, u, 0.13, 0.0)
        assert 0.0 <= phi < prev
        prev = phi
    # sliding reduces it further (Zhou & Hoeprich eq. 21 denominator)
    assert ehl.zhu_cheng_thermal_factor(1.5e9, 2.3e11, 1e-3, 10.0, 0.13, 0.5) < \
        ehl.zhu_cheng_thermal_factor(1.5e9, 2.3e11, 1e-3, 10.0, 0.13, 0.0)
    L_T = 1e-3 * 10.0**2 / 0.13
    expected = (1 - 13.2 * (1.5e9 / 2.3e11) * L_T**0.42) / (1 + 0.213 * L_T**0.64)
    assert ehl.zhu_cheng_thermal_factor(1.5e9, 2.3e11, 1e-3, 10.0, 0.13, 0.0) == pytest.approx(expected, rel=1e-13)


def test_film_parameter_and_roughness():
    assert ehl.composite_roughness(3e-8, 4e-8) == pytest.approx(5e-8)
    assert ehl.film_parameter(1e-7, 5e-8) == pytest.approx(2.0)
    assert ehl.film_parameter(1e-7, 0.0) == math.inf
    with pytest.raises(InputError):
        ehl.film_parameter(1e-7, -1e-8)


def test_regime_corners_and_boundary_continuity():
    # steel ball bearing, mineral oil: piezoviscous-elastic
    assert ehl.regime(5.0, 1000.0, **ARGS) == "PE"
    assert ehl.regime(0.5, 5000.0, **ARGS) == "PE"
    # soft (rubber-like) contact: isoviscous-elastic
    assert ehl.regime(1.0, 10.0, eta0=0.03, alpha=2e-8, e_eff=1e7, rx=0.01, ry=0.01) == "IE"
    # tiny g_V and g_E: isoviscous-rigid
    G = 5000.0
    W = (1e-2 / (1e-2 * G)) ** 3
    U = math.sqrt(W ** (8 / 3) / 1e-2)
    assert ehl.regime_code(U, G, W, ARGS["rx"], ARGS["ry"]) == ehl.IR
    # at a regime change the two adjacent film formulae agree (boundaries are equal-film lines)
    loads = [10 ** (k / 20) for k in range(-200, 80)]
    codes = [ehl.regime_code(*ehl.dimensionless_groups(SPEED, q, ARGS["eta0"], ARGS["alpha"], ARGS["e_eff"], ARGS["rx"]),
                             ARGS["rx"], ARGS["ry"]) for q in loads]
    changes = [i for i in range(1, len(codes)) if codes[i] != codes[i - 1]]
    assert changes, "the load sweep should cross at least one regime boundary"
    adjacent = {frozenset(p) for p in ((ehl.IR, ehl.IE), (ehl.IR, ehl.PR), (ehl.IE, ehl.PE), (ehl.PR, ehl.PE))}
    checked = 0
    for i in changes:
        if frozenset((codes[i - 1], codes[i])) not in adjacent:
            continue  # a diagonal switch near the triple point (documented in ehl.py)
        checked += 1
        lo, hi = loads[i - 1], loads[i]
        for _ in range(80):
            mid = math.sqrt(lo * hi)
            c = ehl.regime_code(*ehl.dimensionless_groups(SPEED, mid, ARGS["eta0"], ARGS["alpha"], ARGS["e_eff"],
                                                          ARGS["rx"]), ARGS["rx"], ARGS["ry"])
            if c == codes[i - 1]:
                lo = mid
            else:
                hi = mid
        U, G, W = ehl.dimensionless_groups(SPEED, lo, ARGS["eta0"], ARGS["alpha"], ARGS["e_eff"], ARGS["rx"])
        films = ehl.regime_films(U, G, W, ARGS["rx"], ARGS["ry"])
        a, b = films[codes[i - 1]], films[codes[i]]
        assert a == pytest.approx(b, rel=1e-6), (ehl.REGIME_NAMES[codes[i - 1]], ehl.REGIME_NAMES[codes[i]])
    assert checked >= 1


def test_bad_film_inputs():
    with pytest.raises(InputError, match="viscosity"):
        ehl.film_thickness(1.0, 100.0, **{**ARGS, "eta0": -0.01})
    with pytest.raises(InputError, match="entrainment_speed"):
        ehl.film_thickness(float("nan"), 100.0, **ARGS)
    with pytest.raises(InputError, match="starvation"):
        ehl.film_thickness(1.0, 100.0, starvation_factor=1.5, **ARGS)


# --------------------------------------------------------------------------- lubricants

def test_library_entries_reproduce_their_viscosity_points():
    names = L.library_names()
    for n in ("iso-vg-68", "hub-grease-base-oil", "mil-prf-23699"):
        assert n in names
    vg68 = L.get_lubricant("iso-vg-68")
    assert vg68.kinematic_viscosity(313.15) == pytest.approx(68e-6, rel=1e-12)
    assert vg68.kinematic_viscosity(373.15) == pytest.approx(8.7e-6, rel=1e-12)
    for lub in L.library().values():
        assert lub.sources, "every library entry cites sources"
        t = 333.15
        beta = lub.viscosity_temperature_coefficient(t)
        h = 1e-3
        num = -(math.log(lub.dynamic_viscosity(t + h)) - math.log(lub.dynamic_viscosity(t - h))) / (2 * h)
        assert beta == pytest.approx(num, rel=1e-6)
        assert lub.dynamic_viscosity(373.15) < lub.dynamic_viscosity(313.15)


def test_lubricant_bad_inputs(tmp_path):
    vg68 = L.get_lubricant("iso-vg-68")
    with pytest.raises(InputError, match="temperature"):
        vg68.dynamic_viscosity(273.15 - 60)
    with pytest.raises(InputError, match="temperature"):
        vg68.dynamic_viscosity(float("nan"))
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "x"\nviscosity = [["40 degC", "-68 mm^2/s"], ["100 degC", "8 mm^2/s"]]\n'
                   'density_15C = "870 kg/m^3"\npressure_viscosity_coefficient = "20 1/GPa"\n'
                   'thermal_conductivity = "0.13 W/(m*K)"\n')
    with pytest.raises(InputError, match="viscosity"):
        L.get_lubricant(str(bad))
    good = tmp_path / "good.toml"
    good.write_text('name = "x"\nviscosity = [["40 degC", "32 cSt"], ["100 degC", "5.4 mm^2/s"]]\n'
                    'density_15C = "0.87 g/ml"\npressure_viscosity_coefficient = "20 1/GPa"\n'
                    'thermal_conductivity = "0.13 W/(m*K)"\n')
    lub = L.get_lubricant(str(good))
    assert lub.kinematic_viscosity(313.15) == pytest.approx(32e-6, rel=1e-12)
    assert lub.density_15 == pytest.approx(870.0)
    with pytest.raises(InputError):
        L.get_lubricant("no-such-oil")
