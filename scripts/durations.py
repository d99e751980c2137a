"""Where a test run's time went, from the file `KINEMATIKA_DURATIONS=FILE` wrote (tests/conftest.py).

    python scripts/durations.py FILE [--top N]

Prints the CPU seconds (user + system, finished children included) and the wall seconds of
each unit of work (a file, or a directory run by one worker: tests/conftest.py's
`ONE_WORKER`), largest CPU first, then the N tests that took the most CPU. A test's CPU is
the difference between its line's running total and the previous line of the same worker,
so it holds what ran between them (fixtures too quick to get a line of their own). CPU is
what a loaded machine does not stretch: compare runs by it, not by the wall.
"""
from __future__ import annotations

import argparse
import collections
import sys

ONE_WORKER = ("tests/explain/", "tests/examples/", "tests/exercise/", "tests/web/")


def unit(nodeid: str) -> str:
    """The unit of work a test belongs to (as tests/conftest.py's `unit`)."""
    path = nodeid.split("::", 1)[0]
    return next((d for d in ONE_WORKER if path.startswith(d)), path)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file")
    parser.add_argument("--top", type=int, default=20)
    args = parser.parse_args(argv)
    last: dict[str, float] = {}
    cpu: collections.Counter = collections.Counter()
    wall: collections.Counter = collections.Counter()
    tests: list[tuple[float, float, str]] = []
    with open(args.file, encoding="utf-8") as lines:
        for line in lines:
            fields = line.rstrip("\n").split("\t")
            if len(fields) < 6:
                sys.exit(f"{args.file}: a line without the CPU columns (written before they were added)")
            seconds, _, when, nodeid, so_far, pid = fields[:6]
            spent = float(so_far) - last.get(pid, 0.0)
            last[pid] = float(so_far)
            cpu[unit(nodeid)] += spent
            wall[unit(nodeid)] += float(seconds)
            tests.append((spent, float(seconds), f"{when:8} {nodeid}"))
    print(f"{'CPU s':>8} {'wall s':>8}  unit   (total CPU {sum(cpu.values()):.0f} s)")
    for name, seconds in cpu.most_common():
        print(f"{seconds:8.1f} {wall[name]:8.1f}  {name}")
    print(f"\n{'CPU s':>8} {'wall s':>8}  test")
    for spent, seconds, name in sorted(tests, reverse=True)[:args.top]:
        print(f"{spent:8.1f} {seconds:8.1f}  {name}")


if __name__ == "__main__":
    try:
        main()
    except BrokenPipeError:         # piped into `head`: the reader has what it wanted
        sys.stderr.close()
