"""[S0] study: axial stiffness of the SKF 7011 CDGA/HC spindle bearing vs load and speed.

Reproduces tables T1–T3 and Fig. 5 of [S0] with our models:
* "without inertia": the thrust model of :mod:`bearingsim.statics.axial` (seed section 2.1);
* "with inertia": the Jones–Harris model of :mod:`bearingsim.statics.jones_harris`
  (seed section 2.2), K_xx of the 5×5 stiffness, outer-raceway control;
* Palmgren: :func:`bearingsim.statics.axial.palmgren_axial_stiffness` with the free contact
  angle α₀ and with the loaded contact angle of the thrust model;
* with ``rings="fe"``: the Jones–Harris model with elastic rings (:mod:`bearingsim.rings.coupling`: ring
  cross-sections estimated from the boundary dimensions, seat sleeves, influence coefficients by harmonic FE)
  at n = 0, next to the paper's FEM column of T3.

The paper's values are read from ``bearingsim/data/seed000.toml``.
"""

from __future__ import annotations

import csv
import math
import tomllib
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np

from ..statics.axial import palmgren_axial_stiffness, solve_thrust
from ..statics.jones_harris import Loads, solve


def seed_tables() -> dict:
    """Tables T1–T3 of [S0] (Ca in N/µm) as transcribed in the package data."""
    return tomllib.loads((resources.files("bearingsim") / "data" / "seed000.toml").read_text(encoding="utf-8"))


