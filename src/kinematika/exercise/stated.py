"""Data as a statement gives it: a number in a unit (`400 mm`, `30°`, `4 rad/s`), and the
same value as the model holds it (0.4 in metres, deg(30) in radians).

A parameter's stated unit comes from the model's `exercise.units`; a parameter written
`deg(...)` in the model is stated in degrees unless the section says otherwise; any other
is a plain number in the model's own units. Stated values are exact decimals (a variant's
`s = 0.45` is 0.45, not 0.45000000000000001), and the model receives them as expressions
(`--set s=450/1000`, `--set beta=deg(35)`), as a teacher would type them.
"""
from __future__ import annotations

import ast
from decimal import Decimal
from fractions import Fraction
from typing import Any, Optional

from ..model.exercise_section import UNITS, ExerciseSection, Unit
from ..model.model import Model
from ..numerals import decimal_sign

ANGLES = {"deg": "deg", "degrees": "deg", "rad": "rad", "radians": "rad"}


def stated_unit(model: Model, section: ExerciseSection, name: str) -> Optional[Unit]:
    """The unit parameter `name` is stated in: the section's, else degrees for a parameter
    the model writes `deg(x)`, else None (a number in the model's units)."""
    unit = section.unit(name)
    if unit is not None:
        return unit
    param = model.parameters.get(name)
    if param is not None and param.value is not None and _degrees_call(param.value.tree):
        return UNITS["deg"]
    return None


def _degrees_call(tree: ast.AST) -> bool:
    return (isinstance(tree, ast.Call) and isinstance(tree.func, ast.Name)
            and ANGLES.get(tree.func.id) == "deg")


def model_factor(unit: Optional[Unit], section: ExerciseSection) -> tuple[Fraction, int]:
    """The size of one stated unit in the model's units, as ratio · π^k: lengths (and the
    lengths in speeds and accelerations) in the section's `length`, angles in radians."""
    if unit is None:
        return Fraction(1), 0
    ratio = unit.ratio
    if unit.kind in ("length", "speed", "accel"):
        ratio = ratio / section.length.ratio
    return ratio, unit.pi


def is_degrees(unit: Optional[Unit]) -> bool:
    """Whether a statement's unit is the degree (π/180 rad): its values reach the model as
    `deg(…)`."""
    return unit is not None and unit.kind == "angle" and unit.pi == 1 and unit.ratio == Fraction(1, 180)


def model_expression(value: Decimal, unit: Optional[Unit], section: ExerciseSection) -> str:
    """The stated `value` as the expression the model receives (`--set NAME=...`):
    `deg(35)` for degrees, `450/1000` for millimetres in a model in metres, `4` as is."""
    number = plain_decimal(value)
    if is_degrees(unit):
        return f"deg({number})"
    ratio, pi = model_factor(unit, section)
    if ratio == 1 and not pi:
        return number
    text = f"({number})" if number.startswith("-") else number
    if ratio.numerator != 1:
        text += f"*{ratio.numerator}"
    if pi:
        text += "*pi"
    if ratio.denominator != 1:
        text += f"/{ratio.denominator}"
    return text


def model_value(value: Decimal, unit: Optional[Unit], section: ExerciseSection) -> float:
    """The stated value in the model's units, as a float."""
    import math

    ratio, pi = model_factor(unit, section)
    return float(value) * float(ratio) * math.pi ** pi


def as_stated(model_number: float, unit: Optional[Unit], section: ExerciseSection) -> float:
    """A value in the model's units as the statement states it (0.4 m → 400 in mm)."""
    import math

    ratio, pi = model_factor(unit, section)
    return model_number / (float(ratio) * math.pi ** pi)


def plain_decimal(value: Decimal) -> str:
    """A decimal as written in a statement: no exponent, no trailing zeros (`0.45`, `400`)."""
    text = format(value.normalize(), "f")
    return "0" if text in ("-0", "") else text


def stated_text(value: Any, unit: Optional[Unit], lang: str, digits: int = 6) -> str:
    """`400 mm`, `30°`, `0,45 m` (the language's decimal sign, a true minus sign): a value
    as the statement prints it. Exact decimals keep their digits; floats get `digits`
    significant ones."""
    number = number_text(value, lang, digits)
    if unit is None:
        return number
    shown = unit.shown
    return f"{number}{shown}" if shown.startswith("°") else f"{number}\u00a0{shown}"


def number_text(value: Any, lang: str, digits: int = 6) -> str:
    """A number in `lang`'s writing: its decimal sign, a true minus sign."""
    if isinstance(value, Decimal):
        text = plain_decimal(value)
    else:
        text = plain_decimal(Decimal(f"{float(value):.{digits}g}"))
    return text.replace(".", decimal_sign(lang)).replace("-", "−")
