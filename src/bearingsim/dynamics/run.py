"""Running a dynamic simulation: stepping, outputs, streaming to netCDF, checkpoints.

:class:`Stepper` advances a :class:`~.model.Model` between output times with the
integrator of :mod:`.integrate` and samples the output quantities.  :func:`simulate`
runs a case (:mod:`.case`) with a progress bar, streams the samples to a netCDF file in
chunks (memory bounded by the chunk), writes periodic checkpoints and resumes from them.
"""

from __future__ import annotations

import math
import os
from contextlib import contextmanager
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import BearingSimError, InputError
from ..io import netcdf as nc
from ..statics import _kernels as kn
from . import analysis
from . import forces as fo
from . import integrate as ig
from . import model as md


class SimulationError(BearingSimError):
    """The integration failed (diverging step, separated balls); data so far are saved."""


@dataclass
class Stepper:
    """State and integrator settings of one run (all SI)."""

    model: md.Model
    loadspec: np.ndarray
    y: np.ndarray
    t: float = 0.0
    h: float = 1e-7
    tol: float = 1e-6
    h_min: float = 1e-13
    method: str = "dopri5"  #: "dopri5" (explicit), "ros2w" or "ros34w" (linearly implicit, for stiff traction)
    jac_every: int = 20  #: steps between Jacobian refreshes (also after two rejections in a row)
    ring_coupling: bool = True  #: ROS34PW2: the inner ring's block and its coupling with the balls in the Jacobian
    max_steps_per_interval: int = 10_000_000
    steps: int = 0
    rejected: int = 0
    atol: np.ndarray = field(default=None, repr=False)
    rtol: np.ndarray = field(default=None, repr=False)

    def __post_init__(self):
        if self.atol is None or self.rtol is None:
            self.atol, self.rtol = md.tolerance_vectors(self.model, self.tol)
        self._args = fo.args_of(self.model, self.loadspec)
        self._info = np.zeros(4)
        if self.method not in ("dopri5", "ros2w", "ros34w"):
            raise InputError("integrator", f"unknown integrator {self.method!r}", "use dopri5, ros2w or ros34w")
        self._blk = np.array([md.N_RING + md.N_BALL * k for k in range(self.model.n_balls)], dtype=np.int64)
        # ROS34PW2 also carries the inner ring's block and its coupling with the balls (a stiff mode at
        # low rolling speed, docs/dynamics.md) unless the ring is held fixed
        m = self.model
        if m.gp[md.G_RING_FIXED] > 0.0 or not self.ring_coupling:
            self._rmass, self._bmass = np.zeros(0), np.zeros((0, 2))
        else:
            self._rmass = np.array([m.gp[md.G_MR]] * 3 + [m.gp[md.G_ITR]] * 2)
            self._bmass = np.array([[m.rows[r, kn.P_MASS], m.rows[r, kn.P_JB]] for r in m.ball_row])
        # the ROS34PW2 Jacobian lives from one call to the next (and in checkpoints)
        self._ws = ig.ros34_workspace(m.n_balls, md.N_BALL, self._rmass.shape[0] == 5)

    def advance(self, t_end: float) -> None:
        """Integrate to t_end [s]; raises :class:`SimulationError` naming the time and body on failure."""
        if self.method == "ros34w":
            status, t, h = ig.advance_ros34(fo.rhs_args, self._args, self.t, float(t_end), self.y, self.h, self.atol,
                                            self.rtol, self.h_min, self.max_steps_per_interval, self._info, self._blk,
                                            md.N_BALL, self.jac_every, self._ws, self._rmass, self._bmass)
        elif self.method == "ros2w":
            status, t, h = ig.advance_ros2(fo.rhs_args, self._args, self.t, float(t_end), self.y, self.h, self.atol,
                                           self.rtol, self.h_min, self.max_steps_per_interval, self._info, self._blk,
                                           md.N_BALL, self.jac_every)
        else:
            status, t, h = ig.advance(fo.rhs_args, self._args, self.t, float(t_end), self.y, self.h, self.atol,
                                      self.rtol, self.h_min, self.max_steps_per_interval, self._info)
        self.steps += int(self._info[0])
        self.rejected += int(self._info[1])
        if status != ig.OK:
            self.t = t
            comp = md.describe_component(self.model, int(self._info[2]))
            raise SimulationError(f"integration failed at t = {t * 1e3:.6g} ms: {ig.STATUS_TEXT[status]}; "
                                  f"largest error in {comp}")
        self.t = t
        self.h = h

    def sample(self) -> dict:
        """Output quantities at the current state (SI)."""
        dy, diag, gd = fo.evaluate(self.model, self.t, self.y, self.loadspec)
        out = sample_from(self.model, self.t, self.y, diag, gd)
        out["power_loss_rolling"] = 0.0
        if int(self.model.gp[md.G_TRAC]) == 2 and self.model.lubs is not None:
            # rolling viscous resistance share: the same state without it (seed 001 eqs. 4-5)
            from ..contact import slices

            if not np.any(self.model.lubs[:, slices.L_ROLLRES] != 0):
                return out
            saved = self.model.lubs.copy()
            try:
                self.model.lubs[:, slices.L_ROLLRES] = 0.0
                _, _, gd2 = fo.evaluate(self.model, self.t, self.y, self.loadspec)
            finally:
                self.model.lubs[:] = saved
            out["power_loss_rolling"] = (gd[fo.GD_PI] + gd[fo.GD_PO]) - (gd2[fo.GD_PI] + gd2[fo.GD_PO])
        return out


