"""Marking a class: each answer right or wrong within the key's tolerance, and a wrong answer
named by the usual mistake whose value it equals (`mistakes`).

`ANSWERS.csv` has the columns `student,variant,question,value` (a decimal comma and a true
minus sign are read too). A blank value is a question left unanswered; a value that is not
a number is wrong. A student's score is the share of the key's numbers of their variant
they got right. A diagnosis names a mistake only when the value matches, within the
tolerance, the answer solved again with that mistake, and does not match the right one.
"""
from __future__ import annotations

import math
import re
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional

from ..errors import KinematikaError
from .build import Exercise, Variant
from .key import Row
from .mistakes import Mistaken

NUMBER = re.compile(r"[+-]?(\d+([.,]\d*)?|[.,]\d+)([eE][+-]?\d+)?\Z")


@dataclass(frozen=True)
class Mark:
    """One answer marked."""

    student: str
    variant: int
    question: str
    value: Optional[float]
    correct: bool
    diagnosis: Optional[str]

    def as_json(self) -> dict[str, Any]:
        """The mark as the page and `grade --json` give it: variant, question, value, correct
        and diagnosis."""
        return {"variant": self.variant, "question": self.question, "value": self.value,
                "correct": self.correct, "diagnosis": self.diagnosis}


def read_number(text: str) -> Optional[float]:
    """A typed number (`-12.5`, `−12,5`, `1.2e3`), or None when it is not one."""
    text = text.strip().replace("−", "-").replace("\u00a0", "").replace(" ", "")
    if not NUMBER.match(text):
        return None
    value = float(text.replace(",", "."))
    return value if math.isfinite(value) else None


def diagnose(right: Row, mistakes: list[Mistaken], value: float, tolerance: float) -> tuple[bool, Optional[str]]:
    """(right?, the mistake it shows or None) for a student's `value` of the key's row."""
    margin = right.margin(tolerance)
    if abs(value - right.value) <= margin:
        return True, None
    for m in mistakes:
        wrong = m.rows.get(right.question)
        if wrong is None or abs(wrong.value - right.value) <= margin:
            continue                        # this mistake gives the right answer here
        if abs(value - wrong.value) <= wrong.margin(tolerance):
            return False, m.kind
    return False, None


class Marker:
    """Marks answers of an exercise's variants, solving each variant's mistakes once."""

    def __init__(self, exercise: Exercise) -> None:
        self.exercise = exercise
        self._mistakes: dict[int, list[Mistaken]] = {}

    def mistakes(self, variant: Variant) -> list[Mistaken]:
        """The usual mistakes' answers for `variant`, solved again once per variant and kept (a
        class has many students per variant)."""
        if variant.number not in self._mistakes:
            self._mistakes[variant.number] = self.exercise.mistakes(variant)
        return self._mistakes[variant.number]

    def mark(self, student: str, variant: Variant, question: str, text: str, where: str) -> Optional[Mark]:
        """One answer (None when left blank); an unknown question is an error at `where`."""
        row = next((r for r in variant.rows if r.question == question), None)
        if row is None:
            raise KinematikaError("usage", "question-not-asked", where, question=question, variant=variant.number,
                                  asked=[r.question for r in variant.rows])
        if not text.strip():
            return None
        value = read_number(text)
        if value is None:
            return Mark(student, variant.number, question, None, False, None)
        correct, kind = diagnose(row, self.mistakes(variant), value, self.exercise.tolerance)
        return Mark(student, variant.number, question, value, correct, kind)


def grade(exercise: Exercise, answers: Path) -> dict[str, Any]:
    """The contract's grading JSON, with a summary per question (`questions`, an extension)."""
    from .folder import read_csv

    marker = Marker(exercise)
    marks: list[Mark] = []
    seen: set = set()
    variants_of: dict[str, set[int]] = {}
    for line, row in enumerate(read_csv(answers, ["student", "variant", "question", "value"]), start=2):
        where = f"{answers.name}:{line}"
        student = row["student"]
        if not student:
            raise KinematikaError("usage", "row-no-student", where)
        try:
            variant = exercise.variant(int(row["variant"]))
        except ValueError:
            raise KinematikaError("usage", "variant-not-number", where, got=repr(row['variant'])) from None
        except KinematikaError as err:
            raise KinematikaError("usage", err.said, where) from None
        key = (student, variant.number, row["question"])
        if key in seen:
            raise KinematikaError("usage", "answered-twice", where, student=student, question=row['question'],
                                  variant=variant.number)
        seen.add(key)
        variants_of.setdefault(student, set()).add(variant.number)
        mark = marker.mark(student, variant, row["question"], row["value"], where)
        if mark is not None:
            marks.append(mark)
    students: dict[str, Any] = {}
    for student, numbers in variants_of.items():
        mine = [m for m in marks if m.student == student]
        total = sum(len(exercise.variant(n).rows) for n in numbers)
        students[student] = {"score": round(sum(m.correct for m in mine) / total, 6) if total else 0.0,
                             "answers": [m.as_json() for m in mine]}
    return {"students": students, "questions": summary(exercise, marks)}


def summary(exercise: Exercise, marks: list[Mark]) -> dict[str, Any]:
    """Per question (q2.y, all variants together): answers, right ones, and the mistakes named
    how often, most frequent first."""
    out: dict[str, Any] = {}
    order = {r.question: i for v in exercise.variants for i, r in enumerate(v.rows)}
    for question in sorted({m.question for m in marks}, key=lambda q: order.get(q, 0)):
        mine = [m for m in marks if m.question == question]
        kinds = Counter(m.diagnosis for m in mine if m.diagnosis)
        out[question] = {"answers": len(mine), "right": sum(m.correct for m in mine),
                         "mistakes": dict(kinds.most_common())}
    return out


def gradebook_csv(result: dict[str, Any]) -> str:
    """A CSV Moodle's gradebook imports (Grades → Import → CSV file): `student` (map it to
    the users' ID number, username or email) and `grade`, the score out of 100."""
    from .folder import _csv_field

    lines = ["student,grade"]
    for student, data in result["students"].items():
        lines.append(f"{_csv_field(student)},{round(100 * data['score'], 2):g}")
    return "\n".join(lines) + "\n"


def summary_text(result: dict[str, Any]) -> str:
    """The teacher's summary: per question, how many right and which mistakes how often; then
    each student's score."""
    lines = ["question   answers  right  mistakes"]
    for question, s in result["questions"].items():
        named = ", ".join(f"{kind} ×{n}" for kind, n in s["mistakes"].items()) or "—"
        lines.append(f"{question:<10} {s['answers']:>7}  {s['right']:>5}  {named}")
    lines.append("")
    lines.append("student    score")
    for student, data in result["students"].items():
        lines.append(f"{student:<10} {100 * data['score']:5.1f} %")
    return "\n".join(lines) + "\n"
