"""Output paths of the commands.

:func:`output_file` / :func:`output_folder` create missing parent folders and check that the file can be written
BEFORE the command computes anything; :func:`atomic_output` writes through a temporary file renamed at the end (a
full disk or a crash leaves no half-written file), with the user's umask; :func:`writing` turns an OSError about an
output into the one-line :class:`~bearingsim.errors.InputError` naming the option.
"""

from __future__ import annotations

import contextlib
import errno
import os
from pathlib import Path
from typing import Iterator

from ..errors import InputError


def _write_fix(err: OSError) -> str:
    e = err.errno
    if e == errno.ENOSPC or e == errno.EDQUOT:
        return "free disk space or write to another folder"
    if e in (errno.EACCES, errno.EPERM, errno.EROFS):
        return "choose a folder you can write to"
    if e == errno.ENOTDIR:
        return "a part of the path is a file, not a folder: choose another path"
    if e == errno.EISDIR:
        return "give a file name, not a folder"
    return "choose another path"


def write_error(option: str, path, err: OSError) -> InputError:
    """The :class:`InputError` for an output that cannot be written (field = the option naming the path)."""
    return InputError(option, f"cannot write {path}: {err.strerror or err}", _write_fix(err))


@contextlib.contextmanager
def writing(option: str, path) -> Iterator[None]:
    """Map an OSError about ``path`` (or a file named after it: ``OUT.tmp``, ``OUT.ckpt.npz``, files in the
    folder ``path``) raised by the block to the :class:`InputError` of :func:`write_error`; other OSErrors
    (an input file) pass unchanged."""
    try:
        yield
    except OSError as err:
        name = err.filename
        if name is None or str(Path(os.fsdecode(name)).expanduser()).startswith(str(Path(path).expanduser())):
            raise write_error(option, path, err) from None
        raise


def _umask() -> int:
    old = os.umask(0o022)
    os.umask(old)
    return old


def _probe_folder(folder: Path) -> None:
    """Create a file in ``folder`` and remove it (an actual write: ``os.access`` says yes to root on read-only
    mounts and on folders with mode 0555)."""
    import tempfile

    tempfile.TemporaryFile(dir=folder).close()


def _check_ancestors(folder: Path, option: str) -> None:
    """The nearest existing ancestor of ``folder`` (itself included) must be a folder."""
    q = folder
    while not q.exists() and q != q.parent:
        q = q.parent
    if q.exists() and not q.is_dir():
        raise InputError(option, f"cannot create the folder {folder}: {q} is a file", "choose another path")


def output_folder(path, option: str = "--out") -> Path:
    """Create the output folder ``path`` (and its parents) and check that files can be written in it."""
    p = Path(path).expanduser()
    try:
        _check_ancestors(p, option)
        p.mkdir(parents=True, exist_ok=True)
        _probe_folder(p)
    except OSError as err:
        raise write_error(option, p, err) from None
    return p


#: the file types of the commands' outputs, by suffix ("" = none): netCDF (``map``, ``simulate``), figures (what
#: matplotlib writes; no suffix writes a PNG), the ROSS export (JSON, or a .toml BearingElement)
NETCDF_SUFFIXES = (".nc",)
FIGURE_SUFFIXES = ("", ".png", ".pdf", ".svg", ".svgz", ".eps", ".ps", ".jpg", ".jpeg", ".tif", ".tiff", ".webp",
                   ".gif", ".avif", ".pgf")
ROSS_SUFFIXES = (".json", ".toml")


def check_suffix(path, option: str, suffixes: tuple[str, ...]) -> None:
    """An :class:`InputError` naming ``option`` when the output file ``path`` ends in none of ``suffixes`` (a folder,
    a device or a pipe, e.g. ``/dev/null``, is taken whatever its name)."""
    p = Path(path).expanduser()
    if p.suffix.lower() in suffixes or (p.exists() and not p.is_file()):
        return
    kinds = ", ".join(x for x in suffixes if x) + (" or none" if "" in suffixes else "")
    raise InputError(option, f"{p.name!r}: this output cannot be written as {p.suffix or 'a file without suffix'}",
                     f"give a name ending in {kinds}")


