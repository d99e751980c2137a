"""The acceleration of a material point (`{acceleration: B@rocker}`), seen from the fixed
frame or from any body (`relative_to`): a_P = a₀ + α × (P − O) + ω × (ω × (P − O)), drag and
Coriolis taken out for a moving observer (`motion.acceleration`). A column of the answer's
`points` table, and with the velocity the contract's default question of every material
point."""
from __future__ import annotations

from typing import Any

from .base import Asked, Figure, QuestionKind, Solved, Words
from .motion import acceleration


class Acceleration(QuestionKind):
    """A material point's acceleration."""

    name = "acceleration"
    summary = "the acceleration of a material point"
    about = "point"
    level = "acceleration"
    unit_kind = "acceleration"
    column = True
    linear = True
    page = True

    def answer(self, sol: Solved, q: Asked) -> Any:
        """a_P relative to `q.relative_to` (`motion.acceleration`)."""
        return acceleration(sol, q)

    def draw(self, figure: Figure, q: Asked) -> None:
        """An arrow at the point."""
        figure.arrow(q, "acceleration")

    def label(self, words: Words, q: Asked) -> Any:
        """a_B, or a_A∈4/2 relative to body 2."""
        return words.sym("a", words.motion(q))


KIND = Acceleration()
