"""The catalogues agree with the glossaries (explain/glossary/LANG.toml): each language's
catalogue uses the course's terms and none of the variants its instructors ruled out (a
Basque crank is a biradera, not a biela; a Catalan rigid body is a sòlid, not a cos), and so
do the names the notes' examples give their bodies."""
from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

import kinematika.explain as explain_package
from kinematika.explain.catalogue import LOCALES

from .helpers import EXAMPLES, model_tree
from .test_catalogues import messages

GLOSSARY = Path(explain_package.__file__).resolve().parent / "glossary"
LANGS = sorted(p.stem for p in GLOSSARY.glob("*.toml"))


def glossary(lang: str) -> dict:
    return tomllib.loads((GLOSSARY / f"{lang}.toml").read_text(encoding="utf-8"))


def found(phrase: str, text: str) -> bool:
    return re.search(r"(?<!\w)" + re.escape(phrase) + r"(?!\w)", text, re.I) is not None


def test_a_glossary_for_each_translated_language():
    assert LANGS == ["ca", "es", "eu"]
    assert {p.stem for p in LOCALES.glob("*.ftl")} - {"en"} == set(LANGS)


@pytest.mark.parametrize("lang", LANGS)
def test_catalogue_uses_the_glossarys_terms(lang):
    text = " ".join(messages(lang).values())
    for concept, entry in glossary(lang).items():
        assert entry["source"].strip(), (lang, concept, "an entry says where it comes from")
        for variant in entry["avoid"]:
            assert not found(variant, text), (lang, concept, f"the catalogue says {variant!r}; use {entry['use']!r}")
        if entry["required"]:
            assert entry["use"].lower() in text.lower(), (lang, concept, f"the catalogue never says {entry['use']!r}")


def test_the_glossary_catches_what_the_instructors_corrected():
    """The variants of issue 24 are ruled out: a test of the test."""
    eu, ca = glossary("eu"), glossary("ca")
    assert found(eu["crank"]["avoid"][0], "Mekanismoa ez da diadetan deskonposatzen biela edo irristari eragileetatik")
    assert any(found(v, "per a cada cos.") for v in ca["rigid-body"]["avoid"])
    assert any(found(v, "bere puntuek O zentrodun") for v in eu["possessive"]["avoid"])


@pytest.mark.parametrize("lang", LANGS)
def test_the_notes_examples_name_their_bodies_by_the_glossary(lang):

    avoid = [v for entry in glossary(lang).values() for v in entry["avoid"]]
    for path in sorted(EXAMPLES.glob("seed_*.yaml")) + sorted(EXAMPLES.glob("fan_*.yaml")):
        names = (model_tree(path.stem).get("names") or {}).get(lang) or {}
        words = " ".join([names.get("title", "")] + list(names.get("bodies", {}).values())
                         + list(names.get("points", {}).values()) + list(names.get("parameters", {}).values())
                         + list(names.get("data", [])) + list(names.get("notes", [])))
        assert names, (path.stem, lang, "no names in this language")
        for variant in avoid:
            assert not found(variant, words), (path.stem, lang, variant)
