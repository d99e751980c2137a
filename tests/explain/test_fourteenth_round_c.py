"""Issue 30, fourteenth round (c): the Catalan and Basque prose a teacher still edited on
main's pages after the thirteenth round, each a rule checked over the seeds and the four
languages where it applies (each test fails on main's pages as the teacher graded them):

1. Basque word order for the line a centre lies on ("*ezkerreko gurpilarekin* mugitzen da,
   zeina J puntuaren inguruan biratzen baita" -> "J puntuaren inguruan biratzen den
   *ezkerreko gurpilarekin* mugitzen da"), and one rule for "solidoa" after a name;
2. a centre placed from one velocity says its side, nothing more (no "on the side the sense
   of ω gives", no values in brackets), and the carried centre's line no bracket;
3. said once: a held pin's sentence (the Data's, not again in the step), the geometric
   contact point's "belongs to neither";
4. C5-1.4's planet centre as its distance from A1 where it is found; C5-1.5's third
   pulley's centre before the block's step;
5. equiprojectivity with positive numbers (never (−a) / (−1)); the centre-on-axle sentence short;
6. the model's words: E.1's arm OC, E.5's flat ground, E.6's wheelbase e and plater pedalduna;
7. a caption naming one point once (the velocity of A and its drag velocity).
"""
from __future__ import annotations

import re

import pytest
import sympy

from .helpers import LANGS, SEEDS, explained, rendered, over
from .test_thirteenth_round_c import repeats


def _prose(text: str) -> str:
    """The page without its tables (a table's column says "solidoa" by itself)."""
    return "\n".join(line for line in text.splitlines() if not line.startswith("|"))


# ---- 1. Basque word order; one rule for "solidoa" -----------------------------------------

@over(name=SEEDS)
def test_basque_has_no_relative_clause_calque(name):
    """"…, zeina X puntuaren inguruan biratzen baita" and "…, zeinean zehar irristatzen baita"
    are Romance relative clauses in Basque words; Basque puts the relative before its noun."""
    text = rendered(name, "eu", "md", drawings=False)
    assert not re.search(r"\bzeina(k|n|ren|rekin)?\b|\bzeinean\b", text), name


@pytest.mark.parametrize("name,said", [
    ("seed_c5_e3_wheels_with_rod", "(A puntua J puntuaren inguruan biratzen den *ezkerreko gurpilarekin* mugitzen da)"),
    # a rolling contact gives the no-slip reason (twentieth round (g)), the strand declined
    ("seed_c5_1_1_pulley_on_cable", "(*polea* ez da irristatzen *eskuineko kable-zatiaren* gainean: *polearen* K "
                                    "puntuak *eskuineko kable-zatiaren* abiadura du, eta *eskuineko "
                                    "kable-zatia* G2 puntuaren inguruan biratzen da)"),
    ("seed_c5_1_2_bar_on_inclined_wheels", "J puntuan, *lurraren* zuzenarekiko normala (J puntua zuzen horretan zehar irristatzen da)"),
])
def test_basque_centre_lines_by_hand(name, said):
    """The teacher's sentences (C5-E.3, C5-1.1: the second strand declined as the first;
    C5-1.2: the slide along the ground's line said as its own clause)."""
    assert said in rendered(name, "eu", "md", drawings=False)


@over(name=SEEDS)
def test_basque_solidoa_only_where_the_name_cannot_decline(name):
    """A body's name that ends in the article -a takes the case ending itself everywhere
    (*polearen*, *kable-zatiarekin*): never "*eskuineko kable-zatia* solidoarekin" beside
    "*ezkerreko kable-zatiarekin*" in one sentence; a plural name goes in the genitive
    plural before the word (*gurpilen* solidoa), never "*gurpilak* solidoarenak"."""
    text = _prose(rendered(name, "eu", "md", drawings=False))
    assert not re.search(r"\*[^*\n]*a\* solidoa", text), re.search(r"\*[^*\n]*a\* solidoa[a-z]*", text)
    assert not re.search(r"\*[^*\n]*ak\* solidoa", text)


def test_basque_plural_body_in_the_genitive():
    text = rendered("seed_c5_e1_cavity", "eu", "md", drawings=False)
    assert "J puntua *gurpilen* solidoaren biraketa-zentro instantaneoa da" in text   # the CIR section's centre (17a)
    assert "*Gurpilen* solidoa irristatu gabe errodatzen da *pista zilindrikoaren* gainean" in text


# ---- 2. the side alone ----------------------------------------------------------------------

OLD_SIDE_LEAD = ("on the side the sense of", "del lado que da el sentido de", "del costat que dona el sentit de",
                 "noranzkoak ematen duen aldean")
