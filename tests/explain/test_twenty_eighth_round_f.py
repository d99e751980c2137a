"""Issue 30, twenty-eighth round (f): the velocity and acceleration polygons as a teacher
draws them (the fifth reading: en item 1 and R2, es G1, ca R4, eu R1).

- A term that would lie on another arrow is drawn beside it and joined to its place by grey
  dashes; the captions said "head to tail" and never what the dashes were (001's revolute
  pairs fig. 3, the rolling pair, C5-1.3, C5-E.1 …). Every polygon with such dashes says so
  in its caption, in the four languages.
"""
from __future__ import annotations

import math

from kinematika.explain.document import Equation, Figure
from .helpers import LANGS, SEEDS, explained, over, rendered

POLYGONS = ("fig.level", "fig.step", "fig.polygon")

MOVED = {"en": "A term that would lie on another arrow is drawn beside it, parallel and to scale; "
               "grey dashes join its ends to the points it runs between.",
         "es": "Un término que quedaría sobre otra flecha se dibuja a su lado, paralelo y a escala; "
               "unos trazos grises unen sus extremos con los puntos entre los que va.",
         "ca": "Un terme que quedaria sobre una altra fletxa es dibuixa al seu costat, paral·lel i a "
               "escala; uns traços grisos uneixen els seus extrems amb els punts entre els quals va.",
         "eu": "Beste gezi baten gainean legokeen terminoa haren alboan marrazten da, paraleloan eta "
               "eskalan; marra eten grisek haren muturrak lotzen dituzte bere bi puntuekin."}


def _polygons(doc) -> list[Figure]:
    """The page's polygons in page order: the levels' and steps' figures, and an equation's
    own (composition of motions: `Equation.polygon`, drawn after it)."""
    out = []
    for b in doc.blocks():
        fig = b.polygon if isinstance(b, Equation) else b
        if isinstance(fig, Figure) and fig.arrows and fig.caption.key.startswith(POLYGONS):
            out.append(fig)
    return out


POLYGON_WORD = {"en": "polygon", "es": "polígono", "ca": "polígon", "eu": "poligono"}


def _captions(page: str, lang: str) -> list[str]:
    """The polygons' captions of a Markdown page, in order (each an italic paragraph after
    its figure, whose first words name the polygon)."""
    lines = page.splitlines()
    return [lines[i + 2] for i, line in enumerate(lines[:-2]) if line.startswith("![")
            and lines[i + 2].startswith("*") and POLYGON_WORD[lang] in lines[i + 2][:40].lower()]


def _figure_captions(name: str, lang: str) -> list[tuple[Figure, str]]:
    """Each polygon of the page with its caption as printed (figures numbered in page order)."""
    _, doc = explained(name)
    figures = _polygons(doc)
    captions = _captions(rendered(name, lang, "md"), lang)
    assert len(captions) == len(figures), (len(captions), len(figures))
    return list(zip(figures, captions))


def _moved_terms(fig: Figure) -> list:
    """The terms drawn away from their place: an arrow both of whose ends a dashed line
    leaves (a join runs from where the term's end was to where it is drawn)."""
    ends = {p for line in fig.lines for p in line}
    return [a for a in fig.arrows if a.start in ends and a.end in ends]


@over(name=SEEDS, lang=LANGS)
def test_a_polygon_with_dashes_says_what_they_are(name, lang):
    """A polygon whose terms are drawn beside their place, joined by grey dashes, says so in
    its caption; one with no dashes does not."""
    for fig, caption in _figure_captions(name, lang):
        moved = _moved_terms(fig)
        assert bool(moved) == bool(fig.lines), (fig.caption.key, len(moved), len(fig.lines))
        assert (MOVED[lang] in caption) == bool(fig.lines), (fig.caption.key, caption[-200:])
