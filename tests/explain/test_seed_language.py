"""The notes' examples explained in the reader's language: in a Spanish, Catalan or Basque
explanation of a worked example no English mechanism word is left (no carrier, sprocket or
block), in the text or in the figures' labels, and the title is the notes' own."""
from __future__ import annotations

import functools
import re

import pytest

from kinematika.draw.options import DrawOptions
from kinematika.draw.build import build_scene

from tests.conftest import KINDS, sampled

from .helpers import EXAMPLES, explained, render_of
from .test_text import plain_text

# the notes' examples of each kind (every one in a deep run)
NOTES = sampled(sorted(p.stem for p in EXAMPLES.glob("seed_*.yaml")) + sorted(p.stem for p in EXAMPLES.glob("fan_*.yaml")),
                KINDS)
# the English words the models' names are made of (bodies, joints, points): none may reach a
# translated explanation
ENGLISH = {"carrier", "sun", "ring", "planet", "block", "blades", "blade", "shaft", "hub", "sprocket",
           "chainring", "frame", "chain", "wheel", "wheels", "pulley", "strand", "belt", "arm", "chassis",
           "rocker", "crank", "slider", "lever", "roller", "bar", "rod", "ground", "support", "cable", "rear",
           "front", "upper", "lower", "plane", "roll", "steer", "sleeve", "cylinder", "semicylinder", "fixed",
           "moving", "left", "right", "guide", "track", "cavity", "vehicle", "bicycle", "tricycle", "fan",
           "transmission", "epicyclic", "contact", "connecting", "gear", "change", "articulated", "unequal"}
# words spelt alike in English and in the language (a Spanish or Catalan cable is a cable)
ALIKE = {"es": {"cable"}, "ca": {"cable"}, "eu": set()}
WORD = re.compile(r"[A-Za-zÀ-ÿ·]+")


@functools.lru_cache(maxsize=None)
def text(name: str, lang: str) -> str:
    """The explanation as a reader reads it (once per example and language)."""
    _, doc = explained(name)
    return plain_text(render_of(doc, lang, "md", drawings=False), "md")


@pytest.mark.parametrize("lang", ["es", "ca", "eu"])
@pytest.mark.parametrize("name", NOTES)
def test_no_english_mechanism_word(name, lang):
    sol, _ = explained(name)
    found = sorted({w for w in WORD.findall(text(name, lang)) if w.lower() in ENGLISH - ALIKE[lang]})
    assert not found, f"English in the {lang} explanation of {name}: {found}"
    labels = [b.label for b in build_scene(sol.inst, sol, DrawOptions(lang=lang, bare=True)).bodies.values()]
    stray = sorted({w for label in labels for w in WORD.findall(label) if w.lower() in ENGLISH})
    assert not stray, f"English in the {lang} figure of {name}: {stray}"


@pytest.mark.parametrize("lang", ["es", "ca", "eu"])
def test_titles_are_the_notes(lang):
    _, doc = explained("seed_c5_1_4_epicyclic")
    title = {"ca": "Transmissió epicicloidal", "es": "Transmisión epicicloidal", "eu": "Transmisio epizikloidala"}[lang]
    assert render_of(doc, lang, "md", drawings=False).lstrip().startswith(f"# {title}")
