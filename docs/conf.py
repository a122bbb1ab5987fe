"""Sphinx configuration of the bearingsim documentation site.

Build: ``python -m sphinx -W --keep-going -b html docs docs/_build/html`` (CI runs it after the tests, so the
validation table shows the deviations that the tests just measured: docs/_generated/validation.json).
"""

from __future__ import annotations

import os
import re
import sys
from pathlib import Path

DOCS = Path(__file__).resolve().parent
ROOT = DOCS.parent
sys.path.insert(0, str(DOCS / "_ext"))

# the gallery scripts and autodoc import bearingsim: one numba thread and a headless matplotlib backend
os.environ.setdefault("NUMBA_NUM_THREADS", "1")
os.environ.setdefault("MPLBACKEND", "Agg")

import bearingsim  # noqa: E402

project = "bearingsim"
author = "the bearingsim maintainers"
copyright = "2026, the bearingsim maintainers"  # noqa: A001 - Sphinx's name
release = bearingsim.__version__
version = ".".join(release.split(".")[:2])

extensions = [
    "myst_parser",
    "sphinx.ext.autodoc",
    "sphinx.ext.autosummary",
    "sphinx.ext.mathjax",
    "numpydoc",
    "sphinx_gallery.gen_gallery",
    "validation_table",
]

source_suffix = {".md": "markdown", ".rst": "restructuredtext"}
root_doc = "index"
exclude_patterns = ["_build", "_generated", "Thumbs.db", ".DS_Store", "**/README.md"]
templates_path = ["_templates"]
html_static_path: list[str] = []  # the theme brings its own assets

# Markdown pages: ```python blocks highlighted, heading anchors for the in-page links
myst_enable_extensions = ["dollarmath", "colon_fence", "deflist"]
myst_heading_anchors = 4
suppress_warnings = ["myst.header"]  # the long theory pages start their sections at ### in places

# API reference: autosummary pages of every public name, numpydoc sections
autosummary_generate = True
autosummary_imported_members = True
autodoc_default_options = {"members": False}
autodoc_typehints = "none"
numpydoc_show_class_members = False
numpydoc_class_members_toctree = False
numpydoc_xref_param_type = False

# examples gallery: the scripts run at build time (each < 20 s on one core)
sphinx_gallery_conf = {
    "examples_dirs": [str(ROOT / "examples" / "gallery")],
    "gallery_dirs": ["auto_examples"],
    "filename_pattern": r"/plot_",
    "download_all_examples": False,
    "remove_config_comments": True,
    "within_subsection_order": "FileNameSortKey",
    "show_memory": False,
}

html_theme = "pydata_sphinx_theme"
html_title = f"bearingsim {release}"
html_theme_options = {
    "navigation_with_keys": False,
    "show_toc_level": 2,
    "secondary_sidebar_items": ["page-toc"],
    "footer_start": ["copyright"],
    "footer_end": ["sphinx-version"],
}
html_sidebars = {"index": [], "getting-started": []}
html_show_sourcelink = False


# --- API docstrings -------------------------------------------------------------------------------------------
# The docstrings write absolute values as |x|, which reStructuredText reads as a substitution: escape the bars.
_BARS = re.compile(r"(?<![|\\`])\|(?=[^\s|])([^|\n]*?[^\s|\\])\|(?![|_])")

# Public names whose docstrings are not in numpydoc form yet (their modules are being edited elsewhere): shown as
# preformatted text so that they read as written. tests/unit/test_public_docstrings.py holds the same list; remove
# a name from both when its docstring gains Parameters/Returns sections.
PREFORMATTED = {
    "bearingsim.ShaftSystem", "bearingsim.Section", "bearingsim.BearingSupport", "bearingsim.SpringSupport",
    "bearingsim.PointLoad", "bearingsim.DistributedLoad", "bearingsim.Gravity", "bearingsim.HelicalGear",
    "bearingsim.PointMass", "bearingsim.solve_shaft", "bearingsim.shaft_modes", "bearingsim.campbell",
    "bearingsim.shaft_to_ross", "bearingsim.rating_summary", "bearingsim.bearing_report", "bearingsim.map_grid",
    # the two layout contracts (docs/api/layouts.md): tables of names and offsets, read as plain text
    "bearingsim.statics.layout", "bearingsim.dynamics.layout",
}


def _prepare_docstring(app, what, name, obj, options, lines):
    """Escape |x| bars; indent the docstrings of PREFORMATTED as a literal block under their summary line."""
    if name in PREFORMATTED and any(ln.strip() for ln in lines[1:]):
        body = [("    " + ln) if ln.strip() else "" for ln in lines[1:]]
        lines[:] = [lines[0], "", "::", "", *body]
        return
    in_literal = False
    for i, line in enumerate(lines):
        if line.rstrip().endswith("::"):
            in_literal = True
        elif in_literal and line.strip() and not line.startswith(" "):
            in_literal = False
        grid_table = line.lstrip().startswith("+-") or (line.lstrip().startswith("|") and line.rstrip().endswith("|")
                                                         and line.count("|") > 2)
        if not in_literal and "|" in line and not grid_table:
            lines[i] = _BARS.sub(r"\\|\1\\|", line)


def setup(app):
    app.connect("autodoc-process-docstring", _prepare_docstring, priority=400)

