"""[S1] hub unit: a reduced, quasi-static model of the paper's hysteresis mechanism, and its upper bounds.

Sakaguchi & Shibutani [S1] (NTN Technical Review 87, §5, Figs. 10–12, eqs. 8–9) explain the loop of
the tilt against the moment by the traction along the major axis of the contact ellipses, which
holds each ball back from the position it would take on the line joining its groove centres.  This
module puts that mechanism, and only that, on top of the quasi-static Jones–Harris solution of the
hub (:mod:`bearingsim.statics.jones_harris`, the load path of :mod:`.hub_static` or of a case file),
so that W_H(V, f) comes out in milliseconds and can be set beside the dynamic runs.

Model (per ball j of row i at azimuth ψ_j(t) = ψ_j0 + ω_c t, ω_c the cage speed; all SI)
------------------------------------------------------------------------------------------
Quasi-static fields from the statics at the moment M(t): inner-contact load Q_j [N], inner
contact angle α_j [rad], tilt γ_qs(M) [rad] and the compliance C = dγ/dM along the load path
[rad/(N m)] (implicit differentiation as in :mod:`.hub_static`).

1. *Forcing.*  A tilt rate γ̇ turns the inner groove's cross-section at azimuth ψ by γ̇ cos ψ about
   the tilt axis; the contact point, f D from the groove centre (f the inner conformity, D the ball
   diameter), moves along the major axis at γ̇ f D cos ψ, and a ball that follows the outer groove
   and rolls between the two sees half of it: the ball's quasi-static position moves along the major
   axis at v_j = γ̇ ℓ_j, ℓ_j = f D cos ψ_j / 2 [m/rad] (half the arm: our reading of [S1] Fig. 11).
2. *Restoring force.*  A ball offset by e [m] from the line joining the groove centres has its two
   load lines (through the groove centres, at (f_i − ½)D and (f_o − ½)D from its centre) turned by
   e/((f − ½)D), which pushes it back with k_t e, k_t = Q/((f_i − ½)D) + Q/((f_o − ½)D) [N/m].
3. *Traction (linear creep).*  The ball slides along the major axis at v_j + ė_j relative to the inner
   groove; at the small transverse slip s = (v + ė)/u (u the rolling speed of the inner contact,
   (ω − ω_c)(d_m − D cos α)/2) the traction is T = −κ Q s, κ = dμ/ds at s → 0 the creep slope.
   The ball's inertia is negligible (its transverse mode is ≈ 10 kHz), so k_t e = T and

       ė + e/τ = −v_j(t),      τ = κ Q/(u k_t) = κ / (u [1/((f_i − ½)D) + 1/((f_o − ½)D)])  [s],

   a first-order lag of the ball behind its quasi-static position; τ does not depend on Q.
   Sliding caps the traction: |k_t e| ≤ μ_max Q, i.e. |e| ≤ μ_max Q/k_t.
4. *Ring.*  By virtual work the tractions act on the tilt with the generalised moment Σ_j T_j ℓ_j,
   so the tilt is γ = γ_qs(M) + C(M) Σ_j T_j ℓ_j (first order in the small correction; T from γ̇_qs).
   Power dissipated −Σ T_j (v_j + ė_j) = Σ k_t e_j²/τ ≥ 0, so the tilt lags.

For a sinusoidal v the lag is e = −v τ/(1 + iωτ): the loop's area ∝ ωτ/(1 + (ωτ)²), largest at ωτ = 1,
zero for τ → 0 (the ball follows) and for τ → ∞ (the ball stays put and only the stiffness
changes).

Creep slope κ (default: the film-elastic law of :mod:`bearingsim.contact.traction`, read there).
At small slip the physical fluid model's mean stress is the elastic branch τ̄ = G s ℓ/(2h)
(Johnson & Tevaarwerk 1977; :func:`~bearingsim.contact.traction.elastic_plastic_mean_stress`) with
G = c₁ p/(c₂ + c₃ t) − c₄ (Dyson's limiting elastic shear modulus, the lubricant's ``lss_c1…c4``,
p [Pa], t [°C]), ℓ = 2b the chord in the rolling direction and h the Hamrock–Dowson central film
(isothermal), so κ = G b/(h p̄) with p̄ = (π/4) p_max the mean pressure across the central chord,
per ball and moment.  The solids' tangential compliance (Kalker) in series, the inlet heating and
mixed lubrication are not included (each lowers κ or shifts it; ``creep_slope`` overrides it).
The seed's Fig. 4 curve corresponds to κ ≈ 10–16 (μ 0.08 reached at s ≈ 0.01).

Upper bounds of the mechanism (computed, per cell, both with the full arm f D, twice the
model's ℓ, so they bound the model for any creep law with |T| ≤ μ_max Q):

* force: every ball fully sliding moves its moment by at most μ_max Q_j f D |cos ψ_j|, so each branch
  of the loop departs from γ_qs by at most C Σ_j μ_max Q_j f D |cos ψ_j| at M = level:
  W_H ≤ 2 C Σ_j μ_max Q_j f D |cos ψ_j|;
* energy: the loop area cannot exceed the sliding work at μ_max, Σ_j ∮ μ_max Q_j f D |cos ψ_j| |dγ_qs|,
  and an elliptic loop of area A has W_H = 2 A cos θ_r / (π M̂) (θ_r = asin((level − M₀)/M̂)).

Numbers for the hub (``examples/hub-moment-50hz.toml``, μ_max = 0.08; W_H in 10⁻³ °, measured 2026-11-24):

    ============  =====================================  ==================================
    km/h          film-elastic κ (84–393), Hz 1/10/50     κ = 15 (seed Fig. 4 slope), 1/10/50
    ============  =====================================  ==================================
    10            0.122 / 0.010 / 0.002  (τ = 333 ms)     0.018 / 0.103 / 0.050  (τ = 12.7 ms)
    50            0.035 / 0.089 / 0.025  (τ = 22.7 ms)    0.004 / 0.034 / 0.103  (τ = 2.5 ms)
    100           0.013 / 0.085 / 0.063  (τ = 7.1 ms)     0.002 / 0.018 / 0.074  (τ = 1.3 ms)
    ============  =====================================  ==================================

Force bound 1.73, energy bound 1.72·10⁻³ ° in every cell (an independent estimate: 1.4–2.9 and 1.5–3.2; the
largest first-order loop ≈ 0.1, here 0.12).  The dynamic run at 100 km/h, 50 Hz gives 0.145 (interval
0.134–0.155) with the loop estimator, 2.3 × this model's 0.063: the dynamic run also has Hunt–Crossley
contact damping and cage friction, and its traction saturates at s ≈ 10⁻⁴–10⁻³ (not linear creep).  The
seed's 6.7 at 10 km/h, 50 Hz is 3.9 × the mechanism's bounds.  Cost: the statics table ≈ 0.3–4 s per shaft
speed (25 solves; cached), the film slope ≈ 0.5 s, then 10–80 ms per cell (2-core machine under load).
"""

