"""Exercises for instructors: variants of a model's problem for every student, a Moodle quiz,
printable sheets, an answer key with worked solutions, and grading that names the mistake.

    >>> from kinematika.exercise import make_exercise, write_exercise
    >>> ex = make_exercise(model, ["s=300:500:10", "beta=20:40:1"], count=30, seed=7, lang="eu")
    >>> write_exercise(ex, Path("sheet"))

A view of the one engine: each variant is the model with its data (`--set`), solved by the
solver; its key is `solve --json`'s answers; the worked solution is `explain`'s; a wrong
answer is named by solving the model again with a usual mistake (`mistakes`, through the
engine's one hook `engine.terms` for the Coriolis and normal terms). See docs/exercises.md.
"""
from __future__ import annotations

from .build import Exercise, Variant, make_exercise
from .folder import load_exercise, write_exercise
from .grading import grade
from .mistakes import KINDS

__all__ = ["KINDS", "Exercise", "Variant", "grade", "load_exercise", "make_exercise", "write_exercise"]
