"""The package's front door: ``import bearingsim`` gives the public API lazily, and the documented module paths
of earlier releases keep working (users' scripts must not break)."""

import subprocess
import sys

import numpy as np

import bearingsim


def test_every_public_name_resolves_to_the_documented_object():
    from bearingsim.dynamics.run import simulate
    from bearingsim.io import load_bearing
    from bearingsim.statics.axial import solve_thrust
    from bearingsim.statics.jones_harris import Loads, solve, solve_many
    from bearingsim.sweep import map_grid

    for name in bearingsim.__all__:
        assert getattr(bearingsim, name) is not None, name
    assert (bearingsim.load_bearing, bearingsim.Loads, bearingsim.solve, bearingsim.solve_many,
            bearingsim.solve_thrust, bearingsim.map_grid, bearingsim.simulate) == (
        load_bearing, Loads, solve, solve_many, solve_thrust, map_grid, simulate)
    assert "solve" in dir(bearingsim)


def test_old_import_paths_keep_working():
    from bearingsim.dynamics.case import load_case  # noqa: F401 - the path the README documented
    from bearingsim.lubricants import get_lubricant

    assert get_lubricant("iso-vg-68").name


def test_front_door_solves_like_the_module_path():
    b = bearingsim.load_bearing("skf-7011-cdga-hc")
    r = bearingsim.solve(b, bearingsim.Loads(fa=3000.0), 1172.9)
    from bearingsim.statics import jones_harris as jh

    r2 = jh.solve(b, jh.Loads(fa=3000.0), 1172.9)
    assert r.converged and np.array_equal(r.displacement, r2.displacement)


def test_import_is_light_and_unknown_names_raise_attribute_error():
    code = ("import sys, bearingsim; bearingsim.__version__; "
            "assert not {'numpy', 'numba', 'xarray', 'dask'} & set(sys.modules), sorted(sys.modules)\n"
            "try:\n    bearingsim.no_such_name\nexcept AttributeError:\n    pass\nelse:\n    raise SystemExit(3)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
