"""quiz.xml read as Moodle's importer reads it (tests/exercise/moodle_rules.py, ported from
the public moodle repository): the issue's quizzes of variants of the P pair and of a
four-bar (`conftest.COUNT` each), and a quiz with its worked solutions as general feedback."""
from __future__ import annotations

import base64
import html
import math
import re
import xml.etree.ElementTree as ET

import pytest
from hypothesis import given, strategies as st

from kinematika.exercise.catalogue import catalogue
from kinematika.exercise.figure import statement_figure
from kinematika.exercise.folder import key_csv
from kinematika.exercise.key import floors_of
from kinematika.exercise.moodle import cloze_text, quiz_xml
from kinematika.exercise.solutions import solution_html

from .conftest import COUNT
from .moodle_rules import extract, validate

MISTAKES = ("coriolis-omitted", "coriolis-doubled", "normal-omitted", "sense-reversed", "drag-as-absolute",
            "degrees-as-radians", "units-mm-as-m", "components-swapped")


def quiz(ex, solutions=False):
    figures, mistakes, worked = {}, {}, {}
    for v in ex.variants:
        figures[v.number] = statement_figure(ex, v, ex.lang)
        mistakes[v.number] = v.mistaken
        if solutions:
            worked[v.number] = solution_html(ex, v, ex.lang)
    return quiz_xml(ex, figures, worked if solutions else None, mistakes)


@pytest.fixture(scope="module")
def quizzes(p_pair_exercise, four_bar_exercise, folders):
    return [(ex, (folders[name] / "quiz.xml").read_text(encoding="utf-8"))
            for name, ex in (("p_pair", p_pair_exercise), ("four_bar", four_bar_exercise))]


def key_of(ex, column=2):
    """key.csv as written: {variant: {question: value text}} (or its tolerance, `column` 3)."""
    out: dict = {}
    for line in key_csv(ex).splitlines()[1:]:
        cells = line.split(",")
        out.setdefault(int(cells[0]), {})[cells[1]] = cells[column]
    return out


