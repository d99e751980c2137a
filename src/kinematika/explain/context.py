"""What every part of the builder reads from the solution: positions, motions, clean values.

Nothing here solves: velocities, accelerations, ω and α all come from the `Solution`.
Numbers are cleaned of round-off at the mechanism's own scale (as the JSON answer is),
symbolic values are kept exact and simplified only when rendered.
"""
from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Callable, Iterator, Optional

from ..algebra.vectors import sub
from ..model.model import PointRef
from ..report.values import number
from ..solution import ZERO, Solution
from .document import Msg, Sym, Value


class Ctx:
    """The solution seen by the explanation builder."""

    def __init__(self, sol: Solution) -> None:
        self.sol = sol
        self.model = sol.model
        self.inst = sol.inst
        self.space = sol.space
        self.frame = sol.model.frame
        self.symbolic = sol.symbolic
        self.planar = sol.space.dim == 2
        self._extra: dict[str, tuple] = {}
        self.worked: set[str] = set()        # derivations written once in the document (a bar's ω)
        self._contacts: dict[str, str] = {}
        self._drawn: Any = None
        self.centre_notes: Any = None        # the instant centres' notes (`centres._notes`), once
        self.centre_how: dict = {}           # how the engine places each pair's centre
        self.centre_points: set[str] = set() # instant centres the velocity steps start from (I14)
        self.centre_sites: dict[str, str] = {}   # ... and those at a point of the body (P): name -> body
        self.witnessed: dict[str, set] = {}       # body -> the points its centre was placed by (M of C5-E.4)
        self.translating: dict[str, Any] = {}    # bodies whose centre is at infinity -> its note
        self.glides_said: set[str] = set()        # bodies whose reason to translate the velocities gave
        self.slides_seen: dict[tuple, Any] = {}  # (level, body, guide body) -> a slide's symbol written in the steps
        self.centre_first_memo: Optional[bool] = None    # the centres before the velocities (`centres.centres_first`)
        self.found_order: dict[frozenset, tuple] = {}    # a step's bodies -> (bodies, sources) as its equations find and read them
        self.kin_reads: dict[tuple, frozenset] = {}      # (level, centres, body) -> the known bodies its rate's equation read (`group`)

    # positions -----------------------------------------------------------------------------
    def pos(self, name: str) -> tuple:
        """Where point `name` is at the instant (a named contact or centre too, see
        `name_position`)."""
        return self._extra[name] if name in self._extra else self.inst.points[name]

    def name_position(self, name: str, position: tuple) -> str:
        """Give an unnamed location (a shape's centre) a name for the equations."""
        self._extra.setdefault(name, position)
        return name

    def contact(self, j) -> str:
        """The name of a touching joint's contact point, placed there: the notation's name,
        the model's point there, else J, K, M … in the joints' order (`draw.names.contact_names`,
        the one rule of the text, the tables and the figures; never the joint's id)."""
        if j.id not in self._contacts:
            from ..draw.names import contact_name

            base = contact_name(self.model, j.id, self.sol)
            self._contacts[j.id] = base
            contact = self.sol.geometry(j.id).contact
            if contact is not None:
                self.name_position(base, contact.point)
        return self._contacts[j.id]

    def page_names(self) -> set[str]:
        """Every name the page may write alone: the model's points and bodies, the contacts
        and the locations named for the equations (`name_position`)."""
        return set(self.model.points) | set(self.model.bodies) | set(self._contacts.values()) | set(self._extra)

    def r(self, q: str, p: str) -> tuple:
        """The position vector from point q to point p: r_qp = p − q (as in ω × r_AB)."""
        return sub(self.pos(p), self.pos(q))

    # motion ----------------------------------------------------------------------------------
    def rel(self, body: Optional[str]) -> Optional[str]:
        """The body an answer is relative to, or None for the frame (named or not)."""
        return None if body in (None, self.frame) else body

    def vel(self, body: str, point: str, relative_to: Optional[str] = None) -> tuple:
        """The velocity of `body`'s material point at `point`, seen from `relative_to`: v = v₀ +
        ω × (P − O), read from the solution."""
        m = self.sol.motion
        return m.velocity(self.sol.state(body, self.rel(relative_to)), self.pos(point))

    def acc(self, body: str, point: str, relative_to: Optional[str] = None) -> tuple:
        """The acceleration of `body`'s material point at `point`, seen from `relative_to`: a =
        a₀ + α × r + ω × (ω × r), read from the solution."""
        m = self.sol.motion
        return m.acceleration(self.sol.state(body, self.rel(relative_to)), self.pos(point))

    def omega(self, body: str, relative_to: Optional[str] = None) -> Any:
        """ω of `body`, relative to `relative_to` when given."""
        return self.sol.omega(body, self.rel(relative_to))

    def alpha(self, body: str, relative_to: Optional[str] = None) -> Any:
        """α of `body`, relative to `relative_to` when given (the derivative seen from that
        body)."""
        return self.sol.alpha(body, self.rel(relative_to))

    # values ----------------------------------------------------------------------------------
    def scale_of(self, unit: str) -> float:
        """The mechanism's own size of a kind of quantity (accelerations at least ω·v)."""
        sol = self.sol
        accel = sol.shown_accel_scale()
        return {"speed": sol.speed_scale(), "accel": accel, "rate": sol.rate_scale(),
                "rate2": accel / self.inst.scale, "len": self.inst.scale}.get(unit, 1.0)

    def clean(self, x: Any, unit: str) -> Any:
        """Numbers rounded to 12 digits, below the contract's zero (1e-9 of the scale) 0."""
        if isinstance(x, tuple):
            return tuple(self.clean(c, unit) for c in x)
        if self.symbolic:
            return x
        return 0.0 if abs(x) <= ZERO * self.scale_of(unit) else number(x)

    def value(self, x: Any, unit: str) -> Value:
        """`x` cleaned (`clean`) as a document `Value` with its kind of unit."""
        return Value(self.clean(x, unit), unit)

    def num(self, x: Any) -> Any:
        """A value (scalar or vector) as floats: symbols at their sample values."""
        if isinstance(x, tuple):
            return tuple(self.inst.num(c) for c in x)
        return self.inst.num(x)

    def drawn(self, x: Any) -> Any:
        """A value as the figures show it: symbols at the numbers the mechanism is drawn at
        (the model's `draw_at`, the solver's sample values for the rest), so that a polygon
        and the mechanism's figure show one mechanism."""
        if isinstance(x, tuple):
            return tuple(self.drawn(c) for c in x)
        if not self.symbolic:
            return self.inst.num(x)
        if self._drawn is None:
            from ..draw.projection import projection
            from ..draw.scene import Numbers, drawing_values

            # only its scalars are read (never projected): the plane's projection, whatever the model's
            self._drawn = Numbers(self.inst, projection(2), drawing_values(self.inst))
        return self._drawn.scalar(x)

    def drawn_values(self) -> dict[str, float]:
        """The numbers a symbolic model's figures are drawn at, by name (empty when numeric)."""
        from ..draw.scene import drawing_values

        return {str(k): v for k, v in sorted(drawing_values(self.inst).items(), key=lambda kv: str(kv[0]))}

    def is_zero(self, x: Any, unit: str) -> bool:
        """Whether `x` is zero at the mechanism's own scale of its kind of quantity
        (`scale_of`)."""
        return self.sol.is_zero(x, self.scale_of(unit))

    def fixed(self, body: str) -> bool:
        """Whether `body` does not move: the frame, or a body welded to it (C5-1.2's inclined
        planes): its points have neither velocity nor acceleration, said, not derived."""
        if not hasattr(self, "_fixed"):
            from .kinds import welds

            fixed, grew = {self.frame}, True
            while grew:
                grew = False
                for j in self.model.joints:
                    if welds(j) and len({j.a, j.b} & fixed) == 1:
                        fixed |= {j.a, j.b}
                        grew = True
            self._fixed = fixed
        return body in self._fixed

    # names -----------------------------------------------------------------------------------
    def shared(self, point: str) -> bool:
        """Whether every body carrying `point` moves alike there (a bare name is enough)."""
        return self.model.share_motion(point, self.model.carriers(point))

    def point_label(self, point: str, body: str) -> str:
        """`B` when B is one point of every body carrying it, else `B∈body`; `O` too for the
        point where `body` is pinned to a body that does not move (C5-E.1's bar OC about O,
        whose wheels also carry a point at O): the fixed pivot is written bare, as the notes
        write v_C = v_O + ω × OC, and the other bodies' points there keep their body
        (O∈wheels). Bodies pinned (or welded) together at the point share one label, the
        first of them (`motion_key`): one velocity, one symbol on the page (twenty-first round
        (e): 001's Step 2 wrote v_{B∈rocker} where the question and the caption say v_{B∈N},
        the block N pinned to the rocker at B; the slides write one v_B for both)."""
        if point in self.inst.points and body in self.model.carriers(point) and (
                self.shared(point) or self.pivot(point, body)):
            return point
        if point in self.centre_points:              # an instant centre: the point of its body there
            return point
        return self.label_body(point, body)

    def label_body(self, point: str, body: str) -> str:
        """`point∈b` for the body b that names the material point of `body` at `point` on the
        page: of the bodies pinned (or welded) to `body` there, the one a question or a driver
        names at that point (001's B@N, C5-2.1's F@front), else the first (`motion_key`)."""
        if point not in self.inst.points or body not in self.model.carriers(point):
            return f"{point}∈{body}"
        mine = next(c for c in self.model.motion_classes(point, self.model.carriers(point)) if body in c)
        named = self._named_at(point)
        return f"{point}∈{next((b for b in mine if b in named), mine[0])}"

    def _named_at(self, point: str) -> list:
        """The bodies the model's questions and velocity drivers name at `point` (B@N)."""
        out = []
        for q in self.model.questions:
            ref = q.target if isinstance(q.target, PointRef) else None
            if ref is None and isinstance(q.target, str) and "@" in q.target:
                ref = self.model.resolve_point(q.target)
            if ref is not None and ref.point == point and ref.body:
                out.append(ref.body)
        for d in self.model.drivers:
            if d.kind == "velocity" and d.driven_point().point == point and d.driven_point().body:
                out.append(d.driven_point().body)
        return out


    def pivot(self, point: str, body: str) -> bool:
        """Whether `body` is pinned (or welded) at `point` to a body that does not move,
        directly or through bodies pinned there: its material point there is at rest."""
        classes = self.model.motion_classes(point, self.model.carriers(point))
        mine = next((c for c in classes if body in c), [])
        return len(mine) > 1 and any(self.fixed(b) for b in mine)

    def motion_key(self, point: str, body: str) -> str:
        """Which material point this is, by its motion: one key for the points of bodies
        pinned (or welded) together there, whatever their labels (B∈N and B∈rocker)."""
        if point not in self.inst.points or body not in self.model.carriers(point):
            return f"{point}∈{body}"
        classes = self.model.motion_classes(point, self.model.carriers(point))
        if len(classes) == 1:
            return point
        return f"{point}∈{next(c for c in classes if body in c)[0]}"

    def labels(self) -> set:
        """The point labels a page may write: the model's points and the names given to
        contacts and centres (`name_position`), which a segment's juxtaposition must not
        confuse (`segment`)."""
        return set(self.inst.points) | set(self._extra)

    def ref(self, point: str, body: str) -> PointRef:
        """The material point `point` of `body`."""
        return PointRef(point, body)


