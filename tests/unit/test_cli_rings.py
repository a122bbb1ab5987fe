"""``--rings`` on ``static`` (issue 16 item 2): through the installed console script."""

import json
import subprocess


def _run(*args):
    return subprocess.run(["bearingsim", *args], capture_output=True, text=True, timeout=600)


def test_static_names_the_ring_model_and_fe_rings_are_softer():
    rigid = _run("static", "skf-7011-cdga-hc", "--fa", "3 kN", "--json")
    fe = _run("static", "skf-7011-cdga-hc", "--fa", "3 kN", "--rings", "fe", "--json")
    assert rigid.returncode == 0 and fe.returncode == 0, rigid.stderr + fe.stderr
    dr, df = json.loads(rigid.stdout), json.loads(fe.stdout)
    assert dr["rings"]["model"] == "rigid" and df["rings"]["model"] == "fe"
    assert df["rings"]["residual_m"] < 1e-11 and df["converged"]
    # elastic rings and seats add compliance in series with the contacts: softer, by less than the seats alone
    # could (docs/rings.md: 0.92-0.94 of the rigid stiffness for the 7011 at 1-5 kN)
    ratio = df["axial_stiffness_N_per_m"] / dr["axial_stiffness_N_per_m"]
    assert 0.85 < ratio < 0.99, ratio
    human = _run("static", "skf-7011-cdga-hc", "--fa", "3 kN", "--rings", "fe")
    assert human.returncode == 0 and "rings: elastic" in human.stdout


def test_bad_ring_model_is_one_line():
    r = _run("static", "skf-7011-cdga-hc", "--fa", "3 kN", "--rings", "soft")
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "--rings" in r.stderr