from __future__ import annotations

import math
import time

import numpy as np
from numba import njit

from ..errors import InputError
from .hub_static import TYRE_RADIUS, tied_loads, vehicle_speed_to_shaft

#: μ_max default: the level of [S1] Fig. 4's traction curve (≈ 0.08)
MU_MAX = 0.08

_TABLES: dict = {}


def _channels_tie(case):
    """(offset[5], amplitude[5], frequency) of a case whose load channels are single in-phase sines (or constant)."""
    chans = case.loads.channels
    off = np.zeros(5)
    amp = np.zeros(5)
    freq = None
    phase = None
    for k, ch in enumerate(chans):
        off[k] = ch.offset
        if getattr(ch, "table", None) is not None:
            raise InputError("loads", "the reduced model needs sine loads, not tables", "use sines in phase")
        if len(ch.sines) > 1:
            raise InputError("loads", "the reduced model needs one sine per channel", "use one sine per channel")
        if ch.sines:
            a, f, ph = ch.sines[0]
            if phase is not None and (abs(ph - phase) > 1e-12 or abs(f - freq) > 1e-12 * f):
                raise InputError("loads", "the reduced model needs all varying channels in phase at one frequency",
                                 "give the load channels the same frequency and phase")
            amp[k], freq, phase = a, f, ph
    if amp[4] == 0.0:
        raise InputError("loads", "the moment mz does not vary", 'give mz as a sine, e.g. amplitude = "600 N*m"')
    return off, amp, freq


def _loads_at(s, off, amp):
    from ..statics.jones_harris import Loads

    v = off + amp * s
    return Loads(fa=v[0], fr_y=v[1], fr_z=v[2], m_y=v[3], m_z=v[4])


