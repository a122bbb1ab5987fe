"""The one netCDF writer (bearingsim.io.netcdf) and the one spelling of units in output files.

Mechanism tests: every ``units`` attribute of a map file and of a dynamic-run file parses with pint (it used
to hold ``m | rad``, ``m or rad`` and ``N*m`` next to ``N m``); a variable mixing quantities carries the unit of
each component, and those units are the physics of the variable (K[i, j] q_j has the unit of F_i); the
in-memory Datasets carry the same attributes as the files; the writer publishes atomically, with the user's
umask, and leaves nothing behind on failure.
"""

from __future__ import annotations

import dataclasses
import errno
import os
from pathlib import Path

import netCDF4
import numpy as np
import pint
import pytest

from bearingsim import sweep
from bearingsim.dynamics.case import load_case
from bearingsim.dynamics.run import simulate
from bearingsim.io import netcdf as nc

ROOT = Path(__file__).resolve().parents[2]
UREG = pint.UnitRegistry()


@pytest.fixture(scope="module")
def map_file(tmp_path_factory):
    out = tmp_path_factory.mktemp("map") / "m.nc"
    mem = sweep.map_grid("skf-7011-cdga-hc", fa="1000:3000:3", fr="0:500:2", workers=1)
    sweep.map_grid("skf-7011-cdga-hc", fa="1000:3000:3", fr="0:500:2", workers=1, out=out).close()
    return out, mem


@pytest.fixture(scope="module")
def run_file(tmp_path_factory):
    out = tmp_path_factory.mktemp("run") / "r.nc"
    c = load_case(ROOT / "examples" / "spindle-7011.toml")
    c = dataclasses.replace(c, duration=2 * c.output_interval, integrator="dopri5")
    res = simulate(c, out=out)
    mem = simulate(c)
    return out, res, mem


def _units_of(path: Path) -> dict:
    with netCDF4.Dataset(path) as ds:
        return {k: {a: v.getncattr(a) for a in v.ncattrs() if a.startswith("units")} for k, v in ds.variables.items()}


@pytest.mark.parametrize("which", ["map", "run"])
def test_every_units_attribute_parses_with_pint(which, map_file, run_file):
    path = map_file[0] if which == "map" else run_file[0]
    units = _units_of(path)
    n = 0
    for name, attrs in units.items():
        if "units" in attrs:
            UREG.parse_units(attrs["units"])  # raises on "m or rad"
            assert "|" not in attrs["units"], name  # pint reads "m | rad" as m·rad: a wrong unit, no error
            n += 1
        if "units_by_component" in attrs:
            assert attrs["units"] == nc.MIXED_UNITS, name
            for u in attrs["units_by_component"].split(", "):
                UREG.parse_units(u)
    assert n >= (13 if which == "map" else 30)
    assert not any("*" in a.get("units", "") for a in units.values())  # one spelling: "N m", not "N*m"


def test_mixed_variables_carry_the_unit_of_each_component(map_file, run_file):
    with netCDF4.Dataset(map_file[0]) as ds:
        q = nc.component_units({a: ds["displacement"].getncattr(a) for a in ds["displacement"].ncattrs()})
        k = nc.component_units({a: ds["stiffness"].getncattr(a) for a in ds["stiffness"].ncattrs()}, (5, 5))
    assert q == ["m", "m", "m", "rad", "rad"]
    force = ["N", "N", "N", "N m", "N m"]
    for i in range(5):
        for j in range(5):  # K[i, j] dq_j is a change of F_i
            assert (UREG.parse_units(k[i][j]) * UREG.parse_units(q[j])).dimensionality == \
                UREG.parse_units(force[i]).dimensionality, (i, j, k[i][j])
    assert k[0][3] == "N/rad" and k[3][0] == "N m/m"  # rows: loads, columns: displacements (K dq = dF)
    with netCDF4.Dataset(run_file[0]) as ds:
        assert ds["applied_load"].units_by_component == "N, N, N, N m, N m"
        assert ds["inner_ring_velocity"].units_by_component == "m/s, m/s, m/s, rad/s, rad/s"
        assert ds["inner_ring_friction_torque"].units == "N m"


def _plain(attrs) -> dict:
    return {k: np.asarray(v).tolist() for k, v in attrs.items() if not k.startswith("_")}


