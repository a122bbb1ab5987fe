"""Pure axial (thrust) load without inertial forces, and Palmgren's axial stiffness.

[S0] section 2.1 (after Harris & Kotzalas 2007 vol. 1 ch. 7).  With A = (f_i + f_o − 1) D,
K_n the ball's combined load–deflection constant and Z balls equally loaded:

    Fa / (Z K_n A^1.5) = sin α (cos α₀ / cos α − 1)^1.5          ([S0] eq. 3)
    cos α = cos α₀ / [1 + (Fa / (Z K_n A^1.5 sin α))^(2/3)]        ([S0] eq. 4, fixed point)
    δa = A sin(α − α₀) / cos α                                      ([S0] eq. 5)
    Ca = dFa/dδa                                                     ([S0] eq. 6)

Ca in closed form, with c = cos α₀ / cos α:
    dFa/dα = Z K_n A^1.5 [cos α (c − 1)^1.5 + 1.5 tan²α cos α₀ (c − 1)^0.5]
    dδa/dα = A cos α₀ / cos²α
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..errors import InputError
from ..units import api_quantity


@dataclass(frozen=True)
class ThrustSolution:
    """Contact angle and axial deflection under a centric thrust load (all SI)."""

    axial_load: float  #: Fa [N]
    contact_angle: float  #: loaded contact angle α [rad]
    axial_deflection: float  #: δa [m]
    normal_approach: float  #: δn per ball [m]
    ball_load: float  #: Q = Fa / (Z sin α) [N]
    axial_stiffness: float  #: Ca = dFa/dδa [N/m]
    converged: bool
    iterations: int
    method: str


def thrust_load_of_angle(alpha: float, free_angle: float, z: int, kn: float, big_a: float) -> float:
    """Fa(α) = Z K_n A^1.5 sin α (cos α₀/cos α − 1)^1.5  [N]  ([S0] eq. 3)."""
    c = math.cos(free_angle) / math.cos(alpha) - 1.0
    return z * kn * big_a**1.5 * math.sin(alpha) * max(c, 0.0) ** 1.5


def contact_angle_fixed_point(fa: float, free_angle: float, z: int, kn: float, big_a: float,
                              tol: float = 1e-12, maxiter: int = 500) -> tuple[float, bool, int]:
    """The fixed-point iteration on cos α of [S0] (eq. 4), started from α₁ = α₀.

    Returns (α [rad], converged, iterations).  The iteration is a contraction for usual
    spindle-bearing loads but may fail for α₀ = 0 (deep-groove bearings: sin α₀ = 0 gives
    an infinite first step); use :func:`contact_angle_bracketed` then.
    """
    c = fa / (z * kn * big_a**1.5)
    alpha = free_angle
    for it in range(1, maxiter + 1):
        s = math.sin(alpha)
        if s <= 0.0:
            return alpha, False, it
        new = math.acos(math.cos(free_angle) / (1.0 + (c / s) ** (2.0 / 3.0)))
        if abs(new - alpha) <= tol:
            return new, True, it
        alpha = new
    return alpha, False, maxiter


def contact_angle_bracketed(fa: float, free_angle: float, z: int, kn: float, big_a: float,
                            tol: float = 1e-14) -> tuple[float, int]:
    """Loaded contact angle by Brent's method on [α₀, π/2) (always converges; Fa(α) is monotonic)."""
    from scipy.optimize import brentq  # imported here: scipy.optimize costs ~0.3 s at start-up

    if fa == 0.0:
        return free_angle, 0
    hi = 0.5 * math.pi - 1e-12
    g = lambda a: thrust_load_of_angle(a, free_angle, z, kn, big_a) - fa  # noqa: E731
    a, r = brentq(g, free_angle, hi, xtol=tol, rtol=8.9e-16, full_output=True)
    return a, r.iterations


