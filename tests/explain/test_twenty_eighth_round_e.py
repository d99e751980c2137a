"""Issue 30, twenty-eighth round (e): the Data sections, and the Basque and Catalan wording,
after the fifth reading (four teachers, one a language; docs/explain.md, "Twenty-eighth
round (e)").

Each rule is general and checked over the notes' seeds in the four languages where it can
be; the pages the readers quoted are checked by hand beside it.
"""
from __future__ import annotations

import re

from .helpers import LANGS, SEEDS, model_tree, over, plain_page

# the legend of shortened subscripts, as each language opens it
LEGEND = {"en": "Notation:", "es": "Notación:", "ca": "Notació:", "eu": "Notazioa:"}
DATA = {"en": "## Data", "es": "## Datos", "ca": "## Dades", "eu": "## Datuak"}


def _data(page: str, lang: str) -> str:
    """The page's Data section, its italics taken off."""
    start = page.index(DATA[lang])
    end = page.index("\n## ", start + 3)
    return page[start:end].replace("*", "")


def _opening(text: str) -> str:
    """The first four words of a model's paragraph (what the page writes of it unchanged)."""
    return " ".join(text.replace("*", "").split()[:4])


# -- 1. the statement first, then the notation --------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_the_notation_follows_the_statement(name: str, lang: str) -> None:
    """The model's statement of the mechanism (`names.LANG.data`) comes before any legend of
    shortened subscripts: a notation before the mechanism is described names bodies the
    reader has not met (C5-E.6's "Notation: ω_wheel1 … ω_{sprocket rel frame}" opened the
    Data, before the bicycle)."""
    page = plain_page(name, lang)
    data = _data(page, lang)
    said = (model_tree(name).get("names") or {}).get(lang, {}).get("data") or []
    if LEGEND[lang] not in data:
        return
    legend = data.index(LEGEND[lang])
    for paragraph in said:
        opening = _opening(paragraph)
        assert opening in data, (opening, data[:400])
        assert data.index(opening) < legend, (opening, data[legend:legend + 80])


def test_the_bicycles_data_open_with_the_bicycle_by_hand() -> None:
    """C5-E.6: the first words of the Data after the units and the sign convention are the
    bicycle's, and the notation stands before the tables."""
    first = {"en": "The bicycle moves without slipping", "es": "La bicicleta se mueve sin deslizar",
             "ca": "La bicicleta es mou sense lliscar", "eu": "Bizikleta irristatu gabe mugitzen da"}
    for lang in LANGS:
        data = _data(plain_page("seed_c5_e6_bicycle", lang), lang)
        paragraphs = [p for p in data.split("\n\n")[1:] if p.strip()]
        assert paragraphs[2].startswith(first[lang]), (lang, paragraphs[2][:60])
        assert LEGEND[lang] not in data, lang       # 29 (b): the statement writes no shortened subscript


# -- 2. one name a thing, and two things never one name and its plural -----------------------------------------------
# the articles and prepositions a point's name is built with (dels/del, de los/del …)
LINKS = {"de", "del", "dels", "la", "el", "los", "las", "les", "els", "the", "of", "a", "al"}


def _words(name: str) -> tuple[str, ...]:
    """A name's words, singular (a final -s or -es taken off), without its articles."""
    return tuple(re.sub(r"(?<=\w\w\w)e?s$", "", w) for w in re.findall(r"\w+", name.lower()) if w not in LINKS)


@over(name=SEEDS, lang=LANGS)
def test_no_two_points_are_named_by_one_name_and_its_plural(name: str, lang: str) -> None:
    """Two points of one model are never named by words that differ only by a plural or an
    article: C5-E.6's C "eix dels pedals" and P "eix del pedal" (ca). The notes' words: C
    is the centre of the pedals ("centre dels pedals"), P the end of a pedal."""
    points = ((model_tree(name).get("names") or {}).get(lang) or {}).get("points") or {}
    seen: dict[tuple, str] = {}
    for p, said in points.items():
        said = said if isinstance(said, str) else str(said)
        key = _words(said)
        assert key not in seen, (seen.get(key), p, said)
        seen[key] = p


def test_the_bicycles_pedals_are_one_word_by_hand() -> None:
    """C5-E.6: the crank of length L is the notes' "pedal" in es, ca and eu wherever the page
    names it (L's row, the statement, P's row); es never calls it a "biela" beside it."""
    es = plain_page("seed_c5_e6_bicycle", "es")
    assert "biela" not in es.lower()
    assert "| *L* | longitud de los pedales |" in es and "los pedales tienen longitud L" in es
    ca = plain_page("seed_c5_e6_bicycle", "ca")
    assert "| C | centre dels pedals |" in ca and "| P | extrem del pedal, a L per sota de C |" in ca   # where: 29 (b)
    assert "eix dels pedals" not in ca and "eix del pedal" not in ca
    assert "L’enunciat anomena r el radi del *plat amb els pedals* i R el del *pinyó*" in ca
    eu = plain_page("seed_c5_e6_bicycle", "eu")
    assert "pedal-beso" not in eu and "| *L* | pedalen luzera |" in eu and "| P | pedalaren muturra, C-tik L beherago |" in eu
    assert "*Plater pedaldunak* eta *pinoiak* erradio desberdinak dituzte" in eu


