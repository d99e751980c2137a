"""Step-by-step solutions in the textbook's method (the course notes' relative-motion
method, instant centres, composition of motions), in four languages.

    >>> from kinematika.explain import explain
    >>> html = explain("examples/four_bar.yaml", lang="eu", fmt="html")

The builder (`build`) arranges the solver's values into the notes' equations as a
language-free `Document`; `render` writes it as Markdown, HTML or LaTeX through the
message catalogues in `locales/`. Nothing here solves: every number is the solver's (a
model given to `explain` is solved by the sweep layer, `sweep.posing`, first).
"""
from __future__ import annotations

from ..model.source import ModelLike
from ..solution import Solution
from ..sweep.posing import solved as solve
from .builder import build
from .catalogue import LANGS
from .document import Document
from .render import FORMATS, render


def explain(source: ModelLike, lang: str = "en", fmt: str = "md", symbolic: bool | None = None,
            length_unit: str = "m") -> str:
    """The step-by-step solution of `source` (a `Solution`, or a model, solved first)."""
    sol = source if isinstance(source, Solution) else solve(source, symbolic)
    return render(build(sol, length_unit), lang, fmt)


__all__ = ["FORMATS", "LANGS", "Document", "build", "explain", "render"]
