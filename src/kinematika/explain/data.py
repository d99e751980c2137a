"""The Data section: everything the solution uses, stated before it, as a statement states
it (issue 30: a student redoes the whole solution from the page alone).

- the units, or that the data are symbols; the sign convention of angular quantities;
- what the model says of its data in the reader's language (`names.LANG.data`: the
  geometry it chose where the notes' figure is lost, an assumption);
- each parameter: its symbol, what it is (`names.LANG.parameters`) and its value with
  its unit, the unit read off where the model uses it (a length in a point's coordinate
  or a radius, an angle under `deg` or a cosine, a rate in an ω driver …);
- each point: what it is and where it is (its coordinates, written in the parameters
  when they are formulas: A = (ρ/sin β, 0) = (0.2, 0) m), or that it is placed by
  construction (the Position section);
- each body's shapes: a circle's centre and radius, a line's point and direction;
- the given motion: each driver's value (and its acceleration when accelerations are
  explained).

Every value is the model's own, evaluated; nothing is solved here.
"""
from __future__ import annotations

import ast
import re
from typing import Any, Optional

from ..model.body_shapes import Circle, Disc, Line, Plane
from .context import Ctx, radius_formula
from .context import model_formula as _formula
from .document import (Ann, CentreNote, Described, Drawing, Inline, Msg, Name, Names, Section, Sym, Table, Told, Value, msg,
                       names, point)
from .planar import driver_msg

# the kinds of quantity a parameter may be, by where the model uses it
DRIVER_UNIT = {("omega", "v"): "rate", ("omega", "a"): "rate2", ("velocity", "v"): "speed",
               ("velocity", "a"): "accel"}


def data_section(ctx: Ctx, length_unit: str, accelerations: bool) -> Section:
    """The Data section of the explanation of `ctx`'s solution."""
    sec = Section(msg("sec.data"))
    # the units of the quantities the page writes: no accelerations on a page of velocities
    # alone (twenty-fifth round (a): C5-1.2 listed "acceleracions en m/s²")
    sec.add(msg("data.symbolic", unit=length_unit) if ctx.symbolic
            else msg("data.numeric", unit=length_unit, accelerations=int(accelerations)))
    # the sign convention names the rates the page uses: no angular accelerations on a page
    # that asks none (C5-2.1, 2.2: "angular velocities … are signed")
    sec.add(msg("data.planar", accelerations=int(accelerations)) if ctx.planar else msg("data.spatial"))
    sec.add(Told("data"))
    rows = parameter_rows(ctx)
    if rows:
        sec.add(Table([msg("col.symbol"), msg("col.what"), msg("col.value")], rows))
    sec.add(Table([msg("col.point"), msg("col.what"), msg("col.position")], point_rows(ctx)))
    rows = shape_rows(ctx)
    if rows:
        sec.add(Table([msg("col.body"), msg("col.shape"), msg("col.given")], rows))
    given = [driver_msg(ctx, d, "v") for d in ctx.model.drivers]
    if accelerations:
        given += [driver_msg(ctx, d, "a") for d in ctx.model.drivers if d.accel is not None]
    sec.add(*given)
    return sec


# parameters ---------------------------------------------------------------------------------
def parameter_rows(ctx: Ctx) -> list:
    """[symbol, what it is, value] of each parameter: a symbolic one is a symbol (its sample
    value is given under each figure)."""
    kinds = parameter_kinds(ctx.model)
    rows = []
    for name, p in ctx.model.parameters.items():
        if p.value is None or (ctx.symbolic and name not in ctx.inst.env):
            value: Any = msg("data.symbol")
        else:
            value = parameter_value(ctx, name, p.value, kinds.get(name, ""))
        rows.append([Name(name, "param"), Described("parameter", name), value])
    return rows


