"""`kinematika explore`: a design study over the model's parameters, here or on Dask."""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import typer

from .app import ModelArg, app, guarded, output_file


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
            ) -> None:
    """Evaluate many designs of MODEL (values of its parameters) and write one row each: the
    parameters, whether it assembles (and why not), and the metrics."""
    from ..explore.evaluate import Sweep
    from ..explore.study import make_study, write_study
    from ..sweep.progress import reporter

    def work() -> int:
        study = make_study(model, vary, metric, grid, samples, seed, Sweep(joint, by, steps), chunk)
        output_file(output, "-o")
        bar = reporter(True, study.designs.count, f"exploring {study.designs.count} designs")
        try:
            write_study(study, output, resume, scheduler, workers, bar)
        finally:
            bar(None)
        return study.designs.count

    count = guarded(False, work)
    print(f"wrote {count} designs to {output}", file=sys.stderr)
