"""HTML report of the hub hysteresis study (:mod:`.hub_dynamic`): ``report.html`` and its PNG figures in one folder,
openable from disk (no server).

Contents: the analogues of Sakaguchi & Shibutani [S1] Figs. 6 (loops at 50 Hz, one per vehicle speed), 7 (loops at
10 km/h, one per load frequency), 8 (the definition of W_H on one of our loops) and 9 (bubble chart of W_H: ours
beside the paper's two readings :data:`~.hub_dynamic.SEED_FIG9` / :data:`~.hub_dynamic.SEED_FIG9_ALT`); the
per-cell table (W_H with its 95 % interval, loop area, phase lag, compliance against the quasi-static one, reduced
model, the mechanism's bound, the paper's values); the sensitivity of the reduced model's W_H to the creep slope and
μ_max when that model is available; the dynamic sensitivities (W_H of one cell with one input changed: creep slope,
film + solids compliance, μ_max, strips per ellipse, groove conformity) read from the folder of
:mod:`.hub_sensitivity` runs when one is given (else listed as missing); the assumptions of the case; and a plain
verdict per claim of the paper (:func:`verdicts`).

Loops are drawn twice: the tilt against the moment as the paper does (the loop is a few 10⁻⁴ of the tilt range, so
it looks like a line), and the tilt minus its straight-line fit on the moment, which opens the loop up.  The thin
line is the simulated last cycle; the thick one is the mean loop over the cycles the estimator used (least-squares
fit of harmonics 0–5 of the load frequency, the estimator's own model, for display only — W_H itself comes from the
estimator).

Verdict rules (stated in the report next to each verdict): a lag is confirmed in a cell when the 95 % interval of
W_H lies above 0; a trend along an axis holds when every step along it moves W_H the claimed way by more than the
two intervals' half-widths together (else "not resolved"); the compliance is independent of speed and frequency
when its spread over the cells is under 2 % of its mean (the paper's Figs. 6–7 lines share one slope to the eye).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..errors import BearingSimError
from ..report import html as H
from .hub_dynamic import SEED_FIG9, SEED_FIG9_ALT, HysteresisStudy

#: relative spread of the compliance over the cells under which it counts as independent of speed and frequency
COMPLIANCE_SPREAD = 0.02
#: harmonics of the display fit (the estimator's default)
N_HARMONICS = 5


# ---- display fit ---------------------------------------------------------------------------------
def mean_loop(record: dict, first_cycle: int = 0, n: int = N_HARMONICS, points: int = 400):
    """(moment [N m], tilt [rad]) of the mean loop over the cycles from ``first_cycle`` on: least-squares fit of
    harmonics 0..n of the load frequency f to each signal (y ≈ a₀ + Σ a_k cos 2πkft + b_k sin 2πkft), evaluated
    at ``points`` phases of one period.  For display only."""
    t = np.asarray(record["time"], dtype=float)
    f = float(record["frequency_hz"])
    sel = t >= t[0] + first_cycle / f - 1e-12
    tt = t[sel] - t[0]
    cols = [np.ones_like(tt)]
    for k in range(1, n + 1):
        cols += [np.cos(2 * np.pi * k * f * tt), np.sin(2 * np.pi * k * f * tt)]
    a = np.column_stack(cols)
    ph = np.linspace(0.0, 1.0 / f, points, endpoint=False)
    e = [np.ones_like(ph)]
    for k in range(1, n + 1):
        e += [np.cos(2 * np.pi * k * f * ph), np.sin(2 * np.pi * k * f * ph)]
    e = np.column_stack(e)
    out = []
    for name in ("moment", "tilt"):
        c, *_ = np.linalg.lstsq(a, np.asarray(record[name], dtype=float)[sel], rcond=None)
        out.append(e @ c)
    return out[0], out[1]


def _detrend(m, g, ref_m, ref_g):
    """Tilt minus the straight line fitted to (ref_m, ref_g) [rad]."""
    p = np.polyfit(ref_m, ref_g, 1)
    return g - np.polyval(p, m)


def _first(cell) -> int:
    return int(cell.estimate.first_cycle) if cell.estimate is not None else 0


# ---- figures -------------------------------------------------------------------------------------
def _loops_figure(cells, label, path, title):
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from .hub_dynamic import last_cycle

    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2))
    for i, c in enumerate(cells):
        col = f"C{i}"
        m, g = last_cycle(c.record)
        mm, gm = mean_loop(c.record, _first(c))
        a1.plot(m / 1e3, np.degrees(g), color=col, lw=0.6, alpha=0.6)
        a1.plot(mm / 1e3, np.degrees(gm), color=col, lw=1.6, label=label(c))
        a2.plot(m / 1e3, np.degrees(_detrend(m, g, mm, gm)) * 1e3, color=col, lw=0.5, alpha=0.5)
        a2.plot(mm / 1e3, np.degrees(_detrend(mm, gm, mm, gm)) * 1e3, color=col, lw=1.6, label=label(c))
    for a in (a1, a2):
        a.axvline(0.3, color="k", lw=0.6, ls=":")
        a.set_xlabel("moment M [kN·m]")
        a.legend(fontsize=8)
    a1.set_ylabel("inclining angle γz [deg]")
    a2.set_ylabel("γz − straight-line fit [10⁻³ deg]")
    a1.set_title(title, fontsize=10)
    a2.set_title("the same loops opened up (straight line removed)", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _definition_figure(cell, level, path):
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    mm, gm = mean_loop(cell.record, _first(cell), points=2000)
    d = np.degrees(_detrend(mm, gm, mm, gm)) * 1e3
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.plot(mm / 1e3, d, "C0", lw=1.6, label="mean loop (harmonic fit over the cycles used)")
    # the crossings of the fitted loop at M = level, rising (dM/dt > 0) and falling
    dm = np.gradient(mm)
    pts = {}
    for i in range(len(mm)):
        j = (i + 1) % len(mm)
        if (mm[i] - level) * (mm[j] - level) < 0:
            w = (level - mm[i]) / (mm[j] - mm[i])
            pts["rising" if dm[i] > 0 else "falling"] = d[i] + w * (d[j] - d[i])
    ax.axvline(level / 1e3, color="k", lw=0.6, ls=":")
    for k, mk in (("rising", "^"), ("falling", "v")):
        if k in pts:
            ax.plot([level / 1e3], [pts[k]], mk, color="C3", ms=9, label=f"P at {level / 1e3:g} kN·m, M {k}")
    if len(pts) == 2:
        ax.annotate("", xy=(level / 1e3, pts["falling"]), xytext=(level / 1e3, pts["rising"]),
                    arrowprops=dict(arrowstyle="<->", color="C3"))
        ax.text(level / 1e3 + 0.02, 0.5 * (pts["falling"] + pts["rising"]),
                f"W_H = falling − rising\n= {pts['falling'] - pts['rising']:.3f}·10⁻³ deg", color="C3", fontsize=9)
    ax.set_xlabel("moment M [kN·m]")
    ax.set_ylabel("γz − straight-line fit [10⁻³ deg]")
    ax.set_title(f"W_H on our loop: {cell.speed_kmh:g} km/h, {cell.frequency_hz:g} Hz ([S1] Fig. 8)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _bubble_figure(study, path):
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    speeds = sorted({10.0, 50.0, 100.0} | {c.speed_kmh for c in study.cells})
    freqs = sorted({1.0, 10.0, 50.0} | {c.frequency_hz for c in study.cells})
    xi = {v: i for i, v in enumerate(speeds)}
    yi = {f: i for i, f in enumerate(freqs)}
    fig, ax = plt.subplots(figsize=(7.5, 5))
    scale = 90.0  # marker area per 10⁻³ deg

    def bubbles(values, dx, color, label, hatch_negative=True):
        first = True
        for (v, f), w in values.items():
            if v not in xi or f not in yi or w is None or not np.isfinite(w):
                continue
            ax.scatter(xi[v] + dx, yi[f], s=scale * max(abs(w), 0.02), color=color if w >= 0 else "none",
                       edgecolors=color, alpha=0.6, label=label if first else None)
            ax.annotate(f"{w:.2f}" if abs(w) < 1 else f"{w:.1f}", (xi[v] + dx, yi[f]), fontsize=7,
                        ha="center", va="center")
            first = False

    ours = {(c.speed_kmh, c.frequency_hz): (math.degrees(c.wh) * 1e3 if np.isfinite(c.wh) else None)
            for c in study.cells}
    bubbles({(float(v), float(f)): w for (v, f), w in SEED_FIG9.items()}, -0.22, "C1", "[S1] Fig. 9, reading A")
    bubbles({(float(v), float(f)): w for (v, f), w in SEED_FIG9_ALT.items()}, 0.0, "C2",
            "[S1] Fig. 9, reading B")
    bubbles(ours, 0.22, "C0", "ours (hollow: negative)")
    ax.set_xticks(range(len(speeds)), [f"{v:g}" for v in speeds])
    ax.set_yticks(range(len(freqs)), [f"{f:g}" for f in freqs])
    ax.set_xlim(-0.6, len(speeds) - 0.4)
    ax.set_ylim(-0.6, len(freqs) - 0.4)
    ax.set_xlabel("vehicle speed [km/h]")
    ax.set_ylabel("load frequency [Hz]")
    ax.set_title("W_H [10⁻³ deg]: bubble area ∝ W_H ([S1] Fig. 9 analogue)", fontsize=10)
    ax.legend(fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=3, markerscale=0.4)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def _sensitivity(study, folder):
    """Reduced-model W_H against the creep slope and μ_max at one cell ((html, figure name) or None, why)."""
    if not any(c.reduced for c in study.cells):
        return None, "the reduced model was not available"
    try:
        from . import hub_reduced
        from .hub_reduced import reduced_wh
    except ImportError as exc:
        return None, f"the reduced model cannot be imported ({exc})"
    cell = _pick([c for c in study.cells if c.reduced], 10.0, 50.0)
    case = getattr(cell, "case", None)
    base = cell.reduced
    slope0 = base.get("creep_slope")  # the median film-elastic slope of the cell; varied as one uniform slope
    mu0 = base.get("mu_max", getattr(hub_reduced, "MU_MAX", None))
    if case is None or slope0 is None or mu0 is None:
        return None, "the reduced model's result does not give its creep slope and μ_max (needed to vary them)"
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    factors = np.logspace(-1, 1, 9)
    try:
        ws = [reduced_wh(case, cell.speed_kmh, cell.frequency_hz, level=study.level, creep_slope=slope0 * k)["wh"]
              for k in factors]
        wm = [reduced_wh(case, cell.speed_kmh, cell.frequency_hz, level=study.level, mu_max=mu0 * k)
              for k in factors]
    except Exception as exc:  # noqa: BLE001 - a side figure
        return None, f"the reduced model failed while varied ({type(exc).__name__}: {exc})"
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.8))
    a1.semilogx(factors * slope0, np.degrees(ws) * 1e3, "o-")
    a1.axvline(slope0, color="k", ls=":", lw=0.8)
    a1.set_xlabel("creep slope dμ/ds at s → 0, uniform [-] (dotted: median of the film law)")
    a1.set_ylabel("reduced-model W_H [10⁻³ deg]")
    a2.semilogx(factors * mu0, np.degrees([w["wh"] for w in wm]) * 1e3, "o-", label="reduced W_H")
    a2.semilogx(factors * mu0, np.degrees([w.get("bound_force", np.nan) for w in wm]) * 1e3, "s--",
                label="force bound")
    a2.axvline(mu0, color="k", ls=":", lw=0.8)
    a2.set_xlabel("μ_max [-]")
    a2.legend(fontsize=8)
    fig.suptitle(f"reduced model at {cell.speed_kmh:g} km/h, {cell.frequency_hz:g} Hz", fontsize=10)
    fig.tight_layout()
    fig.savefig(Path(folder) / "sensitivity.png", dpi=110)
    plt.close(fig)
    return "sensitivity.png", ""


def _dynamic_sensitivity(source, folder):
    """Figure and table of the dynamic sensitivity runs stored in ``source``
    (:func:`.hub_sensitivity.load_sensitivities`): per cell, W_H with its 95 % interval for every variant, beside
    the cell's base run.  Returns the HTML."""
    from .hub_sensitivity import load_sensitivities

    runs = load_sensitivities(source)
    if not runs:
        return H.paragraph(f"Dynamic sensitivities: no variant runs in {source}.", "note")
    import matplotlib

    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    cells = sorted({(r["speed_kmh"], r["frequency_hz"]) for r in runs})
    fig, axes = plt.subplots(1, len(cells), figsize=(5.2 * len(cells), 0.35 * max(len(runs), 8) + 1.2), squeeze=False)
    rows = []
    for ax, (v, f) in zip(axes[0], cells):
        mine = [r for r in runs if (r["speed_kmh"], r["frequency_hz"]) == (v, f)]
        base = next((r for r in mine if r["variant"] == "base"), None)
        wb = base["cell"].get("wh_deg") if base else None
        for i, r in enumerate(mine):
            c = r["cell"]
            w, ci = c.get("wh_deg"), c.get("wh_ci95_deg") or [None, None]
            if w is not None and None not in ci:
                ax.errorbar([w * 1e3], [i], xerr=[[(w - ci[0]) * 1e3], [(ci[1] - w) * 1e3]], fmt="o",
                            color="k" if r["variant"] == "base" else "C0", capsize=3)
            ratio = w / wb if (w is not None and wb) else None
            delta = _paired_difference(c, base["cell"]) if base is not None and r is not base else None
            rows.append([f"{v:g} km/h, {f:g} Hz", r["variant"], r["description"],
                         None if w is None else w * 1e3, f"{H.fmt(None if ci[0] is None else ci[0] * 1e3, '.3f')} … "
                         f"{H.fmt(None if ci[1] is None else ci[1] * 1e3, '.3f')}", ratio,
                         "—" if delta is None else "{:+.4f} [{:+.4f}, {:+.4f}]".format(*(x * 1e3 for x in delta)),
                         c.get("cycles_used"), c.get("phase_lag_deg"), c.get("compliance_deg_per_kNm"),
                         c.get("wall_seconds")])
        if wb is not None:
            ax.axvline(wb * 1e3, color="k", ls=":", lw=0.8)
        ax.axvline(0.0, color="0.6", lw=0.6)
        ax.set_yticks(range(len(mine)), [r["variant"] for r in mine], fontsize=8)
        ax.invert_yaxis()
        ax.set_xlabel("W_H [10⁻³ deg] (95 % interval)")
        ax.set_title(f"{v:g} km/h, {f:g} Hz", fontsize=10)
    fig.tight_layout()
    fig.savefig(Path(folder) / "sensitivity_dynamic.png", dpi=110)
    plt.close(fig)
    header = ["cell", "variant", "change", "W_H [10⁻³ deg]", "95 % interval", "÷ base",
              "− base, paired [10⁻³ deg] (95 %)", "cycles used", "phase lag [deg]", "compliance [deg/kN·m]", "wall [s]"]
    specs = [None, None, None, ".4f", None, ".3f", None, "g", ".4f", ".5f", ".0f"]
    return (H.figure("sensitivity_dynamic.png", "Dynamic W_H of one cell with one input changed (black: the case "
                     "as given; dotted: its W_H)")
            + H.table(header, rows, text_columns=(0, 1, 2), ident="sensitivity-dynamic", specs=specs)
            + H.paragraph(f"Runs read from {source} (each variant is the cell's "
                          "case with one change; the same estimator as the grid).  Paired: the mean of the per-cycle "
                          "differences variant − base over the same cycles, with its Student 95 % interval (the runs "
                          "share their start and most of their ringing, so the difference is resolved more finely "
                          "than the two intervals suggest)."))


