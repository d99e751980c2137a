"""Design studies at scale: designs per second, and path synthesis against pylinkage's optimiser.

    .venv/bin/python benchmarks/explore.py throughput [--designs 100000]
    .venv-bench/bin/python benchmarks/explore.py synthesis [--budget 20]

`throughput`: `kinematika explore` on the benchmark four-bar (ground 4, crank 1, coupler
4, rocker 3, coupler point P) varying crank and rocker, 360 positions a design, metrics
transmission, range:rocker and peak_speed:P, written to Parquet: in this process (one
core), and on a local Dask cluster of 2 worker processes (start-up included and
excluded). Scaling efficiency = (rate on 2 workers / rate on 1) / 2.

`synthesis`: the same path-synthesis problem for both tools — choose crank, coupler and
rocker lengths so that P passes through 7 points of the benchmark four-bar's own coupler
curve (taken between the sweep's positions), objective the largest distance from a
target to P's path (360 positions a cycle) — kinematika's differential evolution over
the batch kernel against pylinkage's particle swarm (`particle_swarm_optimization`, its
cycle simulated by `Linkage.step`). Reported: the time each takes to bring the error
below 1e-2 and 1e-3, and the best error each reaches within the same time budget.
The machine is shared: compare ratios taken within one run.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
import contextlib

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "src"))

MODEL = """
name: Benchmark four-bar family
parameters: {g: 4, a: 1, b: 4, c: 3, theta: deg(90)}
points:
  O2: [0, 0]
  O4: [g, 0]
  A: {from: O2, distance: a, angle: theta}
  B: {circles: [[A, b], [O4, c]], side: left}
  P: {frame: [A, B], at: [2, 1]}
bodies: {ground: [O2, O4], crank: [O2, A], coupler: [A, B, P], rocker: [O4, B]}
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [ground, rocker], at: O4}
drivers: [{omega: crank, value: 10, alpha: 0}]
"""
METRICS = ["transmission", "range:rocker", "peak_speed:P"]
BOUNDS = {"a": (0.5, 1.5), "b": (3.0, 5.0), "c": (2.0, 4.0)}
THRESHOLDS = (1e-2, 1e-3)


# throughput ------------------------------------------------------------------------------------
def throughput(designs: int) -> None:
    from kinematika.explore.study import make_study, write_study

    side = round(math.sqrt(designs))
    with tempfile.TemporaryDirectory() as tmp:
        model = Path(tmp) / "four_bar.yaml"
        model.write_text(MODEL)
        study = make_study(model, ["a=0.5:1.5", "c=2:4"], METRICS, grid=side)
        count = study.designs.count
        rows = {}
        cpu, start = time.process_time(), time.perf_counter()
        write_study(study, Path(tmp) / "one.parquet", workers=1)
        rows["1 core (this process)"] = (time.perf_counter() - start, time.process_time() - cpu)
        start = time.perf_counter()
        write_study(study, Path(tmp) / "embedded.parquet", workers=2)
        rows["embedded local cluster, 2 workers (start-up included)"] = (time.perf_counter() - start, math.nan)
        rows["local cluster, 2 workers (started, warm)"] = _warm_cluster(study, Path(tmp))
    wall1, cpu1 = rows["1 core (this process)"]
    print(f"{count} four-bar designs x 361 positions, metrics {', '.join(METRICS)}, Parquet output "
          f"(load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores)")
    for label, (wall, cpu) in rows.items():
        per_cpu = f"{count / cpu:>8.0f} designs per CPU-second" if math.isfinite(cpu) else ""
        print(f"  {label:<56} {count / wall:>8.0f} designs/s ({count * 361 / wall / 1e6:5.2f} M positions/s)"
              f"  {per_cpu}")
    for label, (wall, cpu) in list(rows.items())[1:]:
        print(f"  scaling efficiency, {label}: {wall1 / wall / 2:.0%} in wall time"
              + (f"; designs per worker CPU-second / one process's: {cpu1 / cpu:.0%}"
                 if math.isfinite(cpu) else ""))


def _warm_cluster(study, folder: Path) -> tuple[float, float]:
    """Wall time and the workers' CPU time once the workers are up and prepared (the client's and
    scheduler's share, mostly waiting, is printed apart)."""
    from dask.distributed import Client, LocalCluster

    from kinematika.explore.study import run_chunk, write_study

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                      silence_logs=40) as cluster, Client(cluster) as client:
        client.run(lambda: run_chunk(study, 0) and None)                  # warm both workers
        before, here = sum(client.run(time.process_time).values()), time.process_time()
        start = time.perf_counter()
        write_study(study, folder / "warm.parquet", scheduler=client)
        wall = time.perf_counter() - start
        workers = sum(client.run(time.process_time).values()) - before
    print(f"  (client and scheduler: {time.process_time() - here:.2f} CPU-s; workers: {workers:.2f} CPU-s)")
    return wall, workers


# synthesis -------------------------------------------------------------------------------------
def targets() -> np.ndarray:
    """7 points of the benchmark four-bar's coupler curve, between the sweep's positions."""
    sys.path.insert(0, str(ROOT))
    from tests.sweep.models import four_bar_closed_form

    angles = np.radians(90 + np.array([10.5, 60.3, 115.7, 170.2, 220.9, 275.4, 330.6]))
    ex = four_bar_closed_form(angles, 4.0, 1.0, 4.0, 3.0, 1.0, 10.0, 0.0, (2.0, 1.0))
    return ex["P"][0] + 1j * ex["P"][1]


def path_error(path: np.ndarray, points: np.ndarray) -> float:
    """The largest distance from a target to the polyline through the path's positions."""
    from kinematika.explore.metrics import path_error as batch

    return float(batch(path[None, :], points)[0])


