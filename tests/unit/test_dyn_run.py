"""Dynamic engine: case files, loads in time, streaming output, checkpoints and --resume."""

import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from bearingsim.dynamics import forces as fo
from bearingsim.dynamics import loads as ld
from bearingsim.dynamics.case import case_from_dict, load_case
from bearingsim.dynamics.run import SimulationError, simulate
from bearingsim.errors import InputError

CASE = """
bearing = "skf-7011-cdga-hc"
speed = "10000 rpm"
duration = "{duration}"
output_interval = "0.05 ms"
traction = "coulomb"
chunk = 4
[loads]
fa = "3000 N"
mz = {{ offset = "0 N*m", amplitude = "20 N*m", frequency = "500 Hz" }}
"""


def test_load_channels_match_closed_form():
    ch = [ld.sine(600.0, 50.0, 0.3, offset=100.0), ld.table([0.0, 0.01, 0.02], [0.0, 2000.0, 500.0]),
          ld.constant(-40.0) + ld.sine(10.0, 7.0), ld.LoadChannel(), ld.constant(5.0)]
    hist = ld.LoadHistory(tuple(ch))
    spec = hist.packed()
    out = np.empty(5)
    for t in (0.0, 0.0037, 0.01, 0.015, 0.03):
        fo.loads_at(t, spec, out)
        ref = [100 + 600 * math.sin(2 * math.pi * 50 * t + 0.3), np.interp(t, [0, 0.01, 0.02], [0, 2000, 500]),
               -40 + 10 * math.sin(2 * math.pi * 7 * t), 0.0, 5.0]
        np.testing.assert_allclose(out, ref, rtol=1e-14, atol=1e-12)
        np.testing.assert_allclose(hist.at(t), ref, rtol=1e-14, atol=1e-12)


def test_case_parsing_and_bad_input():
    import tomllib

    data = tomllib.loads(CASE.format(duration="1 ms"))
    c = case_from_dict(data)
    assert c.duration == pytest.approx(1e-3) and c.n_samples == 20
    assert c.loads.at(0.0005)[4] == pytest.approx(20 * math.sin(2 * math.pi * 500 * 0.0005))
    for key, bad in (("duration", "0 ms"), ("duration", "-1 ms"), ("output_interval", "0 s"),
                     ("output_interval", "2 ms")):
        d = dict(data)
        d[key] = bad
        with pytest.raises(InputError) as e:
            case_from_dict(d)
        assert e.value.field == key
    d = dict(data)
    d["speed"] = {"start": "0 rpm", "stop": "1000 rpm", "ramp": "5 ms"}
    s = case_from_dict(d).speed
    assert s.at(2.5e-3) == pytest.approx(500 * math.pi / 30)


