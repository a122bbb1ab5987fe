"""Post-processing of dynamic results: hysteresis of a tilt against a periodic moment.

Functions on plain arrays (SI), so that they serve :class:`bearingsim.dynamics.results.Results`
(``loop_widths`` / ``fluctuation_range`` / ``hysteresis`` call them), the hub study and scripts alike.

Two readings of the loop width W_H of Sakaguchi & Shibutani [S1] (NTN Technical Review 87, Fig. 8:
the tilt where the moment passes 0.3 kN·m falling minus where it passes it rising):

* :func:`hysteresis_estimate` — the estimator: a least-squares fit of harmonics 0…N of the load
  frequency to the response and to the load over each load cycle, W_H read on the fitted periodic
  curves, start-up cycles discarded by a periodicity criterion, mean and 95 % interval over the
  remaining cycles, the loop area ∮ M dγ, and the phase lag and compliance of the fundamental.
* :func:`loop_widths` — the raw two-point reading on the samples, kept as a diagnostic: it reads
  whatever vibration rides on the loop at the two instants (the hub's lightly damped 1.2 kHz tilt
  mode makes it scatter by ±0.5·10⁻³ ° against a loop of ≈ 0.15·10⁻³ ° without the EHL damping).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..errors import InputError


def loop_widths(load: np.ndarray, response: np.ndarray, level: float) -> np.ndarray:
    """Hysteresis widths of ``response`` against ``load`` at the load ``level``, one per load cycle.

    Sakaguchi & Shibutani, NTN Technical Review 87, Fig. 8 definition: for every time the load
    passes ``level`` rising and then falling, the response at the falling crossing minus that at the
    rising one (linear interpolation between samples); positive when the response lags the load.
    load, response : float[n] samples at the same times (e.g. M_z [N m] and the tilt γz [rad]);
    level in the unit of ``load``.  Returns float[cycles] in the unit of ``response``.

    Diagnostic only: unfiltered, it reads any vibration at the two instants
    (use :func:`hysteresis_estimate`).
    """
    m = np.asarray(load) - level
    g = np.asarray(response)
    out = []
    rising = math.nan
    for i in range(1, len(m)):
        if m[i - 1] == m[i] or (m[i - 1] > 0) == (m[i] > 0):
            continue
        w = m[i - 1] / (m[i - 1] - m[i])
        value = g[i - 1] + w * (g[i] - g[i - 1])
        if m[i] > m[i - 1]:
            rising = value
        elif not math.isnan(rising):
            out.append(value - rising)
            rising = math.nan
    return np.array(out)


def fluctuation_range(load: np.ndarray, response: np.ndarray, level: float) -> float:
    """W_H: the two-point width of the last complete load cycle (:func:`loop_widths`); NaN if there is none.

    Diagnostic only (see :func:`loop_widths`); the estimate is :func:`hysteresis_estimate`.
    """
    w = loop_widths(load, response, level)
    return float(w[-1]) if len(w) else math.nan


# --------------------------------------------------------------------------------------------------
# harmonic fit per load cycle


def harmonic_basis(theta: np.ndarray, n_harmonics: int) -> np.ndarray:
    """Columns 1, cos θ, sin θ, cos 2θ, sin 2θ, …, cos Nθ, sin Nθ at the phases θ [rad] → float[len(θ), 2N+1]."""
    theta = np.asarray(theta, dtype=float)
    cols = [np.ones_like(theta)]
    for k in range(1, n_harmonics + 1):
        cols.append(np.cos(k * theta))
        cols.append(np.sin(k * theta))
    return np.stack(cols, axis=-1)


def series_value(coef: np.ndarray, theta) -> np.ndarray:
    """Value of the Fourier series with coefficients (c0, a1, b1, …, aN, bN) at θ [rad]."""
    n = (len(coef) - 1) // 2
    return harmonic_basis(np.atleast_1d(theta), n) @ coef


def series_slope(coef: np.ndarray, theta) -> np.ndarray:
    """dx/dθ of the Fourier series (c0, a1, b1, …) at θ [rad]."""
    theta = np.atleast_1d(np.asarray(theta, dtype=float))
    n = (len(coef) - 1) // 2
    out = np.zeros_like(theta)
    for k in range(1, n + 1):
        out += k * (-coef[2 * k - 1] * np.sin(k * theta) + coef[2 * k] * np.cos(k * theta))
    return out


def fit_cycles(t: np.ndarray, x: np.ndarray, frequency: float, n_harmonics: int = 5) -> np.ndarray:
    """Least-squares fit of harmonics 0…N of ``frequency`` to ``x`` over each complete load cycle.

    Cycle k holds the samples with t[0] + k/f ≤ t < t[0] + (k+1)/f; the phase is θ = 2π f (t − t[0]),
    the same origin for every cycle, so that the coefficients of successive cycles compare directly.
    A cycle is complete when the record reaches its end to within 1.5 sample intervals.
    t [s], x [any unit], frequency [Hz] → float[cycles, 2N+1]: (c0, a1, b1, …, aN, bN) per cycle,
    x ≈ c0 + Σ a_k cos kθ + b_k sin kθ.
    """
    t = np.asarray(t, dtype=float)
    x = np.asarray(x, dtype=float)
    period = 1.0 / frequency
    u = (t - t[0]) / period
    idx = np.floor(u + 1e-9).astype(int)
    dt = float(np.median(np.diff(t))) if len(t) > 1 else period
    n_cycles = int(np.floor((t[-1] - t[0] + 1.5 * dt) / period + 1e-9))
    need = 2 * (2 * n_harmonics + 1)
    out = []
    for k in range(n_cycles):
        sel = idx == k
        if np.count_nonzero(sel) < need:
            raise InputError("output_interval", f"load cycle {k} holds {np.count_nonzero(sel)} samples, fewer than "
                             f"{need} for {n_harmonics} harmonics", "write samples more often (≥ 100 per load cycle)")
        a = harmonic_basis(2.0 * math.pi * u[sel], n_harmonics)
        out.append(np.linalg.lstsq(a, x[sel], rcond=None)[0])
    return np.array(out).reshape(n_cycles, 2 * n_harmonics + 1)


def level_crossings(coef: np.ndarray, level: float, grid: int = 1440) -> tuple[float, float]:
    """Phases θ [rad] in [0, 2π) where the fitted periodic load passes ``level`` rising and falling.

    Bracketed on a grid of ``grid`` phases and solved by Brent's method on the series itself (not on
    samples).  With several crossings of each kind (a load that is not a single sine) the rising one
    with the steepest rise and the falling one with the steepest fall are taken.  (nan, nan) when the
    fitted load does not pass the level.
    """
    from scipy.optimize import brentq

    def f(q: float) -> float:
        return float(series_value(coef, q)[0]) - level

    th = np.linspace(0.0, 2.0 * math.pi, grid + 1)
    v = series_value(coef, th) - level
    rise, fall = [], []
    for i in np.nonzero(np.sign(v[:-1]) != np.sign(v[1:]))[0]:
        fa, fb = f(th[i]), f(th[i + 1])  # the scalar evaluation brentq sees
        if fa == 0.0:
            root = th[i]
        elif fa * fb < 0.0:
            root = brentq(f, th[i], th[i + 1], xtol=1e-15, rtol=4 * np.finfo(float).eps)
        else:  # the grid and the scalar evaluation disagree in the last bits: the root is the nearer end
            root = th[i] if abs(fa) <= abs(fb) else th[i + 1]
        s = float(series_slope(coef, root)[0])
        if s != 0.0:
            (rise if s > 0 else fall).append((s, root % (2.0 * math.pi)))
    if not rise or not fall:
        return math.nan, math.nan
    return max(rise)[1], min(fall)[1]


def loop_area(load_coef: np.ndarray, response_coef: np.ndarray) -> float:
    """∮ M dγ over one period of the two Fourier series (exact) [load unit × response unit, e.g. J].

    Derivation: with M(θ) = A0 + Σ_k (a_k cos kθ + b_k sin kθ) and γ(θ) = C0 + Σ_k (c_k cos kθ + d_k sin kθ),
    dγ = Σ_k k (−c_k sin kθ + d_k cos kθ) dθ, and ∮ M dγ = ∫₀^{2π} M(θ) γ'(θ) dθ.  By orthogonality over
    a period (∫ cos jθ cos kθ = ∫ sin jθ sin kθ = π δ_jk, ∫ cos jθ sin kθ = 0, ∫ γ' = 0 kills A0) only
    a_k·k d_k cos² and b_k·(−k c_k) sin² survive:

        ∮ M dγ = π Σ_k k (a_k d_k − b_k c_k).

    It is the work done on the ring by the moment per cycle, i.e. the energy the tilt dissipates
    against the moment; > 0 for a lag.  Check: M = M̂ sin θ, γ = γ̂ sin(θ − φ) (c₁ = −γ̂ sin φ,
    d₁ = γ̂ cos φ) gives π M̂ γ̂ sin φ, the area of the ellipse.
    """
    n = min(len(load_coef), len(response_coef)) // 2
    s = 0.0
    for k in range(1, n + 1):
        a, b = load_coef[2 * k - 1], load_coef[2 * k]
        c, d = response_coef[2 * k - 1], response_coef[2 * k]
        s += k * (a * d - b * c)
    return math.pi * s


def fundamental(coef: np.ndarray) -> complex:
    """Complex amplitude Z of the fundamental, x₁(θ) = Re(Z e^{iθ}) = a1 cos θ + b1 sin θ ⇒ Z = a1 − i b1."""
    return complex(coef[1], -coef[2])


def leakage_bound(ratio: float, n_harmonics: int = 5, samples_per_cycle: int = 400,
                  level_fraction: float = 0.5) -> float:
    """Largest error of one cycle's W_H per unit amplitude of a vibration at ``ratio`` × the load frequency [-].

    A vibration A cos(rθ + ϕ) with r = f_vib / f_load not an integer is not orthogonal to the harmonics
    over one cycle.  The fit is linear and real, so the error it leaves in W_H is
    Re(A e^{iϕ} E(r)), E(r) = [P e^{irθ}](θ_f) − [P e^{irθ}](θ_r), with P the least-squares projection on
    harmonics 0…N over one cycle; the largest over the vibration's phase is A |E(r)|, which this
    function computes (``samples_per_cycle`` uniform samples; θ_r = asin(level_fraction), θ_f = π − θ_r,
    the crossings of a sine load at level_fraction × its amplitude).

    A closed-form majorant: the projection of e^{irθ} on e^{ikθ} over a period is
    (e^{2πi(r−k)} − 1) / (2πi(r−k)), of modulus |sin πr| / (π|r − k|), so
    |E| ≤ (2|sin πr|/π) Σ_{|k|≤N} 1/|r − k| (≈ 0.25 for r = 24.68, N = 5).  It sums the terms in modulus;
    their phases alternate and the true |E| is far smaller: 0.010 at r = 24.68 (the hub's ≈ 1.23 kHz tilt
    mode at a 50 Hz load), 0 when r is an integer.  The two-point reading takes up to 2A.
    Returns |E(r)| (2 when r ≤ N + 0.5: the vibration is then a harmonic of the loop itself).
    """
    r = abs(float(ratio))
    if r <= n_harmonics + 0.5:
        return 2.0
    th = 2.0 * math.pi * np.arange(samples_per_cycle) / samples_per_cycle
    a = harmonic_basis(th, n_harmonics)
    coef = np.linalg.lstsq(a, np.exp(1j * r * th), rcond=None)[0]
    th_r = math.asin(level_fraction)
    ends = harmonic_basis(np.array([math.pi - th_r, th_r]), n_harmonics) @ coef
    return float(abs(ends[0] - ends[1]))


def mean_leakage_bound(ratio: float, cycles: int, n_harmonics: int = 5, samples_per_cycle: int = 400,
                       level_fraction: float = 0.5) -> float:
    """Largest error of the MEAN of W_H over ``cycles`` successive cycles per unit vibration amplitude [-].

    The vibration's phase advances by 2πr from one cycle to the next, so cycle j's error is
    Re(A e^{i(ϕ + 2πrj)} E(r)) (:func:`leakage_bound`) and the mean over n_c cycles has modulus at most
    A |E(r)| |sin(π r n_c)| / (n_c |sin π r|) (a geometric sum).
    """
    r = abs(float(ratio))
    per_cycle = leakage_bound(r, n_harmonics, samples_per_cycle, level_fraction)
    s = abs(math.sin(math.pi * r))
    if s < 1e-12:
        return 0.0 if r > n_harmonics + 0.5 else per_cycle
    return per_cycle * min(1.0, abs(math.sin(math.pi * r * cycles)) / (cycles * s))


# --------------------------------------------------------------------------------------------------
# the estimator


@dataclass(frozen=True)
class LoopEstimate:
    """Hysteresis of a response against a periodic load (:func:`hysteresis_estimate`); SI, per-cycle arrays."""

    widths: np.ndarray  #: W_H per used cycle [rad], from the harmonic fit, falling − rising at ``level``
    cycles_used: int
    first_cycle: int  #: index of the first cycle used (after the start-up cycles discarded)
    mean: float  #: [rad]
    ci95: tuple  #: 95 % interval of the mean (Student t over cycles) [rad]
    loop_area: float  #: mean energy per cycle dissipated by the tilt against the moment, ∮ M dγ [J]
    loop_area_ci95: tuple
    phase_lag: float  #: lag of the response's fundamental behind the load's [rad], > 0 = lag
    compliance: float  #: |Γ1| / |M1| of the fundamentals [rad/(N m)]
    two_point: np.ndarray  #: the raw two-crossing reading per cycle (diagnostic only) [rad]
    periodic_from: int  #: cycle index where the periodicity criterion first held
    criterion: str  #: plain-text description of the criterion used
    loop_areas: np.ndarray = None  #: ∮ M dγ per used cycle [J]
    cycles_total: int = 0  #: complete load cycles in the record
    status: str = "ok"  #: "ok", or why the estimate is incomplete (too few periodic cycles, no crossing)
    change: np.ndarray = None  #: the periodicity measure Δ_k of every cycle (NaN for cycle 0) [-]

    @property
    def ok(self) -> bool:
        return self.status == "ok"

    def to_dict(self) -> dict:
        """Plain JSON-able dict (SI)."""
        return {"widths": [float(w) for w in self.widths], "cycles_used": self.cycles_used,
                "first_cycle": self.first_cycle, "mean": self.mean, "ci95": list(self.ci95),
                "loop_area": self.loop_area, "loop_area_ci95": list(self.loop_area_ci95),
                "phase_lag": self.phase_lag, "compliance": self.compliance,
                "two_point": [float(w) for w in self.two_point], "periodic_from": self.periodic_from,
                "criterion": self.criterion, "cycles_total": self.cycles_total, "status": self.status}


def t_interval(values: np.ndarray, confidence: float = 0.95) -> tuple[float, float]:
    """Student-t interval of the mean of ``values`` (nan, nan with fewer than 2 values)."""
    from scipy.stats import t as student

    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if len(v) < 2:
        return math.nan, math.nan
    half = float(student.ppf(0.5 + 0.5 * confidence, len(v) - 1) * np.std(v, ddof=1) / math.sqrt(len(v)))
    m = float(np.mean(v))
    return m - half, m + half


def periodicity_change(response_coef: np.ndarray) -> np.ndarray:
    """Δ_k = max(|C0_k − C0_{k−1}|, |Γ1_k − Γ1_{k−1}|) / |Γ1_k| per cycle (NaN for cycle 0) [-].

    C0 the fitted mean and Γ1 the complex fundamental (:func:`fundamental`) of the response in cycle k.
    """
    n = len(response_coef)
    out = np.full(n, math.nan)
    for k in range(1, n):
        g1 = fundamental(response_coef[k])
        d0 = abs(response_coef[k, 0] - response_coef[k - 1, 0])
        d1 = abs(g1 - fundamental(response_coef[k - 1]))
        out[k] = max(d0, d1) / abs(g1) if abs(g1) > 0 else math.inf
    return out


def stationary_floor(response_coef: np.ndarray, change: np.ndarray, factor: float = 1.5) -> float:
    """Scatter floor of the periodicity measure once the response is stationary [-]: ``factor`` × the median
    Δ_k (:func:`periodicity_change`) over the last half of the cycles (k ≥ max(1, n // 2), at least 3 of them)
    when the fitted mean's changes over those cycles are not all of one sign; 0 when they are (a drift is no
    floor) or when there are too few cycles.

    Why: a response that is periodic in the load only up to a ripple at a frequency the load's period does not
    divide — the ball passage under a 1 Hz moment (≈ 9 passes per cycle at 10 km/h, in another phase each
    cycle) — changes its fitted mean and fundamental from cycle to cycle by a stationary scatter that no
    start-up decay goes below; a fixed tolerance under that scatter would never call the run periodic.  The
    scatter enters the interval of W_H; a drift (one sign) would bias it and is not accepted as a floor.
    """
    n = len(change)
    ks = np.arange(max(1, n // 2), n)
    if len(ks) < 3:
        return 0.0
    d0 = response_coef[ks, 0] - response_coef[ks - 1, 0]
    if np.all(d0 > 0) or np.all(d0 < 0):
        return 0.0
    return factor * float(np.median(change[ks]))


def hysteresis_estimate(t, load, response, frequency: float, level: float, n_harmonics: int = 5,
                        min_cycles: int = 6, tolerance: float = 1e-3, first_cycle: int | None = None) -> LoopEstimate:
    """Loop width W_H, loop area, phase lag and compliance of ``response`` against a periodic ``load``.

    Parameters
    ----------
    t : array of float
        Sample times of one run [s].
    load : array of float
        The periodic load at ``t`` [N m] (or any load unit).
    response : array of float
        The response at ``t`` [rad] (or any unit).
    frequency : float
        Load frequency [Hz].
    level : float
        The load at which W_H is read ([S1] Fig. 8: 300 N m), in the unit of ``load``.
    n_harmonics : int
        N, the highest harmonic of the load frequency fitted per cycle.
    min_cycles : int
        Usable cycles needed for a complete estimate.
    tolerance : float
        τ of the periodicity criterion (below).
    first_cycle : int or None
        The first cycle used; None: chosen by the periodicity criterion.

    Returns
    -------
    LoopEstimate
        W_H per cycle with its mean and 95 % interval, loop area, phase lag, compliance, the cycles used and a
        ``status`` (below).

    Notes
    -----
    Method, per load cycle k (exact period 1/f, boundaries t[0] + k/f, :func:`fit_cycles`):

    1. least-squares fit of harmonics 0…N of f (N = ``n_harmonics``) to the response and to the load;
    2. the phases θ_r, θ_f where the fitted load passes ``level`` rising and falling, solved on the
       fitted periodic curve (:func:`level_crossings`), and W_H,k = γ̂_k(θ_f) − γ̂_k(θ_r) (> 0: lag);
    3. the loop area ∮ M dγ of the two fitted series (:func:`loop_area`, exact formula π Σ k (a_k d_k − b_k c_k)).

    Start-up (periodicity criterion): the measure Δ_k of :func:`periodicity_change` compares the fitted
    mean and fundamental of cycle k with those of cycle k − 1, relative to the fundamental's amplitude.
    The first cycle used is the first k ≥ 1 with Δ_k ≤ τ and Δ_{k+1} ≤ τ (two successive changes, so that
    one chance agreement during a transient does not count), τ = max(``tolerance``, the stationary scatter
    floor of :func:`stationary_floor`: 1.5 × the median Δ of the last half of the cycles unless the mean
    drifts); cycle 0 (the start) is never used.  Why 10⁻³: a drift δ of the mean over a cycle biases W_H by about
    δ (θ_f − θ_r)/2π (a ramp in the fitted window), i.e. δ/3 at 0.3 of a 0.6 kN·m sine; at the hub's
    |Γ1| ≈ 0.06 ° a change of 10⁻³|Γ1| is ≈ 0.02·10⁻³ ° of W_H, below the loops studied (≈ 0.1·10⁻³ °).
    ``first_cycle`` overrides the criterion.

    Vibrations above the N-th harmonic are rejected up to leakage (:func:`leakage_bound`): for a
    1.23 kHz tilt mode at a 50 Hz load, per cycle ≤ 0.010 × its amplitude (0 when the ratio is an
    integer), and in the mean over n cycles the per-cycle leakage, rotating by 2π r per cycle, cancels
    further (:func:`mean_leakage_bound`); the two-point reading takes up to twice the amplitude.
    Harmonics of the response above N are cut off.  A single-valued response g(M) to a sine load holds only
    sin(odd k θ) and cos(even k θ) terms, each of which takes the same value at θ_r and θ_f = π − θ_r, so
    truncating them does not bias W_H; only their out-of-phase parts do.  Measured on the lubricated hub
    run (100 km/h, 50 Hz; harmonics 5, 6, 7 of 0.77, 0.20, 0.32·10⁻³ °, 1–2° out of phase) W_H over
    cycles 1–7 is 0.111 / 0.145 / 0.155 / 0.124·10⁻³ ° with N = 3 / 5 / 8 / 12 (at N = 20, harmonics
    up to 1 kHz, the 1.1–1.2 kHz ringing leaks in: −0.02): a systematic uncertainty of ≈ ±0.02·10⁻³ °,
    larger than that run's 95 % interval (±0.01); compare N when it matters.

    Mean and 95 % interval (Student t) of W_H and of the loop area over the cycles used; the phase lag
    (> 0 when the response's fundamental lags the load's) and the compliance |Γ1|/|M1| from the mean
    fitted coefficients of those cycles.  Fewer than ``min_cycles`` usable cycles: the numbers are
    given as far as they exist and ``status`` says why they are incomplete.
    """
    t = np.asarray(t, dtype=float)
    load = np.asarray(load, dtype=float)
    response = np.asarray(response, dtype=float)
    if not (t.ndim == 1 and t.shape == load.shape == response.shape and len(t) > 1):
        raise InputError("t, load, response", "need three 1-D arrays of the same length (> 1)",
                         "pass samples of one run")
    if not np.all(np.diff(t) > 0):
        raise InputError("t", "times must increase strictly", "pass the samples in time order without repeats")
    if not (isinstance(frequency, (int, float)) and math.isfinite(frequency) and frequency > 0):
        raise InputError("frequency", f"must be a positive number of Hz, got {frequency!r}", "e.g. 50")
    if not (isinstance(n_harmonics, int) and n_harmonics >= 1):
        raise InputError("n_harmonics", f"must be an integer ≥ 1, got {n_harmonics!r}", "e.g. 5")
    if not (isinstance(min_cycles, int) and min_cycles >= 2):
        raise InputError("min_cycles", f"must be an integer ≥ 2, got {min_cycles!r}", "e.g. 6")
    if not (tolerance > 0):
        raise InputError("tolerance", f"must be > 0, got {tolerance!r}", "e.g. 1e-3")
    cl = fit_cycles(t, load, frequency, n_harmonics)
    cr = fit_cycles(t, response, frequency, n_harmonics)
    n = len(cr)
    change = periodicity_change(cr) if n else np.zeros(0)
    floor = stationary_floor(cr, change) if n else 0.0
    tau = max(tolerance, floor)
    criterion = (f"cycle k is used from the first k ≥ 1 where the fitted mean and fundamental of the response "
                 f"change from cycle k−1 to k and from k to k+1 by ≤ {tau:.3g} × the fundamental's amplitude "
                 f"(harmonics 0…{n_harmonics} of {frequency:g} Hz fitted per cycle; the larger of {tolerance:g} "
                 f"and the stationary scatter floor {floor:.3g}: 1.5 × the median change of the last half of "
                 "the cycles, 0 when the mean drifts)")
    periodic_from = n
    for k in range(1, n):
        if change[k] <= tau and (k + 1 >= n or change[k + 1] <= tau):
            periodic_from = k
            break
    if first_cycle is not None:
        if not (isinstance(first_cycle, int) and 0 <= first_cycle):
            raise InputError("first_cycle", f"must be an integer ≥ 0, got {first_cycle!r}", "e.g. 1")
        start = min(first_cycle, n)
        criterion = f"first cycle given: {first_cycle} (criterion would give {periodic_from})"
    else:
        start = periodic_from
    widths, areas = [], []
    for k in range(start, n):
        tr, tf = level_crossings(cl[k], level)
        if math.isnan(tr):
            widths.append(math.nan)
        else:
            widths.append(float(series_value(cr[k], tf)[0] - series_value(cr[k], tr)[0]))
        areas.append(loop_area(cl[k], cr[k]))
    widths = np.array(widths)
    areas = np.array(areas)
    used = n - start
    status = "ok"
    if n < 2:
        status = f"only {n} complete load cycle(s) in the record"
    elif start >= n:
        status = f"the periodicity criterion never held in {n} cycles (largest late change {np.nanmin(change[1:]):.3g})"
    elif used < min_cycles:
        status = f"only {used} periodic cycle(s), fewer than min_cycles = {min_cycles}: run longer"
    if used and np.any(~np.isfinite(widths)):
        status = (status + "; " if status != "ok" else "") + f"the fitted load does not pass {level:g} in some cycles"
    if used:
        mc_l = np.mean(cl[start:], axis=0)
        mc_r = np.mean(cr[start:], axis=0)
        z_l, z_r = fundamental(mc_l), fundamental(mc_r)
        lag = float(np.angle(z_l / z_r)) if abs(z_r) > 0 and abs(z_l) > 0 else math.nan
        compliance = abs(z_r) / abs(z_l) if abs(z_l) > 0 else math.nan
        fin = widths[np.isfinite(widths)]
        mean = float(np.mean(fin)) if len(fin) else math.nan
        area = float(np.mean(areas))
    else:
        lag = compliance = mean = area = math.nan
    return LoopEstimate(widths=widths, cycles_used=used, first_cycle=start, mean=mean, ci95=t_interval(widths),
                        loop_area=area, loop_area_ci95=t_interval(areas), phase_lag=lag, compliance=compliance,
                        two_point=loop_widths(load, response, level), periodic_from=periodic_from,
                        criterion=criterion, loop_areas=areas, cycles_total=n, status=status, change=change)


def estimate_frequency(t, load) -> float:
    """Frequency [Hz] of a periodic load from its crossings of the mid-range, rising (NaN if < 2).

    (number of rising crossings − 1) / (time between the first and the last), crossings interpolated
    linearly between samples.  For a single sine (the case files' loads) it is exact to the
    interpolation error; a load with several frequencies needs the frequency given.
    """
    t = np.asarray(t, dtype=float)
    x = np.asarray(load, dtype=float)
    mid = 0.5 * (np.max(x) + np.min(x))
    m = x - mid
    up = np.nonzero((m[:-1] < 0) & (m[1:] >= 0))[0]
    if len(up) < 2:
        return math.nan
    tc = t[up] + (t[up + 1] - t[up]) * (-m[up]) / (m[up + 1] - m[up])
    return float((len(tc) - 1) / (tc[-1] - tc[0]))
