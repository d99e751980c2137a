"""How wide each box's margin is: wide enough for a student who rounds the intermediate
results as the notes do, narrow enough to tell the usual mistakes from the right answer.

**Rounding.** A student who works by hand rounds every intermediate (an angle, a length, an
ω) to three significant figures, which moves each by up to 0.5 % of itself (0.1 % on
average), and the answer moves by what the problem makes of those changes: little for a
velocity proportional to the data, much where a result is a small difference of large
terms. The engine measures it: the variant is solved again with each datum in turn changed
by 0.4 % (`ROUNDING`), and the changes of an answer are added as independent errors (root
of the sum of squares). A box's margin is the section's tolerance (1 % by default) times the
answer's size, plus that allowance.

**Mistakes that barely differ.** A usual mistake whose answer lies within `APART` margins
of the right one could be taken for a rounding: the box's margin is narrowed to tell them
apart, but never below the rounding allowance plus 0.5 % (the answer's own rounding to
three figures: `FLOOR`); when that is not enough, the variant is not drawn. A mistake that
changes an answer by less than a millionth of its size changes nothing there. Nor is a
variant drawn whose answers rounding moves by more than 8 % (`SENSITIVE`): near a dead point
a hand solution cannot be marked to any sensible margin.

Measured on 139 variants of the P pair against a hand solution that rounds every intermediate
and every answer to three figures (tests/exercise/derive.py `p_pair_by_hand`): with 0.4 % and
the 8 % limit, 104 variants are drawn and the margins hold all 1040 of its answers; with
0.25 % or 0.3 %, 2 answers fall out; with a 5 % limit only 14 variants are drawn. The test
`test_a_hand_solution_rounded_to_three_figures_gets_full_marks` keeps it so.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable

from .key import Row
from .mistakes import Mistaken

ROUNDING = 0.004          # a number rounded to 3 significant figures moves by up to 0.5 %, 0.1 % on average
APART = 1.5               # a mistake's answer must lie this many (right + wrong) margins away
FLOOR = 0.005             # a narrowed margin keeps at least this (relative), plus the rounding allowance
NOISE = 1e-6              # a change smaller than this (relative) is no change
SENSITIVE = 0.08          # an answer that rounding moves by more than this is no hand exercise


@dataclass
class Margins:
    """Each row's relative tolerance (its margin over its size), the answers narrowed (q3 or
    q1 -> (mistake, how far it lies, the narrowed tolerance), relative) and, when the variant cannot tell a mistake
    apart, why (`close`: question, mistake, how far)."""

    tolerance: dict[str, float] = field(default_factory=dict)
    narrowed: dict[str, tuple[str, float, float]] = field(default_factory=dict)
    close: tuple = ()


def allowances(rows: list[Row], parameters: dict[str, float],
               solve_with: Callable[[str, float], list[Row]]) -> dict[str, float]:
    """The rounding allowance of each row (absolute): the root of the sum of the squares of
    its changes when each datum changes by `ROUNDING` of itself (`solve_with(name, value)`
    gives the rows solved so; a datum that cannot change, or whose change does not solve,
    adds nothing)."""
    square = {r.question: 0.0 for r in rows}
    for name, value in parameters.items():
        if value == 0 or not math.isfinite(value):
            continue
        try:
            changed = {r.question: r.value for r in solve_with(name, value * (1 + ROUNDING))}
        except Exception:
            continue
        for r in rows:
            if r.question in changed:
                square[r.question] += (changed[r.question] - r.value) ** 2
    return {q: math.sqrt(s) for q, s in square.items()}


def margins(rows: list[Row], allowance: dict[str, float], mistakes: list[Mistaken], tolerance: float) -> Margins:
    """Each row's tolerance, narrowed where a mistake lies close, or why the variant cannot
    tell a mistake apart (`Margins.close`). A vector is judged whole: a mistake is told apart
    by how far its vector lies from the right one (a component it hardly changes is right
    either way, and the mistake is named on the others)."""
    out = Margins()
    for stem, group in _vectors(rows).items():
        size = group[0].size if group[0].size > 0 else 1.0
        extra = max(allowance.get(r.question, 0.0) for r in group) / size
        if extra > SENSITIVE:
            out.close = (stem, "rounding", extra)
            return out
        relative, floor = tolerance + extra, FLOOR + extra
        for m in mistakes:
            wrong = [w for r in group if (w := m.rows.get(r.question)) is not None]
            if len(wrong) < len(group):
                continue
            gap = math.sqrt(sum((w.value - r.value) ** 2 for w, r in zip(wrong, group))) / size
            if gap <= min(relative, NOISE + tolerance):
                continue                        # the mistake changes nothing a margin can see here
            # the widest tolerance that tells them apart: the right margin and the mistaken
            # answer's own (as wide relative to the right size, or to its own when smaller)
            need = gap / (APART * (1 + min(1.0, wrong[0].size / size)))
            if relative <= need:
                continue
            if need < floor:
                out.close = (stem, m.kind, gap)
                return out
            relative = need
            out.narrowed[stem] = (m.kind, gap, need)
        for r in group:
            out.tolerance[r.question] = relative
    return out


def _vectors(rows: list[Row]) -> dict[str, list[Row]]:
    """The rows grouped by vector (`q3.x`, `q3.y` under `q3`); a scalar alone."""
    out: dict[str, list[Row]] = {}
    for r in rows:
        stem, _, axis = r.question.rpartition(".")
        out.setdefault(stem if axis in "xyz" and stem else r.question, []).append(r)
    return out


def data_of(solution: Any) -> dict[str, float]:
    """The model's data as numbers in its units: every parameter with a value."""
    env = solution.inst.env
    out = {}
    for name in solution.model.parameters:
        try:
            out[name] = float(env[name])
        except (KeyError, TypeError, ValueError):
            continue
    return out