def parameter_value(ctx: Ctx, name: str, expr, kind: str) -> Value:
    """The parameter's value with its unit; an angle given in degrees in degrees."""
    x = ctx.inst.env.get(name)
    if x is None:
        from ..expressions import evaluate

        x = evaluate(expr, ctx.inst.env, ctx.inst.backend)
    if kind == "angle" and "deg" in expr.calls():
        import math

        return Value(round(math.degrees(ctx.num(x)), 10), "deg")
    return Value(ctx.clean(x, kind or ""), kind if kind in ("len", "speed", "accel", "rate", "rate2") else "")


def parameter_kinds(model) -> dict[str, str]:
    """What each parameter is a quantity of, read off where the model uses it alone (times a
    number): a length (a point's coordinate, a distance, a radius), an angle (under `deg`, in a
    cosine, a construction's angle), a rate, a speed … (a driver's value). A parameter used
    as two kinds, or only in products with others (r·w), is left without a unit."""
    found: dict[str, set] = {}

    def note(expr, kind: str) -> None:
        if expr is None:
            return
        for n in _alone(expr):
            found.setdefault(n, set()).add(kind)
        for n in _in_angles(expr):
            found.setdefault(n, set()).add("angle")

    for name, p in model.parameters.items():
        if p.value is not None and "deg" in p.value.calls():
            found.setdefault(name, set()).add("angle")
    for spec in model.points.values():
        for expr, kind in _point_exprs(spec):
            note(expr, kind)
    for b in model.bodies.values():
        for s in b.shapes:
            if isinstance(s, (Circle, Disc)):
                note(s.radius, "len")
                for e in s.center:
                    note(e, "len")
    for d in model.drivers:
        if d.kind in ("omega", "velocity"):
            for level, given in (("v", d.value), ("a", d.accel)):
                for e in (given if isinstance(given, tuple) else (given,)):
                    note(e, DRIVER_UNIT[(d.kind, level)])
    return {n: next(iter(k)) for n, k in found.items() if len(k) == 1}


def _point_exprs(spec) -> list[tuple]:
    """A point's expressions with the kind each is: coordinates and distances are lengths,
    a construction's angle an angle."""
    if isinstance(spec, tuple):
        return [(e, "len") for e in spec]
    out = []
    for field_, kind in (("distance", "len"), ("angle", "angle"), ("radius", "len"), ("at", "len"),
                         ("radii", "len"), ("near", "len")):
        value = getattr(spec, field_, None)
        for e in (value if isinstance(value, tuple) else (value,)):
            if e is not None and hasattr(e, "tree"):
                out.append((e, kind))
    return out


def _alone(expr) -> set[str]:
    """The parameter an expression is, up to a number's factor or sign (`r`, `3*r`, `-w`);
    empty for anything else."""
    node = expr.tree
    while True:
        if isinstance(node, ast.UnaryOp):
            node = node.operand
        elif isinstance(node, ast.BinOp) and isinstance(node.op, (ast.Mult, ast.Div)):
            if isinstance(node.left, ast.Constant):
                node = node.right
            elif isinstance(node.right, ast.Constant):
                node = node.left
            else:
                return set()
        else:
            break
    return {node.id} if isinstance(node, ast.Name) else set()


def _in_angles(expr) -> set[str]:
    """The parameters a trigonometric function or `deg` takes (angles)."""
    out: set[str] = set()
    for node in ast.walk(expr.tree):
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in \
                ("cos", "sin", "tan", "deg"):
            for arg in node.args:
                out |= {n.id for n in ast.walk(arg) if isinstance(n, ast.Name)}
    return out


# points and shapes ----------------------------------------------------------------------------
def point_rows(ctx: Ctx) -> list:
    """[point, what it is, where]: a point given by coordinates at them (written in the
    parameters when they are formulas), a constructed one placed in the Position section."""
    rows = []
    for name, spec in ctx.model.points.items():
        if isinstance(spec, tuple):
            where: Any = _coordinates(ctx, spec, ctx.pos(name))
        else:
            where = msg("data.constructed")
        rows.append([point(name), Described("point", name, what_point(ctx, name)), where])
    return rows


