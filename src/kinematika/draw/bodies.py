"""Bodies as a kinematics textbook draws them: bars, ternary plates, wheels, a hatched ground.

A body with two points is a bar; with three or more, the plate of their convex hull (a
bar again when they are collinear). Circles are wheels (with two spokes, so that turning
shows in an animation) or dash-dot pitch circles of gears. The frame is drawn in grey:
its lines and circles hatched on the material's side. What is drawn are marks
(`draw.picture`), each in the body it moves with.
"""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

from .geometry import clip_line, clip_segment, convex_hull, overlap_along, perpendicular, points_to_data
from ..model.wording import noun
from .names import plain, shows_tag
from .context import Context
from .scene import BodyView, ShapeView
from ..joints.symbols import HATCH_BAND
from .style import BAR_WIDTH, GROUND, INK, POINT_LABEL

DOTTED_SPHERE = (4.0, 3.0)      # the sphere of a spherical linkage: dashes, in line widths
FALLING = "\\\\\\\\"              # matplotlib's hatching falling to the right, as dense as the frame's ////
TIE = 0.05                # half the width of the hatched edge a fixed strand is tied to (of the drawing's size)
APART_DASH = (4.0, 3.0)   # a circle in another plane than the ground it crosses: dashes, in line widths
APART_FILL = 0.1          # and its fill, lighter than a wheel's (0.25)
MATERIAL = 0.6       # how deep (of the drawing's size) the ground beyond a hatched edge is an area (`hatched_edge`)
DISC_FILL = 0.5      # a moving disc's translucent fill: under the frame's hatching (zorder 1)
                     # and outline (2), so a track a wheel overlaps stays seen (C5-E.1's 2R
                     # wheel over "pista zilindrikoa"; issue 30, twenty-fourth round (h))


def draw_bodies(ctx: Context) -> None:
    """Every body as a textbook draws it: the frame's shapes hatched and its bars grey, each
    moving body's bars, plates, wheels and curves in its colour, then the points with their
    labels (a spherical linkage's sphere dashed behind)."""
    if ctx.scene.sphere is not None:
        centre, radius = ctx.scene.sphere
        ctx.add("circle", [centre], r=float(radius), colour="#bdbdbd", width=1.0,
                dash=DOTTED_SPHERE, zorder=0, gid="sphere")
    for body in ctx.scene.bodies.values():
        ctx.owner = body.name                 # what is drawn now outlines this body (`Context.avoid`)
        if body.frame:
            for shape in body.shapes:
                _ground_shape(ctx, shape)
            _skeleton(ctx, body, GROUND, 3.0)
            _fixed_circle_name(ctx, body)
        elif body.fixed:
            _fixed_body(ctx, body)
            _fixed_circle_name(ctx, body)
        else:
            _body(ctx, body)
    ctx.owner = None
    _points(ctx)
    _contact_names(ctx)


def _skeleton(ctx: Context, body: BodyView, colour: str, width: float = BAR_WIDTH) -> None:
    """A body drawn as its bars (a carrier's arms, a chassis, a spherical link's arcs)."""
    for line in body.skeleton:
        ctx.add("line", line, width=width, colour=colour, alpha=0.9, cap="round", join="round",
                zorder=2, gid=f"body:{body.name}", moves_with=None if body.frame else body.name)
        ctx.avoid(*line, bar=True, width=width)


