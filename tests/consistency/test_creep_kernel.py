"""The sliced traction kernel's small-slip slope equals traction.creep_slope (issue 13 item 4, brief HC item 3b):
film alone (traction_compliance = "film") and film + solids in series ("film+solids", Kalker's simplified-theory
flexibility L₁ = 8 a_r/(3 C₁₁ G), slices.pack_lubrication_parameters(solids=...)).

Set-up: a ball rolling on a flat race (the contact plane z = 0, rolling along y, the major axis along x) with a
symmetric slip ±s; slope = (F(−s) − F(s))/(2 s Q).  The film's elastic modulus is made uniform over the contact
(Dyson's law replaced by a constant: c₁ = 0, c₄ = −G_f, no floor) and its viscosity very high (Roelands
ln η₀ + 9.67 → 40), so that every strip is in the elastic limit of the Maxwell film (Deborah number ≫ 1) — the
regime creep_slope describes.  (With the real oil the low-pressure edge strips are viscous, and the kernel's
slope is a few per cent lower: measured 3.3 % on this contact.)

The kernel's strips have their mean chord, so its film slope is creep_slope × Σ_j ℓ_j² w/∫ ℓ² dy (Jensen: below
1, → 1 with the strip count); that factor is computed here from the geometry alone.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from bearingsim.contact import ehl, hertz
from bearingsim.contact import slices as S
from bearingsim.contact import traction as tr

D, DM, F_I, Q, U = 0.0111, 0.061, 0.52, 800.0, 2.0
E_EFF = hertz.effective_modulus(208e9, 0.3, 208e9, 0.3)
RX, RY = hertz.raceway_radii(D, DM, F_I, math.radians(35.0), True)
HC = hertz.point_contact_exact(Q, RX, RY, E_EFF)
G_SOLID, NU = 208e9 / 2.6, 0.3
G_FILM = 0.4e9


def _lub(solids=None):
    lub = S.pack_lubrication_parameters("hub-grease-base-oil", 313.15, E_EFF, RX, RY, 0.0, model="fluid",
                                        thermal=False, rolling_resistance=False, solids=solids)
    lub[S.L_LSS_C1] = 0.0
    lub[S.L_LSS_C4] = -G_FILM  # τ_L = r_L G_f: the kernel's film modulus τ_L/r_L = G_f everywhere
    lub[S.L_LSS_FLOOR] = 0.0
    lub[S.L_ROE_LN] = 40.0
    return lub


def _force(s, lub, n):
    out = np.zeros(10)
    r = 0.5 * D
    S.contact_traction(Q, HC.a, HC.b, math.inf, np.zeros(3), np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]),
                       np.array([0.0, 0.0, r]), np.zeros(3), np.array([U * (1 + 0.5 * s) / r, 0.0, 0.0]),
                       np.array([0.0, 0.0, -1.0]), np.array([0.0, U * (1 - 0.5 * s), 0.0]), np.zeros(3), lub, n, out)
    return out[1]


def _kernel_slope(lub, n, s=1e-7):
    return (_force(-s, lub, n) - _force(s, lub, n)) / (2 * s * Q)


def _strip_factor(n):
    """Σ_j ℓ_j² w / ∫ ℓ² dy for n equal strips across the major axis (ℓ_j = strip area / strip width)."""
    h = lambda z: z * math.sqrt(max(0.0, 1 - z * z)) + math.asin(z)  # noqa: E731  (area primitive / (a b))
    xs = np.linspace(-1.0, 1.0, n + 1)
    areas = np.array([h(x1) - h(x0) for x0, x1 in zip(xs[:-1], xs[1:])])  # / (a b)
    w = 2.0 / n  # / a
    return float(np.sum((areas / w) ** 2 * w) / (16.0 / 3.0))  # ∫ ℓ² dy / (a b²) = 16/3


@pytest.mark.parametrize("n", [8, 64])
@pytest.mark.parametrize("solids", [False, True])
def test_kernel_small_slip_slope_is_creep_slope(n, solids):
    lub = _lub((G_SOLID, NU) if solids else None)
    h = ehl.hamrock_dowson_central(U, Q, lub[S.L_ETA0], lub[S.L_ALPHA], E_EFF, RX, RY)
    # rolling direction = the minor semi-axis b; the solids in series give the same strip factor when G_f is uniform
    want = tr.creep_slope(Q, HC.b, HC.a, G_SOLID, NU, G_FILM, h, solids=solids) * _strip_factor(n)
    assert _kernel_slope(lub, n) == pytest.approx(want, rel=2e-6)


def test_the_solids_matter_on_this_contact():
    """The series compliance is not a rounding detail here: the solids halve the slope (film 72, series 37)."""
    k_film = _kernel_slope(_lub(), 64)
    k_series = _kernel_slope(_lub((G_SOLID, NU)), 64)
    assert 0.4 < k_series / k_film < 0.6


def test_film_modulus_factor_scales_the_film_slope():
    lub2 = _lub()
    lub2[S.L_GF_SCALE] = 2.0
    assert _kernel_slope(lub2, 16) == pytest.approx(2.0 * _kernel_slope(_lub(), 16), rel=1e-6)