def test_memory_datasets_have_the_attributes_of_the_files(map_file, run_file):
    import xarray as xr

    for path, mem in ((map_file[0], map_file[1]), (run_file[0], run_file[2].to_xarray())):
        with xr.open_dataset(path) as f:
            for name in mem.variables:
                if name in f.variables:
                    assert _plain(mem[name].attrs) == _plain(f[name].attrs), name


def test_memory_and_file_results_are_the_same_values(map_file, run_file):
    import xarray as xr

    with xr.open_dataset(map_file[0]) as f:
        for name in map_file[1].data_vars:
            np.testing.assert_array_equal(f[name].values, map_file[1][name].values, err_msg=name)
    ds = run_file[2].to_xarray()
    with xr.open_dataset(run_file[0]) as f:
        for name in ds.data_vars:
            np.testing.assert_array_equal(f[name].values, ds[name].values, err_msg=name)


def _schema():
    return dict(dims={"time": None, "x": 2}, variables=[nc.Variable("time", ("time",), "s"),
                                                         nc.Variable("x", ("x",), "m", dtype="f8"),
                                                         nc.Variable("v", ("time", "x"), ("m", "rad"))],
                values={"x": np.array([1.0, 2.0])}, attrs={"title": "t"})


@pytest.mark.parametrize("publish", ["close", "create"])
def test_writer_publishes_atomically_with_the_users_umask(publish, tmp_path):
    final = tmp_path / "f.nc"
    old = os.umask(0o027)
    try:
        w = nc.NetCDFWriter(final, **_schema(), fmt="NETCDF3_64BIT_OFFSET", publish=publish)
    finally:
        os.umask(old)
    assert final.exists() == (publish == "create")
    w.write("v", slice(0, 2), np.arange(4.0).reshape(2, 2))
    w.write("time", slice(0, 2), [0.0, 1.0])
    w.sync()
    w.close()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.nc"]
    assert final.stat().st_mode & 0o777 == 0o640
    with netCDF4.Dataset(final) as ds:
        assert ds["v"].units == "1" and ds["v"].units_by_component == "m, rad" and ds.title == "t"
        np.testing.assert_array_equal(ds["v"][:], np.arange(4.0).reshape(2, 2))
    # appended records: reopen and continue
    w = nc.NetCDFWriter.reopen(final)
    assert w.length("time") == 2
    w.write("time", slice(2, 3), [2.0])
    w.close()
    with netCDF4.Dataset(final) as ds:
        assert len(ds.dimensions["time"]) == 3


def test_writer_failure_leaves_nothing_and_names_the_final_file(tmp_path, monkeypatch):
    final = tmp_path / "f.nc"
    w = nc.NetCDFWriter(final, **_schema())
    w.abort()
    assert list(tmp_path.iterdir()) == []
    # a failing definition (here: a bad dimension) removes the temporary file; the error names the final path
    with pytest.raises(Exception):
        nc.NetCDFWriter(final, dims={"x": 2}, variables=[nc.Variable("v", ("nope",), "m")])
    assert list(tmp_path.iterdir()) == []
    real = netCDF4.Dataset

    def full_disk(*a, **k):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(netCDF4, "Dataset", full_disk)
    with pytest.raises(OSError) as exc:
        nc.NetCDFWriter(final, **_schema(), publish="create")
    assert exc.value.filename == str(final) and exc.value.errno == errno.ENOSPC
    monkeypatch.setattr(netCDF4, "Dataset", real)
    assert list(tmp_path.iterdir()) == []


def test_stale_part_of_a_dead_process_is_removed(tmp_path):
    final = tmp_path / "f.nc"
    part = nc.create_part(final)
    dead = part.with_name(part.name.replace(f"-{os.getpid()}-", "-999999999-"))
    part.rename(dead)
    nc.NetCDFWriter(final, **_schema()).close()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["f.nc"]


def test_units_attributes():
    assert nc.units_attributes("N m") == {"units": "N m"}
    assert nc.units_attributes(None) == {}
    assert nc.units_attributes(("m", "m")) == {"units": "m"}
    assert nc.units_attributes((("N/m", "N/rad"), ("N m/m", "N m/rad"))) == \
        {"units": "1", "units_by_component": "N/m, N/rad, N m/m, N m/rad"}