def axial_stiffness_closed_form(alpha: float, free_angle: float, z: int, kn: float, big_a: float) -> float:
    """Ca = dFa/dδa  [N/m] at the loaded contact angle α (derivation in the module docstring)."""
    c = max(math.cos(free_angle) / math.cos(alpha) - 1.0, 0.0)
    dfa = z * kn * big_a**1.5 * (math.cos(alpha) * c**1.5
                                  + 1.5 * math.tan(alpha) ** 2 * math.cos(free_angle) * c**0.5)
    dda = big_a * math.cos(free_angle) / math.cos(alpha) ** 2
    return dfa / dda


def solve_thrust(bearing, fa: float, method: str = "bracketed") -> ThrustSolution:
    """Contact angle, deflection and axial stiffness of ``bearing`` under thrust ``fa`` (the [S0] model without
    inertia, [S0] §2.1). K_n is evaluated at α₀ (see :attr:`BallBearing.contact_constants`).

    Parameters
    ----------
    bearing : BallBearing
        A single angular contact row.
    fa : float, str or pint.Quantity
        Centric thrust load [N] (a float in N, a string with its unit or a pint Quantity:
        :func:`bearingsim.units.api_quantity`).
    method : str
        ``"bracketed"`` (Brent, always converges) or ``"fixed_point"`` ([S0] eq. 4).

    Returns
    -------
    ThrustSolution
        Loaded contact angle [rad], axial deflection [m], ball load [N] and the closed-form axial stiffness
        Ca = dFa/dδa [N/m].
    """
    import numbers

    fa = api_quantity(fa, "force", "fa")
    if isinstance(fa, bool) or not isinstance(fa, numbers.Real):
        from ..errors import InputTypeError

        raise InputTypeError("fa", f"must be a real number, got {type(fa).__name__} {fa!r}",
                             "pass the thrust load as a float in N (parse units at the edge)")
    if not isinstance(method, str):
        raise InputError("method", f"unknown method {method!r}", 'use "bracketed" or "fixed_point"')
    fa = float(fa)
    if not (math.isfinite(fa) and fa >= 0.0):
        raise InputError("fa", f"axial load must be finite and ≥ 0, got {fa!r} N", "give a thrust load in N")
    a0 = bearing.free_contact_angle
    z = bearing.ball_count
    kn = bearing.contact_constants[2]
    big_a = bearing.total_curvature_distance
    if method == "fixed_point":
        if fa == 0.0:
            alpha, conv, it = a0, True, 0
        else:
            alpha, conv, it = contact_angle_fixed_point(fa, a0, z, kn, big_a)
    elif method == "bracketed":
        alpha, it = contact_angle_bracketed(fa, a0, z, kn, big_a)
        conv = True
    else:
        raise InputError("method", f"unknown method {method!r}", 'use "bracketed" or "fixed_point"')
    dn = big_a * (math.cos(a0) / math.cos(alpha) - 1.0)
    da = big_a * math.sin(alpha - a0) / math.cos(alpha)
    q = fa / (z * math.sin(alpha)) if alpha > 0 else 0.0
    ca = axial_stiffness_closed_form(alpha, a0, z, kn, big_a)
    return ThrustSolution(fa, alpha, da, dn, q, ca, conv, it, method)


def palmgren_axial_deflection(fa: float, z: int, ball_diameter: float, contact_angle: float) -> float:
    """Palmgren's axial deflection of an angular contact ball bearing [m].

    δa = 4.4×10⁻⁴ / sin α · (Q² / D_w)^(1/3)  [mm, with Q in N and D_w in mm],
    Q = Fa / (Z sin α)  (Palmgren, *Ball and Roller Bearing Engineering*, 1959;
    NSK catalogue form; steel on steel).
    """
    q = fa / (z * math.sin(contact_angle))
    dw_mm = ball_diameter * 1e3
    return 4.4e-4 / math.sin(contact_angle) * (q * q / dw_mm) ** (1.0 / 3.0) * 1e-3


def palmgren_axial_stiffness(fa: float, z: int, ball_diameter: float, contact_angle: float) -> float:
    """Ca = dFa/dδa of Palmgren's formula at constant α: Ca = 1.5 Fa / δa  [N/m]."""
    if fa <= 0.0:
        return 0.0
    return 1.5 * fa / palmgren_axial_deflection(fa, z, ball_diameter, contact_angle)
