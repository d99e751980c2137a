"""The figure of a statement: the mechanism drawn to the variant's values (`draw`), with its
data marked as dimensions and no answer drawn (no vectors, centres or circles).

The dimensions are the data the model is built from, as a statement's figure shows them:
each construction's lengths and angles (a polar point's distance and angle, the radii of
circles that meet, the distance of a guide line given by a parameter), and the coordinates
of fixed points written with parameters, measured from the point at the origin;
`exercise.dimensions` adds others. A dimension given by a parameter reads as the statement
states it, with the model's notation (`θ = 35°` for a parameter `th` the model writes
`theta`; `s = 400 mm`); any other its value in the statement's units (mm when the statement
gives its lengths in mm). An angle of zero from a construction's own reference line (a
point on the line O4→A) is no datum and is not drawn. A length is drawn on the side of its
bar where fewer points and marks stand, so that its text does not sit on a pivot.
"""
from __future__ import annotations

import io
import itertools
import math
from decimal import Decimal
from typing import Any, Optional

from ..draw.dimensions import RADIUS, Dimension
from ..joints.capabilities import Centre
from ..model.constructions import CircleLine, Polar, TwoCircles
from ..expressions import Expr
from .stated import number_text, stated_text

WIDTH = 4.6         # inches: printed at its size, so that its text reads as 9 pt
HEIGHT = 4.4        # inches: at most this tall (a tall mechanism is drawn narrower, its text as large)
DPI = 150
Point = tuple[float, float]         # a planar model's point, in model units


def statement_figure(exercise: Any, variant: Any, lang: str) -> bytes:
    """A variant's statement figure (PNG): the mechanism, its data as dimensions and the
    given rotations as arrows."""
    stated = variant.all_stated(exercise)
    dimensions = dimensions_of(exercise, variant.solution, stated, lang)
    return figure_png(variant.solution, dimensions + rates_of(exercise, variant.solution, stated, lang, dimensions), lang)


def figure_png(sol: Any, dimensions: list[Dimension], lang: str) -> bytes:
    """The statement's figure as PNG bytes: at print resolution, in a palette of `COLOURS`
    colours (a line drawing: a third of the bytes of full colour, the same to the eye)."""
    from ..draw import DrawOptions, draw
    from ..draw.lock import MATPLOTLIB

    options = DrawOptions(velocities=False, accelerations=False, centres=False, curvature=False,
                          bare=True, lang=lang, width=_width(sol), dimensions=dimensions)
    with MATPLOTLIB:
        return _palette(_rendered(draw(sol, None, options)))


PAD = 0.08          # inches of white around the drawing
ROOM = 0.6          # inches added around the figure before drawing it, for texts past its edges


def _rendered(fig: Any) -> Any:
    """The figure drawn once at `DPI` and cropped to its drawing plus `PAD` (what
    `savefig(bbox_inches="tight")` gives, which draws it twice); a drawing that reaches past
    the figure's edges is saved the tight way (an RGB image either way)."""
    import math as m

    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from PIL import Image

    fig.set_dpi(DPI)
    fig.patch.set_facecolor("white")
    width, height = fig.get_size_inches()          # room around, for texts past the edges
    for ax in fig.axes:
        x, y, w, h = ax.get_position().bounds
        ax.set_position(((x * width + ROOM) / (width + 2 * ROOM), (y * height + ROOM) / (height + 2 * ROOM),
                         w * width / (width + 2 * ROOM), h * height / (height + 2 * ROOM)))
    fig.set_size_inches(width + 2 * ROOM, height + 2 * ROOM)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    box = fig.get_tightbbox(canvas.get_renderer())
    width, height = fig.get_size_inches()
    if box.x0 < 0 or box.y0 < 0 or box.x1 > width or box.y1 > height:
        out = io.BytesIO()
        fig.savefig(out, format="png", dpi=DPI, facecolor="white", bbox_inches="tight", pad_inches=PAD)
        return Image.open(io.BytesIO(out.getvalue())).convert("RGB")
    pixels = np.asarray(canvas.buffer_rgba())[:, :, :3]
    rows, cols = pixels.shape[:2]
    left, right = max(0, m.floor((box.x0 - PAD) * DPI)), min(cols, m.ceil((box.x1 + PAD) * DPI))
    top, bottom = max(0, m.floor((height - box.y1 - PAD) * DPI)), min(rows, m.ceil((height - box.y0 + PAD) * DPI))
    return Image.fromarray(np.ascontiguousarray(pixels[top:bottom, left:right]))


