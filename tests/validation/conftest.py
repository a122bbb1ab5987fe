"""Recording of the validation tests' comparisons for the documentation's validation table.

Every ``numpy.testing.assert_allclose`` call of a test in this folder (through ``np.testing`` or an imported
``assert_allclose``) goes through :func:`_recording_assert_allclose`: it records the reference (the call's
``err_msg``, which names the source), the tolerance (``rtol``, ``atol``) and the measured deviation, then asserts
exactly as numpy does (same arguments, same failure). Comparisons written otherwise record themselves with the
``validation`` fixture: ``validation.check(actual, desired, rtol=..., atol=..., source="...")`` asserts with
``numpy.testing.assert_allclose`` and records the same fields.

At the end of the session the records are merged (by test id) into ``docs/_generated/validation.json``
(``BEARINGSIM_VALIDATION_JSON`` overrides the path): a build artefact, not in git. The Sphinx extension
``docs/_ext/validation_table.py`` renders the table of docs/validation.md from it and from an AST parse of this
folder's tests (rows of tests that did not run show "not recorded").
"""

from __future__ import annotations

import json
import math
import os
import time
from pathlib import Path

import numpy as np
import numpy.testing
import pytest

ROOT = Path(__file__).resolve().parents[2]
_ORIGINAL = numpy.testing.assert_allclose
_RECORDS: list[dict] = []
_RAN: set[str] = set()


def _output_path() -> Path:
    return Path(os.environ.get("BEARINGSIM_VALIDATION_JSON", ROOT / "docs" / "_generated" / "validation.json"))


def _deviation(actual, desired, rtol: float, atol: float) -> dict:
    """Largest absolute and relative deviations of ``actual`` from ``desired`` and the largest fraction of the
    tolerance ``atol + rtol |desired|`` used (1 = at the limit); None where they are undefined (non-numeric
    arrays, no finite pair)."""
    try:
        a = np.asarray(actual, dtype=float)
        d = np.asarray(desired, dtype=float)
        a, d = np.broadcast_arrays(a, d)
    except (TypeError, ValueError):
        return {"max_abs_dev": None, "max_rel_dev": None, "tolerance_used": None}
    ok = np.isfinite(a) & np.isfinite(d)
    if not ok.any():
        return {"max_abs_dev": None, "max_rel_dev": None, "tolerance_used": None}
    diff = np.abs(a[ok] - d[ok])
    ref = np.abs(d[ok])
    nz = ref > 0
    rel = float(np.max(diff[nz] / ref[nz])) if nz.any() else None
    limit = atol + rtol * ref
    used = float(np.max(np.where(limit > 0, diff / np.where(limit > 0, limit, 1.0), np.where(diff > 0, math.inf, 0.0))))
    return {"max_abs_dev": float(np.max(diff)), "max_rel_dev": rel, "tolerance_used": used}


class _Recorder:
    """The records of one test (its pytest node id)."""

    def __init__(self, nodeid: str):
        self.nodeid = nodeid

    def record(self, actual, desired, rtol: float, atol: float, source: str) -> None:
        _RECORDS.append({"test": self.nodeid, "source": str(source), "rtol": float(rtol), "atol": float(atol),
                         **_deviation(actual, desired, float(rtol), float(atol))})

    def check(self, actual, desired, *, rtol: float = 1e-7, atol: float = 0.0, source: str) -> None:
        """Assert ``actual`` = ``desired`` within ``atol + rtol |desired|`` (numpy.testing.assert_allclose) and
        record the comparison under ``source`` (the published reference it checks)."""
        if not source:
            raise ValueError("validation.check needs the source of the reference value")
        self.record(actual, desired, rtol, atol, source)
        _ORIGINAL(actual, desired, rtol=rtol, atol=atol, err_msg=source)


def _recording_assert_allclose(recorder: _Recorder):
    def assert_allclose(actual, desired, rtol=1e-7, atol=0, equal_nan=True, err_msg="", verbose=True, **kw):
        recorder.record(actual, desired, rtol, atol, err_msg or "(no err_msg)")
        return _ORIGINAL(actual, desired, rtol=rtol, atol=atol, equal_nan=equal_nan, err_msg=err_msg,
                         verbose=verbose, **kw)

    return assert_allclose


@pytest.fixture(autouse=True)
def _record_comparisons(request, monkeypatch):
    """Route the test's assert_allclose calls through the recorder (restored after the test)."""
    recorder = _Recorder(request.node.nodeid)
    _RAN.add(request.node.nodeid)
    wrapped = _recording_assert_allclose(recorder)
    monkeypatch.setattr(numpy.testing, "assert_allclose", wrapped)
    module = getattr(request, "module", None)
    if module is not None and getattr(module, "assert_allclose", None) is _ORIGINAL:
        monkeypatch.setattr(module, "assert_allclose", wrapped)
    request.node._validation_recorder = recorder


@pytest.fixture
def validation(request):
    """``validation.check(actual, desired, rtol=..., atol=..., source="...")``: assert and record."""
    return request.node._validation_recorder


def pytest_sessionfinish(session, exitstatus):
    """Merge this session's records into the JSON artefact: the tests that ran replace their earlier records."""
    if not _RAN:
        return
    path = _output_path()
    old: list[dict] = []
    if path.exists():
        try:
            old = json.loads(path.read_text(encoding="utf-8")).get("records", [])
        except (OSError, ValueError):
            old = []
    kept = [r for r in old if r.get("test") not in _RAN]
    payload = {"generated": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), "records": kept + _RECORDS}
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".json.part")
    tmp.write_text(json.dumps(payload, indent=1, allow_nan=True), encoding="utf-8")
    tmp.replace(path)
