"""Which designs a study evaluates: a grid or a space-filling sample of the varied parameters.

Designs are numbered 0, 1, ... and any range of them is computed on its own, so that a
study is cut into chunks that any worker can evaluate, in any order, with the same values.
A grid takes N equally spaced values of each parameter (both ends included), the first
parameter varying slowest; a sample takes N points of a scrambled Sobol' sequence (scipy's
quasi-Monte-Carlo) fixed by its seed, scaled to the intervals.
"""
from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..errors import KinematikaError

MAX_DESIGNS = 10 ** 10


@dataclass(frozen=True)
class Vary:
    """A varied parameter and its interval."""

    name: str
    low: float
    high: float


def parse_vary(text: str) -> Vary:
    """`NAME=LOW:HIGH` as a `Vary`; a malformed one is a usage error naming it."""
    name, eq, interval = text.partition("=")
    low, colon, high = interval.partition(":")
    try:
        if not (eq and colon and name.strip()):
            raise ValueError
        lo, hi = float(low), float(high)
    except ValueError:
        raise KinematikaError("usage", "vary-form", "--vary", got=repr(text)) from None
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi < lo:
        raise KinematikaError("usage", "vary-interval", "--vary", name=name.strip(), got=f"{lo:g}:{hi:g}")
    return Vary(name.strip(), lo, hi)


@dataclass(frozen=True)
class Designs:
    """The designs of a study: `grid` values per parameter, or `samples` Sobol' points."""

    vary: tuple[Vary, ...]
    grid: Optional[int] = None
    samples: Optional[int] = None
    seed: int = 0

    def __post_init__(self) -> None:
        if not self.vary:
            raise KinematikaError("usage", "vary-none", "--vary")
        names = [v.name for v in self.vary]
        if len(set(names)) != len(names):
            raise KinematikaError("usage", "varied-twice", "--vary", names=names)
        if (self.grid is None) == (self.samples is None):
            raise KinematikaError("usage", "grid-or-samples", "--grid")
        if (self.grid is not None and self.grid < 1) or (self.samples is not None and self.samples < 1):
            raise KinematikaError("usage", "grid-positive", "--grid")
        if self.count > MAX_DESIGNS:
            raise KinematikaError("usage", "designs-too-many", "--grid", count=self.count, limit=MAX_DESIGNS)

    @property
    def names(self) -> list[str]:
        """The varied parameters' names, in the order given."""
        return [v.name for v in self.vary]

    @property
    def count(self) -> int:
        """How many designs: grid^(parameters varied) for a grid, else the number of samples."""
        return self.grid ** len(self.vary) if self.grid is not None else int(self.samples or 0)

    def values(self, start: int, stop: int) -> dict[str, np.ndarray]:
        """The designs start, ..., stop - 1: one array of values per varied parameter."""
        if self.grid is not None:
            index = np.unravel_index(np.arange(start, stop), (self.grid,) * len(self.vary))
            return {v.name: _grid_values(v, self.grid)[i] for v, i in zip(self.vary, index)}
        unit = self._sobol(start, stop - start)
        return {v.name: v.low + unit[:, k] * (v.high - v.low) for k, v in enumerate(self.vary)}

    def _sobol(self, start: int, count: int) -> np.ndarray:
        from scipy.stats import qmc

        engine = qmc.Sobol(len(self.vary), scramble=True, rng=np.random.default_rng(self.seed))
        if start:
            engine.fast_forward(start)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")          # balance properties want powers of 2
            return engine.random(count)


def _grid_values(v: Vary, n: int) -> np.ndarray:
    return np.linspace(v.low, v.high, n) if n > 1 else np.array([v.low])
