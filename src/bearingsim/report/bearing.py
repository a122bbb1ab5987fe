"""The everyday bearing report: one operating point of one bearing (or set) on one page a colleague can read.

:func:`bearing_report` solves the quasi-static equilibrium (:func:`bearingsim.statics.jones_harris.solve`), adds
the friction torque and heat when a lubricant is given (:func:`bearingsim.friction.friction_summary`) and writes
``DIR/report.html`` with its figures beside it (PNG; the page links them by relative name, so the folder opens
from disk without a server and prints to PDF from a browser):

* inputs with units and, per field, its source or the flag that it is an estimate (the bearing file's
  ``[sources]``; :attr:`bearingsim.geometry.BallBearing.estimated`);
* results in the units of the trade (:func:`bearingsim.units.display_unit`): displacements in µm and mrad,
  stiffness in N/µm and N·m/mrad (each matrix cell with its own unit), lives in hours, static safety, friction
  torque, warnings;
* the plots engineers read: ball load Q(ψ) per row (polar), contact angles vs ψ, maximum contact pressure vs ψ
  against the ISO 76 reference of 4200 MPa, the contact ellipse's extent on the groove, and with a map file
  (``bearingsim map … --out map.nc``) the stiffness against speed per load.

Numbers come from the result's own ``to_dict`` (SI) and are converted only for display here.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..life import hours_text
from ..units import display_unit
from . import html as H

#: ISO 76:2006 reference contact pressure of ball bearings [Pa] (the basis of C0)
ISO76_PRESSURE = 4.2e9

_DOF = ("x", "y", "z", "γy", "γz")
_DOF_UNITS = ("m", "m", "m", "rad", "rad")


def _show(value, si_unit: str, spec: str = ".4g") -> str:
    """``value`` [SI] in the unit people read, with the unit."""
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "—"
    unit, f = display_unit(si_unit)
    return f"{format(float(value) * f, spec)} {unit}"


def _stiffness_unit(i: int, j: int) -> str:
    num = "N" if i < 3 else "N m"
    return f"{num}/{_DOF_UNITS[j]}"


def _input_rows(bearing) -> list:
    """(row, field, value, source) of every documented input of each row's bearing."""
    out = []
    fields = (("bore", "bore", "m", "mm", 1e3), ("outside_diameter", "outside diameter", "m", "mm", 1e3),
              ("width", "width", "m", "mm", 1e3), ("ball_diameter", "ball diameter D", "m", "mm", 1e3),
              ("ball_count", "ball count Z", "", "", 1.0), ("pitch_diameter", "pitch diameter d_m", "m", "mm", 1e3),
              ("inner_conformity", "inner conformity f_i", "", "", 1.0),
              ("outer_conformity", "outer conformity f_o", "", "", 1.0),
              ("contact_angle", "contact angle α₀", "rad", "deg", 180.0 / math.pi),
              ("diametral_clearance", "diametral clearance P_d", "m", "µm", 1e6),
              ("dynamic_load_rating", "dynamic load rating C", "N", "kN", 1e-3),
              ("static_load_rating", "static load rating C₀", "N", "kN", 1e-3),
              ("geometry_factor_f0", "factor f₀", "", "", 1.0),
              ("fatigue_load_limit", "fatigue load limit P_u", "N", "kN", 1e-3),
              ("limiting_speed", "limiting speed", "rad/s", "rpm", 30.0 / math.pi))
    for k, row in enumerate(bearing.rows):
        b = row.bearing
        src = b.sources
        est = set(b.estimated)
        for name, label, _, unit, f in fields:
            v = getattr(b, name, None)
            if v is None or (name not in ("diametral_clearance", "ball_count", "contact_angle") and v == 0):
                continue
            key = name if name in src else next((s for s in src if s in name), None)
            note = src.get(key, "") if key else ""
            flag = "ESTIMATE" if (key in est or name in est) else ""
            out.append([k, label, f"{v * f:.5g} {unit}".strip(), flag, note])
        out.append([k, "materials", f"balls {b.ball_material.name}, rings {b.ring_material.name}", "", ""])
    return out


def _save(fig, path: Path, caption: str) -> tuple[str, str]:
    """Write ``fig`` to ``path`` (PNG beside the page) and close it; (file name, caption)."""
    import matplotlib.pyplot as plt

    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path.name, caption