def what_point(ctx: Ctx, name: str) -> Optional[Msg]:
    """What a point is, from the model's structure, for a model that does not say it in
    `names`: the centre of a body's circle, else the point of a joint (its kind and bodies),
    else a point of the bodies that hold it, the preposition (the Basque genitive) on each
    ("un punt del terra, del pla esquerre i del pla dret", `what.of`); None when no body
    holds it."""
    from .kinds import joint_kind

    for b, carrier in ctx.model.bodies.items():
        if any(getattr(s, "center_point", None) == name for s in carrier.shapes):
            return msg("what.centre", body=Name(b, "body"))
    for j in ctx.model.joints:
        if j.at == name:
            return msg("what.joint", joint=Name(j.id, "joint"), kind=joint_kind(ctx, j),
                       a=Name(j.a, "body"), b=Name(j.b, "body"))
    holders = [b for b, carrier in ctx.model.bodies.items() if name in carrier.points]
    touching = _touching(ctx, name, holders)
    if touching is not None:
        return touching
    return msg("what.body", bodies=names(holders, "body", each="what.of")) if holders else None


def _touching(ctx: Ctx, name: str, holders: list[str]) -> Optional[Msg]:
    """A point that is, at the instant, where a body holding it touches another (a rolling
    joint's contact: C5-1.5's T2, where strand 2 leaves pulley 2): "the point of strand 2
    where it touches pulley 2 (joint j4)". A body welded to the frame holds the frame's
    points (C5-1.2's K1), and the point is named after the body actually touched, the one
    the joint joins: "the point of the *left plane* where the *left wheel* touches", never
    "of the *ground*", which the wheel does not touch (issue 30, sixteenth round (c))."""
    from .kinds import welds

    if ctx.symbolic and not ctx.inst.env:
        return None
    where = ctx.num(ctx.pos(name))
    tol = 1e-9 * max(float(ctx.num(ctx.inst.scale)), 1e-300)
    for j in ctx.model.joints:
        if not j.kind.touches or welds(j):
            continue
        contact = ctx.sol.geometry(j.id).contact
        if contact is None or max(abs(a - b) for a, b in zip(ctx.num(contact.point), where)) > tol:
            continue
        pairs = sorted(((j.a, j.b), (j.b, j.a)), key=lambda pair: -_contacts_of(ctx, pair[0]))
        for own, other in pairs:
            if own in holders or any(ctx.fixed(h) and ctx.fixed(own) for h in holders):
                return msg("what.touching", body=Name(own, "body"), other=Name(other, "body"),
                           joint=Name(j.id, "joint"))
    return None


def _contacts_of(ctx: Ctx, body: str) -> int:
    """How many touching joints `body` is in. A contact point both bodies hold is named on the
    one that touches more (the belt or strand that runs from pulley to pulley), so that a page's
    contacts are all points of the same body: C5-1.6's T1 "the point of the *belt* where it
    touches the *fixed pulley*" beside T2 "the point of the *belt* where it touches the *moving
    pulley*", never "of the *moving pulley* where it touches the *belt*" (issue 30, eighteenth
    round (c)); a tie keeps the joint's order (sorted is stable)."""
    from .kinds import welds

    return sum(1 for j in ctx.model.joints if j.kind.touches and not welds(j) and body in (j.a, j.b))


def contact_rows(ctx: Ctx, doc: Any) -> dict[str, str]:
    """Every contact point of the page (J, K, T2 …: the structure table gives each touching
    joint's place, the explanation names some) that is no model's point joins the Data
    section's table of points, with what it is and where, so that every point the page
    writes is located before it is used (C5-1.5's J1 … J10) — and every contact has a
    letter: one the page names only in the structure table is named there too, never given
    by its coordinates alone (issue 30, fourteenth round (b): C5-E.4's "roda dreta – roda
    superior (R/2; R·(√3 + 2)/2)", read as a datum with no name). Returns those contacts
    (joint id -> name): the figures label them (`structure.name_contacts`), so the letter
    is the same in the table, the text and the figure."""
    table = next((b for b in doc.sections[0].blocks if isinstance(b, Table)
                  and getattr(b.header[0], "key", "") == "col.point"), None)
    named = {jid: name for jid, name in ctx._contacts.items() if name not in ctx.model.points}
    if table is None:
        return named
    listed = {row[0].text for row in table.rows if isinstance(row[0], Name)}
    from .kinds import joint_kind

    for jid, name in ctx._contacts.items():
        j = ctx.model.joint(jid)
        if name in listed:
            continue
        what = msg("what.contact", joint=Name(j.id, "joint"), kind=joint_kind(ctx, j),
                   a=Name(j.a, "body"), b=Name(j.b, "body"))
        where: Any = Value(ctx.clean(ctx.pos(name), "len"), "len")
        at = _point_at(ctx, ctx.pos(name))
        if at is not None:                  # the contact is a point the model names (E.3's J1): J1′ = J1 = (0, 0)
            where = Inline([point(at), " = ", where])
        table.rows.append([point(name), what, where])
        listed.add(name)
    return named


