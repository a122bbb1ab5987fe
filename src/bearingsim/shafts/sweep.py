"""Sweeps of a shaft system over speed and preload: the stiffness at a node, the support reactions and the
bearings' lives, as an ``xarray.Dataset`` (SI units in the attributes; written by :mod:`bearingsim.io.netcdf`).

Each point is a :func:`.solve.solve_shaft` equilibrium, warm started from the previous speed of the same preload.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from ..errors import InputError
from .model import BearingSupport, ShaftSystem
from .solve import dof_vector, solve_shaft


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


def shaft_sweep(system: ShaftSystem, speeds, position: float, preload_support: str | None = None, preloads=None,
                lives: bool = True):
    """Stiffness at the node at ``position`` [m], reactions and lives over ``speeds`` [rad/s] (and over
    ``preloads`` of the support ``preload_support``: its ``preload_force`` [N] when it has a spring preload, else
    its ``preload_offset`` [m]).

    Returns an ``xarray.Dataset`` over (preload, speed): ``stiffness_matrix`` (…, row, col) the condensed 5×5
    [SI], ``radial_stiffness``, ``axial_stiffness`` [N/m] and ``tilt_stiffness`` [N·m/rad] (direct: 1/compliance),
    ``reaction`` (…, support, component) [N, N·m], ``basic_rating_life_hours`` and
    ``reference_rating_life_hours`` (…, support) [h] (NaN where not rated), ``converged``.
    """
    import xarray as xr

    sp = np.asarray(speeds, dtype=float).reshape(-1)
    if sp.size == 0 or not np.all(np.isfinite(sp)):
        raise InputError("speeds", "must be finite speeds [rad/s]", "give e.g. 0:2000:21 rad/s")
    system.mesh.node_at(float(position), "position")
    if preloads is None:
        pl = np.array([np.nan])
        systems = [system]
    else:
        if preload_support is None:
            raise InputError("preload_support", "a preload sweep needs the support it acts on", "name a bearing")
        pl = np.asarray(preloads, dtype=float).reshape(-1)
        systems = [_with_preload(system, preload_support, float(p)) for p in pl]
    names = [s.name for s in system.supports]
    npl, nsp, nsu = len(pl), len(sp), len(names)
    kmat = np.full((npl, nsp, 5, 5), np.nan)
    direct = {k: np.full((npl, nsp), np.nan) for k in ("radial", "axial", "tilt")}
    reac = np.full((npl, nsp, nsu, 5), np.nan)
    l10 = np.full((npl, nsp, nsu), np.nan)
    l10r = np.full((npl, nsp, nsu), np.nan)
    conv = np.zeros((npl, nsp), dtype=bool)
    for i, sysi in enumerate(systems):
        w0 = None
        for j, w in enumerate(sp):
            r = solve_shaft(sysi, speed=float(w), initial=w0, bearing_results=lives)
            conv[i, j] = r.converged
            if not r.converged:
                continue
            w0 = dof_vector(r)
            kmat[i, j] = r.stiffness_at(position)
            d = r.direct_stiffness_at(position)
            direct["radial"][i, j], direct["axial"][i, j] = d["radial_N_per_m"], d["axial_N_per_m"]
            direct["tilt"][i, j] = d["tilt_N_m_per_rad"]
            for k, s in enumerate(r.supports):
                reac[i, j, k] = s.reaction
                if s.bearing_result is not None:
                    dd = s.bearing_result.to_dict()
                    l10[i, j, k] = dd.get("basic_rating_life_hours") or np.nan
                    l10r[i, j, k] = dd.get("reference_rating_life_hours") or np.nan
    ds = xr.Dataset(
        {"stiffness_matrix": (("preload", "speed", "row", "col"), kmat,
                              {"units": "SI (N m-1, N rad-1, N m m-1, N m rad-1)", "long_name": "condensed stiffness"}),
         "radial_stiffness": (("preload", "speed"), direct["radial"], {"units": "N m-1"}),
         "axial_stiffness": (("preload", "speed"), direct["axial"], {"units": "N m-1"}),
         "tilt_stiffness": (("preload", "speed"), direct["tilt"], {"units": "N m rad-1"}),
         "reaction": (("preload", "speed", "support", "component"), reac, {"units": "N, N m"}),
         "basic_rating_life_hours": (("preload", "speed", "support"), l10, {"units": "h"}),
         "reference_rating_life_hours": (("preload", "speed", "support"), l10r, {"units": "h"}),
         "converged": (("preload", "speed"), conv, {"units": "1"})},
        coords={"preload": ("preload", pl, {"units": "N or m", "support": preload_support or ""}),
                "speed": ("speed", sp, {"units": "rad s-1"}), "support": names,
                "component": ["Fx", "Fy", "Fz", "My", "Mz"], "row": list("xyzbc"), "col": list("xyzbc")},
        attrs={"title": f"shaft sweep of {system.name}", "position_m": float(position)})
    if preloads is None:
        ds = ds.isel(preload=0, drop=True)
    return ds
