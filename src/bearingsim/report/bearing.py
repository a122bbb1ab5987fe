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

    # 1 load distribution per row, polar
    nrow = int(rows.max()) + 1 if len(rows) else 1
    fig, axs = plt.subplots(1, nrow, subplot_kw={"projection": "polar"}, figsize=(4.2 * nrow, 4.2), squeeze=False)
    for r in range(nrow):
        ax = axs[0, r]
        m = rows == r
        order = np.argsort(psi[m])
        for key, lab in (("inner_load_N", "inner"), ("outer_load_N", "outer")):
            q = np.asarray(balls[key], dtype=float)[m][order]
            ax.plot(np.append(psi[m][order], psi[m][order][:1]), np.append(q, q[:1]), "o-", ms=3, label=lab)
        ax.set_title(f"row {r}: ball load Q [N]", fontsize=10)
        ax.legend(fontsize=7, loc="lower right")
    figs.append(_save(fig, out / f"{stem}_load_distribution.png",
                      "Ball load Q(ψ) per row (inner and outer contact) [N]; ψ = 0 along +y"))

    # 2 contact angles and 3 pressure vs azimuth
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.8))
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
    a1.legend(fontsize=7)
    a2.axhline(ISO76_PRESSURE * 1e-6, color="k", lw=1, ls=":", label="ISO 76 reference 4200 MPa")
    a2.set_xlabel("azimuth ψ [deg]")
    a2.set_ylabel("maximum contact pressure [MPa]")
    a2.legend(fontsize=7)
    figs.append(_save(fig, out / f"{stem}_angles_pressure.png",
                      "Contact angles and maximum contact pressure against the azimuth; dotted: the 4200 MPa "
                      "reference of ISO 76 (the pressure behind the static load rating C₀)"))

    # 4 contact ellipse on the groove: the angular extent α ± a/(f D) of the most loaded ball's ellipse
    fig, ax = plt.subplots(figsize=(5.5, 3.8))
    for r, row in enumerate(res.bearing.rows):
        b = row.bearing
        m = rows == r
        for inner, name_, f in ((True, "inner", b.inner_conformity), (False, "outer", b.outer_conformity)):
            q = np.asarray(balls[f"{name_}_load_N"], dtype=float)[m]
            alpha = np.asarray(balls[f"{name_}_contact_angle_rad"], dtype=float)[m]
            o = np.argsort(psi[m])
            half = np.zeros_like(q)
            for j in range(len(q)):
                if q[j] > 0:
                    half[j] = b.contact(float(q[j]), inner, float(alpha[j])).a / (f * b.ball_diameter)
            deg = np.degrees(psi[m][o])
            lo, hi = np.degrees(alpha[o] - half[o]), np.degrees(alpha[o] + half[o])
            ax.fill_between(deg, lo, hi, alpha=0.3, step=None, label=f"row {r} {name_}: α ± a/(f D)")
    ax.set_xlabel("azimuth ψ [deg]")
    ax.set_ylabel("groove angle covered by the ellipse [deg]")
    ax.legend(fontsize=7)
    figs.append(_save(fig, out / f"{stem}_ellipse.png",
                      "Angular extent of the contact ellipse on the groove (centre α, half-width a/(f·D)); the "
                      "shoulder angle is not part of the bearing file, so truncation cannot be judged here — "
                      "compare the upper edge with the groove's shoulder angle from the drawing"))
    return figs