def _run_cli(args, **kw):
    code = "from bearingsim.cli import main; main()"
    return subprocess.Popen([sys.executable, "-c", code, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            **kw)


@pytest.mark.parametrize("integrator", ["auto", "ros34w"])
def test_resume_after_sigkill_gives_the_same_trajectory(tmp_path, integrator):
    """Bitwise resume with DOPRI5 (the auto choice here) and with ROS34PW2, whose Jacobian lives across
    output intervals and is saved in the checkpoint."""
    import xarray as xr

    case = tmp_path / "case.toml"
    case.write_text(CASE.format(duration="6 ms").replace('traction = "coulomb"',
                                                         f'traction = "coulomb"\nintegrator = "{integrator}"'))
    ref = simulate(load_case(case), out=tmp_path / "ref.nc")
    out = tmp_path / "run.nc"
    ckpt = Path(str(out) + ".ckpt.npz")
    p = _run_cli(["simulate", str(case), "--out", str(out), "--quiet"])
    t0 = time.time()
    while not ckpt.exists() and p.poll() is None and time.time() - t0 < 120:
        time.sleep(0.005)
    time.sleep(0.3)
    killed = p.poll() is None
    if killed:
        os.kill(p.pid, signal.SIGKILL)
    p.wait()
    # the file is readable after the kill (the last complete chunk is valid)
    with xr.open_dataset(out) as ds:
        n_partial = ds.sizes["time"]
    assert n_partial >= 1
    p = _run_cli(["simulate", str(case), "--out", str(out), "--resume", "--quiet"])
    assert p.wait() == 0, p.stderr.read().decode()
    with xr.open_dataset(ref.path) as a, xr.open_dataset(out) as b:
        assert a.sizes["time"] == b.sizes["time"] == 121
        for k in ("inner_ring_displacement", "ball_orbital_speed", "inner_contact_load", "cage_angular_speed"):
            assert np.array_equal(a[k].values, b[k].values), k
    assert killed, "the run finished before it could be killed; lengthen the case"


def test_separation_stops_cleanly_with_data_saved(tmp_path):
    import tomllib

    data = tomllib.loads(CASE.format(duration="2 ms"))
    data["loads"] = {"fa": {"table": [["0 ms", "3000 N"], ["0.5 ms", "3000 N"], ["1 ms", "-3000 N"]]}}
    with pytest.raises(SimulationError, match="separated"):
        simulate(case_from_dict(data), out=tmp_path / "sep.nc")
    import xarray as xr

    with xr.open_dataset(tmp_path / "sep.nc") as ds:
        assert 10 < ds.sizes["time"] < 41
        assert np.all(ds["inner_contact_load"].values[-3:] == 0)


@pytest.mark.parametrize("name", ["spindle-7011.toml", "hub-moment-50hz.toml"])
def test_example_cases_run(name, tmp_path):
    """The example cases parse and run (a few output intervals) through the API, lubricated kernel included."""
    import dataclasses

    root = Path(__file__).resolve().parents[2]
    c = load_case(root / "examples" / name)
    c = dataclasses.replace(c, duration=3 * c.output_interval)
    res = simulate(c, out=tmp_path / "ex.nc")
    ds = res.to_xarray()
    assert ds.sizes["time"] == 4
    # a mixed variable: units "1" and the unit of each dof (bearingsim.io.netcdf; it was "m or rad", which no
    # unit library parses)
    assert ds["inner_ring_displacement"].attrs["units"] == "1"
    assert ds["inner_ring_displacement"].attrs["units_by_component"] == "m, m, m, rad, rad"
    assert np.all(np.isfinite(ds["inner_contact_load"].values))
    assert float(ds["power_loss_inner"].values[-1]) > 0
    ds.close()
    # steady-state means read from the file in blocks equal the plain means of the loaded arrays
    from bearingsim.dynamics.run import Results

    res.BLOCK = 1
    streamed = res.steady_state(fraction=0.7)
    full = Results(data=res.data, attrs={}).steady_state(fraction=0.7)
    t = res.data["time"]
    sel = t >= t[0] + 0.3 * (t[-1] - t[0])
    for k, v in full.items():
        assert streamed[k] == pytest.approx(v, rel=1e-12, abs=1e-300), k
    assert full["power_loss_inner"] == pytest.approx(float(np.mean(res.data["power_loss_inner"][sel])), rel=1e-12)


def test_fluctuation_range_of_a_lagging_tilt_is_closed_form():
    """Seed 001 Fig. 8 definition on a synthetic loop: tilt = c M(t - lag) with M = M0 sin(w t) gives, at M = M0/2,
    W_H = c M0 [sin(5π/6 − φ) − sin(π/6 − φ)] = √3 c M0 sin φ (φ = w lag)."""
    from bearingsim.dynamics.run import Results

    w, m0, c, lag = 2 * math.pi * 50, 600.0, 1.7e-6, 0.3e-3
    t = np.linspace(0.0, 0.05, 20001)
    load = np.zeros((t.size, 5))
    load[:, 4] = m0 * np.sin(w * t)
    disp = np.zeros((t.size, 5))
    disp[:, 4] = c * m0 * np.sin(w * (t - lag))
    res = Results(data={"time": t, "applied_load": load, "inner_ring_displacement": disp}, attrs={})
    expected = math.sqrt(3) * c * m0 * math.sin(w * lag)
    assert res.fluctuation_range(300.0) == pytest.approx(expected, rel=1e-5)
    np.testing.assert_allclose(res.loop_widths(300.0), expected, rtol=1e-5)
    assert len(res.loop_widths(300.0)) == 3  # 2.5 cycles: M passes 300 N m rising then falling in each of 3
    assert math.isnan(res.fluctuation_range(700.0))


@pytest.mark.parametrize("method", ["dopri5", "ros2w", "ros34w"])
def test_stepper_advances_through_the_integrator_contract(method, monkeypatch):
    """Stepper.advance calls ``METHODS[method].advance(workspace, t_end)`` (the contract of
    dynamics.integrate.base), and the trajectory equals that of the method's numba kernel called with the
    arguments the stepper passed before it used the contract (bitwise)."""
    import tomllib

    from bearingsim.dynamics import integrate as ig
    from bearingsim.dynamics import model as md
    from bearingsim.dynamics.run import Stepper, build

    model, loadspec, y0, _ = build(case_from_dict(tomllib.loads(CASE.format(duration="0.1 ms"))))
    st = Stepper(model, loadspec, y0.copy(), method=method, h=1e-7)
    calls = []
    real = ig.METHODS[method].advance

    def spy(ws, t_end):
        calls.append((ws.y is st.y, ws.jacobian is st._ws, t_end))
        return real(ws, t_end)

    monkeypatch.setattr(ig.METHODS[method], "advance", spy)
    times = (2e-5, 5e-5)
    for t_end in times:
        st.advance(t_end)
    assert calls == [(True, True, t) for t in times]
    # the former direct kernel calls, on a second stepper's arrays
    ref = Stepper(model, loadspec, y0.copy(), method=method, h=1e-7)
    kernel = ig.METHODS[method].integrate
    t, h, steps = 0.0, 1e-7, 0
    for t_end in times:
        common = (fo.rhs_args, ref._args, t, t_end, ref.y, h, ref.atol, ref.rtol, ref.h_min,
                  ref.max_steps_per_interval, ref._info)
        if method == "dopri5":
            status, t, h = kernel(*common, ref.vec)
        elif method == "ros2w":
            status, t, h = kernel(*common, ref._blk, md.N_BALL, ref.jac_every, ref.vec)
        else:
            status, t, h = kernel(*common, ref._blk, md.N_BALL, ref.jac_every, ref._ws, ref._rmass, ref._bmass,
                                  vec=ref.vec, rec=ref._args[10])  # (the memo's record: the ring's columns derived)
        assert status == ig.OK
        steps += int(ref._info[0])
    assert st.y.tobytes() == ref.y.tobytes()
    assert (st.t, st.h, st.steps) == (t, h, steps) and st.steps > 0


def test_integrator_attribute_says_whether_ros34pw2_couples_the_ring():
    """The output file's ``integrator`` attribute: ROS34PW2 couples the inner ring with the balls by default
    (it said "block-diagonal per ball", which is only true with the ring held fixed or the coupling off)."""
    import tomllib

    from bearingsim.dynamics import model as md
    from bearingsim.dynamics.run import build, integrator_text

    model = build(case_from_dict(tomllib.loads(CASE.format(duration="0.1 ms"))))[0]
    assert "coupled with the inner ring" in integrator_text("ros34w", model)
    assert "block-diagonal per ball" in integrator_text("ros34w", model, ring_coupling=False)
    model.gp[md.G_RING_FIXED] = 1.0
    assert "block-diagonal per ball" in integrator_text("ros34w", model)
    assert "block-diagonal per ball" in integrator_text("ros2w", model)
    assert integrator_text("dopri5") == "Dormand-Prince 5(4) with error control"


def test_dense_output_samples_do_not_depend_on_the_output_interval(tmp_path):
    """ROS34PW2 with dense output (simulate's default): the steps run past the output times, so a run sampled
    every 0.05 ms and one sampled every 0.1 ms take the same steps and give the same samples at the common times,
    bit for bit; the run whose steps stop at every output time (dense=False) agrees with them to the tolerance."""
    import dataclasses
    import tomllib

    data = tomllib.loads(CASE.format(duration="2 ms"))
    data["integrator"] = "ros34w"
    case = case_from_dict(data)
    fine = simulate(case)
    coarse = simulate(dataclasses.replace(case, output_interval=1e-4))
    clipped = simulate(case, dense=False)
    assert fine.summary["steps"] == coarse.summary["steps"]
    assert fine.attrs["output_sampling"].startswith("dense output") and "ends" in clipped.attrs["output_sampling"]
    # the in-memory runner with a dense stepper samples at the output times too: the same samples as simulate's
    from bearingsim.dynamics.run import Stepper, build, run_stepper

    model, loadspec, y0, _ = build(case)
    st = Stepper(model, loadspec, y0, tol=case.tolerance, h=min(1e-7, case.output_interval), method=case.method,
                 dense=True)
    mem = run_stepper(st, case.duration, case.output_interval).data
    assert st.t >= case.duration  # (the stepper stops at or past the last output time)
    for k in ("time", "inner_ring_displacement", "inner_contact_load"):
        assert np.array_equal(np.asarray(mem[k]), np.asarray(fine.data[k])), k
    assert fine.summary["simulated_seconds"] == pytest.approx(2e-3, abs=1e-15)
    for k in ("time", "inner_ring_displacement", "inner_contact_load", "ball_orbital_speed", "cage_angle"):
        assert np.array_equal(np.asarray(fine.data[k])[::2], np.asarray(coarse.data[k])), k
    a = np.asarray(fine.data["inner_ring_displacement"])
    b = np.asarray(clipped.data["inner_ring_displacement"])
    span = a.max(axis=0) - a.min(axis=0)
    loaded = span > 1e-9  # the coordinates the moment and the axial load move
    assert loaded.sum() >= 2
    np.testing.assert_array_less(np.abs(a - b).max(axis=0)[loaded], 2e-5 * span[loaded])  # (2e-6 measured)
