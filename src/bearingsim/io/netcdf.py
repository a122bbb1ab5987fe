"""The netCDF writer of bearingsim: design-space maps (:func:`bearingsim.sweep.map_grid`) and dynamic runs
(:func:`bearingsim.dynamics.run.simulate`) are written by :class:`NetCDFWriter` from a schema of
:class:`Variable` s, and the in-memory results become :class:`xarray.Dataset` s with the same attributes
(:func:`to_xarray`).

Files
-----
A file is created under a hidden temporary name in the folder of its final name,
``.NAME.HOST-PID-RANDOM.part``, with mode 0666 filtered by the user's umask (as any file the user creates;
``mkstemp`` would give 0600, which the rename would carry over), and reaches its final name by one atomic
``os.replace``.  Leftovers of processes of this host that have ended (killed with SIGKILL) are removed
when the next file of the same name is created.  Two ways to publish:

* ``publish="close"`` (maps): every value is written into the temporary file, renamed by
  :meth:`NetCDFWriter.close`; :meth:`NetCDFWriter.abort` (an interrupt, an error) removes it, so the final
  name never holds a partial file.
* ``publish="create"`` (dynamic runs, a netCDF-3 64-bit-offset file with an unlimited ``time``): the header
  (dimensions, variables, attributes, fixed coordinates) is written into the temporary file and renamed at
  once; the records are then appended in place, each chunk synced (:meth:`NetCDFWriter.sync`).  netCDF-3
  keeps the record count in the header, rewritten at the sync, so a process killed inside a chunk leaves a
  file that ends with the last complete chunk; :meth:`NetCDFWriter.reopen` continues it (``--resume``).

Errors while the file is written are raised by ``error(final_path, exc)`` when the caller gives one (the
map: one-line :class:`~bearingsim.errors.InputError` on ``out``), otherwise as an :class:`OSError` naming the
final path (so that the CLI maps it to its ``--out`` option).

Units
-----
One spelling: every ``units`` attribute is a UDUNITS/CF string that pint parses
(``pint.UnitRegistry().parse_units``): ``N m`` (not ``N*m``), ``rad/s``, ``1`` for a ratio or a count.
A variable whose components carry different quantities (the 5-dof displacement x, y, z [m] and γy, γz
[rad]; the 5×5 stiffness; the applied load Fa, Fr [N] and M [N m]) has ``units = "1"`` — the one value that
is not wrong for the rotational components, and that a unit-aware reader accepts — and the unit of each
component in ``units_by_component``: comma-separated UDUNITS strings in the order of the component
dimension (row-major over the last two dimensions for a matrix).  Read a component's unit with
:func:`component_units`; do not convert a mixed variable with its ``units`` attribute.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

#: ``units`` of a variable whose components have different units (see ``units_by_component``)
MIXED_UNITS = "1"
#: separator of the entries of ``units_by_component`` (a UDUNITS string never holds a comma)
COMPONENT_SEPARATOR = ", "

#: units of the five degrees of freedom (x, y, z, gamma_y, gamma_z) and of their generalised forces
DOF_UNITS = ("m", "m", "m", "rad", "rad")
DOF_RATE_UNITS = ("m/s", "m/s", "m/s", "rad/s", "rad/s")
LOAD_UNITS = ("N", "N", "N", "N m", "N m")
#: K[i, j] = dF_i/dq_j [unit of F_i / unit of q_j]; the 5×5 stiffness, row-major
STIFFNESS_UNITS = tuple(tuple(f"{f}/{q}" for q in DOF_UNITS) for f in LOAD_UNITS)


def units_attributes(units) -> dict:
    """The unit attributes of a variable.

    ``units``: a UDUNITS string (→ ``{"units": units}``), None (no unit attribute: index and label
    variables), or the per-component units: a sequence over the last dimension, or a sequence of sequences
    over the last two (→ ``{"units": MIXED_UNITS, "units_by_component": "m, m, m, rad, rad"}``).  A sequence
    whose entries are all the same unit is written as that one unit.
    """
    if units is None:
        return {}
    if isinstance(units, str):
        return {"units": units}
    flat = [u for row in units for u in ([row] if isinstance(row, str) else row)]
    if len(set(flat)) == 1:
        return {"units": flat[0]}
    return {"units": MIXED_UNITS, "units_by_component": COMPONENT_SEPARATOR.join(flat)}


def component_units(attrs: dict, shape: tuple[int, ...] | None = None):
    """The per-component units of a variable from its attributes: a list (or, with the ``shape`` of the
    component dimensions, a nested list), or the ``units`` string when the variable has one unit."""
    by = attrs.get("units_by_component")
    if by is None:
        return attrs.get("units", "")
    flat = by.split(COMPONENT_SEPARATOR)
    if shape is None or len(shape) == 1:
        return flat
    return np.array(flat, dtype=object).reshape(shape).tolist()


#: largest netCDF-4 chunk the writers ask for [bytes]: HDF5 refuses a chunk of 4 GiB or more ("NetCDF: Bad chunk
#: sizes"), and a chunk larger than the library's chunk cache (a few MiB) is read back and written again by every
#: partial write that touches it
MAX_CHUNK_BYTES = 4 * 2**20


#: largest share of a dimension the chunks may pad past its end (HDF5 allocates whole chunks)
MAX_CHUNK_PADDING = 0.05


def _divisors(n: int) -> list[int]:
    small = [d for d in range(1, int(n ** 0.5) + 1) if n % d == 0]
    return sorted(set(small + [n // d for d in small]))


def capped_chunks(block: Sequence[int], extra: Sequence[int] = (), itemsize: int = 8,
                  max_bytes: int = MAX_CHUNK_BYTES, shape: Sequence[int] | None = None) -> tuple[int, ...]:
    """Chunk sizes of a variable of dimensions (grid dimensions, ``extra`` dimensions) written block by block.

    Along each grid dimension the chunk is a divisor of the ``block`` the writer stores at once (so that a block
    fills whole chunks and no chunk is read back): the largest one whose chunks pad the dimension's length in
    ``shape`` by at most :data:`MAX_CHUNK_PADDING` (HDF5 allocates whole chunks: 2000-point chunks on a
    3000-point axis would take a third more disk).  The ``extra`` dimensions (e.g. the 5 × 5 stiffness) are
    whole.  When a chunk is still more than ``max_bytes``, the outermost grid dimension above 1 is cut to its
    largest divisor that fits, then the next one inwards, and so on."""
    sizes = [max(1, int(n)) for n in block]
    if shape is not None:
        for k, n in enumerate(shape):
            n = max(1, int(n))
            sizes[k] = max(c for c in _divisors(sizes[k]) if -(-n // c) * c - n <= MAX_CHUNK_PADDING * n)
    per_point = int(itemsize) * int(np.prod([int(n) for n in extra], dtype=np.int64)) if extra else int(itemsize)
    for k in range(len(sizes)):
        rest = per_point * int(np.prod(sizes[k + 1:], dtype=np.int64))
        if rest * sizes[k] <= max_bytes:
            break
        room = max(1, max_bytes // rest)
        sizes[k] = max(d for d in _divisors(sizes[k]) if d <= room)
    return tuple(sizes) + tuple(int(n) for n in extra)


#: bytes of a netCDF-4 file besides its values: the HDF5 superblock, the header with the attributes, the chunk
#: index (50–60 kB for a map)
HEADER_BYTES = 64 * 1024


def expected_size(dims: dict, variables: Sequence[Variable]) -> int:
    """Bytes of a file of ``dims`` and ``variables`` as :class:`NetCDFWriter` writes them: the values
    (uncompressed; chunked variables in whole chunks; variable-length strings 16 bytes each) and
    :data:`HEADER_BYTES`."""
    total = HEADER_BYTES
    for v in variables:
        lengths = [int(dims[d] or 0) for d in v.dims]
        if v.chunks is not None:
            lengths = [-(-n // c) * c for n, c in zip(lengths, v.chunks)]
        n = int(np.prod(lengths, dtype=np.int64)) if v.dims else 1
        total += n * (16 if v.dtype is str else np.dtype(v.dtype).itemsize)
    return int(total)


def size_text(nbytes: float) -> str:
    """Bytes in the unit people read: ``"2.9 GB"``, ``"41 MB"``, ``"12 kB"`` (SI prefixes, as ``df -H``)."""
    for unit, f in (("TB", 1e12), ("GB", 1e9), ("MB", 1e6), ("kB", 1e3)):
        if nbytes >= f:
            return f"{nbytes / f:.2g} {unit}" if nbytes < 10 * f else f"{nbytes / f:.0f} {unit}"
    return f"{int(nbytes)} B"


@dataclass(frozen=True)
class Variable:
    """One variable of an output file.

    name, dims : netCDF name and dimension names
    units : see :func:`units_attributes` (a string, per-component units, or None)
    long_name : CF long name
    dtype : numpy dtype string (``"f8"``, ``"i4"``, ``"i1"``) or ``str`` (variable-length strings)
    attrs : further attributes (e.g. CF ``flag_masks``/``flag_meanings``)
    chunks : netCDF-4 chunk sizes (None: the library's choice)
    """

    name: str
    dims: tuple[str, ...]
    units: object = None
    long_name: str = ""
    dtype: object = "f8"
    attrs: dict = field(default_factory=dict)
    chunks: tuple[int, ...] | None = None

    def attributes(self) -> dict:
        out = units_attributes(self.units)
        if self.long_name:
            out["long_name"] = self.long_name
        return out | self.attrs


def _host() -> str:
    import socket

    return socket.gethostname().replace(".", "_").replace("-", "_") or "host"


def _part_prefix(final: Path) -> str:
    """Hidden temporary name of a file being written to ``final``: ``.NAME.HOST-PID-RANDOM.part``."""
    return f".{final.name}."


def create_part(final: Path) -> Path:
    """Create the temporary file of ``final`` in the same folder (so that the last step is an atomic
    rename) with mode 0666 filtered by the user's umask.  The name holds the host and process id, so that a
    later writer can recognise the leftover of a killed process (:func:`remove_stale_parts`)."""
    import secrets

    final = Path(final)
    for _ in range(100):
        tmp = final.parent / f"{_part_prefix(final)}{_host()}-{os.getpid()}-{secrets.token_hex(4)}.part"
        try:
            fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
        except FileExistsError:
            continue
        os.close(fd)
        return tmp
    raise FileExistsError(f"cannot create a temporary file next to {final}")  # pragma: no cover


def remove_stale_parts(final: Path) -> None:
    """Remove temporary files of ``final`` left by processes of this host that have ended (a process
    killed with SIGKILL cannot remove its own)."""
    final = Path(final)
    host = _host()
    prefix = _part_prefix(final)
    try:
        names = [p for p in final.parent.iterdir() if p.name.startswith(prefix) and p.name.endswith(".part")]
    except OSError:
        return
    for p in names:
        tag = p.name[len(prefix):-len(".part")].split("-")
        if len(tag) != 3 or tag[0] != host or not tag[1].isdigit():
            continue
        pid = int(tag[1])
        if pid == os.getpid():
            continue
        try:
            os.kill(pid, 0)
        except ProcessLookupError:
            p.unlink(missing_ok=True)
        except OSError:  # alive (e.g. another user's process): leave it
            pass


class NetCDFWriter:
    """One output file written in pieces (module docstring: temporary file, publishing, errors).

    Parameters
    ----------
    path : final file name
    dims : dimension name → length (None: unlimited)
    variables : the :class:`Variable` s, in file order
    values : name → the values of a variable known at creation (coordinates); written with the header
    attrs : global attributes
    fmt : netCDF format (``"NETCDF4"``; ``"NETCDF3_64BIT_OFFSET"`` for appended records)
    publish : ``"close"`` or ``"create"`` (module docstring)
    error : ``error(final_path, exc) -> Exception`` raised instead of an OSError/RuntimeError of the library
    """

    def __init__(self, path, *, dims: dict, variables: Sequence[Variable], values: dict | None = None,
                 attrs: dict | None = None, fmt: str = "NETCDF4", publish: str = "close",
                 error: Callable[[Path, BaseException], BaseException] | None = None):
        import netCDF4

        if publish not in ("close", "create"):
            raise ValueError(f"publish must be 'close' or 'create', got {publish!r}")
        self.final = Path(path)
        self.publish = publish
        self._error = error
        self.tmp = None
        self.nc = None
        try:
            remove_stale_parts(self.final)
            self.tmp = create_part(self.final)
            self.nc = netCDF4.Dataset(self.tmp, "w", format=fmt)
            self._define(dims, variables, values or {}, attrs or {})
            if publish == "create":
                self.nc.close()
                self.nc = None
                os.replace(self.tmp, self.final)
                self.tmp = None
                self.nc = netCDF4.Dataset(self.final, "a")
        except BaseException as exc:
            self.abort()
            if isinstance(exc, OSError | RuntimeError):
                raise self._failure(exc) from None
            raise

    @classmethod
    def reopen(cls, path, error: Callable[[Path, BaseException], BaseException] | None = None) -> NetCDFWriter:
        """Open an existing file written with ``publish="create"`` to append records to it (a resumed run)."""
        import netCDF4

        self = cls.__new__(cls)
        self.final, self.publish, self._error, self.tmp, self.nc = Path(path), "create", error, None, None
        try:
            self.nc = netCDF4.Dataset(self.final, "a")
        except (OSError, RuntimeError) as exc:
            raise self._failure(exc) from None
        return self

    def _define(self, dims: dict, variables: Sequence[Variable], values: dict, attrs: dict) -> None:
        for d, n in dims.items():
            self.nc.createDimension(d, n)
        for v in variables:
            if v.dtype is str:
                var = self.nc.createVariable(v.name, str, v.dims)
            else:
                var = self.nc.createVariable(v.name, v.dtype, v.dims, zlib=False, chunksizes=v.chunks)
            for k, a in v.attributes().items():
                var.setncattr(k, a)
            if v.name in values:
                val = values[v.name]
                if v.dtype is str:
                    var[:] = np.array(list(val), dtype=object)
                elif v.dims:
                    var[:] = val
                else:
                    var.assignValue(val)
        for k, a in attrs.items():
            self.nc.setncattr(k, a)

    def _failure(self, exc: BaseException) -> BaseException:
        if self._error is not None:
            return self._error(self.final, exc)
        errno = getattr(exc, "errno", None)
        return OSError(errno, f"{getattr(exc, 'strerror', None) or exc}", str(self.final))

    def length(self, dim: str) -> int:
        """The current length of dimension ``dim`` (the number of records of the unlimited one)."""
        return len(self.nc.dimensions[dim])

    def write(self, name: str, index, values) -> None:
        """Store ``values`` in variable ``name`` at ``index`` (a tuple of slices or a slice)."""
        try:
            self.nc.variables[name][index] = values
        except (OSError, RuntimeError) as exc:  # netCDF/HDF5 errors (full disk, I/O)
            raise self._failure(exc) from None

    def sync(self) -> None:
        """Flush to disk (for appended records: the header's record count too)."""
        try:
            self.nc.sync()
        except (OSError, RuntimeError) as exc:
            raise self._failure(exc) from None

    def close(self) -> None:
        """Close the file; with ``publish="close"`` give it the final name (one atomic rename)."""
        try:
            if self.nc is not None:
                self.nc.close()
                self.nc = None
            if self.tmp is not None:
                os.replace(self.tmp, self.final)
                self.tmp = None
        except (OSError, RuntimeError) as exc:
            self.abort()
            raise self._failure(exc) from None

    def abort(self) -> None:
        """Close and remove the temporary file (the final name is never created by an aborted writer; a
        published file of appended records stays as it is, ending with its last synced chunk)."""
        if self.nc is not None:
            try:
                self.nc.close()
            except Exception:  # noqa: BLE001  (already closed or broken: remove the file anyway)
                pass
            self.nc = None
        if self.tmp is not None:
            try:
                self.tmp.unlink(missing_ok=True)
            except OSError:
                pass
            self.tmp = None


def to_xarray(variables: Sequence[Variable], data: dict, attrs: dict | None = None, coords: Sequence[str] = ()):
    """An :class:`xarray.Dataset` of in-memory results with the attributes a file written from the same
    schema has: ``data`` name → values; the variables named in ``coords`` become coordinates (a scalar one
    where its ``dims`` are empty)."""
    import xarray as xr

    cvars, dvars = {}, {}
    for v in variables:
        if v.name not in data:
            continue
        val = data[v.name]
        if v.dtype is str:
            val = list(val)
        elif not v.dims:
            val = float(val) if np.dtype(v.dtype).kind == "f" else val
        (cvars if v.name in coords else dvars)[v.name] = (v.dims, val, v.attributes())
    return xr.Dataset(dvars, coords=cvars, attrs=attrs or {})


__all__ = ["COMPONENT_SEPARATOR", "DOF_RATE_UNITS", "DOF_UNITS", "HEADER_BYTES", "LOAD_UNITS", "MAX_CHUNK_BYTES",
           "MAX_CHUNK_PADDING", "MIXED_UNITS", "STIFFNESS_UNITS", "NetCDFWriter", "Variable", "capped_chunks",
           "component_units", "create_part", "expected_size", "remove_stale_parts", "size_text", "to_xarray",
           "units_attributes"]
