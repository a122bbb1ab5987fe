"""Exception types of bearingsim.

Bad input is an exception (:class:`InputError`), naming the field and the fix.
A solver that does not converge returns a result with ``converged = False``;
:class:`ConvergenceError` is raised only where a caller asked for a converged
answer and none could be had.
"""

from __future__ import annotations

import enum


class ExitCode(enum.IntEnum):
    """Exit status of the ``bearingsim`` command (the one table; :func:`bearingsim.cli.errors.report_error`
    maps every exception to one of them and one line on stderr)."""

    OK = 0
    #: the command ran but its answer is not the asked one (a solver did not converge; a map with
    #: unconverged points), or an internal error (a bug: one line naming it, BEARINGSIM_DEBUG=1 shows it)
    FAILED = 1
    #: the command could not start: bad command line (unknown option or command, missing argument, bad
    #: option value), bad input (:class:`InputError`), an unreadable input or unwritable output file
    USAGE = 2
    #: interrupted by the user (Ctrl-C)
    INTERRUPTED = 130
    #: the reader of standard output closed it early (``| head``): 128 + SIGPIPE, as shell tools end then — not
    #: FAILED, which a script would read as "not converged"
    BROKEN_PIPE = 141


class BearingSimError(Exception):
    """Base class of every error raised on purpose by bearingsim.

    Parameters
    ----------
    *args : str
        The message, as for :class:`Exception`.
    """


class InputError(BearingSimError, ValueError):
    """Invalid user input.

    Parameters
    ----------
    field : str
        Name of the offending input field (as the user wrote it).
    problem : str
        What is wrong with it.
    fix : str
        How to correct it.
    """

    def __init__(self, field: str, problem: str, fix: str = ""):
        self.field = field
        self.problem = problem
        self.fix = fix
        msg = f"{field}: {problem}"
        if fix:
            msg += f" ({fix})"
        super().__init__(msg)


class ConvergenceError(BearingSimError, RuntimeError):
    """A solver did not converge where a converged answer was required.

    Parameters
    ----------
    message : str
        Which solver did not converge, and why.
    residual : float
        The residual it ended with (NaN when unknown); kept as ``self.residual``.
    iterations : int
        The iterations it took; kept as ``self.iterations``.
    """

    def __init__(self, message: str, *, residual: float = float("nan"), iterations: int = 0):
        self.residual = residual
        self.iterations = iterations
        super().__init__(f"{message} (residual {residual:.3g} after {iterations} iterations)")


class InputTypeError(InputError, TypeError):
    """Invalid user input of the wrong type (a str, bool, None or list where a number is expected)."""
