"""Issue 30, twenty-seventh round (g): notation, as a Basque teacher read every seed page
(/work/audit_q_eu R1–R4; the Catalan reader's "que troba el pas").

1. Template sentences that read oddly: "Ekuazio bektorial lau batek …" (lau reads as four),
   the centres' intro worded with one body, the symbolic Data's opening; ca "els termes
   marcats amb ?, que troba el pas".
2. The Basque slides write an acceleration's normal and tangential components a_BA^N and
   a_BA^T (and keep D for a direction so that N names the normal): one per-language notation
   for the equations, the lists of terms and the polygons' labels.
3. A body whose name has several words is written by a short index, declared once before
   its first use: ω_gurpila1 (*ezkerreko gurpila*), never v_{J∈ezkerreko kable-zatia}.
4. An instant centre is written one way on a page (Markdown): I_{polea}, CI_{polea},
   v_{CI_{polea}}, never I_polea beside I_{polea} and v_{C,I_polea}.
"""
from __future__ import annotations

import re

import numpy as np

from kinematika.explain.catalogue import catalogue
from kinematika.explain.render.markdown import MarkdownRenderer

from .helpers import LANGS, SEEDS, explained, model_tree, over, plain_page, recorded_pages, rendered

# ---- 1. the template sentences -------------------------------------------------------------------------------
V_INTRO = {"eu": "Planoko ekuazio bektorial batek bi ezezagun ebazten ditu: urrats bakoitzean ? ikurraz markatutako "
                 "terminoak.",
           "ca": "Una equació vectorial plana resol dues incògnites: el pas troba els termes marcats amb ?."}
OLD = {"eu": ("Ekuazio bektorial lau", "urratsak aurkitzen dituenak", "lagin-balio", "haien formula zehatza",
              "solido baten izenarekin ("),
       "ca": ("que troba el pas",)}


@over(name=SEEDS, lang=("eu", "ca"))
def test_g_template_sentences_read_as_a_teacher_writes(name: str, lang: str) -> None:
    """The velocities' first paragraph ends with the sentence on a plane equation's two
    unknowns as the teacher wrote it (eu: planoko, not lau, "four"); the Basque centres'
    intro states the rule for any body ("solido horren") and gives the page's first centre as
    its example; none of the old phrasings is left."""
    page = plain_page(name, lang)
    assert not [w for w in OLD[lang] if w in page], [w for w in OLD[lang] if w in page]
    if "?" in page and ("## Abiadurak" in page or "## Velocitats" in page):
        assert V_INTRO[lang] in page
    if lang == "eu" and "## Biraketa-zentro instantaneoak" in page and "I ikurrak, bi solidoren" not in page:
        intro = next(ln for ln in page.splitlines() if ln.startswith("I ikurrak,"))
        # relative to the page's fixed body: the ground, or the ceiling of a page with no floor (27th round (e))
        assert re.match(r"I ikurrak, solido baten izena azpiindize duela, solido horren biraketa-zentro "
                        r"instantaneoa \(BZI\) adierazten du \*([^*]+rekiko)\*, hau da, \*\1\* abiadura "
                        r"nulua duen puntua \(adibidez, I_\{", intro), intro


def test_g_the_symbolic_data_opening() -> None:
    """The symbolic pages' first Data sentence, as the Basque teacher would put it."""
    page = plain_page("seed_c5_1_1_pulley_on_cable", "eu")
    assert ("Datuak ikurrak dira eta emaitzak formula gisa ematen dira; irudiak ikurren balio jakin batzuekin "
            "marraztu dira, irudi bakoitzaren azpian emanak.") in page


# ---- 2. the components' superscripts -------------------------------------------------------------------------
COMPONENT = re.compile(r"\ba_(?:\{[^{}]*(?:\{[^{}]*\}[^{}]*)*\}|[^\s^{}]+)\^(\w+)")
SUPER = re.compile(r'baseline-shift="super"[^>]*>([^<]*)<')
SVG_DATA = re.compile(r"data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)")


@over(name=SEEDS, lang=LANGS)
def test_g_normal_and_tangential_superscripts_per_language(name: str, lang: str) -> None:
    """Every a_…^x in the text (equations, lists, the curvature section) and every superscript
    of the polygons' labels (SVG) is N or T in Basque, n or t in the other languages (the
    Catalan notes' a_T^n); a Basque page with accelerations writes at least one ^N."""
    import base64

    want = {"N", "T"} if lang == "eu" else {"n", "t"}
    text = plain_page(name, lang)
    written = set(COMPONENT.findall(text)) - {"geom"}
    assert written <= want, written
    page = rendered(name, lang, "md")
    drawn = {s for data in SVG_DATA.findall(page) for s in SUPER.findall(base64.b64decode(data).decode("utf-8"))}
    drawn -= {"geom", "2", "²"}
    assert drawn <= want, drawn
    if lang == "eu" and "## Azelerazioak" in text and "_{" in text and re.search(r"\^[NT]\b", text):
        assert "N" in written