def sample_from(model: md.Model, t: float, y: np.ndarray, diag: np.ndarray, gd: np.ndarray) -> dict:
    """Pack one output sample (dictionary of numpy arrays / floats, SI)."""
    oc = model.cage_offset
    nc = model.n_cages
    cage = np.array([y[oc + md.N_CAGE * c + 9] for c in range(nc)])
    cage_angle = np.array([y[oc + md.N_CAGE * c + 6] for c in range(nc)])
    cage_pos = np.array([y[oc + md.N_CAGE * c:oc + md.N_CAGE * c + 3] for c in range(nc)])
    deform = np.zeros(nc)
    stress = np.zeros(nc)
    for c in range(nc):
        eta, _ = model.mode_slices(c)
        n, z = eta.stop - eta.start, int(model.cp[c, md.C_Z])
        if n:
            u = np.einsum("k,kjd->jd", y[eta], model.cage_modes[c, :n, 2:2 + 6 * z].reshape(n, z, 6)[:, :, :3])
            deform[c] = np.sqrt((u * u).sum(axis=1)).max()
            stress[c] = np.abs(np.tensordot(y[eta], model.cage_stress[c], (0, 0))).max()
    return {
        "time": t,
        "inner_ring_displacement": y[0:5].copy(),
        "inner_ring_velocity": y[5:10].copy(),
        "applied_load": gd[fo.GD_FA:fo.GD_MZ + 1].copy(),
        "shaft_speed": gd[fo.GD_W],
        "cage_angular_speed": cage,
        "cage_angle": cage_angle,
        "cage_position": cage_pos,
        "ball_orbital_speed": diag[:, fo.D_WM].copy(),
        "ball_spin_speed": diag[:, fo.D_WR].copy(),
        "ball_pitch_angle": diag[:, fo.D_BETA].copy(),
        "inner_contact_load": diag[:, fo.D_QI].copy(),
        "outer_contact_load": diag[:, fo.D_QO].copy(),
        "inner_contact_angle": diag[:, fo.D_AI].copy(),
        "outer_contact_angle": diag[:, fo.D_AO].copy(),
        "inner_approach": diag[:, fo.D_DI].copy(),
        "outer_approach": diag[:, fo.D_DO].copy(),
        "inner_slide_roll_ratio": diag[:, fo.D_SRI].copy(),
        "outer_slide_roll_ratio": diag[:, fo.D_SRO].copy(),
        "inner_power_loss": diag[:, fo.D_PI].copy(),
        "outer_power_loss": diag[:, fo.D_PO].copy(),
        "cage_contact_load": diag[:, fo.D_QC].copy(),
        "cage_power_loss": diag[:, fo.D_PC].copy(),
        "inner_ring_friction_torque": gd[fo.GD_TQI],
        "outer_ring_friction_torque": gd[fo.GD_TQO],
        "power_loss_inner": gd[fo.GD_PI],
        "power_loss_outer": gd[fo.GD_PO],
        "power_loss_cage": gd[fo.GD_PC],
        "power_loss_land": gd[fo.GD_PL],
        "contact_potential_energy": gd[fo.GD_EPOT],
        "cage_strain_energy": gd[fo.GD_ECAGE],
        "cage_pocket_deformation": deform,
        "cage_peak_stress": stress,
    }


