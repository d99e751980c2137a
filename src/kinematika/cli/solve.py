"""`kinematika solve`: the instant, as tables or as the contract's JSON."""
from __future__ import annotations

from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app
from .run import solve_command


@app.command()
def solve(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """Velocity and acceleration of every point and body at the instant, and the answers."""
    solve_command(model, as_json, symbolic)