COLOURS = 64


def _width(sol: Any) -> float:
    """The figure's width (inches): `WIDTH`, or less for a tall mechanism, so that it is at most
    `HEIGHT` tall at the same size of text (draw.figure keeps the axes' height between 0.5
    and 1.25 of their width)."""
    points = [tuple(float(c) for c in p[:2]) for p in sol.inst.points.values()]
    if len(points) < 2:
        return WIDTH
    span_x = max(p[0] for p in points) - min(p[0] for p in points)
    span_y = max(p[1] for p in points) - min(p[1] for p in points)
    aspect = min(max(span_y / span_x if span_x > 0 else 1.25, 0.5), 1.25)
    return min(WIDTH, HEIGHT / (0.96 * aspect))


def printed_width(png: bytes) -> float:
    """How wide a figure prints at its own size (inches): its pixels over `DPI`."""
    return int.from_bytes(png[16:20], "big") / DPI if png[:8] == b"\x89PNG\r\n\x1a\n" else WIDTH


def _palette(picture: Any) -> bytes:
    """An RGB image as a PNG in an adaptive palette of `COLOURS` colours (Pillow's fast octree:
    a sixth of the time of median cut, the same size to a few per cent)."""
    from PIL import Image

    image = picture.quantize(COLOURS, method=Image.Quantize.FASTOCTREE)
    palette = image.getpalette()
    image.putpalette([255 if all(c >= 250 for c in palette[i - i % 3:i - i % 3 + 3]) else v
                      for i, v in enumerate(palette)])          # the paper stays pure white
    out = io.BytesIO()
    image.save(out, format="PNG", compress_level=6)
    return out.getvalue()


class Labels:
    """The text of a dimension: `s = 400 mm` for a parameter, else the value."""

    def __init__(self, exercise: Any, stated: dict[str, Decimal], lang: str) -> None:
        self.exercise = exercise
        self.stated = stated
        self.lang = lang

    def of(self, name: Optional[str], value: float, angle: bool) -> str:
        """`name = value unit` for a parameter `name` (written as the model's notation writes
        it), else `value` in degrees or in the statement's length unit."""
        from ..explain.render.names import unicode_name

        if name in self.stated:
            unit = self.exercise.unit_of(name)
            spelt = self.exercise.model.wording.symbol(name, self.lang) or name
            return f"{unicode_name(spelt)} = {stated_text(self.stated[name], unit, self.lang)}"
        if angle:
            return f"{number_text(math.degrees(value), self.lang, 4)}°"
        unit = statement_length(self.exercise)
        shown = value * self.exercise.section.length.size / unit.size
        return f"{number_text(shown, self.lang, 4)}\u00a0{unit.shown}"


def statement_length(exercise: Any) -> Any:
    """The unit the statement gives its lengths in: the one its length parameters are stated
    in most, else the model's."""
    from collections import Counter

    units = Counter(u.name for u in exercise.section.units.values() if u.kind == "length")
    if not units:
        return exercise.section.length
    from ..model.exercise_section import UNITS

    return UNITS[units.most_common(1)[0][0]]


