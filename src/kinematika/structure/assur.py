"""Structural decomposition of a planar mechanism into its inputs and Assur groups.

A mechanism built the textbook way is a driven crank or slider (an *input*) to which
groups of zero mobility are added one at a time: each group's bodies are found from the
bodies already known. The two-body groups (dyads) are named by their joints in chain
order, R for a revolute and P for a prismatic: RRR, RRP, RPR, PRP. A pin in a slot is a
revolute and a prismatic with a slider block between them, so one body with a revolute
and a slot is a dyad too (RPR when the slot is cut in it, RRP when its pin slides in a
slot of a known body). Any other group of zero mobility (a triad, a gear pair) is
`other`. Position, velocity and acceleration can then be solved group by group in this
order, which is also the order of a step-by-step textbook solution.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import combinations
from typing import Optional

from ..model.model import Driver, Joint, Model

KINDS = ("input", "RRR", "RRP", "RPR", "PRP", "other")

_MAX_OTHER = 4          # largest group of `other` kind searched for


@dataclass
class Group:
    """One step of the decomposition: bodies solved together from the `known` ones.

    For an input, `bodies` is the driven body and `joints` its joint to the frame. For a
    dyad, `joints` is in chain order (attaching, internal, attaching) and `known[0]`,
    `known[-1]` are the bodies attached by `joints[0]`, `joints[-1]` (the same body may
    appear twice); a one-body dyad with a slot has the two attaching joints only.
    """

    kind: str
    bodies: list[str]
    joints: list[str]
    known: list[str]
    letters: str = field(default="", repr=False)   # R/P per pair in chain order (slot = "RP"/"PR")


def assur_groups(model: Model) -> Optional[list[Group]]:
    """Inputs then Assur groups in solving order; None when the model does not decompose."""
    if model.dimension != 2:
        return None
    graph = _Graph(model)
    found = [graph.input_of(d) for d in model.drivers]
    inputs = [g for g in found if g is not None]
    if not inputs or len(inputs) < len(found):
        return None
    groups: list[Group] = []
    for g in inputs:
        if g.bodies[0] in graph.known:
            return None          # two drivers on one body
        graph.solve(g)
        groups.append(g)
    while len(graph.known) < len(model.bodies):
        group = graph.next_dyad() or graph.next_other()
        if group is None:
            return None
        graph.solve(group)
        groups.append(group)
    return groups if not graph.unused else None


class _Graph:
    """Bodies and joints, with what is known so far and which joints are still unused."""

    def __init__(self, model: Model) -> None:
        self.model = model
        self.known = {model.frame}
        self.unused = {j.id: j for j in model.joints}
        self.by_body: dict[str, list[Joint]] = {b: [] for b in model.bodies}
        for j in model.joints:
            self.by_body[j.a].append(j)
            self.by_body[j.b].append(j)

    def solve(self, group: Group) -> None:
        self.known.update(group.bodies)
        for jid in group.joints:
            self.unused.pop(jid, None)

    def input_of(self, d: Driver) -> Optional[Group]:
        """The driven body and its revolute or prismatic joint to the frame."""
        frame = self.model.frame
        if d.kind == "joint":
            assert d.joint is not None          # a joint-rate driver names its joint (model.build)
            j = self.model.joint(d.joint)
            body = j.b if j.a == frame else j.a if j.b == frame else None
        elif d.kind == "omega" and d.relative_to in (None, frame):
            body = d.body
        elif d.kind == "velocity" and d.relative_to in (None, frame):
            assert d.point is not None          # a velocity driver names its point (model.build)
            body = d.point.body
        else:
            return None
        if body is None or body == frame:
            return None
        to_frame = [j for j in self.by_body[body] if frame in (j.a, j.b) and _lower(j)]
        if len(to_frame) != 1 or (d.kind == "joint" and to_frame[0].id != d.joint):
            return None
        j = to_frame[0]
        return Group("input", [body], [j.id], [frame], _letter(j))

    def attaching(self, body: str) -> list[Joint]:
        return [j for j in self.by_body[body] if j.id in self.unused and _other(j, body) in self.known]

    def next_dyad(self) -> Optional[Group]:
        for b1 in self.model.bodies:
            if b1 in self.known:
                continue
            ends = self.attaching(b1)
            if len(ends) == 2 and all(j.kind.chain.pairs for j in ends):
                group = _one_body_dyad(b1, ends)
                if group is not None:
                    return group
            if len(ends) != 1 or not _lower(ends[0]):
                continue
            for j2 in self.by_body[b1]:
                b2 = _other(j2, b1)
                if j2.id not in self.unused or b2 in self.known or not _lower(j2):
                    continue
                tail = self.attaching(b2)
                if len(tail) == 1 and _lower(tail[0]):
                    return dyad(b1, b2, ends[0], j2, tail[0])
        return None

    def next_other(self) -> Optional[Group]:
        """The smallest set of unknown bodies that the known ones fix (Grübler count ≤ 0)."""
        unknown = [b for b in self.model.bodies if b not in self.known]
        for size in range(1, min(_MAX_OTHER, len(unknown)) + 1):
            for bodies in combinations(unknown, size):
                chosen = set(bodies)
                joints = [j for j in self.unused.values()
                          if {j.a, j.b} <= chosen | self.known and {j.a, j.b} & chosen]
                if not joints or not self._connected(chosen, joints):
                    continue
                if 3 * size - sum(j.kind.conditions(2) for j in joints) <= 0:
                    known = sorted({_other(j, b) for j in joints for b in chosen
                                    if b in (j.a, j.b) and _other(j, b) in self.known})
                    return Group("other", list(bodies), [j.id for j in joints], known)
        return None

    @staticmethod
    def _connected(bodies: set[str], joints: list[Joint]) -> bool:
        start = next(iter(bodies))
        seen, todo = {start}, [start]
        while todo:
            b = todo.pop()
            for j in joints:
                if b in (j.a, j.b):
                    o = _other(j, b)
                    if o in bodies and o not in seen:
                        seen.add(o)
                        todo.append(o)
        return seen == bodies


def _other(j: Joint, body: str) -> str:
    return j.b if j.a == body else j.a


def _lower(j: Joint) -> bool:
    """A revolute or prismatic pair: one letter of a dyad's name."""
    return j.kind.chain.pairs == 1


