"""The README's, the getting-started page's and the user guide's Python blocks run as written (examples are
tests), and every relative link of the Markdown pages resolves."""

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
GUIDE = ROOT / "docs" / "user-guide"
PAGES = [ROOT / "docs" / "getting-started.md", *sorted(GUIDE.glob("*.md"))]


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


def test_every_user_guide_page_has_a_runnable_block():
    """Each task page of the user guide shows its Python call (the index page excepted)."""
    missing = [p.name for p in PAGES if p.name != "index.md" and "```python" not in p.read_text(encoding="utf-8")]
    assert not missing, f"user-guide pages without a Python block: {missing}"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_page_python_blocks_run(page, tmp_path, monkeypatch):
    if "```python" not in page.read_text(encoding="utf-8"):
        pytest.skip(f"{page.name} has no Python block")
    ns = _run_blocks(page, tmp_path, monkeypatch)
    checks = {
        "getting-started.md": lambda: ns["r"].converged and ns["d"]["basic_rating_life_hours"] > 0,
        "statics.md": lambda: ns["r"].converged and ns["batch"].converged.all()
        and (tmp_path / "rep" / "report.html").exists(),
        "maps.md": lambda: ns["ds"].converged.all() and ns["k_axial"].shape == (9, 41),
        "dynamics.md": lambda: ns["res"].steady_state()["heat_generation_total_W"] > 0
        and (tmp_path / "run.nc").exists(),
        "lives.md": lambda: ns["lives"]["modified_rating_life_hours"] > 0,
        "lubrication.md": lambda: ns["f"]["friction_torque_N_m"] > 0 and len(ns["contacts"]) > 0,
        "rings.md": lambda: ns["res"].converged and 0.5 < ns["res"].axial_stiffness / ns["rigid"].stiffness[0, 0] < 1,
        "files.md": lambda: ns["b"].ball_count > 0 and len(ns["hub"].rows) == 2,
        "errors.md": lambda: "fa" in ns["message"],
        "shafts.md": lambda: ns["r"].converged and len(ns["m"].frequency_hz) == 6 and ns["m"].frequency_hz[0] > 0,
    }
    assert checks[page.name](), f"{page.name}: the page's example does not give what it says"


def test_guide_bearing_file_example_loads(tmp_path):
    from bearingsim.io import load_bearing

    blocks = re.findall(r"```toml\n(.*?)```", (GUIDE / "files.md").read_text(encoding="utf-8"), flags=re.S)
    single = next(b for b in blocks if 'type = "angular_contact"' in b)
    f = tmp_path / "b.toml"
    f.write_text(single, encoding="utf-8")
    b = load_bearing(f)
    assert b.ball_count == 17 and abs(b.inner_conformity - 5.98 / 11.5) < 1e-12


def test_readme_links_resolve():
    """Every relative link of the README and of the docs' Markdown pages names a file that exists."""
    pages = [README, *sorted(p for p in (ROOT / "docs").rglob("*.md") if "_build" not in p.parts)]
    for page in pages:
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", page.read_text(encoding="utf-8")):
            if "://" in target or target.startswith("mailto:"):
                continue
            assert (page.parent / target).exists(), f"{page.relative_to(ROOT)} links to missing {target}"
