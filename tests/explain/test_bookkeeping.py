"""Seed 001's bookkeeping, checked on every equation of one example of each kind (every
example in a deep run): a term marked ? is one
the equation solves, each ? is one scalar unknown, and the unknowns an equation marks are
as many as it solves — independent (their directions span as many dimensions as there are
marks) and no more than a vector equation gives (2 in the plane, 3 in space). A term found
earlier is marked known when it is used again; a forward evaluation (every term known)
marks its left side as found, the same way in every explanation."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from kinematika.explain.document import Equation, Section

from kinematika.explain.context import Ctx

from tests.conftest import KINDS, sampled

from .helpers import ALL, explained, num
from .test_equations import _direction


# one example of each kind, and the notes' upper wheel (a translating chassis whose points
# move as one a sentence names): every example, every seed in a deep run
# and C5-1.3 (one rate, α of the support, in two terms of one equation)
KEEP = KINDS | {"seed_c5_e4_upper_wheel", "seed_c5_1_3_bar_in_sleeve"}


def direction(sol, ctx: Ctx, ref, eq):
    """The line a ⊥/∥ annotation names: a segment by its two ends (contacts J3 included)."""
    ends = getattr(ref, "ends", None)
    if ends and all(e in sol.inst.points or e in ctx._extra for e in ends):
        p, q = ctx.pos(ends[0]), ctx.pos(ends[1])
        return tuple(b - a for a, b in zip(p, q))
    return _direction(sol, ref, eq)


def context(sol) -> Ctx:
    """The names the explanation gives contacts (J, J3 …), placed."""
    ctx = Ctx(sol)
    for j in sol.model.joints:
        if j.type in ("rolling", "gear") and sol.solver.geos[j.id].contact is not None:
            ctx.contact(j)
    return ctx


def level_equations(doc) -> list[tuple[str, Equation]]:
    """(section key, equation) of the velocity and acceleration steps, in order."""
    out: list = []

    def walk(sec: Section, key: str) -> None:
        for b in sec.blocks:
            if isinstance(b, Section):
                walk(b, key)
            elif isinstance(b, Equation):
                out.append((key, b))
    for s in doc.sections:
        walk(s, s.title.key)
    return out


def marks(t) -> int:
    """The unknowns a term shows: each ?, and a magnitude written as an unknown rate times
    its arm (α·JS, a rate several terms share: counted once by `quantity`)."""
    return sum(a.code in ("?", "rate") for a in (t.mag, t.dir))


def unknown_columns(sol, ctx, eq: Equation, dim: int) -> list[np.ndarray]:
    """The directions the unknowns span: one per ? of magnitude along a known direction,
    the whole space for an unknown direction."""
    cols: list[np.ndarray] = []
    terms = [t for side in eq.sides for t in side]
    if len(eq.sides) == 1:
        terms.append(eq.target)
    for t in terms:
        if not marks(t):
            continue
        if t.dir.code == "?":
            cols += list(np.eye(dim))
            continue
        value = np.array(num(sol, t.value), dtype=float)
        d = direction(sol, ctx, t.dir.ref, eq)
        if d is not None:
            d = np.array(num(sol, d), dtype=float)
            d = d if t.dir.code == "para" else np.array([-d[1], d[0]])
        elif np.linalg.norm(value) > 0:
            d = value
        else:
            d = np.ones(dim)          # a zero term along an unnamed direction: independent enough
        cols.append(d / np.linalg.norm(d))
    return cols


def quantity(t) -> tuple:
    """What a ? stands for: the ω or α of a rotation term (one unknown however many terms
    it appears in), else the term itself."""
    if t.kind in ("rotation", "tangential") and t.how:
        return ("rate", repr(t.how[0]))
    return ("term", t.sym.base, t.sym.sub, t.sym.sup, t.sym.sub_key)


def column(sol, ctx, eq, t, dim) -> list[np.ndarray]:
    return unknown_columns(sol, ctx, Equation(eq.target, [[t]], eq.level), dim)[:marks(t)]


def unknowns(sol, ctx, eq, dim) -> tuple[dict, list]:
    """The distinct unknowns of the equation (quantity -> its number of scalars) and their
    columns. Unknown terms of one side along one line add up to one unknown (the triad's
    two rotations about the Assur point's line)."""
    distinct: dict = {}
    cols: list = []
    for side in eq.sides:
        groups: list[list] = []          # [terms, columns]
        for t in (t for t in side if marks(t)):
            own = column(sol, ctx, eq, t, dim)
            same = next((g for g in groups if len(own) == 1 and len(g[1]) == 1
                         and abs(g[1][0][0] * own[0][1] - g[1][0][1] * own[0][0]) < 1e-9), None)
            if same is not None:
                same[0].append(t)
            else:
                groups.append([[t], own])
        for ts, own in groups:
            key = tuple(sorted(quantity(t) for t in ts)) if len(ts) > 1 else quantity(ts[0])
            if key not in distinct:
                distinct[key] = len(own)
                cols += own
    if len(eq.sides) == 1 and marks(eq.target):
        distinct[("target",)] = marks(eq.target)
        cols += column(sol, ctx, eq, eq.target, dim)       # its magnitude along a known line, or all
    return distinct, cols


@pytest.mark.parametrize("name", sampled(ALL, KEEP))
def test_every_solved_equation_marks_what_it_solves(name):
    """Each ? is an unknown of the equation; the distinct unknowns are at most what its
    vector equalities give (2 per equality in the plane, 3 in space) and, for an equation of
    one or two sides in the plane, independent: their directions span as many dimensions
    as they are."""
    sol, doc = explained(name)
    dim = sol.space.dim
    ctx = context(sol)
    for _, eq in level_equations(doc):
        if eq.level not in ("v", "a"):
            continue
        terms = [t for side in eq.sides for t in side]
        for t in terms + [eq.target]:
            assert (marks(t) > 0) == t.unknown, (name, eq.target.sym, t.sym, "a ? on a term not solved here")
        distinct, cols = unknowns(sol, ctx, eq, dim)
        counted = sum(distinct.values())
        capacity = dim * (1 if len(eq.sides) == 1 else len(eq.sides) - 1)
        assert 1 <= counted <= capacity, (name, eq.target.sym, f"{counted} unknowns marked")
        if dim == 2 and len(eq.sides) <= 2 and cols:
            rank = np.linalg.matrix_rank(np.column_stack(cols), tol=1e-9)
            assert rank == counted, (name, eq.target.sym, f"{counted} unknowns marked, {rank} independent")
def shared(t) -> bool:
    """Whether a term's magnitude is a shared unknown rate times its arm: marked ?, the rate
    said in the sentence before the equation (`shared.share`, twenty-eighth round (c))."""
    return t.mag.code == "?" and bool(t.mag.ref)


def shown(eq) -> int:
    """The unknowns a reader counts on the equation: every ?, the ? of the terms that share
    one rate (α·JS, α·SQ, the sentence before the equation says so) once; the left side of
    an equation of several sides is what they equal, not an unknown of its own."""
    terms = [t for side in eq.sides for t in side] + ([eq.target] if len(eq.sides) == 1 else [])
    rates = {repr(t.mag.ref[0]) for t in terms if shared(t)}
    return sum(a.code == "?" for t in terms for a in (t.mag, t.dir) if not (a is t.mag and shared(t))) + len(rates)


@pytest.mark.parametrize("name", sampled(ALL, KEEP))
def test_the_unknowns_shown_are_those_solved(name):
    """The sentence "a planar equation solves two unknowns" holds on the page: the unknowns a
    reader counts (each ?, each shared rate once) are the equation's distinct unknowns. C5-1.3
    marked a_S = α × JS and a_QS^t = α × SQ both ?, three ? for two unknowns (α and |a_rel|):
    the sentence before the equation says the two share α_euskarria (α_euskarria·JS and
    α_euskarria·SQ) and their two ? count as one."""
    sol, doc = explained(name)
    ctx = context(sol)
    for _, eq in level_equations(doc):
        if eq.level not in ("v", "a"):
            continue
        distinct, _ = unknowns(sol, ctx, eq, sol.space.dim)
        if any(isinstance(k[0], tuple) for k in distinct):
            continue        # a triad's two rotations about one line: one unknown, its sentence says so
        assert shown(eq) == sum(distinct.values()), (name, eq.target.sym, shown(eq), distinct)


def test_the_support_rate_is_one_unknown_in_c5_1_3():
    """C5-1.3, by hand: a_Q = a_S + a_QS^n + a_QS^t + a_rel + a_cor with a_S = α·JS (S on a
    straight path, J the contact) and a_QS^t = α·QS: one rate α, so the equation shows two
    unknowns — α (the ? over both, said once in the sentence before it) and |a_rel| (its ?).
    The marks row writes ? over both, as the notes mark an unknown magnitude (twenty-eighth
    round (c)); the rate and its arm stay in the annotation, for the sentence."""
    sol, doc = explained("seed_c5_1_3_bar_in_sleeve")
    eq = next(e for _, e in level_equations(doc) if e.level == "a"
              and any(t.sym.sub == "S" and t.sym.base == "a" for side in e.sides for t in side))
    terms = {(t.sym.sub, t.sym.sup): t for side in eq.sides for t in side}
    a_s, a_qs = terms[("S", "")], terms[("QS", "t")]
    assert a_s.mag.code == a_qs.mag.code == "?"
    assert a_s.mag.ref[0] == a_qs.mag.ref[0] and a_s.mag.ref[0].base == "α"
    # each in its own segment's order, as its ⊥ below it (twenty-fourth round (c))
    assert a_s.mag.ref[1] == "·SJ" and a_qs.mag.ref[1] == "·QS"
    assert shown(eq) == 2


@pytest.mark.parametrize("name", sampled(ALL, KEEP))
def test_a_term_found_before_is_known(name):
    """Within the velocities (or the accelerations), a term whose symbol and value were
    reached by an earlier equation is not marked unknown again."""
    sol, doc = explained(name)
    seen: dict[str, dict] = {}
    for key, eq in level_equations(doc):
        if key not in ("sec.velocities", "sec.accelerations"):
            continue
        known = seen.setdefault(key, {})
        for t in [x for side in eq.sides for x in side]:
            label = (t.sym.base, t.sym.sub, t.sym.sup)
            if t.unknown and label in known and t.kind == "point":
                before = num(sol, known[label])
                now = num(sol, t.value)
                assert not all(math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12) for a, b in zip(before, now)), \
                    (name, t.sym, "found before, marked ? again")
        for t in [eq.target] + [x for side in eq.sides for x in side]:
            if t.kind == "point":
                known[(t.sym.base, t.sym.sub, t.sym.sup)] = t.value


