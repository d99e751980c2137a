"""The batch axis: many designs of one model swept at once, as arrays (designs × positions).

A design is a set of values of some of the model's parameters. `BatchSweeper` evaluates
the model's expressions and constructions over arrays of those values
(`algebra.arrays`, `engine.array_positions`) and runs the closed form of a crank or slider
followed by dyads (`closed_form`) on a (D, 1) column of drawn designs against a (1, N) row
of increments: each design keeps the branch of its own drawn configuration, as a sweep
does. Designs it cannot take — the drawn configuration cannot be built, or the mechanism
has no closed form — are left to the per-design path (`run_sweep`), which gives the same
rows and says why a design fails in the contract's words.
"""
from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from ..algebra.arrays import Arrays
from ..algebra.vectors import Space
from ..engine.array_positions import array_positions
from ..engine.instant import Instant, _parameters
from ..errors import KinematikaError, speaking
from ..joints.capabilities import Coordinate
from ..model.model import Model
from ..point_pair import PointPair
from ..model.parameter import Parameter
from ..structure.assur import Group, assur_groups
from .closed_form import ClosedForm, InputRates, Outcome, Over, applicable
from .plan import Plan, bad_row, make_plan, swept_joint

SLOT_GAP = 1e-6          # relative to the model's size, as the engine checks a slot's pin


@dataclass
class Batch:
    """The closed form's outcome for D designs over the plan's N rows.

    `drawn` (D,) is True for designs the batch solved: drawn configuration built and
    assembled, not singular, at row 0. The others must go through the per-design path.
    """

    plan: Plan
    outcome: Outcome
    drawn: np.ndarray
    points: dict[str, np.ndarray]        # drawn point locations (D,) complex
    directions: dict[str, np.ndarray]    # unit `along` of prismatic and slot joints (D,) complex

    @property
    def ok(self) -> np.ndarray:
        """(D, N): each row assembled and not singular."""
        return self.outcome.assembled & ~self.outcome.singular

    def reasons(self) -> list[str]:
        """Per design: '' when the whole sweep is assembled, else the error a sweep of it
        stops with (`run_sweep` without `skip_bad`), as 'kind: where: message'."""
        ok = self.ok
        out = [""] * len(ok)
        for d in np.flatnonzero(~ok.all(axis=1) & self.drawn):
            k = int(np.argmin(ok[d]))
            kind = "singular" if self.outcome.singular[d, k] else "assembly"
            out[d] = describe(bad_row(self.plan, k, kind, self.outcome.worst((d, k))))
        return out


def describe(err: KinematikaError) -> str:
    """An error as the `reason` column writes it: 'kind: where: message', in English
    whatever the language of messages (a column of data is the same on every machine)."""
    with speaking("en"):
        return f"{err.kind}: {err}"


