"""The fuzzing campaign: thousands of generated inputs (`cases`) through the command line,
each in its own process (`forks`; a share through a fresh `python -m kinematika` too),
checked against the contract (`contract.check_run`) and, for scaled and renamed models,
against the original's answers.

    .venv/bin/python tests/fuzz/campaign.py --count 5000 [--seed S] [--workers 2] [--keep DIR]
    .venv/bin/python tests/fuzz/campaign.py --seed S --case N      # one input again, verbosely
    KINEMATIKA_FUZZ=5000 .venv/bin/python -m pytest tests/fuzz/test_campaign.py   # the same in pytest

It prints the inputs per class and command, the outcomes (answers, errors by kind), the
slowest and largest processes, and every failure with its seed and number.
"""
from __future__ import annotations

import json
import math
import re
import shutil
import sys
import tempfile
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

if __package__ in (None, ""):                      # run as a script: import as the tests do
    sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
    __package__ = "fuzz"

from .cases import Case, bases, case, symbolic_examples
from .contract import ROOT, Run, check_run, json_wanted, run_cli, without_warnings
from .forks import run_all
from .scaling import ACCELERATION, ALPHA, OMEGA, POSITION, VELOCITY, is_close, expected, factor

CONTROL = re.compile(r"[\x00-\x08\x0b-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
NAN = re.compile(r"(?<![\w.])[-+]?(nan|inf)(?![\w])", re.IGNORECASE)


@dataclass
class Result:
    case: Case
    run: Run
    failure: str = ""


@dataclass
class Summary:
    seed: int
    results: list[Result] = field(default_factory=list)
    seconds: float = 0.0

    @property
    def failures(self) -> list[Result]:
        return [r for r in self.results if r.failure]

    def report(self) -> str:
        inputs = [r for r in self.results if r.case.klass not in ("base", "example")]
        extra = len(self.results) - len(inputs)
        lines = [f"seed {self.seed}: {len(inputs)} inputs (+{extra} runs of the examples) "
                 f"in {self.seconds:.0f} s, {len(self.failures)} failures"]
        examples = [r for r in self.results if r.case.klass == "example"]
        if examples:
            top = max(examples, key=lambda r: r.run.cpu)
            lines.append(f"every example with --symbolic: {sum(r.run.status == 0 for r in examples)}/"
                         f"{len(examples)} answered, most CPU {top.run.cpu:.2f} s ({top.case.note}, "
                         f"wall {top.run.seconds:.2f} s)")
        by_class = Counter(r.case.klass for r in inputs)
        lines.append("inputs per class: " + ", ".join(f"{k} {v}" for k, v in sorted(by_class.items())))
        by_command = Counter(r.case.args[0] if r.case.args else "" for r in inputs)
        lines.append("inputs per command: " + ", ".join(f"{k} {v}" for k, v in sorted(by_command.items())))
        flags = Counter(f for r in inputs for f in ("--json", "--symbolic") if f in r.case.args)
        lines.append("with: " + ", ".join(f"{k} {v}" for k, v in sorted(flags.items())))
        fresh = sum(1 for r in inputs if getattr(r.run, "fresh", False))
        lines.append(f"run as a fresh python -m kinematika: {fresh}; the rest forked")
        outcomes = Counter(_outcome(r.run) for r in inputs)
        lines.append("outcomes: " + ", ".join(f"{k} {v}" for k, v in sorted(outcomes.items())))
        compared = sum(1 for r in inputs if r.case.base)
        lines.append(f"answers compared with the original's (scaled, renamed): {compared}")
        slow = sorted(inputs, key=lambda r: r.run.cpu, reverse=True)[:3]
        lines.append("most CPU: " + "; ".join(f"{r.run.cpu:.1f} s (wall {r.run.seconds:.1f}) #{r.case.number} "
                                              f"{r.case.klass} {r.case.args[0]} {r.case.note[:40]!r}" for r in slow))
        big = max(inputs, key=lambda r: r.run.memory, default=None)
        if big:
            lines.append(f"most memory: {big.run.memory >> 20} MB #{big.case.number} {big.case.note[:40]!r}")
        for r in self.failures:
            lines.append(f"FAIL seed {self.seed} case {r.case.number} [{r.case.klass}] {r.case.note[:60]!r}: "
                         f"{r.failure[:400]}")
        return "\n".join(lines)


def _outcome(run: Run) -> str:
    if run.status == 0:
        return "answer"
    if run.status == 2:
        kind = re.match(r"error \((\w+)\)", without_warnings(run.stderr))
        if kind:
            return f"error {kind.group(1)}"
        try:
            return "error " + json.loads(run.stdout)["error"]["kind"]
        except (ValueError, KeyError, TypeError):
            return "error ?"
    return f"status {run.status}"


def check(case: Case, run: Run, text: str) -> str:
    """The contract for one run, and what its class adds; '' when it holds."""
    try:
        check_run(run)
    except AssertionError as err:
        return str(err) or "contract"
    except ValueError as err:                    # the JSON did not parse
        return f"invalid JSON: {err}: {run.stdout[:200]!r}"
    if run.status == 0 and not json_wanted(run.args) and "--help" not in run.args:
        bad = CONTROL.search(run.stdout)
        if bad:
            return f"control character {bad.group()!r} in the output: {run.stdout[max(0, bad.start() - 40):bad.end() + 40]!r}"
        if without_warnings(run.stderr).strip():
            return f"exit 0 with text on stderr: {run.stderr[:200]!r}"
        if not NAN.search(text + " ".join(run.args)):       # 'nan' the user wrote is shown as written
            bad = NAN.search(run.stdout)
            if bad:
                return f"{bad.group()} in the output: {run.stdout[max(0, bad.start() - 80):bad.end() + 40]!r}"
    return ""


def compare(base: dict, got: dict, length: float, rate: float) -> str:
    """Whether `got` is `base` scaled by `length` and `rate` (every body, point and answer);
    '' when it is."""
    def same(a: Any, b: Any, dim: tuple, where: str) -> str:
        want = _scaled(a, dim, length, rate)
        top = max([abs(x) for x in _numbers(want)] + [0.0])
        if not is_close(b, want, top):
            return f"{where}: {b} instead of {want}"
        return ""

    # by order, not by name: a renamed model has other names for the same things
    for section in ("bodies", "points"):
        if len(base.get(section, {})) != len(got.get(section, {})):
            return f"{len(got.get(section, {}))} {section} instead of {len(base.get(section, {}))}"
    for (name, body), other in zip(base.get("bodies", {}).items(), got.get("bodies", {}).values()):
        for key, dim in (("omega", OMEGA), ("alpha", ALPHA)):
            why = same(body.get(key), other.get(key), dim, f"{name}.{key}")
            if why:
                return why
    for (name, point), other in zip(base.get("points", {}).items(), got.get("points", {}).values()):
        for key, dim in (("position", POSITION), ("velocity", VELOCITY), ("acceleration", ACCELERATION)):
            if key in point:
                why = same(point[key], other.get(key), dim, f"{name}.{key}")
                if why:
                    return why
    for a, b in zip(base.get("answers", []), got.get("answers", [])):
        kind = next(iter(a["ask"]))
        want = expected(a["value"], kind, length, rate)
        top = max([abs(x) for x in _numbers(want)] + [0.0])
        if not is_close(b["value"], want, top):
            return f"answer {a['ask']}: {b['value']} instead of {want}"
    if len(base.get("answers", [])) != len(got.get("answers", [])):
        return "not the same questions answered"
    return ""


def _scaled(value: Any, dim: tuple, length: float, rate: float) -> Any:
    if isinstance(value, list):
        return [_scaled(v, dim, length, rate) for v in value]
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return value * factor(dim, length, rate)
    return value


def _numbers(x: Any) -> list[float]:
    if isinstance(x, dict):
        return [n for v in x.values() for n in _numbers(v)]
    if isinstance(x, list):
        return [n for v in x for n in _numbers(v)]
    return [float(x)] if isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) else []


