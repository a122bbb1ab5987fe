"""Input files: path checks and the one reader of TOML text.

Every input file of bearingsim (bearing, arrangement, clearance, lubricant, case) is read by
:func:`read_toml` (text by :func:`read_text`): a missing file, a directory, a file larger than
:data:`MAX_FILE_BYTES`, a binary file, UTF-16 or Latin-1 text, malformed or too deeply nested
TOML all raise :class:`~bearingsim.errors.InputError` naming the file and the fix — never
``UnicodeDecodeError`` or ``RecursionError``.
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from ..errors import InputError

#: largest input file read [bytes]; bearing, lubricant and case files are a few kB
MAX_FILE_BYTES = 4 * 2**20


def check_path(path, field: str, what: str = "a TOML file"):
    """``path`` as a :class:`~pathlib.Path` (or a package resource); anything else (None, a number,
    a list) raises :class:`InputError` naming ``field``."""
    if isinstance(path, (str, os.PathLike)):
        if isinstance(path, str) and not path.strip():
            raise InputError(field, "empty path", f"give {what}")
        if "\0" in str(path):
            raise InputError(field, "the path contains a NUL character", f"give {what}")
        return Path(path)
    if hasattr(path, "read_bytes") and hasattr(path, "is_file"):  # importlib.resources Traversable
        return path
    raise InputError(field, f"expected a path to {what}, got {type(path).__name__} {path!r}"[:200],
                     f"give {what} as a string or pathlib.Path")


def read_text(path, field: str = "file") -> str:
    """The text of an input file, read as UTF-8 (a UTF-8 byte-order mark is allowed).

    Raises :class:`InputError` (naming ``field`` and the file, with the fix) for a missing or
    unreadable file, a directory or another non-regular file (a FIFO would block), a file over
    :data:`MAX_FILE_BYTES`, a binary file and text that is not UTF-8 (UTF-16, Latin-1/Windows-1252).
    """
    p = check_path(path, field)
    name = str(p)
    fix_exist = "give an existing TOML file or a catalogue name (bearingsim catalog)"
    try:
        if p.is_dir():
            raise InputError(field, f"{name!r} is a directory, not a file", "give the path of a TOML file in it")
        if isinstance(p, Path) and p.exists() and not p.is_file():  # a FIFO or a device could block or never end
            raise InputError(field, f"{name!r} is not a regular file", "give the path of a TOML file")
        if isinstance(p, Path):
            with p.open("rb") as fh:
                data = fh.read(MAX_FILE_BYTES + 1)
        else:
            data = p.read_bytes()
    except InputError:
        raise
    except FileNotFoundError:
        raise InputError(field, f"{name!r} does not exist", fix_exist) from None
    except OSError as exc:
        raise InputError(field, f"cannot read {name!r} ({exc.strerror or exc.__class__.__name__})",
                         "check the path and its permissions") from None
    except ValueError as exc:  # e.g. an embedded NUL from os.PathLike objects
        raise InputError(field, f"cannot open {name!r} ({exc})", fix_exist) from None
    if len(data) > MAX_FILE_BYTES:
        raise InputError(field, f"{name!r} is larger than {MAX_FILE_BYTES // 2**20} MiB",
                         "an input file is a few kB of TOML: check that this is the right file")
    utf16 = _looks_utf16(data)
    if utf16:
        raise InputError(field, f"{name!r} is UTF-16 text (TOML files are UTF-8)",
                         "save the file as UTF-8 (e.g. Notepad: Save as, Encoding UTF-8)")
    if b"\x00" in data:
        raise InputError(field, f"{name!r} is a binary file, not TOML text",
                         "give the bearing/case/lubricant TOML file")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        line = data[:exc.start].count(b"\n") + 1
        raise InputError(field, f"{name!r} is not UTF-8 text (byte 0x{data[exc.start]:02x} on line {line}; "
                         "Latin-1 or Windows-1252?)", "save the file as UTF-8") from None


def _looks_utf16(data: bytes) -> bool:
    """A UTF-16 byte-order mark, or mostly-ASCII text whose every other byte is NUL (UTF-16LE/BE)."""
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        return True
    head = data[:256]
    if len(head) < 4:
        return False
    even, odd = head[0::2], head[1::2]
    return (set(odd) == {0} and 0 not in even) or (set(even) == {0} and 0 not in odd)


def parse_toml(text: str, name: str, field: str = "file") -> dict:
    """Parse TOML text; malformed or too deeply nested TOML raises :class:`InputError`."""
    if not isinstance(text, str):
        raise InputError(field, f"expected TOML text (str), got {type(text).__name__}", "read the file with read_text")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(field, f"{name} is not valid TOML: {exc}", "fix the TOML syntax at that line") from None
    except RecursionError:
        raise InputError(field, f"{name} nests arrays or tables too deeply for a TOML parser",
                         "an input file needs only a few levels of nesting: check the file") from None
    except ValueError as exc:  # e.g. an integer of more than 4300 digits (Python's int conversion limit)
        raise InputError(field, f"{name} holds a value TOML cannot read ({exc})"[:300],
                         "check the numbers in the file") from None


def read_toml(path, field: str = "file") -> dict:
    """Read a TOML input file (every input file goes through here, see :func:`read_text`)."""
    return parse_toml(read_text(path, field), str(path), field)


__all__ = ["MAX_FILE_BYTES", "check_path", "read_text", "parse_toml", "read_toml"]
