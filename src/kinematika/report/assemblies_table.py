"""The assemblies of a mechanism as a table: number, whether drawn, how each dyad closes."""
from __future__ import annotations

from rich.console import Console
from rich.table import Table

from ..text import shown


def print_assemblies(data: dict) -> None:
    """Print `assemblies --json` data for a person (names shown as written: escaped, never
    read as rich markup or terminal codes)."""
    found = data["assemblies"]
    table = Table(title=f"Assemblies — {shown(data.get('name', ''))}", title_justify="left")
    table.add_column("N", justify="right")
    table.add_column("drawn")
    table.add_column("closures")
    for a in found:
        table.add_row(str(a["number"]), "← drawn" if a["drawn"] else "", shown("; ".join(a["closures"])) or "—")
    console = Console(highlight=False, markup=False)
    console.print(table, markup=False)
    count = len(found)
    console.print(f"{count} assembl{'y' if count == 1 else 'ies'} at the drawn input; analyse one "
                  "with --assembly N", markup=False)
