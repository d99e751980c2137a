"""The angular acceleration of a body (`{alpha: coupler}`), relative to the fixed frame or to
any body, as seen from it: α − α_F − ω_F × (ω − ω_F) (`motion.alpha`). A column of the
answer's `bodies` table, and with ω the contract's default question of every body."""
from __future__ import annotations

from typing import Any

from .base import Asked, QuestionKind, Solved, Words
from .motion import alpha


class Alpha(QuestionKind):
    """A body's angular acceleration."""

    name = "alpha"
    summary = "the angular acceleration of a body"
    level = "acceleration"
    unit_kind = "alpha"
    column = True
    linear = True
    page = True

    def answer(self, sol: Solved, q: Asked) -> Any:
        """α of the body relative to `q.relative_to` (`motion.alpha`)."""
        return alpha(sol, q)

    def label(self, words: Words, q: Asked) -> Any:
        """α_coupler, α_coupler/rocker; a vector in space."""
        return words.rate("α", q, vector=not words.planar)


KIND = Alpha()
