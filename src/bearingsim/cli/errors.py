"""Errors of the command line, in one place: every exception that ends a command becomes ONE line on stderr and
an exit status of :class:`bearingsim.errors.ExitCode` (usage errors and bad input 2, failures 1, Ctrl-C 130).

:func:`error_message` is the table; :func:`report_error` shows the line (:func:`bearingsim.cli.main` calls it).
"""

from __future__ import annotations

import os
import sys

import typer

from ..errors import BearingSimError, ExitCode, InputError

#: environment variable: when set to 1, errors are re-raised with their traceback (for developers)
DEBUG_ENV = "BEARINGSIM_DEBUG"
#: where a user reports an internal error
REPORT_TO = "the bearingsim issue tracker"

__all__ = ["DEBUG_ENV", "REPORT_TO", "ExitCode", "debug_enabled", "error_message", "report_error"]


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


#: the library's argument names whose command-line option is spelled otherwise
OPTION_OF = {"chunk_points": "--chunk", "n": "--node"}


def _option_of(field: str, argv: list[str]) -> str:
    """The command-line option for an :class:`InputError`'s field: the library names its arguments (``fr``,
    ``control``, ``workers``, ``chunk_points``), the user typed options (``--fr``, ``--chunk``) — the option when the
    command line holds it, else the field as it is."""
    if field.startswith("-") or not field.isidentifier():
        return field
    given = {a.split("=", 1)[0] for a in argv if a.startswith("--")}
    for opt in (OPTION_OF.get(field), "--" + field.replace("_", "-")):
        if opt is not None and opt in given:
            return opt
    return field


def _input_line(exc: InputError, argv: list[str] | None = None) -> str:
    """``error: FIELD: PROBLEM (FIX)`` on one line; a long problem (it may quote a pasted value) is shortened, never
    the field or the fix."""
    field = _option_of(str(exc.field), list(sys.argv[1:] if argv is None else argv))
    fix = f" ({' '.join(str(exc.fix).split())})" if exc.fix else ""
    return f"error: {field}: {_one_line(exc.problem, limit=240)}{fix}"


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
        return _input_line(exc), ExitCode.USAGE
    if isinstance(exc, BearingSimError):
        return _one_line(f"error: {exc}"), ExitCode.FAILED
    if isinstance(exc, OSError):
        return _os_error_line(exc), ExitCode.USAGE
    if isinstance(exc, MemoryError):
        return ("error: out of memory (a grid or a run too large for this machine: use fewer points, a smaller "
                "--chunk or a shorter run)"), ExitCode.FAILED
    from .. import __version__

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
