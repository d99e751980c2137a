"""A model's named value (`parameters:`), in a module of its own: a model without
parameters (a chain of a thousand pins) never makes one, so its command does not define the
class (a dataclass's definition costs about as much as a thousand joints' checks)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from ..expressions import Expr


@dataclass
class Parameter:
    """A named value of the model; `value` None keeps it a symbol, so answers are formulas in
    it; `positive` tells the algebra its sign (lengths are positive; an angle may have either)."""

    name: str
    value: Optional[Expr]          # None: a symbol
    positive: bool = True
