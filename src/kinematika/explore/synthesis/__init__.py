"""Synthesis: the designs that best meet a task — path, function and motion generation.

`synthesize(model, vary, task, ...)` chooses values of the varied parameters (within their
intervals) so that the model meets the task (`task.Task`: targets, timing, objective,
requirements). One command, two paths behind it:

- **the four-bar** (`problem`, `search`, `polish`, `exact`): a model whose moving loop is a
  crank and an RRR dyad, the task's point on the coupler (or its output the rocker or the
  coupler), is scored in closed form — exact starts where they exist (Freudenstein's
  three points, Burmester's three, four and five poses), differential evolution over
  whole generations, restarted, each run's best polished by least squares with the
  analytic Jacobian; feasibility decided exactly;
- **any other model** (`general`): the same objectives on the batch sweep's rows.

The designs written are scored again from the model's own constructions, and each must
pass a full turn of the contract's sweep (3600 steps): a design that breaks a requirement,
or that the sweep cannot follow, is never written. `write_designs` writes them as
`best-N.yaml` (the model with the values as numbers) and `designs.csv`.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Optional

import numpy as np

from ...joints.capabilities import Coordinate
from ...errors import KinematikaError, Names, Said
from ..designs import Vary, parse_vary
from .general import function_targets
from .task import Task

__all__ = ["Synthesis", "function_targets", "synthesize", "write_designs"]

CHECK_STEPS = 3600      # the full turn every written design must pass


@dataclass
class Synthesis:
    """The result: the best designs (parameter values and objective, best first), the task's
    free timing and output zero per design (None when given), how many designs were
    evaluated, and how the best improved ((seconds, objective) pairs)."""

    names: list[str]
    designs: list[dict[str, float]]
    errors: list[float]
    evaluated: int
    objective: str
    history: list[tuple[float, float]] = field(default_factory=list)
    starts: list[Optional[float]] = field(default_factory=list)       # START (degrees) when free
    zeros: list[Optional[float]] = field(default_factory=list)        # the output's zero (degrees) when free
    path: str = "four-bar"                                             # which path found them


def synthesize(model: Any, vary: list[Vary | str], task: Task, population: int = 40,
               generations: Optional[int] = 200, seed: int = 0, best: int = 3,
               seconds: Optional[float] = None, steps: Optional[int] = None,
               progress: Optional[Callable[[float], None]] = None) -> Synthesis:
    """The best `best` distinct designs of `model` for `task`, the parameters `vary` chosen
    within their intervals; the search runs `generations` generations of `population`
    designs in all, or until `seconds` of wall time (the first to come), from `seed`."""
    from ...model.source import as_model
    from ..evaluate import _check_parameters

    m = as_model(model)
    varied = [v if isinstance(v, Vary) else parse_vary(v) for v in vary]
    if not varied:
        raise KinematikaError("usage", "vary-none", "--vary")
    names = [v.name for v in varied]
    if len(set(names)) != len(names):
        raise KinematikaError("usage", "varied-twice", "--vary", names=names)
    _check_parameters(m, names)
    _check_timing(m, task)
    from .fast import fast_task

    fbt = fast_task(m, task, varied)
    if fbt is None:
        from .general import synthesize_general

        result = synthesize_general(m, varied, task, population, generations, seed, 4 * best, seconds, steps)
        return _followed(m, result, best)
    return _four_bar(m, fbt, varied, population, generations, seed, best, seconds, progress)


def _followed(m, result: Synthesis, best: int) -> Synthesis:
    """The designs (best first) the contract's sweep follows over a full turn, when the input
    turns (a slider's input has no turn to check)."""
    from ...sweep.plan import swept_joint

    joint, _ = swept_joint(m, m.sweep.joint if m.sweep else None)
    keep = [i for i, d in enumerate(result.designs)
            if joint.kind.coordinate is not Coordinate.ANGLE or follows_a_turn(m, d, joint.id)][:best]
    if not keep:
        raise KinematikaError("assembly", "synthesis-no-full-turn", "--vary")
    result.designs = [result.designs[i] for i in keep]
    result.errors = [result.errors[i] for i in keep]
    result.starts = [None] * len(keep)
    result.zeros = [None] * len(keep)
    return result


def _check_timing(model, task: Task) -> None:
    """`--timing JOINT` names a driven joint."""
    if task.timing is None:
        return
    from ...sweep.plan import swept_joint

    try:
        swept_joint(model, task.timing.joint)
    except KinematikaError as err:
        raise KinematikaError("usage", err.said, "--timing") from None


def _four_bar(m, fbt, varied: list[Vary], population: int, generations: Optional[int], seed: int, best: int,
              seconds: Optional[float], progress) -> Synthesis:
    from .exact import starts
    from .search import Budget, run

    budget = Budget(generations if generations is not None or seconds is not None else 200, seconds, population)
    archive = run(fbt, budget, seed, starts(fbt), progress)
    names = [v.name for v in varied]
    chosen = []
    for found in archive.best(4 * best, exact=True):
        values = {n: float(found.z[i]) for i, n in enumerate(names)}
        if follows_a_turn(m, values, fbt.roles.joint):
            chosen.append(found)
        if len(chosen) == best:
            break
    if not chosen:
        raise KinematikaError("usage", _nothing_found(fbt.task), "--vary")
    scores = fbt.evaluate(np.array([f.z for f in chosen]), exact=True)
    return Synthesis(names, [{n: float(f.z[i]) for i, n in enumerate(names)} for f in chosen],
                     [float(f.objective) for f in chosen], budget.evaluated, fbt.task.label, archive.history,
                     [float(s) for s in scores.start] if fbt.free_start else [None] * len(chosen),
                     [float(np.degrees(z)) for z in scores.zero] if fbt.free_zero else [None] * len(chosen))


def _nothing_found(task: Task) -> Said:
    """No design of the box assembles at every target (and meets the task's requirements)."""
    why = task.requires.names()
    return Said("synthesis-nothing-found", count=len(why), requirements=Names(why, None))


def follows_a_turn(model, values: dict[str, float], joint: Optional[str]) -> bool:
    """Whether the contract's sweep follows the design over a full turn of its input in
    CHECK_STEPS steps (the check every written design passes)."""
    from ...model.overrides import with_parameters
    from ...sweep.posing import run_sweep

    try:
        run_sweep(with_parameters(model, {k: repr(v) for k, v in values.items()}), joint, 360.0, CHECK_STEPS)
    except KinematikaError:
        return False
    return True


def write_designs(model: Path, result: Synthesis, folder: Path) -> list[Path]:
    """Each design as a model file (the model with its parameters set, as numbers):
    best-1.yaml, …, and `designs.csv`, one row per file with its parameters, the free timing
    and output zero when the task left them free, and its objective."""
    import csv

    import yaml

    from ...model.files import parse_text

    fmt = {".toml": "toml", ".json": "json"}.get(model.suffix.lower(), "yaml")
    tree = parse_text(model.read_text(encoding="utf-8"), fmt, str(model))
    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for rank, (design, error) in enumerate(zip(result.designs, result.errors), start=1):
        copy = dict(tree)
        copy["parameters"] = {**tree.get("parameters", {}), **{k: float(v) for k, v in design.items()}}
        copy["name"] = f"{tree.get('name', model.stem)} — synthesized {rank} ({result.objective} = {error:.6g})"
        path = folder / f"best-{rank}.yaml"
        path.write_text(yaml.safe_dump(copy, sort_keys=False, allow_unicode=True), encoding="utf-8")
        out.append(path)
    extra = [("start", result.starts), ("output_zero", result.zeros)]
    extra = [(k, v) for k, v in extra if any(x is not None for x in v)]
    with open(folder / "designs.csv", "w", newline="", encoding="utf-8") as f:
        writer = csv.writer(f)
        writer.writerow(["design", *result.names, *(k for k, _ in extra), result.objective])
        for i, (path, design, error) in enumerate(zip(out, result.designs, result.errors)):
            writer.writerow([path.name, *(repr(design[n]) for n in result.names),
                             *(repr(v[i]) for _, v in extra), repr(error)])
    return out
