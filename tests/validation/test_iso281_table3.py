"""ISO 281:2007 table 3 (X, Y, e of radial ball bearings): the rows checked against published reproductions in
2026-11 (docs/life.md, "Sources of ISO 281 table 3", lists every row and source).

* JTEKT (Koyo) catalogue, technical section "Calculation of equivalent radial / axial load"
  (koyousa.com/koyocatalog/technical/03/3_1_32.htm): the deep-groove rows (f₀F_a/C₀r 0.172 … 6.89, e, X 0.56,
  Y), the 15° rows (i f₀F_a/C₀r 0.178 … , e, single/tandem X 0.44 Y 1.47 … 1.00, back-to-back/face-to-face X 1
  Y 1.65 … 1.12 and X 0.72 Y 2.39 … 1.63; the page's last abscissa prints 5.35 twice, a typo for 7.14), the 30°
  and 40° rows, and "for i, use 2 for DB & DF arrangements and 1 for single & DT".
* 40° row: NSK leaflet "New 40° angular contact ball bearings" (paperzz.com/doc/7284321): e 1.14; single / DT
  F_a/F_r > e: X 0.35, Y 0.57; DB / DF F_a/F_r ≤ e: X 1, Y 0.55; > e: X 0.57, Y 0.93.
* 5°, 10°, 15° rows: two independent open transcriptions of ISO 281:2007 table 3 (a Rust bearing code, module
  "동정격하중 · 수명 (ISO 281:2007 + ISO 16281)", and a C# spindle-bearing calculator, tables A_15Y / DGY) that agree
  value for value; the 5° single-row cell of the standard reads "use the X, Y and e values applicable to single
  row radial contact groove ball bearings", and the 5°–15° relative-load columns are the deep-groove column divided
  by cos α (0.173 … 6.92 at 5°, 0.178 … 7.14 at 15°).
* The relative axial load of an angular contact pair is i f₀F_a/C₀r (NSK: "for i, use 2 for DB or DF, and 1 for
  DT"), C₀r of the pair.
"""

import math

import numpy as np
import pytest

from bearingsim import life

NSK40 = "NSK leaflet 'New 40° angular contact ball bearings' and JTEKT (Koyo) catalogue 3_1_32 (table 3, 40° row)"
KOYO = "JTEKT (Koyo) catalogue, 'Calculation of equivalent radial / axial load' (koyousa.com ... 3_1_32.htm)"
T3_SMALL = "ISO 281:2007 table 3, 5°-15° rows (two open transcriptions, docs/life.md)"


def test_40deg_row_against_the_nsk_leaflet():
    a = math.radians(40.0)
    np.testing.assert_allclose(life.xy_factors(1000.0, 2000.0, a, 1), (0.35, 0.57, 1.14), atol=1e-12, err_msg=NSK40)
    np.testing.assert_allclose(life.xy_factors(1000.0, 1000.0, a, 1), (1.0, 0.0, 1.14), atol=1e-12, err_msg=NSK40)
    np.testing.assert_allclose(life.xy_factors(1000.0, 1000.0, a, 2), (1.0, 0.55, 1.14), atol=1e-12, err_msg=NSK40)
    np.testing.assert_allclose(life.xy_factors(1000.0, 2000.0, a, 2), (0.57, 0.93, 1.14), atol=1e-12, err_msg=NSK40)


@pytest.mark.parametrize("k, rel, e, y, y1, y2", list(zip(
    range(9), (0.178, 0.357, 0.714, 1.07, 1.43, 2.14, 3.57, 5.35, 7.14),
    (0.38, 0.40, 0.43, 0.46, 0.47, 0.50, 0.55, 0.56, 0.56),
    (1.47, 1.40, 1.30, 1.23, 1.19, 1.12, 1.02, 1.00, 1.00),
    (1.65, 1.57, 1.46, 1.38, 1.34, 1.26, 1.14, 1.12, 1.12),
    (2.39, 2.28, 2.11, 2.00, 1.93, 1.82, 1.66, 1.63, 1.63))))
def test_15deg_rows_single_and_double(k, rel, e, y, y1, y2):
    a = math.radians(15.0)
    np.testing.assert_allclose(life.xy_factors(1000.0, 5000.0, a, 1, rel_load=rel), (0.44, y, e), atol=1e-12,
                               err_msg=KOYO + f", 15° single row, row {k}")
    np.testing.assert_allclose(life.xy_factors(1000.0, 0.5 * e * 1000.0, a, 2, rel_load=rel), (1.0, y1, e),
                               atol=1e-12, err_msg=KOYO + f", 15° DB/DF F_a/F_r <= e, row {k}")
    np.testing.assert_allclose(life.xy_factors(1000.0, 5000.0, a, 2, rel_load=rel), (0.72, y2, e), atol=1e-12,
                               err_msg=KOYO + f", 15° DB/DF F_a/F_r > e, row {k}")


