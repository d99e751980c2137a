"""`kinematika explore`: a design study over the model's parameters, here or on Dask."""
from __future__ import annotations

import sys
from functools import partial
from pathlib import Path
from typing import Optional

import typer

from .app import MessagesOpt, ModelArg, app, guarded, messages, output_file


@app.command()
def explore(model: Path = ModelArg,
            vary: list[str] = typer.Option(..., "--vary", help="NAME=LOW:HIGH, a parameter and its "
                                           "interval (repeat for each parameter)"),
            grid: Optional[int] = typer.Option(None, "--grid", min=1, help="N equally spaced values of "
                                               "each parameter (both ends included)"),
            samples: Optional[int] = typer.Option(None, "--samples", min=1, help="N space-filling "
                                                  "designs (scrambled Sobol')"),
            seed: int = typer.Option(0, "--seed", help="the Sobol' scrambling seed"),
            metric: list[str] = typer.Option([], "--metric", help="a metric per column: grashof, "
                                             "transmission, range:BODY, peak_omega:BODY, ... "
                                             "(see docs/explore.md)"),
            output: Path = typer.Option(..., "-o", "--output", help="the rows: FILE.parquet or FILE.csv"),
            scheduler: Optional[str] = typer.Option(None, "--scheduler", help="run on the Dask cluster "
                                                    "at ADDRESS (default: this machine's cores)"),
            workers: Optional[int] = typer.Option(None, "--workers", min=1, help="local worker "
                                                  "processes (default: one per core; 1: this process)"),
            resume: bool = typer.Option(False, "--resume", help="continue an interrupted study"),
            joint: Optional[str] = typer.Option(None, "--joint", help="the driven joint to sweep"),
            by: Optional[float] = typer.Option(None, "--by", help="how far each design is swept"),
            steps: Optional[int] = typer.Option(None, "--steps", min=1, max=100_000,
                                                help="positions per design"),
            chunk: Optional[int] = typer.Option(None, "--chunk", min=1, help="designs per chunk "
                                                "(written as they finish)"),
            lang: Optional[str] = MessagesOpt,
            ) -> None:
    """Evaluate many designs of MODEL (values of its parameters) and write one row each: the
    parameters, whether it assembles (and why not), and the metrics."""
    messages(lang)
    from ..explore.evaluate import Sweep
    from ..explore.study import Parts, make_study, resume_note, write_study
    from ..sweep.progress import reporter

    def work() -> int:
        study = make_study(model, vary, metric, grid, samples, seed, Sweep(joint, by, steps), chunk)
        output_file(output, "-o")
        bar = reporter(True, study.designs.count, f"exploring {study.designs.count} designs")
        try:
            write_study(study, output, resume, scheduler, workers, bar)
        except KeyboardInterrupt:
            bar(None)
            print(f"stopped{resume_note(Parts(output, study)) or ': nothing was kept'}", file=sys.stderr)
            sys.exit(130)
        finally:
            bar(None)
        return study.designs.count

    count = guarded(False, work)
    print(f"wrote {count} designs to {output}", file=sys.stderr)