SEEDS = sorted(p.stem for p in (Path(__file__).resolve().parents[2] / "examples").glob("seed_*.yaml"))


SAYS_MOTION = ("driver.along", "driver.velocity", "driver.whole", "group.wheel_a", "vehicle.driven", "vehicle.translation",
               "contact.fixed",            # a point of a body welded to the frame does not move
               "rolling.centre", "centre.site", "centre.site_s",   # a contact at rest, a centre placed before
               "centre.site_here", "centre.site_s_here",          # a centre placed just above (round 20e)
               "rolling.same")             # no slip: the two material points at a contact move alike


def _said(b) -> set[str]:
    """The point names a sentence that gives a point's motion names (a driver's datum, a
    wheel's plane, a translation); a rolling contact's sentence names J, not its motion."""
    out: set[str] = set()
    if getattr(b, "key", "") not in SAYS_MOTION:
        return out
    for x in getattr(b, "args", {}).values():
        sub = getattr(x, "sub", None)
        text = getattr(x, "text", None)
        if isinstance(sub, str):
            out.add(sub.split("∈")[0])
        if isinstance(text, str):
            out.add(text)
    return out


def _flat(sec: Section) -> list:
    return [x for b in sec.blocks for x in (_flat(b) if isinstance(b, Section) else [b])]


