"""The order of solution: inputs, then groups solved from the bodies already known.

The dyad (Assur group) decomposition of `kinematika.structure.assur` is used when the
mechanism decomposes; otherwise the order is read from the engine's
block-triangular form of the velocity system (the same matrix the solver used), each new
block's bodies forming one group.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from ..engine.dense import _blocks, independent_rows
from ..errors import KinematikaError
from ..solution import Solution
from ..structure.assur import assur_groups, dyad as assur_dyad
from .kinds import knife_edge, lower

if TYPE_CHECKING:
    from .context import Ctx


@dataclass
class Step:
    """Bodies solved together from the `known` ones, through `joints` (and drivers)."""

    kind: str                    # input, RRR, RRP, RPR, PRP, other
    bodies: list[str]
    joints: list[str]
    known: list[str] = field(default_factory=list)
    letters: str = ""
    source: str = "assur"        # assur or blocks


def solution_order(sol: Solution) -> list[Step]:
    """The steps of the solution in order (Assur groups, else blocks of the system)."""
    groups = assur_groups(sol.model)
    if groups:
        return [Step(g.kind, list(g.bodies), list(g.joints), list(g.known), g.letters) for g in groups]
    return block_order(sol)


def block_order(sol: Solution) -> list[Step]:
    """Groups of bodies in the block-triangular order of the velocity system."""
    solver, inst = sol.solver, sol.inst
    rows = solver.rows_v
    a, _ = solver.matrix(rows)
    n = solver.unknowns.n
    if n == 0:
        return []
    a_num = np.array([[inst.num(c) for c in row] for row in a], dtype=float).reshape(len(a), n)
    scaled = solver.analysis.scaled.matrix if solver.analysis else a_num
    assert isinstance(scaled, np.ndarray), "a system kept sparse (a large numeric model) has no block order here"
    chosen = independent_rows(scaled, n)
    blocks = _blocks(a_num[chosen], chosen)
    known = {sol.model.frame}
    steps: list[Step] = []
    for block_rows, cols in blocks:
        bodies = [b for b in dict.fromkeys(solver.unknowns.body_of(c) for c in cols) if b not in known]
        joints = _joints_of(sol, [rows[r] for r in block_rows], bodies)
        if not bodies:
            if steps:
                steps[-1].joints += [j for j in joints if j not in steps[-1].joints]
            continue
        driven = any(rows[r].driver for r in block_rows)
        kind = "input" if driven and len(bodies) == 1 and _grounded(sol, bodies[0]) else "other"
        step = Step(kind, bodies, joints, jointed(sol.model, bodies, known), source="blocks")
        steps.append(dyad(sol, step, known) if kind == "other" else step)
        known.update(bodies)
    return steps


def dyad(sol: Solution, step: Step, known: set[str]) -> Step:
    """A group of two bodies chained to known ones by three R or P joints, named as a dyad
    (as `structure.assur` names them)."""
    if len(step.bodies) != 2:
        return step
    b1, b2 = step.bodies

    def between(x: str, others: set[str]) -> list:
        return [j for j in sol.model.joints if {j.a, j.b} & {x} and ({j.a, j.b} - {x}) <= others]

    ends1, ends2, middle = between(b1, known), between(b2, known), between(b1, {b2})
    chain = ends1 + middle + ends2
    if (len(ends1) != 1 or len(ends2) != 1 or len(middle) != 1
            or not all(lower(j) for j in chain)):
        return step
    group = assur_dyad(b1, b2, *chain)
    if group is None or group.kind == "other":
        return step
    return Step(group.kind, group.bodies, group.joints, group.known, group.letters, "blocks")


def _joints_of(sol: Solution, rows: list, bodies: list[str]) -> list[str]:
    """The joints of the block's rows that touch its new bodies."""
    found = {r.joint for r in rows if not r.driver}
    return [j.id for j in sol.model.joints if j.id in found and {j.a, j.b} & set(bodies)]


def _grounded(sol: Solution, body: str) -> bool:
    frame = sol.model.frame
    return any({j.a, j.b} == {frame, body} and lower(j)
               for j in sol.model.joints)


