"""The catalogue (issue 15): the ball-set estimate of bearingsim.catalogue (ISO 281 eq. 7 + ISO 76 eq. 1 solved
for Z and D_w), the generated entries against the published data they were made from, and the rating fields of
BallBearing (static_load_rating, geometry_factor_f0, fatigue_load_limit, sources, estimated)."""

import csv
import dataclasses
import math
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearingsim import catalogue as cat
from bearingsim import io
from bearingsim.errors import InputError

ROOT = Path(__file__).resolve().parents[2]
CSV = ROOT / "src" / "bearingsim" / "data" / "catalogue_nsk_e1102e.csv"


def published():
    lines = [ln for ln in CSV.read_text(encoding="utf-8").splitlines() if ln.strip() and not ln.startswith("#")]
    keys = ["designation", "nsk_number", "type", "alpha", "d", "D", "B", "C", "C0", "f0", "n_grease", "n_oil"]
    return [dict(zip(keys, r, strict=True)) for r in csv.reader(lines)]


ROWS = published()


# ---- the standard tables -------------------------------------------------------------------------------------
def test_tables_at_their_nodes_and_between():
    """Table values are returned at the nodes and linearly interpolated between them (ISO 281 §7.1 note)."""
    assert cat.factor_fc(0.05) == 46.7 and cat.factor_fc(0.20) == 59.9 and cat.factor_fc(0.40) == 48.4
    assert cat.factor_fc(0.055) == pytest.approx(0.5 * (46.7 + 49.1), rel=1e-12)
    assert cat.factor_f0(0.0) == 14.7 and cat.factor_f0(0.20) == 14.0 and cat.factor_f0(0.40) == 9.4
    assert cat.factor_f0(0.205) == pytest.approx(0.5 * (14.0 + 13.7), rel=1e-12)
    with pytest.raises(InputError, match="f_c"):
        cat.factor_fc(0.45)
    with pytest.raises(InputError, match="f0"):
        cat.factor_f0(-0.01)


def test_rating_formulas_by_hand():
    """C = b_m f_c (i cos α)^0.7 Z^(2/3) D_w^1.8 and C0 = f0 i Z D_w² cos α in N, mm (one hand evaluation)."""
    z, dw, dm, a = 9, 12.7e-3, 65e-3, 0.0
    g = 12.7 / 65.0
    fc = cat.factor_fc(g)
    assert cat.dynamic_load_rating(z, dw, dm, a) == pytest.approx(1.3 * fc * 9 ** (2 / 3) * 12.7**1.8, rel=1e-12)
    assert cat.static_load_rating(z, dw, dm, a) == pytest.approx(cat.factor_f0(g) * 9 * 12.7**2, rel=1e-12)
    # balls above 25.4 mm: eq. 8 with D_w^1.4 and the factor 3.647 (continuous at 25.4 mm within 0.1 %)
    lo = cat.dynamic_load_rating(8, 25.4e-3 * (1 - 1e-9), 120e-3, 0.0)
    hi = cat.dynamic_load_rating(8, 25.4e-3 * (1 + 1e-9), 120e-3, 0.0)
    assert hi == pytest.approx(lo, rel=1e-3)


def test_cn_clearance_groups():
    assert cat.cn_clearance(10e-3) == pytest.approx((2e-6, 13e-6), rel=1e-12)
    assert cat.cn_clearance(40e-3) == pytest.approx((6e-6, 20e-6), rel=1e-12)  # 30 < d <= 40
    assert cat.cn_clearance(45e-3) == pytest.approx((6e-6, 23e-6), rel=1e-12)
    with pytest.raises(InputError):
        cat.cn_clearance(0.5)


# ---- the estimate ----------------------------------------------------------------------------------------------
@settings(max_examples=40, deadline=None)
@given(z=st.integers(7, 22), dw=st.sampled_from([float(x) for x in cat.INCH_BALLS if 3e-3 < x < 26e-3]), alpha=st.sampled_from([0.0, 15.0, 25.0, 30.0, 40.0]),
       section=st.floats(2.6, 4.8))
def test_estimate_recovers_a_ball_set_from_its_own_rounded_ratings(z, dw, alpha, section):
    """Ratings computed from a standard ball set and rounded to 3 significant digits, as catalogues print them,
    give back that ball set (the two ratings fix Z and D_w)."""
    span = section * dw  # D - d, so that D_w lies in the searched 0.2-0.4 (D - d)
    d = 2.0 * dw * z / math.pi  # a bore that leaves room for the balls on d_m = d + span/2
    dm = d + 0.5 * span
    a = math.radians(alpha)
    if dm * math.sin(math.pi / z) < 1.04 * dw or dw * math.cos(a) / dm > 0.4:
        return  # not a bearing: the balls do not fit
    c = float(f"{cat.dynamic_load_rating(z, dw, dm, a):.3g}")
    c0 = float(f"{cat.static_load_rating(z, dw, dm, a):.3g}")
    e = cat.estimate_ball_set(d, d + span, a, c, c0)
    assert (e.ball_count, e.ball_diameter) == (z, pytest.approx(dw, rel=1e-9))
    assert abs(e.c_error) < 6e-3 and abs(e.c0_error) < 6e-3


