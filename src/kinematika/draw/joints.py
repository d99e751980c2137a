"""Joint symbols painted with matplotlib: each kind of joint says how it is drawn (its
`symbol`: polygons, lines and dots; `kinematika.joints.symbols`), and this module paints
those marks, with the body colours, in the body they move with (an animation moves them),
keeping labels off them. The page paints the same marks (`web/scene_json.py`)."""
from __future__ import annotations

from typing import Any, Optional

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.patches import Polygon

from ..joints import kind as joint_kind
from ..joints.symbols import Mark, ring
from .canvas import Canvas, moving_centroid
from .geometry import Box, clip_line
from .scene import Scene
from .style import GROUND, INK


class SymbolContext:
    """What a joint's symbol needs of the figure (see `joints.symbols`): the scene, the view
    infinite lines stop in, and whether it is a still figure (not an animation's frame)."""

    def __init__(self, scene: Scene, view: Box, still: bool = True) -> None:
        self.scene, self.view, self.still = scene, view, still
        self.size = scene.size
        self.frame = scene.frame.name
        self.dim = scene.dim

    def centroid(self) -> np.ndarray:
        """The centroid of the moving bodies' points (where "away from the mechanism" starts)."""
        return moving_centroid(self.scene, self.view)

    def points(self, body: str) -> list:
        """The page positions of `body`'s points."""
        return list(self.scene.bodies[body].points.values())

    def keep_out(self) -> list[np.ndarray]:
        """Closed outlines ((n, 2) polygons) a fixed guide stops short of: each moving body's
        circles and closed curves (a cam's profile; not its pitch curve, which a roller's
        centre is on)."""
        out = []
        for body in self.scene.bodies.values():
            if body.name == self.frame:
                continue
            for sh in body.shapes:
                if sh.kind == "circle" and not sh.ring:
                    out.append(ring(np.asarray(sh.center, dtype=float), float(sh.radius)))
                elif sh.kind == "curve" and sh.closed and sh.role != "pitch" and sh.vertices is not None:
                    out.append(np.asarray(sh.vertices, dtype=float))
        return out

    def clip(self, p: np.ndarray, d: np.ndarray, inset: float) -> Optional[tuple]:
        """The part of the line through `p` along `d` inside the view shrunk by `inset`, or
        None."""
        return clip_line(p, d, self.view.grow(-inset))


def scene_symbols(scene: Scene, view: Box, still: bool = True) -> list[Mark]:
    """Every joint's marks on a figure of `scene` showing `view`."""
    ctx = SymbolContext(scene, view, still)
    return [m for j in scene.joints for m in joint_kind(j.type).symbol(j, ctx)]


def paint_joints(cv: Canvas) -> None:
    """Every joint's symbol, as its kind describes it (`joints.symbols`), painted in the body it
    moves with; a still figure gets the marks an animation leaves out."""
    for mark in scene_symbols(cv.scene, cv.view, cv.placement is None):
        paint_mark(cv, mark)


def colour_of(cv: Canvas, role: str) -> str:
    """A mark's colour role as a colour: ink, ground, white, none, or body:NAME."""
    if role.startswith("body:"):
        return cv.scene.bodies[role[5:]].colour
    return {"ink": INK, "ground": GROUND, "white": "white", "none": "none"}.get(role, role)


def paint_mark(cv: Canvas, m: Mark) -> None:
    """A mark as a matplotlib artist, in the body it moves with; labels kept off it."""
    edge, fill = colour_of(cv, m.colour), colour_of(cv, m.fill)
    pts = np.asarray(m.points, dtype=float)
    artist: Any
    if m.kind == "dot":
        artist = Line2D([pts[0, 0]], [pts[0, 1]], marker="o", ms=m.size, mfc=fill, mec=edge,
                        mew=m.width, color=fill if m.width == 0 else edge, zorder=m.zorder)
    elif m.kind == "line":
        artist = Line2D(*pts.T, lw=m.width, ls="-." if m.dash else "-", color=edge, zorder=m.zorder,
                        solid_capstyle="butt")
    else:
        artist = Polygon(pts, closed=True, fill=fill != "none" and not m.hatch, fc=fill if fill != "none" else None,
                         ec=edge, lw=m.width, hatch="////" if m.hatch else None, zorder=m.zorder)
    if m.gid:
        artist.set_gid(m.gid)
    cv.add(artist, m.moves_with)
    if m.avoid > 0:
        if m.kind == "dot":
            cv.board.avoid(pts[0], weight=m.avoid, radius=m.radius)
        else:
            cv.board.avoid(*pts, pts[0], weight=m.avoid)