def _figures(res, d: dict, out: Path, stem: str) -> list[tuple[str, str]]:
    """Write the figures; return (file name, caption) pairs."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    balls = res.balls  # dict of per-ball arrays (SI)
    rows = np.asarray(balls["row"], dtype=int)
    psi = np.asarray(balls["azimuth_rad"], dtype=float)
    figs = []

    # 1 load distribution per row: stems outward from the outer raceway (outer contact) and inward from the inner
    #   raceway (inner contact), load direction marked; viewed from +x (y up, z to the left)
    nrow = int(rows.max()) + 1 if len(rows) else 1
    fig, axs = plt.subplots(1, nrow, figsize=(3.6 * nrow, 3.6), squeeze=False)
    qmax = max(float(np.max(balls["inner_load_N"])), float(np.max(balls["outer_load_N"])), 1e-9)
    lo = d["loads"]
    for r in range(nrow):
        ax = axs[0, r]
        m = rows == r
        ro, ri, span = 1.0, 0.62, 0.32  # outer / inner raceway circles and the stem length of the largest load
        t = np.linspace(0, 2 * np.pi, 200)
        ax.plot(-ro * np.sin(t), ro * np.cos(t), color="C1", lw=1)
        ax.plot(-ri * np.sin(t), ri * np.cos(t), color="C0", lw=1)
        for p_, qi, qo in zip(psi[m], np.asarray(balls["inner_load_N"], float)[m],
                              np.asarray(balls["outer_load_N"], float)[m]):
            u = np.array([-np.sin(p_), np.cos(p_)])  # ψ = 0 along +y (up), +z to the left seen from +x
            ax.plot(*np.c_[ro * u, (ro + span * qo / qmax) * u], color="C1", lw=3, solid_capstyle="butt")
            ax.plot(*np.c_[ri * u, (ri - span * qi / qmax) * u], color="C0", lw=3, solid_capstyle="butt")
            ax.plot(*(0.5 * (ro + ri) * u), "o", ms=5, mfc="white", mec="0.4")
        fry, frz = lo["fr_y_N"], lo["fr_z_N"]
        if math.hypot(fry, frz) > 0:
            v = np.array([-frz, fry]) / math.hypot(fry, frz)
            ax.annotate("", xy=0.5 * v, xytext=(0, 0), arrowprops=dict(arrowstyle="-|>", color="k", lw=1.8))
            ax.text(*(0.12 * v + np.array([0.05, -0.12])), f"Fr {math.hypot(fry, frz) / 1e3:.3g} kN", fontsize=7)
        if lo["fa_N"]:
            ax.text(0, -0.3, f"Fa {lo['fa_N'] / 1e3:.3g} kN along x", fontsize=7, ha="center")
        ax.set_aspect("equal")
        ax.set_xlim(-1.45, 1.45)
        ax.set_ylim(-1.45, 1.45)
        ax.axis("off")
        ax.text(0, 1.4, "ψ = 0 (+y)", ha="center", fontsize=7)
        ax.text(-1.42, 0, "+z", ha="left", va="center", fontsize=7)
        ax.set_title((f"row {r}: " if nrow > 1 else "") + f"ball loads, largest {qmax:.4g} N", fontsize=9)
    axs[0, 0].plot([], [], color="C1", lw=3, label="outer raceway contact (outward)")
    axs[0, 0].plot([], [], color="C0", lw=3, label="inner raceway contact (inward)")
    fig.tight_layout(rect=(0, 0.12, 1, 1))
    fig.legend(loc="lower center", fontsize=7, ncol=1, frameon=False)
    figs.append(_save(fig, out / f"{stem}_load_distribution.png",
                      "Ball loads at both raceways: stems outward from the outer raceway and inward from the inner "
                      "raceway, length ∝ Q; arrow: the radial load on the inner ring (seen from +x)"))

    # 2 contact angles and 3 pressure vs azimuth
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(8.5, 3.0))
    for r in range(nrow):
        m = rows == r
        o = np.argsort(psi[m])
        deg = np.degrees(psi[m][o])
        for key, style, lab in (("inner_contact_angle_rad", "o-", "inner"),
                                ("outer_contact_angle_rad", "s--", "outer")):
            a1.plot(deg, np.degrees(np.asarray(balls[key])[m][o]), style, ms=3, label=f"row {r} {lab}")
        for key, lab in (("inner_max_pressure_Pa", "inner"), ("outer_max_pressure_Pa", "outer")):
            a2.plot(deg, np.asarray(balls[key], dtype=float)[m][o] * 1e-6, "o-", ms=3, label=f"row {r} {lab}")
    a1.set_xlabel("azimuth ψ [deg]")
    a1.set_ylabel("contact angle [deg]")
    a1.legend(fontsize=6, ncol=2, loc="best", framealpha=0.7)
    a2.axhline(ISO76_PRESSURE * 1e-6, color="k", lw=1, ls=":", label="ISO 76 reference 4200 MPa")
    a2.set_xlabel("azimuth ψ [deg]")
    a2.set_ylabel("maximum contact pressure [MPa]")
    a2.set_ylim(0, ISO76_PRESSURE * 1.15e-6)
    a2.legend(fontsize=6, ncol=2, loc="lower right", framealpha=0.7)
    figs.append(_save(fig, out / f"{stem}_angles_pressure.png",
                      "Contact angles and maximum contact pressure against the azimuth; dotted: the 4200 MPa "
                      "reference of ISO 76 (the pressure behind the static load rating C₀)"))

    # 4 contact ellipse against the groove shoulder: α ± a/(f D) per ball, the shoulder edge dashed
    fig, axs = plt.subplots(1, 2, figsize=(8.5, 3.0), sharey=True)
    flagged = []
    for k, (inner, name_) in enumerate(((True, "inner"), (False, "outer"))):
        ax = axs[k]
        for r, row in enumerate(res.bearing.rows):
            b = row.bearing
            f = b.inner_conformity if inner else b.outer_conformity
            m = rows == r
            q = np.asarray(balls[f"{name_}_load_N"], dtype=float)[m]
            alpha = np.abs(np.asarray(balls[f"{name_}_contact_angle_rad"], dtype=float)[m])
            o = np.argsort(psi[m])
            half = np.full_like(q, np.nan)
            for j in range(len(q)):
                if q[j] > 0:
                    half[j] = b.contact(float(q[j]), inner, float(alpha[j])).a / (f * b.ball_diameter)
            deg = np.degrees(psi[m][o])
            lab = f"row {r}: " if len(res.bearing.rows) > 1 else ""
            ax.fill_between(deg, np.degrees(alpha[o] - half[o]), np.degrees(alpha[o] + half[o]), alpha=0.35,
                            color=f"C{r}", label=f"{lab}ellipse α ± a/(f·D)")
            theta, basis = shoulder_angle(b, inner)
            ax.axhline(math.degrees(theta), color=f"C{r}", ls="--", lw=1.2,
                       label=f"{lab}shoulder {math.degrees(theta):.0f}° (estimate)")
            top = np.nanmax(alpha + half) if np.any(q > 0) else 0.0
            if top > theta:
                flagged.append(f"{name_} row {r}")
        ax.set_title(f"{name_} raceway", fontsize=9)
        ax.set_xlabel("azimuth ψ [deg]")
        ax.set_ylim(bottom=min(0.0, ax.get_ylim()[0]), top=max(ax.get_ylim()[1], 1.0) * 1.35)
        ax.legend(fontsize=7, loc="upper right", framealpha=0.8)
    axs[0].set_ylabel("groove angle from the bottom [deg]")
    cap = ("Contact ellipse on the groove (band: centre α, half-width a/(f·D)) against the raceway shoulder "
           f"(dashed; ESTIMATE: {basis}). ")
    cap += ("The ellipse runs over the shoulder at: " + ", ".join(flagged) + ".") if flagged else \
        "The ellipse stays below the estimated shoulder."
    figs.append(_save(fig, out / f"{stem}_ellipse.png", cap))
    return figs


def shoulder_angle(bearing, inner: bool) -> tuple[float, str]:
    """Groove angle of the shoulder edge θ_s = arccos(1 − h/(f·D)) [rad] (the edge of the groove circle of radius
    f·D at the height h above the groove bottom) and how h was found.  The bearing file has no shoulder height:
    h is the land height of the ring sections estimated from the boundary dimensions
    (:func:`bearingsim.rings.section.estimate_sections`, lands 0.25 D above/below the groove bottom); without
    boundary dimensions the same 0.25 D."""
    f = bearing.inner_conformity if inner else bearing.outer_conformity
    dw = bearing.ball_diameter
    h = 0.25 * dw
    basis = "shoulder height 0.25·D, the file gives none and no boundary dimensions"
    if bearing.bore > 0 and bearing.outside_diameter > 0 and bearing.width > 0:
        from ..rings.section import estimate_sections

        try:
            sec = estimate_sections(bearing)[0 if inner else 1]
            h = abs(sec.land_radius - sec.groove_bottom_radius)
            basis = (f"shoulder height {h / dw:.2f}·D from the ring sections estimated from the boundary "
                     "dimensions; the file gives none")
        except InputError:
            pass
    return math.acos(max(-1.0, 1.0 - h / (f * dw))), basis


def _speed_figure(b, loads, speed, control, tilt, misalignment, out: Path, stem: str):
    """Axial and radial stiffness against speed, one line per load (the operating load × 0.5, 1, 2)."""
    import dataclasses

    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from ..statics.jones_harris import solve

    rows = b.rows
    lim = min((getattr(r.bearing, "limiting_speed", 0.0) or 0.0) for r in rows)
    top = max(lim if lim > 0 else 0.0, 1.25 * abs(speed), 100.0)
    speeds = np.linspace(0.0, top, 9)
    fig, axs = plt.subplots(1, 2, figsize=(8.5, 3.0))
    rpm = 30.0 / math.pi
    for i, s_ in enumerate((0.5, 1.0, 2.0)):
        ld = dataclasses.replace(loads, fa=loads.fa * s_, fr_y=loads.fr_y * s_, fr_z=loads.fr_z * s_,
                                 m_y=loads.m_y * s_, m_z=loads.m_z * s_)
        k = np.full((len(speeds), 2), np.nan)
        for j, w in enumerate(speeds):
            r_ = solve(b, ld, float(w), control, tilt=tilt, misalignment=misalignment)
            if r_.converged:
                k[j] = r_.stiffness[0, 0], r_.stiffness[1, 1]
        for a, col in zip(axs, range(2)):
            a.plot(speeds * rpm, k[:, col] * 1e-6, "o-", ms=3, color=f"C{i}", label=f"{s_:g} × the load")
    for a, lab in zip(axs, ("axial K_xx [N/µm]", "radial K_yy [N/µm]")):
        a.axvline(abs(speed) * rpm, color="k", ls=":", lw=0.8)
        a.set_xlabel("speed [rpm]")
        a.set_ylabel(lab)
    axs[1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5), frameon=False)
    return _save(fig, out / f"{stem}_stiffness_speed.png",
                 "Stiffness against speed, one line per load (0.5, 1 and 2 × the operating load, all components "
                 "scaled); dotted: the operating speed" + (f"; up to the limiting speed {lim * rpm:.0f} rpm"
                                                            if lim > 0 else ""))


def _check_map_bearing(map_file: Path, bearing) -> None:
    """An :class:`InputError` when the map file was made for another bearing (its ``bearing`` attribute, written by
    :func:`bearingsim.sweep.map_grid`): the report would draw another bearing's stiffness under this one's name.
    Checked before anything is computed; a file that cannot be read is :func:`_map_figure`'s to report."""
    import xarray as xr

    try:
        with xr.open_dataset(map_file) as ds:
            made_for = ds.attrs.get("bearing")
    except (OSError, ValueError):
        return
    name = getattr(bearing, "name", None)
    if made_for is not None and name is not None and str(made_for) != str(name):
        raise InputError("map", f"{map_file.name} is a map of {made_for}, not of {name}",
                         "make the map of this bearing: bearingsim map BEARING --speed … --out FILE.nc")


