"""`kinematika assemblies`: every way the mechanism closes at its drawn input, numbered."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

from .app import JsonOpt, MessagesOpt, ModelArg, SetOpt, app, how, messages, respond


@app.command()
def assemblies(model: Path = ModelArg, as_json: bool = JsonOpt,
               sets: Optional[list[str]] = SetOpt, lang: Optional[str] = MessagesOpt) -> None:
    """Every assembly at the drawn input (both closures of each dyad), numbered; pick one with
    --assembly N on solve, centres, explain, draw, animate and sweep."""
    from ..commands import assemblies_data

    messages(lang, as_json)
    def show(data: dict) -> None:
        from ..report.assemblies_table import print_assemblies

        print_assemblies(data)

    respond(as_json, lambda: assemblies_data(model, how(sets)), show)
