"""``bearingsim map --scheduler tcp://HOST:PORT`` on a real Dask cluster, run the way a user runs it.

A ``dask scheduler`` and ``dask worker`` processes are started on 127.0.0.1 (their own process groups,
killed in the fixture's finalizer even when a test fails); the map runs through the installed
``bearingsim`` script with the scheduler's address.  The cluster map must equal the local map exactly,
survive a worker killed mid-map (SIGKILL: the scheduler runs its block again elsewhere), and fail in
one line leaving no file when the cluster has no worker left.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

distributed = pytest.importorskip("distributed")

GRID = ["skf-7011-cdga-hc", "--fa", "1000:5000:5", "--speed", "0:11200:5", "--chunk", "5"]
#: every wait of these tests is bounded
START_TIMEOUT = 40.0
MAP_TIMEOUT = 60.0


class _Cluster:
    def __init__(self, folder: Path):
        self.folder = folder
        self.procs: list[subprocess.Popen] = []
        self.workers: dict[str, subprocess.Popen] = {}
        self.address = None

    def _start(self, args, log):
        p = subprocess.Popen([sys.executable, "-m", "dask", *args], stdout=subprocess.DEVNULL,
                             stderr=open(self.folder / log, "wb"), start_new_session=True)
        self.procs.append(p)
        return p

    def start_scheduler(self):
        sfile = self.folder / "scheduler.json"
        self._start(["scheduler", "--host", "127.0.0.1", "--port", "0", "--no-dashboard",
                     "--scheduler-file", str(sfile)], "scheduler.log")
        t0 = time.monotonic()
        while time.monotonic() - t0 < START_TIMEOUT:
            if sfile.exists():
                try:
                    self.address = json.loads(sfile.read_text())["address"]
                    return self.address
                except (ValueError, KeyError):  # being written
                    pass
            if self.procs[-1].poll() is not None:
                break
            time.sleep(0.05)
        pytest.fail("the dask scheduler did not start: " + (self.folder / "scheduler.log").read_text()[-2000:])

    def start_worker(self, name: str):
        self.workers[name] = self._start(["worker", self.address, "--nworkers", "1", "--nthreads", "1",
                                          "--no-dashboard", "--name", name], f"worker-{name}.log")

    def kill(self, name: str):
        """SIGKILL a worker (nanny and worker process: its whole process group)."""
        p = self.workers.pop(name)
        os.killpg(p.pid, signal.SIGKILL)
        p.wait(timeout=10)

    def kill_scheduler(self):
        os.killpg(self.procs[0].pid, signal.SIGKILL)
        self.procs[0].wait(timeout=10)

    def close(self):
        for p in self.procs:
            if p.poll() is None:
                try:
                    os.killpg(p.pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            try:
                p.wait(timeout=10)
            except subprocess.TimeoutExpired:  # pragma: no cover
                pass


@pytest.fixture(scope="module", autouse=True)
def compiled_kernels():
    """Compile (or load) the batch kernels once here, so that the map and worker processes load them from
    the cache instead of compiling them side by side (a fresh checkout would otherwise spend the maps'
    time limits compiling)."""
    from bearingsim.sweep import warm_up

    warm_up()


@pytest.fixture
def cluster(tmp_path):
    c = _Cluster(tmp_path)
    try:
        c.start_scheduler()
        yield c
    finally:
        c.close()


def _client(address):
    return distributed.Client(address, timeout="20s", set_as_default=False)


def _wait_workers(client, names, timeout=START_TIMEOUT):
    """{name: worker address} once every named worker is registered with the scheduler."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        info = client.scheduler_info()["workers"]
        by_name = {w["name"]: a for a, w in info.items()}
        if all(n in by_name for n in names):
            return {n: by_name[n] for n in names}
        time.sleep(0.1)
    pytest.fail(f"workers {names} did not register in {timeout} s")


def _map(args, out=None):
    cmd = ["bearingsim", "map", *GRID, *args, "--json"] + (["--out", str(out)] if out is not None else [])
    return subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)


def _finish(p, timeout=MAP_TIMEOUT):
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        pytest.fail(f"the map did not finish in {timeout} s")
    return p.returncode, out.decode(), err.decode()


def _wait_busy(client, address, proc, timeout=START_TIMEOUT):
    """Wait until the worker at ``address`` is running a block of the map (and the map still runs)."""
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        if proc.poll() is not None:
            return False
        if client.processing().get(address):
            return True
        time.sleep(0.02)
    return False


