"""Start-up: a light front door, lazy imports, the first-run compilation note and the numba cache fallback
(issue 11 item 9; the figures are in benchmarks/bench_startup.py, not here: wall times depend on the machine).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest

SCRIPT = shutil.which("bearingsim")
HEAVY = ("numpy", "numba", "scipy", "xarray", "dask", "matplotlib", "netCDF4", "distributed", "pint", "pandas")


def imported_by(code: str) -> set[str]:
    """Top-level packages among HEAVY that running ``code`` in a fresh interpreter imports."""
    probe = f"{code}\nimport sys\nprint(' '.join(m for m in {HEAVY!r} if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True).stdout
    return set(out.split())


def script_imports(*args) -> tuple[set[str], subprocess.CompletedProcess]:
    """Top-level packages the installed script imports for ``args`` (PYTHONPROFILEIMPORTTIME lists them)."""
    env = dict(os.environ, PYTHONPROFILEIMPORTTIME="1")
    p = subprocess.run([SCRIPT, *args], capture_output=True, text=True, env=env, timeout=300)
    mods = set()
    for ln in p.stderr.splitlines():
        if ln.startswith("import time:") and ln.count("|") == 2:
            mods.add(ln.rsplit("|", 1)[1].strip().split(".")[0])
    return mods, p


def test_front_door_is_import_light():
    assert imported_by("import bearingsim; bearingsim.__version__") == set()


def test_cli_module_is_import_light():
    """Every command pays the import of bearingsim.cli: the numerical libraries load in the commands."""
    assert imported_by("import bearingsim.cli") == set()


@pytest.mark.parametrize("args", [("--version",), ("static", "--help"), ("statc",)])
def test_version_help_and_usage_errors_load_no_numerics(args):
    mods, p = script_imports(*args)
    assert p.returncode in (0, 2)
    assert mods & set(HEAVY) == set(), mods & set(HEAVY)


def test_static_json_loads_no_io_or_plotting_libraries():
    """`static --json` needs numpy, numba and the unit parser, not xarray/netCDF/Dask's distributed/matplotlib/rich."""
    mods, p = script_imports("static", "skf-7011-cdga-hc", "--fa", "3000", "--json")
    assert p.returncode == 0, p.stderr[-2000:]
    assert {"numpy", "numba"} <= mods  # the probe sees the imports it should
    assert mods & {"xarray", "netCDF4", "distributed", "matplotlib", "rich", "pandas", "pint", "dask"} == set()


def test_fast_units_equal_pint():
    """The units converted without pint (units._FAST_UNITS) give bitwise pint's value, or pint's error."""
    import math
    import random

    from bearingsim import units
    from bearingsim.errors import InputError

    rng = random.Random(11)
    numbers = [0.0, -0.0, 1.0, -1.0, 1e-300, 5e-324, 1e300, -1e308, 1.7976931348623157e308, 11.1, 72.5, 0.52, 35.0,
               11200.0, 273.15, -273.15, 3000.0]
    numbers += [rng.uniform(-1e4, 1e4) for _ in range(300)] + [rng.uniform(0, 100) / 7 for _ in range(300)]
    numbers += [float(rng.randint(0, 50_000)) for _ in range(300)] + [10.0 ** rng.uniform(-12, 12) for _ in range(300)]

    def outcome(fn):
        try:
            return fn()
        except InputError:
            return "InputError"

    for dimension, table in units._FAST_UNITS.items():
        for unit in table:
            for x in numbers:
                text = f"{x!r} {unit}"
                fast = outcome(lambda: units.parse_quantity(text, dimension, "t"))
                ref = outcome(lambda: units._to_si(x, units._parse_unit(unit, text, "t", ""), text, dimension, "t"))
                assert fast == ref and math.copysign(1, fast if fast != "InputError" else 1) == math.copysign(
                    1, ref if ref != "InputError" else 1), (text, dimension, fast, ref)
    # bare numbers in the command line's default units (rpm, deg, degC) take the same path
    for dimension in ("speed", "angle", "temperature"):
        default = units.DIMENSIONS[dimension][2]
        for x in numbers[:40]:
            ref = outcome(lambda: units._to_si(x, units.registry().Unit(default), f"{x!r} {default}", dimension, "t"))
            assert outcome(lambda: units.parse_quantity(x, dimension, "t")) == ref, (x, dimension)


