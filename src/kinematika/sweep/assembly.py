"""One way a mechanism closes at its drawn input (`Assembly`), as `assemblies` lists them
(dyads closed either way) and `search` finds them (numerically)."""
from __future__ import annotations

from dataclasses import dataclass, field

from ..model.model import Model


@dataclass
class Assembly:
    """One way the mechanism closes at the drawn input."""

    number: int
    drawn: bool
    closures: list[str]                       # how each dyad closes, in words
    model: Model                              # the mechanism posed on this assembly
    points: dict[str, tuple] = field(default_factory=dict)   # every point's place
