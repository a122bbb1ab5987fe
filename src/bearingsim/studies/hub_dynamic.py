"""[S1] hub unit in time: hysteresis of the inner-ring tilt against the moment (Figs. 6–9), as a study grid.

[S1] (Sakaguchi & Shibutani, NTN Technical Review 87) runs the hub unit at 10, 50 and 100 km/h
with the moment, the axial and the radial load varying together at 1, 10 and 50 Hz (Table 2), and
measures the hysteresis of the tilt by the fluctuation range W_H: the difference of the tilt where
the moment passes 0.3 kN·m falling and rising (its Fig. 8).  Its Fig. 9 gives W_H for the nine
(speed, frequency) pairs; the extracted text lists the bubble labels 3.0 0.7 0.3 / 4.1 1.3 1.3 /
6.7 4.2 0.9 (·10⁻³ deg) without their positions.  Of the eight ways to lay three groups of three on
the 3 × 3 grid, two break the paper's statement (W_H grows with the load-variation frequency and
falls with the vehicle speed; slide-roll ratio ∝ frequency · load / speed, its eq. 9) only once;
the others break it 5–10 times.  :data:`SEED_FIG9` (groups = frequencies 1, 10, 50 Hz, speeds
10, 50, 100 km/h in order) and :data:`SEED_FIG9_ALT` (groups = speeds 100, 50, 10 km/h, frequencies
50, 10, 1 Hz) are those two readings; both give 6.7 at (10 km/h, 50 Hz); at (100 km/h, 50 Hz) they
give 0.9 and 3.0.

The study takes a case file (e.g. ``examples/hub-moment-50hz.toml``: loads, lubricant, inner-ring
mass and the assumed hub data) and changes only the shaft speed (vehicle speed over the tyre
radius of :mod:`.hub_static`), the frequency of every sine load channel, the duration
(``startup + cycles`` whole load cycles), the traction law if asked, and, if needed, the output
interval (at least 200 samples per cycle).

Grid execution (:func:`run_study`): one task per (speed, frequency) cell, :func:`run_cell`, run by the
task runners of the maps (:func:`bearingsim.sweep.run_tasks_locally` — this process or a pool of
local processes — and :func:`bearingsim.sweep.run_tasks_on_cluster` on a Dask cluster).  A cell
returns its time series (time, moment, axial and radial load, tilt γz); with an output folder the
cell's run streams to ``hub_<v>kmh_<f>Hz.nc`` there (with the dynamic engine's wall-clock checkpoints
``….nc.ckpt.npz``), and this process stores each finished cell as ``….npz`` (series) and ``….json``
(what the cell was: the case fingerprint) — the JSON last, written atomically.  A study run again
with the same folder takes every cell whose JSON matches its case from the folder, resumes a cell
that has a checkpoint of the same case, and runs the others: a killed study continues where it
stopped.

Analysis (:func:`analyse_cell`, in this process, milliseconds): the loop estimator
:func:`bearingsim.dynamics.analysis.hysteresis_estimate` (harmonic fit per load cycle, start-up cycles
discarded by its periodicity criterion, mean and 95 % interval of W_H over the cycles used, loop
area, phase lag and compliance of the fundamental; the two-point reading kept as a diagnostic), the
quasi-static compliance of the same load path (:func:`static_compliance`), the reduced model and the
mechanism's bounds (:func:`bearingsim.studies.hub_reduced.reduced_wh`).  Wherever one of them is not
available, the field is ``None`` and the reason is in the study's ``notes``.
"""

from __future__ import annotations

import copy
import csv
import json
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import InputError
from .hub_static import TYRE_RADIUS, shaft_speed_entry, vehicle_speed_to_shaft  # noqa: F401 (tests, scripts)

#: [S1] Fig. 9, W_H [1e-3 deg] by (vehicle speed [km/h], load frequency [Hz]); our reading (module docstring)
SEED_FIG9 = {(10, 50): 6.7, (50, 50): 4.2, (100, 50): 0.9,
             (10, 10): 4.1, (50, 10): 1.3, (100, 10): 1.3,
             (10, 1): 3.0, (50, 1): 0.7, (100, 1): 0.3}
#: the other reading that breaks the paper's stated trends only once (module docstring)
SEED_FIG9_ALT = {(10, 50): 6.7, (50, 50): 4.1, (100, 50): 3.0,
                 (10, 10): 4.2, (50, 10): 1.3, (100, 10): 0.7,
                 (10, 1): 0.9, (50, 1): 1.3, (100, 1): 0.3}

