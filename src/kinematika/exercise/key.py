"""The key of an exercise: one row per number a student gives, named as the contract names
it (`q2` for the 2nd question, `q2.y` for a component, `q5.point.x` inside a compound
answer), with its value in the model's units, its unit and the tolerance.

The values are `kinematika solve --json`'s answers of the variant (the same numbers,
flattened): a scalar is one row; a vector one row per component (`.x`, `.y`, `.z`); a
compound answer (an instant centre's `point`, a curvature's `radius` and `center`, a
decomposition's parts) one row per number along its path of keys. A part that is not a
number (a centre at infinity's `null`, `rest: true`) has no row.

A value is right within `tolerance` (relative) times its size: for a vector's component the
size of the vector, so that a small component of a large vector is not held to a tighter
absolute margin than the vector; for a scalar its own; and never less than 1 % of the
mechanism's own scale for that kind of quantity (its largest speed, acceleration, rate),
so that a zero answer has a margin too.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Iterator, Optional

from ..report.units import answer_kind, field_kind, unit

AXES = "xyz"
FLOOR = 0.01      # a value is measured against at least 1 % of the mechanism's scale of its kind


@dataclass(frozen=True)
class Row:
    """One number of the key: `question` (q2.y), its value, the size it is measured against
    (`size`: the vector's magnitude, or the value's) and the kind of quantity."""

    question: str
    value: float
    size: float
    kind: str
    ask: int                     # the 1-based position of its question in the model's `ask`

    def margin(self, tolerance: float) -> float:
        """The absolute margin of a right answer: tolerance × size."""
        return tolerance * self.size

    def unit(self, length: str) -> str:
        """The row's unit from the model's length unit `length`: "mm/s²" for an acceleration in
        mm, "rad/s" for ω."""
        return unit(self.kind, length)


def rows_of(ask: int, kind: str, value: Any, floors: dict[str, float]) -> list[Row]:
    """The rows of question number `ask` (1-based) of `kind` with the answer `value` (the
    contract's JSON value); `floors` are the smallest sizes of each kind of quantity."""
    return list(_walk(f"q{ask}", answer_kind(kind) or kind, value, ask, floors))


def _walk(name: str, kind: str, value: Any, ask: int, floors: dict[str, float]) -> Iterator[Row]:
    floor = floors.get(kind, 0.0)
    if isinstance(value, bool) or value is None:
        return
    if _number(value):
        yield Row(name, float(value), max(abs(float(value)), floor), kind, ask)
        return
    if isinstance(value, list) and value and all(_number(v) for v in value):
        size = max(math.hypot(*value), floor)
        for axis, v in zip(AXES, value):
            yield Row(f"{name}.{axis}", float(v), size, kind, ask)
        return
    if isinstance(value, dict):
        for key, part in value.items():
            part_kind = field_kind(key, kind) or "unit"
            yield from _walk(f"{name}.{key}", part_kind, part, ask, floors)


def _number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def graded(section_ask: Optional[tuple[int, ...]], questions: int) -> list[int]:
    """The 1-based numbers of the graded questions: the section's, else every question."""
    return list(section_ask) if section_ask is not None else list(range(1, questions + 1))


def key_rows(answers: list[dict], kinds: list[str], asks: list[int], floors: dict[str, float]) -> list[Row]:
    """The rows of the graded questions `asks` of a variant's answers (`solve --json`'s)."""
    out: list[Row] = []
    for k in asks:
        out += rows_of(k, kinds[k - 1], answers[k - 1]["value"], floors)
    return out


def floors_of(sol: Any) -> dict[str, float]:
    """The smallest size a value of each kind is measured against: `FLOOR` of the
    mechanism's own scale of that kind (its largest speed, acceleration, rate …), so that a
    zero answer has a margin too. A unit vector's size is 1."""
    from ..report.json_answer import answer_scales

    scale, _ = answer_scales(sol)
    return {**{kind: FLOOR * value for kind, value in scale.items()}, "unit": 1.0}


def value_text(x: float) -> str:
    """A key's value as written in key.csv and in the quiz: Python's shortest exact form
    (`-73.661877341`, `1e-05`), which Moodle's number syntax reads."""
    return repr(float(x)) if x != 0 else "0"
