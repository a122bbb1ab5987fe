"""bearingsim: ball-bearing mechanics — Hertz contact, Jones–Harris quasi-static equilibrium, stiffness,
lubrication and multibody dynamics.

The front door is kept import-light: ``import bearingsim`` loads no numerical library (numpy, numba, xarray,
dask); the submodules load them when they are used.  Two things happen here, before any kernel module is
imported:

* ``bearingsim.__version__`` — the installed distribution's version (single source: ``pyproject.toml``, read
  through :mod:`importlib.metadata`; from a source tree that is not installed, read from ``pyproject.toml``).
* the numba cache folder — the compiled kernels are cached on disk (``cache=True``).  numba looks for a
  writable folder in this order: ``NUMBA_CACHE_DIR``, ``__pycache__`` next to the modules, the user cache
  (``$XDG_CACHE_HOME/numba`` or ``~/.cache/numba``); when none is writable (a read-only install with a
  read-only HOME) every kernel import fails with "cannot cache function".  :func:`_configure_numba_cache`
  checks this chain first and, when needed, points ``NUMBA_CACHE_DIR`` at
  ``$XDG_CACHE_HOME/bearingsim/numba`` (or ``~/.cache/bearingsim/numba``) or at a per-user temporary folder,
  with one line on stderr.
"""

from __future__ import annotations

import os
import sys

#: The public API, loaded on first use (PEP 562) so that ``import bearingsim`` stays numerics-free:
#: ``bearingsim.solve(...)`` imports :mod:`bearingsim.statics.jones_harris` the first time it is touched.
#: name -> (module, attribute); the documented module paths keep working as well.
_PUBLIC = {
    # bearings and files
    "load_bearing": ("bearingsim.io", "load_bearing"),
    "BallBearing": ("bearingsim.geometry", "BallBearing"),
    "catalog_names": ("bearingsim.io", "catalog_names"),
    # quasi-static equilibrium
    "Loads": ("bearingsim.statics.jones_harris", "Loads"),
    "solve": ("bearingsim.statics.jones_harris", "solve"),
    "solve_many": ("bearingsim.statics.jones_harris", "solve_many"),
    "StaticResult": ("bearingsim.statics.jones_harris", "StaticResult"),
    "solve_thrust": ("bearingsim.statics.axial", "solve_thrust"),
    # lives, safety, friction, elastic rings, report
    "rating_summary": ("bearingsim.life", "rating_summary"),
    "friction_summary": ("bearingsim.friction", "friction_summary"),
    "solve_elastic_rings": ("bearingsim.rings.coupling", "solve"),
    "bearing_report": ("bearingsim.report.bearing", "bearing_report"),
    # sweeps
    "map_grid": ("bearingsim.sweep", "map_grid"),
    # lubrication
    "get_lubricant": ("bearingsim.io", "get_lubricant"),
    # dynamics
    "load_case": ("bearingsim.io", "load_case"),
    "simulate": ("bearingsim.dynamics.run", "simulate"),
    "hysteresis_estimate": ("bearingsim.dynamics.analysis", "hysteresis_estimate"),
    "reduced_wh": ("bearingsim.studies.hub_reduced", "reduced_wh"),
    # shaft systems
    "ShaftSystem": ("bearingsim.shafts.model", "ShaftSystem"),
    "Section": ("bearingsim.shafts.model", "Section"),
    "BearingSupport": ("bearingsim.shafts.model", "BearingSupport"),
    "SpringSupport": ("bearingsim.shafts.model", "SpringSupport"),
    "PointLoad": ("bearingsim.shafts.model", "PointLoad"),
    "DistributedLoad": ("bearingsim.shafts.model", "DistributedLoad"),
    "Gravity": ("bearingsim.shafts.model", "Gravity"),
    "HelicalGear": ("bearingsim.shafts.model", "HelicalGear"),
    "PointMass": ("bearingsim.shafts.model", "PointMass"),
    "solve_shaft": ("bearingsim.shafts.solve", "solve_shaft"),
    "shaft_modes": ("bearingsim.shafts.modes", "modes"),
    "campbell": ("bearingsim.shafts.modes", "campbell"),
    "shaft_sweep": ("bearingsim.shafts.sweep", "shaft_sweep"),
    "shaft_to_ross": ("bearingsim.shafts.ross", "to_ross"),
    "bearing_reaction": ("bearingsim.statics.jones_harris", "bearing_reaction"),
    # errors
    "BearingSimError": ("bearingsim.errors", "BearingSimError"),
    "InputError": ("bearingsim.errors", "InputError"),
    "ConvergenceError": ("bearingsim.errors", "ConvergenceError"),
}

__all__ = ["__version__", *_PUBLIC]

_DIST = "bearingsim"