@dataclass
class SpindleStudy:
    """Our axial stiffness values [N/m] next to the paper's [N/µm]."""

    bearing: object
    loads: np.ndarray  #: [N]
    t1_without: np.ndarray  #: thrust model at n = 0 [N/m]
    t1_with: np.ndarray  #: Jones–Harris at n = 0 [N/m]
    t2_speeds_rpm: np.ndarray
    t2: np.ndarray  #: Jones–Harris, (speed, load) [N/m]
    palmgren_free: np.ndarray  #: Palmgren at α₀ [N/m]
    palmgren_loaded: np.ndarray  #: Palmgren at the loaded contact angle [N/m]
    fig_speeds_rpm: np.ndarray
    fig: np.ndarray  #: Jones–Harris Ca over fig speeds, (speed, load) [N/m]
    converged: bool
    seed: dict
    #: Jones–Harris with elastic (FE) rings at n = 0 [N/m], None for rigid rings only
    t3_fe_rings: np.ndarray | None = None
    #: the ring model's description (:attr:`bearingsim.rings.coupling.ElasticRings.description`)
    rings_description: dict | None = None

    def deviations(self) -> dict:
        """Relative deviations of ours from the paper (ours/seed − 1) for T1 and T2."""
        s = self.seed
        return {
            "T1_without": self.t1_without / 1e6 / np.array(s["T1"]["without_inertia"]) - 1,
            "T1_with": self.t1_with / 1e6 / np.array(s["T1"]["with_inertia"]) - 1,
            "T2": self.t2 / 1e6 / np.array(s["T2"]["stiffness"]) - 1,
            "T3_palmgren_loaded": self.palmgren_loaded / 1e6 / np.array(s["T3"]["palmgren"]) - 1,
            "T3_palmgren_free": self.palmgren_free / 1e6 / np.array(s["T3"]["palmgren"]) - 1,
        }

    def print_tables(self, console) -> None:
        from rich.table import Table

        s = self.seed
        dev = self.deviations()
        t1 = Table(title="T1/T3: axial stiffness at n = 0 [N/µm]: ours | [S0] | deviation")
        for c in ("Fa [N]", "no inertia", "seed", "dev", "Jones–Harris", "seed", "dev",
                  "Palmgren α₀", "Palmgren α", "seed Palmgren", "dev (α)", "seed FEM"):
            t1.add_column(c, justify="right")
        for i, fa in enumerate(self.loads):
            t1.add_row(f"{fa:.0f}", f"{self.t1_without[i] / 1e6:.1f}", f"{s['T1']['without_inertia'][i]:.1f}",
                       f"{dev['T1_without'][i]:+.1%}", f"{self.t1_with[i] / 1e6:.1f}",
                       f"{s['T1']['with_inertia'][i]:.1f}", f"{dev['T1_with'][i]:+.1%}",
                       f"{self.palmgren_free[i] / 1e6:.1f}", f"{self.palmgren_loaded[i] / 1e6:.1f}",
                       f"{s['T3']['palmgren'][i]:.1f}", f"{dev['T3_palmgren_loaded'][i]:+.1%}",
                       f"{s['T3']['fem'][i]:.1f}")
        console.print(t1)
        if self.t3_fe_rings is not None:
            t3 = Table(title="T3: axial stiffness at n = 0 with elastic rings [N/µm]: ours rigid | ours FE rings | "
                             "[S0] FEM")
            for c in ("Fa [N]", "rigid rings", "FE rings", "FE/rigid", "seed FEM", "seed FEM/seed no inertia",
                      "ours FE/seed FEM"):
                t3.add_column(c, justify="right")
            for i, fa in enumerate(self.loads):
                fem = s["T3"]["fem"][i]
                t3.add_row(f"{fa:.0f}", f"{self.t1_with[i] / 1e6:.1f}", f"{self.t3_fe_rings[i] / 1e6:.1f}",
                           f"{self.t3_fe_rings[i] / self.t1_with[i]:.3f}", f"{fem:.1f}",
                           f"{fem / s['T1']['without_inertia'][i]:.3f}", f"{self.t3_fe_rings[i] / 1e6 / fem - 1:+.1%}")
            console.print(t3)
        t2 = Table(title="T2: axial stiffness with inertia [N/µm]: ours (seed) deviation")
        t2.add_column("n [rpm]", justify="right")
        for fa in self.loads:
            t2.add_column(f"Fa = {fa:.0f} N", justify="right")
        for k, n in enumerate(self.t2_speeds_rpm):
            t2.add_row(f"{n:.0f}", *[f"{self.t2[k, i] / 1e6:.1f} ({s['T2']['stiffness'][k][i]:.1f}) "
                                     f"{dev['T2'][k, i]:+.0%}" for i in range(len(self.loads))])
        console.print(t2)

    def to_csv(self, path: Path) -> Path:
        """One row per (table, speed, load): ours and the paper's Ca in N/µm."""
        path = Path(path)
        s = self.seed
        with path.open("w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["table", "model", "speed_rpm", "axial_load_N", "ours_N_per_um", "seed_N_per_um"])
            for i, fa in enumerate(self.loads):
                w.writerow(["T1", "without_inertia", 0, fa, self.t1_without[i] / 1e6, s["T1"]["without_inertia"][i]])
                w.writerow(["T1", "with_inertia", 0, fa, self.t1_with[i] / 1e6, s["T1"]["with_inertia"][i]])
                w.writerow(["T3", "palmgren_loaded_angle", 0, fa, self.palmgren_loaded[i] / 1e6,
                            s["T3"]["palmgren"][i]])
                w.writerow(["T3", "palmgren_free_angle", 0, fa, self.palmgren_free[i] / 1e6, s["T3"]["palmgren"][i]])
                if self.t3_fe_rings is not None:
                    w.writerow(["T3", "fe_rings", 0, fa, self.t3_fe_rings[i] / 1e6, s["T3"]["fem"][i]])
            for k, n in enumerate(self.t2_speeds_rpm):
                for i, fa in enumerate(self.loads):
                    w.writerow(["T2", "with_inertia", n, fa, self.t2[k, i] / 1e6, s["T2"]["stiffness"][k][i]])
            for k, n in enumerate(self.fig_speeds_rpm):
                for i, fa in enumerate(self.loads):
                    w.writerow(["Fig5", "with_inertia", n, fa, self.fig[k, i] / 1e6, ""])
        return path

    def plot(self, path: Path) -> Path:
        """Fig. 5 of [S0]: Ca vs speed, one line per load; the paper's T2 points as markers."""
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(7, 4.5))
        seed_t2 = np.array(self.seed["T2"]["stiffness"])
        for i, fa in enumerate(self.loads):
            line, = ax.plot(self.fig_speeds_rpm, self.fig[:, i] / 1e6, label=f"Fa = {fa:.0f} N (bearingsim)")
            ax.plot(self.seed["T2"]["speeds_rpm"], seed_t2[:, i], "o", color=line.get_color(), mfc="none",
                    label="[S0] T2" if i == 0 else None)
        ax.set_xlabel("speed n [rpm]")
        ax.set_ylabel("axial stiffness Ca [N/µm]")
        ax.set_title(f"{getattr(self.bearing, 'name', '')}: axial stiffness vs speed ([S0] Fig. 5)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
        fig.tight_layout()
        path = Path(path)
        fig.savefig(path, dpi=120)
        plt.close(fig)
        return path


def run_study(bearing, fig_points: int = 57, rings: str = "rigid") -> SpindleStudy:
    """Compute T1–T3 and Fig. 5 for ``bearing`` (default: the paper's 7011, estimated ball set); ``rings="fe"``
    adds the axial stiffness with elastic rings at n = 0 (T3, next to the paper's FEM column)."""
    from ..errors import InputError

    if rings not in ("rigid", "fe"):
        raise InputError("rings", f"unknown ring model {rings!r}", "use rigid or fe")
    seed = seed_tables()
    loads = np.array(seed["loads_N"], dtype=float)
    t1_without = np.empty(len(loads))
    t1_with = np.empty(len(loads))
    p_free = np.empty(len(loads))
    p_loaded = np.empty(len(loads))
    ok = True
    for i, fa in enumerate(loads):
        th = solve_thrust(bearing, fa)
        t1_without[i] = th.axial_stiffness
        r = solve(bearing, Loads(fa=fa))
        ok &= r.converged
        t1_with[i] = r.axial_stiffness
        p_free[i] = palmgren_axial_stiffness(fa, bearing.ball_count, bearing.ball_diameter,
                                             bearing.free_contact_angle)
        p_loaded[i] = palmgren_axial_stiffness(fa, bearing.ball_count, bearing.ball_diameter, th.contact_angle)

    def speed_sweep(speeds_rpm):
        out = np.empty((len(speeds_rpm), len(loads)))
        nonlocal ok
        for i, fa in enumerate(loads):
            start = None
            for k, n in enumerate(speeds_rpm):
                r = solve(bearing, Loads(fa=fa), n * math.pi / 30.0, initial=start)
                ok &= r.converged
                start = r.displacement
                out[k, i] = r.axial_stiffness
        return out

    t3_fe = desc = None
    if rings == "fe":
        from ..rings.coupling import ring_model
        from ..rings.coupling import solve as solve_fe

        model = ring_model(bearing)
        desc = model.description
        t3_fe = np.empty(len(loads))
        for i, fa in enumerate(loads):
            r = solve_fe(bearing, Loads(fa=fa), rings=model)
            ok &= r.converged
            t3_fe[i] = r.axial_stiffness
    t2_speeds = np.array(seed["T2"]["speeds_rpm"], dtype=float)
    fig_speeds = np.linspace(0.0, 11200.0, fig_points)
    return SpindleStudy(bearing, loads, t1_without, t1_with, t2_speeds, speed_sweep(t2_speeds), p_free, p_loaded,
                        fig_speeds, speed_sweep(fig_speeds), bool(ok), seed, t3_fe, desc)
