"""Time a whole `kinematika solve MODEL --symbolic --json` (start-up included) on every model.

Every shipped example, the construction-built models of `benchmarks/models/symbolic/` and
of the textbook cases (`tests/cases/tb_*.yaml` and `tests/textbook/*.yaml`, errors left
out), and the symbolic contract cases must answer with `--symbolic` in under 5 s (issues
12, 16).
Run:  .venv/bin/python benchmarks/symbolic_examples.py [--repeat 1] [--cap 60] [--markdown]
      [--command solve|centres|explain]
Prints one row per model (best of the repeats, whole process): the seconds on the clock,
the processor seconds (what the load does not change) and the ratio to the 5 s budget; a
model still running at `--cap` seconds is stopped and shown as `>cap`. The load average is
printed first and last: on a shared machine the clock time is the processor time stretched
by the load.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BUDGET = 5.0
CASES = Path("/work/shared/cases")


def models() -> list[Path]:
    """The examples, the benchmark's own symbolic models, and the symbolic contract cases."""
    out = sorted((ROOT / "examples").glob("*.yaml"))
    out += sorted((ROOT / "benchmarks" / "models" / "symbolic").glob("*.yaml"))
    out += [path for path in sorted((ROOT / "tests" / "cases").glob("tb_*.yaml")) if _answers(path)]
    out += [path for path in sorted((ROOT / "tests" / "textbook").glob("*.yaml")) if _answers(path)]
    if CASES.is_dir():
        for path in sorted(CASES.glob("*.yaml")):
            expect = path.with_suffix("").with_suffix(".expect.json")
            if expect.exists() and json.loads(expect.read_text()).get("symbolic"):
                out.append(path)
    return out


def _answers(path: Path) -> bool:
    """A textbook case whose expectation is an answer (not an error)."""
    expect = path.with_suffix("").with_suffix(".expect.json")
    return expect.exists() and "error" not in json.loads(expect.read_text())


def time_solve(path: Path, repeat: int, cap: float, command: str = "solve") -> tuple[float, float, str]:
    """Best clock and processor seconds of `kinematika COMMAND MODEL --symbolic` as a process."""
    exe = Path(sys.executable).parent / "kinematika"
    args = [str(exe), command, str(path), "--symbolic"] + ([] if command == "explain" else ["--json"])
    best, cpu, status = float("inf"), float("inf"), "ok"
    for _ in range(repeat):
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        try:
            done = subprocess.run(args, capture_output=True, text=True, timeout=cap)
        except subprocess.TimeoutExpired:
            return cap, cap, "timeout"
        best = min(best, time.perf_counter() - start)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = min(cpu, after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
        if done.returncode != 0:
            status = "error: " + (done.stdout or done.stderr).strip()[:80]
        elif command == "solve" and json.loads(done.stdout).get("symbolic") is not True:
            status = "not symbolic"
    return best, cpu, status


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--cap", type=float, default=60.0, help="seconds before a run is stopped")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    ap.add_argument("--command", default="solve", choices=["solve", "centres", "explain"])
    args = ap.parse_args()
    print(f"load average at start: {os.getloadavg()[0]:.1f}", flush=True)
    rows = []
    for path in models():
        seconds, cpu, status = time_solve(path, args.repeat, args.cap, args.command)
        shown = f">{seconds:.0f}" if status == "timeout" else f"{seconds:.2f}"
        folder = "contract" if path.parent == CASES else path.parent.name
        name = path.stem if folder == "examples" else f"{folder}/{path.stem}"
        rows.append((name, shown, f"{cpu:.2f}", f"{min(seconds, args.cap) / BUDGET:.0%}", status))
        if not args.markdown:
            print(f"{name:48} {shown:>8} {rows[-1][2]:>6} {rows[-1][3]:>6}  {status}", flush=True)
    if args.markdown:
        print("| model | seconds | processor s | of 5 s | |\n|---|---:|---:|---:|---|")
        for name, shown, cpu, ratio, status in rows:
            print(f"| {name} | {shown} | {cpu} | {ratio} | {'' if status == 'ok' else status} |")
    worst = max(rows, key=lambda r: float(r[1].lstrip(">")))
    print(f"slowest: {worst[0]} {worst[1]} s ({worst[3]} of the budget); "
          f"load average at end: {os.getloadavg()[0]:.1f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
