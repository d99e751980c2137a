"""Issue 30, sixteenth round (c): the Basque, Catalan and Spanish words a teacher still
marked on main's pages, each a rule checked over the 19 seeds and the languages where it
applies:

1. Basque: two point names never stand side by side ("C O-ren zuzen gainean" reads as one
   name): "C zentroa O-ren zuzen gainean"; tangent to a body is "-ekiko ukitzaile"
   ("polearekiko ukitzaileak", never "poleari ukitzaile"); "2 zenbakia", never "2a" (an
   ordinal's look); "propietateagatik"; a bar hinged at two points is "giltzatutako barra",
   as every other page says giltzatu; one term for a pendulum motion, the catalogue's
   "mugimendu pendular";
2. Catalan, Spanish, Basque: a point shared by several bodies has the preposition (the
   genitive) on each body ("un punt del terra, del pla esquerre i del pla dret"), and a
   contact point is named after the body actually touched (C5-1.2's K1: the left plane);
3. Spanish: one name per body, the model's (C5-1.4's sun is "el planeta", never "la rueda
   central" in a parameter's words); a point's description says what the point is, never a
   bare "centro" (C5-E.2's O).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from .helpers import EXAMPLES, SEEDS, rendered, over, model_tree

LOCALES = Path(__file__).resolve().parents[2] / "src" / "kinematika" / "explain" / "locales"


def page(name: str, lang: str) -> str:
    return rendered(name, lang, "md", drawings=False)


def names(name: str) -> dict:
    return model_tree(name).get("names") or {}


# ---- 1. Basque words ------------------------------------------------------------------------

@over(name=SEEDS)
def test_eu_two_point_names_never_side_by_side(name):
    """"C O-ren zuzen gainean" (C5-1.7, 1.8, E.1): a point name followed at once by another
    in a case is read as one name; a word (zentroa) or a comma stands between them."""
    assert not re.search(r"\b[A-Z]\d*′? [A-Z]\d*′?-(?:ren|rekin|ri|tik|ra|n)\b", page(name, "eu"))


@over(name=SEEDS)
def test_eu_the_words_the_reader_marked(name):
    """Tangent to a body is "-ekiko ukitzaile"; "2 zenbakia", not "2a"; the Basque
    "propietateagatik"; "giltzatutako barra"; one term for a pendulum motion."""
    text = page(name, "eu")
    assert not re.search(r"(?:ari|ei) (?:\S+ ){0,3}ukitzaile", text)
    assert "2a bakarrik" not in text
    assert "artikulatutako" not in text
    assert "pendulu-mugimendu" not in text


def test_eu_catalogue_words():
    """The catalogue's sentences, some on no seed's page (the equiprojectivity of a vehicle's
    witness): "propietateagatik", "giltzatutako barra"."""
    text = (LOCALES / "eu.ftl").read_text(encoding="utf-8")
    assert "propietatearengatik" not in text
    assert "Ekiproiektibitatearen propietateagatik" in text
    assert "artikulatutako" not in text
    assert "giltzatutako barra" in text


def test_eu_one_term_for_a_pendulum_motion():
    """C5-1.5: the datum and the strands' sentences said "mugimendu pendular" both; since the
    twenty-ninth round (b) neither does (opaque): strand 1 does not move, the others stay vertical."""
    text = page("seed_c5_1_5_pulley_block", "eu")
    assert "pendular" not in text
    assert "1. kable-zatia* ez da mugitzen" in text


# ---- 2. a shared point's bodies, each with its preposition ----------------------------------

SHARED = {
    ("seed_c5_1_2_bar_on_inclined_wheels", "ca"): "un punt del *terra*, del *pla esquerre* i del *pla dret*",
    ("seed_c5_1_2_bar_on_inclined_wheels", "es"): "un punto del *suelo*, del *plano izquierdo* y del *plano derecho*",
    ("seed_c5_1_2_bar_on_inclined_wheels", "eu"): "*lurraren*, *ezkerreko planoaren* eta *eskuineko planoaren* puntua",
}


@pytest.mark.parametrize("key", sorted(SHARED))
def test_a_shared_point_names_each_body_with_its_preposition(key, tmp_path):
    """The list of a point's bodies, each with its preposition: the words for a point the model
    does not describe. Since the eighteenth round (c) the seeds describe their shared points
    (K0 "el vèrtex on es tallen els dos plans"), so C5-1.2 is read with K0's words taken out."""
    import kinematika
    from kinematika.explain import build, render

    name, lang = key
    text = (EXAMPLES / f"{name}.yaml").read_text(encoding="utf-8")
    text = re.sub(r"^    points: \{K0: [^}]*\}\n", "", text, flags=re.M)
    assert "K0: " not in text.split("names:")[1]
    model = tmp_path / f"{name}.yaml"
    model.write_text(text, encoding="utf-8")
    page_ = render(build(kinematika.solve(model)), lang, "md", drawings=False)
    assert SHARED[key] in page_


