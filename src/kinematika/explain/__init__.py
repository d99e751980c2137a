"""Step-by-step solutions in the textbook's method (the course notes' relative-motion
method, instant centres, composition of motions), in four languages.

    >>> from kinematika.explain import explain
    >>> html = explain("examples/four_bar.yaml", lang="eu", fmt="html")

The builder (`build`) arranges the solver's values into the notes' equations as a
language-free `Document`; `render` writes it as Markdown, HTML or LaTeX through the
message catalogues in `locales/`. Nothing here solves: every number is the solver's.
"""
from __future__ import annotations

from ..api import ModelLike, solve
from .builder import build
from .catalogue import LANGS
from .document import Document
from .render import FORMATS, render


def explain(source: ModelLike, lang: str = "en", fmt: str = "md", symbolic: bool | None = None,
            length_unit: str = "m") -> str:
    """Solve `source` and write its step-by-step solution."""
    return render(build(solve(source, symbolic), length_unit), lang, fmt)


__all__ = ["FORMATS", "LANGS", "Document", "build", "explain", "render"]