# -- 3. the Data say a thing once ------------------------------------------------------------------------------------
@over(name=SEEDS, lang=LANGS)
def test_the_data_say_no_clause_twice(name: str, lang: str) -> None:
    """No clause of four words or more is written twice in the Data's paragraphs (tables
    aside, brackets and commas aside): C5-1.2's "the bar OQ turns at 1 rad/s
    counter-clockwise" ended both of the statement's paragraphs (and "Given: ω_OQ = 1 rad/s"
    said it a third time)."""
    data = _data(plain_page(name, lang), lang)
    text = "\n".join(line for line in data.splitlines() if not line.startswith("|"))
    text = re.sub(r"\([^()]*\)", "", text)
    clauses = [c.replace(",", "").strip().lower() for c in re.split(r"[.;:](?:\s|$)", text)]
    long = [c for c in clauses if len(c.split()) >= 4]
    twice = sorted({c for c in long if long.count(c) > 1})
    assert not twice, twice


def test_the_bars_rotation_is_said_once_in_words_by_hand() -> None:
    """C5-1.2: the bar OQ's rate in words once (the statement), then "Given: ω_OQ = 1 rad/s"."""
    said = {"en": "turns at 1 rad/s", "es": "gira a 1 rad/s", "ca": "gira a 1 rad/s", "eu": "1 rad/s-an biratzen da"}
    for lang, words in said.items():
        data = _data(plain_page("seed_c5_1_2_bar_on_inclined_wheels", lang), lang)
        assert data.count(words) == 1, lang
    eu = plain_page("seed_c5_1_2_bar_on_inclined_wheels", "eu")
    assert "gurpilek planoak K0 puntutik s = 3 m-ko distantziara ukitzen dituzte" in eu
    ca = _data(plain_page("seed_c5_1_2_bar_on_inclined_wheels", "ca"), "ca")
    assert "està articulada a la barra OQ pel punt O; la barra OQ, al seu torn, està articulada pels punts O i Q" in ca


# -- 4. the belt's and the pulley block's statements -----------------------------------------------------------------
DIRECTION_TOO = {"en": "gives the direction of", "es": "da también la dirección de",
                 "ca": "també dona la direcció de", "eu": "norabidea ere ematen du"}


@over(name=SEEDS, lang=LANGS)
def test_the_count_of_freedoms_names_no_one_datums_direction(name: str, lang: str) -> None:
    """The mobility the statement leaves is said with its data alone: "one for each datum
    (v_C1 and v_C3)", never "the statement gives the direction of v_C3 too", which read as if
    v_C1 had none (both are given downwards in the Data's own lines)."""
    assert DIRECTION_TOO[lang] not in plain_page(name, lang)


def test_the_belt_and_the_pulley_block_by_hand() -> None:
    """C5-1.6: the arm, hinged at O (the fixed pulley's centre), carries the moving pulley at
    A (es: "Un brazo articulado en O, centro de la polea fija, y en A lleva …" was garbled);
    C5-1.5: two data, two degrees of freedom; one cable passes over the four pulleys (two of
    them turn on fixed axles: they do not hang)."""
    belt = {"en": "An arm, hinged at O (the centre of the fixed pulley), carries the moving pulley at A;",
            "es": "Un brazo, articulado en O (centro de la polea fija), lleva en A la polea móvil;",
            "eu": "haien O eta A zentroetan giltzatuta,"}
    for lang, text in belt.items():
        assert text in _data(plain_page("seed_c5_1_6_belt", lang), lang), lang
    block = {"en": "The mechanism has two degrees of freedom, one for each datum (v_C1 and v_C3).",
             "es": "El mecanismo tiene dos grados de libertad, uno por cada dato (v_C1 y v_C3).",
             "ca": "El mecanisme té dos graus de llibertat, un per cada dada (v_C1 i v_C3).",
             "eu": "Mekanismoak bi askatasun-gradu ditu, datu bakoitzeko bat (v_C1 eta v_C3)."}
    for lang, text in block.items():
        assert text in plain_page("seed_c5_1_5_pulley_block", lang), lang
    assert "Un mismo cable inextensible pasa por cuatro poleas de radio r" in plain_page("seed_c5_1_5_pulley_block", "es")
    assert "Kable luzaezin bakar batek r erradioko lau polea inguratzen ditu" in plain_page("seed_c5_1_5_pulley_block", "eu")


# -- 5. Basque: the verb last, one name for the instant centre, the words the teacher read ---------------------------
@over(name=SEEDS)
def test_a_basque_equation_sentence_ends_with_its_verb(name: str) -> None:
    """Basque puts "da" after the sentence's last noun, never between a formula and the
    rest: "Beraz, 2. urratsean v_{B∈N} aurkitzeko erabilitako ekuazioa v_{B∈N} = … da", not
    "Beraz, v_{B∈N} = … da 2. urratsean … erabilitako ekuazioa" (001_p_pair, 001_rolling)."""
    page = plain_page(name, "eu")
    assert not re.search(r"Beraz, [va]_\S* = [^.]* da \d+\. urratsean", page), name


