"""Output paths of every command that writes files, through the installed console script (issue 11 item 4).

* a missing output folder is created (it was a FileNotFoundError traceback in map, map --plot, simulate,
  export ross, traction-curve and reproduce hub-static, while reproduce spindle-axial-stiffness created it);
* an output that cannot be written (a folder that cannot be created, a read-only place, a full disk) is one line
  naming the option, exit 2, checked before computing where possible, and leaves no file, finished or partial;
* files are written with the user's umask (the netCDF map was 0600 through ``tempfile.mkstemp``).

Tests run as root in CI, where chmod 0555 does not stop a write: an unwritable folder is made by putting the path
under a regular FILE (NotADirectoryError), and a full disk is /dev/full.
"""

from __future__ import annotations

import os
import shutil
import stat
import subprocess
import tempfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = shutil.which("bearingsim")
CASE = ROOT / "examples" / "spindle-7011.toml"


def run(*args, umask=None):
    assert SCRIPT is not None, "the console script `bearingsim` is not installed (pip install -e .)"
    env = dict(os.environ)
    env.pop("BEARINGSIM_DEBUG", None)
    pre = (lambda: os.umask(umask)) if umask is not None else None
    return subprocess.run([SCRIPT, *map(str, args)], capture_output=True, text=True, env=env, preexec_fn=pre,
                          timeout=600)


def error_lines(p) -> list[str]:
    """stderr without the one-time compilation note (a kernel changed since the last run)."""
    return [ln for ln in p.stderr.splitlines() if ln.strip() and not ln.startswith(("compiling ", "compiled "))]


def leftovers(folder: Path) -> list[str]:
    return sorted(f.name for f in folder.rglob("*") if ".part" in f.name or f.name.endswith(".tmp"))


# command -> (arguments with {d} for the output root, files expected under {d})
COMMANDS = {
    "map": (["map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--out", "{d}/a/b/map.nc", "--plot",
             "{d}/c/d/kxx.png", "--json"], ["a/b/map.nc", "c/d/kxx.png"]),
    "simulate": (["simulate", "{d}/case.toml", "--out", "{d}/a/b/run.nc", "--duration", "0.05 ms", "--quiet",
                  "--json"], ["a/b/run.nc"]),
    "export ross": (["export", "ross", "skf-7011-cdga-hc", "--fa", "1000", "--speed", "0:1000:2", "--out",
                     "{d}/a/b/ross.json"], ["a/b/ross.json"]),
    "traction-curve": (["traction-curve", "--out", "{d}/a/b/traction.png"], ["a/b/traction.png"]),
    "reproduce hub-static": (["reproduce", "hub-static", "--points", "3", "--out", "{d}/a/b"],
                             ["a/b/hub_static.csv", "a/b/hub_static.png"]),
    "reproduce spindle-axial-stiffness": (["reproduce", "spindle-axial-stiffness", "--out", "{d}/a/b"],
                                          ["a/b/spindle_axial_stiffness.csv", "a/b/spindle_axial_stiffness_fig5.png"]),
}


@pytest.mark.parametrize("command", list(COMMANDS))
def test_missing_output_folders_are_created(command, tmp_path):
    args, files = COMMANDS[command]
    # the example case with the explicit integrator, whose kernels compile in a third of ROS34PW2's time
    case = CASE.read_text()
    assert "\nintegrator" not in case and "\ntolerance =" in case
    (tmp_path / "case.toml").write_text(case.replace("\ntolerance =", '\nintegrator = "dopri5"\ntolerance ='))
    p = run(*[a.format(d=tmp_path) for a in args], umask=0o027)
    assert p.returncode == 0, p.stderr
    for f in files:
        path = tmp_path / f
        assert path.is_file() and path.stat().st_size > 0, f
        # the user's umask (027 here), not mkstemp's 0600 nor a fixed 0644
        assert stat.S_IMODE(path.stat().st_mode) == 0o640, (f, oct(path.stat().st_mode))
    assert leftovers(tmp_path) == []


