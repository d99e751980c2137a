"""Design studies: many designs of one model, evaluated in batches, here or on a Dask cluster.

    >>> import kinematika
    >>> table = kinematika.explore("four_bar.yaml", vary={"a": (1, 3), "c": (3, 6)}, grid=50,
    ...                            metrics=["grashof", "transmission", "range:rocker"])

A design is a set of values of the model's parameters (`--vary NAME=LOW:HIGH`); each is
assembled at its drawn input and swept over the model's cycle, and gives one row: the
parameters, `assembles`, `reason` and one column per metric (`metrics` lists them).
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Iterable, Mapping, Optional, Union

from .designs import Vary
from .evaluate import Sweep

__all__ = ["Sweep", "Vary", "explore"]


def explore(model: Any, vary: Union[Mapping[str, tuple], Iterable[str]], metrics: Iterable[str] = (),
            grid: Optional[int] = None, samples: Optional[int] = None, seed: int = 0,
            output: Union[str, Path, None] = None, scheduler: Any = None, workers: Optional[int] = 1,
            resume: bool = False, joint: Optional[str] = None, by: Optional[float] = None,
            steps: Optional[int] = None, chunk: Optional[int] = None, arrow: bool = False) -> Any:
    """Evaluate the designs of `model` (a file, or a model's text) and return their rows.

    `vary`: {name: (low, high)} or ["name=low:high", ...]; `grid` values of each, or
    `samples` Sobol' points (`seed`). `scheduler`: a Dask scheduler's address or Client;
    `workers`: local processes when no scheduler is given (1: this process). With `output`
    (.parquet or .csv) the rows are written there in chunks (`resume` continues an
    interrupted study) and the file is read back. A pandas DataFrame, or an Arrow table
    with `arrow=True`.
    """
    from .study import collect, make_study, write_study

    varied: Iterable[Vary | str] = vary if not isinstance(vary, Mapping) else \
        [Vary(str(k), float(v[0]), float(v[1])) for k, v in vary.items()]
    study = make_study(model, varied, metrics, grid, samples, seed, Sweep(joint, by, steps), chunk)
    if output is None:
        table = collect(study, scheduler, workers)
    else:
        import pyarrow.csv as pcsv
        import pyarrow.parquet as pq

        path = Path(output)
        write_study(study, path, resume, scheduler, workers)
        table = pcsv.read_csv(path) if path.suffix.lower() == ".csv" else pq.read_table(path)
    return table if arrow else table.to_pandas()
