"""How numbers are written in a language: one writer for the text of an explanation and
the figures beside it, so that a student reads the same `2,5` and `−0,3` in both.

The decimal sign is Babel's (`,` in es, ca, eu; `.` in en); a list of numbers (a vector's
components) is separated by `; ` where the decimal sign is a comma. Minus signs are true
minus signs (−), and a power of ten is written by the caller's markup (`×10<sup>−5</sup>`
in HTML, `×10⁻⁵` in a figure).
"""
from __future__ import annotations

import re
from functools import lru_cache
from typing import Callable

DECIMAL = re.compile(r"(?<=\d)\.(?=\d)")     # a decimal point inside a formula's text
SUPERSCRIPTS = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


@lru_cache(maxsize=None)
def decimal_sign(lang: str) -> str:
    """The language's decimal sign (Babel's)."""
    from babel.numbers import get_decimal_symbol

    return get_decimal_symbol(lang)


def separator(decimal: str) -> str:
    """Between the numbers of a list (a vector's components): `; ` where the decimal sign
    is a comma, so that `(0,32; 1,29)` reads as two numbers."""
    return "; " if decimal == "," else ", "


def written(x: float, digits: int, decimal: str, power: Callable[[str, int], str]) -> str:
    """`x` to `digits` significant digits with the `decimal` sign and a true minus sign;
    a number Python writes with an exponent (1e-05) as `power(mantissa, exponent)`."""
    if x == 0:
        return "0"
    text = f"{x:.{digits}g}".replace(".", decimal)
    if "e" in text:
        mantissa, exponent = text.split("e")
        return power(mantissa.replace("-", "−"), int(exponent))
    return text.replace("-", "−")


def superscript_power(mantissa: str, exponent: int) -> str:
    """`1,5×10⁻⁵`: a power of ten in plain text (a figure's label), with the digits raised."""
    return f"{mantissa}×10{str(exponent).translate(SUPERSCRIPTS)}"


# The functions a language writes under another name: Spanish writes the sine sen (sen β),
# as its textbooks and the RAE do; Catalan and Basque write sin, as English (the Catalan
# notes write no trigonometric function, so they keep sympy's name). One table for the
# text (HTML, Markdown), LaTeX and the figures' labels.
FUNCTION_NAMES: dict[str, dict[str, str]] = {"es": {"sin": "sen"}}


def function_names(text: str, lang: str | None, latex: bool = False) -> str:
    """`text`, a formula in sympy's plain form (`sin(β)`) or LaTeX (`\\sin{\\left(β \\right)}`),
    with each function named as `lang` writes it (`sen(β)` in Spanish). Only a call is
    renamed (`sin(`, `\\sin`), never a word or a symbol spelt the same."""
    for name, own in FUNCTION_NAMES.get(lang or "", {}).items():
        if latex:
            text = re.sub(rf"\\{name}(?![A-Za-z])", rf"\\operatorname{{{own}}}", text)
        else:
            text = re.sub(rf"(?<![\w\\]){name}(?=\()", own, text)
    return text
