"""An answer as a student types it: a number, perhaps with a decimal comma, a true minus sign,
thousands separators or an exponent, and perhaps a unit (`0,915 m/s`, `915 mm/s`, `−2.2 m/s²`,
`12 rpm`).

A unit of the quantity's kind is converted to the model's units (`915 mm/s` is 0.915 in a
model in metres); a unit of another kind (`m/s²` for a velocity), or a word that is no unit,
is the mistake `wrong-unit`, and the number is kept as typed. A number without a unit is in
the unit the box shows (the model's).

Decimal and thousands separators: with both `.` and `,` the last is the decimal sign
(`1.234,5`, `1,234.5`); a lone `,` is a decimal comma (`0,915`); several of the same sign
are thousands separators (`1.234.567`). Spaces (also non-breaking and thin ones) are
dropped. Exponents: `1.2e-3`, `1,2E-3`, `1.2×10^-3`, `1.2·10⁻³`.
"""
from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Optional

from ..model.exercise_section import UNITS, ExerciseSection, Unit

NUMBER = re.compile(r"[+-]? ?(?:\d{1,3}(?: \d{3})+(?:[.,]\d*)?|\d[\d.,]*|[.,]\d+)(?:[eE][+-]?\d+)?")
SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")
# the kind of unit each kind of key row is measured in (key.KIND_UNITS)
ROW_UNITS = {"position": "length", "velocity": "speed", "acceleration": "accel", "omega": "rate",
             "alpha": "rate2"}
# units students write that the statement's table (model.exercise_section.UNITS) spells otherwise
ALIASES = {"1/s": "rad/s", "s^-1": "rad/s", "rad·s^-1": "rad/s", "rev/min": "rpm", "r/min": "rpm",
           "min^-1": "rpm", "1/min": "rpm", "1/s^2": "rad/s^2", "s^-2": "rad/s^2", "rad·s^-2": "rad/s^2",
           "°/s": "deg/s", "°/s^2": "deg/s^2", "m·s^-1": "m/s", "mm·s^-1": "mm/s", "cm·s^-1": "cm/s",
           "m·s^-2": "m/s^2", "mm·s^-2": "mm/s^2", "cm·s^-2": "cm/s^2", "ms^-1": "m/s", "ms^-2": "m/s^2"}


@dataclass(frozen=True)
class Typed:
    """What was typed: the text, the number read from it (None when there is none) and the
    unit after it ('' when none; `unit` None when the text is no known unit)."""

    text: str
    number: Optional[float]
    unit_text: str
    unit: Optional[Unit]


def read_typed(text: str) -> Typed:
    """The number and the unit of a typed answer."""
    clean = " ".join(text.replace("−", "-").replace("–", "-").replace("\u00a0", " ").replace("\u2009", " ")
                     .replace("\u202f", " ").split())
    clean = re.sub(r"\s*[x×*·]\s*10\s*\^?\s*([+-]?\d+|[⁻⁺]?[⁰¹²³⁴⁵⁶⁷⁸⁹]+)",
                   lambda m: "e" + m.group(1).translate(SUPERSCRIPTS), clean)
    m = NUMBER.match(clean)
    number = _number(m.group(0).replace(" ", "")) if m else None
    if m is None or number is None:
        return Typed(text, None, "", None)
    rest = clean[m.end():].strip()
    return Typed(text, number, rest, unit_named(rest) if rest else None)


def _number(text: str) -> Optional[float]:
    mantissa, _, exponent = text.replace("E", "e").partition("e")
    dots, commas = mantissa.count("."), mantissa.count(",")
    if dots and commas:
        decimal = "." if mantissa.rfind(".") > mantissa.rfind(",") else ","
        if mantissa.count(decimal) > 1:
            return None
        mantissa = mantissa.replace("," if decimal == "." else ".", "").replace(",", ".")
    elif commas > 1 or dots > 1:
        mantissa = mantissa.replace(",", "").replace(".", "")
    else:
        mantissa = mantissa.replace(",", ".")
    try:
        value = float(mantissa + (f"e{exponent}" if exponent else ""))
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def unit_named(text: str) -> Optional[Unit]:
    """The unit a student wrote (`m/s`, `mm/s²`, `rad/s`, `1/s`, `rpm`, `°/s`), or None."""
    t = text.strip().replace("º", "°").replace("²", "^2").replace("⁻¹", "^-1").replace("⁻²", "^-2")
    t = t.replace("*", "·").replace(".", "·")
    t = ALIASES.get(t, t)
    if t.endswith("2") and not t.endswith("^2") and t[:-1] + "^2" in UNITS:
        t = t[:-1] + "^2"
    return UNITS.get(t) or UNITS.get(t.lower())


def in_model_units(typed: Typed, row_kind: str, section: ExerciseSection) -> tuple[Optional[float], bool]:
    """(the typed value in the model's units, whether its unit is right): a unit of the row's
    kind is converted (lengths, speeds and accelerations against the model's length unit,
    angles in radians); none is the box's unit; any other is wrong and the number is kept."""
    if typed.number is None:
        return None, True
    if not typed.unit_text:
        return typed.number, True
    wanted = ROW_UNITS.get(row_kind)
    if typed.unit is None or wanted is None or typed.unit.kind != wanted:
        return typed.number, False
    base = section.length.size if wanted in ("length", "speed", "accel") else 1.0
    return typed.number * typed.unit.size / base, True
