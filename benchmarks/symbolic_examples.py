"""Time a whole `kinematika solve MODEL --symbolic --json` (start-up included) on every model.

Every shipped example, the symbolic contract cases and the construction-built models of
`benchmarks/models/symbolic/` must answer with `--symbolic` in under 5 s (issues 12, 16).
Run:  .venv/bin/python benchmarks/symbolic_examples.py [--repeat 1] [--cap 60] [--markdown]
Prints one row per model (best of the repeats, whole process) with its ratio to the 5 s
budget; a model still running at `--cap` seconds is stopped and shown as `>cap`.
"""
from __future__ import annotations

import argparse
import json
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
    if CASES.is_dir():
        for path in sorted(CASES.glob("*.yaml")):
            expect = path.with_suffix("").with_suffix(".expect.json")
            if expect.exists() and json.loads(expect.read_text()).get("symbolic"):
                out.append(path)
    return out


def time_solve(path: Path, repeat: int, cap: float) -> tuple[float, str]:
    exe = Path(sys.executable).parent / "kinematika"
    best, status = float("inf"), "ok"
    for _ in range(repeat):
        start = time.perf_counter()
        try:
            done = subprocess.run([str(exe), "solve", str(path), "--symbolic", "--json"],
                                  capture_output=True, text=True, timeout=cap)
        except subprocess.TimeoutExpired:
            return cap, "timeout"
        best = min(best, time.perf_counter() - start)
        if done.returncode != 0:
            status = "error: " + (done.stdout or done.stderr).strip()[:80]
        elif json.loads(done.stdout).get("symbolic") is not True:
            status = "not symbolic"
    return best, status


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--cap", type=float, default=60.0, help="seconds before a run is stopped")
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    args = ap.parse_args()
    rows = []
    for path in models():
        seconds, status = time_solve(path, args.repeat, args.cap)
        shown = f">{seconds:.0f}" if status == "timeout" else f"{seconds:.2f}"
        rows.append((path.stem, shown, f"{min(seconds, args.cap) / BUDGET:.0%}", status))
        if not args.markdown:
            print(f"{path.stem:42} {shown:>8} {rows[-1][2]:>6}  {status}", flush=True)
    if args.markdown:
        print("| model | seconds | of 5 s | |\n|---|---:|---:|---|")
        for name, shown, ratio, status in rows:
            print(f"| {name} | {shown} | {ratio} | {'' if status == 'ok' else status} |")
    worst = max(rows, key=lambda r: float(r[1].lstrip(">")))
    print(f"slowest: {worst[0]} {worst[1]} s ({worst[2]} of the budget)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
