"""`kinematika solve`: the instant, as tables or as the contract's JSON."""
from __future__ import annotations

from pathlib import Path

from typing import Optional

from .app import AssemblyOpt, JsonOpt, MessagesOpt, ModelArg, MoveOpt, SetOpt, SymbolicOpt, app, how, messages
from .run import solve_command


@app.command()
def solve(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt,
          sets: Optional[list[str]] = SetOpt, moves: Optional[list[str]] = MoveOpt,
          assembly: Optional[int] = AssemblyOpt, lang: Optional[str] = MessagesOpt) -> None:
    """Velocity and acceleration of every point and body at the instant, and the answers."""
    messages(lang, as_json)
    solve_command(model, as_json, symbolic, lambda: how(sets, moves, assembly))