# ---- first-run compilation note ----------------------------------------------------------------------------
COMPILE_SMALL = ("from bearingsim.cli.console import announce_compilation, finish_compilation_note\n"
                 "announce_compilation()\n"
                 "import bearingsim.contact.hertz as h\n"
                 "h.elliptic_ke(0.5)\n"
                 "finish_compilation_note()\n")


def run_py(code: str, env: dict) -> subprocess.CompletedProcess:
    e = dict(os.environ)
    e.update(env)
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=e, timeout=300)


def test_compilation_note_on_a_cache_miss_only(tmp_path):
    env = {"NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    cold = run_py(COMPILE_SMALL, env)
    assert cold.returncode == 0, cold.stderr
    err = cold.stderr.splitlines()
    assert err[0].startswith("compiling numerical kernels (first run only")
    assert err[-1].startswith("compiled 1 kernels in") and err[-1].endswith("(cached for the next runs)")
    warm = run_py(COMPILE_SMALL, env)
    assert warm.returncode == 0 and warm.stderr == ""  # loaded from the cache: nothing to say


def test_compilation_note_counts_uncached_kernels_apart():
    """A kernel without cache=True compiles on every run: the note does not promise a first run only."""
    code = ("from bearingsim.cli.console import announce_compilation, finish_compilation_note\n"
            "announce_compilation()\n"
            "from numba import njit\n"
            "def f(x):\n    return x + 1\n"
            "f.__module__ = 'bearingsim.probe'\n"
            "njit(f)(1)\n"
            "def g(x):\n    return x - 1\n"  # not a bearingsim kernel: not counted
            "njit(g)(1)\n"
            "finish_compilation_note()\n")
    p = run_py(code, {})
    assert p.returncode == 0, p.stderr
    lines = p.stderr.splitlines()
    assert len(lines) == 2 and lines[0] == "compiling numerical kernels…", p.stderr
    assert lines[1].startswith("compiled 1 kernels in ") and lines[1].endswith(
        "(1 of them without a disk cache, compiled on every run)")


# ---- numba cache folder fallback ---------------------------------------------------------------------------
def fake_package(root: Path, writable: bool) -> Path:
    """A package folder with the kernel sub-packages; unwritable = their __pycache__ is a regular file (root
    can write in a 0555 folder, but not below a file)."""
    pkg = root / "pkg"
    for sub in ("contact", "statics", "dynamics"):
        (pkg / sub).mkdir(parents=True)
        if not writable:
            (pkg / sub / "__pycache__").write_text("not a folder")
    return pkg


def test_cache_choice(tmp_path, monkeypatch):
    from bearingsim import _choose_numba_cache_dir

    afile = tmp_path / "afile"
    afile.write_text("x")
    xdg = tmp_path / "xdg"
    ok_pkg, ro_pkg = fake_package(tmp_path / "a", True), fake_package(tmp_path / "b", False)

    # a writable NUMBA_CACHE_DIR, or a writable package folder: numba's own choice stands, nothing said
    assert _choose_numba_cache_dir({"NUMBA_CACHE_DIR": str(tmp_path / "given")}, str(ro_pkg)) == (None, None)
    assert _choose_numba_cache_dir({"XDG_CACHE_HOME": str(afile)}, str(ok_pkg)) == (None, None)
    # read-only package, writable user cache: numba's user-wide cache (<XDG>/numba) works by itself
    assert _choose_numba_cache_dir({"XDG_CACHE_HOME": str(xdg)}, str(ro_pkg)) == (None, None)
    # NUMBA_CACHE_DIR unusable: bearingsim's user cache folder, with a note naming the variable
    d, note = _choose_numba_cache_dir({"NUMBA_CACHE_DIR": str(afile / "numba"), "XDG_CACHE_HOME": str(xdg)},
                                      str(ok_pkg))
    assert d == str(xdg / "bearingsim" / "numba") and Path(d).is_dir()
    assert "NUMBA_CACHE_DIR" in note and d in note
    # read-only package and no writable HOME/XDG cache: a per-user temporary folder, said once when created
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path / "tmp"))
    (tmp_path / "tmp").mkdir()
    env = {"XDG_CACHE_HOME": str(afile / "cache"), "HOME": str(afile / "home")}
    d, note = _choose_numba_cache_dir(env, str(ro_pkg))
    assert Path(d).parent == tmp_path / "tmp" and Path(d).name.startswith("bearingsim-numba-")
    assert "package folder is not writable" in note and d in note
    assert _choose_numba_cache_dir(env, str(ro_pkg)) == (d, None)
    # ... but never a folder someone else can write in (numba loads compiled code from it): a fresh private one
    os.chmod(d, 0o777)
    d2, note2 = _choose_numba_cache_dir(env, str(ro_pkg))
    assert d2 != d and Path(d2).parent == tmp_path / "tmp" and "for this run only" in note2
    assert os.stat(d2).st_mode & 0o077 == 0


