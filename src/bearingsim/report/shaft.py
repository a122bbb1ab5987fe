"""The shaft-system report: one equilibrium of a shaft on its bearings on one page (``DIR/report.html``, figures
beside it as PNG, like :mod:`bearingsim.report.bearing`).

* the shaft drawn to scale (sections as outlines, bores dashed) with its supports, loads and masses;
* the deflection line (radial y, z [µm] and slopes [mrad] along x);
* the supports' reactions and the bearings' lives as a table (trade units) and as bars (L10h, L10rh);
* the stiffness at the tool tip (or the file's ``stiffness_at``) against speed (:func:`bearingsim.shafts.sweep.
  shaft_sweep`, 0 to 1.5 × the operating speed) — :func:`plot_sweep` also draws ``bearingsim shaft --speeds --plot``;
* the first mode shapes on the linearised bearings (:func:`bearingsim.shafts.modes.modes`).

Numbers come from the result's ``to_dict`` (SI) and are converted for display only.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..life import hours_text
from ..shafts import BearingSupport, DistributedLoad, Gravity
from ..shafts.modes import modes
from ..shafts.sweep import shaft_sweep
from . import html as H

#: speeds of the report's stiffness-against-speed figure, as fractions of the operating speed
SWEEP_FRACTIONS = np.linspace(0.0, 1.5, 7)
#: the report's mode shapes
REPORT_MODES = 4


def max_pressure(bearing_dict: dict) -> float:
    """The largest contact pressure of a bearing result's ``balls`` (the list of ``static --json``) [Pa]."""
    return max((max(b.get("inner_max_pressure_Pa") or 0.0, b.get("outer_max_pressure_Pa") or 0.0)
                for b in bearing_dict.get("balls") or ()), default=0.0)


def _plt():
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    return plt


def _save(fig, path: Path, caption: str) -> tuple[str, str]:
    plt = _plt()
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path.name, caption


def _draw_shaft(ax, system) -> None:
    """The shaft's outline to scale [mm] (outer diameter solid, bore dashed), centre line dotted."""
    ends = system.section_ends * 1e3
    for k, s in enumerate(system.sections):
        x0, x1 = ends[k], ends[k + 1]
        ro, ri = 0.5e3 * s.outer_diameter, 0.5e3 * s.inner_diameter
        ax.fill_between([x0, x1], [-ro, -ro], [ro, ro], color="#c9d1d9", lw=0)
        ax.plot([x0, x1, x1, x0, x0], [-ro, -ro, ro, ro, -ro], color="#57606a", lw=1)
        if ri > 0:
            ax.plot([x0, x1], [ri, ri], "--", color="#57606a", lw=0.7)
            ax.plot([x0, x1], [-ri, -ri], "--", color="#57606a", lw=0.7)
    ax.axhline(0.0, color="k", lw=0.5, ls=":")


def _radius_at(system, x: float) -> float:
    """Outer radius of the section at ``x`` [m] → [mm]."""
    ends = system.section_ends
    k = int(np.clip(np.searchsorted(ends, x, side="right") - 1, 0, len(system.sections) - 1))
    return 0.5e3 * system.sections[k].outer_diameter


