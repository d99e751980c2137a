"""Values for a model's parameters given from outside the file (`--set r=0.1`, the page).

A constructed model is re-posed by its own parameters (`--set theta=40`), and a symbolic
model is drawn or solved at numbers the user gives: this replaces the named parameters'
values (numbers or expressions, checked like a model file's) in a copy of the model.
`null` (or None from JSON) makes a parameter a symbol, as `null` in the file does: a
numeric model's crank angle becomes θ and the answers formulas in it.
"""
from __future__ import annotations

import contextlib
import dataclasses
import warnings
from typing import Mapping, Optional

from ..errors import KinematikaError, KinematikaWarning, Names, Said
from ..expressions import ExpressionError, evaluate, parse
from .model import Model


def with_parameters(model: Model, values: Mapping[str, Optional[str]]) -> Model:
    """A copy of `model` with the named parameters set to `values`."""
    if not values:
        return model
    from .parameter import Parameter    # (defined only for a model that has one: see its module)

    params = dict(model.parameters)
    for name, text in values.items():
        if name not in params:
            raise KinematikaError("usage", "unknown-parameter", "--set", name=name, parameters=list(params))
        if text is None or str(text).strip() == "null":
            params[name] = Parameter(name, None, params[name].positive)
            continue
        try:
            expr = parse(text)
        except ExpressionError as err:
            raise KinematikaError("schema", err.said, f"--set {name}") from None
        unknown = sorted(expr.names() - set(params) - {"pi"})
        if unknown:
            raise KinematikaError("schema", "unknown-name-in-parameters", f"--set {name}", name=unknown[0], text=text,
                                  parameters=list(params))
        params[name] = Parameter(name, expr, params[name].positive)
    return dataclasses.replace(model, parameters=params)


def numeric_parameters(model: Model) -> dict[str, float]:
    """The parameters that evaluate to numbers (symbols and what depends on them left out),
    each from those before it, in any order of writing."""
    from ..algebra.backend import Numeric

    env: dict[str, float] = {}
    pending = {n: p.value for n, p in model.parameters.items() if p.value is not None}
    progress = True
    while pending and progress:
        progress = False
        for name, value in list(pending.items()):
            if value.names() <= set(env) | {"pi"}:
                with contextlib.suppress(ExpressionError, ValueError, OverflowError):
                    env[name] = float(evaluate(value, env, Numeric()))
                del pending[name]
                progress = True
    return env


def at_draw_numbers(model: Model, what: str, why: Optional[Said] = None,
                    warn: bool = True) -> tuple[Model, list[KinematikaWarning]]:
    """`model`'s symbols given their `draw_at` numbers, for the work that needs numbers (`what`:
    `sweep`; `move`, a move the symbols cannot follow exactly), and the warning that says so
    (`why`, when given, ends it), issued as a Python warning (the command line prints it)
    unless `warn` is False (the caller issues it once the work is under way).
    A symbol without a `draw_at` number is a `schema` error naming it."""
    symbols = [n for n, p in model.parameters.items() if p.value is None]
    if not symbols:
        return model, []
    missing = [n for n in symbols if n not in model.draw_at]
    if missing:
        raise KinematikaError("schema", "needs-draw-at", "parameters", what=what, names=Names(missing))
    values = {n: repr(float(model.draw_at[n])) for n in symbols}
    shown = ", ".join(f"{n} = {model.draw_at[n]:g}" for n in symbols)
    note = KinematikaWarning("at-draw-numbers", "draw_at", what=what, values=shown, why=why or "",
                             said=str(why is not None).lower())
    if warn:
        warnings.warn(note, stacklevel=2)
    return with_parameters(model, values), [note]