#: load cycles simulated before the ``cycles`` the estimator is meant to use (the start is not periodic;
#: the estimator's own periodicity criterion decides how many it actually discards)
STARTUP_CYCLES = 2
#: --traction choices → the dynamic case's traction model ("curve": the sliced lubricated kernel with the fluid
#: law replaced by the four-parameter curve :data:`SEED_FIG4_CURVE`)
TRACTIONS = {"physical": "slices", "none": "none", "curve": "slices"}
#: (μ₀, μ_max, s_max, μ_∞) of a four-parameter traction curve (contact/traction.py, fit_four_parameter) of the
#: shape of [S1] Fig. 4: μ = 0 at s = 0, a peak of 0.08 near s = 0.01, a slow fall; our reading of a figure
#: without stated conditions (μ_∞ = 0.07 assumed).  Used as the fluid law of ``--traction curve``
#: (``[lubrication] fluid_model = "curve"``); the boundary law and the mixing in Λ stay the case's.
SEED_FIG4_CURVE = (0.0, 0.08, 0.01, 0.07)
#: [S1] Fig. 8: W_H is read where the moment passes 0.3 kN·m
LEVEL = 300.0


def _mdeg(x) -> float | None:
    """[rad] → [10⁻³ deg] (None stays None)."""
    return None if x is None or not np.isfinite(x) else math.degrees(float(x)) * 1e3


def _deg(x) -> float | None:
    return None if x is None or not np.isfinite(x) else math.degrees(float(x))


def seed_value(speed_kmh: float, frequency_hz: float, table=None) -> float:
    """[S1] Fig. 9 value [rad] (reading :data:`SEED_FIG9` or ``table``), NaN for a pair the paper did not run."""
    v = (SEED_FIG9 if table is None else table).get((round(speed_kmh), round(frequency_hz)))
    if v is None or abs(speed_kmh - round(speed_kmh)) > 1e-9 or abs(frequency_hz - round(frequency_hz)) > 1e-9:
        return math.nan
    return math.radians(v * 1e-3)


# ---- the case of one cell ---------------------------------------------------------------------
def _set_frequency(spec, f_text: str):
    """Copy of a load-channel spec with the frequency of every sine replaced."""
    if isinstance(spec, dict) and "frequency" in spec:
        spec = dict(spec)
        spec["frequency"] = f_text
    elif isinstance(spec, list):
        spec = [_set_frequency(s, f_text) for s in spec]
    return spec


def traction_model(traction: str | None) -> str | None:
    """The dynamic case's traction model for a ``--traction`` choice (None: keep the case file's)."""
    if traction is None:
        return None
    if traction not in TRACTIONS:
        raise InputError("--traction", f"unknown traction {traction!r}", "use physical, curve or none")
    return TRACTIONS[traction]


def cell_case(case_data: dict, base: Path | None, speed_kmh: float, frequency_hz: float, cycles: int,
              traction: str | None = None):
    """The case of one (speed [km/h], frequency [Hz]) run of ``cycles`` whole load cycles (module docstring)."""
    from ..dynamics.case import case_from_dict
    from ..units import file_input, parse_quantity

    d = copy.deepcopy(case_data)
    d["speed"] = shaft_speed_entry(speed_kmh)
    loads = d.get("loads") or {}
    if not any(isinstance(v, (dict, list)) for v in loads.values()):
        raise InputError("loads", "no load channel varies in time", "give the moment as a sine, e.g. mz = "
                         '{ offset = "0 N*m", amplitude = "600 N*m", frequency = "50 Hz" }')
    d["loads"] = {k: _set_frequency(v, f"{frequency_hz!r} Hz") for k, v in loads.items()}
    d["duration"] = f"{cycles / frequency_hz!r} s"
    if "output_interval" not in d:
        raise InputError("output_interval", "missing from the case file", 'add e.g. output_interval = "0.05 ms"')
    with file_input():  # a field of the case file: a bare number needs its unit, as in case_from_dict
        dt = parse_quantity(d["output_interval"], "time", "output_interval")
    # a whole number of samples per cycle (≥ 200), so that cycle boundaries fall on samples
    per_cycle = max(200, math.ceil(1.0 / (frequency_hz * dt) - 1e-9))
    d["output_interval"] = f"{1.0 / (per_cycle * frequency_hz)!r} s"
    model = traction_model(traction)
    if model is not None:
        d["traction"] = model
    if traction in ("physical", "curve"):
        lub = dict(d.get("lubrication") or {})
        if traction == "curve":
            lub["fluid_model"] = "curve"
            lub["fluid_curve"] = list(SEED_FIG4_CURVE)
        else:
            lub.pop("fluid_curve", None)
            lub["fluid_model"] = "physical"
        d["lubrication"] = lub
    return case_from_dict(d, base=base)


