"""A class's set: `kinematika exercise` of 60 variants, as a teacher runs it (issue 33's
quick-return in Basque and the notes' epicyclic train in Catalan), measured.

For each set: the whole command's wall time and CPU time (its own and its descendants': the
worker processes and Chromium's, sampled), when it wrote its milestone files (a timing log
read from the files' times: the first figure, sheets.html, sheets.pdf, key.html, quiz.xml,
key.pdf, in seconds from its start), then, in this process, each phase's CPU time
(drawing the variants with their margins and mistakes; the statement figures; the worked
solutions; the quiz, sheets and key as HTML) and Chromium's printing of the sheets and of the
key (wall time, and CPU time sampled over its processes with psutil); the sizes of quiz.xml,
key.pdf and sheets.pdf and the key's pages. The issue's starting point is printed beside
(a 60-variant set: key.pdf 64 MB and 688 pages, quiz.xml 13 to 19 MB, about three minutes).

    .venv/bin/python benchmarks/exercise_set.py [--count 60] [--no-print]

Times depend on the machine and its load (printed with the load average); the sizes and
pages do not.
"""
from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SETS = [("quick_return", ["th=20:160:5", "w=5:15:1"], "eu"), ("epicyclic", ["r=30:80:5", "w=2:20:1"], "ca")]
BEFORE = "issue 33's start: key.pdf 64 MB, 688 pages; quiz.xml 13-19 MB; about 180 s"


def pages(pdf: Path) -> int:
    return len(re.findall(rb"/Type\s*/Page[^s]", pdf.read_bytes())) if pdf.exists() else 0


class TreeCPU:
    """The CPU time of this process's descendants while a block runs, sampled (psutil, every
    0.1 s): Chromium's processes are not reaped by this process, so `RUSAGE_CHILDREN` misses
    most of them (it counted 9 s of a print that used 65 s). A process's last sample counts,
    so up to 0.1 s of each may be missed."""

    def __enter__(self) -> "TreeCPU":
        import threading

        import psutil

        self.seen: dict[tuple, float] = {}
        self.stop = threading.Event()
        me = psutil.Process()

        def sample() -> None:
            while not self.stop.is_set():
                for child in me.children(recursive=True):
                    try:
                        t = child.cpu_times()
                        self.seen[(child.pid, child.create_time())] = t.user + t.system
                    except psutil.Error:
                        pass
                time.sleep(0.1)

        self.thread = threading.Thread(target=sample, daemon=True)
        self.thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self.stop.set()
        self.thread.join()
        self.seconds = sum(self.seen.values())


def whole(model: Path, vary: list[str], lang: str, count: int, out: Path, pdf: bool) -> tuple[float, float]:
    """The command's wall time and the CPU time of it and all its descendants."""
    global STARTED
    STARTED = time.time()
    start = time.perf_counter()
    args = [sys.executable, "-m", "kinematika", "exercise", str(model), *(a for v in vary for a in ("--vary", v)),
            "--count", str(count), "--seed", "11", "--lang", lang, "-o", str(out)] + ([] if pdf else ["--no-pdf"])
    with TreeCPU() as tree:
        subprocess.run(args, check=True, capture_output=True)
    return time.perf_counter() - start, tree.seconds


STARTED = 0.0             # when the last command started (the clock of the files' times)
MILESTONES = [("first figure", "figures/variant-001.png"), ("sheets.html", "sheets.html"),
              ("sheets.pdf", "sheets.pdf"), ("key.html", "key.html"), ("quiz.xml", "quiz.xml"),
              ("key.pdf", "key.pdf")]


def timeline(folder: Path) -> str:
    """When the command wrote each milestone file, in seconds from its start (a timing log
    read from the files' times): the variants are drawn before the first figure, the
    figures before sheets.html, the worked solutions before key.html."""
    return ", ".join(f"{label} {(folder / name).stat().st_mtime - STARTED:.0f} s"
                     for label, name in MILESTONES if (folder / name).exists())


def phases(model: Path, vary: list[str], lang: str, count: int, out: Path, pdf: bool) -> dict[str, float]:
    """Each phase's CPU time in this process (one by one, no workers), and printing's wall time."""
    from kinematika.exercise import make_exercise
    from kinematika.exercise.figure import statement_figure
    from kinematika.exercise.moodle import quiz_xml
    from kinematika.exercise.sheets import key_html, sheets_html, students_for
    from kinematika.exercise.solutions import solution_html
    from kinematika.model.files import load_model

    out.mkdir(parents=True, exist_ok=True)
    t = {}
    c = time.process_time()
    ex = make_exercise(load_model(model), vary, count, 11, lang, source=model)
    t["variants (margins, mistakes)"] = time.process_time() - c
    c = time.process_time()
    figures = {v.number: statement_figure(ex, v, lang) for v in ex.variants}
    t["statement figures"] = time.process_time() - c
    c = time.process_time()
    solutions = {v.number: solution_html(ex, v, lang) for v in ex.variants}
    t["worked solutions"] = time.process_time() - c
    c = time.process_time()
    (out / "quiz.xml").write_text(quiz_xml(ex, figures, solutions), encoding="utf-8")
    (out / "sheets.html").write_text(sheets_html(ex, figures, students_for(ex)), encoding="utf-8")
    (out / "key.html").write_text(key_html(ex, figures, solutions), encoding="utf-8")
    t["quiz, sheets, key (HTML)"] = time.process_time() - c
    if pdf:
        from kinematika.exercise.printing import print_pdfs

        for name in ("sheets", "key"):
            w = time.perf_counter()
            with TreeCPU() as tree:
                print_pdfs([(out / f"{name}.html", out / f"{name}.pdf")])
            t[f"printing {name} (wall)"] = time.perf_counter() - w
            t[f"printing {name} (Chromium's CPU)"] = tree.seconds
    return t


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=60)
    parser.add_argument("--no-print", dest="pdf", action="store_false")
    args = parser.parse_args()
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    print(f"{cores} cores, load average {os.getloadavg()[0]:.1f}; {BEFORE}")
    work = Path(tempfile.mkdtemp())
    for name, vary, lang in SETS:
        model = ROOT / "examples" / "exercises" / f"{name}.yaml"
        wall, cpu = whole(model, vary, lang, args.count, work / f"{name}-cli", args.pdf)
        folder = work / f"{name}-cli"
        print(f"\n{name} ({lang}), {args.count} variants: command {wall:.0f} s wall, {cpu:.0f} s CPU "
              f"(with its workers and Chromium's processes)")
        print(f"  quiz.xml {(folder / 'quiz.xml').stat().st_size / 1e6:.1f} MB", end="")
        if args.pdf:
            key = folder / "key.pdf"
            print(f"; key.pdf {key.stat().st_size / 1e6:.1f} MB, {pages(key)} pages; sheets.pdf "
                  f"{(folder / 'sheets.pdf').stat().st_size / 1e6:.1f} MB, {pages(folder / 'sheets.pdf')} pages")
        else:
            print()
        print(f"  written at: {timeline(folder)}")
        for phase, seconds in phases(model, vary, lang, args.count, work / f"{name}-phases", args.pdf).items():
            print(f"  {phase:<30} {seconds:6.1f} s")
    print(f"\nload average {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
