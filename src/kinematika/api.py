"""The Python entry points: load a model, solve it, read the answers."""
from __future__ import annotations

from pathlib import Path
from typing import Any, Union

from .engine.system import InstantSolver
from .engine.instant import instantiate
from .model.build import build_model
from .model.files import load_model, parse_text
from .model.model import Model
from .questions import answer
from .solution import Solution

ModelLike = Union[Model, str, Path, dict]


def as_model(source: ModelLike) -> Model:
    """A `Model` from a model, a file path, a model tree (dict), a `Mechanism` or the text of
    a YAML (or JSON) model (a string of several lines)."""
    if isinstance(source, Model):
        return source
    if isinstance(source, dict):
        return build_model(source)
    if hasattr(source, "to_model"):
        return source.to_model()
    if isinstance(source, str) and "\n" in source:     # a model's text, not a file name
        return build_model(parse_text(source, "yaml", "<text>"))
    return load_model(source)


def solve(source: ModelLike, symbolic: bool | None = None) -> Solution:
    """Solve the instant described by `source` (numerically, or exactly when it has symbols)."""
    model = as_model(source)
    inst = instantiate(model, symbolic)
    solver = InstantSolver(inst)
    motion = solver.solve()
    return Solution(model, inst, motion, solver)


def answers(sol: Solution) -> list[tuple[Any, Any]]:
    """Each question of the model with its raw answer, in order."""
    return [(q, answer(sol, q)) for q in sol.model.questions]
