"""ROSS export (export.py): coefficient mapping, and a ROSS rotor built with the exported elements."""

import json

import numpy as np
import pytest

from bearingsim import export
from bearingsim.errors import InputError
from bearingsim.io import load_bearing
from bearingsim.statics import jones_harris as jh


@pytest.fixture(scope="module")
def pair():
    return load_bearing("skf-7011-cdga-hc-db")


def test_coefficients_map_our_axes_to_ross(pair):
    speeds = np.linspace(0, 1200, 4)
    loads = jh.Loads(fa=300.0, fr_y=500.0, fr_z=200.0)
    c = export.ross_coefficients(pair, speeds, loads)
    for i, w in enumerate(speeds):
        k = jh.solve(pair, loads, w).stiffness
        np.testing.assert_allclose([c["kxx"][i], c["kxy"][i], c["kyx"][i], c["kyy"][i], c["kzz"][i]],
                                   [k[1, 1], k[1, 2], k[2, 1], k[2, 2], k[0, 0]], rtol=1e-7)


def test_json_export_and_bad_speed(pair, tmp_path):
    p = export.export_json(pair, [0.0, 500.0], tmp_path / "b.json")
    doc = json.loads(p.read_text())
    assert len(doc["kxx_N_per_m"]) == 2 and "K[gamma_z,gamma_z]" in doc["dropped_terms"]
    with pytest.raises(InputError) as exc:
        export.ross_coefficients(pair, [-1.0])
    assert exc.value.field == "speed"


def test_ross_rotor_with_exported_bearings(pair):
    rs = pytest.importorskip("ross")
    steel = rs.Material(name="steel_bs", rho=7810, E=211e9, G_s=81.2e9)
    shaft = [rs.ShaftElement(L=0.1, idl=0.0, odl=0.055, material=steel) for _ in range(6)]
    disk = rs.DiskElement.from_geometry(n=3, material=steel, width=0.05, i_d=0.055, o_d=0.2)
    speeds = np.linspace(0, 1200, 5)
    b0 = export.to_ross_bearing(pair, 0, speeds, jh.Loads(fr_y=200.0), tag="front")
    b1 = export.to_ross_bearing(pair, 6, speeds, jh.Loads(fr_y=200.0), tag="rear")
    rotor = rs.Rotor(shaft, [disk], [b0, b1])
    modal = rotor.run_modal(speed=600.0)
    wn = np.sort(np.abs(modal.wn))
    assert np.all(np.isfinite(wn)) and wn[0] > 0
    # the exported element returns our stiffness at a speed on the grid
    k = export.ross_coefficients(pair, [600.0], jh.Loads(fr_y=200.0))["kxx"][0]
    np.testing.assert_allclose(b0.kxx_interpolated(600.0), k, rtol=1e-6)


# ---- issue 11 items 5 and 10: an unloaded bearing and wrong argument types -------------------------
def test_unloaded_bearing_is_refused_not_exported_as_noise():
    """Without load or preload no ball carries load: every coefficient would be round-off."""
    single = load_bearing("skf-7011-cdga-hc")
    for loads in (None, jh.Loads()):
        with pytest.raises(InputError) as exc:
            export.ross_coefficients(single, [0.0, 500.0], loads)
        assert "--fa/--fr" in exc.value.field and "no stiffness" in exc.value.problem
    # a load, or a preloaded set, is exported
    c = export.ross_coefficients(single, [0.0], jh.Loads(fa=500.0))
    assert c["kzz"][0] > 1e7  # K_xx of a 7011 under 500 N is tens of N/µm


def test_preloaded_pair_without_load_is_exported(pair):
    c = export.ross_coefficients(pair, [0.0], None)
    k = jh.solve(pair, jh.Loads(), 0.0).stiffness
    np.testing.assert_allclose(c["kxx"][0], k[1, 1], rtol=1e-7)
    assert c["kxx"][0] > 1e7


@pytest.mark.parametrize("kwargs, field", [
    (dict(bearing=None), "bearing"),
    (dict(bearing=3.5), "bearing"),
    (dict(speeds="1000 rpm"), "speeds"),
    (dict(speeds=None), "speeds"),
    (dict(speeds=[[0.0, "a"]]), "speeds"),
    (dict(loads={"fa": 100.0}), "loads"),
    (dict(loads=100.0), "loads"),
    (dict(control=None), "control"),
    (dict(control="middle"), "control"),
])
def test_wrong_argument_types_name_the_argument(pair, kwargs, field):
    args = dict(bearing=pair, speeds=[0.0], loads=jh.Loads(fa=100.0), control="outer") | kwargs
    with pytest.raises(InputError) as exc:
        export.ross_coefficients(**args)
    assert exc.value.field == field


@pytest.mark.parametrize("path", [None, 3, ["a.json"]])
def test_export_json_path_type(pair, path):
    with pytest.raises(InputError) as exc:
        export.export_json(pair, [0.0], path, jh.Loads(fa=100.0))
    assert exc.value.field == "path"


def test_cli_export_without_load_is_one_line_exit_2(tmp_path):
    import shutil
    import subprocess

    out = tmp_path / "r.json"
    p = subprocess.run([shutil.which("bearingsim"), "export", "ross", "skf-7011-cdga-hc", "--out", str(out)],
                       capture_output=True, text=True, timeout=180)
    text = (p.stdout + p.stderr).strip()
    assert p.returncode == 2 and len(text.splitlines()) == 1, text
    assert "--fa/--fr" in text and "no stiffness" in text
    assert not out.exists()
