"""Design-space maps (sweep.py, statics/_batch.py): grid parsing, correctness, executors, safety."""

import os
import signal
import subprocess
import time

import numpy as np
import pytest

from bearingsim import sweep
from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.statics import jones_harris as jh
from bearingsim.statics._batch import run_batch


def test_parse_grid_inclusive_and_units():
    np.testing.assert_allclose(sweep.parse_grid("1000:5000:9", "force", "fa"), np.linspace(1000, 5000, 9))
    np.testing.assert_allclose(sweep.parse_grid("1 kN:2 kN:3", "force", "fa"), [1000, 1500, 2000])
    np.testing.assert_allclose(sweep.parse_grid("0:6000:3", "speed", "speed"), np.array([0, 3000, 6000]) * np.pi / 30)
    np.testing.assert_allclose(sweep.parse_grid("250 N", "force", "fa"), [250.0])


@pytest.mark.parametrize("spec", ["1000:500:3", "1000:5000", "1000:5000:x", "1000:5000:1", "a:b:3"])
def test_parse_grid_bad_input_names_field(spec):
    with pytest.raises(InputError) as exc:
        sweep.parse_grid(spec, "force", "fa")
    assert exc.value.field == "fa"


def test_batch_matches_single_solves():
    b = load_bearing("skf-7011-cdga-hc")
    loads = np.zeros((6, 5))
    loads[:, 0] = np.linspace(500, 3000, 6)
    loads[:, 1] = 300.0
    loads[:, 3] = 5.0
    om = np.linspace(0, 1000, 6)
    out = run_batch(b, loads, om)
    assert out["converged"].all()
    for i in range(6):
        r = jh.solve(b, jh.Loads(*loads[i]), om[i])
        np.testing.assert_allclose(out["q"][i], r.displacement, rtol=1e-8, atol=1e-15)
        np.testing.assert_allclose(out["k"][i], r.stiffness, rtol=1e-7, atol=1e-6 * abs(r.stiffness).max())
        np.testing.assert_allclose(out["p_inner"][i], r.balls["inner_max_pressure_Pa"].max(), rtol=1e-8)
        loaded = r.balls["inner_load_N"] > 0
        np.testing.assert_allclose(out["alpha_inner_min"][i], r.balls["inner_contact_angle_rad"][loaded].min(),
                                   rtol=1e-8)


def test_map_grid_dataset_and_serial_equals_process_pool():
    kw = dict(fa="500:2000:4", speed="0:9000:5", chunk_points=5)
    a = sweep.map_grid("skf-7011-cdga-hc", workers=1, **kw)
    assert a.stiffness.dims == ("fa", "speed", "dof", "dof2")
    assert int(a.converged.sum()) == 20
    # one point against the direct solve
    r = jh.solve(load_bearing("skf-7011-cdga-hc"), jh.Loads(fa=1000.0), 4500 * np.pi / 30)
    np.testing.assert_allclose(a.stiffness.isel(fa=1, speed=2).values, r.stiffness, rtol=1e-7,
                               atol=1e-6 * abs(r.stiffness).max())
    b = sweep.map_grid("skf-7011-cdga-hc", workers=2, **kw)
    for v in a.data_vars:
        np.testing.assert_array_equal(a[v].values, b[v].values)


@pytest.mark.parametrize("processes", [True, False], ids=["process-workers", "thread-workers"])
def test_local_cluster_equals_serial_exactly(tmp_path, processes):
    """Dask workers as processes, and as threads of one process (the batch kernel releases the GIL, so
    two thread workers solve blocks at the same time): both give the serial map bit for bit."""
    distributed = pytest.importorskip("distributed")
    kw = dict(fa="0:1500:3", fr="0:1000:2", preload="100:200:2", speed="0:6000:3", chunk_points=3)
    serial = sweep.map_grid("skf-7011-cdga-hc-db", workers=1, **kw)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=processes,
                                  dashboard_address=None) as cl, \
            distributed.Client(cl) as client:
        ds = sweep.map_grid("skf-7011-cdga-hc-db", scheduler=client, out=tmp_path / "m.nc", **kw)
        for v in serial.data_vars:
            np.testing.assert_array_equal(serial[v].values, ds[v].values)
        ds.close()
    assert serial.converged.all()


