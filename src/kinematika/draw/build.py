"""The scene of a solved instant built (`build_scene`): the bodies with their points and
shapes, the joints and their skeletons, read from the instant (never solving), and, given
a `Solution`, the results asked for (`results.add_results`). The scene itself, what a
figure shows, is `scene.Scene`.
"""
from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

from ..engine.instant import Instant
from ..shapes import Cam, Circle, Curve, Disc, Line, Plane
from ..errors import KinematikaError
from .options import DrawOptions
from .projection import Projection, projection
from .names import body_labels, body_numbers, listed, names_bodies, numbered, value_text, welded_to_frame
from .results import add_results
from .scene import BodyView, JointView, Numbers, Scene, ShapeView, Vec, drawing_values, numbering_note
from .skeleton import add_skeletons
from .words import word
from .style import body_colour


def build_scene(inst: Instant, sol: Any = None, options: DrawOptions | None = None,
                solver: Any = None, proj: Optional[Projection] = None) -> Scene:
    """The scene of an evaluated instant; with a `Solution`, also the results to show.
    `proj`: another map to the page than the options' view (the page's 3D twin, whose first coordinate is the depth)."""
    options = options or DrawOptions()
    model = inst.model
    proj = proj or projection(model.dimension, options.view, model.up)
    num = Numbers(inst, proj, drawing_values(inst))
    bodies = _bodies(inst, num, options.lang)
    box, size = _extent(bodies, inst)
    geos = _joint_geometries(inst, sol or solver)
    _mark_ground_sides(bodies, model, geos, num)
    _mark_gears(bodies, model, geos, num)
    _mark_other_planes(bodies)
    joints = [_joint(j, geos.get(j.id), num) for j in model.joints]
    for view in joints:
        view.contact_name = (options.contacts or {}).get(view.id, "")
    scene = Scene(model.wording.title(options.lang, model.name) if options.lang else model.name,
                  model.dimension, proj, bodies, joints, size, box)
    add_skeletons(scene, inst, num, geos)
    _grow_box(scene)
    if num.values:
        scene.notes.append(_values_note(num.values, model.draw_at, options.lang))
    if sol is not None:
        add_results(scene, sol, options, num)
    _number_bodies(scene, options.bare, options.lang)
    return scene


def _number_bodies(scene: Scene, always: bool = False, lang: Optional[str] = None) -> None:
    """When a label names a body by its number, the bodies are numbered on the figure and
    the numbering is listed under it; `always` for a figure set in a text that names the
    bodies by number (an explanation's ω_3, I_13)."""
    labels = [v.label for v in scene.vectors] + [m.label for m in scene.marks] + \
        [c.label for c in scene.curvatures]
    if not always and not any(numbered(text) for text in labels):
        return
    scene.numbered = True
    scene.notes.insert(0, numbering_note(scene, lang))


def _values_note(values: dict, given: dict, lang: Optional[str] = None) -> str:
    """Which numbers the figure shows: the model's draw_at, or generic ones."""
    text = listed([f"{s} = {value_text(v, lang)}" for s, v in sorted(values.items(), key=str)], lang)
    if all(str(s) in given for s in values):
        return word("note-drawn-at-given", lang, values=text)
    if any(str(s) in given for s in values):
        return word("note-drawn-at-some", lang, values=text)
    return word("note-drawn-at-generic", lang, values=text)


