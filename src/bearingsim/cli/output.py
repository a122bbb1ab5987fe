"""Small helpers shared by the command-line modules.

* option types used by several commands;
* :func:`report_error` — every exception that ends a command becomes ONE line on stderr and an exit status
  from :class:`bearingsim.errors.ExitCode` (usage errors and bad input 2, failures 1, Ctrl-C 130);
* output paths — :func:`output_file` / :func:`output_folder` create missing parent folders and check that the
  file can be written BEFORE the command computes anything; :func:`atomic_output` writes through a temporary
  file renamed at the end (a full disk or a crash leaves no half-written file), with the user's umask;
* :func:`announce_compilation` — a one-time note on stderr while numba compiles kernels on a first run.
"""

from __future__ import annotations

import contextlib
import errno
import os
import sys
from pathlib import Path
from typing import Annotated, Iterator, Optional

import typer

from .errors import BearingSimError, ExitCode, InputError

# Options shared by the commands that take one operating point (static, lubrication); strings with units,
# bare numbers in N, N·m and rpm (parse_loads).
BearingArg = Annotated[str, typer.Argument(help="Catalogue name or TOML file")]
FaOpt = Annotated[Optional[str], typer.Option("--fa", help='Axial load along +x, e.g. "1000 N"')]
FrOpt = Annotated[Optional[str], typer.Option("--fr", help="Radial load along +y")]
FzOpt = Annotated[Optional[str], typer.Option("--fz", help="Radial load along +z")]
MomentOpt = Annotated[Optional[str], typer.Option("--moment", help='Moment about z, e.g. "1 N*m"')]
MyOpt = Annotated[Optional[str], typer.Option("--my", help="Moment about y")]
SpeedOpt = Annotated[Optional[str], typer.Option("--speed", help='Inner-ring speed, e.g. "11200 rpm"')]
ControlOpt = Annotated[str, typer.Option("--control", help="Raceway control: outer, inner or auto")]

#: environment variable: when set to 1, errors are re-raised with their traceback (for developers)
DEBUG_ENV = "BEARINGSIM_DEBUG"
#: where a user reports an internal error
REPORT_TO = "the bearingsim issue tracker"


def make_console(stderr: bool = False):
    """A rich Console; 160 columns wide when the output is not a terminal (pipes, files, CI logs),
    so that tables are not truncated to 80 columns."""
    from rich.console import Console

    con = Console(stderr=stderr)
    if not con.is_terminal:
        con = Console(stderr=stderr, width=160)
    return con


def parse_loads(fa, fr, fz, moment, my):
    """CLI load options (strings with units; bare numbers in N and N·m) → Loads."""
    from .statics.jones_harris import Loads
    from .units import parse_quantity

    return Loads(
        fa=parse_quantity(fa, "force", "--fa") if fa is not None else 0.0,
        fr_y=parse_quantity(fr, "force", "--fr") if fr is not None else 0.0,
        fr_z=parse_quantity(fz, "force", "--fz") if fz is not None else 0.0,
        m_y=parse_quantity(my, "moment", "--my") if my is not None else 0.0,
        m_z=parse_quantity(moment, "moment", "--moment") if moment is not None else 0.0,
    )


# ---- errors: one line, one exit status ----------------------------------------------------------------------
def debug_enabled() -> bool:
    """True when ``BEARINGSIM_DEBUG`` asks for tracebacks."""
    return os.environ.get(DEBUG_ENV, "").strip().lower() not in ("", "0", "false", "no")


def _click_exception_types() -> tuple[type, ...]:
    """``ClickException`` of every click in this process: typer ≥ 0.20 bundles its own (``typer._click``), older
    typer uses the click package — an ``except click.ClickException`` alone misses the bundled one."""
    types = []
    for mod in ("typer._click.exceptions", "click.exceptions"):
        m = sys.modules.get(mod)
        if m is None and mod.startswith("typer."):
            try:
                import importlib

                m = importlib.import_module(mod)
            except ImportError:
                m = None
        if m is not None and hasattr(m, "ClickException"):
            types.append(m.ClickException)
    return tuple(types)


