"""`move`: the drawn mechanism advanced along driven joints, as the sweep reaches it.

`move: {j1: 30}` (or `--move j1=30`) analyses the configuration a sweep of j1 from 0 to 30
(degrees for a revolute, length for a prismatic) reaches on the branch continuous with the
drawn one: the sweep's last row, written back as a model (`posed`). Several joints are
advanced one after the other, in the order given. A path that meets a dead point or
comes apart first is an `assembly` error saying how far it got.
"""
from __future__ import annotations

import dataclasses
import math
from typing import Any, Mapping

from ..algebra.backend import Numeric
from ..errors import KinematikaError, said_of
from ..expressions import Expr, ExpressionError, evaluate, parse
from ..model.model import Model
from ..model.overrides import at_draw_numbers, numeric_parameters
from .advance import advanced
from .plan import driven_joints
from .posed import posed_model
from .run import Sweeper
from .symbolic_move import symbolic_moved


def moved(model: Model, amounts: Mapping[str, Any]) -> Model:
    """`model` with each joint in `amounts` advanced by its amount (numbers or expressions)."""
    model = dataclasses.replace(model, move={})
    steps = []
    for jid, raw in amounts.items():
        where = f"move.{jid}"
        _check_driven(model, jid, where)
        amount = _amount(model, raw, where)
        if amount != 0:
            steps.append((jid, amount, where))
    if steps and any(p.value is None for p in model.parameters.values()):
        try:
            return symbolic_moved(model, steps)
        except KinematikaError as err:        # the symbols cannot follow: at the figure's numbers
            if err.kind != "schema" or not _drawn_in_numbers(model):
                raise
            model, _ = at_draw_numbers(model, "move", said_of(err))
    for jid, amount, where in steps:
        model = advanced(model, jid, amount, where)
    return model


def as_written(model: Model) -> Model:
    """`model` moved where its own `move:` section says (as `posing.prepare` poses a file)."""
    return moved(model, model.move) if model.move else model


def _drawn_in_numbers(model: Model) -> bool:
    """Whether every symbol of the model has a `draw_at` number (its figure's)."""
    return all(n in model.draw_at for n, p in model.parameters.items() if p.value is None)


def _amount(model: Model, raw: Any, where: str) -> float:
    """The amount as a number: an expression over the parameters that have values."""
    try:
        expr = raw if isinstance(raw, Expr) else parse(raw)
        value = float(evaluate(expr, numeric_parameters(model), Numeric()))
    except ExpressionError as err:
        raise KinematikaError("schema", "move-not-number", where, problem=err.said) from None
    if not math.isfinite(value):
        raise KinematikaError("schema", "move-not-finite", where)
    return value


def _check_driven(model: Model, jid: str, where: str) -> None:
    ids = [j.id for j in model.joints]
    if jid not in ids:
        raise KinematikaError("schema", "unknown-joint", where, joint=jid, joints=ids)
    driven = driven_joints(model)
    if jid not in driven:
        raise KinematikaError("schema", "move-not-driven", where, joint=jid, driven=list(driven), count=len(driven))


def at_row(model: Model, row: int) -> Model:
    """`model` at row `row` of its sweep (its `sweep:` section, else a full turn in 360 steps;
    rows that cannot be assembled skipped, as the page sweeps it): the last row of the sweep
    of `row` steps of the same travel each, so through the limit positions it meets."""
    if any(p.value is None for p in model.parameters.values()):
        raise KinematikaError("schema", "row-needs-numbers", "row")
    sweeper = Sweeper(model)
    plan = sweeper.plan(None, None)
    if row > plan.steps:
        raise KinematikaError("usage", "row-out-of-range", "row", row=row, last=plan.steps)
    result = sweeper.run(plan.by * row / plan.steps, row, skip_bad=True)
    if not result.ok[-1]:
        raise KinematikaError("assembly", "row-cannot-assemble", "row", row=row)
    return posed_model(model, result, -1)
