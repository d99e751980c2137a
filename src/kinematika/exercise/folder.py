"""An exercise's folder (`kinematika exercise -o DIR`), written and read back.

    variants.csv    variant, then one column per varied parameter (values as stated)
    key.csv         variant,question,value,tolerance (one row per number; tolerance relative)
    MODEL           the model file, as given
    exercise.json   how the variants were drawn: the model's file name, --vary, --seed, --lang
    quiz.xml        the Moodle XML quiz (one Cloze question per variant)
    sheets.html     one page per student; sheets.pdf when Chromium prints it
    key.html        the answer key with the worked solutions; key.pdf likewise
    figures/        each variant's figure (variant-001.png …)
    links.txt       variant, then the link fragment that opens it in the page (`kinematika app`)
    students.csv    student,variant (with `--students`: who was given which variant)

`kinematika grade DIR` reads it back: the model, exercise.json and variants.csv give the
variants again (solved again by the same solver), and key.csv must agree with them.
"""
from __future__ import annotations

import csv
import io
import json
from decimal import Decimal, InvalidOperation
from pathlib import Path
from contextlib import contextmanager
from typing import Any, Callable, Iterator, Optional

from ..errors import KinematikaError, Said, parser_problem, reason
from .build import DEFAULT_SECTION, Exercise
from .key import value_text
from .moodle import QuizOptions
from .stated import plain_decimal
from .variants import parse_vary

AGREE = 1e-9           # key.csv and the model solved again agree to this (relative to the value's size)


def write_exercise(ex: Exercise, out: Path, solutions: bool = True, pdf: bool = True,
                   quiz: Optional[QuizOptions] = None,
                   progress: Optional[Callable[[int, int], None]] = None) -> list[Said]:
    """Write the folder; the notes to show (what was written, what was skipped or narrowed).
    `quiz` holds Moodle's options (a question per part, a penalty for a wrong unit);
    `progress(done, total)` is told as the variants' figures and solutions are made.

    In the order that keeps both cores busy: the statement figures first (the sheets need
    nothing else), then the worked solutions while Chromium, started as the figures are
    drawn, prints the sheets; the key prints last while the quiz and the CSV files are
    written."""
    from .printing import missing
    from .sheets import key_html, sheets_html, students_for

    out.mkdir(exist_ok=True)
    (out / "figures").mkdir(exist_ok=True)
    notes = [*ex.notes, Said("exercise-wrote", count=len(ex.variants), folder=str(out))]
    cannot = missing() if pdf else None
    if cannot is not None:
        notes.append(cannot)
    with made(ex, solutions) as (drawn_figures, worked_solutions), \
            _printer(pdf and cannot is None) as printer:       # after the workers' fork
        total = len(ex.variants) * (2 if solutions else 1)
        figures, worked = {}, {}
        for number, png in drawn_figures:
            figures[number] = png
            (out / "figures" / f"variant-{number:03d}.png").write_bytes(png)
            if progress:
                progress(len(figures), total)
        _text(out / "sheets.html", sheets_html(ex, figures, students_for(ex)))
        if printer is not None:
            printer.submit(out / "sheets.html", out / "sheets.pdf")
        for number, solution in worked_solutions:
            worked[number] = solution
            if progress:
                progress(len(figures) + len(worked), total)
        _text(out / "key.html", key_html(ex, figures, worked))
        if printer is not None:
            printer.submit(out / "key.html", out / "key.pdf")
        _rest(ex, out, figures, worked if solutions else None, quiz)
    return notes


def _rest(ex: Exercise, out: Path, figures: dict[int, bytes], worked: Optional[dict[int, str]],
          quiz: Optional[QuizOptions]) -> None:
    """The quiz, the CSV files, the model, exercise.json and links.txt."""
    from .moodle import quiz_xml
    from .roster import students_csv

    mistakes = {v.number: v.mistaken for v in ex.variants}
    _text(out / "variants.csv", variants_csv(ex))
    _text(out / "key.csv", key_csv(ex))
    if ex.source is not None:
        (out / ex.source.name).write_bytes(ex.source.read_bytes())
    _text(out / "exercise.json", json.dumps(meta(ex), ensure_ascii=False, indent=1) + "\n")
    _text(out / "quiz.xml", quiz_xml(ex, figures, worked, mistakes, quiz or QuizOptions()))
    if ex.students:
        _text(out / "students.csv", students_csv(ex.students))
    if ex.source is not None:
        _text(out / "links.txt", "".join(f"{v.number}\t{page_link(ex, v.number)}\n" for v in ex.variants))


