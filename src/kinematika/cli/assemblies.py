"""`kinematika assemblies`: every way the mechanism closes at its drawn input, numbered."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

from .app import JsonOpt, ModelArg, SetOpt, app, posed, respond


@app.command()
def assemblies(model: Path = ModelArg, as_json: bool = JsonOpt,
               sets: Optional[list[str]] = SetOpt) -> None:
    """Every assembly at the drawn input (both closures of each dyad), numbered; pick one with
    --assembly N on solve, centres, explain, draw, animate and sweep."""
    from ..sweep.assemblies import assemblies as find, assemblies_json

    def show(data: dict) -> None:
        from ..report.assemblies_table import print_assemblies

        print_assemblies(data)

    respond(as_json, lambda: {"name": posed(model, sets).name,
                              **assemblies_json(find(posed(model, sets)))}, show)
