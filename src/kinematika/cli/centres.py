"""`kinematika centres`: every instant centre of every pair of bodies, and how it is found."""
from __future__ import annotations

from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app
from .run import centres_command


@app.command()
def centres(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """All instant centres (planar), marking those found from joints and by Aronhold–Kennedy."""
    centres_command(model, as_json, symbolic)
