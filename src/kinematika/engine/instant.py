"""A `Model` evaluated on numbers or on symbols: the geometry of one instant.

Everything the linear systems need is here as backend scalars: point coordinates, shapes,
unit directions of joints and drivers, driver values. For a symbolic model the instant
also carries generic probe values of the symbols, used to find the structure (rank,
independent rows, geometric gaps) numerically.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Optional

from ..algebra.backend import Numeric, Symbolic, probe_values
from ..algebra.vectors import Space, dot, sub
from ..errors import KinematikaError, said_of
from ..model import model as m
from ..expressions import Expr, ExpressionError, evaluate
from .positions import angle_warnings, positions

if TYPE_CHECKING:
    from ..model.parameter import Parameter
    from ..model.body_shapes import CamShape, CurveShape, Shape
    from ..shapes import Cam, Curve


@dataclass
class Instant:
    """A model evaluated at one instant on the backend's scalars (floats or sympy): parameter
    values (`env`), point coordinates, shapes, and for a symbolic model the probe values that
    find its structure numerically. `scale` and `rate` are the model's characteristic length and
    rate (`engine.ranges`); `names` holds the named quantities a long formula is written with,
    and `warnings` the input answered as written that is most likely a mistake."""

    model: m.Model
    backend: Any
    space: Space
    env: dict[str, Any]
    points: dict[str, tuple]
    shapes: dict[str, list]
    probe: dict = field(default_factory=dict)       # symbol -> float (symbolic models)
    scale: float = 1.0                               # characteristic length
    rate: float = 0.0                                # characteristic rate (engine.ranges)
    ref: tuple = ()                                  # where body twists are taken
    names: dict = field(default_factory=dict)        # named quantities (symbolic): symbol ->
                                                     # formula in parameters and earlier names
                                                     # (coordinates x_E, then velocities omega_link)
    warnings: list = field(default_factory=list)     # KinematikaWarning: input answered as written
                                                     # that is most likely a mistake
    drawn: dict = field(default_factory=dict)        # a moved model's turns' pivots: drawn places
    body_turn: Optional[Any] = None                  # a sweep's pose: (body, drawn direction) ->
                                                     # the direction now (`sweep.poses`), for
                                                     # the drivers' directions
    _nums: tuple = field(default=(None, None), init=False, repr=False, compare=False)
                                                     # `num`'s memo: (the probe it was made at,
                                                     # formula -> float)

    @property
    def symbolic(self) -> bool:
        """Whether the instant computes on exact formulas (a parameter left as a symbol, or
        asked for)."""
        return self.backend.symbolic

    def value(self, expr: Expr, where: str) -> Any:
        """Expression `expr` evaluated with the instant's parameters on its backend; an error in
        it becomes a schema error at `where`."""
        try:
            return evaluate(expr, self.env, self.backend)
        except ExpressionError as err:
            raise KinematikaError("schema", err.said, where) from None

    def vector(self, exprs: tuple, where: str) -> tuple:
        """Each component of `exprs` evaluated (`value`), its place named ``where[i]`` in an
        error."""
        env, backend = self.env, self.backend
        try:
            return tuple([evaluate(e, env, backend) for e in exprs])
        except ExpressionError:     # again, component by component: the first error, placed
            return tuple(self.value(e, f"{where}[{i}]") for i, e in enumerate(exprs))

    def unit(self, vec: tuple, where: str) -> tuple:
        """`vec` normalised, whatever its size ([1e-12, 0] is the x axis); a zero vector is a
        schema error at `where`."""
        size = math.hypot(*self.numvec(vec))          # no squares to underflow or overflow
        if not 0 < size < math.inf:
            raise KinematikaError("schema", "direction-zero", where)
        if not self.symbolic:
            return tuple(c / size for c in vec)
        try:
            norm = self.backend.sqrt(dot(vec, vec))
            return tuple(self.backend.simplify(c / norm) for c in vec)
        except ValueError as err:   # sympy's integer factoring fails on some 100-digit norms
            raise KinematikaError("schema", "direction-not-exact", where) from err

    def direction(self, d: m.Direction, where: str) -> tuple:
        """A unit direction from the model: two points (from `start` to `end`, which must
        differ) or a written vector, normalised."""
        if not isinstance(d, tuple):         # two points (`PointPair`), not a written vector
            gap = sub(self.points[d.end], self.points[d.start])
            if math.hypot(*self.numvec(gap)) <= 1e-12 * self.scale:
                raise KinematikaError("schema", "direction-points-coincide", where, start=d.start, end=d.end)
            return self.unit(gap, where)
        return self.unit(self.vector(d, where), where)

    def body_direction(self, body: str, d: m.Direction, where: str) -> tuple:
        """A direction fixed in `body`: as written, turned with the body when the model is
        moved (`Model.turns`); two points give it at the instant anyway."""
        u = self.direction(d, where)
        if self.model.turns and isinstance(d, tuple):      # written, not two points
            from .turns import turned

            u = turned(self, body, u)
        return u

    def num(self, x: Any) -> float:
        """A scalar as a float (a symbolic one at the probe values)."""
        if isinstance(x, (int, float)):
            return float(x)
        if getattr(x, "is_Number", False):
            return float(x)
        # A memo per probe: the explanations ask for the same few formulas thousands of times,
        # each an exact evaluation at two precisions. Probe values are only ever added (a
        # stand-in's, a named quantity's), never changed, and a formula with a symbol not yet
        # probed has no value, so a value once found holds while the probe is the same dict.
        at, memo = self._nums
        if at is not self.probe:
            memo = {}
            self._nums = (self.probe, memo)
        found = memo.get(x)
        if found is None:
            found = memo[x] = self._num_at_probe(x)
        return found

    def _num_at_probe(self, x: Any) -> float:
        from ..algebra.evaluate import complex_value

        z = complex_value(x, self.probe)      # each shared subformula once (long exact numbers)
        if z.imag == 0 or abs(z.imag) <= 1e-12 * abs(z.real):
            return z.real
        raise KinematikaError("schema", "value-not-real", "parameters")

    def numvec(self, v: tuple) -> tuple:
        """A vector's components as floats (a symbolic one at the probe values), to measure and
        compare."""
        return tuple(self.num(c) for c in v)


def instantiate(model: m.Model, symbolic: bool | None = None) -> Instant:
    """Evaluate `model`; symbolic when asked or when a parameter has no value."""
    has_symbols = any(p.value is None for p in model.parameters.values())
    use_symbols = has_symbols if symbolic is None else (symbolic or has_symbols)
    backend = Symbolic() if use_symbols else Numeric()
    env, probe = _parameters(model, backend, force_symbols=bool(symbolic))
    inst = Instant(model, backend, Space(model.dimension), env, {}, {}, probe)
    inst.warnings = angle_warnings(inst)
    try:
        inst.points = positions(inst)
    except KinematikaError:
        _check_coordinates(inst)         # a model out of range says so, not that circles miss
        raise
    if probe:
        inst.probe = _real_probe(inst.points, probe, inst.names)
    inst.scale = _length_scale(inst)
    inst.ref = inst.space.zero() if use_symbols else _centroid(inst)
    inst.shapes = {name: [_shape(inst, s, name) for s in b.shapes]
                   for name, b in model.bodies.items()}
    from .ranges import check_rates

    inst.rate = check_rates(inst)
    return inst


def _parameters(model: m.Model, backend: Any, force_symbols: bool) -> tuple[dict, dict]:
    env: dict[str, Any] = {}
    at_given: dict[Any, Optional[float]] = {}
    pending = dict(model.parameters)
    for name, p in list(pending.items()):
        # forced symbols: the parameters given values; those defined from others stay formulas
        given = p.value is not None and not p.value.names() & set(model.parameters)
        if p.value is None or (force_symbols and backend.symbolic and given):
            env[name] = backend.symbol(name, p.positive)
            del pending[name]
            if p.value is not None:
                at_given[env[name]] = _given_value(p, backend)
    while pending:
        ready = [p for p in pending.values() if p.value is not None and p.value.names() <= set(env) | {"pi"}]
        if not ready:
            raise KinematikaError("schema", "parameters-cycle", "parameters", names=list(pending))
        for p in ready:
            assert p.value is not None                  # those without a value are symbols, above
            try:
                env[p.name] = evaluate(p.value, env, backend)
            except ExpressionError as err:
                raise KinematikaError("schema", err.said, f"parameters.{p.name}") from None
            del pending[p.name]
    probe = probe_values([v for v in env.values() if getattr(v, "is_Symbol", False)])
    probe.update({s: v for s, v in at_given.items() if v is not None})
    return env, probe


def _given_value(p: Parameter, backend: Any) -> float | None:
    """The value a forced symbol was given, to probe the model where its geometry holds;
    None (a generic probe) for 0 or a sign its symbol cannot take."""
    if p.value is None:
        return None
    try:
        value = float(evaluate(p.value, {}, backend))
    except (ExpressionError, TypeError, ValueError):
        return None
    if not math.isfinite(value) or value == 0 or (p.positive and value < 0):
        return None
    return value


def _real_probe(points: dict[str, tuple], probe: dict, names: dict | None = None,
                tries: int = 40) -> dict:
    """Probe values at which every point is real and finite (with the values of the named
    coordinates there, `names`).

    A symbolic model may make sense only for some values of its symbols
    (``sqrt(l**2 - r**2)`` needs l > r): when the default probe falls outside, values spread
    over a wider range (log-uniform in (e⁻², e²)) are tried before giving up.
    """
    import random

    names = names or {}
    probe = {s: v for s, v in probe.items() if s not in names}
    coords = [c for p in points.values() for c in p if not isinstance(c, (int, float))]
    for attempt in range(tries):
        if attempt:
            rng = random.Random(attempt)
            probe = {s: math.exp(rng.uniform(-2, 2)) * (1 if s.is_positive else rng.choice((-1, 1)))
                     for s in probe}
        at = {**probe, **named_values(names, probe)}
        values = list(at.values())[len(probe):] + [complex(c.xreplace(at)) for c in coords]
        if all(math.isfinite(v.real) and abs(v.imag) <= 1e-12 * (1 + abs(v.real)) for v in values):
            return {**probe, **{s: complex(v).real for s, v in at.items() if s in names}}
    raise KinematikaError("geometry", "points-not-real", "points")


def named_values(names: dict, probe: dict) -> dict:
    """The values (complex) of the named coordinates at the symbols' values `probe`, each
    from its formula in the parameters and the names before it."""
    out: dict = {}
    for s, formula in names.items():
        out[s] = complex(formula.xreplace({**probe, **out}))
    return out


def _check_coordinates(inst: Instant) -> None:
    """The explicit coordinates' magnitude within the range the engine computes with."""
    from .ranges import check_size

    sizes = []
    for p in inst.model.points.values():
        for c in p if isinstance(p, tuple) else ():
            try:
                sizes.append(abs(inst.num(inst.value(c, "points"))))
            except KinematikaError:        # that error is the one to report
                return
    top = max(sizes, default=0.0)
    if top > 0:
        check_size(top)


