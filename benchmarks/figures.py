"""What a figure costs: each example drawn to SVG with and without its labels.

    .venv/bin/python benchmarks/figures.py            # about half a minute

For each case: the median CPU time (time.process_time, so that other work on a shared
machine counts less) of `draw(sol)` saved as SVG, with labels and with `labels=False`, and
their ratio: what placing the labels adds to the drawing itself. Text sizes are measured
once per text and font for the whole process (draw.labels.text_extent), as in a server or
a notebook drawing many figures; the first figure of each case is drawn before timing.
"""
from __future__ import annotations

import io
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASES = (("four_bar", {}), ("four_bar", {"centres": True, "accelerations": True}),
         ("quick_return", {"centres": True, "accelerations": True}),
         ("seed_c5_1_5_pulley_block", {"centres": True, "accelerations": True}),
         ("jansen_leg", {"centres": True, "accelerations": True}))


def cpu_ms(fn, repeat: int = 7) -> float:
    fn()
    times = []
    for _ in range(repeat):
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return 1000 * statistics.median(times)


def main() -> int:
    from kinematika.api import solve
    from kinematika.draw import DrawOptions, draw

    print(f"{'case':44s} {'SVG ms':>8s} {'no labels':>10s} {'ratio':>6s}")
    for name, choices in CASES:
        sol = solve(ROOT / "examples" / f"{name}.yaml")

        def svg(labels: bool) -> None:
            fig = draw(sol, options=DrawOptions(labels=labels, **choices))
            fig.savefig(io.StringIO(), format="svg")

        with_labels, without = cpu_ms(lambda: svg(True)), cpu_ms(lambda: svg(False))
        flags = " ".join(f"--{k}" for k in choices)
        print(f"{name + ' ' + flags:44s} {with_labels:8.1f} {without:10.1f} "
              f"{with_labels / without:6.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
