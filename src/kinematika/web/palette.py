"""The page's palette: every kind of element a student places by hand, in one list.

Each `Tool` says what the student clicks (`picks`: a place on the grid or an existing point
`place`, an existing point `point`, an existing body `body`), the small picture on its
button, and the function that writes the element into the model's tree — by construction,
as a problem states it (a link's far end `{from: A, distance: 0.15, angle: deg(30)}`, a
loop closed by two circles, a slider's pin on its guide by a circle and a line). The page
receives this list (`GET /api/palette`) and builds its buttons from it; the words on them
are the catalogues' `tool-KIND` and `tool-KIND-hint`. A new kind of joint or body (a cam,
a curved slot) appears in the palette by one entry here and its two catalogue lines.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Callable, Optional

import numpy as np

from ..errors import KinematikaError
from ..joints.contact import KIND as CONTACT_KIND
from ..joints.curved_slot import KIND as CURVED_SLOT_KIND
from ..joints.gear import KIND as GEAR_KIND
from ..joints.prismatic import KIND as PRISMATIC_KIND
from ..joints.revolute import KIND as REVOLUTE_KIND
from ..joints.rolling import KIND as ROLLING_KIND
from ..joints.slot import KIND as SLOT_KIND
from .tree import Tree, degrees, number

# the joint kinds the tools place, as their modules name them (`kinematika.joints`)
REVOLUTE, PRISMATIC, SLOT, ROLLING = REVOLUTE_KIND.name, PRISMATIC_KIND.name, SLOT_KIND.name, ROLLING_KIND.name
GEAR, CURVED_SLOT, CONTACT = GEAR_KIND.name, CURVED_SLOT_KIND.name, CONTACT_KIND.name

Pick = Any          # a point's name, coordinates [x, y], or {"body": NAME}


@dataclass
class Context:
    """What a writer needs besides the tree: the points' places now, the default names of
    new bodies in the student's language, and the values typed with the tool."""

    tree: Tree
    at: dict[str, np.ndarray]
    names: dict[str, str]
    values: dict[str, Any]

    def place(self, pick: Pick) -> np.ndarray:
        """Where a pick is: a named point's place now, or the coordinates clicked."""
        if isinstance(pick, str):
            if pick not in self.at:
                raise KinematikaError("usage", "pick-no-point", "picks", point=pick)
            return self.at[pick]
        return np.array(pick, dtype=float)

    @property
    def scale(self) -> float:
        """The drawing's size (the largest distance of a point from the first), for rounding."""
        pts = list(self.at.values())
        return max((float(np.linalg.norm(p - pts[0])) for p in pts), default=0.0) or 1.0

    def tidy(self, x: float) -> float | int:
        """A coordinate rounded to a hundred-thousandth of the drawing (no 1e-8 of round-off)."""
        step = 10.0 ** (math.floor(math.log10(self.scale)) - 5)
        return number(round(x / step) * step)

    def body(self, kind: str) -> str:
        """A new body's name: the kind's name in the student's language, numbered (crank1)."""
        return self.tree.fresh_body(self.names.get(kind, kind))


@dataclass(frozen=True)
class Tool:
    """A palette entry: its kind, what is clicked, its picture (SVG path data in a 24 × 24
    box) and the writer, which returns the element to select afterwards."""

    kind: str
    picks: tuple[str, ...]
    icon: str
    write: Callable[[Context, list[Pick]], str]

    def public(self) -> dict[str, Any]:
        """The entry as the page receives it (`GET /api/palette`): kind, picks, icon."""
        return {"kind": self.kind, "picks": list(self.picks), "icon": self.icon}


# the writers ---------------------------------------------------------------------------------
def _new_point(ctx: Context, pick: Pick, pivot: bool = False) -> str:
    """The point picked: its name, or a new point with the coordinates picked (a ground
    pivot when `pivot`)."""
    if isinstance(pick, str):
        return pick
    t = ctx.tree
    name = t.fresh_point(pivot)
    xy = ctx.place(pick)
    t.points()[name] = t.list([number(xy[0]), number(xy[1])])
    ctx.at[name] = xy
    if pivot:
        t.add_to_body(t.frame, name)
    return name


def pivot(ctx: Context, picks: list[Pick]) -> str:
    """A ground pivot: a new point on the ground, or an existing point pinned to it."""
    t, p = ctx.tree, picks[0]
    if not isinstance(p, str):
        return f"point:{_new_point(ctx, p, pivot=True)}"
    owner = t.owner(p)
    t.add_to_body(t.frame, p)
    if owner and owner != t.frame:
        t.add_joint({"type": REVOLUTE, "bodies": t.list([t.frame, owner]), "at": p})
    return f"point:{p}"


