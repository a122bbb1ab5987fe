"""Case files of the dynamic engine (TOML with units): the :class:`Case` dataclass and its checks.

The file is read by :func:`bearingsim.io.case.load_case` (units parsed there, once); ``load_case`` and
``case_from_dict`` stay importable from here.

Example (``examples/spindle-7011.toml``)::

    bearing = "skf-7011-cdga-hc"        # catalogue name or path
    lubricant = "iso-vg-68"             # library name or path
    temperature = "60 degC"
    speed = "10000 rpm"                 # or { start = "0 rpm", stop = "10000 rpm", ramp = "5 ms" }
    duration = "20 ms"
    output_interval = "0.05 ms"
    traction = "slices"                 # slices (lubricated kernel), coulomb (test stand-in), none
    n_slices = 8                        # strips per ellipse; with slice_rule = "gauss" nodes per stretch, with
                                        # "log" nodes in all (6..8)
    slice_rule = "strips"               # "strips" (equal strips, default), "gauss" (Gauss–Legendre between the
                                        # zeros of the rolling slip: smooth in the state, contact/slices.py) or
                                        # "log" (rules exact for the logarithm of those zeros: 7 nodes within 1 %
                                        # of the strip limit on the hub states)
    tolerance = 1e-6                    # integrator tolerance (relative; lengths scaled by 1 mm)
    integrator = "auto"                 # ros34w (W-method, implicit per ball) for traction = "slices", else dopri5;
                                        # or "dopri5", "ros2w", "ros34w"
    multirate = 8                       # ros34w: the most balls a step refines with micro steps of their own
                                        # (the balls that hold the error; 0: none; integrate/multirate.py)
    contact_damping = 0.05              # Hunt–Crossley alpha [s/m], or "ehl": the alpha that gives the loaded
                                        # contacts the lubricant's squeeze-film damping (contact/damping.py)
    gravity = ["0 m/s^2", "0 m/s^2", "-9.81 m/s^2"]   # optional
    load_point = "0 mm"                 # axial position of the load point (default: the bearing's)
    chunk = 200                         # samples per netCDF chunk (memory bound)
    checkpoint_every = "30 s"           # wall-clock time between checkpoints (or an integer: every N chunks)
    control = "outer"                   # raceway control of the quasi-static start
    start = "consistent"                # ring (and ball centre) velocities = d/dt of the quasi-static solution
                                        # at t = 0 (default); "rest": quasi-static positions at rest
    ramp_in = "5 ms"                    # optional: blend the load variation in by a C² smoothstep (loads.py)
    traction_compliance = "film"        # small-slip compliance of the lubricated kernel: "film" (Johnson &
                                        # Tevaarwerk film elasticity) or "film+solids" (Kalker's elastic solids
                                        # in series, contact/traction.py solids_in_series_factor)
    ball_orbit = "free"                 # "held": every ball held at its azimuth by a frictionless constraint
                                        # (no orbital motion; the zero reference of the hub hysteresis)

    [loads]                             # fa, fr (= Fr_y), fz (= Fr_z), my, mz: constant, sine, table, or a list (sum)
    fa = "3000 N"
    mz = { offset = "0 N*m", amplitude = "600 N*m", frequency = "50 Hz" }

    [inner_ring]                        # the rotating body carried by the inner ring (hub, shaft)
    mass = "2 kg"
    transverse_inertia = "0.002 kg*m^2"
    polar_inertia = "0.004 kg*m^2"

    [cage]
    mass = "0.03 kg"
    pocket_clearance = "0.2 mm"
    friction = 0.06                     # Sakaguchi & Shibutani [S1] §3.2
    guidance = "balls"                  # balls, outer-land, inner-land
    land_clearance = "0.2 mm"
    pocket_shape = "sphere"
    # elastic cage (mode synthesis; then give no mass: it comes from the ring): the n lowest
    # free-free modes of a finite-element ring (bearingsim.cage_modes), modal damping ratio, and
    # optional ring data overriding the assumed window cage
    # n_modes = 20
    # modal_damping = 0.02
    # axial_width = "13 mm"
    # radial_thickness = "3 mm"
    # pocket_diameter = "11.5 mm"
    # young_modulus = "206 GPa"
    # poisson = 0.3
    # density = "7850 kg/m^3"
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import dataclass, field

from ..errors import InputError
from .loads import LoadHistory, SpeedHistory


def kernel_slices(n: int, rule: str) -> int:
    """The contact kernel's ``n_slices`` for a case's n_slices and slice_rule (:func:`.contact.slices.traction_at`:
    n equal strips, −n Gauss nodes per stretch, SPLIT_BASE + n strips cut at the zeros of the rolling slip,
    LOG_BASE + n nodes of the log rule)."""
    if rule == "gauss":
        return -n
    if rule == "log":
        from ..contact.slices import LOG_BASE

        return LOG_BASE + n
    if rule == "split":
        from ..contact.slices import SPLIT_BASE

        return SPLIT_BASE + n
    return n


def _log_nodes() -> tuple[int, int]:
    """Fewest and most nodes of the contact kernel's log rule (imported when asked, as :func:`_gauss_max`)."""
    from ..contact.slices import LOG_MAX, LOG_MIN

    return LOG_MIN, LOG_MAX


