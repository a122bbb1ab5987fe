"""The comments and docstrings of ``src/bearingsim`` say what the code does and why, in the present tense.

Guards the rule of docs/development/history.md: the record of how the code became fast or correct (numbered
passes, rounds and sessions, levers "measured and rejected" or "not kept", "was 1.8 ms", "before this
release", issue numbers, commit hashes, "used to", "no longer") lives in that file and the CHANGELOG, not in
the code nor in docs/dynamics.md, which describes the engine as it is.  Every ``.py`` file under ``src/bearingsim`` is read with :mod:`tokenize` (comments) and :mod:`ast`
(docstrings and other bare string statements); nothing is imported.  A measured fact that explains a design
decision stays in the code, said in the present tense ("ROS34PW2 takes a third of DOPRI5's steps on the hub
case"), without the story of how it was found.
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[2] / "src" / "bearingsim"

_ORDINAL = (
    r"(?:fourth|fifth|sixth|seventh|eighth|ninth|tenth|eleventh|twelfth|\w+teenth|twentieth|twenty-\w+"
    r"|thirtieth|\d+(?:st|nd|rd|th))"
)

#: the diary's phrases (case-insensitive), each with the reason it is history rather than description
DIARY = re.compile(
    "|".join(
        [
            # numbered passes, rounds and sessions of the development log ("tenth pass", "fourth and sixth passes")
            rf"\b{_ORDINAL}(?:\s+and\s+{_ORDINAL})?\s+(?:pass|passes|round|rounds|session|sessions)\b",
            r"\b(?:pass|round|session)\s+\d+\b",
            r"\b(?:this|that|last|previous|earlier|an earlier|the same|next)\s+sessions?\b",
            # levers tried: the outcome of an experiment, not a property of the code (a lever arm is mechanics)
            r"\bmeasured and (?:rejected|dropped|reverted|not kept)\b",
            r"\bnot kept\b",
            r"\blevers?\b(?![- ]arms?)",
            r"\bbefore this (?:release|session|change|pass|round)\b",
            # issue numbers of the development log
            r"\bissues?\s+\d+",
            r"\bissue \d+'s\b",
            # a former figure: "was 1.8 ms", "were 30 %"
            r"\b(?:was|were)\s+(?:≈\s*|~\s*|about\s+)?[\d.,]+\s*(?:ms|s|µs|us|ns|%|×|x|MB|GB|min|h)\b",
            # a former behaviour ("the index used to address", "is used to compute" are present tense; "no longer
            # than" is a length)
            r"\bused to be\b",
            r"\b(?:it|this|that|they|we|which|there|code|solver|kernel|engine)\s+used to\b",
            r"\bno longer\b(?! than)",
        ]
    ),
    re.IGNORECASE,
)

#: a commit hash: 7–40 lowercase hexadecimal characters with at least one digit and one letter, preceded by
#: "commit" or standing in parentheses/brackets the way the log cites them
COMMIT = re.compile(r"\bcommits?\s+[0-9a-f]{7,40}\b|[(\[](?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}[)\]]")


def _texts(path: Path) -> list[tuple[int, str]]:
    """(line, text) of every comment and every bare string statement (docstrings included) of one file."""
    src = path.read_text(encoding="utf-8")
    out = [
        (tok.start[0], tok.string)
        for tok in tokenize.generate_tokens(io.StringIO(src).readline)
        if tok.type == tokenize.COMMENT
    ]
    for node in ast.walk(ast.parse(src)):
        if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant) and isinstance(node.value.value, str):
            for k, line in enumerate(node.value.value.splitlines()):
                out.append((node.lineno + k, line))
    return out


def _hits(text: str) -> list[str]:
    return [m.group(0) for m in DIARY.finditer(text)] + [m.group(0) for m in COMMIT.finditer(text)]


@pytest.mark.parametrize(
    "text",
    [
        "issue 14, tenth pass: hub step −20 %",
        "docs/dynamics.md, fourth and sixth passes",
        "the twenty-second pass had preferred even/odd",
        "levers measured and rejected",
        "a lever that is not kept",
        "this call was 1.8 ms",
        "before this release the kernel allocated",
        "the solver used to call scipy",
        "the cache is no longer needed",
        "round 3 of the review",
        "as in session 2",
        "fixed in commit 3f2a9c1",
        "the switch moved in issue 14's twelfth pass",
    ],
)
def test_pattern_flags_diary(text: str) -> None:
    assert _hits(text), f"the diary pattern misses {text!r}"


@pytest.mark.parametrize(
    "text",
    [
        "the lever arm r − c moves with the ball",
        "lever-arm changes, which a W-method tolerates",
        "rejected steps shrink h by the controller's factor",
        "the Jacobian is used to build W",
        "every index used to address the model's arrays",
        "exact to round-off; tested against scipy.special",
        "the moment passes 0.3 kN·m falling",
        "no longer than the contact half-width",
        "one kernel pass over the row's balls",
        "a long-running session: keep the cache bounded",
        "the first step that reaches or passes t_end",
        "1e-12 of the normalised coefficients",
    ],
)
def test_pattern_spares_present_tense(text: str) -> None:
    assert not _hits(text), f"the diary pattern flags the present-tense text {text!r}: {_hits(text)}"


def test_no_diary_words_in_the_dynamics_page() -> None:
    """docs/dynamics.md describes the engine as it is; its development record is docs/development/history.md."""
    page = SRC.parents[1] / "docs" / "dynamics.md"
    found = [
        f"docs/dynamics.md:{k}: {hit!r}"
        for k, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1)
        for hit in _hits(line)
    ]
    assert not found, f"{len(found)} diary phrases in docs/dynamics.md (move them to docs/development/history.md):\n" + (
        "\n".join(found)
    )


def test_no_diary_words_in_src() -> None:
    found = [
        f"{path.relative_to(SRC.parent)}:{line}: {hit!r}"
        for path in sorted(SRC.rglob("*.py"))
        for line, text in _texts(path)
        for hit in _hits(text)
    ]
    assert not found, (
        f"{len(found)} diary phrases in comments/docstrings of src/ (say what the code does and why; the record "
        "goes to docs/development/history.md):\n" + "\n".join(found)
    )