def _check_grid(speeds_kmh, frequencies_hz, cycles, startup):
    if isinstance(cycles, bool) or not (isinstance(cycles, int) and cycles >= 2):
        raise InputError("--cycles", f"need at least 2 load cycles after the start-up, got {cycles!r}",
                         "e.g. --cycles 8 (the estimator wants 6 or more)")
    if isinstance(startup, bool) or not (isinstance(startup, int) and startup >= 0):
        raise InputError("startup", f"must be a whole number of cycles ≥ 0, got {startup!r}", "e.g. 2")
    for name, vals in (("--speeds", speeds_kmh), ("--frequencies", frequencies_hz)):
        if not vals or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) and v > 0
                               for v in vals):
            raise InputError(name, f"must be positive numbers, got {vals!r}", "e.g. 10,50,100")
        if len(set(vals)) != len(vals):
            raise InputError(name, f"a value is given twice in {vals!r}", "give each value once")


def cell_name(speed_kmh: float, frequency_hz: float) -> str:
    """File stem of a cell in the study's folder: ``hub_<v>kmh_<f>Hz``."""
    return f"hub_{speed_kmh:g}kmh_{frequency_hz:g}Hz"


def longest_first(cells, total_cycles: int) -> list:
    """The order the cells are handed to the workers: the longest simulated time first ((startup + cycles)/f),
    the higher speed first among equal times (more steps per simulated second).  Workers take tasks in
    submission order, so this is the longest-processing-time-first schedule (Graham 1969): the long 1 Hz cells
    start at once instead of behind the short ones, and the short cells fill the other workers' time.  The
    study's results and files do not depend on it (cells are keyed by speed and frequency)."""
    return sorted(cells, key=lambda vf: (-total_cycles / vf[1], -vf[0]))


# ---- one cell (a task: runs here, in a local process or on a Dask worker) ---------------------
def run_cell(case_data: dict, base, speed_kmh: float, frequency_hz: float, total_cycles: int,
             traction: str | None = None, out_dir=None) -> dict:
    """Run one cell and return its record: the time series (SI) and what the run was.

    ``out_dir``: the run streams to ``out_dir/<cell>.nc`` with wall-clock checkpoints and resumes from a
    checkpoint of the same case left by a killed run (the folder must be visible to the process that
    runs the cell: same machine or a shared file system); None runs in memory.
    Returns {speed_kmh, frequency_hz, fingerprint, time [s], moment [N m], fa [N], fr [N], tilt [rad],
    wall_seconds, simulated_seconds, steps, resumed (bool)}.
    """
    from ..dynamics.run import simulate

    case = cell_case(case_data, None if base is None else Path(base), speed_kmh, frequency_hz, total_cycles,
                     traction)
    fp = case.fingerprint()
    nc = None
    resumed = False
    if out_dir is not None:
        nc = Path(out_dir) / f"{cell_name(speed_kmh, frequency_hz)}.nc"
        resumed = _checkpoint_matches(nc, fp)
    t0 = time.perf_counter()
    res = simulate(case, out=nc, resume=resumed)
    wall = time.perf_counter() - t0
    t, load, disp = res.read("time", "applied_load", "inner_ring_displacement")
    return {"speed_kmh": float(speed_kmh), "frequency_hz": float(frequency_hz), "fingerprint": fp,
            "time": np.asarray(t, dtype=float), "moment": np.asarray(load[:, 4], dtype=float),
            "fa": np.asarray(load[:, 0], dtype=float), "fr": np.asarray(load[:, 1], dtype=float),
            "tilt": np.asarray(disp[:, 4], dtype=float), "wall_seconds": wall,
            "simulated_seconds": float(res.summary.get("simulated_seconds", math.nan)),
            "steps": int(res.summary.get("steps", 0)), "resumed": resumed}


def _checkpoint_matches(nc: Path, fingerprint: str) -> bool:
    """True when ``nc`` has a readable checkpoint of the case with this fingerprint (a foreign or damaged
    checkpoint is not resumed: the run starts again and replaces it)."""
    ckpt = nc.with_name(nc.name + ".ckpt.npz")
    if not (ckpt.exists() and nc.exists()):
        return False
    try:
        with np.load(ckpt) as c:
            return str(c["fingerprint"]) == fingerprint
    except (OSError, ValueError, EOFError, KeyError):
        return False


