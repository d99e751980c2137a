"""`kinematika solve`: the instant, as tables or as the contract's JSON."""
from __future__ import annotations

from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app, respond


@app.command()
def solve(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """Velocity and acceleration of every point and body at the instant, and the answers."""
    from ..api import solve as solve_model
    from ..report.json_answer import solution_json

    def show(data: dict) -> None:
        from ..report.tables import print_solution

        print_solution(data)

    respond(as_json, lambda: solution_json(solve_model(model, symbolic or None)), show)
