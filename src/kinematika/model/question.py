"""One question of a model's `ask`, in a module of its own: a model whose `ask` is empty (a
chain of a thousand pins asking nothing) makes none, so its command does not define the class
(a dataclass's definition costs about as much as a thousand joints' checks)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional, Union

if TYPE_CHECKING:
    from .point_ref import PointRef


@dataclass
class Question:
    """One question of `ask`: its `kind` (velocity, icr, curvature …), its target (a body, a
    material point or a joint id), the body it is asked `relative_to` and, for a decomposition,
    the `moving` body; `echo` is the question as written, repeated in the answer. What a kind
    means is its module's (`kinematika.questions.QUESTIONS[kind]`): ask it, never its name."""

    kind: str                      # a key of kinematika.questions.QUESTIONS
    index: int
    target: Union[str, PointRef]   # body name, material point or joint id
    echo: dict                     # the question as written, echoed in the answer
    relative_to: Optional[str] = None
    moving: Optional[str] = None

    @property
    def where(self) -> str:
        """Where the question is written, for errors: ``ask[1]``."""
        return f"ask[{self.index}]"

    @property
    def name(self) -> str:
        """The body (or joint) a question about a body or joint asks of (`omega`, `alpha`,
        `icr`, `axis`, `pole`, `contact`): its target, which is then a name."""
        if not isinstance(self.target, str):
            raise TypeError(f"{self.where} asks of a material point, not a body")
        return self.target