_SERIES = ("time", "moment", "fa", "fr", "tilt")
_META = ("speed_kmh", "frequency_hz", "fingerprint", "wall_seconds", "simulated_seconds", "steps", "resumed")


def save_cell(folder: Path, record: dict) -> Path:
    """Store a finished cell in ``folder``: ``<cell>.npz`` (series) then ``<cell>.json`` (what it was), each
    written under a temporary name and renamed, the JSON last: a cell is finished when its JSON exists."""
    folder = Path(folder)
    stem = cell_name(record["speed_kmh"], record["frequency_hz"])
    npz, js = folder / f"{stem}.npz", folder / f"{stem}.json"
    tmp = folder / f".{stem}.npz.part.npz"
    np.savez(tmp, **{k: record[k] for k in _SERIES})
    os.replace(tmp, npz)
    tmpj = folder / f".{stem}.json.part"
    tmpj.write_text(json.dumps({k: record[k] for k in _META} | {"series": npz.name}))
    os.replace(tmpj, js)
    return js


def load_cell(folder: Path, speed_kmh: float, frequency_hz: float, fingerprint: str) -> dict | None:
    """The finished cell stored in ``folder`` for this case fingerprint, or None."""
    stem = cell_name(speed_kmh, frequency_hz)
    js = Path(folder) / f"{stem}.json"
    try:
        meta = json.loads(js.read_text())
        if meta.get("fingerprint") != fingerprint:
            return None
        with np.load(Path(folder) / meta["series"]) as z:
            series = {k: np.array(z[k]) for k in _SERIES}
    except (OSError, ValueError, KeyError, EOFError):
        return None
    return {k: meta[k] for k in _META} | series | {"from_folder": True}


# ---- analysis of a cell -------------------------------------------------------------------------
def static_compliance(case, frequency_hz: float, points: int = 64) -> float:
    """Quasi-static compliance of the cell's load path [rad/(N·m)]: the fundamental of the quasi-static tilt
    over one load cycle divided by the fundamental of the moment, |Γ₁|/|M₁| — the same definition as the
    dynamic estimate's ``compliance`` (amplitude ratio of the fundamentals), so that the two compare
    directly.  The loads of ``points`` equally spaced instants of one period are solved (Jones–Harris,
    :func:`bearingsim.statics.jones_harris.solve`, at the case's shaft speed, with the loads moved to the
    bearing's rows as the dynamic start does, :func:`bearingsim.dynamics.run.build`); the fundamentals are
    the discrete Fourier coefficients X₁ = (2/N) Σ x_k e^(−2πik/N) (exact for a band-limited periodic curve
    sampled N times per period, the aliasing of harmonic N−1 and above aside).
    """
    from ..statics import jones_harris as jh

    freq = float(frequency_hz)
    xl = case.load_point
    w = abs(case.speed.at(0.0))
    tilt = np.empty(points)
    moment = np.empty(points)
    start = None
    for k in range(points):
        tk = k / (points * freq)
        lk = case.loads.at(tk)
        loads = jh.Loads(fa=lk[0], fr_y=lk[1], fr_z=lk[2], m_y=lk[3] - xl * lk[2], m_z=lk[4] + xl * lk[1])
        res = jh.solve(case.bearing, loads, w, control=case.control, initial=start)
        if not res.converged:
            res = jh.solve(case.bearing, loads, w, control=case.control)
        if not res.converged:
            return math.nan
        start = res.displacement
        tilt[k] = res.displacement[4]
        moment[k] = lk[4]
    ph = np.exp(-2j * np.pi * np.arange(points) / points)
    m1 = abs(2.0 / points * np.sum(moment * ph))
    g1 = abs(2.0 / points * np.sum(tilt * ph))
    return g1 / m1 if m1 > 0 else math.nan


def curve_creep_slope(case) -> float | None:
    """dμ/ds at s = 0 [-] of the case's four-parameter fluid curve (``[lubrication] fluid_model = "curve"``):
    μ = (A + B s) e^(−C s) + D gives B − A C (contact/traction.py); None for the physical film law (the reduced
    model then takes the film-elastic slope per ball)."""
    lub = getattr(case, "lubrication", None) or {}
    if lub.get("fluid_model") != "curve" or lub.get("fluid_curve") is None:
        return None
    from ..contact.traction import fit_four_parameter

    a, b, c, _ = fit_four_parameter(*lub["fluid_curve"])
    return float(b - a * c)


