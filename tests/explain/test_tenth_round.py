"""Tenth round: what the first English/Spanish audit found (docs/explain.md, "Tenth round").

Each test fails on the pages main wrote before this round (main at 907f550)."""
from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import kinematika
from kinematika.explain import build, render

from .helpers import ALL, LANGS, explained, rendered, over, model_tree

# the words a page says a driven body speeds up or slows down with, by language
FASTER = {"en": "is speeding up", "es": "se acelera", "ca": "s’accelera", "eu": "azkartzen ari da"}
SLOWER = {"en": "is slowing down", "es": "se frena", "ca": "es frena", "eu": "moteltzen ari da"}
# the same words as a model's own Data text would write them (never: the page derives them)
HAND_WRITTEN = re.compile(r"(?i)speeding|slowing|frenando|acelerando|frenant|accelerant|moteltzen|azkartzen")


def _sense_msgs(doc) -> list:
    data = next(s for s in doc.sections if s.title.key == "sec.data")
    return [b for b in data.blocks if getattr(b, "key", "") == "driver.omega_sense"]


def _expected(model: dict) -> dict:
    """body -> True (speeding up) / False (slowing down), from the model file's own numbers:
    |ω| grows when ω·α > 0."""
    out = {}
    params = model.get("parameters") or {}
    for d in model.get("drivers") or []:
        w, a = (params.get(x, x) if isinstance(x, str) else x for x in (d.get("value"), d.get("alpha")))
        if "omega" in d and isinstance(w, (int, float)) and isinstance(a, (int, float)) and w and a \
                and not d.get("relative_to"):
            out[d["omega"]] = w * a > 0
    return out


@over(name=ALL)
def test_speeding_up_follows_the_signs_of_every_example(name):
    """Every planar example's driven body with a numeric ω and α: the Data says it speeds up
    exactly when ω·α > 0 (seed 001's crank O2E, ω = −5, α = +2, was said to speed up)."""
    model = model_tree(name)
    sol, doc = explained(name)
    data = next(s for s in doc.sections if s.title.key == "sec.data")
    if not any(getattr(b, "key", "") == "data.planar" for b in data.blocks):
        return                                      # spatial: ω and α are vectors
    said = {m.args["body"].text: m.args["faster"] == 1 for m in _sense_msgs(doc)}
    assert said == _expected(model)
    for lang_data in (model.get("names") or {}).values():
        for text in lang_data.get("data") or []:
            assert not HAND_WRITTEN.search(text), f"{name}: a hand-written rate word in the Data: {text}"


@pytest.mark.parametrize("lang", LANGS)
def test_r_pairs_crank_slows_down_in_every_language(lang):
    page = rendered("seed_001_r_pairs", lang, drawings=False)
    assert SLOWER[lang] in page and FASTER[lang] not in page
    assert "speeding up at 2" not in page


def _crank(w: float, a: float) -> dict:
    return {"points": {"O": [0, 0], "A": [1, 0.5]}, "bodies": {"ground": ["O"], "crank": ["O", "A"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"}],
            "drivers": [{"omega": "crank", "value": w, "alpha": a}], "ask": [{"acceleration": "A"}]}


nonzero = st.integers(min_value=-9, max_value=9).filter(bool)


@settings(max_examples=12, deadline=None)
@given(w=nonzero, a=nonzero)
def test_property_speeding_up_iff_omega_alpha_positive(w, a):
    """sign(ω·α) > 0 ⇔ "speeding up", in the English and Spanish pages."""
    doc = build(kinematika.solve(_crank(w, a)))
    (m,) = _sense_msgs(doc)
    assert (m.args["faster"] == 1) == (w * a > 0)
    for lang in ("en", "es"):
        page = render(doc, lang, "md", drawings=False)
        assert ((FASTER if w * a > 0 else SLOWER)[lang] in page)
        assert ((SLOWER if w * a > 0 else FASTER)[lang] not in page)


def test_p_pair_data_sentence_reads():
    page = rendered("seed_001_p_pair_coriolis", "en", drawings=False)
    assert "s along it, is pinned" not in page
    assert "The *block N* slides along it" in page   # its name marked (sixteenth round)


BARE_LEAD = re.compile(r"(?m)^\*[A-Z][^*]*\* [a-z]")        # a paragraph opening *Wheel* rolls


@over(name=["seed_c5_e1_cavity", "seed_c5_e4_upper_wheel", "seed_c5_1_6_belt",
                                  "seed_001_p_pair_coriolis"])
def test_english_body_names_take_the_article(name):
    page = rendered(name, "en", drawings=False)
    assert not BARE_LEAD.search(page), BARE_LEAD.search(page)
    assert re.search(r"(?m)^The \*[a-z]", page)


def test_english_plural_name_takes_a_plural_verb():
    page = rendered("seed_c5_e1_cavity", "en", drawings=False)
    assert "The *wheels* roll without slipping" in page
    assert "*wheels* rolls" not in page.lower()


def test_numbered_name_has_no_article():
    page = rendered("seed_c5_1_5_pulley_block", "en", drawings=False)
    assert "the *pulley 1*" not in page and "*Pulley 1* rolls" in page


def test_relative_convention_names_the_bodies_with_articles():
    assert "of the point Q of the *bar* seen from the *support*" in rendered("seed_c5_1_3_bar_in_sleeve", "en",
                                                                           drawings=False)
    es = rendered("seed_c5_1_3_bar_in_sleeve", "es", drawings=False)
    assert "del punto Q de la *barra* vista desde el *soporte*" in es
    assert "de barra respecto de soporte" not in es


def test_joints_table_names_bare():
    page = rendered("seed_001_r_pairs", "en", drawings=False)
    assert "| revolute (R) | *ground* – *crank O1A* | O1 |" in page


@pytest.mark.parametrize("lang,twice", [("en", "does not turn (ω_chassis = 0): it translates"),
                                        ("es", "no gira (ω_chasis = 0): se traslada")])
def test_translation_said_once(lang, twice):
    """E.4: ω_chassis = 0 "(… at infinity: it translates)", then only that all its points
    share one velocity, not "does not turn (ω = 0): it translates" again."""
    page = rendered("seed_c5_e4_upper_wheel", lang, drawings=False)
    assert twice not in page
    assert ("All the points of the *chassis* have one velocity:" if lang == "en"
            else "Todos los puntos del *chasis* tienen la misma velocidad:") in page


def test_fixed_body_not_said_fixed_twice():
    en = rendered("seed_c5_1_8_contact_points", "en", drawings=False)
    assert "*fixed cylinder*, which is fixed" not in en
    assert "J as a point of the *fixed cylinder* does not move" in en
    es = rendered("seed_c5_1_8_contact_points", "es", drawings=False)
    assert "fijo*, que es fijo" not in es