def _map_figure(map_file: Path, out: Path, stem: str):
    """Axial and radial stiffness against speed per axial load, from a map file (``bearingsim map``)."""
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt
    import xarray as xr

    from ..io import netcdf as nc

    if not Path(map_file).is_file():
        raise InputError("map", f"no such file: {map_file}", "give a file written by bearingsim map --out")
    try:
        ds = xr.open_dataset(map_file)
    except (OSError, ValueError) as exc:
        raise InputError("map", f"cannot read {map_file} as a map file ({type(exc).__name__})",
                         "give a file written by bearingsim map --out") from None
    try:
        if "stiffness" not in ds or "speed" not in ds["stiffness"].dims:
            raise InputError("map", f"{map_file} has no speed axis", "make the map with --speed a grid, e.g. 0:12000:7")
        units = nc.component_units(ds["stiffness"].attrs, (5, 5))
        fig, axs = plt.subplots(1, 2, figsize=(9.5, 3.0))
        su, sf = display_unit(ds["speed"].attrs.get("units", "rad/s"))
        others = [dim for dim in ds["stiffness"].dims if dim not in ("speed", "dof", "dof2")]
        for ax, (i, lab) in zip(axs, ((0, "axial K_xx"), (1, "radial K_yy"))):
            ku, kf = display_unit(units[i][i] if isinstance(units, list) else units)
            k = ds["stiffness"].isel(dof=i, dof2=i)
            if others:
                first = others[0]
                rest = {dd: 0 for dd in others[1:]}
                k = k.isel(**rest) if rest else k
                for v in range(k.sizes[first]):
                    kv = k.isel({first: v})
                    fu, ff = display_unit(ds[first].attrs.get("units", ""))
                    ax.plot(ds["speed"].values * sf, kv.values * kf, "o-", ms=3,
                            label=f"{first} = {float(ds[first].values[v]) * ff:g} {fu}")
                ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.02, 0.5), frameon=False)
            else:
                ax.plot(ds["speed"].values * sf, k.values * kf, "o-", ms=3)
            ax.set_xlabel(f"speed [{su}]")
            ax.set_ylabel(f"{lab} [{ku}]")
        return _save(fig, out / f"{stem}_map_stiffness.png",
                     f"Stiffness against speed per load, from {Path(map_file).name}")
    finally:
        ds.close()


