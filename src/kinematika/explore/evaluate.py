"""One chunk of a study: designs in, rows out (parameters, `assembles`, `reason`, metrics).

The batch kernel (`sweep.batch`) takes every design it can, a few hundred at a time; the
rest — designs whose drawn configuration cannot be built (to say why in the contract's
words), and every design of a model without a closed form — go through the per-design
path (`run_sweep` on the model with the design's values). Both feed the same metric code,
so a row does not depend on the path that computed it (beyond round-off).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from ..errors import KinematikaError
from ..model.model import Model
from ..model.overrides import with_parameters
from ..structure.assur import assur_groups
from ..sweep.batch import BatchSweeper, describe
from .cycle import BatchCycle, ResultCycle
from .metrics import Context, Metric, parse_metric

BATCH = 64              # designs solved together: (BATCH × positions) arrays stay in cache-sized pieces


@dataclass(frozen=True)
class Sweep:
    """The sweep options of a study (None: the model's own, else a full turn in 360 steps)."""

    joint: Optional[str] = None
    by: Optional[float] = None
    steps: Optional[int] = None


class Evaluator:
    """A model prepared for evaluating designs: structure, batch kernel and metrics."""

    def __init__(self, model: Model, varied: list[str], metrics: list[str], sweep: Sweep = Sweep(),
                 files: Optional[dict[str, str]] = None) -> None:
        self.model, self.varied, self.sweep = model, list(varied), sweep
        _check_parameters(model, self.varied)
        self.batch = BatchSweeper(model, self.varied, sweep.joint, sweep.by, sweep.steps)
        plan = self.batch.plan
        self.context = Context(model, assur_groups(model), plan.coordinate, plan.unit)
        self.metrics: list[Metric] = [parse_metric(m, self.context, files) for m in metrics]
        names = [m.name for m in self.metrics]
        if len(set(names)) != len(names) or set(names) & ({"assembles", "reason"} | set(self.varied)):
            raise KinematikaError("usage", "metrics-once", "--metric")

    @property
    def columns(self) -> list[str]:
        """The table's columns in order: the varied parameters, `assembles`, `reason`, then the
        metrics."""
        return self.varied + ["assembles", "reason"] + [m.name for m in self.metrics]

    def evaluate(self, values: dict[str, np.ndarray]) -> dict[str, Any]:
        """The rows of the designs `values` (name → (D,) array), as columns."""
        size = len(values[self.varied[0]])
        out = Rows(size, self.metrics)
        alone = np.ones(size, dtype=bool)
        if self.batch.batchable:
            for start in range(0, size, BATCH):
                part = slice(start, min(start + BATCH, size))
                alone[part] = ~self._batch({k: v[part] for k, v in values.items()}, out, part)
        for d in np.flatnonzero(alone):
            self._alone({k: float(v[d]) for k, v in values.items()}, out, int(d))
        return {**{k: np.asarray(values[k], dtype=float) for k in self.varied}, **out.columns()}

    def _batch(self, values: dict[str, np.ndarray], out: "Rows", part: slice) -> np.ndarray:
        """Solve designs together; returns which of them the batch took."""
        try:
            batch = self.batch.run(values)
        except KinematikaError:
            return np.zeros(part.stop - part.start, dtype=bool)     # e.g. an expression's limit: one by one
        cycle = BatchCycle(batch)
        took = batch.drawn
        out.assembles[part] = took
        reasons = batch.reasons()
        for i in np.flatnonzero(took):
            out.reason[part.start + i] = reasons[i]
        for m in self.metrics:
            values_ = m.values(cycle)
            column = out.values[m.name]
            column[part] = np.where(took, values_, column[part])
        return took

    def _alone(self, values: dict[str, float], out: "Rows", d: int) -> None:
        """One design through `run_sweep`: its reason if it fails, its metrics otherwise."""
        from ..sweep.move import as_written
        from ..sweep.run import Sweeper

        model = with_parameters(self.model, {k: repr(v) for k, v in values.items()})
        s = self.sweep
        try:
            sweeper = Sweeper(as_written(model), s.joint)
            try:
                result = sweeper.run(s.by, s.steps, through=False)   # a cycle of the input, as
            except KinematikaError as err:                           # the batch kernel sweeps it
                out.reason[d] = describe(err)
                result = sweeper.run(s.by, s.steps, skip_bad=True, through=False)
        except KinematikaError as err:
            out.assembles[d] = False
            out.reason[d] = describe(err)
            return
        out.assembles[d] = True
        cycle = ResultCycle(result, sweeper.directions)
        for m in self.metrics:
            out.values[m.name][d] = m.values(cycle)[0]


class Rows:
    """The columns of a chunk being filled: assembles, reason, one per metric."""

    def __init__(self, size: int, metrics: list[Metric]) -> None:
        self.metrics = metrics
        self.assembles = np.zeros(size, dtype=bool)
        self.reason = [""] * size
        self.values = {m.name: (np.full(size, None, dtype=object) if m.kind == "class"
                                else np.full(size, np.nan)) for m in metrics}

    def columns(self) -> dict[str, Any]:
        """The filled chunk as columns: `assembles`, `reason`, and each metric (NaN for a design
        that does not assemble, a class metric None there)."""
        out: dict[str, Any] = {"assembles": self.assembles, "reason": np.array(self.reason, dtype=object)}
        for m in self.metrics:
            values = self.values[m.name]
            if m.kind != "class":
                values = np.where(self.assembles, values, np.nan)
            out[m.name] = values
        return out


def _check_parameters(model: Model, varied: list[str]) -> None:
    """Every varied name is a parameter; every other parameter has a value."""
    for name in varied:
        if name not in model.parameters:
            raise KinematikaError("usage", "unknown-parameter", "--vary", name=name, parameters=list(model.parameters))
    symbols = [n for n, p in model.parameters.items() if p.value is None and n not in varied]
    if symbols:
        raise KinematikaError("usage", "study-needs-numbers", "--vary", names=symbols)
