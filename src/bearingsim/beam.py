"""Shear-deformable (Timoshenko) beam elements: the one formula shared by the cage's frame ring
(:mod:`bearingsim.cage_modes`) and the shaft (:mod:`bearingsim.shafts`).

Element (Przemieniecki, *Theory of Matrix Structural Analysis*, 1968: ch. 5, beam element with shear
deformation; ch. 11, consistent mass): axial and torsion with linear interpolation; bending in each
principal plane with the shear-deformable stiffness, Φ = 12 E I / (κ G A L²), which reduces exactly to
Euler–Bernoulli at Φ = 0.  Consistent mass: cubic Hermite translational mass plus rotary inertia ρI (the
Φ = 0 mass: it reproduces rigid-body motion exactly and converges under mesh refinement).  Gyroscopic matrix
of a spinning element from the same rotary-inertia shape functions with the polar inertia ρ I_p (Nelson &
McVaugh, J. Eng. Ind. 98 (1976) 593, with Φ = 0).

Units: SI throughout — lengths [m], E, G [Pa], ρ [kg/m³], A [m²], I [m⁴].
"""

from __future__ import annotations

import math

import numpy as np

# local DOF order per node of the 3-D frame: u, v, w, θx', θy', θz'; element DOFs 0-5 node a, 6-11 node b
_BEND_XY = (1, 5, 7, 11)  # v1, θz1, v2, θz2 (bending in the x'-y' plane, about z')
_BEND_XZ = (2, 4, 8, 10)  # w1, θy1, w2, θy2 (bending in the x'-z' plane, about y')
_FLIP = np.diag([1.0, -1.0, 1.0, -1.0])  # θy' = −dw/dx' : x'-z' matrices from the x'-y' ones


def cowper_circular(poisson: float, diameter_ratio: float = 0.0) -> float:
    """Timoshenko shear coefficient κ [-] of a solid or hollow circular section (Cowper, J. Appl. Mech. 33
    (1966) 335, table 1): κ = 6(1+ν)(1+m²)² / [(7+6ν)(1+m²)² + (20+12ν)m²], m = d_i/d_o [-]; m = 0 gives the
    solid circle 6(1+ν)/(7+6ν)."""
    m2 = diameter_ratio * diameter_ratio
    a = (1.0 + m2) ** 2
    return 6.0 * (1.0 + poisson) * a / ((7.0 + 6.0 * poisson) * a + (20.0 + 12.0 * poisson) * m2)


def shear_parameter(E: float, i: float, kappa: float, G: float, A: float, L: float) -> float:
    """Φ = 12 E I / (κ G A L²) [-] (Przemieniecki 1968, eq. 5.101): bending over shear flexibility."""
    return 12.0 * E * i / (kappa * G * A * L**2)


def bend_stiffness(ei: float, L: float, phi: float) -> np.ndarray:
    """Shear-deformable bending stiffness (v1, θ1, v2, θ2), θ = dv/dx (Przemieniecki 1968, ch. 5)
    [N/m, N, N·m/rad]."""
    c = ei / ((1.0 + phi) * L**3)
    return c * np.array([[12.0, 6 * L, -12.0, 6 * L],
                         [6 * L, (4 + phi) * L**2, -6 * L, (2 - phi) * L**2],
                         [-12.0, -6 * L, 12.0, -6 * L],
                         [6 * L, (2 - phi) * L**2, -6 * L, (4 + phi) * L**2]])


def _rotary_shape(L: float) -> np.ndarray:
    """∫ N'ᵀ N' dx of the cubic Hermite slopes over (v1, θ1, v2, θ2) [1/m … m] (Przemieniecki 1968, ch. 11)."""
    return np.array([[36.0, 3 * L, -36.0, 3 * L],
                     [3 * L, 4 * L**2, -3 * L, -L**2],
                     [-36.0, -3 * L, 36.0, -3 * L],
                     [3 * L, -L**2, -3 * L, 4 * L**2]]) / (30.0 * L)


