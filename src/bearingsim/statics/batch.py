"""The batch quasi-static solver, public entry: many operating points of one bearing in one compiled loop.

:func:`run_batch` (warm starts along the grid, every unconverged point re-solved by the single path of
:func:`bearingsim.statics.jones_harris.solve`) and its summary layout (:data:`SUMMARY_FIELDS`,
:data:`NSUMMARY`: the columns of ``summary[n, NSUMMARY]``) are the contract used by design-space maps
(:mod:`bearingsim.sweep`) and by the coefficient export (:mod:`bearingsim.export`).  The compiled loop lives in
the private :mod:`bearingsim.statics._batch`; its returned arrays, units and status codes
(:data:`bearingsim.statics.layout.STATUS`) are described in that module's docstring and in :func:`run_batch`.
For results per point with ball tables use :func:`bearingsim.statics.jones_harris.solve_many`.
"""

from __future__ import annotations

from ._batch import NSUMMARY, SUMMARY_FIELDS, run_batch

__all__ = ["NSUMMARY", "SUMMARY_FIELDS", "run_batch"]