def _paired_difference(cell, base):
    """(mean, lo, hi) [deg] of the per-cycle W_H differences cell − base over the same cycles (both cells' estimates
    start at the same cycle and use as many), else None."""
    from ..dynamics.analysis import t_interval

    a, b = cell.get("wh_cycles_deg"), base.get("wh_cycles_deg")
    if not a or not b or len(a) != len(b) or len(a) < 2 or cell.get("first_cycle") != base.get("first_cycle"):
        return None
    d = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
    lo, hi = t_interval(d)
    return float(np.mean(d)), float(lo), float(hi)


def _pick(cells, v, f):
    for c in cells:
        if c.speed_kmh == v and c.frequency_hz == f:
            return c
    return cells[0]


# ---- verdicts ------------------------------------------------------------------------------------
def _interval(c):
    if c.estimate is None:
        return None
    lo, hi = c.estimate.ci95
    return float(lo), float(hi)


def _trend(cells, key_along, key_fixed, increasing: bool):
    """Steps along one axis (at each value of the other): counts of (as claimed, against, unresolved)."""
    groups = {}
    for c in cells:
        if c.estimate is not None and np.isfinite(c.wh):
            groups.setdefault(key_fixed(c), []).append(c)
    yes = no = unresolved = 0
    steps = []
    for g in groups.values():
        g.sort(key=key_along)
        for a, b in zip(g, g[1:]):
            ia, ib = _interval(a), _interval(b)
            half = 0.5 * ((ia[1] - ia[0]) + (ib[1] - ib[0]))
            d = (b.wh - a.wh) if increasing else (a.wh - b.wh)
            if d > half:
                yes += 1
            elif d < -half:
                no += 1
            else:
                unresolved += 1
            steps.append((a, b, d))
    return yes, no, unresolved, len(steps)


