"""[S1] hub unit: quasi-static tilt of the inner ring versus moment (−600 … +600 N·m).

The reference curve every dynamic result of [S1] must meet when the loads vary slowly
([S1] Fig. 6: the tilt–moment lines at 10, 50 and 100 km/h share one slope).

Bearing: catalogue ``hub-seed001`` ([S1] Table 1: two rows of 16 balls of 11.1 mm on a 61 mm
pitch circle, 35°, rows 18.2 mm apart, back-to-back, preload 5,400 N; groove curvatures and
material assumed, see the catalogue files).  Loads ([S1] Table 2) act on the inner ring at the
load acting point, 10.4 mm from the centre between the rows (``load_point`` of the unit).

Tie between the loads (our assumption; Table 2 gives only the ranges, which vary together):
    Fa(M) = Fa_max · M / M_max                       (−1,890 … +1,890 N),
    Fr(M) = (Fr_min + Fr_max)/2 + (Fr_max − Fr_min)/2 · M / M_max   (1,820 … 3,750 N),
i.e. all three vary in phase, as for a cornering wheel: the lateral tyre force Fa acts at the
tyre radius R = M_max / Fa_max = 317.5 mm (a plausible passenger-car tyre radius), so that
M = R · Fa, and the vertical load Fr grows on the outer wheel.  M is the moment about z, Fr acts
along +y, so a positive M tilts the inner ring by a positive γz.

At M = 0 the tilt is not zero: Fr = 2,785 N acts at the load point, 10.4 mm from the centre
between the rows, i.e. with a moment of 29 N·m about that centre.

Moment compliance along the load path: dγz/dM = [K⁻¹ · dF/dM]_γz with dF/dM = (1/R, ΔFr/ΔM, 0, 0, 1)
and K the 5×5 stiffness at the load point (implicit differentiation, no extra solve); the moment
stiffness is its inverse.  The pure tilt stiffness (other loads held) is also given,
1 / (K⁻¹)_γzγz.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..statics import arrangements as ar
from ..statics.jones_harris import Loads, solve

M_MAX = 600.0  #: [N·m] [S1] Table 2
FA_MAX = 1890.0  #: [N] [S1] Table 2
FR_MIN, FR_MAX = 1820.0, 3750.0  #: [N] [S1] Table 2
TYRE_RADIUS = M_MAX / FA_MAX  #: [m] implied by the tie M = R Fa


def tied_loads(moment: float) -> Loads:
    """Loads of [S1] Table 2 tied to the moment M [N·m] (module docstring) → Loads [N, N·m]."""
    s = moment / M_MAX
    return Loads(fa=FA_MAX * s, fr_y=0.5 * (FR_MIN + FR_MAX) + 0.5 * (FR_MAX - FR_MIN) * s, m_z=moment)


def vehicle_speed_to_shaft(v_kmh: float, tyre_radius: float = TYRE_RADIUS) -> float:
    """Shaft speed [rad/s] of a wheel rolling without slip at v [km/h] with tyre radius [m]."""
    return v_kmh / 3.6 / tyre_radius


def shaft_speed_entry(v_kmh: float) -> str:
    """The case-file ``speed`` entry (full precision, in rpm) of the shaft at vehicle speed v [km/h]."""
    return f"{vehicle_speed_to_shaft(v_kmh) * 30 / math.pi!r} rpm"


@dataclass
class HubStaticResult:
    """Tilt–moment curve of the hub unit (SI)."""

    bearing: object
    speed: float  #: shaft speed [rad/s]
    moment: np.ndarray  #: M [N·m]
    fa: np.ndarray  #: [N]
    fr: np.ndarray  #: [N]
    tilt: np.ndarray  #: γz [rad]
    displacement: np.ndarray  #: (n, 5) at the load point [m, rad]
    compliance: np.ndarray  #: dγz/dM along the load path [rad/(N·m)]
    tilt_stiffness: np.ndarray  #: 1/(K⁻¹)_γzγz [N·m/rad]
    row_axial_load: np.ndarray  #: (n, 2) [N]
    lifted_off: np.ndarray  #: (n, 2) bool
    converged: np.ndarray  #: (n,) bool: ring and every ball converged
    ring_converged: np.ndarray = None  #: (n,) bool: ring equilibrium converged (balls off the inner race may not)

    @property
    def moment_stiffness(self) -> np.ndarray:
        """dM/dγz along the load path [N·m/rad]."""
        return 1.0 / self.compliance

    @property
    def secant_compliance(self) -> float:
        """(γ(M_max) − γ(M_min)) / (M_max − M_min) [rad/(N·m)]."""
        return float((self.tilt[-1] - self.tilt[0]) / (self.moment[-1] - self.moment[0]))

    def rows(self) -> list[dict]:
        out = []
        for i in range(len(self.moment)):
            out.append({
                "moment_N_m": float(self.moment[i]), "fa_N": float(self.fa[i]), "fr_N": float(self.fr[i]),
                "tilt_rad": float(self.tilt[i]), "tilt_deg": math.degrees(self.tilt[i]),
                "axial_m": float(self.displacement[i, 0]), "radial_y_m": float(self.displacement[i, 1]),
                "compliance_rad_per_N_m": float(self.compliance[i]),
                "moment_stiffness_N_m_per_rad": float(1.0 / self.compliance[i]),
                "tilt_stiffness_N_m_per_rad": float(self.tilt_stiffness[i]),
                "row0_axial_load_N": float(self.row_axial_load[i, 0]),
                "row1_axial_load_N": float(self.row_axial_load[i, 1]),
                "row0_lifted_off": bool(self.lifted_off[i, 0]), "row1_lifted_off": bool(self.lifted_off[i, 1]),
                "converged": bool(self.converged[i]),
                "ring_converged": bool(self.ring_converged[i]) if self.ring_converged is not None else None,
            })
        return out

    def table(self) -> str:
        """Plain-text table (engineering units for display)."""
        head = (f"{'M N·m':>8} {'Fa N':>8} {'Fr N':>8} {'tilt deg':>10} {'dγ/dM deg/kN·m':>15} "
                f"{'K_M kN·m/deg':>13} {'row0 Fa N':>10} {'row1 Fa N':>10} {'lift-off':>9}")
        lines = [f"{getattr(self.bearing, 'name', '')}: shaft speed {self.speed * 30 / math.pi:.0f} rpm", head]
        for r in self.rows():
            lift = ",".join(str(k) for k in (0, 1) if r[f"row{k}_lifted_off"]) or "-"
            lines.append(f"{r['moment_N_m']:8.1f} {r['fa_N']:8.1f} {r['fr_N']:8.1f} {r['tilt_deg']:10.5f} "
                         f"{math.degrees(r['compliance_rad_per_N_m']) * 1e3:15.5f} "
                         f"{1.0 / (math.degrees(r['compliance_rad_per_N_m']) * 1e3):13.4f} "
                         f"{r['row0_axial_load_N']:10.1f} {r['row1_axial_load_N']:10.1f} {lift:>9}"
                         + ("" if r["converged"] else ("  ring converged; a ball off the inner raceway did not"
                                                       if r["ring_converged"] else "  NOT CONVERGED")))
        lines.append(f"secant compliance over ±{M_MAX:.0f} N·m: {math.degrees(self.secant_compliance) * 1e3:.5f} "
                     f"deg/(kN·m)  (moment stiffness {1.0 / (math.degrees(self.secant_compliance) * 1e3):.4f} "
                     f"kN·m/deg)")
        return "\n".join(lines)

    def to_csv(self, path) -> Path:
        path = Path(path)
        rows = self.rows()
        with path.open("w", newline="", encoding="utf-8") as fh:
            fh.write("# [S1] hub unit, quasi-static tilt vs moment (bearingsim.studies.hub_static); SI units\n")
            w = csv.DictWriter(fh, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
        return path

    def plot(self, path) -> Path:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6, 4.5))
        ax.plot(self.moment / 1e3, np.degrees(self.tilt), "o-", ms=3, label="quasi-static (Jones–Harris)")
        ax.set_xlabel("Moment kN·m")
        ax.set_ylabel("Inclining angle deg")
        ax.set_xlim(-0.8, 0.8)
        ax.set_ylim(-0.10, 0.10)
        ax.grid(True, alpha=0.3)
        ax.set_title(f"{getattr(self.bearing, 'name', '')}, {self.speed * 30 / math.pi:.0f} rpm")
        ax.legend()
        fig.tight_layout()
        fig.savefig(path, dpi=120)
        plt.close(fig)
        return Path(path)


def check_hub(bearing, field: str = "bearing") -> None:
    """An :class:`~bearingsim.errors.InputError` unless ``bearing`` has the two rows of a hub unit (the study reads
    both rows' loads and lift-off; a single-row bearing would fail with an IndexError)."""
    n = len(bearing.rows)
    if n != 2:
        from ..errors import InputError

        raise InputError(field, f"{getattr(bearing, 'name', 'the bearing')} has {n} row{'s' if n != 1 else ''}; this "
                         "study is for a double-row hub unit", "e.g. hub-seed001, or a TOML file with two rows")


def run_study(bearing=None, moments=None, speed: float = 0.0, control: str = "outer") -> HubStaticResult:
    """Tilt vs moment of the hub unit under the tied Table 2 loads.

    Parameters
    ----------
    bearing : the hub unit (default catalogue ``hub-seed001``)
    moments : moments [N·m] (default −600 … +600 in 25 steps)
    speed : shaft speed [rad/s]
    """
    if bearing is None:
        from ..io import load_bearing

        bearing = load_bearing("hub-seed001")
    check_hub(bearing)
    m = np.linspace(-M_MAX, M_MAX, 25) if moments is None else np.asarray(moments, dtype=float)
    n = len(m)
    disp = np.zeros((n, 5))
    comp = np.zeros(n)
    kt = np.zeros(n)
    rowfa = np.zeros((n, len(bearing.rows)))
    lift = np.zeros_like(rowfa, dtype=bool)
    conv = np.zeros(n, dtype=bool)
    ring = np.zeros(n, dtype=bool)
    dfdm = np.array([1.0 / TYRE_RADIUS, 0.5 * (FR_MAX - FR_MIN) / M_MAX, 0.0, 0.0, 1.0])
    # march from M = 0 outwards, warm-starting each point from its neighbour
    order = list(np.argsort(np.abs(m), kind="stable"))
    prev = {}
    for i in order:
        start = None
        if prev:
            j = min(prev, key=lambda k: abs(m[k] - m[i]))
            start = prev[j]
        res = solve(bearing, tied_loads(m[i]), speed, control, initial=start)
        if start is not None and not res.converged:
            cold = solve(bearing, tied_loads(m[i]), speed, control)
            if cold.converged or (res.status.startswith("no equilibrium") and not cold.status.startswith("no eq")):
                res = cold
        conv[i] = res.converged
        ring[i] = res.converged or res.status.startswith("ring converged")
        disp[i] = res.displacement
        kinv = np.linalg.inv(res.stiffness)
        comp[i] = (kinv @ dfdm)[4]
        kt[i] = 1.0 / kinv[4, 4]
        rr = ar.row_results(res)
        rowfa[i] = [r["axial_load_N"] for r in rr]
        lift[i] = [r["lifted_off"] for r in rr]
        if ring[i]:
            prev[i] = res.displacement
    fa = np.array([tied_loads(v).fa for v in m])
    fr = np.array([tied_loads(v).fr_y for v in m])
    return HubStaticResult(bearing, speed, m, fa, fr, disp[:, 4], disp, comp, kt, rowfa, lift, conv, ring)
