"""The cage: a rigid body, or a rigid body carrying elastic modes (mode synthesis).

Sakaguchi & Shibutani [S1] §3 (Table 3): the cage has 3 translations and 3 rotations and, in IBDAS, 56 elastic
modes.  Its rigid state block is

    r (3), v (3), θ, βy, βz, θ̇, β̇y, β̇z                    (N_CAGE = 12 values)

and its pocket surfaces are spheres or cylinders in the pocket frame
(:func:`.model.pocket_geometry`); the contact routine finds the surface point nearest the ball
centre in closed form.  An elastic cage (:func:`attach_elastic_cages`) adds n modal coordinates
η and rates η̇ at the end of the state: its free–free modes come from the finite-element ring of
:mod:`bearingsim.cage_modes` (mass-normalised, rigid-body modes removed, shapes at the pocket
centres), each pocket is displaced by Σ η_k φ_k^u and turned by Σ η_k φ_k^ρ, and the pocket forces
drive the modes through the generalized forces Σ φ_k·F (component-mode synthesis with free–free
modes, Craig, *Structural Dynamics*, 1981, ch. 17; the equations are in :func:`.forces.rhs`).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from ..errors import InputError
from ..statics import layout as kn  # the row-parameter layout (P_*)
from .layout import C_BALL0, C_IP, C_IT, C_MASS, C_MODE0, C_NMODES, C_PSI0, C_RP, C_Z, N_BALL, N_CAGE, N_RING

#: modal damping ratio ζ of every cage mode when none is given [-] (a structural ratio typical of a
#: steel or brass cage; polymer cages damp more)
DEFAULT_MODAL_DAMPING = 0.02


def attach_elastic_cages(model, n_modes: int, ring: dict | None = None,
                         modal_damping: float = DEFAULT_MODAL_DAMPING, cage_mass_given: bool = False) -> None:
    """Make every cage of ``model`` elastic with its ``n_modes`` lowest free–free modes (in place).

    ring : overrides of the assumed cage ring (:func:`bearingsim.cage_modes.default_cage_ring`), SI
        values by :class:`bearingsim.cage_modes.CageRing` field name (e.g. ``axial_width``,
        ``radial_thickness``, ``pocket_diameter``, ``young_modulus``, ``density``); the pitch radius,
        pocket count and first pocket azimuth always come from the bearing row.
    modal_damping : ζ [-] of every mode.
    The cage's mass and moments of inertia become those of the finite-element ring, so that the
    rigid and elastic parts describe one body; giving a cage mass as well is refused.  The ring's
    normal-stress shapes (:func:`bearingsim.cage_modes.stress_shapes`) are kept for the output
    ``cage_peak_stress``.
    """
    from .. import cage_modes as cmod

    if not isinstance(n_modes, int) or isinstance(n_modes, bool) or n_modes < 0:
        raise InputError("cage.n_modes", f"must be a whole number ≥ 0, got {n_modes!r}", "0 for a rigid cage, e.g. 20")
    if n_modes == 0:
        return
    if cage_mass_given:
        raise InputError("cage.mass", "an elastic cage takes its mass from its ring geometry and density",
                         "drop cage.mass, or give density / axial_width / radial_thickness")
    if not (math.isfinite(modal_damping) and 0 <= modal_damping < 1):
        raise InputError("cage.modal_damping", f"must lie in [0, 1), got {modal_damping!r}", "e.g. 0.02")
    ring = dict(ring or {})
    fixed = {"pitch_radius", "pocket_count", "first_pocket_azimuth"} & set(ring)
    if fixed:
        raise InputError(f"cage.{sorted(fixed)[0]}", "comes from the bearing geometry", "drop it from [cage]")
    cp = model.cp
    fes, zmax, solved = [], 0, {}
    for c in range(model.n_cages):
        z = int(cp[c, C_Z])
        row = model.rows[model.ball_row[int(cp[c, C_BALL0])]]
        base = cmod.default_cage_ring(float(row[kn.P_D]), 2.0 * float(cp[c, C_RP]), z)
        try:
            spec = dataclasses.replace(base, pitch_radius=float(cp[c, C_RP]),
                                       first_pocket_azimuth=float(cp[c, C_PSI0]), **ring)
        except TypeError as exc:
            raise InputError("cage", f"unknown cage ring field ({exc})",
                             "use axial_width, radial_thickness, pocket_diameter, young_modulus, poisson, density")
        if spec not in solved:  # the rows of a double-row unit usually share one cage design
            modes = cmod.cage_modes(spec, n_modes)
            solved[spec] = (modes, cmod.stress_shapes(modes))
        fes.append(solved[spec])
        zmax = max(zmax, z)
    cm = np.zeros((model.n_cages, n_modes, 2 + 6 * zmax))
    m0 = N_RING + N_BALL * model.n_balls + N_CAGE * model.n_cages
    model.cage_stress = [s for _, s in fes]
    fes = [f for f, _ in fes]
    for c, fe in enumerate(fes):
        z = int(cp[c, C_Z])
        cm[c, :, 0] = fe.omega
        cm[c, :, 1] = 2.0 * modal_damping * fe.omega
        cm[c, :, 2:2 + 6 * z] = np.asarray(fe.shapes).reshape(n_modes, 6 * z)
        cp[c, C_NMODES] = n_modes
        cp[c, C_MODE0] = m0 + 2 * n_modes * c
        cp[c, C_MASS] = fe.mass
        cp[c, C_IP] = fe.polar_inertia
        cp[c, C_IT] = fe.transverse_inertia
    model.cage_modes = cm
    model.cage_fe = fes
