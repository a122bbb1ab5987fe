"""The dynamic model's named contract (dynamics.layout) and the dynamics package's import structure."""

import ast
from pathlib import Path

import numpy as np
import pytest

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import layout as ly
from bearingsim.dynamics import model as md

DYN = Path(md.__file__).parent


def _imports(path: Path, package: str) -> set[str]:
    """Modules of bearingsim imported by a source file (module level and inside functions)."""
    out = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            names = [mod + "." + a.name for a in node.names]
            out.update(n if _module_file(n) else mod for n in names)
        elif isinstance(node, ast.Import):
            out.update(a.name for a in node.names)
    return {m for m in out if m.startswith("bearingsim")}


def _module_file(name: str) -> Path | None:
    p = DYN.parents[1].joinpath(*name.split("."))
    for cand in (p.with_suffix(".py"), p / "__init__.py"):
        if cand.exists():
            return cand
    return None


def test_layout_is_a_leaf_and_dynamics_has_no_import_cycle():
    """layout imports nothing from bearingsim; no cycle among the dynamics modules (cage <-> model was one)."""
    files = {("bearingsim.dynamics." + ".".join(p.relative_to(DYN).with_suffix("").parts)).replace(".__init__", ""): p
             for p in DYN.rglob("*.py")}
    graph = {}
    for mod, path in files.items():
        package = mod if path.name == "__init__.py" else mod.rsplit(".", 1)[0]
        graph[mod] = {m for m in _imports(path, package) if m in files and m != mod}
    assert graph["bearingsim.dynamics.layout"] == set()
    assert "bearingsim.dynamics.model" not in graph["bearingsim.dynamics.cage"]
    state = {}

    def visit(m, stack):
        state[m] = 1
        for n in graph[m]:
            if state.get(n) == 1:
                pytest.fail(f"import cycle: {' -> '.join(stack + [m, n])}")
            if n not in state:
                visit(n, stack + [m])
        state[m] = 2

    for m in graph:
        if m not in state:
            visit(m, [])


def test_state_offsets_follow_the_layout():
    """Model offsets and sizes are the layout's block sizes; the old names stay importable from model/forces."""
    from bearingsim.io import load_bearing

    m = md.build_model(load_bearing("hub-seed001-row"), cage_modes=4)
    assert m.ball_slice(3) == slice(ly.ball_offset(3), ly.ball_offset(3) + ly.N_BALL)
    assert m.cage_slice(0).start == ly.cage_offset(m.n_balls) == m.cage_offset
    assert m.n_state == ly.cage_offset(m.n_balls, m.n_cages) + 2 * 4
    assert m.mode_slices(0)[0].start == int(m.cp[0, ly.C_MODE0]) == ly.cage_offset(m.n_balls, m.n_cages)
    assert m.rowx.shape[1] == ly.NROWX and m.gp.shape == (ly.NGP,) and m.cp.shape[1] == ly.NCP
    from bearingsim.statics import layout as kn

    np.testing.assert_allclose(m.rowx[:, ly.X_KCI] ** 3, m.rows[:, kn.P_KI], rtol=1e-14)  # K^(1/3) of each row
    np.testing.assert_allclose(m.rowx[:, ly.X_KCO] ** 3, m.rows[:, kn.P_KO], rtol=1e-14)
    assert (md.N_RING, md.C_MASS, md.DOF, fo.D_QC, fo.GD_ECAGE) == (ly.N_RING, ly.C_MASS, ly.DOF, ly.D_QC, ly.GD_ECAGE)
    assert md.describe_component(m, ly.R_QD + 4) == "inner ring gamma_z rate"
    with pytest.raises(AttributeError):
        md.NOT_A_LAYOUT_NAME  # noqa: B018


def test_layout_indices_are_distinct_and_dense():
    """Every index family numbers its columns 0 … size−1 without gaps or repeats."""
    def family(prefix, size, skip=()):
        vals = sorted(getattr(ly, n) for n in dir(ly) if n.startswith(prefix) and n not in skip)
        return vals, list(range(size))

    for prefix, size in (("X_", ly.NROWX), ("C_", ly.NCP), ("D_", ly.NDB), ("GD_", ly.NDG)):
        vals, expected = family(prefix, size)
        assert vals == expected, prefix
    g = sorted(getattr(ly, n) for n in dir(ly) if n.startswith("G_"))
    assert g == [0, 1, 2, 3] + list(range(6, ly.NGP))  # G_GX takes three values
    k = sorted(getattr(ly, n) for n in dir(ly) if n.startswith("K_"))
    assert k == [0, 3] + list(range(6, ly.N_CAGE))