def static_table(bearing, speed: float, off=None, amp=None, n: int = 25, control: str = "outer") -> dict:
    """Quasi-static fields along the load path, at n points s = sin θ ∈ [−1, 1] (M = M₀ + M̂ s).

    Returns s[n], moment[n] [N m], tilt[n] [rad], compliance[n] [rad/(N m)], inner load Q[n, balls] [N],
    inner contact angle alpha[n, balls] [rad], azimuth[balls] [rad], row[balls], orbital speed [rad/s],
    converged[n].  ``off``/``amp`` the load channels' offsets and amplitudes (default: the hub tie of
    :mod:`.hub_static`).  Cached per (bearing (by its repr), speed, loads).
    """
    from ..statics.jones_harris import solve

    if off is None:
        lo, hi = tied_loads(-600.0), tied_loads(600.0)
        lo_v = np.array([lo.fa, lo.fr_y, lo.fr_z, lo.m_y, lo.m_z])
        hi_v = np.array([hi.fa, hi.fr_y, hi.fr_z, hi.m_y, hi.m_z])
        off, amp = 0.5 * (hi_v + lo_v), 0.5 * (hi_v - lo_v)
    key = (repr(bearing), round(float(speed), 9), tuple(np.round(off, 9)), tuple(np.round(amp, 9)), n, control)
    if key in _TABLES:
        return _TABLES[key]
    if len(_TABLES) > 64:  # a long-running session: keep the cache bounded
        _TABLES.clear()
    s = np.linspace(-1.0, 1.0, n)
    order = np.argsort(np.abs(s), kind="stable")
    res_by = {}
    prev = None
    for i in order:
        r = solve(bearing, _loads_at(s[i], off, amp), speed, control,
                  initial=None if prev is None else prev.displacement)
        if not r.converged and prev is not None:
            cold = solve(bearing, _loads_at(s[i], off, amp), speed, control)
            r = cold if cold.converged else r
        res_by[i] = r
        prev = r if r.converged else prev
    q = np.array([res_by[i].balls["inner_load_N"] for i in range(n)])
    alpha = np.array([res_by[i].balls["inner_contact_angle_rad"] for i in range(n)])
    orb = np.array([res_by[i].balls["orbital_speed_rad_s"] for i in range(n)])
    tilt = np.array([res_by[i].displacement[4] for i in range(n)])
    dfds = amp  # dF/ds along the path; dγ/dM = [K⁻¹ dF/ds]_γz / (dM/ds)
    comp = np.array([(np.linalg.solve(res_by[i].stiffness, dfds))[4] / amp[4] for i in range(n)])
    b0 = res_by[order[0]].balls
    out = {"s": s, "moment": off[4] + amp[4] * s, "tilt": tilt, "compliance": comp, "Q": q, "alpha": alpha,
           "azimuth": np.asarray(b0["azimuth_rad"], dtype=float), "row": np.asarray(b0["row"], dtype=int),
           "orbital_speed": float(np.nanmedian(orb)), "converged": np.array([res_by[i].converged for i in range(n)]),
           "off": off, "amp": amp}
    _TABLES[key] = out
    return out


def film_creep_slope(lubricant, temperature: float, q, alpha, u, ball_diameter, pitch_diameter, conformity,
                     e_eff) -> np.ndarray:
    """Creep slope κ = dμ/ds at s → 0 of the film-elastic law, G b/(h p̄) (module docstring) [-], per contact.

    q [N], alpha [rad], u rolling speed [m/s] (arrays of one shape), temperature [K], e_eff [Pa].
    Unloaded contacts (q ≤ 0 or u ≤ 0) give NaN.
    """
    from ..contact import ehl, hertz
    from ..lubricants import get_lubricant

    lub = get_lubricant(lubricant)
    t = lub.check_temperature(temperature)
    eta0 = lub.dynamic_viscosity(t)
    a_p = lub.pressure_viscosity_coefficient
    tc = t - 273.15
    q = np.asarray(q, dtype=float)
    out = np.full(q.shape, math.nan)
    for idx in np.ndindex(q.shape):
        if not (q[idx] > 0 and u[idx] > 0):
            continue
        rx, ry = hertz.raceway_radii(ball_diameter, pitch_diameter, conformity, float(alpha[idx]), True)
        c = hertz.point_contact_exact(float(q[idx]), rx, ry, e_eff)
        h = ehl.hamrock_dowson_central(float(u[idx]), float(q[idx]), eta0, a_p, e_eff, rx, ry)
        pbar = 0.25 * math.pi * c.max_pressure
        g = max(lub.lss_c1 * pbar / (lub.lss_c2 + lub.lss_c3 * tc) - lub.lss_c4,
                lub.lss_floor * pbar / max(lub.lss_ratio, 1e-30))
        out[idx] = g * c.b / (h * pbar) if h > 0 else math.nan
    return out


