"""Every point a page writes is located, and every point located is written (issue 30,
ninth round). Read off the page a reader gets, in the four languages: the names its
sentences, equations and figures write (outside the tables that only say what the points
are) are the rows of the Data section's table of points, no more and no fewer — a contact
the page names nowhere else is not listed (the seventh audit: C5-1.4's K, Q and S, C5-E.2's
N listed and never used), and one it uses is (C5-E.4's M in the upper wheel's centre)."""
from __future__ import annotations

import re

import pytest

from kinematika.draw.names import contact_names

from .helpers import LANGS, SEEDS, explained, rendered
from .helpers import words_of as _words

# a run of capitals, digits and primes (not a word's capital): a point's name, or names side
# by side (G1J, IC)
RUN = re.compile(r"(?<![A-Za-z0-9])[A-Z][A-Z0-9′']*(?![a-zà-öø-ÿ])")


def _sections(page: str) -> list[str]:
    """The page's `## ` sections (the title's part first)."""
    return re.split(r"(?m)^## ", page)


def _located(page: str, names: set[str]) -> set[str]:
    """The first cells of the Data section's rows that are points (| J | …)."""
    data = _sections(page)[1]
    return {m for m in re.findall(r"(?m)^\| ([^|]+?) \|", data) if m in names}


def _split(run: str, names: set[str]) -> set[str]:
    """The names a run is made of, longest first (G1J: G1 and J); letters that are no
    name (the I of IC, a word's capitals) are skipped."""
    out, rest = set(), run
    while rest:
        name = next((n for n in sorted(names, key=len, reverse=True) if rest.startswith(n)), None)
        if name is None:
            rest = rest[1:]
        else:
            out.add(name)
            rest = rest[len(name):]
    return out


def _used(page: str, names: set[str]) -> set[str]:
    """The names written outside the tables of what points are (the Data's rows of points,
    the structure's tables) and outside the M / D / ? marks over and under an equation
    (the legend that explains them too): sentences, equations, figures' labels."""
    parts = _sections(page)
    kept = [parts[0]]
    for k, part in enumerate(parts[1:], start=1):
        lines = []
        in_code = False
        for line in part.splitlines():
            if line.startswith("```"):
                in_code = not in_code
                continue
            if in_code and "=" not in line:
                continue                          # the marks over and under an equation
            if k <= 2 and line.startswith("|"):
                continue                          # Data and Structure tables: what points are
            if re.search(r"(?<!\S)\?(?!\S)", line):
                continue                          # the legend of the marks
            lines.append(line)
        kept.append("\n".join(lines))
    words = _words("\n".join(kept))
    out: set[str] = set()
    for run in RUN.findall(words):
        out |= _split(run.rstrip("′'"), names)
    for sub in re.findall(r"mathrm\{([A-Z][A-Z0-9]*)\}", words):    # a figure's $v_{\mathrm{D}}$
        out |= _split(sub, names)
    return out


def _names(name: str) -> set[str]:
    sol, _ = explained(name)
    return set(sol.model.points) | set(contact_names(sol.model, sol).values())


@pytest.mark.parametrize("lang", LANGS)
@pytest.mark.parametrize("name", SEEDS)
def test_the_points_written_are_the_points_located(name, lang):
    """Both ways: the points written in sentences, equations and figures are rows of the
    points' table, and no row names a point the page never writes elsewhere."""
    page, names = rendered(name, lang), _names(name)
    used, located = _used(page, names), _located(page, names)
    assert not sorted(used - located), (name, lang, "written, not located", sorted(used - located))
    assert not sorted(located - used), (name, lang, "located, never written", sorted(located - used))


def test_by_hand_the_epicyclic_lists_the_contacts_it_uses():
    """C5-1.4, by hand: six contacts J, K, N, Q, S, U (joints j7 … j12 in order). Planet 3,
    asked nothing, has its contacts N (with the sun) and U (with the ring) written only in
    the structure table — and since the fourteenth round (b) every contact the page writes
    has its letter: all six are rows of the points' table, and no structure cell gives a
    contact by its coordinates alone (the old (−√3·r/2; r/2) and (−3·√3·r/2; 3·r/2))."""
    page = rendered("seed_c5_1_4_epicyclic", "ca")
    names = _names("seed_c5_1_4_epicyclic")
    assert _located(page, names) >= {"J", "K", "N", "Q", "S", "U"}
    structure = _sections(page)[2]
    assert structure.count("| — |") == 0
    assert "| (−√3·r/2; r/2) |" not in structure and "| (−3·√3·r/2; 3·r/2) |" not in structure
    assert "| N |" in structure and "| U |" in structure
