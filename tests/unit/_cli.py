"""The installed console script for CLI tests (tests go through ``bearingsim`` as a user does)."""

import shutil
import subprocess

SCRIPT = shutil.which("bearingsim")


def run(*args, check=True):
    """Run ``bearingsim *args``; with ``check`` assert exit 0 (stderr in the message)."""
    assert SCRIPT is not None, "the console script `bearingsim` is not installed (pip install -e .)"
    p = subprocess.run([SCRIPT, *args], capture_output=True, text=True)
    if check:
        assert p.returncode == 0, p.stderr
    return p
