"""`kinematika solve`: the instant, as tables or as the contract's JSON."""
from __future__ import annotations

import json
from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app, guarded


@app.command()
def solve(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """Velocity and acceleration of every point and body at the instant, and the answers."""
    from ..api import solve as solve_model
    from ..report.json_answer import solution_json

    data = guarded(as_json, lambda: solution_json(solve_model(model, symbolic or None)))
    if as_json:
        print(json.dumps(data))
    else:
        from ..report.tables import print_solution

        print_solution(data)
