"""
Tilt of a hub unit under a moment
=================================

The double-row hub unit of the hub-bearing study [S1] (``hub-seed001``) under a moment about z with the tied
axial and radial loads of the study, at rest and at 100 km/h: the quasi-static tilt line that the dynamic
hysteresis loops of ``bearingsim reproduce hub-hysteresis`` run along (the loops' width is the lag of the tilt
behind the moment, a few 10⁻³ °). The moment stiffness does not depend on speed, as [S1] states.
"""

import matplotlib.pyplot as plt
import numpy as np

from bearingsim.studies.hub_static import run_study, vehicle_speed_to_shaft

moments = np.linspace(-600.0, 600.0, 25)
fig, ax = plt.subplots(figsize=(6.4, 4.2))
for v_kmh, style in ((0.0, "o-"), (100.0, "x--")):
    res = run_study(moments=moments, speed=vehicle_speed_to_shaft(v_kmh))
    secant = (res.moment[-1] - res.moment[0]) / np.degrees(res.tilt[-1] - res.tilt[0]) / 1e3   # kN·m/°
    ax.plot(res.moment, np.degrees(res.tilt), style, ms=4, label=f"{v_kmh:.0f} km/h: {secant:.1f} kN·m/° (secant)")
ax.set_xlabel("moment M_z [N·m]")
ax.set_ylabel("tilt of the inner ring γ_z [deg]")
ax.set_title("hub unit (hub-seed001): tilt vs moment")
ax.grid(True, alpha=0.3)
ax.legend()
fig.tight_layout()
plt.show()
