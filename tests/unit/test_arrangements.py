"""Bearing sets and double-row units (statics/arrangements.py): invariants and closed forms."""


import numpy as np
import pytest

from bearingsim.errors import InputError
from bearingsim.io import bearing_from_dict, load_bearing
from bearingsim.statics import arrangements as ar
from bearingsim.statics import jones_harris as jh
from bearingsim.statics.axial import solve_thrust


@pytest.fixture(scope="module")
def row():
    return load_bearing("skf-7011-cdga-hc")


@pytest.fixture(scope="module")
def db(row):
    return ar.make_system(row, "DB", 0.018, preload=300.0)


def test_db_zero_load_equilibrium_carries_preload_in_both_rows(db, row):
    res = jh.solve(db, jh.Loads())
    assert res.converged
    np.testing.assert_allclose(res.displacement, 0.0, atol=1e-15)
    rr = ar.row_results(res)
    np.testing.assert_allclose([r["axial_load_N"] for r in rr], [300.0, 300.0], rtol=1e-9)
    assert not any(r["lifted_off"] for r in rr)
    # every ball carries the thrust-model ball load Q = F0 / (Z sin alpha) (seed 000 eqs. 3-5)
    th = solve_thrust(row, 300.0)
    np.testing.assert_allclose(res.balls["inner_load_N"], th.ball_load, rtol=1e-9)
    # the preload offset equals the single-row thrust deflection at the preload
    np.testing.assert_allclose(db.rows[0].axial_offset, th.axial_deflection, rtol=1e-9)


def test_db_axial_stiffness_is_twice_single_row_at_preload(db, row):
    res = jh.solve(db, jh.Loads(fa=1e-3))
    ca = solve_thrust(row, 300.0).axial_stiffness
    np.testing.assert_allclose(res.stiffness[0, 0], 2.0 * ca, rtol=1e-6,
                               err_msg="closed form: two preloaded rows act as springs in parallel")


def test_lift_off_of_unloaded_row_under_large_axial_load(db):
    small = ar.row_results(jh.solve(db, jh.Loads(fa=300.0)))
    assert not any(r["lifted_off"] for r in small)
    res = jh.solve(db, jh.Loads(fa=3000.0))
    assert res.converged
    rr = ar.row_results(res)
    # row 0 (orientation +1) takes positive Fa; row 1 lifts off
    assert not rr[0]["lifted_off"] and rr[1]["lifted_off"]
    assert rr[1]["loaded_balls"] == 0
    np.testing.assert_allclose(rr[0]["axial_load_N"], 3000.0, rtol=1e-9)
    np.testing.assert_allclose(rr[1]["axial_load_N"], 0.0, atol=1e-9)


def test_lift_off_load_of_a_db_pair_closed_form(db, row):
    """For two identical rows, the unloaded row lifts off when its approach is gone: the loaded row's
    deflection then equals 2 x the preload deflection, i.e. Fa_lift = Fa_thrust(2 delta_0)."""
    d0 = db.rows[0].axial_offset
    fa = [500.0 * k for k in range(1, 20)]
    lift = [ar.row_results(jh.solve(db, jh.Loads(fa=f)))[1]["lifted_off"] for f in fa]
    first = fa[lift.index(True)]
    # thrust load of one row at deflection 2*d0 (bisection on the thrust model)
    from scipy.optimize import brentq
    f_lift = brentq(lambda f: solve_thrust(row, f).axial_deflection - 2 * d0, 1.0, 1e5)
    assert first - 500.0 < f_lift <= first


def test_row_loads_sum_to_external_loads(db):
    loads = jh.Loads(fa=800.0, fr_y=1500.0, fr_z=-400.0, m_y=20.0, m_z=-35.0)
    res = jh.solve(db, loads, speed=800.0)
    assert res.converged
    rr = ar.row_results(res)
    tot = np.zeros(5)
    for r in rr:
        f = r["loads"]
        x = r["position_m"] - db.load_point
        tot += [f["fa_N"], f["fr_y_N"], f["fr_z_N"], f["m_y_N_m"] - x * f["fr_z_N"], f["m_z_N_m"] + x * f["fr_y_N"]]
    np.testing.assert_allclose(tot, loads.as_array(), atol=1e-6 * 1500)


