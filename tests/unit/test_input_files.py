"""Input files (issue 11 item 4): every bad file is one InputError naming the file and the fix.

A binary, UTF-16 or Latin-1 bearing/case/lubricant file raised UnicodeDecodeError, deeply nested TOML
raised RecursionError.  All input files are read by bearingsim.io.read_toml; tested at the API (bearing,
lubricant, case readers) and through the installed console script (one line, exit 2).
"""

from __future__ import annotations

import shutil
import subprocess
import time

import pytest

from bearingsim import io
from bearingsim.dynamics.case import load_case
from bearingsim.errors import InputError
from bearingsim.lubricants import get_lubricant

GOOD_BEARING = """name = "test"
type = "angular_contact"
ball_diameter = "10.319 mm"
ball_count = 21
pitch_diameter = "72.5 mm"
inner_conformity = 0.52
outer_conformity = 0.53
contact_angle = "15 deg"
ball_material = "silicon_nitride"
ring_material = "bearing_steel"
"""


def _bad_files(tmp_path):
    """name -> (path, words the message must contain)."""
    files = {}
    p = tmp_path / "binary.toml"
    p.write_bytes(bytes(range(256)) * 4)
    files["binary"] = (p, "binary")
    p = tmp_path / "utf16.toml"
    p.write_text(GOOD_BEARING, encoding="utf-16")  # with BOM
    files["utf16"] = (p, "UTF-16")
    p = tmp_path / "utf16le.toml"
    p.write_bytes(GOOD_BEARING.encode("utf-16-le"))  # without BOM
    files["utf16le"] = (p, "UTF-16")
    p = tmp_path / "latin1.toml"
    p.write_bytes(('description = "Kugellager Größe 6205"\n' + GOOD_BEARING).encode("latin-1"))
    files["latin1"] = (p, "not UTF-8")
    p = tmp_path / "deep_array.toml"
    p.write_text("a = " + "[" * 50000 + "]" * 50000 + "\n")
    files["deep_array"] = (p, "deeply")
    p = tmp_path / "deep_table.toml"
    p.write_text("a = " + "{b = " * 20000 + "1" + "}" * 20000 + "\n")
    files["deep_table"] = (p, "deeply")
    p = tmp_path / "a_folder.toml"
    p.mkdir()
    files["directory"] = (p, "directory")
    files["missing"] = (tmp_path / "missing.toml", "does not exist")
    p = tmp_path / "huge.toml"
    with p.open("wb") as fh:
        fh.write(b"# " + b"x" * (io.MAX_FILE_BYTES + 10) + b"\n")
    files["huge"] = (p, "larger than")
    return files


@pytest.fixture(scope="module")
def bad_files(tmp_path_factory):
    return _bad_files(tmp_path_factory.mktemp("bad_inputs"))


KINDS = ["binary", "utf16", "utf16le", "latin1", "deep_array", "deep_table", "directory", "missing", "huge"]


def _check(exc: InputError, field: str, path, words: str):
    msg = str(exc)
    assert exc.field == field, msg
    assert str(path) in msg, "the message names the file"
    assert words in msg, msg
    assert exc.fix and "\n" not in msg


@pytest.mark.parametrize("kind", KINDS)
def test_bearing_reader(bad_files, kind):
    path, words = bad_files[kind]
    with pytest.raises(InputError) as info:
        io.load_bearing(path)
    _check(info.value, "bearing", path, words)


@pytest.mark.parametrize("kind", KINDS)
def test_lubricant_reader(bad_files, kind):
    path, words = bad_files[kind]
    with pytest.raises(InputError) as info:
        get_lubricant(path)
    _check(info.value, "lubricant", path, words)


@pytest.mark.parametrize("kind", KINDS)
def test_case_reader(bad_files, kind):
    path, words = bad_files[kind]
    with pytest.raises(InputError) as info:
        load_case(path)
    _check(info.value, "case", path, words)


def test_utf8_with_byte_order_mark_is_read(tmp_path):
    p = tmp_path / "bom.toml"
    p.write_bytes(b"\xef\xbb\xbf" + GOOD_BEARING.encode("utf-8"))
    assert io.load_bearing(p).ball_count == 21