def test_g_the_slides_r_pairs_by_hand() -> None:
    """Seed 001 (the Basque slides, 4.2): a_B = a_A + a_BA^N + a_BA^T, with |a_BA^N| = ω_N²·AB
    ∥ AB and a_BA^T ⊥ AB; the Catalan page keeps a_BA^n, a_BA^t."""
    eu, ca = plain_page("seed_001_r_pairs", "eu"), plain_page("seed_001_r_pairs", "ca")
    assert re.search(r"a_BA\^N +\+ +a_BA\^T", eu) and "a_BA^n" not in eu
    assert re.search(r"a_BA\^n +\+ +a_BA\^t", ca) and "a_BA^N" not in ca


# ---- 3. short indices, declared once --------------------------------------------------------------------------
SUBSCRIPT = re.compile(r"[ωαvaI]_\{([^{}]*)\}")
NOTATION = {"en": "Notation:", "es": "Notación:", "ca": "Notació:", "eu": "Notazioa:"}


def _labels(name: str, lang: str) -> dict[str, str]:
    _, doc = explained(name)
    order = sorted(doc.numbers, key=lambda b: doc.numbers[b])
    return doc.wording.labels(order, lang, tuple(getattr(doc, "parameters", ())))


@over(name=SEEDS, lang=LANGS)
def test_g_no_subscript_is_a_name_of_several_words(name: str, lang: str) -> None:
    """Every body's subscript is one word (ω_gurpila1, ω_{kable-zatia1}); in the text a
    subscript holds a space only around the word that joins a body to the one it is seen
    from (ω_{polea1 rel besoa}, v_{B∈N rel M})."""
    labels = _labels(name, lang)
    assert not [t for t in labels.values() if " " in t], labels
    _, doc = explained(name)
    rel = doc.wording.relative_word(lang)
    spaced = [s for s in SUBSCRIPT.findall(plain_page(name, lang)) if " " in s.replace(f" {rel} ", "")]
    assert not spaced, spaced[:4]


@over(name=SEEDS, lang=LANGS)
def test_g_a_shortened_index_is_declared_once_before_its_use(name: str, lang: str) -> None:
    """A body's index that a student cannot read off its name (gurpila1 for *ezkerreko
    gurpila*) is said in the page's one notation line, and that line stands before the
    first symbol that writes it (C5-E.3's Data "ω_gurpila1 = −ω", C5-2.1's Data v_{F∈furka}),
    but after the model's statement that writes one (C5-E.6's "r ω_pinoia = R ω_platera"):
    the statement is read whole, then its notation (twenty-eighth round (e))."""
    page = plain_page(name, lang)
    lines = [k for k, ln in enumerate(page.splitlines()) if ln.startswith(NOTATION[lang])]
    assert len(lines) <= 1, lines
    _, doc = explained(name)
    renderer = MarkdownRenderer(doc, catalogue(lang))
    spelt = doc.wording.bodies.get(lang, {})
    if not spelt:
        return
    at = page.index(NOTATION[lang]) if lines else len(page)
    for body, label in _labels(name, lang).items():
        if renderer._plain(body, label, spelt):
            continue
        used = re.search(rf"[ωαI]_\{{?{re.escape(label)}\b|∈{re.escape(label)}\b", page)
        if used is None:
            continue
        assert lines, (body, label)
        line = page.splitlines()[lines[0]]
        assert label in line, (label, line)
        if used.start() < at:           # read in the model's statement, the legend right after it (28 e)
            assert _in_statement(name, lang, page, used.start(), at), (label, page[used.start() - 60:used.start() + 20])


def _in_statement(name: str, lang: str, page: str, start: int, at: int) -> bool:
    """Whether the page's text from `start` to the notation line at `at` is the model's
    statement alone (`names.LANG.data`, its paragraphs' first words): the twenty-eighth round
    (e) reads the statement whole, then its notation (C5-E.6's "r ω_pinoia = R ω_platera")."""
    said = [" ".join(p.replace("*", "").split()[:4]) for p in
            (model_tree(name).get("names") or {}).get(lang, {}).get("data") or []]
    begin = page.rfind("\n\n", 0, start) + 2
    paragraphs = [p for p in page[begin:at].split("\n\n") if p.strip()]
    return bool(paragraphs) and all(any(p.replace("*", "").startswith(o) for o in said) for p in paragraphs)


