"""Velocity and acceleration polygons as textbooks draw them (seed 001).

One polygon per level: from the pole o, the absolute velocity (acceleration) of every
point ends at its image, lettered as the point (a, b, o4 …); between images, the relative
terms of the equations, head to tail as they are written (ω × AB from a to b; the normal
and then the tangential component; the slide and the Coriolis term), so the whole level's
equations are one figure (the velocity image of each body). An equation's sides are
chained from the image of their first point; an arrow drawn once is not drawn again.
Terms that fall on one line are drawn side by side, offset across it, so none hides
another. Equations outside the level sections (composition of motions) keep a polygon of
their own.
"""
from __future__ import annotations

import re

import math
from typing import Any

from .context import Ctx
from .document import CENTRE_POINT_RE, Arrow, Described, Equation, Figure, Inline, Lead, Name, Names, msg
from .terms import acceleration_terms

OFFSET = 0.06           # of the polygon's size: the least gap between side-by-side arrows (at least a label's room, `_label_across`)
PARALLEL = 0.02         # sin of the angle under which two arrows read as parallel (about 1°)
ALONG = 0.2             # sin of the angle (about 11°) under which a term out of (into) a blue arrow's end runs along it
SAME = 1e-9             # relative: two points (or arrows) are one
MAX_AT_POINT = 4        # names of one image, written as one label: every point there (C5-2.2's translating chassis: c1, c2, o′, p1)
CROWDED = 3             # images at one point past which a polygon along one line constructs nothing a reader parses


def level_polygon(ctx: Ctx, equations: list[Equation], level: str, step: bool = False) -> Figure | None:
    """The polygon of all the planar equations of a level ('v' or 'a'), or of one step's
    (`step`), or None. None too when it would draw a single arrow: a "polygon" of one vector
    closes nothing and a teacher does not draw it; the equation alone says it all (C5-1.6's
    v_A = v_O + v_AO with v_O = 0, whose one arrow was its whole velocity polygon; the notes
    draw no figure there: issue 30, twenty-eighth round (c))."""
    eqs = [e for e in equations if e.level == level]
    if not ctx.planar or not eqs:
        return None
    poly = _Builder(ctx)
    for eq in eqs:
        poly.equation(eq)
    if len(poly.arrows) < 2:
        return None
    key = ("fig.step_v" if level == "v" else "fig.step_a") if step else ("fig.level_v" if level == "v" else "fig.level_a")
    if key == "fig.level_a":                # the caption names only the kinds of terms drawn
        key = {"coriolis": "fig.level_a", "relative": "fig.level_a_relative",
               "normal": "fig.level_a_normal"}[acceleration_terms(eqs)]
    poly.join_page_points(level)
    images = poly.image_points()
    # the caption's "between the images, the terms (black)" only when a term is drawn there:
    # a polygon of absolute velocities alone (C5-2.1's rolling wheels) has none (issue 30)
    between = int(any(a.style != "result" for a in poly.arrows))
    fig = Figure(msg(key, between=between, **({} if step else lettering(ctx, [label for label, _, _ in images]))),
                 unit="speed" if level == "v" else "accel", sample=ctx.symbolic, values=ctx.drawn_values())
    fig.arrows, fig.lines = _separated(poly.arrows)
    fig.points = [("o", (0.0, 0.0), "pole")] + images
    fig.notes = pole_notes(fig, poly) + at_pole_notes(poly) + drawing_notes(fig, poly.symbols)
    return fig


def term_steps(ctx: Ctx, fig: Figure, steps: list[tuple[int, list[Equation]]]) -> list[int]:
    """The numbers of the steps whose equations draw a black arrow (a term between the
    images) of the level polygon `fig`: the one list its caption's "the equations of Steps
    … (black)" is read from. Counting every step with an equation of the level named steps
    whose equations draw only blue arrows, or none (001's revolute pairs: "Steps 1 to 3" over
    Step 3's two terms; C5-E.6's bicycle "1 to 3" over one v_PC; issue 30, nineteenth round (d)).
    A step's term drawn as a point's own arrow, from an image at the pole to the point's image
    (001's a_AO1^n from o1 = o to a, a_A itself), is drawn all the same: its step is named
    (twenty-ninth round (a): "the equations of Steps 2 and 3" left out Step 1, whose one
    term is the arrow from o to a)."""
    whole = _Builder(ctx)                  # the polygon's arrows as built, before `_separated` moves them
    for _, eqs in steps:
        for eq in eqs:
            whole.equation(eq)
    black = [a for a in whole.arrows if a.style != "result"]
    if len(black) != sum(a.style != "result" for a in fig.arrows):
        return []
    out = []
    for n, eqs in steps:
        poly = _Builder(ctx)
        for eq in eqs:
            poly.equation(eq)
        size = poly.size
        if any(_close(a.start, b.start, size) and _close(a.end, b.end, size)
               for a in poly.terms for b in whole.arrows):
            out.append(n)
    return out


