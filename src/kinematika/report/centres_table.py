"""The table of instant centres (`kinematika centres`)."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any

from ..errors import KinematikaError
from ..limits import NAME_CHARS
from ..questions.centres import all_centres
from ..solution import Solution
from ..text import markup
from .json_answer import answer_scales, where
from .values import plain

if TYPE_CHECKING:
    from rich.console import Console

HOW = {"joint": "joint {}", "weld": "weld {} (one body with {})", "kennedy": "Kennedy via {}",
       "lines": "on the lines of {}", "velocities": "from the velocities"}


def centres_data(sol: Solution) -> dict[str, Any]:
    """Every instant centre of the planar mechanism as data for `kinematika centres --json`: per
    pair of bodies the centre (a point, a direction at infinity, or rest), how it was found (at
    a joint, by Kennedy via two third bodies, or from the velocities), and the named quantities
    of a symbolic model. A 3D model is refused: it has screw axes instead."""
    if sol.space.dim != 2:
        raise KinematikaError("schema", "centres-planar", "dimension")
    fields = answer_scales(sol)[1]
    rows = []
    for c in all_centres(sol):
        rows.append({"bodies": list(c.pair), **plain(c.value, sol.symbolic, sol.inst.scale, fields),
                     "how": c.how, "via": c.via})
    out = {"name": sol.model.name, "symbolic": sol.symbolic, "centres": rows}
    named = where(sol) if sol.symbolic else {}
    if named:
        out["where"] = named                    # the named quantities the formulas use
    return out


def print_centres(data: dict[str, Any], console: Console | None = None) -> None:
    """`centres_data` as a terminal table: bodies, centre and how it was found, then the named
    quantities. (rich is imported here: `centres --json` never needs it.)"""
    from rich.console import Console
    from rich.table import Table

    from .tables import print_where, show

    console = console or Console()
    table = Table(title=f"Instant centres — {markup(data['name'], NAME_CHARS)}", title_justify="left")
    for col in ("bodies", "centre", "found"):
        table.add_column(col)
    for row in data["centres"]:
        if row.get("rest"):
            where = "no relative motion"
        elif row.get("point") is None:
            where = f"at infinity, direction {show(row['direction'])}"
        else:
            where = show(row["point"])
        how = HOW[row["how"]].format(*row["via"]) if row["how"] == "weld" else \
            HOW[row["how"]].format(" and ".join(row["via"]))
        table.add_row(markup(" – ".join(row["bodies"])), markup(where), markup(how))
    console.print(table)
    print_where(data, console)
