"""The integrators' disk cache (dynamics.integrate.specialised): a second process loads the integrator kernels of
the engine's right-hand sides instead of compiling them, and the cache is dropped when a kernel source changes.

Before, every process compiled the generic kernels (they take the right-hand side as an argument, which numba's
disk cache does not serve): ~7 s of CPU for each ``bearingsim simulate``.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap

import pytest

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics.integrate import specialised

CASE = """
bearing = "skf-7011-cdga-hc"
speed = "10000 rpm"
duration = "0.05 ms"
output_interval = "0.05 ms"
traction = "coulomb"
[loads]
fa = "3000 N"
"""

#: run in a fresh interpreter: a short simulation per method, then the bearingsim kernels that compiled and the
#: cache statistics of the specialised kernels it ran (JSON on the last line of stdout)
SCRIPT = textwrap.dedent("""
    import json, sys, tomllib
    from numba.core import event

    compiled = []

    class Listener(event.Listener):
        def on_start(self, ev):
            f = ev.data["dispatcher"].py_func
            if f.__module__.startswith("bearingsim"):
                compiled.append(f.__module__ + "." + f.__name__)

        def on_end(self, ev):
            pass

    event.register("numba:compile", Listener())
    from bearingsim.dynamics.case import case_from_dict
    from bearingsim.dynamics.integrate import specialised
    from bearingsim.dynamics.run import Stepper, build

    model, loadspec, y0, _ = build(case_from_dict(tomllib.loads(sys.argv[1])))
    out = {"compiled": compiled, "stats": {}, "y": {}}
    for method, kernel in (("dopri5", "dopri5"), ("ros34w", "ros34pw2")):
        st = Stepper(model, loadspec, y0.copy(), method=method, h=1e-7, threads=1)
        st.advance(2e-5)
        k = specialised.KERNELS[kernel, "serial"]
        out["stats"][method] = [sum(k.stats.cache_hits.values()), sum(k.stats.cache_misses.values())]
        out["y"][method] = st.y.tobytes().hex()
    print(json.dumps(out))