def lettering(ctx: Ctx, labels: list[str]) -> dict[str, Any]:
    """The caption's example of how images are lettered, taken from the polygon's own images:
    "a for A" where a is one of them, else the first plain image ("p for P", "a1 for A1"),
    never a letter the page writes as a symbol (C5-2.2's length a: "(a, A-rentzat)" beside it
    reads as the length's name) nor the pole o, and no example (`image` 0) when none is left
    (a page with no point A said "(a for A)" of a letter it never draws)."""
    symbols = {str(name) for name in ctx.model.parameters}
    plain = sorted({n for label in labels for n in label.split(", ")
                    if re.fullmatch(r"[a-z][0-9]*", n) and n != "o" and n not in symbols})
    if not plain:
        return {"image": 0, "point": 0}
    image = "a" if "a" in plain else min(plain, key=lambda n: (len(n), n))     # a bare letter first: p before c1
    return {"image": image, "point": image.upper()}


def pole_notes(fig: Figure, poly: "_Builder") -> list:
    """The caption's word on a label it would not explain: the image of O is lettered o′
    because the letter o names the pole (C5-E.1: O the track's centre, whose point of the
    wheels moves; said so, and not "since o is the pole", which read as if O were at the
    pole where it is not: C5-1.2, C5-2.2, twenty-second round (a));
    a point whose lower-case letter is a parameter's symbol is primed the same way, said
    once (C5-E.6's c′ beside the wheelbase c). Where o′ itself lies at the pole, the
    at-pole sentence names it ("o′, the image of O, is at the pole o, since a_O = 0",
    `at_pole_notes`): one sentence per image at the pole (twenty-first round (e))."""
    images = [label for label, _, kind in fig.points if kind == "image"]
    out = []
    if any(re.search(r"(^|, )o′", label) for label in images) and "o′" not in _at_pole(poly):
        out.append(msg("fig.o_prime"))
    primed = sorted({m for label in images for m in re.findall(r"(?:^|, )([a-np-z])′", label)})
    out += [msg("fig.primed", image=f"{x}′", point=x.upper(), symbol=x,
                what=Described("parameter", x, msg("fig.a_symbol"))) for x in primed]
    return out


def degenerate(fig: Figure) -> bool:
    """Whether a polygon constructs nothing and cannot be read: all its arrows lie along one
    direction (no triangle closes: the equations' values say all it would) and more than
    `CROWDED` images fall on one point (C5-1.5's pulleys: five contact points' images
    where the block's speed is, their labels piled up). Such a polygon is left out."""
    dirs = [(a.end[0] - a.start[0], a.end[1] - a.start[1]) for a in fig.arrows]
    dirs = [d for d in dirs if d != (0.0, 0.0)]
    if not dirs:
        return True
    ux, uy = dirs[0]
    along = all(abs(ux * vy - uy * vx) <= 1e-6 * math.hypot(ux, uy) * math.hypot(vx, vy) for vx, vy in dirs)
    crowded = max((name.count(", ") + 1 for name, _, kind in fig.points if kind == "image"), default=0)
    return along and crowded > CROWDED


def polygon(ctx: Ctx, eq: Equation) -> Figure | None:
    """The polygon of one planar equation (outside the level sections), or None."""
    if not ctx.planar or eq.level not in ("v", "a") or not eq.figure:
        return None
    poly = _Builder(ctx, single=True)
    poly.equation(eq)
    if len(poly.arrows) < 2:
        return None
    styles = {a.style for a in poly.arrows}
    summed = any(a.style == "result" and a.label == eq.target.sym for a in poly.arrows)
    fig = Figure(msg("fig.polygon_v" if eq.level == "v" else "fig.polygon_a",     # a sentence, not a list of
                     unknown=int("unknown" in styles), result=int(summed), sym=eq.target.sym),    # phrases

                 unit="speed" if eq.level == "v" else "accel", sample=ctx.symbolic,
                 values=ctx.drawn_values())
    fig.arrows, fig.lines = _separated(poly.arrows)
    fig.points = [("o", (0.0, 0.0), "pole")] + poly.image_points()
    fig.notes = pole_notes(fig, poly) + at_pole_notes(poly) + drawing_notes(fig, poly.symbols)
    return fig