def test_unreachable_scheduler_fails_fast_and_writes_nothing(tmp_path):
    out = tmp_path / "m.nc"
    t0 = time.monotonic()
    with pytest.raises(InputError) as exc:
        sweep.map_grid("skf-7011-cdga-hc", fa="100:200:2", scheduler="tcp://127.0.0.1:1", out=out,
                       scheduler_timeout=2.0)
    assert exc.value.field == "scheduler"
    assert time.monotonic() - t0 < 15.0
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("address", ["", "foo", "tcp://127.0.0.1:notaport", "http://127.0.0.1:8786",
                                     "tcp://127.0.0.1:99999", "tcp://127.0.0.1"])
def test_malformed_scheduler_address_is_refused_before_a_client_is_made(tmp_path, address):
    """A Client made from a malformed address failed late (6 s) with a traceback from its destructor."""
    pytest.importorskip("distributed")
    t0 = time.monotonic()
    with pytest.raises(InputError) as exc:
        sweep.map_grid("skf-7011-cdga-hc", fa="100:200:2", scheduler=address, out=tmp_path / "m.nc")
    assert exc.value.field == "scheduler" and "tcp://127.0.0.1:8786" in exc.value.fix
    assert time.monotonic() - t0 < 1.0
    assert list(tmp_path.iterdir()) == []


def test_interrupted_map_leaves_no_file(tmp_path, monkeypatch):
    calls = {"n": 0}
    real = sweep.solve_block

    def flaky(*a, **k):
        calls["n"] += 1
        if calls["n"] == 2:
            raise KeyboardInterrupt
        return real(*a, **k)

    monkeypatch.setattr(sweep, "solve_block", flaky)
    with pytest.raises(KeyboardInterrupt):
        sweep.map_grid("skf-7011-cdga-hc", fa="100:200:4", chunk_points=1, workers=1, out=tmp_path / "m.nc")
    assert list(tmp_path.iterdir()) == []


def test_netcdf_output_equals_memory(tmp_path):
    kw = dict(fa="500:1500:3", moment="-5:5:3", fr="200 N", speed="3000", workers=1)
    mem = sweep.map_grid("skf-7011-cdga-hc", **kw)
    disk = sweep.map_grid("skf-7011-cdga-hc", out=tmp_path / "m.nc", **kw)
    for v in mem.data_vars:
        np.testing.assert_array_equal(mem[v].values, disk[v].values)
    assert float(disk["fr"]) == 200.0
    disk.close()
    p = sweep.plot_map(mem, tmp_path / "k.png")
    assert p.stat().st_size > 0


def test_preload_grid_needs_a_set():
    with pytest.raises(InputError) as exc:
        sweep.map_grid("skf-7011-cdga-hc", preload="100:200:2")
    assert exc.value.field == "preload"


def test_cli_map_export_and_hub_static(tmp_path):
    import json

    import typer
    from typer.testing import CliRunner

    from bearingsim.cli import sweep as cli_sweep

    app = typer.Typer()
    rep = typer.Typer()
    app.add_typer(rep, name="reproduce")
    cli_sweep.register(app, rep)
    runner = CliRunner()
    out = tmp_path / "m.nc"
    r = runner.invoke(app, ["map", "skf-7011-cdga-hc", "--fa", "1000:2000:3", "--speed", "0:6000:3", "--out",
                            str(out), "--json", "--workers", "1"])
    assert r.exit_code == 0, r.output
    d = json.loads(r.output.strip().splitlines()[-1])
    assert d["points"] == 9 and d["converged"] == 9 and out.exists()
    r = runner.invoke(app, ["map", "skf-7011-cdga-hc", "--fa", "1000:500:3"])
    assert isinstance(r.exception, InputError) and r.exception.field == "fa"
    r = runner.invoke(app, ["export", "ross", "skf-7011-cdga-hc-db", "--speed", "0:6000:3", "--out",
                            str(tmp_path / "b.json")])
    assert r.exit_code == 0, r.output
    assert len(json.loads((tmp_path / "b.json").read_text())["kxx_N_per_m"]) == 3
    r = runner.invoke(app, ["reproduce", "hub-static", "--out", str(tmp_path), "--points", "3"])
    assert r.exit_code == 0, r.output
    assert (tmp_path / "hub_static.csv").exists() and (tmp_path / "hub_static.png").exists()