@contextmanager
def _printer(wanted: bool) -> Iterator[Any]:
    """A `printing.Printer` running for the block when `wanted`, else None."""
    if not wanted:
        yield None
        return
    from .printing import Printer

    with Printer() as printer:
        yield printer


WORKERS_FROM = 4          # variants from which the figures and solutions are made in parallel


@contextmanager
def made(ex: Exercise, solutions: bool) -> Iterator[tuple[Iterator[tuple[int, bytes]], Iterator[tuple[int, str]]]]:
    """The variants' statement figures (PNG), then their worked solutions (HTML; none without
    `solutions`), each in the variants' order, as (number, made) pairs: in a process per core
    when there are several cores and variants and this process runs no other thread (forked
    processes that hold the exercise, forked on entering the block; the same bytes as made
    one by one), else one by one as they are read."""
    import os
    import sys
    import threading

    numbers = [v.number for v in ex.variants]
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    alone = threading.active_count() == 1          # a fork copies no other thread's held lock
    if cores < 2 or len(numbers) < WORKERS_FROM or not alone or not sys.platform.startswith("linux"):
        yield (((n, _figure_of(ex, n)) for n in numbers),
               ((n, _solution_of(ex, n)) for n in (numbers if solutions else [])))
        return
    import multiprocessing
    from concurrent.futures import ProcessPoolExecutor

    global _FORKED
    _FORKED = ex
    pool = ProcessPoolExecutor(min(cores, len(numbers)), mp_context=multiprocessing.get_context("fork"))
    try:
        figures = pool.map(_figure_forked, numbers)          # forks the workers, then queues
        worked = pool.map(_solution_forked, numbers) if solutions else iter(())
        yield zip(numbers, figures), zip(numbers, worked)
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
        _FORKED = None


_FORKED: Any = None          # the exercise the forked workers draw (set before the fork)


def _figure_forked(number: int) -> bytes:
    return _figure_of(_FORKED, number)


def _solution_forked(number: int) -> str:
    return _solution_of(_FORKED, number)


def _figure_of(ex: Exercise, number: int) -> bytes:
    from .figure import statement_figure

    return statement_figure(ex, ex.variant(number), ex.lang)


def _solution_of(ex: Exercise, number: int) -> str:
    from .solutions import solution_html

    return solution_html(ex, ex.variant(number), ex.lang)


def page_link(ex: Exercise, number: int) -> str:
    """The fragment that opens variant `number` in the page's exercise mode (append it to
    the address of `kinematika app`): the model deflated and base64url-encoded, as the
    page's own links hold a model (web/static/js/link.js), with `vary`, `seed`, `variant`
    and `lang`."""
    import base64
    import zlib
    from urllib.parse import urlencode

    source = ex.source
    assert source is not None, "a link holds the model file: an exercise read from one"
    packer = zlib.compressobj(9, zlib.DEFLATED, -15)             # raw deflate, as the page's
    packed = packer.compress(source.read_bytes()) + packer.flush()
    model = base64.urlsafe_b64encode(packed).rstrip(b"=").decode()
    suffix = source.suffix.lower().lstrip(".")
    fmt = {"yml": "yaml"}.get(suffix, suffix)
    query = urlencode([("exercise", "1"), *(("vary", m) for m in meta(ex)["vary"]), ("seed", ex.seed),
                       ("variant", number), ("lang", ex.lang)])
    return f"#{query}&format={fmt}&model={model}"


def _text(path: Path, text: str) -> None:
    path.write_text(text, encoding="utf-8", newline="")


def meta(ex: Exercise) -> dict[str, Any]:
    """`exercise.json`: the model's file name, the `--vary` options (NAME=LOW:HIGH:STEP), the
    count of variants, the seed and the language — what makes the same exercise again."""
    return {"model": ex.source.name if ex.source is not None else None,
            "vary": [f"{v.name}={plain_decimal(v.low)}:{plain_decimal(v.high)}:{plain_decimal(v.step)}"
                     for v in ex.varies],
            "count": len(ex.variants), "seed": ex.seed, "lang": ex.lang}


def variants_csv(ex: Exercise) -> str:
    """`variants.csv`: one row per variant, its number and the varied parameters' values as
    stated."""
    names = [v.name for v in ex.varies]
    lines = [",".join(["variant", *names])]
    for v in ex.variants:
        lines.append(",".join([str(v.number), *(plain_decimal(v.stated[n]) for n in names)]))
    return "\n".join(lines) + "\n"