UNSEEN = 1.0            # an arrow shorter than its head (times this) shows the head alone


def short_arrows(fig: Figure, symbols: dict) -> list:
    """The symbols of the arrows too short to be seen as arrows at the scale the figure is
    drawn at: shorter than their arrowhead (`UNSEEN`), they show the head and no line (C5-E.4's a_U,
    1/32 of a_P, an arrowhead hidden at the pole; a_PU^t a stub at p). `symbols` names the
    arrows drawn without a label (the blue ones, lettered by their images) by their ends."""
    from .render.svg import LINE, MARKER, bounds, points_per_unit

    k = points_per_unit(*bounds(fig), fig.arrows)
    out: list = []
    for a in fig.arrows:
        head = MARKER * LINE.get(a.style, LINE["known"])        # the head's length, as `render.svg` draws it
        sym = a.label if a.label is not None else symbols.get((a.start, a.end))
        if sym is not None and sym not in out and math.dist(a.start, a.end) * k < UNSEEN * head:
            out.append(sym)
    return out


def drawing_notes(fig: Figure, symbols: dict | None = None) -> list:
    """The caption's word on how the polygon departs from a plain chain of arrows: a term
    drawn beside its place (`_separated`: it would lie on another arrow) and joined back to
    its ends by grey dashes. Captions said "head to tail" over terms set aside and tied by
    dashes no sentence explained (001's a_EO2^n beside the blue o→e, C5-E.1's vertical
    terms side by side); and the arrows too short to be seen at its scale (`short_arrows`),
    named, since a term drawn longer than it is would be a lie and one unseen is lost: the
    reader finds its value in the text (C5-E.4's a_U at the pole; issue 30, twenty-eighth
    round (f))."""
    out = [msg("fig.moved_aside")] if fig.lines else []
    short = short_arrows(fig, symbols or {})
    if short:
        out.append(msg("fig.too_short", terms=Names(short), count=len(short)))
        # the caption names them: no label beside an arrow no one sees, piled with the
        # labels where the short terms meet (001's a_BA^t at the pole, C5-1.3's a_QS^n, a_EQ^n)
        fig.arrows = [Arrow(a.start, a.end, None, a.style) if a.label in short else a for a in fig.arrows]
    return out


def at_pole_notes(poly: "_Builder") -> list:
    """The caption's word on the images that fall on the pole, which the figure cannot letter
    apart from o: "a is at o, since a_A = 0" (001's rolling pair, A the fixed point of the
    ground: its acceleration is zero and its image a is the pole). Said of every image a
    term of the polygon's equations names there, at either level (issue 30, twentieth round (c)),
    an instant centre's too ("… and the image of the instant centre I_rod", C5-E.3's v_{I_rod}
    = 0: a caption that says which images are at the pole names them all, twenty-fifth round d)."""
    zero = sorted((name, sym) for name, (xy, sym) in poly.named.items() if poly.at_pole(xy))
    centres = sorted(poly.centres.items())
    # o′ last: its apposition ends in a comma ("o′, the image of O, is at …"), never one
    # before the list's own (", and")
    lettered = [z for z in zero if z[0] != "o′"]
    prime = [z for z in zero if z[0] == "o′"]
    if not zero and not centres:
        return []
    equal: list = []
    for _, sym in lettered + centres + prime:
        equal += [sym, " = "]
    items: list = [Name(n) for n, _ in lettered]
    if centres:
        said = msg("fig.centre_image", centre=Names([Name(t) for t, _ in centres]), count=len(centres))
        items.append(said if items else Lead(said))        # a sentence's first word, capitalised
    # o′ says whose image it is where it is said (`pole_notes`): "o′, the image of O, is at …"
    items += [_o_prime(poly) for _ in prime]
    count = len(lettered) + len(centres) + len(prime)
    return [msg("fig.at_pole", images=Names(items), count=count, zero=Inline(equal + ["0"]))]


def _o_prime(poly: "_Builder") -> Any:
    """How the caption names o′ at the pole: "o′, the image of O,", and where another body's
    point at O has an image of its own (C5-E.1's o′∈wheels, which moves), the O it means:
    the fixed pivot O of the moving body pinned there to a body that does not move ("o′, the
    image of the fixed point O of the arm OC,"; twenty-fifth round d)."""
    ctx = poly.ctx
    others = [n for n in poly.images if n.startswith("o∈")]
    sym = poly.named["o′"][1]
    point = str(sym.sub)
    carriers = ctx.model.carriers(point)
    if not others or not any(ctx.fixed(b) for b in carriers):
        return msg("fig.o_prime_named")
    moving = [b for b in carriers if not ctx.fixed(b) and ctx.point_label(point, b) == point]
    if not moving:
        return msg("fig.o_prime_named")
    return msg("fig.o_prime_fixed", body=Name(moving[0], "body"))


