"""Issue 30, fourteenth round (d): figures and captions the Catalan and Basque teacher read on
main (1b51ca8). Each test is a rule over the 19 seeds in the languages where it applies, and
fails on that output: a centres' caption promising "lines through two centres" no figure draws
(C5-2.1, C5-2.2), a polygon's caption promising relative velocities "(black)" it has none of,
a figure labelling −v(r₁ − r₂)/r₂ what the text writes v·(r₂ − r₁)/r₂ (C5-E.5), and a numeric
page's magnitudes (v_B = 11) with no unit."""
from __future__ import annotations

import base64
import functools
import re

import pytest

from kinematika.draw.build import build_scene
from kinematika.draw.options import DrawOptions
from kinematika.explain.document import Drawing, Equation, Figure

from .helpers import LANGS, SEEDS, SVG, explained, rendered, over

# how each language says a centres' line through two centres, and a polygon's terms between
# the images (the clause the polygon's caption gives only when it draws such a term)
TWO_CENTRES = {"en": "lines through two centres", "es": "rectas que pasan por dos centros",
               "ca": "rectes que passen per dos centres", "eu": "bi zentrotatik pasatzen diren zuzenak"}
BETWEEN = {"en": "between the images", "es": "entre las imágenes", "ca": "entre les imatges",
           "eu": "irudien artean"}
FIGURE_CAPTION = re.compile(r"^\*(.+)\*$", re.M)


def _captions(name: str, lang: str) -> list[str]:
    return FIGURE_CAPTION.findall(rendered(name, lang))


def _centres_drawing(name: str) -> Drawing | None:
    _, doc = explained(name)
    return next((b for b in doc.blocks() if isinstance(b, Drawing) and b.caption.key == "fig.centres"), None)


@pytest.mark.parametrize("name", SEEDS)
def test_centres_caption_promises_two_centre_lines_only_when_drawn(name: str) -> None:
    """The lines through two centres (Aronhold–Kennedy) are named in the caption exactly when
    the figure, drawn with the page's own options, has one: C5-2.1 and C5-2.2 draw only the
    wheels' perpendiculars and a pin velocity's perpendicular."""
    d = _centres_drawing(name)
    if d is None:
        pytest.skip("no centres' figure")
    sol, _ = explained(name)
    scene = build_scene(sol.inst, sol, DrawOptions(**d.options))
    drawn = any(k.key.startswith("kennedy:") for k in scene.kennedy)
    for lang in LANGS:
        said = any(TWO_CENTRES[lang] in c for c in _captions(name, lang))
        assert said == drawn, (name, lang, drawn)


def test_tricycle_caption_names_the_velocity_perpendicular() -> None:
    """C5-2.1: I_chassis on the rear wheels' axle and on the perpendicular to F's velocity —
    the caption names both lines, and no line through two centres."""
    caption = next(c for c in _captions("seed_c5_2_1_tricycle", "ca") if c.startswith("Els centres"))
    assert "les perpendiculars a les rodes" in caption
    assert "les perpendiculars a les velocitats dels punts" in caption
    assert TWO_CENTRES["ca"] not in caption


def _figures(name: str) -> list[Figure | Drawing]:
    """The page's figures, in the order it sets them (each with its caption)."""
    _, doc = explained(name)
    out: list[Figure | Drawing] = []
    for b in doc.blocks():
        if isinstance(b, (Figure, Drawing)):
            out.append(b)
        elif isinstance(b, Equation) and getattr(b, "polygon", None) is not None:
            out.append(b.polygon)            # a composition's own polygon, under its equation
    return out


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_polygon_caption_promises_terms_only_when_drawn(name: str, lang: str) -> None:
    """A level's or a step's polygon says "between the images, the relative velocities
    (black)" only when a black arrow (a term, not a point's absolute velocity) is drawn
    between images; the velocity polygons of C5-1.1, 1.2, 1.6, 1.7, 1.8, 2.1, 2.2 and E.3
    draw absolute velocities only."""
    figures = _figures(name)
    captions = _captions(name, lang)
    assert len(captions) == len(figures), (name, lang, captions)
    polygons = [(f, c) for f, c in zip(figures, captions)
                if isinstance(f, Figure) and f.caption.key.startswith(("fig.level", "fig.step"))]
    if not polygons:
        pytest.skip("no level's or step's polygon")
    for fig, caption in polygons:
        black = any(a.style != "result" for a in fig.arrows)
        assert (BETWEEN[lang] in caption) == black, (name, lang, fig.caption.key, black, caption)


def _labels(page: str) -> list[str]:
    return [c.strip() for b64 in SVG.findall(page)
            for c in re.findall(r"<!--(.*?)-->", base64.b64decode(b64).decode("utf-8"), re.S)]


@over(name=SEEDS)
def test_figure_formulas_never_lead_a_difference_with_its_minus(name: str) -> None:
    """A figure's formula label is written in the text's form: a difference of two terms with
    its positive term first and the product's minus taken into it — never "−v(r₁ − r₂)/r₂" or
    "(−r₁ + r₂)", which the text never writes."""
    for label in _labels(rendered(name, "ca")):
        assert r"\left(- " not in label, (name, label)
        assert not re.search(r"= \$- ?\\dfrac\{[^}]*\\left\(\w", label), (name, label)


def test_unequal_wheels_label_as_the_text() -> None:
    """C5-E.5: the text writes v_P = v·(r₂ − r₁)/r₂ (by hand: P at r₁ below the centre B of
    wheel 2, which rolls at J with ω = −v/r₂: v_P = v + ω·(r₂ − r₁)·… = v(r₂ − r₁)/r₂ along
    x); the figure labels the same form."""
    page = rendered("seed_c5_e5_unequal_wheels", "ca")
    assert "v·(r₂ − r₁)/r₂" in page
    label = next(x for x in _labels(page) if x.startswith(r"$v_{\mathrm{P}}$"))
    assert r"r_{2} - r_{1}" in label and r"r_{1} - r_{2}" not in label


@functools.lru_cache(maxsize=1)
def numeric() -> list[str]:
    """The seeds whose data are numbers (asked when a test runs, not at collection)."""
    return [n for n in SEEDS if not explained(n)[0].symbolic]


UNIT = {"en": "in m/s", "es": "en m/s", "ca": "en m/s", "eu": "(m/s-tan)"}


@over(name=numeric, lang=LANGS)
def test_numeric_magnitudes_have_their_unit(name: str, lang: str) -> None:
    """A numeric page's mechanism figure writes magnitudes (v_B = 11); its caption gives
    their unit once, as the text gives every value's."""
    caption = _captions(name, lang)[0]
    assert UNIT[lang] in caption, (name, lang, caption)


@over(name=lambda: [n for n in SEEDS if n not in numeric()])
def test_symbolic_captions_add_no_unit(name: str) -> None:
    """A symbolic page's labels are formulas of its symbols: no unit is added to its caption."""
    assert "m/s" not in _captions(name, "en")[0]
