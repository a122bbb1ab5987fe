"""Output of a dynamic run: the variable schema, the netCDF file it streams to, and checkpoints.

:data:`VARIABLES` names every output quantity with its dimensions, units (UDUNITS strings, or one per
component along ``dof``, as :func:`bearingsim.io.netcdf.units_attributes` takes them) and long name;
:func:`stack_samples` stacks the samples of :meth:`.stepper.Stepper.sample` along time and
:func:`to_dataset` makes an xarray Dataset of them.  :class:`_Writer` appends samples to a netCDF-3
file through :class:`bearingsim.io.netcdf.NetCDFWriter` (the one writer of the package).  A checkpoint
(``OUT.ckpt.npz``, :func:`_save_checkpoint` / :func:`_read_checkpoint`) holds what a resumed run needs
to repeat the same steps: t, y, the step size, the step counts, the output index, the integrator's
Jacobian and, with dense output, its last step (:attr:`.stepper.Stepper.dense`); it is written under a temporary
name and renamed into place.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..io import netcdf as nc
from . import model as md

#: output variables: name -> (dims, units, long name); units as :func:`bearingsim.io.netcdf.units_attributes`
#: takes them (a UDUNITS string, or one per component along ``dof``)
VARIABLES = {
    "inner_ring_displacement": (("time", "dof"), nc.DOF_UNITS, "inner-ring displacement (x, y, z, gamma_y, gamma_z)"),
    "inner_ring_velocity": (("time", "dof"), nc.DOF_RATE_UNITS, "inner-ring velocity"),
    "applied_load": (("time", "dof"), nc.LOAD_UNITS, "applied load (Fa, Fr_y, Fr_z, M_y, M_z) at the load point"),
    "shaft_speed": (("time",), "rad/s", "inner-ring (shaft) speed"),
    "cage_angular_speed": (("time", "cage"), "rad/s", "cage angular speed about the bearing axis"),
    "cage_angle": (("time", "cage"), "rad", "cage rotation angle about the bearing axis"),
    "cage_position": (("time", "cage", "xyz"), "m", "cage centre displacement"),
    "ball_orbital_speed": (("time", "ball"), "rad/s", "ball orbital (revolution) speed"),
    "ball_spin_speed": (("time", "ball"), "rad/s", "ball spin speed relative to the orbiting frame (Jones sign)"),
    "ball_pitch_angle": (("time", "ball"), "rad", "ball spin-axis pitch angle beta"),
    "inner_contact_load": (("time", "ball"), "N", "ball-inner raceway normal load"),
    "outer_contact_load": (("time", "ball"), "N", "ball-outer raceway normal load"),
    "inner_contact_angle": (("time", "ball"), "rad", "inner contact angle"),
    "outer_contact_angle": (("time", "ball"), "rad", "outer contact angle"),
    "inner_approach": (("time", "ball"), "m", "inner contact approach (negative: gap)"),
    "outer_approach": (("time", "ball"), "m", "outer contact approach (negative: gap)"),
    "inner_slide_roll_ratio": (("time", "ball"), "1", "slide-roll ratio at the inner contact centre"),
    "outer_slide_roll_ratio": (("time", "ball"), "1", "slide-roll ratio at the outer contact centre"),
    "inner_power_loss": (("time", "ball"), "W", "power loss of the ball-inner raceway contact"),
    "outer_power_loss": (("time", "ball"), "W", "power loss of the ball-outer raceway contact"),
    "cage_contact_load": (("time", "ball"), "N", "ball-pocket normal load"),
    "cage_power_loss": (("time", "ball"), "W", "power loss of the ball-pocket contact"),
    "inner_ring_friction_torque": (("time",), "N m", "moment of the contact forces on the inner ring about its axis"),
    "outer_ring_friction_torque": (("time",), "N m", "moment of the contact forces on the outer ring about x"),
    "power_loss_inner": (("time",), "W", "total power loss at the ball-inner raceway contacts"),
    "power_loss_outer": (("time",), "W", "total power loss at the ball-outer raceway contacts"),
    "power_loss_cage": (("time",), "W", "total power loss at the ball-pocket contacts"),
    "power_loss_land": (("time",), "W", "power loss at the cage guiding land"),
    "power_loss_rolling": (("time",), "W", "share of the raceway power loss due to rolling viscous resistance "
                           "(included in power_loss_inner/outer)"),
    "contact_potential_energy": (("time",), "J", "elastic energy stored in all contacts"),
    "cage_strain_energy": (("time",), "J", "elastic strain energy of the cages' modes (0 for rigid cages)"),
    "cage_pocket_deformation": (("time", "cage"), "m",
                                "largest elastic displacement of a pocket centre (0 for a rigid cage)"),
    "cage_peak_stress": (("time", "cage"), "Pa",
                         "largest normal stress magnitude in the cage ring (Navier, recovered quasi-statically from "
                         "the modal deformation; 0 for a rigid cage)"),
}


def stack_samples(samples: list[dict]) -> dict:
    """Stack a list of samples along time."""
    out = {"time": np.array([s["time"] for s in samples])}
    for k in VARIABLES:
        out[k] = np.stack([np.asarray(s[k]) for s in samples])
    return out


def to_dataset(data: dict, attrs: dict | None = None):
    """xarray Dataset of stacked samples with units in the attributes."""
    variables = [nc.Variable("time", ("time",), "s"), nc.Variable("dof", ("dof",), dtype=str), *_variables()]
    return nc.to_xarray(variables, data | {"dof": md.DOF}, attrs, coords=("time", "dof"))


def _variables() -> list:
    """:data:`VARIABLES` as :class:`bearingsim.io.netcdf.Variable` s (the schema of the file and the Dataset)."""
    return [nc.Variable(k, dims, units, desc) for k, (dims, units, desc) in VARIABLES.items()]



class _Writer:
    """Append samples to a netCDF-3 (64-bit offset) file with an unlimited time dimension, through
    :class:`bearingsim.io.netcdf.NetCDFWriter` (``publish="create"``: the header is written under a hidden
    temporary name and renamed; the records are appended in place).

    netCDF-3 keeps the record count in the header, which the library rewrites only when
    the file is synced: a process killed while writing a chunk leaves the file with the
    previous record count, i.e. the last complete chunk stays valid.
    """

    def __init__(self, path: Path, model: md.Model, attrs: dict, start_index: int | None):
        self.path = path
        if start_index is None or not path.exists():
            dims = {"time": None, "dof": 5, "ball": model.n_balls, "cage": model.n_cages, "xyz": 3}
            variables = [nc.Variable("time", ("time",), "s"), nc.Variable("ball", ("ball",), dtype="i4"),
                         nc.Variable("ball_row", ("ball",), dtype="i4"), *_variables()]
            self.file = nc.NetCDFWriter(path, dims=dims, variables=variables, attrs=attrs,
                                        values={"ball": np.arange(model.n_balls), "ball_row": model.ball_row},
                                        fmt="NETCDF3_64BIT_OFFSET", publish="create")
            start_index = 0
        else:
            self.file = nc.NetCDFWriter.reopen(path)
        self.index = start_index

    @property
    def ds(self):
        """The open netCDF4.Dataset."""
        return self.file.nc

    def write(self, samples: list[dict]) -> None:
        if not samples:
            return
        data = stack_samples(samples)
        i0, i1 = self.index, self.index + len(samples)
        for k in VARIABLES:
            self.file.write(k, slice(i0, i1), data[k])
        self.file.write("time", slice(i0, i1), data["time"])
        self.file.sync()
        self.index = i1

    def close(self):
        self.file.close()


# ---- checkpoints -------------------------------------------------------------------------
#: wall-clock seconds between checkpoints unless the case (``checkpoint_every = "10 s"``) or the caller
#: says otherwise: a run killed at any time loses at most this much work (plus one output interval)
CHECKPOINT_SECONDS = 30.0


def _checkpoint_path(out: Path) -> Path:
    return out.with_name(out.name + ".ckpt.npz")


def _read_checkpoint(ckpt: Path, out: Path, fingerprint: str):
    """The checkpoint's arrays, or ``(None, why)`` when there is nothing to resume from."""
    if not ckpt.exists():
        return None, f"no checkpoint {ckpt.name} (the run was stopped before its first one, or it had finished)"
    if not out.exists():
        return None, f"the checkpoint {ckpt.name} has no output file {out.name} to continue"
    try:
        with np.load(ckpt) as c:
            data = {k: c[k] for k in c.files}
    except (OSError, ValueError, EOFError) as exc:  # written by rename, so only a foreign or damaged file
        return None, f"the checkpoint {ckpt.name} cannot be read ({type(exc).__name__})"
    if str(data.get("fingerprint")) != fingerprint:
        raise InputError("--resume", "the checkpoint belongs to a different case", "resume with the same case")
    return data, ""


