"""The explanation's own figures (polygons, and LaTeX's mechanism) laid out once: to scale,
with a scale bar, and every label placed clear of the others and of the drawing.

Labels are placed by the figures' label-placement step (`draw.labels.LabelBoard`: boxes
measured from matplotlib's text extents, greedy then refined, leaders for labels set far
from their anchor) on an invisible matplotlib axes the size of the figure, one unit a
point. The same `Layout` is written as inline SVG (HTML, and Markdown as data URIs) and
as TikZ (LaTeX).
"""
from __future__ import annotations

import math
import re
import threading
from dataclasses import dataclass, field
from html import escape
from typing import Any, Callable, Optional, Sequence

import numpy as np

from ...text import shown, shown_lines
from ..document import Figure, Sym

COLOURS = {"known": "#222222", "unknown": "#c0392b", "result": "#1f5fa8", "velocity": "#2e8b57",
           "construction": "#999999"}
WIDTH, MAX_HEIGHT, MARGIN, BAR = 460, 420, 30, 26
TALL = 680          # points: the height a figure grows to, at most, when a term would be drawn too short
SHORT = 56.0        # points: a labelled term drawn shorter than this crowds its corner (two labels wide)
LINE = {"result": 2.2, "known": 1.8}         # an arrow's line width (points) by style: a result's wider
MARKER = 7.0                                  # an arrowhead's length and width, in its line's widths
FONT, SMALL = 13.0, 0.7                      # label size (units = points), sub/superscript scale


@dataclass
class Text:
    """A label's markup, and its measured size (units)."""

    markup: str
    width: float
    height: float
    tex: str = ""                  # LaTeX's text of a symbol
    raw: str = ""                  # a name's plain text


@dataclass
class Placed:
    """A label placed: its text and colour, its centre and box in figure units (y down), and its
    leader line from the anchor when set far from it."""

    text: Text
    colour: str
    centre: tuple[float, float]              # figure units, y down
    box: tuple[float, float, float, float]   # x0, y0, x1, y1, y down
    leader: Optional[tuple] = None           # ((x, y), (x, y)) from the anchor to the box


@dataclass
class Layout:
    """A figure in figure units (y down): its scale, size and placed labels."""

    fig: Figure
    k: float
    x0: float
    y1: float
    height: float
    labels: list[Placed] = field(default_factory=list)

    def at(self, p: tuple) -> tuple[float, float]:
        """A model point in figure units: to scale, y down, within the margin."""
        return MARGIN + (p[0] - self.x0) * self.k, MARGIN + (self.y1 - p[1]) * self.k


def sym_text(base: str, sub: str, sup: str, tex: str = "") -> Text:
    """A symbol as SVG text (bold italic letter, smaller subscript and superscript) and
    its size."""
    from ...draw.labels import text_extent

    out = sym_markup(base, sub, sup)
    w, h = text_extent(base, FONT, "bold", "italic")
    for part in (sub, sup):
        if part:
            w += text_extent(part, FONT * SMALL)[0]
    return Text(out, w, h * (1.25 if sub or sup else 1.0), tex)


def sym_markup(base: str, sub: str, sup: str, weight: str = "bold") -> str:
    """A symbol's SVG markup: its letter in italics (bold in a label), its subscript and
    superscript smaller and shifted, each part escaped (a label's, `sym_text`)."""
    bold = ' font-weight="bold"' if weight == "bold" else ""
    out = f'<tspan font-style="italic"{bold}>{escape(base)}</tspan>'
    for part, shift in ((sub, "sub"), (sup, "super")):
        if part:
            out += f'<tspan baseline-shift="{shift}" font-size="70%">{escape(part)}</tspan>'
    return out


def plain_text(text: str) -> Text:
    """A plain label (a point's name), control characters shown, escaped for SVG, with its
    measured size."""
    from ...draw.labels import text_extent

    text = shown(text)
    w, h = text_extent(text, FONT)
    return Text(escape(text), w, h, raw=text)


def nice(x: float) -> float:
    """A round length (1, 2 or 5 times a power of ten) near x."""
    if x <= 0:
        return 1.0
    base = 10 ** math.floor(math.log10(x))
    return min((m * base for m in (1, 2, 5, 10)), key=lambda v: abs(v - x))