def jointed(model, bodies: list[str], known: set[str]) -> list[str]:
    """The known bodies jointed to `bodies`, in the joints' order."""
    out = []
    for j in model.joints:
        for x, y in ((j.a, j.b), (j.b, j.a)):
            if x in bodies and y in known and y not in out:
                out.append(y)
    return out


def as_found(ctx: Ctx, step: Step) -> Step:
    """The step with its bodies in the order its velocity equations find them and its sources
    in the order they read them, as `group.group_blocks` recorded them (`Ctx.found_order`):
    the order of solution and the step's title say what the step does (round 20f: C5-1.5's
    step finds strand 2, tangent to both pulleys, before pulley 2: "Strand 2 and pulley 2,
    from pulley 1 and the ceiling"). A step not planned equation by equation is as it was."""
    found = ctx.found_order.get(frozenset(step.bodies))
    if found is None:
        return step
    bodies, known = found
    return Step(step.kind, list(bodies), step.joints, list(known), step.letters, step.source)


def merge_vehicles(ctx: Ctx, steps: list[Step]) -> list[Step]:
    """Consecutive groups on knife-edge wheels solved as one (the notes find a vehicle's
    centre from all its wheels at once: the front wheel's speed locates the chassis')."""
    wheeled = {b for j in ctx.model.joints if knife_edge(j) for b in (j.a, j.b)}
    out: list[Step] = []
    for s in steps:
        prev = out[-1] if out else None
        if (prev is not None and prev.kind == s.kind == "other" and prev.source == s.source == "blocks"
                and set(prev.bodies) & wheeled and set(s.bodies) & wheeled
                and any({j.a, j.b} & set(prev.bodies) and {j.a, j.b} & set(s.bodies) for j in ctx.model.joints)):
            out[-1] = Step("other", prev.bodies + s.bodies, prev.joints + s.joints,
                           list(dict.fromkeys(prev.known + [k for k in s.known if k not in prev.bodies])),
                           source="blocks")
        else:
            out.append(s)
    return out


def asked_order(ctx: Ctx, steps: list[Step]) -> list[Step]:
    """The steps in the order the model asks for their bodies, where the dependencies allow
    it: the notes derive the quantities in the order the exercise asks them (C5-E.4 asks the
    left wheel's ω, then the right wheel's; both are found from the chassis alone, so the
    left wheel's step comes first). Two consecutive steps trade places only when both are
    asked (`_rank`), the later one is asked first, neither is an input, and the later one
    neither is solved from the earlier one's bodies nor goes through a joint touching them
    (each is found without the other): a step nobody asked for keeps its place."""
    rank = {id(s): _rank(ctx, s) for s in steps}
    out = list(steps)
    moved = True
    while moved:
        moved = False
        for i in range(len(out) - 1):
            first, second = out[i], out[i + 1]
            if (rank[id(second)] < rank[id(first)] < len(ctx.model.questions)
                    and "input" not in (first.kind, second.kind) and _apart(ctx, first, second)):
                out[i], out[i + 1] = second, first
                moved = True
    return out


def _rank(ctx: Ctx, step: Step) -> int:
    """The index of the model's first question about one of the step's bodies (its ω, α,
    centre, or one of its points' motion); past the last question when none asks."""
    model = ctx.model
    for q in model.questions:
        target = q.target
        body = getattr(target, "body", None)
        if body is None and isinstance(target, str):
            if target in model.bodies:
                body = target
            else:
                try:
                    body = model.resolve_point(target).body
                except (KeyError, ValueError, KinematikaError):     # a joint's id (a contact asked)
                    body = None
        if body in step.bodies:
            return q.index
    return len(model.questions)


def _apart(ctx: Ctx, first: Step, second: Step) -> bool:
    """Whether `second` is found without `first`: not solved from its bodies, and no joint
    of `second` touches them."""
    mine = set(first.bodies)
    if mine & set(second.known):
        return False
    return not any({ctx.model.joint(j).a, ctx.model.joint(j).b} & mine for j in second.joints)
