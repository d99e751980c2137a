"""The four catalogues are complete (same keys, same placeholders), every key is used by
the code, every key the code uses exists, and each course's own terms are there."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

import kinematika.explain as explain_package
from kinematika.explain.catalogue import LANGS, LOCALES, PLACEHOLDER

SOURCE = Path(explain_package.__file__).resolve().parent
# keys built at run time from a name (f"kind.{step.kind}" ...): the families and their members
FAMILIES = {
    "kind": ["input", "RRR", "RRP", "RPR", "PRP", "other"],
    "joint": ["revolute", "prismatic", "slot", "wheel", "rolling", "gear", "weld", "spherical", "cylindrical"],
    "shape": ["circle", "line", "disc", "plane"],
    "cond": ["revolute", "prismatic", "slot", "wheel", "weld", "spherical", "cylindrical"],
    "centre.joint": ["revolute", "rolling", "gear", "prismatic", "weld"],
}


def messages(lang: str) -> dict[str, str]:
    return yaml.safe_load((LOCALES / f"{lang}.yaml").read_text(encoding="utf-8"))


def literals() -> set[str]:
    text = "\n".join(p.read_text(encoding="utf-8") for p in SOURCE.rglob("*.py"))
    return set(re.findall(r'"([a-zA-Z_]+\.[a-zA-Z_.]+)"', text))


def test_same_keys_in_every_language():
    keys = {lang: set(messages(lang)) for lang in LANGS}
    for lang in LANGS:
        assert keys[lang] == keys["en"], (lang, keys[lang] ^ keys["en"])


@pytest.mark.parametrize("lang", LANGS[1:])
def test_same_placeholders(lang):
    en, other = messages("en"), messages(lang)
    for key, text in en.items():
        assert set(PLACEHOLDER.findall(other[key])) == set(PLACEHOLDER.findall(text)), (lang, key)
        assert other[key].strip(), (lang, key)


def test_no_unused_and_no_missing_keys():
    keys = set(messages("en"))
    used = {k for k in literals() if k in keys}
    source = "".join(p.read_text(encoding="utf-8") for p in SOURCE.rglob("*.py"))
    for family, members in FAMILIES.items():
        assert f'f"{family}.' + "{" in source, f"no key of the family {family} is built in the code"
        used |= {f"{family}.{m}" for m in members}
    assert keys - used == set(), f"unused keys: {sorted(keys - used)}"
    prefixes = ("sec.", "msg.", "col.", "data.", "fig.", "order.", "step.", "driver.", "input.",
                "other.", "rolling.", "dir.", "how.", "carry.", "sense.", "sub.", "centre.", "centres.",
                "rates.", "fields.", "composition.", "curvature.", "answers.", "structure.", "v.", "a.")
    wanted = {k for k in literals() if k.startswith(prefixes)}
    assert wanted - keys == set(), f"keys the code uses but no catalogue has: {sorted(wanted - keys)}"


@pytest.mark.parametrize("lang,terms", [
    ("eu", ["abiadura", "azelerazio", "arrastre", "erlatibo", "Coriolis"]),
    ("ca", ["velocitat", "acceleració", "arrossegament", "relati", "CIR"]),
    ("es", ["velocidad", "aceleración", "arrastre", "relativ", "CIR"]),
    ("en", ["velocity", "acceleration", "drag", "relative", "Coriolis"]),
])
def test_each_course_uses_its_own_terms(lang, terms):
    text = " ".join(messages(lang).values()).lower()
    for term in terms:
        assert term.lower() in text, (lang, term)