def _bodies(inst: Instant, num: Numbers, lang: Optional[str] = None) -> dict[str, BodyView]:
    model = inst.model
    out = {}
    # the figures' tags: the bodies' names' subscripts where the text writes ω_biela, I_biela,
    # else their numbers (3)
    named = names_bodies(model, lang)
    labels = body_labels(model, lang, named=named)
    for name, number in body_numbers(model).items():
        body = model.bodies[name]
        frame = name == model.frame
        points = {p: num.page(inst.points[p]) for p in body.points}
        shapes = [view for s in inst.shapes.get(name, []) for view in _shapes(s, num)]
        read_off = named and model.wording.index(name, lang) is None and labels[name] != str(number)
        out[name] = BodyView(name, number, "#424242" if frame else body_colour(number), frame,
                             points, shapes, label=model.wording.body(name, lang), index=labels[name],
                             read_off=read_off)
    for name in welded_to_frame(model):
        out[name].fixed = True
    for j in model.joints:
        for name in _passing(model, j):
            out[j.a].passing.append(name)
    return {name: out[name] for name in model.bodies}


def _passing(model: Any, j: Any) -> list[str]:
    """The points of a slot's or a guide's body (`j.a`) that are the other body's points
    sliding along it (the quick-return's A on the rocker): at this instant a material point
    of the guide there, but not the pin, which an animation would leave behind."""
    shared = [p for p in model.bodies[j.b].points if p in model.bodies[j.a].points]
    if j.kind.slides and j.kind.guides_point:              # a pin in a slot: the pin's point
        return [p for p in shared if p == j.at]
    if j.kind.slides:                                      # a guide: every shared point
        return shared
    return []


def _shapes(s: Any, num: Numbers) -> list[ShapeView]:
    """A shape's views: one, or a cam's profile and its pitch curve (a roller's centre's path)."""
    if isinstance(s, Cam):
        out = [_curve(s.profile, num, "profile")]
        if s.design.follower.contact.radius > 0:
            out.append(_curve(s.pitch, num, "pitch"))
        return out
    if isinstance(s, Curve):
        return [_curve(s, num, "curve")]
    return [_shape(s, num)]


def _curve(c: Curve, num: Numbers, role: str) -> ShapeView:
    """A curve as a polyline of points (closed or not) on the page."""
    closed = bool(getattr(c.curve, "closed", False))
    pts = c.points(361 if closed else 200)
    return ShapeView("curve", vertices=np.array([num.page(tuple(p)) for p in pts]), role=role, closed=closed)


def _shape(s: Any, num: Numbers) -> ShapeView:
    if isinstance(s, Circle):
        return ShapeView("circle", center=num.page(s.center), radius=num.scalar(s.radius),
                         arc=_page_arc(s.arc, num))
    if isinstance(s, Line):
        d = num.page(s.direction)
        return ShapeView("line", through=num.page(s.through), direction=d / np.linalg.norm(d))
    if isinstance(s, Disc):
        c, r, n = num.vector(s.center), num.scalar(s.radius), num.vector(s.axis)
        u, w = _plane_basis(n)
        t = np.linspace(0, 2 * math.pi, 73)
        rim = c + r * (np.outer(np.cos(t), u) + np.outer(np.sin(t), w))
        return ShapeView("outline", center=num.proj(c), radius=r,
                         vertices=np.array([num.proj(p) for p in rim]))
    assert isinstance(s, Plane)
    return _plane(s, num)


def _page_arc(arc: Optional[tuple[float, float]], num: Numbers) -> Optional[tuple[float, float]]:
    """A circle's arc (model degrees) as page radians, from → to counter-clockwise: its start
    direction as the page shows it, the same sweep."""
    if arc is None:
        return None
    a0 = math.radians(arc[0])
    d = num.page((math.cos(a0), math.sin(a0)))
    start = math.atan2(float(d[1]), float(d[0]))
    return start, start + math.radians(arc[1] - arc[0])


