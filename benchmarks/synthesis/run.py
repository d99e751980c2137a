"""The four standard four-bar path-synthesis benchmarks, posed through the command line.

Each problem is run as a user runs it — `kinematika synthesize four_bar.yaml --vary ...
--target PROBLEM.csv --point P [--timing j1[=30]] --objective sse --require crank-rocker
[--require ordered] --seconds 60 --seed S -o DIR`, a whole process timed by its wall clock —
and the error of the design it writes is recomputed from the written model file alone,
by the contract's own solver (`kinematika.solve` with `move: {j1: ...}`, the crank turned
from the drawn configuration as a sweep turns it): at the timed inputs, or, for free timing,
at each target's nearest point of the coupler curve (the nearest of 720 positions, then
Brent's method on the crank's turn). The written design is checked as well: within the
bounds, a crank-rocker (Grashof by its lengths), every target assembled, free-timing targets
in order along the motion.

    .venv/bin/python benchmarks/synthesis/run.py                      # 4 problems × 5 seeds × 60 s
    .venv/bin/python benchmarks/synthesis/run.py --seconds 20 --seeds 1 --problems Arc5
    .venv/bin/python benchmarks/synthesis/run.py --markdown           # the table of docs/explore.md

The published values and their sources are in `problems.py`.
"""
from __future__ import annotations

import argparse
import csv
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from problems import PROBLEMS, Problem  # noqa: E402

KINEMATIKA = str(Path(sys.executable).with_name("kinematika"))


def command(problem: Problem, seconds: float, seed: int, out: Path) -> list[str]:
    """The command line a user types for the problem."""
    args = [KINEMATIKA, "synthesize", str(HERE / "four_bar.yaml")]
    for name, (low, high) in problem.bounds.items():
        args += ["--vary", f"{name}={low!r}:{high!r}"]
    args += ["--target", str(HERE / problem.file), "--point", "P", "--objective", "sse"]
    if problem.timing:
        args += ["--timing", problem.timing]
    for requirement in problem.requires:
        args += ["--require", requirement]
    return args + ["--seconds", repr(seconds), "--seed", str(seed), "--best", "1", "-o", str(out)]


def targets(problem: Problem) -> tuple[np.ndarray, np.ndarray | None]:
    """The problem's target points (complex) and inputs (degrees) if timed."""
    with open(HERE / problem.file) as f:
        rows = list(csv.DictReader(f))
    xy = np.array([complex(float(r["x"]), float(r["y"])) for r in rows])
    inputs = np.array([float(r["input"]) for r in rows]) if "input" in rows[0] else None
    return xy, inputs


def where(model: Path, move: float) -> complex | None:
    """The coupler point with the crank turned `move` degrees from the drawn configuration,
    by the contract's solver (None where it cannot be assembled)."""
    import kinematika
    from kinematika.errors import KinematikaError

    try:
        x, y = kinematika.solve(str(model), move={"j1": float(move)}).position("P@coupler")[:2]
    except KinematikaError:
        return None
    return complex(float(x), float(y))


def recompute(problem: Problem, model: Path, start: float | None) -> dict:
    """The written design's sum of squared distances, recomputed from its model file, and
    the crank angles (degrees from the drawn configuration) at which it meets the targets."""
    from scipy.optimize import minimize_scalar

    xy, inputs = targets(problem)
    if inputs is not None:
        first = float(problem.timing.partition("=")[2] or start)
        moves = first + inputs
        got = [where(model, q) for q in moves]
        if any(g is None for g in got):
            return {"sse": math.inf, "moves": moves, "assembled": False}
        return {"sse": float(sum(abs(g - t) ** 2 for g, t in zip(got, xy))), "moves": moves, "assembled": True}
    grid = np.arange(0.0, 360.0, 0.5)
    curve = [where(model, q) for q in grid]
    if any(c is None for c in curve):
        return {"sse": math.inf, "moves": None, "assembled": False}
    curve_ = np.array(curve)
    moves, total = [], 0.0
    for t in xy:
        k = int(np.argmin(np.abs(curve_ - t)))
        sol = minimize_scalar(lambda u, t=t, k=k: abs(where(model, grid[k] + u) - t) ** 2, bounds=(-0.5, 0.5),
                              method="bounded", options={"xatol": 1e-10})
        q = grid[k] + sol.x
        for _ in range(4):               # Gauss–Newton on the crank's turn, P' by central differences
            here, h = where(model, q), 1e-4
            slope = (where(model, q + h) - where(model, q - h)) / (2 * h)
            q -= (np.conj(slope) * (here - t)).real / abs(slope) ** 2
        best = min((abs(where(model, q) - t) ** 2, q), (abs(curve_[k] - t) ** 2, grid[k]))
        total += best[0]
        moves.append(best[1])
    return {"sse": total, "moves": np.array(moves), "assembled": True}