def _at_pole(poly: "_Builder") -> set:
    """The names of the images a term of the polygon's equations puts at the pole."""
    return {name for name, (xy, _) in poly.named.items() if poly.at_pole(xy)}


class _Builder:
    """Arrows and images, each drawn once."""

    def __init__(self, ctx: Ctx, single: bool = False) -> None:
        self.ctx, self.single = ctx, single
        self.arrows: list[Arrow] = []
        self.images: dict[str, tuple] = {}
        self.size = max(ctx.scale_of("speed"), 1e-300)
        self.named: dict[str, tuple] = {}   # image -> (its place, the symbol of the motion ending there)
        self.centres: dict[str, Any] = {}   # an instant centre's point at rest (v_{I_rod}) -> its symbol
        self.symbols: dict[tuple, Any] = {}  # an arrow's ends -> its symbol (a blue arrow is drawn without it)
        self.sides: list[list[tuple]] = []  # each side drawn, as its terms' drawn vectors (`_repeated`)
        self.terms: list[Arrow] = []        # each term between images, before a point's own arrow hides it (`term_steps`)

    def at_pole(self, xy: tuple) -> bool:
        return math.hypot(*xy) <= SAME * self._scale()

    def image_points(self) -> list[tuple[str, tuple, str]]:
        """The images off the pole, those at one point written as one label (a, b, d: C5-E.5's
        chassis points, which move alike), so that no two labels fall on each other."""
        groups: list[tuple[list[str], tuple]] = []
        size = self._scale()
        for name, xy in self.images.items():
            if self.at_pole(xy):
                continue
            same = next((g for g in groups if math.hypot(g[1][0] - xy[0], g[1][1] - xy[1]) <= 1e-7 * size), None)
            if same is None:
                groups.append(([name], xy))
            else:
                same[0].append(name)
        return [(", ".join(sorted(names)), xy, "image") for names, xy in groups]

    def join_page_points(self, level: str) -> None:
        """Letter at an image every other point of the page whose motion (`level` 'v' or 'a')
        lands there: a polygon point names all the points it is the image of (C5-2.2's c1, c2,
        o′: the wheels' centres C1 and C2 of the chassis S1 have one velocity, and "c1, o′"
        left out c2; twenty-fourth round (g)). Only points that are one point of every body
        carrying them (their letter needs no body), and only at images already drawn: a
        point no equation names adds no image of its own."""
        size = self._scale()
        spots = [xy for xy in self.images.values() if not self.at_pole(xy)]
        if not spots:
            return
        taken = {n.split("∈")[0] for n in self.images}
        for point in self.ctx.model.points:
            bodies = self.ctx.model.carriers(point)
            name = _letter(point, page_letters(self.ctx))
            if not bodies or not name or name in taken or not self.ctx.shared(point):
                continue
            motion = (self.ctx.vel if level == "v" else self.ctx.acc)(bodies[0], point)
            xy = tuple(float(c) for c in self.ctx.drawn(motion)[:2])
            if any(math.hypot(xy[0] - p[0], xy[1] - p[1]) <= 1e-7 * size for p in spots):
                self.images[name] = xy

    def _scale(self) -> float:
        pts = [p for a in self.arrows for p in (a.start, a.end)]
        return max([math.hypot(*p) for p in pts] + [1e-300])

    def equation(self, eq: Equation) -> None:
        origin = (0.0, 0.0)
        for side in eq.sides:
            if self._repeated(side):
                continue
            tip = origin
            for n, term in enumerate(side):
                if n and term.kind not in RIGID and side[n - 1].kind in RIGID:
                    self._vertex(eq, side[0], tip)
                step = self.ctx.drawn(term.value)
                if step[0] == 0 and step[1] == 0:
                    if term.kind == "point" and not term.sym.sup and tip == origin:
                        self._named(term.sym, origin)          # a point at rest: its image is o
                    continue
                end = (tip[0] + step[0], tip[1] + step[1])
                whole = term.kind == "point" and not term.sym.sup
                if whole and tip == origin:
                    self._image(term.sym.sub, end)
                    self._named(term.sym, end)
                    style = "known" if self.single and not term.unknown else "result"
                    # a side's first term in an equation of two sides (001 p_pair's v_{B∈M} =
                    # v_E + v_BE): the student reads it there, beside its image b∈M
                    self._arrow(Arrow(origin, end, term.sym, style if self.single else "result"),
                                label=self.single or len(eq.sides) > 1)
                else:
                    style = ("unknown" if term.unknown else "known") if self.single else "known"
                    self.terms.append(Arrow(tip, end, term.sym, style))
                    self._arrow(Arrow(tip, end, term.sym, style))
                tip = end
        end = self.ctx.drawn(eq.target.value)
        if eq.target.sym.base in ("v", "a") and not eq.target.sym.sup:
            self._named(eq.target.sym, end)
        if end != origin and eq.target.sym.base in ("v", "a"):
            if not eq.target.sym.sup:
                self._image(eq.target.sym.sub, end)
            self._arrow(Arrow(origin, end, eq.target.sym, "result"), label=self.single)

    def _repeated(self, side: list) -> bool:
        """Whether a side repeats, in another order, the terms of a side already drawn to the
        same image: the same vectors, each again (C5-E.1's a_C = a_C^t + a_C^n of Step 2, the
        path's intrinsic components, after Step 1's a_C = a_O + a_CO^n + a_CO^t, the same two
        vectors about the fixed O). Drawn, it is the other half of one parallelogram: five
        labels round c where three say it (issue 30, twenty-eighth round (f))."""
        steps = [s for s in (tuple(float(c) for c in self.ctx.drawn(t.value)[:2]) for t in side) if s != (0.0, 0.0)]
        end = (sum(s[0] for s in steps), sum(s[1] for s in steps))
        for drawn in self.sides:
            if len(drawn) == len(steps) >= 2 and _close(_sum(drawn), end, self.size) and _same_vectors(drawn, steps, self.size):
                return True
        self.sides.append(steps)
        return False

    def _vertex(self, eq: Equation, first: Any, tip: tuple) -> None:
        """Letter the vertex where a side's rigid-body terms end and its relative terms begin:
        the point the equation is about, as a point of the body those terms rotate with
        (001's rolling pair, a_{F∈N} = a_A + a_FA^n + a_FA^t + a_{F∈N rel R}: the tip after
        a_FA^t is a_{F∈R}, an answer, and its vertex had no letter though the caption says
        every image is lettered; issue 30, twenty-eighth round (f)). The body is the one
        carrying the side's first point (and the point, when it is the model's: a contact's
        point F is carried by none) whose motion there ends at that tip."""
        if eq.point is None or first.kind != "point":
            return
        point, base = eq.point.point, str(first.sym.sub).partition("∈")[0]
        motion = self.ctx.vel if eq.level == "v" else self.ctx.acc
        model = self.ctx.model
        for body in model.carriers(base) if base in model.points else []:
            if point in model.points and body not in model.carriers(point):
                continue
            xy = tuple(float(c) for c in self.ctx.drawn(motion(body, point))[:2])
            if _close(xy, tip, self.size):
                self._image(self.ctx.point_label(point, body), tip)
                return

    def _named(self, sym: Any, xy: tuple) -> None:
        """The image of the point `sym` (v_A, a_A) names, with its place and that symbol; an
        instant centre placed as a point (v_{I_rod}, no letter of its own) is kept apart, by
        its token, for the caption (`at_pole_notes`)."""
        if CENTRE_POINT_RE.fullmatch(str(sym.sub)):
            self.centres.setdefault(str(sym.sub), sym)
            return
        name = _letter(sym.sub, page_letters(self.ctx))
        if name and name not in self.named:
            self.named[name] = (xy, sym)

    def _image(self, label: str, xy: tuple) -> None:
        name = _letter(label, page_letters(self.ctx))
        if name and name not in self.images:
            self.images[name] = xy

    def _arrow(self, a: Arrow, label: bool = True) -> None:
        """Add an arrow once; a point's absolute motion wins over a term that is the same
        arrow from the pole (v_AO2 when O2 is fixed): blue, lettered by its image, and still
        labelled with the term, which the equation writes and the student reads there
        (issue 30, round 29 c: 001 p_pair's o→b∈N lost v_BE, the rocker's term)."""
        if a.label is not None:
            self.symbols.setdefault((a.start, a.end), a.label)
        a = a if label else Arrow(a.start, a.end, None, a.style)
        for i, b in enumerate(self.arrows):
            if _close(a.start, b.start, self.size) and _close(a.end, b.end, self.size):
                if a.style == "result" and b.style != "result" and not self.single:
                    self.arrows[i] = Arrow(a.start, a.end, a.label if a.label is not None else self._read(b.label), a.style)
                elif b.style == "result" and a.style != "result" and b.label is None and not self.single:
                    self.arrows[i] = Arrow(b.start, b.end, self._read(a.label), b.style)
                return
        self.arrows.append(a)


    def _read(self, label: Any) -> Any:
        """A term's label kept on the blue arrow it shares: a relative term between two points
        (v_BE, v_AO1); none for a point's own term (C5-E.4's a_A1^t, a wheel's centre, whose
        arrow the caption names by the point's motion) or a term about an instant centre placed
        as a point (C5-1.1's v_{CI_pulley})."""
        if label is None or CENTRE_POINT_RE.search(str(label.sub)) or str(label.sub) in self.ctx.model.points:
            return None
        return label


