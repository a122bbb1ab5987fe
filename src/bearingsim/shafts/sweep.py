"""Sweeps of a shaft system over speed and preload: the stiffness at a node, the support reactions, the shaft's
misalignment at each support and the bearings' lives and peak pressures.

Each point is a :func:`.solve.solve_shaft` equilibrium, warm started from the previous speed of the same chain.
A chain is one preload's speeds, or a contiguous run of them when a single preload is spread over several
workers; the chains run in this process, in local processes or on a Dask cluster (the map's executors), and
each chain's rows are written to the netCDF file as it finishes (:class:`bearingsim.io.netcdf.NetCDFWriter`,
SI with the units of each component), or gathered into an ``xarray.Dataset`` of the same schema.
"""

from __future__ import annotations

import dataclasses
import os
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..io import netcdf as nc
from .model import BearingSupport, ShaftSystem
from .solve import dof_vector, solve_shaft

#: data variables of a sweep: name → (extra dimensions, units, long name, dtype)
_VARS = {
    "stiffness_matrix": (("row", "col"), nc.STIFFNESS_UNITS, "condensed stiffness of the system at the node", "f8"),
    "radial_stiffness": ((), "N/m", "direct radial stiffness at the node (1 / compliance, y)", "f8"),
    "axial_stiffness": ((), "N/m", "direct axial stiffness at the node (1 / compliance)", "f8"),
    "tilt_stiffness": ((), "N m/rad", "direct tilt stiffness at the node (1 / compliance, about z)", "f8"),
    "reaction": (("support", "component"), nc.LOAD_UNITS, "reaction of each support on the shaft", "f8"),
    "misalignment": (("support", "tilt"), "rad", "tilt of the shaft against the outer ring at each support", "f8"),
    "max_contact_pressure": (("support",), "Pa", "largest Hertz pressure of each bearing", "f8"),
    "basic_rating_life_hours": (("support",), "h", "ISO 281 basic rating life L10h (NaN: not rated)", "f8"),
    "reference_rating_life_hours": (("support",), "h", "ISO/TS 16281 reference rating life L10rh (NaN: not rated)",
                                    "f8"),
    "converged": ((), "1", "1 where the point is an equilibrium (0: not converged, its values NaN)", "i1"),
}


def _with_preload(system: ShaftSystem, name: str, value: float) -> ShaftSystem:
    sups = []
    found = False
    for s in system.supports:
        if s.name == name:
            if not isinstance(s, BearingSupport):
                raise InputError("preload_support", f"{name!r} is a spring, not a bearing", "name a bearing support")
            found = True
            s = dataclasses.replace(s, preload_force=value) if s.preload_force is not None else \
                dataclasses.replace(s, preload_offset=value)
        sups.append(s)
    if not found:
        raise InputError("preload_support", f"no support named {name!r}",
                         f"use one of {', '.join(s.name for s in system.supports)}")
    return dataclasses.replace(system, supports=tuple(sups))


def preload_kind(system: ShaftSystem, name: str) -> str:
    """``"force"`` when the bearing support ``name`` is preloaded by a spring (its ``preload_force`` [N] is
    swept), else ``"length"`` (its ``preload_offset`` [m])."""
    for s in system.supports:
        if s.name == name and isinstance(s, BearingSupport):
            return "force" if s.preload_force is not None else "length"
    return "length"


