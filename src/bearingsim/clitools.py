"""Small helpers shared by the command-line modules."""

from __future__ import annotations


def make_console(stderr: bool = False):
    """A rich Console; 160 columns wide when the output is not a terminal (pipes, files, CI logs),
    so that tables are not truncated to 80 columns."""
    from rich.console import Console

    con = Console(stderr=stderr)
    if not con.is_terminal:
        con = Console(stderr=stderr, width=160)
    return con
