"""Export of speed-dependent bearing stiffness to rotordynamics codes (ROSS).

ROSS (ross-rotordynamics, ``ross.BearingElement``) models a bearing as lateral springs and dampers
between a shaft node and ground: direct and cross-coupled lateral terms kxx, kyy, kxy, kyx and an
axial term kzz, each a function of the rotor speed (``frequency`` [rad/s], interpolated).  ROSS's
rotor axis is z; ours is x.  The right-handed map (our y, z, x) → (ROSS x, y, z) gives

    kxx = K_yy,  kxy = K_yz,  kyx = K_zy,  kyy = K_zz,  kzz = K_xx       (our 5×5 K at each speed)

ROSS cannot take (and this export drops, reporting their size): the tilt stiffnesses
K_γyγy, K_γyγz, K_γzγy, K_γzγz, the translation–tilt couplings (K_yγz, K_zγy, … — large for angular
contact bearings and for the pair's load centre away from the node), and the axial–lateral and
axial–tilt couplings (K_xy, K_xz, K_xγ…).  The damping of rolling bearings is not modelled here
(cxx = cyy = 0 unless given).

The stiffness is the tangent stiffness of the quasi-static Jones–Harris solution at each speed
under the given constant loads (:mod:`bearingsim.statics._batch`, warm-started along the speeds).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from .errors import ConvergenceError, InputError

#: (ROSS name, our row, our column) — our order is (x, y, z, γy, γz)
ROSS_MAP = (("kxx", 1, 1), ("kxy", 1, 2), ("kyx", 2, 1), ("kyy", 2, 2), ("kzz", 0, 0))
DROPPED = ("K[x,y]", "K[x,z]", "K[x,gamma_y]", "K[x,gamma_z]", "K[y,gamma_y]", "K[y,gamma_z]", "K[z,gamma_y]",
           "K[z,gamma_z]", "K[gamma_y,gamma_y]", "K[gamma_y,gamma_z]", "K[gamma_z,gamma_y]", "K[gamma_z,gamma_z]")


def _preloaded(bearing) -> bool:
    """True when the bearing carries load without external load: a radial interference
    (diametral_clearance < 0) of a row, or a set's preload (positive axial offsets)."""
    return (getattr(bearing, "preload", 0.0) > 0.0
            or any(r.axial_offset > 0.0 or r.bearing.diametral_clearance < 0.0 for r in bearing.rows))


def _check_arguments(bearing, speeds, loads, control):
    """The API boundary of the export functions: wrong types and an unloaded bearing raise InputError."""
    from .io import load_bearing
    from .statics.jones_harris import Loads

    if isinstance(bearing, str | Path):
        bearing = load_bearing(bearing)
    if not hasattr(bearing, "row_vectors"):  # the rows protocol (bearingsim.geometry)
        raise InputError("bearing", f"expected a BallBearing, a BearingSystem, a catalogue name or a TOML path, "
                         f"got {type(bearing).__name__}", "e.g. bearingsim.io.load_bearing('skf-7011-cdga-hc')")
    if isinstance(speeds, str | bytes) or speeds is None:
        raise InputError("speeds", f"expected inner-ring speeds in rad/s (numbers), got {speeds!r}"[:160],
                         'give numbers in rad/s, or parse text with bearingsim.sweep.parse_grid("0:10000:11", '
                         '"speed", "speed")')
    try:
        speeds = np.atleast_1d(np.asarray(speeds, dtype=float))
    except (TypeError, ValueError):
        raise InputError("speeds", f"expected numbers in rad/s, got {speeds!r}"[:160], "give a list of floats") \
            from None
    if speeds.ndim != 1 or speeds.size == 0 or not np.all(np.isfinite(speeds)) or np.any(speeds < 0):
        raise InputError("speed", "give one or more finite speeds ≥ 0", 'e.g. --speed "0:12000:13"')
    if loads is None:
        loads = Loads()
    if not isinstance(loads, Loads):
        raise InputError("loads", f"expected a Loads object, got {type(loads).__name__}",
                         "e.g. Loads(fa=1000.0, fr_y=500.0) [N, N·m]")
    if not isinstance(control, str) or control not in ("outer", "inner", "auto"):
        raise InputError("control", f"unknown raceway control {control!r}", "use outer, inner or auto")
    if not np.any(np.asarray(loads.as_array(), dtype=float) != 0.0) and not _preloaded(bearing):
        raise InputError("loads (--fa/--fr)", "an unloaded bearing has no stiffness to export (its balls carry "
                         "no load, so every coefficient is zero up to round-off)",
                         "give a load (--fa, --fr) or a preloaded bearing (a set with preload)")
    return bearing, speeds, loads


