"""Explanations of the repository's examples, built once per test run, and the checks that
tie an explanation's numbers to the solver's."""
from __future__ import annotations

import base64
import contextlib
import copy
import functools
import inspect
import itertools
import math
import re
import sys
import traceback
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import kinematika
from kinematika.explain import build
from kinematika.explain.document import Document, Drawing, Figure, Section

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
# the worked examples of the notes: seeds 000 (the fan), 001 and 002
WORKED = sorted(p.stem for p in EXAMPLES.glob("*.yaml") if p.stem.startswith(("seed_", "fan_")))
ALL = sorted(p.stem for p in EXAMPLES.glob("*.yaml"))
# the notes' examples of seeds 001 and 002, and the languages an explanation is written in
SEEDS = sorted(p.stem for p in EXAMPLES.glob("seed_*.yaml"))
LANGS = ("en", "es", "ca", "eu")

# One module a process: the files of tests/explain import it as `.helpers`. Imported under a
# second name as well (`tests.explain.helpers`: nine files did until stop 47) it is a second
# module with caches of its own, and every example it serves is built, and every page drawn
# and written, a second time (~22 s of CPU a run).
_TWINS = [n for n, m in list(sys.modules.items()) if n != __name__ and getattr(m, "__file__", None) == __file__]
assert not _TWINS, f"tests/explain/helpers.py imported as {__name__} and as {_TWINS}: import it as `.helpers`"


# the example each document `explained` made is the explanation of (by the document's id)
_EXPLAINED: dict[int, tuple[str, Document]] = {}


@functools.lru_cache(maxsize=None)
def explained(name: str) -> tuple[kinematika.Solution, Document]:
    sol = kinematika.solve(EXAMPLES / f"{name}.yaml")
    doc = build(sol)
    _EXPLAINED[id(doc)] = (name, doc)
    return sol, doc


def rendered(name: str, lang: str, fmt: str = "md", drawings: bool = True) -> str:
    """An example's explanation written in `lang` and `fmt`, built and written once a run
    (the test files of tests/explain run in one process: tests/conftest.py's `ONE_WORKER`)."""
    return _rendered(name, lang, fmt, drawings)


@functools.lru_cache(maxsize=None)
def _rendered(name: str, lang: str, fmt: str, drawings: bool) -> str:
    from kinematika.explain import render

    _, doc = explained(name)
    if (name, lang, fmt, drawings) not in RECORDED:
        return render(doc, lang, fmt, drawings=drawings)
    # A page whose label layouts the figure tests read: each is recorded as it is made. What
    # another format of the page made first, and the documents keep (a drawing's SVG in this
    # language, a polygon's layout), is made again here, the same; a polygon's layout that
    # another recorded page made (the languages mostly share one) is recorded there.
    recorded = {id(lay) for found in _LAYOUTS.values() for lay, _, _ in found["polygons"]}
    for block in doc.blocks():
        if isinstance(block, Drawing):
            block._svg.pop(lang, None)
        elif isinstance(block, Figure):
            for key in [k for k, lay in block.layouts.items() if id(lay) not in recorded]:
                del block.layouts[key]
    with _recording() as found:
        page = render(doc, lang, fmt, drawings=drawings)
    _LAYOUTS[(name, lang)] = found
    return page


def render_of(doc: Document, lang: str, fmt: str = "md", drawings: bool = True) -> str:
    """`kinematika.explain.render(doc, lang, fmt, drawings=drawings)`, read from `rendered`'s
    cache when `doc` is an example's explanation made by `explained` (the same document,
    written the same way). Not for a test that patches the drawings: the patched page would
    be cached."""
    from kinematika.explain import render

    found = _EXPLAINED.get(id(doc))
    if found is not None and found[1] is doc:
        return rendered(found[0], lang, fmt, drawings)
    return render(doc, lang, fmt, drawings=drawings)


def model_tree(name: str) -> dict:
    """An example's model file as `yaml.safe_load` reads it (a copy the caller may change),
    read once a run: the rules over the seeds' model texts read each file dozens of times, at
    ~10 ms a read (PyYAML in Python)."""
    return copy.deepcopy(_model_tree(name))


@functools.lru_cache(maxsize=None)
def _model_tree(name: str) -> dict:
    import yaml

    return yaml.safe_load((EXAMPLES / f"{name}.yaml").read_text(encoding="utf-8"))


def num(sol: kinematika.Solution, x: Any) -> Any:
    """Floats (symbols at the solver's sample values)."""
    if isinstance(x, (tuple, list)):
        return tuple(num(sol, c) for c in x)
    return sol.inst.num(x)


def is_close(sol: kinematika.Solution, a: Any, b: Any, scale: float) -> bool:
    a, b = num(sol, a), num(sol, b)
    a = a if isinstance(a, tuple) else (a,)
    b = b if isinstance(b, tuple) else (b,)
    return len(a) == len(b) and all(math.isclose(x, y, rel_tol=1e-7, abs_tol=1e-9 * max(scale, 1e-12))
                                    for x, y in zip(a, b))


