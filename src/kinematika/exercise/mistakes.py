"""The usual mistakes, each modelled where it is made, so that a wrong answer can be named.

A mistake is not guessed from the numbers: the mechanism is solved again as the student
who makes it would solve it, and the answers of that solution are the mistaken values.

| kind | how it is solved again |
| --- | --- |
| `coriolis-omitted`, `coriolis-doubled` | the engine with the Coriolis factor 0 or 2 (`engine.terms`) |
| `normal-omitted` | the engine with the centripetal terms ω × (ω × r) left out (`engine.terms`) |
| `sense-reversed` | a driver's ω (rate, velocity) or its α (acceleration) with the other sign, and everything that follows |
| `degrees-as-radians` | the parameters stated in degrees given their number as radians (30° taken as 30 rad) |
| `units-mm-as-m` | the parameters stated in millimetres given their number as metres |
| `drag-as-absolute` | a point of a body that slides on a moving body: the velocity (acceleration) of the coincident point of that body, the drag, given as the point's own |
| `components-swapped` | a vector's x and y (any two, in 3D) exchanged |

A mistake that changes nothing in a question (the Coriolis term of a linkage without
sliding pairs, a velocity with the normal term left out) gives no diagnosis there: a value
is named by a mistake only when it matches the mistaken value and not the right one.
"""
from __future__ import annotations

import dataclasses
import warnings
from dataclasses import dataclass
from decimal import Decimal
from typing import Any, Callable, Optional

from ..engine.terms import Terms
from ..errors import KinematikaError, KinematikaWarning
from ..expressions import Expr, parse
from ..model.model import Joint, Model, PointRef
from ..model.question import Question
from ..questions import QUESTIONS
from .key import Row, key_rows

KINDS = ("coriolis-omitted", "coriolis-doubled", "normal-omitted", "sense-reversed", "drag-as-absolute",
         "degrees-as-radians", "units-mm-as-m", "components-swapped")
TERMS = {"coriolis-omitted": Terms(coriolis=0), "coriolis-doubled": Terms(coriolis=2),
         "normal-omitted": Terms(normal=0)}


@dataclass(frozen=True)
class Mistaken:
    """The values of some key rows under one mistake (`rows` by question, as `key.Row`)."""

    kind: str
    rows: dict[str, Row]


@dataclass(frozen=True)
class World:
    """What the mistakes of one variant need: the model as given (before `--set`), the
    variant's `--set` values, its stated values (every parameter's, in the statement's
    units), the parameters stated in degrees and in millimetres, the graded questions and
    the right solution's key rows."""

    model: Model
    sets: dict[str, str]
    stated: dict[str, Decimal]
    degrees: tuple[str, ...]
    millimetres: tuple[str, ...]
    metre: str                              # one metre in the model's length unit, as an expression
    asks: list[int]
    solution: Any                           # the variant's right `Solution`
    right: list[Row]                        # its key rows
    solve: Callable[..., Any]               # (model, terms) -> (answers, floors) of a solution


def mistakes_of(world: World) -> list[Mistaken]:
    """Every mistake's values for the graded questions of one variant, in `KINDS` order;
    a mistake whose solution does not exist (30 rad does not assemble) is left out."""
    model = _prepared(world.model, world.sets)
    kinds = [q.kind for q in model.questions]
    out: list[Mistaken] = []

    def solved(kind: str, source: Model, terms: Optional[Terms] = None) -> None:
        try:
            with warnings.catch_warnings():        # 33 "radians" are the mistake, not a slip
                warnings.simplefilter("ignore", KinematikaWarning)
                answers, floors = world.solve(source, terms)
        except KinematikaError:
            return
        rows = key_rows(answers, kinds, world.asks, floors)
        out.append(Mistaken(kind, {r.question: r for r in rows}))

    sliding = any(slides(j) for j in model.joints)
    for kind, terms in TERMS.items():
        if sliding or kind == "normal-omitted":
            solved(kind, model, terms)
    for reversed_model in _senses_reversed(model):
        solved("sense-reversed", reversed_model)
    drag = _drag(world, model)
    if drag is not None:
        out.append(drag)
    if world.degrees:
        solved("degrees-as-radians", _prepared(world.model, {**world.sets, **{
            name: str(world.stated[name]) for name in world.degrees}}))
    if world.millimetres:
        solved("units-mm-as-m", _prepared(world.model, {**world.sets, **{
            name: f"{world.stated[name]}*{world.metre}" for name in world.millimetres}}))
    out += _swapped(world.right)
    return out


