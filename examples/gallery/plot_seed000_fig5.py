"""
Axial stiffness of a spindle bearing with and without inertia ([S0] Fig. 5)
===========================================================================

The SKF 7011 CDGA/HC of the spindle-bearing study [S0]: the axial stiffness C_a against speed at five axial
loads, from the Jones–Harris model with centrifugal force and gyroscopic moment (lines), the model without inertia
(the thrust model of [S0] §2.1, dashed: the same at every speed) and the paper's table T2 (circles). The same
figure as ``bearingsim reproduce spindle-axial-stiffness``, on a coarser speed grid.
"""

import matplotlib.pyplot as plt
import numpy as np

import bearingsim
from bearingsim.studies.spindle import run_study

study = run_study(bearingsim.load_bearing("skf-7011-cdga-hc"), fig_points=15)
seed_t2 = np.array(study.seed["T2"]["stiffness"])

fig, ax = plt.subplots(figsize=(7.0, 4.5))
for i, fa in enumerate(study.loads):
    (line,) = ax.plot(study.fig_speeds_rpm, study.fig[:, i] / 1e6, label=f"F_a = {fa:.0f} N, with inertia")
    ax.axhline(study.t1_without[i] / 1e6, color=line.get_color(), ls="--", lw=0.8)
    ax.plot(study.seed["T2"]["speeds_rpm"], seed_t2[:, i], "o", color=line.get_color(), mfc="none",
            label="[S0] T2" if i == 0 else None)
ax.plot([], [], "k--", lw=0.8, label="without inertia (thrust model)")
ax.set_xlabel("speed n [rpm]")
ax.set_ylabel("axial stiffness C_a [N/µm]")
ax.set_title("SKF 7011 CDGA/HC: axial stiffness vs speed")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
plt.show()
