"""The model a command analyses, posed as asked: parameters given values (`set`), the
assembly chosen (`assembly`), driven joints advanced (`move`, the file's own `move:` section
first) — and that model solved. Posing moves the mechanism as a sweep does, so it lives in
the sweep layer; every view (the command line, Python, the page, explanations, figures)
comes here through `kinematika.api`."""
from __future__ import annotations

import warnings
from typing import Any, Mapping, Optional

from ..engine.terms import MECHANICS, Terms
from ..errors import KinematikaError, KinematikaWarning, Names, Said
from ..model.model import Model
from ..model.overrides import with_parameters
from ..model.source import ModelLike, as_model
from ..solution import Solution, solve_model


def prepare(source: ModelLike, *, fmt: Optional[str] = None,
            set: Optional[Mapping[str, Any]] = None, move: Optional[Mapping[str, Any]] = None,
            assembly: Optional[int] = None, row: Optional[int] = None) -> Model:
    """The model a command analyses: read (`as_model`), with parameters given values (`set`,
    as `--set NAME=VALUE`), on the chosen assembly (`--assembly N`), advanced along driven
    joints (`move`, as `--move J=AMOUNT`), and posed at `row` of its own sweep (through
    limit positions, as the page's slider shows it: `move.at_row`)."""
    model = with_parameters(as_model(source, fmt),
                            {str(k): None if v is None else str(v) for k, v in (set or {}).items()})
    if assembly is not None:
        from .assemblies import with_assembly

        model = with_assembly(model, assembly)
    amounts = {**model.move, **(move or {})}
    if amounts:
        from .move import moved

        model = moved(model, amounts)
    if row:
        from .move import at_row

        model = at_row(model, row)
    return model


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


def solved(source: ModelLike, symbolic: bool | None = None, terms: Terms = MECHANICS,
           **options: Any) -> Solution:
    """`source` prepared (`options` as `prepare`'s) and solved: numerically, or exactly when
    it has symbols (or `symbolic`); with `terms`, as a student with that mistake would
    (`engine.terms`)."""
    return solve_model(prepare(source, **options), symbolic, terms)