@over(name=SEEDS)
def test_the_basque_instant_centre_is_named_in_full(name: str) -> None:
    """Every Basque page names a body's instant centre "biraketa-zentro instantaneoa" (BZI),
    never "biraketa-zentroa" alone (C5-2.1's and 2.2's "*Txasisaren* biraketa-zentroa bi
    zuzen hauetan dago")."""
    page = plain_page(name, "eu")
    bare = re.findall(r"biraketa-zentro(?! instantaneo)\w*", page)
    assert not bare, bare[:3]


ADDS = {"en": "differ by the Coriolis terms", "es": "difieren en los términos de Coriolis",
        "ca": "difereixen en els termes de Coriolis", "eu": "arteko aldea Coriolisen"}


@over(name=SEEDS, lang=LANGS)
def test_a_sum_is_not_called_a_difference(name: str, lang: str) -> None:
    """The rolling pair's two relative accelerations: their SUM is 2 (ω_R − ω_N) × v_{F∈R rel
    N}; the page said they "differ by" it (eu "arteko aldea")."""
    assert ADDS[lang] not in plain_page(name, lang)


def test_the_basque_wording_by_hand() -> None:
    """The Basque teacher's items, each where it was read."""
    p_pair = plain_page("seed_001_p_pair_coriolis", "eu")
    assert ("Beraz, 2. urratsean v_{B∈N} aurkitzeko erabilitako ekuazioa v_{B∈N} = v_{arr,B} + v_{B∈N rel M} da."
            in p_pair)
    assert "puntuko puntuaren" not in p_pair
    rolling = plain_page("seed_001_rolling_pair", "eu")
    assert "Beraz, 2. urratsean α_N eta a_{A∈R rel N} aurkitzeko erabilitako ekuazioa a_A = " in rolling
    assert "Irristadurarik ez: v_{F∈R rel N} = 0; beraz, ez dago Coriolisen terminorik" in rolling     # round 29 c
    assert "*Txasisaren* biraketa-zentro instantaneoa bi zuzen hauetan dago" in plain_page("seed_c5_2_1_tricycle", "eu")
    assert "*S2 txasisaren* biraketa-zentro instantaneoa bi zuzen hauetan dago" in plain_page("seed_c5_2_2_articulated", "eu")
    assert "*OQ elementua* *lurrari* O puntuan giltzatuta dago;" in plain_page("seed_c5_1_3_bar_in_sleeve", "eu")
    assert "*N elementuaren* eta *P elementuaren* A eta E muturrak" in plain_page("seed_001_r_pairs", "eu")
    assert "45° hartzen da, ezkerrerantz (apunteen erantzunak angelu hori eskatzen du; ikus Oharra)" in plain_page("seed_c5_2_1_tricycle", "eu")   # 29 (b)


# -- 6. Catalan: one elision rule, the notes' ------------------------------------------------------------------------
@over(name=SEEDS)
def test_catalan_elides_before_a_vowel_letter_only(name: str) -> None:
    """Catalan elides de/el/la before a point's or a body's letter when the letter is a vowel
    (d'A1, d'O, l'E) and never before a consonant whose letter's name begins with a vowel
    sound: the notes write "respecte de R", "fixa a R", so "de S1", "de F", never "d'S1"
    (C5-2.2 mixed "de S1" ×8 with "d'S1" ×2; C5-1.4 "d'S"). Page and model alike."""
    page = plain_page(name, "ca")
    consonant = re.findall(r"\b[dlDL][’'][B-DF-HJ-NP-TV-Z][0-9′]*\b", page)
    assert not consonant, consonant[:4]
    vowel = re.findall(r"\b(?:[Dd]e|[Ee]l|[Ll]a) [AEIOU][0-9′]*(?![\w′'])", page)
    assert not vowel, vowel[:4]


def test_the_catalan_wording_by_hand() -> None:
    """C5-2.2's S1 and S2 with one form, and the Catalan teacher's sentences."""
    articulated = plain_page("seed_c5_2_2_articulated", "ca")
    assert "d’S1" not in articulated and "d’S2" not in articulated
    assert "les dues rodes de S1" in articulated and "la rotació de les rodes de S2" in articulated
    assert "els dos xassissos, S1 i S2, són idèntics i estan articulats a O, i les quatre rodes són iguals" in articulated
    assert "a partir de les velocitats d’A2 i de S" in plain_page("seed_c5_1_4_epicyclic", "ca")
    assert "Al punt B, el *bloc N* està articulat a un *balancí*" in plain_page("seed_001_p_pair_coriolis", "ca")
    gears = _data(plain_page("seed_c5_e2_gear_change", "ca"), "ca")
    assert "El braç, articulat pel seu centre al centre O de la roda central fixa (també de radi r), gira" in gears
