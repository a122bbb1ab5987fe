"""Resume at any time (issue 11 item 8): wall-clock checkpoints, ``--resume`` without a checkpoint,
no checkpoint left after a completed run, and bitwise resumes after SIGKILLs of the real
``bearingsim simulate`` process at several points (before the first checkpoint included)."""

from __future__ import annotations

import os
import signal
import subprocess
import time
import tomllib
from pathlib import Path

import numpy as np
import pytest

from bearingsim.dynamics import run as rn
from bearingsim.dynamics.case import case_from_dict
from bearingsim.errors import InputError

# DOPRI5 with the Coulomb stand-in: a few seconds per run; chunk larger than the run, so that every
# checkpoint before the end comes from the wall-clock interval
CASE = """
bearing = "skf-7011-cdga-hc"
speed = "10000 rpm"
duration = "{duration}"
output_interval = "0.05 ms"
traction = "coulomb"
chunk = 1000
[loads]
fa = "3000 N"
mz = {{ offset = "0 N*m", amplitude = "20 N*m", frequency = "500 Hz" }}
"""


def _case(duration="1 ms", **extra):
    data = tomllib.loads(CASE.format(duration=duration))
    data.update(extra)
    return case_from_dict(data)


def test_wall_clock_checkpoints_come_before_the_first_chunk_and_go_after_completion(tmp_path, monkeypatch):
    saved = []
    real = rn._save_checkpoint

    def spy(path, stepper, index, fp):
        saved.append(index)
        real(path, stepper, index, fp)

    monkeypatch.setattr(rn, "_save_checkpoint", spy)
    out = tmp_path / "run.nc"
    case = _case("0.5 ms")  # 10 samples, far fewer than one chunk (1000)
    rn.simulate(case, out=out, checkpoint_seconds=1e-9)  # interval always elapsed: one after every sample
    assert saved == list(range(2, 12))  # the record count after samples 1..10 (sample 0 is the start)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.nc"]  # no checkpoint (nor its temporary) left
    Path(str(out) + ".ckpt.npz.tmp.npz").write_bytes(b"half-saved by a killed run")
    saved.clear()
    rn.simulate(case, out=out, checkpoint_seconds=1e9)  # interval never elapsed, no full chunk: none
    assert saved == []
    import xarray as xr

    with xr.open_dataset(out) as ds:
        assert ds.sizes["time"] == 11
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.nc"]


def test_resume_without_checkpoint_starts_from_the_beginning_with_a_note(tmp_path):
    out = tmp_path / "run.nc"
    case = _case("0.3 ms")
    ref = rn.simulate(case)  # in memory
    with pytest.warns(UserWarning, match="no checkpoint run.nc.ckpt.npz.*starting from the beginning"):
        res = rn.simulate(case, out=out, resume=True)
    for k in ("inner_ring_displacement", "ball_orbital_speed", "cage_angular_speed"):
        assert np.array_equal(ref.data[k], res.data[k]), k
    # a stale checkpoint never meets a new file: a run without --resume removes it
    ckpt = Path(str(out) + ".ckpt.npz")
    ckpt.write_bytes(b"stale")
    rn.simulate(case, out=out)
    assert not ckpt.exists()
    # a checkpoint of another case is refused (not overwritten)
    rn._save_checkpoint(ckpt, rn.Stepper(*rn.build(case)[:3]), 1, "another case")
    with pytest.raises(InputError, match="different case"):
        rn.simulate(case, out=out, resume=True)


def test_checkpoint_interval_in_the_case_file(tmp_path):
    c = _case(checkpoint_every="10 s")
    assert c.checkpoint_interval == 10.0 and c.checkpoint_every == 1
    assert c.fingerprint() == _case().fingerprint()  # how often to checkpoint is not part of the trajectory
    assert _case(checkpoint_every=3).checkpoint_every == 3 and _case(checkpoint_every=3).checkpoint_interval is None
    for bad in ("0 s", "-5 s", "5 m", 0, True, 2.5):
        with pytest.raises(InputError) as e:
            _case(checkpoint_every=bad)
        assert e.value.field == "checkpoint_every", bad
    with pytest.raises(InputError) as e:
        rn.simulate(_case(), out=tmp_path / "x.nc", checkpoint_seconds=0.0)
    assert e.value.field == "checkpoint_every"


