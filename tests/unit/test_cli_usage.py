"""Command-line usage errors, --version, --help and internal errors, through the installed console script.

Each class of mistake a user makes on the command line ends in ONE line on stderr starting with "error:" and exit
status 2 (issue 11 item 2; typer bundles its own click, whose exceptions the old ``except click.ClickException``
never caught: 40–100-line tracebacks with exit 1).  A bug inside a command is one line naming the error and where
to report it, exit 1; ``BEARINGSIM_DEBUG=1`` shows the traceback.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tomllib
from importlib.metadata import version
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = shutil.which("bearingsim")


def run(*args, env=None):
    assert SCRIPT is not None, "the console script `bearingsim` is not installed (pip install -e .)"
    e = dict(os.environ)
    e.pop("BEARINGSIM_DEBUG", None)
    e.update(env or {})
    return subprocess.run([SCRIPT, *args], capture_output=True, text=True, env=e, timeout=300)


def lines(text: str) -> list[str]:
    return [ln for ln in text.splitlines() if ln.strip()]


@pytest.mark.parametrize("args, must_say", [
    (("--bogus",), "No such option: --bogus"),                                   # unknown option (top level)
    (("static", "skf-7011-cdga-hc", "--bogus"), "No such option: --bogus"),      # unknown option (command)
    (("static",), "Missing argument"),                                             # missing argument
    (("statc",), "Did you mean 'static'"),                                        # misspelled command
    (("reproduce", "hub-statc"), "Did you mean 'hub-static'?"),                    # misspelled sub-command
    (("static", "skf-7011-cdga-hc", "--fx", "3"), "--fa"),                        # misspelled option: the hint
    (("static", "skf-7011-cdga-hc", "--fa"), "'--fa' requires an argument"),       # option without its value
    (("map", "skf-7011-cdga-hc", "--workers", "two"), "'--workers'"),             # bad option value (type)
    (("--ver",), "--version"),                                                     # near miss of --version
])
def test_usage_error_is_one_line_exit_2(args, must_say):
    p = run(*args)
    assert p.returncode == 2, (p.returncode, p.stderr)
    err = lines(p.stderr)
    assert len(err) == 1, p.stderr
    assert err[0].startswith("error: ") and must_say in err[0], err[0]
    assert "Traceback" not in p.stderr and p.stdout == ""


def test_version_is_the_distribution_version():
    """`bearingsim --version` prints the installed version, which is pyproject's (single source) and the
    package's __version__."""
    p = run("--version")
    assert p.returncode == 0 and p.stderr == ""
    with open(ROOT / "pyproject.toml", "rb") as fh:
        declared = tomllib.load(fh)["project"]["version"]
    assert p.stdout == f"bearingsim {declared}\n"
    assert version("bearingsim") == declared
    api = subprocess.run([sys.executable, "-c", "import bearingsim; print(bearingsim.__version__)"],
                         capture_output=True, text=True, check=True).stdout.strip()
    assert api == declared


@pytest.mark.parametrize("args, must_show", [
    (("--help",), "static"),
    (("static", "--help"), "--fa"),
    (("reproduce", "--help"), "hub-static"),
    (("map", "--help"), "--scheduler"),
])
def test_help_exits_0(args, must_show):
    p = run(*args)
    assert p.returncode == 0, p.stderr
    assert must_show in p.stdout and p.stderr == ""


def test_bare_command_shows_help():
    """`bearingsim` alone prints the help (click's status 2 for a missing command, no error line)."""
    p = run()
    assert p.returncode == 2
    assert "static" in p.stdout and "Usage" in p.stdout
    assert p.stderr.strip() == ""


@pytest.fixture
def broken_command(tmp_path):
    """A sitecustomize that makes the load parser of every command raise an unexpected RuntimeError (a stand-in
    for a bug), loaded by the installed script through PYTHONPATH."""
    (tmp_path / "sitecustomize.py").write_text(
        "import bearingsim.cli.options as ct\n"
        "def _boom(*a, **k):\n"
        "    raise RuntimeError('boom from the test')\n"
        "ct.parse_loads = _boom\n")
    pp = os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return {"PYTHONPATH": pp}


def test_internal_error_is_one_line_exit_1(broken_command):
    p = run("static", "skf-7011-cdga-hc", "--fa", "1000", "--json", env=broken_command)
    assert p.returncode == 1, p.stderr
    err = lines(p.stderr)
    assert len(err) == 1, p.stderr
    line = err[0]
    assert line.startswith("error: internal error") and "RuntimeError: boom from the test" in line
    assert "report" in line and "BEARINGSIM_DEBUG=1" in line
    assert "Traceback" not in p.stderr and p.stdout == ""


def test_debug_env_shows_the_traceback(broken_command):
    p = run("static", "skf-7011-cdga-hc", "--fa", "1000", "--json", env={**broken_command, "BEARINGSIM_DEBUG": "1"})
    assert p.returncode == 1
    assert "Traceback" in p.stderr and "boom from the test" in p.stderr


def test_usage_errors_stay_one_line_in_debug_mode():
    p = run("statc", env={"BEARINGSIM_DEBUG": "1"})
    assert p.returncode == 2 and len(lines(p.stderr)) == 1 and "Traceback" not in p.stderr


def test_python_m_bearingsim_names_the_program():
    """`python -m bearingsim` reports errors under the program name, not __main__.py."""
    p = subprocess.run([sys.executable, "-m", "bearingsim", "statc"], capture_output=True, text=True)
    assert p.returncode == 2 and "'bearingsim --help'" in p.stderr and "__main__" not in p.stderr