def verdicts(study: HysteresisStudy) -> list[dict]:
    """One plain verdict per claim of [S1]: {claim, verdict ('confirmed' / 'not confirmed' / 'contradicted' /
    'not resolved' / 'not tested'), evidence}."""
    cells = [c for c in study.cells if c.estimate is not None and np.isfinite(c.wh)]
    out = []
    comp = [float(c.estimate.compliance) for c in cells]
    stat = [c.static_compliance for c in cells if np.isfinite(c.static_compliance)]
    if len(comp) >= 2:
        spread = (max(comp) - min(comp)) / np.mean(comp)
        ratio = [float(c.estimate.compliance) / c.static_compliance for c in cells if np.isfinite(c.static_compliance)]
        ev = (f"dynamic compliance {min(comp) * 180e3 / math.pi:.4f} … {max(comp) * 180e3 / math.pi:.4f} deg/(kN·m) "
              f"over {len(comp)} cells, spread {spread * 100:.2f} % (threshold {COMPLIANCE_SPREAD * 100:g} %)")
        if ratio:
            ev += f"; dynamic/quasi-static {min(ratio):.4f} … {max(ratio):.4f}"
        out.append({"claim": "The tilt stiffness (slope of the loops) does not depend on speed or frequency "
                             "(Figs. 6–7)", "verdict": "confirmed" if spread < COMPLIANCE_SPREAD else "not confirmed",
                    "evidence": ev})
    else:
        out.append({"claim": "The tilt stiffness does not depend on speed or frequency (Figs. 6–7)",
                    "verdict": "not tested", "evidence": f"{len(comp)} analysed cell(s); needs two or more"
                    + (f" (quasi-static compliance known for {len(stat)})" if stat else "")})
    if cells:
        lag = sum(_interval(c)[0] > 0 for c in cells)
        lead = sum(_interval(c)[1] < 0 for c in cells)
        v = "confirmed" if lag == len(cells) else ("contradicted" if lead == len(cells) else
                                                   ("not resolved" if lag == 0 and lead == 0 else "not confirmed"))
        out.append({"claim": "The tilt lags the moment (W_H > 0; § 4)", "verdict": v,
                    "evidence": f"95 % interval of W_H above 0 in {lag}, below 0 in {lead}, containing 0 in "
                                f"{len(cells) - lag - lead} of {len(cells)} cells"})
    else:
        out.append({"claim": "The tilt lags the moment (W_H > 0)", "verdict": "not tested", "evidence": "no cell"})
    for claim, along, fixed, inc in (
            ("W_H grows with the load frequency (Fig. 9)", lambda c: c.frequency_hz, lambda c: c.speed_kmh, True),
            ("W_H falls as the vehicle speed rises (Fig. 9)", lambda c: c.speed_kmh, lambda c: c.frequency_hz, False)):
        yes, no, unres, n = _trend(cells, along, fixed, increasing=inc)
        if n == 0:
            out.append({"claim": claim, "verdict": "not tested", "evidence": "no two cells along this axis"})
            continue
        v = "confirmed" if yes == n else ("contradicted" if no == n else ("not resolved" if yes == 0 and no == 0
                                                                          else "not confirmed"))
        out.append({"claim": claim, "verdict": v,
                    "evidence": f"{n} step(s): {yes} as claimed, {no} against, {unres} within the intervals"})
    seeded = [c for c in cells if np.isfinite(c.seed())]
    if seeded:
        r1 = [c.wh / c.seed() for c in seeded]
        r2 = [c.wh / c.seed(SEED_FIG9_ALT) for c in seeded]
        bounded = [c for c in seeded if np.isfinite(c.bound())]
        over = [c for c in bounded if min(c.seed(), c.seed(SEED_FIG9_ALT)) > c.bound()]
        ev = (f"ours / [S1] = {min(r1):.3g} … {max(r1):.3g} (reading A), {min(r2):.3g} … {max(r2):.3g} "
              f"(reading B) over {len(seeded)} cells")
        if bounded:
            ev += (f"; the paper's value exceeds the mechanism's bound (smaller of force and energy bounds) under "
                   f"both readings in {len(over)} of {len(bounded)} cells")
        else:
            ev += "; the mechanism's bounds were not available"
        v = "confirmed" if all(0.5 <= r <= 2 for r in r1) else "not confirmed"
        out.append({"claim": "Magnitudes of W_H: 0.3–6.7·10⁻³ deg (Fig. 9)", "verdict": v, "evidence": ev})
    else:
        out.append({"claim": "Magnitudes of W_H (Fig. 9)", "verdict": "not tested",
                    "evidence": "no analysed cell at a (speed, frequency) pair of the paper"})
    return out