def test_non_ascii_utf8_is_read(tmp_path):
    p = tmp_path / "umlaut.toml"
    p.write_text('description = "Kugellager Größe, α₀ = 15°"\n' + GOOD_BEARING, encoding="utf-8")
    assert io.load_bearing(p).notes["description"].startswith("Kugellager Größe")


def test_deep_nesting_is_refused_quickly(bad_files):
    t0 = time.perf_counter()
    with pytest.raises(InputError):
        io.read_toml(bad_files["deep_array"][0], "bearing")
    assert time.perf_counter() - t0 < 5.0


@pytest.mark.parametrize("value", [None, 3, 2.5, ["a.toml"], {"a": 1}, b"x.toml"])
def test_read_toml_wrong_type_names_the_argument(value):
    with pytest.raises(InputError) as info:
        io.read_toml(value, "case")
    assert info.value.field == "case" and type(value).__name__ in str(info.value)


def test_package_files_go_through_the_same_reader():
    """The catalogue and the lubricant library are read by io.read_toml too (valid UTF-8 TOML)."""
    assert len(io.catalog_entries()) == len(io.catalog_names()) >= 5
    assert get_lubricant("iso-vg-68").kinematic_viscosity(313.15) == pytest.approx(68e-6, rel=1e-12)


# ---- through the installed console script ----------------------------------------------------------
BIN = shutil.which("bearingsim")


def _cli(*args):
    assert BIN, "the bearingsim console script is not installed"
    p = subprocess.run([BIN, *map(str, args)], capture_output=True, text=True, timeout=180)
    return p.returncode, (p.stdout + p.stderr).strip()


@pytest.mark.parametrize("kind", ["binary", "utf16", "latin1", "deep_array"])  # the rest: API tests above
def test_cli_static_bad_bearing_file(bad_files, kind):
    path, words = bad_files[kind]
    code, out = _cli("static", path, "--fa", "1000")
    assert code == 2, out
    assert len(out.splitlines()) == 1 and "Traceback" not in out, out
    assert str(path) in out and words in out


@pytest.mark.parametrize("kind", ["deep_table"])
def test_cli_lubrication_bad_lubricant_file(bad_files, kind):
    path, words = bad_files[kind]
    code, out = _cli("lubrication", "skf-7011-cdga-hc", "--lubricant", path, "--fa", "1000", "--speed", "1000")
    assert code == 2, out
    assert len(out.splitlines()) == 1 and "Traceback" not in out, out
    assert str(path) in out and words in out


@pytest.mark.parametrize("kind", ["utf16le"])
def test_cli_simulate_bad_case_file(bad_files, kind, tmp_path):
    path, words = bad_files[kind]
    code, out = _cli("simulate", path, "--out", tmp_path / "run.nc")
    assert code == 2, out
    assert len(out.splitlines()) == 1 and "Traceback" not in out, out
    assert str(path) in out and words in out
    assert not (tmp_path / "run.nc").exists()


# ---- fuzz: any table of any TOML values gives a result or an InputError, nothing else ----------------
from hypothesis import HealthCheck, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from bearingsim.dynamics.case import case_from_dict  # noqa: E402
from bearingsim.io.case import _KEYS as CASE_KEYS  # noqa: E402
from bearingsim.lubricants import lubricant_from_dict  # noqa: E402

_WORDS = ["10 mm", "72.5 mm", "15 deg", "0 mm", "-5 mm", "1e9 mm", "5 kg", "3 N", "0.52", "1e400", "208 GPa",
          "7850 kg/m^3", "20 kN", "abc", "", "60 degC", "10 ms", "1000 rpm", "9**9 N", "3000,5 N", "silicon_nitride",
          "bearing_steel", "angular_contact", "deep_groove", "DB", "skf-7011-cdga-hc", "iso-vg-68", "slices", "none",
          "outer"]
_SCALAR = st.one_of(st.sampled_from(_WORDS), st.integers(-10**20, 10**20), st.floats(), st.booleans(),
                    st.text(max_size=12))
_VALUE = st.recursive(_SCALAR, lambda ch: st.one_of(st.lists(ch, max_size=3), st.dictionaries(st.sampled_from(
    ["youngs_modulus", "poisson_ratio", "density", "name", "mass", "offset", "amplitude", "frequency", "start", "stop",
     "ramp", "table", "fa", "mz", "bearing", "position"]), ch, max_size=3)), max_leaves=6)