def test_symmetric_stiffness_at_rest_and_finite_difference(db):
    loads = jh.Loads(fa=500.0, fr_y=900.0, fr_z=300.0, m_y=15.0, m_z=-10.0)
    res = jh.solve(db, loads)
    k = res.stiffness
    np.testing.assert_allclose(k, k.T, rtol=1e-7, atol=1e-9 * np.max(np.abs(k)))
    # central difference of the ring load at the solution
    rows = db.row_vectors()
    from bearingsim.statics import _kernels as kn
    zmax = int(rows[:, kn.P_Z].max())

    def force(q):
        out = np.zeros(5)
        kn.ring_assemble(rows, q, 0.0, 0, np.zeros((2, zmax), dtype=np.int64), np.zeros((2, zmax, 2)),
                         np.zeros(5), out, np.zeros((5, 5)), np.zeros((2, zmax, 12)), 1e-12, 60)
        return out
    q0 = res.displacement
    kfd = np.zeros((5, 5))
    for j in range(5):
        h = 1e-9 if j < 3 else 1e-8
        dq = np.zeros(5)
        dq[j] = h
        kfd[:, j] = -(force(q0 + dq) - force(q0 - dq)) / (2 * h)
    np.testing.assert_allclose(k, kfd, rtol=1e-5, atol=1e-6 * np.max(np.abs(k)))


def test_db_has_larger_moment_stiffness_than_df_and_same_axial(row):
    db = ar.make_system(row, "DB", 0.018, preload=300.0)
    df = ar.make_system(row, "DF", 0.018, preload=300.0)
    kdb = jh.solve(db, jh.Loads()).stiffness
    kdf = jh.solve(df, jh.Loads()).stiffness
    np.testing.assert_allclose(kdb[0, 0], kdf[0, 0], rtol=1e-9)
    assert kdb[4, 4] > 1.5 * kdf[4, 4]


def test_mirror_symmetry_of_db_pair(db):
    a = jh.solve(db, jh.Loads(fa=700.0, fr_y=500.0))
    b = jh.solve(db, jh.Loads(fa=-700.0, fr_y=500.0))
    np.testing.assert_allclose(a.displacement[0], -b.displacement[0], rtol=1e-8)
    np.testing.assert_allclose(a.displacement[1], b.displacement[1], rtol=1e-8)
    np.testing.assert_allclose(a.displacement[4], -b.displacement[4], rtol=1e-7, atol=1e-14)


def test_toml_rows_form_equals_arrangement_form(db):
    e = db.rows[0].axial_offset
    data = {"name": "x", "rows": [
        {"bearing": "skf-7011-cdga-hc", "position": "-9 mm", "orientation": 1, "axial_offset": f"{e * 1e3!r} mm"},
        {"bearing": "skf-7011-cdga-hc", "position": "9 mm", "orientation": -1, "axial_offset": f"{e * 1e3!r} mm"},
    ]}
    s = bearing_from_dict(data)
    np.testing.assert_allclose(s.row_vectors(), db.row_vectors(), rtol=1e-12)
    s2 = bearing_from_dict({"name": "y", "rows": data["rows"][:1] + data["rows"][1:], "preload": "300 N"})
    np.testing.assert_allclose(s2.rows[0].axial_offset, e, rtol=1e-9)


def test_catalogue_entries_work_with_static_solver():
    for name in ("hub-seed001", "skf-7011-cdga-hc-db"):
        s = load_bearing(name)
        res = jh.solve(s, jh.Loads(fa=500.0, fr_y=1000.0), speed=500.0)
        assert res.converged
        d = res.to_dict()
        assert d["bearing"] == s.name
    hub = load_bearing("hub-seed001")
    np.testing.assert_allclose(hub.rest_preload(), [5400.0, 5400.0], rtol=1e-9)
    np.testing.assert_allclose(hub.rows[1].position - hub.rows[0].position, 0.0182, rtol=1e-12)


@pytest.mark.parametrize("data, field", [
    ({"arrangement": "DB", "row": "skf-7011-cdga-hc", "row_spacing": "5 mm"}, "row_spacing"),
    ({"arrangement": "DB", "row": "skf-7011-cdga-hc", "preload_offset": "500 um"}, "preload"),
    ({"arrangement": "DB", "row": "skf-7011-cdga-hc", "preload": "1 MN"}, "preload"),
    ({"arrangement": "DT", "row": "skf-7011-cdga-hc", "preload": "100 N"}, "preload"),
    ({"arrangement": "XX", "row": "skf-7011-cdga-hc"}, "arrangement"),
    ({"arrangement": "DB", "row": "skf-7011-cdga-hc", "preload": "100 N", "preload_offset": "1 um"}, "preload"),
    ({"rows": [{"bearing": "skf-7011-cdga-hc", "position": "0 mm", "orientation": 2}]}, "rows[0].orientation"),
    ({"rows": [{"bearing": "skf-7011-cdga-hc"}]}, "rows[0].position"),
    ({"arrangement": "DB", "row": "skf-7011-cdga-hc", "colour": "red"}, "colour"),
])
def test_bad_input_names_the_field(data, field):
    with pytest.raises(InputError) as exc:
        bearing_from_dict(data)
    assert exc.value.field == field