# an output below a regular file: the folder cannot be created (NotADirectoryError, also as root)
UNWRITABLE = {
    "map --out": (["map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--out", "{f}/sub/map.nc"], "--out"),
    "map --plot": (["map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--out", "{d}/map.nc", "--plot",
                    "{f}/kxx.png"], "--plot"),
    "simulate": (["simulate", str(CASE), "--out", "{f}/run.nc", "--duration", "0.05 ms", "--quiet"], "--out"),
    "export ross": (["export", "ross", "skf-7011-cdga-hc", "--fa", "1000", "--out", "{f}/ross.json"], "--out"),
    "traction-curve": (["traction-curve", "--out", "{f}/sub/traction.png"], "--out"),
    "reproduce hub-static": (["reproduce", "hub-static", "--points", "3", "--out", "{f}/sub"], "--out"),
    "reproduce spindle-axial-stiffness": (["reproduce", "spindle-axial-stiffness", "--out", "{f}"], "--out"),
}


@pytest.mark.parametrize("case", list(UNWRITABLE))
def test_unwritable_output_is_one_line_exit_2_before_computing(case, tmp_path):
    args, option = UNWRITABLE[case]
    afile = tmp_path / "afile"
    afile.write_text("a regular file\n")
    out = tmp_path / "out"
    out.mkdir()
    p = run(*[a.format(f=afile, d=out) for a in args])
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith(f"error: {option}: "), p.stderr
    assert "Traceback" not in p.stderr
    assert "compiling" not in p.stderr  # refused before any kernel ran
    assert sorted(os.listdir(tmp_path)) == ["afile", "out"] and os.listdir(out) == []  # map --plot: no map.nc


def _read_only_folder(tmp_path: Path) -> Path | None:
    """A folder where creating a file fails: chmod 0555 for a normal user; as root (where permissions do not
    apply) a read-only mount such as /sys, if this machine has one."""
    if hasattr(os, "geteuid") and os.geteuid() != 0:
        d = tmp_path / "ro"
        d.mkdir()
        d.chmod(0o555)
        return d
    for cand in (Path("/sys"), Path("/proc/sys")):
        if cand.is_dir():
            try:
                tempfile.TemporaryFile(dir=cand).close()
            except OSError:
                return cand
    return None


def test_read_only_folder_is_one_line_exit_2(tmp_path):
    ro = _read_only_folder(tmp_path)
    if ro is None:
        pytest.skip("no read-only folder on this machine")
    try:
        p = run("export", "ross", "skf-7011-cdga-hc", "--fa", "1000", "--out", ro / "bearingsim-test-ross.json")
        assert p.returncode == 2, p.stderr
        err = error_lines(p)
        assert len(err) == 1 and err[0].startswith("error: --out: cannot write"), p.stderr
        assert not (ro / "bearingsim-test-ross.json").exists()
    finally:
        if ro.is_relative_to(tmp_path):
            ro.chmod(0o755)


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full (a device that is always full)")
@pytest.mark.parametrize("args", [
    ["export", "ross", "skf-7011-cdga-hc", "--fa", "1000", "--speed", "0:1000:2", "--out", "/dev/full"],
    ["traction-curve", "--out", "/dev/full"],
])
def test_full_disk_is_one_line_exit_2(args):
    before = set(os.listdir(tempfile.gettempdir()))
    p = run(*args)
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith("error: --out: cannot write /dev/full: No space left"), p.stderr
    new = set(os.listdir(tempfile.gettempdir())) - before
    assert not [n for n in new if n.startswith(".full.")], new  # the temporary file was removed
    assert not Path("/dev/full.png").exists()  # matplotlib's habit of appending ".png" is not followed


# ---- the mechanism (cli.output), in-process ------------------------------------------------------------------
def test_atomic_output_keeps_the_old_file_when_the_writer_fails(tmp_path):
    from bearingsim.cli.output import atomic_output
    from bearingsim.errors import InputError

    target = tmp_path / "sub" / "result.csv"
    with atomic_output(target, "--out") as tmp:
        tmp.write_text("first\n")
    assert target.read_text() == "first\n"

    with pytest.raises(InputError, match="--out: cannot write .*No space left"):
        with atomic_output(target, "--out") as tmp:
            tmp.write_text("half of the sec")
            raise OSError(28, "No space left on device")
    assert target.read_text() == "first\n"  # untouched, not half-written
    assert os.listdir(target.parent) == ["result.csv"]  # no temporary file left

    with pytest.raises(KeyboardInterrupt):
        with atomic_output(target, "--out") as tmp:
            tmp.write_text("interrupted")
            raise KeyboardInterrupt
    assert target.read_text() == "first\n" and os.listdir(target.parent) == ["result.csv"]