def _plane(s: Plane, num: Numbers) -> ShapeView:
    """A square patch of the plane under the mechanism: centred at the points' centroid
    projected on the plane, as wide as the points' spread."""
    pts = np.array([num.vector(p) for p in num.inst.points.values()])
    n = num.vector(s.normal)
    n /= np.linalg.norm(n)
    through = num.vector(s.through)
    centre = pts.mean(axis=0)
    centre = centre - ((centre - through) @ n) * n
    half = max(float(np.abs(pts - centre).max()) * 1.15, 0.5 * float(num.inst.scale))
    u, w = _plane_basis(n)
    corners = [centre + half * (i * u + k * w) for i, k in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return ShapeView("outline", through=num.proj(through), role="plane",
                     vertices=np.array([num.proj(c) for c in corners]))


def _plane_basis(n: Vec) -> tuple[Vec, Vec]:
    """Two unit vectors spanning the plane normal to `n`."""
    n = n / np.linalg.norm(n)
    helper = np.array([1.0, 0, 0]) if abs(n[0]) < 0.9 else np.array([0, 1.0, 0])
    u = np.cross(n, helper)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def _extent(bodies: dict[str, BodyView], inst: Instant) -> tuple[tuple, float]:
    """The bounding box of points and finite shapes, and its size (larger side)."""
    xy = [p for b in bodies.values() for p in b.points.values()]
    for b in bodies.values():
        for s in b.shapes:
            if s.kind == "circle" and s.arc is not None:
                xy += list(s.outline())        # a part of a disc: its own extent (a semicylinder)
            elif s.kind == "circle":
                xy += [s.centre() - s.radius, s.centre() + s.radius]
            elif s.vertices is not None:
                xy += list(s.vertices)
    if not xy:
        xy = [np.zeros(2)]
    arr = np.array(xy)
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    size = float(max(hi - lo))
    if size <= 1e-12 * max(1.0, float(np.abs(arr).max())):
        size = float(inst.scale) or 1.0
        lo, hi = lo - size / 2, hi + size / 2
    return (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])), size


def _grow_box(scene: Scene) -> None:
    """The mechanism's box with its skeletons' arcs and the sphere they lie on."""
    extra = [p for b in scene.bodies.values() for line in b.skeleton for p in line]
    if scene.sphere is not None:
        c, r = scene.sphere
        extra += [c - r, c + r]
    if not extra:
        return
    arr = np.vstack([np.array(scene.box).reshape(2, 2)] + [np.asarray(extra)])
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    scene.box = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
    scene.size = max(scene.size, float(max(hi - lo)))


def _joint_geometries(inst: Instant, solved: Any) -> dict:
    """Each joint's evaluated geometry: the solver's when there is one, else evaluated here
    (a joint whose geometry does not hold is left out of the drawing, not an error)."""
    solver = getattr(solved, "solver", solved)
    if solver is not None and hasattr(solver, "geos"):
        return solver.geos
    from ..engine.joints import joint_geometry

    out = {}
    for j in inst.model.joints:
        try:
            out[j.id] = joint_geometry(inst, j)
        except KinematikaError:
            continue
    return out


def _joint(j: Any, geo: Any, num: Numbers) -> JointView:
    view = JointView(j.id, j.type, j.a, j.b)
    if geo is None:
        return view
    if geo.at is not None:
        view.at = num.page(geo.at)
    if geo.along is not None:
        d = num.page(geo.along)
        norm = np.linalg.norm(d)
        view.along = d / norm if norm > 1e-9 else None
    if geo.axis is not None:
        view.axis = num.page(geo.axis)
    if geo.contact is not None:
        view.contact = num.page(geo.contact.point)
    view.radius = geo.roller
    along = j.along
    if j.kind.guides_point and hasattr(along, "start"):          # a slot given by two points
        pts = num.inst.points
        view.span = (num.page(pts[along.start]), num.page(pts[along.end]))
    return view


def _contacts(model: Any, geos: dict, num: Numbers):
    """(joint, contact point on the page, contact kind) of each joint that rolls."""
    for j in model.joints:
        geo = geos.get(j.id)
        if j.kind.rolls and geo is not None and geo.contact is not None:
            yield j, num.page(geo.contact.point), geo.contact.kind


