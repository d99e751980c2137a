"""What the asked quantities need: an explanation explains what is asked and what it takes,
nothing more (the notes never work out a point nobody needs).

A forward evaluation in the velocity or acceleration steps (v_P = v_Q + ω × QP, every term
known) is kept when its point is asked (its velocity, acceleration, curvature, intrinsic
components or composition), when a later equation uses it as a known term, or when an
instant centre is found from it; the others are dropped, last first, so that a chain of
points nobody needs goes as a whole. An equation that finds the rate (ω or α) of a moving
body the structure lists stays, as if asked (`listed_bodies`: the student who reads the
table asks for every row, round 17a, and a body's step is written the way its kind is,
round 27b); other equations that find an unknown (a slide, a point) always stay. A model
without questions asks for everything, and keeps everything.
"""
from __future__ import annotations

import re
from typing import Any

from ..questions import QUESTIONS
from .context import Ctx
from .document import CentreNote, Derived, Document, Equation, Inline, Lead, Msg, Names, Section, Sym, Table, Term

LEVELS = ("sec.velocities", "sec.accelerations")


def accelerations_asked(ctx: Ctx) -> bool:
    """Whether anything asked needs accelerations: when only velocities, angular velocities
    and instant centres are asked (the epicyclic train, the pulleys, C5-E.3), the explanation
    stops at the velocities, as the notes do. A model without questions asks for everything."""
    return ctx.model.default_questions or any(QUESTIONS[q.kind].level == "acceleration" for q in ctx.model.questions)


def centres_asked_first(ctx: Ctx) -> bool:
    """Whether the model asks an instant centre before anything of the accelerations: then
    the centres found from the velocities are said right after the velocities, before the
    accelerations, in the order the questions come (C5-E.6: the notes' first question is the
    pedals' centre, their second the curvature of P's path)."""
    if ctx.model.default_questions:
        return False
    from .asked import worked

    centres = worked(ctx).centres
    for q in ctx.model.questions:
        if q in centres:
            return True
        if QUESTIONS[q.kind].level == "acceleration":
            return False
    return False


def prune(ctx: Ctx, doc: Document) -> None:
    """Drop the forward evaluations of the level sections that nothing needs."""
    if ctx.model.default_questions:
        return
    kept = _snapshot(doc.sections)
    wanted = _asked_bodies(ctx) | listed_bodies(ctx)
    unworked = _prune(ctx, doc, wanted)
    halves = unworked.get("a", set()) - unworked.get("v", set())
    if halves:                  # ω worked, α not: the table would show a hole — work α out too
        _restore(kept)
        unworked = _prune(ctx, doc, wanted | halves)
    steps, idle, rated = _idle(ctx, doc, unworked.get("v", set()))
    centres = frozenset(s.centre for s in steps if s.centre)
    if centres:
        # the centre of a wheel given its rate after the steps: its motion stays in the step
        # of the body that carries it, as that step wrote it (C5-1.2's v_Q = v_{I_OQ} +
        # v_{Q,I_OQ} in Step 1, round 24d), not a line of the wheel's own step
        _restore(kept)
        unworked = _prune(ctx, doc, wanted | halves, centres)
        steps, idle, rated = _idle(ctx, doc, unworked.get("v", set()))
    _drop_rows(doc, unworked.get("v", set()), unworked.get("a", set()) - rated, keep=rated)
    for step in steps:
        _idle_step(doc, step)
    if idle:
        for s in doc.sections:
            if s.title.key in ("sec.rates_summary", "sec.rates_summary_v"):
                # before the table that prints their rates (round 20a): a line is read before
                # the value it finds is listed
                at = next((k for k, b in enumerate(s.blocks) if isinstance(b, Table)), len(s.blocks))
                s.blocks[at:at] = idle


def listed_bodies(ctx: Ctx) -> set[str]:
    """The moving bodies the structure table lists: each keeps the equation its step finds
    its rate with, as if asked, written the way the step writes its kind (issue 30,
    twenty-seventh round (b): C5-E.6's front wheel read "its contact point J is its instant
    centre, so: v_F = −ω·R_wheel" beside the rear wheel's vector equation; C5-1.4's third
    planet "by symmetry" beside the first one's centre and equation). A body whose rate no
    step finds is left to `idle`."""
    return {b for b in ctx.model.moving_bodies if not ctx.fixed(b)}