def checks(problem: Problem, params: dict[str, float], moves: np.ndarray | None, assembled: bool) -> list[str]:
    """What the written design breaks (empty: nothing)."""
    broken = [f"{k} outside its bounds" for k, (lo, hi) in problem.bounds.items() if not lo <= params[k] <= hi]
    lengths = [params[k] for k in ("r1", "r2", "r3", "r4")]
    shortest, longest = min(lengths), max(lengths)
    if not (params["r2"] < min(params["r1"], params["r3"], params["r4"])
            and shortest + longest < sum(lengths) - shortest - longest):
        broken.append("not a crank-rocker")          # Grashof, the crank the shortest link
    if not assembled:
        broken.append("a target is not assembled")
    if "ordered" in problem.requires and moves is not None:
        along = np.mod(moves - moves[0], 360.0)
        along[1:] = np.where(along[1:] < 1e-9, 360.0, along[1:])
        if (np.diff(along) < -1e-9).any():
            broken.append("targets out of order")
    return broken


def run_one(problem: Problem, seconds: float, seed: int, folder: Path) -> dict:
    """One run of the command, and its written design recomputed."""
    out = folder / f"{problem.name}-{seed}"
    started = time.perf_counter()
    done = subprocess.run(command(problem, seconds, seed, out), capture_output=True, text=True)
    wall = time.perf_counter() - started
    if done.returncode != 0:
        return {"seed": seed, "wall": wall, "error": done.stdout + done.stderr}
    with open(out / "designs.csv") as f:
        row = next(csv.DictReader(f))
    params = {k: float(row[k]) for k in problem.bounds}
    full = {**problem.fixed, **params}
    start = float(row["start"]) if "start" in row else None
    got = recompute(problem, out / "best-1.yaml", start)
    return {"seed": seed, "wall": wall, "reported": float(row["sse"]), "sse": got["sse"],
            "broken": checks(problem, full, got["moves"], got["assembled"]), "params": params}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=50.0, help="each run's --seconds (the process's start-up and writing fit in a minute)")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--problems", nargs="*", default=[p.name for p in PROBLEMS])
    parser.add_argument("--markdown", action="store_true", help="print the table for docs/explore.md")
    args = parser.parse_args()
    load = os.getloadavg()[0]
    results: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        for problem in PROBLEMS:
            if problem.name not in args.problems:
                continue
            results[problem.name] = []
            for seed in range(args.seeds):
                r = run_one(problem, args.seconds, seed, Path(tmp))
                results[problem.name].append(r)
                print(f"{problem.name} seed {seed}: {r.get('sse', 'error')!r} (reported {r.get('reported')!r}), "
                      f"{r['wall']:.1f} s, {r.get('broken') or r.get('error', '')}", file=sys.stderr, flush=True)
    print(table(results, args, load))


def table(results: dict[str, list[dict]], args, load: float) -> str:
    """The results as a Markdown table."""
    lines = ["| problem | best published (sum of squared distances) | kinematika, best of the seeds | median | "
             "wall time per run | seeds | every design valid |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    by_name = {p.name: p for p in PROBLEMS}
    for name, runs in results.items():
        p = by_name[name]
        ok = [r for r in runs if "sse" in r]
        errors = [r["sse"] for r in ok]
        valid = all(not r["broken"] for r in ok) and len(ok) == len(runs)
        best = f"{min(errors):.8g}" if errors else "—"
        median = f"{statistics.median(errors):.8g}" if errors else "—"
        walls = [r["wall"] for r in runs]
        lines.append(f"| {name} | {p.published:.8g} ({p.source}) | {best} | {median} | "
                     f"{min(walls):.0f}–{max(walls):.0f} s | {len(runs)} | {'yes' if valid else 'NO'} |")
    lines.append("")
    lines.append(f"`--seconds {args.seconds:g}`, seeds 0–{args.seeds - 1}; load average at the start {load:.1f} "
                 f"on {os.cpu_count()} cores.")
    return "\n".join(lines)


if __name__ == "__main__":
    main()
