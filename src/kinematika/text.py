"""Names and messages made safe to show: shown as written, never interpreted.

A name in a model file is untrusted text. Printed raw, control characters drive the
terminal (``\\x1b]0;title\\x07`` sets the window title, ``\\x1b[2J`` clears the screen),
bidirectional overrides reorder what is read, a lone surrogate cannot be encoded, and
rich's markup (``[bold]``, ``[/]``) is read as formatting. Every view prints names through
`shown` (and `markup` where rich reads markup); `brief` bounds the text of any value put
into a message.
"""
from __future__ import annotations

import re
import reprlib
from typing import Any

# C0 and C1 controls, DEL, line and paragraph separators, bidirectional controls, surrogates
_UNSAFE = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069"
                     "\ud800-\udfff]")
_NAMED = {"\n": "\\n", "\r": "\\r", "\t": "\\t"}


def _escape(match: re.Match) -> str:
    c = match.group()
    if c in _NAMED:
        return _NAMED[c]
    code = ord(c)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def shown(text: Any, limit: int | None = None) -> str:
    """`text` as one printable line: control characters, separators, bidirectional controls
    and lone surrogates written as escapes (``\\x1b``, ``\\n``, ``\\ud800``); cut to `limit`
    characters with … when given."""
    text = text if isinstance(text, str) else str(text)
    if not text.isprintable():
        text = _UNSAFE.sub(_escape, text)
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
    return shown(_REPR.repr(value), limit)


def names(items: Any, limit: int = 12) -> str:
    """Names joined by commas for a message: at most `limit` of them, then how many more."""
    items = list(items)
    head = ", ".join(shown(n, 40) for n in items[:limit])
    more = len(items) - limit
    return head + (f", … ({more} more)" if more > 0 else "")