def bounds(fig: Figure) -> tuple[float, float, float, float]:
    """The box of everything a figure draws (arrows, segments, lines, circles, points), 2 %
    larger on each side; a unit box when it draws nothing."""
    xs, ys = [], []
    for a in fig.arrows:
        xs += [a.start[0], a.end[0]]
        ys += [a.start[1], a.end[1]]
    for p, q in fig.segments + fig.lines:
        xs += [p[0], q[0]]
        ys += [p[1], q[1]]
    for c, r in fig.circles:
        xs += [c[0] - r, c[0] + r]
        ys += [c[1] - r, c[1] + r]
    for _, p, _ in fig.points:
        xs.append(p[0])
        ys.append(p[1])
    if not xs:
        return 0.0, 0.0, 1.0, 1.0
    x0, x1, y0, y1 = min(xs), max(xs), min(ys), max(ys)
    span = max(x1 - x0, y1 - y0, 1e-300)
    return x0 - 0.02 * span, y0 - 0.02 * span, x1 + 0.02 * span, y1 + 0.02 * span


def layout(fig: Figure, label: Callable[[Sym | str], Text]) -> Layout:
    """Scale the figure into WIDTH × at most MAX_HEIGHT, then place its labels: the points'
    names (the pole and the images first) and the arrows' symbols beside their middles;
    `label` writes a symbol, or a point's name (a str).
    Laid out once per set of label texts (the languages mostly share one)."""
    texts = {id(a): label(a.label) for a in fig.arrows if a.label is not None}
    names = [label(name) for name, _, _ in fig.points]       # a point's name: the callable takes a str too
    key = tuple((t.markup, t.tex) for t in list(texts.values()) + names)
    if key not in fig.layouts:
        fig.layouts[key] = _layout(fig, texts, names)
    return fig.layouts[key]


def points_per_unit(x0: float, y0: float, x1: float, y1: float, arrows: Sequence = ()) -> float:
    """The scale a figure whose drawing spans the box (x0, y0)–(x1, y1) is drawn at, in points
    per model unit: as large as fits WIDTH × MAX_HEIGHT within the margins. A figure whose
    shortest labelled term (of `arrows`, model units) would be drawn shorter than `SHORT`
    grows, as far as it needs and WIDTH × `TALL` allows: its corner had no room for the
    term's label beside the others' (001's rolling pair: a_AB^n, a_FB^n, o and a_Cor,A piled
    at the pole; issue 30, twenty-ninth round (f)). A wide figure, which fills the page's
    width already, does not grow. A term shorter than its head even at the largest scale is
    not grown for: it is named in the caption as too short to see, without its label
    (`polygon.short_arrows`), and the scale is the same with its label or without."""
    w, h = max(x1 - x0, 1e-300), max(y1 - y0, 1e-300)
    k = min((WIDTH - 2 * MARGIN) / w, (MAX_HEIGHT - 2 * MARGIN) / h)
    most = max(k, min((WIDTH - 2 * MARGIN) / w, (TALL - 2 * MARGIN) / h))
    seen = [math.dist(a.start, a.end) for a in arrows if a.label is not None
            and math.dist(a.start, a.end) * most >= MARKER * LINE.get(a.style, LINE["known"])]
    if seen and min(seen) * k < SHORT:
        k = min(most, SHORT / min(seen))
    return k


def outward(p: tuple, arrows: list, size: float) -> Optional[tuple]:
    """The direction a point's name (the pole's, an image's) is drawn towards: away from the
    arrows that meet at `p` (the negated sum of their directions from it), out of the
    polygon's corner, where no arrow's shaft or head is; None where none meets it or they
    cancel. "o" was set between the pole's arrows, by a_C^t's head and text (C5-1.7), or on
    "a, b, c" (C5-E.5; issue 30, twenty-ninth round (f)). `size` (model units) sets how near
    an end must lie to meet it (10⁻⁶ of it)."""
    sx = sy = 0.0
    for a in arrows:
        for here, there in ((a.start, a.end), (a.end, a.start)):
            n = math.dist(here, there)
            if n > 0 and math.dist(here, p) <= 1e-6 * size:
                sx += (there[0] - here[0]) / n
                sy += (there[1] - here[1]) / n
    if math.hypot(sx, sy) < 1e-6:
        return None
    return -sx, -sy


def _layout(fig: Figure, texts: dict, names: list) -> Layout:
    x0, y0, x1, y1 = bounds(fig)
    h = max(y1 - y0, 1e-300)
    k = points_per_unit(x0, y0, x1, y1, fig.arrows)
    out = Layout(fig, k, x0, y1, h * k + 2 * MARGIN + BAR)
    items: list[tuple[Text, str, tuple, int, Optional[tuple], Optional[tuple]]] = \
        [(text, COLOURS["known"], p, 0 if style == "pole" else 1, outward(p, fig.arrows, max(x1 - x0, h)), None)
         for text, (_, p, style) in zip(names, fig.points)]
    for a in fig.arrows:
        if a.label is not None:             # beside its middle, or slid along it (`draw.labels.SLIDE`)
            (ax, ay), (bx, by) = a.start, a.end
            items.append((texts[id(a)], COLOURS[a.style], ((ax + bx) / 2, (ay + by) / 2), 2,
                          (-(by - ay), bx - ax), (a.start, a.end)))
    if items:
        out.labels = _place(out, items)
    return out