def _layout_figure(sf, out: Path):

    plt = _plt()
    system = sf.system
    fig, ax = plt.subplots(figsize=(10, 3.6))
    _draw_shaft(ax, system)
    rmax = max(0.5e3 * s.outer_diameter for s in system.sections)
    for s in system.supports:
        x = s.position * 1e3
        r = _radius_at(system, s.position)
        bearing = isinstance(s, BearingSupport)
        rows = s.bearing.rows if bearing else ()
        if rows:
            for row in rows:
                xr = x + row.position * 1e3 - getattr(s.bearing, "load_point", 0.0) * 1e3
                for sign in (1, -1):
                    ax.add_patch(plt.Circle((xr, sign * (r + 4)), 3.5, fill=False, color="#0969da", lw=1.3))
        else:
            for sign in (1, -1):
                ax.plot([x - 4, x + 4, x, x - 4], [sign * (r + 10), sign * (r + 10), sign * r, sign * (r + 10)],
                        color="#8250df", lw=1.3)
        ax.annotate(s.name, (x, -(r + 14)), ha="center", va="top", fontsize=8, color="#0969da" if bearing
                    else "#8250df")
    for ld in system.loads:
        if isinstance(ld, Gravity) or getattr(ld, "name", "") == "stiffness_at":
            continue
        if isinstance(ld, DistributedLoad):
            ax.axvspan(ld.start * 1e3, ld.end * 1e3, color="#fb8500", alpha=0.15)
            continue
        x = ld.position * 1e3
        v = ld.vector()
        r = _radius_at(system, ld.position)
        ax.annotate("", xy=(x, r), xytext=(x, r + 0.6 * rmax), arrowprops={"arrowstyle": "->", "color": "#cf222e"})
        fx, fy, fz = v[:3]
        ax.annotate(f"{ld.name}\nF = ({fx:.0f}, {fy:.0f}, {fz:.0f}) N", (x, r + 0.62 * rmax), ha="center",
                    va="bottom", fontsize=7, color="#cf222e")
    for m in system.masses:
        ax.plot([m.position * 1e3], [0.0], "s", color="#1a7f37", ms=6)
        ax.annotate(f"{m.name} {m.mass:.3g} kg", (m.position * 1e3, 2.0), fontsize=7, color="#1a7f37")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("axial position x [mm]")
    ax.set_ylabel("radius [mm]")
    return _save(fig, out / "shaft_layout.png",
                 "The shaft to scale: sections (bores dashed), bearings (circles: one per row of balls), springs "
                 "(triangles), loads (arrows, force components in N) and point masses (squares)")


def _deflection_figure(res, out: Path):
    plt = _plt()
    x = res.nodes * 1e3
    u = res.displacement
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(10, 5.2), sharex=True)
    a1.plot(x, u[:, 1] * 1e6, "o-", ms=2.5, label="δy")
    a1.plot(x, u[:, 2] * 1e6, "s-", ms=2.5, label="δz")
    a1.plot(x, u[:, 0] * 1e6, ":", label="δx (axial)")
    a2.plot(x, u[:, 4] * 1e3, "o-", ms=2.5, label="γz = dy/dx")
    a2.plot(x, u[:, 3] * 1e3, "s-", ms=2.5, label="γy = −dz/dx")
    for s in res.supports:
        for ax in (a1, a2):
            ax.axvline(s.position * 1e3, color="#0969da", lw=0.8, ls="--")
    a1.set_ylabel("deflection [µm]")
    a2.set_ylabel("slope [mrad]")
    a2.set_xlabel("axial position x [mm]")
    a1.legend(fontsize=7)
    a2.legend(fontsize=7)
    return _save(fig, out / "shaft_deflection.png",
                 "Deflection line of the shaft at the equilibrium: translations [µm] and slopes [mrad] along x; "
                 "dashed: the supports")


def _lives_figure(rows: list, out: Path):
    plt = _plt()
    names = [r[0] for r in rows]
    fig, ax = plt.subplots(figsize=(7, 0.6 * len(names) + 1.6))
    y = np.arange(len(names))
    for off, key, lab in ((-0.18, 1, "L10h (ISO 281)"), (0.18, 2, "L10rh (ISO/TS 16281)")):
        vals = [r[key] if r[key] is not None else np.nan for r in rows]
        ax.barh(y + off, vals, height=0.34, label=lab)
    ax.set_yticks(y, names)
    ax.set_xscale("log")
    ax.set_xlabel("rating life [h]")
    ax.legend(fontsize=7)
    return _save(fig, out / "shaft_lives.png", "Rating lives of the bearings (log scale; a missing bar: not "
                 "rated, see the notes)")


