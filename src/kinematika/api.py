"""The Python entry points: load a model, solve it, read the answers.

    >>> import kinematika
    >>> sol = kinematika.solve("examples/four_bar.yaml")
    >>> sol.velocity("B"), sol.omega("coupler")

`solve` and `prepare` are the sweep layer's (`sweep.posing`: posing a model moves it as a
sweep does); the Jupyter drawings of a `Solution` register here, from above the views.
"""
from __future__ import annotations

from typing import Any, Optional

from .model.builder import Mechanism
from .model.source import ModelLike, as_model
from .solution import Solution
from .sweep.posing import prepare, solved

__all__ = ["Mechanism", "ModelLike", "answers", "as_model", "prepare", "solve"]


def solve(source: ModelLike, symbolic: bool | None = None, **options: Any) -> Solution:
    """Solve the instant described by `source` (numerically, or exactly when it has symbols);
    `options` are `prepare`'s (set, move, assembly, fmt)."""
    return solved(source, symbolic, **options)


def answers(sol: Solution) -> list[tuple[Any, Any]]:
    """Each question of the model with its raw answer, in order."""
    from .questions import answer       # the questions' modules only when a model asks them

    return [(q, answer(sol, q)) for q in sol.model.questions]


def _solution_svg(sol: Solution) -> Optional[str]:
    """Jupyter: a solved instant shows itself as its figure."""
    from .draw.jupyter import solution_svg

    return solution_svg(sol)


def _mechanism_svg(m: Any) -> Optional[str]:
    """Jupyter: a model being built shows itself drawn (solved when it can be)."""
    from .draw.jupyter import model_svg

    try:
        return model_svg(m.to_model())
    except Exception:            # a half-built model: Jupyter shows its text instead
        return None


def _solve_mechanism(m: Any, symbolic: bool | None = None, **options: Any) -> Solution:
    """`Mechanism.solve`: the mechanism built so far, solved (`options` as `prepare`'s)."""
    return solved(m.to_model(), symbolic, **options)


def _mechanism_assemblies(m: Any) -> list:
    """`Mechanism.assemblies`: every assembly at the drawn input (`kinematika assemblies`)."""
    from .sweep.assemblies import assemblies

    return assemblies(m.to_model())


# the hooks of the lower layers' classes, registered from above
# (each `type: ignore` below: an attribute added to a class of a lower layer, which cannot import
# the drawing and the sweeps; mypy sees the class as defined)
Solution._repr_svg_ = _solution_svg                    # type: ignore[attr-defined]
Mechanism._repr_svg_ = _mechanism_svg                  # type: ignore[attr-defined]
Mechanism.solve = _solve_mechanism                     # type: ignore[attr-defined]
Mechanism.assemblies = _mechanism_assemblies           # type: ignore[attr-defined]
