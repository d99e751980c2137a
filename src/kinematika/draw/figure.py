"""A still figure of a scene: the layout (what must fit, the figure's shape), the painting
in order, the labels, the legend and the notes.

The axes frame the mechanism, its arrows, and the centres and curvature circles that fit
while the frame stays within `REACH` times the mechanism's size; what lies outside the
axes is shown at their edge (see `marks`), and infinite lines stop just inside them.
The figure's shape follows the view's, within bounds, at equal scale on both axes; after
the labels are placed, the limits grow until every label lies inside the axes.
"""
from __future__ import annotations

import re
import textwrap
from pathlib import Path
from typing import Any, Optional

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from .lock import MATPLOTLIB
from .mathcache import shared as _shared_mathtext
from .bodies import cable_strand, fixed_ends
from .canvas import Canvas
from .dimensions import avoid_dimensions, paint_dimensions, reach
from .geometry import Box
from .marks import KENNEDY, NORMAL, mark_groups
from .paint import paint
from .picture import picture
from ..text import shown
from .names import bare, coordinates, plain
from .options import DrawOptions
from .scene import Scene
from .style import (ACCELERATION, CENTRE, CURVATURE, INK, LONGEST, SHORTEST, TITLE_SIZE, VELOCITY)
from .vectors import Arrow, arrows
from .words import word

REACH = 2.0          # the frame is at most this many times the mechanism with its arrows
BEYOND = 3.0         # drawing sizes a zoomable figure's infinite lines reach past its frame
ZOOMABLE_REACH = 1.5  # REACH of a zoomable figure's first frame (a page's box of fixed shape)
ZOOMABLE_MARGIN = 0.22  # its room for labels (placed without measuring the drawing: more room)
_shared_mathtext()          # formulas laid out once per process, not once per figure

CLIP_MARGIN = 0.06   # infinite lines and far marks stop this far (drawing sizes) inside the axes
LABEL_MARGIN = 0.12  # room kept around the framed content for labels
ASPECT = (0.5, 1.25)  # bounds of the axes' height/width
TOP, LEGEND, NOTE = 0.55, 0.32, 0.2   # inches: title band, legend row, one note line
TRIAD = 0.9          # inches: the 3D axis triad's inset (square)
FORMATS = ("png", "svg", "pdf")
NBSP = "\u00a0"      # keeps `r = 0.1` and `2 crank` on one line of the notes


def render(scene: Scene, options: Optional[DrawOptions] = None) -> Figure:
    """The figure of `scene`: mechanism, vectors, centres, curvature, labels, legend (laid
    out under `MATPLOTLIB`: labels are placed by their measured text)."""
    with MATPLOTLIB:
        return _render(scene, options or DrawOptions())


def _render(scene: Scene, options: DrawOptions) -> Figure:
    drawn = arrows(scene.vectors, scene.size, bars(scene), grounds(scene))
    content = framed_box(scene, drawn)
    dimensions = options.dimensions if scene.dim == 2 else None
    if dimensions:
        content = content.union(reach(dimensions, scene.size, Box(*scene.box).centre))
    notes = [] if options.bare else _notes(scene, drawn, options.lang)
    fig, ax = new_figure(content.grow((CLIP_MARGIN + LABEL_MARGIN) * scene.size), options,
                         len(notes), TRIAD if scene.dim == 3 else 0.0)
    view = _limits(ax).grow(-CLIP_MARGIN * scene.size)   # what the axes show, less a margin
    cv = Canvas(ax, scene, view, labels=options.labels, words=not options.bare, lang=options.lang)
    paint(cv, picture(scene, view, drawn, labels=options.labels, words=not options.bare,
                      lang=options.lang, per_point=per_point(ax)))
    if dimensions:
        paint_dimensions(ax, dimensions, scene.size, Box(*scene.box).centre)
        avoid_dimensions(cv.board, ax, dimensions, scene.size, Box(*scene.box).centre)
    _place_labels(fig, ax, cv)
    if scene.dim == 3:
        _triad(fig, scene)
    if not options.bare:
        _title(fig, options.title or scene.name)
        _legend(fig, scene, drawn, notes, options.lang)
    return fig


def per_point(ax: Any) -> float:
    """The drawing's units a point on the page, as the axes `ax` show them (equal scale)."""
    (x0, x1), pos = ax.get_xlim(), ax.get_position()
    return abs(x1 - x0) / max(pos.width * ax.figure.get_figwidth() * 72.0, 1e-300)