@dataclass
class CellResult:
    """One analysed cell (SI; rad, J, N·m)."""

    speed_kmh: float
    frequency_hz: float
    record: dict = field(repr=False)  #: the cell's record (:func:`run_cell`)
    estimate: object = None  #: :class:`bearingsim.dynamics.analysis.LoopEstimate` or None
    static_compliance: float = math.nan  #: [rad/(N m)]
    reduced: dict | None = None  #: :func:`bearingsim.studies.hub_reduced.reduced_wh` result or None
    #: the same with the spin-softened creep slope of the case's own traction kernel (``creep_slope="kernel"``)
    reduced_kernel: dict | None = None
    notes: list = field(default_factory=list)
    case: object = field(default=None, repr=False)  #: the cell's :class:`~bearingsim.dynamics.case.Case`

    def seed(self, table=None) -> float:
        """[S1] Fig. 9 value [rad] (:data:`SEED_FIG9` or ``table``), NaN for a pair the paper did not run."""
        return seed_value(self.speed_kmh, self.frequency_hz, table)

    @property
    def wh(self) -> float:
        return float(self.estimate.mean) if self.estimate is not None else math.nan

    def bound(self) -> float:
        """The smaller of the mechanism's force and energy bounds on W_H [rad] (NaN without a reduced model)."""
        if not self.reduced:
            return math.nan
        vals = [self.reduced.get(k) for k in ("bound_force", "bound_energy")]
        vals = [float(v) for v in vals if v is not None and np.isfinite(v)]
        return min(vals) if vals else math.nan

    def to_dict(self) -> dict:
        """The cell's JSON row (``--json``): SI except the fields named ``_deg``."""
        e = self.estimate
        red = self.reduced or {}
        comp = None if e is None else float(e.compliance)
        return {
            "vehicle_speed_kmh": self.speed_kmh, "frequency_hz": self.frequency_hz,
            "wh_deg": None if e is None else _deg(e.mean),
            "wh_ci95_deg": None if e is None else [_deg(e.ci95[0]), _deg(e.ci95[1])],
            "cycles_used": None if e is None else int(e.cycles_used),
            "first_cycle": None if e is None else int(e.first_cycle),
            "wh_cycles_deg": None if e is None else [_deg(w) for w in e.widths],
            "two_point_deg": None if e is None else [_deg(w) for w in e.two_point],
            "loop_area_J": None if e is None else float(e.loop_area),
            "loop_area_ci95_J": None if e is None else [float(e.loop_area_ci95[0]), float(e.loop_area_ci95[1])],
            "phase_lag_deg": None if e is None else _deg(e.phase_lag),
            "compliance_deg_per_kNm": None if comp is None else math.degrees(comp) * 1e3,
            "static_compliance_deg_per_kNm": (math.degrees(self.static_compliance) * 1e3
                                              if np.isfinite(self.static_compliance) else None),
            "reduced_model_wh_deg": _deg(red.get("wh")) if red else None,
            "reduced_model_kernel_wh_deg": _deg(self.reduced_kernel.get("wh")) if self.reduced_kernel else None,
            "reduced_model_kernel_creep_slope": (float(self.reduced_kernel["creep_slope"]) if self.reduced_kernel
                                                 else None),
            "reduced_model_phase_lag_deg": _deg(red.get("phase_lag")) if red else None,
            "bound_wh_deg": _deg(self.bound()),
            "bound_force_wh_deg": _deg(red.get("bound_force")) if red else None,
            "bound_energy_wh_deg": _deg(red.get("bound_energy")) if red else None,
            "seed_wh_deg": _deg(self.seed()), "seed_wh_alt_deg": _deg(self.seed(SEED_FIG9_ALT)),
            "wall_seconds": float(self.record.get("wall_seconds", math.nan)),
            "simulated_seconds": float(self.record.get("simulated_seconds", math.nan)),
            "steps": int(self.record.get("steps", 0)),
            "from_earlier_run": bool(self.record.get("from_folder", False)),
            "resumed_from_checkpoint": bool(self.record.get("resumed", False)),
            "notes": list(self.notes),
        }


