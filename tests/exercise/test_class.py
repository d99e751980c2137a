"""A real class: the roster (who was given which variant), answers as students and
spreadsheets write them, and marks that follow a student's working. Every expected value
comes from the hand derivation (derive.py), never from the code under test."""
from __future__ import annotations

import copy
import math

import pytest

from kinematika.exercise import grade
from kinematika.exercise.roster import Student, assigned, read_class

from . import derive
from .conftest import p_pair_data


def hand(variant, **changed):
    """The hand answers of a P-pair variant as key rows {question: (value, size)}; `changed`
    replaces data (SI units)."""
    return derive.rows(derive.p_pair(**{**p_pair_data(variant.stated), **changed}))


@pytest.fixture(scope="module")
def klass(p_pair_exercise):
    """The P-pair exercise given to a class of five (the roster drawn from the seed)."""
    ex = copy.copy(p_pair_exercise)
    ex.students = assigned([Student(s) for s in ("ane", "jon", "miren", "iñaki", "unai")],
                           len(ex.variants), ex.seed)
    return ex


def variant_of(ex, student):
    return ex.variant(next(s.variant for s in ex.students if s.id == student))


def csv_rows(student, variant, answers, sep=","):
    return "".join(f"{student}{sep}{variant.number}{sep}{q}{sep}{v}\n" for q, v in answers.items())


def right_answers(variant, text=repr):
    return {q: text(x) for q, (x, _) in hand(variant).items()}


def test_the_class_gets_distinct_variants_drawn_reproducibly_from_the_seed():
    students = [Student(f"s{i}") for i in range(12)]
    first, again, other = assigned(students, 30, 7), assigned(students, 30, 7), assigned(students, 30, 8)
    assert [s.variant for s in first] == [s.variant for s in again] != [s.variant for s in other]
    assert len({s.variant for s in first}) == 12 and all(1 <= s.variant <= 30 for s in first)
    few = assigned(students, 5, 7)                 # fewer variants than students: dealt again
    assert sorted(s.variant for s in few[:5]) == [1, 2, 3, 4, 5] and [s.variant for s in few[5:10]] == [
        s.variant for s in few[:5]]


@pytest.mark.parametrize("encoding, sep", [("utf-8", ","), ("utf-8-sig", ";"), ("cp1252", ";")])
def test_the_roster_is_read_as_moodles_participants_export(tmp_path, encoding, sep):
    text = sep.join(["ID number", "First name", "Last name", "Email address"]) + "\n" + "\n".join(
        sep.join(row) for row in [("7001", "Iñaki", "Ibáñez", "iibanez@ikasle.eus"),
                                  ("7002", "Núria", "Puig i Solé", "npuig@alumnes.cat")]) + "\n"
    path = tmp_path / "class.csv"
    path.write_bytes(text.encode(encoding))
    assert read_class(path) == [Student("7001", "Iñaki Ibáñez", "iibanez@ikasle.eus"),
                                Student("7002", "Núria Puig i Solé", "npuig@alumnes.cat")]


def test_a_roster_row_for_another_variant_an_unknown_student_and_a_missing_one(klass, tmp_path):
    ane, jon = variant_of(klass, "ane"), variant_of(klass, "jon")
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + csv_rows("ane", ane, right_answers(ane))
                       + csv_rows("jon", ane, right_answers(ane))            # jon copies ane's variant
                       + csv_rows("zoe", ane, right_answers(ane))            # not on the list
                       + csv_rows("miren", jon, right_answers(jon))          # miren answers jon's
                       + csv_rows("miren", variant_of(klass, "miren"),
                                  dict(list(right_answers(variant_of(klass, "miren")).items())[:2])),
                       encoding="utf-8")
    result = grade(klass, answers)
    assert result["students"]["ane"]["score"] == 1
    assert result["students"]["jon"]["score"] == 0
    assert {a["diagnosis"] for a in result["students"]["jon"]["answers"]} == {"wrong-variant"}
    assert not any(a["correct"] for a in result["students"]["jon"]["answers"])
    assert result["unknown"] == ["zoe"] and "zoe" not in result["students"]
    # miren: her own q1 and q2 right (2 of 6 questions), jon's variant all wrong-variant
    miren = result["students"]["miren"]
    assert miren["score"] == pytest.approx(2 / 6) and miren["variant"] == variant_of(klass, "miren").number
    assert sum(a["diagnosis"] == "wrong-variant" for a in miren["answers"]) == 10
    # on the list with no row: 0, listed
    for absent in ("iñaki", "unai"):
        assert result["students"][absent] == {"score": 0.0, "variant": variant_of(klass, absent).number,
                                              "answers": []}


def test_without_a_roster_a_second_variant_is_wrong_variant_not_a_lower_score(p_pair_exercise, tmp_path):
    one, two = p_pair_exercise.variants[0], p_pair_exercise.variants[1]
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + csv_rows("x", one, right_answers(one))
                       + csv_rows("x", two, dict(list(right_answers(two).items())[:3])), encoding="utf-8")
    x = grade(p_pair_exercise, answers)["students"]["x"]
    assert x["score"] == 1 and x["variant"] == 1
    assert [a["diagnosis"] for a in x["answers"] if a["variant"] == 2] == ["wrong-variant"] * 3


