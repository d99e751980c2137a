"""Figures as inline SVG: arrows, segments, circles and labelled points, to scale, with a
scale bar; used by the HTML page and (as data URIs) by Markdown."""
from __future__ import annotations

import math
from html import escape
from typing import Callable

from ..document import Figure, Sym

COLOURS = {"known": "#222222", "unknown": "#c0392b", "result": "#1f5fa8", "velocity": "#2e8b57",
           "construction": "#999999"}
WIDTH, MAX_HEIGHT, MARGIN = 460, 340, 36


def sym_label(base: str, sub: str, sup: str) -> str:
    """A symbol as SVG text: bold italic letter, smaller subscript and superscript."""
    out = f'<tspan font-style="italic" font-weight="bold">{escape(base)}</tspan>'
    if sub:
        out += f'<tspan baseline-shift="sub" font-size="70%">{escape(sub)}</tspan>'
    if sup:
        out += f'<tspan baseline-shift="super" font-size="70%">{escape(sup)}</tspan>'
    return out


def nice(x: float) -> float:
    """A round length (1, 2 or 5 times a power of ten) near x."""
    if x <= 0:
        return 1.0
    base = 10 ** math.floor(math.log10(x))
    return min((m * base for m in (1, 2, 5, 10)), key=lambda v: abs(v - x))


def bounds(fig: Figure) -> tuple[float, float, float, float]:
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


def svg(fig: Figure, label: Callable[[Sym], str], unit: str) -> str:
    """The figure as an <svg> element; `label` gives a symbol's SVG text, `unit` the bar's unit."""
    x0, y0, x1, y1 = bounds(fig)
    w, h = max(x1 - x0, 1e-300), max(y1 - y0, 1e-300)
    k = min((WIDTH - 2 * MARGIN) / w, (MAX_HEIGHT - 2 * MARGIN) / h)
    height = h * k + 2 * MARGIN + 24

    def at(p: tuple) -> tuple[float, float]:
        return MARGIN + (p[0] - x0) * k, MARGIN + (y1 - p[1]) * k

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height:.0f}" '
           f'viewBox="0 0 {WIDTH} {height:.0f}" font-family="DejaVu Sans, Arial, sans-serif" font-size="13">',
           "<defs>" + "".join(
               f'<marker id="h{name}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" '
               f'markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="{c}"/></marker>'
               for name, c in COLOURS.items()) + "</defs>"]
    for c, r in fig.circles:
        cx, cy = at(c)
        out.append(f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="{r * k:.1f}" fill="none" stroke="#777" '
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
        width = 2.2 if arrow.style == "result" else 1.8
        out.append(f'<line x1="{ax:.1f}" y1="{ay:.1f}" x2="{bx:.1f}" y2="{by:.1f}" stroke="{colour}" '
                   f'stroke-width="{width}" marker-end="url(#h{arrow.style})"/>')
        if arrow.label is not None:
            lx, ly = _label_spot(ax, ay, bx, by, arrow.style == "result")
            out.append(f'<text x="{lx:.1f}" y="{ly:.1f}" fill="{colour}" text-anchor="middle" '
                       f'dominant-baseline="middle" stroke="white" stroke-width="3" '
                       f'paint-order="stroke">{label(arrow.label)}</text>')
    for name, p, style in fig.points:
        px, py = at(p)
        if style == "ground":
            out.append(f'<path d="M{px:.1f},{py:.1f} l-7,12 h14 z" fill="#ddd" stroke="#444"/>')
        out.append(f'<circle cx="{px:.1f}" cy="{py:.1f}" r="3" fill="#222"/>')
        out.append(f'<text x="{px + 6:.1f}" y="{py - 6:.1f}" fill="#222">{escape(name)}</text>')
    out.append(_scale_bar(fig, k, height, unit))
    out.append("</svg>")
    return "".join(out)


def _label_spot(ax: float, ay: float, bx: float, by: float, result: bool) -> tuple[float, float]:
    """Beside the arrow: terms at the middle on the left, the result at a third on the right."""
    dx, dy = bx - ax, by - ay
    size = math.hypot(dx, dy) or 1.0
    nx, ny = -dy / size, dx / size
    along, side = (0.35, -1) if result else (0.5, 1)
    return ax + along * dx - side * 16 * nx, ay + along * dy - side * 16 * ny


def _scale_bar(fig: Figure, k: float, height: float, unit: str) -> str:
    length = nice(90 / k)
    px = length * k
    y = height - 14
    text = f"{length:g} {unit}".strip()
    return (f'<line x1="{MARGIN}" y1="{y:.1f}" x2="{MARGIN + px:.1f}" y2="{y:.1f}" stroke="#222" '
            f'stroke-width="2"/><line x1="{MARGIN}" y1="{y - 4:.1f}" x2="{MARGIN}" y2="{y + 4:.1f}" '
            f'stroke="#222"/><line x1="{MARGIN + px:.1f}" y1="{y - 4:.1f}" x2="{MARGIN + px:.1f}" '
            f'y2="{y + 4:.1f}" stroke="#222"/><text x="{MARGIN + px + 8:.1f}" y="{y + 4:.1f}" '
            f'fill="#222">{escape(text)}</text>')
