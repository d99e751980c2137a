"""C5-2.2 (articulated vehicle) on the notes' road (issue 30): v_P by equiprojectivity written
as an equation a student redoes, S2's centre said against the notes' "perpendicular a la
velocitat de P i l'eix de les rodes", and ω′ in the notes' form ω/(2√2).

By hand (S1 along x at rω, S2 trailing at 45°, OP = a, P the midpoint of S2's axle):
OP/|OP| = (−1, −1)/√2, v_O · OP/|OP| = −rω/√2; P moves along S2's wheels, e = (1, 1)/√2,
e · OP/|OP| = −1, so |v_P| = (−rω/√2)/(−1) = rω/√2 and v_P = (rω/2, rω/2). P lies on S2's
axle and v_P ⊥ that axle, so the perpendicular to v_P through P IS the axle: the notes' two
lines are one, and the centre comes from the axle and the perpendicular to v_O through O,
I = (0, −√2 a). C4 is a/2 from I, ω_S2 = rω/(√2 a), v_C4 = rω/(2√2) = r ω′: ω′ = ω/(2√2)."""
from __future__ import annotations

import pytest
import sympy

from .helpers import LANGS, rendered

NAME = "seed_c5_2_2_articulated"

# the equation of equiprojectivity, with its numbers, in each language: along PO, the segment
# that makes e · u positive (fourteenth round: never (−√2·r·ω/2) / (−1)); by hand, v_O =
# (rω, 0), u = PO/|PO| = (1, 1)/√2, v_O · u = rω/√2, the wheel's plane along (1, 1)/√2 = u: v_P is
# along PO (twentieth round (a): said as the line, v_P = |v_P| PO/|PO|), so |v_P| = rω/√2
EQUATION = {
    "en": ("v_P · PO/|PO| = v_O · PO/|PO|, with PO/|PO| = (√2/2, √2/2), so that v_O · PO/|PO| = √2·r·ω/2",
           "v_P = |v_P| PO/|PO|.", "|v_P| = √2·r·ω/2 = r·ω/√2"),
    "es": ("v_P · PO/|PO| = v_O · PO/|PO|, con PO/|PO| = (√2/2; √2/2), de modo que v_O · PO/|PO| = √2·r·ω/2",
           "v_P = |v_P| PO/|PO|.", "|v_P| = √2·r·ω/2 = r·ω/√2"),
    "ca": ("v_P · PO/|PO| = v_O · PO/|PO|, amb PO/|PO| = (√2/2; √2/2), de manera que v_O · PO/|PO| = √2·r·ω/2",
           "v_P = |v_P| PO/|PO|.", "|v_P| = √2·r·ω/2 = r·ω/√2"),
    "eu": ("v_P · PO/|PO| = v_O · PO/|PO|, non PO/|PO| = (√2/2; √2/2); beraz, v_O · PO/|PO| = √2·r·ω/2",
           "v_P = |v_P| PO/|PO|.", "|v_P| = √2·r·ω/2 = r·ω/√2"),
}

# why the perpendicular to v_P does not place the centre (it is the axle), then the centre
ON_AXLE = {      # fifteenth round (a): said once, inside the centre's sentence
    "en": ("which is also the perpendicular to v_P through P", "the perpendicular to v_O at O",
           "The instant centre of the *chassis S2*"),
    "es": ("que es también la perpendicular a v_P por P", "la perpendicular a v_O por el punto O",
           "El CIR del *chasis S2*"),
    "ca": ("que és també la perpendicular a v_P per P", "la perpendicular a v_O pel punt O",
           "El CIR del *xassís S2*"),
    "eu": ("P puntuan v_P abiadurarekiko perpendikularra ere badena",
           "v_O abiadurarekiko perpendikularra O puntuan", "*S2 txasisaren* biraketa-zentro instantaneoa"),   # 28 e
}


@pytest.mark.parametrize("lang", LANGS)
def test_v_p_by_equiprojectivity_is_an_equation_to_redo(lang):
    page = rendered(NAME, lang, drawings=False)
    for part in EQUATION[lang]:
        assert part in page, part


@pytest.mark.parametrize("lang", LANGS)
def test_the_centre_says_why_the_perpendicular_to_v_p_is_not_the_second_line(lang):
    page = rendered(NAME, lang, drawings=False)
    said, second, centre = ON_AXLE[lang]
    sentence = next(line for line in page.splitlines() if line.startswith(centre))
    assert said in sentence and second in sentence, sentence
    assert page.count(said) == 1 and page.index("v_P · PO/|PO|") < page.index(sentence)


@pytest.mark.parametrize("lang", LANGS)
def test_the_spin_is_written_as_the_notes_write_it(lang):
    page = rendered(NAME, lang, drawings=False)
    assert "ω′ = |v_C4| / r = √2·ω/4 = ω/(2√2)" in page   # r a symbol (fourteenth round), |v| (sixteenth)
    assert "| ω′ | √2·ω/4 = ω/(2√2) |" in page


def test_the_root_form_rule():
    """√n·x/k with k a multiple of n is x/((k/n)√n); nothing else is rewritten."""
    from kinematika.explain.render.base import root_form

    w, r, a = sympy.symbols("w r a", positive=True)
    assert root_form(sympy.sqrt(2) * w / 4) == (w, 2, 2)
    assert root_form(sympy.sqrt(2) * r * w / 2) == (r * w, 1, 2)
    assert root_form(-sympy.sqrt(2) * w / 4) == (-w, 2, 2)
    assert root_form(sympy.sqrt(3) * w / 6) == (w, 2, 3)
    assert root_form(sympy.sqrt(3) * w / 4) is None              # 4 is not a multiple of 3
    assert root_form(sympy.sqrt(2) * r * w / (2 * a)) is None    # a quotient of symbols: left as sympy writes it
    assert root_form(3 * sympy.sqrt(2) * w / 4) is None          # coefficient not 1/k
    assert root_form(w / 4) is None and root_form(sympy.sqrt(2) / 4) is None
