"""
Load distribution of a deep-groove bearing
==========================================

The ball loads Q(ψ) of a 6205 under a combined load at 1500 rpm, from the Jones–Harris equilibrium: the load zone
under the radial load, the axial load spreading it around the ring.
"""

import matplotlib.pyplot as plt
import numpy as np

import bearingsim

bearing = bearingsim.load_bearing("6205")
fig, ax = plt.subplots(figsize=(6.4, 4.0))
for fa in (0.0, 500.0, 1500.0):
    r = bearingsim.solve(bearing, bearingsim.Loads(fr_y=2000.0, fa=fa), speed="1500 rpm")
    psi = (np.degrees(r.balls["azimuth_rad"]) + 180.0) % 360.0 - 180.0
    order = np.argsort(psi)
    ax.plot(psi[order], r.balls["inner_load_N"][order], "o-", label=f"F_r = 2 kN, F_a = {fa / 1e3:g} kN")
ax.set_xlabel("ball azimuth ψ [deg] (0 on +y, the radial load's direction)")
ax.set_ylabel("inner contact load Q_i [N]")
ax.set_title("6205 at 1500 rpm")
ax.legend()
fig.tight_layout()
plt.show()
