"""Shared fixtures of the bearingsim test suite (fixtures only, no tests).

Bearings are built once per session: the catalogue entries of issue 2 and a deep-groove
bearing with clearance written to a temporary TOML file.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import pytest
from hypothesis import settings

# the dynamic engine can run its ball contacts on threads (issue 14): tests use one thread whatever the default
# (set before numba is imported — the fixtures import bearingsim lazily; inherited by the CLI subprocesses).
# tests/unit/test_dyn_threads.py runs its two-thread checks in a subprocess of its own.
os.environ.setdefault("NUMBA_NUM_THREADS", "1")

# deterministic property tests in CI (same examples every run)
settings.register_profile("bearingsim", derandomize=True)
settings.load_profile("bearingsim")

DATA = Path(__file__).parent / "data"

RPM = math.pi / 30.0  #: rad/s per rpm, written out by hand (2π/60)


@pytest.fixture(scope="session")
def b7011():
    """SKF 7011 CDGA/HC hybrid spindle bearing of seed 000 (catalogue, ball set estimated)."""
    from bearingsim.io import load_bearing

    return load_bearing("skf-7011-cdga-hc")


@pytest.fixture(scope="session")
def b218():
    """Harris & Kotzalas' 218 angular contact bearing (catalogue)."""
    from bearingsim.io import load_bearing

    return load_bearing("harris-218")


@pytest.fixture(scope="session")
def bhub():
    """One row of the seed 001 hub bearing (catalogue)."""
    from bearingsim.io import load_bearing

    return load_bearing("hub-seed001-row")


DEEP_GROOVE_TOML = """\
name = "test deep groove, 6209-like"
type = "deep_groove"
ball_diameter = "12.7 mm"
ball_count = 9
pitch_diameter = "65 mm"
inner_conformity = 0.52
outer_conformity = 0.52
diametral_clearance = "0.015 mm"
ball_material = "bearing_steel"
ring_material = "bearing_steel"
"""


@pytest.fixture(scope="session")
def deep_groove_toml(tmp_path_factory) -> Path:
    """Path of a deep-groove bearing TOML with 15 µm diametral clearance."""
    p = tmp_path_factory.mktemp("bearings") / "deep_groove.toml"
    p.write_text(DEEP_GROOVE_TOML, encoding="utf-8")
    return p


@pytest.fixture(scope="session")
def deep_groove(deep_groove_toml):
    """The deep-groove bearing of :func:`deep_groove_toml`, loaded through bearingsim.io."""
    from bearingsim.io import load_bearing

    return load_bearing(deep_groove_toml)


@pytest.fixture(scope="session")
def benchmark_module():
    """Factory: import a script of benchmarks/ by its name (e.g. "bench_dynamics") as a module."""
    import importlib.util

    def _load(name: str):
        path = Path(__file__).resolve().parents[1] / "benchmarks" / f"{name}.py"
        spec = importlib.util.spec_from_file_location(name, path)
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        return mod

    return _load


@pytest.fixture
def write_toml(tmp_path):
    """Factory: write a TOML text to a fresh file in tmp_path and return its path."""

    def _write(text: str, name: str = "bearing.toml") -> Path:
        p = tmp_path / name
        p.write_text(text, encoding="utf-8")
        return p

    return _write


@pytest.fixture(scope="session")
def hub():
    """The double-row hub unit of Sakaguchi & Shibutani [S1] (catalogue)."""
    from bearingsim.io import load_bearing

    return load_bearing("hub-seed001")


@pytest.fixture(scope="session")
def hub_study(hub):
    """The hub unit's quasi-static tilt–moment study at 13 moments, −600 … 600 N·m (studies/hub_static.py)."""
    import numpy as np

    from bearingsim.studies import hub_static as hs

    return hs.run_study(hub, np.linspace(-600, 600, 13))