# ---- variable metadata (units in attributes) -------------------------------------------
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


class Results:
    """Results of :func:`simulate`: the output variables (SI) and the run's summary.

    With an output file the data stay on disk (``to_xarray`` opens it lazily) and
    ``data`` loads them on first use.
    """

    def __init__(self, data: dict | None, attrs: dict, path: str | None = None, summary: dict | None = None):
        if data is None and path is None:
            raise ValueError("Results need data or a file")
        self._data = data
        self.attrs = attrs
        self.path = path
        self.summary = summary or {}

    def to_xarray(self):
        """xarray Dataset with units in the attributes (opened from the file when there is one)."""
        if self.path is not None and self._data is None:
            import xarray as xr

            return xr.open_dataset(self.path)
        return to_dataset(self._data, self.attrs)

    @property
    def data(self) -> dict:
        """Stacked output variables (numpy arrays, SI)."""
        if self._data is None:
            ds = self.to_xarray()
            self._data = {"time": ds["time"].values}
            for k in VARIABLES:
                self._data[k] = ds[k].values
            ds.close()
        return self._data

    def steady_state(self, fraction: float = 0.5) -> dict:
        """Friction torque and heat by contact type averaged over the last ``fraction`` of the run.

        Power loss per contact type [W] (ball–inner, ball–outer, ball–cage, cage land; the
        rolling resistance is inside the raceway terms when the traction kernel provides it),
        the friction torque on the inner ring [N·m], and for elastic cages the largest elastic
        pocket displacement and normal stress over that part of the run,
        ``cage_pocket_deformation_max`` [m] and ``cage_peak_stress_max`` [Pa] (0 for rigid cages).
        """
        names = ("power_loss_inner", "power_loss_outer", "power_loss_cage", "power_loss_land", "power_loss_rolling",
                 "inner_ring_friction_torque", "outer_ring_friction_torque")
        with self._columns() as read:
            t = read("time")
            i0 = int(np.searchsorted(t, t[0] + (1 - fraction) * (t[-1] - t[0])))
            n = len(t)
            out = {}
            # means in blocks of rows: memory bounded by the block, not by the run
            for k in names:
                total = 0.0
                for a in range(i0, n, self.BLOCK):
                    total += float(np.sum(read(k, a, min(n, a + self.BLOCK))))
                out[k] = total / max(n - i0, 1)
            for k in ("cage_pocket_deformation", "cage_peak_stress"):
                out[k + "_max"] = max((float(np.max(read(k, a, min(n, a + self.BLOCK)), initial=0.0))
                                       for a in range(i0, n, self.BLOCK)), default=0.0)
            # mean cage speed from its angle (the cage rattles in its pocket clearance)
            if n - i0 > 1:
                dth = read("cage_angle", n - 1, n)[0] - read("cage_angle", i0, i0 + 1)[0]
                out["cage_angular_speed"] = float(np.mean(dth / (t[-1] - t[i0])))
            else:
                out["cage_angular_speed"] = float(np.mean(read("cage_angular_speed", i0, n)))
        out["heat_generation_total_W"] = out["power_loss_inner"] + out["power_loss_outer"] + \
            out["power_loss_cage"] + out["power_loss_land"]
        return out

    BLOCK = 20_000  #: rows read at a time from an output file

    def read(self, *names: str) -> list[np.ndarray]:
        """The given output variables (SI arrays), read from the file without loading the others."""
        with self._columns() as read:
            return [np.asarray(read(n)) for n in names]

    @contextmanager
    def _columns(self):
        """Yield read(name, start=0, stop=None) -> rows of one output variable, from memory or the file."""
        if self._data is not None or self.path is None:
            data = self.data
            yield lambda name, start=0, stop=None: data[name][start:stop]
            return
        import xarray as xr

        with xr.open_dataset(self.path) as ds:
            yield lambda name, start=0, stop=None: ds[name][start:stop].values

    def loop_widths(self, moment: float = 300.0, dof: int = 4, load: int = 4) -> np.ndarray:
        """Hysteresis of the tilt against the moment per load cycle, seed 001 Fig. 8 definition [rad].

        For every time the applied load ``applied_load[:, load]`` (default M_z) passes ``moment``
        [N·m] rising and then falling: the tilt (``inner_ring_displacement[:, dof]``, default γz) at
        the falling crossing minus that at the rising one (linear interpolation between samples);
        positive when the tilt lags the moment.  Seed 001 evaluates it at 0.3 kN·m.
        """
        with self._columns() as read:  # only the two variables, not the whole run
            m = read("applied_load")[:, load]
            g = read("inner_ring_displacement")[:, dof]
        return analysis.loop_widths(m, g, moment)

    def fluctuation_range(self, moment: float = 300.0, dof: int = 4, load: int = 4) -> float:
        """W_H of the last complete load cycle [rad] (:meth:`loop_widths`); NaN if there is none."""
        w = self.loop_widths(moment, dof, load)
        return float(w[-1]) if len(w) else math.nan

    def plot(self, variables=("inner_ring_displacement", "cage_angular_speed"), ax=None):
        """Plot variables against time (matplotlib); returns the figure."""
        import matplotlib.pyplot as plt

        fig, axes = plt.subplots(len(variables), 1, sharex=True, figsize=(7, 2.5 * len(variables)))
        axes = np.atleast_1d(axes)
        for a, name in zip(axes, variables):
            v = self.data[name]
            a.plot(self.data["time"] * 1e3, v.reshape(len(v), -1))
            u = VARIABLES[name][1]
            a.set_ylabel(f"{name} [{u if isinstance(u, str) else ', '.join(dict.fromkeys(u))}]")
        axes[-1].set_xlabel("time [ms]")
        return fig

    def plot_hysteresis(self, dof: int = 4, load: int = 4):
        """Tilt against moment (seed 001 Fig. 6)."""
        import matplotlib.pyplot as plt

        fig, a = plt.subplots()
        a.plot(self.data["applied_load"][:, load], np.degrees(self.data["inner_ring_displacement"][:, dof]))
        a.set_xlabel(f"{md.DOF[load]} load")
        a.set_ylabel("inclining angle [deg]")
        return fig