def _rolling_speed(omega, w_c, dm, d, alpha):
    """Rolling (entraining) speed of the inner contact, (ω − ω_c)(d_m − D cos α)/2 [m/s] (Jones' kinematics with the
    cage at ω_c; ω, ω_c [rad/s], d_m, D [m], α [rad]; arrays broadcast)."""
    return np.abs(omega - w_c) * 0.5 * (dm - d * np.cos(alpha))


def kernel_creep_slope(case, speed_kmh: float, s: float = 0.0, step: float = 1e-6) -> dict:
    """Effective creep slope of the ball's transverse (major-axis) sliding in the dynamic model's own traction
    kernel, per ball, at the quasi-static state of the load path point ``s`` (M = M₀ + M̂ s) [-].

    Why: the film-elastic slope κ_f = G b/(h p̄) (:func:`film_creep_slope`) is the slope of the traction at a
    contact whose slip is small everywhere.  A ball in an angular contact groove spins against the raceway
    (ω_s ≠ 0), so the local slip s_spin(x) = ω_s x/u at a point x along the major axis is far beyond the film's
    elastic limit over most of the ellipse: the local traction is saturated, μ(|s|) s/|s|.  A small extra
    transverse slip s_t then mainly *turns* the saturated traction vector, dτ_t/ds_t ≈ μ(|s|)/|s|, and the
    contact's transverse slope is ≈ ∫ p μ(|s|)/|s| dA / Q — set by the spin-to-roll ratio (kinematics), not by
    the film.  This function measures that slope on the kernel instead of assuming a formula.

    Method: the dynamic model of ``case`` (:func:`bearingsim.dynamics.model.build_model`, the case's traction
    and lubricant, contact damping off so that only traction answers) at the quasi-static solution for the loads
    of ``s`` and the shaft speed of ``speed_kmh``; every ball's centre velocity is perturbed by ±``step`` [m/s]
    along the bearing axis and along its radius (all balls at once: a ball's acceleration depends only on its own
    velocity, the rings' and the cage's state), giving each ball's 2×2 damping block C = dF/dv [N s/m] in its
    cross-section.  A velocity along the contact normal does not change the tangential slip, so C has rank ≈ 1
    and its trace is the resistance along the major axis; with the reduced model's traction T = −κ (Q_i + Q_o)
    s_t, s_t = v_t/u, κ_eff = −tr(C) u/(Q_i + Q_o), u the inner contact's rolling speed (ω − ω_c)(d_m − D cos α)/2.

    Returns {"kappa": float[balls] (NaN for unloaded balls, in the order of :func:`static_table`), "median",
    "film": float[balls] (:func:`film_creep_slope` at the same state, for comparison), "shaft_speed" [rad/s]}.
    Measured on ``examples/hub-moment-50hz.toml`` at M = 0.3 kN·m (2026-11-24): κ_eff 5.4–8.9 (median 7.0 at
    10 km/h, 7.3 at 100 km/h) against the film's 46–577; 8 strips give the same within 6 %.
    """
    from ..dynamics import forces as fo
    from ..dynamics import layout as ly
    from ..dynamics import model as md
    from ..dynamics.loads import constant_loads
    from ..statics import jones_harris as jh
    from ..statics import layout as kn

    if not (isinstance(speed_kmh, (int, float)) and math.isfinite(speed_kmh) and speed_kmh > 0):
        raise InputError("speed_kmh", f"must be a positive number, got {speed_kmh!r}", "e.g. 50")
    if not (isinstance(s, (int, float)) and -1.0 <= s <= 1.0):
        raise InputError("s", f"must be in [-1, 1] (M = M0 + M^ s), got {s!r}", "e.g. 0")
    bearing = case.bearing
    off, amp, _ = _channels_tie(case)
    omega = vehicle_speed_to_shaft(float(speed_kmh), TYRE_RADIUS)
    loads = _loads_at(s, off, amp)
    res = jh.solve(bearing, loads, omega, getattr(case, "control", "outer"))
    if not res.converged:
        raise InputError("loads", f"no quasi-static equilibrium at s = {s} ({res.status})", "check the case's loads")
    opts = dict(case.model_options())
    opts.update(speed=(omega, omega, 0.0), damping_alpha=0.0)
    model = md.build_model(bearing, **opts)
    y0 = md.initial_state(model, res, omega)
    spec = constant_loads(loads.fa, loads.fr_y, loads.fr_z, loads.m_y, loads.m_z)
    nb = model.n_balls
    pos = np.array([y0[model.ball_slice(k).start + ly.B_POS:model.ball_slice(k).start + ly.B_POS + 3]
                    for k in range(nb)])
    e_r = np.zeros((nb, 3))
    e_r[:, 1:] = pos[:, 1:] / np.hypot(pos[:, 1], pos[:, 2])[:, None]
    e_x = np.zeros((nb, 3))
    e_x[:, 0] = 1.0
    mass = np.array([model.rows[int(model.ball_row[k]), kn.P_MASS] for k in range(nb)])

    def acc_along(direction, sign):
        y = y0.copy()
        for k in range(nb):
            o = model.ball_slice(k).start + ly.B_VEL
            y[o:o + 3] += sign * step * direction[k]
        dy, _, _ = fo.evaluate(model, 0.0, y, spec, want_diag=False)
        return np.array([dy[model.ball_slice(k).start + ly.B_VEL:model.ball_slice(k).start + ly.B_VEL + 3]
                         for k in range(nb)])

    trace = np.zeros(nb)
    for direction in (e_x, e_r):
        da = acc_along(direction, 1.0) - acc_along(direction, -1.0)
        trace += mass * np.sum(da * direction, axis=1) / (2.0 * step)
    balls = res.balls
    qi = np.asarray(balls["inner_load_N"], dtype=float)
    qo = np.asarray(balls["outer_load_N"], dtype=float)
    alpha = np.asarray(balls["inner_contact_angle_rad"], dtype=float)
    rows = bearing.rows
    ball_row = np.asarray(balls["row"], dtype=int)
    d = np.array([rows[i].bearing.ball_diameter for i in ball_row])
    dm = np.array([rows[i].bearing.pitch_diameter for i in ball_row])
    w_c = float(np.nanmedian(np.asarray(balls["orbital_speed_rad_s"], dtype=float)))
    u = _rolling_speed(omega, w_c, dm, d, alpha)
    loaded = (qi > 0) & (qo > 0)
    kappa = np.where(loaded, -trace * u / np.where(loaded, qi + qo, 1.0), math.nan)
    b0 = rows[0].bearing
    film = film_creep_slope(case.lubricant, case.temperature, qi, alpha, u, float(d[0]), float(dm[0]),
                            float(b0.inner_conformity), b0.effective_modulus)
    return {"kappa": kappa, "median": float(np.nanmedian(kappa)), "film": film, "shaft_speed": omega}


