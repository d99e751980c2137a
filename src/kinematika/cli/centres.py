"""`kinematika centres`: every instant centre of every pair of bodies, and how it is found."""
from __future__ import annotations

import json
from pathlib import Path

from .app import JsonOpt, ModelArg, SymbolicOpt, app, guarded


@app.command()
def centres(model: Path = ModelArg, as_json: bool = JsonOpt, symbolic: bool = SymbolicOpt) -> None:
    """All instant centres (planar), marking those found from joints and by Aronhold–Kennedy."""
    from ..api import solve as solve_model
    from ..report.centres_table import centres_data, print_centres

    data = guarded(as_json, lambda: centres_data(solve_model(model, symbolic or None)))
    if as_json:
        print(json.dumps(data))
    else:
        print_centres(data)