def analyse_cell(record: dict, case, level: float = LEVEL, reduced: bool = True) -> CellResult:
    """Estimate W_H of a cell's record (:func:`run_cell`) and add the quasi-static compliance, the reduced
    model and the bounds (module docstring)."""
    out = CellResult(record["speed_kmh"], record["frequency_hz"], record, case=case)
    try:
        from ..dynamics.analysis import hysteresis_estimate
    except ImportError:
        out.notes.append("loop estimator (dynamics.analysis.hysteresis_estimate) not available")
    else:
        try:
            out.estimate = hysteresis_estimate(record["time"], record["moment"], record["tilt"],
                                               record["frequency_hz"], level)
        except InputError as exc:
            out.notes.append(f"loop estimator: {exc}")
        else:
            status = getattr(out.estimate, "status", "ok")
            if status != "ok":  # too few periodic cycles, no crossing ...: the numbers as far as they exist
                out.notes.append(f"loop estimator: {status}")
    out.static_compliance = static_compliance(case, record["frequency_hz"])
    if reduced:
        try:
            from .hub_reduced import reduced_wh
        except ImportError:
            out.notes.append("reduced model (studies.hub_reduced.reduced_wh) not available")
        else:
            try:
                out.reduced = reduced_wh(case, record["speed_kmh"], record["frequency_hz"], level=level,
                                         creep_slope=curve_creep_slope(case))
            except Exception as exc:  # noqa: BLE001 - a failing side model must not lose hours of runs
                out.notes.append(f"reduced model failed: {type(exc).__name__}: {exc}")
            if getattr(case, "traction", None) == "slices":  # the kernel's slope needs the sliced traction
                try:
                    out.reduced_kernel = reduced_wh(case, record["speed_kmh"], record["frequency_hz"], level=level,
                                                    creep_slope="kernel")
                except Exception as exc:  # noqa: BLE001 - as above
                    out.notes.append(f"reduced model (kernel slope) failed: {type(exc).__name__}: {exc}")
    return out


