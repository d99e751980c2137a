"""Drivers in time: rates kept as written, or expressions in the time `t`.

A model whose drivers change in time declares the parameter `t` (its value is the drawn
configuration's time, usually 0) and writes the rates in it: `{omega: crank, value:
"2*sin(t)"}`. A simulation sets `t` to each instant's time, and the parameters written in
`t` follow. A driver's acceleration in time is the derivative of its rate, taken exactly
(sympy) once: `2*cos(t)`; a rate that is constant has none (a written `accel` is then left
out, and the summary says so, since the rate stays as written). The time may reach only the
drivers' rates: a point, a shape or a joint written in `t` would move by itself, which a
simulation does not follow (a `schema` error naming the place).
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any, Callable, Iterator

from ..algebra.backend import Numeric
from ..errors import KinematikaError, Names, Num, Said
from ..expressions import Expr, ExpressionError, evaluate, parse
from ..model.model import Model
from ..model.parameter import Parameter
from ..model.overrides import numeric_parameters

TIME = "t"
_NUMERIC = Numeric()


@dataclass
class Timing:
    """How a model's drivers change in time: the model as it is simulated (each driver's
    `accel` the derivative of its rate), the parameters that follow `t` (in the order they
    are computed) and the derivatives' functions, each with the place of its driver."""

    model: Model
    start: float = 0.0
    follow: list[str] = field(default_factory=list)          # parameters written in t, in order
    rates: dict[str, tuple[Callable[[float], float], str]] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)           # accelerations left out, said once

    @property
    def changes(self) -> bool:
        """Whether any driver changes in time."""
        return bool(self.rates)

    def env(self, base: dict[str, Any], t: float, accelerations: bool = True) -> dict[str, Any]:
        """The parameters' values at time `t`: `base` with `t`, what is written in it, and (when
        `accelerations`: the velocities alone need none) the drivers' accelerations there; a
        rate that cannot be evaluated is a `schema` error at its driver (or parameter) naming
        the time."""
        if not self.changes and TIME not in base:
            return base
        env = dict(base)
        env[TIME] = t
        for name in self.follow:
            try:
                env[name] = evaluate(_written(self.model.parameters[name]), env, _NUMERIC)
            except ExpressionError as err:
                raise KinematikaError("schema", "simulate-at", f"parameters.{name}", at=Num(t, ".6g"),
                                      what=err.said) from None
        for name, (rate, where) in (self.rates if accelerations else {}).items():
            env[name] = rate(t)
            if not math.isfinite(env[name]):
                raise KinematikaError("schema", "simulate-at", where, at=Num(t, ".6g"),
                                      what=Said("simulate-rate-not-finite"))
        return env


def timing(model: Model) -> Timing:
    """The drivers of `model` in time (see the module): `model` must have numbers for every
    parameter (`t` included, when it has one)."""
    params = model.parameters
    timed = _written_in_time(params)
    _only_in_rates(model, timed)
    numbers = numeric_parameters(model)
    start = 0.0
    if TIME in params:
        if TIME not in numbers:
            raise KinematikaError("schema", "simulate-time-needs-value", f"parameters.{TIME}")
        start = numbers[TIME]
    out = Timing(model, start, [n for n in _ordered(params, timed) if n != TIME])
    taken = set(params)
    extra: dict[str, Parameter] = {}
    drivers = []
    for d in model.drivers:
        values = _expressions_of(d.value)
        if any(e.names() & timed for e in values):
            names = []
            for k, e in enumerate(values):
                name = _fresh(f"_rate_of_drivers_{d.index}" + (f"_{k}" if len(values) > 1 else ""), taken)
                out.rates[name] = (_derivative(e, model, timed, d.where), d.where)
                extra[name] = Parameter(name, parse(0), positive=False)
                names.append(parse(name))
            accel: Any = tuple(names) if isinstance(d.value, tuple) else names[0]
        else:
            accel = tuple(parse(0) for _ in values) if isinstance(d.value, tuple) else parse(0)
            if any(_nonzero(e, numbers) for e in _expressions_of(d.accel)):
                out.notes.append(f"{d.where}: its accel is left out: the rate stays as written in "
                                 "time (write it as an expression in t, e.g. \"3 + 0.5*t\", to change it)")
        drivers.append(dataclasses.replace(d, accel=accel))
    out.model = dataclasses.replace(model, parameters={**params, **extra}, drivers=drivers)
    return out


