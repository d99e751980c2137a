"""What the asked quantities need: an explanation explains what is asked and what it takes,
nothing more (the notes never work out a point nobody needs).

A forward evaluation in the velocity or acceleration steps (v_P = v_Q + ω × QP, every term
known) is kept when its point is asked (its velocity, acceleration, curvature, intrinsic
components or composition), when a later equation uses it as a known term, or when an
instant centre is found from it; the others are dropped, last first, so that a chain of
points nobody needs goes as a whole. Equations that find an unknown (an ω, a slide) always
stay. A model without questions asks for everything, and keeps everything.
"""
from __future__ import annotations

import re

from ..questions import QUESTIONS
from .context import Ctx
from .document import CentreNote, Document, Equation, Msg, Section

LEVELS = ("sec.velocities", "sec.accelerations")


def accelerations_asked(ctx: Ctx) -> bool:
    """Whether anything asked needs accelerations: when only velocities, angular velocities
    and instant centres are asked (the epicyclic train, the pulleys, C5-E.3), the explanation
    stops at the velocities, as the notes do. A model without questions asks for everything."""
    return ctx.model.default_questions or any(QUESTIONS[q.kind].level == "acceleration" for q in ctx.model.questions)


def prune(ctx: Ctx, doc: Document) -> None:
    """Drop the forward evaluations of the level sections that nothing needs."""
    if ctx.model.default_questions:
        return
    asked = _asked_points(ctx)
    for sec in reversed(doc.sections):       # the later first: what they drop, the earlier need not keep
        if sec.title.key in LEVELS:
            used, terms = _used_after(doc, sec)
            _prune_section(sec, "v" if sec.title.key == LEVELS[0] else "a", asked, used, terms)
            _drop_unused_rest(sec)


AT_REST = ("rolling.centre", "centre.site", "centre.site_i")


def _drop_unused_rest(sec: Section) -> None:
    """A sentence that a point is at rest (a contact on a fixed body, an instant centre)
    goes with the equations that start from it: none left, the sentence goes too (the belt
    touching the fixed pulley, which nothing asks)."""
    used = {(t.sym.base, t.sym.sub) for b in _blocks(sec) if isinstance(b, Equation)
            for t in [b.target] + [t for side in b.sides for t in side]}
    for holder, block in _messages(sec):
        if block.key in AT_REST and (block.args["sym"].base, block.args["sym"].sub) not in used:
            holder.blocks.remove(block)


def _messages(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        if isinstance(b, Section):
            out += _messages(b)
        elif isinstance(b, Msg):
            out.append((sec, b))
    return out


def _asked_points(ctx: Ctx) -> set[str]:
    """The point names the questions are about (any body's point of that name)."""
    out: set[str] = set()
    for q in ctx.model.questions:
        if QUESTIONS[q.kind].about == "point":
            ref = ctx.model.resolve_point(q.target) if isinstance(q.target, str) else q.target
            out.add(ref.point)
    return out


def _point_of(label: str) -> str:
    return label.split("∈")[0].split("/")[0]


def _used_after(doc: Document, sec: Section) -> tuple[set[str], set[tuple]]:
    """What the rest of the document uses: the point names of instant centres found from a
    point's velocity, and the (v|a, label) of the known point terms of its equations (the
    geometric contact point's v_J^geom = v_S + …, a composition's drag a_S + …)."""
    names: set[str] = set()
    terms: set[tuple] = set()
    started = False
    for s in doc.sections:
        if s is sec:                       # what the section itself needs, `_prune_section` finds
            started = True
            continue
        if not started:
            continue
        for b in _blocks(s):
            if isinstance(b, CentreNote):
                names.update(w[0] for w in b.witnesses if isinstance(w[0], str))
            elif isinstance(b, Equation):
                terms.update(_point_terms(b))
    return names, terms


def _point_terms(eq: Equation) -> set[tuple]:
    """(base, label) of the equation's point terms and of its left side when known."""
    known_target = [] if eq.target.unknown else [eq.target]
    return {(t.sym.base, t.sym.sub) for t in [t for side in eq.sides for t in side] + known_target
            if t.kind == "point"}


def _blocks(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        out += _blocks(b) if isinstance(b, Section) else [b]
    return out


def _prune_section(sec: Section, level: str, asked: set[str], used: set[str], terms: set[tuple]) -> None:
    """Walk the section's equations of its level from the last: keep what is needed and what
    it uses (a velocity worked out among the accelerations, the geometric contact point's,
    serves a term there: it stays, and so does what it uses)."""
    needed = set(used) | set(asked)
    needed_labels: set[tuple] = set(terms)
    holders = [(h, eq) for h, eq in _holders(sec) if isinstance(eq, Msg) or eq.level == level]
    dropped = []
    for holder, eq in reversed(holders):
        if isinstance(eq, Msg):             # no slip in a sentence, v_J∈9 = v_J∈8: a forward step too
            target, other = eq.args["sym"], eq.args["other"]
            if (target.base, target.sub) not in needed_labels and _point_of(target.sub) not in needed:
                holder.blocks.remove(eq)
            else:
                needed_labels.add((other.base, other.sub))
            continue
        forward = not any(t.unknown for side in eq.sides for t in side)
        label = (eq.target.sym.base, eq.target.sym.sub)
        point = _point_of(eq.target.sym.sub)
        if forward and eq.target.kind == "point" and label not in needed_labels and point not in needed:
            holder.blocks.remove(eq)
            dropped.append(eq)
            continue
        needed_labels.update(_point_terms(eq))      # v_J7∈4 = v_K + …: its known left side too
    _drop_orphans(sec, dropped)


def _names(eq: Equation) -> set[str]:
    """The point names an equation's terms mention (J7 in v_J7∈4, a_{J7∈7/4}, v_{J7-H})."""
    out: set[str] = set()
    for t in [eq.target] + [t for side in eq.sides for t in side]:
        out.update(x for x in re.split(r"[∈/,\-]", t.sym.sub) if x)
    return out


def _drop_orphans(sec: Section, dropped: list[Equation]) -> None:
    """The sentences written for a dropped equation alone — a contact's no-slip, the rule of
    its geometric point and that point's velocity — go with it, when no equation left in
    the section speaks of that contact (the chain's J7 on the pinion, which nothing asks)."""
    if not dropped:
        return
    left = set().union(*[_names(b) for b in _blocks(sec) if isinstance(b, Equation)
                         and not any(b in eq.owned for eq in dropped)] or [set()])
    for eq in dropped:
        if not eq.owned or set(eq.contacts) & left:
            continue
        for holder, block in _owned_holders(sec, eq.owned):
            holder.blocks.remove(block)


def _owned_holders(sec: Section, owned: list) -> list:
    out: list = []
    for b in sec.blocks:
        if isinstance(b, Section):
            out += _owned_holders(b, owned)
        elif any(b is o for o in owned):
            out.append((sec, b))
    return out


def _holders(sec: Section) -> list[tuple[Section, Equation | Msg]]:
    """The section's equations, and its no-slip sentences (`rolling.same`), in order, with
    the section that holds each."""
    out: list = []
    for b in sec.blocks:
        if isinstance(b, Section):
            out += _holders(b)
        elif isinstance(b, Equation) or (isinstance(b, Msg) and b.key == "rolling.same"):
            out.append((sec, b))
    return out
