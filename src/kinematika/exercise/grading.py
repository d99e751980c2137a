"""Marking a class: each answer right or wrong within its box's margin, a wrong answer named
by the usual mistake whose value it equals (`mistakes`), and marks that follow a student's
working (`carried`).

`ANSWERS.csv` has the columns `student,variant,question,value`, `,` or `;` separated, UTF-8
(with or without BOM) or cp1252 (`table`); a value is read as a student types it, with a
decimal comma and a unit (`typed`). With a class (`students.csv`, from `exercise --students`)
every row is checked against the variant the student was given:

- a row for another variant is wrong, with the diagnosis `wrong-variant`;
- a student not on the list is left out of the gradebook and listed under `unknown`;
- a student on the list with no row scores 0;
- without a list, a student's variant is the one they answered most numbers of, and rows
  of any other are `wrong-variant`.

A blank value is a question left unanswered; a value that is not a number is wrong, and
what was typed is kept (`typed`). A row that cannot be read (no student, a variant or a
question that does not exist, a number answered twice) is listed under `unreadable` with its
line number, and every other row is graded. A student's score is the weighted share
(`weights`) of their variant's numbers they got right.

A diagnosis names a mistake only when the value matches, within the margin, the answer
solved again with that mistake, and does not match the right one; `sense-reversed` only
when the student's other answers show the reversed sense too (a reversed relative velocity
beside a right ω is not a reversed ω).
"""
from __future__ import annotations

import dataclasses
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Optional

from ..errors import KinematikaError, Names, Num, Said
from .build import Exercise, Variant
from .key import Row
from .mistakes import Mistaken
from .table import Line, Unreadable, csv_field, read_table
from .typed import in_model_units, read_typed

WHOLE_WORLD = ("sense-reversed",)      # a mistake a student makes everywhere or nowhere


@dataclass(frozen=True)
class Mark:
    """One answer marked: the number typed and read (in the model's units), right or not,
    the mistake it shows, and the earlier answer it follows from when credited so."""

    student: str
    variant: int
    question: str
    typed: str
    value: Optional[float]
    correct: bool
    diagnosis: Optional[str]
    carried_from: Optional[str] = None

    def as_json(self) -> dict[str, Any]:
        """The mark as the page and `grade --json` give it: variant, question, typed, value,
        correct, diagnosis (and `carried_from` when it follows from an earlier answer)."""
        out = {"variant": self.variant, "question": self.question, "typed": self.typed, "value": self.value,
               "correct": self.correct, "diagnosis": self.diagnosis}
        if self.carried_from:
            out["carried_from"] = self.carried_from
        return out


def read_number(text: str) -> Optional[float]:
    """A typed number without a unit (`-12.5`, `−12,5`, `1.2e3`), or None."""
    typed = read_typed(text)
    return typed.number if not typed.unit_text else None


def diagnose(right: Row, mistakes: list[Mistaken], value: float, tolerance: float) -> tuple[bool, Optional[str]]:
    """(right?, the mistake it shows or None) for a student's `value` of the key's row, with
    the box's relative `tolerance` (a mistaken value's margin is as wide, relative to it)."""
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
    """Marks answers of an exercise's variants (their mistakes solved once, when drawn; the
    solutions that carry a student's error forward once per variant)."""

    def __init__(self, exercise: Exercise) -> None:
        self.exercise = exercise
        self._bases: dict[int, Any] = {}

    def basis(self, variant: Variant) -> Any:
        """The variant's `carried.Basis`, solved once."""
        from .carried import basis

        if variant.number not in self._bases:
            self._bases[variant.number] = basis(self.exercise, variant)
        return self._bases[variant.number]

    def mistakes(self, variant: Variant) -> list[Mistaken]:
        """The usual mistakes' answers for `variant` (solved when it was drawn or read)."""
        if not variant.mistaken:
            self.exercise.judged(variant)
        return variant.mistaken

    def mark(self, student: str, variant: Variant, question: str, text: str, where: str) -> Optional[Mark]:
        """One answer (None when left blank); an unknown question is an error at `where`."""
        row = self.row(variant, question, where)
        if not text.strip():
            return None
        typed = read_typed(text)
        value, unit_right = in_model_units(typed, row.kind, self.exercise.section)
        if value is None:
            return Mark(student, variant.number, question, text, None, False, None)
        if not unit_right:
            return Mark(student, variant.number, question, text, value, False, "wrong-unit")
        correct, kind = diagnose(row, self.mistakes(variant), value, variant.tolerance_of(row))
        return Mark(student, variant.number, question, text, value, correct, kind)

    @staticmethod
    def row(variant: Variant, question: str, where: str) -> Row:
        """The key row `question` of `variant`; a usage error at `where` when it is not asked."""
        row = next((r for r in variant.rows if r.question == question), None)
        if row is None:
            raise KinematikaError("usage", "question-not-asked", where, question=question, variant=variant.number,
                                  asked=[r.question for r in variant.rows])
        return row