def zoomable(scene: Scene, options: Optional[DrawOptions] = None,
             frame: Optional[Box] = None) -> tuple[list, Box]:
    """The picture of a figure that is zoomed and panned (the page's) showing `frame`, and
    that frame; without one, the box it frames first, laid out as a still figure is (the
    mechanism, its arrows and the results within `ZOOMABLE_REACH`, with room for labels).
    Its infinite lines reach `BEYOND` drawing sizes past the frame."""
    options = options or DrawOptions()
    drawn = arrows(scene.vectors, scene.size, bars(scene), grounds(scene))
    if frame is None:
        view = framed_box(scene, drawn, ZOOMABLE_REACH).grow(ZOOMABLE_MARGIN * scene.size)
        frame = view.grow(CLIP_MARGIN * scene.size)
    else:
        view = frame.grow(-CLIP_MARGIN * scene.size) if min(frame.width, frame.height) > \
            4 * CLIP_MARGIN * scene.size else frame
    marks = picture(scene, view, drawn, labels=options.labels, lang=options.lang,
                    reach=frame.grow(BEYOND * scene.size))
    return marks, frame


def bars(scene: Scene) -> list:
    """The segments drawn as bars: between the points of each moving body (its skeleton's
    pieces when it has one), so that arrows keep off them."""
    out = []
    for body in scene.bodies.values():
        if body.frame:
            continue
        if body.skeleton:
            out += [(line[i], line[i + 1]) for line in body.skeleton for i in range(len(line) - 1)]
            continue
        pts = list(body.points.values())
        out += [(p, q) for i, p in enumerate(pts) for q in pts[i + 1:]]
    return out


def grounds(scene: Scene) -> list:
    """The ground's straight edges as drawn, hatched on their material's side, which arrows
    keep out of (`vectors.off_ground`): the frame's lines (far beyond the figure both ways)
    and the pieces of the fixed bodies' lines (`bodies.fixed_ends`: C5-1.2's inclined planes),
    each as its two ends; a fixed strand is no ground (`bodies.cable_strand`)."""
    out = []
    far = 1e3 * scene.size
    for body in scene.bodies.values():
        for shape in body.shapes:
            if shape.kind != "line" or not (body.frame or body.fixed):
                continue
            through, direction = shape.line()
            ends = None if body.frame else fixed_ends(scene, body, shape)
            if body.fixed and cable_strand(scene, body):
                continue
            out.append(ends or (through - far * direction, through + far * direction))
    return out


def framed_box(scene: Scene, drawn: list[Arrow], reach: float = REACH) -> Box:
    """The mechanism and its arrows, and, nearest first, the results that fit while the
    frame stays within `reach` times the size of the mechanism with its arrows (a centre
    farther off is shown at the edge, so that it does not shrink the mechanism)."""
    box = Box(*scene.box).union([a.end for a in drawn] + [a.start for a in drawn])
    limit = reach * max(box.width, box.height, scene.size)
    extras = [[m.point] for m in scene.marks if m.point is not None]
    for c in scene.curvatures:
        extras += [list(c.circle), [c.centre]]
    extras += [[a.point] for a in scene.axes]
    extras = [pts for pts in extras if np.all(np.isfinite(pts))]
    for pts in sorted(extras, key=lambda pts: _distance(box, pts)):
        trial = box.union(pts)
        if max(trial.width, trial.height) <= limit:
            box = trial
    return box


def _distance(box: Box, pts: list) -> float:
    """How far the farthest of `pts` lies outside `box`."""
    arr = np.asarray(pts, dtype=float)
    dx = np.maximum(np.maximum(box.xmin - arr[:, 0], arr[:, 0] - box.xmax), 0)
    dy = np.maximum(np.maximum(box.ymin - arr[:, 1], arr[:, 1] - box.ymax), 0)
    return float(np.max(np.hypot(dx, dy)))


