"""`kinematika explore`: a design study over the model's parameters, here or on Dask."""
from __future__ import annotations

import sys
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
                                        "(LOW:HIGH, degrees from the drawn position)"),
               points: int = typer.Option(7, "--points", min=2, help="precision points of the "
                                          "function (Chebyshev spacing)"),
               population: int = typer.Option(40, "--population", min=4, help="designs per generation"),
               generations: int = typer.Option(200, "--generations", min=1, help="at most this many"),
               seed: int = typer.Option(0, "--seed", help="the optimiser's seed"),
               best: int = typer.Option(3, "--best", min=1, help="how many distinct designs to keep"),
               out: Path = typer.Option(..., "-o", "--output-dir", help="folder for the best designs' "
                                        "model files"),
               plot: Optional[Path] = typer.Option(None, "--plot", help="draw the best designs over "
                                                   "the targets to FILE"),
               steps: Optional[int] = typer.Option(None, "--steps", min=1, max=100_000,
                                                   help="positions per design"),
               lang: Optional[str] = MessagesOpt,
               ) -> None:
    """Choose parameter values so that a point follows target points (path generation), a body's
    rotation follows a function of the input's (function generation) or a body passes through
    poses (motion generation); write the best designs as model files."""
    messages(lang)
    from ..explore.evaluate import Sweep
    from ..explore.synthesis import synthesize as run, write_designs

    def work():
        objective, files = _objective(model, target, target_function, target_motion, point, output_body,
                                      over, points)
        result = run(model, vary, objective, population, generations, seed, best, Sweep(steps=steps),
                     files=files)
        if not result.designs:
            from ..errors import KinematikaError

            raise KinematikaError("assembly", "synthesis-no-design", "--vary")
        written = write_designs(model, result, out)
        if plot is not None:
            _plot_synthesis(model, result, point, output_file(plot, "--plot"), files, objective)
        return result, written

    result, written = guarded(False, work)
    for path, design, error in zip(written, result.designs, result.errors):
        values = ", ".join(f"{k} = {v:.6g}" for k, v in design.items())
        print(f"{path}: {values}; {result.objective} = {error:.6g}")
    print(f"({result.evaluated} designs evaluated)")


def _objective(model: Path, target, function, motion, point, body, over, points) -> tuple[str, dict]:
    """The metric to minimise and the target files' text."""
    from ..errors import KinematikaError

    given = [x for x in (target, function, motion) if x is not None]
    if len(given) != 1:
        raise KinematikaError("usage", "synthesis-one-target", "--target")
    if function is not None:
        if not body:
            raise KinematikaError("usage", "function-needs-output", "--output")
        if function.lower().endswith(".csv"):
            name = Path(function).name
            return f"structural_error:{body}={name}", {name: _target_text(Path(function), "--target-function")}
        from ..explore.designs import parse_vary
        from ..explore.synthesis import function_targets

        span = parse_vary(f"x={over}")
        return f"structural_error:{body}=function.csv", {
            "function.csv": function_targets(function, (span.low, span.high), points)}
    if not point:
        raise KinematikaError("usage", "path-needs-point", "--point")
    kind = "path_error" if target is not None else "motion_error"
    path = target if target is not None else motion
    option = "--target" if target is not None else "--target-motion"
    return f"{kind}:{point}={path.name}", {path.name: _target_text(path, option)}


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


def _plot_synthesis(model: Path, result, point, plot: Path, files: dict, objective: str) -> None:
    """Path and motion generation: the paths over the targets; function: rotation over targets."""
    from ..api import as_model
    from ..explore.metrics import read_table
    from ..explore.plots import function_over_targets, paths_over_targets
    from ..explore.study import _target_files

    kind, _, rest = objective.partition(":")
    name = rest.partition("=")[2]
    texts = dict(_target_files((objective,), model.parent, files))
    table = read_table(name, texts, "--plot", 2)
    labels = [f"{i + 1}: {objective.partition('=')[0]} = {e:.3g}" for i, e in enumerate(result.errors)]
    m = as_model(model)
    if kind == "structural_error":
        function_over_targets(m, result.designs, rest.partition("=")[0], table, plot, labels)
    else:
        paths_over_targets(m, result.designs, point, table[:, 0] + 1j * table[:, 1], plot, labels)


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
        if (map_ is None) == (pareto is None):
            raise KinematikaError("usage", "map-or-pareto", "--map")
        if map_ is not None:
            names = _split(map_, 3, "--map")
            plots.metric_map(table, *names, out)
            return f"drew {names[2]} over {names[0]} and {names[1]} to {out}"
        names = _split(pareto, 2, "--pareto")
        front = plots.pareto(table, *names, out, maximize)
        return f"drew {len(front)} designs on the Pareto front to {out}"

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
