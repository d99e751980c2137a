"""Human-readable answers in the terminal (rich tables).

Names and formulas are printed as written: control characters escaped, rich markup not
read (`text.markup`)."""
from __future__ import annotations

from typing import Any, Optional

from rich.console import Console
from rich.table import Table

from ..limits import NAME_CHARS
from ..text import markup
from .units import answer_kind, field_kind, unit


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


def print_solution(data: dict, console: Console | None = None, length: str = "m") -> None:
    """Bodies, points and the answers to the questions, as tables, each quantity with its
    unit (`units`: from the model's length unit `length`)."""
    console = console or Console()
    mode = "exact formulas" if data["symbolic"] else "numbers"
    console.print(f"[bold]{markup(data['name'], NAME_CHARS)}[/bold]  ({data['dimension']}D, {data['dof']} degree"
                  f"{'s' if data['dof'] != 1 else ''} of freedom, {mode})")
    bodies = Table(title="Bodies (relative to the ground)", title_justify="left")
    for col in ("body", f"ω ({unit('omega')})", f"α ({unit('alpha')})"):
        bodies.add_column(markup(col))
    for name, b in data["bodies"].items():
        bodies.add_row(markup(name), markup(show(b["omega"])), markup(show(b["alpha"])))
    console.print(bodies)
    points = Table(title="Points (relative to the ground)", title_justify="left")
    points.add_column("point")
    for col in ("position", "velocity", "acceleration"):
        points.add_column(markup(f"{col} ({unit(col, length)})"))
    for name, p in data["points"].items():
        points.add_row(markup(name), *(markup(show(p[k])) for k in ("position", "velocity", "acceleration")))
    console.print(points)
    answers = Table(title="Answers", title_justify="left")
    answers.add_column("question")
    answers.add_column("answer")
    for entry in data["answers"]:
        kind = next(k for k in entry["ask"] if k not in ("relative_to", "moving"))
        answers.add_row(markup(ask_text(entry["ask"])), markup(with_units(entry["value"], answer_kind(kind), length)))
    console.print(answers)
    print_where(data, console)


def with_units(value: Any, kind: Optional[str], length: str = "m") -> str:
    """An answer's value as text with its unit: `(-0.386, 0) m/s`; each field of a compound
    answer with its own (`radius: 0.2 m  center: (0.1, 0.3) m`)."""
    if isinstance(value, dict):
        return "  ".join(f"{k}: {with_units(v, field_kind(k, kind), length)}" for k, v in value.items())
    text = show(value)
    u = unit(kind, length) if value is not None and not isinstance(value, bool) else ""
    return f"{text} {u}" if u else text


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

