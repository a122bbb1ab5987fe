"""Before/after in the same minutes: run one benchmark command alternately in an earlier commit and in this tree.

These shared machines vary by 2× with load, so a speed change is only read against the commit before it, measured
in the same run.  This script checks the earlier commit out as a detached git worktree (kept for the next call,
under the system's temporary folder), then runs the command ``--rounds`` times in each tree, alternating (before,
after, before, after …), with ``PYTHONPATH`` at each tree's ``src`` and the benchmark script taken from the same
tree, and prints every run's lines that carry a figure, then the figures side by side.

Usage:  python benchmarks/bench_compare.py REV [--rounds 2] [--grep TEXT] -- SCRIPT [ARGS ...]
e.g.    python benchmarks/bench_compare.py 847a792 -- bench_dynamics.py --case b --threads 2

SCRIPT is a file name under ``benchmarks/`` (the earlier commit's own copy runs in its tree; if it has none, this
tree's runs there).  ``--grep``: the lines to keep (default: lines with "wall s per simulated s", "points/s",
" µs" or " us").  The first run in a new worktree compiles its numba kernels; the benchmarks here exclude
compilation from their figures (bench_dynamics warms up first), others may not: use --rounds ≥ 2 and read the
later rounds.  Not a test: figures depend on the machine.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
KEEP = ("wall s per simulated s", "points/s", " µs", " us")
#: "-> 166.9 wall s per simulated s", "50,500 points/s", "82.3 us" …: the first figure of a kept line
FIGURE = re.compile(r"(?:->\s*)?([0-9][0-9,]*\.?[0-9]*)\s*(?:wall s per simulated s|points/s|µs|us)\b")


def first_figure(line: str) -> float | None:
    """The first figure of a benchmark line (``-> X wall s per simulated s``, ``N points/s``, ``X µs``), or None."""
    m = FIGURE.search(line)
    return float(m.group(1).replace(",", "")) if m else None


def worktree(rev: str) -> Path:
    """A detached worktree of ``rev`` (made once, reused by later calls)."""
    sha = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "--verify", f"{rev}^{{commit}}"], check=True,
                         capture_output=True, text=True).stdout.strip()
    path = Path(tempfile.gettempdir()) / f"bearingsim-bench-{sha[:12]}"
    if not (path / "src").is_dir():
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(path), sha], check=True,
                       capture_output=True, text=True)
    return path


def run_in(tree: Path, script: str, args: list[str], grep: tuple[str, ...]) -> list[str]:
    """The kept lines of one run of ``benchmarks/SCRIPT ARGS`` with ``tree``'s sources."""
    bench = tree / "benchmarks" / script
    if not bench.exists():
        bench = ROOT / "benchmarks" / script
    env = dict(os.environ, PYTHONPATH=str(tree / "src"))
    r = subprocess.run([sys.executable, str(bench), *args], cwd=tree, env=env, capture_output=True, text=True)
    if r.returncode != 0:
        tail = (r.stderr or r.stdout).strip().splitlines()[-1:] or ["(no output)"]
        return [f"FAILED (exit {r.returncode}): {tail[0]}"]
    return [ln for ln in r.stdout.splitlines() if any(g in ln for g in grep)]


def main(argv=None) -> None:
    argv = sys.argv[1:] if argv is None else argv
    if "--" not in argv:
        raise SystemExit("usage: bench_compare.py REV [--rounds N] [--grep TEXT] -- SCRIPT [ARGS ...]")
    cut = argv.index("--")
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("rev", help="the earlier commit (any git revision)")
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--grep", action="append", default=None, help="keep the lines containing this (repeatable)")
    a = ap.parse_args(argv[:cut])
    if not argv[cut + 1:]:
        raise SystemExit("bench_compare.py: name the benchmark script after --")
    script, args = argv[cut + 1], argv[cut + 2:]
    grep = tuple(a.grep) if a.grep else KEEP
    before = worktree(a.rev)
    figures: dict[str, list[list[float]]] = {"before": [], "after": []}
    for rnd in range(1, a.rounds + 1):
        for label, tree in (("before", before), ("after", ROOT)):
            lines = run_in(tree, script, args, grep)
            figures[label].append([f for f in map(first_figure, lines) if f is not None])
            for ln in lines:
                print(f"round {rnd} {label:6s} | {ln}", flush=True)
    print(f"figures ({a.rev} → this tree), per kept line, every round:")
    n = max((len(f) for runs in figures.values() for f in runs), default=0)
    for i in range(n):
        cols = [" / ".join(f"{r[i]:g}" for r in figures[lab] if i < len(r)) for lab in ("before", "after")]
        print(f"  line {i + 1}: {cols[0]} → {cols[1]}")


if __name__ == "__main__":
    main()
