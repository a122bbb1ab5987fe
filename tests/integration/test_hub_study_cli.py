"""``bearingsim reproduce hub-hysteresis`` through the installed console script: the JSON of a tiny grid with its
HTML report and local worker processes, the study continued after a SIGKILL (finished cells from the folder, the
running cell from its checkpoint, bitwise equal to an uninterrupted run), one cell on a real Dask cluster, and bad
input in one line.

Cells are short to keep CI fast: 1000 Hz loads (the moment's frequency is a parameter of the study; the paper's
1–50 Hz cells take minutes to hours each) and, except where the lubricated traction is the point, ``--traction
none`` (no traction: DOPRI5, ~0.2 s per load cycle instead of ~4 s).
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

CASE = Path(__file__).resolve().parents[2] / "examples" / "hub-moment-50hz.toml"
TIMEOUT = 240.0


def _cli(*args, **kw):
    return subprocess.Popen(["bearingsim", "reproduce", "hub-hysteresis", *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True, **kw)


def _finish(p, timeout=TIMEOUT):
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.communicate()
        pytest.fail(f"the study did not finish in {timeout} s")
    return p.returncode, out.decode(), err.decode()


def _series(folder: Path, stem: str) -> dict:
    with np.load(folder / f"{stem}.npz") as z:
        return {k: np.array(z[k]) for k in z.files}


def test_json_of_a_two_cell_grid_on_local_workers_with_report_then_rerun_from_the_folder(tmp_path):
    out, rep = tmp_path / "out", tmp_path / "rep"
    args = [CASE, "--speeds", "50,100", "--frequencies", "1000", "--cycles", "6", "--startup-cycles", "1",
            "--traction", "none", "--workers", "2", "--json", "--report", rep, "--out", out]
    rc, stdout, err = _finish(_cli(*args))
    assert rc == 0, err
    data = json.loads(stdout)
    assert [(c["vehicle_speed_kmh"], c["frequency_hz"]) for c in data["cells"]] == [(50.0, 1000.0), (100.0, 1000.0)]
    for c in data["cells"]:
        assert c["simulated_seconds"] == pytest.approx(7 / 1000.0, rel=1e-9)
        # the loop estimator ran: numbers where its periodicity criterion held, else a note saying why
        # (without traction nothing damps the balls: these short frictionless cells may not settle)
        assert len(c["two_point_deg"]) == 7  # the diagnostic reading of every cycle
        if c["wh_deg"] is None:
            assert c["cycles_used"] == 0 and any(n.startswith("loop estimator:") for n in c["notes"]), c
        else:
            lo, hi = c["wh_ci95_deg"]
            assert lo <= c["wh_deg"] <= hi and c["compliance_deg_per_kNm"] > 0
            assert 1 <= c["cycles_used"] <= 6 and len(c["wh_cycles_deg"]) == c["cycles_used"]
        assert c["static_compliance_deg_per_kNm"] > 0
        assert c["seed_wh_deg"] is None  # 1000 Hz: no pair of the paper
        assert not c["from_earlier_run"]
    assert data["traction"] == "none" and data["cycles"] == 6 and data["startup_cycles"] == 1
    for stem in ("hub_50kmh_1000Hz", "hub_100kmh_1000Hz"):
        assert (out / f"{stem}.json").exists() and (out / f"{stem}.npz").exists() and (out / f"{stem}.nc").exists()
    assert not list(out.glob("*.ckpt.npz"))
    assert json.loads((out / "hub_hysteresis.json").read_text())["cells"] == data["cells"]
    assert (out / "hub_hysteresis.csv").read_text().count("\n") == 3
    html = (rep / "report.html").read_text()
    assert 'src="fig9_bubbles.png"' in html and (rep / "fig9_bubbles.png").stat().st_size > 0
    assert html.count("<tr>") >= 2 + 5 + 1
    # the same command again: every cell from the folder (no run), the same numbers
    t0 = time.monotonic()
    rc, stdout2, err = _finish(_cli(*args))
    assert rc == 0, err
    again = json.loads(stdout2)
    assert all(c["from_earlier_run"] for c in again["cells"])
    assert "2 of 2 cells taken from the earlier run" in " ".join(again["notes"])
    for a, b in zip(data["cells"], again["cells"]):
        for k in ("wh_deg", "wh_ci95_deg", "two_point_deg", "loop_area_J", "phase_lag_deg", "notes"):
            assert a[k] == b[k], k
    assert time.monotonic() - t0 < 60


def _checkpoint_index(ckpt: Path) -> int:
    try:
        with np.load(ckpt) as c:
            return int(c["index"])
    except (OSError, ValueError, EOFError, KeyError):
        return -1


def test_sigkill_then_rerun_continues_from_finished_cells_and_the_running_cells_checkpoint(tmp_path):
    """The study process (cells run in it, --workers 1) is SIGKILLed after its first cell is stored and a wall-clock
    checkpoint of its second cell is written; run again, it takes the first cell from the folder, resumes the second
    from the checkpoint, and the second cell's series equal an uninterrupted run of that cell bit for bit."""
    case = tmp_path / "case.toml"
    case.write_text(CASE.read_text().replace('traction = "slices"', 'traction = "none"\ncheckpoint_every = "0.2 s"'))
    common = ["--frequencies", "1000", "--cycles", "24", "--startup-cycles", "0", "--workers", "1", "--json"]
    ref = _cli(case, "--speeds", "50", *common, "--out", tmp_path / "ref")  # uninterrupted, alongside
    out = tmp_path / "out"
    first, second = out / "hub_100kmh_1000Hz.json", out / "hub_50kmh_1000Hz.nc.ckpt.npz"
    p = _cli(case, "--speeds", "100,50", *common, "--out", out)
    t0 = time.monotonic()
    while time.monotonic() - t0 < TIMEOUT:
        if p.poll() is not None:
            pytest.fail(f"the study ended ({p.returncode}) before the kill: {p.stderr.read().decode()[-800:]}")
        if first.exists() and _checkpoint_index(second) > 0:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=10)
            break
        time.sleep(0.02)
    else:
        os.killpg(p.pid, signal.SIGKILL)
        pytest.fail("no stored first cell and checkpoint of the second in time")
    assert not (out / "hub_50kmh_1000Hz.json").exists()  # killed inside the second cell
    stamp = first.stat().st_mtime_ns
    rc, stdout, err = _finish(_cli(case, "--speeds", "100,50", *common, "--out", out))
    assert rc == 0, err
    cells = {c["vehicle_speed_kmh"]: c for c in json.loads(stdout)["cells"]}
    assert cells[100.0]["from_earlier_run"] and not cells[100.0]["resumed_from_checkpoint"]
    assert cells[50.0]["resumed_from_checkpoint"] and not cells[50.0]["from_earlier_run"]
    assert first.stat().st_mtime_ns == stamp  # the finished cell was not run again
    assert not list(out.glob("*.ckpt.npz"))
    rc, _, err = _finish(ref)
    assert rc == 0, err
    a, b = _series(out, "hub_50kmh_1000Hz"), _series(tmp_path / "ref", "hub_50kmh_1000Hz")
    assert a.keys() == b.keys()
    for k in a:
        assert np.array_equal(a[k], b[k]), k