#: defaults the report applies to inputs the caller does not give (shown as "(default)" on the page)
DEFAULTS = {"speed": 0.0, "control": "outer", "tilt": "free", "temperature": 333.15,
            "lubrication_method": "oil_bath"}

_FRICTION_LABELS = (("palmgren_load_N_m", "Palmgren: load-dependent term M₁"),
                    ("palmgren_viscous_N_m", "Palmgren: viscous term M₀"),
                    ("rolling_N_m", "rolling resistance of the EHL film"), ("spin_N_m", "spin at the contacts"),
                    ("sliding_N_m", "sliding (micro-slip) at the contacts"), ("drag_N_m", "ball drag in the lubricant"),
                    ("cage_land_N_m", "cage land"), ("cage_pocket_N_m", "cage pockets"),
                    ("jet_momentum_N_m", "oil-jet momentum"))
_CONTROL_LABELS = {"outer": "outer-raceway control", "inner": "inner-raceway control",
                   "auto": "per ball (inner or outer, whichever holds)"}
_METHOD_LABELS = {"oil_bath": "oil bath", "oil_mist": "oil mist", "oil_jet": "oil jet", "grease": "grease"}
#: identifiers that library notes may contain, with the words the page uses instead
_WORDS = {"fatigue_load_limit_N": "fatigue load limit P_u", "static_load_rating_N": "static load rating C₀",
          "geometry_factor_f0": "factor f₀", "dynamic_load_rating_N": "dynamic load rating C",
          "ball_count": "ball count", "ball_diameter": "ball diameter", "diametral_clearance": "diametral clearance",
          "inner_conformity": "inner conformity", "outer_conformity": "outer conformity",
          "pitch_diameter": "pitch diameter", "contact_angle": "contact angle",
          "fatigue_load_limit": "fatigue load limit",
          "static_load_rating": "static load rating", "dynamic_load_rating": "dynamic load rating",
          "bearing_steel": "bearing steel", "silicon_nitride": "silicon nitride", "palmgren": "Palmgren",
          "physical": "physics-based"}


