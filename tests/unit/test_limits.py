"""Plausibility limits (issue 11 item 5, solver parts): warnings on results and flags in maps.

Limits (bearingsim.limits, each with its source): 4.2 GPa static contact-pressure limit of ball bearings
(ISO 76:2006), contact angle past 80°, the bearing's limiting speed, ball lift-off at speed; a loaded
contact at 90° or more is not converged (status 6).
"""

from __future__ import annotations

import json
import math
import subprocess

import numpy as np
import pytest

from bearingsim import limits
from bearingsim.errors import InputError
from bearingsim.statics import jones_harris as jh
from bearingsim.sweep import map_grid


def test_limit_values_and_flag_bits_are_distinct_powers_of_two():
    assert limits.STATIC_PRESSURE_LIMIT == 4.2e9
    assert limits.CONTACT_ANGLE_LIMIT == pytest.approx(math.radians(80.0), rel=1e-15)
    bits = list(limits.FLAGS.values())
    assert len(set(bits)) == len(bits) and all(b > 0 and b & (b - 1) == 0 for b in bits)
    attrs = limits.cf_attributes()
    assert attrs["flag_masks"].tolist() == bits and attrs["flag_meanings"].split() == list(limits.FLAGS)


def test_huge_axial_load_on_the_7011_is_not_a_silent_converged(b7011):
    """--fa 1e9 returned "converged" with δx 25.8 mm and 84.7 GPa, without a word: now it carries the
    pressure and contact-angle warnings (JSON and result)."""
    r = jh.solve(b7011, jh.Loads(fa=1e9), 0.0)
    text = " ".join(r.warnings)
    assert "static limit 4.2 GPa" in text and "ISO 76" in text and "past 80°" in text
    assert r.to_dict()["warnings"] == r.warnings


def test_ordinary_operating_point_has_no_warning(b7011):
    r = jh.solve(b7011, jh.Loads(fa=3000.0), 11200 * math.pi / 30)
    assert r.converged and r.warnings == []


def test_pressure_warning_threshold(b7011):
    """Just below and just above the load that gives 4.2 GPa at the balls of a pure thrust (all balls equal:
    Q = (p / C_p)³, Fa ≈ Z Q sin α at the free angle; half and three times that load bracket the limit)."""
    cp = b7011.row_parameters()[17]
    q = (limits.STATIC_PRESSURE_LIMIT / cp) ** 3
    fa = 21 * q * math.sin(math.radians(15.0))
    lo = jh.solve(b7011, jh.Loads(fa=0.5 * fa), 0.0)
    hi = jh.solve(b7011, jh.Loads(fa=3.0 * fa), 0.0)
    p_lo = max(lo.balls["inner_max_pressure_Pa"].max(), lo.balls["outer_max_pressure_Pa"].max())
    p_hi = max(hi.balls["inner_max_pressure_Pa"].max(), hi.balls["outer_max_pressure_Pa"].max())
    assert p_lo < limits.STATIC_PRESSURE_LIMIT < p_hi
    assert not any("pressure" in w for w in lo.warnings) and any("pressure" in w for w in hi.warnings)


def test_partial_load_zone_is_not_lift_off_at_rest_or_at_speed(deep_groove):
    """Partial load zone of a deep-groove bearing under radial load: the same balls unloaded at rest and at speed,
    so no lift-off warning at either (lift-off: balls unloaded at speed beyond those unloaded at rest)."""
    rest = jh.solve(deep_groove, jh.Loads(fr_y=3000.0), 0.0)
    run = jh.solve(deep_groove, jh.Loads(fr_y=3000.0), 2000.0)
    assert rest.converged and run.converged
    assert np.any(~(run.balls["inner_load_N"] > 0))
    assert not any("lift" in w for w in rest.warnings + run.warnings)


def test_limiting_speed_warning_when_the_bearing_gives_one(b7011):
    import dataclasses

    class WithLimit:
        pass

    r = jh.solve(b7011, jh.Loads(fa=3000.0), 1500.0)
    fake = WithLimit()
    fake.__dict__.update({f.name: getattr(b7011, f.name) for f in dataclasses.fields(b7011)})
    fake.limiting_speed = 1000.0
    assert limits.limiting_speed(fake) == 1000.0 and limits.limiting_speed(b7011) == 0.0
    r.bearing = fake
    assert any("limiting speed" in w for w in limits.static_warnings(r))


