"""Whole processes where a user waits for start-up, side by side in one run (issues 31 and 34):

- one instant of a 1000-body chain (`chain.py`), `kinematika solve CHAIN --json`, against
  `python -c "import numpy"` (issue 34's target: at most 2×);
- a four-bar `kinematika sweep --steps 359 --json` (360 positions) against the numpy script
  doing the same work, `numpy_four_bar.py json 360` (target: at most 1.5×);
- `kinematika solve four_bar.yaml --json` against `import numpy` (issue 16's: at most 1.5×);
- `kinematika simulate` of the tractor and trailer over 60 s (issue 31's target: under a
  second on a quiet machine): `tractor_trailer_turning.yaml` (301 rows, the whole minute)
  and `tractor_trailer.yaml --time 60` (200 steps; its front wheel is driven along a fixed
  direction, so the motion reaches a dead point at t = 3.65 s and stops there, status 2).

    .venv/bin/python benchmarks/start_up.py                 # 9 rounds, about a minute
    .venv/bin/python benchmarks/start_up.py --rounds 15 --only chain sweep
    git archive OLD src | tar -x -C /tmp/old && \
    .venv/bin/python benchmarks/start_up.py --against /tmp/old/src   # before and after, paired

Each round runs every process once, in an order shuffled per round (seeded), so that each
ratio is taken between runs made moments apart under the same load (paired runs); the
table gives the median of each ratio over the rounds, and the median wall and CPU (user +
system) times. One warm-up round is not counted. kinematika's modules are compiled to
bytecode first, as `pip install` does (PYTHONDONTWRITEBYTECODE would otherwise make every
start compile them). The load average is printed at the start and the end: on the shared
2-core machine, absolute times move with it by a factor of two or more; the ratios much less.

`--against SRC` runs every kinematika process a second time in each round with another
checkout's `src` first on PYTHONPATH (an older commit, say), and adds a table of both
with the median of the paired ratios after / before.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent


def run(cmd: list[str], ok: tuple[int, ...] = (0,), env: dict | None = None) -> tuple[float, float]:
    """Wall time and CPU time (user + system, s) of one whole process."""
    start = time.perf_counter()
    child = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) not in ok:
        raise RuntimeError(f"{' '.join(cmd)} ended with status {os.waitstatus_to_exitcode(status)}")
    return wall, usage.ru_utime + usage.ru_stime


def processes(folder: Path) -> dict[str, tuple[list[str], tuple[int, ...]]]:
    """Each process measured: its command line and the exit statuses it may end with."""
    import yaml

    sys.path.insert(0, str(HERE))
    from chain import four_bar_chain

    chain = folder / "chain1000.yaml"
    chain.write_text(yaml.safe_dump(four_bar_chain(1000), sort_keys=False), encoding="utf-8")
    chain_json = folder / "chain1000.json"      # the same model as JSON: what reading YAML costs
    chain_json.write_text(json.dumps(four_bar_chain(1000)), encoding="utf-8")
    py = sys.executable
    kin = str(Path(py).parent / "kinematika")
    return {
        "numpy": ([py, "-c", "import numpy"], (0,)),
        "chain": ([kin, "solve", str(chain), "--json"], (0,)),
        "chain-json": ([kin, "solve", str(chain_json), "--json"], (0,)),
        "solve": ([kin, "solve", str(ROOT / "examples" / "four_bar.yaml"), "--json"], (0,)),
        "script": ([py, str(HERE / "numpy_four_bar.py"), "json", "360"], (0,)),
        "sweep": ([kin, "sweep", str(HERE / "models" / "four_bar.yaml"), "--steps", "359", "--json"], (0,)),
        "simulate": ([kin, "simulate", str(ROOT / "examples" / "tractor_trailer_turning.yaml"), "--time", "60"],
                     (0,)),
        "stopping": ([kin, "simulate", str(ROOT / "examples" / "tractor_trailer.yaml"), "--time", "60"], (2,)),
    }


# (row, process, its peer, the target ratio or None, an absolute target in seconds or None)
TABLE = [
    ("python -c 'import numpy'", "numpy", None, None, None),
    ("kinematika solve chain of 1000 bodies --json", "chain", "numpy", 2.0, None),
    ("the same chain written as JSON (not the target: what reading YAML costs)", "chain-json", "numpy", None, None),
    ("kinematika solve four_bar --json", "solve", "numpy", 1.5, None),
    ("numpy script, 360 positions to JSON", "script", None, None, None),
    ("kinematika sweep four_bar --steps 359 --json", "sweep", "script", 1.5, None),
    ("kinematika simulate tractor_trailer_turning --time 60", "simulate", "numpy", None, 1.0),
    ("kinematika simulate tractor_trailer --time 60 (stops at 3.65 s)", "stopping", "numpy", None, 1.0),
]
PEER_NAMES = {"numpy": "`import numpy`", "script": "the numpy script"}


def compile_bytecode(against: str | None = None) -> None:
    """kinematika's modules compiled to bytecode once, as `pip install` does (and those of
    the `--against` tree)."""
    import kinematika

    for tree in filter(None, (str(Path(kinematika.__file__).parent), against)):
        subprocess.run([sys.executable, "-m", "compileall", "-q", tree], check=True, stdout=subprocess.DEVNULL)


BEFORE = "@before"      # the suffix of a process run with the `--against` tree


def measure(names: list[str], rounds: int, seed: int, against: str | None = None
            ) -> dict[str, list[tuple[float, float]]]:
    """`rounds` paired rounds (after one warm-up round): each process once per round, in a
    shuffled order (with `against`, each kinematika process also with that tree first on
    PYTHONPATH); every run's (wall, CPU)."""
    old = None
    if against:
        old = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, (against, os.environ.get("PYTHONPATH")))))
        names = names + [n + BEFORE for n in names if n not in PEER_NAMES]
    times: dict[str, list[tuple[float, float]]] = {n: [] for n in names}
    shuffle = random.Random(seed)
    with tempfile.TemporaryDirectory() as folder:
        table = processes(Path(folder))
        for k in range(rounds + 1):
            order = list(names)
            shuffle.shuffle(order)
            for name in order:
                cmd, ok = table[name.removesuffix(BEFORE)]
                result = run(cmd, ok, old if name.endswith(BEFORE) else None)
                if k:
                    times[name].append(result)
    return times


