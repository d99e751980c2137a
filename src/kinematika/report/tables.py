"""Human-readable answers in the terminal (rich tables).

Names and formulas are printed as written: control characters escaped, rich markup not
read (`text.markup`)."""
from __future__ import annotations

from typing import Any

from rich.console import Console
from rich.table import Table

from ..limits import NAME_CHARS
from ..text import markup


def show(value: Any) -> str:
    """A compact text form of a plain answer value."""
    if value is None:
        return "—"
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, list):
        return "(" + ", ".join(show(v) for v in value) + ")"
    if isinstance(value, dict):
        return "  ".join(f"{k}: {show(v)}" for k, v in value.items())
    return str(value)


def ask_text(ask: dict) -> str:
    """A question as one line of text, its key first: ``velocity B@rocker, relative_to crank``."""
    main = next(iter(ask.items()))
    extra = "".join(f", {k} {v}" for k, v in list(ask.items())[1:])
    return f"{main[0]} {main[1]}{extra}"


def print_solution(data: dict, console: Console | None = None) -> None:
    """Bodies, points and the answers to the questions, as tables."""
    console = console or Console()
    mode = "exact formulas" if data["symbolic"] else "numbers"
    console.print(f"[bold]{markup(data['name'], NAME_CHARS)}[/bold]  ({data['dimension']}D, {data['dof']} degree"
                  f"{'s' if data['dof'] != 1 else ''} of freedom, {mode})")
    bodies = Table(title="Bodies (relative to the ground)", title_justify="left")
    for col in ("body", "ω", "α"):
        bodies.add_column(col)
    for name, b in data["bodies"].items():
        bodies.add_row(markup(name), markup(show(b["omega"])), markup(show(b["alpha"])))
    console.print(bodies)
    points = Table(title="Points (relative to the ground)", title_justify="left")
    for col in ("point", "position", "velocity", "acceleration"):
        points.add_column(col)
    for name, p in data["points"].items():
        points.add_row(markup(name), *(markup(show(p[k])) for k in ("position", "velocity", "acceleration")))
    console.print(points)
    answers = Table(title="Answers", title_justify="left")
    answers.add_column("question")
    answers.add_column("answer")
    for entry in data["answers"]:
        answers.add_row(markup(ask_text(entry["ask"])), markup(show(entry["value"])))
    console.print(answers)
    print_where(data, console)


def print_where(data: dict, console: Console) -> None:
    """The named coordinates the formulas use (a symbolic answer's `where`), in order."""
    if not data.get("where"):
        return
    table = Table(title="Where (named coordinates, each in the parameters and the names above it)",
                  title_justify="left")
    table.add_column("name")
    table.add_column("formula")
    for name, formula in data["where"].items():
        table.add_row(markup(name), markup(formula))
    console.print(table)