@dataclass(frozen=True)
class Answer:
    """A row of the answers file, read: who, which variant, which number, what was typed."""

    line: int
    student: str
    variant: int
    question: str
    text: str


def read_answers(exercise: Exercise, path: Path, assigned: dict[str, int]) -> tuple[list[Answer], list[Unreadable]]:
    """The rows of `ANSWERS.csv` that can be read, and the others with their line numbers."""
    table = read_table(path, ["student", "question", "value"] + ([] if assigned else ["variant"]),
                       optional=("variant",), decimal_last=True)
    bad = list(table.unreadable)
    out: list[Answer] = []
    seen: dict[tuple, int] = {}
    for line in table.rows:
        try:
            answer = _answer(exercise, line, assigned)
        except KinematikaError as err:
            bad.append(Unreadable(line.number, err.said))
            continue
        key = (answer.student, answer.variant, answer.question)
        if key in seen:
            bad.append(Unreadable(line.number, Said("answered-twice", student=answer.student,
                                                    question=answer.question, variant=answer.variant,
                                                    first=seen[key])))
            continue
        seen[key] = line.number
        out.append(answer)
    return out, sorted(bad, key=lambda u: u.number)


def _answer(exercise: Exercise, line: Line, assigned: dict[str, int]) -> Answer:
    cells = line.cells
    student = cells["student"]
    if not student:
        raise KinematikaError("usage", "row-no-student")
    text = cells["variant"]
    if not text and student in assigned:
        number = assigned[student]
    else:
        try:
            number = int(text)
        except ValueError:
            raise KinematikaError("usage", "variant-not-number", got=repr(text)) from None
    variant = exercise.variant(number)
    Marker.row(variant, cells["question"], "")
    return Answer(line.number, student, number, cells["question"], cells["value"])


def grade(exercise: Exercise, answers: Path, carry: bool = True) -> dict[str, Any]:
    """The contract's grading JSON: `students` (score, variant, answers), `unknown` (ids not on
    the class list), `unreadable` (rows not read: line and error) and a summary per question
    (`questions`); with `carry`, later answers that follow from a student's earlier wrong one
    are credited (`carried`)."""
    from .weights import row_weights

    marker = Marker(exercise)
    roster = {s.id: s.variant for s in exercise.students}
    rows, unreadable = read_answers(exercise, answers, roster)
    by_student: dict[str, list[Answer]] = {}
    for a in rows:
        by_student.setdefault(a.student, []).append(a)
    unknown = [s for s in by_student if roster and s not in roster]
    students: dict[str, Any] = {}
    all_marks: list[Mark] = []
    for student in [*roster, *(s for s in by_student if not roster)]:
        mine = by_student.get(student, [])
        number = roster.get(student) or _most_answered(mine)
        variant = exercise.variant(number)
        marks = []
        for a in mine:
            where = f"{answers.name}:{a.line}"
            if a.variant != number:
                mark = marker.mark(student, exercise.variant(a.variant), a.question, a.text, where)
                if mark is not None:
                    marks.append(Mark(student, a.variant, a.question, a.text, mark.value, False, "wrong-variant"))
                continue
            mark = marker.mark(student, variant, a.question, a.text, where)
            if mark is not None:
                marks.append(mark)
        marks = checked(marks, marker, variant, carry)
        weights = row_weights(variant.rows, exercise.section.weights)
        total = sum(weights.values())
        got = sum(weights[m.question] for m in marks if m.correct and m.variant == number)
        students[student] = {"score": round(float(got / total), 6) if total else 0.0, "variant": number,
                             "answers": [m.as_json() for m in marks]}
        all_marks += marks
    return {"students": students, "unknown": unknown, "unreadable": [u.as_json() for u in unreadable],
            "questions": summary(exercise, all_marks)}


def _most_answered(answers: list[Answer]) -> int:
    """The variant a student answered most numbers of (the first such on a tie)."""
    counts = Counter(a.variant for a in answers)
    best = max(counts.values())
    return next(a.variant for a in answers if counts[a.variant] == best)


def checked(marks: list[Mark], marker: Marker, variant: Variant, carry: bool = True) -> list[Mark]:
    """One student's marks of their variant made final: later answers that follow from an
    earlier wrong one credited (with `carry`), and `sense-reversed` kept only where the
    student's other answers show it too."""
    return _sense_checked(_carried(marks, marker, variant) if carry else marks, variant)