def human(text) -> str:
    """``text`` with the library's identifiers (field and material names) replaced by words and module paths
    dropped."""
    out = re.sub(r"\s*\(bearingsim\.[\w.]+\)", "", str(text))  # module paths are for the code, not the page
    out = re.sub(r"\bbearingsim(\.[a-z_]\w*){2,}", "bearingsim", out)
    for key in sorted(_WORDS, key=len, reverse=True):
        out = re.sub(rf"\b{re.escape(key)}\b", _WORDS[key], out)
    return out


def _value(text: str, given: bool) -> str:
    return text if given else f"{text} (default)"


def _api_call(bearing, loads, speed, kwargs: dict) -> str:
    """The Python call that makes this report (for the page's provenance line)."""
    name = bearing if isinstance(bearing, (str, Path)) else getattr(bearing, "name", "bearing")
    lf = ", ".join(f"{k}={getattr(loads, k)!r}" for k in ("fa", "fr_y", "fr_z", "m_y", "m_z") if getattr(loads, k))
    args = [repr(str(name)), f"Loads({lf})"] + ([repr(float(speed))] if speed is not None else [])
    args += [f"{k}={v!r}" for k, v in kwargs.items() if v is not None]
    return f"bearingsim.bearing_report({', '.join(args)})"


def _per_ball(d: dict) -> tuple[list, list]:
    """Header and rows of the per-ball table (display units)."""
    header = ["row", "ball", "ψ [deg]", "Q inner [N]", "Q outer [N]", "α inner [deg]", "α outer [deg]",
              "p_max inner [MPa]", "p_max outer [MPa]", "orbit [rpm]", "spin [rpm]", "control"]
    rows = []
    per_row: dict = {}
    for bd in d["balls"]:
        r = int(bd.get("row", 0))
        per_row[r] = per_row.get(r, 0) + 1
        loaded = bd["inner_load_N"] > 0 or bd["outer_load_N"] > 0
        ang = (lambda v: math.degrees(v)) if loaded else (lambda v: None)
        rows.append([r, per_row[r], math.degrees(bd["azimuth_rad"]), bd["inner_load_N"], bd["outer_load_N"],
                     ang(bd["inner_contact_angle_rad"]), ang(bd["outer_contact_angle_rad"]),
                     bd["inner_max_pressure_Pa"] * 1e-6, bd["outer_max_pressure_Pa"] * 1e-6,
                     bd["orbital_speed_rad_s"] * 30 / math.pi, bd["spin_speed_rad_s"] * 30 / math.pi,
                     "inner" if bd.get("inner_control") else "outer"])
    return header, rows


