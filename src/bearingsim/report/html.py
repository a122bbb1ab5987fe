"""Generic pieces of a self-contained HTML report: page skeleton (the style sheet ``style.css`` inlined, so the
page opens from disk without a server), sections, tables, figures (image files beside the page, linked by
relative name) and escaping.  No study-specific content here.
"""

from __future__ import annotations

import html as _html
import math
from importlib import resources
from pathlib import Path


def escape(text) -> str:
    """Text → HTML (quotes included)."""
    return _html.escape(str(text), quote=True)


def style() -> str:
    """The shared style sheet (package data ``bearingsim/report/style.css``)."""
    return resources.files(__package__).joinpath("style.css").read_text(encoding="utf-8")


def page(title: str, body: str, generator: str = "bearingsim") -> str:
    """A whole HTML5 page: ``title`` (escaped) and ``body`` (HTML), the style sheet inlined."""
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<meta name=\"generator\" content=\"{escape(generator)}\">\n<title>{escape(title)}</title>\n"
            f"<style>\n{style()}</style>\n</head>\n<body>\n<h1>{escape(title)}</h1>\n{body}\n</body>\n</html>\n")


def section(title: str, body: str, ident: str | None = None) -> str:
    """``<section>`` with an ``<h2>`` title (escaped) and ``body`` (HTML)."""
    attr = f" id=\"{escape(ident)}\"" if ident else ""
    return f"<section{attr}>\n<h2>{escape(title)}</h2>\n{body}\n</section>\n"


def paragraph(text: str, cls: str | None = None) -> str:
    """``<p>`` of plain text (escaped)."""
    c = f" class=\"{escape(cls)}\"" if cls else ""
    return f"<p{c}>{escape(text)}</p>\n"


def fmt(value, spec: str = ".3g", missing: str = "—") -> str:
    """A number for a table cell; None/NaN → ``missing``; strings unchanged."""
    if value is None:
        return missing
    if isinstance(value, str):
        return value
    try:
        v = float(value)
    except (TypeError, ValueError):
        return str(value)
    return missing if not math.isfinite(v) else format(v, spec)


def table(header: list, rows: list, caption: str | None = None, text_columns: tuple = (), ident: str | None = None,
          specs: list | None = None) -> str:
    """``<table>``: ``header`` (strings), ``rows`` (lists of values, formatted by :func:`fmt` with
    ``specs[j]``), columns ``text_columns`` left-aligned; every cell escaped."""
    attr = f" id=\"{escape(ident)}\"" if ident else ""
    out = [f"<table{attr}>"]
    if caption:
        out.append(f"<caption>{escape(caption)}</caption>")

    def cls(j):
        return " class=\"text\"" if j in text_columns else ""

    out.append("<thead><tr>" + "".join(f"<th{cls(j)}>{escape(h)}</th>" for j, h in enumerate(header)) + "</tr></thead>")
    out.append("<tbody>")
    for r in rows:
        cells = []
        for j, v in enumerate(r):
            spec = specs[j] if specs and j < len(specs) and specs[j] else ".3g"
            cells.append(f"<td{cls(j)}>{escape(fmt(v, spec))}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</tbody></table>\n")
    return "\n".join(out)


def figure(src: str, caption: str, alt: str | None = None) -> str:
    """``<figure>`` of an image file beside the page (``src`` a relative file name)."""
    return (f"<figure><img src=\"{escape(src)}\" alt=\"{escape(alt or caption)}\">"
            f"<figcaption>{escape(caption)}</figcaption></figure>\n")


def bullet_list(items: list, raw: bool = False) -> str:
    """``<ul>`` of plain-text items (escaped unless ``raw``)."""
    return "<ul>\n" + "".join(f"<li>{it if raw else escape(it)}</li>\n" for it in items) + "</ul>\n"


def write_page(path, title: str, body: str) -> Path:
    """Write :func:`page` to ``path`` (UTF-8) and return the path."""
    path = Path(path)
    path.write_text(page(title, body), encoding="utf-8")
    return path


__all__ = ["bullet_list", "escape", "figure", "fmt", "page", "paragraph", "section", "style", "table", "write_page"]
