"""A design study run in chunks, here or on a Dask cluster, written as it goes.

The designs are cut into chunks of `chunk` consecutive designs. Each chunk is evaluated
on its own (`run_chunk`: by this process, by a pool of local processes, or by a worker of a
dask.distributed cluster)
and, when it comes back, written to `OUT.parts/part-NNNNNN.parquet` (a temporary name,
then renamed: a part on disk is always whole). When every chunk is there the parts are
joined, in order, into the output (`.parquet` or `.csv`) and the folder is removed. A
study interrupted at any moment is continued with `resume`: the parts already written are
kept and only the missing chunks are computed, so no design is lost or written twice.
The rows do not depend on where, or in which order, chunks were computed.
"""
from __future__ import annotations

import functools
import hashlib
import json
import os
import shutil
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Optional

import numpy as np

from ..errors import KinematikaError, Said, reason
from ..memory import arrays_on_heap
from .designs import Designs, Vary
from .evaluate import Evaluator, Sweep

CHUNK = 4096            # designs per chunk (batch kernel)
CHUNK_ALONE = 64        # designs per chunk for models solved one design at a time
WINDOW = 3              # chunks in flight per worker


@dataclass(frozen=True)
class Study:
    """Everything a worker needs to evaluate any chunk (picklable; no file is read there)."""

    model: str                              # the model's text
    fmt: str                                # yaml, toml or json
    designs: Designs
    metrics: tuple[str, ...]
    files: tuple[tuple[str, str], ...] = ()     # target files as written → their text
    sweep: Sweep = field(default_factory=Sweep)
    chunk: int = 0                          # 0: chosen by the kind of model

    @property
    def signature(self) -> str:
        """A digest of the study: a resumed study must be the same one."""
        data = asdict(self)
        return hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode()).hexdigest()[:20]

    @property
    def chunks(self) -> int:
        """How many chunks: ⌈designs / chunk⌉ (the last may be shorter)."""
        return -(-self.designs.count // self.chunk)

    def bounds(self, index: int) -> tuple[int, int]:
        """Designs [start, stop) of chunk `index`."""
        start = index * self.chunk
        return start, min(start + self.chunk, self.designs.count)


@functools.lru_cache(maxsize=4)
def evaluator(study: Study) -> Evaluator:
    """The study's prepared model, once per process (a worker keeps it between chunks)."""
    from ..model.source import as_model

    arrays_on_heap()
    model = as_model(study.model, study.fmt)
    return Evaluator(model, study.designs.names, list(study.metrics), study.sweep, files=dict(study.files))


def run_chunk(study: Study, index: int) -> Any:
    """The rows of chunk `index` as an Arrow table."""
    start, stop = study.bounds(index)
    ev = evaluator(study)
    return to_table(ev, ev.evaluate(study.designs.values(start, stop)))


def to_table(ev: Evaluator, columns: dict[str, Any]) -> Any:
    """Columns as an Arrow table: NaN metrics become nulls, classes strings, counts integers."""
    import pyarrow as pa

    arrays = {name: pa.array(columns[name], pa.float64()) for name in ev.varied}
    arrays["assembles"] = pa.array(columns["assembles"], pa.bool_())
    arrays["reason"] = pa.array(list(columns["reason"]), pa.string())
    for m in ev.metrics:
        values = columns[m.name]
        if m.kind == "class":
            arrays[m.name] = pa.array(list(values), pa.string())
            continue
        values = np.asarray(values, dtype=float)
        missing = ~np.isfinite(values)
        if m.kind == "count":
            arrays[m.name] = pa.array(np.where(missing, 0, values).astype(np.int64), pa.int64(), mask=missing)
        else:
            arrays[m.name] = pa.array(values, pa.float64(), mask=missing)
    return pa.table(arrays)


# running ---------------------------------------------------------------------------------------
Progress = Callable[[int], None]


def compute(study: Study, pending: list[int], done: Callable[[int, Any], None],
            scheduler: Any = None, workers: Optional[int] = None) -> None:
    """Evaluate the chunks `pending`, calling `done(index, table)` as each comes back (in any
    order): in this process, in a pool of `workers` local processes, or on the Dask cluster
    at `scheduler` (an address, or a dask.distributed Client)."""
    workers = workers if workers is not None else (os.cpu_count() or 1)
    if scheduler is not None:
        _on_scheduler(study, pending, done, scheduler)
    elif workers <= 1 or len(pending) <= 1:
        for index in pending:
            done(index, run_chunk(study, index))
    else:
        _in_processes(study, pending, done, workers)


def _in_processes(study: Study, pending: list[int], done: Callable[[int, Any], None], workers: int) -> None:
    """The chunks in a pool of local processes (the standard library's; no cluster needed),
    `WINDOW` chunks in flight per process. Processes are spawned, not forked: the caller may
    have threads (the page's server, Jupyter)."""
    import multiprocessing
    from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

    from concurrent.futures.process import BrokenProcessPool

    todo = iter(pending)
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(max_workers=min(workers, len(pending)), mp_context=context) as pool:
        running = {pool.submit(run_chunk, study, i): i for i in _take(todo, WINDOW * workers)}
        try:
            while running:
                finished, _ = wait(running, return_when=FIRST_COMPLETED)
                for future in finished:
                    done(running.pop(future), future.result())
                    running.update({pool.submit(run_chunk, study, i): i for i in _take(todo, 1)})
        except BrokenProcessPool:
            raise KinematikaError("limit", "study-worker-died", "--workers") from None
        except BaseException:
            for future in running:
                future.cancel()
            raise


def _on_scheduler(study: Study, pending: list[int], done: Callable[[int, Any], None], scheduler: Any) -> None:
    """The chunks on a Dask cluster: `scheduler` is its address or a Client."""
    from ..extras import need

    distributed = need("dask.distributed", Said("study-on-dask"), "--scheduler")
    if isinstance(scheduler, str):
        try:
            client = distributed.Client(scheduler, timeout="20s")
        except OSError as err:
            raise KinematikaError("usage", "dask-unreachable", "--scheduler", scheduler=scheduler,
                                  reason=reason(err)) from None
    else:
        client = scheduler
    try:
        _on_cluster(client, study, pending, done)
    finally:
        if client is not scheduler:
            client.close()


def _on_cluster(client: Any, study: Study, pending: list[int], done: Callable[[int, Any], None]) -> None:
    from dask.distributed import as_completed

    width = max(1, WINDOW * len(client.scheduler_info().get("workers", {}) or [1]))
    todo = iter(pending)
    first = [client.submit(run_chunk, study, i, key=f"kinematika-{study.signature}-{i}", pure=False)
             for i in _take(todo, width)]
    index_of = {f.key: i for f, i in zip(first, pending)}
    queue = as_completed(first)
    for future in queue:
        index = index_of.pop(future.key)
        done(index, future.result())
        future.release()
        for i in _take(todo, 1):
            nxt = client.submit(run_chunk, study, i, key=f"kinematika-{study.signature}-{i}", pure=False)
            index_of[nxt.key] = i
            queue.add(nxt)


def _take(it: Iterable[int], n: int) -> list[int]:
    out = []
    for x in it:
        out.append(x)
        if len(out) == n:
            break
    return out


# writing ---------------------------------------------------------------------------------------
class Parts:
    """The folder of finished chunks beside the output, with the study's signature."""

    def __init__(self, output: Path, study: Study) -> None:
        self.output, self.study = output, study
        self.folder = output.with_name(output.name + ".parts")
        self.manifest = self.folder / "study.json"

    def open(self, resume: bool) -> set[int]:
        """Start (or, with `resume`, continue) the study; the chunks already written. The
        folder is made when the first chunk is written (`write`): a run that computes nothing
        leaves nothing."""
        if self.folder.exists():
            if not resume:
                raise KinematikaError("usage", "study-interrupted", "--resume", folder=str(self.folder))
            try:
                signature = json.loads(self.manifest.read_text())["signature"]
            except (OSError, ValueError, KeyError):
                signature = None
            if signature != self.study.signature:
                raise KinematikaError("usage", "study-different", "--resume", folder=str(self.folder))
            return self.written()
        return set()

    def written(self) -> set[int]:
        """The chunks on disk."""
        return {int(p.stem.split("-")[1]) for p in self.folder.glob("part-*.parquet")}

    def _make(self) -> None:
        if not self.manifest.exists():
            self.folder.mkdir(exist_ok=True)
            self.manifest.write_text(json.dumps({"signature": self.study.signature,
                                                 "designs": self.study.designs.count,
                                                 "chunk": self.study.chunk}))

    def path(self, index: int) -> Path:
        """Where chunk `index` is written: ``part-000012.parquet`` in the parts folder."""
        return self.folder / f"part-{index:06d}.parquet"

    def write(self, index: int, table: Any) -> None:
        """A finished chunk, whole or not at all (written aside, then renamed)."""
        import pyarrow.parquet as pq

        self._make()
        tmp = self.folder / f"tmp-{index:06d}.parquet"
        pq.write_table(table, tmp)
        os.replace(tmp, self.path(index))

    def join(self) -> None:
        """The parts, in order, into the output; then the folder goes."""
        import pyarrow.parquet as pq

        tmp = self.output.with_name(self.output.name + ".tmp")
        writer = _writer(tmp, pq.read_schema(self.path(0)), self.output.suffix.lower())
        try:
            for index in range(self.study.chunks):
                writer.write_table(pq.read_table(self.path(index)))
        finally:
            writer.close()
        os.replace(tmp, self.output)
        shutil.rmtree(self.folder)


def _writer(path: Path, schema: Any, suffix: str) -> Any:
    if suffix == ".csv":
        import pyarrow.csv as pcsv

        return pcsv.CSVWriter(str(path), schema, write_options=pcsv.WriteOptions(quoting_style="needed"))
    import pyarrow.parquet as pq

    return pq.ParquetWriter(str(path), schema)


def write_study(study: Study, output: Path, resume: bool = False, scheduler: Any = None,
                workers: Optional[int] = None, progress: Optional[Progress] = None) -> None:
    """Run the study into `output` (.parquet or .csv), in chunks, resumable. A run stopped by
    an error keeps the chunks it finished and its error says how to resume; one that
    finished none leaves no folder behind."""
    if output.suffix.lower() not in (".parquet", ".csv"):
        raise KinematikaError("usage", "study-output", "-o", name=output.name)
    parts = Parts(output, study)
    finished = parts.open(resume)
    count = sum(np.subtract(*study.bounds(i)[::-1]) for i in finished)
    if progress:
        progress(int(count))

    def done(index: int, table: Any) -> None:
        nonlocal count
        parts.write(index, table)
        count += table.num_rows
        if progress:
            progress(int(count))

    try:
        compute(study, [i for i in range(study.chunks) if i not in finished], done, scheduler, workers)
    except KinematikaError as err:
        raise KinematikaError(err.kind, "study-stopped", err.where, problem=err.said, note=resume_note(parts)) from None
    parts.join()


def resume_note(parts: Parts) -> Said:
    """What an interrupted study left: nothing, or the finished designs and how to go on."""
    if not parts.folder.exists():
        return Said("nothing")
    kept = sum(np.subtract(*parts.study.bounds(i)[::-1]) for i in parts.written())
    return Said("study-kept", kept=int(kept), folder=parts.folder.name)


def collect(study: Study, scheduler: Any = None, workers: Optional[int] = None,
            progress: Optional[Progress] = None) -> Any:
    """Run the study and return its rows as one Arrow table (for studies that fit in memory)."""
    import pyarrow as pa

    tables: dict[int, Any] = {}
    count = 0

    def done(index: int, table: Any) -> None:
        nonlocal count
        tables[index] = table
        count += table.num_rows
        if progress:
            progress(count)

    compute(study, list(range(study.chunks)), done, scheduler, workers)
    return pa.concat_tables([tables[i] for i in range(study.chunks)])


def make_study(source: Any, vary: Iterable[Vary | str], metrics: Iterable[str], grid: Optional[int] = None,
               samples: Optional[int] = None, seed: int = 0, sweep: Sweep = Sweep(),
               chunk: Optional[int] = None, files: Optional[dict[str, str]] = None,
               what: str = "explore") -> Study:
    """A `Study` from a model file (or model text), checked here, where the files are.
    `files` gives the text of target files by name instead of reading them; `what` names the
    command for an error about a missing optional dependency."""
    _need_extra(what)
    text, fmt, base = _model_text(source)
    designs = Designs(tuple(v if isinstance(v, Vary) else _vary(v) for v in vary), grid, samples, seed)
    metrics = tuple(metrics)
    texts = _target_files(metrics, base, files or {})
    study = Study(text, fmt, designs, metrics, texts, sweep, 0)
    ev = evaluator(study)                       # checks the model, parameters and metrics here
    size = chunk or (CHUNK if ev.batch.batchable else CHUNK_ALONE)
    return Study(text, fmt, designs, metrics, texts, sweep, int(size))


def _need_extra(what: str) -> None:
    from ..extras import need

    need("pyarrow", what)
    need("pandas", what)


def _vary(text: str) -> Vary:
    from .designs import parse_vary

    return parse_vary(text)


def _model_text(source: Any) -> tuple[str, str, Path]:
    """The model's text and format, and the folder relative file names are read from."""
    if isinstance(source, (str, Path)) and "\n" not in str(source):
        path = Path(source)
        try:
            text = path.read_text(encoding="utf-8")
        except OSError as err:
            raise KinematikaError("syntax", "cannot-read", str(path), path=str(path), reason=reason(err)) from None
        fmt = {".toml": "toml", ".json": "json"}.get(path.suffix.lower(), "yaml")
        return text, fmt, path.parent
    if isinstance(source, str):
        return source, "yaml", Path(".")
    if isinstance(source, dict):
        return json.dumps(source), "json", Path(".")
    raise KinematikaError("usage", "study-needs-model", "model")


def _target_files(metrics: tuple[str, ...], base: Path, given: dict[str, str]) -> tuple[tuple[str, str], ...]:
    """The text of every file a metric names (`path_error:P=FILE.csv`), read here."""
    out = {}
    for m in metrics:
        head, eq, arg = m.partition("=")
        name = arg.strip()
        if name in given:
            out[name] = given[name]
        elif eq and name.lower().endswith(".csv"):
            path = Path(name) if Path(name).is_absolute() else base / name
            try:
                out[name] = path.read_text(encoding="utf-8")
            except OSError as err:
                raise KinematikaError("usage", "cannot-read", f"--metric {m}", path=name, reason=reason(err)) from None
    return tuple(sorted(out.items()))