RIGID = ("rotation", "normal", "tangential")     # the kinds of a rigid body's terms about a point of it


def _sum(steps: list[tuple]) -> tuple:
    return (sum(s[0] for s in steps), sum(s[1] for s in steps))


def _same_vectors(a: list[tuple], b: list[tuple], size: float) -> bool:
    """Whether the lists of vectors a and b hold the same vectors, in any order."""
    rest = list(b)
    for v in a:
        match = next((i for i, w in enumerate(rest) if _close(v, w, size)), None)
        if match is None:
            return False
        rest.pop(match)
    return True


def _close(p: tuple, q: tuple, size: float) -> bool:
    return math.hypot(p[0] - q[0], p[1] - q[1]) <= 1e-7 * size


def page_letters(ctx: Ctx) -> frozenset[str]:
    """The one-letter symbols a page writes besides the polygon's images: its parameters
    (C5-E.6's wheelbase c, C5-2.2's length a)."""
    return frozenset(str(n) for n in ctx.model.parameters if len(str(n)) == 1)


def _letter(label: str, taken: frozenset[str] = frozenset()) -> str:
    """The image of a material point in the polygon: its name in lower case (A → a, O4 →
    o4), with the body when the label names one (B∈2, the guide's point under the block:
    b∈2, apart from the block's own b). The image of a motion relative to a body (B/2)
    is not a point's: no letter. An image never reads as another symbol of the page: the
    pole is o, so a point O's image is o′, and a letter the page writes as a parameter is
    primed too (C5-E.6's crank axle C: c′, beside the wheelbase c)."""
    if "/" in label:
        return ""
    name, _, body = label.partition("∈")
    if not name or not name[0].isalpha():
        return ""
    # o is the pole: O's image is o′; a body's point at O keeps its body and no prime (o∈wheels),
    # so that o′ names one image, the bare O's (C5-E.1: "o′∈wheels" beside a caption's "o′, the
    # image of the fixed point O of the arm", two points lettered o′; twenty-eighth round (f))
    letter = name.lower() if name.lower() not in ({*taken} if body else {"o", *taken}) else name.lower() + "′"
    if re.fullmatch(r"j\d+", letter):
        letter = name            # a contact J10's image: j10 would read as a joint's id
    return letter + (f"∈{body}" if body else "")


