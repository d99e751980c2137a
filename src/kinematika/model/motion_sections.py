"""The records of a model's motion: its `sweep` and `simulate` sections, and the bodies
carried when a model with symbolic parameters is moved (`Turn`).

Apart from `model.model` because most models have none of them and every command imports
the model's records: Python 3.11 compiles a dataclass's generated methods at import (about
2.5 M instructions a class), so these three are imported where the first is made or read
(docs/architecture.md, "The imports left inside functions").
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from ..expressions import Direction, Expr


@dataclass(frozen=True)
class Turn:
    """A body carried rigidly from its drawn pose when a model with symbolic parameters is
    moved (`move`): p ↦ P + R (p − P₀), P₀ and P its `pivot`'s drawn and present places, R
    the rotation by `angle` (radians), or the one that takes the drawn direction P₀→T₀ to
    the present P→T (`toward` T: a point of the body, or a pin sliding in a slot of it
    along PT when `slides`); or shifted by `shift` along `along`. The input's turn is about
    its pivot on the frame; the other bodies' turns are found in closed form
    (`sweep.carried`), and the constructions follow."""

    body: str
    pivot: Optional[str] = None
    angle: Optional[Expr] = None
    along: Optional[Direction] = None
    shift: Optional[Expr] = None
    toward: Optional[str] = None
    slides: bool = False

    @property
    def anchors(self) -> list[str]:
        """The points whose places the turn is taken from (pivot, toward)."""
        return [p for p in (self.pivot, self.toward) if p is not None]


@dataclass
class Sweep:
    """A model's `sweep` section: the joint whose coordinate advances (None: the first driven
    joint), by how much in all (degrees or length) and in how many steps."""

    joint: Optional[str]
    by: Expr
    steps: int


@dataclass
class Simulate:
    """A model's `simulate` section: how long its motion is followed in time (seconds) and in
    how many equal steps of time."""

    time: Expr
    steps: int
