"""The unit of every quantity an answer gives, from the model's length unit L: positions in
L, velocities in L/s, accelerations in L/s², ω in rad/s, α in rad/s². The length unit is the
model's `exercise.length` when it states one, else the metre.

The terminal's tables (`tables`) write them in their headings, the exercises' keys and
sheets (`exercise.key`) beside each number."""
from __future__ import annotations

from typing import Any, Optional

from ..questions import QUESTIONS, field_kinds

# the unit of each kind of quantity, from the model's length unit L
KIND_UNITS = {"position": "{L}", "velocity": "{L}/s", "acceleration": "{L}/s²", "omega": "rad/s",
              "alpha": "rad/s²"}


def unit(kind: Optional[str], length: str = "m") -> str:
    """The unit of a kind of quantity (`velocity` → "m/s"); "" for none (a direction)."""
    return KIND_UNITS.get(kind or "", "").replace("{L}", length)


def answer_kind(question: str) -> Optional[str]:
    """The kind of quantity a kind of question answers (`QuestionKind.unit_kind`; the fields
    of a compound answer have their own: `field_kind`); None for a key that is no question's."""
    return QUESTIONS[question].unit_kind if question in QUESTIONS else None


def length_of(model: Any) -> str:
    """The model's length unit: its exercise's `length`, else m."""
    exercise = getattr(model, "exercise", None)
    return exercise.length.name if exercise is not None else "m"


def field_kind(name: str, parent: Optional[str]) -> Optional[str]:
    """The kind of a compound answer's field (`radius` a position, `coriolis` an
    acceleration: the question kinds' `fields`); a part of a decomposition (`drag`, `total`)
    is of its parent's kind."""
    return field_kinds().get(name, parent)
