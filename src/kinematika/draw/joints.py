"""Joint symbols: pins, fixed pivots, sliders on guides, slots, knife-edge wheels.

Each symbol is fixed in the body it belongs to, so that an animation moves it with that
body: a slider's block with the slider, its guide with the guiding body; a pin with the
moving body of the pair.
"""
from __future__ import annotations

from typing import Optional

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from .bodies import hatched_edge
from .canvas import Canvas
from .geometry import clip_line, perpendicular, rectangle, stadium, unit
from .scene import JointView
from .style import BLOCK, GROUND, INK, PIN_SIZE, SLOT_WIDTH, SUPPORT, HATCH_BAND


def paint_joints(cv: Canvas) -> None:
    for j in cv.scene.joints:
        painter = PAINTERS.get(j.type)
        if painter is not None:
            painter(cv, j)


def _frame(cv: Canvas) -> str:
    return cv.scene.frame.name


def _mover(cv: Canvas, j: JointView) -> Optional[str]:
    """The body a symbol at the joint moves with: the second body unless it is the frame."""
    frame = _frame(cv)
    if j.b != frame:
        return j.b
    return j.a if j.a != frame else None


def _pin(cv: Canvas, j: JointView, centre_dot: bool = False, body: Optional[str] = "") -> None:
    """A pin at the joint, moving with `body` (by default the pair's moving body)."""
    p = j.at
    body = _mover(cv, j) if body == "" else body
    cv.add(Line2D([p[0]], [p[1]], marker="o", ms=PIN_SIZE, mfc="white", mec=INK, mew=1.6,
                  zorder=6, gid=f"joint:{j.id}"), body)
    if centre_dot:
        cv.add(Line2D([p[0]], [p[1]], marker="o", ms=2.5, color=INK, zorder=7), body)
    cv.board.avoid(p, weight=2.0, radius=4.0)


def _revolute(cv: Canvas, j: JointView) -> None:
    if j.at is None:
        return
    if _frame(cv) in (j.a, j.b):
        _support(cv, j.at)
    if j.axis is not None and np.linalg.norm(j.axis) > 1e-6:
        _axis_line(cv, j)
    _pin(cv, j)


def _spherical(cv: Canvas, j: JointView) -> None:
    if j.at is not None:
        if _frame(cv) in (j.a, j.b):
            _support(cv, j.at)
        _pin(cv, j, centre_dot=True)


def _axis_line(cv: Canvas, j: JointView) -> None:
    """A 3D joint's axis, dash-dot, through the joint (its page image)."""
    half = 0.14 * cv.size * j.axis
    seg = np.array([j.at - half, j.at + half])
    cv.add(Line2D(*seg.T, lw=1.0, ls="-.", color=INK, zorder=3), _mover(cv, j))


def _support(cv: Canvas, p: np.ndarray) -> None:
    """A fixed pivot: a triangle from the pin to a hatched base, below the pin (in a planar
    model, above it when the pin is clearly above the rest of the mechanism: it hangs)."""
    h = SUPPORT * cv.size
    d = p - cv.moving_centroid()
    hanging = cv.scene.dim == 2 and d[1] > 0.3 * np.linalg.norm(d) and d[1] > 1e-9
    down = np.array([0.0, 1.0]) if hanging else np.array([0.0, -1.0])   # 3D: the vertical
    side = np.array([1.0, 0.0])
    base = p + down * h
    tri = [p, base - 0.75 * h * side, base + 0.75 * h * side]
    cv.add(Polygon(tri, closed=True, fc="#e0e0e0", ec=GROUND, lw=1.3, zorder=2, gid="ground:pivot"))
    cv.add(Line2D(*np.array([base - h * side, base + h * side]).T, lw=1.8, color=GROUND, zorder=2))
    band = 0.55 * h
    cv.add(Polygon([base - h * side, base + h * side, base + h * side + band * down,
                    base - h * side + band * down], closed=True, fill=False, ec=GROUND, lw=0,
                   hatch="////", zorder=1))
    cv.board.avoid(*tri, p)
    cv.board.avoid(base - h * side, base + h * side + band * down)


def _slider_centre(cv: Canvas, j: JointView) -> Optional[np.ndarray]:
    if j.at is not None:
        return j.at
    for name in (j.b, j.a):
        pts = list(cv.scene.bodies[name].points.values())
        if pts and name != _frame(cv):
            return np.mean(pts, axis=0)
    return None