def test_estimate_reports_residuals_and_a_runner_up():
    e = cat.estimate_ball_set(40e-3, 80e-3, 0.0, 29100.0, 17900.0)
    assert e.c_error == pytest.approx(e.dynamic_load_rating / 29100.0 - 1.0, rel=1e-12)
    assert e.c0_error == pytest.approx(e.static_load_rating / 17900.0 - 1.0, rel=1e-12)
    assert e.score == pytest.approx(math.log1p(e.c_error) ** 2 + math.log1p(e.c0_error) ** 2, rel=1e-9)
    assert len(e.runner_up) == 3 and e.runner_up[2] >= e.score


@pytest.mark.parametrize("kw, field", [
    (dict(bore=-1.0), "bore"), (dict(outside_diameter=0.03), "outside_diameter"),
    (dict(dynamic_rating=0.0), "dynamic_load_rating"), (dict(static_rating="19 kN"), "static_load_rating"),
    (dict(contact_angle=math.radians(70)), "contact_angle"),
])
def test_estimate_refuses_bad_input(kw, field):
    args = dict(bore=0.04, outside_diameter=0.08, contact_angle=0.0, dynamic_rating=29100.0, static_rating=17900.0)
    args.update(kw)
    with pytest.raises(InputError) as ei:
        cat.estimate_ball_set(**args)
    assert ei.value.field == field


