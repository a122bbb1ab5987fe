"""What a new user hit (issue 42, command-line half), each through the installed console script."""

from __future__ import annotations

import pytest

from _cli import run  # tests/unit/_cli.py: the installed console script


@pytest.mark.parametrize("argv, option", [
    (("static", "6205", "--fr", "2000", "--fr", "3000"), "--fr"),
    (("static", "6205", "--fr=2000", "--speed", "1500", "--fr", "3000"), "--fr"),
    (("lubrication", "6205", "--fa", "1000", "--fa", "2000"), "--fa"),
    (("map", "6205", "--speed", "0:10:3", "--speed", "5"), "--speed"),
    (("reproduce", "hub-hysteresis", "case.toml", "--speeds", "10", "--speeds", "50"), "--speeds"),
    (("static", "6205", "--json", "--json"), "--json"),
])
def test_a_repeated_option_is_a_usage_error(argv, option):
    """`--fr 2000 --fr 3000` is refused (exit 2, one line naming the option), for every command alike."""
    p = run(*argv, check=False)
    assert p.returncode == 2, p.stderr
    lines = p.stderr.strip().splitlines()
    assert len(lines) == 1 and option in lines[0] and "more than once" in lines[0], p.stderr
    assert p.stdout == ""
