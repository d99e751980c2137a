"""A label of the figures' placement step whose size is measured piece by piece (a
symbol's letter, subscript and superscript) rather than from one string."""
from __future__ import annotations

from dataclasses import dataclass

from ...draw.labels import Label


@dataclass
class Sized(Label):
    """A label whose size is given (measured piece by piece: a symbol's letter, subscript and
    superscript) instead of measured from its text."""

    width: float = 0.0
    height: float = 0.0

    @property
    def extent(self) -> tuple[float, float]:
        """(width, height) in points, as given."""
        return self.width, self.height