def new_figure(limits: Box, options: DrawOptions, n_notes: int,
               bottom: float = 0.0) -> tuple[Figure, Any]:
    """A figure whose axes show `limits` at equal scale, with room below for the legend, the
    notes (`n_notes` lines) and at least `bottom` inches."""
    aspect = min(max(limits.height / max(limits.width, 1e-300), ASPECT[0]), ASPECT[1])
    limits = limits.with_aspect(aspect)
    width = options.width
    axes_w, axes_h = 0.96 * width, 0.96 * width * aspect
    top = 0.1 if options.bare else TOP
    bottom = max(0.1 if options.bare else LEGEND + NOTE * n_notes + 0.1, bottom)
    height = top + axes_h + bottom
    fig = Figure(figsize=(width, height))
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0.02, bottom / height, axes_w / width, axes_h / height))
    _set_limits(ax, limits)
    ax.set_axis_off()
    return fig, ax


def _limits(ax: Any) -> Box:
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    return Box(x0, y0, x1, y1)


def _set_limits(ax: Any, box: Box) -> None:
    """Limits around `box` at equal scale on both axes (matching the axes' shape)."""
    pos, fig = ax.get_position(), ax.figure
    box = box.with_aspect(pos.height * fig.get_figheight() / (pos.width * fig.get_figwidth()))
    ax.set_xlim(box.xmin, box.xmax)
    ax.set_ylim(box.ymin, box.ymax)


def _place_labels(fig: Figure, ax: Any, cv: Canvas) -> None:
    """Place the labels; while some would stick out of the axes, widen the limits and redo
    (placing is arithmetic on cached text sizes, so redoing is cheap)."""
    for attempt in range(4):
        placed = cv.board.layout(ax)
        grow = _overflow(ax, placed)
        if grow is None or attempt == 3:
            break
        x0, x1 = ax.get_xlim()
        y0, y1 = ax.get_ylim()
        _set_limits(ax, Box(x0 - grow[0], y0 - grow[1], x1 + grow[2], y1 + grow[3]))
    cv.board.place(ax, placed)


def _overflow(ax: Any, placed: list) -> Optional[tuple]:
    """How far (data units: left, bottom, right, top) the labels stick out of the axes."""
    box = ax.get_window_extent()
    left = bottom = right = top = 0.0
    for p in placed:
        x0, y0, x1, y1 = p.box
        left, bottom = max(left, box.x0 - x0), max(bottom, box.y0 - y0)
        right, top = max(right, x1 - box.x1), max(top, y1 - box.y1)
    if max(left, bottom, right, top) <= 0.5:
        return None
    per_px = (ax.get_xlim()[1] - ax.get_xlim()[0]) / box.width
    return tuple((v + 6) * per_px if v > 0 else 0.0 for v in (left, bottom, right, top))


def _title(fig: Figure, title: str) -> None:
    fig.text(0.5, 1 - 0.3 / fig.get_figheight(), plain(title), ha="center",
             va="center", fontsize=TITLE_SIZE, weight="bold", color=INK)


def _notes(scene: Scene, drawn: list[Arrow], lang: Optional[str] = None) -> list[str]:
    notes = list(scene.notes)
    for group in mark_groups(scene.marks, scene.size):
        if group[0].direction is not None:
            notes.append(word("note-at-infinity", lang, labels=bare(", ".join(m.label for m in group)),
                              direction=coordinates(group[0].direction, lang=lang)))
    rest = [bare(m.label) for m in scene.marks if m.rest]
    if rest:
        notes.append(word("note-no-relative-motion", lang, count=len(rest), labels=", ".join(rest)))
    if any(a.enlarged for a in drawn):
        notes.append(word("note-enlarged", lang, longest=f"{LONGEST:.0%}", shortest=f"{SHORTEST:.0%}"))
    if scene.dim == 3:
        view = word("view-iso", lang) if scene.projection.view == "iso" else scene.projection.view
        up = next((name for name, d in scene.projection.axes().items()
                   if abs(d[0]) < 1e-9 and d[1] > 1e-9), None)
        notes.append(word("note-3d", lang, view=view, up=up or "none"))
    lines: list[str] = []
    for note in notes:
        note = shown(note)                     # names in notes: control characters escaped
        kept = re.sub(r"(?<=\b\d) (?=\w)", NBSP, note.replace(" = ", f"{NBSP}={NBSP}"))
        lines += [line.replace(NBSP, " ") for line in textwrap.wrap(kept.replace("$", r"\$"), 100)]
    return lines