@pytest.mark.parametrize("k, rel5, rel_dg, e_dg, y_dg, e2, y1, y2", list(zip(
    range(9), (0.173, 0.346, 0.692, 1.04, 1.38, 2.08, 3.46, 5.19, 6.92),
    (0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89),
    (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44),
    (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00),
    (0.23, 0.26, 0.30, 0.34, 0.36, 0.40, 0.45, 0.50, 0.52),
    (2.78, 2.40, 2.07, 1.87, 1.75, 1.58, 1.39, 1.26, 1.21),
    (3.74, 3.23, 2.78, 2.52, 2.36, 2.13, 1.87, 1.69, 1.63))))
def test_5deg_single_row_is_the_deep_groove_row_and_double_row_its_own(k, rel5, rel_dg, e_dg, y_dg, e2, y1, y2):
    a = math.radians(5.0)
    # single row: the deep-groove X, Y and e (the standard's text in the 5° single-row cell), at f0 Fa/C0r
    np.testing.assert_allclose(life.xy_factors(1000.0, 5000.0, a, 1, rel_load=rel_dg), (0.56, y_dg, e_dg),
                               atol=1e-12, err_msg=T3_SMALL + f", 5° single row = radial contact groove, row {k}")
    # F_a/F_r between the deep-groove e and the 5° double-row e (which the single row took before 2026-11): the
    # single row is already past its e, X = 0.56
    fa = 0.5 * (e_dg + e2) * 1000.0
    np.testing.assert_allclose(life.xy_factors(1000.0, fa, a, 1, rel_load=rel_dg), (0.56, y_dg, e_dg), atol=1e-12,
                               err_msg=T3_SMALL + f", 5° single row takes the deep-groove e, row {k}")
    # double row: the 5° columns, at i f0 Fa/C0r = 0.173 ... 6.92
    np.testing.assert_allclose(life.xy_factors(1000.0, 0.5 * e2 * 1000.0, a, 2, rel_load=rel5), (1.0, y1, e2),
                               atol=1e-12, err_msg=T3_SMALL + f", 5° double row F_a/F_r <= e, row {k}")
    np.testing.assert_allclose(life.xy_factors(1000.0, 5000.0, a, 2, rel_load=rel5), (0.78, y2, e2), atol=1e-12,
                               err_msg=T3_SMALL + f", 5° double row F_a/F_r > e, row {k}")


def test_pair_relative_axial_load_carries_i():
    """A DB pair of 15° bearings with C0r (pair) = 2 C0 and f0: table 3 is entered at 2 f0 Fa / C0r (pair); a
    tandem pair at f0 Fa / C0r (pair) — i.e. the same per-ball load as a single bearing carrying the whole Fa
    (DB: one row carries it) or half of it (DT)."""
    a = math.radians(15.0)
    f0, c0_single, fa, fr = 14.0, 10.0e3, 2000.0, 1000.0
    rel_db = 2 * f0 * fa / (2 * c0_single)
    rel_single = f0 * fa / c0_single
    assert rel_db == rel_single, "one row of a DB pair carries Fa: same relative load as a single bearing"
    x, y, e = life.xy_factors(fr, fa, a, 2, rel_load=rel_db)
    # rel = 2.8 lies between the tabulated 2.14 and 3.57: e and Y2 interpolated linearly
    t = (rel_db - 2.14) / (3.57 - 2.14)
    np.testing.assert_allclose((x, y, e), (0.72, 1.82 + t * (1.66 - 1.82), 0.50 + t * (0.55 - 0.50)), atol=1e-12,
                               err_msg=T3_SMALL + ", i f0 Fa/C0r of a DB pair")


def test_30deg_row_against_the_koyo_catalogue():
    a = math.radians(30.0)
    np.testing.assert_allclose(life.xy_factors(1000.0, 2000.0, a, 1), (0.39, 0.76, 0.80), atol=1e-12, err_msg=KOYO)
    np.testing.assert_allclose(life.xy_factors(1000.0, 500.0, a, 2), (1.0, 0.78, 0.80), atol=1e-12, err_msg=KOYO)
    np.testing.assert_allclose(life.xy_factors(1000.0, 2000.0, a, 2), (0.63, 1.24, 0.80), atol=1e-12, err_msg=KOYO)


@pytest.mark.parametrize("rel, e, y", list(zip((0.172, 0.345, 0.689, 1.03, 1.38, 2.07, 3.45, 5.17, 6.89),
                                               (0.19, 0.22, 0.26, 0.28, 0.30, 0.34, 0.38, 0.42, 0.44),
                                               (2.30, 1.99, 1.71, 1.55, 1.45, 1.31, 1.15, 1.04, 1.00))))
def test_deep_groove_rows_against_the_koyo_catalogue(rel, e, y):
    np.testing.assert_allclose(life.xy_factors(1000.0, 3000.0, 0.0, 1, "deep_groove", rel), (0.56, y, e), atol=1e-12,
                               err_msg=KOYO + ", deep groove")
