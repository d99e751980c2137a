"""`kinematika solve`: the instant, as tables or as the contract's JSON."""
from __future__ import annotations

from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app, respond


@app.command()
def solve(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """Velocity and acceleration of every point and body at the instant, and the answers."""
    from ..commands import solve_data

    def show(data: dict) -> None:
        from ..report.tables import print_solution

        print_solution(data)

    respond(as_json, lambda: solve_data(model, symbolic or None), show)