# ---- the page ------------------------------------------------------------------------------------
def _assumptions(study) -> list[str]:
    from ..io import read_toml
    from .hub_static import TYRE_RADIUS

    items = []
    try:
        d = read_toml(Path(study.case), "case")
    except Exception as exc:  # noqa: BLE001 - the report still shows the results
        return [f"case file {study.case} cannot be read again ({exc})"]
    ring = d.get("inner_ring", {})
    items.append(f"hub inertia (case file [inner_ring], assumed: the paper gives none): mass {ring.get('mass', '?')}, "
                 f"transverse inertia {ring.get('transverse_inertia', '?')}, polar {ring.get('polar_inertia', '?')}")
    items.append(f"bearing {d.get('bearing')}: ball and groove data in the catalogue file (groove curvatures "
                 "assumed there: the paper gives none)")
    try:
        from ..io import load_bearing

        b = load_bearing(d.get("bearing"))
        r0 = b.rows[0].bearing  # the rows protocol (bearingsim.geometry)
        items.append(f"groove curvature ratios f_i = {r0.inner_conformity:.4f}, f_o = {r0.outer_conformity:.4f}")
    except BearingSimError as exc:  # the report still shows the results, and says why this line is missing
        items.append(f"groove curvature ratios: the case's bearing cannot be read again ({exc})")
    items.append("load path: Fa, Fr and M in phase, Fa = 1890 N · M/600 N·m, Fr = 2785 N + 965 N · M/600 N·m "
                 "([S1] Table 2 ranges; the tie is our assumption)")
    items.append(f"tyre rolling radius {TYRE_RADIUS * 1e3:.1f} mm (M_max/Fa_max; assumed), which turns the vehicle "
                 "speed into the shaft speed")
    items.append(f"lubricant {d.get('lubricant')} at {d.get('temperature')}; traction "
                 f"{study.traction or d.get('traction', 'slices')} with {d.get('n_slices', 8)} slices per contact; "
                 f"contact damping {d.get('contact_damping', 'default')}")
    items.append(f"each cell: {study.startup} start-up + {study.cycles} load cycles; W_H read at "
                 f"{study.level / 1e3:g} kN·m")
    return items