def _separated(arrows: list[Arrow]) -> tuple[list[Arrow], list[tuple[tuple, tuple]]]:
    """Arrows moved across their line, in turn, while one runs along one already placed closer
    than the gap (`_overlap`): collinear terms side by side, and a term that runs a hair's
    breadth beside another (C5-E.4's blue a_P beside a_PU^n, 0.5 apart on a polygon 16 long)
    moved off it too, each to its own side, so that no arrow reads as drawn over another
    (issue 30, twenty-fourth round (g)).

    An absolute motion (blue) never moves: it runs from the pole to the image it letters, as
    the caption says ("each absolute velocity ends at its image"; the twenty-fourth round's
    blue arrows moved aside ended beside their dots: C5-2.2, C5-E.1's o′ a dot no arrow
    reached; twenty-fifth round (c)). Only terms (black) move aside, and a term moved keeps
    its ends joined to the points it runs between: the second list, thin lines from each
    moved end back to where it was (an image, or the tip of the term before it).

    The gap leaves room for a term's label between the two arrows, at the scale the polygon
    is drawn at (`_label_across`): a label's height beside horizontal arrows, its width
    beside vertical ones. A term goes to the side where it and its joins cross the fewest
    arrows (`_aside`): into the polygon, across its arrows, no side of it was clear for its
    label (issue 30, twenty-seventh round (a))."""
    pts = [p for a in arrows for p in (a.start, a.end)]
    size = max(*(abs(p[0]) for p in pts), *(abs(p[1]) for p in pts), 1e-300)
    k = _drawn_scale(pts, arrows)
    placed: dict[int, Arrow] = {}
    joins: list[tuple[tuple, tuple]] = []
    order = sorted(range(len(arrows)), key=lambda i: arrows[i].style != "result")
    for i in order:
        a = arrows[i]
        if a.style == "result" and any(b.style == "result" for b in arrows):
            placed[i] = a                       # blue: from the pole to its image, where it is
            continue
        gap = max(OFFSET * size, _label_across(a) / k)      # room for its label beside it
        near = [_across(a, b) for b in placed.values() if _along(a, a, b, math.inf, gap)]     # side by side
        # the least move that clears them all: none, or just `gap` to either side of one, to
        # the side where it crosses the fewest other arrows (`_aside`)
        shifts = sorted({0.0, *(s + d for s in near for d in (gap, -gap))}, key=lambda s: (abs(s), -s))
        clear = [(abs(s), _shifted(a, s)) for s in shifts]
        clear = [(s, m) for s, m in clear if not any(_along(m, a, b, gap, gap) for b in placed.values())]
        if not clear:
            moved = _shifted(a, shifts[-1])
        elif clear[0][0] == 0.0:
            moved = a
        else:                       # the least move to either side: one gap on each
            moved = _aside(a, [m for s, m in clear if s <= clear[0][0] + gap * (1 + 1e-9)],
                           [b for j, b in enumerate(arrows) if j != i], _chain(arrows, i))
        placed[i] = moved
        if moved.start != a.start:
            joins += [(a.start, moved.start), (a.end, moved.end)]
    return [placed[i] for i in range(len(arrows))], joins


