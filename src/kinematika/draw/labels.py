"""Label placement: every label near its anchor, clear of the other labels and of the drawing.

Labels are collected while the figure is painted and placed at the end, once the axes
limits are final. Each label's size is measured once per text and font (`text_extent`,
cached for the whole process), so placing is arithmetic on boxes: no text is laid out
while positions are tried.

Placement is greedy, then refined. In order of importance each label tries boxes around
its anchor (`DIRECTIONS` directions at the `DISTANCES`) and takes the cheapest: overlapping
a placed label (or coming within `GAP` of it) or covering an arrow's tip (`LabelBoard.tip`)
costs most, then leaving the axes, then covering what is drawn (arrows and
marks weigh more than bars), then the distance from the anchor and, for a vector, not lying
beyond its tip. A label of a long arrow (`Label.along`) may sit beside any of a few points
of its arrow (`SLIDE`), not only beside its middle: in a polygon where several arrows cross
or meet, the middle is often where the others are. Then, a few times over, every label is taken out and put back at its best
place given all the others, until none moves. A label placed far from its anchor gets a
thin leader line, which later labels keep clear of.
"""
from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np
from matplotlib.lines import Line2D
from matplotlib.path import Path
from scipy.spatial import cKDTree

from .style import LABEL_SIZE
import itertools

DISTANCES = (2.5, 6.0, 11.0, 17.0, 25.0, 35.0, 48.0, 64.0, 84.0, 108.0)   # points: anchor to box
DIRECTIONS = 16
LEADER = 16.0            # points: labels farther than this from their anchor get a leader
PAD = 1.5                # points kept free around each label's text
OBSTACLE_PAD = 2.5       # points: half a thin line's width around drawn geometry
SAMPLE = 4.0             # points between samples of drawn lines
PASSES = 4               # refinement passes at most
TRIES = 6                # a stuck label's cheapest places tried, moving the labels in the way (`Layout._unstick`)
GAP = 3.0                # points kept between two labels' boxes (beyond PAD): no two touch
TIP = 7.0                # points around an arrow's tip that no label covers (its head)
HEAD = (0.0, 2.0, 4.0, 6.0)   # points back from a mechanism arrow's tip along its shaft: its head (15 pt × 0.4)
SLIDE = (0.5, 0.35, 0.65, 0.22, 0.78)   # where along its arrow an arrow's label may sit
SLIDE_END = 18.0         # points: a slid anchor stays this far from the arrow's ends
LEADER_CLEAR = 6.0       # points of a leader next to its anchor (on its own arrow) not weighed
BAR_CLEAR = 2.5          # points kept between a label's text and the edge of a wide bar (`LabelBoard.avoid`'s width)
BLOCK = "block:"          # the owner a joint's block's outline is kept under (`draw.paint`), after its mark's gid
CLOSE = 14.0             # points: two points' labels nearer than this sit on opposite sides
POINT_GIDS = ("point:", "contact:")      # the labels of points (a dot with its letter)
DOT_GIDS = POINT_GIDS + ("icr:", "centre:", "pole:")   # labels whose anchor is a dot or ring drawn there (a point, a centre)
DOT_NEAR = 4.0           # points: a leader passing this close to another label's dot runs through it

# cost weights
OVERLAP, OVERLAP_AREA, OUTSIDE, COVER, LEADER_CROSS = 400.0, 400.0, 1000.0, 5.0, 60.0
STUCK = OVERLAP          # a label is stuck when its place costs this much more than its cheapest place (`Layout._unstick`)
LEADER_VALUE = 15.0      # a mechanism vector's value on a leader (placed `LEADER` or more from its arrow)
OUTSIDE_VALUE = 120.0    # a mechanism vector's value out of the axes, × the part out: the axes grow to it
LEADER_OVER = 450.0      # a leader across another label's box, for labels not on an arrow (`Label.along`): worse than a name on another body (`AREA`)
                         # or through another label's dot (a point, a centre: `Layout._dots_passed`)
ARROW_CROSS = 450.0      # a leader across an arrow (exactly, not sampled): worse than a box over an arrow
ARROW_UNDER = 400.0      # a polygon label's box over another arrow (exactly): as bad as over a label
BODY_CROSS = 60.0        # a leader across a drawn body's outline (a wheel's rim, the ground's line), each time
BAR_CROSS = 200.0        # a leader across another body's bar, each time: half a name on that body (`AREA`)
AREA = 400.0            # a body's name or a vector's value over another body's area or over hatching,
                        # × the box's part covered; and for each line of another body through its box
GROUND = 2.5            # × `AREA`: a body's name or a vector's value beyond the ground's line, in its material
                        # (`LabelBoard.area`'s `ground`): worse than a leader across a bar or two (`BAR_CROSS`)
AREA_GRID = (8, 4)      # points across and up a label's box tested for lying in a body's area
LINE_OVER = 150.0        # a label across a drawn line that is not another body's (its own body's outline,
                         # hatching, a construction line), each line: worse than a leader across one (`BODY_CROSS`)
DRAWN = (0.5, 3.0)       # the `avoid` weights of such lines (hatching 0.7, construction 0.5; arrows weigh 3)
TOWARDS = 60.0           # a close point's label leaning towards the other point (× cosine)
DISTANCE, PREFER, ALONG = 0.15, 5.0, 0.04      # ALONG: per point an anchor slides off the middle
SHAFT = 0.5              # per point a mechanism vector's value slides back from its tip along its shaft (`Label.shaft`)
                         # and a name is led from another spot of its body (`Label.spots`)
SPOT_CLEAR = 6.0         # points: a name's spot this near another body's bar or an arrow is not used
NOT_OWN = 600.0          # a polygon term's label nearer another arrow than its own (`Layout._not_own`): as over a label
OWN_MARGIN = 4.0         # points by which a polygon term's label lies nearer its own arrow than any other
END_CLEAR = 8.0          # points of each end of an arrow (at most a quarter of it) that a label is not read beside
OTHER_DOT = 140.0        # a centre's label nearer another labelled point than its own ring (`Layout._other_dot`):
                         # less than across a body's line (`LINE_OVER`), which reads worse still


@dataclass
class Label:
    """A text to place near its `anchor` (data coordinates), in `colour`, with its `priority`
    (lower placed first), its `gid`, and a preferred direction on the page (a vector's label
    beyond its tip)."""

    anchor: np.ndarray                 # data coordinates
    text: str
    colour: str
    priority: int                      # lower is placed first
    gid: str
    prefer: Optional[np.ndarray] = None   # a preferred direction on the page
    size: float = LABEL_SIZE
    weight: str = "normal"
    style: str = "normal"
    along: Optional[np.ndarray] = None    # an arrow's (start, end), data: the anchor may slide on it
    shaft: Optional[np.ndarray] = None    # a mechanism vector's arrow (start, end), data: likewise (`SHAFT`)
    off_arrows: bool = False              # a polygon's image name: no arrow may run through its box
    spots: Optional[np.ndarray] = None    # a body's name: other points of its body (data) it may be led from

    @property
    def extent(self) -> tuple[float, float]:
        """(width, height) of the text in points."""
        return text_extent(self.text, self.size, self.weight, self.style)


@dataclass
class Placement:
    """Where a label went: its box (display pixels), its offset from the anchor (points), and
    the anchor it is placed by (data coordinates: the label's own, or a point of its arrow
    when it slid, `Label.along`), where its leader starts."""

    label: Label
    box: np.ndarray                    # x0, y0, x1, y1
    offset: tuple[float, float]
    leader: bool
    at: Optional[np.ndarray] = None    # data coordinates of the anchor used (None: label.anchor)

    @property
    def anchor(self) -> np.ndarray:
        """The anchor the label is placed by, in data coordinates."""
        return self.label.anchor if self.at is None else self.at


