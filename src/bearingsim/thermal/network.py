"""Steady thermal network: nodes, conductances, heat sources, a linear solve and its energy balance.

A node is free (its temperature is unknown) or fixed (a boundary: coolant inlet, ambient).  Between two
nodes a conductance G [W/K] carries Q = G (T_a − T_b).  The steady balance of each free node,
Σ_b G_ab (T_a − T_b) = Q_a, is the linear system G T = Q (Incropera, DeWitt, Bergman & Lavine 2007,
*Fundamentals of Heat and Mass Transfer* 6th ed., § 4.4, the finite-difference energy balance with
thermal resistances).  A coolant stream of capacity ṁ c_p that enters at T_in and leaves mixed at the
temperature of its node is a conductance ṁ c_p from that node to a fixed node at T_in (upwind, exact for
a well-mixed outlet).

Resistances of the elements used here (Incropera et al. 2007 § 3.3, table 3.3):
* radial conduction through a cylindrical shell r₁ < r < r₂ of length L: R = ln(r₂/r₁) / (2π k L);
* axial conduction through a bar of cross-section A and length L: R = L / (k A);
* convection over an area A with coefficient h: R = 1 / (h A).
All SI: [K], [W], [W/K], [m], [W/(m K)], [W/(m² K)].
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError


def _positive(name: str, value: float) -> float:
    v = float(value)
    if not (math.isfinite(v) and v > 0.0):
        raise InputError(name, f"must be positive and finite, got {value!r}", "give a positive value in SI units")
    return v


def radial_conduction(conductivity: float, r_inner: float, r_outer: float, length: float) -> float:
    """Conductance [W/K] of a cylindrical shell, 2π k L / ln(r₂/r₁) (Incropera et al. 2007 eq. 3.27).

    conductivity [W/(m K)]; r_inner < r_outer [m]; length [m]."""
    k = _positive("conductivity", conductivity)
    r1, r2 = _positive("r_inner", r_inner), _positive("r_outer", r_outer)
    L = _positive("length", length)
    if not r2 > r1:
        raise InputError("r_outer", f"must exceed r_inner ({r1} m), got {r2} m", "swap the radii")
    return 2.0 * math.pi * k * L / math.log(r2 / r1)


def axial_conduction(conductivity: float, area: float, length: float) -> float:
    """Conductance [W/K] of a bar, k A / L (Incropera et al. 2007 eq. 3.6).  [W/(m K)], [m²], [m]."""
    return _positive("conductivity", conductivity) * _positive("area", area) / _positive("length", length)


def convection(coefficient: float, area: float) -> float:
    """Conductance [W/K] of a convective surface, h A (Incropera et al. 2007 eq. 3.9).  [W/(m² K)], [m²]."""
    return _positive("coefficient", coefficient) * _positive("area", area)


@dataclass
class NetworkSolution:
    """Temperatures [K] of every node, heat [W] leaving through each fixed node (positive out of the
    network), heat generated [W] and the relative energy imbalance |Q_gen − Q_out| / max(Q_gen, 1e-30)."""

    temperatures: dict
    heat_removed: dict
    heat_generated: float
    energy_balance_error: float

    def to_dict(self) -> dict:
        return {"temperatures_K": dict(self.temperatures), "heat_removed_W": dict(self.heat_removed),
                "heat_generated_W": self.heat_generated, "energy_balance_error": self.energy_balance_error}


@dataclass
class ThermalNetwork:
    """A steady network of conductances (module docstring).  Build it with :meth:`add_node`,
    :meth:`add_fixed`, :meth:`connect` and :meth:`add_heat`; :meth:`solve` returns a :class:`NetworkSolution`."""

    free: list = field(default_factory=list)
    fixed: dict = field(default_factory=dict)
    links: list = field(default_factory=list)
    sources: dict = field(default_factory=dict)

    def add_node(self, name: str) -> None:
        if name in self.free or name in self.fixed:
            raise InputError("node", f"node {name!r} defined twice", "give every node one name")
        self.free.append(name)

    def add_fixed(self, name: str, temperature: float) -> None:
        if name in self.free or name in self.fixed:
            raise InputError("node", f"node {name!r} defined twice", "give every node one name")
        t = float(temperature)
        if not (math.isfinite(t) and t > 0.0):
            raise InputError(f"{name}.temperature", f"must be above 0 K, got {temperature!r}", 'e.g. "20 degC"')
        self.fixed[name] = t

    def connect(self, a: str, b: str, conductance: float, label: str | None = None) -> None:
        """A conductance [W/K] between nodes a and b (label names it in errors)."""
        for n in (a, b):
            if n not in self.free and n not in self.fixed:
                raise InputError("node", f"unknown node {n!r}", f"add it first ({', '.join(self.free)})")
        g = float(conductance)
        if not (math.isfinite(g) and g >= 0.0):
            raise InputError(label or f"conductance {a}-{b}", f"must not be negative, got {conductance!r}",
                             "check the conductivity, area or flow it is made of")
        self.links.append((a, b, g))

    def add_heat(self, node: str, power: float) -> None:
        """A heat source [W] at a free node (sums when called twice)."""
        if node not in self.free:
            raise InputError("node", f"heat must enter a free node, got {node!r}", f"use one of {self.free}")
        p = float(power)
        if not math.isfinite(p):
            raise InputError(f"heat at {node}", f"must be finite, got {power!r}", "check the heat sources")
        self.sources[node] = self.sources.get(node, 0.0) + p

    def solve(self) -> NetworkSolution:
        """Steady temperatures: G T = Q over the free nodes (module docstring)."""
        if not self.fixed:
            raise InputError("network", "no fixed-temperature node: the steady state is undetermined",
                             "add a coolant inlet or the ambient")
        idx = {n: i for i, n in enumerate(self.free)}
        n = len(self.free)
        g = np.zeros((n, n))
        q = np.array([self.sources.get(name, 0.0) for name in self.free])
        for a, b, c in self.links:
            for x, y in ((a, b), (b, a)):
                if x in idx:
                    g[idx[x], idx[x]] += c
                    if y in idx:
                        g[idx[x], idx[y]] -= c
                    else:
                        q[idx[x]] += c * self.fixed[y]
        try:
            t = np.linalg.solve(g, q)
        except np.linalg.LinAlgError:
            raise InputError("network", "a node is not connected to any fixed-temperature node",
                             "connect every node, directly or through others, to the coolant or the ambient") from None
        temps = {name: float(t[i]) for name, i in idx.items()}
        temps.update(self.fixed)
        removed = {name: 0.0 for name in self.fixed}
        for a, b, c in self.links:
            if a in self.fixed and b not in self.fixed:
                removed[a] += c * (temps[b] - temps[a])
            elif b in self.fixed and a not in self.fixed:
                removed[b] += c * (temps[a] - temps[b])
        gen = float(sum(self.sources.values()))
        out = float(sum(removed.values()))
        err = abs(gen - out) / max(abs(gen), 1e-30) if gen != 0 else abs(out)
        return NetworkSolution(temps, removed, gen, err)


__all__ = ["ThermalNetwork", "NetworkSolution", "radial_conduction", "axial_conduction", "convection"]
