"""Answers as plain data: floats (cleaned of round-off) or formula strings (simplified)."""
from __future__ import annotations

import math
from typing import Any

SIGNIFICANT = 12


def plain(value: Any, symbolic: bool, scale: float = 1.0) -> Any:
    """Convert a raw answer (nested dicts, tuples, scalars) into JSON-able data."""
    if value is None or isinstance(value, bool) or isinstance(value, str):
        return value
    if isinstance(value, dict):
        return {k: plain(v, symbolic, scale) for k, v in value.items()}
    if isinstance(value, (tuple, list)):
        return [plain(v, symbolic, scale) for v in value]
    if symbolic:
        return formula(value)
    return number(value, scale)


def number(x: Any, scale: float = 1.0) -> float:
    """A float rounded to 12 significant digits, with round-off below 1e-12·scale set to 0."""
    x = float(x)
    if not math.isfinite(x):
        return x
    if abs(x) <= 1e-12 * scale or x == 0:
        return 0.0
    digits = SIGNIFICANT - 1 - int(math.floor(math.log10(abs(x))))
    return float(round(x, digits)) + 0.0


def formula(x: Any) -> str:
    """A simplified formula in sympy's syntax (`4*Omega/3`, `sqrt(2)*r*w/4`)."""
    return str(tidy(x))


def tidy(x: Any) -> Any:
    """A readable exact form: the canonical rational form, factored."""
    import sympy

    from ..algebra.fields import canonical

    x = sympy.sympify(x)
    return x if x.is_Atom else canonical(x)
