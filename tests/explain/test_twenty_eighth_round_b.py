"""Issue 30, twenty-eighth round (b): two teachers' items (docs/explain.md, "Twenty-eighth
round (b)").

- No seed names a point with a letter of the notes' marks M and D: "v_D" under a mark "D"
  read badly, and the sentence "… it is not the point D" read as a patch. The notes name no
  point D or M on these pages (seed 002): C5-1.1's lowest point of the pulley is unnamed
  there, now P (the notes' letter for the point asked about); C5-2.1's middle of the rear
  axle is unnamed there, now P (C5-2.2 calls an axle's middle P: "punt mig de l'eix (punt
  P)"); C5-E.5's centre of wheel 1 is the notes' C ("v_T(CIR ≡ I) = v_T(C) + Ω^roda1 × CI").
  A user's model that names a point M or D still gets the sentence.
- A symbolic page's polygon is drawn at the values given under it, so its scale bar reads as
  a numeric page's: a round number with its unit, "0.5 m/s", "5 m/s²" (not "|a_P|/5" or
  "r₁·v²/(5·r₂²)"), in the language's decimal sign, and it measures the polygon: an arrow
  as long as n bars is n times the bar's value.
"""
from __future__ import annotations

import math
import re

import kinematika
from kinematika.explain import build, render

from .helpers import LANGS, SEEDS, explained, model_tree, over, rendered
from .test_twenty_fourth_round_e import ONE

# the sentence after the legend for a letter that is also a point of the page (24th round (e))
CLASH = re.compile(r"not the points? |no es el punto |no és el punt |ez da [MD] puntua|no son los puntos "
                   r"|no són els punts |ez dira M eta D puntuak")


# ---- no seed point is called M or D ---------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_no_seed_point_is_named_as_a_mark(name, lang):
    """No seed's point or contact is M or D, so no seed page needs the "not the point"
    sentence (C5-1.1's and C5-E.5's D, C5-2.1's M before)."""
    sol, doc = explained(name)
    points = set(sol.model.points) | set(doc.joints.values())
    assert not points & {"M", "D"}, points & {"M", "D"}
    assert not CLASH.search(rendered(name, lang, drawings=False))


def test_the_pulleys_lowest_point_is_p():
    """C5-1.1: the lowest point of the pulley (radius r, centre C at the origin) is P = (0, −r);
    the pulley turns about I = (0, −2r) at ω = −v/(2r), so v_P = ω k × (P − I) = ω k × (0, r)
    = (−ω r, 0) = (v/2, 0), the page's answer v_P."""
    sol, _ = explained("seed_c5_1_1_pulley_on_cable")
    assert "P" in sol.model.points and "pulley" in sol.model.carriers("P")
    md = rendered("seed_c5_1_1_pulley_on_cable", "en", drawings=False)
    assert "| P | lowest point of the *pulley* | (0, −r) |" in md
    assert "| v_P | (v/2, 0) |" in md


def test_the_tricycles_axle_middle_is_p():
    """C5-2.1: the middle of the rear axle, half-way between the wheels' centres C1 = (0, s)
    and C2 = (0, −s), is P = (0, 0), a point of the chassis (Catalan writes (0; 0))."""
    sol, _ = explained("seed_c5_2_1_tricycle")
    assert "P" in sol.model.points and "chassis" in sol.model.carriers("P")
    for lang, said in (("en", "| P | middle of the rear axle | (0, 0) |"),
                       ("ca", "| P | punt mig de l’eix posterior | (0; 0) |")):
        assert said in rendered("seed_c5_2_1_tricycle", lang, drawings=False)


def test_the_centre_of_wheel_1_is_the_notes_c():
    """C5-E.5: the notes find wheel 1's instant centre from its centre C: 0 = v + (v/r₁) k ×
    CI ⇒ CI = r₁ upwards. Wheel 1 (radius r₁) sits on wheel R (radius R, centre at height R),
    so C = (0, 2R + r₁), and the page finds the centre r₁ above C."""
    sol, _ = explained("seed_c5_e5_unequal_wheels")
    assert "C" in sol.model.points and "wheel1" in sol.model.carriers("C")
    md = rendered("seed_c5_e5_unequal_wheels", "en", drawings=False)
    assert "| C | centre of *wheel 1* | (0, 2·R + r₁) |" in md
    assert "= r₁ from C, above C, so the instant centre is at (0, 2·(R + r₁))" in md


def _renamed(tree, old: str, new: str):
    """A model tree with point `old` called `new` everywhere it is named whole (a key, a list
    item, a value: never inside a formula)."""
    if isinstance(tree, dict):
        return {(new if k == old else k): _renamed(v, old, new) for k, v in tree.items()}
    if isinstance(tree, list):
        return [_renamed(v, old, new) for v in tree]
    return new if tree == old else tree


