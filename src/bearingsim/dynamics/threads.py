"""numba's threading layer for the engine's parallel kernels (``forces._balls_parallel``,
``integrate.linalg.coupled_w_threaded``), chosen and started in one place: every module that holds a
``parallel=True`` kernel imports this one first.

Layer: OpenMP first, else workqueue, unless the user chose one (NUMBA_THREADING_LAYER).  A right-hand side is
≈ 90 µs of work split once per call, so the layer's wake-up decides: on this idle 2-core machine, hub case (b),
20 ms, 2 threads: omp 110 wall s per simulated s against 171 on one thread, workqueue 310 (it wakes sleeping
threads for every call; omp's threads spin briefly between calls).  Spinning threads are the wrong choice on an
oversubscribed machine (load 14 on 2 cores: 1.9 ms per call against 0.44 for workqueue), which is why the CLI's
default thread count counts only idle cores (:func:`.stepper.idle_cores`).  omp needs libgomp (on every Linux
with gcc); without it numba falls back to workqueue.  The result does not depend on the layer (bit for bit).

Started at import (``numba.get_num_threads()`` starts it; no parallel region runs): a cached kernel that calls a
parallel one (``forces.rhs`` → ``balls_on_raceways`` → ``_balls_parallel``) needs the layer's scheduling symbols
when it is loaded, and numba registers them only when the layer starts; a process that loaded such a kernel from
the disk cache before any parallel region has run dies with "LLVM ERROR: Symbol not found: allocate_sched" or a
segmentation fault (tests/unit/test_dyn_threads.py).
"""

from __future__ import annotations

import os

import numba

if "NUMBA_THREADING_LAYER" not in os.environ:
    numba.config.THREADING_LAYER = "default"
    numba.config.THREADING_LAYER_PRIORITY = ["omp", "workqueue", "tbb"]
numba.get_num_threads()
