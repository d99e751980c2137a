"""Load test of the page's server: N users solving and sweeping at once, on 127.0.0.1 only.

    .venv/bin/python benchmarks/load_test.py                      # 50 users, 60 s, think 1 s
    .venv/bin/python benchmarks/load_test.py --users 50 --seconds 60 --think 0   # flat out

It starts `kinematika app --no-browser` on a free port of 127.0.0.1 (a separate process,
as an instructor would run it), then each simulated user repeats what the page does on a
change of the model: `POST /api/solve`, `/api/draw`, `/api/sweep` (a full turn, as the
page asks) and `/api/sketch` (the builder's places), on one of five linkages with its crank speed changed, then waits `--think`
seconds (random ±50 %). The run is bounded in time (`--seconds`) and in requests
(`--max-requests`), and stops by itself. It prints latency percentiles per endpoint, the
throughput and every error (a run passes with none).
"""
from __future__ import annotations

import argparse
import asyncio
import json
import random
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

import httpx

ROOT = Path(__file__).resolve().parent.parent
MODELS = ["four_bar.yaml", "slider_crank.yaml", "quick_return.yaml", "watt_six_bar.yaml",
          "jansen_leg.yaml"]
HOST = "127.0.0.1"


def start_server(workers: int) -> tuple[subprocess.Popen, str]:
    """`kinematika app` on a free port of 127.0.0.1; its URL once it answers."""
    proc = subprocess.Popen([sys.executable, "-m", "kinematika", "app", "--no-browser",
                             "--host", HOST, "--port", "0", "--workers", str(workers)],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=ROOT)
    line = proc.stdout.readline()
    m = re.search(r"(http://127\.0\.0\.1:\d+/)", line)
    if not m:
        proc.kill()
        raise SystemExit(f"the server did not start: {line!r}")
    deadline = time.monotonic() + 30
    while True:                      # the worker processes take a moment to start
        try:
            if httpx.get(m.group(1) + "api/start", timeout=5).status_code == 200:
                return proc, m.group(1)
        except httpx.HTTPError:
            pass
        if time.monotonic() > deadline:
            proc.kill()
            raise SystemExit("the server did not answer within 30 s")
        time.sleep(0.2)


def parameters(text: str) -> str | None:
    """The crank-speed parameter a model's driver uses (to vary the requests)."""
    m = re.search(r"omega: \w+, value: ([A-Za-z_]\w*)", text)
    return m.group(1) if m else None


async def user(client: httpx.AsyncClient, texts: list[tuple[str, str | None]], stop: float,
               think: float, budget: list[int], log: dict, errors: list[str]) -> None:
    rnd = random.Random()
    while time.monotonic() < stop and budget[0] > 0:
        text, param = rnd.choice(texts)
        body: dict = {"model": text, "format": "yaml"}
        if param:
            body["set"] = {param: round(rnd.uniform(1, 20), 3)}
        for endpoint, extra in (("solve", {}), ("draw", {"centres": True}),
                                ("sweep", {"skip_bad": True}), ("sketch", {})):
            if time.monotonic() >= stop or budget[0] <= 0:
                return
            budget[0] -= 1
            t0 = time.perf_counter()
            try:
                r = await client.post(f"/api/{endpoint}", json={**body, **extra})
                ok = r.status_code == 200
                if ok:
                    json.loads(r.content)
                else:
                    errors.append(f"{endpoint}: HTTP {r.status_code} {r.text[:200]}")
            except (httpx.HTTPError, ValueError) as err:
                ok = False
                errors.append(f"{endpoint}: {type(err).__name__}: {err}")
            log.setdefault(endpoint, []).append(time.perf_counter() - t0)
        if think > 0:
            await asyncio.sleep(think * rnd.uniform(0.5, 1.5))


def percentile(values: list[float], q: float) -> float:
    values = sorted(values)
    return values[min(len(values) - 1, round(q / 100 * (len(values) - 1)))]


async def run(args: argparse.Namespace, url: str) -> tuple[dict, list[str], float]:
    texts = [((ROOT / "examples" / name).read_text(), None) for name in MODELS]
    texts = [(t, parameters(t)) for t, _ in texts]
    log: dict[str, list[float]] = {}
    errors: list[str] = []
    budget = [args.max_requests]
    limits = httpx.Limits(max_connections=args.users, max_keepalive_connections=args.users)
    async with httpx.AsyncClient(base_url=url, timeout=60, limits=limits) as client:
        await client.post("/api/solve", json={"model": texts[0][0]})          # warm up
        t0 = time.monotonic()
        stop = t0 + args.seconds
        await asyncio.gather(*(user(client, texts, stop, args.think, budget, log, errors)
                               for _ in range(args.users)))
        elapsed = time.monotonic() - t0
    return log, errors, elapsed


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--users", type=int, default=50)
    parser.add_argument("--seconds", type=float, default=60.0)
    parser.add_argument("--think", type=float, default=1.0, help="seconds between a user's changes")
    parser.add_argument("--max-requests", type=int, default=200_000)
    parser.add_argument("--workers", type=int, default=1, help="server processes (--workers)")
    args = parser.parse_args()
    if not (1 <= args.users <= 500 and 0 < args.seconds <= 600):
        raise SystemExit("bounded: 1 to 500 users, at most 600 s")
    proc, url = start_server(args.workers)
    try:
        log, errors, elapsed = asyncio.run(run(args, url))
    finally:
        proc.terminate()
        proc.wait(10)
    total = sum(len(v) for v in log.values())
    print(f"{args.users} users, {args.workers} server process(es), {elapsed:.0f} s, "
          f"think {args.think:g} s: {total} requests, "
          f"{total / elapsed:.1f} requests/s, {len(log.get('sweep', [])) / elapsed:.1f} "
          f"model changes/s (solve + draw + sweep + sketch), {len(errors)} errors")
    print(f"{'endpoint':<10}{'count':>7}{'p50 ms':>10}{'p90 ms':>10}{'p99 ms':>10}{'max ms':>10}")
    everything = [x for v in log.values() for x in v]
    for name, values in [*log.items(), ("all", everything)]:
        ms = [1000 * x for x in values]
        print(f"{name:<10}{len(ms):>7}{percentile(ms, 50):>10.0f}{percentile(ms, 90):>10.0f}"
              f"{percentile(ms, 99):>10.0f}{max(ms):>10.0f}")
    if errors:
        print("errors:", *errors[:20], sep="\n  ")
    print(f"(mean {statistics.mean(everything) * 1000:.0f} ms; client and server share this "
          "machine's cores)")
    sys.exit(1 if errors else 0)


if __name__ == "__main__":
    main()