def test_a_users_point_named_d_or_m_still_gets_the_sentence():
    """The rule stays for a user's model: the pulley with its lowest point called D, the
    tricycle with its axle's middle called M, say after the legend that the letter is the
    mark, not the point, in every language."""
    for name, letter in (("seed_c5_1_1_pulley_on_cable", "D"), ("seed_c5_2_1_tricycle", "M")):
        tree = _renamed(model_tree(name), "P", letter)
        doc = build(kinematika.solve(tree))
        assert doc.worded_marks == (letter,)
        for lang in LANGS:
            assert ONE[lang][letter] in render(doc, lang, "md", drawings=False), (name, lang)


# ---- scale bars read as numbers with their units --------------------------------------------
SVG = re.compile(r"<svg xmlns=.*?</svg>", re.S)
BAR = re.compile(r'<line x1="([0-9.]+)" y1="([0-9.]+)" x2="([0-9.]+)" y2="\2" stroke="#222" stroke-width="2"/>'
                 r'.*?<text x="[0-9.]+" y="[0-9.]+" fill="#222">(.*?)</text>', re.S)
ARROW = re.compile(r'<line x1="([-0-9.]+)" y1="([-0-9.]+)" x2="([-0-9.]+)" y2="([-0-9.]+)" stroke="#[0-9a-fA-F]+" '
                   r'stroke-width="(?:2\.2|1\.8)" marker-end=')
UNIT = {"speed": "m/s", "accel": "m/s²"}


def _bars(page: str) -> list[tuple[str, float, list[float]]]:
    """Each polygon of an HTML page: its bar's text, the bar's length and its arrows' lengths
    (points)."""
    out = []
    for fig in SVG.findall(page):
        bar = BAR.search(fig)
        if bar is None:
            continue
        arrows = [math.hypot(float(x2) - float(x1), float(y2) - float(y1)) for x1, y1, x2, y2 in ARROW.findall(fig)]
        out.append((bar.group(4), float(bar.group(3)) - float(bar.group(1)), arrows))
    return out


@over(name=SEEDS, lang=LANGS)
def test_every_polygons_bar_is_a_number_with_its_unit(name, lang):
    """Symbolic or numeric, a polygon's bar reads "0.5 m/s" ("0,5 m/s" in es, ca, eu) or
    "5 m/s²": a round number and the unit, no symbol."""
    _, doc = explained(name)
    sign = "." if lang == "en" else ","
    for text, _, _ in _bars(rendered(name, lang, "html")):
        assert re.fullmatch(rf"[0-9]+(?:{re.escape(sign)}[0-9]+)? m/s²?", text), (text, doc.symbolic)


def test_the_bar_measures_the_symbolic_polygon():
    """The bar is a scale a student uses at the values under the figure. C5-E.4 (R = 0.25,
    v = 2): the top point's acceleration a_P = v²/R = 16 m/s² (the notes' answer) is the
    acceleration polygon's longest arrow; C5-1.1 (r = 0.1, v = 1): the centre moves at
    v = 1 m/s and the lowest point at v/2 = 0.5 m/s. Each is as many bars long as its value
    over the bar's."""
    for name, unit, wanted in (("seed_c5_e4_upper_wheel", "m/s²", [16.0]),
                               ("seed_c5_1_1_pulley_on_cable", "m/s", [1.0, 0.5])):
        assert explained(name)[1].symbolic
        for lang in ("en", "eu"):
            figs = [f for f in _bars(rendered(name, lang, "html")) if f[0].endswith(" " + unit)]
            assert figs, (name, lang)
            text, length, arrows = figs[-1]
            per = length / float(text.split()[0].replace(",", "."))         # points a unit
            for value in wanted:
                assert any(abs(a / per - value) <= 0.02 * value for a in arrows), (name, lang, value, [a / per for a in arrows])


def test_a_symbolic_tex_bar_has_its_unit():
    """LaTeX draws the same bars: a number and its unit, m/s under C5-E.5's velocity polygon,
    m/s² under its acceleration polygon (m under the mechanism drawn in TikZ). (C5-E.4's, read
    until the twenty-ninth round (d), lost its velocity polygon: a line of two arrows with four
    images at u, `polygon.degenerate`.)"""
    tex = rendered("seed_c5_e5_unequal_wheels", "en", "tex")
    bars = re.findall(r"\\draw\[\|-\|\][^\n]*node\[right\] \{(.*)\};", tex)
    assert any(b.endswith(" m/s") for b in bars) and any(b.endswith(" m/s$^2$") for b in bars), bars
    assert all(re.fullmatch(r"[0-9]+(?:\.[0-9]+)? m(?:/s(?:\$\^2\$)?)?", b) for b in bars), bars
