"""Eleventh round: what the three audits of 30 Nov 2026 still left (docs/explain.md, "Eleventh
round"): each a rule or the model's names and notation, over the nineteen seeds in the four
languages where it applies.

Each test fails on the pages main wrote before this round (main at 3b4edd4)."""
from __future__ import annotations

import re

import pytest

from kinematika.model.subscripts import named_labels

from .helpers import LANGS, SEEDS, rendered, over, model_tree

# the words a centre placed between/beyond two parallel velocities ends with, by language
# ("where the speed falls to zero, at ..."), up to the colon before its coordinates
ZERO_AT = {"en": r"where the speed falls to zero, at ([^:]*):",
           "es": r"donde la velocidad se anula, a ([^:]*):",
           "ca": r"on la velocitat s’anul·la, a ([^:]*):",
           "eu": r"abiadura nulua den tokian, ([^:]*):"}


@over(name=SEEDS, lang=LANGS)
def test_a_centre_between_parallel_velocities_says_its_distance_plainly(name, lang):
    """'at r/2 from C3', never 'at C3 I_pulley3 = r/2 from C3' (a segment set equal to the
    distance it is measured from): the distance, then the point it is measured from."""
    page = rendered(name, lang)
    for said in re.findall(ZERO_AT[lang], page):
        assert "=" not in said and "I_" not in said, said


def test_the_pulley_blocks_third_centre_is_r_over_2_from_c3():
    """C5-1.5 by hand: C3 falls at 2v, T4 (r to its left) rises at 2v, so the speed, linear
    along C3T4, is zero midway: r/2 from C3."""
    expected = {"en": "at r/2 from C3:", "es": "a r/2 de C3:", "ca": "a r/2 de C3:",
                "eu": "C3 puntutik r/2 distantziara:"}
    for lang in LANGS:
        assert expected[lang] in rendered("seed_c5_1_5_pulley_block", lang), lang


def test_a_basque_subscript_is_a_word_with_its_article():
    """A Basque name declines its last word only: *gurpil zentrala*'s head word is the stem
    gurpil, written alone with its article, gurpila (never ω_gurpil, no word of the page)."""
    labels = named_labels(["ground", "sun", "ring"], {"ground": "lurra", "sun": "gurpil zentrala",
                                                       "ring": "koroa"}, "eu", {})
    assert labels["sun"] == "gurpila"
    assert labels["ring"] == "koroa"
    labels = named_labels(["ground", "p"], {"ground": "lurra", "p": "polea finkoa"}, "eu", {})
    assert labels["p"] == "polea"          # a stem already ending in -a keeps it


@over(name=["seed_c5_1_4_epicyclic", "seed_c5_e2_gear_change"])
def test_no_basque_page_writes_a_bare_stem(name):
    page = rendered(name, "eu")
    assert not re.search(r"ω_gurpil(?!a)", page)
    assert "ω_zentrala" in page          # the central wheel among meshing wheels (fourteenth round)


# a language's "and" between two names of a list, by language
AND = {"en": "and", "es": "y", "ca": "i", "eu": "eta"}


@over(name=SEEDS, lang=LANGS)
def test_no_name_joined_with_and_inside_a_list_joined_with_and(name, lang):
    """'*chain* and *chainring and pedals*' reads as three bodies: a name in a list joined
    by "and" holds no "and" of its own."""
    a = AND[lang]
    page = rendered(name, lang, drawings=False)
    found = re.search(rf"\*[^*\n]+\* {a} \*[^*\n]* {a} [^*\n]*\*", page)
    assert not found, found and found.group(0)


