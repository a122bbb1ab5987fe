"""Heat generation of the jet-lubricated 35-mm-bore angular contact ball bearing of Parker (1984, NASA TP-2275):
Palmgren's model and the physics-based model against the measured heat, per point, without tuning.

Data (tests/data/parker1984_35mm_heat.csv, geometry tests/data/parker1984_35mm_bearing.toml): a SECONDARY
quotation (values digitised from the report's figures by a later paper, ±3 % stated); the report itself could
not be retrieved (docs/friction.md).  Operating point: 667 N thrust, MIL-L-23699 (our mil-prf-23699) at the
394 K inlet temperature, oil jet 760 cm³/min, outer ring held, 28 000 – 72 000 rpm.

Bands (docs/friction.md, validation table):
* Palmgren within a factor 2 of the measurement at every point: its f0 is tabulated to one digit and the
  table's own ranges span up to ×2.9 (grease 0.7–2); the data's ±5 % is small against that.  Measured:
  +37 … +64 %.  Its speed exponent (log–log slope 28k→72k rpm) within 0.2 of the measured 1.47 (the ±5 %
  band of the two end points alone allows ±0.11).
* Physics-based model: a LOWER bound — it leaves out cage friction, the churning and momentum of the jet oil
  and the temperature rise of the contacts — asserted as 0.25 < model/measured < 1.  Measured: 0.34 … 0.54,
  i.e. it misses by a factor 2–3; this is stated plainly in docs/friction.md.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import numpy as np
import pytest

from bearingsim.friction import friction_summary
from bearingsim.io import load_bearing
from bearingsim.statics.jones_harris import Loads, solve

DATA = Path(__file__).resolve().parents[1] / "data"
SOURCE = "Parker 1984 NASA TP-2275 35-mm-bore ACBB heat generation (secondary quotation, tests/data)"


def _rows():
    with open(DATA / "parker1984_35mm_heat.csv") as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


@pytest.fixture(scope="module")
def points():
    b = load_bearing(str(DATA / "parker1984_35mm_bearing.toml"))
    out = []
    for r in _rows():
        n = float(r["speed_rpm"])
        res = solve(b, Loads(fa=float(r["thrust_N"])), n * math.pi / 30.0, "outer")
        assert res.converged, res.status
        s = friction_summary(res, "mil-prf-23699", float(r["oil_inlet_K"]), lubrication_method="oil_jet",
                             oil_flow=float(r["oil_flow_cm3_min"]) * 1e-6 / 60.0)
        out.append((n, float(r["heat_generation_W"]), s))
    return out


def test_palmgren_against_parker(points):
    n = np.array([p[0] for p in points])
    meas = np.array([p[1] for p in points])
    model = np.array([p[2]["palmgren_power_W"] for p in points])
    ratio = model / meas
    table = ", ".join(f"{k:.0f} rpm: {m:.0f} W vs {x:.0f} W ({100 * (r - 1):+.0f} %)"
                      for k, m, x, r in zip(n, model, meas, ratio))
    assert np.all((ratio > 0.5) & (ratio < 2.0)), f"{SOURCE}: Palmgren outside ×2: {table}"
    slope_meas = math.log(meas[-1] / meas[0]) / math.log(n[-1] / n[0])
    slope_model = math.log(model[-1] / model[0]) / math.log(n[-1] / n[0])
    np.testing.assert_allclose(slope_model, slope_meas, atol=0.2,
                               err_msg=f"{SOURCE}: speed exponent of Palmgren's heat; {table}")


def test_physical_model_against_parker(points):
    meas = np.array([p[1] for p in points])
    model = np.array([p[2]["physical_power_W"] for p in points])
    ratio = model / meas
    table = ", ".join(f"{p[0]:.0f} rpm: {m:.0f} W vs {x:.0f} W (×{r:.2f}; rolling {p[2]['rolling_W']:.0f}, spin "
                      f"{p[2]['spin_W']:.0f}, sliding {p[2]['sliding_W']:.0f}, drag {p[2]['drag_W']:.0f} W)"
                      for p, m, x, r in zip(points, model, meas, ratio))
    assert np.all(ratio < 1.0), f"{SOURCE}: the physics-based model (no cage, no churning) should stay below: {table}"
    assert np.all(ratio > 0.25), f"{SOURCE}: the physics-based model misses by more than ×4: {table}"
    # every source is present and the drag uses Parker's oil fraction of the mixture
    for _, _, s in points:
        assert s["rolling_W"] > 0 and s["spin_W"] > 0 and s["drag_W"] > 0 and 0 < s["oil_volume_fraction"] < 0.01
