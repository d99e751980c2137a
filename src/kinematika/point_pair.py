"""A direction given by two points (`PointPair`), the other form of a model's `Direction`
(`expressions`), in a module of its own: a model whose directions are all written as
vectors, or that has none (the 1000-body chain), does not define it (docs/performance.md).
Its readers tell the two forms apart by the written vector's type, a tuple."""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class PointPair:
    """A direction given by two points, from `start` to `end`."""

    start: str
    end: str