def box_weights(questions):
    """Each box's grade when every question (q2, whatever its parts) weighs the same: the
    least whole numbers n / (the question's count of boxes)."""
    counts = {}
    for q in questions:
        counts[q.split(".")[0]] = counts.get(q.split(".")[0], 0) + 1
    whole = math.lcm(*counts.values())
    weights = {q: whole // counts[q.split(".")[0]] for q in questions}
    common = math.gcd(*weights.values())
    return {q: w // common for q, w in weights.items()}


def test_the_quizzes_are_moodle_xml_with_one_cloze_question_per_variant(quizzes):
    for _, text in quizzes:
        root = ET.fromstring(text.encode())
        assert root.tag == "quiz"
        questions = root.findall("question")
        assert questions[0].get("type") == "category"
        assert questions[0].findtext("category/text").startswith("$course$/top/")
        cloze = questions[1:]
        assert len(cloze) == COUNT and all(q.get("type") == "cloze" for q in cloze)
        names = [q.findtext("name/text") for q in cloze]
        ids = [q.findtext("idnumber") for q in cloze]
        assert all(names) and len(set(names)) == COUNT and len(set(ids)) == COUNT
        for q in cloze:
            assert q.find("questiontext").get("format") == "html"
            assert q.find("generalfeedback").get("format") == "html"
            assert 0 <= float(q.findtext("penalty")) <= 1 and q.findtext("hidden") == "0"


def test_question_texts_are_cdata_and_their_figures_are_files_they_show(quizzes):
    for _, text in quizzes:
        assert text.count("<questiontext format=\"html\">\n      <text><![CDATA[") == COUNT
        for q in ET.fromstring(text.encode()).findall("question[@type='cloze']"):
            body = q.findtext("questiontext/text")
            files = q.findall("questiontext/file")
            assert len(files) == 1
            f = files[0]
            assert f.get("path") == "/" and f.get("encoding") == "base64"
            assert base64.b64decode(f.text, validate=True)[:8] == b"\x89PNG\r\n\x1a\n"
            shown = set(re.findall(r"@@PLUGINFILE@@/([^\"'\s>]+)", body))
            assert shown == {f.get("name")}


def test_every_part_is_a_numerical_subquestion_of_the_keys_value_and_absolute_margin(quizzes):
    for ex, text in quizzes:
        key, tolerances = key_of(ex), key_of(ex, 3)
        floors = {v.number: {r.question: floors_of(v.solution)[r.kind] for r in v.rows} for v in ex.variants}
        mistake_words = {catalogue(ex.lang).format(f"mistake-{k}") for k in MISTAKES}
        right_words = catalogue(ex.lang).format("feedback-right")
        for number, q in enumerate(ET.fromstring(text.encode()).findall("question[@type='cloze']"), start=1):
            rest, subs = extract(q.findtext("questiontext/text"))
            assert validate(subs) == []
            assert not re.search(r"\{[0-9]*:[A-Z_]+:", rest)          # nothing left that reads as Cloze
            questions = list(key[number])
            assert len(subs) == len(questions)
            values = {qn: float(v) for qn, v in key[number].items()}
            weights = box_weights(questions)
            for question, sub in zip(questions, subs):
                assert sub.qtype == "numerical" and sub.mark == str(weights[question])
                right, *wrong = sub.alternatives
                assert right.fraction == 1 and right.answer == key[number][question]
                assert right.feedback == right_words
                stem = question.rsplit(".", 1)[0] if "." in question else question
                size = math.hypot(*[x for qn, x in values.items() if qn == question or qn.startswith(stem + ".")])
                # absolute: the box's relative tolerance (key.csv) times the size, never below
                # 1 % of the mechanism's scale for the quantity (key.floors_of)
                floor = floors[number][question]
                relative = float(tolerances[number][question])
                assert float(right.tolerance) == pytest.approx(relative * max(size, floor), rel=1e-5)
                assert float(right.tolerance) >= 0.005 * size * (1 - 1e-12)
                for w in wrong:
                    assert w.fraction == 0 and w.feedback in mistake_words
                    assert abs(float(w.answer) - float(right.answer)) > float(right.tolerance)


def test_the_p_pair_quiz_names_the_coriolis_mistakes_where_they_change_the_answer(quizzes):
    ex, text = quizzes[0]
    words = catalogue("en").format("mistake-coriolis-omitted")
    first = ET.fromstring(text.encode()).findall("question[@type='cloze']")[0]
    _, subs = extract(first.findtext("questiontext/text"))
    by_question = dict(zip(key_of(ex)[1], subs))
    assert any(w.feedback == words for w in by_question["q2"].alternatives[1:])       # α_EB
    assert not any(w.feedback == words for w in by_question["q1"].alternatives[1:])   # ω_EB: no


def test_worked_solutions_are_the_general_feedback(p_pair_exercise):
    from .conftest import P_PAIR, P_PAIR_VARY, make

    ex = make(P_PAIR, P_PAIR_VARY, 2, 11, "eu")
    text = quiz(ex, solutions=True)
    for q in ET.fromstring(text.encode()).findall("question[@type='cloze']"):
        feedback = q.findtext("generalfeedback/text")
        assert feedback.startswith('<div class="kinematika-solution"><style>')
        assert "<svg" in feedback and "<body" not in feedback and "<html" not in feedback
        assert "Abiadurak" in feedback                    # the Basque explanation's section
        styles = re.search(r"<style>(.*?)</style>", feedback, re.S).group(1)
        assert all(rule.startswith(".kinematika-solution") for rule in re.findall(r"[^{}]+(?=\{)", styles))


@given(st.text(alphabet=st.sampled_from(list("ab }~#\\\"&<>%=:1.")), max_size=30))
def test_a_feedback_text_reaches_moodle_as_its_html(text):
    _, subs = extract("{1:NUMERICAL:=1.5:0.1#" + cloze_text(text) + "~%0%2:0.1#" + cloze_text(text) + "}")
    # the feedback as Moodle stores it (HTML) shows the text as written
    assert [html.unescape(a.feedback) for a in subs[0].alternatives] == [text] * 2
    assert all("<" not in a.feedback for a in subs[0].alternatives)
    assert [a.answer for a in subs[0].alternatives] == ["1.5", "2"]


def test_split_writes_a_question_per_graded_part_in_a_category_each(p_pair_exercise):
    from kinematika.exercise.moodle import QuizOptions

    figures = {v.number: b"\x89PNG\r\n\x1a\n" for v in p_pair_exercise.variants}
    text = quiz_xml(p_pair_exercise, figures, None, None, QuizOptions(split=True))
    root = ET.fromstring(text.encode())
    categories = [q.findtext("category/text") for q in root.findall("question[@type='category']")]
    assert categories == [f"$course$/top/kinematika/P pair with Coriolis/question {k}" for k in range(1, 7)]
    cloze = root.findall("question[@type='cloze']")
    assert len(cloze) == 6 * COUNT and len({q.findtext("idnumber") for q in cloze}) == 6 * COUNT
    key = key_of(p_pair_exercise)
    for k in range(6):                               # part k+1 of variant 1 asks that question's numbers
        _, subs = extract(cloze[COUNT * k].findtext("questiontext/text"))
        asked = [q for q in key[1] if q.split(".")[0] == f"q{k + 1}"]
        assert [s.alternatives[0].answer for s in subs] == [key[1][q] for q in asked]
        assert validate(subs) == []


def test_a_unit_penalty_gives_part_credit_for_the_right_number_in_another_unit(p_pair_exercise):
    from kinematika.exercise.moodle import QuizOptions

    v = p_pair_exercise.variants[0]
    figures = {x.number: b"" for x in p_pair_exercise.variants}
    text = quiz_xml(p_pair_exercise, figures, None, None, QuizOptions(unit_penalty=0.4))
    first = ET.fromstring(text.encode()).findall("question[@type='cloze']")[0]
    _, subs = extract(first.findtext("questiontext/text"))
    by_question = dict(zip([r.question for r in v.rows], subs))
    right = {r.question: r.value for r in v.rows}
    speed = by_question["q5.x"].alternatives                         # a velocity in m/s
    in_mm = [a for a in speed if "mm/s" in a.feedback]
    assert len(in_mm) == 1 and in_mm[0].fraction == pytest.approx(0.6)
    assert float(in_mm[0].answer) == pytest.approx(1000 * right["q5.x"], rel=1e-12)
    rate = by_question["q1"].alternatives                            # ω in rad/s: rpm, °/s
    rpm = [a for a in rate if "rpm" in a.feedback]
    assert len(rpm) == 1 and float(rpm[0].answer) == pytest.approx(right["q1"] * 30 / math.pi, rel=1e-12)
    assert validate(subs) == []
    plain = quiz_xml(p_pair_exercise, figures, None)                       # without the option: none
    assert "mm/s" not in "".join(a.feedback for s in extract(ET.fromstring(plain.encode()).findall(
        "question[@type='cloze']")[0].findtext("questiontext/text"))[1] for a in s.alternatives)
