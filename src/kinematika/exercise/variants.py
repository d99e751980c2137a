"""The variants of an exercise: each student's data, drawn on the grids a statement uses.

`--vary NAME=LOW:HIGH[:STEP]` gives a parameter's interval and its step, in the unit the
statement states it in (5 mm, 1°, 0.5 rad/s): its values are LOW, LOW + STEP, … up to HIGH,
as exact decimals. A variant takes one value of each varied parameter, drawn uniformly
from the grids by numpy's generator seeded with `--seed` alone, so that the same seed gives
the same variants on any machine. A drawn variant is kept when

- it is new (no two variants have the same data),
- the mechanism assembles with it (its points can be constructed and the joints hold),
- its usual mistakes can be told from the right answer (`margins`), and
- it is not near a dead point: the condition number of the dimensionless constraint
  Jacobian, which the solver measures anyway (`engine.mobility`, the `singular` error at
  1e10), is at most `MAX_CONDITION`. Well-placed linkages measure 5 to 25 (the four-bar
  and the P-pair examples over their whole ranges); within a few degrees of a dead point
  the number passes 100.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal, InvalidOperation
from typing import Any, Callable, Optional

from ..errors import KinematikaError

MAX_CONDITION = 100.0
MAX_GRID = 1_000_000          # values of one parameter's grid
MAX_VARIANTS = 1000           # variants of one exercise (a class, several times over)
TRIES = 20                    # draws per variant asked before giving up (plus a margin)
NAME = re.compile(r"\w+\Z")


@dataclass(frozen=True)
class Vary:
    """A varied parameter: its grid LOW, LOW + STEP, … ≤ HIGH, in the statement's unit."""

    name: str
    low: Decimal
    high: Decimal
    step: Decimal

    @property
    def count(self) -> int:
        """How many values the grid has."""
        return int((self.high - self.low) // self.step) + 1

    def value(self, k: int) -> Decimal:
        """The grid's k-th value (0-based), exactly."""
        return self.low + k * self.step


def parse_vary(text: str) -> Vary:
    """`NAME=LOW:HIGH[:STEP]` as a `Vary`; the step defaults to a tenth of the interval's
    order of magnitude (0.8:1.2 → 0.01; 5:15 → 1). A malformed one is a usage error."""
    name, eq, rest = text.partition("=")
    parts = rest.split(":")
    try:
        if not eq or not NAME.match(name.strip()) or len(parts) not in (2, 3):
            raise InvalidOperation
        low, high = Decimal(parts[0].strip()), Decimal(parts[1].strip())
        step = Decimal(parts[2].strip()) if len(parts) == 3 else default_step(low, high)
        if not all(x.is_finite() for x in (low, high, step)):
            raise InvalidOperation
    except (InvalidOperation, ValueError):
        raise KinematikaError("usage", "vary-step-form", "--vary", got=repr(text)) from None
    name = name.strip()
    if high < low or step <= 0:
        raise KinematikaError("usage", "vary-step-interval", "--vary", name=name, got=rest)
    vary = Vary(name, low, high, step)
    if vary.count > MAX_GRID:
        raise KinematikaError("usage", "vary-grid-large", "--vary", name=name, count=vary.count, limit=MAX_GRID)
    return vary


def default_step(low: Decimal, high: Decimal) -> Decimal:
    """A tenth of the interval's order of magnitude (1 for a single value)."""
    span = high - low
    if span <= 0:
        return Decimal(1)
    return Decimal(1).scaleb(math.floor(math.log10(span)) - 1)


@dataclass(frozen=True)
class Drawn:
    """A candidate's fate: kept (with what the acceptance returned) or why not."""

    kept: Any = None
    reason: Optional[str] = None       # "assembly", "dead-point", "mistake-close"


def draw_variants(varies: list[Vary], count: int, seed: int,
                  accept: Callable[[dict[str, Decimal]], Drawn]) -> list[tuple[dict[str, Decimal], Any]]:
    """`count` distinct variants (the stated values and what `accept` kept of each), drawn in
    the generator's order; an `assembly` error naming `--vary` when the grids do not hold so
    many that assemble away from dead points."""
    import numpy as np

    names = [v.name for v in varies]
    if len(set(names)) != len(names):
        raise KinematikaError("usage", "varied-twice", "--vary", names=names)
    if not 1 <= count <= MAX_VARIANTS:
        raise KinematikaError("usage", "count-range", "--count", limit=MAX_VARIANTS, got=count)
    total = math.prod(v.count for v in varies)
    if total < count:
        raise KinematikaError("usage", "grids-too-small", "--vary", total=total, count=count)
    rng = np.random.default_rng(seed)
    seen: set[tuple[int, ...]] = set()
    out: list[tuple[dict[str, Decimal], Any]] = []
    failed = {"assembly": 0, "dead-point": 0, "mistake-close": 0}
    tries = TRIES * count + 200
    while len(out) < count and tries > 0 and len(seen) < total:
        tries -= 1
        ks = tuple(int(rng.integers(v.count)) for v in varies)
        if ks in seen:
            continue
        seen.add(ks)
        stated = {v.name: v.value(k) for v, k in zip(varies, ks)}
        drawn = accept(stated)
        if drawn.reason is not None:
            failed[drawn.reason] = failed.get(drawn.reason, 0) + 1
            continue
        out.append((stated, drawn.kept))
    if len(out) < count:
        raise KinematikaError("assembly", "variants-few", "--vary", found=len(out), count=count, drawn=len(seen),
                              apart=failed['assembly'], dead=failed['dead-point'],
                              close=failed['mistake-close'])
    return out
