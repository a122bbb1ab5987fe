"""The map's file through the installed console script: chunks HDF5 accepts (a 10⁸-point map used to fail with
"NetCDF: Bad chunk sizes"), the size said before solving and checked against the free space, and SIGTERM
ending the command cleanly (issue 42 item 2)."""

from __future__ import annotations

import glob
import os
import shutil
import signal
import subprocess
import time

import numpy as np
import pytest
from _cli import SCRIPT, run  # tests/unit/_cli.py: the installed console script

from bearingsim import sweep
from bearingsim.io import netcdf as nc


def _axes(**grid):
    return {name: np.asarray(grid.get(name, [0.0]), dtype=float) for name, _, _ in sweep.AXES}


@pytest.mark.parametrize("shape", [(10000, 10000), (3000, 3000), (3001, 7), (41,), (5, 100, 100)])
def test_map_chunks_stay_under_the_cap_and_align_with_the_solver_blocks(shape):
    """Every chunk is at most MAX_CHUNK_BYTES (HDF5 refuses 4 GiB; the stiffness of a 10⁴ × 10⁴ map chunked over
    the last two axes was 20 GB), divides the solver's block (a block fills whole chunks) and pads no axis by
    more than MAX_CHUNK_PADDING."""
    dims = ["fa", "fr", "speed"][-len(shape):]
    block = sweep.block_shape(shape, 2000)
    _, variables = sweep._schema(dims, shape, _axes(**{d: np.arange(n) for d, n in zip(dims, shape)}), block)
    for v in variables:
        if v.chunks is None or not v.dims or v.dims[0] not in dims:
            continue
        size = int(np.prod(v.chunks)) * np.dtype(v.dtype).itemsize
        assert size <= nc.MAX_CHUNK_BYTES, (v.name, v.chunks)
        for c, b, n in zip(v.chunks, block, shape):
            assert b % c == 0, (v.name, v.chunks, block)
            assert -(-n // c) * c - n <= nc.MAX_CHUNK_PADDING * n, (v.name, v.chunks, shape)


def test_map_says_its_file_size_before_solving_and_the_file_has_that_size(tmp_path):
    out = tmp_path / "m.nc"
    p = run("map", "6205", "--fr", "500:5000:61", "--speed", "0:6000:50", "--workers", "1", "--out", str(out))
    first = p.stdout.splitlines()[0]
    assert first.startswith("3,050 points: the map file") and first.endswith(" MB"), p.stdout
    said = float(first.rsplit(" ", 2)[-2]) * 1e6
    # the line rounds to 2 digits (1.1 MB); the estimate counts the values, whole chunks and the header
    assert abs(out.stat().st_size - said) <= 0.05 * said, (out.stat().st_size, first)


@pytest.mark.skipif(not os.path.isdir("/dev/shm"), reason="needs a small file system (/dev/shm)")
def test_a_map_larger_than_the_free_space_is_refused_before_solving(tmp_path):
    """10⁸ points (the documented maximum, ≈ 32 GB) on /dev/shm: refused at once in one line with both sizes,
    exit 2, nothing written (the check uses shutil.disk_usage of the target folder)."""
    folder = os.path.join("/dev/shm", f"bearingsim-map-{os.getpid()}")
    need = 10**8 * sum(np.dtype(dt).itemsize * 5 ** len(extra) for _, extra, dt, _, _ in sweep._VARS.values())
    if shutil.disk_usage("/dev/shm").free > need:
        pytest.skip("/dev/shm has room for the 10^8-point map")
    os.makedirs(folder)
    try:
        t0 = time.monotonic()
        p = run("map", "6205", "--fr", "0:5000:10000", "--speed", "0:6000:10000", "--json", "--out",
                os.path.join(folder, "m.nc"), check=False)
        lines = p.stderr.strip().splitlines()
        assert p.returncode == 2 and len(lines) == 1, p.stderr
        assert lines[0].startswith("error: --out: the map needs 3") and " GB free" in lines[0], lines[0]
        assert time.monotonic() - t0 < 60 and os.listdir(folder) == []
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _children(pid: int) -> list[int]:
    out = []
    for f in glob.glob(f"/proc/{pid}/task/*/children"):
        with open(f) as fh:
            out += [int(x) for x in fh.read().split()]
    return out


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:
        with open(f"/proc/{pid}/stat") as fh:
            return fh.read().rsplit(")", 1)[1].split()[0] != "Z"  # a zombie has ended
    except OSError:
        return False


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="needs /proc to find the pool's processes")
def test_sigterm_ends_a_map_on_two_workers_cleanly(tmp_path):
    """SIGTERM to the real ``bearingsim map --workers 2`` while it writes: exit 143 and the one line
    "terminated" (no "leaked semaphore" warning, no traceback), the temporary file removed, no final file, and
    every child process (the pool's workers, multiprocessing's resource tracker) gone."""
    out = tmp_path / "m.nc"
    p = subprocess.Popen([SCRIPT, "map", "6205", "--fr", "0:5000:400", "--speed", "0:6000:400", "--workers", "2",
                          "--json", "--out", str(out)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                         start_new_session=True)
    try:
        t0 = time.monotonic()
        kids: list[int] = []
        while p.poll() is None and time.monotonic() - t0 < 120:
            kids = _children(p.pid)
            if len(kids) >= 3 and glob.glob(str(tmp_path / ".m.nc.*.part")):
                break
            time.sleep(0.05)
        time.sleep(0.5)  # the workers are solving blocks
        assert p.poll() is None, "the map ended before SIGTERM"
        kids = _children(p.pid)
        p.send_signal(signal.SIGTERM)
        _, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    assert p.returncode == 143, err.decode()
    assert err.decode().strip().splitlines()[-1] == "terminated" and "Traceback" not in err.decode()
    assert "leaked" not in err.decode(), err.decode()
    assert list(tmp_path.iterdir()) == []
    assert len(kids) >= 2
    t0 = time.monotonic()
    while any(_alive(k) for k in kids) and time.monotonic() - t0 < 10:
        time.sleep(0.05)
    assert not [k for k in kids if _alive(k)], "child processes survived the map"