def _place(lay: Layout, items: list) -> list[Placed]:
    """The labels placed by the figures' LabelBoard on an axes of the figure's size."""
    from ...draw.labels import LabelBoard
    from .placing import Sized

    fig = lay.fig
    ax = _axes(lay.height)

    def data(p: tuple) -> tuple[float, float]:
        u, v = lay.at(p)
        return u, lay.height - v

    board = LabelBoard()
    for i, (text, colour, anchor, priority, prefer, along) in enumerate(items):
        board.labels.append(Sized(np.asarray(data(anchor), dtype=float), text.markup, colour, priority, str(i),
                                  None if prefer is None else np.asarray(prefer, dtype=float),
                                  along=None if along is None else np.array([data(along[0]), data(along[1])]),
                                  width=text.width, height=text.height, off_arrows=along is None))
    for a in fig.arrows:
        board.arrow(data(a.start), data(a.end))
        head = arrowhead(data(a.start), data(a.end), LINE.get(a.style, LINE["known"]))
        if head:
            board.avoid(*head, head[0], weight=3.0)
    for p, q in fig.segments:
        board.avoid(data(p), data(q), weight=1.0)
    for p, q in fig.lines:
        board.avoid(data(p), data(q), weight=0.5)
    for c, r in fig.circles:
        ring = [data((c[0] + r * math.cos(t), c[1] + r * math.sin(t))) for t in np.linspace(0, 2 * math.pi, 48)]
        board.avoid(*ring, weight=1.0)
    for _, p, _ in fig.points:
        board.avoid(data(p), weight=3.0, radius=3.0)
    # the scale bar's row, its text included, across the figure: a label there read as the
    # bar's (C5-1.1's "k∈polea, …" beside "v/5"; twenty-fifth round (c))
    board.avoid((MARGIN, BAR), (WIDTH - MARGIN, BAR), (WIDTH - MARGIN, BAR - 8), (MARGIN, BAR - 8),
                (MARGIN, 10), (WIDTH - MARGIN, 10), weight=3.0)
    placed = board.layout(ax)
    out = []
    by_gid = {str(i): item for i, item in enumerate(items)}
    arrows = [(lay.at(a.start), lay.at(a.end)) for a in fig.arrows]
    dots = [lay.at(p) for _, p, _ in fig.points]
    for spot in placed:
        text, colour, anchor, _, _, along = by_gid[spot.label.gid]
        bx0, by0, bx1, by1 = (float(c) for c in spot.box)
        box = (bx0, lay.height - by1, bx1, lay.height - by0)
        centre = ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)
        leader = None
        ax_, ay_ = (float(c) for c in spot.anchor)
        start = (ax_, lay.height - ay_)
        if spot.leader or (_nearer_another(box, anchor, along, lay, arrows, dots)
                           and not _crosses_another(start, _edge(start, box), along, lay, arrows)):
            leader = (start, _edge(start, box))
        out.append(Placed(text, colour, centre, box, leader))
    return out


def arrowhead(start: tuple, end: tuple, width: float) -> list[tuple]:
    """The outline of the head `svg` draws at an arrow's `end` (figure or data units, one
    unit a point): its marker, `MARKER` line widths long and as wide, tip first; [] for an
    arrow of no length. Labels keep off it as off the shaft: the tip's round of
    `draw.labels.TIP` points left the back of a 13-point head bare, and C5-1.7's "o", r_pairs'
    a_BA^t sat on heads (issue 30, twenty-ninth round (f))."""
    (ax, ay), (bx, by) = start, end
    n = math.hypot(bx - ax, by - ay)
    if n == 0:
        return []
    ux, uy = (bx - ax) / n, (by - ay) / n
    back, half = MARKER * width, MARKER * width / 2
    cx, cy = bx - back * ux, by - back * uy
    return [(bx, by), (cx - half * uy, cy + half * ux), (cx + half * uy, cy - half * ux)]


