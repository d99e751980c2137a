"""Explanations of the repository's examples, built once per test run, and the checks that
tie an explanation's numbers to the solver's."""
from __future__ import annotations

import base64
import functools
import math
import re
from pathlib import Path
from typing import Any

import kinematika
from kinematika.explain import build
from kinematika.explain.document import Document, Section

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
# the worked examples of the notes: seeds 000 (the fan), 001 and 002
WORKED = sorted(p.stem for p in EXAMPLES.glob("*.yaml") if p.stem.startswith(("seed_", "fan_")))
ALL = sorted(p.stem for p in EXAMPLES.glob("*.yaml"))
# the notes' examples of seeds 001 and 002, and the languages an explanation is written in
SEEDS = sorted(p.stem for p in EXAMPLES.glob("seed_*.yaml"))
LANGS = ("en", "es", "ca", "eu")


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
    return render(doc, lang, fmt, drawings=drawings)


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


def recorded_pages(current: list, langs: tuple = ("en", "ca")) -> dict:
    """What a patched drawing step appends to `current` while each of the notes' seeds is
    written in `langs` (Markdown), a list per (seed, language): the label layouts the figure
    tests read in display units. The caller patches and restores the step."""
    from kinematika.explain import render

    found = {}
    for name in NOTES_SEEDS:
        doc = build(kinematika.solve(EXAMPLES / f"{name}.yaml"))
        for lang in langs:
            current.clear()
            render(doc, lang, "md")
            found[(name, lang)] = list(current)
    return found