class Segment(str):
    """A segment's name as written (AB, OA1) that keeps its two points: run together, the
    name alone cannot be split back (A1A2), and names may hold `-` themselves (`-x`)."""

    ends: tuple[str, str] = ("", "")


# Pairs of points are written as the slides and notes write segments, by juxtaposition (AB,
# v_BA, OA1, A1A2, v_{A1O}); a separator only where the run-together text splits into two of
# the page's point labels another way (O1A when the model also has a point 1A): the reader
# must find the two points, and "B-A" reads as the difference B − A, pointing the other way.
_LABELS: ContextVar[Optional[Callable[[], set]]] = ContextVar("labels", default=None)


@contextmanager
def point_labels(labels: Callable[[], set]) -> Iterator[None]:
    """Build a page whose point labels (the model's points, contacts, centres placed as points)
    are read from `labels` when a segment is named (`segment`)."""
    token = _LABELS.set(labels)
    try:
        yield
    finally:
        _LABELS.reset(token)


def ambiguous(q: str, p: str, labels: set) -> bool:
    """Whether q + p run together splits into two labels in another way than q | p (O1 + A
    against O + 1A): then the pair needs a separator to be read back."""
    joined, names = q + p, labels | {q, p}
    return any(joined[:k] in names and joined[k:] in names
               for k in range(1, len(joined)) if k != len(q))


