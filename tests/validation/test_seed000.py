"""Seed 000 (axial stiffness of the SKF 7011 CDGA/HC P4 hybrid spindle bearing): tables T1–T3.

Reference values: tests/data/seed000_tables.csv, transcribed by hand from
shared/seeds/000_d04d0d17023f2682.txt (decimal commas → points) and cross-checked below
against the lead's independent transcription in bearingsim/data/seed000.toml.

Geometry: the catalogue entry ``skf-7011-cdga-hc``.  Its ball set (Z = 21, D = 10.319 mm,
f_i = 0.52, f_o = 0.53, d_m = 72.5 mm) is ESTIMATED from the boundary dimensions (no public
source); it was not fitted to T1, and these tests must not be "fixed" by tuning it.

Deviations found (ours / seed − 1), axial model without inertia vs T1 "without inertial":
    1000 N +4.6 %, 2000 N +2.4 %, 3000 N +7.6 %, 4000 N +12.9 %, 5000 N +14.1 %.
The issue's aim is ≤ 10 %; it holds for 1000–3000 N only — see test_t1_high_loads_deviation.
Run ``pytest tests/validation/test_seed000.py -rP`` to print the full comparison.
"""

from __future__ import annotations

import csv
import math
import tomllib
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearingsim.statics import axial
from bearingsim.statics.jones_harris import Loads, solve

RPM = math.pi / 30.0
CSV = Path(__file__).parent.parent / "data" / "seed000_tables.csv"
LOADS = [1000, 2000, 3000, 4000, 5000]
T2_SPEEDS = [2800, 3550, 4000, 5000, 6000, 7000, 9000, 11000]
SRC_T1 = "seed 000 table T1 (Ca without inertial forces, n = 0)"
SRC_T2 = "seed 000 table T2 (Ca with inertial forces)"
SRC_T3 = "seed 000 table T3 (Palmgren column, ref. [7] of the seed)"


def read_seed() -> dict:
    out = {}
    with CSV.open(encoding="utf-8") as f:
        lines = [ln for ln in f if not ln.startswith("#")]
    for row in csv.DictReader(lines):
        out[(row["table"], int(row["fa_N"]), int(row["speed_rpm"]), row["model"])] = float(row["ca_N_per_um"])
    return out


@pytest.fixture(scope="module")
def seed():
    return read_seed()


@pytest.fixture(scope="module")
def ours(b7011):
    """Our Ca [N/µm]: axial model, JH at the seed's speeds (outer control), Palmgren at α and α₀."""
    res = {"axial": {}, "jh": {}, "palmgren_loaded": {}, "palmgren_free": {}, "converged": True}
    for fa in LOADS:
        t = axial.solve_thrust(b7011, float(fa))
        res["axial"][fa] = t.axial_stiffness / 1e6
        res["palmgren_loaded"][fa] = axial.palmgren_axial_stiffness(fa, b7011.ball_count, b7011.ball_diameter,
                                                                    t.contact_angle) / 1e6
        res["palmgren_free"][fa] = axial.palmgren_axial_stiffness(fa, b7011.ball_count, b7011.ball_diameter,
                                                                  b7011.free_contact_angle) / 1e6
        for n in [0] + T2_SPEEDS:
            r = solve(b7011, Loads(fa=float(fa)), n * RPM, control="outer")
            res["converged"] &= bool(r.converged)
            res["jh"][(fa, n)] = r.axial_stiffness / 1e6
    return res


def test_transcription_matches_package_data(seed):
    """Two independent transcriptions of the seed's tables agree exactly."""
    data = tomllib.loads((resources.files("bearingsim") / "data" / "seed000.toml").read_text(encoding="utf-8"))
    for i, fa in enumerate(LOADS):
        assert seed[("T1", fa, 0, "without_inertia")] == data["T1"]["without_inertia"][i], SRC_T1
        assert seed[("T1", fa, 0, "with_inertia")] == data["T1"]["with_inertia"][i], SRC_T1
        for col in ("without_inertia", "with_inertia", "palmgren", "fem"):
            assert seed[("T3", fa, 0, col)] == data["T3"][col][i], f"seed 000 table T3, {col}, {fa} N"
        for k, n in enumerate(T2_SPEEDS):
            assert seed[("T2", fa, n, "with_inertia")] == data["T2"]["stiffness"][k][i], SRC_T2 + f" {n} rpm {fa} N"