def section(doc: Document, key: str) -> Section:
    """The document's section whose title is message `key` (sec.centres, sec.velocities …)."""
    return next(s for s in doc.sections if s.title.key == key)


def blocks(sec: Section) -> list:
    """Every block of a section, its subsections' blocks in their place."""
    out: list = []
    for b in sec.blocks:
        out += blocks(b) if isinstance(b, Section) else [b]
    return out


SVG = re.compile(r"data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)")
# a Markdown page's figure definitions, at its end: `[fig-1]: data:image/svg+xml;base64,…`
DEFINITIONS = re.compile(r"^\[fig-\d+\]: \S+$", re.M)


def body_of(page: str) -> str:
    """A Markdown page without its figures' reference definitions: the text a reader reads."""
    return DEFINITIONS.sub("", page)


def words_of(page: str) -> str:
    """What a reader sees of a page: its text and tables, and the labels its figures set
    (an SVG's <text>, and matplotlib's comment with each label it draws as paths)."""
    figures = [base64.b64decode(b64).decode("utf-8") for b64 in SVG.findall(page)]
    out = []
    for part in [SVG.sub("", body_of(page))] + figures:
        out += re.findall(r"<!--(.*?)-->", part, flags=re.S)
        part = re.sub(r"<(style|script)\b.*?</\1>", "", part, flags=re.S)
        out.append(re.sub(r"<[^>]*>", " ", part))
    return "\n".join(out)


NOTES_SEEDS = [s for s in SEEDS if s.startswith(("seed_001_", "seed_c5_"))]


# The pages whose label layouts are recorded while `rendered` writes them (the notes' seeds in
# every language; Markdown with its drawings), and what was recorded, by (seed, language):
# {"labels": [(placed, tips, px) of each label layout, display units], "polygons": [(layout,
# items, placed) of each polygon], "drawings": [(placed, `Layout`) of each label layout of a
# mechanism drawing, the lines drawn under it its `recorded_lines`, the marks painted its
# `recorded_marks`], …: `_recording`}. The layout rules read English and Catalan, whose words
# are the longest (`RECORDED_LANGS`); the drawn lines are read in all four.
RECORDED_LANGS = ("en", "ca")
RECORDED = frozenset((name, lang, "md", True) for name in NOTES_SEEDS for lang in LANGS)
_LAYOUTS: dict[tuple[str, str], dict[str, list]] = {}

DRAWN = (0.5, 3.0)      # the board's weights of drawn lines (hatching 0.7, bars and outlines 1); arrows weigh 3


@contextlib.contextmanager
def _recording():
    """Every label layout (`draw.labels.Layout.run`: a mechanism's or a polygon's labels) and
    every polygon's placement (`explain.render.svg._place`) made inside the block, appended to
    the dict it yields as they are made; each call returns what it returned (the page is
    written as without the recording). A layout of a mechanism drawing (inside
    `kinematika.draw.svg`, as `Drawing.svg` calls it) is also recorded as a drawing's, with
    the lines drawn under its labels (`_lines_drawn`) as its `recorded_lines`, and every mark
    painted on its figure (`draw.paint.paint_mark`'s, data coordinates) as its `recorded_marks`
    (one list a figure, shared by the layouts tried while its limits grew). Each mechanism
    drawing as a whole is recorded as a "figures" entry: (its options, the marks last painted,
    the labels last placed, the data → display transform), what `figures` reads."""
    from kinematika import draw as draw_package
    from kinematika.draw import figure, labels, paint
    from kinematika.explain.render import svg as svg_module

    found: dict[str, list] = {"labels": [], "polygons": [], "areas": [], "layouts": [], "drawings": [], "figures": []}
    init, run, place = labels.Layout.__init__, labels.Layout.run, svg_module._place
    paint_mark, svg, paint_all = paint.paint_mark, draw_package.svg, figure.paint
    drawing = [0]           # inside a mechanism drawing
    seen: dict = {}         # the drawing being made: its marks, axes and labels as last made

    def recorded_svg(*args, **kw):
        drawing[0] += 1
        seen.clear()
        try:
            out = svg(*args, **kw)
        finally:
            drawing[0] -= 1
        options = {k: v for k, v in kw.items() if k not in ("bare", "lang")}
        found["figures"].append((options, seen["marks"], seen.get("placed", []), seen["ax"].transData))
        return out

    def recorded_paint(cv, marks):
        seen["marks"], seen["ax"] = list(marks), cv.ax
        return paint_all(cv, marks)

    def recorded_init(self, board, ax):
        init(self, board, ax)
        if drawing[0]:
            self.recorded_lines = _lines_drawn(board, ax)
            self.recorded_marks = board.__dict__.setdefault("painted", [])

    def recorded_run(self):
        out = run(self)
        found["labels"].append((out, self.tips, self.px))
        found["areas"].append((out, self.areas))
        found["layouts"].append((out, self))
        if hasattr(self, "recorded_lines"):
            found["drawings"].append((out, self))
            seen["placed"] = out
        return out

    def recorded_place(lay, items):
        out = place(lay, items)
        found["polygons"].append((lay, items, out))
        return out

    def recorded_paint_mark(cv, m):
        if m.kind == "line" and (m.group or "").startswith(("kennedy:", "normal:")):
            cv.board.__dict__.setdefault("construction", []).append(np.asarray(m.points, dtype=float))
        cv.board.__dict__.setdefault("painted", []).append(m)
        return paint_mark(cv, m)

    labels.Layout.__init__, labels.Layout.run, svg_module._place = recorded_init, recorded_run, recorded_place
    paint.paint_mark, draw_package.svg, figure.paint = recorded_paint_mark, recorded_svg, recorded_paint
    try:
        yield found
    finally:
        labels.Layout.__init__, labels.Layout.run, svg_module._place = init, run, place
        paint.paint_mark, draw_package.svg, figure.paint = paint_mark, svg, paint_all