# ---- the generated entries --------------------------------------------------------------------------------------
def test_generated_entries_are_up_to_date():
    """Every entry is what tools/make_catalogue.py writes from the published CSV (nobody edited one by hand)."""
    p = subprocess.run([sys.executable, str(ROOT / "tools" / "make_catalogue.py"), "--check"], capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr


def test_catalogue_covers_the_series_and_bores():
    names = set(io.catalog_names())
    bores = ["00", "01", "02", "03"] + [f"{k:02d}" for k in range(4, 21)]
    for series in ("60", "62", "63"):
        assert {series + b for b in bores} <= names
    for series, angles in (("70", ("15", "25", "30")), ("72", ("15", "30", "40"))):
        assert {f"{series}{b}-{a}" for b in bores for a in angles} <= names
    assert {"harris-218", "skf-7011-cdga-hc", "skf-7011-cdga-hc-db", "hub-seed001", "hub-seed001-row"} <= names


@pytest.mark.parametrize("row", ROWS[::7], ids=lambda r: r["designation"])
def test_entries_carry_the_published_numbers_and_flag_estimates(row):
    b = io.load_bearing(row["designation"])
    assert b.bore == pytest.approx(float(row["d"]) * 1e-3, rel=1e-12)
    assert b.outside_diameter == pytest.approx(float(row["D"]) * 1e-3, rel=1e-12)
    assert b.width == pytest.approx(float(row["B"]) * 1e-3, rel=1e-12)
    assert b.dynamic_load_rating == pytest.approx(float(row["C"]), rel=1e-12)
    assert b.static_load_rating == pytest.approx(float(row["C0"]), rel=1e-12)
    assert b.geometry_factor_f0 == (float(row["f0"]) if row["f0"] else 0.0)
    assert b.limiting_speed == pytest.approx(float(row["n_oil"]) * math.pi / 30, rel=1e-12)
    assert f"{row['n_grease']} rpm with grease" in b.sources["limiting_speed"]
    assert b.kind == row["type"]
    if b.kind == "angular_contact":
        assert b.contact_angle == pytest.approx(math.radians(float(row["alpha"])), rel=1e-12)
    assert {"ball_count", "ball_diameter", "pitch_diameter", "inner_conformity", "outer_conformity"} <= set(
        b.estimated)
    assert not {"bore", "dynamic_load_rating", "static_load_rating"} & set(b.estimated)
    assert "NSK" in b.sources["dynamic_load_rating"]
    # the estimated ball set reproduces the published ratings within the fit's stated residual (< 2 %)
    c = cat.dynamic_load_rating(b.ball_count, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    c0 = cat.static_load_rating(b.ball_count, b.ball_diameter, b.pitch_diameter, b.contact_angle)
    assert abs(c / b.dynamic_load_rating - 1) < 0.01 and abs(c0 / b.static_load_rating - 1) < 0.02


def test_the_25_deg_entries_come_from_ntn():
    b = io.load_bearing("7014-25")
    assert b.contact_angle == pytest.approx(math.radians(25.0), rel=1e-12)
    assert (b.dynamic_load_rating, b.static_load_rating) == (pytest.approx(46000.0), pytest.approx(43000.0))
    assert b.sources["dynamic_load_rating"].startswith("NTN-SNR") and "ball_count" in b.estimated


def test_deep_groove_entries_get_the_cn_mid_clearance():
    b = io.load_bearing("6205")
    lo, hi = cat.cn_clearance(b.bore)
    assert b.diametral_clearance == pytest.approx(0.5 * (lo + hi), rel=1e-9)
    assert "diametral_clearance" in b.estimated and b.free_contact_angle > 0


# ---- the rating fields of BallBearing ---------------------------------------------------------------------------
@pytest.fixture(scope="module")
def b6208():
    return io.load_bearing("6208")


@pytest.mark.parametrize("change, field", [
    (dict(static_load_rating=-1.0), "static_load_rating"),
    (dict(static_load_rating=math.inf), "static_load_rating"),
    (dict(fatigue_load_limit=-5.0), "fatigue_load_limit"),
    (dict(fatigue_load_limit=20e3), "fatigue_load_limit"),  # above C0 = 17.9 kN: a unit slip
    (dict(geometry_factor_f0=140.0), "geometry_factor_f0"),
    (dict(geometry_factor_f0=2.0), "geometry_factor_f0"),
    (dict(geometry_factor_f0="14"), "geometry_factor_f0"),
])
def test_rating_fields_are_checked(b6208, change, field):
    with pytest.raises(InputError) as ei:
        dataclasses.replace(b6208, **change)
    assert ei.value.field == field


def test_rating_fields_from_a_users_file(b6208):
    data = io.resolve_bearing_data("6208")
    data = {k: v for k, v in data.items() if k != "sources"}
    data.update(static_load_rating="19 kN", geometry_factor_f0=14, fatigue_load_limit="0.815 kN",
                dynamic_load_rating="30.7 kN")
    b = io.bearing_from_dict(data)
    assert (b.static_load_rating, b.geometry_factor_f0, b.fatigue_load_limit, b.dynamic_load_rating) == (
        pytest.approx(19e3), 14.0, pytest.approx(815.0), pytest.approx(30.7e3))
    assert b.estimated == () and b.sources == {}
    with pytest.raises(InputError) as ei:
        io.bearing_from_dict({**data, "static_load_rating": 19000})
    assert ei.value.field == "static_load_rating"
    with pytest.raises(InputError) as ei:
        io.bearing_from_dict({**data, "geometry_factor_f0": "14"})
    assert ei.value.field == "geometry_factor_f0"


def test_sources_and_estimated(b6208):
    assert "description" not in b6208.sources
    assert b6208.sources["static_load_rating"].startswith("NSK")
    assert b6208.estimated.index("ball_count") < b6208.estimated.index("ball_diameter")  # file order
    b = dataclasses.replace(b6208, notes={"bore": "ISO 15", "ball_count": "  estimate: by eye",
                                          "pitch_diameter": "Assumed (d+D)/2", "description": "x"})
    assert b.estimated == ("ball_count", "pitch_diameter")


@pytest.mark.parametrize("fit, size, seat, field", [
    ("k5", 2e-3, "shaft", "--shaft-fit"), ("k5", 0.4, "shaft", "--shaft-fit"), ("x5", 0.04, "shaft", "--shaft-fit"),
    ("H7", 0.04, "shaft", "--shaft-fit"), ("k5", 0.04, "housing", "--housing-fit"), ("Q7", 0.04, "housing",
                                                                                     "--housing-fit"),
    ("k5", -0.04, "shaft", "bore"), ("k5", 0.04, "ring", "seat"),
])
def test_fit_interference_refuses_what_the_tables_do_not_hold(fit, size, seat, field):
    with pytest.raises(InputError) as ei:
        cat.fit_interference(fit, size, seat)
    assert ei.value.field == field


def test_fit_interference_limits_and_size_steps():
    """Interference limits = shaft deviations minus the bore's (0, Δdmp); 30 mm belongs to 18–30, 30.001 to 30–50."""
    lo, mean, hi = cat.fit_interference("k5", 0.030, "shaft")
    assert (lo, hi) == (pytest.approx(2e-6), pytest.approx((2 + 9 + 10) * 1e-6))
    lo2, _, hi2 = cat.fit_interference("k5", 0.030001, "shaft")
    assert (lo2, hi2) == (pytest.approx(2e-6), pytest.approx((2 + 11 + 12) * 1e-6))
    lo, mean, hi = cat.fit_interference("JS7", 0.1, "housing")
    assert lo == pytest.approx(-(15 + 17.5) * 1e-6) and hi == pytest.approx(17.5e-6)


def test_every_fourth_generated_entry_solves():
    """The estimated ball sets are bearings the solver takes: Fr = 0.1 C, Fa = 0.05 C at 30 % of the limiting
    speed converge to an equilibrium (all 189 do; every fourth is checked here to stay fast)."""
    from bearingsim.statics.jones_harris import Loads, solve

    names = [n for n in io.catalog_names() if n[0] in "67"][::4]
    assert len(names) > 40
    for n in names:
        b = io.load_bearing(n)
        r = solve(b, Loads(fa=0.05 * b.dynamic_load_rating, fr_y=0.1 * b.dynamic_load_rating), 0.3 * b.limiting_speed)
        assert r.converged, (n, r.status, r.residual)
        assert abs(r.residual) < 1e-6 * b.dynamic_load_rating, n
