"""What a reader sees wrong with a mechanism figure's labels, measured on what is painted
(issue 30, twenty-seventh round (c)), not on the label placer's own arithmetic.

Every mechanism drawing of an explanation's page, as the page draws it, with each painted
mark (`draw.paint.paint_mark`: its kind, its points, its body) and the labels as placed (the
last layout of a figure, the one drawn), recorded by `helpers._recording`; all in display
pixels. From them:

- a body's lines: its bars (`body:` lines), its outlines and rims (`shape:`, `ground:` marks,
  a plate's outline), a belt's loop — strokes 1.5 points wide or more; construction lines, a
  wheel's thin cross and a ring's ticks are not a body's lines here;
- a body's fills: a disc, a plate, a ring's band (filled marks) and the frame's hatching (any
  hatched mark), which is nobody's to write on;
- a label's body: a name's (`body:NAME`), a vector value's (the body of its point), none for a
  point's, a contact's or a centre's.

The faults (`faults`): a name or value across another body's line, on another body's fill
or on hatching (its own too); a leader (drawn, or the short way from the anchor to a label
set beside it without one) that crosses another body's line, and of those a way across
a bar; a leader across a vector's arrow.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Optional

import numpy as np
from matplotlib.path import Path

from .helpers import LANGS, explained, recorded_pages

WIDE = 1.5           # points: a stroke this wide or wider is a body's line (a cross line is 1)
HATCHED_PART = 0.05  # a box more than this part on hatching or another body's fill is on it
START = 3.0          # pixels: a line within this of where a leader starts is the one it starts on


@dataclass
class Line:
    points: np.ndarray          # display (n, 2)
    owner: str                  # the body, "fixed" for the frame and what is welded to it
    bar: bool                   # a bar (a body drawn as its bars, a two-point body)


@dataclass
class Fill:
    path: Path                  # display
    owner: str
    hatched: bool
    hole: Optional[Path] = None     # a ring's band: its inner disc is not filled


@dataclass
class Placed:
    text: str
    gid: str
    box: np.ndarray             # x0, y0, x1, y1 of its text (display)
    anchor: np.ndarray          # display
    leader: bool
    owner: Optional[str]        # a name's or value's body ("fixed" for the frame's), else None


@dataclass
class Drawn:
    labels: list[Placed] = field(default_factory=list)
    lines: list[Line] = field(default_factory=list)
    fills: list[Fill] = field(default_factory=list)
    arrows: list[np.ndarray] = field(default_factory=list)   # each vector's arrow (start, end), display


def _circle(centre: np.ndarray, r: float, n: int = 96) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n + 1)
    return centre + r * np.column_stack([np.cos(t), np.sin(t)])


def _owner(mark, fixed: set) -> str:
    if mark.moves_with is None or mark.moves_with in fixed:
        return "fixed"
    return mark.moves_with


def _geometry(mark, transform, fixed: set) -> tuple[list[Line], list[Fill]]:
    """A painted mark's lines and fills, display coordinates."""
    pts = np.asarray(mark.points, dtype=float)
    owner = _owner(mark, fixed)
    gid = mark.gid or ""
    lines, fills = [], []
    body_line = gid.startswith(("body:", "shape:", "ground:")) and mark.width >= WIDE
    if mark.kind == "line" and body_line:
        lines.append(Line(transform.transform(pts), owner, gid.startswith("body:")))
    elif mark.kind == "polygon":
        ring = np.vstack([pts, pts[:1]])
        if body_line:
            lines.append(Line(transform.transform(ring), owner, False))
        if mark.hatch or mark.fill != "none":
            fills.append(Fill(Path(transform.transform(ring)), owner, bool(mark.hatch)))
    elif mark.kind == "circle":
        ring = _circle(pts[0], mark.r)
        if body_line:
            lines.append(Line(transform.transform(ring), owner, False))
        if mark.fill != "none" or mark.hatch:
            fills.append(Fill(Path(transform.transform(ring)), owner, bool(mark.hatch)))
    elif mark.kind == "ring" and (mark.fill != "none" or mark.hatch):
        outer, inner = _circle(pts[0], mark.r), _circle(pts[0], mark.r - mark.band)
        fills.append(Fill(Path(transform.transform(outer)), owner, bool(mark.hatch),
                          Path(transform.transform(inner))))
    return lines, fills


def _label_owner(gid: str, fixed: set) -> Optional[str]:
    from kinematika.draw.labels import label_owner

    owner = label_owner(gid)
    return "fixed" if owner in fixed else owner


@functools.lru_cache(maxsize=None)
def drawn(name: str, lang: str) -> tuple[Drawn, ...]:
    """Each mechanism drawing of the seed's explanation in `lang`, as painted and labelled:
    read off the page's own drawings as `helpers._recording` kept them (the marks painted on
    each figure, and its last label layout, the one drawn: the layouts tried while its limits
    grew share the figure's list of marks)."""
    from kinematika.draw.build import welded_to_frame

    sol, _ = explained(name)
    fixed = {sol.model.frame} | welded_to_frame(sol.model)
    last: dict[int, tuple] = {}
    for placed, lay in recorded_pages("drawings", LANGS)[(name, lang)]:
        last[id(lay.recorded_marks)] = (placed, lay)
    out: list[Drawn] = []
    for placed, lay in last.values():
        fig, transform = Drawn(), lay.ax.transData
        for m in lay.recorded_marks:
            if m.kind == "arrow":
                fig.arrows.append(transform.transform(np.asarray(m.points, dtype=float)[:2]))
            lines, fills = _geometry(m, transform, fixed)
            fig.lines += lines
            fig.fills += fills
        for p in placed:
            fig.labels.append(Placed(p.label.text, p.label.gid, np.asarray(p.box, dtype=float),
                                     transform.transform(p.anchor), bool(p.leader),
                                     _label_owner(p.label.gid, fixed)))
        out.append(fig)
    return tuple(out)