def _prismatic(cv: Canvas, j: JointView) -> None:
    """A block (second body) on its guide (first body); a fixed guide is hatched."""
    along = j.along if j.along is not None else (unit(j.axis) if j.axis is not None else None)
    centre = _slider_centre(cv, j)
    if along is None or centre is None:
        return
    length, height = (f * cv.size for f in BLOCK)
    _guide(cv, j.a, centre, along, height)
    block = rectangle(centre, along, length, height)
    colour = cv.scene.bodies[j.b].colour if j.b != _frame(cv) else GROUND
    cv.add(Polygon(block, closed=True, fc=colour, ec=INK, lw=1.3, zorder=4,
                   gid=f"joint:{j.id}"), _mover(cv, j) if j.b != _frame(cv) else None)
    cv.board.avoid(*block, block[0])
    cv.board.avoid(*rectangle(centre, along, 0.6 * length, 0.4 * height)[[0, 1, 2, 3, 0]])


def _guide(cv: Canvas, body: str, centre: np.ndarray, along: np.ndarray, height: float) -> None:
    frame = body == _frame(cv)
    if frame:
        n = perpendicular(along)
        side = n if float(n @ (centre - cv.moving_centroid())) > 1e-12 * cv.size else -n
        seg = clip_line(centre + side * height / 2, along, cv.view.grow(-HATCH_BAND * cv.size))
        if seg is not None:
            hatched_edge(cv, *seg, side, "ground:guide")
        return
    colour = cv.scene.bodies[body].colour
    pts = list(cv.scene.bodies[body].points.values()) + [centre]
    ts = [float((p - centre) @ along) for p in pts]
    margin = 0.12 * cv.size
    seg = np.array([centre + (min(ts) - margin) * along, centre + (max(ts) + margin) * along])
    cv.add(Line2D(*seg.T, lw=3.0, color=colour, zorder=3, solid_capstyle="butt"), body)
    cv.board.avoid(*seg)


def _slot(cv: Canvas, j: JointView) -> None:
    """A slot of the first body (a rounded outline along its line) and the pin in it."""
    if j.at is None or j.along is None:
        return
    half = SLOT_WIDTH * cv.size / 2
    if j.span is not None:
        p, q = j.span
        d = unit(q - p)
        p, q = p - 2 * half * d, q + 2 * half * d
        if float((j.at - p) @ d) < 0 or float((j.at - q) @ d) > 0:   # pin beyond the given span
            ts = [float((x - p) @ d) for x in (p, q, j.at)]
            p, q = p + (min(ts) - 2 * half) * d, p + (max(ts) + 2 * half) * d
    else:
        p, q = j.at - 0.15 * cv.size * j.along, j.at + 0.15 * cv.size * j.along
    colour = GROUND if j.a == _frame(cv) else cv.scene.bodies[j.a].colour
    outline = stadium(p, q, half)
    cv.add(Polygon(outline, closed=True, fc="white", ec=colour, lw=2.0, zorder=3,
                   gid=f"slot:{j.id}"), None if j.a == _frame(cv) else j.a)
    cv.board.avoid(*outline)
    _pin(cv, j, body=None if j.b == _frame(cv) else j.b)   # the pin is the second body's


def _wheel(cv: Canvas, j: JointView) -> None:
    """A knife edge seen from above: a narrow dark wheel along its rolling direction."""
    if j.at is None or j.along is None:
        return
    wheel = rectangle(j.at, j.along, 0.10 * cv.size, 0.03 * cv.size)
    cv.add(Polygon(wheel, closed=True, fc=INK, ec=INK, lw=1.0, zorder=5, gid=f"joint:{j.id}"),
           _mover(cv, j))
    cv.board.avoid(*wheel, wheel[0])


def _contact(cv: Canvas, j: JointView) -> None:
    """The contact point of a rolling pair (a still figure only: it is no body's point)."""
    if j.contact is not None and cv.placement is None:
        p = j.contact
        cv.add(Line2D([p[0]], [p[1]], marker="o", ms=3.5, color=INK, zorder=6,
                      gid=f"joint:{j.id}"))
        cv.board.avoid(p)


PAINTERS = {"revolute": _revolute, "spherical": _spherical, "prismatic": _prismatic,
            "cylindrical": _prismatic, "slot": _slot, "wheel": _wheel, "rolling": _contact,
            "gear": _contact}
