"""A numeric snapshot of what a figure shows, read from a solved instant (never solving).

Everything here is floats in page coordinates (projected for a 3D model): the bodies with
their points and shapes, the joints, and the results asked for — vectors, instant
centres, curvature circles, screw axes. A symbolic model is drawn at its probe values
(`Instant.probe`), which `notes` reports. Painting (`draw.figure`) reads only a `Scene`,
so the same scene serves a still figure, an animation frame and Jupyter.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from ..engine.instant import Instant
from ..shapes import Cam, Circle, Curve, Disc, Line, Plane
from ..errors import KinematikaError
from ..joints import kind as joint_kind
from ..model.model import PointRef
from .options import DrawOptions
from .projection import Projection, projection
from .names import body_labels, body_numbers, listed, numbered, point_symbol, value_text
from .skeleton import add_skeletons
from .style import body_colour

Vec = np.ndarray


@dataclass
class ShapeView:
    """A body's shape on the page: a circle, an infinite line, or a closed outline (3D)."""

    kind: str                              # "circle", "line", "outline" (3D) or "curve"
    center: Optional[Vec] = None
    radius: float = 0.0
    through: Optional[Vec] = None
    direction: Optional[Vec] = None        # unit (line)
    vertices: Optional[Vec] = None         # (n, 2) (outline, curve)
    role: str = "plain"                    # "gear": drawn as a pitch circle; a cam's "profile"
                                           # and "pitch" curve
    closed: bool = True                    # a curve that closes (a cam's profile)
    ring: bool = False                     # the outer circle of an internal contact
    hatch_towards: Optional[Vec] = None    # ground line: the side its material is on
    material_inside: bool = True           # ground circle: a drum (True) or a cavity (False)


@dataclass
class BodyView:
    """A body on the page: its name and number (the frame is 1), colour, whether it is the
    frame, its points and shapes, the points that slide along it, and the polylines drawn as its
    bars."""

    name: str
    number: int                            # the frame is 1, the others 2, 3, … in file order
    colour: str
    frame: bool
    points: dict[str, Vec]
    shapes: list[ShapeView] = field(default_factory=list)
    passing: list[str] = field(default_factory=list)   # points that slide along this body
    skeleton: list[Vec] = field(default_factory=list)  # polylines drawn as its bars, if any
    label: str = ""                        # its name as the figure writes it (the model's
                                           # name in the figure's language, else its own)
    index: str = ""                        # how labels write it: its number, or the model's index


@dataclass
class JointView:
    """A joint on the page: its place, directions and contact (what its kind draws)."""

    id: str
    type: str
    a: str
    b: str
    at: Optional[Vec] = None
    along: Optional[Vec] = None            # unit on the page
    axis: Optional[Vec] = None             # page image of a 3D axis (not unit)
    span: Optional[tuple[Vec, Vec]] = None  # a slot given by two points
    contact: Optional[Vec] = None
    radius: float = 0.0                    # a cam follower's roller

    @property
    def kind(self) -> Any:
        """What the joint is (`kinematika.joints`)."""
        return joint_kind(self.type)


@dataclass
class VectorView:
    """A velocity or acceleration arrow of material point `ref` (relative to a body, if
    `relative_to`): its label, origin and page value, the model vector's magnitude and the
    magnitude as shown."""

    kind: str                              # "velocity" or "acceleration"
    ref: str                               # the material point, P@body
    label: str                             # the symbol, e.g. $v_B$
    origin: Vec
    value: Vec                             # on the page
    magnitude: float                       # of the model vector
    text: str                              # the magnitude as shown (a number or a formula)
    relative_to: Optional[str] = None

    @property
    def key(self) -> str:
        """Identifies the arrow (its gid): `velocity:B@rocker`, `velocity:B@rod/crank`."""
        return f"{self.kind}:{self.ref}" + (f"/{self.relative_to}" if self.relative_to else "")


@dataclass
class MarkView:
    """A marked point: an instant centre, an acceleration pole or a contact."""

    kind: str                              # "icr", "pole" or "contact"
    key: str                               # identifies the artist (gid)
    label: str
    point: Optional[Vec] = None
    direction: Optional[Vec] = None        # a centre at infinity (unit)
    pair: tuple[str, ...] = ()
    rest: bool = False                     # no relative motion: no centre


@dataclass
class KennedyLine:
    """A line of three collinear centres: through `through`, along `direction`."""

    key: str
    through: Vec
    direction: Vec
    anchors: list[Vec]                     # the finite centres it must reach


@dataclass
class CurvatureView:
    """A point's path curvature on the page: the point, its centre of curvature, the radius ρ
    and the osculating circle's polyline."""

    ref: str
    label: str
    point: Vec
    centre: Vec
    radius: float
    circle: Vec                            # (n, 2): the osculating circle on the page


