"""A driven joint advanced from the drawing by an amount, as a sweep reaches it (`swept_to`,
`advanced`): the sweep of that joint to the amount (a row a degree, or a 50th of the
model's size), every row assembled, else an `assembly` error saying how far it got. A
model's `move` (`move`, `symbolic_move`) is made of these.
"""
from __future__ import annotations

import math
from typing import Any

from ..errors import KinematikaError, Num
from ..joints.capabilities import Coordinate
from ..model.model import Model
from .plan import check_travel
from .posed import posed_model
from .run import Sweeper

DEGREES_PER_STEP = 1.0          # continuation steps of a revolute
LENGTHS_PER_STEP = 0.02         # of a prismatic, in model sizes
MAX_STEPS = 200_000


def advanced(model: Model, jid: str, amount: float, where: str) -> Model:
    """`model` posed where the sweep of joint `jid` by `amount` ends (`swept_to`)."""
    return posed_model(model, swept_to(model, jid, amount), -1)


def swept_to(model: Model, jid: str, amount: float) -> Any:
    """The sweep of joint `jid` from the drawing to `amount` (a row a degree, or a 50th of
    the model's size), every row assembled, else the `assembly` error saying how far."""
    sweeper = Sweeper(model, jid)
    check_travel(amount, model.joint(jid), sweeper.inst.scale, f"move.{jid}", "a move of")
    turns = model.joint(jid).kind.coordinate is Coordinate.ANGLE
    per_step = DEGREES_PER_STEP if turns else LENGTHS_PER_STEP * sweeper.inst.scale
    steps = min(MAX_STEPS, max(1, math.ceil(abs(amount) / per_step)))
    result = sweeper.run(amount, steps, skip_bad=True, through=False)   # to the coordinate, not through limits
    if not result.ok.all():
        raise _unreachable(result, jid, amount, "°" if turns else "")
    return result


def _unreachable(result: Any, jid: str, amount: float, unit: str) -> KinematikaError:
    """How far the joint got before the first position that cannot be assembled."""
    bad = int((~result.ok).nonzero()[0][0])
    got = float(result.coordinate[max(bad - 1, 0)])
    edges = [x for x in result.dead_points if abs(x) <= abs(amount) and x * amount >= 0]
    if edges:
        got = min(edges, key=abs)
    return KinematikaError("assembly", "move-unreachable", f"move.{jid}", joint=jid, amount=amount, unit=unit,
                           got=Num(got, ".6g"))