def _cli(*args):
    return subprocess.Popen(["bearingsim", "simulate", *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True)


def _checkpoint_index(ckpt: Path) -> int:
    try:
        with np.load(ckpt) as c:
            return int(c["index"])
    except (OSError, ValueError, EOFError, KeyError):  # absent, or being renamed into place
        return -1


def _kill_when(p, condition, what, timeout=60.0):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        if p.poll() is not None:
            pytest.fail(f"the run ended ({p.returncode}) before {what}: {p.stderr.read().decode()[-500:]}")
        if condition():
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=10)
            return
        time.sleep(0.01)
    os.killpg(p.pid, signal.SIGKILL)
    pytest.fail(f"timed out waiting for {what}")


def test_sigkill_at_any_point_then_resume_gives_the_uninterrupted_trajectory_bitwise(tmp_path):
    """The real CLI process is SIGKILLed (1) after it created its output but before any checkpoint,
    (2) right after its first wall-clock checkpoint, (3) after a later one; every time it is resumed
    with --resume, and the finished file equals an uninterrupted run in every variable, bit for bit.
    16 ms: the part after the first checkpoint must outlast another checkpoint interval (0.2 s of wall time)
    on a fast machine too — with 8 ms a resumed run finished in 0.199 s once the engine got faster (issue 14)."""
    import xarray as xr

    case = tmp_path / "case.toml"
    case.write_text(CASE.format(duration="16 ms"))
    ref, out = tmp_path / "ref.nc", tmp_path / "run.nc"
    ckpt = Path(str(out) + ".ckpt.npz")
    pref = _cli(case, "--out", ref, "--quiet")  # the uninterrupted reference, alongside
    every = ["--checkpoint-every", "0.2 s", "--quiet"]
    # (1) killed before its first checkpoint (output file created, 0-1 records)
    p = _cli(case, "--out", out, *every)
    _kill_when(p, lambda: out.exists() and not ckpt.exists(), "the output file appeared")
    assert not ckpt.exists()
    # (2) resumed without a checkpoint: starts again with a one-line note; killed after its first checkpoint
    p = _cli(case, "--out", out, "--resume", *every)
    _kill_when(p, lambda: _checkpoint_index(ckpt) > 0, "the first checkpoint")
    note = p.stderr.read().decode().strip().splitlines()
    assert note and note[0].startswith("--resume: no checkpoint") and "starting from the beginning" in note[0], note
    first = _checkpoint_index(ckpt)
    # (3) resumed from it; killed after a later checkpoint
    p = _cli(case, "--out", out, "--resume", *every)
    _kill_when(p, lambda: _checkpoint_index(ckpt) > first, "a later checkpoint")
    second = _checkpoint_index(ckpt)
    assert 0 < first < second < 321
    # (4) resumed to the end: the checkpoint goes, the file equals the reference bitwise
    p = _cli(case, "--out", out, "--resume", *every)
    _, err = p.communicate(timeout=120)
    assert p.returncode == 0, err.decode()
    assert "starting from the beginning" not in err.decode()
    assert not ckpt.exists()
    _, err = pref.communicate(timeout=120)
    assert pref.returncode == 0, err.decode()
    with xr.open_dataset(ref) as a, xr.open_dataset(out) as b:
        assert a.sizes["time"] == b.sizes["time"] == 321
        for k in a.variables:
            assert np.array_equal(a[k].values, b[k].values), k


def test_cli_checkpoint_every_bad_value_is_one_line_exit_2(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text(CASE.format(duration="0.1 ms"))
    for bad in ("0 s", "ten seconds"):
        p = _cli(case, "--out", tmp_path / "x.nc", "--checkpoint-every", bad)
        _, err = p.communicate(timeout=60)
        lines = err.decode().strip().splitlines()
        assert p.returncode == 2 and len(lines) == 1 and "--checkpoint-every" in lines[0], (bad, err)
