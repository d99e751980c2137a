"""`kinematika draw` and `kinematika animate`: the mechanism as a figure, and in motion."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from ..text import shown
from .app import AssemblyOpt, ModelArg, MoveOpt, SetOpt, app, how
from .shared import guarded, options_named, output_file, sweep_options, writing

VIEWS = ("iso", "top", "front", "side")


def _names(values: Optional[list[str]]) -> Optional[list[str]]:
    """Repeated and comma-separated names as one list (`--points A,B --points C`)."""
    if not values:
        return None
    return [n.strip() for v in values for n in v.split(",") if n.strip()]


def _check_output(output: Path, formats: tuple[str, ...]) -> None:
    if output.suffix.lower().lstrip(".") not in formats:
        raise typer.BadParameter(f"{output.name!r}: give a file ending in "
                                 f"{', '.join('.' + f for f in formats)}", param_hint="'-o'")


def _model(model: Path, sets: Optional[list[str]], moves: Optional[list[str]], assembly: Optional[int]):
    """The model with `--set`, `--assembly` and `--move` applied."""
    return how(sets, moves, assembly).model(model)


OutputOpt = typer.Option(..., "-o", "--output", help="the file to write", show_default=False)
WidthOpt = typer.Option(8.0, "--width", min=1.0, max=100.0, help="figure width in inches")
LangOpt = typer.Option(None, "--lang", help="numbers as an explanation in en, es, ca or eu writes "
                       "them (2,5 and −0,3 in es; default: 2.5 and -0.3)")


@app.command()
def draw(
    model: Path = ModelArg,
    output: Path = OutputOpt,
    velocities: Optional[bool] = typer.Option(
        None, "--velocities/--no-velocities",
        help="velocity arrows at every shown point / none (default: the asked velocities)"),
    accelerations: Optional[bool] = typer.Option(
        None, "--accelerations/--no-accelerations",
        help="acceleration arrows at every shown point / none (default: the asked ones)"),
    centres: Optional[bool] = typer.Option(
        None, "--centres/--no-centres",
        help="every instant centre with its Aronhold-Kennedy lines / none (default: asked icr)"),
    curvature: Optional[bool] = typer.Option(
        None, "--curvature/--no-curvature", help="the asked curvature circles (default) / none"),
    labels: bool = typer.Option(True, "--labels/--no-labels", help="names and magnitudes"),
    points: Optional[list[str]] = typer.Option(
        None, "--points", help="the points to draw vectors at (comma-separated, repeatable)"),
    view: str = typer.Option("iso", "--view", help="3D projection: iso, top, front or side"),
    assignments: Optional[list[str]] = SetOpt,
    moves: Optional[list[str]] = MoveOpt,
    assembly: Optional[int] = AssemblyOpt,
    width: float = WidthOpt,
    lang: Optional[str] = LangOpt,
) -> None:
    """The mechanism at its instant, with vectors, instant centres and curvature (PNG, SVG, PDF)."""
    from ..draw.figure import FORMATS

    _check_output(output, FORMATS)
    if view not in VIEWS:
        raise typer.BadParameter(f"{view!r}: choose one of {', '.join(VIEWS)}", param_hint="'--view'")

    def work() -> Path:
        from ..draw import DrawOptions, draw as draw_figure

        options = DrawOptions(velocities=velocities, accelerations=accelerations, centres=centres,
                              curvature=curvature, labels=labels, points=_names(points), view=view,
                              width=width, lang=lang)
        from ..budget import exact_work

        target = output_file(output, "-o")
        given = _model(model, assignments, moves, assembly)
        with writing(target, "-o"), exact_work(given):     # symbols: solve's budget
            draw_figure(given, target, options)
        return output

    guarded(False, work)
    print(f"wrote {shown(output)}")


@app.command()
def animate(
    model: Path = ModelArg,
    output: Path = OutputOpt,
    joint: Optional[str] = typer.Option(None, "--joint", help="the driven joint to sweep"),
    by: Optional[float] = typer.Option(None, "--by", help="its advance: degrees or length"),
    steps: Optional[int] = typer.Option(None, "--steps", min=1, max=100_000, help="positions computed"),
    frames: int = typer.Option(120, "--frames", min=2, max=10_000, help="at most this many frames"),
    fps: int = typer.Option(20, "--fps", min=1, max=120, help="frames per second"),
    velocities: Optional[bool] = typer.Option(
        None, "--velocities/--no-velocities", help="live velocity arrows (default: the asked ones)"),
    accelerations: Optional[bool] = typer.Option(
        None, "--accelerations/--no-accelerations", help="live acceleration arrows"),
    trace: Optional[list[str]] = typer.Option(
        None, "--trace", help="points whose paths are traced (default: the asked points)"),
    skip_bad: bool = typer.Option(False, "--skip-bad", help="skip positions that cannot be assembled"),
    assignments: Optional[list[str]] = SetOpt,
    moves: Optional[list[str]] = MoveOpt,
    assembly: Optional[int] = AssemblyOpt,
    width: float = typer.Option(8.0, "--width", min=1.0, max=50.0,
                                help="frame width in inches (100 pixels an inch)"),
    lang: Optional[str] = LangOpt,
) -> None:
    """The motion over the sweep (GIF, or MP4 with ffmpeg), with traced paths and live vectors."""
    from ..draw.animation import FORMATS

    _check_output(output, FORMATS)

    def work() -> Path:
        from ..draw import DrawOptions
        from ..draw.animation import animate as render

        options = DrawOptions(velocities=velocities, accelerations=accelerations, width=width,
                              lang=lang)
        target = output_file(output, "-o")
        with writing(target, "-o"), options_named(sweep_options(joint, by, steps)):
            return render(_model(model, assignments, moves, assembly), target, joint=joint, by=by,
                          steps=steps, frames=frames, fps=fps, options=options, trace=_names(trace),
                          skip_bad=skip_bad, progress=True)

    guarded(False, work)
    print(f"wrote {shown(output)}")