def kinematika_synthesis(budget: float, seed: int) -> dict:
    from kinematika.explore.synthesis import synthesize
    from kinematika.explore.synthesis.task import make_task

    pts = targets()
    text = "".join(f"{float(p.real)!r},{float(p.imag)!r}\n" for p in pts)
    vary = [f"{k}={lo}:{hi}" for k, (lo, hi) in BOUNDS.items()]
    task = make_task("path", "t.csv", text, "--target", point="P")
    start = time.perf_counter()
    result = synthesize(MODEL, vary, task, population=45, generations=None, seed=seed, seconds=budget)
    wall = time.perf_counter() - start
    return {"history": result.history, "best": result.errors[0], "design": result.designs[0],
            "evaluated": result.evaluated, "wall": wall}


class _Stop(Exception):
    pass


def pylinkage_synthesis(budget: float, seed: int) -> dict:
    """pylinkage's particle swarm on the same problem (a full cycle of 360 steps a design)."""
    import pylinkage as pl

    pts = targets()
    o2, o4 = pl.Ground(0.0, 0.0, name="O2"), pl.Ground(4.0, 0.0, name="O4")
    crank = pl.Crank(anchor=o2, radius=1.0, angular_velocity=2 * math.pi / 360, initial_angle=math.pi / 2)
    b = pl.RRRDyad(crank.output, o4, distance1=4.0, distance2=3.0, x=0.0, y=0.0, name="B")
    b_xy = _circle_meet((0.0, 1.0), 4.0, (4.0, 0.0), 3.0)
    b.x, b.y = b_xy
    p = pl.FixedDyad(crank.output, b, distance=math.sqrt(5), angle=math.atan2(1, 2), name="P")
    linkage = pl.Linkage([o2, o4, crank, b, p], name="four_bar")
    fixed = list(linkage.get_constraints())
    init = linkage.get_coords()
    record: list[tuple[float, float]] = []
    best = [math.inf]
    count = [0]
    start = time.perf_counter()

    def fitness(linkage, params, init_pos=None):
        if time.perf_counter() - start > budget:
            raise _Stop
        linkage.set_coords(init)
        constraints = list(fixed)
        constraints[0], constraints[1], constraints[2] = params       # crank, coupler, rocker
        linkage.set_constraints(constraints)
        count[0] += 1
        try:
            loci = np.array([[complex(*xy) for xy in frame] for frame in linkage.step(iterations=360)])
        except pl.UnbuildableError:
            return math.inf
        path = np.append(loci[:, -1], loci[0, -1])
        err = path_error(path, pts)
        if err < best[0]:
            best[0] = err
            record.append((time.perf_counter() - start, err))
        return err

    lo, hi = zip(*BOUNDS.values())
    np.random.seed(seed)
    with contextlib.suppress(_Stop):
        pl.particle_swarm_optimization(fitness, linkage, dimensions=3, bounds=(lo, hi), n_particles=45,
                                       iterations=100_000, order_relation=min, verbose=False)
    return {"history": record, "best": best[0], "evaluated": count[0], "wall": time.perf_counter() - start}


def _circle_meet(p, r1, q, r2):
    dx, dy = q[0] - p[0], q[1] - p[1]
    d2 = dx * dx + dy * dy
    f = (r1 * r1 - r2 * r2 + d2) / (2 * d2)
    h = math.sqrt(r1 * r1 / d2 - f * f)
    return (p[0] + f * dx - h * dy, p[1] + f * dy + h * dx)


def _best_at(history: list[tuple[float, float]], seconds: float) -> float:
    return min((e for t, e in history if t <= seconds), default=math.nan)


def _time_to(history: list[tuple[float, float]], threshold: float) -> float:
    return next((t for t, e in history if e <= threshold), math.nan)


def synthesis(budget: float, seed: int) -> None:
    runs = {"kinematika (differential evolution, batch kernel)": kinematika_synthesis(budget, seed),
            "pylinkage (particle swarm, Linkage.step)": pylinkage_synthesis(budget, seed)}
    print(f"path synthesis of the benchmark four-bar (crank, coupler, rocker), 7 targets, 360 positions "
          f"a cycle, {budget:g} s budget, seed {seed}")
    for name, r in runs.items():
        times = ", ".join(f"error < {th:g} after {_time_to(r['history'], th):.3g} s" for th in THRESHOLDS)
        print(f"  {name:<52} best error {r['best']:.3g}; {times}; "
              f"{r['evaluated']} designs ({r['evaluated'] / r['wall']:.0f}/s)")
    k, p = runs.values()
    for t in (1.0, 2.0, 5.0, budget):
        print(f"  best error after {t:g} s: kinematika {_best_at(k['history'], t):.3g}, "
              f"pylinkage {_best_at(p['history'], t):.3g}")
    for th in THRESHOLDS:
        tk, tp = _time_to(k["history"], th), _time_to(p["history"], th)
        print(f"  time to error < {th:g}: pylinkage / kinematika = {tp / tk:.3g}x" if math.isfinite(tp)
              else f"  time to error < {th:g}: kinematika {tk:.3g} s, pylinkage not within {budget:g} s")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="what", required=True)
    t = sub.add_parser("throughput")
    t.add_argument("--designs", type=int, default=100_000)
    s = sub.add_parser("synthesis")
    s.add_argument("--budget", type=float, default=20.0)
    s.add_argument("--seed", type=int, default=1)
    args = parser.parse_args()
    if args.what == "throughput":
        throughput(args.designs)
    else:
        synthesis(args.budget, args.seed)


if __name__ == "__main__":
    main()
