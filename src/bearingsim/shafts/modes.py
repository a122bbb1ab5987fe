"""Natural frequencies and mode shapes of a shaft on its linearised bearings, and the Campbell diagram.

At a static equilibrium (:func:`.solve.solve_shaft`) every bearing is replaced by its 5×5 tangent stiffness;
the free outer-ring DOF (housing springs, spring preload) carry no mass and are condensed statically (exact for
massless DOF).  Without gyroscopic terms the modes solve the symmetric problem K φ = ω² M φ (consistent mass
of the beam plus point masses and diametral inertias, :func:`.solve.linear_model`); with them the state-space
problem of M q̈ + Ω G₁ q̇ + K q = 0 (G₁ of :func:`bearingsim.beam.shaft_element_matrices` and the point polar
inertias), whose eigenvalues λ = ±iω give the whirl frequencies (Lalanne & Ferraris, *Rotordynamics
Prediction in Engineering*, 2nd ed. 1998, ch. 2–3).  Units: frequencies [Hz], speeds [rad/s], shapes per node
(x, y, z, γy, γz) normalised to a largest translation of 1.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from ..errors import InputError
from .model import ShaftSystem
from .solve import ShaftResult, dof_vector, linear_model, solve_shaft


@dataclass
class ModalResult:
    """``frequency_hz`` float[n_modes] [Hz] ascending; ``shapes`` float[n_modes, n_nodes, 5] (real part, largest
    translation 1); ``speed`` [rad/s]; ``nodes`` [m]; ``gyroscopic`` whether G₁ was included; ``whirl``
    +1 forward, −1 backward, 0 planar/axial per mode (sense of the y–z orbit at the node of largest motion)."""

    frequency_hz: np.ndarray
    shapes: np.ndarray
    speed: float
    nodes: np.ndarray
    gyroscopic: bool
    whirl: np.ndarray

    def to_dict(self) -> dict:
        return {"frequency_hz": [float(v) for v in self.frequency_hz],
                "shape": [[[float(v) for v in node] for node in mode] for mode in self.shapes],
                "whirl": [int(v) for v in self.whirl], "speed_rad_s": float(self.speed),
                "gyroscopic": bool(self.gyroscopic), "nodes": [float(v) for v in self.nodes]}


def _condensed(result: ShaftResult):
    """(K, M, G₁) over the shaft DOF: the free outer-ring DOF condensed out of the tangent (massless)."""
    lm = linear_model(result.system)
    ns = lm.n_shaft
    free = result.free
    kt = result.tangent
    s = free < ns
    kss, ksm, kmm = kt[np.ix_(s, s)], kt[np.ix_(s, ~s)], kt[np.ix_(~s, ~s)]
    k = kss - ksm @ np.linalg.solve(kmm, ksm.T) if kmm.size else kss
    return 0.5 * (k + k.T), lm.M[:ns, :ns], lm.G1[:ns, :ns]


def _normalise(v: np.ndarray, n_nodes: int) -> np.ndarray:
    sh = v.reshape(n_nodes, 5)
    tr = sh[:, :3]
    i = np.unravel_index(np.argmax(np.abs(tr)), tr.shape)
    return sh / tr[i]


def modes(result: ShaftResult, n_modes: int = 6, gyroscopic: bool = False) -> ModalResult:
    """The ``n_modes`` lowest natural frequencies and shapes of the shaft on its bearings linearised at
    ``result`` (its speed; gyroscopic coupling at that speed when ``gyroscopic``)."""
    if isinstance(n_modes, bool) or not isinstance(n_modes, int) or n_modes < 1:
        raise InputError("modes", f"must be a positive integer, got {n_modes!r}", "e.g. 6")
    k, m, g1 = _condensed(result)
    nn = result.system.mesh.n_nodes
    n = k.shape[0]
    n_modes = min(n_modes, n)
    omega = float(result.speed)
    if not gyroscopic or omega == 0.0:
        w2, vec = sla.eigh(k, m, subset_by_index=(0, n_modes - 1))
        freq = np.sqrt(np.maximum(w2, 0.0)) / (2 * np.pi)
        shapes = np.array([_normalise(vec[:, j], nn) for j in range(n_modes)])
        return ModalResult(freq, shapes, omega, result.nodes.copy(), False, np.zeros(n_modes, dtype=int))
    # first-order form B ż = A z, z = (q, q̇): A = [[0, I], [−K, −ΩG₁]], B = diag(I, M); the eigenvalues nearest
    # to a small negative shift (shift-invert Arnoldi) are the lowest whirl frequencies ±iω
    from scipy.sparse import bmat, csc_matrix, identity
    from scipy.sparse.linalg import eigs

    eye = identity(n, format="csc")
    a = bmat([[None, eye], [csc_matrix(-k), csc_matrix(-omega * g1)]], format="csc")
    bm = bmat([[eye, None], [None, csc_matrix(m)]], format="csc")
    nev = min(2 * n_modes + 4, 2 * n - 2)
    if 2 * n > 80:
        lam, vec = eigs(a, k=nev, M=bm, sigma=-1.0)
    else:
        lam, vec = sla.eig(a.toarray(), bm.toarray())
    keep = lam.imag > -1e-9 * np.max(np.abs(lam))
    lam, vec = lam[keep], vec[:n, keep]
    order = np.argsort(np.abs(lam.imag))[:n_modes]
    freq = np.abs(lam[order].imag) / (2 * np.pi)
    shapes, whirl = [], []
    for j in order:
        v = vec[:, j]
        v = v / v[np.argmax(np.abs(v))]
        shapes.append(_normalise(v.real, nn))
        sh = v.reshape(nn, 5)
        i = int(np.argmax(np.abs(sh[:, 1]) + np.abs(sh[:, 2])))
        # (y, z) ∝ Re[(a, b) e^{iωt}], ω > 0: the orbit turns from +y towards +z (forward, with the spin about
        # +x) when Im(conj(a) b) < 0, e.g. (1, −i) → (cos ωt, sin ωt)
        c = float(np.imag(np.conj(sh[i, 1]) * sh[i, 2]))
        whirl.append(0 if abs(c) < 1e-6 * (abs(sh[i, 1]) ** 2 + abs(sh[i, 2]) ** 2 + 1e-300) else -int(np.sign(c)))
    return ModalResult(freq, np.array(shapes), omega, result.nodes.copy(), True, np.array(whirl))


def campbell(system: ShaftSystem, speeds, n_modes: int = 6, gyroscopic: bool = True):
    """Natural frequencies over ``speeds`` [rad/s]: at each speed the static equilibrium (warm started from the
    previous speed) and its modes.  Returns an ``xarray.Dataset`` with ``frequency`` (speed, mode) [Hz],
    ``whirl`` (speed, mode) and ``converged`` (speed), SI units in the attributes."""
    import xarray as xr

    sp = np.asarray(speeds, dtype=float).reshape(-1)
    if sp.size == 0 or not np.all(np.isfinite(sp)):
        raise InputError("speeds", "must be finite speeds [rad/s]", "give e.g. 0:2000:21 rad/s")
    freq = np.full((sp.size, n_modes), np.nan)
    whirl = np.zeros((sp.size, n_modes), dtype=int)
    conv = np.zeros(sp.size, dtype=bool)
    w0 = None
    for i, w in enumerate(sp):
        r = solve_shaft(system, speed=float(w), initial=w0, bearing_results=False)
        conv[i] = r.converged
        if r.converged:
            w0 = dof_vector(r)
        mr = modes(r, n_modes, gyroscopic)
        freq[i, :len(mr.frequency_hz)] = mr.frequency_hz
        whirl[i, :len(mr.whirl)] = mr.whirl
    return xr.Dataset(
        {"frequency": (("speed", "mode"), freq, {"units": "Hz", "long_name": "natural frequency"}),
         "whirl": (("speed", "mode"), whirl, {"units": "1", "long_name": "+1 forward, -1 backward, 0 planar"}),
         "converged": (("speed",), conv, {"units": "1"})},
        coords={"speed": ("speed", sp, {"units": "rad s-1"}), "mode": np.arange(1, n_modes + 1)},
        attrs={"title": f"Campbell diagram of {system.name}", "gyroscopic": int(gyroscopic)})