def _legend(fig: Figure, scene: Scene, drawn: list[Arrow], notes: list[str],
            lang: Optional[str] = None) -> None:
    handles = []
    kinds = {a.view.kind for a in drawn if a.drawn}
    if "velocity" in kinds:
        handles.append(Line2D([], [], color=VELOCITY, lw=2.2, label=word("legend-velocity", lang)))
    if "acceleration" in kinds:
        handles.append(Line2D([], [], color=ACCELERATION, lw=2.2, label=word("legend-acceleration", lang)))
    if any(m.kind == "icr" for m in scene.marks):
        handles.append(Line2D([], [], marker="o", ms=8, mfc="white", mec=CENTRE, mew=2, ls="",
                              label=word("legend-centre", lang)))
    if scene.kennedy:
        handles.append(Line2D([], [], **KENNEDY, label=word("legend-kennedy", lang)))
    if scene.normals:
        handles.append(Line2D([], [], **NORMAL, label=word("legend-normal", lang)))
    if any(m.kind == "pole" for m in scene.marks):
        handles.append(Line2D([], [], marker="D", ms=6, mfc="white", mec=ACCELERATION, ls="",
                              label=word("legend-pole", lang)))
    if scene.curvatures:
        handles.append(Line2D([], [], color=CURVATURE, lw=1.3, label=word("legend-curvature", lang)))
    height = fig.get_figheight()
    y = (NOTE * len(notes) + 0.1 + LEGEND / 2) / height
    if handles:
        fig.legend(handles=handles, loc="center", bbox_to_anchor=(0.5, y), ncol=len(handles),
                   frameon=False, fontsize=8.5, handlelength=2.2)
    for i, note in enumerate(notes):
        fig.text(0.02, (NOTE * (len(notes) - i - 0.5) + 0.05) / height, note, fontsize=7.5,
                 color="#555555", va="center", ha="left")


def _triad(fig: Figure, scene: Scene) -> None:
    """The page images of the x, y, z axes, in a small inset at the lower right of the
    figure (below the drawing, beside the notes)."""
    w, h = fig.get_figwidth(), fig.get_figheight()
    inset = fig.add_axes((1 - TRIAD / w, 0.04 / h, (TRIAD - 0.1) / w, (TRIAD - 0.1) / h))
    inset.set_axis_off()
    inset.set_xlim(-1.3, 1.3)
    inset.set_ylim(-1.3, 1.3)
    for name, d in scene.projection.axes().items():
        inset.annotate("", xy=tuple(d), xytext=(0, 0),
                       arrowprops=dict(arrowstyle="-|>", color=INK, lw=1.0, shrinkA=0, shrinkB=0))
        if np.linalg.norm(d) > 0.2:
            x, y = 1.2 * d
            inset.text(x, y, name, ha="center", va="center", fontsize=9, color=INK,
                       style="italic")


def save(fig: Figure, path: Path | str, dpi: int = 110) -> Path:
    """Write `fig` as PNG, SVG or PDF (by the file's suffix), without a date in the file:
    the same figure writes the same bytes."""
    path = Path(path)
    fmt = path.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise ValueError(f"cannot write {path.name!r}: give a .png, .svg or .pdf file")
    undated = {"svg": {"Date": None}, "pdf": {"CreationDate": None, "ModDate": None}}.get(fmt, {})
    with MATPLOTLIB:
        fig.savefig(path, format=fmt, dpi=dpi, facecolor="white", metadata=undated)
    return path


def svg_text(fig: Figure) -> str:
    """`fig` as SVG text, the same bytes for the same figure (no date, fixed clip-path ids):
    an explanation or a page that embeds it is reproducible."""
    import io

    out = io.StringIO()
    with MATPLOTLIB:
        fig.savefig(out, format="svg", facecolor="white", metadata={"Date": None})
    return _numbered_ids(out.getvalue())


def _numbered_ids(text: str) -> str:
    """matplotlib names clip paths, hatches and markers by a hash of their coordinates and
    a salt (random unless the global `svg.hashsalt` is set), so the same drawing, or one
    reached by another route (a sweep row rather than a move), differs in its ids: number
    them in order of appearance instead (no global setting, safe in the page's threads)."""
    import re

    names: dict[str, str] = {}
    for found in re.finditer(r'id="([phm][0-9a-f]{10})"', text):
        names.setdefault(found.group(1), f"{found.group(1)[0]}{len(names) + 1}")
    if not names:
        return text
    return re.sub(r"\b[phm][0-9a-f]{10}\b", lambda m: names.get(m.group(0), m.group(0)), text)