@dataclass
class LabelBoard:
    """Labels to place and the drawn geometry they should keep clear of."""

    labels: list[Label] = field(default_factory=list)
    obstacles: list[tuple] = field(default_factory=list)   # (data polyline, weight, radius)
    tips: list[np.ndarray] = field(default_factory=list)   # arrows' tips (data coordinates)
    owners: list[str] = field(default_factory=list)        # each obstacle's body ("" for none)
    bars: list[bool] = field(default_factory=list)         # whether each obstacle is a bar
    areas: list[tuple[str, np.ndarray]] = field(default_factory=list)   # (body or "" for hatching, polygon, data)
    grounds: list[bool] = field(default_factory=list)      # whether each area is the material beyond a ground's line
    arrows: list[np.ndarray] = field(default_factory=list)  # a polygon's arrows, (start, end) data
    heads: list[np.ndarray] = field(default_factory=list)  # a mechanism's arrows: (start, end), data
    widths: list[float] = field(default_factory=list)      # each obstacle's drawn width, points (0: thin)
    centres: list[int] = field(default_factory=list)       # the obstacles that are wheels' centre lines

    def add(self, anchor: Any, text: str, colour: str, priority: int, gid: str,
            prefer: Any = None, **kw: Any) -> None:
        """Collect a label (placed later by `layout`, once the axes' limits are final)."""
        pref = None if prefer is None else np.asarray(prefer, dtype=float)
        self.labels.append(Label(np.asarray(anchor, dtype=float), text, colour, priority, gid,
                                 pref, **kw))

    def avoid(self, *polyline: Any, weight: float = 1.0, radius: float = 0.0, owner: str = "",
              bar: bool = False, width: float = 0.0, centre: bool = False) -> None:
        """Keep labels off the drawn polyline through these points (a single point too);
        `weight` says how bad covering it is (arrows and marks more than bars), `radius`
        (points) how far around each point the drawing reaches (a marker's size), `owner`
        the body it outlines (its name's leader may cross it: `Layout._leader_over`), `bar`
        whether it is a bar (no leader crosses another body's: `BAR_CROSS`), `width` (points)
        how wide it is drawn (a bar's, which a label keeps `BAR_CLEAR` from), `centre`
        whether it is a wheel's centre line (a point's letter keeps off it too)."""
        if centre:
            self.centres.append(len(self.obstacles))
        self.obstacles.append((np.array([np.asarray(p, dtype=float) for p in polyline]), weight,
                               radius))
        self.owners.append(owner)
        self.bars.append(bar)
        self.widths.append(width)

    def area(self, owner: str, polygon: Any, ground: bool = False) -> None:
        """The region body `owner` covers (a closed polygon, data coordinates: a wheel's disc,
        a plate, a ring's band), which another body's name or a vector's value does not sit
        on (`Layout._areas`); `owner` "" for a hatched fill (the frame's hatching), which no
        name or value sits on, its own body's neither: text over hatching is not read; `owner`
        names the bodies welded together as one piece, joined by "+" (`draw.context.Context.
        welded`): a name is at home on any of them. `ground`: the fixed body's material beyond
        a ground's line (`draw.bodies.hatched_edge`), weighed `GROUND` times another body's
        area (`Layout._areas`)."""
        self.areas.append((owner, np.asarray(polygon, dtype=float)))
        self.grounds.append(ground)

    def tip(self, point: Any) -> None:
        """An arrow's tip: no label may cover its head (`TIP` points around it), which in a
        crowded polygon read as the label of the arrow ending there (issue 30, sixteenth
        round (d)); weighed as a label's overlap, not as a drawn line."""
        self.tips.append(np.asarray(point, dtype=float))

    def arrow(self, start: Any, end: Any) -> None:
        """A polygon's arrow from `start` to `end` (data): kept clear as a drawn line (weight
        3), its head as a tip (`tip`), and one of the arrows a term's label must lie nearer
        its own than (`Layout._not_own`)."""
        self.avoid(start, end, weight=3.0)
        self.tip(end)
        self.arrows.append(np.array([np.asarray(start, dtype=float), np.asarray(end, dtype=float)]))
    def head(self, start: Any, end: Any) -> None:
        """A mechanism's arrow from `start` to `end`: no label may cover its head (`HEAD`
        points back from its tip along its shaft), which a label set on it hid: C5-1.3's
        v_ar,E over the head of its own short arrow (issue 30, twenty-seventh round (f)). Its
        own label beyond the tip, or beside the shaft, covers no point of it."""
        self.heads.append(np.array([start, end], dtype=float))

    def layout(self, ax: Any) -> list[Placement]:
        """The best place of every label in `ax` (display pixels), without drawing anything."""
        return Layout(self, ax).run()

    def place(self, ax: Any, placements: Optional[list[Placement]] = None) -> list[Any]:
        """Draw the labels in `ax` (as annotations) where `layout` put them."""
        return [_annotation(ax, p) for p in (placements or self.layout(ax))]


@functools.lru_cache(maxsize=8192)
def text_extent(text: str, size: float, weight: str = "normal",
                style: str = "normal") -> tuple[float, float]:
    """(width, height) in points of `text` drawn at `size`: measured once, then remembered
    (Agg's metrics at 72 dpi, a formula's as the SVG writer lays it out: `_measuring`)."""
    fig, renderer = _scratch()
    t = fig.text(0, 0, text, fontsize=size, weight=weight, style=style)
    try:
        bb = t.get_window_extent(renderer)
    finally:
        t.remove()
    return float(bb.width), float(bb.height)