# ---- the study ----------------------------------------------------------------------------------
@dataclass
class HysteresisStudy:
    """The analysed grid: cells in (speed, frequency) order and what was run."""

    cells: list
    level: float = LEVEL
    cycles: int = 8
    startup: int = STARTUP_CYCLES
    traction: str | None = None
    case: str = ""
    wall_seconds: float = math.nan
    notes: list = field(default_factory=list)

    def to_dict(self) -> dict:
        """The study's JSON (``--json``); a number that does not exist (NaN) is null."""
        return _finite({
                "case": self.case, "level_N_m": self.level, "cycles": self.cycles, "startup_cycles": self.startup,
                "traction": self.traction or "case file", "wall_seconds": self.wall_seconds,
                "estimator": self._criterion(), "cells": [c.to_dict() for c in self.cells], "notes": self.notes,
                "seed_readings": "seed_wh_deg: SEED_FIG9, seed_wh_alt_deg: SEED_FIG9_ALT "
                                 "(bearingsim/studies/hub_dynamic.py)"})

    def _criterion(self) -> str | None:
        for c in self.cells:
            if c.estimate is not None:
                return str(c.estimate.criterion)
        return None

    def rows(self) -> list[dict]:
        """Table rows in trade units ([10⁻³ deg], [mJ], [deg/(kN·m)])."""
        out = []
        for c in self.cells:
            d = c.to_dict()
            ci = d["wh_ci95_deg"] or [None, None]
            out.append({"speed_kmh": c.speed_kmh, "frequency_hz": c.frequency_hz, "cycles_used": d["cycles_used"],
                        "W_H_mdeg": _mdeg(c.wh), "W_H_ci95_lo_mdeg": _x1e3(ci[0]), "W_H_ci95_hi_mdeg": _x1e3(ci[1]),
                        "two_point_mean_mdeg": _x1e3(np.mean(d["two_point_deg"])) if d["two_point_deg"] else None,
                        "loop_area_mJ": None if d["loop_area_J"] is None else d["loop_area_J"] * 1e3,
                        "phase_lag_deg": d["phase_lag_deg"], "compliance_deg_per_kNm": d["compliance_deg_per_kNm"],
                        "static_compliance_deg_per_kNm": d["static_compliance_deg_per_kNm"],
                        "reduced_W_H_mdeg": _x1e3(d["reduced_model_wh_deg"]),
                        "reduced_kernel_W_H_mdeg": _x1e3(d["reduced_model_kernel_wh_deg"]),
                        "bound_W_H_mdeg": _x1e3(d["bound_wh_deg"]),
                        "seed_fig9_mdeg": _x1e3(d["seed_wh_deg"]), "seed_fig9_alt_mdeg": _x1e3(d["seed_wh_alt_deg"]),
                        "wall_s": d["wall_seconds"], "steps": d["steps"]})
        return out

    def print_table(self, console) -> None:
        from rich.table import Table

        t = Table(title=f"[S1] hub unit: loop width W_H at {self.level / 1e3:g} kN·m (harmonic fit per cycle, "
                        "falling − rising; 10⁻³ deg; > 0 = lag)")
        cols = ("km/h", "Hz", "cycles", "W_H", "95 % interval", "two-point", "loop mJ", "lag °",
                "compl. °/kN·m", "static", "reduced", "red. spin", "bound", "seed*", "or*", "wall s")
        for c in cols:
            t.add_column(c, justify="right")

        def f(x, spec=".3f"):
            return "—" if x is None or not np.isfinite(x) else format(x, spec)

        for r in self.rows():
            t.add_row(f"{r['speed_kmh']:g}", f"{r['frequency_hz']:g}", str(r["cycles_used"] or "—"),
                      f(r["W_H_mdeg"]), f"{f(r['W_H_ci95_lo_mdeg'])} … {f(r['W_H_ci95_hi_mdeg'])}",
                      f(r["two_point_mean_mdeg"]), f(r["loop_area_mJ"], ".4f"), f(r["phase_lag_deg"], ".4f"),
                      f(r["compliance_deg_per_kNm"], ".4f"), f(r["static_compliance_deg_per_kNm"], ".4f"),
                      f(r["reduced_W_H_mdeg"]), f(r["reduced_kernel_W_H_mdeg"]), f(r["bound_W_H_mdeg"]),
                      f(r["seed_fig9_mdeg"], ".1f"),
                      f(r["seed_fig9_alt_mdeg"], ".1f"), f(r["wall_s"], ".0f"))
        console.print(t)
        console.print("* the two readings of the paper's Fig. 9 consistent with its stated trends "
                      "(bearingsim/studies/hub_dynamic.py); the paper's loop lags the moment (W_H > 0)")
        for n in self.notes:
            console.print(f"note: {n}", markup=False, highlight=False)

    def to_csv(self, path) -> Path:
        path = Path(path)
        rows = self.rows()
        with open(path, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
        return path

    def plot(self, path) -> Path:
        """Tilt against moment of the last cycle of every cell ([S1] Fig. 6/7 style)."""
        import matplotlib

        matplotlib.use("Agg", force=False)
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4))
        for c in self.cells:
            m, g = last_cycle(c.record)
            ax.plot(m / 1e3, np.degrees(g), label=f"{c.speed_kmh:g} km/h, {c.frequency_hz:g} Hz")
        ax.set_xlabel("moment [kN·m]")
        ax.set_ylabel("inclining angle γz [deg]")
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(path, dpi=120)
        plt.close(fig)
        return Path(path)