# C5-E.6's wheel radius as each language writes it (the notes' R_roda in Catalan)
WHEEL_RADIUS = {"ca": "R_roda", "en": "R_wheel", "es": "R_rueda", "eu": "R_gurpila"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_bicycles_wheel_radius_is_written_in_the_pages_language(lang):
    """The Catalan R_roda only on the Catalan page; the others write their own, in the
    formulas, the figures' 'Drawn at' and the model's own words (its Data and Notes) alike."""
    page = rendered("seed_c5_e6_bicycle", lang)
    others = [w for k, w in WHEEL_RADIUS.items() if k != lang]
    assert WHEEL_RADIUS[lang] in page
    assert not [w for w in others if w in page]
    note = page[page.rindex("ℜ = (R/r)²"):]
    assert f"d = {WHEEL_RADIUS[lang]} R/r" in note


@over(name=SEEDS, lang=LANGS)
def test_no_polygon_image_is_a_symbol_of_the_page(name, lang):
    """A polygon's image is its point's letter in lower case; when that letter is a
    parameter of the page (C5-E.6's crank axle C beside the wheelbase c) it is primed, c′,
    as O's image is o′ beside the pole o, and the caption says so."""

    model = model_tree(name)
    letters = {p for p in (model.get("parameters") or {}) if len(p) == 1 and p.islower()}
    page = rendered(name, lang, "html")
    labels = re.findall(r"<text[^>]*>([^<]*)</text>", page)
    images = {x.strip() for label in labels for x in label.split(",")}
    assert not (images & letters), (images & letters)


def test_the_bicycles_crank_axle_image_is_c():
    """C5-E.6's crank axle C has its plain image c since the fourteenth round named the
    wheelbase e (no parameter c to step aside from: no c′ and no note explaining it)."""
    for lang in LANGS:
        page = rendered("seed_c5_e6_bicycle", lang, "html")
        labels = {x.strip() for label in re.findall(r"<text[^>]*>([^<]*)</text>", page) for x in label.split(",")}
        assert "c" in labels and "c′" not in labels, lang


# English abbreviations a point of C5-2.1 and 2.2 was called by (rear left, rear right, wheel)
ENGLISH_LABELS = re.compile(r"\b(?:RL|RR|W[1-4])\b")


@over(name=["seed_c5_2_1_tricycle", "seed_c5_2_2_articulated"], lang=LANGS)
def test_the_vehicles_wheel_centres_are_language_neutral_letters(name, lang):
    """The notes name no wheel centre in 2.1 and 2.2; they write a wheel's centre C_roda,
    so the model's centres are C1, C2 … (one set of letters in every language), never the
    English RL, RR, W1…W4 on a Catalan or Basque page."""
    page = rendered(name, lang)
    assert not ENGLISH_LABELS.findall(page), sorted(set(ENGLISH_LABELS.findall(page)))


# the words a position "across a line" says its side with: as one looks from the origin
# towards the line's other point, never "to its left/right" alone
SIDE_ALONE = {"en": r"across it, to its (?:left|right)", "es": r"a su (?:izquierda|derecha):",
              "ca": r"a la seva (?:esquerra|dreta):", "eu": r"perpendikularrean, (?:ezkerretara|eskuinetara):"}


@over(name=SEEDS, lang=LANGS)
def test_a_side_across_a_line_says_which_way_it_is_looked_along(name, lang):
    assert not re.search(SIDE_ALONE[lang], rendered(name, lang, drawings=False))


def test_the_articulated_vehicles_right_wheel_is_left_of_o_towards_p():
    """C5-2.2 by hand: S2 trails S1 (moving +x), heading from P to O, i.e. (1, 1)/√2; its
    right wheel's centre C4 = P + (a/2)(1, −1)/√2 = (−√2a/4, −3√2a/4) is on the right of that
    heading and on the left of O→P (the opposite heading): the page now says it as the
    vehicle heads (seventeenth round (a): the right wheel on the right, looking from P towards O)."""
    page = rendered("seed_c5_2_2_articulated", "en", drawings=False)
    assert "| C4 | centre of the right wheel of S2 |" in page
    assert ("C4 is at a distance a from O along OP and a/2 across it, on the right as one looks "
            "from P towards O: C4 = (−√2·a/4, −3·√2·a/4).") in page


@pytest.mark.parametrize("lang", ["es", "ca"])
def test_the_articulated_vehicles_data_reads(lang):
    page = rendered("seed_c5_2_2_articulated", lang, drawings=False)
    assert not re.search(r"\ba a d", page)


def _structure_column(page: str) -> list[str]:
    """The first cells of the structure's bodies table: the section after the Data, its
    first table's rows (past the header and its rule)."""
    section = page.split("\n## ")[2]
    table = section[section.index("\n|"):].split("\n\n")[0].strip().splitlines()[2:]
    return [row.split("|")[1].strip() for row in table]


@over(name=SEEDS, lang=LANGS)
def test_the_structure_column_does_not_mix_letters_and_numbers(name, lang):
    """One style down the column: all numbers, or all the notation's letters."""
    cells = _structure_column(rendered(name, lang, drawings=False))
    assert cells, name
    assert all(c.isdigit() for c in cells) or not any(c.isdigit() for c in cells), cells


@pytest.mark.parametrize("lang", LANGS)
def test_the_p_pairs_bodies_are_numbered_in_the_notes_order(lang):
    """Seed 001's P pair: the slides letter M and N but not the frame nor the rocker, so the
    column numbers all four, the frame 1 and the others in the file's order; the letters
    stay in the names and in ω_M, ω_N."""
    page = rendered("seed_001_p_pair_coriolis", lang, drawings=False)
    assert _structure_column(page) == ["1", "2", "3", "4"]
    assert "ω_M" in page and "ω_N" in page


@over(name=SEEDS, lang=LANGS)
def test_a_markdown_caption_is_read_once_with_one_emphasis(name, lang):
    """Each figure: a short alternative text (its title, no longer than the caption's first
    clause) and the caption below in one italic span, no star inside it (`*R*` nested in
    `*…*` closes the caption's italics)."""
    lines = rendered(name, lang).splitlines()
    images = [k for k, line in enumerate(lines) if re.match(r"!\[[^\n]*\]\[fig-\d+\]$", line)]
    assert images
    for k in images:
        alt = re.match(r"!\[(.*)\]\[fig-\d+\]$", lines[k]).group(1)
        caption = lines[k + 2]
        assert caption.startswith("*") and caption.endswith("*"), caption
        inner = caption[1:-1]
        assert "*" not in inner.replace("\\*", ""), caption
        assert alt and inner.startswith(alt) and len(alt) < len(inner) and not re.search(r"[,:;]", alt), alt


# "distance from P = d" in the answers' table, by language
FROM = {"en": "distance from {p} = {d}", "es": "distancia a {p} = {d}", "ca": "distància {de}{p} = {d}",
        "eu": "{p} puntura dagoen distantzia = {d}"}


def _from(lang: str, p: str, d: str) -> str:
    de = "d’" if p[0] in "AEIOU" else "de "
    return FROM[lang].format(p=p, d=d, de=de)


@pytest.mark.parametrize("lang", LANGS)
def test_the_planets_centre_is_two_fifths_r_from_its_centre(lang):
    """C5-1.4 by hand: A1 moves at 2rω, the ring's contact N (r below A1) at 3rω the other
    way; the speed is linear along A1N, zero at 2/(2+3) of r from A1: the notes' (2/5)r."""
    page = rendered("seed_c5_1_4_epicyclic", lang, drawings=False)
    assert _from(lang, "A1", "2·r/5") in page


@pytest.mark.parametrize("lang", LANGS)
def test_the_pedals_centre_is_its_depth_below_c(lang):
    """C5-E.6 by hand: v_C = v, ω = r v/(R R_roda), so the centre is v/ω = R R_roda/r from C
    (the notes' d), on the perpendicular to v_C through C."""
    w = {"ca": "R_roda", "en": "R_wheel", "es": "R_rueda", "eu": "R_gurpila"}[lang]
    page = rendered("seed_c5_e6_bicycle", lang, drawings=False)
    assert _from(lang, "C", f"R·{w}/r") in page


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name,chassis", [("seed_c5_e5_unequal_wheels", {"en": "chassis", "es": "chasis", "ca": "xassís",
                                                                          "eu": "txasisa"}),
                                          ("seed_c5_e6_bicycle", {"en": "frame", "es": "cuadro", "ca": "quadre",
                                                                   "eu": "koadroa"})])
def test_the_chassis_translates_before_the_velocity_equations(name, chassis, lang):
    """C5-E.5 and E.6: both wheels' centres stay at their radii above one straight ground, so
    they move on parallel straight lines (one line when the radii are equal) and the chassis
    pinned at them translates, as the notes state: ω = 0 said before any velocity equation,
    never solved from v_A = v_J∈wheel2 + v_BJ + v_AB (two unknown rotations), and no term
    ω_chassis × … anywhere."""
    page = rendered(name, lang, drawings=False)
    velocities = page[page.index("\n## ", page.index("\n## ") + 1):]
    velocities = velocities[velocities.index("\n### "):]
    w = f"ω_{chassis[lang]}"
    said = velocities.index(f"{w} = 0 (")
    assert said < velocities.index("```")
    assert f"{w} ×" not in page and f"{w}·" not in page