def dimensions_of(exercise: Any, sol: Any, stated: dict[str, Decimal], lang: str) -> list[Dimension]:
    """The dimension marks of a variant's figure (planar models; none in 3D)."""
    model, inst = sol.model, sol.inst
    if model.dimension != 2:
        return []
    labels = Labels(exercise, stated, lang)
    at = {name: _planar(inst.points[name]) for name in model.points}
    out: list[Dimension] = []
    seen: set = set()
    done: set[str] = set()              # each parameter dimensioned once

    def length(p: str | Point, q: str | Point, expr: Optional[Expr], along: str = "aligned",
               text: Optional[str] = None) -> None:
        name = _name(expr) if expr is not None else None
        if text is None and (name in done or (name is None and expr is not None and expr.names())):
            return                      # a parameter already shown, or a length that follows from the data
        a, b = (at[p] if isinstance(p, str) else p), (at[q] if isinstance(q, str) else q)
        key = (frozenset((a, b)), along)
        if key in seen or a == b:
            return
        seen.add(key)
        if name is not None:
            done.add(name)
        if along == "aligned":
            gap = math.dist(a, b)
        else:
            gap = abs(b["xy".index(along)] - a["xy".index(along)])
        side = _clear_side(a, b, list(at.values()), out) if along == "aligned" else None
        out.append(Dimension("length", a, b, text or labels.of(name, gap, False), along, side=side))

    origin = next((name for name, c in model.points.items() if isinstance(c, tuple)
                   and all(e.text.strip() in ("0", "0.0") for e in c)), None)
    for name, c in model.points.items():
        if isinstance(c, Polar) and isinstance(c.origin, str):
            reference = 0.0
            if c.reference is not None and all(isinstance(r, str) for r in c.reference):
                a, b = at[c.reference[0]], at[c.reference[1]]
                reference = math.atan2(b[1] - a[1], b[0] - a[0])
            sweep = math.remainder(float(inst.value(c.angle, f"points.{name}.angle")), 2 * math.pi)
            length(c.origin, name, c.distance)
            angle = _name(c.angle)
            if angle is not None and angle in stated and angle not in done:      # the data only
                done.add(angle)
                out.append(Dimension("angle", at[c.origin], at[name], labels.of(angle, sweep, True),
                                     reference=reference, sweep=sweep))
        elif isinstance(c, TwoCircles):
            for centre, radius in zip(c.centers, c.radii):
                if isinstance(centre, str):
                    length(centre, name, radius)
        elif isinstance(c, CircleLine):
            if isinstance(c.center, str):
                length(c.center, name, c.radius)
            _guide(name, c.line, origin, length)
        elif isinstance(c, tuple) and origin is not None and name != origin:
            for axis, expr in zip("xy", c):
                if expr.names():
                    length(origin, name, expr, axis)
    _radii(model, inst, at, done, length, out)
    for mark in exercise.section.dimensions:
        named = mark.label if mark.label in stated else None
        p, q = mark.between
        length(p, q, _parsed(named), mark.along, None if named else mark.label)
    return out


def _parsed(name: Optional[str]) -> Optional[Expr]:
    from ..expressions import parse

    return parse(name) if name else None


def _radii(model: Any, inst: Any, at: dict, done: set, length: Any, out: list) -> None:
    """A body's circle whose radius is a parameter not yet shown (the planets' r): its radius,
    on the circle and towards the direction where the figure is clearest."""
    taken = list(at.values()) + [((d.start[0] + d.end[0]) / 2, (d.start[1] + d.end[1]) / 2) for d in out]
    found: dict[str, list] = {}
    for body in model.bodies.values():
        for shape in body.shapes:
            radius, centre = getattr(shape, "radius", None), getattr(shape, "center_point", None)
            if (isinstance(radius, Expr) and centre in at and (name := _name(radius)) is not None
                    and name not in done):
                found.setdefault(name, []).append((radius, centre, float(inst.value(
                    radius, f"bodies.{body.name}.radius"))))

    def clear(c: tuple, r: float, a: int) -> float:
        mid = (c[0] + 0.55 * r * math.cos(math.radians(a)), c[1] + 0.55 * r * math.sin(math.radians(a)))
        return min((math.dist(mid, q) for q in taken), default=0.0)

    for circles in found.values():
        radius, centre, r, angle = max(((e, c, r, a) for e, c, r in circles for a in range(0, 360, 30)),
                                       key=lambda t: clear(at[t[1]], t[2], t[3]))
        c = at[centre]
        length(centre, (c[0] + r * math.cos(math.radians(angle)), c[1] + r * math.sin(math.radians(angle))), radius)