def _length_scale(inst: Instant) -> float:
    """The model's size: the largest distance of a point from the centroid, or radius.

    Never below 1e-9 of the coordinates' magnitude (nor zero), so that a model whose
    points nearly coincide still gets a usable scale. A size outside `limits.SCALE` (in
    either direction) is refused: squares and cubes of lengths would leave the floats.
    """
    pts = [inst.numvec(p) for p in inst.points.values()]
    center = [math.fsum(c / len(pts) for c in axis) for axis in zip(*pts)]
    spread = max(math.dist(p, center) for p in pts)
    radii = [abs(inst.num(inst.value(s.radius, "radius"))) for b in inst.model.bodies.values()
             for s in b.shapes if hasattr(s, "radius")]
    magnitude = max(abs(c) for p in pts for c in p)
    size = max([spread, 1e-9 * magnitude] + radii)
    if size == 0:
        return 1.0
    from .ranges import check_size

    check_size(size)
    return size


def _centroid(inst: Instant) -> tuple:
    pts = list(inst.points.values())
    return tuple(sum(c) / len(pts) for c in zip(*pts))


def _shape(inst: Instant, s: Shape, body: str) -> Any:
    from ..model import body_shapes as ms     # only a body with shapes needs them (start-up)
    from ..shapes import Circle, Disc, Line, Plane

    where = f"bodies.{body}"
    if isinstance(s, ms.Circle):
        return Circle(_at(inst, s.center, s.center_point, body), _radius(inst, s.radius, where),
                      s.center_point, _arc(inst, s.arc, body))
    if isinstance(s, ms.Line):
        return Line(_at(inst, s.through, s.through_point, body),
                    inst.body_direction(body, s.direction, f"{where}.line.direction"), s.through_point)
    if isinstance(s, ms.Disc):
        return Disc(_at(inst, s.center, s.center_point, body), _radius(inst, s.radius, where),
                    inst.body_direction(body, s.axis, f"{where}.disc.axis"), s.center_point)
    if isinstance(s, ms.Plane):
        return Plane(_at(inst, s.through, s.through_point, body),
                     inst.body_direction(body, s.normal, f"{where}.plane.normal"), s.through_point)
    if inst.symbolic:
        raise KinematikaError("schema", "curves-need-numbers", where)
    if isinstance(s, ms.CurveShape):
        return _curve(inst, s, body, where)
    return _cam(inst, s, body, where)