def test_all_solves_converged(ours):
    assert ours["converged"], "every operating point of seed 000 T1/T2 must converge"


def test_report(seed, ours):
    """Prints the comparison (shown with -rP).  Asserts only that every number is finite."""
    lines = ["Fa[N]  ours_axial  seed_T1  dev   | ours_JH(n=0) seed_T1_with dev | Palm(a) Palm(a0) seed_Palm dev(a)"]
    for fa in LOADS:
        a, s1, s1w = ours["axial"][fa], seed[("T1", fa, 0, "without_inertia")], seed[("T1", fa, 0, "with_inertia")]
        j0, pl, pf, sp = ours["jh"][(fa, 0)], ours["palmgren_loaded"][fa], ours["palmgren_free"][fa], \
            seed[("T3", fa, 0, "palmgren")]
        lines.append(f"{fa:5d}  {a:10.1f}  {s1:7.1f} {a / s1 - 1:+6.1%} | {j0:12.1f} {s1w:12.1f} {j0 / s1w - 1:+6.1%} |"
                     f" {pl:7.1f} {pf:8.1f} {sp:9.1f} {pl / sp - 1:+6.1%}")
    lines.append("T2 (ours / seed, N/um):  rpm  " + "  ".join(f"{fa:>13d}" for fa in LOADS))
    for n in T2_SPEEDS:
        cells = [f"{ours['jh'][(fa, n)]:6.1f}/{seed[('T2', fa, n, 'with_inertia')]:6.1f}" for fa in LOADS]
        lines.append(f"{'':24s}{n:5d}  " + "  ".join(cells))
    print("\n".join(lines))
    assert all(math.isfinite(v) for v in ours["axial"].values()), SRC_T1


@pytest.mark.parametrize("fa", [1000, 2000, 3000])
def test_t1_within_ten_percent(seed, ours, fa):
    """Issue 2 aim: T1 within 10 % with the documented (estimated) geometry — holds for 1000–3000 N."""
    assert_allclose(ours["axial"][fa], seed[("T1", fa, 0, "without_inertia")], rtol=0.10, err_msg=SRC_T1)


def test_t1_high_loads_deviation(seed, ours):
    """DEVIATES: at 4000 N and 5000 N our Ca is 12.9 % and 14.1 % above T1 (aim ≤ 10 % not met).

    Why: the ball set is estimated (no public source), and Ca's growth with load depends on it
    through the load parameter Fa/(Z K_n A^1.5) (how fast the contact angle grows).  We do not
    tune the geometry to the table.  Also, the seed's own T1 increments per 1000 N (35.7, 21.1,
    16.1, 18.8 N/µm) are not monotonic, while the model's Ca(Fa) is concave (Hertz Ca ∝ Fa^⅓
    at fixed α, stiffened smoothly by the growing α); no smooth model follows both the seed's
    3000 N and 5000 N points.  What the physics supports, and is asserted here:
      * Ca rises with Fa, faster than the fixed-angle Hertz law Fa^⅓ (the contact angle grows),
        in our model and in the seed's table alike;
      * our Ca(Fa) is concave;
      * the deviation is one-sided (ours stiffer) — a systematic geometry difference, not noise.
    The magnitudes at 4000/5000 N are reported (module docstring, test_report), not validated.
    """
    fa = np.array(LOADS, float)
    o = np.array([ours["axial"][f] for f in LOADS])
    s = np.array([seed[("T1", f, 0, "without_inertia")] for f in LOADS])
    hertz_fixed_angle = (fa / fa[0]) ** (1 / 3)
    for curve, name in ((o, "ours"), (s, "seed T1")):
        assert np.all(np.diff(curve) > 0), f"{name}: Ca must rise with Fa ({SRC_T1})"
        assert np.all(curve[1:] / curve[0] > hertz_fixed_angle[1:]), f"{name}: faster than Fa^(1/3) ({SRC_T1})"
    assert np.all(np.diff(np.diff(o)) < 0), "our Ca(Fa) should be concave"
    dev = o / s - 1
    assert np.all(dev > 0), SRC_T1 + ": deviation expected one-sided (ours stiffer)"
    assert dev[3] > 0.10 and dev[4] > 0.10, "deviation now within 10 %: update this docstring and docs/validation.md"


