"""Colours, line widths and sizes of the figures, in one place.

Results have strong reserved colours (velocity blue, acceleration red, centres purple,
curvature green); bodies get muted colours that none of those can be mistaken for.
Sizes of symbols are fractions of the drawing size, so a figure reads the same whatever
the model's units.
"""
from __future__ import annotations

import re

VELOCITY = "#1565c0"
ACCELERATION = "#c62828"
CENTRE = "#7b1fa2"
CURVATURE = "#2e7d32"
GROUND = "#424242"
INK = "#212121"
POINT_LABEL = "#37474f"
BODY_COLOURS = ("#78909c", "#c49a3a", "#8d6e63", "#5f8a8b", "#b0855c", "#9e9d24",
                "#a1887f", "#607d8b", "#d08c60", "#7e6b8f")
KIND_COLOURS = {"velocity": VELOCITY, "acceleration": ACCELERATION}

BAR_WIDTH = 7.0             # points
PIN_SIZE = 7.5              # marker size of a revolute pin, points
LABEL_SIZE = 9.0            # font size of labels
TITLE_SIZE = 12.0

LONGEST = 0.33              # the longest vector of each kind, as a fraction of the drawing size
SHORTEST = 0.07             # the shortest drawn vector (shorter ones are enlarged to this)
SUPPORT = 0.045             # size of a fixed-pivot symbol
BLOCK = (0.11, 0.06)        # slider block: length and height
SLOT_WIDTH = 0.035
HATCH_BAND = 0.03


def body_colour(number: int) -> str:
    """The colour of the body numbered `number` (the frame is 1 and is drawn in GROUND)."""
    return BODY_COLOURS[(number - 2) % len(BODY_COLOURS)]


_SIMPLE = re.compile(r"^[A-Za-z0-9_@/.' -]+$")


def symbol(letter: str, name: str) -> str:
    """`letter` with subscript `name` ($v_B$), in mathtext when `name` is simple enough,
    else as plain text v(name): any model name is drawn safely."""
    if _SIMPLE.match(name):
        inner = name.replace("_", r"\_").replace(" ", r"\ ")
        return "$" + letter + r"_{\mathrm{" + inner + "}}$"
    return f"{letter}({plain_name(name)})"


def plain_name(text: str) -> str:
    """A model name made safe for ordinary text (a `$` would start mathtext)."""
    return text.replace("$", r"\$")


def equation(lhs: str, rhs: str) -> str:
    """`lhs = rhs`, or `lhs ≈ x` when the value is only approximate."""
    return f"{lhs} {rhs}" if rhs.startswith("≈") else f"{lhs} = {rhs}"


def number(x: float, scale: float = 1.0) -> str:
    """3 significant digits, with round-off below 1e-9 of `scale` shown as 0."""
    return "0" if abs(x) <= 1e-9 * scale else f"{x:.3g}"
