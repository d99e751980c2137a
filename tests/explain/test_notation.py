"""The notes' notation in the explanations (issue 30, the independent audit's S3, S4, S7 and
its notes on C5-1.6, E.5 and E.6): bodies written by their names, not their numbers in the
file; relative quantities without a slash that reads as a fraction; compositions written
relative + drag = absolute; rates read off as scalars, never a vector over a vector; a
belt's run not listed as a turning body; the radius of curvature apart from the radii."""
from __future__ import annotations

import re

import pytest

from kinematika.explain.catalogue import LANGS
from kinematika.model.subscripts import named_labels

from .helpers import WORKED, explained, rendered

SEEDS = [n for n in WORKED if n.startswith("seed_")]
# a rate written with a number for its body: ω_6, α_{3 REL 2}
NUMBERED_RATE = re.compile(r"[ωα]_\{?(\d+)\b")
# a subscript with a slash (ω_{3/2}, v_{Q∈3/4}) or a sub/sub-script one in HTML
SLASHED = re.compile(r"_\{[^}]*/[^}]*\}|<sub>[^<]*/[^<]*</sub>")
# a velocity or acceleration symbol divided by a segment or another such symbol (v_{O-I17} / I17-O)
VECTOR_OVER_VECTOR = re.compile(r"(?<![|\\])\b[va]_(\{[^}]*\}|[^\s|\\{²]+)(\^\w+)? / ([A-Z]|[va]_)")


def _text(name: str, lang: str, fmt: str = "md") -> str:
    return rendered(name, lang, fmt, drawings=False)


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_no_body_number_slash_or_vector_division(name, lang):
    """No ω or α is subscripted with a body's number unless the model's notation gives that
    number (C5-E.5's wheels 1 and 2, as the notes' roda1, roda2); no subscript holds a slash;
    no velocity is divided by a segment or a vector."""
    sol, _ = explained(name)
    given = {sol.model.wording.index(b, lang) for b in sol.model.bodies} - {None}
    for fmt in ("md", "html"):
        text = _text(name, lang, fmt)
        numbered = {m.group(1) for m in NUMBERED_RATE.finditer(text)} - given
        assert not numbered, (name, lang, fmt, numbered)
        slash = SLASHED.search(text)
        assert slash is None, (name, lang, fmt, text[max(0, slash.start() - 60):slash.end() + 20])
        if fmt == "md":
            over = VECTOR_OVER_VECTOR.search(text)
            assert over is None, (name, lang, text[max(0, over.start() - 60):over.end() + 20])


@pytest.mark.parametrize("lang,absolute,relative,drag", [
    ("ca", "ω_politja2", "ω_{politja2 rel braç}", "ω_braç"),
    ("eu", "ω_polea2", "ω_{polea2 rel besoa}", "ω_besoa"),
    ("es", "ω_polea2", "ω_{polea2 rel brazo}", "ω_brazo"),
    ("en", "ω_pulley2", "ω_{pulley2 rel arm}", "ω_arm"),
])
def test_belt_composition_runs_relative_plus_drag(lang, absolute, relative, drag):
    """C5-1.6 as the notes compose it from the arm (=REL): Ω_AB = Ω_REL + Ω_ar, the moving
    pulley's 2ω clockwise relative to the arm plus the arm's ω; the fixed pulley's rate
    relative to the arm read off ω_fixed = ω_{fixed rel arm} + ω_arm = 0 (the absolute on the
    left, as the notes write it); never ω_R/t = ω_R − ω_t alone."""
    text = _text("seed_c5_1_6_belt", lang)
    assert f"{absolute} = {relative} + {drag} = −ω" in text
    fixed = re.search(r"(ω_\S+) = (ω_\{[^}]*\}) \+ " + re.escape(drag) + r" = 0 ⇒ \2 = −" + re.escape(drag), text)
    assert fixed is not None, text[text.find(" = 0 ⇒") - 100:text.find(" = 0 ⇒") + 100]
    for line in text.splitlines():
        backwards = re.match(r"(ω|α)_\{[^}]*\} = (ω|α)_\S+ − (ω|α)_", line)
        assert backwards is None, line         # a relative rate is read off its composition (⇒), not stated


