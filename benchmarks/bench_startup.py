"""Start-up benchmark of the command line (issue 11, item 9).  Prints figures; not a test.

(a) import time of ``bearingsim.cli`` (what every command pays before it runs), best of 5;
(b) first call after install: ``bearingsim static skf-7011-cdga-hc --fa 3000 --json`` with an empty numba
    cache (NUMBA_CACHE_DIR pointed at a fresh temporary folder, so every kernel the command needs is compiled);
(c) the same call warm (cache filled by (b)): best and median of N wall times, and the best CPU time
    (user + system of the child: less sensitive than wall time to other jobs on a shared machine);
(d) ``bearingsim --version`` and ``bearingsim static --help`` (no kernels, no numerical imports), best of 5.

By default the console script on PATH is timed, as a user runs it (on a pyenv install that is a shell shim which
adds ~0.1 s to every call; the script it execs is timed too).  ``--src A B ...`` times source trees side by side
instead (PYTHONPATH=TREE, the same launcher for each, warm runs interleaved round-robin so that the load of the
machine falls on all of them alike): e.g. a ``git worktree`` of an older commit against ``src``.

Run:  python benchmarks/bench_startup.py [--runs 5] [--cold-runs 1] [--skip-cold] [--src TREE ...]
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ARGS = ["static", "skf-7011-cdga-hc", "--fa", "3000", "--json"]
LAUNCH = "import sys; sys.argv[0] = 'bearingsim'; from bearingsim.cli import main; sys.exit(main())"


def timed(cmd, env) -> tuple[float, float, subprocess.CompletedProcess]:
    """Wall and CPU (user + system) time [s] of one subprocess run, and its result."""
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    wall = time.perf_counter() - t
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime), p


class Target:
    """One way of running the command line: a console script, or a source tree through PYTHONPATH."""

    def __init__(self, name: str, prefix: list[str], pythonpath: str | None = None):
        self.name, self.prefix = name, prefix
        self.env = dict(os.environ)
        self.env.pop("BEARINGSIM_DEBUG", None)
        self.env.pop("NUMBA_CACHE_DIR", None)
        if pythonpath:
            self.env["PYTHONPATH"] = os.pathsep.join([pythonpath, os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
        self.cache = tempfile.mkdtemp(prefix="bearingsim-bench-numba-")
        self.env["NUMBA_CACHE_DIR"] = self.cache
        self.warm_wall: list[float] = []
        self.warm_cpu: list[float] = []

    def run(self, args, check: bool = True):
        wall, cpu, p = timed(self.prefix + list(args), self.env)
        if check and p.returncode != 0:
            sys.exit(f"{self.name}: `{' '.join(args)}` failed (exit {p.returncode}): {p.stderr.strip()[-800:]}")
        return wall, cpu, p

    def import_time(self, n: int = 5) -> float:
        code = "import time; t = time.perf_counter(); import bearingsim.cli; print(time.perf_counter() - t)"
        return min(float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=self.env,
                                        check=True).stdout) for _ in range(n))

    def close(self):
        shutil.rmtree(self.cache, ignore_errors=True)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5, help="warm runs per target")
    ap.add_argument("--cold-runs", type=int, default=1, help="first-call runs, each with a fresh cache")
    ap.add_argument("--skip-cold", action="store_true", help="fill the cache without timing it")
    ap.add_argument("--src", nargs="+", metavar="TREE", help="source trees (folders holding bearingsim/) to compare")
    args = ap.parse_args()

    if args.src:
        targets = [Target(f"tree {s}", [sys.executable, "-c", LAUNCH], str(Path(s).resolve())) for s in args.src]
    else:
        on_path = shutil.which("bearingsim")
        if on_path is None:
            sys.exit("the console script `bearingsim` is not on PATH (pip install -e .)")
        targets = [Target(f"`bearingsim` on PATH ({on_path})", [on_path])]
        script = Path(sys.prefix) / "bin" / "bearingsim"
        if script.is_file() and script.resolve() != Path(on_path).resolve():
            targets.append(Target(f"the script it runs ({script})", [str(script)]))

    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; python {sys.version.split()[0]}")
    for t in targets:
        print(f"[{t.name}]")
        print(f"  (a) import bearingsim.cli: {t.import_time() * 1e3:.0f} ms (best of 5)")
        for i in range(max(args.cold_runs, 1)):
            if i:
                shutil.rmtree(t.cache, ignore_errors=True)
                os.makedirs(t.cache)
            wall, cpu, p = t.run(ARGS)
            note = [ln for ln in p.stderr.splitlines() if ln.strip()]
            if not args.skip_cold:
                print(f"  (b) first call, empty numba cache: {wall:.2f} s wall, {cpu:.2f} s CPU"
                      + (f"  [stderr: {note[0][:100]}]" if note else "  [nothing on stderr]"))
    for _ in range(args.runs):  # round-robin: the machine's load falls on every target alike
        for t in targets:
            wall, cpu, _ = t.run(ARGS)
            t.warm_wall.append(wall)
            t.warm_cpu.append(cpu)
    for t in targets:
        print(f"[{t.name}]")
        print(f"  (c) warm `bearingsim {' '.join(ARGS)}`: best {min(t.warm_wall):.2f} s, median "
              f"{statistics.median(t.warm_wall):.2f} s wall; best {min(t.warm_cpu):.2f} s CPU ({args.runs} runs)")
        for extra in (["--version"], ["static", "--help"]):
            runs = [t.run(extra, check=False) for _ in range(5)]
            rc = runs[0][2].returncode
            print(f"  (d) `bearingsim {' '.join(extra)}`: {min(r[0] for r in runs):.2f} s wall (best of 5)"
                  + (f", exit {rc}: {runs[0][2].stderr.strip().splitlines()[-1][:80]}" if rc else ""))
        t.close()
    print(f"load average {os.getloadavg()[0]:.2f} at the end")


if __name__ == "__main__":
    main()
