"""
Deflection of a milling spindle on its bearings
===============================================

``examples/spindle-milling.toml``: a stepped spindle on a front set of angular contact bearings and a rear
bearing, loaded at the tool tip. ``bearingsim.solve_shaft`` finds the static equilibrium with every bearing's
full 5-DOF Jones–Harris response at the shaft speed; the figure shows the radial deflection along the shaft and
the bearing positions. From the command line: ``bearingsim shaft examples/spindle-milling.toml``.
"""

from pathlib import Path

import matplotlib.pyplot as plt

import bearingsim
from bearingsim.io.shaft_system import load_shaft_system

here = Path(__file__).resolve().parent if "__file__" in globals() else Path.cwd()
case = next(p / "examples" / "spindle-milling.toml" for p in (here, *here.parents)
            if (p / "examples" / "spindle-milling.toml").exists())
shaft = load_shaft_system(case)
r = bearingsim.solve_shaft(shaft.system)

fig, ax = plt.subplots(figsize=(7.0, 3.8))
ax.plot(r.nodes * 1e3, r.displacement[:, 1] * 1e6, "-", label="δy")
ax.plot(r.nodes * 1e3, r.displacement[:, 2] * 1e6, "-", label="δz")
for s in shaft.system.supports:
    ax.axvline(s.position * 1e3, color="0.5", ls=":", lw=1)
    ax.annotate(s.name, (s.position * 1e3, 0), xytext=(3, 4), textcoords="offset points", fontsize=8)
ax.axhline(0.0, color="k", lw=0.5)
ax.set_xlabel("axial position x [mm]")
ax.set_ylabel("radial deflection [µm]")
k = r.direct_stiffness_at(shaft.tool_tip)["radial_N_per_m"] / 1e6
ax.set_title(f"{shaft.system.name}: radial stiffness at the tool tip {k:.1f} N/µm")
ax.legend()
fig.tight_layout()
plt.show()