def segment(q: str, p: str) -> Segment:
    """The name of the segment from q to p as the notes write it, the two labels run together
    (AB, OA1, A1A2); O1-A only where the juxtaposition is `ambiguous` among the page's labels."""
    source = _LABELS.get()
    labels = source() if source is not None else set()
    seg = Segment(f"{q}-{p}" if ambiguous(q, p, labels) else q + p)
    seg.ends = (q, p)
    return seg


def split_pair(seg: str) -> tuple[str, str]:
    """The two point names of a segment `segment` wrote (OA1, O1-A): its own ends when it
    kept them, else the split into the page's labels (the first, else after one character)."""
    if isinstance(seg, Segment):
        return seg.ends
    if "-" in seg:
        q, p = seg.split("-", 1)
        return q, p
    source = _LABELS.get()
    labels = source() if source is not None else set()
    for k in range(1, len(seg)):
        if seg[:k] in labels and seg[k:] in labels:
            return seg[:k], seg[k:]
    return seg[0], seg[1:]


def read_off(ctx: "Ctx", term: Sym, length: Any, value: Any) -> list:
    """How a rate is read off a rotation term, as the notes write it: a scalar relation of
    magnitudes with the sense as a sign, ω = −|v_H-J| / JH (clockwise) or α = |aᵗ| / r,
    never a vector divided by a vector (v_{O-I17} / I17-O)."""
    sign = _sign(ctx, value)
    return (["−"] if sign < 0 else []) + ["|", term, "| / ", length]