@dataclass
class AxisView:
    """A 3D body's instantaneous screw axis on the page: a point of it and the page image of its
    unit direction."""

    key: str
    label: str
    point: Vec
    direction: Vec                         # page image of the unit direction


@dataclass
class Scene:
    """Everything a figure shows, as floats on the page: bodies, joints, the mechanism's size
    and box, and the results asked for (vectors, marked points, Kennedy lines and normals,
    curvatures, screw axes) with notes such as the values a symbolic model is drawn at."""

    name: str
    dim: int
    projection: Projection
    bodies: dict[str, BodyView]
    joints: list[JointView]
    size: float                            # the mechanism's extent: what symbols scale by
    box: tuple[float, float, float, float]  # xmin, ymin, xmax, ymax of the mechanism
    vectors: list[VectorView] = field(default_factory=list)
    marks: list[MarkView] = field(default_factory=list)
    kennedy: list[KennedyLine] = field(default_factory=list)
    normals: list[KennedyLine] = field(default_factory=list)   # wheel and slot normals
    curvatures: list[CurvatureView] = field(default_factory=list)
    axes: list[AxisView] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    numbered: bool = False                 # labels name bodies by number: bodies say theirs
    sphere: Optional[tuple] = None         # (centre, radius) of a spherical linkage's sphere

    @property
    def frame(self) -> BodyView:
        """The fixed body's view."""
        return next(b for b in self.bodies.values() if b.frame)

    def point(self, name: str) -> Vec:
        """The page position of point `name` (from the first body that carries it); KeyError if
        none does."""
        for body in self.bodies.values():
            if name in body.points:
                return body.points[name]
        raise KeyError(name)


# building --------------------------------------------------------------------------------
def build_scene(inst: Instant, sol: Any = None, options: DrawOptions | None = None,
                solver: Any = None, proj: Optional[Projection] = None) -> Scene:
    """The scene of an evaluated instant; with a `Solution`, also the results to show.
    `proj`: another map to the page than the options' view (the page's 3D twin, whose first coordinate is the depth)."""
    from .results import add_results   # results read the Solution; geometry needs only inst

    options = options or DrawOptions()
    model = inst.model
    proj = proj or projection(model.dimension, options.view, model.up)
    num = Numbers(inst, proj, drawing_values(inst))
    bodies = _bodies(inst, num, options.lang)
    box, size = _extent(bodies, inst)
    geos = _joint_geometries(inst, sol or solver)
    _mark_ground_sides(bodies, model, geos, num)
    _mark_gears(bodies, model, geos, num)
    joints = [_joint(j, geos.get(j.id), num) for j in model.joints]
    scene = Scene(model.name, model.dimension, proj, bodies, joints, size, box)
    add_skeletons(scene, inst, num, geos)
    _grow_box(scene)
    if num.values:
        scene.notes.append(_values_note(num.values, model.draw_at, options.lang))
    if sol is not None:
        add_results(scene, sol, options, num)
    _number_bodies(scene, options.bare)
    return scene


def _number_bodies(scene: Scene, always: bool = False) -> None:
    """When a label names a body by its number, the bodies are numbered on the figure and
    the numbering is listed under it; `always` for a figure set in a text that names the
    bodies by number (an explanation's ω_3, I_13)."""
    labels = [v.label for v in scene.vectors] + [m.label for m in scene.marks] + \
        [c.label for c in scene.curvatures]
    if not always and not any(numbered(text) for text in labels):
        return
    scene.numbered = True
    scene.notes.insert(0, numbering_note(scene))


def numbering(scene: Scene) -> list[tuple[Any, str]]:
    """The bodies' numbers (or the indices the model's notation gives them) with the names the
    figure gives them (their label, else their name), in order."""
    return [(b.index if b.index and b.index != str(b.number) else b.number, b.label or b.name)
            for b in sorted(scene.bodies.values(), key=lambda b: b.number)]


def numbering_note(scene: Scene) -> str:
    """The note under a figure that numbers its bodies: 'bodies: 1 ground, 2 crank, …'."""
    return "bodies: " + ", ".join(f"{n} {name}" for n, name in numbering(scene))