def bend_mass(rho_a: float, rho_i: float, L: float) -> np.ndarray:
    """Consistent bending mass (v1, θ1, v2, θ2): Hermite translational + rotary inertia
    (Przemieniecki 1968, ch. 11, with Φ = 0) [kg, kg·m, kg·m²]; ρA [kg/m], ρI [kg·m]."""
    mt = rho_a * L / 420.0 * np.array([[156.0, 22 * L, 54.0, -13 * L],
                                       [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                                       [54.0, 13 * L, 156.0, -22 * L],
                                       [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    return mt + rho_i * _rotary_shape(L)


def element_matrices(L: float, sec: dict, E: float, G: float, rho: float, kappa: float,
                     shear: bool, rotary: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """Local 12 × 12 stiffness and consistent mass of a straight 3-D frame element [SI].

    Local axes: x' element axis; I_z' = sec["I_in"] (bending in the x'-y' plane), I_y' = sec["I_out"]
    (bending in the x'-z' plane); sec also holds "A" [m²], "J" (torsion) and "I_p" [m⁴].
    """
    A, i_in, i_out, J, ip = sec["A"], sec["I_in"], sec["I_out"], sec["J"], sec["I_p"]
    r = 1.0 if rotary else 0.0
    k = np.zeros((12, 12))
    m = np.zeros((12, 12))
    bar = np.array([[1.0, -1.0], [-1.0, 1.0]])
    lin = np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
    ax, tw = [0, 6], [3, 9]
    k[np.ix_(ax, ax)] = E * A / L * bar
    k[np.ix_(tw, tw)] = G * J / L * bar
    m[np.ix_(ax, ax)] = rho * A * L * lin
    m[np.ix_(tw, tw)] = r * rho * ip * L * lin
    phi_y = shear_parameter(E, i_in, kappa, G, A, L) if shear else 0.0
    phi_z = shear_parameter(E, i_out, kappa, G, A, L) if shear else 0.0
    ixy, ixz = list(_BEND_XY), list(_BEND_XZ)
    k[np.ix_(ixy, ixy)] = bend_stiffness(E * i_in, L, phi_y)
    k[np.ix_(ixz, ixz)] = _FLIP @ bend_stiffness(E * i_out, L, phi_z) @ _FLIP
    m[np.ix_(ixy, ixy)] = bend_mass(rho * A, r * rho * i_in, L)
    m[np.ix_(ixz, ixz)] = _FLIP @ bend_mass(rho * A, r * rho * i_out, L) @ _FLIP
    return k, m


# shaft element: 5 DOF per node (x, y, z, γy, γz), element DOFs 0-4 node a, 5-9 node b
_SHAFT_AX = (0, 5)
_SHAFT_XY = (1, 4, 6, 9)  # y1, γz1, y2, γz2 (γz = dy/dx)
_SHAFT_XZ = (2, 3, 7, 8)  # z1, γy1, z2, γy2 (γy = −dz/dx)


def shaft_element_matrices(L: float, E: float, G: float, rho: float, A: float, i: float, kappa: float,
                           shear: bool = True) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """10 × 10 stiffness K, consistent mass M and gyroscopic matrix per unit spin G₁ of an axisymmetric shaft
    element with nodal DOF (x, y, z, γy, γz) [m, rad]: the bar and the two bending planes of
    :func:`element_matrices` (torsion omitted), I = I_y = I_z [m⁴], polar I_p = 2I.

    G₁ couples the planes: the equations of motion are M q̈ + Ω G₁ q̇ + K q = F at spin Ω [rad/s] about +x;
    for a rigid disc G₁ reduces to I_p [[0, 1], [−1, 0]] on (γy, γz) (H = I_p Ω e_x + I_d γ̇, dH/dt = M;
    Nelson & McVaugh 1976 with Φ = 0).  Units: K [N/m …], M [kg …], G₁ [kg·m² …].
    """
    phi = shear_parameter(E, i, kappa, G, A, L) if shear else 0.0
    k = np.zeros((10, 10))
    m = np.zeros((10, 10))
    g = np.zeros((10, 10))
    ax, ixy, ixz = list(_SHAFT_AX), list(_SHAFT_XY), list(_SHAFT_XZ)
    k[np.ix_(ax, ax)] = E * A / L * np.array([[1.0, -1.0], [-1.0, 1.0]])
    m[np.ix_(ax, ax)] = rho * A * L * np.array([[2.0, 1.0], [1.0, 2.0]]) / 6.0
    k[np.ix_(ixy, ixy)] = bend_stiffness(E * i, L, phi)
    k[np.ix_(ixz, ixz)] = _FLIP @ bend_stiffness(E * i, L, phi) @ _FLIP
    mb = bend_mass(rho * A, rho * i, L)
    m[np.ix_(ixy, ixy)] = mb
    m[np.ix_(ixz, ixz)] = _FLIP @ mb @ _FLIP
    # θy(x) = −N'(x) F a_xz, θz(x) = N'(x) a_xy: virtual work of the gyroscopic moment ρ I_p Ω (θ̇z, −θ̇y)
    gxz = -rho * 2.0 * i * (_FLIP @ _rotary_shape(L))
    g[np.ix_(ixz, ixy)] = gxz
    g[np.ix_(ixy, ixz)] = -gxz.T
    return k, m, g


def circular_section(outer_diameter: float, inner_diameter: float = 0.0) -> tuple[float, float]:
    """(A [m²], I [m⁴]) of a solid or hollow circle: A = π(d_o² − d_i²)/4, I = π(d_o⁴ − d_i⁴)/64."""
    return (math.pi * (outer_diameter**2 - inner_diameter**2) / 4.0,
            math.pi * (outer_diameter**4 - inner_diameter**4) / 64.0)