def test_units_decimal_commas_and_what_was_typed(klass, tmp_path):
    v = variant_of(klass, "ane")
    right = hand(v)
    vx, ax = right["q5.x"][0], right["q6.x"][0]
    typed = {"q1": f"{right['q1'][0]:.4f} rad/s".replace(".", ","),     # 12,3456 rad/s
             "q5.x": f"{1000 * vx:.2f} mm/s",                             # converted from mm/s
             "q5.y": f"{right['q5.y'][0]:.4f} m/s²",                       # an acceleration's unit
             "q6.x": f"{ax:.4f} furlongs",                               # no unit at all
             "q6.y": f"{right['q6.y'][0] * 100:.2f} cm/s^2".replace("-", "−")}
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + "".join(
        f'ane,{v.number},{q},"{t}"\n' for q, t in typed.items()), encoding="utf-8")
    marks = {a["question"]: a for a in grade(klass, answers)["students"]["ane"]["answers"]}
    assert {q: m["typed"] for q, m in marks.items()} == typed                     # nothing typed is lost
    assert marks["q1"]["correct"] and marks["q1"]["value"] == pytest.approx(right["q1"][0], abs=1e-4)
    assert marks["q5.x"]["correct"] and marks["q5.x"]["value"] == pytest.approx(vx, abs=1e-5)
    assert marks["q6.y"]["correct"] and marks["q6.y"]["value"] == pytest.approx(right["q6.y"][0], abs=1e-4)
    for q in ("q5.y", "q6.x"):
        assert not marks[q]["correct"] and marks[q]["diagnosis"] == "wrong-unit"


@pytest.mark.parametrize("encoding, sep", [("utf-8-sig", ","), ("cp1252", ";"), ("utf-8", ";")])
def test_spreadsheet_files_semicolons_cp1252_and_a_bom(klass, tmp_path, encoding, sep):
    v = variant_of(klass, "iñaki")
    comma = {q: f"{x:.6g}".replace(".", ",") for q, (x, _) in hand(v).items()}
    text = sep.join(["Student", "Variant", "Question", "Value"]) + "\n" + "".join(
        sep.join(["iñaki", str(v.number), q, f'"{t}"' if sep == "," else t]) + "\n" for q, t in comma.items())
    answers = tmp_path / "answers.csv"
    answers.write_bytes(text.encode(encoding))
    result = grade(klass, answers)
    assert result["unreadable"] == [] and result["students"]["iñaki"]["score"] == 1


def test_an_unquoted_decimal_comma_in_a_comma_file_is_read(klass, tmp_path):
    v = variant_of(klass, "unai")
    q1 = hand(v)["q1"][0]
    answers = tmp_path / "answers.csv"
    answers.write_text(f"student,variant,question,value\nunai,{v.number},q1,{q1:.4f}\n".replace(
        f"{q1:.4f}", f"{q1:.4f}".replace(".", ",")), encoding="utf-8")
    mark = grade(klass, answers)["students"]["unai"]["answers"][0]
    assert mark["correct"] and mark["typed"] == f"{q1:.4f}".replace(".", ",")


def test_a_hand_solution_rounded_to_three_figures_gets_full_marks(p_pair_exercise, tmp_path):
    """Every intermediate rounded to 3 significant figures, as on paper, in every variant."""
    lines = []
    for v in p_pair_exercise.variants:
        by_hand = derive.rows(derive.p_pair_by_hand(**p_pair_data(v.stated)))
        lines += [f"s{v.number},{v.number},{q},{x!r}\n" for q, (x, _) in by_hand.items()]
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + "".join(lines), encoding="utf-8")
    result = grade(p_pair_exercise, answers, carry=False)
    assert all(s["score"] == 1 for s in result["students"].values()), {
        k: [(a["question"], a["value"]) for a in s["answers"] if not a["correct"]]
        for k, s in result["students"].items() if s["score"] < 1}


def test_an_error_carried_forward_from_a_wrong_rate_earns_the_later_marks(p_pair_exercise, tmp_path):
    """The student's ω_EB is 12 % off (a slip in the velocity triangle); every later answer
    is what the notes' method gives from that ω: the mechanism driven 12 % faster."""
    v = p_pair_exercise.variants[3]
    data = p_pair_data(v.stated)
    theirs = hand(v, w=1.12 * data["w"])
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + csv_rows("x", v, {q: repr(x) for q, (x, _) in theirs.items()}),
                       encoding="utf-8")
    x = grade(p_pair_exercise, answers)["students"]["x"]
    marks = {a["question"]: a for a in x["answers"]}
    assert not marks["q1"]["correct"] and "carried_from" not in marks["q1"]
    assert all(m["correct"] and m["carried_from"] == "q1" for q, m in marks.items() if q != "q1")
    assert x["score"] == pytest.approx(5 / 6)
    without = grade(p_pair_exercise, answers, carry=False)["students"]["x"]
    assert without["score"] < 0.5


