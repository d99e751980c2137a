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
               "dashed lines join its ends to the points it runs between.",
         "es": "Un término que quedaría sobre otra flecha se dibuja a su lado, paralelo y a escala; "
               "unas líneas discontinuas unen sus extremos con los puntos entre los que va.",
         "ca": "Un terme que quedaria sobre una altra fletxa es dibuixa al seu costat, paral·lel i a "
               "escala; unes línies discontínues uneixen els seus extrems amb els punts entre els quals va.",
         "eu": "Beste gezi baten gainean legokeen terminoa haren alboan marrazten da, paraleloan eta "
               "eskalan; marra etenek haren muturrak lotzen dituzte bere bi puntuekin."}


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


def _level_a(name: str) -> Figure:
    """The page's acceleration polygon (of the level)."""
    _, doc = explained(name)
    return next(f for f in _polygons(doc) if f.caption.key.startswith("fig.level_a"))


def test_the_cavity_draws_a_c_once():
    """C5-E.1: a_C is split twice, a_O + a_CO^n + a_CO^t in Step 1 (the arm OC about the
    fixed O) and a_C^t + a_C^n in Step 2 (the path's intrinsic components); C moves on a
    circle about O, so both splits are the same two vectors, and the figure drew the
    second half of one parallelogram, five labels round c. The polygon draws the terms of
    the arm (CO), of P (PC) and of the wheels' point at O (OC), and no second split of a_C."""
    fig = _level_a("seed_c5_e1_cavity")
    terms = sorted((a.label.sub, a.label.sup) for a in fig.arrows if a.style != "result")
    assert terms == [("CO", "n"), ("CO", "t"), ("OC", "n"), ("OC", "t"), ("PC", "n"), ("PC", "t")], terms


@over(name=SEEDS)
def test_no_image_is_lettered_with_a_prime_and_a_body(name):
    """o′ is O's image, primed because o is the pole; a body's point at O keeps its body and
    needs no prime (o∈wheels): C5-E.1 lettered "o′∈wheels" while its caption called o′ "the
    image of the fixed point O of the arm OC", at the pole: two points lettered o′."""
    _, doc = explained(name)
    for fig in _polygons(doc):
        for label, _, _ in fig.points:
            assert not any("′∈" in n for n in label.split(", ")), (fig.caption.key, label)


def test_the_cavity_letters_the_wheels_point_at_o_apart_from_o_prime():
    """C5-E.1: the wheels' point at O has its own image, v_{O∈wheels} = 6Rθ̇ along x (the
    wheels roll with ω = −2θ̇ about J, 3R below O), lettered o∈wheels; o′ is not lettered
    apart, being at the pole (v_O = 0)."""
    _, doc = explained("seed_c5_e1_cavity")
    fig = next(f for f in _polygons(doc) if f.caption.key.startswith("fig.level_v"))
    R, thetad = 0.1, 2.0                                    # the page's draw_at
    images = {n: p for label, p, _ in fig.points for n in label.split(", ")}
    assert "o∈wheels" in images and "o′" not in images, images
    x, y = images["o∈wheels"]
    assert math.isclose(abs(x), 6 * R * thetad, rel_tol=1e-6) and abs(y) < 1e-9, (x, y)


def test_the_rolling_pair_letters_f_in_r():
    """001's rolling pair: a_{F∈N} = a_A + a_FA^n + a_FA^t + a_{F∈N rel R}; the vertex after
    a_FA^t is a_{F∈R}, an answer, and had no letter. By hand (the fifth reading, en §4):
    a_{F∈R} = (0.625, −1.804) m/s²; the vertex is lettered f∈R, where a_FA^t ends."""
    fig = _level_a("seed_001_rolling_pair")
    images = {n: p for label, p, _ in fig.points for n in label.split(", ")}
    assert "f∈R" in images, sorted(images)
    x, y = images["f∈R"]
    assert math.isclose(x, 0.625, abs_tol=2e-3) and math.isclose(y, -1.804, abs_tol=2e-3), (x, y)
    ends = [a.end for a in fig.arrows if a.label is not None and (a.label.sub, a.label.sup) == ("FA", "t")]
    assert ends and all(math.dist(e, (x, y)) < 1e-9 for e in ends), ends


TOO_SHORT = {"en": "too short to be seen at this scale (shorter than an arrowhead)",
             "es": "para verse a esta escala (más cort",
             "ca": "per veure’s a aquesta escala (més curt",
             "eu": "laburregia"}
HEAD = 7.0                  # the arrowhead's length in its line's widths (the SVG's marker)
WIDTH = {"result": 2.2}     # blue arrows' width; the others' 1.8


@over(name=SEEDS, lang=LANGS)
def test_an_arrow_too_short_to_see_is_named_in_the_caption(name, lang):
    """An arrow shorter than its own arrowhead, as drawn, shows a head and no line (C5-E.4's
    a_U = −v̇ at the pole, 1/32 of a_P = v²/R at the drawn numbers; a_PU^t a stub at p): its
    caption says which arrows are too short to be seen, and no label is set beside such a
    term, where the labels of the short terms piled up (001's a_BA^t at the pole, C5-1.3's
    a_QS^n, a_EQ^n round q). An arrow that can be seen carries no such sentence."""
    rendered(name, lang, "html")                        # lays the figures out
    for fig, caption in _figure_captions(name, lang):
        ks = {round(lay.k, 9) for lay in fig.layouts.values()}
        assert len(ks) == 1, ks
        k = ks.pop()
        short = [a for a in fig.arrows if math.dist(a.start, a.end) * k < HEAD * WIDTH.get(a.style, 1.8)]
        assert (TOO_SHORT[lang] in caption) == bool(short), (fig.caption.key, len(short), caption[-250:])
        assert all(a.label is None for a in short), (fig.caption.key, [a.label for a in short])


def test_the_upper_wheel_names_a_u_and_a_pu_t():
    """C5-E.4, drawn since the twenty-ninth round (d) at R = 0.25, v = 2, v̇ = 8 (it was 0.5, and
    the caption named a_U and a_PU^t too short to be seen): a_U = (−v̇, 0) is 8 long and
    a_PU^t = α × UP is v̇ = 8 too (α = −v̇/R, UP = R), beside a_PU^n = v²/R = 16; every term
    shows, and the caption names none."""
    caption = next(c for f, c in _figure_captions("seed_c5_e4_upper_wheel", "en") if f.caption.key.startswith("fig.level_a"))
    assert "too short" not in caption and "v̇ = 8" in caption, caption