def _carried(marks: list[Mark], marker: Marker, variant: Variant) -> list[Mark]:
    """The marks with the wrong answers that follow from an earlier wrong one credited."""
    from .carried import carried

    wrong = {m.question: m.value for m in marks if m.variant == variant.number and not m.correct
             and m.value is not None and m.diagnosis != "wrong-unit"}
    follows = carried(marker.exercise, variant, wrong, marker.basis(variant) if wrong else None)
    return [dataclasses.replace(m, correct=True, diagnosis=None, carried_from=follows[m.question])
            if m.variant == variant.number and m.question in follows and not m.correct else m for m in marks]


def _sense_checked(marks: list[Mark], variant: Variant) -> list[Mark]:
    """A whole-world diagnosis (`sense-reversed`) kept only when no answer of the student is
    right where that mistake would have changed it."""
    right = {m.question for m in marks if m.correct and not m.carried_from and m.variant == variant.number}
    rows = {r.question: r for r in variant.rows}
    out = []
    for m in marks:
        if m.diagnosis in WHOLE_WORLD:
            worlds = [w for w in variant.mistaken if w.kind == m.diagnosis and m.question in w.rows
                      and abs(m.value - w.rows[m.question].value) <= w.rows[m.question].margin(
                          variant.tolerance_of(rows[m.question]))]
            if worlds and all(_contradicted(w, right, rows, variant) for w in worlds):
                m = dataclasses.replace(m, diagnosis=None)
        out.append(m)
    return out


def _contradicted(world: Mistaken, right: set[str], rows: dict[str, Row], variant: Variant) -> bool:
    for question in right:
        wrong = world.rows.get(question)
        if wrong is not None and abs(wrong.value - rows[question].value) > variant.margin(rows[question]):
            return True
    return False


def summary(exercise: Exercise, marks: list[Mark]) -> dict[str, Any]:
    """Per question (q2.y, all variants together): answers, right ones, those credited as
    following from an earlier answer, and the mistakes named how often, most frequent first."""
    out: dict[str, Any] = {}
    order = {r.question: i for v in exercise.variants for i, r in enumerate(v.rows)}
    for question in sorted({m.question for m in marks}, key=lambda q: order.get(q, 0)):
        mine = [m for m in marks if m.question == question]
        kinds = Counter(m.diagnosis for m in mine if m.diagnosis)
        out[question] = {"answers": len(mine), "right": sum(m.correct for m in mine),
                         "carried": sum(1 for m in mine if m.carried_from),
                         "mistakes": dict(kinds.most_common())}
    return out


def gradebook_csv(result: dict[str, Any]) -> str:
    """A CSV Moodle's gradebook imports (Grades → Import → CSV file): `student` (map it to
    the users' ID number, username or email) and `grade`, the score out of 100."""
    lines = ["student,grade"]
    for student, data in result["students"].items():
        lines.append(f"{csv_field(student)},{round(100 * data['score'], 2):g}")
    return "\n".join(lines) + "\n"


def summary_text(result: dict[str, Any], answers: str = "answers.csv") -> str:
    """The teacher's summary, its headings in the language in use: per question, how many
    right and which mistakes how often; then each student's score; then the students not on
    the list and the rows not read."""
    def heading(column: str) -> str:
        return Said("grade-column", column=column).said()

    q, n, r, c, m, s_, v, sc = (heading(k) for k in ("question", "answers", "right", "carried", "mistakes",
                                                     "student", "variant", "score"))
    wq = max([10, len(q), *(len(k) for k in result["questions"])])
    wn, wr, wc = max(7, len(n)), max(5, len(r)), max(7, len(c))
    lines = [f"{q:<{wq}} {n:>{wn}}  {r:>{wr}}  {c:>{wc}}  {m}"]
    for question, s in result["questions"].items():
        named = ", ".join(f"{kind} ×{k}" for kind, k in s["mistakes"].items()) or "—"
        lines.append(f"{question:<{wq}} {s['answers']:>{wn}}  {s['right']:>{wr}}  {s['carried']:>{wc}}  {named}")
    lines.append("")
    ws, wv = max([10, len(s_), *(len(k) for k in result["students"])]), max(7, len(v))
    lines.append(f"{s_:<{ws}} {v:>{wv}}  {sc}")
    for student, data in result["students"].items():
        score = Said("grade-score", score=Num(100 * data["score"], ".1f")).said()
        lines.append(f"{student:<{ws}} {data['variant']:>{wv}}  {score:>7}")
    if result["unknown"]:
        lines += ["", Said("students-unknown", students=Names(result["unknown"], None)).said()]
    lines += [not_read(answers, u) for u in result["unreadable"]]
    return "\n".join(lines) + "\n"


def not_read(answers: str, unreadable: dict[str, Any]) -> str:
    """The line that says a row of the answers file was not read, and why."""
    return Said("row-not-read", place=f"{answers}:{unreadable['line']}", error=unreadable["error"]).said()
