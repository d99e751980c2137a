"""`grade` on synthetic classes: answers planted from the hand derivations (right ones, each
usual mistake made by hand, and numbers that are no mistake), each within the rounding a
student makes. Every planted mistake must be named, no right answer diagnosed."""
from __future__ import annotations

import math
import random
import re

import pytest

from kinematika.errors import KinematikaError
from kinematika.exercise import KINDS, grade

from . import derive
from .conftest import four_bar_data, p_pair_data

TOLERANCE = 0.01


def p_pair_worlds(stated):
    """Each mistake's hand values for one P-pair variant: kind -> list of row dicts."""
    data = p_pair_data(stated)
    worlds = {"right": [derive.p_pair(**data)]}
    worlds["coriolis-omitted"] = [derive.p_pair(**data, c=0)]
    worlds["coriolis-doubled"] = [derive.p_pair(**data, c=2)]
    worlds["normal-omitted"] = [derive.p_pair(**data, n=0)]
    worlds["sense-reversed"] = [derive.p_pair(**{**data, "w": -data["w"]}),
                                derive.p_pair(**{**data, "al": -data["al"]})]
    worlds["drag-as-absolute"] = [derive.p_pair_drag(data["s"], data["beta"], data["w"], data["al"])]
    degrees = {**data, "beta": math.degrees(data["beta"])}        # 33° read as 33 rad
    worlds["degrees-as-radians"] = [derive.p_pair(**degrees)]
    metres = {**data, **{k: 1000 * data[k] for k in ("s", "ex", "ey")}}
    worlds["units-mm-as-m"] = [derive.p_pair(**metres)]
    return _rows(worlds)


def four_bar_worlds(stated):
    data = four_bar_data(stated)
    worlds = {"right": [derive.four_bar(**data)], "normal-omitted": [derive.four_bar(**data, n=0)],
              "sense-reversed": [derive.four_bar(**{**data, "w2": -data["w2"]})],
              "degrees-as-radians": [derive.four_bar(**{**data, "theta": math.degrees(data["theta"])})],
              "units-mm-as-m": [derive.four_bar(**{**data, **{k: 1000 * data[k] for k in "dabc"}})]}
    return _rows(worlds)


def _rows(worlds):
    out = {kind: [derive.rows(w) for w in ws if w is not None] for kind, ws in worlds.items()}
    right = out["right"][0]
    swapped = {}
    for q, (_, size) in right.items():
        stem, _, axis = q.rpartition(".")
        if axis in ("x", "y"):
            swapped[q] = right[f"{stem}.{'y' if axis == 'x' else 'x'}"][0], size
    out["components-swapped"] = [swapped]
    return out


def _matches(value, target, tolerance):
    x, size = target
    return abs(value - x) <= tolerance * size


def expected_diagnosis(worlds, question, value, tolerance):
    """What grade must say of `value` by the hand values and the box's tolerance: right, else
    the first kind (in the contract's order) whose value it matches and that differs from the
    right one."""
    right = worlds["right"][0][question]
    if _matches(value, right, tolerance):
        return True, None
    for kind in KINDS:
        for rows in worlds.get(kind, []):
            wrong = rows.get(question)
            if wrong is not None and not _matches(wrong[0], right, tolerance) and _matches(value, wrong, tolerance):
                return False, kind
    return False, None