def test_unwritable_numba_cache_dir_falls_back_with_one_line(tmp_path):
    """An unusable NUMBA_CACHE_DIR: one note, the command still answers, the kernels are cached in the
    fallback (they were before in-tree: numba skips the variable silently, and fails when nothing else works)."""
    afile = tmp_path / "afile"
    afile.write_text("x")
    env = {"NUMBA_CACHE_DIR": str(afile / "numba"), "XDG_CACHE_HOME": str(tmp_path / "xdg")}
    fallback = tmp_path / "xdg" / "bearingsim" / "numba"
    p = subprocess.run([SCRIPT, "static", "no-such-bearing"], capture_output=True, text=True,
                       env={**os.environ, **env}, timeout=300)
    err = p.stderr.splitlines()
    assert p.returncode == 2 and len(err) == 2, p.stderr
    assert err[0] == f"note: NUMBA_CACHE_DIR={afile / 'numba'} is not writable; compiled kernels are cached in " \
                     f"{fallback}"
    assert err[1].startswith("error: ") and "no-such-bearing" in err[1]
    c = run_py(COMPILE_SMALL, env)
    assert c.returncode == 0 and "cannot cache" not in c.stderr, c.stderr
    assert list(fallback.rglob("hertz.elliptic_ke-*.nbi")), sorted(fallback.rglob("*"))


def test_stale_kernel_caches_are_dropped_once_when_a_kernel_module_changes(tmp_path):
    """numba checks a cached kernel against its own file only, so a kernel calling into an edited module is served
    stale (a segmentation fault in forces.evaluate was seen after such an edit): the in-tree caches of the kernel
    packages go when any of their modules changes, and only then."""
    import os

    from bearingsim import _drop_stale_kernel_caches

    pkg = tmp_path / "bearingsim"
    for sub in ("contact", "statics", "dynamics"):
        (pkg / sub / "__pycache__").mkdir(parents=True)
        (pkg / sub / "m.py").write_text("x = 1\n")
    caches = [pkg / "dynamics" / "__pycache__" / "m.f-1.py311.nbi", pkg / "contact" / "__pycache__" / "m.g-3.py311.nbc"]
    keep = pkg / "dynamics" / "__pycache__" / "m.cpython-311.pyc"

    def fill():
        for f in caches + [keep]:
            f.write_bytes(b"x")

    fill()
    assert _drop_stale_kernel_caches(str(pkg)) == 2  # no stamp yet: whatever is there is of unknown sources
    assert not any(f.exists() for f in caches) and keep.exists()
    fill()
    assert _drop_stale_kernel_caches(str(pkg)) == 0  # unchanged sources: the caches stay
    assert all(f.exists() for f in caches)
    st = os.stat(pkg / "statics" / "m.py")
    os.utime(pkg / "statics" / "m.py", ns=(st.st_atime_ns, st.st_mtime_ns + 10**9))  # an edit of one module
    assert _drop_stale_kernel_caches(str(pkg)) == 2
    assert not any(f.exists() for f in caches) and keep.exists()
    (pkg / "contact" / "new.py").write_text("y = 2\n")  # a new module counts too
    fill()
    assert _drop_stale_kernel_caches(str(pkg)) == 2