# The longest factor `read_along` simplifies (sympy's operations): a factor a reader reads off
# an arm is short (r, 3·r/5, √3·r); a solved four-bar's closed form (75 operations) took 4 s of
# `sympy.simplify` a read-off and came back no shorter, so it is written as solved.
SIMPLIFIED_OPS = 30


def read_along(ctx: "Ctx", term: Sym, length: Any, rate: Sym, arm: Optional[tuple]) -> Optional[list]:
    """How a rate is read off its term on a symbolic page: from one component of the term,
    "along x: a_H = −α·R ⇒ " (written before the rate, `Derived.lead`), never from a
    magnitude, −|a_H| / GH, which holds only for the sense the figure shows when the data are
    symbols of any value (issue 30, twenty-fifth round d). With the term = rate k × arm and
    arm = (x, y), the term's x component is −rate·y and its y component rate·x: the component
    read is the one that multiplies the rate by the simpler factor (an arm along an axis: its
    one nonzero coordinate), in brackets unless one symbol (along y: v_NP = −ω·(R/2)), and
    the arm's components are written first, so that the factor is read off them: GH = (0, R);
    along x: a_H = −α·R ⇒ (twenty-eighth round (d): a reader must see the length used with its
    value, never "along x: v_QI = ω·IQ" with IQ = 3r/5 printed nowhere). None on a numeric
    page (a known number's magnitude is its value, `read_off`) and in 3D."""
    if not ctx.symbolic or arm is None or len(arm) != 2:
        return None
    try:
        x, y = (float(c) for c in ctx.num(tuple(arm)))
    except (TypeError, ValueError):
        return None
    size = (x * x + y * y) ** 0.5
    if size == 0:
        return None
    import sympy

    parts = {"x": (-1 if y > 0 else 1, abs(sympy.sympify(arm[1]))), "y": (1 if x > 0 else -1, abs(sympy.sympify(arm[0])))}
    if abs(x) <= 1e-9 * size:
        axis = "x"
    elif abs(y) <= 1e-9 * size:
        axis = "y"
    else:
        axis = min(parts, key=lambda k: (sympy.count_ops(parts[k][1]), k))
    sign, part = parts[axis]
    if sympy.count_ops(part) <= SIMPLIFIED_OPS:
        part = sympy.simplify(part)
    value = Value(part, "len")
    factor = [value] if part.is_Symbol else ["(", value, ")"]
    arm_is = [length, " = ", Value(ctx.clean(tuple(arm), "len"), "len"), "; "]
    return [*arm_is, Msg("readoff.along_x" if axis == "x" else "readoff.along_y", {}), " ", term, " = ",
            "−" if sign < 0 else "", rate, "·", *factor, " ⇒ "]