def _nearer_another(box: tuple, anchor: tuple, along: Optional[tuple], lay: Layout, arrows: list,
                    dots: list) -> bool:
    """Whether a polygon's label (its `box`, figure units) lies nearer another arrow than its
    own (an arrow's label, `along` its start and end) or nearer another image's dot than its
    own point's (an image's name at `anchor`): read beside it, it names that one (C5-E.1's
    a_PC^n and a_C^n stacked by three parallel arrows at c, twenty-fourth round (g)). Such a
    label is drawn with its leader, whatever its distance."""
    if along is not None:
        own = (lay.at(along[0]), lay.at(along[1]))
        mine = _box_to_segment(box, *own)
        others = [_box_to_segment(box, p, q) for p, q in arrows
                  if not (math.dist(p, own[0]) < 0.5 and math.dist(q, own[1]) < 0.5)]
    else:
        here = lay.at(anchor)
        mine = _box_to_segment(box, here, here)
        others = [_box_to_segment(box, d, d) for d in dots if math.dist(d, here) >= 0.5]
    return any(d < mine - 1.0 for d in others)


def _crosses_another(p: tuple, q: tuple, along: Optional[tuple], lay: Layout, arrows: list) -> bool:
    """Whether a leader pq would cross an arrow other than its own (`along`): a leader the
    placement did not choose is drawn only where it crosses none (nineteenth round (d))."""
    own = None if along is None else (lay.at(along[0]), lay.at(along[1]))

    def side(o: tuple, u: tuple, v: tuple) -> float:
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    for a, b in arrows:
        if own is not None and math.dist(a, own[0]) < 0.5 and math.dist(b, own[1]) < 0.5:
            continue
        if side(p, q, a) * side(p, q, b) < 0 and side(a, b, p) * side(a, b, q) < 0:
            return True
    return False


def _box_to_segment(box: tuple, p: tuple, q: tuple, samples: int = 48) -> float:
    """The distance (figure units) from a box (x0, y0, x1, y1) to the segment pq, sampled."""
    t = np.linspace(0.0, 1.0, samples)[:, None]
    pts = np.asarray(p, float) + t * (np.asarray(q, float) - np.asarray(p, float))
    dx = np.maximum(np.maximum(box[0] - pts[:, 0], pts[:, 0] - box[2]), 0.0)
    dy = np.maximum(np.maximum(box[1] - pts[:, 1], pts[:, 1] - box[3]), 0.0)
    return float(np.min(np.hypot(dx, dy)))


_SCRATCH = threading.local()      # each thread's axes to place a figure's labels on


def _axes(height: float) -> Any:
    """An axes filling a figure WIDTH × `height` points at 72 dpi, figure units (y down) as
    data (x = u, y = height - v), for `LabelBoard.layout` to read its transform and extent.
    Nothing is drawn on it, so one per thread serves every figure, resized: a new matplotlib
    figure and axes for each took ~20 ms, more than placing its labels. The sizes and limits
    set are a new one's, so its transforms are the same numbers."""
    ax: Any = getattr(_SCRATCH, "ax", None)        # its figure a matplotlib Figure (never a SubFigure)
    if ax is None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure as MplFigure

        mpl = MplFigure(figsize=(WIDTH / 72, height / 72), dpi=72)
        FigureCanvasAgg(mpl)
        ax = _SCRATCH.ax = mpl.add_axes((0, 0, 1, 1))
        ax.set_axis_off()
    ax.figure.set_size_inches(WIDTH / 72, height / 72)
    ax.set_xlim(0, WIDTH)
    ax.set_ylim(0, height)
    return ax


def _edge(start: tuple, box: tuple) -> tuple:
    """Where the segment from `start` to the middle of `box` enters it."""
    cx, cy = (box[0] + box[2]) / 2, (box[1] + box[3]) / 2
    dx, dy = cx - start[0], cy - start[1]
    hw, hh = (box[2] - box[0]) / 2, (box[3] - box[1]) / 2
    t = min(hw / abs(dx) if abs(dx) > 1e-9 else math.inf, hh / abs(dy) if abs(dy) > 1e-9 else math.inf, 1.0)
    return cx - t * dx, cy - t * dy