@pytest.mark.parametrize("name", sampled(SEEDS, KEEP))
def test_every_known_point_is_written_before_it_is_used(name):
    """A student can check every known term: a point's velocity or acceleration marked known
    in a step's equation was written by an earlier equation (the pinion's J7 where the chain
    touches it: v_J7∈4 = v_H + ω_4 × H-J7 before the chain's equation), or is a point of the
    frame or pinned to it, or a sentence before it names the point (a driver's datum, a
    wheel's plane, a translating body's point it moves as)."""
    sol, doc = explained(name)
    frame, model = sol.model.frame, sol.model
    fixed = set(model.bodies[frame].points)
    seen: set[tuple] = set()
    said: set[str] = set()
    moves_as: dict[str, str] = {}
    for sec in doc.sections:
        if sec.title.key not in ("sec.velocities", "sec.accelerations"):
            continue
        for b in _flat(sec):
            if not isinstance(b, Equation):
                said |= _said(b)
                if getattr(b, "key", "") == "vehicle.translation":
                    moves_as[str(b.args["body"])] = str(b.args["point"])
                continue
            terms = [t for side in b.sides for t in side] + ([] if b.target.unknown else [b.target])
            for t in terms:
                if t.kind != "point" or t.unknown or t.sym.sup:
                    continue
                point, _, body = t.sym.sub.partition("∈")
                ok = ((t.sym.base, t.sym.sub) in seen or body == frame or point in fixed or point in said
                      or any(moves_as.get(c) in said for c in model.carriers(point)))
                assert ok, f"{name}: {t.sym.base}_{t.sym.sub} is marked known and was never written"
            for t in [b.target] + [t for side in b.sides for t in side]:
                seen.add((t.sym.base, t.sym.sub))