def link(ctx: Context, picks: list[Pick]) -> str:
    """A binary link from the first pick to the second: a new far end is placed from the
    first by its length and angle; an existing one closes a loop (see `_close`)."""
    t = ctx.tree
    start = _new_point(ctx, picks[0])
    end = picks[1]
    joined = [(p, t.owner(p)) for p in (start, end) if isinstance(p, str)]
    body = ctx.body("link")
    if isinstance(end, str):
        if end == start:
            raise KinematikaError("usage", "link-two-points", "picks")
        _close(ctx, end, start)
    else:
        end = _polar(ctx, start, ctx.place(end))
    t.bodies()[body] = t.list([start, end])
    for p, owner in joined:
        if owner:
            t.add_joint({"type": REVOLUTE, "bodies": t.list([owner, body]), "at": p})
    return f"body:{body}"


def _polar(ctx: Context, origin: str, to: np.ndarray) -> str:
    """A new point at `to`, written as its distance and angle from `origin`."""
    t = ctx.tree
    d = to - ctx.at[origin]
    if math.hypot(*d) == 0:
        raise KinematikaError("usage", "link-length", "picks")
    name = t.fresh_point()
    t.points()[name] = t.map({"from": origin, "distance": number(math.hypot(*d)),
                              "angle": degrees(math.degrees(math.atan2(d[1], d[0])))})
    ctx.at[name] = to
    return name


def _by_distance(t: Any, point: str) -> Any:
    """The spec of `point` when it is placed by its distance from one point (the one
    condition a new link can turn into two); None for a point given by coordinates; a usage
    error when it already has two conditions."""
    spec = t.points()[point]
    if not isinstance(spec, dict):
        return None
    if "from" not in spec or "reference" in spec:
        raise KinematikaError("usage", "point-two-conditions", f"points.{point}", point=point)
    return spec


def _close(ctx: Context, point: str, other: str) -> None:
    """A link from `other` to an existing `point` closes a loop: a point that was placed by
    its distance from one point is now where two circles meet (its old distance, and the
    new link's length), on the side it is drawn; a point given by coordinates stays."""
    t = ctx.tree
    spec = _by_distance(t, point)
    if spec is None:
        return
    centre = str(spec["from"])
    c, p, q = ctx.at[centre], ctx.at[other], ctx.at[point]
    length = number(float(np.linalg.norm(q - p)))
    (ux, uy), (vx, vy) = p - c, q - c
    side = "left" if ux * vy - uy * vx > 0 else "right"
    t.points()[point] = t.map({"circles": [[centre, spec["distance"]], [other, length]],
                               "side": side})


def _guide(ctx: Context, point: str, line: Any, direction: np.ndarray) -> None:
    """`point`, placed by its distance from another point, now also on a line: where the
    circle meets the line, on the side it is drawn."""
    t = ctx.tree
    spec = _by_distance(t, point)
    if spec is None:
        return
    centre = ctx.at[str(spec["from"])]
    q = ctx.at[point]
    foot_t = float((centre - q) @ direction)           # the centre's foot, along the line from q
    side = "ahead" if -foot_t >= 0 else "behind"
    t.points()[point] = t.map({"circle": [str(spec["from"]), spec["distance"]], "line": line,
                               "side": side})


def slider(ctx: Context, picks: list[Pick]) -> str:
    """A slider (a block) carrying the picked point, on a straight guide fixed to the ground
    through it (horizontal unless an `angle` is typed, in degrees); the guide is written
    through its point nearest the origin (`[0, -0.02]`: 20 mm below a pivot at the origin)."""
    t, p = ctx.tree, picks[0]
    if not isinstance(p, str):
        p = _new_point(ctx, p)
    angle = math.radians(float(ctx.values.get("angle", 0)))
    d = np.array([math.cos(angle), math.sin(angle)])
    along = t.list([number(d[0], 12), number(d[1], 12)])
    xy = ctx.at[p] - (ctx.at[p] @ d) * d            # the guide's point nearest the origin
    _guide(ctx, p, t.map({"through": t.list([ctx.tidy(xy[0]), ctx.tidy(xy[1])]),
                          "direction": t.list([number(d[0], 12), number(d[1], 12)])}), d)
    owner = t.owner(p)
    body = ctx.body("slider")
    t.bodies()[body] = t.list([p])
    if owner:
        t.add_joint({"type": REVOLUTE, "bodies": t.list([owner, body]), "at": p})
    t.add_joint({"type": PRISMATIC, "bodies": t.list([t.frame, body]), "along": along})
    return f"body:{body}"