def test_cli_map_on_a_real_cluster_equals_the_local_map_and_survives_a_killed_worker(cluster, tmp_path):
    """Two workers; worker A is SIGKILLed while it runs a block: the scheduler reruns the block on B, the
    map exits 0, and every variable equals the local (in-process) map bitwise."""
    import xarray as xr

    local = _map(["--workers", "1"], tmp_path / "local.nc")  # runs while the cluster starts
    cluster.start_worker("A")
    cluster.start_worker("B")
    with _client(cluster.address) as client:
        addr = _wait_workers(client, ["A", "B"])
        p = _map(["--scheduler", cluster.address], tmp_path / "cluster.nc")
        busy = _wait_busy(client, addr["A"], p)
        if busy:
            cluster.kill("A")
        rc, out, err = _finish(p)
        assert rc == 0, err
        assert busy, "worker A never ran a block of the map before it finished"
    assert json.loads(out)["converged"] == 25
    rcl, _, errl = _finish(local)
    assert rcl == 0, errl
    with xr.open_dataset(tmp_path / "local.nc") as a, xr.open_dataset(tmp_path / "cluster.nc") as b:
        assert set(a.data_vars) == set(b.data_vars)
        for v in a.data_vars:
            np.testing.assert_array_equal(a[v].values, b[v].values, err_msg=v)  # NaN = NaN (lives without C)
    assert sorted(p.name for p in tmp_path.glob("*.nc")) == ["cluster.nc", "local.nc"]
    assert not list(tmp_path.glob(".*.part")), "a temporary map file was left behind"
    # the map gets the user's file mode (umask), not mkstemp's 0600
    umask = os.umask(0)
    os.umask(umask)
    assert (tmp_path / "cluster.nc").stat().st_mode & 0o777 == 0o666 & ~umask


def test_cluster_losing_its_last_worker_fails_in_one_line_and_leaves_no_file(cluster, tmp_path):
    cluster.start_worker("A")
    with _client(cluster.address) as client:
        addr = _wait_workers(client, ["A"])
        out = tmp_path / "m.nc"
        t0 = time.monotonic()
        p = _map(["--scheduler", cluster.address, "--worker-timeout", "2"], out)
        busy = _wait_busy(client, addr["A"], p)
        if busy:
            cluster.kill("A")
        rc, _, err = _finish(p)
    assert busy, "the worker never ran a block of the map"
    assert rc == 1, err
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error:") and "no worker" in lines[0], err
    assert time.monotonic() - t0 < 30
    assert list(tmp_path.glob("m.nc*")) == [] and list(tmp_path.glob(".m.nc*")) == []


def test_scheduler_killed_mid_map_fails_in_one_line_and_leaves_no_file(cluster, tmp_path):
    cluster.start_worker("A")
    with _client(cluster.address) as client:
        addr = _wait_workers(client, ["A"])
        p = _map(["--scheduler", cluster.address], tmp_path / "m.nc")
        busy = _wait_busy(client, addr["A"], p)
        if busy:
            cluster.kill_scheduler()
        rc, _, err = _finish(p)
    assert busy, "the worker never ran a block of the map"
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    assert rc == 1 and len(lines) == 1 and lines[0].startswith("error: lost the Dask scheduler"), err
    assert list(tmp_path.glob("m.nc*")) == [] and list(tmp_path.glob(".m.nc*")) == []


def test_cli_unreachable_scheduler_is_one_line_exit_2(tmp_path):
    """Nothing listens on port 1 (connection refused until the 3 s timeout).  Malformed addresses:
    tests/unit/test_sweep.py::test_malformed_scheduler_address_is_refused_before_a_client_is_made."""
    t0 = time.monotonic()
    rc, _, err = _finish(_map(["--scheduler", "tcp://127.0.0.1:1"], tmp_path / "m.nc"), timeout=30)
    assert rc == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: --scheduler:"), err
    assert time.monotonic() - t0 < 20
    assert list(tmp_path.iterdir()) == []


def test_cli_shaft_preload_sweep_on_a_real_cluster_equals_the_local_sweep(cluster, tmp_path):
    """``bearingsim shaft FILE --speeds … --preloads … --scheduler ADDR``: each preload's chain of speeds runs on a
    worker of a real cluster and streams into the file; the file equals the in-process sweep to round-off (each chain
    is the same sequence of warm-started solves wherever it runs; dask workers run numpy's BLAS on one thread, which
    sums the condensation's products in another order: 5e-13 seen)."""
    import xarray as xr

    spindle = str(Path(__file__).resolve().parents[2] / "examples" / "spindle-milling.toml")
    args = ["shaft", spindle, "--speeds", "0:12000:3", "--preloads", "rear=100 N:600 N:2", "--json"]
    local = subprocess.Popen(["bearingsim", *args, "--out", str(tmp_path / "local.nc")], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, start_new_session=True)
    cluster.start_worker("A")
    cluster.start_worker("B")
    with _client(cluster.address) as client:
        _wait_workers(client, ["A", "B"])
        p = subprocess.Popen(["bearingsim", *args, "--scheduler", cluster.address, "--out",
                              str(tmp_path / "cluster.nc")], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             start_new_session=True)
        rc, out, err = _finish(p, timeout=3 * MAP_TIMEOUT)
        assert rc == 0, err
    rcl, _, errl = _finish(local, timeout=3 * MAP_TIMEOUT)
    assert rcl == 0, errl
    assert json.loads(out)["converged"] == [[True] * 3] * 2
    with xr.open_dataset(tmp_path / "local.nc") as a, xr.open_dataset(tmp_path / "cluster.nc") as b:
        assert set(a.data_vars) == set(b.data_vars) and b.sizes["preload"] == 2
        for v in a.data_vars:
            np.testing.assert_allclose(a[v].values, b[v].values, rtol=1e-10, atol=0, err_msg=v)
    assert not list(tmp_path.glob(".*.part")), "a temporary sweep file was left behind"
