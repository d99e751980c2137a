"""Arrays of designs: the third algebra, beside `backend.Numeric` and `backend.Symbolic`.

A design study evaluates one model at many parameter values at once. Here a parameter is
a numpy array (one value per design) and every expression, construction and closed-form
formula broadcasts over it. Nothing raises for one bad design: a value that cannot be
computed (the square root of a negative number, a logarithm of zero) is NaN, and the
caller asks the per-design path why (`sweep.batch`).
"""
from __future__ import annotations

from typing import Any, Callable

import numpy as np

from ..expressions import ExpressionError


class Arrays:
    """Numpy arrays, one value per design; `values` holds the varied parameters' arrays."""

    symbolic = False
    pi = np.pi

    def __init__(self, values: dict[str, np.ndarray]) -> None:
        self.values = values

    def number(self, value: int | float) -> float:
        """A number written in the model, as a float (the same in every design)."""
        return float(value)

    def function(self, name: str) -> Callable[..., Any]:
        """The model's function `name` (sin, sqrt, atan2, deg …) on arrays: NaN outside its
        domain for a design, never an error for the study."""
        return _FUNCTIONS[name]

    def check(self, value: Any, source: str) -> Any:
        """A computed value, kept as it is: a non-finite entry marks its own design, and the
        per-design path says why."""
        return value               # a non-finite value marks its design, not the study

    def symbol(self, name: str, positive: bool = True) -> np.ndarray:
        """A varied parameter: its array of values."""
        if name not in self.values:
            raise ExpressionError("parameter-no-value", name=name)
        return self.values[name]

    def sqrt(self, x: Any) -> Any:
        """√x for each design; round-off below zero (> −1e-12) is 0, a real negative NaN."""
        return _sqrt(x)

    def simplify(self, x: Any) -> Any:
        """`x` unchanged: arrays of numbers have nothing to simplify (the `Symbolic` backend
        simplifies)."""
        return x


def _sqrt(x: Any) -> Any:
    """√x; round-off below zero (> -1e-12) is 0, a real negative is NaN (as `Numeric` raises)."""
    x = np.asarray(x, dtype=float)
    return np.sqrt(np.where((x < 0) & (x > -1e-12), 0.0, x))


def _where_defined(f: Callable, low: float = -np.inf, high: float = np.inf,
                   open_low: bool = False) -> Callable:
    """f where its argument lies in its domain, NaN elsewhere."""
    def g(x: Any) -> Any:
        x = np.asarray(x, dtype=float)
        inside = (x > low if open_low else x >= low) & (x <= high)
        return np.where(inside, f(np.where(inside, x, high if np.isfinite(high) else 1.0)), np.nan)
    return g


_FUNCTIONS: dict[str, Callable[..., Any]] = {
    "sqrt": _sqrt, "cbrt": np.cbrt, "sin": np.sin, "cos": np.cos, "tan": np.tan,
    "asin": _where_defined(np.arcsin, -1.0, 1.0), "acos": _where_defined(np.arccos, -1.0, 1.0),
    "atan": np.arctan, "atan2": np.arctan2, "exp": np.exp,
    "log": _where_defined(np.log, 0.0, np.inf, open_low=True), "abs": np.abs,
    "deg": np.radians, "rad": np.radians, "radians": np.radians, "degrees": np.degrees,
    "sinh": np.sinh, "cosh": np.cosh, "tanh": np.tanh,
}