@functools.lru_cache(maxsize=1)
def _scratch() -> tuple[Any, Any]:
    """A figure at 72 dpi (one pixel per point) to measure text in, and its renderer."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(dpi=72)
    FigureCanvasAgg(fig)
    return fig, _measuring()


def _measuring() -> Any:
    """Agg's renderer at 72 dpi, except that a formula ($…$) is measured as the SVG writer
    measures and sets it (matplotlib's `TextToPath`: laid out once at its reference size,
    then scaled). A formula's layout (pyparsing) takes ~20 ms; Agg lays it out at the
    label's own size, so each label of an explanation's figures (SVG) was laid out twice,
    once to place it and once to draw it; now once (the process's `mathcache`). Its width,
    height and depth are rounded up to whole points as Agg rounds them at 72 dpi, so a box
    is never smaller than its text: a PNG's raster glyphs (110 dpi, hinted) come up to
    4 % larger than the outline's. Plain text keeps Agg's hinted metrics."""
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.textpath import text_to_path

    class Measuring(RendererAgg):
        def get_text_width_height_descent(self, s: str, prop: Any, ismath: Any) -> Any:
            if ismath is True:
                w, h, d = text_to_path.get_text_width_height_descent(s, prop, ismath)
                return math.ceil(w), math.ceil(h - d) + math.ceil(d), math.ceil(d)
            return super().get_text_width_height_descent(s, prop, ismath)

    return Measuring(1, 1, 72)


class Layout:
    """One placement run: the board's labels and obstacles in display pixels."""

    def __init__(self, board: LabelBoard, ax: Any) -> None:
        self.ax = ax
        self.px = ax.figure.dpi / 72.0                    # pixels per point
        box = ax.get_window_extent()
        self.axes = np.array([box.x0, box.y0, box.x1, box.y1])
        self.labels = sorted(board.labels, key=lambda lb: lb.priority)
        self.obstacles, self.weights = _sample(board.obstacles, ax.transData, SAMPLE * self.px)
        self.unit = _directions()
        self.tips = ax.transData.transform(np.array(board.tips)) if board.tips else np.zeros((0, 2))
        self.heads = _head_points(board.heads, ax.transData, self.px)
        self.arrows = _arrow_segments(board.obstacles, ax.transData)
        self.terms = (np.array([ax.transData.transform(a) for a in board.arrows]) if board.arrows
                      else np.zeros((0, 2, 2)))       # a polygon's arrows (display), for `_not_own`
        owners = board.owners if len(board.owners) == len(board.obstacles) else [""] * len(board.obstacles)
        self.outlines = _arrow_segments(board.obstacles, ax.transData, low=1.0, high=3.0)
        self.outline_owners = np.array([o for (line, weight, _), o in zip(board.obstacles, owners)
                                        if 1.0 <= weight < 3.0 and len(line) >= 2
                                        for _ in range(len(line) - 1)], dtype=object)
        bars = board.bars if len(board.bars) == len(board.obstacles) else [False] * len(board.obstacles)
        self.outline_bars = np.array([b for (line, weight, _), b in zip(board.obstacles, bars)
                                      if 1.0 <= weight < 3.0 and len(line) >= 2
                                      for _ in range(len(line) - 1)], dtype=bool)
        widths = board.widths if len(board.widths) == len(board.obstacles) else [0.0] * len(board.obstacles)
        self.drawn, self.drawn_line, self.drawn_owner, self.drawn_width = _drawn_lines(
            board.obstacles, owners, ax.transData, widths)
        self.centre_lines = np.isin(self.drawn_line, board.centres)   # wheels' centre lines among them
        grounds = board.grounds if len(board.grounds) == len(board.areas) else [False] * len(board.areas)
        self.areas = [(owner, Path(ax.transData.transform(poly))) for owner, poly in board.areas
                      if len(poly) >= 3]
        self.grounds = [g for (_, poly), g in zip(board.areas, grounds) if len(poly) >= 3]
        dots = [lb.anchor for lb in self.labels if lb.gid.startswith(DOT_GIDS)]
        self.dots = ax.transData.transform(np.array(dots)) if dots else np.zeros((0, 2))
        solid = self.obstacles[self.weights >= 1.0]
        # the drawing a leader should not run over (arrows, bars, marks), searched by a tree
        self.solid = cKDTree(solid) if len(solid) else None

    def run(self) -> list[Placement]:
        """Every label's placement: greedily, most important first, each at its cheapest
        candidate box given those already placed, then refined for at most `PASSES` passes until
        no label moves."""
        n = len(self.labels)
        if not n:
            return []
        anchors = self.ax.transData.transform(np.array([lb.anchor for lb in self.labels]))
        sizes = np.array([lb.extent for lb in self.labels]) * self.px + 2 * PAD * self.px
        cands = [self._candidates(self.labels[i], anchors[i], sizes[i]) for i in range(n)]
        base = [self._fixed_cost(self.labels[i], *cands[i][:3]) + cands[i][4] +
                self._leader_over(self.labels[i], cands[i]) + self._apart(i, anchors, cands[i]) +
                self._areas(self.labels[i], cands[i][0]) + self._lines_under(self.labels[i], cands[i][0]) +
                self._other_dot(self.labels[i], anchors[i], cands[i][0])
                for i in range(n)]
        choice = [-1] * n
        for i in range(n):                                 # greedy, most important first
            choice[i] = int(np.argmin(base[i] + self._mutual(i, cands, choice)))
        for _ in range(PASSES):                            # refine until nothing moves
            moved = False
            for i in range(n):
                cost = base[i] + self._mutual(i, cands, choice)
                best = int(np.argmin(cost))
                if cost[best] < cost[choice[i]] - 1e-9:
                    choice[i], moved = best, True
            if not moved:
                break
        self._unstick(base, cands, choice)
        out = []
        inverse = self.ax.transData.inverted()
        for i, k in enumerate(choice):
            boxes, dist, _, at, _ = cands[i]
            centre = (boxes[k, :2] + boxes[k, 2:]) / 2
            offset = tuple((centre - at[k]) / self.px)
            inner = boxes[k] + np.array([1, 1, -1, -1]) * PAD * self.px
            slid = None if np.allclose(at[k], anchors[i]) else inverse.transform(at[k])
            out.append(Placement(self.labels[i], inner, offset, dist[k] >= LEADER, slid))
        return out

    def _unstick(self, base: list, cands: list, choice: list[int]) -> None:
        """Move two labels at once where moving one cannot help: a label whose place costs at
        least `STUCK` more than its cheapest place of its own tries its `TRIES` cheapest places
        (`base`), each with the labels whose boxes it would cover moved to their best
        places around it; the first arrangement with a lower total cost (every label's own
        cost and its cost against the others) is kept. One label at a time (the refinement)
        leaves a name where a value placed earlier took its only free room, though the value
        had room beside it: C5-E.6's "chainring with pedals", whose one clear place between
        the rear wheel and the ground is under v_P's value, went under the ground (issue 30,
        twenty-eighth round)."""
        n = len(choice)
        total = self._total(base, cands, choice)
        for i in range(n):
            now = base[i][choice[i]] + self._mutual(i, cands, choice)[choice[i]]
            if now - base[i].min() < STUCK:
                continue
            for k in np.argsort(base[i], kind="stable")[:TRIES]:
                if base[i][k] >= now:
                    break
                trial = list(choice)
                trial[i] = int(k)
                box = cands[i][0][k][None, :] + np.array([-1, -1, 1, 1]) * GAP * self.px
                for j in range(n):
                    if j != i and _overlaps(box, cands[j][0][trial[j]][None, :])[0, 0] > 0:
                        trial[j] = int(np.argmin(base[j] + self._mutual(j, cands, trial)))
                cost = self._total(base, cands, trial)
                if cost < total - 1e-9:
                    choice[:], total = trial, cost
                    break

    def _total(self, base: list, cands: list, choice: list[int]) -> float:
        """The layout's cost: each label's own cost at its place and its cost against the others."""
        return float(sum(base[i][k] + self._mutual(i, cands, choice)[k] for i, k in enumerate(choice)))

    def _candidates(self, label: Label, anchor: np.ndarray, size: np.ndarray) -> tuple:
        """(boxes (K, 4), distance in points (K,), direction (K, 2), anchor (K, 2), cost of
        sliding (K,)) around the anchor, or around each of the points of its arrow where it
        may slide (`slide_points`)."""
        per = len(DISTANCES) * len(self.unit)
        dist = np.repeat(np.array(DISTANCES), len(self.unit))
        dirs = np.tile(self.unit, (len(DISTANCES), 1))
        half = size / 2
        reach = np.abs(dirs) @ half                        # the box's half-extent along dir
        points, slid = self.slide_points(label, anchor)
        at = np.repeat(points, per, axis=0)
        centre = at + np.tile(dirs * (dist * self.px + reach)[:, None], (len(points), 1))
        boxes = np.hstack([centre - half, centre + half])
        rate = ALONG if label.along is not None else SHAFT
        return (boxes, np.tile(dist, len(points)), np.tile(dirs, (len(points), 1)), at,
                np.repeat(rate * slid, per))

    def slide_points(self, label: Label, anchor: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The points (display) a label may be placed by, and how far each lies from `anchor`
        (points): the anchor alone, or for an arrow's label (`Label.along`) the points at the
        fractions `SLIDE` of its arrow that lie `SLIDE_END` from both its ends. Its middle,
        where a polygon's arrows cross and meet, is often taken (001's acceleration polygon,
        issue 30, eighteenth round (d)). A mechanism vector's value (`Label.shaft`) slides
        the same way back from its tip, at `SHAFT` a point (dearer than a polygon's `ALONG`:
        beyond the tip is its place), so that where its tip lies on another body it sits
        beside its own shaft, clear of that body, not on the body or across its rim at the end
        of a long leader (C5-E.6's v_P, ending inside the front wheel; twenty-fourth round (b)).
        A body's name with `Label.spots` may be led from any of them too, at `SHAFT` a point
        off its anchor: a wheel's name from any side of its disc, not from its upper left
        alone, which an arrow, a bar and a belt may hem in (C5-1.6's moving pulley, its
        name's leader across the belt's run; twenty-seventh round (c))."""
        if label.spots is not None and len(label.spots):
            spots = self.ax.transData.transform(np.asarray(label.spots, dtype=float))
            led = np.vstack([anchor[None, :], spots[self._clear_spots(label, spots)]])
            return led, np.linalg.norm(led - anchor, axis=1) / self.px
        along = label.along if label.along is not None else label.shaft
        if along is None:
            return anchor[None, :], np.zeros(1)
        a, b = self.ax.transData.transform(np.asarray(along, dtype=float))
        length = float(np.linalg.norm(b - a)) / self.px
        pts, off = [anchor], [0.0]
        for t in SLIDE[1:]:
            if min(t, 1 - t) * length >= SLIDE_END:
                p = a + t * (b - a)
                pts.append(p)
                off.append(float(np.linalg.norm(p - anchor)) / self.px)
        return np.array(pts), np.array(off)

    def _clear_spots(self, label: Label, spots: np.ndarray) -> np.ndarray:
        """Which of a name's other spots (display) lie clear of what is drawn over its body:
        farther than `SPOT_CLEAR` points from another body's bar and from every arrow. A
        leader starting on another body's bar reads as that bar's (C5-E.5's "R erradioko
        gurpila" led from the chassis bar, which runs up its wheel's disc). Thin lines do not
        count: a wheel's radii to its points run under the arm that carries it (C5-E.1)."""
        owner = label_owner(label.gid)
        bars = (self.outline_owners != owner) & self.outline_bars if len(self.outline_bars) else np.zeros(0, bool)
        other = self.outlines[bars] if len(bars) else np.zeros((0, 2, 2))
        segs = np.concatenate([other, self.arrows]) if len(self.arrows) else other
        if not len(segs):
            return np.ones(len(spots), bool)
        a, b = segs[:, 0][None], segs[:, 1][None]                                  # (1, M, 2)
        ab = b - a
        t = np.clip(((spots[:, None, :] - a) * ab).sum(axis=-1) / np.maximum((ab * ab).sum(axis=-1), 1e-12), 0, 1)
        gap = np.linalg.norm(a + t[..., None] * ab - spots[:, None, :], axis=-1)  # (K, M)
        return gap.min(axis=1) > SPOT_CLEAR * self.px

    def _fixed_cost(self, label: Label, boxes: np.ndarray, dist: np.ndarray,
                    dirs: np.ndarray) -> np.ndarray:
        """What does not depend on the other labels: the axes, the drawing, the distance."""
        area = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
        ax0, ay0, ax1, ay1 = self.axes
        inside = (np.clip(np.minimum(boxes[:, 2], ax1) - np.maximum(boxes[:, 0], ax0), 0, None) *
                  np.clip(np.minimum(boxes[:, 3], ay1) - np.maximum(boxes[:, 1], ay0), 0, None))
        # a mechanism vector's value may reach out of the axes, which then grow to hold it
        # (`figure._place_labels`), rather than go far along a leader: C5-1.3's v_ar,E, a short
        # arrow by the frame's edge, with the ground below it (twenty-seventh round (f))
        outside = OUTSIDE_VALUE if label.shaft is not None else OUTSIDE
        cost = outside * (1 - inside / area) + DISTANCE * dist
        if label.shaft is not None:             # ... and sits by its arrow, on no leader where it can
            cost += LEADER_VALUE * (dist >= LEADER)
        cost += COVER * _covered(boxes, self.obstacles, self.weights, OBSTACLE_PAD * self.px)
        cost += OVERLAP * _covered(boxes, self.tips, np.ones(len(self.tips)), TIP * self.px)
        cost += OVERLAP * np.minimum(_covered(boxes, self.heads, np.ones(len(self.heads)), 0.0), 1.0)
        if label.prefer is not None and np.linalg.norm(label.prefer) > 0:
            p = label.prefer / np.linalg.norm(label.prefer)
            cost += PREFER * (1 - dirs @ p)
        if label.along is not None or label.off_arrows:
            cost += ARROW_UNDER * self._over_arrows(label, boxes)
        if label.along is not None:
            cost += NOT_OWN * self._not_own(label, boxes, dist)
        return cost

    def _not_own(self, label: Label, boxes: np.ndarray, dist: np.ndarray) -> np.ndarray:
        """For each box of a polygon term's label (`Label.along`), whether it reads as another
        arrow's: 1, else 0. A label beside its arrow (no leader, `dist` < `LEADER`) is read as
        the label of the line nearest it, so another arrow of the polygon (`LabelBoard.arrow`)
        must lie at least `OWN_MARGIN` points farther from its text box than its own; a label
        set off with a leader is read by its leader, so no other arrow may come within
        `OWN_MARGIN` of it (its own is far). Each arrow is measured without `END_CLEAR` at
        its ends (`trimmed`): at a corner, a label just beyond one arrow's end reads as the
        label of the line it lies beside. At a corner where several short terms meet an
        image, or beside side-by-side terms, the box beside a term's middle lay nearer a
        neighbour's line (001's a_FB^t outside a_F∈N/R, 1.9 pt from it and 12.5 from its own;
        C5-1.3's v_{Q∈bar rel support} by the blue o→e; issue 30, twenty-seventh round (a)).
        Where no box is clear, all pay alike and the other costs choose."""
        if len(self.terms) < 2:
            return np.zeros(len(boxes))
        own = self.ax.transData.transform(np.asarray(label.along, dtype=float))
        mine = np.all(np.linalg.norm(self.terms - own[None], axis=2) <= 0.5 * self.px, axis=1)
        if not mine.any() or mine.all():
            return np.zeros(len(boxes))
        inner = boxes + np.array([1, 1, -1, -1]) * PAD * self.px
        near = _box_segment_distance(inner, trimmed(self.terms, END_CLEAR * self.px))      # (K, M)
        d_own = np.where(dist < LEADER, near[:, mine].min(axis=1), 0.0)
        return (near[:, ~mine].min(axis=1) < d_own + OWN_MARGIN * self.px).astype(float)

    def _over_arrows(self, label: Label, boxes: np.ndarray) -> np.ndarray:
        """For each box of a polygon's label (an arrow's, `Label.along`, or an image's name,
        `Label.off_arrows`), how many segments of the arrows run through it (its text box,
        without `PAD`), counted exactly (`_segments_in_boxes`): a label on another arrow reads
        as that arrow's (001's a_AB^n on the blue a_F∈N, issue 30, twenty-first round (c)), and
        one on its own arrow, or an image's letter on an arrow, is read through a line (C5-E.1's
        "v_PC" and "p" on collinear arrows, twenty-fourth round (g)): its own arrow counts too.
        Where the space beside it is short, the label goes farther, with its leader."""
        if not len(self.arrows):
            return np.zeros(len(boxes))
        inner = boxes + np.array([1, 1, -1, -1]) * PAD * self.px
        return _segments_in_boxes(self.arrows, inner)

    def _apart(self, i: int, anchors: np.ndarray, cand: tuple) -> np.ndarray:
        """What a point's label costs for leaning towards another labelled point closer than
        `CLOSE` points: `TOWARDS` × the cosine of its direction with the line to that point,
        when positive. Two such labels then sit on opposite sides, each beyond its own dot,
        never side by side where either could be read as the other's (C5-E.6's H, the
        sprocket's centre, and T1, r above it: "H" and "T1" both above, issue 30, nineteenth
        round (d)). A point with a label elsewhere (an arrow's, a body's) is not weighed."""
        cost = np.zeros(len(cand[0]))
        if not self.labels[i].gid.startswith(POINT_GIDS):
            return cost
        for j, other in enumerate(self.labels):
            d = anchors[j] - anchors[i]
            gap = float(np.linalg.norm(d)) / self.px
            if j == i or not other.gid.startswith(POINT_GIDS) or not 1e-6 < gap < CLOSE:
                continue
            cost += TOWARDS * np.clip(cand[2] @ (d / np.linalg.norm(d)), 0, None)
        return cost

    def _other_dot(self, label: Label, anchor: np.ndarray, boxes: np.ndarray) -> np.ndarray:
        """What an instant centre's label costs for lying nearer another labelled point than its
        own ring (box centre to dot): `OTHER_DOT`, for the label is read as that point's. C5-E.2's
        I_planet1, once the planet's subscript was short (issue 30, twenty-seventh round (g)),
        went up beside A1, 35 points above its ring at the contact J, clear of every line: a
        reader took it for A1's. Other labels sit by their point or arrow (`_apart`, the
        polygons' own rules)."""
        if not label.gid.startswith("centre:") or not len(self.dots):
            return np.zeros(len(boxes))
        others = self.dots[np.linalg.norm(self.dots - anchor, axis=1) > DOT_NEAR * self.px]
        if not len(others):
            return np.zeros(len(boxes))
        centres = (boxes[:, :2] + boxes[:, 2:]) / 2
        own = np.linalg.norm(centres - anchor, axis=1)
        nearest = np.linalg.norm(centres[:, None, :] - others[None, :, :], axis=2).min(axis=1)
        return OTHER_DOT * (nearest < own)

    def _areas(self, label: Label, boxes: np.ndarray) -> np.ndarray:
        """What a body's name or a vector's value costs for lying on another body's area
        (`LabelBoard.area`) or on hatching: `AREA` × the part of its box (sampled on
        `AREA_GRID`) inside the discs, plates and bands of bodies other than its own
        (`label_owner`), and inside any hatched fill, its own body's too (owner ""): text
        over hatching is not read (C5-E.2's "gurpil zentral finkoa" on the fixed wheel's
        hatched band; issue 30, twenty-seventh round (c)). Covering only outlines was weighed:
        a name inside another wheel, clear of its rim, was free and read as that wheel's
        (C5-E.6's quadre on the front wheel, C5-E.4's xassís in the left wheel, C5-1.4's
        portador in planet 2, C5-1.3's v_E on the support; twenty-first round (d)). Labels of
        points and centres are not weighed: they sit on their point, wherever it is.

        The ground's material beyond its line (`LabelBoard.area`'s `ground`) weighs `GROUND`
        times as much: a moving body's name under the ground is read as the ground's, and no
        reader looks there for a wheel's or a chainring's name. Weighed as another body's
        area alone it cost less than a leader across one bar and a rim, and C5-E.6's
        chainring, inside the chain's loop, was named under the ground (issue 30,
        twenty-eighth round (g))."""
        owner = label_owner(label.gid)
        if owner is None:
            return np.zeros(len(boxes))
        cost = np.zeros(len(boxes))
        for ground, weight in ((False, AREA), (True, GROUND * AREA)):
            others = [path for (body, path), g in zip(self.areas, self.grounds)
                      if g == ground and owner not in body.split("+")]
            if others:
                cost += weight * covered_part(boxes, others)
        return cost

    def _lines_under(self, label: Label, boxes: np.ndarray) -> np.ndarray:
        """What a label costs for lying across drawn lines (a body's outline, bar, rim or
        hatching; a construction line: `avoid` weights in `DRAWN`) that run through its box
        grown by `OBSTACLE_PAD` (its text and `PAD`, 4 points: half a bar's width, so that no
        bar's stroke touches it), counted exactly, each line once (`_lines_in_boxes`). One
        rule, two weights, by what the line does to the label: another body's line through a
        body's name or a vector's value reads it as that body's, as much as lying on its
        area: `AREA` each (C5-E.6's v_P on the front wheel's rim, twenty-fourth round (b);
        C5-1.2's v_J∈OJ across the left wheel's rim, C5-2.2's v_O on the chassis' bar,
        C5-1.4's names across the planets, twenty-fourth round (f)); any other line (its own
        body's: a name across its own wheel's rim, C5-E.5's "R erradioko gurpila"; hatching;
        a dash-dot construction line, C5-1.1) only makes it hard to read: `LINE_OVER` each.
        Inside a disc or beside it is free. A value's box crossed by another body's outline
        paid twice before, `RIM` and `LINE_OVER`: two rules for one fault (twenty-seventh
        round (c)). Sampling the lines (`COVER`) weighs a line by its length inside the box,
        a few points for a rim crossed at its edge, less than a step away from the anchor.

        A wide bar (its drawn width, `LabelBoard.avoid`) keeps a vector's value or a centre's
        label `BAR_CLEAR` points off its edge, not its centre line: touching a bar's stroke,
        it read as written over it (C5-1.2's v_J∈OJ on the OJ bar, C5-1.3's I_barra = (12; 24)
        on the bar; twenty-seventh round (f)). A body's name, set beside its bar or between
        two strands, keeps the old room. A point's letter pays only for a joint's block edge
        through it (`_block_edges`)."""
        if not len(self.drawn):
            return np.zeros(len(boxes))
        through = self._centres_through(label)
        if label.gid.startswith(POINT_GIDS):
            return LINE_OVER * (self._block_edges(boxes + np.array([-1, -1, 1, 1]) * OBSTACLE_PAD * self.px)
                                + self._centre_lines(boxes, through))
        owner = label_owner(label.gid)
        blocks = np.array([str(o).startswith(BLOCK) for o in self.drawn_owner], dtype=bool)
        other = (~np.isin(self.drawn_owner, [*self._piece(owner), ""]) & ~blocks if owner is not None
                 else np.zeros(len(self.drawn), bool))
        named = label.gid.startswith("body:")          # a body's name may sit close by a bar
        cost = np.zeros(len(boxes))
        for width in np.unique(self.drawn_width):     # a wide bar keeps `BAR_CLEAR` off its edge
            pad = OBSTACLE_PAD if named else max(OBSTACLE_PAD, width / 2 + BAR_CLEAR - PAD)
            grown = boxes + np.array([-1, -1, 1, 1]) * pad * self.px
            at = (self.drawn_width == width) & ~through
            mine, theirs = at & ~other, at & other
            if mine.any():
                cost += LINE_OVER * _lines_in_boxes(self.drawn[mine], self.drawn_line[mine], grown)
            if theirs.any():
                cost += AREA * _lines_in_boxes(self.drawn[theirs], self.drawn_line[theirs], grown)
        return cost

    def _piece(self, owner: str) -> set[str]:
        """`owner` and the bodies welded to it (`LabelBoard.area`'s "rear+sprocket"): one rigid
        piece, whose lines are its own to each of their names. C5-E.6's sprocket, named on the
        rear wheel it is welded to, paid the wheel's radii as another body's lines."""
        piece = {owner}
        for body, _ in self.areas:
            if owner in body.split("+"):
                piece.update(body.split("+"))
        return piece

    def _centres_through(self, label: Label) -> np.ndarray:
        """Which of the drawn lines are wheels' centre lines through the label's anchor (a
        point or centre at the wheel's centre: C5-1.4's I_carrier, I_sun, I_ring at O, C1 at
        pulley 1's centre): every box beside its anchor touches them, and held against it
        they sent its label away from its point, on a leader."""
        if not self.centre_lines.any():
            return self.centre_lines
        p = self.ax.transData.transform(np.asarray(label.anchor, dtype=float))
        a, b = self.drawn[:, 0], self.drawn[:, 1]
        ab = b - a
        t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0.0, 1.0)
        near = np.hypot(*(a + t[:, None] * ab - p).T) <= self.px
        return self.centre_lines & near

    def _centre_lines(self, boxes: np.ndarray, through: np.ndarray) -> np.ndarray:
        """For each box of a point's letter, how many wheels' centre lines run through it. A
        letter set on a pulley's diameter, away from its point, reads as the centre's or as
        lost inside the disc: C5-1.5's T7 inside pulley 4, under C4, not at its contact (issue
        30, twenty-ninth round (e)); beside its dot, clear of the line, it is read as the
        point's."""
        centres = self.centre_lines & ~through
        if not centres.any():
            return np.zeros(len(boxes))
        return _lines_in_boxes(self.drawn[centres], self.drawn_line[centres], boxes)

    def _block_edges(self, boxes: np.ndarray) -> np.ndarray:
        """For each box of a point's letter, how many joints' blocks (a slider's: `BLOCK`
        owners) have their outline through it. A point's letter sits by its dot over any line
        but a block's edge: across it, half on the block and half off, the letter read as
        hidden by the block (001's A on the slider; issue 30, twenty-seventh round (f)); on
        the block, clear of its edge, or off it, it is read whole."""
        blocks = np.array([str(o).startswith(BLOCK) for o in self.drawn_owner], dtype=bool)
        if not blocks.any():
            return np.zeros(len(boxes))
        return _lines_in_boxes(self.drawn[blocks], self.drawn_line[blocks], boxes)

    def _leader_over(self, label: Label, cand: tuple) -> np.ndarray:
        """What the way from a label's anchor to its box costs for crossing what is drawn.
        That way is its leader, and for a body's name or a vector's value also the short
        way from its anchor to a box set beside it without one (`LEADER` points or less):
        a line between a name and its body reads the name as the other side's (C5-1.6's
        "polea mugikorra" above the belt's run, its pulley below it; issue 30,
        twenty-seventh round (c)). It costs `BODY_CROSS` for each time it crosses a drawn
        body's outline or the ground's line (a body's name: another body's, as it reaches
        into its own), and `BAR_CROSS` for each bar of another body, counted exactly (`_outlines_crossed`):
        a leader across a wheel or the ground reads as pointing at it (C5-1.2's v_J∈OJ across
        the left wheel, C5-1.4's I labels across the planet, C5-E.6's chainring name across
        the ground; twentieth round (c)), and one across a bar is lost in it or reads as
        the bar's (C5-E.5's "R erradioko gurpila" across the chassis, twenty-seventh round
        (c)). The leader of an arrow's label (`Label.along`: a polygon's) also costs
        `LEADER_CROSS` / 3 for each sample of it (at most 0.9 `LEADER_CROSS`) (every
        `SAMPLE` points, from `LEADER_CLEAR` beyond its anchor to the box) on an arrow, a bar
        or a mark: a leader drawn across other arrows of a polygon led the eye to the wrong
        arrow (001's a_AB^t across a_FB^t and a_F∈N/R, eighteenth round (d)). The leader of
        an arrow's label, of a body's name or of a vector's value costs `ARROW_CROSS` for
        each arrow it crosses, counted exactly (`_arrows_crossed`): a polygon's arrows, and a
        mechanism's vectors, which a name's leader across them pointed along (C5-1.2's bar
        OJ across v_J, C5-E.1's arm OC across v_P; twenty-seventh round (c))."""
        boxes, dist, _, at, _ = cand
        cost = np.zeros(len(boxes))
        far = np.flatnonzero(dist >= LEADER)
        # a body's name is read as the side its short way ends on; a vector's value by the arrow
        # it sits beside: one inside a slot crosses the slot's line by any way out of it (C5-1.2's
        # v_J∈OJ, started at J in the twenty-eighth round (g), went out on a 78-point leader)
        way = np.arange(len(boxes)) if label.gid.startswith("body:") else far
        if len(way) and len(self.outlines):
            cost[way] = self._outlines_crossed(label, at[way], _edges(at[way], boxes[way]))
        if not len(far) or not len(self.obstacles):
            return cost
        centres = (boxes[far, :2] + boxes[far, 2:]) / 2
        d = centres - at[far]
        length = np.linalg.norm(d, axis=1)
        edge = _edges(at[far], boxes[far])
        if label.along is not None or label_owner(label.gid) is not None:
            cost[far] += ARROW_CROSS * _arrows_crossed(at[far], edge, self.arrows, OBSTACLE_PAD * self.px)
        if label.along is None:
            dots = self._dots_passed(at, edge, far, len(boxes)) if label.gid.startswith(DOT_GIDS) else 0.0
            return cost + LEADER_OVER * dots
        reach = np.linalg.norm(edge - at[far], axis=1)
        step, pad = SAMPLE * self.px, OBSTACLE_PAD * self.px
        s = np.arange(LEADER_CLEAR * self.px, float(reach.max()) + step, step)          # (S,)
        pts = at[far][:, None, :] + (s[None, :, None] / np.maximum(length, 1e-9)[:, None, None]) * d[:, None, :]
        valid = s[None, :] <= reach[:, None]                                           # (F, S)
        flat = pts.reshape(-1, 2)
        if self.solid is None:
            return cost
        # the nearest solid sample in the max-norm: within `pad` in x and in y, as before
        hit = np.zeros(len(flat), bool)
        inside = valid.ravel()
        near, _ = self.solid.query(flat[inside], p=np.inf, distance_upper_bound=2 * pad)
        hit[inside] = near < pad
        # at most just under a leader through a label (`LEADER_CROSS`), which reads worse
        cost[far] += np.minimum(LEADER_CROSS / 3 * (hit.reshape(valid.shape) & valid).sum(axis=1),
                                0.9 * LEADER_CROSS)
        return cost

    def _outlines_crossed(self, label: Label, starts: np.ndarray, ends: np.ndarray) -> np.ndarray:
        """For each way starts[k]→ends[k] of `label` to its box, `BODY_CROSS` for each drawn
        outline it crosses and `BAR_CROSS` for each bar of a body other than the label's own
        (`_arrows_crossed`: exactly, not those it starts on); a body's name does not count its
        own body's outlines and bars (it reaches into its body)."""
        owner = label_owner(label.gid)
        keep = np.ones(len(self.outlines), bool)
        if label.gid.startswith("body:") and len(self.outline_owners):
            keep = self.outline_owners != owner
        bar = keep & self.outline_bars & (self.outline_owners != owner) if len(self.outline_bars) else keep & False
        pad = OBSTACLE_PAD * self.px
        cost = BODY_CROSS * _arrows_crossed(starts, ends, self.outlines[keep & ~bar], pad)
        if bar.any():
            cost += BAR_CROSS * _arrows_crossed(starts, ends, self.outlines[bar], pad)
        return cost

    def _dots_passed(self, at: np.ndarray, edge: np.ndarray, far: np.ndarray, n: int) -> np.ndarray:
        """For each of `n` candidates of a point's or a centre's label, how many labelled dots
        (a point's, a centre's ring: `DOT_GIDS`) other than its own anchor the leader of those
        that have one (`far`: from `at` to `edge`) runs within `DOT_NEAR` points of. A leader through another point
        reads as pointing at it, and one running along a bar or a cross line is not seen at
        all: C5-E.2's I_upper planet sat above A1, its leader hidden along the arm from its
        ring at J through A1, and read as A1's (issue 30, twenty-fifth round (b)). Weighed as a
        leader across another label's box (`LEADER_OVER`). A body's name is not weighed: its
        anchor is no dot, and the places its leader then took were worse (C5-1.5's pulley 1
        across strand 2)."""
        out = np.zeros(n)
        if not len(self.dots) or not len(far):
            return out
        a, b = at[far], edge
        d = b - a
        length2 = np.maximum((d * d).sum(axis=1), 1e-12)
        rel = self.dots[None, :, :] - a[:, None, :]                                   # (F, D, 2)
        t = np.clip((rel * d[:, None, :]).sum(axis=2) / length2[:, None], 0.0, 1.0)
        gap = np.linalg.norm(rel - t[..., None] * d[:, None, :], axis=2)
        own = np.linalg.norm(rel, axis=2) <= DOT_NEAR * self.px                        # its own anchor, or a dot there
        out[far] = ((gap <= DOT_NEAR * self.px) & ~own).sum(axis=1)
        return out

    def _mutual(self, i: int, cands: list, choice: list[int]) -> np.ndarray:
        """The cost of each of label i's candidates against the other labels as placed:
        overlaps, covering their anchors, and leaders crossing labels either way."""
        boxes, dist, _, at, _ = cands[i]
        others = [j for j in range(len(choice)) if j != i and choice[j] >= 0]
        if not others:
            return np.zeros(len(boxes))
        placed = np.array([cands[j][0][choice[j]] for j in others])
        # a leader over a label: a mechanism figure's names and values weigh it above lying
        # on another body (`AREA`); a polygon's labels keep `LEADER_CROSS` against `ARROW_CROSS`
        over = LEADER_CROSS if self.labels[i].along is not None else LEADER_OVER
        area = (boxes[0, 2] - boxes[0, 0]) * (boxes[0, 3] - boxes[0, 1])
        ov = _overlaps(boxes, placed + np.array([-1, -1, 1, 1]) * GAP * self.px)
        cost = OVERLAP * (ov > 0).sum(axis=1) + OVERLAP_AREA * ov.sum(axis=1) / area
        # my leader across placed labels
        far = dist >= LEADER
        if far.any():
            centres = (boxes[far, :2] + boxes[far, 2:]) / 2
            cost[far] += over * _segments_hit(at[far], centres, placed)
        # placed labels' leaders across me, and my leader across theirs
        lead = [j for j in others if cands[j][1][choice[j]] >= LEADER]
        if lead:
            starts = np.array([cands[j][3][choice[j]] for j in lead])
            ends = np.array([(cands[j][0][choice[j], :2] + cands[j][0][choice[j], 2:]) / 2
                             for j in lead])
            t = np.linspace(0.1, 0.9, 9)[None, :, None]
            pts = (starts[:, None, :] + t * (ends - starts)[:, None, :]).reshape(-1, 2)
            cost += over * _covered(boxes, pts, np.ones(len(pts)), 0.0) / 3
            if far.any():
                mine = (boxes[far, :2] + boxes[far, 2:]) / 2
                cost[far] += LEADER_CROSS * _crossing(at[far][:, None, :], mine, starts, ends)
        return cost


def label_owner(gid: str) -> Optional[str]:
    """The body a label belongs to, read off its gid: a body's name (`body:NAME`), a vector's
    value (`velocity:P@NAME`, `acceleration:P@NAME/REF`, a drag motion's `velocity:P@NAME:drag`:
    NAME's point at P); None for any other label."""
    if gid.startswith("body:"):
        return gid.removeprefix("body:")
    kind, _, ref = gid.partition(":")
    if kind in ("velocity", "acceleration") and "@" in ref:
        return ref.split("@", 1)[1].split("/", 1)[0].split(":", 1)[0]
    return None


def covered_part(boxes: np.ndarray, paths: list) -> np.ndarray:
    """For each box (K, 4, display), the part of it (0 to 1) inside any of `paths`
    (matplotlib Paths, display), sampled at the centres of an `AREA_GRID` of cells."""
    nx, ny = AREA_GRID
    u = (np.arange(nx) + 0.5) / nx
    v = (np.arange(ny) + 0.5) / ny
    fx, fy = (a.ravel() for a in np.meshgrid(u, v))
    xs = boxes[:, 0:1] + fx[None, :] * (boxes[:, 2:3] - boxes[:, 0:1])
    ys = boxes[:, 1:2] + fy[None, :] * (boxes[:, 3:4] - boxes[:, 1:2])
    pts = np.column_stack([xs.ravel(), ys.ravel()])
    inside = np.zeros(len(pts), bool)
    for path in paths:
        near = np.arange(len(pts))
        if np.isfinite(path.vertices).all():                  # a point beyond its vertices' box is outside
            lo, hi = path.vertices.min(axis=0), path.vertices.max(axis=0)
            near = near[np.all((pts >= lo) & (pts <= hi), axis=1)]
        if len(near):
            inside[near] |= path.contains_points(pts[near])
    return inside.reshape(len(boxes), -1).mean(axis=1)


def _head_points(heads: list, transform: Any, px: float) -> np.ndarray:
    """The points (display) of the mechanism's arrows' heads (`LabelBoard.head`): each tip and
    the points `HEAD` back from it along its shaft (at most the arrow's length)."""
    out = []
    for start, end in heads:
        a, b = transform.transform(np.asarray([start, end], dtype=float))
        length = float(np.linalg.norm(b - a))
        if length <= 0:
            continue
        u = (b - a) / length
        out += [b - min(t * px, length) * u for t in HEAD]
    return np.array(out) if out else np.zeros((0, 2))


def _directions() -> np.ndarray:
    t = 2 * math.pi * np.arange(DIRECTIONS) / DIRECTIONS
    return np.column_stack([np.cos(t), np.sin(t)])


def _sample(obstacles: list, transform: Any, step: float) -> tuple[np.ndarray, np.ndarray]:
    """The obstacles as display points about `step` apart, and each point's weight."""
    pts, weights = [], []
    ring = np.vstack([[0.0, 0.0], _directions()[::2]])
    for line, weight, radius in obstacles:
        disp = transform.transform(line)
        disp = disp[np.all(np.isfinite(disp), axis=1)]
        if not len(disp):
            continue
        pieces = [disp[:1]]
        for p, q in itertools.pairwise(disp):
            n = max(1, int(np.linalg.norm(q - p) / step))
            t = np.linspace(0, 1, n + 1)[1:, None]
            pieces.append(p + t * (q - p))
        seg = np.vstack(pieces)
        if radius > 0:                       # a marker: its outline too
            seg = (seg[:, None, :] + radius * step / SAMPLE * ring[None]).reshape(-1, 2)
        pts.append(seg)
        weights.append(np.full(len(seg), weight))
    if not pts:
        return np.zeros((0, 2)), np.zeros(0)
    return np.vstack(pts), np.concatenate(weights)


def _covered(boxes: np.ndarray, pts: np.ndarray, weights: np.ndarray, pad: float) -> np.ndarray:
    """For each box, the total weight of the points inside it (grown by `pad`)."""
    if not len(pts):
        return np.zeros(len(boxes))
    lo, hi = boxes[:, :2].min(axis=0) - pad, boxes[:, 2:].max(axis=0) + pad
    near = np.all((pts >= lo) & (pts <= hi), axis=1)
    pts, weights = pts[near], weights[near]
    if not len(pts):
        return np.zeros(len(boxes))
    x, y = pts[:, 0][None, :], pts[:, 1][None, :]
    inside = ((x > boxes[:, 0:1] - pad) & (x < boxes[:, 2:3] + pad) &
              (y > boxes[:, 1:2] - pad) & (y < boxes[:, 3:4] + pad))
    return inside.astype(float) @ weights


def _overlaps(boxes: np.ndarray, others: np.ndarray) -> np.ndarray:
    """(K, M) overlap areas of K boxes with M others."""
    w = np.minimum(boxes[:, None, 2], others[None, :, 2]) - np.maximum(boxes[:, None, 0],
                                                                      others[None, :, 0])
    h = np.minimum(boxes[:, None, 3], others[None, :, 3]) - np.maximum(boxes[:, None, 1],
                                                                      others[None, :, 1])
    return np.clip(w, 0, None) * np.clip(h, 0, None)


def _segments_hit(start: np.ndarray, ends: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """For each segment start→end (`start` one point, or one per segment), how many of
    `boxes` it passes through (sampled)."""
    t = np.linspace(0.15, 0.85, 8)
    start = np.broadcast_to(start, ends.shape)[:, None, :]
    pts = start + t[None, :, None] * (ends[:, None, :] - start)          # (K, 8, 2)
    x, y = pts[..., 0][..., None], pts[..., 1][..., None]
    inside = ((x > boxes[:, 0]) & (x < boxes[:, 2]) & (y > boxes[:, 1]) & (y < boxes[:, 3]))
    return inside.any(axis=1).sum(axis=1).astype(float)


def _segments_in_boxes(segs: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """For each box (K, 4: x0, y0, x1, y1), how many of the segments (M, 2, 2) pass through
    it: the segment p + t (q − p), 0 ≤ t ≤ 1, clipped to the box by its slabs (Liang–Barsky)
    keeps a part of positive length."""
    if not len(segs) or not len(boxes):
        return np.zeros(len(boxes))
    return _segment_hits(_meeting(segs, boxes), boxes).sum(axis=1).astype(float)


def _meeting(segs: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """The segments (M, 2, 2) whose bounding box meets the bounding box of all the `boxes`
    (a label's candidates, clustered about its anchor): a segment clear of it passes through
    none of them (its slabs' interval lies outside [0, 1]), so the counts are the same over
    these alone."""
    lo, hi = boxes[:, :2].min(axis=0), boxes[:, 2:].max(axis=0)
    return segs[np.all((segs.max(axis=1) >= lo) & (segs.min(axis=1) <= hi), axis=1)]


def _segment_hits(segs: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """(K, M): whether each of the segments (M, 2, 2) passes through each box (K, 4), clipped
    to the box by its slabs (Liang–Barsky) keeping a part of positive length."""
    # only the pairs whose bounding boxes meet are clipped: a segment clear of a box's
    # bounding box has its slabs' interval outside [0, 1] (the same verdict, computed alone)
    meet = np.all((segs.max(axis=1)[None] >= boxes[:, None, :2]) & (segs.min(axis=1)[None] <= boxes[:, None, 2:]),
                  axis=2)                                            # (K, M)
    k, m = np.nonzero(meet)
    p, d = segs[m, 0], segs[:, 1][m] - segs[:, 0][m]                 # (N, 2), each pair's segment
    lo, hi = boxes[k, :2], boxes[k, 2:]                              # (N, 2), its box
    with np.errstate(divide="ignore", invalid="ignore"):
        t1, t2 = (lo - p) / d, (hi - p) / d
    flat = np.abs(d) < 1e-12                                         # parallel to a slab: inside it or never
    inside = (p >= lo) & (p <= hi)
    t_in = np.where(flat, np.where(inside, -np.inf, np.inf), np.minimum(t1, t2))
    t_out = np.where(flat, np.where(inside, np.inf, -np.inf), np.maximum(t1, t2))
    meet[k, m] = np.minimum(t_out.min(axis=-1), 1.0) - np.maximum(t_in.max(axis=-1), 0.0) > 1e-9
    return meet


def trimmed(segs: np.ndarray, end: float) -> np.ndarray:
    """The segments (M, 2, 2) without `end` at each of their ends (at most a quarter of each):
    the part of an arrow a label is read beside. At a corner where two arrows meet, a label
    just beyond one's end is no nearer it than the other's start, yet it reads as the label
    of the line it lies along, not of the corner's other line going away from it."""
    d = segs[:, 1] - segs[:, 0]
    length = np.linalg.norm(d, axis=1)
    cut = np.minimum(end, 0.25 * length) / np.maximum(length, 1e-12)
    return np.stack([segs[:, 0] + cut[:, None] * d, segs[:, 1] - cut[:, None] * d], axis=1)


def _box_segment_distance(boxes: np.ndarray, segs: np.ndarray) -> np.ndarray:
    """(K, M): the distance from each box (K, 4: x0, y0, x1, y1) to each segment (M, 2, 2):
    0 where the segment passes through the box (`_segment_hits`), else the least of its ends'
    distances to the box and the box's corners' distances to the segment."""
    lo, hi = boxes[:, None, None, :2], boxes[:, None, None, 2:]               # (K, 1, 1, 2)
    ends = segs[None]                                                         # (1, M, 2, 2)
    gap = np.maximum(np.maximum(lo - ends, ends - hi), 0.0)
    d_ends = np.linalg.norm(gap, axis=3).min(axis=2)                          # (K, M)
    corners = np.stack([boxes[:, [0, 1]], boxes[:, [2, 1]], boxes[:, [0, 3]], boxes[:, [2, 3]]], axis=1)
    a, b = segs[:, 0][None, None], segs[:, 1][None, None]                     # (1, 1, M, 2)
    ab = b - a
    c = corners[:, :, None, :]                                                # (K, 4, 1, 2)
    t = np.clip(((c - a) * ab).sum(axis=3) / np.maximum((ab * ab).sum(axis=3), 1e-12), 0.0, 1.0)
    d_corners = np.linalg.norm(a + t[..., None] * ab - c, axis=3).min(axis=1)  # (K, M)
    out = np.minimum(d_ends, d_corners)
    return np.where(_segment_hits(segs, boxes), 0.0, out)


def _lines_in_boxes(segs: np.ndarray, line: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """For each box (K, 4), how many distinct drawn lines pass through it: `segs` (M, 2, 2)
    are their segments, `line` (M,) the line each belongs to (a rim is one line, however
    many segments draw it)."""
    if not len(segs) or not len(boxes):
        return np.zeros(len(boxes))
    lo, hi = boxes[:, :2].min(axis=0), boxes[:, 2:].max(axis=0)
    near = np.all((segs.max(axis=1) >= lo) & (segs.min(axis=1) <= hi), axis=1)
    segs, line = segs[near], line[near]
    if not len(segs):
        return np.zeros(len(boxes))
    order = np.argsort(line, kind="stable")                          # each line's segments together
    segs, line = segs[order], line[order]
    first = np.flatnonzero(np.r_[True, line[1:] != line[:-1]])       # where each line's run begins
    hits = _segment_hits(segs, boxes)                                # (K, M)
    return np.logical_or.reduceat(hits, first, axis=1).sum(axis=1).astype(float)


def _drawn_lines(obstacles: list, owners: list, transform: Any,
                 widths: Optional[list] = None) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The segments (M, 2, 2, display) of the drawn lines whose `avoid` weight is in `DRAWN`
    (outlines, bars, rims, hatching, construction lines), the line (M,) each belongs to, its
    body (M,: "" for none) and its drawn width (M, points: 0 for a thin line), for
    `Layout._lines_under`."""
    segs, lines, own, wide = [], [], [], []
    widths = widths if widths is not None else [0.0] * len(obstacles)
    for k, ((line, weight, _), owner, width) in enumerate(zip(obstacles, owners, widths)):
        if DRAWN[0] <= weight < DRAWN[1] and len(line) >= 2:
            q = transform.transform(line)
            segs.append(np.stack([q[:-1], q[1:]], axis=1))
            lines += [k] * (len(q) - 1)
            own += [owner] * (len(q) - 1)
            wide += [width] * (len(q) - 1)
    if not segs:
        return np.zeros((0, 2, 2)), np.zeros(0, int), np.zeros(0, dtype=object), np.zeros(0)
    return np.concatenate(segs), np.array(lines), np.array(own, dtype=object), np.array(wide, dtype=float)


def _crossing(p: np.ndarray, qs: np.ndarray, starts: np.ndarray, ends: np.ndarray) -> np.ndarray:
    """For each segment p→q (q in `qs`; `p` one point, or (K, 1, 2) one per q), how many of
    the segments starts→ends it crosses."""
    def side(o, u, v):
        return (u[..., 0] - o[..., 0]) * (v[..., 1] - o[..., 1]) - \
            (u[..., 1] - o[..., 1]) * (v[..., 0] - o[..., 0])
    q = qs[:, None, :]                                  # (K, 1, 2) against (M, 2)
    d1, d2 = side(starts, ends, p), side(starts, ends, q)
    d3, d4 = side(p, q, starts), side(p, q, ends)
    return ((d1 * d2 < 0) & (d3 * d4 < 0)).sum(axis=1).astype(float)


def _arrow_segments(obstacles: list, transform: Any, low: float = 3.0, high: float = math.inf) -> np.ndarray:
    """(M, 2, 2) the segments (display) of the drawn polylines weighing as arrows (weight ≥ 3:
    a polygon's arrows), or weighing from `low` up to `high` (1 to 3: the bodies' outlines,
    bars and the ground's line, not its hatching), for a leader's crossings to be counted
    exactly (`_arrows_crossed`)."""
    segs = [np.stack([q[:-1], q[1:]], axis=1) for q in
            (transform.transform(line) for line, weight, _ in obstacles if low <= weight < high and len(line) >= 2)]
    return np.concatenate(segs) if segs else np.zeros((0, 2, 2))


def _near_box(segs: np.ndarray, points: np.ndarray, pad: float) -> np.ndarray:
    """The segments (M, 2, 2) whose bounding box, grown by `pad`, meets the bounding box of
    `points` (the leaders' ends): a segment a leader crosses, or that runs within `pad` of
    it, is among them, so `_arrows_crossed` counts the same over these alone, without the
    distances to every outline of the figure (most of a figure's label placement)."""
    lo, hi = points.min(axis=0) - pad, points.max(axis=0) + pad
    keep = np.all((segs.max(axis=1) >= lo) & (segs.min(axis=1) <= hi), axis=1)
    return segs[keep]


def _arrows_crossed(starts: np.ndarray, ends: np.ndarray, segs: np.ndarray, pad: float) -> np.ndarray:
    """For each leader starts[k]→ends[k], how many of the segments `segs` it crosses or runs
    within `pad` of (through the pole, where arrows start, too); a segment the leader starts
    on or next to (its own arrow, an arrow meeting it there) is not counted. Sampling the
    leader and the arrows every few points, as `_leader_over` does for what a leader runs
    over, misses a crossing between two samples: 001's a_FB^n, 35 pt long at the pole o,
    kept its leader across a_FA^n (issue 30, nineteenth round (d))."""
    if not len(segs) or not len(starts):
        return np.zeros(len(starts))
    segs = _near_box(segs, np.concatenate([starts, ends]), pad)
    if not len(segs):
        return np.zeros(len(starts))
    a, b = segs[:, 0][None], segs[:, 1][None]                     # (1, M, 2)
    p, q = starts[:, None, :], ends[:, None, :]                    # (K, 1, 2)

    def side(o, u, v):
        return (u[..., 0] - o[..., 0]) * (v[..., 1] - o[..., 1]) - (u[..., 1] - o[..., 1]) * (v[..., 0] - o[..., 0])

    def off(x, u, v):                                              # distance from x to segment uv
        uv = v - u
        t = np.clip(((x - u) * uv).sum(axis=-1) / np.maximum((uv * uv).sum(axis=-1), 1e-12), 0, 1)
        return np.linalg.norm(u + t[..., None] * uv - x, axis=-1)
    crossed = (side(a, b, p) * side(a, b, q) < 0) & (side(p, q, a) * side(p, q, b) < 0)
    # the distances only for the pairs whose bounding boxes lie within `pad` (and a pixel) of
    # each other: any other is farther than `pad` everywhere (not near, and the leader does
    # not start on it), so it counts if it is crossed, as when every distance was measured
    gap = np.maximum(segs.min(axis=1)[None] - np.maximum(starts, ends)[:, None],
                     np.minimum(starts, ends)[:, None] - segs.max(axis=1)[None]).max(axis=2)   # (K, M)
    k, m = np.nonzero(gap <= pad + 1.0)
    near, clear = np.zeros(crossed.shape, bool), np.ones(crossed.shape, bool)
    pk, qk, ak, bk = starts[k], ends[k], segs[m, 0], segs[m, 1]
    near[k, m] = np.minimum.reduce([off(qk, ak, bk), off(ak, pk, qk), off(bk, pk, qk)]) <= pad
    clear[k, m] = off(pk, ak, bk) > pad
    return ((crossed | near) & clear).sum(axis=1).astype(float)


def _annotation(ax: Any, p: Placement) -> Any:
    """The label's text in data coordinates (the same place at any dpi: the offset in
    points and the data-to-pixel scale both grow with the dpi), and its leader line."""
    label = p.label
    inv = ax.transData.inverted()
    anchor = ax.transData.transform(p.anchor)
    centre = (p.box[:2] + p.box[2:]) / 2
    text = ax.text(*inv.transform(centre), label.text, ha="center", va="center",
                   fontsize=label.size, color=label.colour, weight=label.weight,
                   style=label.style, zorder=20, gid=f"label:{label.gid}", clip_on=False,
                   bbox=dict(boxstyle="round,pad=0.12", fc="white", ec="none", alpha=0.75))
    if p.leader:
        end = _edge(anchor, p.box)
        ax.add_line(Line2D(*inv.transform(np.array([anchor, end])).T, lw=0.6, alpha=0.7,
                           color=label.colour, zorder=19, gid=f"leader:{label.gid}"))
    return text


def _edges(starts: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """`_edge` of each start (K, 2) and box (K, 4) at once, the same arithmetic row by row."""
    centre = (boxes[:, :2] + boxes[:, 2:]) / 2
    d = centre - starts
    half = (boxes[:, 2:] - boxes[:, :2]) / 2
    with np.errstate(divide="ignore"):
        t = np.min(np.where(np.abs(d) > 1e-9, half / np.abs(np.where(d == 0, 1, d)), np.inf), axis=1)
    return centre - np.minimum(t, 1.0)[:, None] * d


def _edge(start: np.ndarray, box: np.ndarray) -> np.ndarray:
    """Where the segment from `start` to the centre of `box` enters the box (`_edges` of one)."""
    return _edges(np.asarray(start, dtype=float)[None, :], np.asarray(box, dtype=float)[None, :])[0]