OLD_CARRIED = ("(it passes through the points they turn about)", "(pasa por los puntos alrededor de los cuales giran)",
               "(passa pels punts al voltant dels quals giren)", "(zuzen hori biratzen diren puntuetatik pasatzen da)")


@over(name=SEEDS, lang=LANGS)
def test_a_centre_says_its_side_and_nothing_more(name, lang):
    text = rendered(name, lang, "md", drawings=False)
    assert not any(x in text for x in OLD_SIDE_LEAD + OLD_CARRIED), name
    assert not re.search(r"\((with|con|amb) v_\S+ = \(", text)
    assert not re.search(r"\(v_\S+ = \([^()]*\) eta ω\S* = [^()]* izanik\)", text)


@pytest.mark.parametrize("lang,said", [
    ("ca", "= √17·r d’A, per sobre i a la dreta d’A, de manera que el CIR és a (8·r; 2·r)."),
    ("en", "= √17·r from A, above and to the right of A, so the instant centre is at (8·r, 2·r)."),
    ("eu", "= √17·r distantziara, A puntuaren gainean eta eskuinean; beraz, BZIa (8·r; 2·r) puntuan."),
])
def test_the_belts_centre_by_hand(lang, said):
    """C5-1.6: ω = −ω k, v_A = (−rω, 4rω): AI = ω × v_A / ω² = (4r, r), above and right of
    A = (4r, r), |AI| = √17 r, I = (8r, 2r)."""
    assert said in rendered("seed_c5_1_6_belt", lang, "md", drawings=False)


# ---- 3. said once ---------------------------------------------------------------------------

@over(name=SEEDS, lang=LANGS)
def test_no_sentence_of_the_data_said_again_in_a_step(name, lang):
    """The thirteenth round's repeat check without its exemption for the Data: a datum's
    sentence is said once (a step may recall a datum as "Given: symbol = value")."""
    page = rendered(name, lang, "md", drawings=False)
    found = [(a, b) for a, b in repeats(page) if not a.startswith(("Given:", "Dato:", "Dada:", "Datua:"))]
    assert found == [], found


def test_the_repeat_check_finds_the_held_pin_twice():
    old = ("## Dades\n\nEn aquest instant la *forquilla davantera* no gira respecte del *xassís* a "
           "l’articulació F: δ̇ = 0.\n\n## Velocitats\n\nEn aquest instant la *forquilla davantera* no gira "
           "respecte del *xassís* a l’articulació F: δ̇ = 0.\n")
    assert repeats(old)


