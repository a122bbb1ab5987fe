"""Design-space maps: the quasi-static solution over a grid of loads, speeds and preloads.

``map_grid(bearing, fa=..., fr=..., moment=..., speed=..., preload=...)`` evaluates every point of
the grid with the batch kernel (:mod:`bearingsim.statics._batch`: warm starts from the neighbouring
point, serpentine order inside each block) and returns an :class:`xarray.Dataset` with the
displacements, the 5×5 stiffness, the contact-angle extremes, the maximum pressures and the
convergence flags over the grid.

Execution: the grid is cut into rectangular blocks of at most ``chunk_points`` points (the last grid
dimension split first, then whole rows, whole planes, ... outwards; :func:`_blocks`).  Each block is
solved independently and deterministically, so the result does not depend on where the blocks run:
in this process (``workers=1``), in a local process pool (default, one worker per core), or on a Dask
cluster (``scheduler="tcp://host:port"`` or a ``distributed.Client``; a worker that dies has its block
run again elsewhere, a cluster without workers for ``worker_timeout`` or a lost scheduler is a one-line
:class:`MapError`).  With ``out=path`` the blocks are streamed (:class:`bearingsim.io.netcdf.NetCDFWriter`,
units spelled as that module says) into a netCDF file under a hidden
temporary name in the same folder (mode 0666 less the user's umask), renamed at the end; an interrupt
or an error removes the temporary file (never a corrupt map), and the leftover of a killed map process
is removed by the next map to the same name.  A write error (full disk) is an :class:`InputError` on
``out``.

Grid axes (SI inside; the CLI parses units):
    preload [N]   (bearing systems only; each value rebuilds the set's preload offsets)
    fa [N], fr [N] (radial load along +y), fr_z [N], moment [N·m] (about z, the moment of Fr_y at the
    load point), m_y [N·m], speed [rad/s]
A single value is a scalar coordinate; a grid "START:STOP:COUNT" (inclusive) is a dimension.
"""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path

import numpy as np

from .errors import BearingSimError, InputError
from .io import netcdf as nc
from .statics.layout import STATUS_LONG_NAME, status_cf_attributes
from .units import display_unit

#: grid axes in storage order (outermost first), with their dimension for units.py and SI unit
AXES = (("preload", "force", "N"), ("fa", "force", "N"), ("fr", "force", "N"), ("fr_z", "force", "N"),
        ("m_y", "moment", "N m"), ("moment", "moment", "N m"), ("speed", "speed", "rad/s"))
_LOAD_INDEX = {"fa": 0, "fr": 1, "fr_z": 2, "m_y": 3, "moment": 4}
DOF = ("x", "y", "z", "gamma_y", "gamma_z")
#: maps with fewer points run in this process unless ``workers`` is given
SERIAL_BELOW = 20000


#: largest number of points of one grid axis and of a whole map (a map point costs ~0.1 ms and
#: ~200 bytes of output: 10⁸ points are hours of work and ~20 GB; COUNT = 10¹¹ would ask for terabytes)
MAX_GRID_POINTS = 10**8


def check_grid_size(shape: tuple, field: str = "grid") -> int:
    """The number of points of a grid of ``shape``; more than :data:`MAX_GRID_POINTS` raises
    :class:`InputError` (before anything is allocated)."""
    n = 1
    for k in shape:
        n *= int(k)
    if n > MAX_GRID_POINTS:
        raise InputError(field, f"the grid has {n:,} points ({' × '.join(str(int(k)) for k in shape)}), more than "
                         f"the {MAX_GRID_POINTS:.0e} a map may have", "use fewer points (COUNT) per axis")
    return n


def parse_grid(spec, dimension: str, field: str) -> np.ndarray:
    """``"START:STOP:COUNT"`` (inclusive, 2 ≤ COUNT ≤ MAX_GRID_POINTS, STOP > START) or a single value → SI array.

    Python numbers (and lists/arrays of numbers) are taken as SI; strings are parsed with units.

    START and STOP take units as in :func:`bearingsim.units.parse_quantity` (``"1 kN:5 kN:9"``;
    bare numbers in the default unit of ``dimension``).  A list of values is also accepted.
    COUNT is a plain decimal integer (no exponent, no arithmetic); it is checked before the grid
    is allocated.
    """
    from .units import MAX_LENGTH, parse_quantity

    if isinstance(spec, np.ndarray | list | tuple):
        if len(spec) > MAX_GRID_POINTS:
            raise InputError(field, f"{len(spec):,} values is more than {MAX_GRID_POINTS:.0e}", "give fewer values")
        # numbers are SI already; strings carry units
        try:
            vals = np.array([float(v) if isinstance(v, int | float | np.number) and not isinstance(v, bool | np.bool_)
                             else parse_quantity(v, dimension, field) for v in np.ravel(spec)], dtype=float)
        except OverflowError:
            raise InputError(field, "a value is beyond the floating-point range", "give finite values") from None
        if np.ndim(spec) != 1:
            raise InputError(field, f"expected a flat list of values, got shape {np.shape(spec)}",
                             "give a one-dimensional list")
        if vals.size == 0:
            raise InputError(field, "empty list of values", "give at least one value")
        if not np.all(np.isfinite(vals)):
            raise InputError(field, "values must be finite", "check the list")
        return vals
    if isinstance(spec, str) and ":" in spec:
        if len(spec) > 3 * MAX_LENGTH:
            raise InputError(field, f"grid spec of {len(spec)} characters",
                             'write START:STOP:COUNT, e.g. "1000:5000:9"')
        parts = spec.split(":")
        if len(parts) != 3:
            raise InputError(field, f"grid spec {spec!r} is not START:STOP:COUNT", 'e.g. "1000:5000:9"')
        start = parse_quantity(parts[0].strip(), dimension, field)
        stop = parse_quantity(parts[1].strip(), dimension, field)
        ctext = parts[2].strip()
        if not (ctext.isascii() and ctext.isdigit()) or len(ctext) > 12:
            raise InputError(field, f"COUNT in {spec!r} must be a whole number of points", 'e.g. "1000:5000:9"')
        count = int(ctext)
        if count < 2:
            raise InputError(field, f"COUNT must be at least 2 in {spec!r}", "use a single value for one point")
        if count > MAX_GRID_POINTS:
            raise InputError(field, f"COUNT {count:,} in {spec!r} is more than {MAX_GRID_POINTS:.0e} points",
                             "use fewer points")
        if not stop > start:
            raise InputError(field, f"grid {spec!r} has STOP ≤ START", f"write it increasing, e.g. "
                             f'"{parts[1].strip()}:{parts[0].strip()}:{count}"')
        return np.linspace(start, stop, count)
    if spec is None or isinstance(spec, bool | dict | set | bytes):
        raise InputError(field, f"expected a value or a grid START:STOP:COUNT, got {spec!r}"[:160],
                         'e.g. "1000:5000:9" or a list of values')
    return np.array([parse_quantity(spec, dimension, field)], dtype=float)


