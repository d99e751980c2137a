"""The words a joint kind answers the rest of kinematika with, typed in one place.

A kind's capabilities that are not yes/no (`JointKind.coordinate`, `centre`, `chain`,
`along_in`, `point_on`, the needs in `fields`) take their values from the enumerations
and literals below: a module that asks compares with a member (`kind.coordinate is
Coordinate.ANGLE`), never with a string spelled again, so a misspelt capability is an
`AttributeError` at import and a mypy error, not a comparison that is quietly false.

The enumerations are `StrEnum`s: a member is its word (`Coordinate.ANGLE == "angle"`), so
what is written from them (JSON, messages) is unchanged.
"""
from __future__ import annotations

from enum import StrEnum
from typing import Literal


class Coordinate(StrEnum):
    """The joint's own coordinate, which a driver may give the rate of and a sweep advance:
    an angle (degrees in files, rad/s for its rate) or a length."""

    ANGLE = "angle"
    LENGTH = "length"


class Centre(StrEnum):
    """Where a joint puts the relative instant centre of its two bodies by itself."""

    PIN = "pin"                 # at its point `at`
    CONTACT = "contact"         # at the contact point (rolling without slipping)
    INFINITY = "infinity"       # at infinity, normal to the sliding
    REST = "rest"               # none: the bodies move as one
    NORMAL = "normal"           # only a line through it: the normal at the pin or contact
    NONE = ""                   # nothing

    @property
    def placed(self) -> bool:
        """Whether the joint alone places the centre (a point, at infinity, or none at rest),
        so it is found without Aronhold–Kennedy."""
        return self in (Centre.PIN, Centre.CONTACT, Centre.INFINITY, Centre.REST)


class Chain(StrEnum):
    """The lower pairs a joint is in a chain, read from its body `a` to `b`; they name the
    dyads (RRR, RRP, …)."""

    R = "R"                     # a turning pair
    P = "P"                     # a sliding pair
    PR = "PR"                   # a pin in a slot: the slot's line in a, a slider block, the pin of b
    NONE = ""                   # not a lower pair of a chain

    @property
    def pairs(self) -> int:
        """How many lower pairs it counts for in a chain (0, 1, or 2 for a pin in a slot)."""
        return len(self.value)

    def read_from(self, a_first: bool) -> str:
        """Its letters read from body `a` (`a_first`) or from `b` (reversed: "RP")."""
        return self.value if a_first else self.value[::-1]


class Side(StrEnum):
    """One of a joint's two bodies: `a`, the first, or `b`."""

    A = "a"
    B = "b"


class PointOn(StrEnum):
    """The bodies that must carry the joint's point `at`."""

    AB = "ab"                   # both (a pin)
    B = "b"                     # the second (a pin in a slot, a follower, a wheel)
    NONE = ""                   # neither (or no point)

    def bodies(self, a: str, b: str) -> tuple[str, ...]:
        """The names of those bodies, for the joint between `a` and `b`."""
        return {PointOn.AB: (a, b), PointOn.B: (b,)}.get(self, ())


Need = Literal["required", "optional", "required in 3D", "optional in 3D"]
"""Whether a kind needs one of a joint's optional keys (`JointKind.fields`): in every model,
never, or only in 3D ("required in 3D" is absent in a planar model; "optional in 3D" too)."""

CentreLine = Literal["", "normal", "slot", "wheel"]
"""With `Centre.NORMAL`, which line the centre is on, in an explanation's words (its message
`centre-line-…`): the common normal at the contact, the normal to a slot at its pin, a
wheel's axle."""

__all__ = ["Centre", "CentreLine", "Chain", "Coordinate", "Need", "PointOn", "Side"]