def plant(ex, worlds_of, students, seed):
    """A class: student i gets variant i mod N and makes one usual mistake throughout (in turn,
    every kind), or none, or writes numbers no mistake gives; every value rounded as a
    student would (within a third of its box's margin), typed with a point or a comma."""
    rng = random.Random(seed)
    rows, planted = [], {}
    choices = [None, *KINDS, "nonsense"]
    for i in range(students):
        v = ex.variants[i % len(ex.variants)]
        worlds = worlds_of(v.stated)
        right = worlds["right"][0]
        kind = choices[(i + i // len(ex.variants)) % len(choices)]
        world = rng.choice(worlds[kind]) if worlds.get(kind) else None
        tolerance = {r.question: v.tolerance_of(r) for r in v.rows}
        for question, (value, size) in right.items():
            if kind == "nonsense":
                target = (value * 1.37 + 0.11 * size + 1.0, size)
            else:
                target = world.get(question, (value, size)) if world else (value, size)
            answer = target[0] + rng.uniform(-1, 1) * tolerance[question] / 3 * target[1]
            text = repr(answer) if rng.random() < 0.8 else repr(answer).replace(".", ",").replace("-", "−")
            rows.append(f"s{i:03d},{v.number},{question},\"{text}\"")
            planted[(f"s{i:03d}", question)] = (kind, answer, worlds, tolerance[question])
    return "student,variant,question,value\n" + "\n".join(rows) + "\n", planted


def sense_kept(student, question, value, planted):
    """`sense-reversed` stands only when no answer the student got right is one the reversed
    sense would have changed (a reversed relative velocity beside a right ω is not a reversed ω)."""
    _, _, worlds, _ = planted[(student, question)]
    right = worlds["right"][0]
    mine = {q: p for (s, q), p in planted.items() if s == student}
    right_ones = [q for q, (_, v, w, tol) in mine.items() if expected_diagnosis(w, q, v, tol)[0]]
    matching = [w for w in worlds["sense-reversed"] if question in w
                and _matches(value, w[question], planted[(student, question)][3])]
    return any(all(_matches(w[q][0], right[q], mine[q][3]) for q in right_ones if q in w) for w in matching)


def check(result, planted):
    kinds_found = set()
    for (student, question), (kind, value, worlds, tolerance) in planted.items():
        mark = next(a for a in result["students"][student]["answers"] if a["question"] == question)
        correct, diagnosis = expected_diagnosis(worlds, question, value, tolerance)
        if diagnosis == "sense-reversed" and not sense_kept(student, question, value, planted):
            diagnosis = None
        assert (mark["correct"], mark["diagnosis"]) == (correct, diagnosis), (student, question, kind)
        if kind is None:
            assert mark["correct"] and mark["diagnosis"] is None
        if mark["diagnosis"]:
            kinds_found.add(mark["diagnosis"])
    return kinds_found


def test_a_class_of_200_has_every_planted_mistake_named_and_no_right_answer_diagnosed(p_pair_exercise, tmp_path):
    text, planted = plant(p_pair_exercise, p_pair_worlds, 200, 2026)
    answers = tmp_path / "answers.csv"
    answers.write_text(text, encoding="utf-8")
    result = grade(p_pair_exercise, answers, carry=False)
    found = check(result, planted)
    assert found == set(KINDS)                   # every kind planted, and named
    named_as_planted = sum(1 for (s, q), (kind, _, _, _) in planted.items() if kind in KINDS and next(
        a for a in result["students"][s]["answers"] if a["question"] == q)["diagnosis"] == kind)
    changed = sum(1 for (s, q), (kind, value, worlds, tol) in planted.items() if kind in KINDS
                  and not _matches(value, worlds["right"][0][q], tol))
    assert named_as_planted >= 0.9 * changed
    # the summary counts what the answers say
    for question, summary in result["questions"].items():
        marks = [a for s in result["students"].values() for a in s["answers"] if a["question"] == question]
        assert summary["right"] == sum(a["correct"] for a in marks)
    right_students = {s for (s, _), (kind, *_) in planted.items() if kind is None}
    assert all(result["students"][s]["score"] == 1 for s in right_students)


def test_a_four_bar_class_has_its_mistakes_named(four_bar_exercise, tmp_path):
    text, planted = plant(four_bar_exercise, four_bar_worlds, 60, 7)
    answers = tmp_path / "answers.csv"
    answers.write_text(text, encoding="utf-8")
    found = check(grade(four_bar_exercise, answers, carry=False), planted)
    assert {"normal-omitted", "sense-reversed", "units-mm-as-m", "components-swapped"} <= found


def test_a_mistake_that_changes_nothing_names_nothing(four_bar_exercise, tmp_path):
    # the four-bar has no sliding pair: the Coriolis mistakes give the right values, which stay right
    v = four_bar_exercise.variants[0]
    answers = tmp_path / "a.csv"
    answers.write_text("student,variant,question,value\n" + "".join(
        f"x,{v.number},{r.question},{r.value!r}\n" for r in v.rows))
    result = grade(four_bar_exercise, answers)["students"]["x"]
    assert result["score"] == 1 and all(a["diagnosis"] is None for a in result["answers"])


def test_a_file_without_the_columns_is_one_error(p_pair_exercise, tmp_path):
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question\nx,1,q1\n")
    with pytest.raises(KinematikaError) as err:
        grade(p_pair_exercise, answers)
    assert err.value.where == "answers.csv" and "value" in err.value.message


@pytest.mark.parametrize("bad, why", [
    ("x,99,q1,1", "no variant 99"),
    ("x,1,q9,1", "'q9' is not asked"),
    ("x,1,q1,2", "twice (first on line 2)"),
    (",1,q1,2", "without a student"),
    ("x,one,q1,2", "is not a number"),
    ("x,1,q1,1,2,3", "6 fields"),
])
def test_a_row_that_cannot_be_read_is_listed_with_its_line_and_the_others_are_graded(p_pair_exercise, tmp_path, bad, why):
    v = p_pair_exercise.variants[0]
    right = {r.question: r.value for r in v.rows}
    answers = tmp_path / "answers.csv"
    answers.write_text(f"student,variant,question,value\nx,1,q1,{right['q1']!r}\n{bad}\n"
                       f"y,1,q2,{right['q2']!r}\n", encoding="utf-8")
    result = grade(p_pair_exercise, answers)
    assert [u["line"] for u in result["unreadable"]] == [3]
    assert why in result["unreadable"][0]["error"]
    assert result["students"]["x"]["answers"][0]["correct"] and result["students"]["y"]["answers"][0]["correct"]


# the same rows, as a Basque and a Catalan teacher read them (the words written here by hand)
SAID = {"eu": ["ikaslerik gabeko errenkada", "bi aldiz erantzuten du", "lehen aldiz 2. lerroan", "6 eremu",
               "ez da irakurri", "goiburuak 4 ditu"],
        "ca": ["una fila sense estudiant", "respon dues vegades", "a la línia 2", "6 camps", "no llegida",
               "la capçalera en té 4"]}


@pytest.mark.parametrize("lang", ["eu", "ca"])
def test_the_rows_not_read_and_the_summary_are_said_in_the_teachers_language(p_pair_exercise, tmp_path, lang):
    from kinematika.errors import speaking
    from kinematika.exercise.grading import summary_text

    v = p_pair_exercise.variants[0]
    answers = tmp_path / "answers.csv"
    answers.write_text(f"student,variant,question,value\nx,1,q1,{v.rows[0].value!r}\n,1,q1,2\nx,1,q1,3\n"
                       "x,1,q1,1,2,3\n", encoding="utf-8")
    with speaking(lang):
        result = grade(p_pair_exercise, answers)
        text = summary_text(result, "answers.csv")
    errors = " ".join(u["error"] for u in result["unreadable"])
    assert [u["line"] for u in result["unreadable"]] == [3, 4, 5]
    for words in SAID[lang]:
        assert words in text, (words, text)
    for english in ("without", "twice", "fields", "not read", "student    "):
        assert english not in text and english not in errors
    heading = {"eu": "ikaslea", "ca": "estudiant"}[lang]
    assert re.search(rf"^{heading} +{dict(eu='aldaera', ca='variant')[lang]} +nota$", text, re.M)
    # q1 right, one of the P pair's six questions, each the same weight: 1/6 = 16,7 %
    assert len({r.question.split(".")[0] for r in v.rows}) == 6
    assert re.search(r"^x +1 +" + {"eu": r"%16,7", "ca": r"16,7 %"}[lang] + "$", text, re.M), text


def test_blank_and_unreadable_answers_keep_what_was_typed(p_pair_exercise, tmp_path):
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\nx,1,q1,\nx,1,q2,abc\n")
    result = grade(p_pair_exercise, answers)["students"]["x"]
    assert result["score"] == 0 and result["answers"] == [
        {"variant": 1, "question": "q2", "typed": "abc", "value": None, "correct": False, "diagnosis": None}]
