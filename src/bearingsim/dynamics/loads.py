"""Load and speed histories: constants, sines, piecewise-linear tables and their sums.

A load channel (Fa, Fr_y, Fr_z, M_y, M_z on the inner ring, at the load point) is

    F(t) = offset + Σ_k A_k sin(2π f_k t + φ_k) + table(t),

with table(t) the piecewise-linear interpolation of (t_i, F_i), held constant outside
its range.  The channels are packed into one float array (:func:`pack_loads`) evaluated by the
numba kernel :func:`loads_at` inside the equations of motion; the Python side (``LoadChannel(t)``,
``LoadHistory.at``) calls the same kernel, so a history has one evaluation.  The shaft speed is
constant or a linear ramp Ω₀ → Ω₁ over t_ramp (:func:`speed_ramp`, also behind ``SpeedHistory.at``).

Packed layout (float64)::

    spec[0:5]                  start index of each channel's block
    spec[5]                    ramp-in length T_r [s] (0: none; :func:`ramp_weight`)
    block: offset, n_s, (A, f [Hz], φ [rad]) × n_s, n_t, t_1 … t_nt [s], F_1 … F_nt

Ramp-in (``ramp_in = "5 ms"`` in a case file): the *variation* of every channel is blended in by the
C² smoothstep S(x) = 10x³ − 15x⁴ + 6x⁵ (S(0) = 0, S(1) = 1, S′ = S″ = 0 at both ends),

    F_r(t) = F(0) + S(t/T_r) (F(t) − F(0))   for 0 ≤ t < T_r,   F(t) afterwards.

The loads at t = 0 are unchanged (the quasi-static start is that of F(0)), and dF_r/dt = d²F_r/dt² = 0
at t = 0, so a start at rest in the quasi-static position of F(0) is consistent with the loads (no step
in the force rate to excite the ring's modes).  Offsets and preloads are not ramped: multiplying the
whole load by S would start an angular-contact row unloaded (no equilibrium) and ramp the axial
preload, which kicks the axial mode instead.

TOML forms (units at the edge, :mod:`bearingsim.units`)::

    fa = "3000 N"                                                  # constant
    mz = { offset = "0 N*m", amplitude = "600 N*m", frequency = "50 Hz", phase = "0 deg" }
    fr = { table = [["0 ms", "0 N"], ["5 ms", "2000 N"]] }         # piecewise linear
    my = [ "100 N*m", { amplitude = "50 N*m", frequency = "10 Hz" } ]   # a sum
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np
from numba import njit

from ..errors import InputError
from . import layout as ly

CHANNELS = ("fa", "fr", "fz", "my", "mz")  #: TOML keys, in the order (Fa, Fr_y, Fr_z, M_y, M_z)
DIMS = ("force", "force", "force", "moment", "moment")


# ---- numba kernels -----------------------------------------------------------------------
@njit(cache=True)
def smoothstep(x):
    """C² smoothstep S(x) = 10x³ − 15x⁴ + 6x⁵ on [0, 1] (0 below, 1 above) [-]: the quintic with S′ = S″ = 0
    at both ends (the lowest-degree polynomial with those six conditions)."""
    if x <= 0.0:
        return 0.0
    if x >= 1.0:
        return 1.0
    return x * x * x * (10.0 + x * (-15.0 + 6.0 * x))


@njit(cache=True)
def ramp_weight(t, tr):
    """Weight S(t/T_r) of the load variation during the ramp-in (module docstring); 1 without a ramp."""
    if tr <= 0.0:
        return 1.0
    return smoothstep(t / tr)


@njit(cache=True)
def speed_ramp(t, w0, w1, tr):
    """Shaft speed Ω(t) [rad/s]: constant w0 (tr = 0), or a linear ramp from w0 to w1 over tr [s]."""
    if tr > 0.0 and t < tr:
        return w0 + (w1 - w0) * t / tr
    if tr > 0.0:
        return w1
    return w0


@njit(cache=True)
def speed_at(t, gp):
    """Shaft speed Ω(t) [rad/s] of the model's global parameters gp (G_W0, G_W1, G_TRAMP)."""
    return speed_ramp(t, gp[ly.G_W0], gp[ly.G_W1], gp[ly.G_TRAMP])


@njit(cache=True)
def load_channel(t, spec, start):
    """One load channel at time t: offset + Σ amp sin(2π f t + φ) + piecewise-linear table (held
    constant outside its range; bisection for the interval)."""
    i = start
    val = spec[i]
    ns = int(spec[i + 1])
    i += 2
    for _ in range(ns):
        val += spec[i] * math.sin(2.0 * math.pi * spec[i + 1] * t + spec[i + 2])
        i += 3
    nt = int(spec[i])
    i += 1
    if nt > 0:
        tt = spec[i:i + nt]
        vv = spec[i + nt:i + 2 * nt]
        if t <= tt[0]:
            val += vv[0]
        elif t >= tt[nt - 1]:
            val += vv[nt - 1]
        else:
            lo = 0
            hi = nt - 1
            while hi - lo > 1:
                mid = (lo + hi) // 2
                if tt[mid] <= t:
                    lo = mid
                else:
                    hi = mid
            w = (t - tt[lo]) / (tt[hi] - tt[lo])
            val += vv[lo] + w * (vv[hi] - vv[lo])
    return val


