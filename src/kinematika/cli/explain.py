"""`kinematika explain`: the step-by-step solution in the notes' method, in four languages."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from .app import AssemblyOpt, ModelArg, MoveOpt, SetOpt, SymbolicOpt, app, how
from .shared import guarded, output_file, writing

LangOpt = typer.Option("en", "--lang", help="language: en, es, ca or eu")
FormatOpt = typer.Option("md", "--format", help="md, html (one self-contained page) or tex")
OutOpt = typer.Option(None, "-o", "--output", help="write to FILE instead of standard output (Markdown: each "
                      "figure as an SVG file beside it, FILE's name.fig-1.svg …)")
UnitOpt = typer.Option("m", "--length-unit", help="the name of the model's length unit")


@app.command()
def explain(model: Path = ModelArg, lang: str = LangOpt, fmt: str = FormatOpt,
            output: Optional[Path] = OutOpt, symbolic: bool = SymbolicOpt,
            length_unit: str = UnitOpt, sets: Optional[list[str]] = SetOpt,
            moves: Optional[list[str]] = MoveOpt, assembly: Optional[int] = AssemblyOpt) -> None:
    """Step-by-step solution: structure, vector equations with M/D/?, polygons, centres."""
    from ..languages import known

    guarded(False, lambda: known(lang, "--lang", "usage"))      # before the explanation's imports (2 s)
    from ..commands import explain_text

    text = guarded(False, lambda: explain_text(model, lang, fmt, symbolic or None, length_unit,
                                                     how(sets, moves, assembly)))
    if output is None:
        typer.echo(text, nl=False)
        return

    def write_file() -> None:
        target = output_file(output, "-o")
        page, files = text, dict[str, str]()
        if fmt == "md":                 # the figures as SVG files beside the page, linked by name
            from ..explain.render.markdown import figure_files
            page, files = figure_files(text, target)
        with writing(target, "-o"):
            for name, drawing in files.items():
                (target.parent / name).write_text(drawing, encoding="utf-8")
            target.write_text(page, encoding="utf-8")

    guarded(False, write_file)
