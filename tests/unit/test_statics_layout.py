"""The public row-parameter layout and the one table of solver status codes (bearingsim.statics.layout).

Mechanism tests (issue 12, "named contracts"): the layout module is a leaf, every index is dense and
documented in the module's table with the index it has, the private kernels and the geometry use exactly
these names, and every status table of the package (results, map files) is this one.
"""

from __future__ import annotations

import ast
import re

import numpy as np
import pytest

from bearingsim.statics import layout as L


def _row_names():
    return sorted((n for n in vars(L) if n.startswith("P_")), key=lambda n: getattr(L, n))


def test_layout_is_a_leaf():
    tree = ast.parse(open(L.__file__, encoding="utf-8").read())
    imported = [a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names]
    imported += [n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)]
    assert imported == ["__future__"], imported


def test_row_indices_dense_and_documented():
    names = _row_names()
    assert [getattr(L, n) for n in names] == list(range(L.NPAR))
    # the docstring table: "P_X   idx   meaning   unit" — each name documented with its own index and a unit
    rows = {m.group(1): (int(m.group(2)), m.group(3)) for m in
            re.finditer(r"^(P_[A-Z0-9]+)\s+(\d+)\s+.*?(\[[^\]]+\])\s*$", L.__doc__, re.M)}
    assert sorted(rows) == sorted(names)
    for n in names:
        assert rows[n][0] == getattr(L, n), n


def test_kernels_and_geometry_use_the_layout():
    from bearingsim.geometry import BallBearing  # noqa: F401
    from bearingsim.io import load_bearing
    from bearingsim.statics import _kernels as kn

    for n in [*_row_names(), "NPAR", "CONTROL_OUTER", "CONTROL_INNER", "CONTROL_AUTO"]:
        assert getattr(kn, n) == getattr(L, n), n
    b = load_bearing("skf-7011-cdga-hc")
    p = b.row_parameters(0.003, -1.0, 2e-6, 0.25)
    assert p.shape == (L.NPAR,)
    assert p[L.P_XROW] == 0.003 and p[L.P_SIGN] == -1.0 and p[L.P_AXOFF] == 2e-6 and p[L.P_PSI0] == 0.25
    assert p[L.P_Z] == b.ball_count and p[L.P_D] == b.ball_diameter and p[L.P_DM] == b.pitch_diameter


def test_one_status_table():
    from bearingsim import sweep
    from bearingsim.statics import jones_harris as jh

    assert jh.STATUS is L.STATUS
    codes = [getattr(L, n) for n in vars(L) if n.startswith("STATUS_") and isinstance(getattr(L, n), int)]
    assert sorted(codes) == list(range(len(codes))) == sorted(L.STATUS) == sorted(L.STATUS_SHORT)
    meanings = [m for _, m in L.STATUS_SHORT.values()]
    assert len(set(meanings)) == len(meanings) and all(re.fullmatch(r"[a-z0-9_]+", m) for m in meanings)
    # the map file's status variable: its long name lists every code, its CF flags are the table
    long_name = sweep._VARS["status"][4]
    for code, (short, _) in L.STATUS_SHORT.items():
        assert f"{code} {short}" in long_name
    attrs = sweep._var_attrs("status")
    assert attrs["flag_values"].dtype == np.int32
    assert list(attrs["flag_values"]) == sorted(L.STATUS)
    assert attrs["flag_meanings"].split() == meanings


def test_result_status_text_from_the_table():
    from bearingsim.io import load_bearing
    from bearingsim.statics import jones_harris as jh

    res = jh.solve(load_bearing("skf-7011-cdga-hc"), jh.Loads(fa=1000.0), 0.0)
    assert res.status_code == L.STATUS_CONVERGED and res.status == L.STATUS[L.STATUS_CONVERGED]


def test_row_formulas_once_kernels_and_dynamics_agree_bitwise():
    """The groove-centre position and the ball speed constants are written once (layout); the compiled
    kernels' copies and the dynamic model's groove circles give the same bits on real rows."""
    from bearingsim.dynamics import layout as dly
    from bearingsim.dynamics import model as md
    from bearingsim.io import load_bearing
    from bearingsim.statics import _kernels as kn

    system = load_bearing("hub-seed001")
    rows = system.row_vectors()
    rng = np.random.default_rng(12)
    for par in rows:
        for w2 in [0.0, *(rng.uniform(0.0, 1e7, 5))]:
            assert kn.ball_speed_constants(par, w2) == L.ball_speed_constants(par, w2)
        assert kn.inner_groove_centre_axial(par) == L.inner_groove_centre_axial(par)
    rx = md.row_extras(system, rows)
    for r, par in enumerate(rows):
        assert rx[r, dly.X_XGI] == L.inner_groove_centre_axial(par)
        assert rx[r, dly.X_XGO] == L.outer_groove_centre_axial(par)
        assert rx[r, dly.X_RGO] == L.outer_groove_centre_radius(par)
    # the centrifugal constant is F_c at ω_m = ω: ½ m d_m ω² (Harris & Kotzalas 2007 vol. 2 ch. 3)
    par = rows[0]
    _, cf = L.ball_speed_constants(par, 100.0**2)
    assert cf == pytest.approx(0.5 * par[L.P_MASS] * par[L.P_DM] * 1e4, rel=1e-15)


def test_hertz_scaling_laws_match_the_full_contact():
    """Q = K δ^1.5 and p_max = C_p Q^(1/3) (contact.hertz) reproduce the full Hertz solution of a row's
    contact at other loads (Hamrock & Brewe 1983 eqs. 11–13)."""
    from bearingsim.contact import hertz
    from bearingsim.io import load_bearing

    b = load_bearing("skf-7011-cdga-hc")
    c1 = b.contact(1.0, True)
    for q in (10.0, 500.0, 3000.0):
        c = b.contact(q, True)
        assert hertz.max_pressure_from_load(c1.max_pressure, q) == pytest.approx(c.max_pressure, rel=1e-12)
        assert hertz.load_from_approach(c.stiffness_constant, c.approach) == pytest.approx(q, rel=1e-12)
        assert hertz.approach_from_load(c.stiffness_constant, q) == pytest.approx(c.approach, rel=1e-12)