def _idle(ctx: Ctx, doc: Document, unworked: set[str]) -> tuple[list, list, set[str]]:
    """The steps and the lines for the moving bodies the structure lists and no step works
    out (`idle.idle_blocks`), and those given a rate there."""
    from .idle import idle_blocks, written_motions

    listed = [b for b in ctx.model.moving_bodies if not ctx.fixed(b)]
    idle = [b for b in listed if b in unworked]
    if not idle:
        return [], [], set()
    accel = any(s.title.key == "sec.rates_summary" for s in doc.sections)
    return idle_blocks(ctx, idle, [b for b in listed if b not in unworked], accel, written_motions(doc.sections))


def _idle_step(doc: Document, step: Any) -> None:
    """A body given its rate after the solver's steps (`idle.IdleStep`) gets a numbered step
    of its own at the end of the velocities (and of the accelerations), and the order of
    solution an item for it: "4. The *front wheel*, from the *ground* and the *frame*." Every
    body, and every point velocity, is derived in a step the order lists; the summary of
    rates only collects (round 24d)."""
    from .order import Step
    from .structure import order_item, step_title

    found = Step("other", [step.body], [], list(step.known))
    for sec in doc.sections:
        lines = {LEVELS[0]: step.velocity, LEVELS[1]: step.acceleration}.get(sec.title.key)
        if sec.title.key == "sec.structure":
            for sub in (b for b in sec.blocks if isinstance(b, Section) and b.title.key == "sec.order"):
                n = sum(1 for m in sub.blocks if isinstance(m, Msg) and m.key in ORDER_ITEMS)
                sub.add(order_item(n + 1, found))
        elif lines:
            numbered = [k for k, b in enumerate(sec.blocks) if isinstance(b, Section) and b.title.key in STEP_TITLES]
            at = numbered[-1] + 1 if numbered else len(sec.blocks)
            sec.blocks.insert(at, Section(step_title(len(numbered) + 1, found), list(lines), level=3))


def _snapshot(blocks: list) -> list:
    """What pruning changes in a document's sections (their lists of blocks, their titles'
    arguments), to put back (`_restore`): the sections stay the same objects, which the
    builder still holds (it draws the polygons into them after pruning)."""
    out: list = []
    for b in blocks:
        if isinstance(b, Section):
            args = dict(b.title.args) if isinstance(b.title, Msg) else None
            out.append((b, list(b.blocks), args))
            out += _snapshot(b.blocks)
    return out


def _restore(snapshot: list) -> None:
    for sec, blocks, args in snapshot:
        sec.blocks = blocks
        if args is not None:
            sec.title.args = args


def _prune(ctx: Ctx, doc: Document, bodies: set[str], points: frozenset[str] = frozenset()) -> dict[str, set[str]]:
    """One pass of `prune` keeping the rates of `bodies` and the motions of `points` (as if
    asked): the bodies left unworked, by level.
    A body whose ω the explanation works out has its α worked out too (when accelerations
    are explained): the table of rates has no holes (C5-E.4's right wheel, C5-E.6's front
    wheel)."""
    asked = _asked_points(ctx) | points
    unworked: dict[str, set[str]] = {}
    for sec in reversed(doc.sections):       # the later first: what they drop, the earlier need not keep
        if sec.title.key in LEVELS:
            used, terms = _used_after(doc, sec)
            rates = _rates_after(ctx, doc, sec) | bodies
            level = "v" if sec.title.key == LEVELS[0] else "a"
            unworked[level] = _prune_section(sec, level, asked, used, terms, rates)
            _drop_unused_rest(sec)
            _untitle(sec, unworked[level])
    return unworked


AT_REST = ("rolling.centre", "centre.site", "centre.site_s", "centre.site_here", "centre.site_s_here")