def _finite(x):
    """``x`` with every non-finite float (NaN, ±inf) replaced by None, through dicts and lists (valid JSON)."""
    if isinstance(x, dict):
        return {k: _finite(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_finite(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def _x1e3(x):
    return None if x is None or not np.isfinite(x) else float(x) * 1e3


def last_cycle(record: dict) -> tuple[np.ndarray, np.ndarray]:
    """(moment [N m], tilt [rad]) of the last whole load cycle of a cell's record."""
    t = np.asarray(record["time"])
    sel = t >= t[-1] - 1.0 / record["frequency_hz"] - 1e-12
    return np.asarray(record["moment"])[sel], np.asarray(record["tilt"])[sel]


def _warm_up(case) -> None:
    """Compile (first run) or load the dynamic kernels in this process before local worker processes start, so
    that they load them from the disk cache instead of each compiling them (two output samples of ``case``)."""
    import dataclasses

    from ..dynamics.run import simulate

    simulate(dataclasses.replace(case, duration=2 * case.output_interval))


def run_study(case_path, speeds_kmh=(100.0,), frequencies_hz=(50.0,), cycles: int = 8,
              startup: int = STARTUP_CYCLES, traction: str | None = None, level: float = LEVEL, out_dir=None,
              workers: int | None = None, scheduler=None, worker_timeout: float = 600.0, progress: bool = False,
              console=None, reduced: bool = True, on_cell=None, finished_only: bool = False) -> HysteresisStudy:
    """Run the hub case on the grid speeds [km/h] × frequencies [Hz] for ``startup + cycles`` load cycles each
    and analyse every cell (module docstring).

    ``out_dir``: the folder of the cells' runs and finished cells (resume: module docstring); None keeps
    everything in memory.  ``workers``: local processes (default: one per cell up to the cores; 1 = this
    process); ``scheduler``: a Dask scheduler address or ``distributed.Client`` (one task per cell; overrides
    ``workers``).  ``progress``: a cell progress bar on ``console``.  ``on_cell(record)`` is called in this
    process as each cell finishes (after it is stored).  ``finished_only``: run nothing; analyse the cells of
    the grid already finished in ``out_dir`` (the others are named in the notes) — a report of a long grid so far.
    """
    from ..io import read_toml
    from ..sweep import _close, _connect, _QuietDistributed, run_tasks_locally, run_tasks_on_cluster

    _check_grid(speeds_kmh, frequencies_hz, cycles, startup)
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int) or workers < 1):
        raise InputError("--workers", f"must be a positive integer, got {workers!r}", "e.g. --workers 2")
    traction_model(traction)  # refuse an unknown or missing law before anything runs
    p = Path(case_path)
    data = read_toml(p, "case")
    total = startup + cycles
    grid = [(float(v), float(f)) for v in speeds_kmh for f in frequencies_hz]
    cases = {vf: cell_case(data, p.parent, vf[0], vf[1], total, traction) for vf in grid}  # bad input: now
    folder = None if out_dir is None else Path(out_dir)
    records = {}
    if folder is not None:
        for vf in grid:
            rec = load_cell(folder, vf[0], vf[1], cases[vf].fingerprint())
            if rec is not None:
                records[vf] = rec
    todo = longest_first([vf for vf in grid if vf not in records], total)
    notes = []
    if finished_only:
        if folder is None:
            raise InputError("--finished-only", "needs the folder of an earlier run", "give --out FOLDER")
        if not records:
            raise InputError("--finished-only", f"no finished cell of this grid in {folder}",
                             "run the study first (same case, --cycles, --startup-cycles, --traction)")
        if todo:
            notes.append("not run yet: " + ", ".join(f"{v:g} km/h {f:g} Hz" for v, f in todo))
        grid = [vf for vf in grid if vf in records]
        todo = []
    if records:
        notes.append(f"{len(records)} of {len(grid)} cells taken from the earlier run in {folder}")
    t0 = time.perf_counter()
    bar = task = None
    if progress and todo:
        from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

        bar = Progress(TextColumn("hub study"), BarColumn(), TextColumn("{task.completed}/{task.total} cells"),
                       TimeElapsedColumn(), console=console)
        bar.start()
        task = bar.add_task("cells", total=len(todo))

    def done(vf, rec):
        if folder is not None:
            save_cell(folder, rec)
        records[vf] = rec
        if on_cell is not None:
            on_cell(rec)
        if bar is not None:
            bar.advance(task)

    args = [(data, str(p.parent.resolve()), vf[0], vf[1], total, traction,
             None if folder is None else str(folder.resolve())) for vf in todo]
    try:
        if not todo:
            pass
        elif scheduler is not None:
            client, own = _connect(scheduler, 3.0)
            quiet = _QuietDistributed().__enter__() if own else None
            try:
                run_tasks_on_cluster(client, run_cell, args, todo, done, worker_timeout, what="cells")
            finally:
                if own:
                    _close(client, quiet)
        else:
            n = workers if workers is not None else min(len(todo), os.cpu_count() or 1)
            if n > 1 and len(todo) > 1:
                _warm_up(cases[todo[0]])
            run_tasks_locally(run_cell, args, todo, done, n, what="cells", job="the hub study")
    finally:
        if bar is not None:
            bar.stop()
    wall = time.perf_counter() - t0
    cells = [analyse_cell(records[vf], cases[vf], level, reduced) for vf in grid]
    for c in cells:
        notes.extend(f"{c.speed_kmh:g} km/h, {c.frequency_hz:g} Hz: {n}" for n in c.notes)
    return HysteresisStudy(cells, level, cycles, startup, traction, str(case_path), wall, notes)


__all__ = ["LEVEL", "SEED_FIG4_CURVE", "SEED_FIG9", "SEED_FIG9_ALT", "STARTUP_CYCLES", "TRACTIONS", "TYRE_RADIUS",
           "CellResult", "HysteresisStudy", "analyse_cell", "cell_case", "cell_name", "curve_creep_slope", "last_cycle",
           "load_cell", "run_cell", "run_study", "save_cell", "seed_value", "static_compliance", "traction_model"]
