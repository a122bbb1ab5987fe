"""The README's and the user guide's Python tours run as written (examples are tests)."""

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
GUIDE = ROOT / "docs" / "guide.md"


def _run_blocks(path: Path, tmp_path, monkeypatch) -> dict:
    """Every ```python block of ``path``, run in order in one namespace where the relative paths resolve, without
    writing into the repository."""
    if not (tmp_path / "examples").exists():
        (tmp_path / "examples").symlink_to(ROOT / "examples")
    monkeypatch.chdir(tmp_path)
    blocks = re.findall(r"```python\n(.*?)```", path.read_text(encoding="utf-8"), flags=re.S)
    assert blocks, f"{path.name} has a Python tour"
    namespace: dict = {}
    for code in blocks:
        exec(compile(code, str(path), "exec"), namespace)  # noqa: S102 - our own pages
    return namespace


def test_readme_python_block_runs(tmp_path, monkeypatch):
    ns = _run_blocks(README, tmp_path, monkeypatch)
    assert ns["r"].converged
    assert abs(ns["r"].speed - 11200 * 2 * 3.141592653589793 / 60) < 1e-9  # "11200 rpm" taken as rpm


def test_guide_python_blocks_run(tmp_path, monkeypatch):
    ns = _run_blocks(GUIDE, tmp_path, monkeypatch)
    assert ns["r"].converged
    assert ns["ds"].converged.all()
    assert ns["res"].steady_state()["heat_generation_total_W"] > 0
    assert (tmp_path / "run.nc").exists()


def test_guide_bearing_file_example_loads(tmp_path):
    from bearingsim.io import load_bearing

    blocks = re.findall(r"```toml\n(.*?)```", GUIDE.read_text(encoding="utf-8"), flags=re.S)
    single = next(b for b in blocks if 'type = "angular_contact"' in b)
    f = tmp_path / "b.toml"
    f.write_text(single, encoding="utf-8")
    b = load_bearing(f)
    assert b.ball_count == 17 and abs(b.inner_conformity - 5.98 / 11.5) < 1e-12


def test_readme_links_resolve():
    """Every relative link of the README and of the docs' Markdown pages names a file that exists."""
    pages = [README, *sorted((ROOT / "docs").rglob("*.md"))]
    for page in pages:
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", page.read_text(encoding="utf-8")):
            if "://" in target or target.startswith("mailto:"):
                continue
            assert (page.parent / target).exists(), f"{page.relative_to(ROOT)} links to missing {target}"
