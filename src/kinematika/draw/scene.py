"""A numeric snapshot of what a figure shows, read from a solved instant (never solving).

Everything here is floats in page coordinates (projected for a 3D model): the bodies with
their points and shapes, the joints, and the results asked for — vectors, instant
centres, curvature circles, screw axes. A symbolic model is drawn at its probe values
(`Instant.probe`), which `notes` reports. Painting (`draw.figure`) reads only a `Scene`,
so the same scene serves a still figure, an animation frame and Jupyter.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Optional

import numpy as np

from ..engine.instant import Instant, named_values
from ..errors import KinematikaError
from ..joints import kind as joint_kind
from ..model.model import PointRef
from .projection import Projection
from .names import point_symbol

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
    arc: Optional[tuple[float, float]] = None  # circle: the part its body is (radians on the page,
                                           # from → to counter-clockwise; a semicylinder)
    apart: bool = False                    # a moving circle in another plane than the ground it
                                           # crosses (`build._mark_other_planes`): drawn dashed

    def centre(self) -> Vec:
        """A circle's centre (the scene sets it for every circle)."""
        assert self.center is not None, f"a {self.kind} shape has no centre"
        return self.center

    def outline(self, n: int = 72) -> Vec:
        """A circle's outline, (n + 1, 2) closed: the whole circle, or for an `arc` the arc
        and the chord back to its start (a semicylinder's half-disc, its flat side)."""
        a0, a1 = self.arc if self.arc is not None else (0.0, 2 * np.pi)
        t = np.linspace(a0, a1, n + 1)
        pts = self.centre() + self.radius * np.column_stack([np.cos(t), np.sin(t)])
        return pts if self.arc is None else np.vstack([pts, pts[:1]])

    def line(self) -> tuple[Vec, Vec]:
        """A line's point and unit direction (the scene sets both for every line)."""
        assert self.through is not None and self.direction is not None, f"a {self.kind} shape is no line"
        return self.through, self.direction

    def polyline(self) -> Vec:
        """An outline's or a curve's vertices, (n, 2) (the scene sets them for both)."""
        assert self.vertices is not None, f"a {self.kind} shape has no vertices"
        return self.vertices


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
    read_off: bool = False                 # `index` is read off its name (ω_zentrala of *gurpil zentral
                                           # finkoa*): no number, no index the notation gives it
    fixed: bool = False                    # welded to the frame (an inclined plane): drawn as ground


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
    contact_name: str = ""                 # the letter the text names the contact by (labelled)

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


def numbering(scene: Scene) -> list[tuple[Any, str]]:
    """The bodies' numbers (or the indices the model's notation gives them) with the names the
    figure gives them (their label, else their name), in order."""
    return [(b.index if b.index and b.index != str(b.number) else b.number, b.label or b.name)
            for b in sorted(scene.bodies.values(), key=lambda b: b.number)]


def numbering_note(scene: Scene, lang: Optional[str] = None) -> str:
    """The note under a figure that numbers its bodies: 'bodies: 1 ground, 2 crank, …' (in
    the figure's language)."""
    from .words import word

    return word("note-bodies", lang, bodies=", ".join(f"{n} {name}" for n, name in numbering(scene)))


def drawing_values(inst: Instant) -> dict:
    """The numbers a symbolic model is drawn at: its `draw_at` values, the solver's generic
    probe values for the other symbols. Empty for a numeric model."""
    if not (inst.symbolic and inst.probe):
        return {}
    given = inst.model.draw_at
    values = {s: float(given.get(str(s), v)) for s, v in inst.probe.items() if s not in inst.names}
    if any(str(s) in given for s in values):
        at = {**values, **named_values(inst.names, values)}      # named coordinates there
        for name, vec in inst.points.items():
            if any(abs(complex(c.xreplace(at) if hasattr(c, "xreplace") else c).imag) > 1e-12
                   for c in vec):
                raise KinematikaError("schema", "draw-at-not-real", "draw_at", point=name)
    return values


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
                self._at = {**self.values, **{s: v.real for s, v in
                                          named_values(self.inst.names, self.values).items()}}
        return float(x.xreplace(self._at))

    def vector(self, v: tuple) -> Vec:
        """A model vector (3D kept as is) as floats."""
        return np.array([self.scalar(c) for c in v], dtype=float)

    def page(self, v: tuple) -> Vec:
        """A model point or vector projected on the page."""
        return self.proj(self.vector(v))


def vector_label(kind: str, model: Any, ref: PointRef, relative_to: Optional[str],
                 lang: Optional[str] = None) -> str:
    """$v_B$, $a_{B∈3}$ (B of body 3, when B's carriers move differently), $v_{B∈3/2}$
    (relative to body 2); bodies by their labels (`names.body_labels`)."""
    return point_symbol("v" if kind == "velocity" else "a", model, ref.point, ref.body,
                        relative_to, lang)
