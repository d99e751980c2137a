"""Issue 30, nineteenth round (a): one symbol for a relative vector on a page. The steps
wrote v_{B∈N rel M}, the composition of motions v_{rel,B}, the answers both — two names
of one vector read as two vectors. The composition and the answers now write it as the
steps do, both bodies named, joined by the model's word (`notation: {relative: WORD}`,
the slides' rel), else the language's."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
import yaml

import kinematika
from kinematika.errors import KinematikaError
from kinematika.explain import build, render

from .helpers import LANGS, NOTES_SEEDS, over, rendered, model_tree

# the composition's old point-only form of the relative part (v_{rel,B}, a_{REL,B})
POINT_ONLY = re.compile(r"\b[va]_\{(?:rel|REL),[^}]*\}")
# a relative vector with both bodies, in any language's word
BOTH = re.compile(r"\b[va]_\{[^{}∈ ]+∈[^{}]+? (?:rel\.?|REL) [^{}]+\}")


@over(name=NOTES_SEEDS, lang=LANGS)
def test_relative_vector_has_one_symbol(name: str, lang: str) -> None:
    page = rendered(name, lang, drawings=False)
    assert not POINT_ONLY.findall(page), (name, lang, POINT_ONLY.findall(page))
    rows = [line for line in page.splitlines() if line.startswith("| ") and "; " in line and "∈" in line]
    steps = page.split("\n## ")[:-1]          # every section but the answers
    for row in rows:
        for sym in BOTH.findall(row):
            assert any(sym in s for s in steps), (name, lang, sym)


@pytest.mark.parametrize("lang", LANGS)
def test_slides_coriolis_step_composition_answers_alike(lang: str) -> None:
    """Slides 4.3 (P pair with Coriolis): B∈N slides on the guide M. Step 2's
    v_B∈rocker = v_B∈M + v_{B∈N rel M}; the composition's relative part and the answers'
    row write the same v_{B∈N rel M} and a_{B∈N rel M}, with the slides' word rel."""
    page = rendered("seed_001_p_pair_coriolis", lang, drawings=False)
    answers = page.split("\n## ")[-1]
    composition = page.split("\n## ")[-2]
    for level in "va":
        sym = f"{level}_{{B∈N rel M}}"
        assert sym in composition and sym in answers, (lang, sym)
    assert "∈N rel. M" not in page, lang


def _model(tmp_path: Path, word: object) -> Path:
    spec = model_tree("seed_001_p_pair_coriolis")
    spec["notation"]["relative"] = word
    out = tmp_path / "m.yaml"
    out.write_text(yaml.safe_dump(spec, allow_unicode=True), encoding="utf-8")
    return out


def test_notation_relative_word_is_used(tmp_path: Path) -> None:
    """`notation: {relative: REL}` (the C5 chapter's word) joins the bodies on the page."""
    doc = build(kinematika.solve(_model(tmp_path, {"ca": "REL", "eu": "rel"})))
    ca, eu = render(doc, "ca", "md", drawings=False), render(doc, "eu", "md", drawings=False)
    assert "v_{B∈N REL M}" in ca and "rel. M" not in ca
    assert "v_{B∈N rel M}" in eu


@pytest.mark.parametrize("word", ["r e l", "relatiu_a", 3])
def test_notation_relative_word_shape(tmp_path: Path, word: object) -> None:
    with pytest.raises(KinematikaError) as err:
        kinematika.solve(_model(tmp_path, word))
    assert "notation.relative" in str(err.value)