def test_map_carries_warning_flags_with_cf_attributes(b7011, tmp_path):
    """solve_many and the map: an int bitmask per point, CF flag_masks/flag_meanings in the netCDF."""
    ds = map_grid(b7011, fa=[3000.0, 1e9], speed=[0.0, 1000.0], out=tmp_path / "m.nc")
    f = ds["warning_flags"].values
    assert f.dtype.kind == "i"
    assert np.all(f[0] == 0)
    assert np.all(f[1] & limits.FLAG_PRESSURE) and np.all(f[1] & limits.FLAG_CONTACT_ANGLE)
    assert ds["warning_flags"].attrs["flag_meanings"].split() == list(limits.FLAGS)
    assert list(ds["warning_flags"].attrs["flag_masks"]) == list(limits.FLAGS.values())
    m = jh.solve_many(b7011, np.array([[3000.0, 0, 0, 0, 0], [1e9, 0, 0, 0, 0], [-1000.0, 0, 0, 0, 0]]),
                      np.zeros(3))
    assert m.warning_flags[0] == 0 and m.warning_flags[1] & limits.FLAG_PRESSURE
    assert m.warning_flags[2] & limits.FLAG_NOT_EQUILIBRIUM and not m.converged[2]


def test_cli_static_prints_and_writes_the_warnings():
    """Installed console script: the 7011 under 1e9 N gives the warnings in the JSON and the text."""
    out = subprocess.run(["bearingsim", "static", "skf-7011-cdga-hc", "--fa", "1e9 N", "--json"],
                         capture_output=True, text=True, timeout=300)
    d = json.loads(out.stdout)
    assert any("4.2 GPa" in w for w in d["warnings"])
    txt = subprocess.run(["bearingsim", "static", "skf-7011-cdga-hc", "--fa", "1e9 N"], capture_output=True,
                         text=True, timeout=300)
    assert "warning:" in txt.stdout and "4.2 GPa" in txt.stdout


def test_limiting_speed_from_the_bearing_file_warns_in_rows_and_sets(tmp_path):
    """`limiting_speed` in a bearing file (a unit required) feeds the speed warning, also through a DB set."""
    from bearingsim.io import load_bearing
    from bearingsim.statics import jones_harris as jh

    row = tmp_path / "row.toml"
    row.write_text('name = "r"\ntype = "angular_contact"\nball_diameter = "10.319 mm"\nball_count = 21\n'
                   'pitch_diameter = "72.5 mm"\ninner_conformity = 0.52\nouter_conformity = 0.53\n'
                   'contact_angle = "15 deg"\nball_material = "bearing_steel"\nring_material = "bearing_steel"\n'
                   'limiting_speed = "8000 rpm"\n', encoding="utf-8")
    b = load_bearing(row)
    assert b.limiting_speed == pytest.approx(8000 * math.pi / 30, rel=1e-12)
    fast = jh.solve(b, jh.Loads(fa=2000.0), 9000 * math.pi / 30)
    slow = jh.solve(b, jh.Loads(fa=2000.0), 7000 * math.pi / 30)
    assert fast.converged and any("limiting speed" in w for w in fast.warnings), fast.warnings
    assert not any("limiting speed" in w for w in slow.warnings)
    pair = tmp_path / "pair.toml"
    pair.write_text(f'name = "p"\ntype = "bearing_set"\narrangement = "DB"\nrow = "{row.as_posix()}"\n'
                    'row_spacing = "18 mm"\npreload = "500 N"\n', encoding="utf-8")
    res = jh.solve(load_bearing(pair), jh.Loads(fa=500.0), 9000 * math.pi / 30)
    assert any("limiting speed" in w for w in res.warnings), res.warnings
    bare = row.read_text(encoding="utf-8").replace('"8000 rpm"', "8000")
    row.write_text(bare, encoding="utf-8")
    with pytest.raises(InputError, match="limiting_speed"):
        load_bearing(row)