def _one_line(text: str, limit: int = 400) -> str:
    s = " ".join(str(text).split())
    return s if len(s) <= limit else s[: limit - 1] + "…"


def _usage_line(exc) -> str:
    """``error: <click's message>`` with its "did you mean" / possible options, and where help is."""
    msg = exc.format_message()
    ctx = getattr(exc, "ctx", None)
    hint = ""
    if ctx is not None:
        try:
            if ctx.command.get_help_option(ctx) is not None:
                hint = f" (see '{ctx.command_path} {ctx.help_option_names[0]}')"
        except Exception:  # noqa: BLE001 - a hint must never replace the error itself
            hint = ""
    return _one_line(f"error: {msg}{hint}")


def _os_error_line(exc: OSError) -> str:
    what = exc.strerror or str(exc)
    name = exc.filename if exc.filename is not None else ""
    return _one_line(f"error: {name}: {what}" if name else f"error: {what}")


def error_message(exc: BaseException) -> tuple[str | None, int]:
    """The one line (None: already shown, e.g. help) and the exit status for an exception that ended a command.

    The single table of messages and exit codes of the command line:

    ===============================================  =========================================  ======
    exception                                         line on stderr                              status
    ===============================================  =========================================  ======
    click/typer usage error (unknown option or        ``error: No such command 'statc'. Did you   2
    command, missing argument, bad option value)      mean 'static'? (see 'bearingsim --help')``
    :class:`~bearingsim.errors.InputError`            ``error: --fa: ...``                        2
    :class:`OSError` reaching the top (a file)        ``error: FILE: Permission denied``          2
    other :class:`~bearingsim.errors.BearingSimError` ``error: ...``                              1
    :class:`MemoryError`                              ``error: out of memory ...``                1
    KeyboardInterrupt / Abort                         ``aborted``                                 130
    anything else (a bug)                             ``error: internal error (...) — report``    1
    ===============================================  =========================================  ======
    """
    if isinstance(exc, KeyboardInterrupt | typer.Abort):
        return "aborted", ExitCode.INTERRUPTED
    if isinstance(exc, typer.Exit):
        return None, int(exc.exit_code)
    click_types = _click_exception_types()
    if click_types and isinstance(exc, click_types):
        code = int(getattr(exc, "exit_code", ExitCode.USAGE))
        if type(exc).__name__ == "NoArgsIsHelpError":  # `bearingsim` or `bearingsim reproduce` alone: the help
            return None, code
        return _usage_line(exc), (ExitCode.USAGE if code == ExitCode.USAGE else code)
    if isinstance(exc, InputError):
        return _one_line(f"error: {exc}"), ExitCode.USAGE
    if isinstance(exc, BearingSimError):
        return _one_line(f"error: {exc}"), ExitCode.FAILED
    if isinstance(exc, OSError):
        return _os_error_line(exc), ExitCode.USAGE
    if isinstance(exc, MemoryError):
        return ("error: out of memory (a grid or a run too large for this machine: use fewer points, a smaller "
                "--chunk or a shorter run)"), ExitCode.FAILED
    from . import __version__

    return _one_line(f"error: internal error in bearingsim {__version__} ({type(exc).__name__}: {exc}); please "
                     f"report it to {REPORT_TO} with the command line (rerun with {DEBUG_ENV}=1 for the traceback)",
                     limit=600), ExitCode.FAILED


def report_error(exc: BaseException) -> int:
    """Show ``exc`` as :func:`error_message` says (help for a bare group) and return the exit status.

    With ``BEARINGSIM_DEBUG=1`` every error except a usage error and Ctrl-C is re-raised (full traceback)."""
    line, code = error_message(exc)
    if line is None and type(exc).__name__ == "NoArgsIsHelpError":
        text = exc.format_message()  # typer's rich help is printed while formatting and comes back empty
        if text.strip():
            typer.echo(text)
        return code
    click_types = _click_exception_types()
    usage = bool(click_types) and isinstance(exc, click_types)
    if debug_enabled() and not usage and not isinstance(exc, KeyboardInterrupt | typer.Abort | typer.Exit):
        raise exc
    if line is not None:
        typer.echo(line, err=True)
    return code


