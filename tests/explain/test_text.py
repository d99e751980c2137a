"""The explanation of one example of each kind (every example in a deep run), in every
language, as Markdown and as HTML, reads as text a teacher wrote: no catalogue key, no fragment of the model's syntax, no English word in
a translated text, no `(s)`-style plural."""
from __future__ import annotations

import html
import re

import pytest

from kinematika.explain.catalogue import LANGS, catalogue

from tests.conftest import KINDS, sampled

from .helpers import ALL, body_of, explained, render_of

NAMES = sampled(ALL, KINDS)

# the model's syntax and the code's internals, as they must never reach a reader
SYNTAX = [
    (r"\w@\w", "a material point written as in the model (A@crank)"),
    (r"(?m)\b(relative_to|moving|decompose|velocity|acceleration|omega|alpha|icr|curvature|contact|axis|pole|"
     r"intrinsic)\s*:\s*[\w@]+\s*(,|\||$)", "a question as written"),
    (r"\b(body_a|body_b|tangential_vector|normal_vector|rates_summary)\b", "an answer's key"),
    (r"\b(geometric|velocity|acceleration|total|drag|relative|coriolis)\.(velocity|acceleration|drag|relative|total|coriolis)\b",
     "an answer's key path"),
    (r"\b(deg|sqrt|atan2?)\(|\b(cos|sin|tan)\([^)]*(deg\(|\*)", "an expression as written"),   # sin(β) is math
    (r"\w\*\w|\*\*", "a product written as in the model"),
    (r"\b(Abs|sign|Piecewise|atan2)\(", "a function written as sympy prints it"),
    (r"\bpi\b", "π written as pi"),
    (r"\b(None|True|False)\b", "a Python value"),
    (r"\b(Name|Msg|Sym|Value|Inline)\(", "a Python object"),
    (r"\{\s*\$\w+\s*\}|(?<![_^])\{\s*\w+\s*\}(?!\S)", "a placeholder"),     # not a subscript or superscript in braces: v_{A∈2/3}, CI_{plat}, J^{geom}
]
PASTED_PLURAL = re.compile(r"\w\((s|es|ons|ak|ek)\)")
WORD = re.compile(r"[A-Za-zÀ-ÿ’']+")
# words shared by the languages or names of people and methods (kept in every language)
SHARED = {"normal", "Coriolis", "Assur", "Aronhold", "Kennedy", "RRR", "RRP", "RPR", "PRP", "rad", "total",
          "geom", "Cor", "ω", "α"}


def plain_text(text: str, fmt: str) -> str:
    """What a reader reads: markup, inline images and the model's own title taken away."""
    if fmt == "html":
        text = re.sub(r"<title>.*?</title>|<style>.*?</style>", " ", text, flags=re.S)
        text = re.sub(r"<h1>.*?</h1>", " ", text, count=1, flags=re.S)
        text = html.unescape(re.sub(r"<[^>]+>", " ", text))
    else:
        text = re.sub(r"\]\[fig-\d+\]", "]", body_of(text))
        text = re.sub(r"^# .*$", " ", text, count=1, flags=re.M)
    return text


def english_words(lang: str) -> set[str]:
    """Words of the English catalogue that the other language does not also use."""
    def words(l: str) -> set[str]:
        return {w.lower() for w in WORD.findall(catalogue(l).source) if len(w) > 3}
    return words("en") - words(lang) - {w.lower() for w in SHARED}


def model_words(sol, lang: str | None = None) -> set[str]:
    """The model's own names (bodies, points, joints, parameters): the user's words."""
    m = sol.model
    names = list(m.bodies) + list(sol.inst.points) + [j.id for j in m.joints] + list(m.parameters)
    if lang is not None:                 # the model's own words in the language (names.LANG)
        w = m.wording
        names += list(w.points.get(lang, {}).values()) + list(w.parameters.get(lang, {}).values())
        names += w.data.get(lang, []) + w.notes.get(lang, []) + list(w.bodies.get(lang, {}).values())
    return {w.lower() for n in names for w in WORD.findall(n)}


@pytest.mark.parametrize("fmt", ["md", "html"])
@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", NAMES)
def test_reads_as_text(name, lang, fmt):
    sol, doc = explained(name)
    text = plain_text(render_of(doc, lang, fmt, drawings=False), fmt)
    keys = set(catalogue("en").keys())
    keys |= {k.replace("-", ".") for k in keys}
    found = set(re.findall(r"[A-Za-z][\w]*(?:[-.][\w]+)+", text)) & keys
    assert not found, f"catalogue keys in the text: {sorted(found)}"
    for pattern, what in SYNTAX:
        m = re.search(pattern, text)
        assert m is None, f"{what}: …{text[max(0, m.start() - 60):m.end() + 60]}…"
    if fmt == "html":      # Markdown writes every subscript ω_2; a page must set it as one
        m = re.search(r"[ωαθφu]_\w", text)
        assert m is None, f"a subscript written with an underscore: …{text[max(0, m.start() - 60):m.end() + 60]}…"
    m = PASTED_PLURAL.search(text)
    assert m is None, f"a pasted plural: …{text[max(0, m.start() - 40):m.end() + 20]}…"
    if lang != "en":
        english = english_words(lang) - model_words(sol, lang)
        stray = sorted({w for w in WORD.findall(text) if w.lower() in english})
        assert not stray, f"English words in the {lang} text: {stray}"


BAR = re.compile(r"(?<!\\)\|")


@pytest.mark.parametrize("name", NAMES)
def test_markdown_tables_keep_their_columns(name):
    """Every row of a Markdown table has the header's cells: a formula's bars |x| are
    escaped (the tricycle's speed √2·v₀·|L − s|/(2·L) split its row in two cells)."""
    _, doc = explained(name)
    lines = render_of(doc, "en", "md", drawings=False).splitlines()
    for i, line in enumerate(lines[:-1]):
        if line.startswith("| ") and lines[i + 1].startswith("| ---"):
            header = len(BAR.findall(line))
            for row in lines[i + 2:]:
                if not row.startswith("|"):
                    break
                assert len(BAR.findall(row)) == header, row[:200]
