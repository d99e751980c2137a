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

from ..questions import QUESTIONS
from .context import Ctx
from .document import CentreNote, Document, Equation, Section

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
    for sec in doc.sections:
        if sec.title.key in LEVELS:
            used, terms = _used_after(doc, sec)
            _prune_section(sec, "v" if sec.title.key == LEVELS[0] else "a", asked, used, terms)


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
        if s is sec:
            started = True
            for b in _blocks(s):           # a velocity written among the accelerations
                if isinstance(b, Equation) and sec.title.key == LEVELS[0] and b.level == "v":
                    terms.update(_point_terms(b))
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
    holders = [(h, eq) for h, eq in _holders(sec) if eq.level == level]
    for holder, eq in reversed(holders):
        forward = not any(t.unknown for side in eq.sides for t in side)
        label = (eq.target.sym.base, eq.target.sym.sub)
        point = _point_of(eq.target.sym.sub)
        if forward and eq.target.kind == "point" and label not in needed_labels and point not in needed:
            holder.blocks.remove(eq)
            continue
        needed_labels.update(_point_terms(eq))      # v_J7∈4 = v_K + …: its known left side too


def _holders(sec: Section) -> list[tuple[Section, Equation]]:
    out: list = []
    for b in sec.blocks:
        if isinstance(b, Section):
            out += _holders(b)
        elif isinstance(b, Equation):
            out.append((sec, b))
    return out