def _interp_rows(s_grid, table, s):
    """Linear interpolation of table[n, ...] at s (array) along the first axis."""
    idx = np.clip(np.searchsorted(s_grid, s) - 1, 0, len(s_grid) - 2)
    w = (s - s_grid[idx]) / (s_grid[idx + 1] - s_grid[idx])
    w = w.reshape(w.shape + (1,) * (table.ndim - 1))
    return table[idx] * (1 - w) + table[idx + 1] * w


def reduced_wh(case_or_bearing, speed_kmh: float, frequency_hz: float, level: float = 300.0,
               creep_slope: float | None = None, mu_max: float = MU_MAX, cycles: int = 2, steps_per_cycle: int = 360,
               lubricant=None, temperature: float | None = None, n_table: int = 25, max_cycles: int = 40,
               orbit: bool = True) -> dict:
    """W_H of the reduced traction-lag model (module docstring) and the mechanism's force and energy bounds.

    Parameters
    ----------
    case_or_bearing : Case or bearing
        A dynamic case (:class:`bearingsim.dynamics.case.Case`: bearing, in-phase sine loads, lubricant,
        temperature) or a bearing (the hub tie of :mod:`.hub_static`, M̂ = 600 N m; then give
        ``lubricant``/``temperature`` or ``creep_slope``).
    speed_kmh : float
        Vehicle speed [km/h] (shaft speed over the tyre radius of :mod:`.hub_static`).
    frequency_hz : float
        Load frequency [Hz].
    level : float
        Moment at which W_H is read [N m].
    creep_slope : float, "kernel" or None
        κ = dμ/ds at small slip [-] (None: the film-elastic slope per ball and moment; "kernel": the
        spin-softened slope of the dynamic model's traction kernel per ball, :func:`kernel_creep_slope` at the
        mean moment, needs a case).
    mu_max : float
        Traction cap [-].
    cycles : int
        Load cycles on the time grid (the balls orbit over them; the last one is solved for its periodic lag and
        read).
    steps_per_cycle : int
        Time steps per cycle (exponential update of the linear lag, exact for τ and v constant over a step).
    lubricant, temperature : name or Lubricant, float
        With a bearing: the lubricant and its temperature [K] of the film-elastic slope.
    n_table : int
        Points of the quasi-static table along the load path (:func:`static_table`) the ball loads are
        interpolated in.
    max_cycles : int
        Cap on the cycles integrated for the start-up.
    orbit : bool
        The balls orbit at the cage speed (False: frozen at their azimuths, to isolate the lag).

    Returns
    -------
    dict
        SI: ``wh`` [rad], ``phase_lag`` [rad], ``loop_area`` [J], ``tau`` [s] (median over the
        loaded balls and the cycle), ``tau_rows`` [s] per bearing row, ``omega_tau`` (2π f τ), ``creep_slope``
        (median κ used), ``bound_force`` and ``bound_energy`` [rad], ``sliding_work`` [J per cycle at μ_max],
        ``saturated_fraction`` (share of ball-steps at the μ_max cap), ``dissipated`` [J] (sliding work of the model
        over the cycle read, ∮ −Σ T (v + ė) dt), ``tilt_work`` [J] (∮ −Σ T v dt, the part that passes through the
        tilt and must equal ``loop_area`` to first order; the rest, ∮ Σ k_t e ė dt = −∮ Σ ½ e² dk_t, is exchanged with
        the varying normal loads, which the model does not feed back to the ring), ``compliance`` [rad/(N m)] at
        ``level``, ``cycles`` (integrated), ``settled`` (exp(−t/τ_max) left of the start-up at the last cycle),
        ``wall_seconds``.
    """
    t_wall = time.perf_counter()
    for name, v in (("speed_kmh", speed_kmh), ("frequency_hz", frequency_hz)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(name, f"must be a positive number, got {v!r}", "e.g. 50")
    kernel = isinstance(creep_slope, str)
    if kernel and creep_slope != "kernel":
        raise InputError("creep_slope", f"unknown creep slope {creep_slope!r}", 'give a number, None or "kernel"')
    if not kernel and creep_slope is not None and not (isinstance(creep_slope, (int, float))
                                                       and math.isfinite(creep_slope) and creep_slope > 0):
        raise InputError("creep_slope", f"must be positive, got {creep_slope!r}", "e.g. 15 (dμ/ds at small slip)")
    if not (math.isfinite(mu_max) and mu_max > 0):
        raise InputError("mu_max", f"must be positive, got {mu_max!r}", "e.g. 0.08")
    if hasattr(case_or_bearing, "loads") and hasattr(case_or_bearing, "bearing"):
        case = case_or_bearing
        bearing = case.bearing
        off, amp, _ = _channels_tie(case)
        lubricant = case.lubricant if lubricant is None else lubricant
        temperature = case.temperature if temperature is None else temperature
        control = getattr(case, "control", "outer")
    else:
        bearing = case_or_bearing
        off = amp = None
        control = "outer"
    omega = vehicle_speed_to_shaft(float(speed_kmh), TYRE_RADIUS)
    tab = static_table(bearing, omega, off, amp, n=n_table, control=control)
    m0, mhat = float(tab["off"][4]), float(tab["amp"][4])
    if not (abs(level - m0) < abs(mhat)):
        raise InputError("level", f"{level!r} N m is not passed by the moment {m0:g} ± {abs(mhat):g} N m",
                         "choose a level inside the moment's range")
    rows = bearing.rows
    n_per = [r.bearing.ball_count for r in rows]
    ball_row = tab["row"]
    d = np.array([rows[i].bearing.ball_diameter for i in ball_row])
    dm = np.array([rows[i].bearing.pitch_diameter for i in ball_row])
    fi = np.array([rows[i].bearing.inner_conformity for i in ball_row])
    fo = np.array([rows[i].bearing.outer_conformity for i in ball_row])
    lever = 0.5 * fi * d  # ℓ / cos ψ [m/rad]
    kt_per_q = 1.0 / ((fi - 0.5) * d) + 1.0 / ((fo - 0.5) * d)  # k_t / Q [1/m]
    w_c = tab["orbital_speed"]

    u_tab = _rolling_speed(omega, w_c, dm[None, :], d[None, :], tab["alpha"])
    if kernel:
        if off is None:
            raise InputError("creep_slope", '"kernel" needs a dynamic case (its traction model and lubricant)',
                             "pass the case instead of the bearing")
        key = ("kernel", id(tab), case.fingerprint())
        if key not in _TABLES:
            k = kernel_creep_slope(case, float(speed_kmh))["kappa"]
            _TABLES[key] = np.broadcast_to(np.where(np.isfinite(k), k, np.nanmax(k)), tab["Q"].shape).copy()
        kap_tab = _TABLES[key]
    elif creep_slope is None:
        if lubricant is None:
            raise InputError("creep_slope", "no lubricant to compute the film-elastic creep slope from",
                             "give creep_slope = dμ/ds, or a case with a lubricant")
        e_eff = rows[0].bearing.effective_modulus
        # κ on the table's moments (per ball of the pattern), then interpolated
        key = ("kappa", id(tab), repr(lubricant), temperature)
        if key not in _TABLES:
            k = film_creep_slope(lubricant, temperature if temperature is not None else 313.15, tab["Q"],
                                 tab["alpha"], u_tab, float(d[0]), float(dm[0]), float(fi[0]), e_eff)
            _TABLES[key] = np.where(np.isfinite(k), k, np.nanmax(k))
        kap_tab = _TABLES[key]
    else:
        kap_tab = np.full_like(tab["Q"], float(creep_slope))
    tau_tab = kap_tab / (np.maximum(u_tab, 1e-12) * kt_per_q[None, :])
    tau_max = float(np.max(tau_tab[tab["Q"] > 0])) if np.any(tab["Q"] > 0) else 0.0

    # time grid: at least `cycles` cycles and enough for the lag's start-up, exp(−t/τ), to decay to e⁻⁷
    # (at most ``max_cycles``); M = M0 + M̂ sin θ
    cycles = max(int(cycles), min(int(max_cycles), int(math.ceil(7.0 * tau_max * frequency_hz)) + 1))
    n_steps = cycles * steps_per_cycle
    theta = 2.0 * math.pi * np.arange(n_steps + 1) / steps_per_cycle
    t = theta / (2.0 * math.pi * frequency_hz)
    s = np.sin(theta)
    q = np.maximum(_interp_rows(tab["s"], tab["Q"], s), 0.0)  # [n+1, balls]
    kappa = _interp_rows(tab["s"], kap_tab, s)
    gamma_qs = _interp_rows(tab["s"], tab["tilt"], s)
    comp = _interp_rows(tab["s"], tab["compliance"], s)
    u = _interp_rows(tab["s"], u_tab, s)
    # the balls orbit: azimuth ψ_j(t) = ψ_j0 + ω_c t; the fields of the pattern are read at the ball's azimuth
    psi = tab["azimuth"][None, :] + (w_c if orbit else 0.0) * t[:, None]
    q, kappa = _at_azimuth(tab, q, kappa, psi, n_per)
    u, _ = _at_azimuth(tab, u, u, psi, n_per)
    tau = kappa / (np.maximum(u, 1e-12) * kt_per_q[None, :])  # [s]
    ell = lever[None, :] * np.cos(psi)  # [m/rad]
    dgam = np.gradient(gamma_qs, t)  # γ̇_qs
    v = dgam[:, None] * ell  # [m/s]
    e_cap = mu_max / kt_per_q  # |e| ≤ μ_max Q / k_t
    # march the lag from e = 0 over the whole grid (the balls orbit meanwhile) and read the last cycle:
    # e_{k+1} = d_k e_k + g_k, d_k = exp(−h/τ), g_k = −v τ (1 − d_k) (exact for τ, v constant over a step),
    # capped at |e| ≤ μ_max Q/k_t.  ``settled``: exp(−t_last/τ_max), what is left of the start-up.
    h = t[1] - t[0]
    tk = 0.5 * (tau[:-1] + tau[1:])
    vk = 0.5 * (v[:-1] + v[1:])
    dec = np.exp(-h / tk)
    gk = -vk * tk * (1.0 - dec)
    first = (cycles - 1) * steps_per_cycle
    e, sat = _march(dec, gk, e_cap, q > 0, first)
    loaded = q > 0
    traction = kt_per_q[None, :] * q * e  # T_j = k_t e [N]
    dmom = np.sum(traction * ell, axis=1)  # Σ T_j ℓ_j [N m]
    gamma = gamma_qs + comp * dmom
    # energy dissipated by the sliding over the last cycle, ∫ −Σ T_j (v_j + ė_j) dt (midpoint rule) [J]
    lc = slice(first, n_steps)
    t_mid = 0.5 * (traction[first:-1] + traction[first + 1:])
    slip = vk[lc] + np.diff(e[first:], axis=0) / h
    dissipated = float(-np.sum(t_mid * slip) * h)
    tilt_work = float(-np.sum(t_mid * vk[lc]) * h)  # ∮ −Σ T_j v_j dt: the work the tilt does on the tractions
    moment = m0 + mhat * s
    from ..dynamics.analysis import hysteresis_estimate

    last = slice((cycles - 1) * steps_per_cycle, n_steps)
    est = hysteresis_estimate(t[last], moment[last], gamma[last], float(frequency_hz), float(level),
                              first_cycle=0, min_cycles=2)
    # bounds (module docstring), at M = level for the force bound
    s_lvl = (level - m0) / mhat
    q_l = np.maximum(_interp_rows(tab["s"], tab["Q"], np.array([s_lvl]))[0], 0.0)
    c_l = float(_interp_rows(tab["s"], tab["compliance"], np.array([s_lvl]))[0])
    arm = fi * d * np.abs(np.cos(tab["azimuth"]))
    bound_force = 2.0 * abs(c_l) * float(np.sum(mu_max * q_l * arm))
    cyc = slice((cycles - 1) * steps_per_cycle, n_steps + 1)
    rate = np.abs(dgam[cyc])
    work_density = np.sum(mu_max * q[cyc] * fi[None, :] * d[None, :] * np.abs(np.cos(psi[cyc])), axis=1) * rate
    sliding_work = float(np.trapezoid(work_density, t[cyc]))
    th_r = math.asin(s_lvl)
    bound_energy = 2.0 * sliding_work * math.cos(th_r) / (math.pi * abs(mhat))
    tau_loaded = tau[cyc][loaded[cyc]]
    tau_rows = [float(np.median(tau[cyc][:, ball_row == i][loaded[cyc][:, ball_row == i]]))
                if np.any(loaded[cyc][:, ball_row == i]) else math.nan for i in range(len(rows))]
    tau_med = float(np.median(tau_loaded)) if tau_loaded.size else math.nan
    return {"wh": float(est.mean), "phase_lag": float(est.phase_lag), "loop_area": float(est.loop_area),
            "tau": tau_med, "tau_rows": tau_rows, "omega_tau": 2.0 * math.pi * frequency_hz * tau_med,
            "creep_slope": float(np.median(kappa[cyc][loaded[cyc]])) if tau_loaded.size else math.nan,
            "mu_max": float(mu_max), "bound_force": bound_force, "bound_energy": bound_energy,
            "sliding_work": sliding_work, "dissipated": dissipated, "tilt_work": tilt_work,
            "saturated_fraction": sat / max(int(np.count_nonzero(loaded[first + 1:])), 1),
            "compliance": c_l, "shaft_speed": omega, "cage_speed": w_c,
            "static_converged": bool(np.all(tab["converged"])), "cycles": cycles,
            "settled": math.exp(-(cycles - 1) / (frequency_hz * tau_max)) if tau_max > 0 else 0.0,
            "wall_seconds": time.perf_counter() - t_wall}


@njit(cache=True)
def _march(dec, gk, e_cap, loaded, first):
    """e_{k+1} = clip(d_k e_k + g_k, ±e_cap) from e_0 = 0 → (e[n+1, balls], count of capped loaded ball-steps from
    step ``first`` on)."""
    n, m = dec.shape
    e = np.zeros((n + 1, m))
    sat = 0
    for k in range(n):
        for j in range(m):
            x = e[k, j] * dec[k, j] + gk[k, j]
            c = e_cap[j]
            if x > c or x < -c:
                if k >= first and loaded[k + 1, j]:
                    sat += 1
                x = c if x > c else -c
            e[k + 1, j] = x
    return e, sat


def _at_azimuth(tab, a, b, psi, n_per):
    """Values of the per-ball fields a, b [n, balls] (given at the table's fixed azimuths) at the balls' current
    azimuths psi [n, balls]: periodic linear interpolation within each row."""
    az = tab["azimuth"]
    out_a = np.empty_like(a)
    out_b = np.empty_like(b)
    start = 0
    for nb in n_per:
        sl = slice(start, start + nb)
        a0 = az[sl][0]
        step = 2.0 * math.pi / nb
        x = ((psi[:, sl] - a0) / step) % nb
        i0 = np.floor(x).astype(int) % nb
        i1 = (i0 + 1) % nb
        w = x - np.floor(x)
        rows_idx = np.arange(a.shape[0])[:, None]
        out_a[:, sl] = a[:, sl][rows_idx, i0] * (1 - w) + a[:, sl][rows_idx, i1] * w
        out_b[:, sl] = b[:, sl][rows_idx, i0] * (1 - w) + b[:, sl][rows_idx, i1] * w
        start += nb
    return out_a, out_b


__all__ = ["MU_MAX", "film_creep_slope", "reduced_wh", "static_table"]
