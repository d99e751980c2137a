"""Every instant centre of every pair of bodies, and how each is found (planar).

The centres themselves come from the solved velocities (`icr.instant_centre`). Alongside,
the textbook's reasoning is reconstructed: a pair joined directly has its centre at the
joint (revolute point, rolling contact, at infinity across a prismatic guide); the other
centres follow by Aronhold–Kennedy — the centres of three bodies taken two by two lie on
one line — as the intersection of two such lines.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations
from typing import Any, Optional

from ..solution import Solution
from .icr import instant_centre


@dataclass
class Centre:
    """The instant centre of `pair[1]` relative to `pair[0]` (the same for the reverse pair)."""

    pair: tuple[str, str]
    value: dict[str, Any]                  # {"point": p} | {"point": None, "direction": d} | rest
    how: str                               # "joint", "kennedy" or "velocities"
    via: list[str] = field(default_factory=list)   # the joint id, or the two third bodies

    @property
    def finite(self) -> bool:
        """Whether the centre is a point (not at infinity, not a rest)."""
        return self.value.get("point") is not None


FIXED = ("pin", "contact", "infinity", "rest")     # a joint's own centre, found without Kennedy
                                                   # ("normal": only a line through it)


def direct_centre(sol: Solution, a: str, b: str) -> Optional[tuple[str, str]]:
    """(how the joint places it, joint id) when a joint between a and b places their centre
    by itself (its kind's `centre`: at its pin, its contact, at infinity, or none at rest)."""
    for j in sol.model.joints:
        if {j.a, j.b} == {a, b} and j.kind.centre in FIXED:
            return j.kind.centre, j.id
    return None


def all_centres(sol: Solution) -> list[Centre]:
    """One `Centre` per pair of bodies, direct ones first, then in the order Kennedy finds them."""
    bodies = list(sol.model.bodies)
    known: dict[frozenset, Centre] = {}
    for a, b in combinations(bodies, 2):
        found = direct_centre(sol, a, b)
        if found:
            pin = _pin(sol, found)
            known[frozenset((a, b))] = Centre((a, b), instant_centre(sol, b, a, pin), "joint", [found[1]])
    progress = True
    while progress:
        progress = False
        for a, b in combinations(bodies, 2):
            key = frozenset((a, b))
            if key in known:
                continue
            thirds = [k for k in bodies if k not in (a, b) and frozenset((a, k)) in known
                      and frozenset((k, b)) in known and _is_line(known, a, k, b)]
            if len(thirds) >= 2:
                known[key] = Centre((a, b), instant_centre(sol, b, a), "kennedy", thirds[:2])
                progress = True
    out = list(known.values())
    for a, b in combinations(bodies, 2):
        if frozenset((a, b)) not in known:
            out.append(Centre((a, b), instant_centre(sol, b, a), "velocities"))
    return out


def _pin(sol: Solution, found: tuple[str, str]) -> str | None:
    """The point of a pin (its bodies' centre while they turn), else None."""
    how, jid = found
    if how != "pin":
        return None
    return next((j.at for j in sol.model.joints if j.id == jid and isinstance(j.at, str)), None)


def _is_line(known: dict[frozenset, Centre], a: str, k: str, b: str) -> bool:
    """Two centres define a Kennedy line unless both are at rest (no line)."""
    return not (known[frozenset((a, k))].value.get("rest") or known[frozenset((k, b))].value.get("rest"))


def collinear(sol: Solution, c1: dict, c2: dict, c3: dict) -> bool:
    """Whether three centres (finite or at infinity) lie on one line, at the model's scale."""
    h1, h2, h3 = (_homogeneous(c) for c in (c1, c2, c3))
    if h1 is None or h2 is None or h3 is None:
        return True
    (x1, y1, w1), (x2, y2, w2), (x3, y3, w3) = h1, h2, h3
    det = x1 * (y2 * w3 - w2 * y3) - y1 * (x2 * w3 - w2 * x3) + w1 * (x2 * y3 - y2 * x3)
    return sol.is_zero(det, sol.inst.scale ** 2 * 1e3)


def _homogeneous(c: dict) -> Optional[tuple]:
    if c.get("rest"):
        return None
    if c.get("point") is not None:
        x, y = c["point"]
        return (x, y, 1)
    dx, dy = c["direction"]
    return (dx, dy, 0)