def report(times: dict[str, list[tuple[float, float]]]) -> list[str]:
    """The markdown table: median times, and the median over rounds of each paired ratio."""
    lines = ["| process | wall (median) | CPU (median) | wall ratio (median of paired) | CPU ratio | target | met |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for label, name, peer, target, seconds in TABLE:
        if name not in times:
            continue
        runs = times[name]
        wall = statistics.median(r[0] for r in runs)
        cpu = statistics.median(r[1] for r in runs)
        ratio = cpu_ratio = ""
        goal = met = ""
        if peer is not None and peer in times:
            pairs = list(zip(runs, times[peer]))
            wall_r = statistics.median(a[0] / b[0] for a, b in pairs)
            cpu_r = statistics.median(a[1] / b[1] for a, b in pairs)
            ratio, cpu_ratio = f"{wall_r:.2f}× {PEER_NAMES[peer]}", f"{cpu_r:.2f}×"
            if target is not None:
                goal, met = f"≤ {target:g}× {PEER_NAMES[peer]}", "met" if wall_r <= target else "not met"
        if seconds is not None:
            goal, met = f"< {seconds:g} s (quiet machine)", "met" if wall < seconds else "not met (here)"
        lines.append(f"| {label} | {wall * 1e3:.0f} ms | {cpu * 1e3:.0f} ms | {ratio} | {cpu_ratio} | {goal} | {met} |")
    return lines


def report_against(times: dict[str, list[tuple[float, float]]]) -> list[str]:
    """Before (the `--against` tree) and after (this one), paired: medians and the median of
    the paired ratios after / before, and each one's paired ratio to its peer."""
    lines = ["| process | before: wall (CPU) | after: wall (CPU) | after / before, wall (CPU) | "
             "before / peer | after / peer |", "| --- | --- | --- | --- | --- | --- |"]
    for label, name, peer, _, _ in TABLE:
        if name + BEFORE not in times:
            continue
        after, before = times[name], times[name + BEFORE]
        cells = []
        for runs in (before, after):
            cells.append(f"{statistics.median(r[0] for r in runs) * 1e3:.0f} ms "
                         f"({statistics.median(r[1] for r in runs) * 1e3:.0f} ms)")
        wall = statistics.median(a[0] / b[0] for a, b in zip(after, before))
        cpu = statistics.median(a[1] / b[1] for a, b in zip(after, before))
        cells.append(f"{wall:.2f} ({cpu:.2f})")
        for runs in (before, after):
            if peer in times:
                r = statistics.median(a[0] / b[0] for a, b in zip(runs, times[peer]))
                cells.append(f"{r:.2f}× {PEER_NAMES[peer]}")
            else:
                cells.append("")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--rounds", type=int, default=9)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--only", nargs="+", choices=["chain", "chain-json", "solve", "sweep", "simulate", "stopping"],
                        help="measure only these (with their peers)")
    parser.add_argument("--against", help="another checkout's src folder: each kinematika process run "
                        "with it too, paired (before and after)")
    args = parser.parse_args()
    names = [name for _, name, _, _, _ in TABLE]
    if args.only:
        peers = {peer for _, name, peer, _, _ in TABLE if name in args.only and peer}
        names = [n for n in names if n in args.only or n in peers]
    compile_bytecode(args.against)
    start = os.getloadavg()
    times = measure(names, args.rounds, args.seed, args.against)
    end = os.getloadavg()
    print(f"{args.rounds} paired rounds on {os.cpu_count()} cores; load average {start[0]:.2f} at the start, "
          f"{end[0]:.2f} at the end\n")
    print("\n".join(report(times)))
    if args.against:
        print(f"\nBefore: {args.against} first on PYTHONPATH; after: this checkout.\n")
        print("\n".join(report_against(times)))


if __name__ == "__main__":
    main()