@over(name=SEEDS, lang=("ca", "es"))
def test_no_list_of_bodies_drops_the_preposition(name, lang):
    """"del terra, el pla esquerre i el pla dret": after the first body a list never goes on
    with a bare article where the first had "de"."""
    pattern = r"\b(?:del|de la|de les|dels|de los|de las|d’)\s?\*[^*]+\*(?:, (?:el |la |les |els |los |las |l’)?\*[^*]+\*)* (?:i|y) (?:el|la|les|els|los|las|l’) ?\*"
    assert not re.search(pattern, page(name, lang))


TOUCHED = {"en": "the point of the *left plane* where it touches the *left wheel*",
           "es": "el punto del *plano izquierdo* donde toca la *rueda izquierda*",
           "ca": "el punt del *pla esquerre* on toca la *roda esquerra*",
           "eu": "*ezkerreko planoak* *ezkerreko gurpila* ukitzen duen puntua"}


@pytest.mark.parametrize("lang", sorted(TOUCHED))
def test_a_contact_is_the_point_of_the_body_touched(lang):
    """C5-1.2's K1 is held by the ground (welded to the plane) but the wheel touches the
    plane: the description names the plane."""
    text = page("seed_c5_1_2_bar_on_inclined_wheels", lang)
    row = next(ln for ln in text.splitlines() if ln.startswith("| K1 |"))
    assert TOUCHED[lang] in row


# ---- 3. one name per body; a point's description says what it is ----------------------------

# the words a model could call one body by; the model names it by one of them
SYNONYMS = {"es": [("planeta", "rueda central")], "ca": [("roda central", "planeta")],
            "eu": [("gurpil zentral", "planeta")]}


@over(name=SEEDS, lang=sorted(SYNONYMS))
def test_the_models_words_call_a_body_by_its_name(name, lang):
    """C5-1.4 es: the sun is "el planeta" but a parameter said "radio de la rueda central":
    the model's own words (points, parameters, data, notes) use the body's name."""
    words = names(name).get(lang) or {}
    bodies = " | ".join(str(b) for b in (words.get("bodies") or {}).values())
    told = " | ".join(str(x) for key in ("points", "parameters") for x in (words.get(key) or {}).values())
    told += " | " + " | ".join(str(x) for key in ("data", "notes") for x in (words.get(key) or []))
    for pair in SYNONYMS[lang]:
        for used, other in (pair, pair[::-1]):
            if used in bodies and other not in bodies:
                assert other not in told


@over(name=SEEDS, lang=("en", "es", "ca", "eu"))
def test_a_points_description_says_what_it_is(name, lang):
    """C5-E.2 es "| O | centro |": a centre says whose it is."""
    points = (names(name).get(lang) or {}).get("points") or {}
    bare = {"centre", "center", "centro", "zentroa"}
    assert not [p for p, what in points.items() if str(what).strip().lower() in bare]


def test_gear_change_centre_in_the_table():
    assert "| O | centro de la *rueda central fija* |" in page("seed_c5_e2_gear_change", "es")   # a body name in italics: the sixteenth round (g)