def _lines_drawn(board, ax) -> list:
    """The lines a mechanism drawing's labels lie over, as (display points (n, 2), body or ""
    or "construction"): from the label board, its bodies' outlines, bars, rims and hatching
    (`DRAWN`'s weights) with their bodies, and every construction line as painted (a
    Kennedy line, a normal: `_recording`), whether or not the placer was told of it."""
    owners = board.owners if len(board.owners) == len(board.obstacles) else [""] * len(board.obstacles)
    lines = [(ax.transData.transform(line), owner) for (line, weight, _), owner in zip(board.obstacles, owners)
             if DRAWN[0] <= weight < DRAWN[1] and len(line) >= 2]
    return lines + [(ax.transData.transform(line), "construction") for line in getattr(board, "construction", [])]


def recorded_pages(kind: str, langs: tuple = RECORDED_LANGS) -> dict:
    """What was recorded of `kind` ("labels", "polygons", "areas": each label layout's
    placements and its bodies' areas, "layouts": its placements and the `Layout` itself, or
    "drawings": the same of a mechanism drawing's layouts only; see `_LAYOUTS`)
    while each of the notes' seeds was written in `langs` (Markdown, with its drawings), a
    list per (seed, language). The pages are `rendered`'s: each is drawn once a run, for the
    figure tests and every other test that reads it."""
    for name in NOTES_SEEDS:
        for lang in langs:
            rendered(name, lang, "md")
    return {(name, lang): _LAYOUTS[(name, lang)][kind] for name in NOTES_SEEDS for lang in langs}


def figures(name: str, lang: str) -> list:
    """Each mechanism drawing of one of the notes' seeds' pages in `lang`: (its options, its
    marks, its labels' placements, its data → display transform), as `draw.svg` made them
    while `rendered` wrote the page (`_recording`'s "figures"): drawn once a run for every
    test that reads them."""
    assert (name, lang, "md", True) in RECORDED, f"{name} in {lang} is not a recorded page"
    rendered(name, lang, "md")
    return _LAYOUTS[(name, lang)]["figures"]


def over(**grids) -> Any:
    """A rule checked over a grid of pages as ONE test: `@over(name=SEEDS, lang=LANGS)` on a
    check taking `name` and `lang` (and any fixtures) runs it on every combination and fails
    once, naming every failing (seed, language) with its message. One test item a rule, not
    76: pytest's collection, reports and setup for each item cost more than most checks. A
    grid given as a function is asked for its values when the test runs: one that needs the
    examples solved (the numeric seeds) is not solved at collection, in every worker."""
    def wrap(check):
        params = inspect.signature(check).parameters
        here = inspect.getsourcefile(check)
        missing = set(grids) - set(params)
        assert not missing, f"{check.__name__} takes no {missing}"

        def test(**fixtures):
            cases = list(itertools.product(*(g() if callable(g) else g for g in grids.values())))
            failed = []
            for values in cases:
                try:
                    check(**dict(zip(grids, values)), **fixtures)
                except (Exception, pytest.fail.Exception) as e:     # said with the other pages' failures
                    said = "".join(traceback.format_exception_only(e)).strip().replace("\n", "\n    ")
                    where = [f.lineno for f in traceback.extract_tb(e.__traceback__) if f.filename == here]
                    failed.append(f"{', '.join(map(str, values))} (line {where[-1] if where else '?'}): {said}")
            assert not failed, f"{len(failed)} of {len(cases)} pages fail {check.__name__}:\n" + "\n".join(failed)

        functools.update_wrapper(test, check)
        del test.__wrapped__                    # pytest reads the fixtures from the signature
        test.__signature__ = inspect.Signature([p for n, p in params.items() if n not in grids])
        return test
    return wrap


def plain_page(name: str, lang: str) -> str:
    """A seed's page as Markdown without its figures: what a rule over the words reads."""
    return rendered(name, lang, "md", drawings=False)


def scratch_axes() -> object:
    """A 400 × 400 pt matplotlib axes, figure points as data, for a label layout built by hand."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(400 / 72, 400 / 72), dpi=72)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, 400)
    ax.set_ylim(0, 400)
    return ax
