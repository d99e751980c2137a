"""A planar mechanism of any size: a chain of parallelogram four-bar loops.

Stage 0 is a crank pivoted at O0 = (0, 0) with its pin A0 at (0, 1). Loop i (1, 2, ...)
adds a coupler from A(i-1) to A(i) = (4i, 1) and a rocker pivoted on the ground at
O(i) = (4i, 0): a parallelogram (ground 4, crank 1, coupler 4, rocker 1), so every rocker
turns exactly as the crank does and every coupler translates (an answer known by hand).
The rocker of one loop is the crank of the next.
"""
from __future__ import annotations


def four_bar_chain(bodies: int, w: float = 10.0, alpha: float = 0.0) -> dict:
    """A model tree with about `bodies` moving bodies (1 + 2 per loop)."""
    loops = max(0, (bodies - 1) // 2)
    points = {"O0": [0.0, 0.0], "A0": [0.0, 1.0]}
    tree_bodies: dict = {"ground": ["O0"], "crank": ["O0", "A0"]}
    joints = [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O0"}]
    previous = "crank"
    for i in range(1, loops + 1):
        points[f"O{i}"] = [4.0 * i, 0.0]
        points[f"A{i}"] = [4.0 * i, 1.0]
        tree_bodies["ground"].append(f"O{i}")
        tree_bodies[f"coupler{i}"] = [f"A{i - 1}", f"A{i}"]
        tree_bodies[f"rocker{i}"] = [f"O{i}", f"A{i}"]
        joints += [{"type": "revolute", "bodies": [previous, f"coupler{i}"], "at": f"A{i - 1}"},
                   {"type": "revolute", "bodies": [f"coupler{i}", f"rocker{i}"], "at": f"A{i}"},
                   {"type": "revolute", "bodies": [f"rocker{i}", "ground"], "at": f"O{i}"}]
        previous = f"rocker{i}"
    return {"name": f"Chain of {loops} parallelogram loops", "points": points, "bodies": tree_bodies,
            "joints": joints, "drivers": [{"omega": "crank", "value": w, "alpha": alpha}], "ask": []}
