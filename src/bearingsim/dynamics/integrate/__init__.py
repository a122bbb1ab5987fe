"""Time integrators of the dynamic engine, in the shape of scipy's ``integrate._ivp``.

=====================  =====================================================================
:mod:`.base`           the contract: :class:`Workspace` and ``advance(workspace, t_end) -> status``
:mod:`.common`         status codes (:class:`Status`, :data:`STATUS_TEXT`), error norm, step-size
                       control, step clipping
:mod:`.dopri5`         DOPRI5, explicit Runge–Kutta 5(4) — the default without traction or with the
                       Coulomb stand-in
:mod:`.ros2`           ROS2, second-order W-method (per-ball block Jacobian)
:mod:`.ros34pw2`       ROS34PW2, third-order W-method — the default with the lubricated traction
                       kernel, with the inner ring's block and its coupling with the balls in J
:mod:`.jacobian`       finite-difference Jacobians of the W-methods
:mod:`.linalg`         W = I − γhJ: per-ball block inverses and the arrowhead (Schur complement) solve
:mod:`.specialised`    the methods' kernels specialised for the engine's right-hand sides
                       (``forces.rhs_args``, ``rhs_args_threaded``), cached on disk
=====================  =====================================================================

Every method: ``METHODS[name].advance(ws, t_end)`` integrates a :class:`Workspace` to exactly t_end
and returns a :class:`Status`; the numba kernel behind it is ``METHODS[name].integrate(...)``.
Why these methods and their measured costs: docs/dynamics.md.

The names of the former single module stay importable from here: ``advance`` (the DOPRI5 kernel,
:func:`.dopri5.integrate`), ``advance_ros2``, ``advance_ros34``, ``fixed_steps``,
``fixed_steps_ros34``, ``ros34_workspace``, ``no_coupling``, ``NR``, the status codes and tableau
constants, and the linear-algebra helpers under their former private names.
"""

from __future__ import annotations

from . import dopri5, ros2, ros34pw2
from .base import INFO_SIZE, Workspace, ros34_workspace
from .common import MAX_STEPS, NOT_FINITE, OK, STATUS_TEXT, STEP_TOO_SMALL, Status, clip_step, error_norm
from .dopri5 import (  # noqa: F401
    A21,
    A31,
    A32,
    A41,
    A42,
    A43,
    A51,
    A52,
    A53,
    A54,
    A61,
    A62,
    A63,
    A64,
    A65,
    B1,
    B3,
    B4,
    B5,
    B6,
    C2,
    C3,
    C4,
    C5,
    E1,
    E3,
    E4,
    E5,
    E6,
    E7,
    fixed_steps,
)
from .dopri5 import integrate as advance  # the former name of the DOPRI5 kernel
from .jacobian import block_jac, ring_jac, ring_rows
from .linalg import (
    NR,
    apply_w,
    block_w_inverse,
    coupled_apply_w,
    coupled_w,
    invert_small,
    kinematic_rows,
    no_coupling,
    w_inverse,
    w_solve,
)
from .ros2 import ROS2_GAMMA
from .ros2 import integrate as advance_ros2
from .ros34pw2 import (  # noqa: F401
    R34_A21,
    R34_A31,
    R34_A32,
    R34_A41,
    R34_A42,
    R34_A43,
    R34_ALPHA2,
    R34_ALPHA3,
    R34_ALPHA4,
    R34_C21,
    R34_C31,
    R34_C32,
    R34_C41,
    R34_C42,
    R34_C43,
    R34_E,
    R34_G,
    R34_GROW,
    R34_KI,
    R34_KP,
    R34_M,
)
from .ros34pw2 import fixed_steps as fixed_steps_ros34
from .ros34pw2 import integrate as advance_ros34

#: integrator name (``Case.integrator``, ``Stepper.method``) → its module
METHODS = {"dopri5": dopri5, "ros2w": ros2, "ros34w": ros34pw2}

# former private names (tests and scripts)
_error_norm = error_norm
_clip_step = clip_step
_block_jac = block_jac
_ring_jac = ring_jac
_ring_rows = ring_rows
_apply_w = apply_w
_invert_small = invert_small
_kinematic_rows = kinematic_rows
_w_inverse = w_inverse
_coupled_w = coupled_w
_coupled_apply_w = coupled_apply_w
_stages = dopri5.stages
_ros34_stages = ros34pw2.stages

__all__ = ["INFO_SIZE", "METHODS", "MAX_STEPS", "NOT_FINITE", "NR", "OK", "R34_G", "ROS2_GAMMA", "STATUS_TEXT",
           "STEP_TOO_SMALL", "Status", "Workspace", "advance", "advance_ros2", "advance_ros34", "block_w_inverse",
           "fixed_steps", "fixed_steps_ros34", "no_coupling", "ros34_workspace", "w_solve"]


def advance_workspace(ws: Workspace, t_end: float, method: str) -> Status:
    """``METHODS[method].advance(ws, t_end)``: integrate ``ws`` to t_end [s] with the named method."""
    return METHODS[method].advance(ws, t_end)