def rates_of(exercise: Any, sol: Any, stated: dict[str, Decimal], lang: str,
             dimensions: list[Dimension]) -> list[Dimension]:
    """The given rotations (a body's ω, and α, relative to the frame about its fixed pivot) as
    curved arrows about the pivot (an angle's mark of `draw.dimensions`: an arc with its head
    at the end, in the sense of the rotation, and its text), their text where the figure is
    clearest, so that the figure's labels keep off them as off the other marks."""
    model, inst = sol.model, sol.inst
    if model.dimension != 2:
        return []
    at = {name: _planar(inst.points[name]) for name in model.points}
    size = max((math.dist(p, q) for p in at.values() for q in at.values()), default=1.0) or 1.0
    taken = (list(at.values()) + [_mark_point(d, size) for d in dimensions] + _mark_lines(dimensions, at, size)
             + _bars(model, at))
    out: list[Dimension] = []
    for d in model.drivers:
        if d.kind != "omega" or d.relative_to not in (None, model.frame) or not isinstance(d.value, Expr):
            continue
        pivot = next((j.at for j in model.joints if j.kind.pins and j.kind.centre is Centre.PIN and {j.a, j.b} == {d.body, model.frame}
                      and isinstance(j.at, str)), None)
        if pivot is None:
            continue
        value = float(inst.value(d.value, f"{d.where}.value"))
        if value == 0:
            continue
        radius = _arrow_radius(model.bodies[d.body], pivot, at, inst, size)
        text = _rate_text(exercise, d, value, stated, lang)
        angle = max(range(0, 360, 15), key=lambda a: _clearance(at[pivot], radius, a, taken, len(text) * size / 60))
        sweep = math.copysign(SWEEP, value)
        start = math.radians(angle) - sweep / 2
        arm = radius / 0.6                       # draw.dimensions draws an angle's arc at 0.6 of its arm
        end = (at[pivot][0] + arm * math.cos(start + sweep), at[pivot][1] + arm * math.sin(start + sweep))
        out.append(Dimension("angle", at[pivot], end, text, reference=start, sweep=sweep))
        taken.append(_text_point(at[pivot], radius, angle))
    return out


SWEEP = math.radians(100)          # a rotation's arrow: this much of a turn