def svg(fig: Figure, label: Callable[[Sym | str], Text], unit: str, prefix: str = "f",
        number: Callable[[float], str] = lambda x: f"{x:g}") -> str:
    """The figure as an <svg> element; `label` gives a symbol's text, `unit` the bar's unit,
    `prefix` keeps its ids apart from other figures' on the page; the bar is a round number
    of units (`bar_length`), written by `number` with the language's decimal sign."""
    lay = layout(fig, label)
    height = lay.height
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0f}" '
           f'viewBox="0 0 {WIDTH} {height:.0f}" font-family="DejaVu Sans, Arial, sans-serif" font-size="{FONT:g}">',
           "<defs>" + "".join(
               f'<marker id="{prefix}-{name}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="{MARKER:g}" '
               f'markerHeight="{MARKER:g}" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="{c}"/></marker>'
               for name, c in COLOURS.items()) + "</defs>"]
    at = lay.at
    for c, r in fig.circles:
        cx, cy = at(c)
        out.append(f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="{r * lay.k:.1f}" fill="none" stroke="#777" '
                   'stroke-width="1.2"/>')
    for p, q in fig.lines:
        (ax, ay), (bx, by) = at(p), at(q)
        out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" stroke="#777" '
                   'stroke-width="1.2" stroke-dasharray="6 3"/>')
    for p, q in fig.segments:
        (ax, ay), (bx, by) = at(p), at(q)
        out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" stroke="#444" '
                   'stroke-width="3" stroke-linecap="round"/>')
    for arrow in fig.arrows:
        (ax, ay), (bx, by) = at(arrow.start), at(arrow.end)
        colour = COLOURS[arrow.style]
        width = LINE.get(arrow.style, LINE["known"])
        out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" stroke="{colour}" '
                   f'stroke-width="{width}" marker-end="url(#{prefix}-{arrow.style})"/>')
    for _, p, style in fig.points:
        px, py = at(p)
        if style == "ground":
            out.append(f'<path d="M{px:.1f},{py:.1f} l-7,12 h14 z" fill="#ddd" stroke="#444"/>')
        out.append(f'<circle cx="{px:.1f}" cy="{py:.1f}" r="3" fill="#222"/>')
    for lb in lay.labels:
        if lb.leader is not None:
            (ax, ay), (bx, by) = lb.leader
            out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" stroke="{lb.colour}" '
                       'stroke-width="0.6" opacity="0.7"/>')
        out.append(f'<text x="{lb.centre[0]:.1f}" y="{lb.centre[1]:.1f}" fill="{lb.colour}" text-anchor="middle" '
                   f'dominant-baseline="central" stroke="white" stroke-width="3" '
                   f'paint-order="stroke">{lb.text.markup}</text>')
    out.append(_scale_bar(lay, unit, number))
    out.append("</svg>")
    return "".join(out)


def bar_length(k: float) -> float:
    """A scale bar's count of its unit (m/s, m/s²): a round number (`nice`) of units about 90
    points long at `k` points a unit."""
    return nice(90 / k)


def _scale_bar(lay: Layout, unit: str, number: Callable[[float], str]) -> str:
    """The bar under a figure, `bar_length` units long, with its count and unit ("0,5 m/s")."""
    count = bar_length(lay.k)
    px = count * lay.k
    y = lay.height - 14
    text = f"{number(count)} {escape(unit)}".strip()
    return (f'<line x1="{MARGIN}" y1="{y:.1f}" x2="{MARGIN + px:.1f}" y2="{y:.1f}" stroke="#222" '
            f'stroke-width="2"/><line x1="{MARGIN}" y1="{y - 4:.1f}" x2="{MARGIN}" y2="{y + 4:.1f}" '
            f'stroke="#222"/><line x1="{MARGIN + px:.1f}" y1="{y - 4:.1f}" x2="{MARGIN + px:.1f}" '
            f'y2="{y + 4:.1f}" stroke="#222"/><text x="{MARGIN + px + 8:.1f}" y="{y + 4:.1f}" '
            f'fill="#222">{text}</text>')


def embedded(text: str, prefix: str) -> str:
    """A standalone SVG (matplotlib's) made fit to sit inline in a page beside others: no
    XML prologue, doctype or comments, no control character (a model's names make ids),
    every id and reference to it prefixed and every id unique, its size set by the page's
    style from its viewBox."""
    text = re.sub(r"<\?xml[^>]*>\s*|<!DOCTYPE[^>]*>\s*", "", text)
    text = re.sub(r"<!--.*?-->", "", text, flags=re.S)     # matplotlib's comments (the labels' text)
    text = shown_lines(text)                                   # control characters of names in ids
    seen: dict[str, int] = {}

    def unique(m) -> str:          # a figure may give several artists one gid (body:crank)
        name = m.group(1)
        seen[name] = seen.get(name, 0) + 1
        return f'id="{prefix}-{name}"' if seen[name] == 1 else f'id="{prefix}-{name}-{seen[name]}"'
    text = re.sub(r'\bid="([^"]+)"', unique, text)
    text = re.sub(r'url\(#([^)]+)\)', lambda m: f"url(#{prefix}-{m.group(1)})", text)
    text = re.sub(r'href="#([^"]+)"', lambda m: f'href="#{prefix}-{m.group(1)}"', text)
    return re.sub(r'<svg([^>]*?)\swidth="[^"]*"\s+height="[^"]*"', r"<svg\1", text, count=1)
