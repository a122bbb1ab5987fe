"""Command-line interface (typer + rich): the ``bearingsim`` app and its entry point :func:`main`.

Thin: parse, call the API, print.  The package:

* :mod:`.options` — option types shared by the commands (bearing, loads, speed, control, --out), each declared once;
* :mod:`.errors` — every exception that ends a command becomes one line on stderr and an exit status of
  :class:`~bearingsim.errors.ExitCode` (usage errors and bad input 2, failures 1, Ctrl-C 130) — never a
  traceback, unless ``BEARINGSIM_DEBUG=1``;
* :mod:`.output` — output paths checked before computing, atomic writes; :mod:`.console` — rich console and the
  first-run compilation note;
* one module per command group, module-level command functions registered here: :mod:`.catalog` (catalog),
  :mod:`.clearance` (clearance), :mod:`.static` (static, reproduce spindle-axial-stiffness), :mod:`.sweep` (map,
  export ross, reproduce hub-static), :mod:`.dynamics`
  (simulate), :mod:`.hysteresis` (reproduce hub-hysteresis), :mod:`.lubrication` (lubrication, lubricants,
  traction-curve), :mod:`.cage` (cage-modes).

Importing this package loads typer only: the numerical libraries are imported inside the commands, so that
``bearingsim --version``, ``--help`` and usage errors stay fast.  No module of the package imports from here.
"""

from __future__ import annotations

import signal
import sys
import threading

import typer

from . import cage, catalog, clearance, dynamics, hysteresis, lubrication, report, shaft, static, sweep
from .options import SingleUseOptions

app = typer.Typer(add_completion=False, no_args_is_help=True, cls=SingleUseOptions,
                  help="bearingsim: ball bearing statics, stiffness, lubrication and dynamics.")
reproduce_app = typer.Typer(no_args_is_help=True, cls=SingleUseOptions,
                            help="Reproduce the published studies (references in docs/references.md).")
app.add_typer(reproduce_app, name="reproduce")


def _print_version(value: bool) -> None:
    if value:
        from .. import __version__

        typer.echo(f"bearingsim {__version__}")
        raise typer.Exit(0)


@app.callback()
def _root(
    version: bool = typer.Option(False, "--version", callback=_print_version, is_eager=True,
                                 help="Print the version and exit"),
):
    """bearingsim: ball bearing statics, stiffness, lubrication and dynamics."""


catalog.register(app)
clearance.register(app)
static.register(app, reproduce_app)
cage.register(app)
lubrication.register(app)
sweep.register(app, reproduce_app)
dynamics.register(app, reproduce_app)
hysteresis.register(app, reproduce_app)
report.register(app)
shaft.register(app)


#: exit status after SIGTERM: 128 + the signal's number, as a shell reports a process ended by it
TERMINATED = 128 + signal.SIGTERM


def _terminated(signum, frame) -> None:
    """SIGTERM handler of the command: raise ``SystemExit(TERMINATED)`` in the main thread, so that the command
    unwinds like any error (a map's process pool shuts down and joins its workers, its temporary file is
    removed, a run keeps its last checkpoint); a second SIGTERM during that ends the process at once."""
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    raise SystemExit(TERMINATED)


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``bearingsim`` script: every error ends in one line on stderr and the exit status of
    :class:`~bearingsim.errors.ExitCode` (:func:`bearingsim.cli.errors.report_error`); SIGTERM ends the command
    cleanly with status 143 and the line ``terminated``."""
    from ..errors import ExitCode
    from .console import finish_compilation_note
    from .errors import report_error

    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGTERM, _terminated)
    try:
        rc = app(args=argv, prog_name="bearingsim", standalone_mode=False)
    except SystemExit as exc:
        finish_compilation_note()
        if exc.code == TERMINATED:
            typer.echo("terminated", err=True)
        if exc.code == 1 and type(sys.stdout).__name__ == "PacifyFlushWrapper":
            # click's own handling of a broken stdout (typer.echo): status 1 with stdout wrapped to write nothing
            from .console import quiet_stdout

            quiet_stdout()
            sys.exit(ExitCode.BROKEN_PIPE)
        raise
    except BrokenPipeError:  # stdout's reader has gone (`| head`): end quietly, as shell tools do
        from .console import quiet_stdout

        quiet_stdout()
        sys.exit(ExitCode.BROKEN_PIPE)
    except BaseException as exc:  # noqa: BLE001 - the one place where an error becomes a line and a status
        finish_compilation_note()
        sys.exit(report_error(exc))
    finish_compilation_note()
    if isinstance(rc, int) and rc != 0:  # typer.Exit(code) comes back as a return value
        if rc == ExitCode.INTERRUPTED:  # typer turns Ctrl-C into Exit(130)
            typer.echo("aborted", err=True)
        sys.exit(rc)


__all__ = ["app", "main", "reproduce_app"]


if __name__ == "__main__":  # pragma: no cover
    main()