# ---- output paths ------------------------------------------------------------------------------------------
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


def output_file(path, option: str = "--out", *, renamed: bool = False) -> Path:
    """Prepare the output FILE ``path``: create missing parent folders and check, before any computing, that the
    file can be written (an existing regular file is opened for appending and closed: nothing changes).

    ``renamed``: the writer creates a temporary file next to ``path`` and renames it onto ``path`` (the netCDF
    writers of ``map`` and ``simulate``); then ``path`` must not be a device or a pipe — the rename would put a
    regular file in place of ``/dev/null`` (as root)."""
    p = Path(path).expanduser()
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


def apply_umask(path) -> None:
    """Give a finished output file the mode a new file gets from the user's umask (writers that go through
    ``tempfile.mkstemp`` leave 0600)."""
    with contextlib.suppress(OSError):
        os.chmod(path, 0o666 & ~_umask())


# ---- first-run compilation note ------------------------------------------------------------------------------
class _CompileNote:
    """numba listener: says once, on stderr, that kernels are being compiled (a cache miss: first run after an
    install or a change of the kernels), with a count on a terminal, and how long it took at the end.  Only
    bearingsim's kernels are counted (numba compiles some of its own helpers inside them); kernels without
    ``cache=True`` are counted apart, since they compile on every run."""

    HEAD = "compiling numerical kernels"

    def __init__(self):
        self.cached = 0
        self.uncached = 0
        self.t0 = None
        self.tty = False

    def start(self, name: str, cached: bool) -> None:
        import time

        if self.t0 is None:
            self.t0 = time.perf_counter()
            self.tty = bool(getattr(sys.stderr, "isatty", lambda: False)())
            what = " (first run only, or after an update; typically 10–60 s)" if cached else ""
            self._write(f"{self.HEAD}{what}…" + ("" if self.tty else "\n"))
        if self.tty:
            self._write(f"\r\x1b[2K{self.HEAD}: {self.cached + self.uncached} done, now {name}…")

    def end(self, cached: bool) -> None:
        if cached:
            self.cached += 1
        else:
            self.uncached += 1

    def finish(self) -> None:
        import time

        if self.t0 is None:
            return
        dt = time.perf_counter() - self.t0
        n = self.cached + self.uncached
        tail = "cached for the next runs" if not self.uncached else (
            f"{self.uncached} of them without a disk cache, compiled on every run")
        self._write(("\r\x1b[2K" if self.tty else "") + f"compiled {n} kernels in {dt:.0f} s ({tail})\n")
        self.t0 = None
        self.cached = self.uncached = 0

    @staticmethod
    def _write(text: str) -> None:
        try:
            sys.stderr.write(text)
            sys.stderr.flush()
        except (OSError, ValueError):
            pass


_NOTE: _CompileNote | None = None


def announce_compilation() -> None:
    """Install (once per process) the numba listener of :class:`_CompileNote`.  Call it at the start of a command
    that runs compiled kernels; it imports numba (which such a command imports anyway)."""
    global _NOTE
    if _NOTE is not None:
        return
    from numba.core import event

    note = _CompileNote()

    def kernel(ev):
        """(name, cached) of a bearingsim kernel being compiled, None for numba's own helpers."""
        disp = (ev.data or {}).get("dispatcher")
        func = getattr(disp, "py_func", None)
        if not str(getattr(func, "__module__", "")).startswith("bearingsim"):
            return None
        return func.__name__, type(getattr(disp, "_cache", None)).__name__ not in ("NullCache", "NoneType")

    class _Listener(event.Listener):
        def on_start(self, ev):
            k = kernel(ev)
            if k is not None:
                note.start(*k)

        def on_end(self, ev):
            k = kernel(ev)
            if k is not None:
                note.end(k[1])

    event.register("numba:compile", _Listener())
    _NOTE = note


def finish_compilation_note() -> None:
    """Close the compilation note (its last line) if kernels were compiled in this process."""
    if _NOTE is not None:
        _NOTE.finish()