def write_report(study: HysteresisStudy, folder, sensitivity=None) -> Path:
    """Write ``folder/report.html`` and its figures (PNG) beside it; returns the page's path.  ``sensitivity``: the
    folder of dynamic sensitivity runs (:mod:`.hub_sensitivity`) to show, or None."""
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    body = []
    body.append(H.paragraph(
        f"Case {study.case}; {len(study.cells)} cell(s); W_H is the tilt where the moment passes "
        f"{study.level / 1e3:g} kN·m falling minus rising ([S1] Fig. 8), from a harmonic fit per load cycle "
        "(the estimator's harmonic fit); positive = the tilt lags the moment.  Wall time of the "
        f"cells run now: {H.fmt(study.wall_seconds, '.0f')} s."))
    if study.notes:
        body.append(H.section("Notes", H.bullet_list(study.notes), "notes"))
    # verdicts
    rows = []
    for v in verdicts(study):
        rows.append([v["claim"], v["verdict"], v["evidence"]])
    body.append(H.section("Verdict per claim of the paper", H.table(
        ["claim of [S1]", "verdict", "evidence"], rows, text_columns=(0, 1, 2), ident="verdicts") + H.paragraph(
        "Rules: a lag is confirmed where the 95 % interval of W_H lies above 0; a trend step counts when W_H moves "
        "by more than the two intervals' half-widths together; the compliance is speed- and frequency-independent "
        f"when its spread is under {COMPLIANCE_SPREAD * 100:g} % of its mean; magnitudes are confirmed only within "
        "a factor 2 of the paper (reading A of its Fig. 9)."), "verdicts-section"))
    # figures
    figs = []
    # [S1] Figs. 6 and 7: the loops at 50 Hz per vehicle speed, and at 10 km/h per load frequency
    for pick, order, label, name, title, caption, none in (
            (lambda c: c.frequency_hz == 50.0, lambda c: c.speed_kmh, lambda c: f"{c.speed_kmh:g} km/h",
             "fig6_loops_50Hz.png", "loops at 50 Hz, one per vehicle speed ([S1] Fig. 6)",
             "[S1] Fig. 6 analogue: tilt against moment at 50 Hz for each vehicle speed (thin: last simulated "
             "cycle; thick: mean loop of the cycles used)", "[S1] Fig. 6 analogue: no analysed cell at 50 Hz."),
            (lambda c: c.speed_kmh == 10.0, lambda c: c.frequency_hz, lambda c: f"{c.frequency_hz:g} Hz",
             "fig7_loops_10kmh.png", "loops at 10 km/h, one per load frequency ([S1] Fig. 7)",
             "[S1] Fig. 7 analogue: tilt against moment at 10 km/h for each load frequency",
             "[S1] Fig. 7 analogue: no analysed cell at 10 km/h.")):
        cells = sorted((c for c in study.cells if pick(c) and c.estimate is not None), key=order)
        if cells:
            _loops_figure(cells, label, folder / name, title)
            figs.append(H.figure(name, caption))
        else:
            figs.append(H.paragraph(none, "note"))
    analysed = [c for c in study.cells if c.estimate is not None]
    if analysed:
        c8 = _pick(analysed, 10.0, 50.0)
        _definition_figure(c8, study.level, folder / "fig8_wh_definition.png")
        figs.append(H.figure("fig8_wh_definition.png", "[S1] Fig. 8 analogue: W_H read on our mean loop at "
                             f"{c8.speed_kmh:g} km/h, {c8.frequency_hz:g} Hz"))
    _bubble_figure(study, folder / "fig9_bubbles.png")
    figs.append(H.figure("fig9_bubbles.png", "[S1] Fig. 9 analogue: W_H per (speed, frequency), ours beside the "
                         "paper's two readings"))
    body.append(H.section("Figures", "".join(figs), "figures"))
    # table
    header = ["km/h", "Hz", "cycles used", "W_H [10⁻³ deg]", "95 % interval", "two-point mean", "loop area [mJ]",
              "phase lag [deg]", "compliance [deg/kN·m]", "quasi-static", "reduced W_H (film κ)",
              "reduced W_H (spin-softened κ)", "bound", "[S1] reading A", "[S1] reading B", "wall [s]"]
    trows = []
    for r in study.rows():
        trows.append([r["speed_kmh"], r["frequency_hz"], r["cycles_used"], r["W_H_mdeg"],
                      f"{H.fmt(r['W_H_ci95_lo_mdeg'], '.3f')} … {H.fmt(r['W_H_ci95_hi_mdeg'], '.3f')}",
                      r["two_point_mean_mdeg"], r["loop_area_mJ"], r["phase_lag_deg"], r["compliance_deg_per_kNm"],
                      r["static_compliance_deg_per_kNm"], r["reduced_W_H_mdeg"], r.get("reduced_kernel_W_H_mdeg"),
                      r["bound_W_H_mdeg"],
                      r["seed_fig9_mdeg"], r["seed_fig9_alt_mdeg"], r["wall_s"]])
    specs = ["g", "g", "g", ".3f", None, ".3f", ".4f", ".4f", ".5f", ".5f", ".3f", ".3f", ".3f", ".1f", ".1f", ".0f"]
    body.append(H.section("Cells", H.table(header, trows, ident="cells", specs=specs) + H.paragraph(
        "Reduced W_H: the quasi-static model of the paper's mechanism with the film-elastic "
        "creep slope, and with the spin-softened slope measured on the case's own traction kernel "
        "(the ball's spin saturates the traction, so a small transverse slip turns "
        "it); bound: the smaller "
        "of the mechanism's force and energy upper bounds; [S1] reading A, B: the two readings of the paper's Fig. 9 "
        "(reading A and reading B, the two placements of its printed labels that keep its stated trends).  "
        "Two-point mean: the raw reading at two instants per cycle (diagnostic only)."),
        "cells-section"))
    # sensitivity
    fig, why = _sensitivity(study, folder)
    sens = []
    if fig:
        sens.append(H.figure(fig, "Reduced-model W_H against the creep slope (left) and μ_max (right)"))
    else:
        sens.append(H.paragraph(f"Sensitivity to the creep slope and μ_max: not shown — {why}.", "note"))
    if sensitivity is None:
        sens.append(H.paragraph("Sensitivity of the dynamic W_H to the creep slope, μ_max, the slice count and the "
                                "groove conformity: not run for this report (the sensitivity runs are shown with "
                                "--sensitivity DIR).", "note"))
    else:
        sens.append(_dynamic_sensitivity(sensitivity, folder))
    body.append(H.section("Sensitivity", "".join(sens), "sensitivity"))
    body.append(H.section("Assumptions", H.bullet_list(_assumptions(study)), "assumptions"))
    return H.write_page(folder / "report.html", "Hub bearing: tilt–moment hysteresis ([S1] Figs. 6–9)",
                        "".join(body))


__all__ = ["COMPLIANCE_SPREAD", "mean_loop", "verdicts", "write_report"]