def test_batch_predictor_and_reordering_do_not_change_the_solution():
    b = load_bearing("skf-7011-cdga-hc")
    rng = np.random.default_rng(1)
    n = 40
    loads = np.column_stack([rng.uniform(800, 3000, n), rng.uniform(-300, 300, n), rng.uniform(-300, 300, n),
                             rng.uniform(-5, 5, n), rng.uniform(-5, 5, n)])
    om = rng.uniform(0, 1000, n)
    a = run_batch(b, loads, om, predictor=False)
    c = run_batch(b, loads, om, predictor=True, reorder=True)
    ok = a["converged"] & c["converged"]
    assert ok.sum() >= 0.9 * n
    np.testing.assert_allclose(c["q"][ok], a["q"][ok], rtol=1e-7, atol=1e-14)
    np.testing.assert_allclose(c["k"][ok], a["k"][ok], rtol=1e-6, atol=1e-6 * np.abs(a["k"]).max())


# ---- behaviour added for speed (issue 3 item 7): coupled Newton, blocks, serpentine order ----------------------
def _random_points(seed, n):
    rng = np.random.default_rng(seed)
    loads = np.column_stack([rng.uniform(500, 5000, n), rng.uniform(-2000, 2000, n), rng.uniform(-2000, 2000, n),
                             rng.uniform(-50, 50, n), rng.uniform(-50, 50, n)])
    return loads, rng.uniform(0, 11200, n) * np.pi / 30


def _status_of(r):
    if r.converged:
        return 0
    return 3 if r.status.startswith("the only equilibrium") else -1


def test_batch_coupled_newton_same_status_and_equilibria_as_single_solves():
    """The batch (coupled ring-ball Newton, warm starts, Z-order) against independent cold single solves
    (jones_harris.solve, nested Newton): every point gets the same status, including the points whose
    equilibrium puts a contact past the groove bottom (status 3), and the same converged equilibria."""
    b = load_bearing("skf-7011-cdga-hc")
    loads, om = _random_points(3, 60)
    out = run_batch(b, loads, om, reorder=True)
    ref = [jh.solve(b, jh.Loads(*loads[i]), om[i]) for i in range(len(om))]
    np.testing.assert_array_equal(out["status"], [_status_of(r) for r in ref])
    assert (out["status"] == 3).sum() >= 3 and (out["status"] == 0).sum() >= 40
    w = np.array([1.0, 1.0, 1.0, 0.5 * b.pitch_diameter, 0.5 * b.pitch_diameter])  # rotations as arc lengths
    for i in np.flatnonzero(out["status"] == 0):
        r = ref[i]
        scale = np.abs(r.displacement * w).max()
        np.testing.assert_allclose(out["q"][i] * w, r.displacement * w, rtol=0, atol=1e-8 * scale)
        np.testing.assert_allclose(out["k"][i], r.stiffness, rtol=0, atol=1e-7 * np.abs(r.stiffness).max())


