"""What the commands show on the terminal besides their results: a rich console wide enough for pipes, and the
one-time note on stderr while numba compiles kernels on a first run (:func:`announce_compilation`)."""

from __future__ import annotations

import sys


def make_console(stderr: bool = False):
    """A rich Console; 160 columns wide when the output is not a terminal (pipes, files, CI logs),
    so that tables are not truncated to 80 columns."""
    from rich.console import Console

    class _Console(Console):
        def on_broken_pipe(self) -> None:
            """stdout's reader has gone (``| head``): rich's own handling ends with status 1, which this command
            line reserves for "not converged"; end with :attr:`~bearingsim.errors.ExitCode.BROKEN_PIPE` instead."""
            from ..errors import ExitCode

            self.quiet = True
            quiet_stdout()
            raise SystemExit(ExitCode.BROKEN_PIPE)

    con = _Console(stderr=stderr)
    if not con.is_terminal:
        con = _Console(stderr=stderr, width=160)
    return con


def status_text(converged: bool, status: str, iterations: int, residual: float, unit: str = "N") -> str:
    """The solver line of every command: "converged (residual 6.1e-12 N, 8 iterations)", or "NOT CONVERGED:
    reason (residual …, … iterations)" (rich markup) — the reason only when it says more than the verdict."""
    tail = f"residual {residual:.2g} {unit}, {iterations} iterations"
    if converged:
        extra = "" if str(status).strip().lower() in ("", "converged") else f"{status}; "
        return f"converged ({extra}{tail})"
    return f"[red]NOT CONVERGED[/]: {status} ({tail})"


def quiet_stdout() -> None:
    """Point stdout at the null device (its reader has gone), so that nothing written later, nor Python's flush at
    exit, fails again (the recipe of the Python docs' note on SIGPIPE)."""
    import os
    import sys

    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError, AttributeError):
        pass


class _CompileNote:
    """numba listener: says once, on stderr, that kernels are being compiled (a cache miss: first run after an
    install or a change of the kernels), with a count on a terminal, and how long it took at the end.  Only
    bearingsim's kernels are counted (numba compiles some of its own helpers inside them); kernels without
    ``cache=True`` are counted apart, since they compile on every run — unless they are compiled inside a cached
    kernel (the integrators inside their cached specialisations, :mod:`bearingsim.dynamics.integrate.specialised`),
    whose disk cache holds them: the next run loads that kernel and compiles neither."""

    HEAD = "compiling numerical kernels"

    def __init__(self):
        self.cached = 0
        self.uncached = 0
        self.inside = 0  #: cached kernels being compiled now (a kernel compiled inside one is cached with it)
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
                name, cached = k
                note.start(name, cached or note.inside > 0)
                note.inside += cached

        def on_end(self, ev):
            k = kernel(ev)
            if k is not None:
                cached = k[1]
                note.inside -= cached
                note.end(cached or note.inside > 0)

    event.register("numba:compile", _Listener())
    _NOTE = note


def finish_compilation_note() -> None:
    """Close the compilation note (its last line) if kernels were compiled in this process."""
    if _NOTE is not None:
        _NOTE.finish()