_BEARING = dict(GOOD_TABLE := {"name": "t", "type": "angular_contact", "ball_diameter": "10.319 mm", "ball_count": 21,
                               "pitch_diameter": "72.5 mm", "inner_conformity": 0.52, "outer_conformity": 0.53,
                               "contact_angle": "15 deg", "ball_material": "silicon_nitride",
                               "ring_material": "bearing_steel"})
_LUB = {"viscosity": [["40 degC", "68 mm^2/s"], ["100 degC", "8.7 mm^2/s"]], "density_15C": "875 kg/m^3",
        "pressure_viscosity_coefficient": "21 1/GPa", "thermal_conductivity": "0.13 W/(m*K)"}
_CASE = {"bearing": "skf-7011-cdga-hc", "speed": "1000 rpm", "duration": "1 ms", "output_interval": "0.1 ms",
         "traction": "none"}
_FUZZ = settings(max_examples=250, deadline=None, suppress_health_check=list(HealthCheck))


def _only_input_error(fn, data):
    try:
        fn(data)
    except InputError as exc:
        assert "\n" not in str(exc) and exc.field


@_FUZZ
@given(upd=st.dictionaries(st.sampled_from(sorted(io.bearing._BEARING_KEYS) + ["rows", "arrangement", "row", "preload"]),
                           _VALUE, max_size=4), drop=st.sets(st.sampled_from(sorted(_BEARING)), max_size=2))
def test_fuzz_bearing_tables(upd, drop):
    _only_input_error(io.bearing_from_dict, {k: v for k, v in _BEARING.items() if k not in drop} | upd)


@_FUZZ
@given(upd=st.dictionaries(st.sampled_from(sorted(_LUB) + ["lss_ratio", "lss_c4", "temperature_range", "name",
                                                             "sources", "eyring_stress"]), _VALUE, max_size=3))
def test_fuzz_lubricant_tables(upd):
    _only_input_error(lubricant_from_dict, _LUB | upd)


@_FUZZ
@given(upd=st.dictionaries(st.sampled_from(sorted(CASE_KEYS)), _VALUE, max_size=3))
def test_fuzz_case_tables(upd):
    _only_input_error(case_from_dict, _CASE | upd)


@_FUZZ
@given(parts=st.lists(st.sampled_from(list('[]{}="., \n#abc019-:+eE') + ["a = ", "\\u", "'''", '"""']),
                     max_size=120))
def test_fuzz_toml_text(parts):
    text = "".join(parts)
    try:
        io.parse_toml(text, "fuzz.toml", "bearing")
    except InputError as exc:
        assert exc.field == "bearing"


def test_fifo_and_devices_are_refused_without_blocking(tmp_path):
    import os

    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    t0 = time.perf_counter()
    for path in (fifo, "/dev/zero"):
        with pytest.raises(InputError) as info:
            io.load_bearing(path)
        assert "not a regular file" in str(info.value)
    assert time.perf_counter() - t0 < 2.0


def test_integer_beyond_pythons_digit_limit(write_toml):
    with pytest.raises(InputError) as info:
        io.load_bearing(write_toml("ball_count = " + "9" * 5000 + "\n"))
    assert info.value.field == "bearing" and "digits" in str(info.value)
    with pytest.raises(InputError) as info:  # a huge hexadecimal integer is read, then refused as a ball count
        io.load_bearing(write_toml(GOOD_BEARING.replace("ball_count = 21", "ball_count = 0x" + "f" * 3000)))
    assert info.value.field == "ball_count"


@pytest.mark.parametrize("data, words", [
    (GOOD_BEARING.encode("utf-16-be"), "UTF-16"),
    (b"\x00" * 4096, "binary"),  # all zeros is not UTF-16 text
    (b"\x89HDF\r\n\x1a\n" + b"\x00" * 600, "binary"),  # a netCDF-4 output given as input
])
def test_utf16_is_told_apart_from_binary(tmp_path, data, words):
    p = tmp_path / "x.toml"
    p.write_bytes(data)
    with pytest.raises(InputError) as info:
        io.read_toml(p, "bearing")
    assert words in str(info.value)