@app.command()
def synthesize(model: Path = ModelArg,
               vary: list[str] = typer.Option(..., "--vary", help="NAME=LOW:HIGH, a parameter to "
                                              "choose and its interval (repeat)"),
               target: Optional[Path] = typer.Option(None, "--target", help="path generation: a CSV "
                                                     "of target points x,y for --point"),
               target_function: Optional[str] = typer.Option(None, "--target-function", help="function "
                                                             "generation: a CSV of (input, rotation) "
                                                             "rows, or an expression in x (degrees)"),
               target_motion: Optional[Path] = typer.Option(None, "--target-motion", help="motion "
                                                            "generation: a CSV of poses x,y,angle"),
               point: Optional[str] = typer.Option(None, "--point", help="the point that follows the "
                                                   "path (or the motion)"),
               output_body: Optional[str] = typer.Option(None, "--output", help="the body whose rotation "
                                                         "follows the function"),
               over: str = typer.Option("0:90", "--over", help="the input's range of the function "
                                        "(LOW:HIGH, degrees from the input's zero)"),
               points: int = typer.Option(7, "--points", min=2, help="precision points of the "
                                          "function (Chebyshev spacing)"),
               timing: Optional[str] = typer.Option(None, "--timing", help="JOINT[=START]: the targets' "
                                                    "input column is the joint's travel from the first "
                                                    "target, met START from the drawn configuration "
                                                    "(free without =START)"),
               objective: str = typer.Option("max", "--objective", help="sse (the sum of the squared "
                                             "errors) or max (the largest error)"),
               require: list[str] = typer.Option([], "--require", help="crank-rocker, ordered or "
                                                 "transmission=DEG (repeat)"),
               output_zero: Optional[str] = typer.Option(None, "--output-zero", help="function "
                                                         "generation: the output's zero, 'free' or "
                                                         "its line's absolute angle (degrees); default "
                                                         "its drawn position"),
               seconds: Optional[float] = typer.Option(None, "--seconds", min=0.0, help="stop after S "
                                                       "seconds of wall time and write what was found"),
               population: int = typer.Option(40, "--population", min=4, help="designs per generation"),
               generations: Optional[int] = typer.Option(None, "--generations", min=1, help="at most this "
                                                         "many in all (default 200, or no limit with "
                                                         "--seconds)"),
               seed: int = typer.Option(0, "--seed", help="the optimiser's seed"),
               best: int = typer.Option(3, "--best", min=1, help="how many distinct designs to keep"),
               out: Path = typer.Option(..., "-o", "--output-dir", help="folder for the best designs' "
                                        "model files and designs.csv"),
               plot: Optional[Path] = typer.Option(None, "--plot", help="draw the best designs over "
                                                   "the targets to FILE"),
               steps: Optional[int] = typer.Option(None, "--steps", min=1, max=100_000,
                                                   help="positions per design (models other than a "
                                                   "four-bar)"),
               lang: Optional[str] = MessagesOpt,
               ) -> None:
    """Choose parameter values so that a point follows target points (path generation), a body's
    rotation follows a function of the input's (function generation) or a body passes through
    poses (motion generation); write the best designs as model files."""
    messages(lang)
    from ..explore.synthesis import synthesize as run, write_designs

    def work():
        task = _task(model, target, target_function, target_motion, point, output_body, over, points, timing,
                     objective, require, output_zero)
        result = run(model, vary, task, population, generations, seed, best, seconds, steps)
        written = write_designs(model, result, out)
        if plot is not None:
            _plot_synthesis(model, result, task, output_file(plot, "--plot"))
        return result, written

    result, written = guarded(False, work)
    for i, (path, design, error) in enumerate(zip(written, result.designs, result.errors)):
        values = ", ".join(f"{k} = {v:.6g}" for k, v in design.items())
        extra = "".join(f"; {name} = {v[i]:.6g}" for name, v in (("start", result.starts),
                                                                  ("output zero", result.zeros))
                        if v and v[i] is not None)
        print(f"{path}: {values}{extra}; {result.objective} = {error:.6g}")
    print(f"({result.evaluated} designs evaluated)")


def _task(model: Path, target, function, motion, point, body, over, points, timing, objective, require,
          output_zero):
    """The task as posed on the command line (`explore.synthesis.task`)."""
    from ..errors import KinematikaError
    from ..explore.synthesis.task import (make_task, parse_objective, parse_output_zero, parse_requirements,
                                          parse_timing)

    given = [x for x in (target, function, motion) if x is not None]
    if len(given) != 1:
        raise KinematikaError("usage", "synthesis-one-target", "--target")
    posed = partial(make_task, objective=parse_objective(objective), timing=parse_timing(timing),
                    requires=parse_requirements(list(require)))
    if function is not None:
        if not body:
            raise KinematikaError("usage", "function-needs-output", "--output")
        zero = parse_output_zero(output_zero)
        if function.lower().endswith(".csv"):
            path = Path(function)
            return posed("function", path.name, _target_text(path, "--target-function"), "--target-function",
                         body=body, output_zero=zero)
        from ..explore.designs import parse_vary
        from ..explore.synthesis import function_targets

        span = parse_vary(f"x={over}")
        return posed("function", "function.csv", function_targets(function, (span.low, span.high), points),
                     "--target-function", body=body, output_zero=zero)
    if output_zero is not None:
        raise KinematikaError("usage", "output-zero-function-only", "--output-zero")
    if not point:
        raise KinematikaError("usage", "path-needs-point", "--point")
    kind, path, option = ("path", target, "--target") if target is not None else ("motion", motion, "--target-motion")
    return posed(kind, path.name, _target_text(path, option), option, point=point)


