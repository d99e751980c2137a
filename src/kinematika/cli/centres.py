"""`kinematika centres`: every instant centre of every pair of bodies, and how it is found."""
from __future__ import annotations

from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app, respond


@app.command()
def centres(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """All instant centres (planar), marking those found from joints and by Aronhold–Kennedy."""
    from ..commands import centres_data
    from ..report.centres_table import print_centres

    respond(as_json, lambda: centres_data(model, symbolic or None), print_centres)
