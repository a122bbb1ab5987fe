"""Thermal operating point of a bearing: the fixed point temperatures → clearance → loads → friction → temperatures.

One iteration (Picard, with under-relaxation ``relaxation``):

1. temperatures → operating clearance: :func:`bearing_at_temperatures` calls the clearance model
   (:class:`bearingsim.statics.clearance.OperatingClearance`: ring and ball thermal growth, fits,
   centrifugal expansion of the inner ring);
2. clearance → load distribution and ball speeds (``mechanics``; by default :func:`bearingsim.solve`);
3. → heat per source at the oil's node temperature (:func:`bearingsim.friction.friction_summary`: rolling,
   spin, sliding, ball drag, cage land and pockets, jet momentum);
4. → temperatures: the steady network of :func:`build_network` (:mod:`.network`, correlations
   :mod:`.correlations`).

Placement of the heat: a contact's rolling, spin and sliding loss goes half to the ball and half to the
ring — the inner and the outer contacts taken as equal shares of the total (the per-contact split is not
carried); ball drag and jet momentum to the oil; the cage land loss half to the guiding ring and half to
the oil; the pocket loss to the balls.

Nodes: inner ring, outer ring, balls, oil (the bearing cavity's oil, leaving at its temperature), shaft,
housing; fixed: oil inlet, ambient.  The shaft is a bar of length ``shaft_length`` from the inner ring to a
point at ambient; the housing a cylinder of ``housing_width`` with natural convection outside.

A shaft solver couples here through ``mechanics``: any callable taking the node temperatures [K] (dict)
and returning a result with ``converged``, ``balls``, ``bearing``, ``speed`` (what :func:`bearingsim.solve`
returns), e.g. one that applies :func:`bearing_at_temperatures` to each support and solves the shaft.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from ..contact import hertz
from ..errors import InputError
from ..friction import friction_summary
from ..lubricants import get_lubricant
from ..statics.clearance import OperatingClearance
from ..statics.jones_harris import solve
from . import correlations as C
from .network import ThermalNetwork, axial_conduction, convection, radial_conduction

NODES = ("inner_ring", "outer_ring", "balls", "oil", "shaft", "housing")
#: temperature range the network accepts for its boundaries [K]: −100 … 500 °C (the clearance command's range)
T_MIN, T_MAX = 173.15, 773.15


@dataclass(frozen=True)
class ThermalSetup:
    """Cooling and mounting of one bearing (all SI).

    oil_inlet_temperature [K]; oil_flow [m³/s] (jet or circulation); oil_specific_heat [J/(kg K)]
    (2000: ester and mineral oils 1.9–2.1 kJ/(kg K) at 100 °C, Incropera et al. 2007 table A.5 engine oil
    2.2 at 400 K); ambient_temperature [K]; reference_temperature [K] of the fits and clearance;
    housing_outside_diameter, housing_width [m] (0: outside diameter + 2 × ring width, and the ring width);
    shaft_length [m]; conductivities [W/(m K)]; shaft_interference, housing_interference [m]; cage: a
    :class:`bearingsim.friction.CageLand`, "estimate" or None."""

    oil_inlet_temperature: float = 313.15
    oil_flow: float = 1e-5
    oil_specific_heat: float = 2000.0
    ambient_temperature: float = 293.15
    reference_temperature: float = 293.15
    housing_outside_diameter: float = 0.0
    housing_width: float = 0.0
    shaft_length: float = 0.1
    ring_conductivity: float = C.STEEL_CONDUCTIVITY
    shaft_conductivity: float = C.STEEL_CONDUCTIVITY
    housing_conductivity: float = C.STEEL_CONDUCTIVITY
    shaft_interference: float = 0.0
    housing_interference: float = 0.0
    cage: object = "estimate"

    def __post_init__(self):
        for f in dataclasses.fields(self):
            v = getattr(self, f.name)
            if f.name == "cage" or f.name.endswith("interference"):
                continue
            if not (isinstance(v, (int, float)) and math.isfinite(v)):
                raise InputError(f"thermal.{f.name}", f"must be a finite number, got {v!r}", "give a number in SI")
            if f.name.endswith("temperature"):
                if not (T_MIN <= v <= T_MAX):
                    raise InputError(f"thermal.{f.name}", f"{v - 273.15:.1f} degC is outside the materials' range "
                                     f"({T_MIN - 273.15:.0f} … {T_MAX - 273.15:.0f} degC)", 'e.g. "40 degC"')
            elif f.name in ("housing_outside_diameter", "housing_width"):
                if v < 0:
                    raise InputError(f"thermal.{f.name}", f"must not be negative, got {v}", "give 0 to estimate it")
            elif not v > 0:
                raise InputError(f"thermal.{f.name}", f"must be positive, got {v}", "give a positive value in SI")


@dataclass
class ThermalOperatingPoint:
    """Result of :func:`thermal_operating_point`: node temperatures [K], the operating clearance change [m],
    the mechanics result at the fixed point, heat per source [W] and removed per path [W], and the solver's
    ``converged``, ``status``, ``residual`` (max |ΔT| of the last iteration [K]), ``iterations``, ``warnings``."""

    temperatures: dict
    clearance_change: float
    result: object
    heat_sources: dict
    heat_removed: dict
    energy_balance_error: float
    converged: bool
    status: str
    residual: float
    iterations: int
    warnings: list

    def to_dict(self) -> dict:
        return {"temperatures_K": dict(self.temperatures), "diametral_clearance_change_m": self.clearance_change,
                "heat_sources_W": dict(self.heat_sources), "heat_removed_W": dict(self.heat_removed),
                "energy_balance_error": self.energy_balance_error, "converged": self.converged,
                "status": self.status, "residual_K": self.residual, "iterations": self.iterations,
                "warnings": list(self.warnings)}


def operating_clearance(bearing, temperatures: dict, speed: float, setup: ThermalSetup):
    """The clearance model (:class:`bearingsim.statics.clearance.OperatingClearance`) at these temperatures."""

    return OperatingClearance(
        shaft_interference=setup.shaft_interference, housing_interference=setup.housing_interference,
        reference_temperature=setup.reference_temperature,
        inner_ring_temperature=temperatures["inner_ring"], outer_ring_temperature=temperatures["outer_ring"],
        ball_temperature=temperatures["balls"], shaft_temperature=temperatures["shaft"],
        housing_temperature=temperatures["housing"], speed=speed)


def bearing_at_temperatures(bearing, temperatures: dict, speed: float, setup: ThermalSetup):
    """A copy of ``bearing`` with its operating clearance at the ring, ball, shaft and housing temperatures [K]
    (the seam a shaft solver calls per support)."""
    return operating_clearance(bearing, temperatures, speed, setup).apply(bearing)


def _ring_dims(bearing, setup):
    dw, dm = bearing.ball_diameter, bearing.pitch_diameter
    di, do = dm - dw, dm + dw
    bore = bearing.bore if bearing.bore > 0 else di - 0.6 * dw
    od = bearing.outside_diameter if bearing.outside_diameter > 0 else do + 0.6 * dw
    width = bearing.width if bearing.width > 0 else 1.6 * dw
    dh = setup.housing_outside_diameter or od + 2.0 * width
    wh = setup.housing_width or width
    return dw, dm, di, do, bore, od, width, dh, wh


def build_network(result, setup: ThermalSetup, heat: dict, temperatures: dict, lubricant) -> ThermalNetwork:
    """The network of one single-row bearing (module docstring) with the heat per node ``heat`` [W] and the
    convection evaluated at ``temperatures`` [K]."""

    b = result.bearing
    lub = get_lubricant(lubricant)
    dw, dm, di, do, bore, od, width, dh, wh = _ring_dims(b, setup)
    t_oil = min(max(temperatures["oil"], lub.min_temperature), lub.max_temperature)  # properties inside the range
    rho, eta, k_oil = lub.density(t_oil), lub.dynamic_viscosity(t_oil), lub.thermal_conductivity
    omega = abs(float(result.speed))
    balls = result.balls
    wc = float(sum(abs(w) for w in balls["orbital_speed_rad_s"]) / len(balls["orbital_speed_rad_s"]))
    k_ball = C.SILICON_NITRIDE_CONDUCTIVITY if "nitride" in b.ball_material.name.lower() else C.STEEL_CONDUCTIVITY
    g_in = g_out = 0.0
    for j in range(len(balls["azimuth_rad"])):
        for inner in (True, False):
            q = float(balls["inner_load_N" if inner else "outer_load_N"][j])
            if not q > 0:
                continue
            a = float(balls["inner_contact_angle_rad" if inner else "outer_contact_angle_rad"][j])
            f = b.inner_conformity if inner else b.outer_conformity
            hz = hertz.point_contact_exact(q, *hertz.raceway_radii(dw, dm, f, a, inner), b.effective_modulus)
            g = C.contact_conductance(hz.a, hz.b, setup.ring_conductivity, k_ball)
            if inner:
                g_in += g
            else:
                g_out += g
    net = ThermalNetwork()
    for n in NODES:
        net.add_node(n)
    net.add_fixed("oil_inlet", setup.oil_inlet_temperature)
    net.add_fixed("ambient", setup.ambient_temperature)
    cp = setup.oil_specific_heat
    net.connect("inner_ring", "balls", g_in, "ball-inner raceway contacts")
    net.connect("outer_ring", "balls", g_out, "ball-outer raceway contacts")
    # forced convection to the oil: balls at their orbital speed, rings at their speed relative to the cage
    h_ball = C.flat_plate_convection(wc * dm / 2, dw, rho, eta, k_oil, cp)
    h_ir = C.flat_plate_convection((omega - wc) * di / 2, width, rho, eta, k_oil, cp)
    h_or = C.flat_plate_convection(wc * do / 2, width, rho, eta, k_oil, cp)
    z = b.ball_count
    net.connect("balls", "oil", h_ball * z * math.pi * dw**2, "ball convection")
    net.connect("inner_ring", "oil", h_ir * math.pi * di * 0.5 * width, "inner ring convection")
    net.connect("outer_ring", "oil", h_or * math.pi * do * 0.5 * width, "outer ring convection")
    net.connect("oil", "oil_inlet", rho * setup.oil_flow * cp, "thermal.oil_flow")
    net.connect("inner_ring", "shaft", radial_conduction(setup.ring_conductivity, bore / 2, di / 2, width))
    net.connect("outer_ring", "housing", 1.0 / (1.0 / radial_conduction(setup.ring_conductivity, do / 2, od / 2, width)
                                                + 1.0 / radial_conduction(setup.housing_conductivity, od / 2, dh / 2,
                                                                          wh)))
    net.connect("shaft", "ambient", axial_conduction(setup.shaft_conductivity, math.pi * bore**2 / 4,
                                                     setup.shaft_length), "thermal.shaft_length")
    h_nat = C.natural_convection_cylinder(dh, max(temperatures["housing"], setup.ambient_temperature + 0.01),
                                          setup.ambient_temperature)
    net.connect("housing", "ambient", convection(h_nat, math.pi * dh * wh + 0.5 * math.pi * (dh**2 - od**2)),
                "housing outer surface")
    for node, p in heat.items():
        net.add_heat(node, p)
    return net


def place_heat(summary: dict, guidance: str = "outer") -> dict:
    """Heat per node [W] from a :func:`bearingsim.friction.friction_summary` dict (module docstring)."""
    contact = sum(summary.get(k) or 0.0 for k in ("rolling_W", "spin_W", "sliding_W"))
    land = summary.get("cage_land_W") or 0.0
    ring = "outer_ring" if guidance == "outer" else "inner_ring"
    heat = {"balls": 0.5 * contact + (summary.get("cage_pocket_W") or 0.0), "inner_ring": 0.25 * contact,
            "outer_ring": 0.25 * contact,
            "oil": (summary.get("drag_W") or 0.0) + (summary.get("jet_momentum_W") or 0.0) + 0.5 * land}
    heat[ring] += 0.5 * land
    return heat


def thermal_operating_point(bearing, loads, speed: float, lubricant, setup: ThermalSetup | None = None, *,
                            control: str = "outer", mechanics=None, tol: float = 0.01, max_iterations: int = 60,
                            relaxation: float = 0.7) -> ThermalOperatingPoint:
    """The fixed point of module docstring items 1–4.

    bearing : single-row BallBearing; loads : Loads [N, N·m]; speed [rad/s]; lubricant : name or Lubricant;
    mechanics : callable(temperatures dict [K]) -> static result (None: :func:`bearingsim.solve` of the bearing
    with its operating clearance); tol [K] on max |ΔT|.  Not converged with status "no fixed point (thermal
    runaway)" when the temperatures leave the lubricant's range or keep rising past ``max_iterations``."""

    setup = setup or ThermalSetup()
    lub = get_lubricant(lubricant)
    if setup.oil_inlet_temperature > lub.max_temperature:
        raise InputError("thermal.oil_inlet_temperature",
                         f"{setup.oil_inlet_temperature - 273.15:.1f} degC is above the coolant's range (its boiling "
                         f"or decomposition; {lub.name}: up to {lub.max_temperature - 273.15:.0f} degC)",
                         "give a lower inlet temperature")
    guidance = getattr(setup.cage, "guidance", "outer")
    if mechanics is None:
        def mechanics(temps):
            return solve(bearing_at_temperatures(bearing, temps, speed, setup), loads, speed, control)
    temps = {n: setup.oil_inlet_temperature for n in NODES}
    status, converged, residual, warnings = "maximum iterations reached", False, math.inf, []
    res = summary = sol = None
    history = []
    it = over = 0
    for it in range(1, max_iterations + 1):
        try:
            res = mechanics(temps)
        except InputError as e:  # the operating clearance leaves the bearing model's domain
            status = f"no fixed point: at the temperatures of iteration {it} the bearing is refused ({e})"
            break
        if not res.converged:
            status = f"load distribution did not converge at the temperatures of iteration {it}: {res.status}"
            break
        t_oil = min(max(temps["oil"], lub.min_temperature), lub.max_temperature)
        summary = friction_summary(res, lub, t_oil, model="physical", oil_flow=setup.oil_flow, cage=setup.cage)
        heat = place_heat(summary, guidance)
        sol = build_network(res, setup, heat, temps, lub).solve()
        new = {n: sol.temperatures[n] for n in NODES}
        residual = max(abs(new[n] - temps[n]) for n in NODES)
        history.append(residual)
        temps = {n: temps[n] + relaxation * (new[n] - temps[n]) for n in NODES}
        hot = max(temps.values())
        over = over + 1 if hot > min(lub.max_temperature, T_MAX) else 0
        if over >= 3:
            status = ("no fixed point (thermal runaway): the temperatures stay past the lubricant's range "
                      f"({hot - 273.15:.0f} degC > {lub.max_temperature - 273.15:.0f} degC)")
            break
        if residual < tol:
            converged, status = True, "converged"
            break
        if len(history) > 8 and all(history[-k] > history[-k - 1] for k in range(1, 6)):
            status = "no fixed point (thermal runaway): the temperature change grows from iteration to iteration"
            break
    change = operating_clearance(bearing, temps, speed, setup).change(bearing)["diametral_clearance_change_m"]
    if res is None or summary is None:
        raise InputError("thermal", status, "check the cooling (oil flow, inlet temperature) and the clearance")
    sources = {k[:-2]: summary.get(k) for k in ("rolling_W", "spin_W", "sliding_W", "drag_W", "cage_land_W",
                                                  "cage_pocket_W", "jet_momentum_W")} if summary else {}
    if summary and summary.get("cage_land_estimated"):
        warnings.append("cage land geometry estimated from the ball set (friction.CageLand.estimate)")
    return ThermalOperatingPoint(temperatures=temps, clearance_change=change, result=res, heat_sources=sources,
                                 heat_removed=dict(sol.heat_removed) if sol else {},
                                 energy_balance_error=sol.energy_balance_error if sol else math.nan,
                                 converged=converged, status=status, residual=residual, iterations=it,
                                 warnings=warnings)


__all__ = ["ThermalSetup", "ThermalOperatingPoint", "thermal_operating_point", "bearing_at_temperatures",
           "operating_clearance", "build_network", "place_heat", "NODES"]
