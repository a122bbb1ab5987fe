"""The two-material harmonic FE (a ring bonded to a seat sleeve of another material, issue 16) against the
closed form of a compound (shrink-fit type, bonded) thick cylinder under internal pressure.

Lamé in each layer k: u = A_k r + B_k / r, σ_r = E_k/(1 − ν²) [(1 + ν) A_k − (1 − ν) B_k / r²]
(Timoshenko & Goodier, Theory of Elasticity, §28; the compound cylinder: Ugural & Fenster, Advanced Strength and
Applied Elasticity, §8.5); conditions σ_r(a) = −p, σ_r(c) = 0, u and σ_r continuous at the interface b.  With
ν = 0 in both layers the open-ended (free faces) cylinder is in a plane state exactly (ε_z = 0 everywhere, no
interface shear), so the FE must reproduce it to its discretisation error (quadratic elements, h⁴ at the nodes).
"""

import numpy as np
import pytest

from bearingsim.rings.axisymmetric import HarmonicRing
from bearingsim.rings.section import mesh_rectangle


def _compound(a, b, c, e1, e2, p, radii):
    """u_r [m] of the bonded two-layer cylinder (ν = 0) at ``radii``."""
    # unknowns A1, B1, A2, B2; σ_r = E (A − B/r²) for ν = 0
    m = np.array([[e1, -e1 / a ** 2, 0.0, 0.0],
                  [0.0, 0.0, e2, -e2 / c ** 2],
                  [b, 1.0 / b, -b, -1.0 / b],
                  [e1, -e1 / b ** 2, -e2, e2 / b ** 2]])
    a1, b1, a2, b2 = np.linalg.solve(m, np.array([-p, 0.0, 0.0, 0.0]))
    r = np.asarray(radii)
    return np.where(r <= b, a1 * r + b1 / r, a2 * r + b2 / r)


@pytest.mark.parametrize("e2_over_e1", [0.35, 3.0])
def test_compound_cylinder_two_materials(e2_over_e1):
    a, b, c, p, e1 = 0.02, 0.03, 0.045, 1.0e7, 2.0e11
    e2 = e2_over_e1 * e1
    mesh = mesh_rectangle(a, c, 0.01, 10, 4)  # interface b = 0.03 on a node line (10 layers of 2.5 mm)
    ring = HarmonicRing(mesh, e1, 0.0, free=True, second_material=(lambda x: x[0] > b, e2, 0.0))
    u_fe = ring.probe(np.vstack([[a, b, c], np.zeros(3)])) @ ring.solve(0, ring.pressure_load("inner", p))
    exact = _compound(a, b, c, e1, e2, p, [a, b, c])
    one = _compound(a, b, c, e1, e1, p, [a, b, c])
    assert abs(exact[0] / one[0] - 1) > 0.05  # the second material matters here
    # nodal error h⁴: 3e-5 (5 layers), 2e-6 (10), 1.3e-7 (20) for both ratios
    np.testing.assert_allclose(u_fe[:3], exact, rtol=1e-5,
                               err_msg="compound thick cylinder, Lamé per layer (Timoshenko & Goodier §28)")