def _gauss_max() -> int:
    """Most Gauss nodes per stretch of the contact kernel (imported when asked: the kernel module is heavy)."""
    from ..contact.slices import GAUSS_MAX

    return GAUSS_MAX

#: initial-state options (Case.start)
START_MODES = ("consistent", "rest")
#: small-slip compliance of the lubricated traction kernel (Case.traction_compliance)
TRACTION_COMPLIANCES = ("film", "film+solids")
#: the balls' orbital (azimuthal) motion (Case.ball_orbit)
BALL_ORBITS = ("free", "held")
#: the most balls a ROS34PW2 step refines with micro steps of their own (:mod:`.integrate.multirate`)
MULTIRATE_DEFAULT = 8
#: most output samples of one run (duration / output_interval): 10⁷ samples of a 21-ball bearing are
#: tens of GB of netCDF; more is a unit slip ("1e300 s"), not a simulation
MAX_SAMPLES = 10**7
#: most samples buffered in memory before a netCDF chunk is written
MAX_CHUNK = 100_000


@dataclass(frozen=True)
class Case:
    """A dynamic simulation case (all SI)."""

    bearing: object
    loads: LoadHistory
    speed: SpeedHistory
    duration: float
    output_interval: float
    lubricant: object = None
    temperature: float = 333.15
    traction: str = "slices"
    n_slices: int = 8
    #: "strips": ``n_slices`` equal strips along the major axis; "gauss": ``n_slices`` Gauss–Legendre nodes on each
    #: stretch between the zeros of the rolling-direction slip (:func:`bearingsim.contact.slices.rolling_slip_zeros`)
    slice_rule: str = "strips"
    tolerance: float = 1e-6
    contact_damping: float | str = 0.05  #: Hunt–Crossley α [s/m] or "ehl" (:meth:`damping_alpha`)
    gravity: tuple = (0.0, 0.0, 0.0)
    load_point: float = 0.0  #: relative to the origin of the bearing's kernel rows [m]
    ring_mass: float = 2.0
    ring_inertia: tuple | None = None
    cage: dict = field(default_factory=dict)
    lubrication: dict = field(default_factory=dict)
    chunk: int = 200
    control: str = "outer"
    checkpoint_every: int = 1  #: chunks between checkpoints
    checkpoint_interval: float | None = None  #: wall-clock seconds between checkpoints (None: run.CHECKPOINT_SECONDS)
    integrator: str = "auto"  #: "auto", "dopri5", "ros2w" or "ros34w" (see docs/dynamics.md)
    #: "consistent": start with the velocities of the quasi-static solution (model.quasi_static_rates);
    #: "rest": quasi-static positions at rest (the former start; kicks the ring's modes under varying loads)
    start: str = "consistent"
    #: "film": the film's elastic compliance alone in the lubricated kernel; "film+solids": the solids' (Kalker's
    #: simplified theory) in series (:func:`bearingsim.contact.traction.solids_in_series_factor`)
    traction_compliance: str = "film"
    #: "free"; "held": the balls' azimuth held fixed by a frictionless constraint (:func:`.model.build_model`)
    ball_orbit: str = "free"
    #: ROS34PW2: the most balls one step refines with micro steps of their own (0: none; :mod:`.integrate.multirate`)
    multirate: int = MULTIRATE_DEFAULT
    source: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        if not (math.isfinite(self.duration) and self.duration > 0):
            raise InputError("duration", f"must be positive, got {self.duration!r} s", 'e.g. "20 ms"')
        if not (math.isfinite(self.output_interval) and self.output_interval > 0):
            raise InputError("output_interval", f"must be positive, got {self.output_interval!r} s", 'e.g. "0.05 ms"')
        if self.output_interval > self.duration:
            raise InputError("output_interval", "is longer than the duration", "give an interval ≤ duration")
        if self.duration / self.output_interval > MAX_SAMPLES:
            raise InputError("output_interval", f"{self.duration:.4g} s at {self.output_interval:.4g} s per sample is "
                             f"more than {MAX_SAMPLES:.0e} output samples", "give a longer output_interval")
        if not (0 < self.tolerance < 1e-2):
            raise InputError("tolerance", f"must lie in (0, 1e-2), got {self.tolerance!r}", "e.g. 1e-6")
        if self.traction not in ("slices", "coulomb", "none"):
            raise InputError("traction", f"unknown model {self.traction!r}", "use slices, coulomb or none")
        if self.traction == "slices" and self.lubricant is None:
            raise InputError("lubricant", "the sliced-ellipse traction needs a lubricant",
                             'add lubricant = "iso-vg-68" or set traction = "none"')
        if isinstance(self.n_slices, bool) or not (isinstance(self.n_slices, int) and 1 <= self.n_slices <= 64):
            raise InputError("n_slices", f"must be an integer in 1..64, got {self.n_slices!r}", "e.g. 8")
        if self.slice_rule not in ("strips", "gauss", "split", "log"):
            raise InputError("slice_rule", f"unknown rule {self.slice_rule!r}"[:120],
                             'use "strips", "split", "gauss" or "log"')
        if self.slice_rule == "log":
            lo, hi = _log_nodes()
            if not lo <= self.n_slices <= hi:
                raise InputError("n_slices", f"with slice_rule = \"log\" it counts nodes in all: {lo}..{hi}, got "
                                 f"{self.n_slices}", "e.g. n_slices = 7")
        if self.slice_rule == "gauss" and self.n_slices > (GAUSS_MAX := _gauss_max()):
            raise InputError("n_slices", f"with slice_rule = \"gauss\" it counts nodes per stretch: 1..{GAUSS_MAX}, "
                             f"got {self.n_slices}", "e.g. n_slices = 4")
        if isinstance(self.chunk, bool) or not (isinstance(self.chunk, int) and 1 <= self.chunk <= MAX_CHUNK):
            raise InputError("chunk", f"must be an integer in 1..{MAX_CHUNK}, got {self.chunk!r}", "e.g. 200")
        if isinstance(self.contact_damping, str):
            if self.contact_damping != "ehl":
                raise InputError("contact_damping", f"unknown model {self.contact_damping!r}",
                                 'give a Hunt–Crossley alpha in s/m (e.g. 0.05) or "ehl"')
            if self.lubricant is None:
                raise InputError("contact_damping", '"ehl" needs a lubricant',
                                 'add lubricant = "iso-vg-68" or give a numeric alpha (e.g. 0.05)')
        elif isinstance(self.contact_damping, bool) or not isinstance(self.contact_damping, (int, float)) \
                or not (0 <= self.contact_damping < math.inf):
            raise InputError("contact_damping", f"must be a finite number ≥ 0, got {self.contact_damping!r}",
                             "e.g. 0.05 (s/m)")
        if self.integrator not in ("auto", "dopri5", "ros2w", "ros34w"):
            raise InputError("integrator", f"unknown integrator {self.integrator!r}",
                             "use auto, dopri5, ros2w or ros34w")
        if isinstance(self.checkpoint_every, bool) or not isinstance(self.checkpoint_every, int) or \
                self.checkpoint_every < 1:
            raise InputError("checkpoint_every", f"must be a number of chunks ≥ 1 or a wall-clock time, got "
                             f"{self.checkpoint_every!r}", 'e.g. 1 or "30 s"')
        if self.checkpoint_interval is not None and not (0 < self.checkpoint_interval < math.inf):
            raise InputError("checkpoint_every", f"must be a positive time, got {self.checkpoint_interval!r} s",
                             'e.g. "30 s"')
        if self.start not in START_MODES:
            raise InputError("start", f"unknown start {self.start!r}", "use consistent or rest")
        if not self.ring_mass > 0:
            raise InputError("inner_ring.mass", "must be positive", 'e.g. "2 kg"')
        if self.traction_compliance not in TRACTION_COMPLIANCES:
            raise InputError("traction_compliance", f"unknown option {self.traction_compliance!r}"[:160],
                             'use "film" or "film+solids"')
        if isinstance(self.multirate, bool) or not isinstance(self.multirate, int) or not 0 <= self.multirate <= 1000:
            raise InputError("multirate", f"must be a whole number of balls, 0 to 1000, got {self.multirate!r}"[:160],
                             "e.g. 8 (0: no refinement)")
        if self.ball_orbit not in BALL_ORBITS:
            raise InputError("ball_orbit", f"unknown option {self.ball_orbit!r}"[:160], 'use "free" or "held"')

    @property
    def method(self) -> str:
        """The integrator used: "auto" is the W-method ROS34PW2 for the lubricated kernel (whose
        traction creep is stiff) and DOPRI5 otherwise (docs/dynamics.md, Integrator)."""
        if self.integrator != "auto":
            return self.integrator
        return "ros34w" if self.traction == "slices" else "dopri5"

    @property
    def n_samples(self) -> int:
        """Output samples after the initial one."""
        return int(round(self.duration / self.output_interval))

    def fingerprint(self) -> str:
        """Hash of the inputs that determine the trajectory (a resume must match it)."""
        src = {k: v for k, v in self.source.items() if k != "checkpoint_every"}  # not part of the trajectory
        return hashlib.sha256(json.dumps(src, sort_keys=True, default=str).encode()).hexdigest()[:16]

    def damping_alpha(self) -> float:
        """Hunt–Crossley α [s/m] of the run: the number given, or for ``contact_damping = "ehl"`` the α that gives
        the loaded contacts of the quasi-static start (loads and speed at t = 0) the squeeze-film damping of
        :func:`bearingsim.contact.damping.equivalent_alpha` (Σ c_ehl / Σ 1.5 Q)."""
        if not isinstance(self.contact_damping, str):
            return float(self.contact_damping)
        from ..contact.damping import equivalent_alpha
        from ..statics import jones_harris as jh
        from .model import _static_loads

        w0 = abs(self.speed.at(0.0))
        res = jh.solve(self.bearing, _static_loads(self.loads, 0.0, self.load_point), w0, control=self.control)
        if not res.converged or not w0 > 0:
            raise InputError("contact_damping", '"ehl" needs a converged quasi-static start at a speed > 0 '
                             f"(converged: {res.converged}, speed {w0:.4g} rad/s)",
                             "give a numeric Hunt–Crossley alpha (e.g. 0.05) for runs from standstill")
        return equivalent_alpha(res, self.lubricant, self.temperature)

    def solids_shear(self) -> tuple[float, float]:
        """(G [Pa], ν [-]) of the ball–raceway pair for Kalker's creep: 2/G = 1/G_ball + 1/G_ring, ν the mean of the
        two (Kalker's theory takes one ν; quasi-identical for steel on steel)."""
        row = self.bearing.rows[0].bearing
        mats = (row.ball_material, row.ring_material)
        g = [m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio)) for m in mats]
        return 2.0 / (1.0 / g[0] + 1.0 / g[1]), 0.5 * (mats[0].poisson_ratio + mats[1].poisson_ratio)

    def model_options(self) -> dict:
        c = self.cage
        lub = dict(self.lubrication or {})
        if self.traction_compliance == "film+solids":
            lub["solids"] = self.solids_shear()
        return dict(ring_mass=self.ring_mass, ring_inertia=self.ring_inertia, gravity=self.gravity,
                    damping_alpha=self.damping_alpha(), traction=self.traction,
                    # (the rules are the lubricated kernel's; the Coulomb stand-in takes n_slices equal strips)
                    n_slices=(kernel_slices(self.n_slices, self.slice_rule) if self.traction == "slices"
                              else self.n_slices),
                    load_point=self.load_point, speed=self.speed.as_tuple(), lubricant=self.lubricant,
                    temperature=self.temperature, lubrication=lub or None, ball_orbit=self.ball_orbit,
                    cage_mass=c.get("mass"), pocket_clearance=c.get("pocket_clearance"),
                    cage_mu=c.get("friction", 0.06), guidance=c.get("guidance", "balls"),
                    land_clearance=c.get("land_clearance", 2e-4), pocket_shape=c.get("pocket_shape", "sphere"),
                    cage=c.get("enabled", True), cage_modes=c.get("n_modes", 0), cage_ring=c.get("ring"),
                    modal_damping=c.get("modal_damping"))


#: the case-file reader lives in :mod:`bearingsim.io.case` (every file format in one package); its names
#: stay importable from here (forwarded on first use: :mod:`bearingsim.io.case` imports :class:`Case`)
_READERS = ("case_from_dict", "load_case")


def __getattr__(name: str):
    if name in _READERS:
        from ..io import case as _reader

        return getattr(_reader, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