def _arc(inst: Instant, arc: Optional[tuple[float, float]], body: str) -> Optional[tuple[float, float]]:
    """A circle's arc (degrees) at this instant: as written, advanced by its body's turn when
    the model is moved (`turns.turned`: the arc's start direction turned with the body)."""
    if arc is None or not inst.model.turns:
        return arc
    from .turns import turned

    a0 = math.radians(arc[0])
    u = turned(inst, body, (math.cos(a0), math.sin(a0)))
    turn = math.degrees(math.atan2(inst.num(u[1]), inst.num(u[0]))) - arc[0]
    return arc[0] + turn, arc[1] + turn


def _curve(inst: Instant, s: CurveShape, body: str, where: str) -> Curve:
    """A spline through the curve's points at this instant (carried with the body when the
    model is moved: a rigid motion moves the spline through moved points)."""
    from ..curves import Spline
    from ..shapes import Curve

    pts = [inst.numvec(_at(inst, () if isinstance(p, str) else p, p if isinstance(p, str) else None, body))
           for p in s.through]
    try:
        spline = Spline(pts, closed=s.closed)
    except ValueError as err:
        raise KinematikaError("geometry", "curve-through-points", f"{where}.curve", why=said_of(err)) from None
    return Curve(spline, role="curve")


def _cam(inst: Instant, s: CamShape, body: str, where: str) -> Cam:
    """A cam's profile and pitch curve, in the cam's own coordinates placed at `center`: a disc
    cam turned by `layout` + σθ (θ its cam angle: the drawing's, advanced by the body's turn
    since), a plate cam by `layout` (its `center` the plate's own origin, which the program's
    travel θ has carried along the frame's x from the follower's line)."""
    from ..shapes import Cam, Curve
    from .turns import turned

    design = s.design.cam
    center = inst.numvec(_at(inst, s.center, s.center_point, body))
    layout = float(inst.num(inst.value(s.layout, f"{where}.cam.layout")))
    theta = float(inst.num(inst.value(s.angle, f"{where}.cam.angle")))
    placed = layout
    if not _translates(design):
        ux = inst.numvec(turned(inst, body, (1, 0)))
        theta += design.sense * math.atan2(ux[1], ux[0])     # the body's turn since the drawing
        placed = layout + design.sense * theta
    return Cam(design, Curve(design.profile, center, placed, "profile"), Curve(design.pitch, center, placed, "pitch"),
               center, theta, layout, not _translates(design))


def _translates(design: Any) -> bool:
    """A plate (translating) cam, which slides instead of turning."""
    from ..cams.profile import PlateCam

    return isinstance(design, PlateCam)


def _at(inst: Instant, coords: tuple, point: Optional[str], body: str) -> tuple:
    """A shape's location: the named point's coordinates at the instant, or its own (carried
    with its body when the model is moved)."""
    if point:
        return inst.points[point]
    p = inst.vector(coords, f"bodies.{body}")
    turn = next((t for t in inst.model.turns if t.body == body), None)
    if turn is not None:
        from .turns import carry

        p = carry(inst, turn, p, inst.points)
    return p


def _radius(inst: Instant, expr: Expr, where: str) -> Any:
    r = inst.value(expr, f"{where}.radius")
    if inst.num(r) <= 0:
        raise KinematikaError("schema", "radius-positive", where, radius=float(inst.num(r)))
    return r