# ---- blocks ------------------------------------------------------------------------------------
def block_shape(shape: tuple, chunk_points: int) -> tuple[int, ...]:
    """The shape of the first (and largest) block of :func:`_blocks`: the last dimension up to ``chunk_points``,
    then as many whole rows, planes, ... as fit."""
    sizes = []
    room = max(1, int(chunk_points))
    for n in reversed(shape):
        r = max(1, min(int(n), room))
        sizes.append(r)
        room = max(1, room // r)
    return tuple(sizes[::-1])


def _blocks(shape: tuple, chunk_points: int):
    """Rectangular blocks of the grid (tuples of slices, one per dimension) of at most ``chunk_points``
    points: the last dimension is split first, then as many whole rows of it as fit, then whole planes,
    and so on outwards.  The blocks depend only on the grid and ``chunk_points`` (never on the
    executor), so every executor solves the same blocks and returns the same numbers."""
    if len(shape) == 0:
        return [()]
    sizes = block_shape(shape, chunk_points)
    starts = [range(0, n, r) for n, r in zip(shape, sizes)]
    out = []
    for idx in np.ndindex(*[len(st) for st in starts]):
        out.append(tuple(slice(starts[k][i], min(starts[k][i] + sizes[k], shape[k])) for k, i in enumerate(idx)))
    return out


def _snake(shape: tuple) -> np.ndarray:
    """Boustrophedon visiting order of a block: int[npts, ndim] grid indices in which consecutive points
    differ by one step along one dimension (a reflected mixed-radix Gray code: index k runs backwards
    when the indices before it sum to an odd number)."""
    digits = np.unravel_index(np.arange(int(np.prod(shape))), shape)
    parity = np.zeros(len(digits[0]), dtype=np.int64)
    cols = []
    for n, d in zip(shape, digits):
        i = np.where(parity % 2 == 1, n - 1 - d, d)
        cols.append(i)
        parity += i
    return np.column_stack(cols)


def _with_preload(bearing, preload: float):
    from .statics import arrangements as ar

    if not isinstance(bearing, ar.BearingSystem):
        raise InputError("preload", "a preload grid needs a bearing set or double-row unit",
                         "use an arrangement (e.g. skf-7011-cdga-hc-db) or drop --preload")
    if preload == 0:
        rows = tuple(dataclasses.replace(r, axial_offset=0.0) for r in bearing.rows)
    else:
        e = ar._preload_offset(bearing.rows, preload)
        rows = tuple(dataclasses.replace(r, axial_offset=e) for r in bearing.rows)
    return dataclasses.replace(bearing, rows=rows, preload=float(preload))


def solve_block(bearing, axes: dict, block: tuple, control: str = "outer", rings=None) -> dict:
    """Solve one rectangular block of the grid (runs anywhere: local, process pool, Dask worker).

    ``axes`` maps every axis name of :data:`AXES` to its value array (length 1 for scalars);
    ``block`` holds one slice per grid dimension (the axes with more than one value, in AXES order).
    Points are visited in serpentine order so that each starts next to the previous one.
    ``rings``: None for rigid rings (the batch kernel), or the
    :class:`bearingsim.rings.coupling.ElasticRings` of the bearing (computed once by :func:`map_grid` and sent
    with the block): every point is solved by :func:`bearingsim.rings.coupling.solve_points`, warm-started
    from the previous point of the serpentine.
    """
    from .statics.batch import NSUMMARY, run_batch

    dims = [name for name, _, _ in AXES if len(axes[name]) > 1]
    vals = {name: np.asarray(axes[name], dtype=float) for name, _, _ in AXES}
    sub = {d: vals[d][s] for d, s in zip(dims, block)}
    for name, _, _ in AXES:
        if name not in sub:
            sub[name] = vals[name]
    shape = tuple(len(sub[d]) for d in dims)
    # serpentine (boustrophedon) order over the block: each point next to the previous one
    flat = list(_snake(shape).T) if dims else []
    npts = int(np.prod(shape)) if dims else 1
    pick = {d: sub[d][flat[i]] for i, d in enumerate(dims)}
    for name, _, _ in AXES:
        if name not in pick:
            pick[name] = np.full(npts, sub[name][0])
    pre = pick["preload"]
    res = {"q": np.zeros((npts, 5)), "k": np.zeros((npts, 5, 5)), "status": np.zeros(npts, dtype=np.int64),
           "iterations": np.zeros(npts, dtype=np.int64), "residual": np.zeros(npts),
           "summary": np.zeros((npts, NSUMMARY)), "warning_flags": np.zeros(npts, dtype=np.int32)}
    # one batch per preload value (the preload changes the bearing)
    for pv in np.unique(pre) if "preload" in dims or axes.get("_preload_given") else [None]:
        sel = np.ones(npts, dtype=bool) if pv is None else (pre == pv)
        brg = bearing if pv is None else _with_preload(bearing, float(pv))
        loads = np.zeros((int(sel.sum()), 5))
        for name, j in _LOAD_INDEX.items():
            loads[:, j] = pick[name][sel]
        if rings is None:
            out = run_batch(brg, loads, pick["speed"][sel], control)
        else:
            from .rings.coupling import solve_points

            out = solve_points(brg, loads, pick["speed"][sel], control, rings)
        for key in res:
            res[key][sel] = out[key]
    # ISO 281 basic rating life of every point from its external loads and speed (life.basic_rating_life_arrays;
    # the preload and the moments are not part of ISO 281's P): L10 [revolutions, SI count] and L10h [s]
    from .life import basic_rating_life_arrays

    l10, l10h = basic_rating_life_arrays(bearing, np.hypot(pick["fr"], pick["fr_z"]), pick["fa"], pick["speed"])
    res["l10_rev"] = l10 * 1e6
    res["l10_s"] = l10h * 3600.0
    # back to the block's C order
    order = np.ravel_multi_index(tuple(flat), shape) if dims else np.zeros(1, dtype=np.int64)
    back = {}
    for key, v in res.items():
        w = np.empty_like(v)
        w[order] = v
        back[key] = w.reshape(shape + v.shape[1:])
    return back


# ---- output ------------------------------------------------------------------------------------
_VARS = {
    # name: (source key, extra dims, dtype, units (bearingsim.io.netcdf.units_attributes), long name)
    "displacement": ("q", ("dof",), "f8", nc.DOF_UNITS, "inner-ring displacement (x, y, z, gamma_y, gamma_z)"),
    "stiffness": ("k", ("dof", "dof2"), "f8", nc.STIFFNESS_UNITS,
                  "5x5 stiffness matrix K[i, j] = dF_i/dq_j (rows: Fa, Fr_y, Fr_z, M_y, M_z; columns: x, y, z, "
                  "gamma_y, gamma_z)"),
    "status": ("status", (), "i4", "1", STATUS_LONG_NAME),  # codes: bearingsim.statics.layout.STATUS
    "warning_flags": ("warning_flags", (), "i4", "1", "plausibility warnings (bitmask, bearingsim.limits)"),
    "converged": ("converged", (), "i1", "1", "1 when the point converged"),
    "iterations": ("iterations", (), "i4", "1", "ring Newton iterations (warm + cold start)"),
    "residual": ("residual", (), "f8", "N", "max |ring residual|, moments divided by the pitch radius"),
    "max_pressure_inner": ("p_inner", (), "f8", "Pa", "maximum inner contact pressure"),
    "max_pressure_outer": ("p_outer", (), "f8", "Pa", "maximum outer contact pressure"),
    "contact_angle_inner_min": ("alpha_inner_min", (), "f8", "rad", "smallest inner contact angle, loaded balls"),
    "contact_angle_inner_max": ("alpha_inner_max", (), "f8", "rad", "largest inner contact angle, loaded balls"),
    "contact_angle_outer_min": ("alpha_outer_min", (), "f8", "rad", "smallest outer contact angle, loaded balls"),
    "contact_angle_outer_max": ("alpha_outer_max", (), "f8", "rad", "largest outer contact angle, loaded balls"),
    "basic_rating_life": ("l10_rev", (), "f8", "1", "ISO 281 basic rating life L10 in revolutions (external Fa and "
                          "Fr only; inf at zero load, NaN where ISO 281 gives none)"),
    "basic_rating_life_time": ("l10_s", (), "f8", "s", "ISO 281 basic rating life L10h at the point's speed "
                               "(NaN at zero speed)"),
}
_SUMMARY_INDEX = {"p_inner": 0, "p_outer": 1, "alpha_inner_min": 2, "alpha_inner_max": 3,
                  "alpha_outer_min": 4, "alpha_outer_max": 5}


def _var_attrs(name: str) -> dict:
    """Extra attributes of a map variable: CF flag_masks/flag_meanings of ``warning_flags`` (bits in
    :mod:`bearingsim.limits`), CF flag_values/flag_meanings of ``status`` (:mod:`bearingsim.statics.layout`)."""
    if name == "warning_flags":
        from .limits import cf_attributes

        return cf_attributes()
    if name == "basic_rating_life_time":
        return {"units_display": "h"}
    if name == "basic_rating_life":
        return {"units_display": "1e6 rev"}
    if name == "status":
        attrs = status_cf_attributes()
        attrs["flag_values"] = np.array(attrs["flag_values"], dtype=np.int32)  # the variable's type (CF §3.5)
        return attrs
    return {}


def _block_var(block_res: dict, key: str):
    if key == "converged":
        return (block_res["status"] == 0).astype(np.int8)
    if key in _SUMMARY_INDEX:
        return block_res["summary"][..., _SUMMARY_INDEX[key]]
    return block_res[key]


def _schema(dims: list, shape: tuple, axes: dict, block: tuple | None = None) -> tuple[dict, list]:
    """Dimensions and variables of a map (:class:`bearingsim.io.netcdf.Variable`): the grid axes (a
    dimension each when gridded, else a scalar coordinate), the ``dof`` labels and :data:`_VARS`, chunked as the
    solver's ``block`` (:func:`block_shape`; default: the whole grid) with at most
    :data:`bearingsim.io.netcdf.MAX_CHUNK_BYTES` per chunk (:func:`bearingsim.io.netcdf.capped_chunks`)."""
    dimensions = dict(zip(dims, shape)) | {"dof": 5, "dof2": 5}
    # a speed axis is stored in rad/s (SI) and tells readers the unit people use (rpm)
    variables = [nc.Variable(name, (name,) if name in dims else (), u,
                             attrs={"units_display": display_unit(u)[0]} if u == "rad/s" else {})
                 for name, _, u in AXES]
    variables += [nc.Variable("dof", ("dof",), dtype=str), nc.Variable("dof2", ("dof2",), dtype=str)]
    block = tuple(shape) if block is None else tuple(block)
    for name, (_, extra, dt, u, long) in _VARS.items():
        variables.append(nc.Variable(name, tuple(dims) + extra, u, long, dt, _var_attrs(name),
                                     nc.capped_chunks(block, (5,) * len(extra), np.dtype(dt).itemsize, shape=shape)
                                     if dims else None))
    return dimensions, variables


def _coordinates(dims: list, axes: dict) -> dict:
    out = {name: (axes[name] if name in dims else float(axes[name][0])) for name, _, _ in AXES}
    return out | {"dof": DOF, "dof2": DOF}


class _MapSink:
    """Where the blocks of a map go: a netCDF file (:class:`bearingsim.io.netcdf.NetCDFWriter`, streamed to a
    temporary file and renamed at the end) when ``path`` is given, else arrays in memory."""

    def __init__(self, path, dims, shape, axes, attrs, block=None, notify=None):
        self.dims, self.shape, self.axes, self.attrs = dims, shape, axes, attrs
        self.dimensions, self.variables = _schema(dims, shape, axes, block)
        self.file = None
        self.data = None
        if path is not None:
            need = nc.expected_size(self.dimensions, self.variables)
            if notify is not None:
                notify(f"{int(np.prod(shape)):,} points: the map file {path} will take {nc.size_text(need)}")
            _check_free_space(Path(path), need)
            self.file = nc.NetCDFWriter(path, dims=self.dimensions, variables=self.variables,
                                        values=_coordinates(dims, axes), attrs=attrs, error=_write_error)
        else:
            self.data = {name: np.zeros(shape + (5,) * len(extra), dtype=dt)
                         for name, (_, extra, dt, _, _) in _VARS.items()}

    @property
    def final(self) -> Path:
        return self.file.final

    def write(self, block, res):
        for name, (key, _, _, _, _) in _VARS.items():
            if self.file is not None:
                try:
                    values = _block_var(res, key)
                except OSError as exc:
                    raise _write_error(self.file.final, exc) from None
                self.file.write(name, block, values)
            else:
                self.data[name][block] = _block_var(res, key)

    def close(self):
        if self.file is not None:
            self.file.close()

    def abort(self):
        if self.file is not None:
            self.file.abort()

    def dataset(self):
        """The in-memory map as an :class:`xarray.Dataset` (the attributes of the file)."""
        coords = [name for name, _, _ in AXES] + ["dof", "dof2"]
        return nc.to_xarray(self.variables, _coordinates(self.dims, self.axes) | self.data, self.attrs, coords)


#: room kept free beside a map's values for the file's header and chunk index [bytes]
_HEADROOM = 16 * 2**20


def _check_free_space(path: Path, need: int) -> None:
    """An :class:`InputError` on ``out`` when the folder of ``path`` has less free space than the map's ``need``
    bytes (and :data:`_HEADROOM`), before anything is written (a folder that does not exist yet: no check here)."""
    import shutil

    limit = _file_size_limit()
    if limit is not None and need > limit:
        raise InputError("out", f"the map needs {nc.size_text(need)} and this process may write files of at most "
                         f"{nc.size_text(limit)} (ulimit -f)", "raise the limit (ulimit -f) or use fewer points; "
                         "nothing was written")
    try:
        free = shutil.disk_usage(path.parent).free
    except OSError:
        return
    if need + _HEADROOM > free:
        raise InputError("out", f"the map needs {nc.size_text(need)} and {str(path.parent)!r} has "
                         f"{nc.size_text(free)} free", "free disk space, write to another folder or use fewer points; "
                         "nothing was written")


def _file_size_limit() -> int | None:
    """The largest file this process may write (RLIMIT_FSIZE, ``ulimit -f``) [bytes], None when unlimited."""
    try:
        import resource

        soft = resource.getrlimit(resource.RLIMIT_FSIZE)[0]
    except (ImportError, OSError, ValueError):
        return None
    return None if soft == resource.RLIM_INFINITY else int(soft)


def _write_error(final: Path, exc: BaseException) -> InputError:
    """The one-line error of a failed write of the map ``final``, naming its cause: the errno of an OSError
    (full disk, permissions), a full disk seen after a library error (HDF5 reports ENOSPC as "NetCDF: HDF
    error"), else the netCDF library's own message."""
    import errno
    import shutil

    what = f"cannot write the map {str(final)!r}"
    code = getattr(exc, "errno", None)
    limit = _file_size_limit()
    if code == errno.EFBIG or (limit is not None and not isinstance(exc, OSError)):
        return InputError("out", f"{what}: past the file-size limit of this process, {nc.size_text(limit or 0)} "
                          f"(ulimit -f; {type(exc).__name__}: {exc})",
                          "raise the limit (ulimit -f) or use fewer points; nothing was written")
    if code in (errno.ENOSPC, errno.EDQUOT):
        return InputError("out", f"{what}: the disk is full ({exc})",
                          "free disk space or write to another folder; nothing was written")
    if code in (errno.EACCES, errno.EPERM, errno.EROFS):
        return InputError("out", f"{what}: permission denied ({exc})",
                          "choose a folder you can write to; nothing was written")
    if code in (errno.ENOENT, errno.ENOTDIR):
        return InputError("out", f"{what}: the folder does not exist ({exc})",
                          "create the folder or give another path; nothing was written")
    try:
        full = shutil.disk_usage(final.parent).free < _HEADROOM
    except OSError:
        full = False
    if full:
        return InputError("out", f"{what}: the disk is full ({type(exc).__name__}: {exc})",
                          "free disk space or write to another folder; nothing was written")
    return InputError("out", f"{what}: the netCDF library failed ({type(exc).__name__}: {exc})",
                      "nothing was written; report it with the command line (BEARINGSIM_DEBUG=1 shows where)")


# ---- executors -----------------------------------------------------------------------------------
class MapError(BearingSimError, RuntimeError):
    """A map could not be completed (its Dask cluster lost every worker, a block was lost with the
    workers that ran it, or the scheduler went away); the output file is not written."""


def _connect(scheduler, timeout: float):
    """``(client, owned)``: a ``distributed.Client`` connected to ``scheduler`` (an address; owned, to be
    closed by the map) or the caller's Client.  An unreachable address is an :class:`InputError`."""
    try:
        from distributed import Client
    except ImportError:  # pragma: no cover
        raise InputError("scheduler", "dask.distributed is not installed", "pip install 'dask[distributed]'") from None
    if not isinstance(scheduler, str):
        if not all(hasattr(scheduler, a) for a in ("map", "gather", "loop")):
            raise InputError("scheduler", f"expected an address tcp://host:port or a distributed.Client, got "
                             f"{type(scheduler).__name__}", "e.g. --scheduler tcp://127.0.0.1:8786")
        return scheduler, False  # a Client given by the caller
    _check_address(scheduler)  # a malformed address must not reach Client (it fails late and noisily)
    try:
        return Client(scheduler, timeout=f"{timeout}s", set_as_default=False), True
    except (OSError, TimeoutError, ValueError, TypeError) as exc:
        raise InputError("scheduler", f"cannot reach the Dask scheduler at {scheduler!r} ({type(exc).__name__}: "
                         f"{exc})", "start it (dask scheduler) or check the address, e.g. tcp://127.0.0.1:8786") \
            from None


def _check_address(address: str) -> None:
    """``tcp://HOST:PORT`` (or tls://, ws://, wss://, or HOST:PORT) with a port in 1..65535, else InputError."""
    from distributed.comm.addressing import parse_address, parse_host_port

    fix = "give the scheduler's address, e.g. tcp://127.0.0.1:8786"
    try:
        scheme, loc = parse_address(address.strip(), strict=False)
        if scheme not in ("tcp", "tls", "ws", "wss", "ucx"):
            raise InputError("scheduler", f"unknown protocol {scheme!r} in {address!r}", fix)
        _, port = parse_host_port(loc)
    except (ValueError, TypeError) as exc:
        if isinstance(exc, InputError):
            raise
        raise InputError("scheduler", f"not a scheduler address: {address!r} ({exc})", fix) from None
    if not 1 <= int(port) <= 65535:
        raise InputError("scheduler", f"port {port} out of range in {address!r}", fix)


def _run_on_cluster(client, bearing, axes, blocks, control, done, worker_timeout: float, poll: float = 1.0,
                    rings=None):
    """Solve ``blocks`` on the cluster of ``client``, calling ``done(block, result)`` as they finish
    (:func:`run_tasks_on_cluster` with :func:`solve_block`; FE ring coefficients travel with each block)."""
    extra = () if rings is None else (rings,)  # the rigid path's call is unchanged
    run_tasks_on_cluster(client, solve_block, [(bearing, axes, b, control, *extra) for b in blocks], blocks, done,
                         worker_timeout, poll)


def run_tasks_on_cluster(client, fn, args: list, keys: list, done, worker_timeout: float, poll: float = 1.0,
                         what: str = "blocks"):
    """Run ``fn(*args[i])`` for every i on the cluster of ``client``, calling ``done(keys[i], result)`` as
    they finish (the map's blocks; the hub study's cells).  ``what`` names the tasks in error messages.

    Everything goes through ``client`` itself (never the process's default client: a client connected
    to an address by :func:`_connect` is not the default, and ``distributed.as_completed`` without a
    loop looks up the default and fails with "No clients found").  The bearing travels with each task
    (a few kB): tasks without data dependencies are balanced freely by the scheduler (a scattered
    dependency pinned most tasks to one worker).  The results of all blocks finished so far are fetched
    in one gather (not one round trip per block), so that this process — which also hosts the scheduler
    of a LocalCluster — takes as little CPU as possible from the workers.

    A worker that dies takes its running block with it; the scheduler runs the block again on another
    worker (the result is the same: blocks are deterministic).  When the cluster has had no worker for
    ``worker_timeout`` [s], when a block has killed its workers too often (dask's ``allowed-failures``)
    or when the scheduler goes away, :class:`MapError` is raised (one line; the caller removes the
    temporary file).
    """
    import queue
    import time

    blocks = keys
    futures = client.map(fn, *zip(*args), pure=False)
    remaining = {f.key: (f, b) for f, b in zip(futures, blocks)}
    finished_q: queue.SimpleQueue = queue.SimpleQueue()
    for f in futures:
        f.add_done_callback(finished_q.put)  # runs on the client's own loop (no default client needed)
    del futures
    alone_since = None
    try:
        while remaining:
            finished = []
            try:
                finished.append(finished_q.get(timeout=poll))
                while True:  # and every other block finished by now: one gather
                    finished.append(finished_q.get_nowait())
            except queue.Empty:
                pass
            finished = [remaining[f.key][0] for f in finished if f.key in remaining]
            if finished:
                alone_since = None
                try:
                    results = client.gather(finished)
                except Exception as exc:  # noqa: BLE001 - cluster failures become one line
                    err = _cluster_error(exc)
                    if err is None:
                        raise  # an error of the block itself (InputError, or a bug to report)
                    raise err from None
                for f, res in zip(finished, results):
                    done(remaining.pop(f.key)[1], res)
                    f.release()  # the block's result leaves the cluster once written
                continue
            if client.status not in ("running", "connecting"):
                raise MapError(f"lost the connection to the Dask scheduler (client {client.status}); "
                               f"{len(remaining)} of {len(blocks)} {what} unfinished")
            try:
                nworkers = len(client.nthreads())
            except Exception as exc:  # noqa: BLE001
                raise (_cluster_error(exc) or exc) from None
            if nworkers:
                alone_since = None
            elif alone_since is None:
                alone_since = time.monotonic()
            elif time.monotonic() - alone_since > worker_timeout:
                raise MapError(f"the Dask cluster has had no worker for {worker_timeout:g} s; "
                               f"{len(remaining)} of {len(blocks)} {what} unfinished (start workers with "
                               "dask worker ADDRESS, or raise --worker-timeout)")
    except BaseException:
        if remaining:
            try:
                client.cancel([f for f, _ in remaining.values()])
            except Exception:  # noqa: BLE001 - the cluster may be gone already
                pass
        raise


def run_tasks_locally(fn, args: list, keys: list, done, nworkers: int, what: str = "blocks",
                      job: str = "the map") -> None:
    """Run ``fn(*args[i])`` for every i, calling ``done(keys[i], result)`` as they finish: in this process when
    ``nworkers`` is 1 or there is one task, else in a pool of ``nworkers`` spawned processes (a process that
    dies is a :class:`MapError` naming ``job`` and how many ``what`` were left)."""
    if nworkers == 1 or len(args) == 1:
        for k, a in zip(keys, args):
            done(k, fn(*a))
        return
    import multiprocessing as mp
    from concurrent.futures import ProcessPoolExecutor
    from concurrent.futures import as_completed as cf_completed
    from concurrent.futures.process import BrokenProcessPool

    ctx = mp.get_context("spawn")

    with ProcessPoolExecutor(max_workers=min(nworkers, len(args)), mp_context=ctx) as ex:
        futs = {}
        n_done = 0
        try:
            # submitting inside the try: a worker that dies while tasks are still being submitted breaks the
            # pool there (BrokenProcessPool from submit), which is the same failure as one seen in a result
            for k, a in zip(keys, args):
                futs[ex.submit(fn, *a)] = k
            for f in cf_completed(list(futs)):
                done(futs.pop(f), f.result())  # pop: the result is released once written
                n_done += 1
        except BrokenProcessPool as exc:
            raise MapError(f"a worker process of {job} died ({exc}); {len(args) - n_done} of {len(args)} "
                           f"{what} unfinished (out of memory? try fewer --workers)") from None
        except BaseException:
            for f in futs:
                f.cancel()
            raise


def _close(client, quiet) -> None:
    """Close a client the map opened (quietly and briefly: its scheduler may be gone)."""
    try:
        client.close(timeout=5)
    except Exception:  # noqa: BLE001 - nothing left to save
        pass
    finally:
        if quiet is not None:
            quiet.__exit__(None, None, None)


def _cluster_error(exc: BaseException) -> MapError | None:
    """The :class:`MapError` for a failure of the cluster itself; None for any other error."""
    name = type(exc).__name__
    if name == "KilledWorker":
        return MapError(f"a block of the map was lost with every worker that ran it ({exc}); the workers may "
                        "be running out of memory")
    if name in ("CancelledError", "FutureCancelledError", "CommClosedError") or \
            isinstance(exc, ConnectionError | TimeoutError):
        why = "connection lost" if "connection" in str(exc).lower() else f"{name}: {str(exc)[:120]}"
        return MapError(f"lost the Dask scheduler during the map ({why}); restart the scheduler and run the map again")
    return None


class _QuietDistributed:
    """Silence the client-side loggers of ``distributed`` while a map owns its client (the CLI path): a lost
    worker or scheduler is reported in one line by the map, not by pages of reconnect tracebacks."""

    def __enter__(self):
        import logging

        names = ["distributed"] + [n for n in logging.root.manager.loggerDict if n.startswith("distributed.")]
        self.saved = [(lg, lg.level) for lg in map(logging.getLogger, names)]
        for lg, _ in self.saved:
            lg.setLevel(logging.CRITICAL + 1)
        return self

    def __exit__(self, *exc):
        for lg, level in self.saved:
            lg.setLevel(level)
        return False


def map_grid(bearing, *, fa=0.0, fr=0.0, fr_z=0.0, m_y=0.0, moment=0.0, speed=0.0, preload=None,
             control: str = "outer", out: str | Path | None = None, workers: int | None = None,
             scheduler=None, chunk_points: int = 2000, progress: bool = False, scheduler_timeout: float = 3.0,
             worker_timeout: float = 60.0, rings=None, notify=None):
    """Quasi-static map of ``bearing`` over a grid → :class:`xarray.Dataset`.

    Parameters
    ----------
    bearing : BallBearing, BearingSystem, or a catalogue name / TOML path
    fa, fr, fr_z, m_y, moment : value or grid ([N], [N·m]); a string "START:STOP:COUNT" (units allowed)
        or a list/array of SI values or a single value.  ``fr`` is along +y, ``moment`` about z.
    speed : inner-ring speed, value or grid (strings: bare number = rpm; Python numbers and arrays: [rad/s])
    preload : preload force per row [N] (bearing systems), value or grid; None keeps the bearing's own
    control : raceway control ``"outer"``, ``"inner"``, ``"auto"``
    out : netCDF path; the map streams to it (temporary name, renamed at the end) and the returned
        Dataset is opened lazily from it
    workers : local processes (default: all cores for maps of SERIAL_BELOW points or more, else this
        process; 1 = in this process)
    scheduler : Dask scheduler address or a ``distributed.Client`` (overrides ``workers``)
    scheduler_timeout : seconds to wait for the scheduler at the start (unreachable: :class:`InputError`)
    worker_timeout : seconds the map waits on a cluster without workers before it fails
        (:class:`MapError`); a block lost with a dead worker is run again on another one
    chunk_points : maximum points per block
    progress : show a rich progress bar
    rings : ``"rigid"`` (the batch kernel), ``"fe"`` (elastic rings, docs/rings.md: the influence coefficients are
        computed once here — or read from their disk cache — and sent to the workers with the blocks; every
        point is solved by :func:`bearingsim.rings.coupling.solve`), an
        :class:`bearingsim.rings.coupling.ElasticRings`, or None: the bearing file's ``[rings]`` model (rigid
        without one).  The output's attribute ``rings`` names the model.
    notify : ``notify(text)`` is called with one line of news before the map is solved (the size of the file
        ``out``: the CLI prints it), or None
    """
    if isinstance(bearing, str | Path):
        from .io import load_bearing

        bearing = load_bearing(bearing)
    if control not in ("outer", "inner", "auto"):
        raise InputError("control", f"unknown raceway control {control!r}", "use outer, inner or auto")
    ring_name, ring_coeffs = _ring_choice(bearing, rings)
    spec = {"fa": fa, "fr": fr, "fr_z": fr_z, "m_y": m_y, "moment": moment, "speed": speed,
            "preload": 0.0 if preload is None else preload}
    axes = {}
    for name, dim, _ in AXES:
        v = spec[name]
        if isinstance(v, int | float | np.floating | np.integer) and not isinstance(v, bool):
            arr = np.array([float(v)])
        else:
            arr = parse_grid(v, dim, name)
        if not np.all(np.isfinite(arr)):
            raise InputError(name, "values must be finite", "check the grid")
        axes[name] = arr
    if preload is not None:
        axes["_preload_given"] = True
        if np.any(axes["preload"] < 0):
            raise InputError("preload", "must not be negative", "give a preload ≥ 0 N")
        _with_preload(bearing, float(axes["preload"][0]))  # validate early (raises InputError)
    if not isinstance(chunk_points, int) or chunk_points < 1:
        raise InputError("chunk_points", f"must be a positive integer, got {chunk_points!r}", "e.g. 2000")
    dims = [name for name, _, _ in AXES if len(axes[name]) > 1]
    shape = tuple(len(axes[d]) for d in dims)
    check_grid_size(shape)  # before blocks or output are allocated
    blocks = _blocks(shape, chunk_points)
    npts = int(np.prod(shape)) if shape else 1
    attrs = {"bearing": getattr(bearing, "name", "bearing"), "control": control, "model": "Jones-Harris quasi-static",
             "source": "bearingsim.sweep.map_grid", "stiffness_order": "x, y, z, gamma_y, gamma_z",
             "load_convention": "loads on the inner ring at the load point; fr along +y, moment about z",
             "rings": ring_name}
    if ring_coeffs is not None:
        import json

        attrs["model"] += " with elastic rings (finite elements, docs/rings.md)"
        attrs["rings_description"] = json.dumps(ring_coeffs.description)
    if isinstance(worker_timeout, bool) or not isinstance(worker_timeout, int | float) or \
            not (0 < worker_timeout < float("inf")):
        raise InputError("worker_timeout", f"must be a positive number of seconds, got {worker_timeout!r}", "e.g. 60")
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise InputError("workers", f"must be a positive integer, got {workers!r}", "e.g. --workers 2")
    if workers is not None:
        nworkers = workers
    else:
        # starting processes costs seconds (interpreter + compiled kernels): small maps run here
        nworkers = 1 if npts < SERIAL_BELOW else (os.cpu_count() or 1)
    client = own_client = None
    if scheduler is not None:
        client, own_client = _connect(scheduler, scheduler_timeout)  # before any file is created
    quiet = _QuietDistributed().__enter__() if own_client else None
    try:
        sink = _MapSink(Path(out) if out is not None else None, dims, shape, axes, attrs,
                        block_shape(shape, chunk_points) if shape else None, notify)
    except BaseException:
        if own_client:
            _close(client, quiet)
        raise
    bar = None
    try:
        if progress:
            from rich.progress import BarColumn, Progress, TextColumn, TimeRemainingColumn

            bar = Progress(TextColumn("map"), BarColumn(), TextColumn("{task.completed}/{task.total} points"),
                           TimeRemainingColumn())
            bar.start()
            task = bar.add_task("map", total=npts)

        def done(block, res):
            sink.write(block, res)
            if bar is not None:
                bar.advance(task, int(res["status"].size))

        if client is not None:
            _run_on_cluster(client, bearing, axes, blocks, control, done, worker_timeout, rings=ring_coeffs)
        else:
            extra = () if ring_coeffs is None else (ring_coeffs,)  # the rigid path's call is unchanged
            run_tasks_locally(solve_block, [(bearing, axes, b, control, *extra) for b in blocks], blocks, done,
                              nworkers)
        if bar is not None:
            bar.stop()
            bar = None
    except BaseException:
        if bar is not None:
            bar.stop()
        sink.abort()
        if own_client:
            _close(client, quiet)
        raise
    if own_client:
        _close(client, quiet)
    if sink.file is not None:
        sink.close()
        import xarray as xr

        return xr.open_dataset(sink.final)
    return sink.dataset()


def _ring_choice(bearing, rings):
    """("rigid" or "fe", the ElasticRings or None) for :func:`map_grid`'s ``rings``."""
    from .rings.spec import RING_MODELS, model_of

    if rings is None:
        rings = model_of(bearing)
    if isinstance(rings, str):
        if rings not in RING_MODELS:
            raise InputError("rings", f"unknown ring model {rings!r}", "use rigid or fe")
        if rings == "rigid":
            return "rigid", None
        from .rings.coupling import ring_model

        return "fe", ring_model(bearing)  # once per map (disk cache); travels to the workers with the blocks
    from .rings.coupling import ElasticRings, _check_rings

    if not isinstance(rings, ElasticRings):
        raise InputError("rings", f"expected rigid, fe or ElasticRings, got {type(rings).__name__}", "use rigid or fe")
    _check_rings(bearing, rings)
    return "fe", rings


def warm_up(bearing="skf-7011-cdga-hc") -> bool:
    """Load the compiled kernels in this process (run it on every Dask worker with ``client.run(warm_up)``
    before timing: the first block a worker solves otherwise pays the numba cache load)."""
    if isinstance(bearing, str | Path):
        from .io import load_bearing

        bearing = load_bearing(bearing)
    solve_block(bearing, {name: np.array([0.0]) for name, _, _ in AXES} | {"fa": np.array([100.0, 200.0]),
                                                                           "speed": np.array([0.0, 100.0])},
                (slice(0, 2), slice(0, 2)))
    return True


#: (SI unit, units_display) → factor for map variables shown in a unit of the trade that is not the general display
#: unit of their SI unit (:func:`bearingsim.units.display_unit` keeps s as s): lives in hours and 10⁶ revolutions
_SHOWN_AS = {("s", "h"): 1.0 / 3600.0, ("1", "1e6 rev"): 1e-6}


def plot_unit(ds, var: str = "stiffness", i: int = 0, j: int = 0) -> tuple[str, float]:
    """(unit people read, factor from the stored SI value) of map variable ``var`` (for the stiffness: of K[i, j],
    each component in its own unit)."""
    if var == "stiffness":
        return display_unit(nc.component_units(ds[var].attrs, (5, 5))[i][j])
    units, shown = ds[var].attrs.get("units", ""), ds[var].attrs.get("units_display")
    if (units, shown) in _SHOWN_AS:  # e.g. a life stored in s, shown in h
        return shown, _SHOWN_AS[(units, shown)]
    return display_unit(units)


def plot_map(ds, path: str | Path, var: str = "stiffness", i: int = 0, j: int = 0):
    """Write a stiffness map K[i, j] over the (first two) grid dimensions to ``path`` (matplotlib), axes and
    colour bar in the units people read (:func:`bearingsim.units.display_unit`: rpm, N, N/µm, N·m/mrad …),
    one unit per panel (the unit of the component K[i, j])."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    k = ds[var].isel(dof=i, dof2=j) if var == "stiffness" else ds[var]
    grid_dims = [d for d in k.dims]
    fig, ax = plt.subplots(figsize=(6, 4.5))
    label = f"K[{DOF[i]},{DOF[j]}]" if var == "stiffness" else var
    unit, f_v = plot_unit(ds, var, i, j)

    def axis(name):
        u, f = display_unit(ds[name].attrs.get("units", ""))
        return ds[name].values * f, f"{name} [{u}]"

    if len(grid_dims) >= 2:
        extra = {d: 0 for d in grid_dims[:-2]}
        kk = k.isel(**extra) if extra else k
        (xv, xl), (yv, yl) = axis(grid_dims[-1]), axis(grid_dims[-2])
        m = ax.pcolormesh(xv, yv, kk.values * f_v, shading="auto")
        fig.colorbar(m, ax=ax, label=f"{label} [{unit}]")
        ax.set_xlabel(xl)
        ax.set_ylabel(yl)
    elif len(grid_dims) == 1:
        xv, xl = axis(grid_dims[0])
        ax.plot(xv, k.values * f_v, "o-")
        ax.set_xlabel(xl)
        ax.set_ylabel(f"{label} [{unit}]")
    ax.set_title(f"{ds.attrs.get('bearing', '')}: {label}")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return Path(path)
