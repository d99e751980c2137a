"""Colours, line widths and sizes of the figures, in one place.

Results have strong reserved colours (velocity blue, acceleration red, centres purple,
curvature green); bodies get muted colours that none of those can be mistaken for.
Sizes of symbols are fractions of the drawing size, so a figure reads the same whatever
the model's units.
"""
from __future__ import annotations

VELOCITY = "#1565c0"
ACCELERATION = "#c62828"
CENTRE = "#7b1fa2"
CURVATURE = "#2e7d32"
GROUND = "#424242"
INK = "#212121"
POINT_LABEL = "#37474f"
PATH = "#6d4c41"             # a point's path over a motion (a coupler curve)
DIMENSION = "#455a64"        # a statement's dimension marks (lengths, angles)
BODY_COLOURS = ("#78909c", "#c49a3a", "#8d6e63", "#5f8a8b", "#b0855c", "#9e9d24",
                "#a1887f", "#607d8b", "#d08c60", "#7e6b8f")
KIND_COLOURS = {"velocity": VELOCITY, "acceleration": ACCELERATION}

BAR_WIDTH = 7.0             # points
LABEL_SIZE = 9.0            # font size of labels
TITLE_SIZE = 12.0

LONGEST = 0.33              # the longest vector of each kind, as a fraction of the drawing size
SHORTEST = 0.07             # the shortest drawn vector (shorter ones are enlarged to this)


def body_colour(number: int) -> str:
    """The colour of the body numbered `number` (the frame is 1 and is drawn in GROUND)."""
    return BODY_COLOURS[(number - 2) % len(BODY_COLOURS)]
