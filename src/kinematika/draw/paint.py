"""The matplotlib painter: every mark of a picture (`draw.picture`) as the artist it names,
with no rule of its own about what is drawn — as the page's painter
(`web/static/js/figure.js`) paints the same marks as SVG.

A mark fixed in a body is drawn through that body's placement (an animation moves it); a
text goes on the label board, placed when the figure is finished; a "clear" mark, and any
mark with an `avoid` weight, is kept clear of by the labels.
"""
from __future__ import annotations

import functools
from typing import Any, Optional

import numpy as np
from matplotlib._enums import CapStyle, JoinStyle     # documented: matplotlib.org/stable/api/_enums_api.html
from matplotlib.backend_bases import GraphicsContextBase
from matplotlib.lines import Line2D
from matplotlib.markers import MarkerStyle
from matplotlib.patches import Annulus, Circle, FancyArrowPatch, Polygon
from matplotlib.patheffects import withStroke
from matplotlib.transforms import offset_copy

from ..joints.symbols import Mark
from .canvas import Canvas
from .labels import BLOCK
from .geometry import perpendicular, unit
from .style import LABEL_SIZE


def paint(cv: Canvas, marks: list[Mark]) -> None:
    """Paint `marks` in order (matplotlib stacks them by their zorder)."""
    for mark in marks:
        paint_mark(cv, mark)


def paint_mark(cv: Canvas, m: Mark) -> Optional[Any]:
    """A mark as a matplotlib artist (None for a text, a clear mark or a zero arrow)."""
    pts = np.asarray(m.points, dtype=float)
    if m.kind == "text":
        cv.label(pts[0], m.text, m.colour, m.priority, m.gid, m.prefer, weight=m.weight,
                 style=m.style, size=m.size or LABEL_SIZE, shaft=m.shaft, spots=m.spots)
        return None
    if m.kind == "clear" and m.group.startswith(("area:", "ground-area:")):
        kind, _, owner = m.group.partition(":")
        cv.board.area(owner, pts, ground=kind == "ground-area")
        return None
    if m.kind == "clear" and m.group.startswith("head:"):
        cv.board.head(*pts[:2])
        return None
    if m.kind != "clear":
        drawn = artist(m)
        if drawn is None:
            return None
        if m.kind == "arrow" and m.shift:
            n = perpendicular(unit(pts[1] - pts[0])) * m.shift
            drawn.set_transform(offset_copy(cv.transform(m.moves_with), fig=cv.ax.figure,
                                            x=n[0], y=n[1], units="points"))
            cv.ax.add_patch(drawn)
        else:
            cv.add(drawn, m.moves_with)
    if m.avoid > 0:
        _avoid(cv, m, pts)
    if m.hatch and m.kind in ("polygon", "ring"):
        cv.board.area("", hatched_region(m, pts))
    return None


def hatched_region(m: Mark, pts: np.ndarray) -> np.ndarray:
    """The region a hatched mark covers (a closed polygon, data coordinates): a polygon's
    own, a ring's band as its outer circle then its inner one backwards. No name or value
    sits on it (`LabelBoard.area` with no owner)."""
    if m.kind == "polygon":
        return np.vstack([pts, pts[:1]])
    t = np.linspace(0, 2 * np.pi, 37)
    circle = np.column_stack([np.cos(t), np.sin(t)])
    return np.vstack([pts[0] + m.r * circle, (pts[0] + (m.r - m.band) * circle)[::-1]])


def artist(m: Mark) -> Optional[Any]:
    """The matplotlib artist of a drawn mark (not a text or a clear mark), with its gid; None
    for an arrow of no length."""
    drawn = ARTISTS[m.kind](m, np.asarray(m.points, dtype=float))
    if drawn is not None and m.gid:
        drawn.set_gid(m.gid)
    return drawn


def _avoid(cv: Canvas, m: Mark, pts: np.ndarray) -> None:
    """Labels keep off the mark: a clear mark's polyline, a dot's point, another's points
    round (back to the first)."""
    if m.kind == "clear":
        role, _, owner = (m.group or "").partition(":")
        outline = role in ("outline", "bar", "centre")
        cv.board.avoid(*pts, weight=m.avoid, radius=m.radius, owner=owner if outline else "",
                       bar=role == "bar", width=m.width, centre=role == "centre")
    elif m.kind == "dot":
        cv.board.avoid(pts[0], weight=m.avoid, radius=m.radius)
    else:                                     # a joint's block is its symbol's (`labels.BLOCK`)
        block = m.kind == "polygon" and m.gid.startswith("joint:")
        cv.board.avoid(*pts, pts[0], weight=m.avoid, owner=f"{BLOCK}{m.gid}" if block else "")