def _samples(points: np.ndarray, step: float = 0.5) -> np.ndarray:
    """The polyline through `points` sampled every `step` pixels."""
    p, q = points[:-1], points[1:]
    n = np.maximum(2, (np.linalg.norm(q - p, axis=1) / step).astype(int) + 1)
    seg = np.repeat(np.arange(len(p)), n)
    t = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n - 1, n)
    return p[seg] + t[:, None] * (q - p)[seg]


def through(points: np.ndarray, box: np.ndarray) -> bool:
    """Whether the polyline runs through the box (a sample strictly inside it)."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    if lo[0] >= box[2] or hi[0] <= box[0] or lo[1] >= box[3] or hi[1] <= box[1]:
        return False
    s = _samples(points)
    return bool(np.any((s[:, 0] > box[0]) & (s[:, 0] < box[2]) & (s[:, 1] > box[1]) & (s[:, 1] < box[3])))


def part_inside(box: np.ndarray, fills: list[Fill]) -> float:
    """The part of the box inside any of the fills (a grid of about one sample a pixel)."""
    if not fills:
        return 0.0
    nx, ny = max(2, int(box[2] - box[0])), max(2, int(box[3] - box[1]))
    xs, ys = np.meshgrid(np.linspace(box[0], box[2], nx), np.linspace(box[1], box[3], ny))
    pts = np.column_stack([xs.ravel(), ys.ravel()])
    inside = np.zeros(len(pts), bool)
    for f in fills:
        here = f.path.contains_points(pts)
        if f.hole is not None:
            here &= ~f.hole.contains_points(pts)
        inside |= here
    return float(inside.mean())


def _cross(p: np.ndarray, q: np.ndarray, line: np.ndarray) -> bool:
    """Whether the segment p→q crosses the polyline (proper crossings of its segments)."""
    a, b = line[:-1], line[1:]

    def side(o, u, v):
        return (u[..., 0] - o[..., 0]) * (v[..., 1] - o[..., 1]) - (u[..., 1] - o[..., 1]) * (v[..., 0] - o[..., 0])
    d1, d2 = side(a, b, p[None]), side(a, b, q[None])
    d3, d4 = side(p[None], q[None], a), side(p[None], q[None], b)
    return bool(np.any((d1 * d2 < 0) & (d3 * d4 < 0)))


def _near(point: np.ndarray, line: np.ndarray, pad: float) -> bool:
    """Whether the polyline passes within `pad` of the point."""
    return bool(np.min(np.linalg.norm(_samples(line) - point, axis=1)) <= pad)


def leader_end(anchor: np.ndarray, box: np.ndarray) -> np.ndarray:
    """Where the segment from the anchor to the box's centre enters the box (the anchor
    itself when it is inside)."""
    centre = (box[:2] + box[2:]) / 2
    d = centre - anchor
    half = (box[2:] - box[:2]) / 2
    with np.errstate(divide="ignore"):
        t = np.min(np.where(np.abs(d) > 1e-9, half / np.abs(np.where(d == 0, 1, d)), np.inf))
    return centre - min(t, 1.0) * d


def faults(fig: Drawn, px: float = 1.0) -> dict[str, list[str]]:
    """Each fault of one drawing, by kind, as "label text: what" lines. `px`: pixels a point."""
    out: dict[str, list[str]] = {k: [] for k in ("line", "fill", "hatch", "leader", "bar", "link", "arrow")}
    for lab in fig.labels:
        if lab.gid.startswith(("point:", "contact:")):
            continue
        own = lab.owner
        if own is not None:
            crossed = sorted({ln.owner for ln in fig.lines if ln.owner != own and through(ln.points, lab.box)})
            if crossed:
                out["line"].append(f"{lab.text}: across {crossed}")
            other = [f for f in fig.fills if f.owner != own and not f.hatched]
            if part_inside(lab.box, other) > HATCHED_PART:
                out["fill"].append(f"{lab.text}: on another body's fill")
            if part_inside(lab.box, [f for f in fig.fills if f.hatched]) > HATCHED_PART:
                out["hatch"].append(f"{lab.text}: on hatching")
        end = leader_end(lab.anchor, lab.box)
        if np.linalg.norm(end - lab.anchor) < 1e-6:
            continue
        kind = "leader" if lab.leader else "link"
        if lab.leader:
            out["arrow"] += [f"{lab.text}: leader across an arrow" for arrow in fig.arrows
                             if not _near(lab.anchor, arrow, START * px) and _cross(lab.anchor, end, arrow)]
        if kind == "link" and own is None:
            continue                         # a point's or centre's label beside its dot
        for ln in fig.lines:
            if ln.owner == own or _near(lab.anchor, ln.points, START * px):
                continue                     # its own body's, or the line it starts on
            if _cross(lab.anchor, end, ln.points):
                out[kind].append(f"{lab.text}: crosses {ln.owner}'s {'bar' if ln.bar else 'line'}")
                if ln.bar:
                    out["bar"].append(f"{lab.text}: {kind} across {ln.owner}'s bar")
    return out
