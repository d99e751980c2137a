"""Every word a student of a Basque or Catalan class reads is in that language, with the
model's names: the quiz's questions, the sheets and the worked solutions of the two exercises
made of the notes' problems (the quick-return and the epicyclic train). No raw key
(`tangential_vector`), no body's id (`planet1`, `carrier`, `ground`), no English word of the
catalogues, and the Moodle category named after the problem."""
from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

from kinematika.exercise import make_exercise
from kinematika.exercise.moodle import question_text, quiz_xml
from kinematika.exercise.sheets import key_html, sheets_html, students_for
from kinematika.exercise.solutions import solution_html
from kinematika.model.files import load_model

from tests.conftest import EXAMPLES

SRC = Path(__file__).resolve().parents[2] / "src" / "kinematika"
EXERCISES = {"quick_return": ["th=20:160:5", "w=5:15:1"], "epicyclic": ["r=30:80:5", "w=2:20:1"]}
# English words a wrong page would show that no catalogue has (the bodies' ids of the two models)
IDS = {"ground", "crank", "rocker", "link", "ram", "carrier", "sun", "ring", "planet"}


def words(path: Path) -> set[str]:
    """The words of a Fluent catalogue's messages (its placeholders and selectors left out)."""
    text = re.sub(r"\{\s*\$\w+\s*\}|\{[^}]*->|^#.*$", " ", path.read_text(encoding="utf-8"), flags=re.M)
    return {w.lower() for w in re.findall(r"[A-Za-zÀ-ÿ·’']{3,}", text)}


def catalogue_words(lang: str) -> set[str]:
    return set().union(*(words(SRC / part / "locales" / f"{lang}.ftl") for part in ("exercise", "explain", "errors")))


def shown_text(page: str) -> str:
    """What a reader sees of an HTML page: no style, script or figure markup, no tags, no
    Cloze fields, entities decoded. The key's column of answer ids (`q6.normal_vector.x`,
    set as code: what the teacher's answers.csv names) is an identifier, not a word."""
    page = re.sub(r"<style.*?</style>|<svg.*?</svg>|<script.*?</script>|<code class=\"id\">[^<]*</code>", " ",
                  page, flags=re.S)
    page = re.sub(r"\{\d*:NUMERICAL:[^}]*\}", " ", page)
    return html.unescape(re.sub(r"<[^>]+>", " ", page))


@pytest.fixture(scope="module", params=[(m, lang) for m in EXERCISES for lang in ("eu", "ca")],
                ids=lambda p: f"{p[0]}-{p[1]}")
def pages(request):
    name, lang = request.param
    path = EXAMPLES / "exercises" / f"{name}.yaml"
    ex = make_exercise(load_model(path), EXERCISES[name], 2, 11, lang, source=path)
    v = ex.variants[0]
    solution = solution_html(ex, v, lang)
    figures = {x.number: b"" for x in ex.variants}
    quiz = quiz_xml(ex, figures, {v.number: solution})
    return ex, lang, quiz, [question_text(ex, v, lang, v.mistaken), sheets_html(ex, figures, students_for(ex)),
                            key_html(ex, figures, {v.number: solution}), solution]


def test_no_english_word_and_no_raw_key_in_a_basque_or_catalan_class(pages):
    ex, lang, _, texts = pages
    english = (catalogue_words("en") | IDS) - catalogue_words(lang)
    for page in texts:
        text = shown_text(page)
        found = {w.lower() for w in re.findall(r"[A-Za-zÀ-ÿ·’']{3,}", text)}
        assert not found & english, sorted(found & english)
        assert not re.findall(r"\b[a-z]+_[a-z_]+\b", text)                   # tangential_vector
        assert not re.search(r"\bplanet\d|\bq-\w|\bpart-\w|\bask-\w", text)  # ids and catalogue keys


def test_the_models_names_are_the_ones_read(pages):
    ex, lang, quiz, texts = pages
    names = ex.model.wording.bodies[lang]
    question = shown_text(texts[0])
    for q in ex.model.questions:
        if q.kind in ("omega", "alpha", "icr"):                  # about a body: named as the notes name it
            name = names[str(q.target)]
            assert re.sub(r"^(el|la|els|les) ", "", name) in question, (name, question)
    category = re.search(r"<category>\s*<text>([^<]+)</text>", quiz).group(1)
    assert category == f"$course$/top/kinematika/{ex.model.wording.title(lang, '')}" and "seed" not in category