def drawing_values(inst: Instant) -> dict:
    """The numbers a symbolic model is drawn at: its `draw_at` values, the solver's generic
    probe values for the other symbols. Empty for a numeric model."""
    if not (inst.symbolic and inst.probe):
        return {}
    given = inst.model.draw_at
    values = {s: float(given.get(str(s), v)) for s, v in inst.probe.items() if s not in inst.names}
    if any(str(s) in given for s in values):
        from ..engine.instant import named_values

        at = {**values, **named_values(inst.names, values)}      # named coordinates there
        for name, vec in inst.points.items():
            if any(abs(complex(c.xreplace(at) if hasattr(c, "xreplace") else c).imag) > 1e-12
                   for c in vec):
                raise KinematikaError("schema", "draw-at-not-real", "draw_at", point=name)
    return values


def _values_note(values: dict, given: dict, lang: Optional[str] = None) -> str:
    """Which numbers the figure shows: the model's draw_at, or generic ones."""
    text = listed([f"{s} = {value_text(v, lang)}" for s, v in sorted(values.items(), key=str)], lang)
    if all(str(s) in given for s in values):
        return f"symbolic model drawn at {text} (its draw_at values)"
    if any(str(s) in given for s in values):
        return f"symbolic model drawn at {text} (draw_at values, generic ones for the rest)"
    return f"symbolic model drawn at generic values {text} (a model's draw_at sets them)"


class Numbers:
    """Backend values (floats, or sympy at the drawing values) as page coordinates."""

    def __init__(self, inst: Instant, proj: Projection, values: Optional[dict] = None) -> None:
        self.inst, self.proj = inst, proj
        self.values = values or {}
        self._at = dict(self.values)        # with the named quantities' values there

    def scalar(self, x: Any) -> float:
        """A backend value as a float: a number as it is, a formula at the drawing values (and
        the named quantities' values there)."""
        if isinstance(x, (int, float)) or not self.values:
            return self.inst.num(x)
        if len(self._at) != len(self.values) + len(self.inst.names):    # names added since
            from ..engine.instant import named_values

            self._at = {**self.values, **{s: v.real for s, v in
                                          named_values(self.inst.names, self.values).items()}}
        return float(x.xreplace(self._at))

    def vector(self, v: tuple) -> Vec:
        """A model vector (3D kept as is) as floats."""
        return np.array([self.scalar(c) for c in v], dtype=float)

    def page(self, v: tuple) -> Vec:
        """A model point or vector projected on the page."""
        return self.proj(self.vector(v))


def _bodies(inst: Instant, num: Numbers, lang: Optional[str] = None) -> dict[str, BodyView]:
    model = inst.model
    out = {}
    labels = body_labels(model, lang)
    for name, number in body_numbers(model).items():
        body = model.bodies[name]
        frame = name == model.frame
        points = {p: num.page(inst.points[p]) for p in body.points}
        shapes = [view for s in inst.shapes.get(name, []) for view in _shapes(s, num)]
        out[name] = BodyView(name, number, "#424242" if frame else body_colour(number), frame,
                             points, shapes, label=model.wording.body(name, lang), index=labels[name])
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
        return ShapeView("circle", center=num.page(s.center), radius=num.scalar(s.radius))
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
            if s.kind == "circle":
                xy += [s.center - s.radius, s.center + s.radius]
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
    away from the rolling body — outside a cavity, inside a drum, below a track."""
    frame = bodies[model.frame]
    for j, contact, _ in _contacts(model, geos, num):
        if model.frame not in (j.a, j.b) or not frame.shapes:
            continue
        fixed = _nearest_shape(frame.shapes, contact)
        partner = _nearest_shape(bodies[j.b if j.a == model.frame else j.a].shapes, contact)
        if fixed is None:
            continue
        if fixed.kind == "line" and partner is not None and partner.kind == "circle":
            fixed.hatch_towards = contact - partner.center
        elif fixed.kind == "circle" and partner is not None and partner.kind == "circle":
            fixed.material_inside = np.linalg.norm(partner.center - fixed.center) >= fixed.radius


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


def _nearest_shape(shapes: list[ShapeView], p: Vec) -> Optional[ShapeView]:
    def gap(s: ShapeView) -> float:
        if s.kind == "circle":
            return abs(np.linalg.norm(p - s.center) - s.radius)
        if s.kind == "line":
            n = np.array([-s.direction[1], s.direction[0]])
            return abs(float((p - s.through) @ n))
        return math.inf
    best = min(shapes, key=gap, default=None)
    return best if best is not None and gap(best) < math.inf else None


def vector_label(kind: str, model: Any, ref: PointRef, relative_to: Optional[str],
                 lang: Optional[str] = None) -> str:
    """$v_B$, $a_{B∈3}$ (B of body 3, when B's carriers move differently), $v_{B∈3/2}$
    (relative to body 2); bodies by their labels (`names.body_labels`)."""
    return point_symbol("v" if kind == "velocity" else "a", model, ref.point, ref.body,
                        relative_to, lang)