def _colour(c: str) -> Any:
    return "none" if c == "none" else c


def _dashes(m: Mark) -> Any:
    """matplotlib's line style: solid, dash-dot, or dashes in line widths (which it scales)."""
    if m.dash is True:
        return "-."
    if m.dash:
        return (0, tuple(m.dash))
    return "-"


def _alpha(m: Mark) -> Optional[float]:
    return None if m.alpha == 1.0 else m.alpha


def _dot(m: Mark, pts: np.ndarray) -> Line2D:
    return Line2D([pts[0, 0]], [pts[0, 1]], marker=m.shape, ms=m.size, mfc=_colour(m.fill),
                  mec=_colour(m.colour), mew=m.width, ls="", alpha=_alpha(m), zorder=m.zorder)


@functools.cache
def marker_outline(shape: str) -> Optional[tuple[tuple[float, float], ...]]:
    """The outline of a dot's marker `shape` ("D", "X", "P") as matplotlib paints it, its
    vertices in units of the marker's size (points) about its centre; None for a circle ("o").
    The page paints a dot from these vertices, so both painters draw the one marker."""
    if shape == "o":
        return None
    style = MarkerStyle(shape)
    outline = np.asarray(style.get_path().transformed(style.get_transform()).to_polygons()[0], dtype=float)
    return tuple((float(u), float(v)) for u, v in outline[:-1])   # closed: the first not repeated


def _line(m: Mark, pts: np.ndarray) -> Line2D:
    cap, join = CapStyle(m.cap or "projecting"), JoinStyle(m.join or "miter")   # what Line2D makes of them
    return Line2D(*pts.T, lw=m.width, ls=_dashes(m), color=m.colour, alpha=_alpha(m),
                  solid_capstyle=cap, dash_capstyle=cap, solid_joinstyle=join,
                  dash_joinstyle=join, zorder=m.zorder)


def _filled(m: Mark) -> dict:
    """A patch's fill and edge: a hatched patch has no fill, its hatching in its colour."""
    fill = m.fill != "none" and not m.hatch
    return dict(fill=fill, fc=m.fill if fill else None, ec=_colour(m.colour), lw=m.width,
                hatch=(m.hatch if isinstance(m.hatch, str) else HATCH) if m.hatch else None, alpha=_alpha(m), zorder=m.zorder,
                capstyle=m.cap or "butt")


HATCH = "////"          # the frame's hatching: lines rising to the right


@functools.cache
def hatching() -> dict[str, float]:
    """The frame's hatching as matplotlib paints it, for the page to paint the same: the
    distance between its lines across them and their width, in points — read from
    matplotlib's own hatch path (drawn in tiles of one inch, 72 points; its lines run along
    (1, 1), so a line's offset across them is (x − y)/√2)."""
    gc = GraphicsContextBase()
    gc.set_hatch(HATCH)
    v = np.asarray(gc.get_hatch_path().vertices, dtype=float)
    steps = np.diff(np.sort((v[:, 0] - v[:, 1]) / np.sqrt(2)))
    return {"spacing": float(steps[steps > 1e-9].min() * 72), "width": float(gc.get_hatch_linewidth())}


def _polygon(m: Mark, pts: np.ndarray) -> Polygon:
    return Polygon(pts, closed=True, joinstyle=m.join or "miter", **_filled(m))


def _circle(m: Mark, pts: np.ndarray) -> Circle:
    return Circle(pts[0], m.r, ls=_dashes(m), **_filled(m))


def _ring(m: Mark, pts: np.ndarray) -> Annulus:
    return Annulus(pts[0], m.r, m.band, **_filled(m))


def _arrow(m: Mark, pts: np.ndarray) -> Optional[FancyArrowPatch]:
    if not np.linalg.norm(pts[1] - pts[0]) > 0:
        return None                                   # a zero vector: no arrow
    arrow = FancyArrowPatch(tuple(pts[0]), tuple(pts[1]), arrowstyle=m.head, mutation_scale=m.size,
                            lw=m.width, color=m.colour, shrinkA=0, shrinkB=0, zorder=m.zorder)
    if m.halo > 0:                                    # its white casing under it (`Mark.halo`)
        arrow.set_path_effects([withStroke(linewidth=m.width + 2 * m.halo, foreground="white")])
    return arrow


ARTISTS = {"dot": _dot, "line": _line, "polygon": _polygon, "circle": _circle, "ring": _ring,
           "arrow": _arrow}