LABEL_BOX = (30.0, 16.0)    # points: a term's label (a_FB^t), width and height, as the figures set it


def _drawn_scale(pts: list[tuple], arrows: list) -> float:
    """Points per model unit at which a polygon through `pts` (its arrows' ends) and its pole
    is drawn (`render.svg.points_per_unit`, the bounds 2 % larger as `render.svg.bounds`,
    grown for its shortest labelled term among `arrows`)."""
    from .render.svg import points_per_unit

    xs, ys = [0.0] + [p[0] for p in pts], [0.0] + [p[1] for p in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-300)
    return points_per_unit(min(xs) - 0.02 * span, min(ys) - 0.02 * span, max(xs) + 0.02 * span, max(ys) + 0.02 * span,
                           arrows)


def _label_across(a: Arrow) -> float:
    """The room (points) a term's label needs between arrow `a` and one beside it: the
    label's box across `a`'s direction (`LABEL_BOX`: w |sin θ| + h |cos θ|), its text's
    nearest to its own arrow (`draw.labels.PAD` + the least of `DISTANCES`) and the other
    arrow that and `OWN_MARGIN` farther (`draw.labels.Layout._not_own`), and a point.
    Side-by-side terms closer than that left no room between them for either label, which
    then sat outside, by the other's line (001's a_FB^t outside a_F∈N/R, 10.6 pt apart;
    C5-E.1's three vertical terms 15.6 pt apart for labels 26 pt wide; issue 30,
    twenty-seventh round (a))."""
    from ..draw.labels import DISTANCES, OWN_MARGIN, PAD

    dx, dy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    n = math.hypot(dx, dy) or 1.0
    w, h = LABEL_BOX
    near = PAD + DISTANCES[0]               # the label's text from its own arrow, at its nearest
    return w * abs(dy) / n + h * abs(dx) / n + near + (near + OWN_MARGIN) + 1.0


def _aside(a: Arrow, moves: list[Arrow], others: list[Arrow], chain: list[Arrow]) -> Arrow:
    """Of the places term `a` may be moved aside to (`moves`: the least move to either side,
    the least first), the one where it and the two thin lines joining it back to its ends
    cross or run along the fewest of the polygon's `others` arrows (as built), the least move
    of equals; a join may run along the terms of `chain` (the term before `a` in its equation
    and the one after, which it leads into). A term moved into the polygon, across the arrows
    there, left its label no side clear of them: 001's a_EO2^n moved from o→e towards o→b,
    across that blue arrow and into the narrow angle between the two, its label beside o→a;
    the other way it lies outside, clear of every arrow. C5-E.1's a_OC^n moved right of o
    drew its join at c along a_CO^t (issue 30, twenty-seventh round (a))."""
    def hits(m: Arrow) -> int:
        joins = [Arrow(a.start, m.start, None, "known"), Arrow(a.end, m.end, None, "known")]
        return sum(_crosses(m, b) for b in others) + sum(
            _crosses(j, b) or (b not in chain and _overlap(b, j, 1e-6 * _length(b)))
            for j in joins for b in others)
    return min(moves, key=hits)             # min keeps the least move of equals


