"""`kinematika centres`: every instant centre of every pair of bodies, and how it is found."""
from __future__ import annotations

from pathlib import Path

from typing import Optional

from .app import AssemblyOpt, JsonOpt, MessagesOpt, ModelArg, MoveOpt, SetOpt, SymbolicOpt, app, how, messages
from .run import centres_command


@app.command()
def centres(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt,
          sets: Optional[list[str]] = SetOpt, moves: Optional[list[str]] = MoveOpt,
          assembly: Optional[int] = AssemblyOpt, lang: Optional[str] = MessagesOpt) -> None:
    """All instant centres (planar), marking those found from joints and by Aronhold–Kennedy."""
    messages(lang, as_json)
    centres_command(model, as_json, symbolic, lambda: how(sets, moves, assembly))
