"""Small model trees shared by the core tests (built in code, so tests need no files)."""
from __future__ import annotations

import copy
import math
from pathlib import Path

import yaml

# Crank-rocker: ground 4, crank 1, coupler 4, rocker 3; crank vertical, B on the open branch.
BX = (48 + 8 * math.sqrt(2)) / 17
BY = 4 * BX - 11

FOUR_BAR = {
    "name": "Four-bar",
    "parameters": {"w2": 10},
    "points": {"O2": [0, 0], "A": [0, 1],
               "B": ["(48 + 8*sqrt(2))/17", "4*(48 + 8*sqrt(2))/17 - 11"], "O4": [4, 0]},
    "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B"],
               "rocker": ["B", "O4"]},
    "joints": [
        {"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
        {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
        {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
        {"type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"},
    ],
    "drivers": [{"omega": "crank", "value": "w2", "alpha": 0}],
}


def four_bar(**changes) -> dict:
    """A copy of the four-bar tree with top-level keys replaced."""
    tree = copy.deepcopy(FOUR_BAR)
    tree.update(copy.deepcopy(changes))
    return tree


def four_bar_closed_form(w2: float = 10.0, al2: float = 0.0):
    """ω3, ω4, α3, α4 from the loop equation A + L3 e3 = O4 + L4 e4, differentiated by hand.

    Velocity: ω2 k×OA + ω3 k×AB = ω4 k×O4B, two scalar equations in ω3, ω4 (Cramer).
    Acceleration: α2 k×OA − ω2² OA + α3 k×AB − ω3² AB = α4 k×O4B − ω4² O4B.
    """
    oa = (0.0, 1.0)
    ab = (BX - 0.0, BY - 1.0)
    o4b = (BX - 4.0, BY - 0.0)

    def perp(v):
        return (-v[1], v[0])

    def solve2(c1, c2, rhs):
        det = c1[0] * c2[1] - c1[1] * c2[0]
        return ((rhs[0] * c2[1] - rhs[1] * c2[0]) / det, (c1[0] * rhs[1] - c1[1] * rhs[0]) / det)

    # unknowns (ω3, ω4): ω3 k×AB − ω4 k×O4B = −ω2 k×OA
    rhs = tuple(-w2 * c for c in perp(oa))
    w3, w4 = solve2(perp(ab), tuple(-c for c in perp(o4b)), rhs)
    known = tuple(-al2 * p + w2 ** 2 * a + w3 ** 2 * b - w4 ** 2 * c
                  for p, a, b, c in zip(perp(oa), oa, ab, o4b))
    a3, a4 = solve2(perp(ab), tuple(-c for c in perp(o4b)), known)
    return w3, w4, a3, a4


JANSEN_TOP = ("a", "l", "m", "j", "b", "d", "e", "theta", "w")     # the top's parameters


def jansen(top: bool = True, theta_symbol: bool = True) -> dict:
    """Jansen's leg (examples/jansen_leg.yaml), its crank angle a symbol; with `top`, cut to
    its crank and top triangle (O-A, A-B, Z-B-E: two circle intersections in a chain, B then
    E from B's roots), asked E's velocity and acceleration — the smallest piece of the leg
    whose exact answers take named coordinates, a quarter of the whole leg's work."""
    tree = yaml.safe_load((Path(__file__).resolve().parents[2] / "examples" / "jansen_leg.yaml").read_text())
    if theta_symbol:
        tree["parameters"]["theta"] = None
    if top:
        tree["parameters"] = {k: tree["parameters"][k] for k in JANSEN_TOP}
        tree["points"] = {k: tree["points"][k] for k in "ZOABE"}
        tree["bodies"] = {k: tree["bodies"][k] for k in ("ground", "crank", "upper", "top")}
        tree["joints"] = tree["joints"][:4]
        tree["ask"] = [{"velocity": "E"}, {"acceleration": "E"}]
        del tree["sweep"]
    return tree