def _sign(ctx: "Ctx", value: Any) -> int:
    """The sign of a scalar as its value is written: a formula's leading minus (−v/R_roda,
    whatever the symbols' values), a number's sign; 0 when it cannot be read."""
    if getattr(value, "free_symbols", None):
        return -1 if value.could_extract_minus_sign() else 1
    try:
        x = float(ctx.num(value))
    except (TypeError, ValueError):
        return 0
    return -1 if x < 0 else (1 if x > 0 else 0)


def composed(absolute: Sym, relative: Sym, drag: Sym, frame: bool = False) -> list:
    """The composition of rotations in the notes' direction, relative + drag = absolute,
    written before a relative rate is read off it: `ω_b = ω_{b rel a} + ω_a ⇒ `. The absolute
    stands on the left even when it is known to be zero (the body is the frame, a pulley fixed
    to the ground): `ω_b = ω_{b rel a} + ω_a = 0 ⇒ `, as the notes write Ω_AB = Ω_REL + Ω_ar,
    never `0 = ω_{b rel a} + ω_a`, which hides which rate is zero."""
    return [absolute, " = ", relative, " + ", drag] + ([" = 0"] if frame else []) + [" ⇒ "]


def fixed_sign(ctx: "Ctx", value: Any) -> int:
    """+1 or −1 when a scalar's sign is known whatever its symbols' values (a number; a
    formula positive or negative for every value of its positive parameters), else 0."""
    import sympy

    if getattr(value, "free_symbols", None):
        expr = sympy.sympify(value)
        return 1 if expr.is_positive else (-1 if expr.is_negative else 0)
    try:
        x = float(ctx.num(value))
    except (TypeError, ValueError):
        return 0
    return (x > 0) - (x < 0)


def magnitude(ctx: "Ctx", sym: Sym, value: Any) -> list:
    """A planar rate as a magnitude's factor (the M row of an equation): the symbol where its
    value is positive whatever the symbols' values, else its absolute value, |ω_wheel|·CJ
    where ω_wheel = −ω (twenty-ninth round (a): a magnitude is never a signed product); a
    rate that is zero has no sign to take off (α_O1A·AO1 with α_O1A = 0)."""
    plain = fixed_sign(ctx, value) > 0 or ctx.is_zero(value, "")
    return [sym] if plain else ["|", sym, "|"]


def omega_sym(body: str, relative_to: Optional[str] = None, vector: bool = False) -> Sym:
    """ω of `body` (relative to another body when given); a vector in 3D."""
    sub_ = body if relative_to is None else f"{body}/{relative_to}"
    return Sym("ω", sub_, vector=vector)


def alpha_sym(body: str, relative_to: Optional[str] = None, vector: bool = False) -> Sym:
    """α of `body` (relative to another body when given); a vector in 3D."""
    sub_ = body if relative_to is None else f"{body}/{relative_to}"
    return Sym("α", sub_, vector=vector)


def model_formula(ctx: "Ctx", exprs: tuple) -> Optional[tuple]:
    """The expressions in the parameters' symbols (a numeric model's formulas), or None when
    they are plain numbers."""
    names = set().union(*(e.names() for e in exprs)) & set(ctx.model.parameters)
    if not names:
        return None
    import sympy

    from ..algebra.backend import Symbolic
    from ..expressions import evaluate

    env = {n: sympy.Symbol(n, positive=True) for n in ctx.model.parameters}
    return tuple(evaluate(e, env, Symbolic()) for e in exprs)


def radius_formula(ctx: "Ctx", spec: Any) -> Optional[Any]:
    """A circle's radius as the model writes it in its parameters (r, not 1 m) in a numeric
    model, or None when it is a plain number or the model is symbolic (its value is then
    the formula already): a relation such as a wheel's rolling, ω = |v_O| / r, is written
    with the symbol, its value being in the Data (nineteenth round b)."""
    if ctx.symbolic or getattr(spec, "radius", None) is None:
        return None
    formula = model_formula(ctx, (spec.radius,))
    return None if formula is None else formula[0]
