"""Time a whole `kinematika solve MODEL --json` (start-up included) on every symbolic example.

Issue 3's bar: a symbolic solve of any worked example of the course notes takes under 2 s.
Run:  .venv/bin/python benchmarks/symbolic_examples.py [--repeat 3]
Prints one row per example (best of the repeats) and the ratio to the 2 s budget.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BUDGET = 2.0


def symbolic_examples() -> list[Path]:
    """Examples whose answers are formulas (a parameter left as a symbol)."""
    import yaml

    out = []
    for path in sorted((ROOT / "examples").glob("*.yaml")):
        params = (yaml.safe_load(path.read_text()) or {}).get("parameters") or {}
        if any(v is None or (isinstance(v, dict) and (v.get("value") is None or v.get("symbolic")))
               for v in params.values()):
            out.append(path)
    return out


def time_solve(path: Path, repeat: int) -> tuple[float, bool]:
    exe = Path(sys.executable).parent / "kinematika"
    best, ok = float("inf"), True
    for _ in range(repeat):
        start = time.perf_counter()
        done = subprocess.run([str(exe), "solve", str(path), "--json"], capture_output=True, text=True)
        best = min(best, time.perf_counter() - start)
        ok = ok and done.returncode == 0 and json.loads(done.stdout).get("symbolic") is True
    return best, ok


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=3)
    args = ap.parse_args()
    worst = 0.0
    print(f"{'example':42} {'seconds':>8} {'of 2 s':>7}")
    for path in symbolic_examples():
        seconds, ok = time_solve(path, args.repeat)
        worst = max(worst, seconds)
        print(f"{path.stem:42} {seconds:8.2f} {seconds / BUDGET:7.0%}{'' if ok else '  FAILED'}")
    print(f"slowest: {worst:.2f} s ({worst / BUDGET:.0%} of the budget)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
