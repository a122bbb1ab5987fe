"""The integrators specialised for the engine's two right-hand sides, cached on disk.

The generic kernels (``dopri5.integrate``, ``ros2.integrate``, ``ros34pw2.integrate``) take the right-hand
side as an argument; numba does not cache such a function on disk, so each process compiled them again
(~7 s of CPU for the hub case, most of a short ``bearingsim simulate``).  The kernels here call the generic
ones with :func:`bearingsim.dynamics.forces.rhs_args` or :func:`~bearingsim.dynamics.forces.rhs_args_threaded`
named as a module global and take no function argument, so numba caches them, the generic kernels compiled
inside them included: from the second process on they are loaded, not compiled.  They compile to the very
same code as the generic kernel called with that right-hand side (the same results bit for bit).  Every
method's ``advance(ws, t_end)`` runs the kernel here when the workspace holds it (``ws.kernel``, set by the
stepper with :func:`engine_kernel` when ``ws.fun`` is one of the two) and the generic kernel for any other
right-hand side (the tests' own).

Cache invalidation: numba checks a cached function against its own source file only, not against the
functions it calls, so these kernels (which hold compiled copies of the integrators, of the right-hand side
and of the contact kernels) would run stale code after an edit of ``forces.py`` or of an integrator module.
Their cache stamp therefore also holds :func:`sources_digest`, a hash of every module of the kernel packages
(``contact``, ``statics``, ``dynamics``: ``bearingsim._kernel_modules``): an edit of any of them
compiles these kernels again (once, ~10 s), an unchanged install loads them.  When they are compiled again,
numba takes the right-hand side from its own cache (``cache=True`` in forces.py, checked against forces.py
alone), which ``bearingsim._drop_stale_kernel_caches`` empties whenever a module of the kernel packages changed
(with numba's in-tree cache; a NUMBA_CACHE_DIR of the user's own is left alone).  The stamp goes
through numba's cache-locator interface (``numba.core.caching``, not a public API): if that ever fails, the
kernels are compiled per process again (correct, only slower); ``tests/unit/test_integrator_cache.py``
notices it.
"""

from __future__ import annotations

import functools
import hashlib
import os
import warnings

import numpy as np
from numba import njit

from ... import _kernel_modules
from .. import forces
from . import dopri5, multirate, ros2, ros34pw2

#: src/bearingsim
PACKAGE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
_DIGEST: str | None = None

# The kernels here hand compiled functions (the right-hand sides) to the integrators as values, which numba calls an
# experimental feature and warns of at every compilation ("First-class function type feature is experimental",
# printed at a user's first run).  The results are pinned by the engine's tests, not by numba's label: the notice
# is silenced for the warnings numba attributes to this package's kernels only.
warnings.filterwarnings("ignore", message=r".*First-class function type feature is experimental",
                        module=r".*bearingsim")  # (numba's message opens with terminal codes; its module is a path)


def kernel_sources(root: str = PACKAGE_DIR) -> list[str]:
    """The modules of the kernel packages under ``root`` (``bearingsim._kernel_modules``: every module of
    ``contact``, ``statics``, ``dynamics``, so that no dependency is missed)."""
    return _kernel_modules(root)


def sources_digest(root: str | None = None) -> str:
    """sha256 of the path and content of every module of :func:`kernel_sources` (of the installed package when
    ``root`` is None, computed once per process: ~1 ms)."""
    global _DIGEST
    if root is None and _DIGEST is not None:
        return _DIGEST
    h = hashlib.sha256()
    for rel in kernel_sources(root or PACKAGE_DIR):
        with open(os.path.join(root or PACKAGE_DIR, rel), "rb") as fh:
            h.update(rel.encode() + b"\0" + hashlib.sha256(fh.read()).digest())
    if root is None:
        _DIGEST = h.hexdigest()
        return _DIGEST
    return h.hexdigest()


@functools.lru_cache(maxsize=1)
def _sources_cache_class():
    """numba's FunctionCache with the source stamp (the freshness check of the cache index) extended by
    :func:`sources_digest`; a stamp that differs drops the index, so the kernel is compiled again."""
    from numba.core.caching import CompileResultCacheImpl, FunctionCache

    class _StampedLocator:
        """numba's cache locator for the function, with the kernel packages' digest in its source stamp."""

        def __init__(self, locator):
            self._locator = locator

        def get_source_stamp(self):
            return self._locator.get_source_stamp(), sources_digest()

        def __getattr__(self, name):
            return getattr(self._locator, name)

    class _Impl(CompileResultCacheImpl):
        def __init__(self, py_func):
            super().__init__(py_func)
            self._locator = _StampedLocator(self._locator)

    class KernelSourcesCache(FunctionCache):
        _impl_class = _Impl

    return KernelSourcesCache


