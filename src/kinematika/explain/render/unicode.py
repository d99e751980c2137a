"""Exact values as readable one-line Unicode formulas (HTML, Markdown) or LaTeX."""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Any

from ...report.values import formula, tidy

SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


@lru_cache(maxsize=4096)
def _tidy(expr: Any) -> Any:
    """Simplified once per expression: the four languages and three formats share it."""
    return tidy(expr)


def unicode_formula(expr: Any) -> str:
    """`sqrt(2)*r**2*w/4` as `√2·r²·w/4`."""
    text = _bars(formula(expr))              # printed once (a long formula takes long to print)
    text = re.sub(r"\*\*(-?\d+)", lambda m: m.group(1).translate(SUPERSCRIPTS), text)
    text = re.sub(r"sqrt\((\w+)\)", r"√\1", text)
    text = text.replace("sqrt(", "√(").replace("**", "^").replace("*", "·")
    text = re.sub(r"\bpi\b", "π", text)
    return text.replace(" - ", " − ").replace("-", "−")


def _bars(text: str) -> str:
    """sympy's `Abs(x)` as the |x| a reader writes (nested ones too)."""
    while (start := text.find("Abs(")) >= 0:
        depth, end = 0, start + 3
        for end in range(start + 3, len(text)):
            depth += {"(": 1, ")": -1}.get(text[end], 0)
            if depth == 0:
                break
        text = text[:start] + "|" + text[start + 4:end] + "|" + text[end + 1:]
    return text


def latex_formula(expr: Any) -> str:
    import sympy

    return sympy.latex(_tidy(expr))
