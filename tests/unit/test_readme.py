"""The README's Python tour runs as written (examples are tests)."""

import re
from pathlib import Path

README = Path(__file__).resolve().parents[2] / "README.md"


def test_readme_python_blocks_run(tmp_path, monkeypatch):
    # run where the README's relative paths resolve, without writing into the repository
    (tmp_path / "examples").symlink_to(README.parent / "examples")
    monkeypatch.chdir(tmp_path)
    blocks = re.findall(r"```python\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    assert blocks, "the README has a Python tour"
    for code in blocks:
        namespace: dict = {}
        exec(compile(code, str(README), "exec"), namespace)  # noqa: S102 - our own README
    assert namespace["r"].converged
    assert namespace["ds"].converged.all()
    assert namespace["res"].steady_state()["heat_generation_total_W"] > 0
    assert (tmp_path / "run.nc").exists()


def test_readme_bearing_file_example_loads(tmp_path):
    from bearingsim.io import load_bearing

    blocks = re.findall(r"```toml\n(.*?)```", README.read_text(encoding="utf-8"), flags=re.S)
    single = next(b for b in blocks if 'type = "angular_contact"' in b)
    f = tmp_path / "b.toml"
    f.write_text(single, encoding="utf-8")
    b = load_bearing(f)
    assert b.ball_count == 17 and abs(b.inner_conformity - 5.98 / 11.5) < 1e-12