class BatchSweeper:
    """A model prepared for sweeps of many designs (values of the parameters `varied`)."""

    def __init__(self, model: Model, varied: list[str], joint: Optional[str] = None,
                 by: Optional[float] = None, steps: Optional[int] = None) -> None:
        self.model = model
        self.varied = list(varied)
        self.symbols = model_with_symbols(model, self.varied)
        self.joint, self.driver = swept_joint(model, joint if joint is not None else
                                              (model.sweep.joint if model.sweep else None))
        self.groups = assur_groups(model)
        self.options = (by, steps)
        self.plan = self._plan()
        self.batchable = self._batchable()

    def _batchable(self) -> bool:
        """Closed form, a driver whose rates are its values (ω or a joint's rate), and a sweep
        whose length does not depend on the design."""
        if self.groups is None or not applicable(self.model, self.groups, self.joint, self.driver):
            return False
        if self.driver.kind not in ("omega", "joint"):
            return False
        return self.driver.kind == "joint" or self.joint.kind.coordinate is Coordinate.ANGLE

    def _plan(self) -> Plan:
        """The sweep's rows, the same for every design."""
        section = self.model.sweep
        if self.options[0] is None and section is not None and section.by.names() & set(self.varied):
            raise KinematikaError("usage", "sweep-by-varied", "sweep.by", by=section.by.text)
        inst = self._instant({name: np.zeros(1) for name in self.varied})
        return make_plan(inst, self.joint.id, *self.options)

    def _instant(self, values: dict[str, np.ndarray]) -> Instant:
        env, _ = _parameters(self.symbols, Arrays(values), False)
        return Instant(self.symbols, Arrays(values), Space(2), env, {}, {})

    def run(self, values: dict[str, np.ndarray]) -> Batch:
        """Sweep the designs `values` (name → (D,) array) over the plan's rows."""
        assert self.batchable
        size = len(next(iter(values.values())))
        with np.errstate(all="ignore"):
            inst = self._instant({k: np.asarray(v, dtype=float) for k, v in values.items()})
            xy = array_positions(inst)
            points = {name: _column(p[0], size) + 1j * _column(p[1], size) for name, p in xy.items()}
            drawn = np.logical_and.reduce([np.isfinite(p) for p in points.values()])
            directions = self._directions(inst, points, size)
            for u in directions.values():
                drawn &= np.isfinite(u)
            drawn &= self._slots_hold(points, directions)
            rates = self._rates(inst, directions, size)
            for r in (rates.omega, rates.alpha, rates.v, rates.a):
                drawn &= np.isfinite(np.broadcast_to(r, (size, 1))[:, 0])
            columns: dict[str, Over] = {k: p[:, None] for k, p in points.items()}
            along: dict[str, Over] = {k: u[:, None] for k, u in directions.items()}
            closed = ClosedForm(self.model, columns, along, self._groups(), self.joint, rates)
            outcome = closed.solve(self.plan.increments[None, :])
        drawn &= outcome.assembled[:, 0] & ~outcome.singular[:, 0]
        return Batch(self.plan, outcome, drawn, points, directions)

    def _groups(self) -> list[Group]:
        """The inputs and Assur groups (a batchable model, which has a closed form, has them)."""
        assert self.groups is not None, "a batchable model decomposes into groups"
        return self.groups

    def _directions(self, inst: Instant, points: dict[str, np.ndarray], size: int) -> dict[str, np.ndarray]:
        """Each prismatic or slot joint's unit `along` (fixed in its first body), per design."""
        out = {}
        for j in self.model.joints:
            if j.along is None:
                continue
            if isinstance(j.along, PointPair):
                d = points[j.along.end] - points[j.along.start]
            else:
                x, y = inst.vector(j.along, f"{j.where}.along")
                d = _column(x, size) + 1j * _column(y, size)
            norm = np.abs(d)
            out[j.id] = np.where(norm > 1e-12, d / norm, np.nan)
        return out

    def _slots_hold(self, points: dict[str, np.ndarray], directions: dict[str, np.ndarray]) -> np.ndarray:
        """Designs whose slot pins lie on their lines (else the engine's `geometry` error)."""
        size = len(next(iter(points.values())))
        holds = np.ones(size, dtype=bool)
        slots = [(j, j.along) for j in self.model.joints if j.kind.guides_point and j.kind.slides
                 and isinstance(j.along, PointPair)]
        if not slots:
            return holds
        stack = np.array(list(points.values()))
        scale = np.abs(stack - stack.mean(axis=0)).max(axis=0)
        for j, along in slots:
            gap = _cross(points[j.point_at()] - points[along.start], directions[j.id])
            holds &= np.abs(gap) <= SLOT_GAP * scale
        return holds

    def _rates(self, inst: Instant, directions: dict[str, np.ndarray], size: int) -> InputRates:
        """The input's ω, α (crank) or v, a (slider) from its driver's values, per design."""
        d, j, frame = self.driver, self.joint, self.model.frame
        value = _column(inst.value(d.rate(), f"{d.where}.value"), size)[:, None]
        accel = _column(inst.value(d.rate(accel=True), f"{d.where}.accel"), size)[:, None]
        sign = 1.0 if d.kind == "omega" or j.a == frame else -1.0      # a joint's rate is b relative to a
        body = self._groups()[0].bodies[0]
        if j.kind.coordinate is Coordinate.ANGLE:
            return InputRates(j.point_at(), sign * value, sign * accel, 0j, 0j)
        names = self.model.bodies[body].points
        origin = names[0] if names else next(iter(self.model.points))
        u = directions[j.id][:, None]
        return InputRates(origin, 0.0, 0.0, sign * value * u, sign * accel * u)


def model_with_symbols(model: Model, varied: list[str]) -> Model:
    """A copy of `model` whose varied parameters have no value (each design gives one)."""
    params = dict(model.parameters)
    for name in varied:
        params[name] = Parameter(name, None, params[name].positive)
    return dataclasses.replace(model, parameters=params)


def _column(value: Any, size: int) -> np.ndarray:
    """A value per design: an array as it is, a number repeated."""
    return np.broadcast_to(np.asarray(value, dtype=float), (size,))


def _cross(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    return p.real * q.imag - p.imag * q.real