def _read_version() -> str:
    """Version of the installed distribution (pyproject's ``[project] version``), or of the source tree."""
    try:
        from importlib.metadata import PackageNotFoundError, version
    except ImportError:  # pragma: no cover - Python >= 3.8 always has it
        PackageNotFoundError, version = Exception, None
    if version is not None:
        try:
            return version(_DIST)
        except PackageNotFoundError:
            pass
    # not installed (e.g. PYTHONPATH=src): the source tree's pyproject.toml
    pyproject = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir, "pyproject.toml")
    try:
        import tomllib

        with open(pyproject, "rb") as fh:
            return str(tomllib.load(fh)["project"]["version"])
    except (OSError, KeyError, ValueError):
        return "0+unknown"


def __dir__():
    return sorted(set(globals()) | set(__all__))


def __getattr__(name: str):
    # PEP 562: the version and the public API are loaded on first use (importlib.metadata costs a few ms that most
    # imports do not need)
    if name == "__version__":
        v = _read_version()
        globals()["__version__"] = v
        return v
    if name in _PUBLIC:
        import importlib

        module, attr = _PUBLIC[name]
        value = getattr(importlib.import_module(module), attr)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


# ---- numba cache folder ------------------------------------------------------------------------------------
#: sub-packages whose modules hold ``cache=True`` kernels (their ``__pycache__`` is numba's in-tree cache)
_KERNEL_PACKAGES = ("contact", "statics", "dynamics")


def _writable_folder(path: str, create: bool) -> bool:
    """True when a file can be created in ``path`` (made first when ``create``).  A real probe, as numba does
    (``os.access`` says yes to root on read-only mounts such as /sys and on folders with mode 0555)."""
    import tempfile

    try:
        if create:
            os.makedirs(path, exist_ok=True)
        elif not os.path.isdir(path):
            return False
        tempfile.TemporaryFile(dir=path).close()
        return True
    except OSError:
        return False


def _in_tree_writable(package_dir: str) -> bool:
    """numba's in-tree locator: ``__pycache__`` next to each kernel module (created when missing, as numba does)."""
    return all(_writable_folder(os.path.join(package_dir, sub, "__pycache__"), create=True)
               for sub in _KERNEL_PACKAGES if os.path.isdir(os.path.join(package_dir, sub)))


def _user_cache_root(environ) -> str:
    """``$XDG_CACHE_HOME`` or ``~/.cache`` (the XDG base-directory rule numba's own user-wide cache follows)."""
    xdg = environ.get("XDG_CACHE_HOME")
    if xdg and os.path.isabs(xdg):
        return xdg
    home = environ.get("HOME") or os.path.expanduser("~")
    return os.path.join(home, ".cache")


def _choose_numba_cache_dir(environ, package_dir: str) -> tuple[str | None, str | None]:
    """Decide where numba caches the kernels.

    Returns ``(cache_dir, note)``: ``cache_dir`` is the folder to put in ``NUMBA_CACHE_DIR`` (None: leave
    numba's own choice alone) and ``note`` the one line for stderr (None: nothing to say).  Order: a writable
    ``NUMBA_CACHE_DIR``; numba's in-tree ``__pycache__``; numba's user cache ``<cache root>/numba``; then
    ``<cache root>/bearingsim/numba``; then ``<tmp>/bearingsim-numba-<uid>`` (only if it is this user's and
    nobody else can write in it); then a fresh private temporary folder for this process.
    """
    import tempfile

    given = environ.get("NUMBA_CACHE_DIR", "")
    if given and _writable_folder(given, create=True):
        return None, None
    root = _user_cache_root(environ)
    if given:
        why = f"NUMBA_CACHE_DIR={given} is not writable"
    else:
        why = "the package folder is not writable"
        if _in_tree_writable(package_dir):
            return None, None
        # numba itself falls back to <cache root>/numba when it can create it
        if _writable_folder(os.path.join(root, "numba"), create=True):
            return None, None
    uid = os.getuid() if hasattr(os, "getuid") else None
    shared_tmp = os.path.join(tempfile.gettempdir(), f"bearingsim-numba-{uid if uid is not None else 'user'}")
    for cand in (os.path.join(root, "bearingsim", "numba"), shared_tmp):
        existed = os.path.isdir(cand)
        if cand == shared_tmp and not _private_folder(cand, uid):
            continue
        if _writable_folder(cand, create=True):
            if given or not existed:
                return cand, f"note: {why}; compiled kernels are cached in {cand}"
            return cand, None  # the fallback in use since an earlier run: said once, when created
    try:  # a fresh private folder for this process (no reuse, but never another user's files)
        cand = tempfile.mkdtemp(prefix="bearingsim-numba-")
        return cand, f"note: {why}; compiled kernels are cached in {cand} for this run only"
    except OSError:
        return None, (f"note: {why} and no user or temporary cache folder is writable; numba will report "
                      "'cannot cache function' (set NUMBA_CACHE_DIR to a writable folder)")