def _written_in_time(params: dict[str, Parameter]) -> set[str]:
    """`t` and the parameters written in it, however indirectly."""
    if TIME not in params:
        return set()
    timed = {TIME}
    grown = True
    while grown:
        grown = False
        for name, p in params.items():
            if name not in timed and p.value is not None and p.value.names() & timed:
                timed.add(name)
                grown = True
    return timed


def _ordered(params: dict[str, Parameter], names: set[str]) -> list[str]:
    """`names` in an order in which each is computed after those it is written in."""
    out: list[str] = []
    pending = [n for n in params if n in names]
    while pending:
        ready = [n for n in pending if not (_names(params[n]) & (set(pending) - {n}))]
        if not ready:            # a cycle: the model's own check reports it
            return out + pending
        out += ready
        pending = [n for n in pending if n not in ready]
    return out


def _only_in_rates(model: Model, timed: set[str]) -> None:
    """The time reaches the drivers' rates only (see the module)."""
    if not timed:
        return
    places: list[tuple[str, Any]] = [(f"points.{n}", p) for n, p in model.points.items()]
    places += [(f"bodies.{n}", b.shapes) for n, b in model.bodies.items()]
    places += [(j.where, j) for j in model.joints]
    places += [(f"{d.where}.along", d.along) for d in model.drivers]
    places += [(f"move.{n}", e) for n, e in model.move.items()]
    for where, thing in places:
        for place, expr in _expressions(thing, where):
            if expr.names() & timed:
                raise KinematikaError("schema", "simulate-time-only-in-rates", place)


def _expressions(thing: Any, where: str) -> Iterator[tuple[str, Expr]]:
    """Every expression in a part of the model, with its place."""
    if isinstance(thing, Expr):
        yield where, thing
    elif dataclasses.is_dataclass(thing) and not isinstance(thing, type):
        for f in dataclasses.fields(thing):
            yield from _expressions(getattr(thing, f.name), where)
    elif isinstance(thing, (list, tuple)):
        for i, x in enumerate(thing):
            yield from _expressions(x, f"{where}[{i}]")


def _expressions_of(value: Any) -> tuple[Expr, ...]:
    """A driver's value or accel as its expressions (one, or a vector's)."""
    return tuple(e for e in (value if isinstance(value, tuple) else (value,)) if e is not None)


def _names(p: Parameter) -> set[str]:
    """The names a parameter is written in (none for a symbol)."""
    return p.value.names() if p.value is not None else set()


def _written(p: Parameter) -> Expr:
    """A parameter's expression (a simulated model's parameters all have one)."""
    if p.value is None:
        raise KinematikaError("schema", "needs-draw-at", f"parameters.{p.name}", what="simulate",
                              names=Names([p.name]))
    return p.value


def _nonzero(expr: Expr, numbers: dict[str, float]) -> bool:
    try:
        return float(evaluate(expr, numbers, _NUMERIC)) != 0.0
    except (ExpressionError, TypeError, ValueError):
        return True


def _fresh(name: str, taken: set[str]) -> str:
    while name in taken:
        name = "_" + name
    taken.add(name)
    return name


def _derivative(expr: Expr, model: Model, timed: set[str], where: str) -> Callable[[float], float]:
    """d(expr)/dt as a function of t, from the exact derivative (the other parameters at their
    numbers); the function raises a `schema` error at `where` where it cannot be evaluated."""
    import numpy as np
    import sympy

    from ..algebra.backend import Symbolic

    backend = Symbolic()
    t = sympy.Symbol(TIME, real=True)
    env: dict[str, Any] = {n: sympy.Float(v) for n, v in numeric_parameters(model).items() if n not in timed}
    env[TIME] = t
    params = model.parameters
    try:
        for name in _ordered(params, timed):
            if name != TIME:
                env[name] = evaluate(_written(params[name]), env, backend)
        rate = sympy.diff(evaluate(expr, env, backend), t)
    except (ExpressionError, TypeError, ValueError) as err:
        raise KinematikaError("schema", "simulate-rate-not-taken", where,
                              problem=err.said if isinstance(err, ExpressionError) else str(err)) from None
    function = sympy.lambdify(t, rate, modules="numpy")

    def derivative(time: float) -> float:
        with np.errstate(all="ignore"):
            try:
                value = complex(function(time))
            except (ArithmeticError, ValueError, TypeError) as err:
                raise KinematikaError("schema", "simulate-at", where, at=Num(time, ".6g"),
                                      what=Said("simulate-rate-not-evaluated", problem=str(err))) from None
        if value.imag != 0 or not math.isfinite(value.real):
            raise KinematikaError("schema", "simulate-at", where, at=Num(time, ".6g"),
                                  what=Said("simulate-rate-not-real"))
        return value.real

    return derivative
