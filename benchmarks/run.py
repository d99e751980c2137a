"""kinematika's speed next to its peers, in one run: prints a table of times and ratios.

    bash benchmarks/setup.sh                       # once: .venv-bench with the peers
    .venv-bench/bin/python benchmarks/run.py       # about three minutes

Cases: the crank-rocker with a coupler point, an offset slider-crank, a Watt six-bar and a
Jansen leg, a full crank turn in 3600 positions, with positions, velocities and
accelerations of every point and ω, α of every body. In process: kinematika (a prepared
`Sweeper`, and `run_sweep` on a loaded model, analysis included), the closed-form numpy
four-bar written by hand, pylinkage with numba (`step_fast_with_kinematics`) and without
(`step_with_derivatives` with NUMBA_DISABLE_JIT=1, in a child process), and `mechanism`
(four-bar and slider-crank). Whole processes: `kinematika sweep MODEL` against each peer's
script (`peers.py`). Then one instant of chains of 125 to 2000 bodies (sparse path), the
batch axis (100 000 four-bar designs x 360 positions as arrays), exact formulas (every
model with `--symbolic`, and the general four-bar against sympy deriving it by hand), and
last a table of every target of issue 16 with what this run measured.
Times are the best of several repeats; ratios are taken within this run.
"""
from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
import timeit
from pathlib import Path

import numpy as np
import itertools

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

CASES = ("four_bar", "slider_crank", "watt_six_bar", "jansen_leg")
MODELS = {"four_bar": HERE / "models" / "four_bar.yaml", "slider_crank": HERE / "models" / "slider_crank.yaml",
          "watt_six_bar": HERE.parent / "examples" / "watt_six_bar.yaml",
          "jansen_leg": HERE.parent / "examples" / "jansen_leg.yaml"}


def best(fn, repeat: int, number: int = 1) -> float:
    """Best CPU time of `repeat` runs of `number` calls, per call, in seconds (CPU time, so
    that other work on the shared machine counts less than in wall time)."""
    return min(timeit.repeat(fn, number=number, repeat=repeat, timer=time.process_time)) / number


def in_process(n: int, repeat: int, mechanism_n: int) -> dict[str, dict[str, float]]:
    from kinematika import load_model
    from kinematika.sweep import run_sweep
    from kinematika.sweep.run import Sweeper
    from numpy_four_bar import four_bar
    from peers import mechanism_build, mechanism_work, pylinkage_build, pylinkage_work

    out: dict[str, dict[str, float]] = {}
    for case in CASES:
        row = out.setdefault(case, {})
        model = load_model(MODELS[case])
        sweeper = Sweeper(model)
        row["kinematika"] = best(lambda: sweeper.run(steps=n - 1), repeat, 5)
        row["kinematika run_sweep"] = best(lambda: run_sweep(model, steps=n - 1), repeat, 3)
        if case == "four_bar":
            theta = np.radians(90 + np.linspace(0, 360, n))
            row["numpy closed form"] = best(lambda: four_bar(theta), repeat, 5)
            row["kinematika"] = best(lambda: sweeper.run(steps=n - 1), repeat, 5)   # same moment
        linkage, links = pylinkage_build(case, n)
        pylinkage_work(linkage, links, n, fast=True)                              # compile first
        row["pylinkage+numba"] = best(lambda: pylinkage_work(linkage, links, n, fast=True), repeat, 3)
        row["pylinkage"] = child_time("pylinkage-slow", case, n)
        if mechanism_n and case in ("four_bar", "slider_crank"):
            mech = mechanism_build(case, mechanism_n)
            row["mechanism"] = best(lambda: mechanism_work(mech), 1) * n / mechanism_n
    return out


def child_time(tool: str, case: str, n: int) -> float:
    """pylinkage without numba, timed inside a child process started with NUMBA_DISABLE_JIT=1."""
    code = ("import sys, time, timeit; sys.path.insert(0, %r); from peers import *; "
            "lk, links = pylinkage_build(%r, %d); "
            "print(min(timeit.repeat(lambda: pylinkage_work(lk, links, %d, fast=False), number=1, repeat=2, "
            "timer=time.process_time)))"
            % (str(HERE), case, n, n))
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, check=True)
    return float(done.stdout.strip().splitlines()[-1])   # (the child times CPU too)


