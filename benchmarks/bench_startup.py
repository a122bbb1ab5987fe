"""Start-up benchmark of the command line (issue 11, item 9).  Prints figures; not a test.

(a) import time of ``bearingsim.cli`` (what every command pays before it runs), best of 5;
(b) first call after install: ``bearingsim static skf-7011-cdga-hc --fa 3000 --json`` with an empty numba
    cache (NUMBA_CACHE_DIR pointed at a fresh temporary folder, so every kernel the command needs is compiled);
(c) the same call warm (cache filled by (b)), best and median of 5;
(d) ``bearingsim --version`` and ``bearingsim static --help`` (no kernels, no numerical imports), best of 5.

Wall-clock times of the installed console script (subprocess), as a user sees them; the machine's load average
is printed with them because the figures move with it.

Run:  python benchmarks/bench_startup.py [--cold-runs N] [--skip-cold]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

CMD = ["bearingsim", "static", "skf-7011-cdga-hc", "--fa", "3000", "--json"]


def wall(cmd, env=None) -> tuple[float, subprocess.CompletedProcess]:
    """Wall time [s] of one subprocess run and its result."""
    t = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, env=env)
    return time.perf_counter() - t, p


def import_time(n: int = 5) -> float:
    """Best time [s] of ``import bearingsim.cli`` in a fresh interpreter (interpreter start excluded)."""
    code = "import time; t = time.perf_counter(); import bearingsim.cli; print(time.perf_counter() - t)"
    return min(float(subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                                    check=True).stdout) for _ in range(n))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cold-runs", type=int, default=1, help="first-call runs, each with a fresh cache")
    ap.add_argument("--skip-cold", action="store_true", help="only the warm figures (uses the default cache)")
    args = ap.parse_args()
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; python {sys.version.split()[0]}")
    print(f"(a) import bearingsim.cli: {import_time() * 1e3:.0f} ms (best of 5)")

    env = dict(os.environ)
    env.pop("BEARINGSIM_DEBUG", None)
    tmp = None
    if not args.skip_cold:
        for i in range(args.cold_runs):
            if tmp:
                shutil.rmtree(tmp, ignore_errors=True)
            tmp = tempfile.mkdtemp(prefix="bearingsim-numba-")
            env["NUMBA_CACHE_DIR"] = tmp
            dt, p = wall(CMD, env)
            if p.returncode != 0:
                sys.exit(f"cold run failed (exit {p.returncode}): {p.stderr.strip()[-500:]}")
            note = p.stderr.strip().splitlines()
            print(f"(b) first call, empty numba cache: {dt:.2f} s wall"
                  + (f"  [stderr: {note[0][:90]}]" if note else "  [no message on stderr]"))
    ts = []
    for _ in range(5):
        dt, p = wall(CMD, env)
        if p.returncode != 0:
            sys.exit(f"warm run failed (exit {p.returncode}): {p.stderr.strip()[-500:]}")
        ts.append(dt)
    print(f"(c) warm `{' '.join(CMD)}`: best {min(ts):.2f} s, median {statistics.median(ts):.2f} s wall")
    for cmd in (["bearingsim", "--version"], ["bearingsim", "static", "--help"]):
        best = min(wall(cmd, env)[0] for _ in range(5))
        print(f"(d) `{' '.join(cmd)}`: {best:.2f} s wall (best of 5)")
    if tmp:
        shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    main()