def test_t1_with_inertia_at_rest_is_the_axial_model(ours):
    """At n = 0 the Jones–Harris model is the axial model (issue 2: ≤ 0.1 %; here ≤ 1e-8).

    The seed's own two models differ by up to 5.6 % at n = 0 (T1: 115.4 vs 108.9 N/µm at 2000 N),
    which it attributes to 'different approaches'; ours do not."""
    for fa in LOADS:
        assert_allclose(ours["jh"][(fa, 0)], ours["axial"][fa], rtol=1e-8,
                        err_msg="seed 000 sections 2.1/2.2: same physics at n = 0")


@pytest.mark.parametrize("fa", LOADS)
def test_t2_ca_falls_with_speed(seed, ours, fa):
    """Seed 000 T2 / Fig. 5: at every load Ca falls monotonically with speed (0 and the seed's speeds)."""
    ca = np.array([ours["jh"][(fa, n)] for n in [0] + T2_SPEEDS])
    assert np.all(np.diff(ca) < 0), SRC_T2 + f": Ca not falling with speed at {fa} N: {ca}"
    ref = np.array([seed[("T2", fa, n, "with_inertia")] for n in T2_SPEEDS])
    assert np.all(np.diff(ref) < 0), SRC_T2 + ": the seed's own table is monotonic too"


def test_t2_speed_effect_is_smaller_than_the_seeds(seed, ours):
    """REPORTED DEVIATION (not a pass criterion of issue 2): at 11000 rpm the seed's Ca falls to
    22.0 N/µm at 1000 N (−72 % from T1), ours only by ≈ 6 %.  With a 10.3 mm Si₃N₄ ball
    (m ≈ 1.8 g) at ω_m ≈ 500 rad/s the centrifugal force is ≈ 16 N against a ball load ≈ 160 N,
    and the gyroscopic couple is < 1 N·D; a drop of 70 % cannot follow from these forces.
    Asserted: the relative drop is larger at low load than at high load, as in the seed (the
    axial load acts as preload, seed §3), and ours is smaller than the seed's at every load."""
    drop_ours = [1 - ours["jh"][(fa, 11000)] / ours["jh"][(fa, 0)] for fa in LOADS]
    drop_seed = [1 - seed[("T2", fa, 11000, "with_inertia")] / seed[("T1", fa, 0, "with_inertia")] for fa in LOADS]
    assert np.all(np.diff(drop_ours) < 0), "seed 000 section 3: axial load acts as preload against the speed effect"
    assert drop_seed[0] > drop_seed[-1], SRC_T2
    assert np.all(np.array(drop_ours) < np.array(drop_seed)), SRC_T2 + ": our speed effect is smaller (reported)"


@pytest.mark.parametrize("fa", LOADS)
def test_t3_palmgren_at_loaded_angle(seed, ours, fa):
    """Our Palmgren Ca (NSK form, at the loaded contact angle of the axial model) vs the seed's
    Palmgren column: deviations −3.7, −7.1, −4.5, −4.8, −0.8 % (all within 10 %)."""
    assert_allclose(ours["palmgren_loaded"][fa], seed[("T3", fa, 0, "palmgren")], rtol=0.10, err_msg=SRC_T3)


def test_t3_palmgren_needs_the_loaded_angle(seed, ours):
    """At the fixed free angle Palmgren gives Ca ∝ Fa^⅓ exactly (ratio 5^⅓ = 1.71 from 1000 to
    5000 N); the seed's Palmgren column rises by 2.15, so it was evaluated at the loaded angle."""
    r_free = ours["palmgren_free"][5000] / ours["palmgren_free"][1000]
    assert_allclose(r_free, 5 ** (1 / 3), rtol=1e-12, err_msg="Palmgren at constant alpha")
    r_seed = seed[("T3", 5000, 0, "palmgren")] / seed[("T3", 1000, 0, "palmgren")]
    r_loaded = ours["palmgren_loaded"][5000] / ours["palmgren_loaded"][1000]
    assert r_seed > 1.15 * r_free, SRC_T3 + ": the seed's Palmgren column grows faster than Fa^(1/3)"
    assert_allclose(r_loaded, r_seed, rtol=0.10, err_msg=SRC_T3 + " (growth 1000 -> 5000 N)")