def whole_process(n: int, repeat: int, mechanism_n: int) -> dict[str, dict[str, float]]:
    """Wall time of whole commands: start-up, model, sweep, output."""
    bindir = Path(sys.executable).parent
    kin = str(bindir / "kinematika")
    peers = str(HERE / "peers.py")
    out: dict[str, dict[str, float]] = {}
    for case in CASES:
        row = out.setdefault(case, {})
        row["kinematika sweep"] = wall([kin, "sweep", str(MODELS[case]), "--steps", str(n - 1)], repeat)
        row["kinematika sweep --json"] = wall([kin, "sweep", str(MODELS[case]), "--steps", str(n - 1),
                                               "--json"], repeat)
        row["pylinkage+numba"] = wall([sys.executable, peers, "pylinkage", case, str(n)], repeat)
        row["pylinkage"] = wall([sys.executable, peers, "pylinkage", case, str(n), "slow"], 1,
                                {"NUMBA_DISABLE_JIT": "1"})
        if mechanism_n and case in ("four_bar", "slider_crank"):
            row["mechanism"] = wall([sys.executable, peers, "mechanism", case, str(mechanism_n)], 1)
    out["(python + numpy import)"] = {"floor": wall([sys.executable, "-c", "import numpy"], repeat)}
    return out


def wall(cmd: list[str], repeat: int, env: dict | None = None) -> float:
    times = []
    for _ in range(repeat + 1):          # the first run warms caches (numba's, the disk's)
        start = time.perf_counter()
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True,
                       env=dict(os.environ, **(env or {})))
        times.append(time.perf_counter() - start)
    return min(times[1:]) if len(times) > 1 else times[0]


def scaling(sizes: list[int], repeat: int) -> list[tuple[int, float, float]]:
    """One instant (velocities and accelerations) of a chain of parallelogram loops."""
    from chain import four_bar_chain
    from kinematika.engine.instant import instantiate
    from kinematika.engine.system import InstantSolver
    from kinematika.model.build import build_model

    rows = []
    for size in sizes:
        model = build_model(four_bar_chain(size))
        inst = instantiate(model, False)
        solve = best(lambda: InstantSolver(inst).solve(), repeat)
        whole = best(lambda: InstantSolver(instantiate(build_model(four_bar_chain(size)), False)).solve(), 2)
        rows.append((len(model.moving_bodies), solve, whole))
    return rows


NEWTON = {"rssr_spatial_four_bar": -60.0, "hooke_joint": 360.0, "spherical_four_bar": 360.0}


def newton_in_process(n: int, repeat: int, general_n: int) -> dict[str, tuple[float, float]]:
    """Per position: the compiled Newton path (a prepared `Sweeper`, n positions) and the
    general one (`general_n` positions, the compiled path switched off)."""
    import kinematika.sweep.compiled as compiled
    from kinematika.sweep.run import Sweeper

    out = {}
    for name, by in NEWTON.items():
        sweeper = Sweeper(HERE.parent / "examples" / f"{name}.yaml")
        fast = best(lambda: sweeper.run(by, n - 1), repeat) / n
        saved = compiled.compiled_sweep
        compiled.compiled_sweep = lambda *args: None
        try:
            general = best(lambda: sweeper.run(by, general_n - 1), 1) / general_n
        finally:
            compiled.compiled_sweep = saved
        out[name] = (fast, general)
    return out


def median_wall(cmd: list[str], repeat: int) -> float:
    """Median wall time of `repeat` runs after one warm-up run."""
    times = []
    for _ in range(repeat + 1):
        start = time.perf_counter()
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        times.append(time.perf_counter() - start)
    return statistics.median(times[1:])


def wall_and_memory(cmd: list[str]) -> tuple[float, float]:
    """Wall time (s) and peak memory (MB) of one process."""
    wall, _, mb = wall_cpu_memory(cmd)
    return wall, mb