def sweep_chain(system: ShaftSystem, speeds, position: float, lives: bool = True) -> dict:
    """The rows of one chain: each speed of ``speeds`` [rad/s] solved warm from the last converged one; a dict
    of arrays over the speeds with the keys of the sweep's variables (NaN where not converged)."""
    sp = np.asarray(speeds, dtype=float)
    nsu = len(system.supports)
    out = {"stiffness_matrix": np.full((sp.size, 5, 5), np.nan), "radial_stiffness": np.full(sp.size, np.nan),
           "axial_stiffness": np.full(sp.size, np.nan), "tilt_stiffness": np.full(sp.size, np.nan),
           "reaction": np.full((sp.size, nsu, 5), np.nan), "misalignment": np.full((sp.size, nsu, 2), np.nan),
           "max_contact_pressure": np.full((sp.size, nsu), np.nan),
           "basic_rating_life_hours": np.full((sp.size, nsu), np.nan),
           "reference_rating_life_hours": np.full((sp.size, nsu), np.nan),
           "converged": np.zeros(sp.size, dtype=np.int8)}
    w0 = None
    for j, w in enumerate(sp):
        r = solve_shaft(system, speed=float(w), initial=w0, bearing_results=lives)
        if not r.converged:
            continue
        out["converged"][j] = 1
        w0 = dof_vector(r)
        out["stiffness_matrix"][j] = r.stiffness_at(position)
        d = r.direct_stiffness_at(position)
        out["radial_stiffness"][j], out["axial_stiffness"][j] = d["radial_N_per_m"], d["axial_N_per_m"]
        out["tilt_stiffness"][j] = d["tilt_N_m_per_rad"]
        for k, s in enumerate(r.supports):
            out["reaction"][j, k] = s.reaction
            out["misalignment"][j, k] = s.misalignment
            b = s.bearing_result
            if b is not None:
                out["max_contact_pressure"][j, k] = max(float(np.max(b.balls["inner_max_pressure_Pa"])),
                                                        float(np.max(b.balls["outer_max_pressure_Pa"])))
                if lives:
                    dd = b.to_dict()
                    for key in ("basic_rating_life_hours", "reference_rating_life_hours"):
                        h = dd.get(key)
                        out[key][j, k] = np.nan if h is None else float(h)
    return out


def _schema(system: ShaftSystem, npl: int | None, nsp: int, preload_units: str | None):
    lead = ("preload", "speed") if npl is not None else ("speed",)
    dims = {"speed": nsp, "support": len(system.supports), "component": 5, "tilt": 2, "row": 5, "col": 5}
    if npl is not None:
        dims = {"preload": npl} | dims
    variables = [nc.Variable("speed", ("speed",), "rad/s", "shaft speed", attrs={"units_display": "rpm"}),
                 nc.Variable("support", ("support",), None, "support name", str),
                 nc.Variable("component", ("component",), None, "reaction component", str),
                 nc.Variable("tilt", ("tilt",), None, "tilt component (about y, about z)", str),
                 nc.Variable("row", ("row",), None, "generalised force (Fx, Fy, Fz, My, Mz)", str),
                 nc.Variable("col", ("col",), None, "degree of freedom (x, y, z, gamma_y, gamma_z)", str)]
    if npl is not None:
        variables.insert(0, nc.Variable("preload", ("preload",), preload_units, "preload of the swept support"))
    for name, (extra, units, long, dt) in _VARS.items():
        attrs = {"flag_values": "0 1", "flag_meanings": "not_converged converged"} if name == "converged" else {}
        variables.append(nc.Variable(name, lead + extra, units, long, dt, attrs))
    return dims, variables


def _labels(system: ShaftSystem) -> dict:
    return {"support": [s.name for s in system.supports], "component": ["Fx", "Fy", "Fz", "My", "Mz"],
            "tilt": ["gamma_y", "gamma_z"], "row": ["Fx", "Fy", "Fz", "My", "Mz"],
            "col": ["x", "y", "z", "gamma_y", "gamma_z"]}