def _drop_unused_rest(sec: Section) -> None:
    """A sentence that a point is at rest (a contact on a fixed body, an instant centre)
    goes with the equations that start from it: none left, the sentence goes too (the belt
    touching the fixed pulley, which nothing asks)."""
    used = {(t.sym.base, t.sym.sub) for b in sec.leaves() if isinstance(b, Equation)
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


def _asked_bodies(ctx: Ctx) -> set[str]:
    """The bodies whose rate an answer needs: every body a question names (its ω, its α, the
    body of an asked point, a contact's two bodies), except an instant centre's, which the
    centres section places from the joints (its rate, when the centre is found from it, is
    a use of that rate: `_rates_after`)."""
    out: set[str] = set()
    for q in ctx.model.questions:
        about = QUESTIONS[q.kind].about
        if about == "point":
            ref = ctx.model.resolve_point(q.target) if isinstance(q.target, str) else q.target
            out.add(ref.body)
        elif about == "joint":
            j = ctx.model.joint(q.name)
            out.update((j.a, j.b))
        elif QUESTIONS[q.kind].needs_rate:
            out.add(q.name)
        for b in (q.relative_to, getattr(q, "moving", None)):
            if b:
                out.add(b)
    return out


def _syms(x, out: set) -> set:
    """Every symbol in a block or its parts (terms, formulas, message arguments)."""
    if isinstance(x, Sym):
        out.add((x.base, x.sub))
    elif isinstance(x, (list, tuple)):
        for y in x:
            _syms(y, out)
    elif isinstance(x, dict):
        for y in x.values():
            _syms(y, out)
    elif isinstance(x, (Msg,)):
        _syms(x.args, out)
    elif isinstance(x, (Inline, Names)):
        _syms(x.items, out)
    elif isinstance(x, Term):
        _syms([x.sym, x.how, x.mag.ref, x.dir.ref], out)
    elif isinstance(x, Equation):
        _syms([x.target] + [t for side in x.sides for t in side], out)
    elif isinstance(x, Derived):
        _syms([x.how, x.remark], out)
    elif isinstance(x, Table):
        _syms([x.header, x.rows], out)
    elif isinstance(x, Section):
        _syms([x.title, x.blocks], out)
    return out


def _rate_bodies(ctx: Ctx, syms: set) -> set[str]:
    """The bodies whose ω or α (absolute or relative: ω_3/2 needs ω_3) the symbols name."""
    return {part for base, sub in syms if base in ("ω", "α") for part in sub.split("/") if part in ctx.model.bodies}


def _rates_after(ctx: Ctx, doc: Document, sec: Section) -> set[str]:
    """The bodies whose rate the rest of the document uses: in an equation, a value read
    off one, a sentence, a check; an instant centre found from a rate (0 = v_Q + ω × QI)."""
    syms: set = set()
    out: set[str] = set()
    for s in doc.sections[doc.sections.index(sec) + 1:]:
        if s.title.key in ("sec.rates_summary", "sec.rates_summary_v", "sec.answers"):
            continue                    # they list the rates found, they do not use them
        for b in s.leaves():
            if isinstance(b, CentreNote):
                if b.rate is not None or b.how in ("rate", "field", "check"):
                    out.update(x for x in b.pair if x != ctx.frame)
            else:
                _syms(b, syms)
    return out | _rate_bodies(ctx, syms)


def _drop_rows(doc: Document, bodies: set[str], alphas: set[str], keep: frozenset | set = frozenset()) -> None:
    """The rates' table lists what the explanation found: a body whose ω was not worked out
    has no row, one whose α was not, no α (—); the order of solution names the bodies each
    step works out."""
    if not bodies and not alphas:
        return
    for s in doc.sections:
        if s.title.key in ("sec.rates_summary", "sec.rates_summary_v"):
            for t in (b for b in s.blocks if isinstance(b, Table)):
                # a body given its rate in a line after the table (`idle`) keeps its row
                t.rows = [r for r in t.rows if getattr(r[0], "text", None) not in bodies - set(keep)]
                for r in t.rows:
                    if len(r) > 2 and getattr(r[0], "text", None) in alphas:
                        r[2] = "—"
        if s.title.key == "sec.structure":
            for m in (b for b in s.leaves() if isinstance(b, Msg) and b.key in ORDER_ITEMS):
                _unname(m, bodies)
            _drop_order_items(s, bodies)


def _drop_order_items(sec: Section, bodies: set[str]) -> None:
    """An item of the order of solution whose every body went unworked goes, and the rest are
    numbered on: the order lists the steps the page writes (C5-1.4's third planet, which
    nothing asks, is no "6." without a step 6)."""
    def unworked(m: Msg) -> bool:
        named = m.args.get("bodies")
        named = named.item if isinstance(named, Lead) else named
        return isinstance(named, Names) and all(getattr(n, "text", n) in bodies for n in named.items)

    for sub in (b for b in sec.blocks if isinstance(b, Section)):
        sub.blocks = [b for b in sub.blocks
                      if not (isinstance(b, Msg) and b.key in ORDER_ITEMS and unworked(b))]
        n = 0
        for m in (b for b in sub.blocks if isinstance(b, Msg) and b.key in ORDER_ITEMS):
            if isinstance(m.args.get("n"), int):
                n += 1
                m.args["n"] = n


STEP_TITLES = ("step.title", "step.title_group")
# the order of solution's items: found from bodies, or (the first, a translating chassis) from the data
ORDER_ITEMS = ("order.item", "order.item_group", "order.item_data", "order.item_group_data", "order.item_through",
               "order.item_group_through")


def _untitle(sec: Section, bodies: set[str]) -> None:
    """A step's title names the bodies it works out: not one whose rate went unworked; a
    step left with nothing to say goes, and the steps after it are numbered on (C5-E.4's
    right wheel at accelerations, which nothing asks: no "Step 2" with nothing under it)."""
    sec.blocks = [b for b in sec.blocks if not (isinstance(b, Section) and b.title.key in STEP_TITLES
                                                and not b.blocks)]
    n = 0
    for step in (b for b in sec.blocks if isinstance(b, Section)):
        _unname(step.title, bodies)
        if step.title.key in STEP_TITLES and isinstance(step.title.args.get("n"), int):
            n += 1
            step.title.args["n"] = n


def _unname(m: Msg, bodies: set[str]) -> None:
    """An item of the order of solution names the bodies its step works out: one whose rate
    went unworked leaves the list. A step that found its bodies from others through such a
    body keeps it as the way it went: "1. The *bar OQ*, from the *left plane* and the *right
    plane*, through the *left wheel* and the *right wheel*" (issue 30, twenty-seventh round
    (e): C5-1.2's bar is placed by the wheels' centres, which roll on the planes, and the
    item read as if the planes gave it alone)."""
    named = m.args.get("bodies")
    lead = isinstance(named, Lead)
    named = named.item if isinstance(named, Lead) else named
    if bodies and isinstance(named, Names):
        left = [n for n in named.items if getattr(n, "text", n) not in bodies]
        if left and len(left) < len(named.items):
            kept = Names(left, named.each)
            m.args["bodies"] = Lead(kept) if lead else kept
            if m.key in THROUGH:
                m.key = THROUGH[m.key]
                m.args["through"] = Names([n for n in named.items if n not in left], "order.from")


# an item found from bodies, and the same item naming the bodies it went through (`_unname`)
THROUGH = {"order.item": "order.item_through", "order.item_group": "order.item_group_through"}


# the sentences that carry a point's velocity across a contact (v_J∈9 = v_J∈8): forward steps
FORWARD = ("rolling.same", "rolling.equal")


def _point_of(label: str) -> str:
    return label.split("∈")[0].split("/")[0]


def _used_after(doc: Document, sec: Section) -> tuple[set[str], set[tuple]]:
    """What the rest of the document uses: the point names of instant centres found from a
    point's velocity, and the (v|a, label) of the known point terms of its equations (the
    geometric contact point's v_J^geom = v_S + …, a composition's drag a_S + …). A centre
    placed in a velocity step reads its witnesses' velocities too, which that section then
    keeps (round 27b: C5-1.4's second planet's centre "A2 moves at (−r·ω, √3·r·ω)" with v_A2
    never written)."""
    names: set[str] = set()
    terms: set[tuple] = set()
    started = False
    for s in doc.sections:
        if s is sec:                       # what the section itself needs, `_prune_section` finds
            started = True
            names.update(w[0] for b in s.leaves() if isinstance(b, CentreNote) for w in b.witnesses
                         if isinstance(w[0], str))
            continue
        if not started:
            continue
        for b in s.leaves():
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



def _prune_section(sec: Section, level: str, asked: set[str], used: set[str], terms: set[tuple],
                   rates: set[str]) -> set[str]:
    """Walk the section's equations of its level from the last: keep what is needed and what
    it uses (a velocity worked out among the accelerations, the geometric contact point's,
    serves a term there: it stays, and so does what it uses). The bodies whose rate an
    equation found and which went with it are returned."""
    needed = set(used) | set(asked)
    needed_labels: set[tuple] = set(terms)
    rates = set(rates)
    holders = [(h, eq) for h, eq in _holders(sec) if not isinstance(eq, Equation) or eq.level == level]
    dropped = []
    unneeded: dict[int, tuple] = {}          # id of the term a rate nobody needs is read off -> (holder, value)
    unworked: set[str] = set()
    for holder, eq in reversed(holders):
        if isinstance(eq, Derived):
            if eq.source is not None and eq.body not in rates:
                unneeded[id(eq.source)] = (holder, eq)
            else:
                rates |= _rate_bodies_of(_syms([eq.how, eq.remark], set()))
            continue
        if isinstance(eq, Msg) and eq.key not in FORWARD:
            rates |= _rate_bodies_of(_syms(eq, set()))
            continue
        if isinstance(eq, Msg):             # no slip in a sentence, v_J∈9 = v_J∈8: a forward step too
            target, other = eq.args["sym"], eq.args["other"]
            if (target.base, target.sub) not in needed_labels and _point_of(target.sub) not in needed:
                holder.blocks.remove(eq)
            else:
                needed_labels.add((other.base, other.sub))
            continue
        unknowns = [t for side in eq.sides for t in side if t.unknown]
        forward = not unknowns
        label = (eq.target.sym.base, eq.target.sym.sub)
        point = _point_of(eq.target.sym.sub)
        if forward and eq.target.kind == "point" and label not in needed_labels and point not in needed:
            holder.blocks.remove(eq)
            dropped.append(eq)
            continue
        if unknowns and not eq.target.unknown and all(id(t) in unneeded for t in unknowns):
            holder.blocks.remove(eq)            # it finds only rates nobody needs
            dropped.append(eq)
            for t in unknowns:
                owner, value = unneeded.pop(id(t))
                owner.blocks.remove(value)
                unworked.add(value.body)
            continue
        needed_labels.update(_point_terms(eq))      # v_J7∈4 = v_K + …: its known left side too
        for t in (t for side in eq.sides for t in side if not t.unknown):
            rates |= _rate_bodies_of(_syms(t.how, set()))
        for t in unknowns:                  # its rate is read here after all: it stays
            kept = unneeded.pop(id(t), None)
            if kept is not None:
                rates |= _rate_bodies_of(_syms(kept[1].how, set()))
    _drop_orphans(sec, dropped)
    return unworked


def _rate_bodies_of(syms: set) -> set[str]:
    """The bodies whose ω or α the symbols name (subscripts split at /)."""
    return {part for base, sub in syms if base in ("ω", "α") for part in sub.split("/") if part}


def _names(eq: Equation) -> set[str]:
    """The point names an equation's terms mention (J7 in v_J7∈4, a_{J7∈7/4}, v_{J7-H})."""
    out: set[str] = set()
    for t in eq.terms:
        out.update(x for x in re.split(r"[∈/,\-]", t.sym.sub) if x)
    return out


def _drop_orphans(sec: Section, dropped: list[Equation]) -> None:
    """The sentences written for a dropped equation alone — a contact's no-slip, the rule of
    its geometric point and that point's velocity — go with it, when no equation left in
    the section speaks of that contact (the chain's J7 on the pinion, which nothing asks)."""
    if not dropped:
        return
    left = set().union(*[_names(b) for b in sec.leaves() if isinstance(b, Equation)
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
    """The section's equations, its sentences (the no-slip `rolling.same` a forward step) and
    the rates read off its equations, in order, with the section that holds each."""
    out: list = []
    for b in sec.blocks:
        if isinstance(b, Section):
            out += _holders(b)
        elif isinstance(b, (Equation, Msg)) or (isinstance(b, Derived) and b.kind in ("omega", "alpha")):
            out.append((sec, b))
    return out
