"""Sphinx directive ``validation-table``: the validation table, generated from the validation tests themselves.

Rows come from two places, so that the table cannot drift from the tests:

* the records that tests/validation/conftest.py writes when the tests run (``docs/_generated/validation.json``):
  for every comparison the reference (``err_msg``), the tolerance (``rtol``, ``atol``) and the measured deviation;
* an AST parse of ``tests/validation/test_*.py`` for the tests without records (not run before this build, or
  asserting otherwise than with ``assert_allclose``): the ``err_msg`` strings and ``rtol``/``atol`` of their
  calls, or the test's docstring, with the deviation "not recorded".

One row per test function and reference: parametrised cases and repeated calls are folded into the row (the
largest deviation, the number of comparisons).
"""

from __future__ import annotations

import ast
import json
import os
from collections import OrderedDict
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import Directive

ROOT = Path(__file__).resolve().parents[2]
TESTS = ROOT / "tests" / "validation"
JSON = Path(os.environ.get("BEARINGSIM_VALIDATION_JSON", ROOT / "docs" / "_generated" / "validation.json"))


def _fmt(x: float | None) -> str:
    if x is None:
        return "–"
    if x == 0:
        return "0"
    return f"{x:.2g}"


def _tolerance(rtol: float, atol: float) -> str:
    parts = []
    if rtol:
        parts.append(f"rtol {_fmt(rtol)}")
    if atol:
        parts.append(f"atol {_fmt(atol)}")
    return ", ".join(parts) or "exact"


def _constants(tree: ast.Module) -> dict[str, str]:
    """Module-level string constants (err_msg is often a named source)."""
    out = {}
    for node in tree.body:
        if isinstance(node, ast.Assign) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
            for t in node.targets:
                if isinstance(t, ast.Name):
                    out[t.id] = node.value.value
    return out


def _text(node: ast.AST | None, consts: dict[str, str]) -> str | None:
    if node is None:
        return None
    if isinstance(node, ast.Constant):
        return str(node.value)
    if isinstance(node, ast.Name) and node.id in consts:
        return consts[node.id]
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        left, right = _text(node.left, consts), _text(node.right, consts)
        if left is not None and right is not None:
            return left + right
    return ast.unparse(node)


def _first_sentence(doc: str, limit: int = 200) -> str:
    text = " ".join(doc.split())
    cut = text.find(". ")
    text = text if cut < 0 else text[: cut + 1]
    return text if len(text) <= limit else text[: limit - 1].rstrip() + "…"


def _calls(func: ast.AST, consts: dict[str, str]) -> list[dict]:
    """The comparisons of one test function: (source, rtol, atol) of every call with an err_msg or source."""
    found = []
    for node in ast.walk(func):
        if not isinstance(node, ast.Call):
            continue
        kw = {k.arg: k.value for k in node.keywords if k.arg}
        src = kw.get("err_msg", kw.get("source"))
        if src is None:
            continue
        name = ast.unparse(node.func)
        rtol = kw.get("rtol")
        if rtol is None and name.endswith("assert_allclose") and len(node.args) > 2:
            rtol = node.args[2]
        atol = kw.get("atol")
        if rtol is not None:
            rtol_t = _text(rtol, consts)
        else:  # numpy's and the fixture's default
            rtol_t = "1e-7" if name.endswith(("assert_allclose", "check")) else None
        atol_t = _text(atol, consts) if atol is not None else None
        found.append({"source": _text(src, consts), "rtol": rtol_t, "atol": atol_t})
    return found


def parse_tests() -> OrderedDict:
    """test id (file::function) -> {"doc": first docstring line, "calls": [...]} in source order."""
    out: OrderedDict = OrderedDict()
    for path in sorted(TESTS.glob("test_*.py")):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        consts = _constants(tree)
        rel = path.relative_to(ROOT).as_posix()

        def visit(body, prefix):
            for node in body:
                if isinstance(node, ast.ClassDef) and node.name.startswith("Test"):
                    visit(node.body, f"{prefix}{node.name}::")
                elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and node.name.startswith("test"):
                    doc = _first_sentence(ast.get_docstring(node) or "")
                    out[f"{rel}::{prefix}{node.name}"] = {"doc": doc, "calls": _calls(node, consts)}

        visit(tree.body, "")
    return out


