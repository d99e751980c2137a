"""Every instant centre of every pair of bodies, and how each is found (planar).

The centres themselves come from the solved velocities (`icr.instant_centre`). Alongside,
the textbook's reasoning is reconstructed from the structure alone: a pair joined directly
has its centre at the joint (revolute point, rolling contact, at infinity across a
prismatic guide); a body welded to another shares its centres; the other centres follow by
Aronhold–Kennedy — the centres of three bodies taken two by two lie on one line — as the
intersection of two such lines, or of one with a line a joint gives (the normal to a slot
at its pin, the axle of a knife-edge wheel). A centre none of these reaches is found from
the velocities (`how` "velocities").
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations
from typing import Any, Optional

from ..joints.capabilities import Centre as JointCentre
from .base import Solved
from .icr import instant_centre


FIXED = tuple(c for c in JointCentre if c.placed)     # a joint's own centre, found without Kennedy


@dataclass
class Centre:
    """The instant centre of `pair[1]` relative to `pair[0]` (the same for the reverse pair)."""

    pair: tuple[str, str]
    value: dict[str, Any]                  # {"point": p} | {"point": None, "direction": d} | rest
    how: str                               # "joint", "weld", "kennedy", "lines" or "velocities"
    via: list[str] = field(default_factory=list)   # the joint id, the weld and the body welded,
                                                   # the two third bodies, or (lines) each line's
    lines: list[tuple[str, str]] = field(default_factory=list)   # ("third", body) | ("joint", id)

    @property
    def finite(self) -> bool:
        """Whether the centre is a point (not at infinity, not a rest)."""
        return self.value.get("point") is not None


def direct_centre(sol: Solved, a: str, b: str) -> Optional[tuple[JointCentre, str]]:
    """(how the joint places it, joint id) when a joint between a and b places their centre
    by itself (its kind's `centre`: at its pin, its contact, at infinity, or none at rest)."""
    for j in sol.model.joints:
        if {j.a, j.b} == {a, b} and j.kind.centre.placed:
            return j.kind.centre, j.id
    return None


def all_centres(sol: Solved) -> list[Centre]:
    """One `Centre` per pair of bodies: direct ones first, then in the order the structure
    finds them (welds, Kennedy, Kennedy with a joint's line), the rest from the velocities."""
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
            reached = _structural(sol, known, bodies, a, b)
            if reached is not None:
                known[key] = reached
                progress = True
    out = list(known.values())
    for a, b in combinations(bodies, 2):
        if frozenset((a, b)) not in known:
            out.append(Centre((a, b), instant_centre(sol, b, a), "velocities"))
    return out


def _structural(sol: Solved, known: dict, bodies: list[str], a: str, b: str) -> Optional[Centre]:
    """The centre of (a, b) from centres already known: by a weld, by two Kennedy lines, or by
    Kennedy lines and the lines joints give; None when the structure does not yet fix it."""
    for x, y in ((a, b), (b, a)):
        for j, other in _welded(sol, y):
            if other != x and frozenset((x, other)) in known and not known[frozenset((x, other))].value.get("rest"):
                pair = (a, b)
                return Centre(pair, instant_centre(sol, b, a), "weld", [j, other])
    thirds: list[str] = []
    for k in bodies:        # a body welded to a third already taken gives the same line: once
        if (k not in (a, b) and frozenset((a, k)) in known and frozenset((k, b)) in known
                and _is_line(known, a, k, b) and not any(other in thirds for _, other in _welded(sol, k))):
            thirds.append(k)
    if len(thirds) >= 2:
        return Centre((a, b), instant_centre(sol, b, a), "kennedy", thirds[:2])
    candidates = [("third", k, _kennedy_line(sol, known, a, k, b)) for k in thirds]
    candidates += [("joint", j.id, _joint_line(sol, j)) for j in sol.model.joints
                   if {j.a, j.b} == {a, b} and crossed_by_a_normal(j)]
    lines: list[tuple[str, str, tuple]] = [(kind, name, line) for kind, name, line in candidates if line is not None]
    for i, first in enumerate(lines):
        for second in lines[i + 1:]:
            if not same_line(sol.inst, first[2], second[2]):
                return Centre((a, b), instant_centre(sol, b, a), "lines", [first[1], second[1]],
                              [(first[0], first[1]), (second[0], second[1])])
    return None


def crossed_by_a_normal(j: Any) -> bool:
    """Whether the joint puts the relative centre of its bodies on one line through it: the
    normal to a slot at its pin, the axle of a knife-edge wheel (no velocity across them),
    the common normal at a contact that slides (a cam)."""
    return bool(j.kind.guides_point or j.kind.centre is JointCentre.NORMAL)


def _welded(sol: Solved, body: str) -> list[tuple[str, str]]:
    """(weld joint, other body) of each weld of `body`: the two are one rigid body."""
    return [(j.id, j.b if j.a == body else j.a) for j in sol.model.joints
            if body in (j.a, j.b) and j.kind.rigid]


def _kennedy_line(sol: Solved, known: dict, a: str, k: str, b: str) -> Optional[tuple]:
    """(point, direction) as floats of the line through the centres a–k and k–b."""
    return centre_line(sol.inst, known[frozenset((a, k))].value, known[frozenset((k, b))].value)


def centre_line(inst: Any, c1: dict, c2: dict) -> Optional[tuple]:
    """The line through two instant centres as (point, direction) in floats (a centre at
    infinity gives the line through the other along its direction); None when both are at
    infinity or the two coincide. `inst` is the instant the centres were found at."""
    p1, p2 = c1.get("point"), c2.get("point")
    if p1 is None and p2 is None:
        return None
    if p1 is None or p2 is None:
        p, c = (p1, c2) if p2 is None else (p2, c1)
        d = c.get("direction")
        return None if d is None else (_floats(inst, p), _floats(inst, d))
    x, y = _floats(inst, p1), _floats(inst, p2)
    d = (y[0] - x[0], y[1] - x[1])
    return None if (d[0] ** 2 + d[1] ** 2) ** 0.5 <= 1e-9 * inst.scale else (x, d)


def _joint_line(sol: Solved, j: Any) -> Optional[tuple]:
    """(point, direction) as floats of the normal to a slot or a wheel's plane at its point,
    or of the common normal at a contact."""
    geo = sol.solver.geos.get(j.id)
    contact = getattr(geo, "contact", None) if geo is not None else None
    if contact is not None and getattr(contact, "normal", None) and getattr(contact, "point", None) is not None:
        return _floats(sol.inst, contact.point), _floats(sol.inst, contact.normal)
    if geo is None or geo.at is None or geo.along is None:
        return None
    e = _floats(sol.inst, geo.along)
    return _floats(sol.inst, geo.at), (-e[1], e[0])


def same_line(inst: Any, l1: tuple, l2: tuple) -> bool:
    """Whether two lines (point, direction) are one: d × e = 0 and d × (q − p) = 0 to the
    instant's scale (parallel lines that are two meet at infinity: a centre)."""
    (p, d), (q, e) = l1, l2
    nd, ne = (d[0] ** 2 + d[1] ** 2) ** 0.5, (e[0] ** 2 + e[1] ** 2) ** 0.5
    if abs(d[0] * e[1] - d[1] * e[0]) > 1e-9 * nd * ne:
        return False
    w = (q[0] - p[0], q[1] - p[1])
    return abs(d[0] * w[1] - d[1] * w[0]) <= 1e-9 * nd * inst.scale


def _floats(inst: Any, v: Any) -> tuple:
    return tuple(float(inst.num(c)) for c in v)


def _pin(sol: Solved, found: tuple[JointCentre, str]) -> str | None:
    """The point of a pin (its bodies' centre while they turn), else None."""
    how, jid = found
    if how is not JointCentre.PIN:
        return None
    return next((j.at for j in sol.model.joints if j.id == jid and isinstance(j.at, str)), None)


def _is_line(known: dict[frozenset, Centre], a: str, k: str, b: str) -> bool:
    """Two centres define a Kennedy line unless both are at rest (no line)."""
    return not (known[frozenset((a, k))].value.get("rest") or known[frozenset((k, b))].value.get("rest"))


def collinear(sol: Solved, c1: dict, c2: dict, c3: dict) -> bool:
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