def _body(ctx: Context, body: BodyView) -> None:
    pts = _distinct(list(body.points.values()), 1e-9 * ctx.size)
    anchor = None
    wheels = [s for s in body.shapes if s.kind == "circle" and not s.ring]
    if wheels and all(_on_wheel(p, wheels) for p in pts):
        _radii(ctx, body, pts, wheels)       # the disc is the body: mark its points by radii
        pts = []
    elif wheels:                             # a crank on a disc: its points on the disc by radii
        on = [p for p in pts if _on_wheel(p, wheels) and not _at_centre(p, wheels, ctx.size)]
        _radii(ctx, body, on, wheels)
        pts = [p for p in pts if not any(p is q for q in on)]
    side = None                              # a bar's label beside it, away from the mechanism
    spots = None                             # other points of the body its name may be led from
    if body.skeleton:
        _skeleton(ctx, body, body.colour)
        longest = max(body.skeleton, key=lambda line: float(np.ptp(np.asarray(line), axis=0).sum()))
        anchor, pts = np.asarray(longest)[len(longest) // 2], []
        spots = bar_spots(longest)
        if len(longest) == 2:
            anchor = (longest[0] + longest[1]) / 2
            side = _beside(ctx, longest[0], longest[1])
    if len(pts) >= 3:
        hull = convex_hull(pts)
        if len(hull) >= 3 and _area(hull) > 1e-5 * ctx.size ** 2:
            ctx.add("polygon", hull, colour=body.colour, fill=body.colour, alpha=0.38, width=2.5,
                    join="round", zorder=2, gid=f"body:{body.name}", moves_with=body.name)
            ctx.avoid(*hull, hull[0])
            ctx.area(*hull)
            anchor = np.mean(hull, axis=0)
        else:
            pts = _extremes(pts)
    if len(pts) == 2:
        ctx.add("line", pts, width=BAR_WIDTH, colour=body.colour, alpha=0.9, cap="round",
                zorder=2, gid=f"body:{body.name}", moves_with=body.name)
        ctx.avoid(*pts, bar=True, width=BAR_WIDTH)
        anchor = (pts[0] + pts[1]) / 2
        side = _beside(ctx, pts[0], pts[1])
        spots = bar_spots(pts)
    prefer = None
    for shape in body.shapes:
        _moving_shape(ctx, body, shape)
        if anchor is None and shape.kind == "circle":
            anchor = shape_anchor(shape, ring_band(ctx, shape))
            spots = shape_spots(shape, ring_band(ctx, shape))
            prefer = UP_LEFT if shape.ring else None
        elif spots is not None and shape.kind == "circle" and not shape.ring:
            spots = _wheel_spots(spots, shape_spots(shape))
    if anchor is None and pts:
        anchor = pts[0]
    if anchor is not None:
        name = plain(noun(body.label or body.name)) + _tag(ctx, body)
        ctx.label(anchor, name, body.colour, 5, f"body:{body.name}", body=body.name, side=side, prefer=prefer,
                  group=f"body:{body.name}", style="italic", radius=BAR_WIDTH / 2 if side is not None else 0.0,
                  spots=spots)


def _wheel_spots(spots: np.ndarray, wheel: Optional[np.ndarray]) -> np.ndarray:
    """A crank's name's spots (`bar_spots`) and its disc's (`shape_spots`): a crank on a
    disc is one body, named from either. C5-E.6's chainring lies inside the chain's loop,
    and its crank's stretch there runs by the frame's bar: led from the crank alone, its
    name crossed the frame and the chain, or went under the ground (issue 30,
    twenty-eighth round (g)); from its disc's top it crosses the chain's run alone. The
    disc's spots at two depths: a chain wrapped round the rim and a frame through the axle
    leave a narrow band between them."""
    if wheel is None:
        return spots
    centre = wheel.mean(axis=0)
    return np.vstack([spots, wheel, centre + 0.75 * (wheel - centre)])     # and nearer its centre


def _tag(ctx: Context, body: Any) -> str:
    """` (3)` after a body's name when the figure is numbered, unless the name already reads
    its tag (`names.shows_tag`: no `roda 1 (1)`), or the tag is a subscript read off the
    name (`BodyView.read_off`): a figure names a body as the text does, by its name, and
    the text defines a shortened subscript where it writes one ("ω_zentrala *gurpil zentral
    finkoaren* abiadura angeluarra da"). "gurpil zentral finkoa (zentrala)" on C5-E.2's
    figure was heavy, and C5-1.7's "(euskarria)" is written nowhere else on its page (issue
    30, twenty-seventh round (c)). A number, or an index the model's notation gives, is
    said: the text's symbols name the body by it alone (ω_3, I_13)."""
    tag = str(body.index or body.number)
    if not ctx.scene.numbered or body.read_off or not shows_tag(tag, noun(body.label or body.name)):
        return ""
    return f" ({tag})"


def _beside(ctx: Context, p: np.ndarray, q: np.ndarray) -> Optional[np.ndarray]:
    """The side of the bar pq its name goes: across it, away from the moving bodies' centroid
    (upwards when the bar passes through it)."""
    d = np.asarray(q, dtype=float) - np.asarray(p, dtype=float)
    if np.linalg.norm(d) <= 1e-12 * ctx.size:
        return None
    n = perpendicular(d / np.linalg.norm(d))
    away = float(n @ ((p + q) / 2 - ctx.centroid()))
    if abs(away) <= 1e-9 * ctx.size:
        away = float(n[1]) or float(n[0])
    return n if away > 0 else -n


def _on_wheel(p: np.ndarray, wheels: list[ShapeView]) -> bool:
    return any(np.linalg.norm(p - w.center) <= w.radius * (1 + 1e-6) for w in wheels)


def _at_centre(p: np.ndarray, wheels: list[ShapeView], size: float) -> bool:
    """Whether `p` is a wheel's centre: where a crank on the disc starts (`_body`). A body
    with a disc and points off it (C5-E.6's chainring: the chain's contact T2 on its rim, the
    pedal P on its crank, L below the axle C) is its disc, with its points on the disc marked
    by radii, and its crank, a bar from the centre to the points off the disc: one bar through
    T2, C and P read as a crank from the top of the chainring to the pedal (issue 30,
    twenty-seventh round (f))."""
    return any(np.linalg.norm(p - w.center) <= 1e-9 * size for w in wheels)


def _radii(ctx: Context, body: BodyView, pts: list, wheels: list[ShapeView]) -> None:
    """Lines from a wheel's centre to its marked points (a wheel's points are on its disc)."""
    for p in pts:
        w = min(wheels, key=lambda s: np.linalg.norm(p - s.center))
        if np.linalg.norm(p - w.center) > 1e-9 * ctx.size:
            ctx.add("line", [w.center, p], width=2.0, colour=body.colour, zorder=3, cap="round",
                    moves_with=body.name)
            ctx.avoid(w.center, p)


def _moving_shape(ctx: Context, body: BodyView, s: ShapeView) -> None:
    gid, name = f"shape:{body.name}", body.name
    if s.kind == "circle" and s.ring:
        _ring_gear(ctx, body, s)
    elif s.kind == "circle" and s.arc is not None:
        outline = s.outline()                # a part of a disc: filled, its arc and chord drawn
        ctx.add("polygon", outline, colour="none", fill=body.colour, alpha=0.25, width=0,
                zorder=DISC_FILL, moves_with=name)
        ctx.add("line", outline, width=2.2, colour=body.colour, join="round", zorder=3, gid=gid,
                moves_with=name)
        ctx.avoid(*outline)
        ctx.area(*outline)
    elif s.kind == "circle":
        gear, centre = s.role == "gear", s.centre()
        fill = 0.18 if gear else 0.25
        ctx.add("circle", [centre], r=s.radius, colour="none", fill=body.colour,
                alpha=APART_FILL if s.apart else fill, width=0, zorder=DISC_FILL, moves_with=name)
        ctx.add("circle", [centre], r=s.radius, colour=body.colour, width=1.6 if gear or s.apart else 2.2,
                dash=APART_DASH if s.apart else gear, zorder=3, gid=gid, moves_with=name)
        for arm in cross_hair(ctx, centre, s.radius):
            ctx.add("line", arm, width=1.0, colour=body.colour, alpha=0.4 if s.apart else 0.8, zorder=3,
                    moves_with=name, avoid=0.0)
            ctx.avoid(*arm, width=CROSS_HAIR, centre=True)
        ctx.avoid(*_ring(centre, s.radius))
        ctx.area(*_ring(centre, s.radius))
        wrap = cable_wrap(ctx.scene, body, s)
        if wrap is not None:
            arc, colour = wrap
            # on the rim, which labels already keep off (the disc's `avoid` above)
            ctx.add("line", arc, width=WRAP_WIDTH, colour=colour, zorder=3.5, cap="round",
                    gid=f"wrap:{name}", moves_with=name)
    elif s.kind == "line":
        loop = belt_loop(ctx, body, s)
        if loop is not None:
            ctx.add("line", loop, width=2.6, colour=body.colour, zorder=3.5, gid=gid, moves_with=name)
            ctx.avoid(*loop)
            return
        seg = _line_span(ctx, body, s)
        if seg is not None:
            ctx.add("line", seg, width=2.2, colour=body.colour, zorder=2, gid=gid, moves_with=name)
            ctx.avoid(*seg)
    elif s.kind == "curve":
        _moving_curve(ctx, body, s, gid)
    elif s.vertices is not None:
        ctx.add("polygon", s.vertices, colour=body.colour, fill=body.colour, alpha=0.3, width=1.5,
                zorder=1, gid=gid, moves_with=name)
        ctx.avoid(*s.vertices)
        ctx.area(*s.vertices)


CROSS_HAIR = 5.0     # points: the width a wheel's cross-hair is kept clear by a label as a bar's
                    # is (`LabelBoard.avoid`'s width: `BAR_CLEAR` off its stroke)


def cross_hair(ctx: Context, centre: np.ndarray, radius: float) -> list[np.ndarray]:
    """A wheel's centre lines (its two spokes, which show it turn in an animation): four arms
    from its centre, 0.8 of its radius long, less each arm that a vector's arrow runs along
    (`geometry.overlap_along`) for more than a fifth of it: drawn under C5-1.7's v_C and
    C5-E.4's v_U, leaving the centre along the horizontal diameter, the line vanished under
    the arrow and the arrow's value lay on it; a teacher breaks the centre line where an
    arrow leaves the centre along it (issue 30, twenty-ninth round (e)). Whole arms are kept
    as a line through the centre (one mark for two opposite arms)."""
    arms = []
    near = points_to_data(CROSS_HAIR, ctx.view, getattr(ctx, "per_point", None))
    for d in (np.array([1.0, 0.0]), np.array([0.0, 1.0])):
        kept = [float(sign) for sign in (-1.0, 1.0)
                if not any(overlap_along(a, b, centre, centre + sign * 0.8 * radius * d, near) > 0.16 * radius
                           for a, b in ctx.arrows)]
        if len(kept) == 2:
            arms.append(np.array([centre - 0.8 * radius * d, centre + 0.8 * radius * d]))
        elif kept:
            arms.append(np.array([centre, centre + kept[0] * 0.8 * radius * d]))
    return arms


def _moving_curve(ctx: Context, body: BodyView, s: ShapeView, gid: str) -> None:
    """A body's curve: a cam's profile filled, its pitch curve dash-dot, a curve (a slot's
    path, a profile through points) as a line."""
    vertices = s.polyline()
    if s.role == "pitch":
        ctx.add("line", vertices, width=1.0, dash=True, colour=body.colour, zorder=2,
                moves_with=body.name)
        return
    if s.closed and s.role == "profile":
        ctx.add("polygon", vertices, colour="none", fill=body.colour, alpha=0.2, width=0,
                zorder=DISC_FILL, moves_with=body.name)
        ctx.area(*vertices)
    ctx.add("line", vertices, width=2.2, colour=body.colour, zorder=3, gid=gid, moves_with=body.name)
    ctx.avoid(*vertices[::8])


WRAP_WIDTH = 2.2     # the cable's arc wrapped round a pulley: as thin as its strands, over the rim (2.2)


def strand(scene: Any, body: Optional[BodyView]) -> bool:
    """Whether a body is a strand of cable: a straight body (a line, no circle), moving, or
    fixed and tied as a cable (`cable_strand`)."""
    if body is None or not any(sh.kind == "line" for sh in body.shapes) \
            or any(sh.kind == "circle" for sh in body.shapes):
        return False
    return not (body.frame or body.fixed) or cable_strand(scene, body)


def cable_wrap(scene: Any, body: BodyView, s: ShapeView) -> Optional[tuple[np.ndarray, str]]:
    """The arc of cable wrapped round a pulley, and its colour; None where the wheel is no
    pulley. A pulley hangs in (or turns under) one cable: two strands roll on its circle, each
    tangent to it at its contact T and running away from it to its other points and contacts
    (unit direction d). The cable comes in along the first strand (travelling −d₁ at T₁),
    follows the circle in that sense and leaves along the second (travelling +d₂ at T₂): the
    arc from T₁ to T₂ in the sense of (T₁ − C) × (−d₁). A wheel between two straight bodies
    that the cable's path does not join so (a roller between plates) is no pulley. Drawn with
    strands that stop at their tangent points (`_line_span`), a pulley read as floating beside
    its cable (C5-1.1, C5-1.5; issue 30, twenty-ninth round (d)); a belt, one body round two
    pulleys, draws its own wrap (`belt_loop`)."""
    centre, tol = s.centre(), 1e-6 * max(s.radius, 1e-300)
    ends = []
    for j in scene.joints:
        if j.contact is None or body.name not in (j.a, j.b) or not j.kind.rolls or j.kind.pitch:
            continue
        other = scene.bodies.get(j.b if j.a == body.name else j.a)
        if not strand(scene, other):
            continue
        t = np.asarray(j.contact, dtype=float)
        if abs(float(np.linalg.norm(t - centre)) - s.radius) > 1e-4 * s.radius:
            return None
        away = _away(scene, other, t, tol)
        if away is None:
            return None
        ends.append((t, away, other))
    if len(ends) != 2:
        return None
    (t1, d1, first), (t2, d2, second) = ends
    r1 = t1 - centre
    turn = float(r1[0] * -d1[1] - r1[1] * -d1[0])                # (T₁ − C) × (−d₁)
    if abs(turn) <= tol * s.radius:
        return None
    sense = 1.0 if turn > 0 else -1.0
    leaving = sense * perpendicular(t2 - centre)         # the travel round the circle at T₂
    if float(leaving @ d2) <= 0:
        return None
    a1 = float(np.arctan2(*(t1 - centre)[::-1]))
    a2 = float(np.arctan2(*(t2 - centre)[::-1]))
    sweep = (a2 - a1) % (2 * np.pi) if sense > 0 else -((a1 - a2) % (2 * np.pi))
    ts = a1 + np.linspace(0.0, sweep, 48)
    arc = centre + s.radius * np.column_stack([np.cos(ts), np.sin(ts)])
    moving = [b for b in (first, second) if not (b.frame or b.fixed)]
    return arc, (moving[0].colour if moving else GROUND)


def _away(scene: Any, body: BodyView, t: np.ndarray, tol: float) -> Optional[np.ndarray]:
    """The unit direction along a strand from its contact `t` towards the rest of it (its
    points and its other contacts); None when they lie on both sides, or nowhere."""
    line = next(sh for sh in body.shapes if sh.kind == "line")
    _, direction = line.line()
    u = np.asarray(direction, dtype=float) / float(np.linalg.norm(direction))
    rest = [np.asarray(p, dtype=float) for p in body.points.values()]
    rest += [np.asarray(j.contact, dtype=float) for j in scene.joints
             if j.contact is not None and body.name in (j.a, j.b)]
    along = [float((p - t) @ u) for p in rest if float(np.linalg.norm(p - t)) > tol]
    if not along or (min(along) < -tol and max(along) > tol):
        return None
    return u if max(along) > tol else -u


def belt_loop(ctx: Context, body: BodyView, s: ShapeView) -> Optional[np.ndarray]:
    """A belt or chain: a line body rolling on two circles that lie on one side of it is the
    straight run of a loop wrapped round both (an open belt). The loop as a closed polyline:
    this run from contact to contact, the far side of the second circle, the other run (the
    first's mirror in the line of centres) and the far side of the first; None otherwise."""
    touching = []
    for j in ctx.scene.joints:
        contact = j.contact
        if contact is None or body.name not in (j.a, j.b):
            continue
        other = ctx.scene.bodies.get(j.b if j.a == body.name else j.a)
        circles = [c for c in (other.shapes if other else []) if c.kind == "circle"]
        if not circles:
            return None
        circle = min(circles, key=lambda c: abs(np.linalg.norm(contact - c.centre()) - c.radius))
        touching.append((np.asarray(contact, float), circle))
    if len(touching) != 2:
        return None
    (t1, c1), (t2, c2) = touching
    through, direction = s.line()
    n = perpendicular(direction)
    if float((c1.centre() - through) @ n) * float((c2.centre() - through) @ n) <= 0:
        return None                     # circles on both sides: a crossed strand, drawn straight
    axis = c2.centre() - c1.centre()
    if np.linalg.norm(axis) <= 1e-9 * ctx.size:
        return None
    u = axis / np.linalg.norm(axis)

    def mirror(p: np.ndarray) -> np.ndarray:
        r = p - c1.centre()
        return c1.centre() + 2 * (r @ u) * u - r
    m1, m2 = mirror(t1), mirror(t2)
    return np.vstack([[t1], [t2], _far_arc(c2, t2, m2, u), [m2], [m1], _far_arc(c1, m1, t1, -u), [t1]])


def _far_arc(c: ShapeView, start: np.ndarray, end: np.ndarray, away: np.ndarray) -> np.ndarray:
    """Points of the circle from `start` to `end` the long way round the side facing `away`."""
    centre = c.centre()
    a0 = np.arctan2(*(start - centre)[::-1])
    a1 = np.arctan2(*(end - centre)[::-1])
    mid = np.arctan2(away[1], away[0])
    sweep = (a1 - a0) % (2 * np.pi)
    if not _within(a0, sweep, mid):
        sweep -= 2 * np.pi
    ts = a0 + np.linspace(0, sweep, 48)
    return centre + c.radius * np.column_stack([np.cos(ts), np.sin(ts)])


def _within(a0: float, sweep: float, angle: float) -> bool:
    """Whether `angle` lies on the counter-clockwise arc of `sweep` from a0."""
    return (angle - a0) % (2 * np.pi) <= sweep


def _line_span(ctx: Context, body: BodyView, s: ShapeView) -> Optional[tuple[np.ndarray, np.ndarray]]:
    """The part of a moving body's line worth drawing (a chain's run, a rack): over its
    points and the contacts on it, a little beyond a point, inside the reach — but never
    beyond a contact at its end: a strand or a straight run leaves its pulley at the tangent
    point, so it is drawn from there, not through it (C5-1.1's strands ran past J and K); nor
    beyond a point at its end, where a cable is tied (C5-1.1's strands ran past G1 and G2,
    above the ceiling; issue 30, sixteenth round (f)) — unless the line guides another body,
    which needs the room to slide on, or its points and contacts are one place."""
    through, direction = s.line()
    pts = list(body.points.values())
    contacts = [j.contact for j in ctx.scene.joints if body.name in (j.a, j.b) and j.contact is not None]
    if not pts and not contacts:
        return clip_line(through, direction, ctx.reach)
    at_points = [float((p - through) @ direction) for p in pts]
    at_contacts = [float((p - through) @ direction) for p in contacts]
    margin, tol = 0.1 * ctx.size, 1e-9 * ctx.size
    lo, hi = min(at_points + at_contacts), max(at_points + at_contacts)
    guides = any(j.a == body.name and (j.kind.slides or j.kind.guides_point) for j in ctx.scene.joints)
    if not guides and hi - lo > tol:           # a strand ends at its points and contacts
        margin = 0.0
    lo_contact = any(t <= lo + tol for t in at_contacts)          # a contact at the end (C5-1.5's T1 too)
    hi_contact = any(t >= hi - tol for t in at_contacts)
    return clip_segment(through + (lo - (0.0 if lo_contact else margin)) * direction,
                        through + (hi + (0.0 if hi_contact else margin)) * direction, ctx.reach)


def _ring_gear(ctx: Context, body: BodyView, s: ShapeView) -> None:
    """A ring (another circle rolls inside it): a band outside its circle, with ticks so
    that its turning shows."""
    band, centre = ring_band(ctx, s), s.centre()
    name = body.name
    ctx.add("ring", [centre], r=s.radius + band, band=band, colour="none", fill=body.colour,
            alpha=0.45, width=0, zorder=DISC_FILL, moves_with=name)
    ctx.add("circle", [centre], r=s.radius, colour=body.colour, width=2.2, dash=s.role == "gear",
            zorder=3, gid=f"shape:{name}", moves_with=name)
    for t in np.linspace(0, 2 * np.pi, 12, endpoint=False):
        d = np.array([np.cos(t), np.sin(t)])
        ctx.add("line", [centre + s.radius * d, centre + (s.radius + band) * d], width=1.0,
                colour=body.colour, zorder=2, moves_with=name)
    ctx.avoid(*_ring(centre, s.radius))
    ctx.avoid(*_ring(centre, s.radius + band))
    ctx.area(*_ring(centre, s.radius + band), *_ring(centre, s.radius)[::-1])


UP_LEFT = np.array([-0.7071, 0.7071])


def ring_band(ctx: Context, s: ShapeView) -> float:
    """The width of the band drawn outside a ring's circle (`_ring_gear`): the frame's hatch
    band and a half, at most 0.3 of the radius; 0 for a wheel."""
    return min(HATCH_BAND * 1.5 * ctx.size, 0.3 * s.radius) if s.ring else 0.0


def shape_anchor(s: ShapeView, band: float = 0.0) -> np.ndarray:
    """Where a circle-shaped body's name goes, up-left: inside a wheel (0.6 of its radius), and
    for a ring on the outer edge of its band (`band` beyond its circle), its label pushed outwards
    (`_body`'s `prefer`). A ring holds other wheels: a label anchored on its circle, between the
    band's two edges the placer keeps clear of, is pushed inwards onto a wheel it holds (C5-1.4's
    corona read inside satellite 3); outside the band nothing else is drawn."""
    return s.centre() + (s.radius + band if s.ring else 0.6 * s.radius) * UP_LEFT


BAR_SPOTS = (0.2, 0.35, 0.65, 0.8)     # where along its bar a bar's name may also be led from


def bar_spots(line: Any) -> np.ndarray:
    """The other points a bar's name may be led from (`draw.labels`' `Label.spots`): at the
    fractions `BAR_SPOTS` of the polyline's length, so that a bar lying inside another
    body's disc is named beside its stretch nearest the disc's edge (C5-E.1's arm OC from
    O, at the wheels' rim, not from its middle, inside them; issue 30, twenty-seventh round
    (c))."""
    line = np.asarray(line, dtype=float)
    steps = np.linalg.norm(np.diff(line, axis=0), axis=1)
    at = np.concatenate([[0.0], np.cumsum(steps)])
    return np.column_stack([np.interp(np.array(BAR_SPOTS) * at[-1], at, line[:, k]) for k in (0, 1)])


def shape_spots(s: ShapeView, band: float = 0.0, inside: bool = True) -> Optional[np.ndarray]:
    """The other points a circle-shaped body's name may be led from (`draw.labels`'
    `Label.spots`): as `shape_anchor`'s, in the eight directions round the circle, so that
    what is drawn on one side of a wheel (an arrow, a bar, a belt) does not hem its name in.
    None for a part of a disc (its name goes towards its arc)."""
    if s.arc is not None:
        return None
    t = np.arange(8) * np.pi / 4
    reach = s.radius + band if s.ring or not inside else 0.6 * s.radius
    return s.centre() + reach * np.column_stack([np.cos(t), np.sin(t)])


def _fixed_body(ctx: Context, body: BodyView) -> None:
    """A body welded to the frame is ground (C5-1.2's inclined planes): its lines are drawn
    as the pieces of ground they are — hatched segments over the points they hold and the
    contacts on them (`_fixed_span`), never whole lines crossing the figure — its other
    shapes as the frame's, its bars grey, its name beside it in the ground's grey."""
    anchor, side = None, None
    for s in body.shapes:
        if s.kind != "line":
            _ground_shape(ctx, s)
            continue
        if cable_strand(ctx.scene, body):
            anchor, side = _tied_strand(ctx, body, s)
            continue
        seg = _fixed_span(ctx, body, s)
        if seg is None:
            continue
        through, direction = s.line()
        n = perpendicular(direction)
        towards = s.hatch_towards if s.hatch_towards is not None else through - ctx.centroid()
        side = n if float(n @ towards) >= 0 else -n
        hatched_edge(ctx, *seg, side, f"ground:{body.name}")
        anchor = (seg[0] + seg[1]) / 2
    _skeleton(ctx, body, GROUND, 3.0)
    if anchor is not None:
        name = plain(noun(body.label or body.name)) + _tag(ctx, body)
        ctx.label(anchor, name, GROUND, 5, f"body:{body.name}", side=side, group=f"body:{body.name}",
                  style="italic")


def cable_strand(scene: Any, body: BodyView) -> bool:
    """Whether a fixed line body is a strand of a cable, not a piece of ground: it touches a
    wheel that a moving strand (a straight body: a line, no circle) also touches — the one
    cable wrapped round that pulley, in by one strand and out by the other (C5-1.5's strand 1,
    tied to the ceiling, beside strand 2 on pulley 1). A wheel that rolls on fixed lines
    alone (C5-1.2's inclined planes) rolls on the ground."""
    for j in scene.joints:
        if j.contact is None or body.name not in (j.a, j.b):
            continue
        wheel = j.b if j.a == body.name else j.a
        for k in scene.joints:
            other = scene.bodies.get(k.b if k.a == wheel else k.a)
            if k is j or k.contact is None or wheel not in (k.a, k.b) or other is None:
                continue
            if not (other.frame or other.fixed) and any(sh.kind == "line" for sh in other.shapes) \
                    and not any(sh.kind == "circle" for sh in other.shapes):
                return True
    return False


def _tied_strand(ctx: Context, body: BodyView, s: ShapeView) -> tuple[Optional[np.ndarray], Optional[np.ndarray]]:
    """A fixed strand (`cable_strand`) drawn as what it is: a cable in the ground's grey, from
    its points to the pulley it leaves (`_line_span`), tied at each of its points that ends it
    to a short hatched edge across it, hatched beyond the point — the ceiling it hangs from.
    Drawn hatched along its length, as a fixed line is, it read as a wall, and its point G,
    where the notes tie it to the ceiling, as floating (C5-1.5; issue 30, twenty-seventh round
    (f)). Its name's anchor and side, as a bar's."""
    seg = _line_span(ctx, body, s)
    if seg is None:
        return None, None
    p, q = (np.asarray(x, dtype=float) for x in seg)
    ctx.add("line", [p, q], width=2.2, colour=GROUND, zorder=2, gid=f"shape:{body.name}")
    ctx.avoid(p, q)
    half = TIE * ctx.size
    for end, other in ((p, q), (q, p)):
        if not any(np.linalg.norm(end - np.asarray(x, dtype=float)) <= 1e-6 * ctx.size for x in body.points.values()):
            continue
        out = (end - other) / max(float(np.linalg.norm(end - other)), 1e-300)
        across = perpendicular(out)
        hatched_edge(ctx, end - half * across, end + half * across, out, f"ground:tie:{body.name}")
    return (p + q) / 2, _beside(ctx, p, q)


def _fixed_span(ctx: Context, body: BodyView, s: ShapeView) -> Optional[tuple[np.ndarray, np.ndarray]]:
    """The piece of a fixed line worth drawing (`fixed_ends`), inside the reach."""
    through, direction = s.line()
    ends = fixed_ends(ctx.scene, body, s)
    if ends is None:
        return clip_line(through, direction, ctx.reach)
    return clip_segment(*ends, ctx.reach)


def fixed_ends(scene: Any, body: BodyView, s: ShapeView) -> Optional[tuple[np.ndarray, np.ndarray]]:
    """The ends of the piece of a fixed line worth drawing: from the body's own points on it
    (where the piece ends, a plane's corner) to a wheel's radius beyond each contact on it (a
    tenth of the figure when what touches it is no circle); None for the whole line."""
    through, direction = s.line()
    n = perpendicular(direction)
    own = [float((p - through) @ direction) for p in body.points.values()
           if abs(float((p - through) @ n)) <= 1e-6 * scene.size]
    ts = list(own)
    for j in scene.joints:
        if body.name not in (j.a, j.b) or j.contact is None:
            continue
        other = scene.bodies.get(j.b if j.a == body.name else j.a)
        reach = min((c.radius for c in (other.shapes if other else []) if c.kind == "circle"),
                    default=0.1 * scene.size)
        t = float((j.contact - through) @ direction)
        below, above = not own or t <= min(own), not own or t >= max(own)
        ts += [t] + ([t - reach] if below else []) + ([t + reach] if above else [])
    if len(ts) < 2:
        return None
    return through + min(ts) * direction, through + max(ts) * direction


def _fixed_circle_name(ctx: Context, body: BodyView) -> None:
    """A fixed body drawn as a circle of its own (C5-E.2's fixed central wheel, C5-1.8's
    cylinder, a drum) is named beside it as a moving wheel is, in the ground's grey: the text
    names it as a body ("la roda central fixa"), and its hatched circle alone reads as any
    piece of ground (issue 30, fourteenth round (b)). The frame's line, pivots and guides
    are its standard symbols and need no words; a welded line is named by `_fixed_body`."""
    circles = [s for s in body.shapes if s.kind == "circle"]
    if not circles:
        return
    s = max(circles, key=lambda c: c.radius)
    inside = s.material_inside
    band = 0.0 if inside else min(HATCH_BAND * ctx.size, s.radius)
    towards = UP_LEFT
    if s.arc is not None:                    # a part of a disc: towards its arc's middle
        mid = 0.5 * (s.arc[0] + s.arc[1])
        towards = np.array([np.cos(mid), np.sin(mid)]) + 0.5 * UP_LEFT
        towards = towards / np.linalg.norm(towards)
    anchor = s.centre() + (0.6 * s.radius if inside else s.radius + band) * towards
    name = plain(noun(body.label or body.name)) + _tag(ctx, body)
    ctx.label(anchor, name, GROUND, 5, f"body:{body.name}", group=f"body:{body.name}", style="italic",
              prefer=None if inside else UP_LEFT, spots=shape_spots(s, band, inside))


def _ground_shape(ctx: Context, s: ShapeView) -> None:
    band = HATCH_BAND * ctx.size
    if s.kind == "line":
        through, direction = s.line()
        seg = clip_line(through, direction, ctx.reach.grow(-band))
        if seg is None:
            return
        n = perpendicular(direction)
        towards = s.hatch_towards if s.hatch_towards is not None else \
            through - ctx.centroid()
        hatched_edge(ctx, *seg, n if float(n @ towards) >= 0 else -n, "ground:line")
    elif s.kind == "circle" and s.arc is not None:
        _ground_arc(ctx, s, band)
    elif s.kind == "circle":
        centre = s.centre()
        outer = s.radius if s.material_inside else s.radius + min(band, s.radius)
        width = min(band, 0.5 * s.radius)
        ctx.add("circle", [centre], r=s.radius, colour=GROUND, width=1.8, zorder=2,
                gid="ground:circle")
        ctx.add("ring", [centre], r=outer, band=width, colour=GROUND, width=0, hatch=True,
                zorder=1)
        ctx.avoid(*_ring(centre, s.radius))
        ctx.area(*(_ring(centre, s.radius) if s.material_inside else
                   np.vstack([_ring(centre, outer), _ring(centre, s.radius)[::-1]])))
    elif s.kind == "curve":
        vertices = s.polyline()
        ctx.add("line", vertices, width=1.8, colour=GROUND, zorder=2, gid="ground:curve")
        ctx.avoid(*vertices[::8])
    elif s.vertices is not None:
        ctx.add("polygon", s.vertices, fill="#f0f0f0", colour="#9e9e9e", width=1.0, zorder=0,
                gid="ground:plane")


def _ground_arc(ctx: Context, s: ShapeView, band: float) -> None:
    """A fixed part of a disc (a semicylinder, `arc` [0, 180]): its arc and flat side drawn in
    the ground's grey, the arc hatched along its material's side (inside a drum, outside a
    cavity) and the flat side hatched beyond it, the ground it rests on (issue 30,
    twenty-fourth round (h): C5-1.7's semicylinder read as a whole cylinder)."""
    centre, outline = s.centre(), s.outline()
    arc = outline[:-1]
    width = min(band, 0.5 * s.radius)
    inner = centre + (arc - centre) * ((s.radius - width if s.material_inside else s.radius + width) / s.radius)
    ctx.add("line", arc, width=1.8, colour=GROUND, zorder=2, gid="ground:circle")
    ctx.add("polygon", np.vstack([arc, inner[::-1]]), colour=GROUND, width=0, hatch=True, zorder=1)
    chord = arc[-1] - arc[0]
    side = perpendicular(chord / np.linalg.norm(chord))
    mid = float(np.mean(s.arc or (0.0, 0.0)))
    if float(side @ np.array([np.cos(mid), np.sin(mid)])) > 0:
        side = -side                         # away from the arc: the ground under the flat side
    hatched_edge(ctx, arc[-1], arc[0], side, "ground:circle")
    ctx.avoid(*outline)
    ctx.area(*(outline if s.material_inside else np.vstack([arc, inner[::-1]])))


def _across(edge: np.ndarray) -> bool | str:
    """The hatching of a fixed edge: the frame's lines rising to the right (True), or falling
    to the right when the edge itself rises within 25° of 45° (C5-1.2's right plane) — hatching
    along the edge would read as a double line, not as ground."""
    angle = float(np.degrees(np.arctan2(edge[1], edge[0]))) % 180.0
    return FALLING if abs(angle - 45.0) < 25.0 else True


def hatched_edge(ctx: Context, p: np.ndarray, q: np.ndarray, side: np.ndarray, gid: str) -> None:
    """A fixed edge from p to q, hatched on `side` (where the frame's material is). The
    material beyond it, `MATERIAL` of the drawing deep, is the fixed body's area: another
    body's name or a vector's value is not set in the ground, under its hatching, where it
    reads as no part of the mechanism and hangs on a long leader (C5-1.3's v_ar,E under the
    ground, far from its short arrow; C5-E.6's sprocket and chainring named under the ground;
    issue 30, twenty-seventh round (f))."""
    band = HATCH_BAND * ctx.size
    ctx.add("line", [p, q], width=1.8, colour=GROUND, zorder=2, gid=gid)
    ctx.add("polygon", [p, q, q + band * side, p + band * side], colour=GROUND, width=0,
            hatch=_across(q - p), zorder=1)
    ctx.avoid(p, q)
    ctx.avoid(p + 0.5 * band * side, q + 0.5 * band * side, weight=0.7)
    ctx.avoid(p + band * side, q + band * side, weight=0.7)
    deep = MATERIAL * ctx.size
    ctx.area(p, q, q + deep * side, p + deep * side, ground=True)


def _points(ctx: Context) -> None:
    """A dot at every point, and its name once (points shared by bodies are one place): the
    first dot of each name is the point's (`point:NAME`, what the page drags)."""
    named: set[str] = set()
    for body in ctx.scene.bodies.values():
        for name, p in body.points.items():
            if name in body.passing:
                continue
            mover = None if body.frame else body.name
            first = name not in named
            ctx.add("dot", [p], colour=INK, fill=INK, width=1.0, size=3.2, zorder=4,
                    moves_with=mover, group=f"point:{name}" if first else "")
            ctx.avoid(p, weight=2.0, radius=2.0)
            if first:
                named.add(name)
                ctx.label(p, plain(name), POINT_LABEL, 3, f"point:{name}", body=mover,
                          group=f"point:{name}", weight="bold", radius=2.0)


def _contact_names(ctx: Context) -> None:
    """The letter of each contact point the text names (`JointView.contact_name`, from
    `DrawOptions.contacts`), set by its dot as a point's name is: a page that says "the
    contact J" shows J where the wheel touches (issue 30, thirteenth round). A contact that
    is a model's point is already labelled by `_points`; one the text never names has no
    letter (a still figure only: the dot is no body's point). A contact where a model's
    point is labelled already is not labelled again; the contact's mark (`draw.marks`, a
    `contact` question's answer) leaves its letter to this one, the page's: 001's "F  F" and
    C5-1.8's "J  J" (issue 30, fourteenth round (b))."""
    if not ctx.still:
        return
    named = {n for body in ctx.scene.bodies.values() for n in body.points}
    done: set[str] = set()
    for j in ctx.scene.joints:
        name = j.contact_name
        if not name or j.contact is None or name in named or name in done:
            continue
        done.add(name)
        p = np.asarray(j.contact, dtype=float)
        if labelled_at(ctx, p):
            continue
        ctx.avoid(p, weight=2.0, radius=2.0)
        ctx.label(p, plain(name), POINT_LABEL, 3, f"contact:{name}", weight="bold", radius=2.0)


def labelled_at(ctx: Context, p: np.ndarray, contacts: bool = False) -> bool:
    """Whether a label already stands for the place `p`: a body's point there (and with
    `contacts`, a contact the page names, labelled by `_contact_names`): one place, one
    letter on a figure."""
    tol = 1e-6 * ctx.size
    pts = [q for body in ctx.scene.bodies.values() for n, q in body.points.items() if n not in body.passing]
    if contacts and ctx.still:
        pts += [j.contact for j in ctx.scene.joints if j.contact_name and j.contact is not None]
    return any(float(np.linalg.norm(np.asarray(q, dtype=float) - p)) <= tol for q in pts)


def _distinct(pts: list, tol: float) -> list:
    out: list = []
    for p in pts:
        if all(np.linalg.norm(p - q) > tol for q in out):
            out.append(p)
    return out


def _extremes(pts: list) -> list:
    """The two points farthest apart (the ends of a collinear body)."""
    best = max(((p, q) for i, p in enumerate(pts) for q in pts[i + 1:]),
               key=lambda pq: np.linalg.norm(pq[0] - pq[1]))
    return list(best)


def _area(poly: np.ndarray) -> float:
    x, y = poly[:, 0], poly[:, 1]
    return 0.5 * abs(float(x @ np.roll(y, 1) - y @ np.roll(x, 1)))


def _ring(centre: np.ndarray, radius: float, n: int = 36) -> np.ndarray:
    t = np.linspace(0, 2 * np.pi, n + 1)
    return centre + radius * np.column_stack([np.cos(t), np.sin(t)])
