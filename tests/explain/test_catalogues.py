"""The four Fluent catalogues parse, are complete (same keys, same variables), every key is
used by the code, every key the code uses exists, plurals are real plural forms, and each
course's own terms are there."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from fluent.syntax import FluentParser, ast as ftl

import kinematika.explain as explain_package
import kinematika.questions as questions_package
from kinematika.explain.catalogue import LANGS, LOCALES, VARIABLE, catalogue
from kinematika.explain.centres import SIDES
from kinematika.joints import KINDS
from kinematika.model.wording import PART_SUBSCRIPTS
from kinematika.questions import QUESTIONS, QuestionKind
from kinematika.questions.centres import FIXED

SOURCE = Path(explain_package.__file__).resolve().parent
# the question kinds write their names and their answers' parts in the explanation's words
SOURCES = [SOURCE, Path(questions_package.__file__).resolve().parent]
# keys built at run time from a name (f"kind.{step.kind}" ...): the families and their members
FAMILIES = {
    "kind": ["input", "RRR", "RRP", "RPR", "PRP", "other"],
    "joint": list(KINDS) + ["slot_fixed"],                  # every kind of joint has its name (kinds.kind_key)
    "shape": ["circle", "line", "disc", "plane", "curveshape", "camshape"],
    "cond": [k.name for k in KINDS.values() if not k.rolls] + ["slot_fixed"],  # rolling pairs are written out
    "centre.joint": [k.name for k in KINDS.values() if k.centre in FIXED] + ["revolute_fixed", "revolute_tied"],   # 29 (b)
    "centre.line": ["slot", "wheel", "normal", "slot_fixed"],
    "fig.normal": ["slot", "wheel", "normal", "slot_fixed"],   # the centres caption's lines (structure._normal_lines)
    "ask": [k.name for k in QUESTIONS.values() if type(k).label is QuestionKind.label],   # `ask.NAME`
    "ans": ["point", "direction", "center", "tangent", "slide"],
    "centre.proportional": ["between", "outside"],
    "centre.carried": ["between", "outside", "between_from", "outside_from"],
    "centre.parallel": ["between", "outside"],
    "pos": ["left", "right", "ahead", "behind", "open", "crossed"],
    "side": list(SIDES),                                      # the side a centre lies on (centres.side_of)
}


def messages(lang: str) -> dict[str, str]:
    """Each message's source text under its code key (dashes back to dots)."""
    resource = FluentParser().parse((LOCALES / f"{lang}.ftl").read_text(encoding="utf-8"))
    junk = [e for e in resource.body if isinstance(e, ftl.Junk)]
    assert not junk, (lang, junk[0].content[:200])
    text = (LOCALES / f"{lang}.ftl").read_text(encoding="utf-8")
    out = {}
    for entry in resource.body:
        if isinstance(entry, ftl.Message):
            span = entry.value.span
            out[entry.id.name.replace("-", ".")] = text[span.start:span.end]
    return out


def literals() -> set[str]:
    text = "\n".join(p.read_text(encoding="utf-8") for d in SOURCES for p in d.rglob("*.py"))
    return set(re.findall(r'"([a-zA-Z_]+\.[a-zA-Z_.]+)"', text))


def test_same_keys_in_every_language():
    keys = {lang: set(messages(lang)) for lang in LANGS}
    for lang in LANGS:
        assert keys[lang] == keys["en"], (lang, keys[lang] ^ keys["en"])


@pytest.mark.parametrize("lang", LANGS[1:])
def test_same_placeholders(lang):
    en, other = messages("en"), messages(lang)
    for key, text in en.items():
        # a list's count (`$seen_n`, `$through_n`: the renderer adds one for every list argument)
        # is the language's own, for its plural
        counts = {f"{v}_n" for v in VARIABLE.findall(text)}
        assert set(VARIABLE.findall(other[key])) - {"known_n", "joints_n", "bodies_n"} <= \
            set(VARIABLE.findall(text)) | {"known_n", "joints_n", "bodies_n"} | counts, (lang, key)
        assert set(VARIABLE.findall(text)) <= set(VARIABLE.findall(other[key])) | {"joints_n"}, (lang, key)
        assert other[key].strip(), (lang, key)


def test_no_unused_and_no_missing_keys():
    keys = set(messages("en"))
    used = {k for k in literals() if k in keys}
    source = "".join(p.read_text(encoding="utf-8") for d in SOURCES for p in d.rglob("*.py"))
    for family, members in FAMILIES.items():
        assert f'f"{family}.' + "{" in source, f"no key of the family {family} is built in the code"
        used |= {f"{family}.{m}" for m in members}
    assert keys - used == set(), f"unused keys: {sorted(keys - used)}"
    prefixes = ("sec.", "msg.", "col.", "data.", "fig.", "order.", "step.", "driver.", "input.",
                "other.", "rolling.", "dir.", "how.", "carry.", "sense.", "centre.", "centres.",
                "rates.", "fields.", "composition.", "pos.", "curvature.", "answers.", "structure.", "v.", "a.", "ask.", "ans.")
    wanted = {k for k in literals() if k.startswith(prefixes)}
    assert wanted - keys == set(), f"keys the code uses but no catalogue has: {sorted(wanted - keys)}"
    parts = {k for k in literals() if k.startswith("sub.")}       # the parts' subscripts: model.wording
    assert parts and parts <= set(PART_SUBSCRIPTS), sorted(parts - set(PART_SUBSCRIPTS))
    assert all(set(words) == set(LANGS) for words in PART_SUBSCRIPTS.values())


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


@pytest.mark.parametrize("lang", LANGS)
def test_no_pasted_plurals(lang):
    """Plurals come from the catalogue's plural forms, never as `degree(s)` or `condició(ons)`."""
    for key, text in messages(lang).items():
        assert not re.search(r"\w\((s|es|ons|ak|ek)\)", text), (lang, key)


@pytest.mark.parametrize("lang,one,two,many", [
    ("en", "one degree of freedom", "two degrees of freedom", "4 degrees of freedom"),
    ("es", "un grado de libertad", "dos grados de libertad", "4 grados de libertad"),
    ("ca", "un grau de llibertat", "dos graus de llibertat", "4 graus de llibertat"),
    ("eu", "askatasun-gradu bat du", "bi askatasun-gradu ditu", "4 askatasun-gradu ditu"),
])
def test_plural_forms_chosen_by_count(lang, one, two, many):
    """A small count in words, as a teacher writes it ("dos grados de libertad", a Spanish
    reader beside "un grado": stop 46), a larger one in digits."""
    cat = catalogue(lang)
    args = {"n": 6, "moving": 2, "rank": 5, "conditions": 1}
    assert one in cat.format("structure.dof", {**args, "dof": 1})
    assert two in cat.format("structure.dof", {**args, "dof": 2})
    assert many in cat.format("structure.dof", {**args, "dof": 4})


def test_catalan_elides_before_vowel_sounds():
    from kinematika.explain.catalogue import elision
    assert [elision(n) for n in ("O4", "A", "F", "B", "AB", "ring", "arm", "handle", "P", "S1", "R")] == \
        ["vowel", "vowel", "other", "other", "vowel", "other", "vowel", "vowel", "other", "other", "other"]   # F, S1, R: as the notes (28 e)
