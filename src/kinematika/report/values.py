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
    """The shortest of a few cheap simplifications; full `simplify` only for small formulas."""
    import sympy

    x = sympy.sympify(x)
    radicals = any(p.base.is_number and not p.exp.is_integer for p in x.atoms(sympy.Pow))
    if x.is_number:
        return sympy.radsimp(x) if radicals else x
    candidates = [x]
    try:
        base = sympy.cancel(sympy.radsimp(x) if radicals else x)
        candidates += [base, sympy.factor(base), sympy.factor_terms(base)]
        if sympy.count_ops(base) < 40:
            candidates.append(sympy.simplify(base))
    except (sympy.PolynomialError, TypeError, ValueError):  # pragma: no cover - odd formulas
        pass
    return min(candidates, key=lambda e: (sympy.count_ops(e), len(str(e))))