def _chains(npl: int, nsp: int, workers: int) -> list[tuple[int, slice]]:
    """(preload index, speed slice) of each chain: one per preload, or, for a single preload, up to ``workers``
    contiguous runs of at least 4 speeds (each starts cold)."""
    if npl > 1 or workers <= 1:
        return [(i, slice(0, nsp)) for i in range(npl)]
    n = max(1, min(workers, nsp // 4))
    edges = np.linspace(0, nsp, n + 1).round().astype(int)
    return [(0, slice(int(a), int(b))) for a, b in zip(edges[:-1], edges[1:])]


def shaft_sweep(system: ShaftSystem, speeds, position: float, preload_support: str | None = None, preloads=None,
                lives: bool = True, *, out: str | Path | None = None, workers: int | None = 1, scheduler=None,
                scheduler_timeout: float = 3.0, worker_timeout: float = 60.0, attrs: dict | None = None):
    """Stiffness at the node at ``position`` [m], reactions, misalignments, peak pressures and lives over
    ``speeds`` [rad/s] (and over ``preloads`` of the support ``preload_support``: its ``preload_force`` [N] when it
    has a spring preload, else its ``preload_offset`` [m]).

    Parameters
    ----------
    system : the shaft system
    speeds : shaft speeds [rad/s]
    position : axial position of the node whose stiffness is reported [m]
    preload_support, preloads : the bearing support whose preload is swept and the preload values [N or m]
    lives : rate the bearings (ISO 281 and ISO/TS 16281 lives) at every point
    out : netCDF file written as the chains finish (None: the dataset in memory)
    workers : local processes (1: this process; None: every core); ignored with ``scheduler``
    scheduler : a Dask scheduler address ``tcp://host:port`` or a ``distributed.Client``
    scheduler_timeout, worker_timeout : seconds to reach the scheduler, and without any worker before failing

    Returns
    -------
    xarray.Dataset over (preload,) speed with the variables of :data:`_VARS` (SI; ``units`` and
    ``units_by_component`` as every file of the library), or, with ``out``, the path of the file written.
    """
    from .. import sweep as map_sweep

    sp = np.asarray(speeds, dtype=float).reshape(-1)
    if sp.size == 0 or not np.all(np.isfinite(sp)):
        raise InputError("speeds", "must be finite speeds [rad/s]", "give e.g. 0:2000:21 rad/s")
    system.mesh.node_at(float(position), "position")
    if preloads is None:
        pl, systems, punits = None, [system], None
    else:
        if preload_support is None:
            raise InputError("preload_support", "a preload sweep needs the support it acts on", "name a bearing")
        pl = np.asarray(preloads, dtype=float).reshape(-1)
        if pl.size == 0 or not np.all(np.isfinite(pl)):
            raise InputError("preloads", "must be finite preloads [N or m]", "give e.g. 100:800:8 N")
        systems = [_with_preload(system, preload_support, float(p)) for p in pl]
        punits = "N" if preload_kind(system, preload_support) == "force" else "m"
    if workers is None:
        workers = os.cpu_count() or 1
    if not isinstance(workers, int) or isinstance(workers, bool) or workers < 1:
        raise InputError("workers", f"must be a whole number ≥ 1, got {workers!r}", "e.g. workers=2")
    npl = 1 if pl is None else pl.size
    dims, variables = _schema(system, None if pl is None else pl.size, sp.size, punits)
    values = _labels(system) | {"speed": sp} | ({} if pl is None else {"preload": pl})
    attrs = {"title": f"shaft sweep of {system.name}", "position_m": float(position),
             "preload_support": preload_support or ""} | (attrs or {})
    chains = _chains(npl, sp.size, 1 if scheduler is not None else workers)
    args = [(systems[i], sp[s], float(position), lives) for i, s in chains]
    writer = data = None
    if out is not None:
        writer = nc.NetCDFWriter(out, dims=dims, variables=variables, values=values, attrs=attrs)
    else:
        data = {name: np.zeros((npl, sp.size) + tuple(dims[d] for d in extra), dtype=dt)
                for name, (extra, _, _, dt) in _VARS.items()}

    def done(chain, rows):
        i, s = chain
        for name, v in rows.items():
            if writer is not None:
                writer.write(name, (i, s) if pl is not None else s, v)
            else:
                data[name][i, s] = v

    try:
        if scheduler is None:
            map_sweep.run_tasks_locally(sweep_chain, args, chains, done, workers, what="chains",
                                        job="the shaft sweep")
        else:
            client, owned = map_sweep._connect(scheduler, scheduler_timeout)
            quiet = map_sweep._QuietDistributed().__enter__() if owned else None
            try:
                map_sweep.run_tasks_on_cluster(client, sweep_chain, args, chains, done, worker_timeout,
                                               what="chains")
            finally:
                if owned:
                    map_sweep._close(client, quiet)
    except BaseException:
        if writer is not None:
            writer.abort()
        raise
    if writer is not None:
        writer.close()
        return writer.final
    if pl is None:
        data = {k: v[0] for k, v in data.items()}
    coords = ["speed", "support", "component", "tilt", "row", "col"] + ([] if pl is None else ["preload"])
    return nc.to_xarray(variables, values | data, attrs, coords)