def run_stepper(stepper: Stepper, duration: float, output_interval: float, progress=None) -> Results:
    """Run in memory (tests and the API without a file): samples at every output interval."""
    n = int(round(duration / output_interval))
    samples = [stepper.sample()]
    t0 = stepper.t
    for i in range(1, n + 1):
        stepper.advance(t0 + i * output_interval)
        samples.append(stepper.sample())
    return Results(data=stack_samples(samples), attrs={})


# ---- the case runner ---------------------------------------------------------------------
def build(case):
    """(model, loadspec, initial state) of a case; the start is the quasi-static solution."""
    from ..statics import jones_harris as jh

    model = md.build_model(case.bearing, **case.model_options())
    loadspec = case.loads.packed()
    l0 = case.loads.at(0.0)
    xl = case.load_point
    static_loads = jh.Loads(fa=l0[0], fr_y=l0[1], fr_z=l0[2], m_y=l0[3] - xl * l0[2], m_z=l0[4] + xl * l0[1])
    w0 = case.speed.at(0.0)
    res = jh.solve(case.bearing, static_loads, abs(w0), control=case.control)
    if not res.converged:
        res = jh.solve(case.bearing, static_loads, 0.0, control=case.control)
    if not res.converged:
        raise InputError("loads", f"no quasi-static equilibrium for the loads at t = 0 ({res.status})",
                         "the initial loads must be carried by the bearing (e.g. an axial load on an angular "
                         "contact row)")
    y0 = md.initial_state(model, res, w0)
    return model, loadspec, y0, res


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


#: wall-clock seconds between checkpoints unless the case (``checkpoint_every = "10 s"``) or the caller
#: says otherwise: a run killed at any time loses at most this much work (plus one output interval)
CHECKPOINT_SECONDS = 30.0


def _checkpoint_path(out: Path) -> Path:
    return out.with_name(out.name + ".ckpt.npz")


def _note(console, text: str) -> None:
    """One line for the user: on ``console`` (the CLI's stderr) or as a Python warning (the API)."""
    if console is not None:
        console.print(text, markup=False, highlight=False, soft_wrap=True)
    else:
        import warnings

        warnings.warn(text, stacklevel=3)


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


