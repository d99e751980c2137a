"""The Python entry points: load a model, solve it, read the answers."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Mapping, Optional, Union

from .engine.system import InstantSolver
from .engine.instant import instantiate
from .model.build import build_model
from .model.files import load_model, parse_text
from .model.model import Model
from .questions import answer
from .solution import Solution

ModelLike = Union[Model, str, Path, dict]


def as_model(source: ModelLike, fmt: Optional[str] = None) -> Model:
    """A `Model` from a model, a file path, a model tree (dict), a `Mechanism` or the text of
    a model (a string of several lines, or any string when `fmt` names its format: 'yaml',
    'toml' or 'json')."""
    if isinstance(source, Model):
        return source
    if isinstance(source, dict):
        return build_model(source)
    if hasattr(source, "to_model"):
        return source.to_model()
    if isinstance(source, str) and (fmt is not None or "\n" in source):   # a model's text
        return build_model(parse_text(source, fmt or "yaml", "<text>"))
    return load_model(source)


def prepare(source: ModelLike, *, fmt: Optional[str] = None,
            set: Optional[Mapping[str, Any]] = None, move: Optional[Mapping[str, Any]] = None,
            assembly: Optional[int] = None) -> Model:
    """The model a command analyses: read (`as_model`), with parameters given values (`set`,
    as `--set NAME=VALUE`), on the chosen assembly (`--assembly N`) and advanced along driven
    joints (`move`, as `--move J=AMOUNT`). Every view (CLI, Python, the page) comes here."""
    from .model.overrides import with_parameters

    model = with_parameters(as_model(source, fmt),
                            {str(k): None if v is None else str(v) for k, v in (set or {}).items()})
    if assembly is not None:
        from .sweep.assemblies import with_assembly

        model = with_assembly(model, assembly)
    amounts = {**model.move, **(move or {})}
    if amounts:
        from .sweep.move import moved

        model = moved(model, amounts)
    return model


def solve(source: ModelLike, symbolic: bool | None = None, **options: Any) -> Solution:
    """Solve the instant described by `source` (numerically, or exactly when it has symbols);
    `options` are `prepare`'s (set, move, assembly, fmt)."""
    model = prepare(source, **options)
    inst = instantiate(model, symbolic)
    solver = InstantSolver(inst)
    motion = solver.solve()
    return Solution(model, inst, motion, solver)


def answers(sol: Solution) -> list[tuple[Any, Any]]:
    """Each question of the model with its raw answer, in order."""
    return [(q, answer(sol, q)) for q in sol.model.questions]