def _mark_ground_sides(bodies: dict[str, BodyView], model: Any, geos: dict, num: Numbers) -> None:
    """For a fixed shape another body rolls on, the side its material is on (for hatching):
    away from the rolling body — outside a cavity, inside a drum, below a track. A body
    welded to the frame is ground too (an inclined plane a wheel rolls on)."""
    ground = {name for name, b in bodies.items() if b.frame or b.fixed}
    for j, contact, _ in _contacts(model, geos, num):
        still = [name for name in (j.a, j.b) if name in ground]
        if len(still) != 1 or not bodies[still[0]].shapes:
            continue
        fixed = _nearest_shape(bodies[still[0]].shapes, contact)
        partner = _nearest_shape(bodies[j.b if j.a == still[0] else j.a].shapes, contact)
        if fixed is None:
            continue
        if fixed.kind == "line" and partner is not None and partner.kind == "circle":
            fixed.hatch_towards = contact - partner.center
        elif fixed.kind == "circle" and partner is not None and partner.kind == "circle":
            fixed.material_inside = float(np.linalg.norm(partner.centre() - fixed.centre())) >= fixed.radius


def _mark_gears(bodies: dict[str, BodyView], model: Any, geos: dict, num: Numbers) -> None:
    """Gear circles are pitch circles (drawn dash-dot); the outer circle of an internal
    contact is a ring (drawn as a band around its inside, not a filled disc)."""
    for j, contact, kind in _contacts(model, geos, num):
        circles = []
        for name in (j.a, j.b):
            shape = _nearest_shape(bodies[name].shapes, contact)
            if shape is not None and shape.kind == "circle":
                circles.append(shape)
                if j.kind.pitch:
                    shape.role = "gear"
        if kind == "internal" and len(circles) == 2:
            outer = max(circles, key=lambda c: c.radius)
            outer.ring = True


def _mark_other_planes(bodies: dict[str, BodyView]) -> None:
    """A moving body's circle that crosses the ground's outline (a fixed circle or line
    through its disc, not touching it) lies in another plane: two bodies of one plane do
    not overlap. It is marked `apart`, drawn dashed and light (`bodies._moving_shape`): C5-E.1's
    2R wheel, solidary with the R wheel that rolls in the track, passes over the track's
    wall, and drawn as the other wheels are it read as crossing it (issue 30,
    twenty-seventh round (f))."""
    ground = [s for b in bodies.values() if b.frame or b.fixed for s in b.shapes]
    size = max([abs(float(x)) for b in bodies.values() for p in b.points.values() for x in p] + [1.0])
    tol = 1e-6 * size
    for body in bodies.values():
        if body.frame or body.fixed:
            continue
        for s in body.shapes:
            if s.kind == "circle" and s.arc is None and not s.ring and any(_crosses(s, g, tol) for g in ground):
                s.apart = True


def _crosses(s: ShapeView, g: ShapeView, tol: float) -> bool:
    """Whether the ground's shape `g` (a circle or a line) runs through the disc of the
    circle `s`, cutting its rim twice (a tangent one touches it)."""
    if g.kind == "circle" and g.arc is None:
        d = float(np.linalg.norm(s.centre() - g.centre()))
        return abs(s.radius - g.radius) + tol < d < s.radius + g.radius - tol
    if g.kind == "line":
        through, direction = g.line()
        n = np.array([-direction[1], direction[0]])
        return abs(float((s.centre() - through) @ n)) < s.radius - tol
    return False


def _nearest_shape(shapes: list[ShapeView], p: Vec) -> Optional[ShapeView]:
    def gap(s: ShapeView) -> float:
        if s.kind == "circle":
            return abs(float(np.linalg.norm(p - s.centre())) - s.radius)
        if s.kind == "line":
            through, direction = s.line()
            n = np.array([-direction[1], direction[0]])
            return abs(float((p - through) @ n))
        return math.inf
    best = min(shapes, key=gap, default=None)
    return best if best is not None and gap(best) < math.inf else None