def slot(ctx: Context, picks: list[Pick]) -> str:
    """A pin (the picked point) in a straight slot along the picked body's first two points."""
    t, pin, slotted = ctx.tree, picks[0], picks[1]["body"]
    if not isinstance(pin, str):
        pin = _new_point(ctx, pin)
    ends = t.body_points(slotted)[:2]
    if len(ends) < 2 or pin in ends:
        raise KinematikaError("usage", "slot-own-points", "picks", body=slotted)
    owner = t.owner(pin)
    d = ctx.at[ends[1]] - ctx.at[ends[0]]
    _guide(ctx, pin, t.list(ends), d / np.linalg.norm(d))
    t.add_to_body(slotted, pin)
    t.add_joint({"type": SLOT, "bodies": t.list([slotted, owner or slotted]), "at": pin,
                 "along": t.list(ends)})
    return f"body:{slotted}"


def plate(ctx: Context, picks: list[Pick]) -> str:
    """A point fixed to a body (which becomes a plate): written in the frame of the body's
    first two points, `{frame: [A, B], at: [along, across]}`."""
    t, body = ctx.tree, picks[0]["body"]
    ends = t.body_points(body)[:2]
    if len(ends) < 2:
        raise KinematikaError("usage", "plate-two-points", "picks", body=body)
    p, q = ctx.at[ends[0]], ctx.at[ends[1]]
    u = (q - p) / np.linalg.norm(q - p)
    n = np.array([-u[1], u[0]])
    to = ctx.place(picks[1])
    name = t.fresh_point()
    t.points()[name] = t.map({"frame": t.list(ends),
                              "at": t.list([number(float((to - p) @ u)), number(float((to - p) @ n))])})
    ctx.at[name] = to
    t.add_to_body(body, name)
    return f"body:{body}"


def wheel(ctx: Context, picks: list[Pick]) -> str:
    """A wheel rolling on a straight track of the ground: the first pick is the contact
    point on the track, the second the wheel's centre; the radius is a parameter (R1, ...)
    that places the centre and sizes the circle."""
    t = ctx.tree
    if t.bodies().get(t.frame) is not None and isinstance(t.bodies()[t.frame], dict) \
            and "line" in t.bodies()[t.frame]:
        raise KinematikaError("usage", "track-once", "picks")
    contact = _new_point(ctx, picks[0], pivot=True)
    k = ctx.at[contact]
    c = ctx.place(picks[1])
    radius = float(np.linalg.norm(c - k))
    if radius == 0:
        raise KinematikaError("usage", "wheel-centre", "picks")
    angle = math.degrees(math.atan2(*(c - k)[::-1]))
    tangent = [number(math.cos(math.radians(angle - 90)), 12),
               number(math.sin(math.radians(angle - 90)), 12)]
    r = t.fresh_parameter("R")
    t.set_parameter(r, number(radius))
    centre = t.fresh_point()
    t.points()[centre] = t.map({"from": contact, "distance": r, "angle": degrees(angle)})
    ctx.at[centre] = c
    ground = t.bodies()[t.frame]
    listed = [str(x) for x in (ground.get("points", []) if isinstance(ground, dict) else ground)]
    t.bodies()[t.frame] = t.map({"points": listed,
                                 "line": {"through": contact, "direction": tangent}})
    body = ctx.body("wheel")
    t.bodies()[body] = t.map({"points": [centre, contact], "circle": {"center": centre, "radius": r}})
    t.add_joint({"type": ROLLING, "bodies": t.list([t.frame, body])})
    return f"body:{body}"


def gear(ctx: Context, picks: list[Pick]) -> str:
    """A pair of gears on ground pivots at the two picks, meshing (external): their pitch
    radii are parameters whose sum is the distance between the centres."""
    t = ctx.tree
    first = _new_point(ctx, picks[0], pivot=True)
    a, b = ctx.at[first], ctx.place(picks[1])
    gap = float(np.linalg.norm(b - a))
    if gap == 0:
        raise KinematikaError("usage", "gear-centre", "picks")
    ra, rb = t.fresh_parameter("r"), None
    t.set_parameter(ra, number(gap / 2))
    rb = t.fresh_parameter("r")
    t.set_parameter(rb, number(gap / 2))
    if isinstance(picks[1], str):
        second = picks[1]
        t.add_to_body(t.frame, second)
    else:
        second = t.fresh_point(pivot=True)
        t.points()[second] = t.map({"from": first, "distance": f"{ra} + {rb}",
                                    "angle": degrees(math.degrees(math.atan2(*(b - a)[::-1])))})
        ctx.at[second] = b
        t.add_to_body(t.frame, second)
    bodies = []
    for centre, r in ((first, ra), (second, rb)):
        body = ctx.body("gear")
        t.bodies()[body] = t.map({"points": [centre], "circle": {"center": centre, "radius": r}})
        t.add_joint({"type": REVOLUTE, "bodies": t.list([t.frame, body]), "at": centre})
        bodies.append(body)
    t.add_joint({"type": GEAR, "bodies": t.list(bodies)})
    return f"body:{bodies[0]}"