def _argv(args: list[str]) -> list[str]:
    """Arguments as a process receives them (bytes; what cannot be encoded arrives escaped)."""
    import os

    out = []
    for a in args:
        try:
            os.fsencode(a)
            out.append(a)
        except UnicodeEncodeError:
            out.append(os.fsdecode(a.encode("utf-8", "surrogatepass")))
    return [a.replace("\x00", "") for a in out]


def run(count: int, seed: int, workers: int = 2, fresh_every: int = 25, keep: Path | None = None,
        numbers: list[int] | None = None, progress: bool = False, examples: bool = False) -> Summary:
    """`count` inputs of the campaign `seed` (or the inputs `numbers`), checked; with
    `examples`, every shipped example solved with `--symbolic` as well."""
    start = time.monotonic()
    summary = Summary(seed)
    scratch = Path(tempfile.mkdtemp(prefix="kinematika-fuzz-"))
    drawn = [case(seed, n) for n in (numbers if numbers is not None else range(count))]
    wanted = {c.base for c in drawn}
    cases = [c for c in bases() if c.note in wanted] + drawn
    if examples:
        cases += symbolic_examples()
    texts: dict[int, str] = {}

    def jobs():
        for i, c in enumerate(cases):
            folder = scratch / str(i)
            folder.mkdir()
            args = _argv(c.materialise(folder))
            texts[i] = "".join(v if isinstance(v, str) else "" for v in c.files.values())
            if c.klass not in ("base", "example") and fresh_every and c.number % fresh_every == fresh_every - 1:
                continue                                   # run below as a fresh process
            yield i, args, ROOT

    done = 0
    results: dict[int, Result] = {}
    for i, r in run_all(jobs(), workers):
        results[i] = Result(cases[i], r, check(cases[i], r, texts[i]))
        done += 1
        if progress and done % 200 == 0:
            print(f"  {done} runs, {time.monotonic() - start:.0f} s, "
                  f"{sum(1 for x in results.values() if x.failure)} failures", file=sys.stderr, flush=True)
    for i, c in enumerate(cases):                          # the fresh processes
        if i not in results:
            r = run_cli(_argv([a.replace("{dir}", str(scratch / str(i))) for a in c.args]), cwd=ROOT)
            r.fresh = True
            results[i] = Result(c, r, check(c, r, texts.get(i, "")))
    base = {r.case.note: r.run for r in results.values() if r.case.klass == "base"}
    for r in results.values():
        if r.failure or not r.case.base or r.case.base not in base:
            continue
        original = base[r.case.base]
        if original.status != 0:
            continue
        if r.run.status != 0:
            if r.case.strict or (r.case.klass == "renamed" and _ordinary(r.case)):
                r.failure = f"the original answers, this gives: {(r.run.stdout or r.run.stderr)[:300]}"
            continue
        try:
            why = compare(json.loads(original.stdout), json.loads(r.run.stdout), r.case.length, r.case.rate)
        except (ValueError, KeyError, TypeError, AttributeError) as err:
            why = f"answers not comparable: {err!r}"
        if why:
            r.failure = "wrong answer: " + why
    for r in results.values():
        if r.case.klass == "example" and not r.failure and r.run.status != 0:
            r.failure = f"a shipped example does not answer with --symbolic: {r.run.stdout[:200]}"
    summary.results = [results[i] for i in range(len(cases))]
    summary.seconds = time.monotonic() - start
    if keep:
        for r in summary.failures:
            folder = keep / f"{seed}-{r.case.number}"
            shutil.rmtree(folder, ignore_errors=True)
            shutil.copytree(scratch / str(cases.index(r.case)), folder, symlinks=True,
                            ignore=lambda d, names: [n for n in names if (Path(d) / n).is_fifo()])
            (folder / "RUN.txt").write_text(f"{r.case.args!r}\n{r.failure}\n--- stdout\n{r.run.stdout[:5000]}\n"
                                            f"--- stderr\n{r.run.stderr[:5000]}\n", errors="replace")
    shutil.rmtree(scratch, ignore_errors=True)
    return summary


def _ordinary(c: Case) -> bool:
    """A rename to a name a model may use (a plain identifier of ordinary length)."""
    new = c.name
    return bool(re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,60}", new)) and new not in (
        "lambda", "pi", "sqrt", "None", "True", "abs", "ground", "_kw_lambda_", "__import__")


def main() -> None:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=500)
    parser.add_argument("--seed", type=int, default=int(time.time()) % 100_000)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--case", type=int, action="append", help="run only these inputs, verbosely")
    parser.add_argument("--keep", type=Path, help="copy each failing input's files here")
    parser.add_argument("--examples", action="store_true", help="solve every example with --symbolic too")
    ns = parser.parse_args()
    summary = run(ns.count, ns.seed, ns.workers, keep=ns.keep, numbers=ns.case, progress=not ns.case,
                  examples=ns.examples)
    if ns.case:
        for r in summary.results:
            if r.case.klass not in ("base", "example"):
                print(r.case.klass, r.case.note, r.case.args, "->", r.run.status, f"{r.run.cpu:.2f} s CPU")
                print(r.run.stdout[:2000], r.run.stderr[:2000], sep="\n")
    print(summary.report())
    sys.exit(1 if summary.failures else 0)


if __name__ == "__main__":
    main()