def _cached(func):
    """``njit`` with the disk cache of :func:`_sources_cache_class` (no cache if numba's interface changed)."""
    disp = njit(func)
    try:
        disp._cache = _sources_cache_class()(disp.py_func)
    except Exception:  # noqa: BLE001 - never stop an import over a cache: compiled per process instead
        pass
    return disp


# ---- DOPRI5 ------------------------------------------------------------------------------------------------
@_cached
def dopri5_serial(args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, vec):
    """:func:`.dopri5.integrate` with ``fun`` = :func:`~bearingsim.dynamics.forces.rhs_args`."""
    return dopri5.integrate(forces.rhs_args, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, vec)


@_cached
def dopri5_threaded(args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, vec):
    """:func:`.dopri5.integrate` with ``fun`` = :func:`~bearingsim.dynamics.forces.rhs_args_threaded`."""
    return dopri5.integrate(forces.rhs_args_threaded, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, vec)


# ---- ROS2 --------------------------------------------------------------------------------------------------
@_cached
def ros2_serial(args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, vec):
    """:func:`.ros2.integrate` with ``fun`` = :func:`~bearingsim.dynamics.forces.rhs_args`."""
    return ros2.integrate(forces.rhs_args, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk,
                          jac_every, vec)


@_cached
def ros2_threaded(args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, vec):
    """:func:`.ros2.integrate` with ``fun`` = :func:`~bearingsim.dynamics.forces.rhs_args_threaded`."""
    return ros2.integrate(forces.rhs_args_threaded, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk,
                          nbk, jac_every, vec)


# ---- ROS34PW2 (without the profiling statistics of bench_dynamics --steps, which calls the generic kernel) ---
@_cached
def ros34_serial(args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, ws, rmass, bmass,
                 vec, dns, dst, mr):
    """:func:`.ros34pw2.integrate` with ``fun`` = :func:`~bearingsim.dynamics.forces.rhs_args` (and the masked
    right-hand side of the multirate refinement, :func:`~bearingsim.dynamics.forces.rhs_masked`)."""
    return ros34pw2.integrate(forces.rhs_args, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk,
                              jac_every, ws, rmass, bmass, np.zeros(0), False, vec, dns, dst, args[10],
                              forces.rhs_masked, mr, forces.rhs_split, forces.split_work(args))


@_cached
def ros34_threaded(args, t, t_end, y, h, atol, rtol, h_min, max_steps, info, blk, nbk, jac_every, ws, rmass,
                   bmass, vec, dns, dst, mr):
    """:func:`.ros34pw2.integrate` with ``fun`` = :func:`~bearingsim.dynamics.forces.rhs_args_threaded` (the
    refinement's two groups of balls on two threads, each with the serial masked right-hand side,
    :func:`.multirate.refine_groups_threaded`)."""
    return ros34pw2.integrate(forces.rhs_args_threaded, args, t, t_end, y, h, atol, rtol, h_min, max_steps, info,
                              blk, nbk, jac_every, ws, rmass, bmass, np.zeros(0), True, vec, dns, dst, args[10],
                              forces.rhs_masked, mr, forces.rhs_split, forces.split_work(args),
                              multirate.refine_groups_threaded)


#: (method module name, ``"serial"`` for rhs_args or ``"threaded"`` for rhs_args_threaded) → cached kernel
KERNELS = {
    ("dopri5", "serial"): dopri5_serial,
    ("dopri5", "threaded"): dopri5_threaded,
    ("ros2", "serial"): ros2_serial,
    ("ros2", "threaded"): ros2_threaded,
    ("ros34pw2", "serial"): ros34_serial,
    ("ros34pw2", "threaded"): ros34_threaded,
}


def engine_kernel(method: str, fun):
    """The cached kernel of :data:`KERNELS` for the method module ``method`` (``"dopri5"``, ``"ros2"``,
    ``"ros34pw2"``) when ``fun`` is :func:`bearingsim.dynamics.forces.rhs_args` or ``rhs_args_threaded``; None
    for any other right-hand side (then ``advance`` calls the generic kernel with ``fun``)."""
    if fun is forces.rhs_args:
        return KERNELS[method, "serial"]
    if fun is forces.rhs_args_threaded:
        return KERNELS[method, "threaded"]
    return None