def _check_map_bearing(map_file: Path, bearing) -> None:
    """An :class:`InputError` when the map file was made for another bearing (its ``bearing`` attribute, written by
    :func:`bearingsim.sweep.map_grid`): the report had drawn another bearing's stiffness under this one's name.
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
        fig, axs = plt.subplots(1, 2, figsize=(10, 3.8))
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
                ax.legend(fontsize=7)
            else:
                ax.plot(ds["speed"].values * sf, k.values * kf, "o-", ms=3)
            ax.set_xlabel(f"speed [{su}]")
            ax.set_ylabel(f"{lab} [{ku}]")
        return _save(fig, out / f"{stem}_map_stiffness.png",
                     f"Stiffness against speed per load, from {Path(map_file).name}")
    finally:
        ds.close()


def bearing_report(bearing, loads, speed: float = 0.0, *, out_dir, lubricant=None, temperature: float | None = None,
                   control: str = "outer", map_file=None, lubrication_method: str = "oil_bath",
                   tilt: str = "free", misalignment=None) -> Path:
    """Write ``out_dir/report.html`` and its figures for one operating point; return the page's path.

    bearing : BallBearing or BearingSystem (or a catalogue name / TOML path); loads : ``Loads`` [N, N m];
    speed [rad/s]; lubricant (name, path or Lubricant) and temperature [K] for the friction torque;
    map_file : a map netCDF file for the stiffness-vs-speed figure (optional); tilt, misalignment : the tilt control
    of :func:`bearingsim.statics.jones_harris.solve` ("free", or "fixed" at (γy, γz) [rad], reaction moment shown).
    """
    from ..io import load_bearing
    from ..statics.jones_harris import solve

    b = load_bearing(bearing)
    if map_file is not None:
        _check_map_bearing(Path(map_file), b)
    out = Path(out_dir)
    if lubricant is not None and temperature is None:
        raise InputError("temperature", "a lubricant needs its operating temperature", 'e.g. --temperature "60 degC"')
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

    # ---- inputs
    ld = d["loads"]
    op = [["axial load Fa", _show(ld["fa_N"], "N")], ["radial load Fr (y)", _show(ld["fr_y_N"], "N")],
          ["radial load Fr (z)", _show(ld["fr_z_N"], "N")], ["moment My", _show(ld["m_y_N_m"], "N m")],
          ["moment Mz", _show(ld["m_z_N_m"], "N m")], ["inner-ring speed", _show(d["speed_rad_s"], "rad/s")],
          ["raceway control", d["control"]]]
    if d["tilt"]["mode"] == "fixed":
        op.append(["inner-ring tilt", "held at γy = {:.4g} mrad, γz = {:.4g} mrad".format(
            *(1e3 * v for v in d["tilt"]["misalignment_rad"]))])
    if lubricant is not None:
        op += [["lubricant", str(getattr(lubricant, "name", lubricant))],
               ["temperature", f"{temperature - 273.15:.1f} °C"]]
    body = H.table(["operating point", "value"], op, text_columns=(0, 1))
    body += H.table(["row", "field", "value", "flag", "source"], _input_rows(b), text_columns=(1, 2, 3, 4),
                    caption=f"{d['bearing']}: data and sources (ESTIMATE: not a published value)")
    parts.append(H.section("Inputs", body, "inputs"))

    # ---- results
    disp = d["displacement"]
    summary = [["status", f"{d['status']} (residual {d['residual_N']:.2g} N, {d['iterations']} iterations)"],
               ["axial displacement", _show(disp["axial_m"], "m", ".4g")],
               ["radial displacement", _show(disp["radial_m"], "m", ".4g")],
               ["tilt", _show(disp["tilt_rad"], "rad", ".4g")],
               *([["reaction moment (tilt held) My, Mz", ", ".join(_show(v, "N m", ".4g") for v in
                                                                   d["tilt"]["reaction_moment_N_m"])]]
                 if d["tilt"]["mode"] == "fixed" and d["tilt"].get("reaction_moment_N_m") else []),
               ["axial stiffness K_xx", _show(d["axial_stiffness_N_per_m"], "N/m", ".4g")],
               ["cage speed", _show(d.get("cage_speed_rad_s"), "rad/s", ".5g")],
               ["basic rating life L10h (ISO 281)", hours_text(d.get("basic_rating_life_hours"))],
               ["modified rating life L_nmh (ISO 281)", hours_text(d.get("modified_rating_life_hours"))],
               ["reference rating life L10rh (ISO/TS 16281)", hours_text(d.get("reference_rating_life_hours"))],
               ["static safety s₀ = C₀/P₀ (ISO 76)", H.fmt(d.get("static_safety_factor"), ".3g")],
               ["static safety from p_max vs 4200 MPa", H.fmt(d.get("static_safety_factor_pressure"), ".3g")]]
    if fr is not None:
        summary += [["friction torque", f"{fr['friction_torque_N_m'] * 1e3:.4g} N·mm ({fr.get('headline_model')})"],
                    ["power loss", f"{fr['power_loss_W']:.4g} W"]]
    notes = list(d.get("warnings") or []) + list(d.get("life_notes") or [])
    if d.get("estimated"):
        notes.append("estimated inputs used by the lives and safety: " + ", ".join(d["estimated"]))
    body = H.table(["result", "value"], summary, text_columns=(0, 1))
    k = np.asarray(d["stiffness_matrix"], dtype=float)
    krows = []
    # round-off below 1e-9 of the geometric mean of the two diagonal terms is shown as 0 (a symmetric load
    # leaves cross terms of 1e-13 N/µm that would read as results)
    diag = np.abs(np.diag(k))
    for i in range(5):
        cells = [_DOF[i]]
        for j in range(5):
            small = abs(k[i, j]) <= 1e-9 * math.sqrt(diag[i] * diag[j])
            cells.append(_show(0.0 if small else k[i, j], _stiffness_unit(i, j), ".4g"))
        krows.append(cells)
    body += H.table(["K"] + list(_DOF), krows, text_columns=tuple(range(6)),
                    caption="stiffness matrix at the load point, each cell in its own unit "
                            "(force or moment per displacement or tilt)")
    if fr is not None:
        srcs = [[key.replace("_N_m", ""), f"{fr[key] * 1e3:.4g} N·mm"] for key in
                ("palmgren_load_N_m", "palmgren_viscous_N_m", "rolling_N_m", "spin_N_m", "sliding_N_m", "drag_N_m")
                if fr.get(key) is not None]
        body += H.table(["friction source", "torque"], srcs, text_columns=(0, 1),
                        caption="friction torque per source (Palmgren; physics-based at Jones kinematics)")
    if notes:
        body += "<div class=\"note\">" + H.bullet_list(notes) + "</div>"
    parts.append(H.section("Results", body, "results"))

    # ---- figures
    figs = _figures(res, d, out, stem)
    if map_file is not None:
        figs.append(_map_figure(Path(map_file), out, stem))
    parts.append(H.section("Figures", "".join(H.figure(n, c) for n, c in figs), "figures"))
    parts.append(H.paragraph("Quasi-static Jones–Harris equilibrium (rigid rings) by bearingsim; lives per "
                             "ISO 281:2007 and ISO/TS 16281:2008, static safety per ISO 76:2006; all numbers "
                             "stored in SI in the JSON of `bearingsim static --json`.", "note"))
    return H.write_page(out / "report.html", f"Bearing report — {d['bearing']}", "".join(parts))


__all__ = ["ISO76_PRESSURE", "bearing_report"]