def ross_coefficients(bearing, speeds, loads=None, control: str = "outer") -> dict:
    """Stiffness coefficients over ``speeds`` [rad/s] in ROSS's names [N/m], plus the full 5×5 matrices.

    Parameters
    ----------
    bearing : BallBearing or BearingSystem (or a catalogue name / TOML path)
    speeds : array of inner-ring speeds [rad/s] (ROSS ``frequency``)
    loads : :class:`~bearingsim.statics.jones_harris.Loads` (constant over the speeds)
    control : raceway control

    Raises :class:`InputError` for arguments of the wrong type and for a bearing with neither
    load nor preload (its stiffness is zero: nothing to export), :class:`ConvergenceError` if any
    speed did not converge.
    """
    from .statics.batch import run_batch

    bearing, speeds, loads = _check_arguments(bearing, speeds, loads, control)
    arr = np.tile(loads.as_array(), (speeds.size, 1))
    out = run_batch(bearing, arr, speeds, control)
    if not out["converged"].all():
        bad = speeds[~out["converged"]]
        raise ConvergenceError(f"no equilibrium at speeds {bad.tolist()} rad/s",
                               iterations=int(out["iterations"].max()), residual=float(out["residual"].max()))
    k = out["k"]
    res = {"frequency": speeds, "stiffness_5x5": k}
    for name, i, j in ROSS_MAP:
        res[name] = k[:, i, j].copy()
    return res


def to_ross_bearing(bearing, n: int, speeds, loads=None, control: str = "outer", damping: float = 0.0,
                    n_link: int | None = None, tag: str | None = None):
    """A ``ross.BearingElement`` at shaft node ``n`` with our speed-dependent stiffness.

    damping [N·s/m] is applied as cxx = cyy (the quasi-static model gives none).  Requires the optional
    extra ``bearingsim[ross]``.
    """
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 0:
        raise InputError("n", f"expected a shaft node number ≥ 0, got {n!r}", "e.g. 0")
    if isinstance(damping, bool) or not isinstance(damping, int | float) or not (math.isfinite(damping)
                                                                                 and damping >= 0):
        raise InputError("damping", f"expected a damping ≥ 0 in N·s/m, got {damping!r}", "e.g. 0.0")
    try:
        import ross as rs
    except ImportError:
        raise InputError("ross", "ross-rotordynamics is not installed",
                         "pip install 'bearingsim[ross]' (or ross-rotordynamics)") from None
    c = ross_coefficients(bearing, speeds, loads, control)
    nf = c["frequency"].size
    kw = {name: (c[name] if nf > 1 else float(c[name][0])) for name, _, _ in ROSS_MAP}
    cc = np.full(nf, float(damping)) if nf > 1 else float(damping)
    return rs.BearingElement(n=n, cxx=cc, cyy=cc, frequency=c["frequency"] if nf > 1 else None, n_link=n_link,
                             tag=tag or getattr(bearing, "name", "bearing"), **kw)


def export_json(bearing, speeds, path, loads=None, control: str = "outer") -> Path:
    """Write the ROSS coefficients (and the dropped 5×5 terms) to a JSON file in SI."""
    if not isinstance(path, str | Path) or not str(path).strip():
        raise InputError("path", f"expected an output file path, got {path!r}"[:160], 'e.g. "bearing_ross.json"')
    c = ross_coefficients(bearing, speeds, loads, control)
    k = c["stiffness_5x5"]
    doc = {
        "bearing": getattr(bearing, "name", "bearing"),
        "convention": "ROSS BearingElement: rotor axis z; our (y, z, x) -> ROSS (x, y, z); SI units",
        "frequency_rad_s": c["frequency"].tolist(),
        **{f"{name}_N_per_m": c[name].tolist() for name, _, _ in ROSS_MAP},
        "dropped_terms": list(DROPPED),
        "dropped_max_abs": {
            "translation_tilt_N_per_rad": float(np.abs(k[:, 1:3, 3:5]).max()),
            "tilt_N_m_per_rad": float(np.abs(k[:, 3:5, 3:5]).max()),
            "axial_lateral_N_per_m": float(np.abs(k[:, 0, 1:3]).max()),
        },
        "stiffness_5x5_order": ["x", "y", "z", "gamma_y", "gamma_z"],
        "stiffness_5x5": k.tolist(),
    }
    path = Path(path)
    path.write_text(json.dumps(doc, indent=1), encoding="utf-8")
    return path
