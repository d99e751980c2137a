"""How much each number a student gives counts.

Each graded question weighs the same by default (its `exercise.weights` entry otherwise),
and its weight is shared equally among its numbers: the nine numbers of an intrinsic
acceleration count as much together as the one ω of a rocker, not nine times as much. A
student's score is the weighted share of their variant's numbers they got right, and each
box of the Moodle quiz gets the same weight as a whole number (Moodle's Cloze writes a
subquestion's grade `{W:NUMERICAL:…}` as an integer).
"""
from __future__ import annotations

import math
from fractions import Fraction

from .key import Row


def row_weights(rows: list[Row], weights: dict[int, float]) -> dict[str, Fraction]:
    """Each row's weight (by question): its question's weight (`weights` by 1-based question
    number, 1 when not given) over the question's count of numbers."""
    counts: dict[int, int] = {}
    for r in rows:
        counts[r.ask] = counts.get(r.ask, 0) + 1
    return {r.question: Fraction(weights.get(r.ask, 1)).limit_denominator(1000) / counts[r.ask] for r in rows}


def whole(weights: dict[str, Fraction]) -> dict[str, int]:
    """The same weights as the smallest whole numbers in the same ratios (Moodle's marks)."""
    if not weights:
        return {}
    scale = math.lcm(*(w.denominator for w in weights.values()))
    ints = {q: int(w * scale) for q, w in weights.items()}
    common = math.gcd(*ints.values()) or 1
    return {q: max(1, n // common) for q, n in ints.items()}