@pytest.mark.parametrize("name,run", [("seed_c5_1_6_belt", "belt"), ("seed_c5_e6_bicycle", "chain")])
def test_a_belt_run_is_not_in_the_rates_table(name, run):
    """A belt's or chain's straight run is carried by the arm (frame) that holds the axles; the
    notes give it no rate, and the table of rates does not list it (round 29 c, reversing
    twentieth round g's listing)."""
    from kinematika.explain.document import Name, Table

    _, doc = explained(name)
    rates = [b for s in doc.sections for b in s.blocks if isinstance(b, Table) and len(b.header) >= 2
             and getattr(b.header[1], "key", "") == "col.omega"]
    assert rates
    listed = {c.text for t in rates for row in t.rows for c in row[:1] if isinstance(c, Name)}
    assert run not in listed


def test_unequal_wheels_as_the_notes_write_them():
    """C5-E.5: the relative velocity of A about B is the slides' v_AB (A about B, as v_BA is B
    about A), never the hyphenated v_{A-B} a reader takes for a difference; the radius of curvature is the notes' ℜ (ρ is a wheel's radius); the result
    v_P = v (r₂ − r₁)/r₂ carries no minus in front of a turned difference."""
    text = _text("seed_c5_e5_unequal_wheels", "ca")
    # v_AB left with the chained equation (eleventh round: the chassis translates, said
    # first); P about B is still written the slides' way
    assert "v_PB" in text and "v_{A-B}" not in text and "v_{P-B}" not in text
    assert "ℜ_P = " in text and "ρ_P" not in text
    assert "v·(r₂ − r₁)/r₂" in text and "−v·(r₁ − r₂)" not in text


@pytest.mark.parametrize("lang,names,expected", [
    # the first word in Catalan and Spanish; where two bodies share it, the word with each
    # one's rank (roda1, roda2: twenty-seventh round (g), never the words roda posterior)
    ("ca", {"g": "el terra", "f": "el quadre", "r": "la roda posterior", "s": "el pinyó",
            "w": "la roda davantera", "c": "el plat i els pedals"},
     ["terra", "quadre", "roda1", "pinyó", "roda2", "plat"]),
    # a number joins the word (the notes' roda1); a capital code is the slides' ω_N
    ("ca", {"g": "el terra", "a": "el satèl·lit 1", "b": "el satèl·lit 2", "n": "l’element N"},
     ["terra", "satèl·lit1", "satèl·lit2", "N"]),
    # Basque: the word not ending in -ko (ezkerreko gurpila, polea finkoa), 1. satelitea
    ("eu", {"g": "polea finkoa", "a": "ezkerreko gurpila", "b": "1. satelitea", "n": "2. satelitea"},
     ["polea", "gurpila", "satelitea1", "satelitea2"]),
    # English: the last word (left wheel), with its rank where two share it
    ("en", {"g": "fixed pulley", "a": "moving pulley", "b": "arm", "n": "chassis S1"},
     ["pulley1", "pulley2", "arm", "S1"]),
    # Spanish plural article (las ruedas)
    ("es", {"g": "la pista", "a": "las ruedas", "b": "la recta OC", "n": "el brazo"},
     ["pista", "ruedas", "OC", "brazo"]),
])
def test_subscripts_read_off_the_names(lang, names, expected):
    order = list(names)
    labels = named_labels(order, names, lang, {})
    assert [labels[b] for b in order] == expected


def test_numbers_without_names_and_given_indices_kept():
    """A model that names no body in the language keeps the numbers; an index the notation
    gives is kept and never taken by another body."""
    assert named_labels(["g", "a", "b"], {}, "ca", {"a": "N"}) == {"g": "1", "a": "N", "b": "3"}
    assert named_labels(["g", "a", "b"], {"g": "el terra", "a": "la roda", "b": "la roda"}, "ca", {}) == \
        {"g": "terra", "a": "2", "b": "3"}