def curved_slot(ctx: Context, picks: list[Pick]) -> str:
    """A pin (the first pick) in a circular slot of a body (the second pick) whose centre is
    the third pick: the body gets the slot's arc, `circle: {center: C, radius: |CP|}`, with C
    a point it carries, and the joint `curved_slot` at the pin."""
    t, pin, slotted = ctx.tree, picks[0], picks[1]["body"]
    if not isinstance(pin, str):
        pin = _new_point(ctx, pin)
    body = t.bodies().get(slotted)
    if body is None:
        raise KinematikaError("usage", "no-body", "picks", body=slotted)
    if isinstance(body, dict) and any(k in body for k in ("circle", "curve", "cam", "line")):
        raise KinematikaError("usage", "slot-outline-once", "picks", body=slotted)
    owner = t.owner(pin)
    if owner is None or owner == slotted:
        raise KinematikaError("usage", "pin-other-body", "picks", pin=pin, body=slotted)
    centre = picks[2]
    if not isinstance(centre, str):
        centre = t.fresh_point()
        xy = ctx.place(picks[2])
        t.points()[centre] = t.list([ctx.tidy(xy[0]), ctx.tidy(xy[1])])
        ctx.at[centre] = xy
    radius = float(np.linalg.norm(ctx.at[pin] - ctx.at[centre]))
    if radius == 0:
        raise KinematikaError("usage", "slot-centre-pin", "picks")
    listed = t.body_points(slotted)
    t.bodies()[slotted] = t.map({"points": listed + ([centre] if centre not in listed else []),
                                 "circle": {"center": centre, "radius": number(radius)}})
    t.add_joint({"type": CURVED_SLOT, "bodies": t.list([slotted, owner]), "at": pin})
    return f"body:{slotted}"


def contact(ctx: Context, picks: list[Pick]) -> str:
    """Two bodies whose outlines (a circle, a line, a curve, a cam) touch and slide on each
    other: the joint `contact` (a cam and its follower; a disc on a flat face)."""
    t = ctx.tree
    a, b = picks[0]["body"], picks[1]["body"]
    if a == b:
        raise KinematikaError("usage", "contact-two-bodies", "picks")
    for name in (a, b):
        body = t.bodies().get(name)
        if not (isinstance(body, dict) and any(k in body for k in ("circle", "line", "curve", "cam"))):
            raise KinematikaError("usage", "contact-no-outline", "picks", body=name)
    t.add_joint({"type": CONTACT, "bodies": t.list([a, b])})
    return f"body:{a}"


# the palette -----------------------------------------------------------------------------------
TOOLS: tuple[Tool, ...] = (
    Tool("pivot", ("place",), "M12 8a3 3 0 1 0 .01 0M12 11 6 19h12ZM4 21h16", pivot),
    Tool("link", ("place", "place"), "M5 18 19 6M5 18a2 2 0 1 0 .01 0M19 6a2 2 0 1 0 .01 0", link),
    Tool("plate", ("body", "place"), "M4 18 12 5l8 13Z", plate),
    Tool("slider", ("point",), "M7 9h10v6H7ZM2 17h20", slider),
    Tool(SLOT, ("point", "body"), "M5 9h14a3 3 0 0 1 0 6H5a3 3 0 0 1 0-6M12 12a1.5 1.5 0 1 0 .01 0",
         slot),
    Tool("wheel", ("place", "place"), "M12 11a7 7 0 1 0 .01 0M12 4v14M2 21h20", wheel),
    Tool(GEAR, ("place", "place"), "M8 12a5 5 0 1 0 .01 0M18 12a4 4 0 1 0 .01 0", gear),
    Tool(CURVED_SLOT, ("point", "body", "place"), "M4 17a9 9 0 0 1 16 0M12 8a1.5 1.5 0 1 0 .01 0",
         curved_slot),
    Tool(CONTACT, ("body", "body"), "M12 4a6 6 0 1 0 .01 0M3 20h18M12 16v4", contact),
)
BY_KIND = {t.kind: t for t in TOOLS}


def tool(kind: str) -> Tool:
    """The palette's tool of a kind; an unknown kind is a `usage` error naming the known ones."""
    found: Optional[Tool] = BY_KIND.get(kind)
    if found is None:
        raise KinematikaError("usage", "tool-unknown", "kind", tool=kind, tools=list(BY_KIND))
    return found
