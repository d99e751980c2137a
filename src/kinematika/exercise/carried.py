"""Error carried forward: a later answer that follows from the student's own earlier wrong
answer earns its marks, as a teacher marks a worked solution.

The engine gives the problem's answers for any given motion from three solutions of the
variant, because of how the problem is built: the velocity problem is linear and
homogeneous in the drivers' rates, and the acceleration problem is linear in the drivers'
accelerations plus terms quadratic in the velocities (ω², the Coriolis 2 ω × v_rel). So with
the rates scaled by f and the one driver's acceleration changed by δ,

    velocities, ω:       f · V
    accelerations, α:    f² · A₀ + A_given + δ · A₁

where V and A₀ are the answers with the given rates and no driver acceleration, A_given the
answers at rest with the given driver accelerations, and A₁ those with a unit one (one
driver). A student's wrong velocity or ω is the answer of the rates scaled by their value
over the right one (f); a wrong acceleration or α, for one driver, the answer of the δ that
gives it, in the right velocities or in the student's carried ones. Each later answer is
compared with that world within its box's margin.

"Later" is later in the statement's order of questions; the earlier answer stays wrong. Only
answers linear in those fields (velocities, accelerations, ω, α and their decompositions)
carry; centres, curvatures and intrinsic components are marked as they are.
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any, Optional

from ..errors import KinematikaError
from ..expressions import Expr, parse
from ..questions import QUESTIONS
from .key import Row

VELOCITY_LEVEL = ("velocity", "omega")
ACCELERATION_LEVEL = ("acceleration", "alpha")
FLOOR = 0.01                  # a carried answer's margin: at least this share of the right one's
NOISE = 1e-9


@dataclass
class Basis:
    """The variant's answers that make any carried world: V and A₀ (given rates, no driver
    acceleration), A_given (at rest, the given driver accelerations), A₁ (at rest, a unit
    acceleration of the one driver; None with several drivers)."""

    rates: dict[str, float]
    accelerations: dict[str, float]
    given: dict[str, float]
    unit: Optional[dict[str, float]]

    def world(self, factor: float, extra: float = 0.0) -> dict[str, float]:
        """The answers with the rates times `factor` and the driver's acceleration plus `extra`."""
        out = {q: factor * v for q, v in self.rates.items()}
        for q, a in self.accelerations.items():
            out[q] = factor ** 2 * a + self.given[q] + (extra * self.unit[q] if self.unit else 0.0)
        return out


def basis(exercise: Any, variant: Any) -> Optional[Basis]:
    """The variant's basis (three or four solutions), or None when its drivers are not
    scalar rates (a vector driver) or a solution fails."""
    from ..sweep.posing import prepare

    model = prepare(exercise.model, set=variant.sets)
    drivers = list(model.drivers)
    if not drivers or not all(isinstance(d.value, Expr) for d in drivers):
        return None
    kinds = [q.kind for q in exercise.model.questions]
    linear = {r.question for r in variant.rows if QUESTIONS[kinds[r.ask - 1]].linear}

    def solved(rate: Optional[str], accel: Optional[str]) -> Optional[dict[str, float]]:
        changed = [dataclasses.replace(d, value=parse(rate) if rate is not None else d.value,
                                       accel=parse(accel) if accel is not None else d.accel) for d in drivers]
        try:
            rows = _rows(exercise, dataclasses.replace(model, drivers=changed))
        except KinematikaError:
            return None
        return {q: v for q, v in rows.items() if q in linear}

    at_rates = solved(None, "0")
    at_rest = solved("0", None)
    if at_rates is None or at_rest is None:
        return None
    level = {r.question: r.kind for r in variant.rows}
    rates = {q: v for q, v in at_rates.items() if level[q] in VELOCITY_LEVEL}
    accelerations = {q: v for q, v in at_rates.items() if level[q] in ACCELERATION_LEVEL}
    unit = None
    if len(drivers) == 1 and drivers[0].accel is not None:
        pushed = solved("0", f"({drivers[0].rate(accel=True).text})+1")
        if pushed is not None:
            unit = {q: pushed[q] - at_rest[q] for q in accelerations}
    return Basis(rates, accelerations, {q: at_rest[q] for q in accelerations}, unit)


def _rows(exercise: Any, model: Any) -> dict[str, float]:
    from .build import _answers_and_floors
    from .key import key_rows

    answers, floors = _answers_and_floors(model)
    kinds = [q.kind for q in exercise.model.questions]
    return {r.question: r.value for r in key_rows(answers, kinds, exercise.asks, floors)}


def carried(exercise: Any, variant: Any, wrong: dict[str, float], base: Optional[Basis]) -> dict[str, str]:
    """The wrong answers (question -> the student's value in the model's units) that follow
    from an earlier wrong one: question -> the question they follow from."""
    if not wrong or base is None:
        return {}
    rows = {r.question: r for r in variant.rows}
    out: dict[str, str] = {}
    order = sorted((q for q in wrong if q in base.rates or q in base.accelerations), key=lambda q: (rows[q].ask, q))

    def credit(source: Row, world: dict[str, float], level: tuple[str, ...]) -> None:
        sizes = _sizes(world, rows)
        for question, value in wrong.items():
            row = rows[question]
            if question in out or row.ask <= source.ask or question not in world or row.kind not in level:
                continue
            if abs(value - world[question]) <= variant.tolerance_of(row) * sizes[question]:
                out[question] = source.question

    factors = [1.0]
    for question in order:
        source = rows[question]
        if question in base.rates and abs(source.value) > variant.margin(source):
            f = wrong[question] / base.rates[question]
            factors.append(f)
            credit(source, base.world(f), VELOCITY_LEVEL + ACCELERATION_LEVEL)
    if base.unit is not None:
        for question in order:
            source = rows[question]
            slope = base.unit.get(question, 0.0)
            if question not in base.accelerations or abs(slope) <= NOISE * max(source.size, 1e-300):
                continue
            for f in factors:
                at = base.world(f)[question]
                credit(source, base.world(f, (wrong[question] - at) / slope), ACCELERATION_LEVEL)
    return out


def _sizes(world: dict[str, float], rows: dict[str, Row]) -> dict[str, float]:
    """Each carried answer's size: its vector's magnitude in that world (at least `FLOOR` of
    the right answer's size)."""
    groups: dict[str, list[str]] = {}
    for q in world:
        stem, _, axis = q.rpartition(".")
        groups.setdefault(stem if stem and axis in "xyz" else q, []).append(q)
    out = {}
    for members in groups.values():
        size = math.sqrt(sum(world[q] ** 2 for q in members))
        for q in members:
            out[q] = max(size, FLOOR * rows[q].size)
    return out
