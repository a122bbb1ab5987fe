"""The results of a dynamic run (:class:`Results`): the output variables, in memory or read from the
output file block by block, the run's summary, steady-state averages, hysteresis loop widths
(through :mod:`.analysis`) and plots.
"""

from __future__ import annotations

import math
from contextlib import contextmanager

import numpy as np

from . import analysis
from . import model as md
from .output import VARIABLES, to_dataset


class Results:
    """Results of :func:`simulate`: the output variables (SI) and the run's summary.

    With an output file the data stay on disk (``to_xarray`` opens it lazily) and
    ``data`` loads them on first use.
    """

    def __init__(self, data: dict | None, attrs: dict, path: str | None = None, summary: dict | None = None):
        if data is None and path is None:
            raise ValueError("Results need data or a file")
        self._data = data
        self.attrs = attrs
        self.path = path
        self.summary = summary or {}

    def to_xarray(self):
        """xarray Dataset with units in the attributes (opened from the file when there is one)."""
        if self.path is not None and self._data is None:
            import xarray as xr

            return xr.open_dataset(self.path)
        return to_dataset(self._data, self.attrs)

    @property
    def data(self) -> dict:
        """Stacked output variables (numpy arrays, SI)."""
        if self._data is None:
            ds = self.to_xarray()
            self._data = {"time": ds["time"].values}
            for k in VARIABLES:
                self._data[k] = ds[k].values
            ds.close()
        return self._data

    def steady_state(self, fraction: float = 0.5) -> dict:
        """Friction torque and heat by contact type averaged over the last ``fraction`` of the run.

        Power loss per contact type [W] (ball–inner, ball–outer, ball–cage, cage land; the
        rolling resistance is inside the raceway terms when the traction kernel provides it),
        the friction torque on the inner ring [N·m], and for elastic cages the largest elastic
        pocket displacement and normal stress over that part of the run,
        ``cage_pocket_deformation_max`` [m] and ``cage_peak_stress_max`` [Pa] (0 for rigid cages).
        """
        names = ("power_loss_inner", "power_loss_outer", "power_loss_cage", "power_loss_land", "power_loss_rolling",
                 "inner_ring_friction_torque", "outer_ring_friction_torque")
        with self._columns() as read:
            t = read("time")
            i0 = int(np.searchsorted(t, t[0] + (1 - fraction) * (t[-1] - t[0])))
            n = len(t)
            out = {}
            # means in blocks of rows: memory bounded by the block, not by the run
            for k in names:
                total = 0.0
                for a in range(i0, n, self.BLOCK):
                    total += float(np.sum(read(k, a, min(n, a + self.BLOCK))))
                out[k] = total / max(n - i0, 1)
            for k in ("cage_pocket_deformation", "cage_peak_stress"):
                out[k + "_max"] = max((float(np.max(read(k, a, min(n, a + self.BLOCK)), initial=0.0))
                                       for a in range(i0, n, self.BLOCK)), default=0.0)
            # mean cage speed from its angle (the cage rattles in its pocket clearance)
            if n - i0 > 1:
                dth = read("cage_angle", n - 1, n)[0] - read("cage_angle", i0, i0 + 1)[0]
                out["cage_angular_speed"] = float(np.mean(dth / (t[-1] - t[i0])))
            else:
                out["cage_angular_speed"] = float(np.mean(read("cage_angular_speed", i0, n)))
        out["heat_generation_total_W"] = out["power_loss_inner"] + out["power_loss_outer"] + \
            out["power_loss_cage"] + out["power_loss_land"]
        return out

    BLOCK = 20_000  #: rows read at a time from an output file

    def read(self, *names: str) -> list[np.ndarray]:
        """The given output variables (SI arrays), read from the file without loading the others."""
        with self._columns() as read:
            return [np.asarray(read(n)) for n in names]

    @contextmanager
    def _columns(self):
        """Yield read(name, start=0, stop=None) -> rows of one output variable, from memory or the file."""
        if self._data is not None or self.path is None:
            data = self.data
            yield lambda name, start=0, stop=None: data[name][start:stop]
            return
        import xarray as xr

        with xr.open_dataset(self.path) as ds:
            yield lambda name, start=0, stop=None: ds[name][start:stop].values

    def loop_widths(self, moment: float = 300.0, dof: int = 4, load: int = 4) -> np.ndarray:
        """Two-point hysteresis reading per load cycle, Sakaguchi & Shibutani [S1] Fig. 8 definition [rad] (diagnostic).

        For every time the applied load ``applied_load[:, load]`` (default M_z) passes ``moment``
        [N·m] rising and then falling: the tilt (``inner_ring_displacement[:, dof]``, default γz) at
        the falling crossing minus that at the rising one (linear interpolation between samples);
        positive when the tilt lags the moment.  [S1] evaluates it at 0.3 kN·m.  Unfiltered, it reads
        whatever vibration rides on the loop at the two instants: the estimate is :meth:`hysteresis`.
        """
        with self._columns() as read:  # only the two variables, not the whole run
            m = read("applied_load")[:, load]
            g = read("inner_ring_displacement")[:, dof]
        return analysis.loop_widths(m, g, moment)

    def fluctuation_range(self, moment: float = 300.0, dof: int = 4, load: int = 4) -> float:
        """Two-point W_H of the last complete load cycle [rad] (:meth:`loop_widths`, diagnostic); NaN if there is none.

        The estimate with its interval over the periodic cycles is :meth:`hysteresis` (``.mean``, ``.ci95``).
        """
        w = self.loop_widths(moment, dof, load)
        return float(w[-1]) if len(w) else math.nan

    def load_frequency(self, load: int = 4) -> float:
        """Frequency [Hz] of the load channel ``load``: ``attrs["load_frequency_hz"]`` when the run stored it,
        else estimated from the applied load's rising crossings of its mid-range
        (:func:`.analysis.estimate_frequency`; exact for a single sine, NaN when it does not vary)."""
        f = self.attrs.get("load_frequency_hz") if isinstance(self.attrs, dict) else None
        if f is not None and math.isfinite(float(f)) and float(f) > 0:
            return float(f)
        with self._columns() as read:
            t = read("time")
            m = read("applied_load")[:, load]
        return analysis.estimate_frequency(t, m)

    def hysteresis(self, level: float = 300.0, dof: int = 4, load: int = 4, frequency: float | None = None,
                   **options) -> "analysis.LoopEstimate":
        """Loop of the tilt against the moment: W_H per periodic cycle with mean and 95 % interval, loop area,
        phase lag and compliance of the fundamental (:func:`.analysis.hysteresis_estimate`; SI: rad, J).

        level : load at which W_H is read [N·m] ([S1] Fig. 8: 300); dof : column of
        ``inner_ring_displacement`` (4 = γz); load : column of ``applied_load`` (4 = M_z); frequency :
        of the load [Hz], from :meth:`load_frequency` when None.  ``options`` go to the estimator
        (n_harmonics, min_cycles, tolerance, first_cycle).
        """
        from ..errors import InputError

        if frequency is None:
            frequency = self.load_frequency(load)
            if not (math.isfinite(frequency) and frequency > 0):
                raise InputError("frequency", f"the applied load (column {load}) does not vary periodically",
                                 "give frequency= in Hz, or run with a sine load")
        with self._columns() as read:
            t = np.asarray(read("time"))
            m = np.asarray(read("applied_load")[:, load])
            g = np.asarray(read("inner_ring_displacement")[:, dof])
        return analysis.hysteresis_estimate(t, m, g, frequency, level, **options)

    def plot(self, variables=("inner_ring_displacement", "cage_angular_speed"), ax=None):
        """Plot variables against time (matplotlib); returns the figure."""
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(len(variables), 1, sharex=True, figsize=(7, 2.5 * len(variables)))
        axes = np.atleast_1d(axes)
        for a, name in zip(axes, variables):
            v = self.data[name]
            a.plot(self.data["time"] * 1e3, v.reshape(len(v), -1))
            u = VARIABLES[name][1]
            a.set_ylabel(f"{name} [{u if isinstance(u, str) else ', '.join(dict.fromkeys(u))}]")
        axes[-1].set_xlabel("time [ms]")
        return fig

    def plot_hysteresis(self, dof: int = 4, load: int = 4):
        """Tilt against moment ([S1] Fig. 6)."""
        import matplotlib.pyplot as plt

        fig, a = plt.subplots()
        a.plot(self.data["applied_load"][:, load], np.degrees(self.data["inner_ring_displacement"][:, dof]))
        a.set_xlabel(f"{md.DOF[load]} load")
        a.set_ylabel("inclining angle [deg]")
        return fig

