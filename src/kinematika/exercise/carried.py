"""Error carried forward: a later answer that follows from the student's own earlier wrong
answer earns its marks, as a teacher marks a worked solution.

The engine solves the problem again from the student's value. At the velocity level the
given motion's rates scale every velocity and ω together (the velocity problem is linear
and homogeneous in the drivers' rates), so a student's wrong velocity or ω is the answer of
the mechanism driven at the rates scaled by (their value / the right value): that mechanism
is solved again, accelerations included, and each later answer is compared with it. At the
acceleration level, for a mechanism with one driver, the acceleration answers are affine in
the driver's acceleration: the one that gives the student's wrong acceleration is found from
two solutions and the mechanism solved again with it (in the right velocities and in the
student's carried ones).

"Later" is later in the statement's order of questions. The earlier answer stays wrong; a
later one is credited only when it matches the world of an earlier wrong one, within its
box's margin.
"""
from __future__ import annotations

import dataclasses
from typing import Any, Callable, Optional

from ..expressions import Expr, parse
from .key import Row

VELOCITY_LEVEL = ("velocity", "omega")
ACCELERATION_LEVEL = ("acceleration", "alpha")
NOISE = 1e-9


def carried(exercise: Any, variant: Any, wrong: dict[str, float]) -> dict[str, str]:
    """The wrong answers (question -> the student's value in the model's units) that follow
    from an earlier wrong one: question -> the question they follow from."""
    if not wrong:
        return {}
    from ..sweep.posing import prepare

    model = prepare(exercise.model, set=variant.sets)
    drivers = list(model.drivers)
    if not drivers or not all(isinstance(d.value, Expr) for d in drivers):
        return {}
    rows = {r.question: r for r in variant.rows}
    solve = _solver(exercise)
    out: dict[str, str] = {}

    def credit(source: Row, world: dict[str, Row], level: tuple[str, ...] = VELOCITY_LEVEL + ACCELERATION_LEVEL) -> None:
        for question, value in wrong.items():
            row = rows[question]
            there = world.get(question)
            if question in out or row.ask <= source.ask or there is None or row.kind not in level + ("position",):
                continue
            if abs(value - there.value) <= there.margin(variant.tolerance_of(row)):
                out[question] = source.question

    velocity_worlds: list[tuple[Optional[Row], Any]] = [(None, model)]
    for question, value in sorted(wrong.items(), key=lambda qv: _order(rows[qv[0]])):
        source = rows[question]
        if source.kind not in VELOCITY_LEVEL or abs(source.value) <= variant.margin(source):
            continue
        scaled = _scaled(model, value / source.value)
        world = solve(scaled)
        if world is not None:
            credit(source, world)
            velocity_worlds.append((source, scaled))
    if len(drivers) == 1 and drivers[0].accel is not None and isinstance(drivers[0].accel, Expr):
        for question, value in sorted(wrong.items(), key=lambda qv: _order(rows[qv[0]])):
            source = rows[question]
            if source.kind not in ACCELERATION_LEVEL:
                continue
            for _, base in velocity_worlds:
                world = _accelerated(base, question, value, solve)
                if world is not None:
                    credit(source, world, ACCELERATION_LEVEL)
    return out


def _order(row: Row) -> tuple[int, str]:
    return row.ask, row.question


def _solver(exercise: Any) -> Callable[[Any], Optional[dict[str, Row]]]:
    from ..errors import KinematikaError
    from .build import _answers_and_floors
    from .key import key_rows

    kinds = [q.kind for q in exercise.model.questions]

    def solve(model: Any) -> Optional[dict[str, Row]]:
        try:
            answers, floors = _answers_and_floors(model)
        except KinematikaError:
            return None
        return {r.question: r for r in key_rows(answers, kinds, exercise.asks, floors)}
    return solve


def _scaled(model: Any, factor: float) -> Any:
    """The model with every driver's rate times `factor` (its accelerations as given)."""
    drivers = [dataclasses.replace(d, value=parse(f"({d.value.text})*({factor!r})")) for d in model.drivers]
    return dataclasses.replace(model, drivers=drivers)


def _accelerated(model: Any, question: str, value: float,
                 solve: Callable[[Any], Optional[dict[str, Row]]]) -> Optional[dict[str, Row]]:
    """The one driver's acceleration that makes answer `question` equal `value` (the answer
    is affine in it), and the mechanism solved with it; None when the answer does not depend
    on it."""
    d = model.drivers[0]

    def with_accel(extra: float) -> Any:
        return dataclasses.replace(model, drivers=[dataclasses.replace(d, accel=parse(f"({d.accel.text})+({extra!r})"))])

    at0, at1 = solve(model), solve(with_accel(1.0))
    if at0 is None or at1 is None or question not in at0:
        return None
    slope = at1[question].value - at0[question].value
    if abs(slope) <= NOISE * max(at0[question].size, 1e-300):
        return None
    return solve(with_accel((value - at0[question].value) / slope))