def _private_folder(path: str, uid: int | None) -> bool:
    """True when ``path`` is (or is now made) a folder of this user that nobody else can write: a cache folder in
    a shared temporary directory must not be one another user prepared (numba loads compiled code from it)."""
    import stat

    try:
        os.makedirs(path, mode=0o700, exist_ok=True)
        st = os.lstat(path)
    except OSError:
        return False
    return (stat.S_ISDIR(st.st_mode) and not st.st_mode & 0o022
            and (uid is None or st.st_uid == uid))


#: the in-tree stamp of the kernel packages' sources the cached kernels were compiled from
_SOURCES_STAMP = "kernel-sources.stamp"


def _kernel_modules(package_dir: str) -> list[str]:
    """The modules of :data:`_KERNEL_PACKAGES` under ``package_dir`` (paths relative to it, with ``/``, sorted):
    the sources numba's cached kernels can hold compiled code of (global constants of layout modules too)."""
    found = []
    for sub in _KERNEL_PACKAGES:
        for folder, dirs, names in os.walk(os.path.join(package_dir, sub)):
            dirs[:] = [d for d in dirs if d != "__pycache__"]
            found += [os.path.relpath(os.path.join(folder, n), package_dir).replace(os.sep, "/")
                      for n in names if n.endswith(".py")]
    return sorted(found)


def _kernel_sources_stamp(package_dir: str) -> str:
    """sha256 of (path, size, modification time) of every module of :func:`_kernel_modules` (≈ 0.3 ms)."""
    import hashlib

    h = hashlib.sha256()
    for rel in _kernel_modules(package_dir):
        st = os.stat(os.path.join(package_dir, rel))
        h.update(f"{rel}\0{st.st_size}\0{st.st_mtime_ns}\n".encode())
    return h.hexdigest()


def _drop_stale_kernel_caches(package_dir: str) -> int:
    """Delete numba's in-tree cache files (``__pycache__/*.nbi``, ``*.nbc`` of :data:`_KERNEL_PACKAGES`) when
    a module of those packages changed since they were written; returns how many files were deleted.

    numba checks a cached kernel against its own source file only: after an edit of one module, a cached kernel
    of another module that calls into it is loaded with the old code inlined — wrong results, or a segmentation
    fault when a signature or an array layout changed (seen in this project's tests).  An installed release
    never changes, so this only acts after a developer's edit (or a checkout), once: the next run compiles again
    (≈ 40 s).  A package folder that cannot be written is left alone."""
    stamp_file = os.path.join(package_dir, "__pycache__", _SOURCES_STAMP)
    stamp = _kernel_sources_stamp(package_dir)
    try:
        with open(stamp_file, encoding="ascii") as fh:
            if fh.read().strip() == stamp:
                return 0
    except OSError:
        pass
    dropped = 0
    for sub in _KERNEL_PACKAGES:
        for folder, _dirs, names in os.walk(os.path.join(package_dir, sub)):
            if os.path.basename(folder) != "__pycache__":
                continue
            for n in names:
                if n.endswith((".nbi", ".nbc")):
                    try:
                        os.remove(os.path.join(folder, n))
                        dropped += 1
                    except OSError:
                        pass
    os.makedirs(os.path.dirname(stamp_file), exist_ok=True)
    tmp = f"{stamp_file}.{os.getpid()}.tmp"
    with open(tmp, "w", encoding="ascii") as fh:
        fh.write(stamp + "\n")
    os.replace(tmp, stamp_file)
    return dropped


def _configure_numba_cache() -> None:
    """Apply :func:`_choose_numba_cache_dir` to this process (before numba reads its configuration); with
    numba's in-tree cache, first drop the kernel caches that older sources left (:func:`_drop_stale_kernel_caches`)."""
    package_dir = os.path.dirname(os.path.abspath(__file__))
    try:
        cache_dir, note = _choose_numba_cache_dir(os.environ, package_dir)
    except Exception:  # noqa: BLE001 - a cache decision must never stop the import
        return
    if cache_dir is None and not os.environ.get("NUMBA_CACHE_DIR"):
        try:
            _drop_stale_kernel_caches(package_dir)
        except Exception:  # noqa: BLE001 - (a read-only or half-writable tree): numba's own checks remain
            pass
    if cache_dir is not None:
        os.environ["NUMBA_CACHE_DIR"] = cache_dir
        cfg = sys.modules.get("numba.core.config")
        if cfg is not None:  # numba was imported before bearingsim: its configuration is already read
            cfg.CACHE_DIR = cache_dir
    if note:
        try:
            sys.stderr.write(note + "\n")
        except (OSError, AttributeError, ValueError):
            pass


_configure_numba_cache()