# the tables that say what the page's points are, not where it uses them
_NAMING_TABLES = ("col.point", "col.number", "col.joint")


def _naming(block: Any) -> bool:
    return isinstance(block, Table) and getattr(block.header[0], "key", "") in _NAMING_TABLES


def points_used(ctx: Ctx, doc: Any) -> set[str]:
    """Every point name the page writes outside the tables that only say what its points are
    (the Data's points, the structure's bodies and joints): in its sentences (Name), its
    symbols' subscripts and segments (v_{J∈2}, ⊥ G1J, v_{C1-J1}: `split_names`), the
    centres' constructions (a witness point, a contact a centre is at)."""
    import dataclasses

    known = set(ctx.model.points) | set(ctx._contacts.values())
    contacts = dict(ctx._contacts)
    out: set[str] = set()

    def walk(x: Any) -> None:
        if isinstance(x, Name):
            if x.kind == "point":
                out.update(split_names(x.text, known))
        elif isinstance(x, str):
            return
        elif isinstance(x, Sym):
            for part in re.split(r"[-,/ ]", x.sub):
                out.update(split_names(part.split("∈")[0].strip(), known))
        elif isinstance(x, Ann):
            if isinstance(x.ref, str):
                out.update(split_names(x.ref.strip(), known))
            else:
                walk(x.ref)
        elif isinstance(x, CentreNote):
            for w in x.witnesses:
                out.update(split_names(str(w[0]), known))
            if x.how == "joint":
                out.update(contacts[v] for v in x.via if v in contacts)
            walk([v for k, v in vars(x).items() if k not in ("witnesses",)])
        elif isinstance(x, (Drawing,)) or (isinstance(x, Table) and _naming(x)):
            return
        elif isinstance(x, dict):
            walk(list(x.values()))
        elif isinstance(x, (list, tuple)):
            for v in x:
                walk(v)
        elif dataclasses.is_dataclass(x) and not isinstance(x, type):
            walk([getattr(x, f.name) for f in dataclasses.fields(x)])

    walk(doc.sections)
    return out & known


def split_names(text: str, known: set[str]) -> set[str]:
    """The known point names a segment or name is made of, longest first (G1J → G1, J;
    IC → I, C; RL stays RL when RL is a point)."""
    out: set[str] = set()
    rest = text
    while rest:
        name = next((n for n in sorted(known, key=len, reverse=True) if n and rest.startswith(n)), None)
        if name is None:
            rest = rest[1:]
            continue
        out.add(name)
        rest = rest[len(name):]
    return out


def _point_at(ctx: Ctx, where: tuple) -> Optional[str]:
    """The model's point at `where` at the instant, if any."""
    if ctx.symbolic and not ctx.inst.env:
        return None
    here = ctx.num(where)
    tol = 1e-9 * max(float(ctx.num(ctx.inst.scale)), 1e-300)
    return next((p for p in ctx.model.points
                 if max(abs(a - b) for a, b in zip(ctx.num(ctx.pos(p)), here)) <= tol), None)