def wall_cpu_memory(cmd: list[str]) -> tuple[float, float, float]:
    """Wall time (s), CPU time (s, user + system) and peak memory (MB) of one process."""
    start = time.perf_counter()
    child = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, status, usage = os.wait4(child.pid, 0)
    if status:
        raise RuntimeError(f"{cmd} failed")
    return time.perf_counter() - start, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def start_up_and_output(repeat: int, big_rows: int) -> dict[str, float]:
    """Whole processes where users wait: start-up, one small instant, a sweep with --json
    against a numpy script doing the same work, a very long sweep, large models."""
    from chain import four_bar_chain
    import yaml

    py, kin = sys.executable, str(Path(sys.executable).parent / "kinematika")
    four = str(MODELS["four_bar"])
    out = {"python -c 'import numpy'": median_wall([py, "-c", "import numpy"], repeat),
           "kinematika solve four_bar --json": median_wall(
               [kin, "solve", str(HERE.parent / "examples" / "four_bar.yaml"), "--json"], repeat),
           "numpy script, 3600 positions to JSON": median_wall(
               [py, str(HERE / "numpy_four_bar.py"), "json", "3600"], repeat),
           "kinematika sweep four_bar --steps 3599 --json": median_wall(
               [kin, "sweep", four, "--steps", "3599", "--json"], repeat)}
    if big_rows:
        # the check's output is thrown away, not held: a child forked from a large parent
        # would count the parent's pages in its peak memory
        refused = subprocess.run([kin, "sweep", four, "--steps", str(big_rows - 1), "--json"],
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if refused.returncode == 2:
            refused = subprocess.run([kin, "sweep", four, "--steps", str(big_rows - 1), "--json"],
                                     capture_output=True, text=True)
        if refused.returncode == 2 and "more than a sweep holds" in refused.stdout:
            # issue 12's limit on the values one sweep holds (limits.SWEEP_VALUES)
            out[f"  (refused: {big_rows} rows, over limits.SWEEP_VALUES)"] = float(big_rows)
            big_rows = int(refused.stdout.split("take at most ")[1].split()[0]) + 1
        t, mb = wall_and_memory([kin, "sweep", four, "--steps", str(big_rows - 1), "--json"])
        out[f"kinematika sweep four_bar --steps {big_rows - 1} --json"] = t
        out["  (peak memory, MB)"] = mb
    with tempfile.TemporaryDirectory() as folder:
        for bodies in (1000, 10000):
            path = Path(folder) / f"chain{bodies}.yaml"
            path.write_text(yaml.safe_dump(four_bar_chain(bodies), sort_keys=False))
            cmd = [kin, "solve", str(path), "--json"]
            wall_cpu_memory(cmd)                                   # warm the disk cache
            runs = [wall_cpu_memory(cmd) for _ in range(max(1, repeat // 2))]
            out[f"kinematika solve chain of {bodies} bodies --json"] = statistics.median(r[0] for r in runs)
            out[f"  (CPU time, chain of {bodies})"] = statistics.median(r[1] for r in runs)
    return out


def batch(designs: int, chunk: int = 64) -> tuple[float, int]:
    """CPU seconds for `designs` four-bars (crank a, rocker c varied on a grid) over 361
    positions each, by the batch kernel in chunks of `chunk` designs (explore's size), and
    how many it solved."""
    from explore import MODEL              # the design-study benchmark's four-bar family
    from kinematika.api import as_model
    from kinematika.sweep.batch import BatchSweeper

    sweeper = BatchSweeper(as_model(MODEL, "yaml"), ["a", "c"], steps=360)
    side = int(np.ceil(np.sqrt(designs)))
    a, c = (v.ravel()[:designs] for v in np.meshgrid(np.linspace(0.5, 1.5, side), np.linspace(2, 4, side)))
    sweeper.run({"a": a[:chunk], "c": c[:chunk]})                # warm
    solved = 0
    start = time.process_time()
    for i in range(0, designs, chunk):
        solved += int(sweeper.run({"a": a[i:i + chunk], "c": c[i:i + chunk]}).drawn.sum())
    return time.process_time() - start, solved


def symbolic(cap: float, sympy_cap: float) -> dict:
    """Whole processes: every model with `--symbolic` (the slowest, how many over 5 s), and
    the general four-bar by kinematika and by sympy (`peers.py sympy`)."""
    from symbolic_examples import BUDGET, models, time_solve

    times, failed = {}, []
    for path in models():
        seconds, _, status = time_solve(path, 1, cap)
        times[path.stem] = seconds
        if status != "ok":
            why = "a limit error" if '"kind":"limit"' in status else status[:60]
            failed.append(f"{path.stem} ({why})")
    general = times.get("four_bar_general", float("nan"))
    start = time.perf_counter()
    try:
        subprocess.run([sys.executable, str(HERE / "peers.py"), "sympy", "four_bar_general", "0"],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=sympy_cap, check=True)
        by_sympy, capped = time.perf_counter() - start, False
    except subprocess.TimeoutExpired:
        by_sympy, capped = sympy_cap, True
    slowest = max(times, key=times.get)
    return {"models": len(times), "over": sum(t > BUDGET for t in times.values()), "slowest": slowest,
            "failed": failed, "over_names": [k for k, t in times.items() if t > BUDGET],
            "slowest_s": times[slowest], "general": general, "sympy": by_sympy, "sympy_capped": capped}


def compile_bytecode() -> None:
    """kinematika's modules compiled to bytecode once, as `pip install` does: with
    PYTHONDONTWRITEBYTECODE set (some shells and containers set it) an editable install would
    otherwise compile every module from source at every start, which is not what users wait for."""
    import kinematika

    subprocess.run([sys.executable, "-m", "compileall", "-q", str(Path(kinematika.__file__).parent)],
                   check=True, stdout=subprocess.DEVNULL)


def ms(t: float) -> str:
    return f"{t * 1e3:.3g} ms" if t < 1 else f"{t:.3g} s"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--positions", type=int, default=3600)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--mechanism-positions", type=int, default=360,
                        help="positions for `mechanism` (its time is scaled to --positions); 0 skips it")
    parser.add_argument("--big-rows", type=int, default=360_000,
                        help="rows of the long `sweep --json` run (0 skips it)")
    parser.add_argument("--designs", type=int, default=100_000, help="four-bar designs of the batch (0 skips it)")
    parser.add_argument("--symbolic-cap", type=float, default=60.0,
                        help="seconds before a `--symbolic` run is stopped; 0 skips exact formulas")
    parser.add_argument("--sympy-cap", type=float, default=120.0, help="seconds before sympy's derivation is stopped")
    args = parser.parse_args()
    n = args.positions
    load = os.getloadavg()
    print(f"# kinematika benchmark: {n} positions per sweep, best of {args.repeat}\n")
    print(f"load average at the start: {' '.join(f'{x:.1f}' for x in load)} ({os.cpu_count()} cores)\n")
    compile_bytecode()
    targets: list[tuple[str, str, str, bool | str | None]] = []  # (target, measured, ratio to a peer, met)
    outputs = start_up_and_output(args.repeat, args.big_rows)
    print("## Where users wait: whole processes (median wall time)\n")
    print("| process | time | ratio |")
    print("|---|---|---|")
    floor = outputs["python -c 'import numpy'"]
    script = outputs["numpy script, 3600 positions to JSON"]
    for what, t in outputs.items():
        if what.startswith("  (peak"):
            print(f"| {what.strip()} | {t:.0f} MB | |")
            continue
        if what.startswith("  (CPU"):
            print(f"| {what.strip()} | {ms(t)} | |")
            continue
        if what.startswith("  (refused"):
            print(f"| {what.strip()} | — | |")
            continue
        ratio = ""
        if what.startswith("kinematika solve four_bar"):
            ratio = f"{t / floor:.2f}× `import numpy`"
            targets.append(("`solve four_bar --json` ≤ 1.5× `python -c 'import numpy'`", ms(t), ratio, t / floor <= 1.5))
        elif what == "kinematika sweep four_bar --steps 3599 --json":
            ratio = f"{t / script:.2f}× the numpy script"
            targets.append(("`sweep --json`, 3600 positions ≤ 1.5× the numpy script", ms(t), ratio, t / script <= 1.5))
        elif what.startswith("kinematika sweep four_bar"):
            rows_run = int(what.split()[4]) + 1
            ratio = f"{t / script:.2f}× the numpy script (3600 positions)"
            refused = any(k.startswith("  (refused") for k in outputs)
            targets.append(("`sweep --json`, 360 000 positions < 2 s",
                            (f"refused by the 5 M-value limit; {rows_run} rows (the most allowed): " if refused else "")
                            + ms(t), ratio, None if refused else t < 2))
        elif what.startswith("kinematika solve chain"):
            bodies = int(what.split()[4])
            cpu = outputs[f"  (CPU time, chain of {bodies})"]
            limit = 0.3 if bodies == 1000 else 3.0
            ratio = f"{t / floor:.1f}× `import numpy`"
            targets.append((f"one instant of a {bodies}-body chain < {limit:g} s (whole process)",
                            f"{ms(t)} wall, {ms(cpu)} CPU", ratio,
                            True if t < limit else "met in CPU time, not in wall time under this load"
                            if cpu < limit else False))
        print(f"| {what} | {ms(t)} | {ratio} |")
    if args.big_rows:
        mb = next(v for k, v in outputs.items() if k.startswith("  (peak"))
        refused = any(k.startswith("  (refused") for k in outputs)
        targets.append(("`sweep --json`, 360 000 positions < 400 MB",
                        ("at the most allowed rows (above): " if refused else "") + f"{mb:.0f} MB", "",
                        None if refused else mb < 400))
    print()
    inner = in_process(n, args.repeat, args.mechanism_positions)
    print("## In process, CPU time (one sweep: positions, velocities, accelerations of every point; "
          "ω, α of every body)\n")
    tools = ["kinematika", "kinematika run_sweep", "numpy closed form", "pylinkage+numba", "pylinkage", "mechanism"]
    print("| case | " + " | ".join(tools).replace("| pylinkage |", "| pylinkage, no numba |") + " |")
    print("|---" * (len(tools) + 1) + "|")
    for case, row in inner.items():
        cells = [f"{ms(row[t])} ({row[t] / n * 1e6:.3g} µs/pos)" if t in row else "—" for t in tools]
        print(f"| {case} | " + " | ".join(cells) + " |")
    print("\nRatios (same run):")
    for case, row in inner.items():
        k = row["kinematika"]
        parts = []
        if "numpy closed form" in row:
            parts.append(f"kinematika / numpy closed form = {k / row['numpy closed form']:.2f}× "
                         f"(run_sweep incl. analysis: {row['kinematika run_sweep'] / row['numpy closed form']:.2f}×)")
        parts.append(f"pylinkage+numba / kinematika = {row['pylinkage+numba'] / k:.1f}×")
        parts.append(f"pylinkage without numba / kinematika = {row['pylinkage'] / k:.0f}×")
        if "mechanism" in row:
            parts.append(f"mechanism / kinematika = {row['mechanism'] / k:.0f}×")
        print(f"- {case}: " + "; ".join(parts))
    newton = newton_in_process(n, args.repeat, min(n, 360))
    closed = inner["four_bar"]["numpy closed form"] / n
    numba = inner["four_bar"]["pylinkage+numba"] / n
    print("\n## The Newton path (spatial linkages, in process, CPU time per position)\n")
    print("| mechanism | compiled | general path | speed-up | compiled / numpy closed-form four-bar | "
          "compiled / pylinkage+numba four-bar |")
    print("|---|---|---|---|---|---|")
    for name, (fast, general) in newton.items():
        print(f"| {name} | {fast * 1e6:.3g} µs | {general * 1e6:.3g} µs | {general / fast:.0f}× | "
              f"{fast / closed:.0f}× | {fast / numba:.0f}× |")
        targets.append((f"compiled Newton path, {name} < 20 µs a position", f"{fast * 1e6:.3g} µs",
                        f"{fast / closed:.0f}× numpy closed form, {fast / numba:.0f}× pylinkage+numba (planar four-bar)",
                        fast < 20e-6))
    outer = whole_process(n, max(2, args.repeat // 2), args.mechanism_positions)
    print("\n## Whole process (start-up included; `mechanism` at --mechanism-positions)\n")
    tools = ["kinematika sweep", "kinematika sweep --json", "pylinkage+numba", "pylinkage", "mechanism"]
    print("| case | " + " | ".join(tools).replace("| pylinkage |", "| pylinkage, no numba |") + " |")
    print("|---" * (len(tools) + 1) + "|")
    for case, row in outer.items():
        if case.startswith("("):
            continue
        print(f"| {case} | " + " | ".join(ms(row[t]) if t in row else "—" for t in tools) + " |")
    floor = outer["(python + numpy import)"]["floor"]
    print(f"\n`python -c 'import numpy'` alone: {ms(floor)}")
    for case, row in outer.items():
        if case.startswith("("):
            continue
        peers = {t: v for t, v in row.items() if not t.startswith("kinematika")}
        fastest = min(peers, key=peers.get)
        print(f"- {case}: fastest peer {fastest} {ms(peers[fastest])} / kinematika sweep "
              f"{ms(row['kinematika sweep'])} = {peers[fastest] / row['kinematika sweep']:.2f}×")
    print("\n## One instant of a large planar mechanism (chain of four-bar loops, sparse path, in process, CPU time)\n")
    print("| moving bodies | solve (velocity + acceleration) | with model build | per body |")
    print("|---|---|---|---|")
    rows = scaling([125, 250, 500, 1000, 2000], args.repeat)
    for bodies, solve, whole in rows:
        print(f"| {bodies} | {ms(solve)} | {ms(whole)} | {solve / bodies * 1e6:.1f} µs |")
    growth = [b2[1] / b1[1] for b1, b2 in itertools.pairwise(rows)]
    print("\nGrowth of the solve time per doubling of the bodies: " + ", ".join(f"{g:.2f}×" for g in growth)
          + " (2.00× is linear)")
    if args.designs:
        cpu, solved = batch(args.designs)
        positions = args.designs * 361
        print(f"\n## The batch axis (in process, one core)\n\n{args.designs} four-bar designs (crank and rocker "
              f"varied) × 361 positions by the batch kernel: {ms(cpu)} CPU, {args.designs / cpu:.0f} designs "
              f"per CPU-second, {cpu / positions * 1e9:.0f} ns a design-position ({solved} designs assembled); "
              f"the numpy closed form takes {closed * 1e9:.0f} ns a position of one design, "
              f"pylinkage+numba {numba * 1e9:.0f} ns")
        targets.append((f"{args.designs} four-bar designs × 361 positions run as arrays",
                        f"{ms(cpu)} CPU ({args.designs / cpu:.0f} designs/s)",
                        f"{cpu / positions / closed:.2f}× numpy closed form, "
                        f"{numba * positions / cpu:.0f}× faster than pylinkage+numba (per position)", None))
    if args.symbolic_cap:
        found = symbolic(args.symbolic_cap, args.sympy_cap)
        sympy_shown = (">" if found["sympy_capped"] else "") + ms(found["sympy"])
        print(f"\n## Exact formulas (whole processes, `solve --symbolic --json`)\n\n"
              f"{found['models']} models (examples, symbolic cases, benchmarks/models/symbolic): slowest "
              f"{found['slowest']} {ms(found['slowest_s'])}, {found['over']} over 5 s "
              f"({', '.join(found['over_names']) or 'none'}; failed or stopped: {', '.join(found['failed']) or 'none'}). "
              f"The general four-bar "
              f"(a, b, c, d, θ, w all symbols): kinematika {ms(found['general'])}, sympy deriving it by hand "
              f"(peers.py sympy: loop solved, results simplified) {sympy_shown}")
        targets.append(("every model answers with `--symbolic` within 5 s",
                        f"slowest {found['slowest']} {ms(found['slowest_s'])}, {found['over']} of "
                        f"{found['models']} over"
                        + (f"; refused: {', '.join(found['failed'])}" if found["failed"] else ""),
                        "", found["over"] == 0 and not found["failed"]))
        ratio = found["sympy"] / found["general"]
        targets.append(("general four-bar, exact ω, α (no target: against sympy)", ms(found["general"]),
                        f"sympy {sympy_shown} = {'>' if found['sympy_capped'] else ''}{ratio:.0f}× kinematika", None))
    targets.append(("drawing: slider move to updated picture < 20 ms (the page, in Chromium)",
                    "not measured here: tests/web prints it (`slider to painted frame`)", "", None))
    end = os.getloadavg()
    print(f"\n## Issue 16's targets: target / measured (load average {load[0]:.1f} at the start, "
          f"{end[0]:.1f} at the end, {os.cpu_count()} cores)\n")
    print("| target | measured | ratio | |")
    print("|---|---|---|---|")
    for target, measured, ratio, met in targets:
        verdict = "" if met is None else met if isinstance(met, str) else "met" if met else "**not met**"
        print(f"| {target} | {measured} | {ratio} | {verdict} |")


if __name__ == "__main__":
    main()