def load_records() -> tuple[dict, str | None]:
    """Recorded comparisons grouped by test function (parameters stripped), and the run's time stamp."""
    if not JSON.exists():
        return {}, None
    data = json.loads(JSON.read_text(encoding="utf-8"))
    grouped: dict = {}
    for r in data.get("records", []):
        base = r["test"].split("[", 1)[0]
        grouped.setdefault(base, []).append(r)
    return grouped, data.get("generated")


def table_rows() -> list[dict]:
    """The rows of the table: test, reference, tolerance, deviation, recorded (bool)."""
    tests = parse_tests()
    records, _ = load_records()
    rows = []
    for test_id, info in tests.items():
        recs = records.get(test_id)
        if recs:
            groups: OrderedDict = OrderedDict()
            for r in recs:
                groups.setdefault((r["source"], r["rtol"], r["atol"]), []).append(r)
            for (source, rtol, atol), rs in groups.items():
                rel = [r["max_rel_dev"] for r in rs if r["max_rel_dev"] is not None]
                ab = [r["max_abs_dev"] for r in rs if r["max_abs_dev"] is not None]
                used = [r["tolerance_used"] for r in rs if r["tolerance_used"] is not None]
                if rtol and rel:
                    dev = f"{_fmt(max(rel))} relative"
                elif ab:
                    dev = f"{_fmt(max(ab))} absolute"
                else:
                    dev = "–"
                if used:
                    dev += f" ({_fmt(max(used))} of the tolerance)"
                n = len(rs)
                rows.append({"test": test_id, "reference": source, "tolerance": _tolerance(rtol, atol),
                             "deviation": dev + (f", {n} comparisons" if n > 1 else ""), "recorded": True})
            continue
        calls = info["calls"]
        if calls:
            seen = set()
            for c in calls:
                key = (c["source"], c["rtol"], c["atol"])
                if key in seen:
                    continue
                seen.add(key)
                tol = ", ".join(p for p in (f"rtol {c['rtol']}" if c["rtol"] else "",
                                            f"atol {c['atol']}" if c["atol"] else "") if p) or "in the test"
                rows.append({"test": test_id, "reference": c["source"], "tolerance": tol,
                             "deviation": "not recorded", "recorded": False})
        else:
            rows.append({"test": test_id, "reference": info["doc"] or "(see the test)", "tolerance": "in the test",
                         "deviation": "not recorded", "recorded": False})
    return rows


def _cell(text: str, literal: bool = False) -> nodes.entry:
    entry = nodes.entry()
    para = nodes.paragraph()
    para += nodes.literal(text=text) if literal else nodes.Text(text)
    entry += para
    return entry


class ValidationTable(Directive):
    """``.. validation-table::`` (MyST: a ``{validation-table}`` fence)."""

    has_content = False

    def run(self):
        env = self.state.document.settings.env
        for path in sorted(TESTS.glob("test_*.py")):
            env.note_dependency(str(path))
        if JSON.exists():
            env.note_dependency(str(JSON))
        rows = table_rows()
        _, stamp = load_records()
        n_rec = sum(r["recorded"] for r in rows)
        summary = nodes.paragraph(text=(
            f"{len(rows)} rows from {len({r['test'].split('::')[0] for r in rows})} test files; "
            f"{n_rec} carry the deviation measured "
            + (f"by the test run of {stamp} (UTC)." if stamp else "(no test run recorded before this build).")))
        headers = ["test", "reference (the test's err_msg)", "tolerance", "measured deviation"]
        widths = [22, 40, 12, 26]
        table = nodes.table(classes=["validation-table"])
        group = nodes.tgroup(cols=len(headers))
        table += group
        for w in widths:
            group += nodes.colspec(colwidth=w)
        head = nodes.thead()
        row = nodes.row()
        for h in headers:
            row += _cell(h)
        head += row
        group += head
        body = nodes.tbody()
        for r in rows:
            tr = nodes.row()
            tr += _cell(r["test"].replace("tests/validation/", ""), literal=True)
            tr += _cell(r["reference"])
            tr += _cell(r["tolerance"])
            tr += _cell(r["deviation"])
            body += tr
        group += body
        return [summary, table]


def setup(app):
    app.add_directive("validation-table", ValidationTable)
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True}
