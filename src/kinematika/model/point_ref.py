"""A material point (``point@body``), in a module of its own so that a question
(`model.question`) names it without importing the whole model."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PointRef:
    """A material point: the point `point` of body `body` (written ``point@body``)."""

    point: str
    body: str

    def __str__(self) -> str:
        return f"{self.point}@{self.body}"


def written(pairs: list[tuple[str, str]]) -> list[str]:
    """``point@body`` of each (point, body): the texts `str(PointRef(point, body))` gives, for
    many points at once without a `PointRef` each (an answer's table names every material
    point: about 6 k instructions a point made and written, docs/performance.md)."""
    return [f"{point}@{body}" for point, body in pairs]