def _mark_lines(dimensions: list[Dimension], at: dict, size: float) -> list[tuple[float, float]]:
    """Points along the lines and arcs the dimensions draw (draw.dimensions.placed), a text
    must keep off them too."""
    import numpy as np

    from ..draw.dimensions import placed

    centre = np.mean(np.array(list(at.values())), axis=0)
    out = []
    for d in dimensions:
        arrow = placed(d, size, centre).arrow
        out += [tuple(p) for p in arrow[:: max(1, len(arrow) // 6)]] + [tuple(arrow[-1])]
    return out


def _mark_point(d: Dimension, size: float) -> tuple[float, float]:
    """Where a dimension's text stands, about: a length's middle, an angle's arc's middle."""
    if d.kind != "angle":
        return (d.start[0] + d.end[0]) / 2, (d.start[1] + d.end[1]) / 2
    arm = math.dist(d.start, d.end)
    mid = d.reference + (d.sweep or 0.0) / 2
    r = min(RADIUS * size, 0.6 * arm) * 1.3
    return d.start[0] + r * math.cos(mid), d.start[1] + r * math.sin(mid)


def _arrow_radius(body: Any, pivot: str, at: dict, inst: Any, size: float) -> float:
    for shape in body.shapes:
        if getattr(shape, "center_point", None) == pivot and getattr(shape, "radius", None) is not None:
            return 1.12 * float(inst.value(shape.radius, f"bodies.{body.name}.radius"))
    reach = max((math.dist(at[pivot], at[p]) for p in body.points if p in at), default=0.0)
    return min(max(0.3 * reach, 0.045 * size), 0.1 * size)      # inside an angle's arc (draw.dimensions)


def _rate_text(exercise: Any, d: Any, value: float, stated: dict[str, Decimal], lang: str) -> str:
    """`ω = 6 rad/s` (the datum as stated, its sense drawn), with `α = −2 rad/s²` when given."""
    names = sorted(d.value.names() & set(stated))
    unit = exercise.unit_of(names[0]) if len(names) == 1 else None
    shown = stated_text(abs(stated[names[0]]), unit, lang) if len(names) == 1 else f"{number_text(abs(value), lang, 4)}"
    text = f"ω = {shown}" + ("" if len(names) == 1 and unit is not None else "\u00a0rad/s")
    if isinstance(d.accel, Expr):
        accel = sorted(d.accel.names() & set(stated))
        if len(accel) == 1 and stated[accel[0]] != 0:
            text += f", α = {stated_text(stated[accel[0]], exercise.unit_of(accel[0]), lang)}"
    return text


def _text_point(pivot: tuple, radius: float, angle: float) -> tuple[float, float]:
    a = math.radians(angle)
    return pivot[0] + 1.4 * radius * math.cos(a), pivot[1] + 1.4 * radius * math.sin(a)


def _clearance(pivot: tuple, radius: float, angle: float, taken: list[tuple], width: float) -> float:
    """How far the arrow's text (at `angle`, `width` long, running away from the pivot as
    draw.dimensions sets an angle's text) stands from the nearest point, bar or mark."""
    p = _text_point(pivot, radius, angle)
    way = 1.0 if math.cos(math.radians(angle)) >= 0 else -1.0
    along = [(p[0] + way * width * k / 4, p[1]) for k in range(5)]
    return min((math.dist(a, q) for a in along for q in taken), default=math.inf)


def _bars(model: Any, at: dict) -> list[tuple[float, float]]:
    """Points along each body's bars (between its points), a text must not sit on."""
    out = []
    for body in model.bodies.values():
        pts = [at[p] for p in body.points if p in at]
        for a, b in itertools.pairwise(pts):
            out += [(a[0] + (b[0] - a[0]) * k / 6, a[1] + (b[1] - a[1]) * k / 6) for k in range(1, 6)]
    return out


def _guide(name: str, line: Any, origin: Optional[str], length: Any) -> None:
    """A guide line through a point given by parameters (`{through: [0, h], direction: [1, 0]}`)
    dimensioned from the point at the origin to the point `name` on it, along the axis across
    the line (its height for a horizontal guide)."""
    if origin is None or not isinstance(line.through, tuple) or line.direction is None:
        return
    direction = [e.text.strip() for e in line.direction]
    for axis, across in (("y", 1), ("x", 0)):           # a horizontal line ([1, 0]): its height (y)
        if direction[across] not in ("0", "0.0"):
            continue
        expr = line.through[across]
        if expr.names():
            length(origin, name, expr, axis)


def _clear_side(a: tuple, b: tuple, points: list[tuple], marks: list[Dimension]) -> Optional[str]:
    """The side (left or right of a→b) where a length's text, drawn `OFFSET` off its bar
    (draw.dimensions), stands clearer of the points and of the texts of the marks already
    placed; None (away from the mechanism's centre) when both are as clear."""
    import numpy as np

    from ..draw.dimensions import OFFSET, placed

    span = math.dist(a, b)
    size = max((math.dist(p, q) for p in points for q in points), default=span) or span
    if span == 0:
        return None
    centre = np.mean(np.array(points), axis=0)
    texts = [tuple(placed(m, size, centre).text_at) for m in marks]
    mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
    left = (-(b[1] - a[1]) / span, (b[0] - a[0]) / span)

    def crowd(sign: float) -> float:
        at = (mid[0] + sign * left[0] * (OFFSET + 0.03) * size, mid[1] + sign * left[1] * (OFFSET + 0.03) * size)
        near = [math.dist(at, q) for q in [*points, *texts] if q not in (a, b)]
        return sum(max(0.0, 0.15 * size - d) for d in near)

    lc, rc = crowd(1.0), crowd(-1.0)
    if abs(lc - rc) <= 1e-9 * size:
        return None
    return "left" if lc < rc else "right"


def _planar(p: tuple) -> Point:
    """A planar model's point as two floats (its coordinates on the instant's scalars)."""
    x, y = p
    return float(x), float(y)


def _name(expr: Expr) -> Optional[str]:
    """The parameter an expression is, when it is one name alone."""
    text = expr.text.strip()
    return text if text.isidentifier() else None
