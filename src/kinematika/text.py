"""Names and messages made safe to show: shown as written, never interpreted.

A name in a model file is untrusted text. Printed raw, control characters drive the
terminal (``\\x1b]0;title\\x07`` sets the window title, ``\\x1b[2J`` clears the screen),
bidirectional overrides reorder what is read, a lone surrogate cannot be encoded, and
rich's markup (``[bold]``, ``[/]``) is read as formatting. Every view prints names through
`shown` (and `markup` where rich reads markup); `brief` bounds the text of any value put
into a message.
"""
from __future__ import annotations

import reprlib
import unicodedata
from typing import Any

_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _escape(c: str) -> str:
    if c in _NAMED:
        return _NAMED[c]
    code = ord(c)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}" if code < 0x10000 else f"\\U{code:08x}"


def shown(text: Any, limit: int | None = None) -> str:
    """`text` as one printable line: every character Python does not call printable (control
    characters, separators, bidirectional and other format controls such as zero-width
    spaces, lone surrogates) written as an escape (``\\x1b``, ``\\n``, ``\\u200b``,
    ``\\ud800``), spaces of every width kept; cut to `limit` characters with … when given."""
    text = text if isinstance(text, str) else str(text)
    if not text.isprintable():
        text = "".join(c if c.isprintable() or unicodedata.category(c) == "Zs" else _escape(c) for c in text)
    return clip(text, limit) if limit is not None else text


def shown_lines(text: str) -> str:
    """A whole document (an explanation, a table) with its line breaks kept and every other
    control character escaped as `shown` does: names inside it can drive no terminal."""
    if text.isprintable():
        return text
    return "\n".join(shown(line) for line in text.split("\n"))


def clip(text: str, limit: int) -> str:
    """`text` cut to at most `limit` characters, the cut marked with …"""
    return text if len(text) <= limit else text[:max(limit - 1, 0)] + "…"


def clip_middle(text: str, limit: int) -> str:
    """`text` cut in the middle (a long path keeps its start and its file name)."""
    if len(text) <= limit:
        return text
    head = (limit - 1) // 2
    return text[:head] + "…" + text[len(text) - (limit - 1 - head):]


def markup(text: Any, limit: int | None = None) -> str:
    """`shown(text)` with rich's markup escaped, for strings that rich will print."""
    from rich.markup import escape

    return escape(shown(text, limit))


_REPR = reprlib.Repr()
_REPR.maxstring = _REPR.maxother = 60
_REPR.maxlist = _REPR.maxtuple = _REPR.maxdict = _REPR.maxset = 6
_REPR.maxlevel = 3


def brief(value: Any, limit: int = 60) -> str:
    """A short repr of any value for a message: bounded work and length whatever its size
    (a YAML alias bomb, a 30,000-character name), control characters escaped."""
    if isinstance(value, str):
        return repr(value) if len(value) <= limit else repr(value[:limit - 1])[:-1] + "…'"
    if isinstance(value, int) and not isinstance(value, bool) and value.bit_length() > 3 * limit:
        # repr of an integer past Python's 4300 digits raises; past `limit` it is cut anyway
        return f"{'-' if value < 0 else ''}an integer of {int(value.bit_length() * 0.30103) + 1} digits"
    try:
        return shown(_REPR.repr(value), limit)
    except ValueError:                          # an integer too long to write, deeper inside
        return f"a {type(value).__name__} too large to show"


def names(items: Any, limit: int = 12) -> str:
    """Names joined by commas for a message: at most `limit` of them, then how many more."""
    items = list(items)
    head = ", ".join(shown(n, 40) for n in items[:limit])
    more = len(items) - limit
    return head + (f", … ({more} more)" if more > 0 else "")