def test_tandem_pair_shares_the_axial_load(row):
    dt = ar.make_system(row, "DT", 0.018)
    res = jh.solve(dt, jh.Loads(fa=2000.0))
    assert res.converged
    rr = ar.row_results(res)
    np.testing.assert_allclose([r["axial_load_N"] for r in rr], [1000.0, 1000.0], rtol=1e-9)
    th = solve_thrust(row, 1000.0)
    np.testing.assert_allclose(res.displacement[0], th.axial_deflection, rtol=1e-8,
                               err_msg="closed form: tandem rows share the load equally (thrust model)")
    np.testing.assert_allclose(res.stiffness[0, 0], 2 * th.axial_stiffness, rtol=1e-6)


def test_three_row_set_preload_balances(row):
    # two rows facing +x (tandem) against one facing -x: the single row carries the sum of the other two
    rows = (ar.Row(row, -0.027, 1.0), ar.Row(row, -0.009, 1.0), ar.Row(row, 0.018, -1.0))
    e = ar._preload_offset(rows, 400.0)
    import dataclasses
    s = ar.BearingSystem("tbt", tuple(dataclasses.replace(r, axial_offset=e) for r in rows))
    fa = s.rest_preload()
    np.testing.assert_allclose(fa[0] + fa[1], 400.0, rtol=1e-9)
    np.testing.assert_allclose(fa[2], fa[0] + fa[1], rtol=1e-9)
    np.testing.assert_allclose(fa[0], fa[1], rtol=1e-9)


def test_arrangement_reader_lives_in_io_and_old_names_forward():
    """The TOML reader of sets moved to bearingsim.io.arrangement; the old statics names are the same objects."""
    from bearingsim.io import arrangement as reader
    from bearingsim.statics import arrangements as ar_mod

    for name in ("_KEYS", "_ROW_KEYS", "_row_bearing", "arrangement_from_dict"):
        assert getattr(ar_mod, name) is getattr(reader, name)
    import bearingsim.io as bio

    assert bio.arrangement_from_dict is reader.arrangement_from_dict
    with pytest.raises(AttributeError):
        ar_mod.no_such_name  # noqa: B018


@pytest.mark.parametrize("control", ["outer", "inner", "auto"])
@pytest.mark.parametrize("speed_rpm", [0.0, 8000.0])
@pytest.mark.parametrize("which", ["hub", "db", "dt"])
def test_row_forces_of_the_solve_equal_one_kernel_pass_per_row(row, which, speed_rpm, control):
    """The row loads stored by solve (summed from its own ball table) are those of re-running
    ring_assemble over each row's balls at the solution (the pre-refactor bookkeeping), to round-off."""
    system, loads = {
        "hub": (load_bearing("hub-seed001"), jh.Loads(fa=945.0, fr_y=3268.0, m_z=300.0)),
        "db": (ar.make_system(row, "DB", 0.018, preload=300.0), jh.Loads(fa=800.0, fr_y=1500.0, m_y=20.0)),
        "dt": (ar.make_system(row, "DT", 0.018), jh.Loads(fa=2000.0, fr_y=500.0)),
    }[which]
    res = jh.solve(system, loads, speed_rpm * np.pi / 30.0, control=control)
    assert res.converged, res.status
    kernel = np.array(ar._row_forces(system, res.displacement, res.speed, res))
    assert res.row_forces.shape == (len(system.rows), 5)
    np.testing.assert_allclose(res.row_forces, kernel, rtol=0, atol=1e-12 * np.max(np.abs(kernel)))
    # and row_results reports exactly the stored forces
    rr = ar.row_results(res)
    np.testing.assert_array_equal([[r["loads"]["fa_N"], r["loads"]["fr_y_N"], r["loads"]["fr_z_N"]] for r in rr],
                                  res.row_forces[:, :3])