@njit(cache=True)
def loads_at(t, spec, out):
    """(Fa, Fr_y, Fr_z, M_y, M_z) at time t [N, N·m] from the packed specification (with the ramp-in of
    spec[5]: F(0) + S(t/T_r)(F(t) − F(0)) while t < T_r)."""
    tr = spec[5]
    w = ramp_weight(t, tr)
    for k in range(5):
        v = load_channel(t, spec, int(spec[k]))
        if w < 1.0:
            v0 = load_channel(0.0, spec, int(spec[k]))
            v = v0 + w * (v - v0)
        out[k] = v


def _channel_block(ch: dict) -> list:
    """The packed block of one channel (module docstring)."""
    blk = [float(ch.get("offset", 0.0)), float(len(ch.get("sines", ())))]
    for a, f, ph in ch.get("sines", ()):
        blk += [float(a), float(f), float(ph)]
    tab = ch.get("table")
    if tab is None:
        blk.append(0.0)
    else:
        tt, vv = (np.asarray(tab[0], float), np.asarray(tab[1], float))
        blk.append(float(len(tt)))
        blk += list(tt) + list(vv)
    return blk


def pack_loads(channels, ramp_in: float = 0.0) -> np.ndarray:
    """Pack five load channels for :func:`loads_at`.

    ``channels``: five dicts with keys offset [N or N·m], sines (list of (amplitude,
    frequency [Hz], phase [rad])), table (tuple of time [s] and value arrays, or None);
    ``ramp_in``: length of the C² ramp-in of the load variation [s] (0: none; module docstring).
    """
    ramp_in = _check_ramp(ramp_in)
    blocks = [_channel_block(ch) for ch in channels]
    out = [0.0] * 5 + [ramp_in]
    pos = 6
    for k, blk in enumerate(blocks):
        out[k] = float(pos)
        pos += len(blk)
    for blk in blocks:
        out += blk
    return np.array(out, dtype=float)


def _check_ramp(ramp_in) -> float:
    if isinstance(ramp_in, bool) or not isinstance(ramp_in, (int, float)) or not (0.0 <= ramp_in < math.inf):
        raise InputError("ramp_in", f"must be a finite time ≥ 0, got {ramp_in!r}",
                         'e.g. ramp_in = "5 ms" (several periods of the slowest ring mode), or omit it')
    return float(ramp_in)


def constant_loads(fa=0.0, fr_y=0.0, fr_z=0.0, m_y=0.0, m_z=0.0) -> np.ndarray:
    """Packed constant loads [N, N·m]."""
    return pack_loads([{"offset": v} for v in (fa, fr_y, fr_z, m_y, m_z)])


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
        """Value at time t [s] (the numba kernel :func:`load_channel`)."""
        return float(load_channel(float(t), self._packed, 0))

    @cached_property
    def _packed(self) -> np.ndarray:
        return np.array(_channel_block(self.as_dict()), dtype=float)

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
    ramp_in: float = 0.0  #: length of the C² ramp-in of the load variation [s] (module docstring)

    def __post_init__(self):
        if len(self.channels) != 5:
            raise InputError("loads", "needs five channels (fa, fr, fz, my, mz)", "")
        _check_ramp(self.ramp_in)

    def at(self, t: float) -> np.ndarray:
        """(Fa, Fr_y, Fr_z, M_y, M_z) at time t [N, N·m] (the numba kernel :func:`loads_at`)."""
        out = np.empty(5)
        loads_at(float(t), self._packed, out)
        return out

    def packed(self) -> np.ndarray:
        """The packed specification of the five channels (:func:`pack_loads`)."""
        return pack_loads([c.as_dict() for c in self.channels], self.ramp_in)

    def rate(self, t: float, h: float | None = None) -> np.ndarray:
        """dF/dt at t [N/s, N·m/s] by the central difference (F(t + h) − F(t − h)) / 2h of :meth:`at`
        (h default: 10⁻⁴ of the shortest sine period or ramp, at most 10 µs)."""
        if h is None:
            h = self.rate_step()
        return (self.at(t + h) - self.at(t - h)) / (2.0 * h)

    def rate_step(self) -> float:
        """Time step [s] for :meth:`rate`: 10⁻⁴ of the shortest time scale of the history (sine period,
        ramp-in), at most 10 µs; the central difference's relative error is then ≈ (2π·10⁻⁴)²/6 ≈ 7·10⁻⁸."""
        scales = [1e-1]
        for c in self.channels:
            scales += [1.0 / f for _, f, _ in c.sines if f > 0]
            if c.table is not None:
                scales += list(np.diff(c.table[0]))
        if self.ramp_in > 0:
            scales.append(self.ramp_in)
        return min(1e-5, 1e-4 * min(scales))

    @cached_property
    def _packed(self) -> np.ndarray:
        return self.packed()


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
        """Ω(t) [rad/s] (the numba kernel :func:`speed_ramp`)."""
        w0, w1, tr = self.as_tuple()
        return float(speed_ramp(float(t), float(w0), float(w1), float(tr)))


def parse_channel(value, dim: str, field: str) -> LoadChannel:
    """A load channel from its TOML form (see the module docstring)."""
    from ..units import parse_quantity
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
    from ..units import parse_quantity

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