def _save_checkpoint(path: Path, stepper: Stepper, index: int, fingerprint: str) -> None:
    tmp = _checkpoint_tmp(path)
    np.savez(tmp, t=stepper.t, h=stepper.h, y=stepper.y, index=index, steps=stepper.steps,
             rejected=stepper.rejected, fingerprint=fingerprint,
             **{f"jacobian_{i}": a for i, a in enumerate(stepper._ws)})
    os.replace(tmp, path)


def simulate(case, out: str | Path | None = None, resume: bool = False, progress: bool = False,
             console=None, checkpoint_seconds: float | None = None) -> Results:
    """Run a dynamic case.

    Parameters
    ----------
    case : :class:`~.case.Case` or a path to a case TOML file
    out : netCDF file for the output (streamed in chunks); None keeps the samples in memory.  A
        checkpoint ``OUT.ckpt.npz`` is written after every ``checkpoint_every`` chunks and at the first
        output time after ``checkpoint_seconds`` of wall-clock time since the last one (so a long run
        killed at any time can be resumed); it is removed when the run completes
    resume : continue from the checkpoint of ``out`` (same case required); the trajectory
        is bitwise the same as an uninterrupted run (the integrator restarts from the
        checkpointed t, y, step size and Jacobian, and every output time is hit exactly).
        Without a checkpoint (the run was killed before its first one, or it had completed) the run
        starts from the beginning with a one-line note (on ``console``, else a Python warning)
    progress : show a progress bar (simulated time, rate, ETA)
    console : a ``rich`` console for the progress bar and notes
    checkpoint_seconds : wall-clock interval between checkpoints [s] (default: the case's
        ``checkpoint_every = "… s"``, else :data:`CHECKPOINT_SECONDS`)

    Returns :class:`Results`.  On a diverging step or when every ball has separated
    the data so far are saved and :class:`SimulationError` is raised.
    """
    from .case import Case, load_case

    if not isinstance(case, Case):
        case = load_case(case)
    if checkpoint_seconds is None:
        checkpoint_seconds = getattr(case, "checkpoint_interval", None) or CHECKPOINT_SECONDS
    if isinstance(checkpoint_seconds, bool) or not isinstance(checkpoint_seconds, int | float) or \
            not (0 < checkpoint_seconds < math.inf):
        raise InputError("checkpoint_every", f"must be a positive wall-clock time, got {checkpoint_seconds!r} s",
                         'e.g. "30 s"')
    model, loadspec, y0, static = build(case)
    fp = case.fingerprint()
    stepper = Stepper(model, loadspec, y0, tol=case.tolerance, h=min(1e-7, case.output_interval),
                      method=case.method)
    attrs = {"title": "bearingsim dynamic simulation", "bearing": model.names.get("bearing", ""),
             "traction": case.traction, "tolerance": case.tolerance, "case_fingerprint": fp,
             "conventions": "x bearing axis, outer ring fixed, psi = 0 on +y, SI units",
             "integrator": {"dopri5": "Dormand-Prince 5(4) with error control",
                            "ros2w": "ROS2 W-method (Verwer et al. 1999), block-diagonal per ball",
                            "ros34w": "ROS34PW2 W-method (Rang & Angermann 2005), block-diagonal per ball"}[case.method]}
    n_total = case.n_samples
    start = 0
    writer = None
    ckpt = None
    out_path = Path(out) if out is not None else None
    samples_mem: list[dict] = []
    if out_path is not None:
        ckpt = _checkpoint_path(out_path)
        c = None
        if resume:
            c, why = _read_checkpoint(ckpt, out_path, fp)
            if c is None:
                _note(console, f"--resume: {why}; starting from the beginning")
        if c is not None:
            stepper.y[:] = c["y"]
            stepper.t = float(c["t"])
            stepper.h = float(c["h"])
            stepper.steps = int(c["steps"])
            stepper.rejected = int(c["rejected"])
            # the integrator's Jacobian: the same steps as without the stop (a checkpoint of an older version
            # has none: the run then starts from a fresh Jacobian, the same trajectory to the tolerance)
            saved = [c.get(f"jacobian_{i}") for i in range(len(stepper._ws))]
            if all(v is not None and v.shape == a.shape for v, a in zip(saved, stepper._ws)):
                for v, a in zip(saved, stepper._ws):
                    a[...] = v
            start = int(c["index"])
            writer = _Writer(out_path, model, attrs, start)
            if len(writer.ds.dimensions["time"]) < start:
                writer.close()
                raise InputError("--resume", f"{out_path.name} holds fewer samples than its checkpoint counts (was "
                                 "the file replaced?)", "run without --resume to start again")
        else:
            ckpt.unlink(missing_ok=True)  # a stale checkpoint must never meet the new file
            writer = _Writer(out_path, model, attrs, None)
    buf: list[dict] = []
    if start == 0:
        buf.append(stepper.sample())
    t_wall0 = time.perf_counter()
    prog = None
    task = None
    if progress:
        from rich.progress import BarColumn, Progress, TextColumn, TimeRemainingColumn

        prog = Progress(TextColumn("[bold]simulate"), BarColumn(),
                        TextColumn("{task.fields[simt]:.3f} / {task.fields[tot]:.3f} ms"),
                        TextColumn("{task.fields[rate]:.3g} wall s per sim s"), TimeRemainingColumn(),
                        console=console, transient=False)
        prog.start()
        task = prog.add_task("sim", total=n_total, completed=max(start - 1, 0), simt=stepper.t * 1e3,
                             tot=case.duration * 1e3, rate=0.0)
    first = start if start > 0 else 1
    chunks = 0
    error = None
    completed = False
    t_sim0 = stepper.t
    last_ckpt = time.monotonic()

    def flush(final=False, checkpoint=False):
        """Write the buffered samples; then a checkpoint after every ``checkpoint_every`` full chunks, when
        asked (wall-clock interval) and at the end of an incomplete run.  The samples are synced before
        the checkpoint that counts them is renamed into place."""
        nonlocal buf, chunks, last_ckpt
        if writer is not None:
            full = len(buf) >= case.chunk
            writer.write(buf)
            chunks += full
            if checkpoint or (final and not completed) or (full and chunks % max(case.checkpoint_every, 1) == 0):
                _save_checkpoint(ckpt, stepper, writer.index, fp)
                last_ckpt = time.monotonic()
        else:
            samples_mem.extend(buf)
        buf = []

    n_free = 0
    try:
        for i in range(first, n_total + 1):
            try:
                stepper.advance(i * case.output_interval)
            except SimulationError as exc:
                error = exc
                break
            s = stepper.sample()
            buf.append(s)
            # the inner ring has left every ball for three output samples in a row
            n_free = n_free + 1 if not np.any(s["inner_contact_load"] > 0) else 0
            if n_free >= 3:
                error = SimulationError(f"every ball has separated from the inner raceway at t = "
                                        f"{stepper.t * 1e3:.6g} ms (the loads lift the inner ring off the balls); "
                                        "data so far saved")
                break
            if len(buf) >= case.chunk:
                flush()
            elif writer is not None and time.monotonic() - last_ckpt >= checkpoint_seconds:
                flush(checkpoint=True)  # the run can be resumed from here, chunk or not
            if prog is not None:
                el = time.perf_counter() - t_wall0
                prog.update(task, completed=i, simt=stepper.t * 1e3,
                            rate=el / max(stepper.t - t_sim0, 1e-30))
        else:
            completed = True
    finally:
        flush(final=True)
        if prog is not None:
            prog.stop()
        if writer is not None:
            writer.close()
    if completed and ckpt is not None:
        ckpt.unlink(missing_ok=True)  # a completed run leaves no checkpoint behind
        _checkpoint_tmp(ckpt).unlink(missing_ok=True)  # (nor one half-saved when an earlier run was killed)
    wall = time.perf_counter() - t_wall0
    summary = {"wall_seconds": wall, "simulated_seconds": stepper.t - t_sim0, "steps": stepper.steps,
               "rejected_steps": stepper.rejected,
               "wall_per_simulated_second": wall / max(stepper.t - t_sim0, 1e-30),
               "initial_static_converged": bool(static.converged)}
    res = Results(data=stack_samples(samples_mem) if writer is None else None, attrs=attrs,
                  path=str(out_path) if out_path else None, summary=summary)
    if error is not None:
        raise error
    return res