def _prepared(model: Model, sets: dict[str, str]) -> Model:
    from ..sweep.posing import prepare

    return prepare(model, set=sets)


# the sense of the given motion --------------------------------------------------------------
def _senses_reversed(model: Model) -> list[Model]:
    """The model with one driver's value, then its acceleration, of the other sign."""
    out = []
    for i, d in enumerate(model.drivers):
        for field in ("value", "accel"):
            given = getattr(d, field)
            if given is None or _zero(given):
                continue
            drivers = list(model.drivers)
            drivers[i] = dataclasses.replace(d, **{field: _negated(given)})
            out.append(dataclasses.replace(model, drivers=drivers))
    return out


def _negated(given: Any) -> Any:
    if isinstance(given, Expr):
        return parse(f"-({given.text})")
    return tuple(_negated(g) for g in given)


def _zero(given: Any) -> bool:
    parts = (given,) if isinstance(given, Expr) else given
    return all(p.text.strip() in ("0", "0.0") for p in parts)


# the drag velocity given as the point's own -----------------------------------------------------
def slides(joint: Joint) -> bool:
    """Whether a joint lets its second body slide on its first (a P pair, a pin in a slot, a
    cylindrical pair): its kind's capability (`kinematika.joints`)."""
    return joint.kind.slides


def guide_of(model: Model, body: str, point: str) -> Optional[str]:
    """The moving body on which `body` slides at `point` (the guide whose coincident point
    gives the drag motion), or None."""
    for j in model.joints:
        if not slides(j) or body not in (j.a, j.b) or (j.at is not None and j.at != point):
            continue
        other = j.a if j.b == body else j.b
        if other != model.frame:
            return other
    return None


def _drag(world: World, model: Model) -> Optional[Mistaken]:
    """The drag velocity (acceleration) of each graded absolute velocity (acceleration) of a
    point of a sliding body: the motion of the guide's coincident point."""
    graded = [k for k in world.asks if _drag_question(model, model.questions[k - 1])]
    if not graded:
        return None
    from .key import floors_of, rows_of

    sol = world.solution
    floors = floors_of(sol)
    rows: dict[str, Row] = {}
    for k in graded:
        q = model.questions[k - 1]
        target = _point_of(q)
        guide = guide_of(model, target.body, target.point)
        state, place = sol.state(guide), sol.position(target)
        value = (sol.motion.velocity(state, place) if QUESTIONS[q.kind].level == "velocity"
                 else sol.motion.acceleration(state, place))
        for row in rows_of(k, q.kind, [float(c) for c in value], floors):
            rows[row.question] = row
    return Mistaken("drag-as-absolute", rows)


def _drag_question(model: Model, q: Question) -> bool:
    kind = QUESTIONS[q.kind]             # a point's velocity or acceleration, in the fixed frame
    return (kind.column and kind.about == "point" and q.relative_to in (None, model.frame)
            and guide_of(model, _point_of(q).body, _point_of(q).point) is not None)


def _point_of(q: Question) -> PointRef:
    """The material point a point question asks of (the builder makes its target one)."""
    if not isinstance(q.target, PointRef):
        raise TypeError(f"{q.where} asks of a body or a joint, not a material point")
    return q.target


# components ---------------------------------------------------------------------------------
def _swapped(right: list[Row]) -> list[Mistaken]:
    """A vector's components exchanged two by two (x and y; in 3D also y and z, x and z)."""
    by_name = {r.question: r for r in right}
    out = []
    for a, b in (("x", "y"), ("y", "z"), ("x", "z")):
        rows = {}
        for r in right:
            stem, _, axis = r.question.rpartition(".")
            if axis in (a, b):
                other = by_name.get(f"{stem}.{b if axis == a else a}")
                if other is not None:
                    rows[r.question] = dataclasses.replace(r, value=other.value)
        if rows:
            out.append(Mistaken("components-swapped", rows))
    return out