""")


def _run(env) -> dict:
    p = subprocess.run([sys.executable, "-c", SCRIPT, CASE], capture_output=True, text=True, env=env, timeout=900)
    assert p.returncode == 0, p.stderr[-3000:]
    return json.loads(p.stdout.strip().splitlines()[-1])


def test_a_second_process_loads_the_integrators_from_the_disk_cache():
    """Two processes run the same short simulations (DOPRI5 and ROS34PW2 on ``forces.rhs_args``): the first may
    compile (an empty cache), the second compiles no bearingsim kernel at all (before: the 4 integrator kernels
    every time) and takes the specialised kernels from the disk cache; the trajectories are the same bit for
    bit."""
    env = dict(os.environ)
    first = _run(env)
    second = _run(env)
    assert second["compiled"] == [], second["compiled"]
    for method in ("dopri5", "ros34w"):
        hits, misses = second["stats"][method]
        assert (hits, misses) == (1, 0), (method, second["stats"])
        assert second["y"][method] == first["y"][method]


def test_engine_right_hand_sides_select_the_cached_kernels():
    """``advance`` runs the specialised kernel for the engine's two right-hand sides only; any other numba
    right-hand side (the tests' own) runs the generic kernel with it."""
    from numba import njit

    for method in ("dopri5", "ros2", "ros34pw2"):
        assert specialised.engine_kernel(method, fo.rhs_args) is specialised.KERNELS[method, "serial"]
        assert specialised.engine_kernel(method, fo.rhs_args_threaded) is specialised.KERNELS[method, "threaded"]

    @njit
    def decay(t, y, dy, args):
        dy[0] = -y[0]

    assert specialised.engine_kernel("dopri5", decay) is None
    # every specialised kernel has the disk cache whose stamp holds the kernel packages' digest (not a silent
    # fallback to no cache after a change of numba's interface)
    for k in specialised.KERNELS.values():
        assert type(k._cache).__name__ == "KernelSourcesCache"
        assert k._cache._impl.locator.get_source_stamp()[1] == specialised.sources_digest()


def test_the_digest_covers_the_kernel_sources(tmp_path):
    """The modules whose compiled code the specialised kernels hold are in the digest (numba alone would check
    only specialised.py, and serve stale code after an edit of forces.py); any edit changes it."""
    rel = specialised.kernel_sources()
    for module in ("dynamics/forces.py", "dynamics/contacts.py", "dynamics/layout.py", "contact/slices.py",
                   "statics/layout.py", "dynamics/integrate/dopri5.py", "dynamics/integrate/specialised.py"):
        assert module in rel
    assert specialised.sources_digest() == specialised.sources_digest(specialised.PACKAGE_DIR)
    for sub in ("dynamics", "contact"):
        (tmp_path / sub).mkdir()
    (tmp_path / "dynamics" / "forces.py").write_text("A = 1\n")
    (tmp_path / "contact" / "slices.py").write_text("B = 1\n")
    d0 = specialised.sources_digest(str(tmp_path))
    (tmp_path / "contact" / "slices.py").write_text("B = 2\n")
    assert specialised.sources_digest(str(tmp_path)) != d0


def test_a_changed_digest_drops_the_cached_kernel(tmp_path, monkeypatch):
    """The mechanism on a small kernel that calls a jitted function of another module: cached, loaded by a new
    dispatcher while the digest is the same, compiled again (with the callee's new code) once it differs."""
    (tmp_path / "callee_mod.py").write_text("from numba import njit\n\n\n@njit\ndef g(x):\n    return x + 1\n")
    (tmp_path / "caller_mod.py").write_text("import callee_mod\n\n\ndef f(x):\n    return callee_mod.g(x)\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    import caller_mod

    monkeypatch.setattr(specialised, "_DIGEST", "digest-1")
    k1 = specialised._cached(caller_mod.f)
    assert k1(1) == 2 and sum(k1.stats.cache_misses.values()) == 1
    k2 = specialised._cached(caller_mod.f)
    assert k2(1) == 2 and (sum(k2.stats.cache_hits.values()), sum(k2.stats.cache_misses.values())) == (1, 0)
    # the callee changes (in another file, which numba's own stamp would not see), and so does the digest
    import callee_mod
    from numba import njit

    monkeypatch.setattr(callee_mod, "g", njit(lambda x: x + 2))
    k3 = specialised._cached(caller_mod.f)
    assert k3(1) == 2, "numba alone serves the stale kernel (same digest): the reason for the digest"
    monkeypatch.setattr(specialised, "_DIGEST", "digest-2")
    k4 = specialised._cached(caller_mod.f)
    assert k4(1) == 3 and sum(k4.stats.cache_misses.values()) == 1


@pytest.mark.parametrize("variant", ["serial", "threaded"])
def test_specialised_kernels_name_their_right_hand_side(variant):
    """Each specialised kernel calls the right-hand side its name says (a swap would still run, on the wrong
    function)."""
    import inspect

    fun = "forces.rhs_args_threaded" if variant == "threaded" else "forces.rhs_args,"
    for (method, v), k in specialised.KERNELS.items():
        if v == variant:
            assert fun in inspect.getsource(k.py_func), (method, variant)


def test_compilation_note_counts_a_kernel_compiled_inside_a_cached_one_as_cached(tmp_path):
    """The ``simulate`` note (cli.console): the generic integrators are compiled without a cache of their own, but
    inside their cached specialisations, whose disk cache holds them: the note says "cached for the next runs"
    (not "compiled on every run"), and the next run compiles nothing and says nothing."""
    (tmp_path / "bearingsim_probe.py").write_text(
        "from numba import njit\n\n\n@njit\ndef inner(x):\n    return x + 1\n\n\n"
        "@njit(cache=True)\ndef outer(x):\n    return 2 * inner(x)\n")
    code = ("from bearingsim.cli.console import announce_compilation, finish_compilation_note\n"
            "announce_compilation()\n"
            "import bearingsim_probe\n"
            "assert bearingsim_probe.outer(1) == 4\n"
            "finish_compilation_note()\n")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(tmp_path), os.environ.get("PYTHONPATH", "")]),
               NUMBA_CACHE_DIR=str(tmp_path / "cache"))
    runs = [subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=300)
            for _ in range(2)]
    assert all(p.returncode == 0 for p in runs), [p.stderr for p in runs]
    lines = runs[0].stderr.splitlines()
    assert lines[-1].startswith("compiled 2 kernels in ") and lines[-1].endswith("(cached for the next runs)"), lines
    assert runs[1].stderr == ""
