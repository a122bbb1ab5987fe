"""Load and speed histories: constants, sines, piecewise-linear tables and their sums.

A load channel (Fa, Fr_y, Fr_z, M_y, M_z on the inner ring, at the load point) is

    F(t) = offset + Σ_k A_k sin(2π f_k t + φ_k) + table(t),

with table(t) the piecewise-linear interpolation of (t_i, F_i), held constant outside
its range.  The channels are packed into one float array evaluated inside the numba
kernels (:func:`bearingsim.dynamics.forces.loads_at`).  The shaft speed is constant or a
linear ramp Ω₀ → Ω₁ over t_ramp.

TOML forms (units at the edge, :mod:`bearingsim.units`)::

    fa = "3000 N"                                                  # constant
    mz = { offset = "0 N*m", amplitude = "600 N*m", frequency = "50 Hz", phase = "0 deg" }
    fr = { table = [["0 ms", "0 N"], ["5 ms", "2000 N"]] }         # piecewise linear
    my = [ "100 N*m", { amplitude = "50 N*m", frequency = "10 Hz" } ]   # a sum
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..units import parse_quantity
from .forces import pack_loads

CHANNELS = ("fa", "fr", "fz", "my", "mz")  #: TOML keys, in the order (Fa, Fr_y, Fr_z, M_y, M_z)
DIMS = ("force", "force", "force", "moment", "moment")


@dataclass(frozen=True)
class LoadChannel:
    """One load history [N or N·m]: offset + sines (amplitude, frequency [Hz], phase [rad]) + table."""

    offset: float = 0.0
    sines: tuple = ()
    table: tuple | None = None  #: (times [s], values)

    def __post_init__(self):
        for a, f, ph in self.sines:
            if not all(math.isfinite(v) for v in (a, f, ph)) or f < 0:
                raise InputError("loads", "a sine needs finite amplitude and phase and a frequency ≥ 0",
                                 'e.g. { amplitude = "600 N*m", frequency = "50 Hz" }')
        if self.table is not None:
            tt, vv = self.table
            if len(tt) < 2 or len(tt) != len(vv) or np.any(np.diff(tt) <= 0):
                raise InputError("loads.table", "needs ≥ 2 rows with strictly increasing times",
                                 'e.g. table = [["0 ms", "0 N"], ["5 ms", "2000 N"]]')

    def __call__(self, t: float) -> float:
        v = self.offset + sum(a * math.sin(2 * math.pi * f * t + ph) for a, f, ph in self.sines)
        if self.table is not None:
            v += float(np.interp(t, self.table[0], self.table[1]))
        return v

    def as_dict(self) -> dict:
        return {"offset": self.offset, "sines": list(self.sines), "table": self.table}

    def __add__(self, other: "LoadChannel") -> "LoadChannel":
        if self.table is not None and other.table is not None:
            tt = np.union1d(self.table[0], other.table[0])
            vv = np.interp(tt, *self.table) + np.interp(tt, *other.table)
            table = (tuple(tt), tuple(vv))
        else:
            table = self.table if self.table is not None else other.table
        return LoadChannel(self.offset + other.offset, tuple(self.sines) + tuple(other.sines), table)


def constant(value: float) -> LoadChannel:
    return LoadChannel(offset=float(value))


def sine(amplitude: float, frequency: float, phase: float = 0.0, offset: float = 0.0) -> LoadChannel:
    return LoadChannel(offset=offset, sines=((float(amplitude), float(frequency), float(phase)),))


def table(times, values) -> LoadChannel:
    return LoadChannel(table=(tuple(float(t) for t in times), tuple(float(v) for v in values)))


@dataclass(frozen=True)
class LoadHistory:
    """The five channels (Fa, Fr_y, Fr_z, M_y, M_z) of the inner-ring load."""

    channels: tuple = field(default_factory=lambda: tuple(LoadChannel() for _ in range(5)))

    def __post_init__(self):
        if len(self.channels) != 5:
            raise InputError("loads", "needs five channels (fa, fr, fz, my, mz)", "")

    def at(self, t: float) -> np.ndarray:
        """(Fa, Fr_y, Fr_z, M_y, M_z) at time t [N, N·m]."""
        return np.array([c(t) for c in self.channels])

    def packed(self) -> np.ndarray:
        return pack_loads([c.as_dict() for c in self.channels])


@dataclass(frozen=True)
class SpeedHistory:
    """Shaft speed [rad/s]: constant (ramp = 0) or a linear ramp start → stop over ``ramp`` [s]."""

    start: float
    stop: float | None = None
    ramp: float = 0.0

    def __post_init__(self):
        if not math.isfinite(self.start) or (self.stop is not None and not math.isfinite(self.stop)):
            raise InputError("speed", "must be finite", 'e.g. "10000 rpm"')
        if self.ramp < 0:
            raise InputError("speed.ramp", f"must be ≥ 0, got {self.ramp!r} s", 'e.g. "5 ms"')

    def as_tuple(self) -> tuple[float, float, float]:
        stop = self.start if self.stop is None else self.stop
        return (self.start, stop, self.ramp if stop != self.start else 0.0)

    def at(self, t: float) -> float:
        w0, w1, tr = self.as_tuple()
        if tr > 0 and t < tr:
            return w0 + (w1 - w0) * t / tr
        return w1 if tr > 0 else w0


def parse_channel(value, dim: str, field: str) -> LoadChannel:
    """A load channel from its TOML form (see the module docstring)."""
    if isinstance(value, list):
        out = LoadChannel()
        for i, v in enumerate(value):
            out = out + parse_channel(v, dim, f"{field}[{i}]")
        return out
    if isinstance(value, dict):
        unknown = set(value) - {"offset", "amplitude", "frequency", "phase", "table"}
        if unknown:
            raise InputError(f"{field}.{sorted(unknown)[0]}", "unknown key",
                             "a load takes offset, amplitude, frequency, phase or table")
        off = parse_quantity(value.get("offset", 0.0), dim, f"{field}.offset")
        sines = ()
        if "amplitude" in value or "frequency" in value:
            if "amplitude" not in value or "frequency" not in value:
                raise InputError(field, "a sine needs both amplitude and frequency",
                                 'e.g. { amplitude = "600 N*m", frequency = "50 Hz" }')
            amp = parse_quantity(value["amplitude"], dim, f"{field}.amplitude")
            freq = parse_quantity(value["frequency"], "frequency", f"{field}.frequency")
            ph = parse_quantity(value.get("phase", 0.0), "angle", f"{field}.phase")
            sines = ((amp, freq, ph),)
        tab = None
        if "table" in value:
            rows = value["table"]
            if not isinstance(rows, list) or not all(isinstance(r, list) and len(r) == 2 for r in rows):
                raise InputError(f"{field}.table", "expected a list of [time, value] pairs",
                                 'e.g. table = [["0 ms", "0 N"], ["5 ms", "2000 N"]]')
            tt = [parse_quantity(r[0], "time", f"{field}.table") for r in rows]
            vv = [parse_quantity(r[1], dim, f"{field}.table") for r in rows]
            tab = (tuple(tt), tuple(vv))
        return LoadChannel(off, sines, tab)
    return LoadChannel(offset=parse_quantity(value, dim, field))


def parse_loads(data: dict | None) -> LoadHistory:
    """The ``[loads]`` table of a case file."""
    data = data or {}
    unknown = set(data) - set(CHANNELS)
    if unknown:
        raise InputError(f"loads.{sorted(unknown)[0]}", "unknown load", f"use {', '.join(CHANNELS)}")
    return LoadHistory(tuple(parse_channel(data[k], d, f"loads.{k}") if k in data else LoadChannel()
                             for k, d in zip(CHANNELS, DIMS)))


def parse_speed(value) -> SpeedHistory:
    """``speed = "10000 rpm"`` or ``{ start = "0 rpm", stop = "10000 rpm", ramp = "5 ms" }``."""
    if isinstance(value, dict):
        unknown = set(value) - {"start", "stop", "ramp"}
        if unknown:
            raise InputError(f"speed.{sorted(unknown)[0]}", "unknown key", "use start, stop, ramp")
        if "stop" not in value:
            raise InputError("speed.stop", "missing", 'e.g. { start = "0 rpm", stop = "10000 rpm", ramp = "5 ms" }')
        return SpeedHistory(parse_quantity(value.get("start", 0.0), "speed", "speed.start"),
                            parse_quantity(value["stop"], "speed", "speed.stop"),
                            parse_quantity(value.get("ramp", 0.0), "time", "speed.ramp"))
    return SpeedHistory(parse_quantity(value, "speed", "speed"))