def key_csv(ex: Exercise) -> str:
    """`key.csv`: one row per number a student gives (variant, question such as q2.y, value,
    tolerance)."""
    lines = ["variant,question,value,tolerance"]
    for v in ex.variants:
        lines += [f"{v.number},{r.question},{value_text(r.value)},{v.tolerance_of(r)!r}" for r in v.rows]
    return "\n".join(lines) + "\n"


# reading a folder back ------------------------------------------------------------------------
def load_exercise(folder: Path) -> Exercise:
    """The exercise of a folder `kinematika exercise` wrote, its variants solved again."""
    from ..model.files import load_model

    info = _json(folder / "exercise.json")
    model_name = info.get("model")
    if not isinstance(model_name, str) or "/" in model_name or "\\" in model_name:
        raise KinematikaError("usage", "exercise-no-model", str(folder))
    model_path = folder / model_name
    model = load_model(model_path)
    try:
        vary, seed, lang = list(info["vary"]), int(info["seed"]), str(info["lang"])
    except (KeyError, TypeError, ValueError):
        raise KinematikaError("usage", "exercise-lacks", str(folder)) from None
    ex = Exercise(model, model.exercise or DEFAULT_SECTION, [parse_vary(t) for t in vary], seed, lang,
                  source=model_path)
    for number, stated in enumerate(_variants(folder / "variants.csv", [v.name for v in ex.varies]), start=1):
        variant = ex.solve(stated)
        variant.number = number
        ex.judged(variant)
        ex.variants.append(variant)
    _check_key(ex, folder / "key.csv")
    from .roster import read_students

    ex.students = read_students(folder / "students.csv", len(ex.variants)) or []
    return ex


def _json(path: Path) -> dict:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except OSError as err:
        raise KinematikaError("usage", "exercise-cannot-read", str(path), path=str(path), reason=reason(err)) from None
    except ValueError as err:
        raise KinematikaError("syntax", "file-not-json", str(path), name=path.name,
                              problem=parser_problem(str(err))) from None
    if not isinstance(data, dict):
        raise KinematikaError("syntax", "file-not-json-object", str(path), name=path.name)
    return data


def read_csv(path: Path, columns: list[str]) -> list[dict[str, str]]:
    """A CSV's rows by the header's names; the `columns` must be there (else a one-line error
    naming the file)."""
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as err:
        raise KinematikaError("usage", "cannot-read", str(path), path=str(path), reason=reason(err)) from None
    except UnicodeDecodeError:
        raise KinematikaError("syntax", "csv-not-utf8", str(path), name=path.name) from None
    reader = csv.DictReader(io.StringIO(text))
    header = [h.strip() for h in reader.fieldnames or []]
    lacking = [c for c in columns if c not in header]
    if lacking:
        raise KinematikaError("syntax", "csv-no-column", path.name, name=path.name, column=lacking[0],
                              header=",".join(header), count=len(header))
    rows = []
    for row in reader:
        rows.append({(k or "").strip(): (v or "").strip() if isinstance(v, str) else "" for k, v in row.items()})
    return rows


def _variants(path: Path, names: list[str]) -> list[dict[str, Decimal]]:
    out: list[dict[str, Decimal]] = []
    for i, row in enumerate(read_csv(path, ["variant", *names]), start=2):
        try:
            if int(row["variant"]) != len(out) + 1:
                raise ValueError
            out.append({n: Decimal(row[n]) for n in names})
        except (ValueError, InvalidOperation):
            raise KinematikaError("syntax", "variants-numbered", f"{path.name}:{i}") from None
    if not out:
        raise KinematikaError("syntax", "variants-none", path.name)
    return out


def _check_key(ex: Exercise, path: Path) -> None:
    """key.csv must hold what the model gives again (an edited model or key is an error)."""
    rows = read_csv(path, ["variant", "question", "value", "tolerance"])
    written = {(r["variant"], r["question"]): r["value"] for r in rows}
    for v in ex.variants:
        for r in v.rows:
            value = written.get((str(v.number), r.question))
            try:
                agree = value is not None and abs(float(value) - r.value) <= AGREE * max(r.size, 1e-300)
            except ValueError:
                agree = False
            if not agree:
                raise KinematikaError("usage", "key-mismatch", path.name, variant=v.number, question=r.question)