def test_an_error_carried_forward_from_a_wrong_angular_acceleration(p_pair_exercise, tmp_path):
    """The student's α_EB is wrong; a_rel (q4) and a_B (q6) follow from it: the P pair solved
    by hand with the guide's α chosen to give that α_EB (the answers are affine in it)."""
    v = p_pair_exercise.variants[5]
    data = p_pair_data(v.stated)
    at0, at1 = derive.p_pair(**{**data, "al": 0.0}), derive.p_pair(**{**data, "al": 1.0})
    right = hand(v)
    wanted = right["q2"][0] * 0.5
    al = (wanted - at0["q2"]) / (at1["q2"] - at0["q2"])
    theirs = hand(v, al=al)
    assert theirs["q2"][0] == pytest.approx(wanted)
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + csv_rows("x", v, {q: repr(x) for q, (x, _) in {
        **right, "q2": theirs["q2"], "q4.x": theirs["q4.x"], "q4.y": theirs["q4.y"],
        "q6.x": theirs["q6.x"], "q6.y": theirs["q6.y"]}.items()}), encoding="utf-8")
    marks = {a["question"]: a for a in grade(p_pair_exercise, answers)["students"]["x"]["answers"]}
    assert not marks["q2"]["correct"]
    assert all(marks[q]["correct"] for q in ("q4.x", "q4.y", "q6.x", "q6.y"))
    moved = [q for q in ("q4.x", "q4.y", "q6.x", "q6.y") if abs(theirs[q][0] - right[q][0]) > 0.1 * right[q][1]]
    assert moved and all(marks[q]["carried_from"] == "q2" for q in moved)


def test_a_later_answer_that_follows_from_nothing_stays_wrong(p_pair_exercise, tmp_path):
    v = p_pair_exercise.variants[3]
    right = hand(v)
    wrong = {**{q: repr(x) for q, (x, _) in right.items()}, "q1": repr(1.12 * right["q1"][0]),
             "q5.x": repr(right["q5.x"][0] * 0.7 + 0.3)}
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + csv_rows("x", v, wrong), encoding="utf-8")
    marks = {a["question"]: a for a in grade(p_pair_exercise, answers)["students"]["x"]["answers"]}
    assert not marks["q5.x"]["correct"] and not marks["q1"]["correct"]


def test_a_reversed_relative_velocity_beside_a_right_rate_is_not_a_reversed_sense(p_pair_exercise, tmp_path):
    v = p_pair_exercise.variants[2]
    right = hand(v)
    answers = {q: repr(x) for q, (x, _) in right.items()}
    answers.update({"q3.x": repr(-right["q3.x"][0]), "q3.y": repr(-right["q3.y"][0])})
    path = tmp_path / "answers.csv"
    path.write_text("student,variant,question,value\n" + csv_rows("x", v, answers), encoding="utf-8")
    marks = {a["question"]: a for a in grade(p_pair_exercise, path)["students"]["x"]["answers"]}
    assert not marks["q3.x"]["correct"] and marks["q3.x"]["diagnosis"] is None
    # the whole solution with ω reversed is named so
    reversed_sense = {q: repr(x) for q, (x, _) in hand(v, w=-p_pair_data(v.stated)["w"]).items()}
    path.write_text("student,variant,question,value\n" + csv_rows("y", v, reversed_sense), encoding="utf-8")
    marks = {a["question"]: a for a in grade(p_pair_exercise, path, carry=False)["students"]["y"]["answers"]}
    assert marks["q1"]["diagnosis"] == "sense-reversed" and marks["q3.x"]["diagnosis"] == "sense-reversed"


def test_each_question_weighs_the_same_and_the_sections_weights_count(p_pair_exercise, tmp_path):
    import dataclasses

    v = p_pair_exercise.variants[0]
    right = hand(v)
    answers = tmp_path / "answers.csv"
    answers.write_text("student,variant,question,value\n" + csv_rows("x", v, {
        "q1": repr(right["q1"][0]), "q6.x": repr(right["q6.x"][0])}), encoding="utf-8")
    # q1 is one number of six equal questions; q6.x half of one
    assert grade(p_pair_exercise, answers)["students"]["x"]["score"] == pytest.approx(1 / 6 + 1 / 12)
    weighted = copy.copy(p_pair_exercise)
    weighted.section = dataclasses.replace(p_pair_exercise.section, weights={1: 4, 2: 1, 3: 1, 4: 1, 5: 1, 6: 2})
    assert grade(weighted, answers)["students"]["x"]["score"] == pytest.approx((4 + 1) / 10)


def test_the_json_of_the_contract_keeps_typed_beside_value(klass, tmp_path):
    v = variant_of(klass, "ane")
    answers = tmp_path / "answers.csv"
    answers.write_text(f"student,variant,question,value\nane,{v.number},q1,\"0,915 m/s\"\n", encoding="utf-8")
    mark = grade(klass, answers)["students"]["ane"]["answers"][0]
    assert list(mark)[:6] == ["variant", "question", "typed", "value", "correct", "diagnosis"]
    assert mark["typed"] == "0,915 m/s" and mark["value"] == 0.915 and mark["diagnosis"] == "wrong-unit"
    assert math.isfinite(mark["value"])
