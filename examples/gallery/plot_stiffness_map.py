"""
A stiffness map over load and speed
===================================

``bearingsim.map_grid`` solves a grid of axial loads × speeds with the compiled batch solver (warm starts along
the grid) and returns an ``xarray.Dataset``; here the axial stiffness K_xx of the 7011 spindle bearing. The same
map from the command line: ``bearingsim map skf-7011-cdga-hc --fa 1000:5000:9 --speed 0:12000:25 --out map.nc
--plot map.png``.
"""

import matplotlib.pyplot as plt

import bearingsim

ds = bearingsim.map_grid("skf-7011-cdga-hc", fa="1000:5000:9", speed="0:12000:25", workers=1)
k_xx = ds["stiffness"].sel(dof="x", dof2="x") / 1e6           # N/µm
rpm = ds["speed"] * 30.0 / 3.141592653589793

fig, ax = plt.subplots(figsize=(6.4, 4.2))
cs = ax.contourf(rpm, ds["fa"] / 1e3, k_xx, levels=16, cmap="viridis")
ax.contour(rpm, ds["fa"] / 1e3, k_xx, levels=cs.levels[::3], colors="w", linewidths=0.5)
fig.colorbar(cs, ax=ax, label="axial stiffness K_xx [N/µm]")
ax.set_xlabel("speed n [rpm]")
ax.set_ylabel("axial load F_a [kN]")
ax.set_title(f"{ds.attrs['bearing']}: all {int(ds.converged.sum())} points converged")
fig.tight_layout()
plt.show()
