"""The velocity of a material point (`{velocity: B@rocker}`), seen from the fixed frame or
from any body (`relative_to`): v_P = v₀ + ω × (P − O) with the body's twist relative to that
frame (`motion.velocity`). A column of the answer's `points` table, and with the
acceleration the contract's default question of every material point."""
from __future__ import annotations

from typing import Any

from .base import Asked, Figure, QuestionKind, Solved, Words
from .motion import velocity


class Velocity(QuestionKind):
    """A material point's velocity."""

    name = "velocity"
    summary = "the velocity of a material point"
    about = "point"
    unit_kind = "velocity"
    column = True
    linear = True
    page = True

    def answer(self, sol: Solved, q: Asked) -> Any:
        """v_P relative to `q.relative_to` (`motion.velocity`)."""
        return velocity(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """An arrow at the point."""
        figure.arrow(q, "velocity")

    def label(self, words: Words, q: Asked) -> Any:
        """v_B, or v_A∈4/2 relative to body 2."""
        return words.sym("v", words.motion(q))


KIND = Velocity()
