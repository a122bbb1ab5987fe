"""The shape of the ``bearingsim.cli`` package (mechanism tests; the behaviour is in test_cli*.py).

* every command registered on the app is a module-level function of a ``bearingsim.cli.*`` module (no closure
  built inside a ``register`` function);
* no module of the package imports from the package's ``__init__`` (the app assembly): ``from . import X`` names
  sibling modules only, and nothing imports ``bearingsim.cli`` by its absolute or ``..cli`` name;
* each shared option (loads, speed, control, the bearing argument) is declared in ``cli/options.py`` only.
"""

from __future__ import annotations

import ast
from pathlib import Path

CLI = Path(__file__).resolve().parents[2] / "src" / "bearingsim" / "cli"
SHARED = ("--fa", "--fr", "--fz", "--moment", "--my", "--speed", "--control")


def _commands(group):
    for c in group.registered_commands:
        yield c.callback
    for g in group.registered_groups:
        yield from _commands(g.typer_instance)


def test_commands_are_module_level_functions():
    from bearingsim.cli import app

    callbacks = list(_commands(app))
    # 11 top-level commands (catalog, clearance, static, cage-modes, lubrication, lubricants, traction-curve, map,
    # simulate, report, shaft), export ross, three reproduce commands
    assert len(callbacks) == 15
    for f in callbacks:
        assert f.__module__.startswith("bearingsim.cli."), f
        assert f.__qualname__ == f.__name__, f"{f.__module__}.{f.__qualname__} is not a module-level function"


def test_no_module_imports_back_from_the_package_init():
    siblings = {p.stem for p in CLI.glob("*.py")} - {"__init__"}
    for path in CLI.glob("*.py"):
        if path.name == "__init__.py":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ImportFrom):
                if node.level == 1 and node.module is None:
                    bad = {a.name for a in node.names} - siblings
                    assert not bad, f"{path.name} imports {bad} from cli/__init__"
                assert not (node.level == 0 and node.module == "bearingsim.cli"), path.name
                assert not (node.level == 2 and node.module == "cli"), path.name
            elif isinstance(node, ast.Import):
                assert all(a.name != "bearingsim.cli" for a in node.names), path.name


def test_shared_options_are_declared_once():
    """No ``typer.Option("--fa", ...)`` (or another shared name) outside options.py, which names each of them."""
    elsewhere = set()
    for path in CLI.glob("*.py"):
        if path.name == "options.py":
            continue
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Call) and ast.unparse(node.func).endswith("Option"):
                elsewhere |= {(path.name, a.value) for a in node.args if isinstance(a, ast.Constant)
                              and a.value in SHARED}
    assert elsewhere == set()
    tree = ast.parse((CLI / "options.py").read_text(encoding="utf-8"))
    constants = {n.value for n in ast.walk(tree) if isinstance(n, ast.Constant)}
    assert set(SHARED) <= constants


def test_map_and_static_share_the_load_declarations():
    """static takes one value per load, map a value or a grid: the same option names, help built by one function."""
    import typer.main

    from bearingsim.cli import app

    cmd = typer.main.get_command(app)
    for name, grid in (("static", False), ("lubrication", False), ("map", True)):
        params = {p.name: p for p in cmd.commands[name].params}
        for key in ("fa", "fr", "fz", "moment", "my", "speed"):
            assert ("START:STOP:COUNT" in params[key].help) is grid, (name, key, params[key].help)