def test_g_the_wheels_by_hand() -> None:
    """C5-1.2 and C5-E.3 by hand: the left and right wheels are wheel 1 and wheel 2 of the
    model (ezkerreko gurpila, eskuineko gurpila: gurpila1, gurpila2), the planes planoa1 and
    planoa2; C5-1.1's strands kable-zatia1 and kable-zatia2; each said once, where the page
    first needs it (E.3: in the Data, before "Datua: ω_gurpila1 = −ω")."""
    bar = plain_page("seed_c5_1_2_bar_on_inclined_wheels", "eu")
    assert "ω_gurpila1 = −|v_OK1| / K1O = −2,91 rad/s" in bar and "ω_gurpila2 = −|v_QK2| / K2Q = −2,91 rad/s" in bar
    assert "ω_{ezkerreko gurpila}" not in bar and "I_{gurpila1}: K1 kontaktu-puntua" in bar
    rod = plain_page("seed_c5_e3_wheels_with_rod", "en")
    note = rod.index("Notation: ω_wheel1 is the angular velocity of the *left wheel*; ω_wheel2 is the angular "
                     "velocity of the *right wheel*")
    assert note < rod.index("Given: ω_wheel1 = −ω (clockwise).") < rod.index("## Structure")     # its sense: round 29a
    cable = plain_page("seed_c5_1_1_pulley_on_cable", "eu")
    assert "v_{J∈kable-zatia1} = v_{J∈polea}" in cable and "ezkerreko kable-zatia}" not in cable


# ---- 4. one style for a centre ---------------------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_g_a_centre_is_written_one_way(name: str, lang: str) -> None:
    """In Markdown an instant centre's subscript is always braced, I_{OQ}: standalone, in a
    segment (OI_{OQ}, I_{OQ}O) and inside a velocity's subscript, which is then the segment
    to it (v_{OI_{OQ}} as v_CJ is CJ), never I_OQ or v_{O,I_OQ}."""
    page = plain_page(name, lang)
    assert not re.search(r"I_(?!\{)\w", page), re.search(r".{30}I_(?!\{)\w.{10}", page)
    assert ",I_" not in page


def test_g_the_pulley_by_hand() -> None:
    """C5-1.1 (eu): v_C = v_{I_{polea}} + v_{CI_{polea}}, v_{CI_{polea}} = ω_polea × I_{polea}C,
    ω_polea = −v/(2·r) from the x component (CI_{polea} = 2r, v_C = v to the right)."""
    page = plain_page("seed_c5_1_1_pulley_on_cable", "eu")
    assert re.search(r"^v_C +=  v_\{I_\{polea\}\}  \+  v_\{CI_\{polea\}\}$", page, re.M)
    assert "v_{CI_{polea}} = ω_polea × I_{polea}C = (v; 0)" in page
    assert "I_{polea}C = (0; 2·r); x norabidean: v_{CI_{polea}} = −ω_polea·(2·r) ⇒ ω_polea = −v/(2·r)" in page


# ---- the figures: a centre's label by its own ring -------------------------------------------------------------
def test_g_a_centres_label_is_nearer_its_ring_than_any_other_dot() -> None:
    """On the notes' seeds' drawings (en, ca) each instant centre's label lies nearer its own
    ring than any other labelled point: C5-E.2's I_planet1 went up beside A1 once the
    planet's subscript was short, and 13 labels of 120 (C5-1.4's I_planet1, C5-1.5's
    I_pulley3, …) already did on the old page."""
    from kinematika.draw.labels import DOT_GIDS, DOT_NEAR

    bad = []
    for (name, lang), layouts in recorded_pages("layouts").items():
        for placed, lay in layouts:
            dots = [lay.ax.transData.transform(q.label.anchor) for q in placed if q.label.gid.startswith(DOT_GIDS)]
            for p in placed:
                if not p.label.gid.startswith("centre:"):
                    continue
                ring = lay.ax.transData.transform(p.label.anchor)
                centre = (p.box[:2] + p.box[2:]) / 2
                others = [d for d in dots if np.linalg.norm(d - ring) > DOT_NEAR * lay.px]
                if others and min(np.linalg.norm(centre - d) for d in others) < np.linalg.norm(centre - ring):
                    bad.append((name, lang, p.label.text))
    assert not bad, bad