def bearing_report(bearing, loads, speed: float | None = None, *, out_dir, lubricant=None,
                   temperature: float | None = None, control: str | None = None, map_file=None,
                   lubrication_method: str | None = None, tilt: str | None = None, misalignment=None,
                   command: str | None = None, given=None) -> Path:
    """Write ``out_dir/report.html`` and its figures for one operating point; return the page's path.

    bearing : BallBearing or BearingSystem (or a catalogue name / TOML path); loads : ``Loads`` [N, N m];
    speed [rad/s]; lubricant (name, path or Lubricant) and temperature [K] for the friction torque and the modified
    life; map_file : a map netCDF file for the stiffness-vs-speed figure (else the report sweeps the speed itself);
    tilt, misalignment : the tilt control of :func:`bearingsim.statics.jones_harris.solve` ("free", or "fixed" at
    (γy, γz) [rad], reaction moment shown).  Inputs left as None take :data:`DEFAULTS` and are shown as defaults.
    command : the command line that makes the report (shown on the page; default: the equivalent Python call);
    given : names of the inputs the user gave (``fa``, ``fr``, ``fz``, ``moment``, ``my``, ``speed``,
    ``temperature``, ``control``, ``tilt``, ``lubrication_method``); default: those passed as not None (loads:
    the non-zero components).
    """
    import datetime

    from .. import __version__
    from ..io import load_bearing
    from ..statics.jones_harris import solve

    kwargs = {"out_dir": str(out_dir), "lubricant": lubricant, "temperature": temperature, "control": control,
              "map_file": None if map_file is None else str(map_file), "lubrication_method": lubrication_method,
              "tilt": tilt, "misalignment": misalignment}
    call = command or _api_call(bearing, loads, speed, kwargs)
    if given is None:
        given = {k for k in ("speed", "temperature", "control", "tilt", "lubrication_method")
                 if {"speed": speed, "temperature": temperature, "control": control, "tilt": tilt,
                     "lubrication_method": lubrication_method}[k] is not None}
        given |= {n for n, k in (("fa", "fa"), ("fr", "fr_y"), ("fz", "fr_z"), ("my", "m_y"), ("moment", "m_z"))
                  if getattr(loads, k)}
    given = set(given)
    speed = DEFAULTS["speed"] if speed is None else speed
    control = control or DEFAULTS["control"]
    tilt = tilt or DEFAULTS["tilt"]
    lubrication_method = lubrication_method or DEFAULTS["lubrication_method"]
    if lubricant is not None and temperature is None:
        temperature = DEFAULTS["temperature"]
        given.discard("temperature")

    b = load_bearing(bearing)
    if map_file is not None:
        _check_map_bearing(Path(map_file), b)
    out = Path(out_dir)
    res = solve(b, loads, speed, control, tilt=tilt, misalignment=misalignment)
    if lubricant is not None and res.converged:  # the modified rating lives need the lubricant (bearingsim.life)
        from ..life import apply_rating

        apply_rating(res, lubricant, temperature)
    d = res.to_dict()
    fr = None
    if lubricant is not None:
        from ..friction import friction_summary

        fr = friction_summary(res, lubricant, temperature, lubrication_method=lubrication_method)
    out.mkdir(parents=True, exist_ok=True)
    stem = "bearing"
    parts = []
    ld = d["loads"]
    disp = d["displacement"]
    lf = d.get("life_factors") or {}

    # ---- summary first: what a colleague reads
    load_txt = ", ".join(f"{lab} {_show(ld[key], unit)}" for lab, key, unit in
                         (("Fa", "fa_N", "N"), ("Fr,y", "fr_y_N", "N"), ("Fr,z", "fr_z_N", "N"),
                          ("My", "m_y_N_m", "N m"), ("Mz", "m_z_N_m", "N m")) if ld[key])
    op_txt = f"{load_txt or 'no load'} at {_value(_show(d['speed_rad_s'], 'rad/s'), 'speed' in given)}"
    if lubricant is not None:
        op_txt += (f"; {getattr(lubricant, 'name', lubricant)} at "
                   f"{_value(f'{temperature - 273.15:.0f} °C', 'temperature' in given)}")
    kr = np.asarray(d["stiffness_matrix"], dtype=float)
    data_kind = "estimated data flagged below" if any(r.bearing.estimated for r in b.rows) else "catalogue data"
    summary = [["bearing", f"{d['bearing']} ({data_kind})"],
               ["operating point", op_txt],
               ["status", "converged" if d["converged"] else f"NOT CONVERGED: {d['status']}"],
               ["basic rating life L10h (ISO 281)", hours_text(d.get("basic_rating_life_hours"))],
               ["modified rating life L_nmh (ISO 281, a1·a_ISO)", hours_text(d.get("modified_rating_life_hours"))
                if lubricant is not None else "— (needs a lubricant)"],
               ["reference rating life L10rh (ISO/TS 16281)", hours_text(d.get("reference_rating_life_hours"))],
               ["static safety s₀ = C₀/P₀ (ISO 76)", H.fmt(d.get("static_safety_factor"), ".3g")],
               ["stiffness axial K_xx, radial K_yy", f"{_show(kr[0, 0], 'N/m')}, {_show(kr[1, 1], 'N/m')}"],
               ["friction torque, power loss", (f"{fr['friction_torque_N_m'] * 1e3:.4g} N·mm, "
                                                f"{fr['power_loss_W']:.4g} W"
                                                " (Palmgren)") if fr is not None else "— (needs a lubricant)"]]
    warn = [human(w) for w in (d.get("warnings") or [])]
    summary.append(["warnings", "; ".join(warn) if warn else "none"])
    made = (f"Made {datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC by bearingsim {__version__} "
            f"with: {call}")
    parts.append(H.section("Summary", H.table(["", ""], summary, text_columns=(0, 1), ident="summary-table")
                           + H.paragraph(made, "made-by"), "summary"))

    # ---- operating point and data
    def row_(label, value, key=None):
        return [label, value if key is None else _value(value, key in given)]

    op = [row_("axial load Fa", _show(ld["fa_N"], "N"), "fa"),
          row_("radial load Fr (y)", _show(ld["fr_y_N"], "N"), "fr"),
          row_("radial load Fr (z)", _show(ld["fr_z_N"], "N"), "fz"),
          row_("moment My", _show(ld["m_y_N_m"], "N m"), "my"),
          row_("moment Mz", _show(ld["m_z_N_m"], "N m"), "moment"),
          row_("inner-ring speed", _show(d["speed_rad_s"], "rad/s"), "speed"),
          row_("raceway control", _CONTROL_LABELS.get(d["control"], d["control"]), "control"),
          row_("inner-ring tilt", "free (moment equilibrium)" if d["tilt"]["mode"] != "fixed" else
               "held at γy = {:.4g} mrad, γz = {:.4g} mrad".format(*(1e3 * v for v in d["tilt"]["misalignment_rad"])),
               "tilt"),
          row_("ring model", "rigid rings")]
    if lubricant is not None:
        op += [row_("lubricant", str(getattr(lubricant, "name", lubricant))),
               row_("temperature", f"{temperature - 273.15:.0f} °C", "temperature"),
               row_("lubrication method (Palmgren f₀)", _METHOD_LABELS.get(lubrication_method, lubrication_method),
                    "lubrication_method")]
    op += [row_("reliability", f"{lf.get('reliability_percent', 90):g} % (a1 = {lf.get('a1', 1):.3g}) (default)"),
           row_("contamination", f"{lf.get('contamination', 'normal')} (default)")] if lubricant is not None else \
        [row_("reliability", f"{lf.get('reliability_percent', 90):g} % (default)")]
    body = H.table(["operating point", "value"], op, text_columns=(0, 1), ident="operating-point")
    body += H.table(["row", "field", "value", "flag", "source"], [[r[0], r[1], human(r[2]), r[3], human(r[4])]
                                                                   for r in _input_rows(b)],
                    text_columns=(1, 2, 3, 4), ident="bearing-data",
                    caption=f"{d['bearing']}: data and sources (ESTIMATE: not a published value)")
    parts.append(H.section("Inputs", body, "inputs"))

    # ---- results in detail
    res_rows = [["status", f"{d['status']} (residual {d['residual_N']:.2g} N, {d['iterations']} iterations)"
                 if not d["converged"] else f"converged: residual {d['residual_N']:.2g} N after {d['iterations']} "
                                            "iterations"],
                ["axial displacement", _show(disp["axial_m"], "m", ".4g")],
                ["radial displacement", _show(disp["radial_m"], "m", ".4g")],
                ["tilt", _show(disp["tilt_rad"], "rad", ".4g")],
                *([["reaction moment (tilt held) My, Mz", ", ".join(_show(v, "N m", ".4g") for v in
                                                                    d["tilt"]["reaction_moment_N_m"])]]
                  if d["tilt"]["mode"] == "fixed" and d["tilt"].get("reaction_moment_N_m") else []),
                ["axial stiffness K_xx", _show(d["axial_stiffness_N_per_m"], "N/m", ".4g")],
                ["cage speed", _show(d.get("cage_speed_rad_s"), "rad/s", ".5g")],
                ["equivalent dynamic load P (ISO 281)", _show(d.get("equivalent_dynamic_load_N"), "N")],
                ["equivalent static load P₀ (ISO 76)", _show(d.get("equivalent_static_load_N"), "N")],
                ["static safety from p_max vs 4200 MPa", H.fmt(d.get("static_safety_factor_pressure"), ".3g")]]
    if lf.get("kappa") is not None:
        res_rows.append(["viscosity ratio κ = ν/ν₁, a_ISO", f"{lf['kappa']:.3g}, {H.fmt(lf.get('a_ISO'), '.3g')}"])
    body = H.table(["result", "value"], res_rows, text_columns=(0, 1), ident="results-table")
    xye = d.get("iso281_factors")
    if xye:
        ratio = abs(ld["fa_N"]) / math.hypot(ld["fr_y_N"], ld["fr_z_N"]) if (ld["fr_y_N"] or ld["fr_z_N"]) else math.inf
        fac = [["X", f"{xye['X']:.3g}"], ["Y", f"{xye['Y']:.3g}"], ["e", f"{xye['e']:.3g}"],
               ["Fa/Fr", ("∞" if not math.isfinite(ratio) else f"{ratio:.3g}")
                + (" > e" if ratio > xye["e"] else " ≤ e")],
               ["relative axial load f₀·Fa/C₀r", H.fmt(xye.get("relative_axial_load"), ".3g")],
               ["P = X·Fr + Y·Fa", _show(d.get("equivalent_dynamic_load_N"), "N")]]
        body += H.table(["ISO 281 factor", "value"], fac, text_columns=(0, 1), ident="iso281-factors",
                        caption="ISO 281:2007 table 3 factors used")
    else:
        body += H.paragraph("ISO 281 factors X, Y, e: none (table 3 has no answer for this bearing; see the notes).",
                            "note")
    krows = []
    # round-off below 1e-9 of the geometric mean of the two diagonal terms is shown as 0 (a symmetric load
    # leaves cross terms of 1e-13 N/µm that would read as results)
    diag = np.abs(np.diag(kr))
    for i in range(5):
        cells = [_DOF[i]]
        for j in range(5):
            small = abs(kr[i, j]) <= 1e-9 * math.sqrt(diag[i] * diag[j])
            cells.append(_show(0.0 if small else kr[i, j], _stiffness_unit(i, j), ".4g"))
        krows.append(cells)
    body += H.table(["K"] + list(_DOF), krows, text_columns=tuple(range(6)), ident="stiffness",
                    caption="stiffness matrix at the load point, each cell in its own unit "
                            "(force or moment per displacement or tilt)")
    if fr is not None:
        srcs = [[lab, f"{fr[key] * 1e3:.4g} N·mm"] for key, lab in _FRICTION_LABELS if fr.get(key) is not None]
        if fr.get("physical_torque_N_m") is not None:
            srcs.append(["physics-based total", f"{fr['physical_torque_N_m'] * 1e3:.4g} N·mm"])
        body += H.table(["friction source", "torque"], srcs, text_columns=(0, 1), ident="friction",
                        caption="friction torque per source (Palmgren's catalogue model, and the physics-based "
                                "model at the Jones ball kinematics)")
    header, brows = _per_ball(d)
    body += H.table(header, brows, ident="balls", text_columns=(11,),
                    specs=["g", "g", ".1f", ".0f", ".0f", ".2f", ".2f", ".0f", ".0f", ".0f", ".0f", None],
                    caption="per ball (angles of unloaded balls not shown)")
    notes = [human(n) for n in list(d.get("life_notes") or [])]
    if d.get("estimated"):
        notes.append("estimated inputs used by the lives and safety: " + ", ".join(human(e) for e in d["estimated"]))
    if fr is not None:
        notes += [human(n) for n in fr.get("notes") or []]
    if notes:
        body += "<div class=\"note\">" + H.bullet_list(notes) + "</div>"
    parts.append(H.section("Results", body, "results"))

    # ---- figures
    figs = _figures(res, d, out, stem)
    if map_file is not None:
        figs.append(_map_figure(Path(map_file), out, stem))
    else:
        figs.append(_speed_figure(b, loads, speed, control, tilt, misalignment, out, stem))
    parts.append(H.section("Figures", "<div class=\"figures\">" + "".join(H.figure(n, c) for n, c in figs)
                           + "</div>", "figures"))
    parts.append(H.paragraph("Quasi-static Jones–Harris equilibrium (rigid rings); lives per ISO 281:2007 and "
                             "ISO/TS 16281:2008, static safety per ISO 76:2006.", "note"))
    return H.write_page(out / "report.html", f"Bearing report — {d['bearing']}", "".join(parts))


__all__ = ["DEFAULTS", "ISO76_PRESSURE", "bearing_report", "human"]
