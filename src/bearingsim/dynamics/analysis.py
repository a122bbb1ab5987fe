"""Post-processing of dynamic results: hysteresis loop widths of a tilt against a periodic moment.

Functions on plain arrays (SI), so that they serve :class:`bearingsim.dynamics.run.Results`
(whose ``loop_widths`` / ``fluctuation_range`` call them), the hub study and scripts alike.
"""

from __future__ import annotations

import math

import numpy as np


def loop_widths(load: np.ndarray, response: np.ndarray, level: float) -> np.ndarray:
    """Hysteresis widths of ``response`` against ``load`` at the load ``level``, one per load cycle.

    Sakaguchi & Shibutani, NTN Technical Review 87, Fig. 8 definition: for every time the load
    passes ``level`` rising and then falling, the response at the falling crossing minus that at the
    rising one (linear interpolation between samples); positive when the response lags the load.
    load, response : float[n] samples at the same times (e.g. M_z [N m] and the tilt γz [rad]);
    level in the unit of ``load``.  Returns float[cycles] in the unit of ``response``.
    """
    m = np.asarray(load) - level
    g = np.asarray(response)
    out = []
    rising = math.nan
    for i in range(1, len(m)):
        if m[i - 1] == m[i] or (m[i - 1] > 0) == (m[i] > 0):
            continue
        w = m[i - 1] / (m[i - 1] - m[i])
        value = g[i - 1] + w * (g[i] - g[i - 1])
        if m[i] > m[i - 1]:
            rising = value
        elif not math.isnan(rising):
            out.append(value - rising)
            rising = math.nan
    return np.array(out)


def fluctuation_range(load: np.ndarray, response: np.ndarray, level: float) -> float:
    """W_H: the width of the last complete load cycle (:func:`loop_widths`); NaN if there is none."""
    w = loop_widths(load, response, level)
    return float(w[-1]) if len(w) else math.nan
