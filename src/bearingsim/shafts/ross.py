"""Export of a shaft system to ROSS (ross-rotordynamics): ``ross.Rotor`` of ``ShaftElement``s (one per beam
element: length, diameters, material, Timoshenko shear with Cowper's coefficient as ours), ``DiskElement``s (the
point masses) and ``BearingElement``s whose lateral and axial coefficients are each support's tangent stiffness
at the static equilibrium of every speed (``frequency`` [rad/s]), so that unbalance response and stability can
continue there.

Axes: ROSS's rotor axis is z, ours x; the map (our y, z, x) → (ROSS x, y, z) and the coefficients taken are
those of :data:`bearingsim.export.ROSS_MAP`.  ROSS's ``BearingElement`` cannot take the tilt stiffness, the
translation–tilt and the axial–lateral couplings of a ball bearing (:data:`bearingsim.export.DROPPED`): the
export names each dropped term with its largest size relative to the support's radial stiffness in
``warnings``; the housing springs and outer-ring DOF (a spring preload's sliding ring) are represented by the
bearing tangent alone (named in ``warnings`` as well).
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from ..export import DROPPED, ROSS_MAP
from .model import BearingSupport, ShaftSystem
from .solve import dof_vector, solve_shaft

_INDEX = {"x": 0, "y": 1, "z": 2, "gamma_y": 3, "gamma_z": 4}


def support_coefficients(system: ShaftSystem, speeds) -> tuple[np.ndarray, dict, list]:
    """(speeds float[n] [rad/s], {support name: float[n, 5, 5] tangent stiffness, shaft frame}, warnings):
    each support's tangent at the static equilibrium of each speed (warm started along the speeds)."""
    sp = np.asarray(speeds, dtype=float).reshape(-1)
    if sp.size == 0 or not np.all(np.isfinite(sp)) or np.any(sp < 0):
        raise InputError("speeds", "give one or more finite speeds ≥ 0 [rad/s]", "e.g. 0:2000:11 rad/s")
    out = {s.name: np.zeros((sp.size, 5, 5)) for s in system.supports}
    warnings = []
    w0 = None
    for i, w in enumerate(sp):
        r = solve_shaft(system, speed=float(w), initial=w0, bearing_results=False)
        if not r.converged:
            raise InputError("speeds", f"no static equilibrium at {w:.6g} rad/s: {r.status}",
                             "export the speeds at which the system converges")
        w0 = dof_vector(r)
        for s in r.supports:
            out[s.name][i] = s.stiffness
    return sp, out, warnings


def to_ross(system: ShaftSystem, speeds, damping: float = 0.0):
    """``(ross.Rotor, warnings)`` of ``system`` with bearing coefficients at ``speeds`` [rad/s]; ``damping``
    [N·s/m] the lateral damping given to every bearing (rolling bearings' damping is not modelled here)."""
    try:
        import ross as rs
    except ImportError:
        raise InputError("ross", "ross-rotordynamics is not installed",
                         "pip install 'bearingsim[ross]' (or ross-rotordynamics)") from None
    sp, coeffs, warnings = support_coefficients(system, speeds)
    mesh = system.mesh
    mats = {}
    shaft = []
    for e in range(mesh.n_nodes - 1):
        sec = system.sections[mesh.element_section[e]]
        m = sec.material
        if m.name not in mats:
            mats[m.name] = rs.Material(name=m.name.replace(" ", "_"), rho=m.density, E=m.youngs_modulus,
                                       Poisson=m.poisson_ratio)
        shaft.append(rs.ShaftElement(L=float(mesh.nodes[e + 1] - mesh.nodes[e]), idl=sec.inner_diameter,
                                     odl=sec.outer_diameter, material=mats[m.name], n=e,
                                     shear_effects=system.shear, rotary_inertia=True, gyroscopic=True,
                                     shear_method_calc="cowper"))
    disks = [rs.DiskElement(n=mesh.node_at(p.position), m=p.mass, Id=p.diametral_inertia, Ip=p.polar_inertia)
             for p in system.masses]
    bearings = []
    c = [float(damping)] * sp.size
    for s in system.supports:
        k = coeffs[s.name]
        kw = {name: [float(v) for v in k[:, i, j]] for name, i, j in ROSS_MAP}
        bearings.append(rs.BearingElement(n=mesh.node_at(s.position), cxx=c, cyy=c, frequency=[float(v) for v in sp],
                                          tag=s.name, **kw))
        kr = max(float(np.max(np.abs(k[:, 1, 1]))), 1e-300)
        dropped = []
        for term in DROPPED:
            a, b = term[2:-1].split(",")
            v = float(np.max(np.abs(k[:, _INDEX[a], _INDEX[b]])))
            if v > 0:
                dropped.append(f"{term} up to {v:.3g} (ratio {v / kr:.3g} to K[y,y] in its unit)")
        if dropped:
            warnings.append(f"{s.name}: ROSS's BearingElement takes no tilt or coupling terms; dropped "
                            + "; ".join(dropped))
        if s.housing_stiffness is not None or (isinstance(s, BearingSupport) and s.preload_force is not None):
            warnings.append(f"{s.name}: the housing spring / sliding outer ring is not exported (the bearing "
                            "tangent alone connects the shaft to ground)")
    return rs.Rotor(shaft_elements=shaft, disk_elements=disks, bearing_elements=bearings), warnings