def output_file(path, option: str = "--out", *, renamed: bool = False, suffixes: tuple[str, ...] | None = None
                ) -> Path:
    """Prepare the output FILE ``path``: create missing parent folders and check, before any computing, that the
    file can be written (an existing regular file is opened for appending and closed: nothing changes).

    ``suffixes``: the file types the command writes (e.g. :data:`NETCDF_SUFFIXES`); another suffix is an
    :class:`InputError` before anything is computed or created (a device or a pipe, e.g. ``/dev/null``, is taken
    whatever its name), so that a map is not written as netCDF under a .csv name and a figure under .txt does not
    fail after the map is computed.

    ``renamed``: the writer creates a temporary file next to ``path`` and renames it onto ``path`` (the netCDF
    writers of ``map`` and ``simulate``); then ``path`` must not be a device or a pipe — the rename would put a
    regular file in place of ``/dev/null`` (as root)."""
    p = Path(path).expanduser()
    if suffixes is not None:
        check_suffix(p, option, suffixes)
    try:
        if p.is_dir():
            raise InputError(option, f"{p} is a folder", "give a file name, e.g. out/map.nc")
        parent = p.parent
        _check_ancestors(parent, option)
        parent.mkdir(parents=True, exist_ok=True)
        if p.exists() and not p.is_file():  # a device or a pipe: never opened here (a pipe would block)
            if renamed:
                raise InputError(option, f"{p} is not a regular file",
                                 "give a file name: this output is written under a temporary name and renamed")
            if not os.access(p, os.W_OK):
                raise OSError(errno.EACCES, os.strerror(errno.EACCES), str(p))
        elif p.exists():
            with open(p, "ab"):
                pass
        else:
            _probe_folder(parent)
    except OSError as err:
        raise write_error(option, p, err) from None
    return p


@contextlib.contextmanager
def atomic_output(path, option: str = "--out", default_suffix: str = "") -> Iterator[Path]:
    """Yield a temporary path for the writer of the output file ``path``; on success the temporary file becomes
    ``path`` (renamed, with the mode the user's umask gives a new file), on any error it is removed and an OSError
    becomes an :class:`InputError` naming ``option`` — a full disk or a crash leaves no half-written file.

    The temporary name ends with ``path``'s suffix (or ``default_suffix`` when ``path`` has none: matplotlib picks
    the format from the suffix and would otherwise append ".png" to the name).  A target that exists and is not a
    regular file (``/dev/null``, ``/dev/full``, a pipe) is written by copying the finished temporary file into it,
    with the write errors checked."""
    import shutil
    import tempfile

    p = output_file(path, option)
    special = p.exists() and not p.is_file()
    folder = Path(tempfile.gettempdir()) if special else p.parent
    try:
        fd, name = tempfile.mkstemp(prefix=f".{p.name}.", suffix=f".part{p.suffix or default_suffix}", dir=folder)
        os.close(fd)
    except OSError as err:
        raise write_error(option, p, err) from None
    tmp = Path(name)
    try:
        yield tmp
        if special:
            with open(tmp, "rb") as src, open(p, "wb") as dst:
                shutil.copyfileobj(src, dst)
            tmp.unlink()
        else:
            os.chmod(tmp, 0o666 & ~_umask())
            os.replace(tmp, p)
    except OSError as err:
        tmp.unlink(missing_ok=True)
        raise write_error(option, p, err) from None
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_study(study, folder: Path, csv_name: str, png_name: str, option: str = "--out") -> tuple[Path, Path]:
    """Write a study's table (``study.to_csv``) and figure (``study.plot``) into ``folder``, each through
    :func:`atomic_output`; returns the two paths.  Used by every ``reproduce`` command."""
    csv, png = Path(folder) / csv_name, Path(folder) / png_name
    with atomic_output(csv, option) as tmp:
        study.to_csv(tmp)
    with atomic_output(png, option) as tmp:
        study.plot(tmp)
    return csv, png


def apply_umask(path) -> None:
    """Give a finished output file the mode a new file gets from the user's umask (writers that go through
    ``tempfile.mkstemp`` leave 0600)."""
    with contextlib.suppress(OSError):
        os.chmod(path, 0o666 & ~_umask())
