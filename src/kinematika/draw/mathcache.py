"""matplotlib's mathtext layouts kept for the whole process, not for one figure.

matplotlib caches a parsed formula (`MathTextParser._parse_cached`, 50 entries) per parser
object, and every renderer makes parsers of its own (`TextToPath`, one per SVG figure), so a
figure never reuses another's layouts: drawing an explanation's three figures parses its
labels ($\\vec{v}_{A}$ …) again in each, and a class's set of 60 worked solutions parses the
same few hundred formulas 60 times (a quarter of the time of its figures). `shared()` keys the
cache by the parser's kind (vector or raster) instead of the parser object: the same formula,
dpi, font and flags give the same layout, whichever parser asks, so the figures are the same
bytes.
"""
from __future__ import annotations

import functools
from typing import Any

SIZE = 4096          # layouts kept (a set of 60 worked solutions needs about 600)
_PARSERS: dict[str, Any] = {}
ORIGINAL: Any = None     # matplotlib's own `_parse_cached` (undecorated), once shared


def shared() -> None:
    """Make every `MathTextParser` use one cache per kind of output (once per process)."""
    from matplotlib.mathtext import MathTextParser as parser_class

    MathTextParser: Any = parser_class          # its private cache is patched, untyped
    if getattr(MathTextParser, "_kinematika_shared", False):
        return
    parse = getattr(MathTextParser._parse_cached, "__wrapped__", None)
    if parse is None:            # another matplotlib: leave its cache as it is
        return
    global ORIGINAL
    ORIGINAL = parse

    @functools.lru_cache(SIZE)
    def layout(kind: str, s: str, dpi: float, prop: Any, antialiased: bool, flags: Any) -> Any:
        return parse(_PARSERS[kind], s, dpi, prop, antialiased, flags)

    def _parse_cached(self: Any, s: str, dpi: float, prop: Any, antialiased: bool, flags: Any) -> Any:
        _PARSERS.setdefault(self._output_type, self)
        return layout(self._output_type, s, dpi, prop, antialiased, flags)

    MathTextParser._parse_cached = _parse_cached
    MathTextParser._kinematika_shared = True
