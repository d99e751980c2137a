"""How long a motion is followed in time, and its rows: the model's `simulate` section with
the command's `--time` and `--steps` over it.

Row k is at time t₀ + k T / N (N steps, N + 1 rows); row 0 is the drawn configuration, t₀
the value of the parameter `t` when the model has one (else 0).
"""
from __future__ import annotations

import math
import numbers
from dataclasses import dataclass
from functools import cached_property
from typing import Any, Optional

import numpy as np

from .. import limits
from ..errors import KinematikaError, Num
from ..sweep.plan import check_steps

DEFAULT_STEPS = 200
DEFAULT_TIME = 10.0          # seconds the page follows a model whose file gives no time
MAX_STEPS = limits.SIMULATE_STEPS


@dataclass(frozen=True)
class Clock:
    """The rows of a simulation: from `start` (seconds) over `duration` in `steps` equal steps."""

    start: float
    duration: float
    steps: int

    @cached_property
    def times(self) -> np.ndarray:
        """The rows' times: start, start + T/N, …, start + T (N + 1 rows)."""
        out = self.start + np.linspace(0.0, self.duration, self.steps + 1)
        out.flags.writeable = False
        return out

    @property
    def end(self) -> float:
        """The last row's time."""
        return self.start + self.duration


def make_clock(model: Any, start: float, time: Optional[float] = None, steps: Optional[int] = None,
               default_time: Optional[float] = None) -> Clock:
    """The clock of `model`'s simulation: its `simulate:` section with `time` and `steps` over
    it (`default_time` when neither gives a time; else a `schema` error asking for one)."""
    section = model.simulate
    if time is None:
        if section is not None:
            from ..algebra.backend import Numeric
            from ..expressions import ExpressionError, evaluate
            from ..model.overrides import numeric_parameters

            try:
                time = float(evaluate(section.time, numeric_parameters(model), Numeric()))
            except (ExpressionError, TypeError, ValueError) as err:
                raise KinematikaError("schema", "simulate-time-not-evaluated", "simulate.time",
                                      problem=err.said if isinstance(err, ExpressionError) else str(err)) from None
        elif default_time is not None:
            time = default_time
        else:
            raise KinematikaError("schema", "simulate-time-missing", "simulate.time")
    if steps is None:
        steps = section.steps if section is not None else DEFAULT_STEPS
    if isinstance(time, bool) or not isinstance(time, numbers.Real) or not math.isfinite(time) or time <= 0:
        raise KinematikaError("schema", "simulate-time-positive", "simulate.time", got=_written(time))
    check_steps(model, steps, MAX_STEPS, "simulate.steps", "simulate-steps-too-many")
    if not math.isfinite(start + float(time)) or float(time) <= 1e-12 * max(1.0, abs(start)):
        raise KinematikaError("schema", "simulate-time-too-short", "simulate.time", time=_written(time),
                              start=float(start))
    return Clock(float(start), float(time), int(steps))


def _written(value: Any) -> Any:
    """A time as a message writes it: a number in the language's signs, else as Python shows it."""
    if isinstance(value, numbers.Real) and not isinstance(value, bool):
        return Num(float(value), ".6g")
    return repr(value)