def test_one_cell_on_a_real_dask_cluster_equals_the_local_run(tmp_path):
    pytest.importorskip("distributed")
    from test_dask_cluster import _client, _Cluster, _wait_workers

    args = ["--speeds", "100", "--frequencies", "1000", "--cycles", "2", "--startup-cycles", "0", "--traction",
            "none", "--json"]
    local = _cli(CASE, *args, "--workers", "1", "--out", tmp_path / "local")  # runs while the cluster starts
    cluster = _Cluster(tmp_path)
    try:
        cluster.start_scheduler()
        cluster.start_worker("A")
        with _client(cluster.address) as client:
            _wait_workers(client, ["A"])
        rc, stdout, err = _finish(_cli(CASE, *args, "--scheduler", cluster.address, "--out", tmp_path / "dask"))
    finally:
        cluster.close()
    assert rc == 0, err
    (cell,) = json.loads(stdout)["cells"]
    assert cell["simulated_seconds"] == pytest.approx(2e-3, rel=1e-9)
    rcl, stdout_l, errl = _finish(local)
    assert rcl == 0, errl
    a, b = _series(tmp_path / "dask", "hub_100kmh_1000Hz"), _series(tmp_path / "local", "hub_100kmh_1000Hz")
    for k in a:
        assert np.array_equal(a[k], b[k]), k


@pytest.mark.parametrize("args, field", [
    (["--traction", "magic"], "--traction"),
    (["--speeds", "fast"], "--speeds"),
    (["--cycles", "1"], "--cycles"),
    (["--workers", "0"], "--workers"),
    (["--frequencies", "50,50"], "--frequencies"),
])
def test_bad_input_is_one_line_and_exit_2(tmp_path, args, field):
    rc, out, err = _finish(_cli(CASE, *args, "--out", tmp_path / "o"), timeout=60)
    assert rc == 2, err
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error:") and field in lines[0], err
    assert not list(tmp_path.glob("o/*.nc"))