def _chain(arrows: list[Arrow], i: int) -> list[Arrow]:
    """The terms next to arrow i in its equation's chain, as built (`_Builder.equation`
    appends a side's terms in turn): the one before, ending where it starts, and the one
    after, starting where it ends."""
    a = arrows[i]
    before = [arrows[i - 1]] if i > 0 and arrows[i - 1].end == a.start else []
    after = [arrows[i + 1]] if i + 1 < len(arrows) and arrows[i + 1].start == a.end else []
    return before + after


def _length(a: Arrow) -> float:
    """The length of arrow a (1 for a point: a scale for `_crosses`'s rounding)."""
    return math.hypot(a.end[0] - a.start[0], a.end[1] - a.start[1]) or 1.0


def _crosses(a: Arrow, b: Arrow) -> bool:
    """Whether the arrows a and b cross (their segments meet at a point inside both, not
    where one only touches the other: a join from an image on a blue arrow)."""
    eps = SAME * _length(a) * _length(b)

    def side(o: tuple, u: tuple, v: tuple) -> float:
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])

    def apart(p: float, q: float) -> bool:
        return (p > eps and q < -eps) or (p < -eps and q > eps)
    return (apart(side(a.start, a.end, b.start), side(a.start, a.end, b.end))
            and apart(side(b.start, b.end, a.start), side(b.start, b.end, a.end)))


def _along(moved: Arrow, a: Arrow, b: Arrow, tol: float, gap: float) -> bool:
    """Whether term `a`, drawn at `moved`, runs along the arrow `b` closer than `tol`: `b`'s
    ends near `moved`'s line, or, where `a` leaves or enters the blue `b` (`_alike`), also
    `moved`'s ends near `b`'s line (a short term beside a long blue arrow)."""
    sin = _alike(a, b, gap)
    return _overlap(moved, b, tol, sin) or (sin == ALONG and _overlap(b, moved, tol, sin))


def _alike(a: Arrow, b: Arrow, gap: float) -> float:
    """The angle (its sine) under which term `a`, within a gap of the arrow `b` placed
    before it, reads as drawn over it: `ALONG` (about 11°) when `b` is blue and `a` leaves
    its start (the pole) or ends at its end (its image), since two arrows out of (into) one
    point that close read as one and their heads pile up (001's a_EO2^n out of o, 4.6° off
    the blue o→e; a_BE^t into b beside o→b; twenty-fifth round (c)); `PARALLEL` else."""
    if b.style == "result" and a.style != "result" and (
            math.dist(a.start, b.start) <= 1e-9 * gap or math.dist(a.end, b.end) <= 1e-9 * gap):
        return ALONG
    return PARALLEL


def _across(a: Arrow, b: Arrow) -> float:
    """How far the middle of `b` lies across the line of `a`, along `a`'s left normal."""
    dx, dy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    n = math.hypot(dx, dy) or 1.0
    mx, my = (b.start[0] + b.end[0]) / 2 - a.start[0], (b.start[1] + b.end[1]) / 2 - a.start[1]
    return (dx * my - dy * mx) / n


def _shifted(a: Arrow, d: float) -> Arrow:
    dx, dy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    n = math.hypot(dx, dy) or 1.0
    ox, oy = -dy / n * d, dx / n * d
    return Arrow((a.start[0] + ox, a.start[1] + oy), (a.end[0] + ox, a.end[1] + oy), a.label, a.style)


def _overlap(a: Arrow, b: Arrow, tol: float, sin: float = PARALLEL) -> bool:
    """Whether two arrows run along one another: both ends of `b` closer than `tol` to the
    line of `a`, their extents overlapping, and their directions within `sin` of each
    other (parallel: `PARALLEL`; a term out of the pole or into an image beside a blue
    arrow: `ALONG`, see `_alike`)."""
    ux, uy = a.end[0] - a.start[0], a.end[1] - a.start[1]
    vx, vy = b.end[0] - b.start[0], b.end[1] - b.start[1]
    la, lb = math.hypot(ux, uy), math.hypot(vx, vy)
    if la == 0 or lb == 0 or abs(ux * vy - uy * vx) > sin * la * lb:
        return False
    wx, wy = b.start[0] - a.start[0], b.start[1] - a.start[1]
    ex, ey = b.end[0] - a.start[0], b.end[1] - a.start[1]
    if max(abs(ux * wy - uy * wx), abs(ux * ey - uy * ex)) / la >= tol * (1 - 1e-9):
        return False
    t0 = (wx * ux + wy * uy) / la
    t1 = (ex * ux + ey * uy) / la
    lo, hi = min(t0, t1), max(t0, t1)
    return hi > 0.02 * la and lo < 0.98 * la
