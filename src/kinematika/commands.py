"""What each command answers, as data or text: one function per command.

The command line prints these and the page's JSON API (`kinematika.web`) answers them, so
that `kinematika solve MODEL --json` and `POST /api/solve` give the same bytes. Every
function takes the model as `api.prepare` does (a path, a text with `fmt`, a tree or a
`Model`) and the same `set`, `move` and `assembly` choices (`How`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping, Optional

from .api import ModelLike, prepare


@dataclass(frozen=True)
class How:
    """The model a command analyses: its text's format and the `--set`, `--move` and
    `--assembly` choices (see `api.prepare`), and for the page a row of its sweep (`row`)."""

    fmt: Optional[str] = None
    set: Mapping[str, Any] = field(default_factory=dict)
    move: Mapping[str, Any] = field(default_factory=dict)
    assembly: Optional[int] = None
    row: Optional[int] = None

    def model(self, source: ModelLike) -> Any:
        """The prepared model `source` with these choices (`api.prepare`: parsed, values set,
        moved, assembly chosen)."""
        return prepare(source, fmt=self.fmt, set=self.set or None, move=self.move or None,
                       assembly=self.assembly, row=self.row)


AS_GIVEN = How()


def json_text(data: Any) -> str:
    """The JSON a command prints with `--json`: one line, then a newline (`report.json_text`)."""
    from .report.json_text import json_bytes

    return json_bytes(data).decode() + "\n"


def solve_data(source: ModelLike, symbolic: Optional[bool] = None, how: How = AS_GIVEN) -> dict:
    """`kinematika solve --json`: the contract's answer."""
    from .api import solve
    from .budget import exact_work
    from .report.json_answer import solution_json

    model = how.model(source)
    with exact_work(model, symbolic):
        return solution_json(solve(model, symbolic))


def centres_data(source: ModelLike, symbolic: Optional[bool] = None, how: How = AS_GIVEN) -> dict:
    """`kinematika centres --json`: every instant centre and how it is found."""
    from .api import solve
    from .budget import exact_work
    from .report.centres_table import centres_data as table

    model = how.model(source)
    with exact_work(model, symbolic):
        return table(solve(model, symbolic))


def sweep_run(source: ModelLike, joint: Optional[str] = None, by: Optional[float] = None,
              steps: Optional[int] = None, skip_bad: bool = False, progress: Any = False,
              how: How = AS_GIVEN) -> tuple[Any, Any]:
    """`kinematika sweep`: the `Sweeper` (for the summary) and its `SweepResult` (whose
    `to_json()` is the contract's answer and `to_csv()` the CSV)."""
    from .sweep.run import Sweeper

    sweeper = Sweeper(how.model(source), joint)
    return sweeper, sweeper.run(by, steps, skip_bad, progress=progress)


def simulate_run(source: ModelLike, time: Optional[float] = None, steps: Optional[int] = None,
                 method: Optional[str] = None, progress: Any = False, how: How = AS_GIVEN,
                 default_time: Optional[float] = None) -> tuple[Any, Any]:
    """`kinematika simulate`: the `Simulator` (for the summary) and its `SimulationResult`
    (whose `to_json()` is the answer); a motion that stops early raises
    `simulate.run.SimulationStopped`, which holds the rows before (`result`)."""
    from .simulate.run import Simulator

    simulator = Simulator(how.model(source), default_time)
    return simulator, simulator.run(time, steps, method, progress)


def assemblies_data(source: ModelLike, how: How = AS_GIVEN) -> dict:
    """`kinematika assemblies --json`: every assembly at the drawn input, numbered, the drawn
    one marked, with how each dyad closes and every material point's place."""
    from .sweep.assemblies import assemblies, assemblies_json

    model = how.model(source)
    return {"name": model.name, **assemblies_json(assemblies(model))}


def explain_text(source: ModelLike, lang: str = "en", fmt: str = "md",
                 symbolic: Optional[bool] = None, length_unit: str = "m",
                 how: How = AS_GIVEN) -> str:
    """`kinematika explain`: the step-by-step solution in `fmt` (md, html, tex)."""
    from .budget import exact_work
    from .explain import explain

    from .draw.lock import MATPLOTLIB

    model = how.model(source)
    with exact_work(model, symbolic), MATPLOTLIB:       # its figures are drawn as it goes
        return explain(model, lang, fmt, symbolic, length_unit)


def draw_scene(source: ModelLike, options: Any = None, how: How = AS_GIVEN) -> Any:
    """The `Scene` that `kinematika draw` paints (the model solved at its instant)."""
    return solved_scene(source, options, how)[1]


def solved_scene(source: ModelLike, options: Any = None, how: How = AS_GIVEN) -> tuple[Any, Any]:
    """The model solved at its instant and the `Scene` drawn from it; a model with symbols
    is solved within the same budget as `solve` (its `limit` error past it)."""
    from .api import solve
    from .budget import exact_work
    from .draw.build import build_scene

    model = how.model(source)
    with exact_work(model):
        sol = solve(model)
        return sol, build_scene(sol.inst, sol, options)
