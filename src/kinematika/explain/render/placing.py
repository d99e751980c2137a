"""A label of the figures' placement step whose size is measured piece by piece (a
symbol's letter, subscript and superscript) rather than from one string."""
from __future__ import annotations

from dataclasses import dataclass

from ...draw.labels import Label


@dataclass
class Sized(Label):
    width: float = 0.0
    height: float = 0.0

    @property
    def extent(self) -> tuple[float, float]:
        return self.width, self.height
