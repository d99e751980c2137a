"""Renderers of an explanation: Markdown, HTML and LaTeX."""
from __future__ import annotations

from ...errors import KinematikaError
from ...text import shown_lines
from ..catalogue import catalogue
from ..document import Document
from .base import Renderer
from .html import HtmlRenderer
from .latex import LatexRenderer
from .markdown import MarkdownRenderer

FORMATS: dict[str, type[Renderer]] = {"md": MarkdownRenderer, "html": HtmlRenderer, "tex": LatexRenderer}


def render(doc: Document, lang: str = "en", fmt: str = "md", drawings: bool = True) -> str:
    """The document as text in `lang` (en, es, ca, eu) and `fmt` (md, html, tex);
    `drawings=False` leaves out the `draw` figures (quick, for checking the text). Control
    characters in the model's names come out escaped (``\\x1b``), as everywhere names are shown."""
    if fmt not in FORMATS:
        raise KinematikaError("schema", "unknown-format", "--format", format=fmt, formats=list(FORMATS))
    return shown_lines(FORMATS[fmt](doc, catalogue(lang), drawings).render())