def plot_sweep(ds, path) -> None:
    """Radial, axial and tilt stiffness at the sweep's node against speed (a :func:`bearingsim.shafts.sweep.
    shaft_sweep` dataset; a line per preload when it has a preload axis) → figure file ``path`` [N/µm, N·m/mrad
    against rpm]."""
    plt = _plt()
    rpm = ds["speed"].values * 30.0 / math.pi
    if "preload" in ds.dims:
        force = ds["preload"].attrs.get("units") == "N"
        lines = [(ds.isel(preload=i), f"{p:.4g} N" if force else f"{p * 1e6:.4g} µm")
                 for i, p in enumerate(ds["preload"].values)]
    else:
        lines = [(ds, None)]
    fig, axs = plt.subplots(1, 3, figsize=(11, 3.4))
    for ax, (key, f, lab) in zip(axs, (("radial_stiffness", 1e-6, "radial [N/µm]"),
                                       ("axial_stiffness", 1e-6, "axial [N/µm]"),
                                       ("tilt_stiffness", 1e-3, "tilt [N·m/mrad]")), strict=True):
        for sub, label in lines:
            ax.plot(rpm, sub[key].values * f, "o-", ms=3, label=label)
        if len(lines) > 1:
            ax.legend(fontsize=7, title=f"preload {ds.attrs.get('preload_support', '')}", title_fontsize=7)
        ax.set_xlabel("speed [rpm]")
        ax.set_ylabel(lab)
        ax.grid(alpha=0.3)
    fig.suptitle(f"stiffness at x = {ds.attrs.get('position_m', float('nan')) * 1e3:.4g} mm against speed",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _modes_figure(modal, out: Path):
    plt = _plt()
    x = modal.nodes * 1e3
    fig, ax = plt.subplots(figsize=(10, 3.8))
    for k, (f, sh) in enumerate(zip(modal.frequency_hz, modal.shapes, strict=True)):
        tr = sh[:, :3]
        j = int(np.argmax(np.max(np.abs(tr), axis=0)))
        ax.plot(x, tr[:, j], "o-", ms=2, label=f"mode {k + 1}: {f:.4g} Hz ({'xyz'[j]})")
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("axial position x [mm]")
    ax.set_ylabel("shape (largest translation 1)")
    ax.legend(fontsize=7)
    return _save(fig, out / "shaft_modes.png", "First mode shapes on the bearings linearised at the equilibrium "
                 "(each in the direction of its largest translation)")


def shaft_report(sf, res, out_dir, sweep=True, n_modes: int = REPORT_MODES) -> Path:
    """Write ``out_dir/report.html`` and its figures for the equilibrium ``res`` of the shaft file ``sf``
    (:class:`bearingsim.io.shaft_system.ShaftFile`); ``sweep``: add the stiffness at the tool tip against speed
    (:data:`SWEEP_FRACTIONS` of the operating speed; needs a tool tip or ``stiffness_at``); returns the page."""

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    d = res.to_dict(stiffness_at=sf.stiffness_at)
    parts = []
    system = sf.system
    op = [["file", str(sf.path or "")], ["speed", f"{res.speed * 30 / math.pi:.0f} rpm"],
          ["status", f"{d['status']} (residual {d['residual']:.2g} N, {d['iterations']} iterations)"],
          ["shaft", f"{len(system.sections)} sections, {system.span[0] * 1e3:.4g} … {system.span[1] * 1e3:.4g} mm, "
                    f"{len(res.nodes) - 1} {'Timoshenko' if system.shear else 'Euler–Bernoulli'} elements"]]
    if sf.description:
        op.insert(0, ["description", sf.description])
    secs = [[k, f"{s.length * 1e3:.4g}", f"{s.outer_diameter * 1e3:.4g}", f"{s.inner_diameter * 1e3:.4g}",
             s.material.name] for k, s in enumerate(system.sections)]
    body = H.table(["", "value"], op, text_columns=(0, 1))
    body += H.table(["section", "length mm", "outer diameter mm", "bore mm", "material"], secs, text_columns=(4,))
    parts.append(H.section("System", body, "system"))

    figs = [_layout_figure(sf, out), _deflection_figure(res, out)]
    if "stiffness_at" in d:
        s = d["stiffness_at"]
        k = [["radial (y)", f"{s['radial_N_per_m'] * 1e-6:.4g} N/µm"],
             ["radial (z)", f"{s['radial_z_N_per_m'] * 1e-6:.4g} N/µm"],
             ["axial", f"{s['axial_N_per_m'] * 1e-6:.4g} N/µm"],
             ["tilt", f"{s['tilt_N_m_per_rad'] * 1e-3:.4g} N·m/mrad"]]
        parts.append(H.section(f"Stiffness at x = {s['position_m'] * 1e3:.4g} mm",
                               H.table(["direction", "stiffness (force over displacement there, all else free)"], k,
                                       text_columns=(0, 1)), "stiffness"))
    rows, lives = [], []
    notes = list(d.get("warnings") or [])
    for sup in d["supports"]:
        f = sup["reaction"]
        tilt = math.hypot(*sup["misalignment_rad"]) * 1e3
        if sup["kind"] == "bearing":
            pm = max_pressure(sup)
            l10, l10r = sup.get("basic_rating_life_hours"), sup.get("reference_rating_life_hours")
            rows.append([sup["name"], sup["bearing"], f"{sup['position_m'] * 1e3:.4g}", *(f"{v:.4g}" for v in f),
                         f"{tilt:.4g}", hours_text(l10), hours_text(l10r), H.fmt(sup.get("static_safety_factor")),
                         f"{pm * 1e-6:.0f}"])
            lives.append((sup["name"], l10, l10r))
            notes += [f"{sup['name']}: {n}" for n in sup.get("life_notes") or ()]
        else:
            rows.append([sup["name"], "spring", f"{sup['position_m'] * 1e3:.4g}", *(f"{v:.4g}" for v in f),
                         f"{tilt:.4g}", "", "", "", ""])
    body = H.table(["support", "bearing", "x mm", "Fx N", "Fy N", "Fz N", "My N·m", "Mz N·m", "tilt mrad", "L10h",
                    "L10rh", "s₀", "p_max MPa"], rows, text_columns=(0, 1),
                   caption="reactions of the supports on the shaft, the shaft's misalignment in each, lives")
    if notes:
        body += "<div class=\"note\">" + H.bullet_list(notes) + "</div>"
    parts.append(H.section("Supports and bearings", body, "supports"))
    if any(v is not None for _, a, b in lives for v in (a, b)):
        figs.append(_lives_figure(lives, out))
    if sweep and sf.stiffness_at is not None and res.speed != 0.0:

        ds = shaft_sweep(system, SWEEP_FRACTIONS * abs(res.speed), sf.stiffness_at, lives=False)
        plot_sweep(ds, out / "shaft_stiffness_speed.png")
        figs.append(("shaft_stiffness_speed.png", "Stiffness at the tool tip against speed (0 to 1.5 × the "
                     "operating speed; bearings softened by centrifugal force and gyroscopic moment)"))
    modal = modes(res, n_modes)
    figs.append(_modes_figure(modal, out))
    parts.append(H.section("Figures", "".join(H.figure(n, c) for n, c in figs), "figures"))
    parts.append(H.paragraph("Shaft of Timoshenko beam elements on full Jones–Harris bearings (each bearing's 5×5 "
                             "response at the shaft speed) by bearingsim; lives per ISO 281:2007 and ISO/TS "
                             "16281:2008; every number in SI in `bearingsim shaft FILE --json`.", "note"))
    return H.write_page(out / "report.html", f"Shaft report — {system.name}", "".join(parts))


__all__ = ["REPORT_MODES", "SWEEP_FRACTIONS", "max_pressure", "plot_sweep", "shaft_report"]