def test_output_file_refuses_a_folder_and_a_path_below_a_file(tmp_path):
    from bearingsim.cli.output import output_file, output_folder
    from bearingsim.errors import InputError

    with pytest.raises(InputError, match="--plot: .* is a folder"):
        output_file(tmp_path, "--plot")
    (tmp_path / "f").write_text("x")
    with pytest.raises(InputError, match="--out: cannot create the folder .* is a file"):
        output_file(tmp_path / "f" / "g" / "x.nc", "--out")
    with pytest.raises(InputError, match="--out: cannot create the folder"):
        output_folder(tmp_path / "f", "--out")
    assert output_file(tmp_path / "new" / "x.nc", "--out") == tmp_path / "new" / "x.nc"
    assert (tmp_path / "new").is_dir() and not (tmp_path / "new" / "x.nc").exists()


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs named pipes")
@pytest.mark.parametrize("args", [
    ["map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--out", "{p}"],
    ["simulate", str(CASE), "--out", "{p}", "--duration", "0.05 ms", "--quiet"],
])
def test_renamed_output_refuses_a_device_or_pipe(args, tmp_path):
    """map and simulate write netCDF under a temporary name and rename it onto --out: onto /dev/null (as root)
    that would replace the device by a regular file.  A pipe stands in for the device here (harmless if the guard
    failed: the pipe would become a file and the test fail)."""
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    p = run(*[a.format(p=fifo) for a in args])
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith(f"error: --out: {fifo} is not a regular file"), p.stderr
    assert stat.S_ISFIFO(os.stat(fifo).st_mode) and sorted(os.listdir(tmp_path)) == ["pipe"]


def test_writing_maps_only_errors_about_the_output(tmp_path):
    """A full disk while a streamed output is written (map, simulate) is the output's InputError; an OSError about
    another file (an input read in the same block) passes unchanged."""
    import errno

    from bearingsim.cli.output import writing
    from bearingsim.errors import InputError

    out = tmp_path / "run.nc"
    for name in (str(out) + ".tmp", str(out) + ".ckpt.npz", None):
        with pytest.raises(InputError, match="--out: cannot write .*No space left.*free disk space"):
            with writing("--out", out):
                raise OSError(errno.ENOSPC, "No space left on device", name)
    with pytest.raises(FileNotFoundError):
        with writing("--out", out):
            raise FileNotFoundError(errno.ENOENT, "No such file or directory", str(tmp_path / "case.toml"))


def test_bad_bearing_is_refused_before_any_output_folder_is_made(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "x"\n', encoding="utf-8")
    out = tmp_path / "new" / "sub" / "m.nc"
    r = subprocess.run(["bearingsim", "map", str(bad), "--fr", "100:200:2", "--out", str(out)],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "ball_diameter" in r.stderr, r.stderr
    assert not (tmp_path / "new").exists(), "a refused map must not leave folders behind"


WRONG_TYPE = {
    "map --out": (["map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--out", "{d}/new/m.csv"], "--out", ".nc"),
    "map --plot": (["map", "skf-7011-cdga-hc", "--fa", "1000:2000:2", "--out", "{d}/new/m.nc", "--plot",
                    "{d}/new/kxx.txt"], "--plot", ".png"),
    "simulate": (["simulate", str(CASE), "--out", "{d}/new/run.csv", "--duration", "0.05 ms", "--quiet"], "--out",
                 ".nc"),
    "export ross": (["export", "ross", "skf-7011-cdga-hc", "--fa", "1000", "--speed", "0:1000:2", "--out",
                     "{d}/new/ross.txt"], "--out", ".json"),
    "traction-curve": (["traction-curve", "--out", "{d}/new/mu.txt"], "--out", ".png"),
}


@pytest.mark.parametrize("name", sorted(WRONG_TYPE))
def test_an_output_of_another_file_type_is_refused_before_anything_is_written(name, tmp_path):
    """A map named .csv was written as netCDF under that name; a figure named .txt failed with an internal error
    after the map had been computed and written (new-user trial, session 26): now one line naming the option and
    the suffixes it takes, exit 2, and nothing created."""
    args, option, example = WRONG_TYPE[name]
    p = run(*[a.replace("{d}", str(tmp_path)) for a in args])
    assert p.returncode == 2, p.stderr
    err = error_lines(p)
    assert len(err) == 1 and err[0].startswith(f"error: {option}: ") and example in err[0], p.stderr
    assert not (tmp_path / "new").exists(), sorted(tmp_path.rglob("*"))