HELD = {"en": "does not turn relative to", "es": "no gira respecto", "ca": "no gira respecte", "eu": "ez da biratzen"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_held_pin_said_once(lang):
    """C5-2.1: the steering held, δ̇ = 0, said in the Data; step 1's composition recalls it
    by its symbol (ω_fork = ψ̇ + δ̇ = ψ̇ + 0)."""
    text = rendered("seed_c5_2_1_tricycle", lang, "md", drawings=False)
    held = [line for line in text.splitlines() if HELD[lang] in line and line.endswith("δ̇ = 0.")]
    assert len(held) == 1, held
    assert re.search(r"^ω_\S+ = ψ̇ \+ δ̇ = ψ̇ \+ 0 = ", text, re.M)


NEITHER = {"en": ("neither", "belongs to neither"), "es": ("ninguno de los dos", "no pertenece a ninguno"),
           "ca": ("cap dels dos", "no pertany a cap"), "eu": ("ez batena ez bestearena", "batena ere")}


@pytest.mark.parametrize("lang", LANGS)
def test_the_geometric_point_belongs_to_neither_said_once(lang):
    """C5-1.8: "que no pertany a cap dels dos", then "no pertany a cap dels dos sòlids:" two
    paragraphs below; said once, where the three points are introduced."""
    text = rendered("seed_c5_1_8_contact_points", lang, "md", drawings=False)
    word, _ = NEITHER[lang]
    assert len(re.findall(word, text)) == 1, lang
    if lang == "eu":
        assert "ez dena ez batena ez bestearena" in text and "ez baita ez batena" not in text


# ---- 4. asked centres as the notes give them --------------------------------------------------

def test_the_planets_centre_where_it_is_found_by_hand():
    """C5-1.4: A1 = (0, −2r) moves with the carrier at v = ω × OA1 = (2rω, 0); N = (0, −3r)
    with the ring at (−3rω, 0); v is linear along x = 0 and vanishes 2/5 of the way from
    A1 to N: I = (0, −12r/5), at 2r/5 from A1, the notes' "(2/5)r del centre"."""
    r, w = sympy.symbols("r omega", positive=True)
    y = sympy.Symbol("y")
    v = 2 * r * w + (y + 2 * r) * (-3 * r * w - 2 * r * w) / (-r)     # linear from A1 (y = −2r) to N (y = −3r)
    root = sympy.solve(sympy.Eq(v, 0), y)[0]
    assert sympy.simplify(root + sympy.Rational(12, 5) * r) == 0
    assert sympy.simplify(abs(root - (-2 * r)) - 2 * r / 5) == 0
    ca = rendered("seed_c5_1_4_epicyclic", "ca", "md", drawings=False)
    assert "on la velocitat s’anul·la, a 2·r/5 d’A1: a (0; −12·r/5)." in ca
    eu = rendered("seed_c5_1_4_epicyclic", "eu", "md", drawings=False)
    assert "abiadura nulua den tokian, A1 puntutik 2·r/5 distantziara: (0; −12·r/5) puntuan." in eu
    assert "distància d’A1 = 2·r/5" in ca             # the answers read the same note


STEP4 = {"en": "### Step 4", "es": "### Paso 4", "ca": "### Pas 4", "eu": "### 4. urratsa"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_third_pulleys_centre_before_the_block(lang):
    """C5-1.5, the notes' order: T4 rises at 2v and C3 falls at 2v, so the third pulley's
    centre is their midpoint, r/2 from C3 ("el CIR d'aquesta politja estarà en el punt mig");
    from there the block's speed. The centre's paragraph comes before step 4."""
    text = rendered("seed_c5_1_5_pulley_block", lang, "md", drawings=False)
    centre = re.search(r"^I_\S*3\S*: ", text, re.M)
    assert centre is not None and centre.start() < text.index(STEP4[lang])


# ---- 5. equiprojectivity with positive numbers -------------------------------------------------

@over(name=SEEDS, lang=LANGS)
def test_no_quotient_of_two_negatives(name, lang):
    text = rendered(name, lang, "md", drawings=False)
    assert not re.search(r"\(−[^()]*\) / \(−", text), name


@pytest.mark.parametrize("lang", LANGS)
def test_the_centre_on_the_axle_is_one_short_sentence(lang):
    """Said once: no sentence of its own repeats what the centre's sentence says of the axle
    (fifteenth round (a) put it inside the centre's sentence, test_c5_2_2_road)."""
    text = rendered("seed_c5_2_2_articulated", lang, "md", drawings=False)
    lines = [x for x in text.splitlines() if "C3" in x and "v_O" in x and "v_P" in x and "PO/|PO|" not in x]
    assert len(lines) == 1, lines


# ---- 6. the model's words --------------------------------------------------------------------

# E.1's arm, E.5's flat ground, E.6's wheelbase e and Basque plater: tests/explain/test_teacher.py's
# test_the_notes_grammar (one table of wrong and right words).


# ---- 7. a caption names one point once --------------------------------------------------------

CAPTION = {"en": "the arrows are the velocity of A and its drag velocity (v_{drag,A})",
           "es": "las flechas son la velocidad de A y su velocidad de arrastre (v_{arr,A})",
           "ca": "les fletxes són la velocitat d’A i la seva velocitat d’arrossegament (v_{ar,A})",
           "eu": "geziak A puntuaren abiadura eta arrastre-abiadura (v_{arr,A}) dira"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_rolling_pairs_caption_names_a_once(lang):
    assert CAPTION[lang] in rendered("seed_001_rolling_pair", lang, "md", drawings=True)


@over(name=SEEDS, lang=LANGS)
def test_no_caption_lists_a_point_twice(name, lang):
    """"geziak A eta A (…) puntuen abiadurak dira": a list of points with one point twice."""
    text = rendered(name, lang, "md", drawings=True)
    for caption in (x for x in text.splitlines() if x.startswith("*") and x.endswith("*")):
        assert not re.search(r"\b([A-Z][A-Z0-9]*) (eta|and|y|i) (de |d’|the drag velocity of )?\1\b", caption), caption
        assert not re.search(r"\bde ([A-Z][A-Z0-9]*) i d’arrossegament de \1\b", caption), caption


def test_the_planets_note_matches_the_solver():
    """The distance the page says is the solver's: |I − A1| for the centre the engine finds."""
    sol, doc = explained("seed_c5_1_4_epicyclic")
    from kinematika.explain.document import CentreNote

    from kinematika.explain.document import Section

    def leaves(blocks: list) -> list:       # the note stands in a velocity step (round 20e)
        return [x for b in blocks for x in (leaves(b.blocks) if isinstance(b, Section) else [b])]

    notes = [b for b in leaves(doc.sections) if isinstance(b, CentreNote) and b.near]
    # each planet's centre from its own axle (round 27b: the three planets placed alike)
    assert sorted((n.pair[1], n.near) for n in notes) == [("planet1", "A1"), ("planet2", "A2"), ("planet3", "A3")]
