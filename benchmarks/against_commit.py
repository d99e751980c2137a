"""Sweeps and one large instant of this checkout against another checkout of kinematika (an
earlier commit), in one run, alternating, CPU time (best of 7): a refactoring must not make
them slower.

    git worktree add /tmp/base COMMIT
    .venv/bin/python benchmarks/against_commit.py /tmp/base

Each side runs in its own process (its own `src` first on the path); the table gives both
times and their ratio.
"""
from __future__ import annotations

import ast
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
CASES = (("four_bar", 3599), ("slider_crank", 3599), ("watt_six_bar", 3599), ("jansen_leg", 3599),
         ("rssr_spatial_four_bar", 359), ("spherical_four_bar", 359))

CHILD = """
import sys, time
sys.path.insert(0, sys.argv[1] + "/src")
sys.path.insert(0, sys.argv[1] + "/benchmarks")
from kinematika.sweep.run import Sweeper
from kinematika.model.files import load_model
from kinematika.model.build import build_model
from kinematika.engine.instant import instantiate
from kinematika.engine.system import InstantSolver
from chain import four_bar_chain

def best(f, n=7):
    out = []
    for _ in range(n):
        t = time.process_time(); f(); out.append(time.process_time() - t)
    return min(out)

res = {}
for case, steps in %r:
    s = Sweeper(load_model(sys.argv[1] + f"/examples/{case}.yaml"))
    res[case + " sweep"] = best(lambda: s.run(steps=steps))
model = build_model(four_bar_chain(999))
inst = instantiate(model, False)
res["chain of 1000 bodies, one instant"] = best(lambda: InstantSolver(inst).solve(), 3)
print(repr(res))
"""


def measure(root: Path) -> dict[str, float]:
    done = subprocess.run([sys.executable, "-c", CHILD % (CASES,), str(root)], capture_output=True, text=True,
                          check=True)
    return ast.literal_eval(done.stdout.strip().splitlines()[-1])


def main() -> None:
    base = Path(sys.argv[1]).resolve()
    here = HERE.parent
    rounds = [(measure(base), measure(here)) for _ in range(2)]
    print(f"| case | {base.name} (ms CPU) | this checkout (ms CPU) | ratio |\n|---|---|---|---|")
    for key in rounds[0][0]:
        old = min(r[0][key] for r in rounds) * 1000
        new = min(r[1][key] for r in rounds) * 1000
        print(f"| {key} | {old:.3g} | {new:.3g} | {new / old:.2f} |")


if __name__ == "__main__":
    main()