def points_named(doc: Any, known: frozenset = frozenset()) -> set[str]:
    """The point names the document's equations write, read off their symbols' subscripts:
    v_J4∈3 → J4, v_{C1-J1} → C1 and J1, a segment of two one-letter names (CJ) → C and J
    (unless it is a `known` point's name: RL)."""
    import re

    out: set[str] = set()
    for eq in doc.equations():
        for term in eq.terms:
            sub = term.sym.sub.split("/")[0].split(",")[0]
            for part in re.split(r"[-,]", sub):
                name = part.split("∈")[0].strip()
                if name:
                    out.add(name)
                    if len(name) == 2 and name.isalpha() and name not in known:
                        out |= {name[0], name[1]}
    return out


def _coordinates(ctx: Ctx, exprs: tuple, value: tuple) -> Any:
    """(x, y) as given: the formula in the parameters, then its value (A = (ρ/sin β, 0) =
    (0.2, 0) m); the value alone when the model writes numbers."""
    shown = Value(ctx.clean(value, "len"), "len")
    formula = _formula(ctx, exprs)
    if formula is None or ctx.symbolic:
        return shown
    return Inline([Value(formula, ""), " = ", shown])


def shape_rows(ctx: Ctx) -> list:
    """[body, shape, what defines it] of every shape: a circle's centre and radius, a line's
    point and direction (a plane's, a disc's axis in space)."""
    rows = []
    for name, b in ctx.model.bodies.items():
        pairs = list(zip(b.shapes, ctx.inst.shapes.get(name, [])))
        concentric = _concentric(ctx, pairs)
        if concentric is not None:
            rows.append([Name(name, "body", bare=True), msg("shape.concentric", n=len(pairs)), concentric])
            continue
        for model_shape, shape in pairs:
            described = _shape(ctx, model_shape, shape)
            if described is not None:
                rows.append([Name(name, "body", bare=True), msg(f"shape.{type(model_shape).__name__.lower()}"),
                             described])
    return rows


def _concentric(ctx: Ctx, pairs: list) -> Any:
    """One body's several circles about one centre said in one row, "centre C, radii R and
    2·R" (C5-E.1's wheels of radii R and 2R, one rigid body): two rows "*wheels* | circle" read
    as two wheels of one name, neither said (issue 30, twenty-seventh round (e)). None unless
    every shape of the body is such a circle."""
    if len(pairs) < 2 or not all(type(s) is Circle for s, _ in pairs):
        return None
    centres = {s.center_point or tuple(ctx.clean(i.center, "len")) for s, i in pairs}
    if len(centres) != 1:
        return None
    spec = pairs[0][0]
    centre = point(spec.center_point) if spec.center_point else Value(ctx.clean(pairs[0][1].center, "len"), "len")
    radii = []
    for s, i in pairs:
        radius: Any = Value(ctx.clean(i.radius, "len"), "len")
        formula = radius_formula(ctx, s)
        radii.append(Inline([Value(formula, ""), " = ", radius]) if formula is not None else radius)
    return msg("data.circles", centre=centre, radii=Names(radii))


def _shape(ctx: Ctx, spec, shape) -> Any:
    if isinstance(spec, (Circle, Disc)):
        centre = point(spec.center_point) if spec.center_point else Value(ctx.clean(shape.center, "len"), "len")
        radius: Value | Inline = Value(ctx.clean(shape.radius, "len"), "len")
        formula = radius_formula(ctx, spec)     # None: a plain number
        if formula is not None:
            radius = Inline([Value(formula, ""), " = ", radius])
        return msg("data.circle", centre=centre, radius=radius)
    if isinstance(spec, (Line, Plane)):
        through_point = getattr(spec, "through_point", None)
        through = point(through_point) if through_point else Value(ctx.clean(shape.through, "len"), "len")
        d = getattr(spec, "direction", None) or getattr(spec, "normal", None)
        direction: Any = Value(ctx.clean(tuple(getattr(shape, "direction", None) or shape.normal), ""), "")
        if d is not None and isinstance(d, tuple) and not ctx.symbolic:
            formula = _formula(ctx, d)
            if formula is not None:
                direction = Value(formula, "")
        return msg("data.line" if isinstance(spec, Line) else "data.plane", through=through, direction=direction)
    return None