def _letter(j: Joint) -> str:
    return j.kind.chain.value


def dyad(b1: str, b2: str, j1: Joint, j2: Joint, j3: Joint) -> Optional[Group]:
    """The dyad b1, b2 chained by revolute or prismatic j1 (to a known body), j2, j3 (to a
    known body), named by its pairs (PRR read from the other end as RRP); None if PPP."""
    letters = _letter(j1) + _letter(j2) + _letter(j3)
    if letters == "PRR":                      # read the chain from the other end
        b1, b2, j1, j3 = b2, b1, j3, j1
        letters = "RRP"
    kind = letters if letters in ("RRR", "RRP", "RPR", "PRP") else "other"
    if letters == "PPP":
        return None                           # not rigid: it slides freely
    return Group(kind, [b1, b2], [j1.id, j2.id, j3.id], [_other(j1, b1), _other(j3, b2)], letters)


def _one_body_dyad(body: str, ends: list[Joint]) -> Optional[Group]:
    """A body with a slot and a revolute or prismatic joint to known bodies."""
    slots = [j for j in ends if j.kind.chain.pairs == 2]
    if len(slots) != 1:
        return None
    slot = slots[0]
    first = next(j for j in ends if j is not slot)
    # the slider block sits between the slot's line (fixed in slot.a) and its pin (on slot.b)
    slot_letters = slot.kind.chain.read_from(slot.a == body)
    letters = _letter(first) + slot_letters
    kinds = {"RPR": "RPR", "RRP": "RRP", "PRP": "PRP"}
    kind = kinds.get(letters, "other")
    return Group(kind, [body], [first.id, slot.id], [_other(first, body), _other(slot, body)], letters)