def test_solve_ring_started_at_a_status3_equilibrium_still_reports_status3():
    """A start that already meets the tolerances (a warm start at the solution) gets the groove-bottom check."""
    from bearingsim.statics import _kernels as kn

    b = load_bearing("skf-7011-cdga-hc")
    loads, om = _random_points(3, 60)
    out = run_batch(b, loads, om, reorder=True)
    i = int(np.flatnonzero(out["status"] == 3)[0])
    rows = np.ascontiguousarray(b.row_vectors())
    z = int(rows[0, kn.P_Z])
    q = np.array(jh.initial_guess(b, jh.Loads(*loads[i])), dtype=float)
    lam = np.zeros((1, z), dtype=np.int64)
    xb = np.zeros((1, z, 2))
    sc = max(1.0, np.abs(loads[i, :3]).max(), 2 * np.abs(loads[i, 3:]).max() / rows[0, kn.P_DM])
    args = (lam, xb, np.zeros((5, 5)), np.zeros((1, z, 12)), jh.TOL_BALL, jh.TOL_RING, jh.MAXIT_BALL, jh.MAXIT_RING, sc)
    st, its, _, _ = kn.solve_ring(rows, loads[i], om[i], kn.CONTROL_OUTER, q, *args)
    assert st == 3 and its > 0
    st, its, _, _ = kn.solve_ring(rows, loads[i], om[i], kn.CONTROL_OUTER, q, *args)
    assert st == 3 and its == 0


@pytest.mark.parametrize("shape, chunk", [((7,), 3), ((4, 5), 5), ((4, 5), 7), ((25, 20, 20), 1000),
                                          ((3, 4, 5, 6), 50), ((2, 3), 100)])
def test_blocks_tile_the_grid_within_the_chunk_size(shape, chunk):
    seen = np.zeros(shape, dtype=int)
    for blk in sweep._blocks(shape, chunk):
        assert len(blk) == len(shape)
        assert seen[blk].size <= chunk
        seen[blk] += 1
    assert (seen == 1).all()


@pytest.mark.parametrize("shape", [(5,), (3, 4), (2, 3, 4), (3, 2, 2, 3)])
def test_snake_order_visits_every_point_once_by_unit_steps(shape):
    idx = sweep._snake(shape)
    assert idx.shape == (int(np.prod(shape)), len(shape))
    assert len({tuple(r) for r in idx}) == len(idx)
    steps = np.abs(np.diff(idx, axis=0))
    assert (steps.sum(axis=1) == 1).all()  # consecutive points are grid neighbours


def test_map_blocks_spanning_outer_dimensions_equal_small_blocks():
    """A block over several outer grid indices gives the same map (to the solver tolerance) as 1-D blocks."""
    kw = dict(fa="1000:3000:3", fr="0:600:3", speed="0:6000:3", workers=1)
    big = sweep.map_grid("skf-7011-cdga-hc", chunk_points=27, **kw)
    small = sweep.map_grid("skf-7011-cdga-hc", chunk_points=3, **kw)
    np.testing.assert_array_equal(big.status.values, small.status.values)
    k = small.stiffness.values
    np.testing.assert_allclose(big.stiffness.values, k, rtol=0, atol=1e-7 * np.abs(k).max())


def test_map_file_takes_the_users_umask_and_a_write_error_is_one_line_leaving_nothing(tmp_path, monkeypatch):
    """The map is created 0666 & ~umask like any file the user writes (mkstemp's 0600 used to reach the
    final file); a full disk while writing is an InputError naming ``out``, and no file remains."""
    import errno

    old = os.umask(0o027)
    try:
        sweep.map_grid("skf-7011-cdga-hc", fa="100:200:2", workers=1, out=tmp_path / "m.nc").close()
    finally:
        os.umask(old)
    assert (tmp_path / "m.nc").stat().st_mode & 0o777 == 0o640
    (tmp_path / "m.nc").unlink()
    calls = {"n": 0}
    real = sweep._block_var

    def full_disk(res, key):  # the first variable of the second block hits a full disk
        calls["n"] += 1
        if calls["n"] == len(sweep._VARS) + 1:
            raise OSError(errno.ENOSPC, "No space left on device")
        return real(res, key)

    monkeypatch.setattr(sweep, "_block_var", full_disk)
    with pytest.raises(InputError) as exc:
        sweep.map_grid("skf-7011-cdga-hc", fa="100:200:4", chunk_points=1, workers=1, out=tmp_path / "m.nc")
    assert exc.value.field == "out" and "No space left" in str(exc.value)
    assert list(tmp_path.iterdir()) == []


