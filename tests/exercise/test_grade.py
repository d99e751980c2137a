"""`grade` on synthetic classes: answers planted from the hand derivations (right ones, each
usual mistake made by hand, and numbers that are no mistake), each within the rounding a
student makes. Every planted mistake must be named, no right answer diagnosed."""
from __future__ import annotations

import math
import random

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


def _matches(value, target):
    x, size = target
    return abs(value - x) <= TOLERANCE * size


def expected_diagnosis(worlds, question, value):
    """What grade must say of `value` by the hand values: right, else the first kind (in the
    contract's order) whose value it matches and that differs from the right one."""
    right = worlds["right"][0][question]
    if _matches(value, right):
        return True, None
    for kind in KINDS:
        for rows in worlds.get(kind, []):
            wrong = rows.get(question)
            if wrong is not None and not _matches(wrong[0], right) and _matches(value, wrong):
                return False, kind
    return False, None


def plant(ex, worlds_of, students, seed):
    """A class: student i gets variant i mod N; each number is right, a mistake (in turn, of
    the kinds that change it clearly) or a number no mistake gives; every value rounded as
    a student would (within a third of the tolerance)."""
    rng = random.Random(seed)
    rows, planted = [], {}
    turn = 0
    for i in range(students):
        v = ex.variants[i % len(ex.variants)]
        worlds = worlds_of(v.stated)
        right = worlds["right"][0]
        for question, (value, size) in right.items():
            choice = rng.random()
            kinds = [kind for kind in KINDS for w in worlds.get(kind, [])
                     if question in w and abs(w[question][0] - value) > 3 * TOLERANCE * max(size, w[question][1])]
            if choice < 0.25 or not kinds:
                kind, target = None, (value, size)
            elif choice < 0.9:
                kind = kinds[turn % len(kinds)]
                turn += 1
                target = next(w[question] for w in worlds[kind]
                              if question in w and abs(w[question][0] - value) > 3 * TOLERANCE * max(size, w[question][1]))
            else:
                kind, target = "nonsense", (value * 1.37 + 0.11 * size + 1.0, size)
            answer = target[0] + rng.uniform(-1, 1) * TOLERANCE / 3 * target[1]
            text = repr(answer) if rng.random() < 0.8 else repr(answer).replace(".", ",").replace("-", "−")
            rows.append(f"s{i:03d},{v.number},{question},\"{text}\"")
            planted[(f"s{i:03d}", question)] = (kind, answer, worlds)
    return "student,variant,question,value\n" + "\n".join(rows) + "\n", planted


def check(result, planted):
    kinds_found = set()
    for (student, question), (kind, value, worlds) in planted.items():
        mark = next(a for a in result["students"][student]["answers"] if a["question"] == question)
        correct, diagnosis = expected_diagnosis(worlds, question, value)
        assert (mark["correct"], mark["diagnosis"]) == (correct, diagnosis), (student, question, kind)
        if kind is None:
            assert mark["correct"] and mark["diagnosis"] is None
        elif kind != "nonsense":
            assert not mark["correct"] and mark["diagnosis"] is not None
            kinds_found.add(mark["diagnosis"])
    return kinds_found


def test_a_class_of_200_has_every_planted_mistake_named_and_no_right_answer_diagnosed(p_pair30, tmp_path):
    text, planted = plant(p_pair30, p_pair_worlds, 200, 2026)
    answers = tmp_path / "answers.csv"
    answers.write_text(text, encoding="utf-8")
    result = grade(p_pair30, answers)
    found = check(result, planted)
    assert found == set(KINDS)                   # every kind planted, and named
    named_as_planted = sum(1 for (s, q), (kind, _, _) in planted.items() if kind in KINDS and next(
        a for a in result["students"][s]["answers"] if a["question"] == q)["diagnosis"] == kind)
    assert named_as_planted >= 0.9 * sum(1 for kind, _, _ in planted.values() if kind in KINDS)
    # the summary counts what the answers say
    for question, summary in result["questions"].items():
        marks = [a for s in result["students"].values() for a in s["answers"] if a["question"] == question]
        assert summary["right"] == sum(a["correct"] for a in marks)
    score = result["students"]["s000"]["score"]
    assert 0 <= score <= 1


def test_a_four_bar_class_has_its_mistakes_named(four_bar30, tmp_path):
    text, planted = plant(four_bar30, four_bar_worlds, 60, 7)
    answers = tmp_path / "answers.csv"
    answers.write_text(text, encoding="utf-8")
    found = check(grade(four_bar30, answers), planted)
    assert {"normal-omitted", "sense-reversed", "units-mm-as-m", "components-swapped"} <= found


def test_a_mistake_that_changes_nothing_names_nothing(four_bar30, tmp_path):
    # the four-bar has no sliding pair: the Coriolis mistakes give the right values, which stay right
    v = four_bar30.variants[0]
    answers = tmp_path / "a.csv"
    answers.write_text("student,variant,question,value\n" + "".join(
        f"x,{v.number},{r.question},{r.value!r}\n" for r in v.rows))
    result = grade(four_bar30, answers)["students"]["x"]
    assert result["score"] == 1 and all(a["diagnosis"] is None for a in result["answers"])


@pytest.mark.parametrize("text, where", [
    ("student,variant,question\nx,1,q1\n", "answers.csv"),
    ("student,variant,question,value\nx,99,q1,1\n", "answers.csv:2"),
    ("student,variant,question,value\nx,1,q9,1\n", "answers.csv:2"),
    ("student,variant,question,value\nx,1,q1,1\nx,1,q1,2\n", "answers.csv:3"),
])
def test_a_bad_answers_file_is_one_error_naming_the_row(p_pair30, tmp_path, text, where):
    answers = tmp_path / "answers.csv"
    answers.write_text(text)
    with pytest.raises(KinematikaError) as err:
        grade(p_pair30, answers)
    assert err.value.where == where


def test_blank_and_unreadable_answers(p_pair30, tmp_path):
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\nx,1,q1,\nx,1,q2,abc\n")
    result = grade(p_pair30, answers)["students"]["x"]
    assert result["score"] == 0 and result["answers"] == [
        {"variant": 1, "question": "q2", "value": None, "correct": False, "diagnosis": None}]
