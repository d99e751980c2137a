"""The angular velocity of a body (`{omega: coupler}`), relative to the fixed frame or to any
body: ω − ω_F (`motion.omega`); a number in the plane, a vector in space. A column of the
answer's `bodies` table, and with α the contract's default question of every body."""
from __future__ import annotations

from typing import Any

from .base import Asked, QuestionKind, Solved, Words
from .motion import omega


class Omega(QuestionKind):
    """A body's angular velocity."""

    name = "omega"
    summary = "the angular velocity of a body"
    unit_kind = "omega"
    column = True
    linear = True
    page = True

    def answer(self, sol: Solved, q: Asked) -> Any:
        """ω of the body relative to `q.relative_to` (`motion.omega`)."""
        return omega(sol, q)

    def label(self, words: Words, q: Asked) -> Any:
        """ω_coupler, ω_coupler/rocker; a vector in space."""
        return words.rate("ω", q, vector=not words.planar)


KIND = Omega()