_SOLVE_BLOCK = sweep.solve_block


def _fails_on_the_second_block(bearing, axes, block, control="outer"):
    if block[0].start == 1:
        raise RuntimeError("block failed")
    return _SOLVE_BLOCK(bearing, axes, block, control)


def test_a_failing_block_on_a_dask_cluster_leaves_no_file(tmp_path, monkeypatch):
    """An error raised by a block on a worker reaches the caller as itself, and the file is removed."""
    distributed = pytest.importorskip("distributed")
    monkeypatch.setattr(sweep, "solve_block", _fails_on_the_second_block)
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=False, dashboard_address=None) as cl, \
            distributed.Client(cl) as client:
        with pytest.raises(RuntimeError, match="block failed"):
            sweep.map_grid("skf-7011-cdga-hc", fa="100:400:4", chunk_points=1, scheduler=client,
                           out=tmp_path / "m.nc")
    assert list(tmp_path.iterdir()) == []


def test_killed_map_process_leaves_no_map_and_the_next_map_clears_its_leftover(tmp_path):
    """SIGKILL of the real ``bearingsim map`` while it writes: the final name never appears (only the hidden
    temporary file of the dead process), and the next map to that name removes that leftover."""
    out = tmp_path / "m.nc"
    p = subprocess.Popen(["bearingsim", "map", "skf-7011-cdga-hc", "--fa", "1000:5000:6", "--speed", "0:11200:6",
                          "--chunk", "1", "--workers", "1", "--json", "--out", str(out)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    t0 = time.monotonic()
    while not list(tmp_path.glob(".m.nc.*.part")) and p.poll() is None and time.monotonic() - t0 < 60:
        time.sleep(0.01)
    alive = p.poll() is None
    os.killpg(p.pid, signal.SIGKILL)
    p.wait(timeout=10)
    assert alive, "the map finished before it could be killed"
    assert not out.exists() and len(list(tmp_path.glob(".m.nc.*.part"))) == 1
    r = subprocess.run(["bearingsim", "map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--workers", "1", "--json",
                        "--out", str(out)], capture_output=True, timeout=120)
    assert r.returncode == 0, r.stderr.decode()
    assert out.exists() and list(tmp_path.iterdir()) == [out]


def test_cli_map_on_a_full_disk_is_one_line_exit_2_and_leaves_nothing(tmp_path):
    """A full disk for the real CLI process: a 30 kB file-size limit (RLIMIT_FSIZE, SIGXFSZ ignored, so a
    write past it fails with EFBIG as on a full file system).  The same map written here is larger than
    that (and this compiles the kernels first: their cache files must not meet the limit)."""
    import resource

    sweep.map_grid("skf-7011-cdga-hc", fa="1000:5000:5", speed="0:11200:5", workers=1,
                   out=tmp_path / "ok.nc").close()
    assert (tmp_path / "ok.nc").stat().st_size > 30000
    args = ["bearingsim", "map", "skf-7011-cdga-hc", "--fa", "1000:5000:5", "--speed", "0:11200:5", "--workers",
            "1", "--json", "--out"]

    def limit():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (30000, 30000))

    out = tmp_path / "sub" / "m.nc"
    out.parent.mkdir()
    r = subprocess.run(args + [str(out)], capture_output=True, timeout=120, preexec_fn=limit)
    lines = r.stderr.decode().strip().splitlines()
    assert r.returncode == 2 and len(lines) == 1 and lines[0].startswith("error: --out:"), r.stderr.decode()
    assert list(out.parent.iterdir()) == []


def _children(pid: int) -> list[tuple[int, str]]:
    """(pid, command line) of the processes whose parent is ``pid`` (Linux /proc)."""
    out = []
    for d in os.listdir("/proc"):
        if not d.isdigit():
            continue
        try:
            with open(f"/proc/{d}/stat") as f:
                ppid = int(f.read().rsplit(")", 1)[1].split()[1])
            if ppid == pid:
                with open(f"/proc/{d}/cmdline", "rb") as f:
                    out.append((int(d), f.read().replace(b"\0", b" ").decode(errors="replace")))
        except (OSError, ValueError, IndexError):
            continue
    return out


@pytest.mark.skipif(not os.path.isdir("/proc/self"), reason="needs /proc to find the pool's processes")
def test_killed_local_pool_worker_is_one_line_and_leaves_no_file(tmp_path):
    """A process of the local pool dies (SIGKILL, as the OOM killer would): the map fails in one line (exit 1)
    instead of a BrokenProcessPool traceback, and writes nothing."""
    out = tmp_path / "m.nc"
    p = subprocess.Popen(["bearingsim", "map", "skf-7011-cdga-hc", "--fa", "1000:5000:20", "--speed", "0:11200:20",
                          "--chunk", "1", "--workers", "2", "--json", "--out", str(out)],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    victim = None
    t0 = time.monotonic()
    while victim is None and p.poll() is None and time.monotonic() - t0 < 60:
        victim = next((c for c, cmd in _children(p.pid) if "spawn_main" in cmd), None)
        time.sleep(0.01)
    try:
        assert victim is not None, "no pool process appeared while the map ran"
        os.kill(victim, signal.SIGKILL)
        _, err = p.communicate(timeout=60)
    finally:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
    lines = err.decode().strip().splitlines()
    assert p.returncode == 1 and len(lines) == 1 and "worker process of the map died" in lines[0], err.decode()
    assert list(tmp_path.iterdir()) == []


def test_map_plot_and_file_speak_the_units_of_the_trade(tmp_path):
    """Issue 15 item 5: the map's plot axes in rpm and N, the colour bar in N/µm (the unit of K[x, x]); the file
    keeps SI (rad/s) and names the display unit of the speed coordinate."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from bearingsim.units import display_unit

    ds = sweep.map_grid("skf-7011-cdga-hc", fa=np.array([500.0, 1000.0, 2000.0]), speed=np.array([0.0, 500.0, 1000.0]),
                        out=tmp_path / "m.nc", workers=1)
    assert ds["speed"].attrs["units"] == "rad/s" and ds["speed"].attrs["units_display"] == "rpm"
    captured = {}
    real_savefig = plt.Figure.savefig

    def spy(fig, *a, **k):
        ax = fig.axes[0]
        captured["x"], captured["y"] = ax.get_xlabel(), ax.get_ylabel()
        captured["cbar"] = fig.axes[1].get_ylabel()
        captured["xlim"] = ax.get_xlim()
        captured["clim"] = ax.collections[0].get_clim()
        return real_savefig(fig, *a, **k)

    plt.Figure.savefig = spy
    try:
        sweep.plot_map(ds, tmp_path / "k.png")
    finally:
        plt.Figure.savefig = real_savefig
    assert captured["x"] == "speed [rpm]" and captured["y"] == "fa [N]"
    assert captured["cbar"] == "K[x,x] [N/µm]"
    # 1000 rad/s = 9549 rpm: the axis spans the grid in rpm (pcolormesh extends half a cell beyond)
    assert 9549.0 < captured["xlim"][1] < 1.3 * 9549.3
    k = ds["stiffness"].isel(dof=0, dof2=0).values
    np.testing.assert_allclose(captured["clim"], (k.min() * 1e-6, k.max() * 1e-6), rtol=1e-12)
    assert display_unit("N m/rad") == ("N·m/mrad", 1e-3) and display_unit("furlong") == ("furlong", 1.0)
