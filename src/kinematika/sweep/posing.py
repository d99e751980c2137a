"""The model a command analyses, posed as asked: parameters given values (`set`), the
assembly chosen (`assembly`), driven joints advanced (`move`, the file's own `move:` section
first) — and that model solved (`solved`) or swept (`run_sweep`). Posing moves the mechanism as a sweep does, so it lives in
the sweep layer; every view (the command line, Python, the page, explanations, figures)
comes here through `kinematika.api`."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Mapping, Optional

from ..engine.terms import MECHANICS, Terms
from ..model.model import Model
from ..model.overrides import with_parameters
from ..model.source import ModelLike, as_model
from ..solution import Solution, solve_model

if TYPE_CHECKING:
    from .result import SweepResult


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


def solved(source: ModelLike, symbolic: bool | None = None, terms: Terms = MECHANICS,
           **options: Any) -> Solution:
    """`source` prepared (`options` as `prepare`'s) and solved: numerically, or exactly when
    it has symbols (or `symbolic`); with `terms`, as a student with that mistake would
    (`engine.terms`)."""
    return solve_model(prepare(source, **options), symbolic, terms)


def run_sweep(source: Any, joint: Optional[str] = None, by: Optional[float] = None,
              steps: Optional[int] = None, skip_bad: bool = False,
              progress: bool | Callable[[int, int], None] = False) -> SweepResult:
    """Sweep `source` (a path, model tree, `Model` or `Mechanism`) over its driven joint.

    `joint`, `by` (degrees or length), `steps` override the model's `sweep:` section. At a
    limit position the input runs back and the motion goes on (`limit_positions`). A row
    that is singular, or a motion that cannot be followed, raises `singular`/`assembly`,
    unless `skip_bad`, which leaves such rows NaN. `progress`: True for a progress bar on a
    terminal, or a callable `(done, total)`. The model is read and posed where its file says
    (`prepare`: its `move:`), then swept (`run.Sweeper`).
    """
    from .run import Sweeper        # start-up: posing a model for one instant loads no sweep

    return Sweeper(prepare(source), joint).run(by, steps, skip_bad, progress)