def _checkpoint_tmp(path: Path) -> Path:
    return path.with_name(path.name + ".tmp.npz")


def _save_checkpoint(path: Path, stepper, index: int, fingerprint: str) -> None:
    """Write the checkpoint of a :class:`~.stepper.Stepper` after ``index`` output records (temporary file, then
    renamed into place)."""
    tmp = _checkpoint_tmp(path)
    np.savez(tmp, t=stepper.t, h=stepper.h, y=stepper.y, index=index, steps=stepper.steps,
             rejected=stepper.rejected, fingerprint=fingerprint,
             **{f"jacobian_{i}": a for i, a in enumerate(stepper._ws)},
             **{f"dense_{i}": a for i, a in enumerate(stepper._dense or ())})
    os.replace(tmp, path)


def _restore_arrays(c: dict, prefix: str, arrays) -> None:
    """Copy the checkpoint's ``prefix_0``, ``prefix_1`` … into ``arrays`` in place, all or none (a checkpoint of an
    older version that lacks them, or holds other shapes, leaves them as they are)."""
    saved = [c.get(f"{prefix}_{i}") for i in range(len(arrays))]
    if all(v is not None and v.shape == a.shape for v, a in zip(saved, arrays)):
        for v, a in zip(saved, arrays):
            a[...] = v


def _restore_checkpoint(c: dict, stepper) -> None:
    """Set a :class:`~.stepper.Stepper` to the state a checkpoint of :func:`_save_checkpoint` holds: t, y, the step
    size and counts, the integrator's Jacobian (the same steps as without the stop; a checkpoint of an older version
    has none, and the run then starts from a fresh Jacobian, the same trajectory to the tolerance) and, with dense
    output, the last step and the controller's memory (without them — an older checkpoint, which stopped at an
    output time — the next step starts afresh)."""
    stepper.y[:] = c["y"]
    stepper.t = float(c["t"])
    stepper.h = float(c["h"])
    stepper.steps = int(c["steps"])
    stepper.rejected = int(c["rejected"])
    _restore_arrays(c, "jacobian", stepper._ws)
    if stepper._dense is not None:
        _restore_arrays(c, "dense", stepper._dense)