def _target_text(path: Path, option: str) -> str:
    """A target file named on the command line (relative to the working folder), as text."""
    from ..errors import KinematikaError, reason

    if path.suffix.lower() != ".csv":
        raise KinematikaError("usage", "target-csv", option, name=path.name)
    try:
        return path.read_text(encoding="utf-8")
    except OSError as err:
        raise KinematikaError("usage", "cannot-read", option, path=str(path), reason=reason(err)) from None
    except UnicodeDecodeError:
        raise KinematikaError("usage", "csv-not-utf8", option, name=str(path)) from None


def _plot_synthesis(model: Path, result, task, plot: Path) -> None:
    """Path and motion generation: the paths over the targets; function: rotation over targets."""
    import numpy as np

    from ..api import as_model
    from ..explore.plots import function_over_targets, paths_over_targets

    labels = [f"{i + 1}: {result.objective} = {e:.3g}" for i, e in enumerate(result.errors)]
    m = as_model(model)
    if task.kind == "function":
        function_over_targets(m, result.designs, task.body, np.column_stack([task.inputs, task.angle]), plot,
                              labels)
    else:
        paths_over_targets(m, result.designs, task.point, task.xy, plot, labels)


@app.command("plot-study")
def plot_study(study: Path = typer.Argument(..., help="a study's rows (.parquet or .csv)"),
               map_: Optional[str] = typer.Option(None, "--map", help="X,Y,METRIC: the metric over two "
                                                  "parameters"),
               pareto: Optional[str] = typer.Option(None, "--pareto", help="M1,M2: two metrics and "
                                                    "their Pareto front (both lower is better)"),
               maximize: list[str] = typer.Option([], "--maximize", help="a metric of --pareto for "
                                                  "which higher is better"),
               output: Path = typer.Option(..., "-o", help="the figure (.png, .svg, .pdf)"),
               lang: Optional[str] = MessagesOpt,
               ) -> None:
    """Draw a study: a metric's map over two parameters, or two metrics and their Pareto front."""
    messages(lang)
    from ..errors import KinematikaError

    def work() -> str:
        from ..explore import plots

        table = _read_study(study)
        out = output_file(output, "-o")
        if map_ is not None and pareto is None:
            x, y, metric = _split(map_, 3, "--map")
            plots.metric_map(table, x, y, metric, out)
            return f"drew {metric} over {x} and {y} to {out}"
        if pareto is not None and map_ is None:
            first, second = _split(pareto, 2, "--pareto")
            front = plots.pareto(table, first, second, out, maximize)
            return f"drew {len(front)} designs on the Pareto front to {out}"
        raise KinematikaError("usage", "map-or-pareto", "--map")

    print(guarded(False, work))


def _split(text: str, count: int, option: str) -> list[str]:
    from ..errors import KinematikaError

    names = [n.strip() for n in _split_names(text)]
    if len(names) != count or not all(names):
        raise KinematikaError("usage", "option-names-count", option, option=option, count=count)
    return names


def _split_names(text: str) -> list[str]:
    """Split on commas outside a metric's argument (`path_error:P=a,b.csv` keeps its file)."""
    return text.split(",")


def _read_study(path: Path):
    from ..errors import KinematikaError, said_of
    from ..extras import need

    need("pyarrow", "plot-study")
    need("pandas", "plot-study")
    try:
        if path.suffix.lower() == ".csv":
            import pandas as pd

            return pd.read_csv(path, keep_default_na=True)
        import pyarrow.parquet as pq

        return pq.read_table(path).to_pandas()
    except (OSError, ValueError) as err:
        raise KinematikaError("usage", "study-unreadable", str(path), path=str(path), reason=said_of(err)) from None
