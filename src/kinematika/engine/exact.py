"""The exact solve of a symbolic instant: coordinates stand in as symbols, then are put back.

A textbook solves the velocity equations of a four-bar in terms of its link vectors and
only then writes the link vectors out; solving with the written-out coordinates (square
roots of the position analysis, angles) makes every step of the elimination drag them
along. Here each point coordinate that is more than a number or a symbol is replaced by
a stand-in symbol carrying its numeric value at the probe; both levels (velocities, then
accelerations from them) are solved exactly in those terms, where the formulas are small,
and the stand-ins are replaced by the coordinates once, in one `ExactField` that writes
each answer in its canonical form.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from ..algebra.backend import Symbolic
from ..shapes import Circle, Disc
from .instant import Instant
from .motion import BodyState, Motion
from .positions import simple_coordinate


@dataclass
class ExactWorld:
    """The solved instant in stand-ins: where point motions are derived, then revealed."""

    inst: Instant
    motion: Motion            # velocities in coordinate stand-ins, accelerations in those and ...
    compact: Motion           # ... the velocities' own stand-ins (the form accelerations are read in)
    reveal: "Reveal"

    def state(self, body: str, relative_to: str | None = None) -> "RevealedState":
        """The motion (ω, v₀, α, a₀) of `body` seen from `relative_to`, revealed lazily:
        velocities read in the coordinates' stand-ins, accelerations in the velocities' own."""
        v, a = self.motion.state(body, relative_to), self.compact.state(body, relative_to)
        return RevealedState(BodyState(v.omega, v.v0, a.alpha, a.a0), self.reveal)

    def velocity(self, body: str, point: str, relative_to: str | None = None) -> tuple:
        """The velocity of `point` of `body` in stand-ins (reveal it to read it)."""
        return self.motion.point_velocity(body, self.inst.points[point], relative_to)

    def acceleration(self, body: str, point: str, relative_to: str | None = None) -> tuple:
        """The acceleration of `point` of `body` seen from `relative_to`, a_P = a₀ + α × r + ω ×
        (ω × r), in stand-ins (the solved velocities kept as stand-ins, so it reads as a sum of
        terms in ω); reveal it to read it."""
        return self.compact.point_acceleration(body, self.inst.points[point], relative_to)


class RevealedState:
    """A body's (ω, v₀, α, a₀) read from its state in stand-ins, each revealed when asked."""

    __slots__ = ("_done", "_raw", "_reveal")

    def __init__(self, raw: BodyState, reveal: "Reveal") -> None:
        self._raw, self._reveal = raw, reveal
        self._done: dict[str, Any] = {}

    def _get(self, name: str) -> Any:
        if name not in self._done:
            self._done[name] = self._reveal.vector(getattr(self._raw, name))
        return self._done[name]

    omega = property(lambda self: self._get("omega"))
    v0 = property(lambda self: self._get("v0"))
    alpha = property(lambda self: self._get("alpha"))
    a0 = property(lambda self: self._get("a0"))


def stand_in_instant(inst: Instant) -> tuple[Instant, dict]:
    """A copy of `inst` whose compound point coordinates are symbols, and the map back."""
    import sympy

    values: dict[Any, Any] = {}
    probe = dict(inst.probe)
    points: dict[str, tuple] = {}
    for name, coords in inst.points.items():
        out = []
        for axis, c in zip("xyz", coords):
            if simple_coordinate(c):
                out.append(c)
                continue
            s = sympy.Dummy(f"{name}_{axis}", real=True)
            values[s] = c
            probe[s] = inst.num(c)
            out.append(s)
        points[name] = tuple(out)
    standin = replace(inst, points=points, probe=probe, backend=_Plain())
    standin.shapes = {body: [_moved_shape(s, points) for s in shapes]
                      for body, shapes in inst.shapes.items()}
    return standin, values


class _Plain(Symbolic):
    """The algebra of the stand-in world: formulas are kept as built (they are small and
    never shown); only what is revealed is simplified."""

    def sqrt(self, x: Any) -> Any:
        return self.sp.sqrt(x)

    def simplify(self, x: Any) -> Any:
        return x


def stand_in_values(xs: list[Any], inst: Instant, prefix: str) -> tuple[list[Any], dict]:
    """Each compound value of `xs` replaced by a stand-in symbol (its probe value added to
    `inst.probe`), and the map from the stand-ins to the values."""
    import sympy

    out, values = [], {}
    for i, x in enumerate(xs):
        if simple_coordinate(x):
            out.append(x)
            continue
        s = sympy.Dummy(f"{prefix}{i}", real=True)
        values[s] = x
        inst.probe[s] = inst.num(x)
        out.append(s)
    return out, values




def _moved_shape(shape: Any, points: dict[str, tuple]) -> Any:
    """The shape with its centre written with the stand-ins of its centre point."""
    if isinstance(shape, (Circle, Disc)) and shape.center_point in points:
        return replace(shape, center=points[shape.center_point])
    return shape


class Reveal:
    """Writes formulas in stand-ins with the coordinates they stand for, factor by factor.

    A formula is first put in its canonical form in the stand-ins (small), split into its
    factors, and each factor's coordinates written in and brought to canonical form within
    a budget (`fields.canonical`); a factor past the budget is written in as it is. The
    factors' roots come out written alike, so that equal bases combine.
    """

    def __init__(self, values: dict, derived: set | None = None, public: dict | None = None,
                 inst: Instant | None = None, probe: dict | None = None) -> None:
        self.values = values
        self.derived = {s: values[s] for s in derived or ()}   # stand-ins for solved values
        self.public = public or {}     # a solved velocity's stand-in -> its name (omega_link)
        self.inst = inst               # where a name used is recorded (`Instant.names`) ...
        self.probe = probe or {}       # ... with its value, the stand-in's here
        # velocities are named only where coordinates are (formulas past reading anyway) or
        # in exact numbers (no symbols): elsewhere answers stay formulas in the parameters
        if inst is None or not (inst.names or not inst.probe):
            self.public = {}
        self.cache: dict[Any, Any] = {}

    def __call__(self, e: Any) -> Any:
        import sympy

        e = sympy.sympify(e)
        if e.is_Atom and e not in self.values:
            return e
        if e in self.cache:
            return self.cache[e]
        out = self._reveal(e)
        self.cache[e] = out
        return out

    def _reveal(self, e: Any) -> Any:
        import sympy

        from ..algebra.fields import canonical

        if not (e.free_symbols & self.values.keys()):
            return canonical(e)
        # solved velocities stay stand-ins here: each is revealed on its own, so that an
        # acceleration reads as the textbook's sum of terms in ω, not as one expanded formula;
        # when that would still be long, the velocities stay named (omega_link, under `where`)
        e = _in_stand_ins(e)
        named = (bool(self.public) and bool(e.free_symbols & self.public.keys())
                 and _written_ops(e, self, {}) > LONG_OPS)
        out = []
        for f in sympy.Mul.make_args(e):
            base, power = f.as_base_exp()
            deps = sorted(base.free_symbols & self.values.keys(), key=str)   # names recorded
            written = base.xreplace({s: self._name(s) if named and s in self.public  # in one order
                                     else self(self.values[s]) for s in deps})
            out.append(canonical(written) ** power)
        return sympy.Mul(*out)

    def _name(self, s: Any) -> Any:
        """The name of a solved velocity, its formula (revealed) and value at the probe
        recorded with the instant's named quantities (`where`)."""
        name = self.public[s]
        if self.inst is not None and name not in self.inst.names:
            self.inst.names[name] = self(self.values[s])
            self.inst.probe[name] = self.probe[s]
        return name

    def vector(self, v: Any) -> Any:
        """`v` revealed component by component (a scalar revealed as it is, for a planar ω or
        α)."""
        return tuple(self(c) for c in v) if isinstance(v, tuple) else self(v)


LONG_OPS = 3000      # an acceleration longer than this with its velocities written in keeps them
                     # named, in a model with named coordinates or without symbols


def _written_ops(e: Any, reveal: Reveal, memo: dict) -> int:
    """The size of `e` with each stand-in written in (as revealed), without writing it."""
    from ..algebra.fields import ops

    if e in memo:
        return memo[e]
    if e in reveal.values:
        out = ops(reveal(reveal.values[e]))
    elif e.is_Atom:
        out = 0
    else:
        args = e.args
        out = (len(args) - 1 if e.is_Add or e.is_Mul else 1) + sum(_written_ops(a, reveal, memo) for a in args)
    memo[e] = out
    return out


FACTOR_OPS = 40     # stand-in formulas factored up to this size (then split into N/D only)


def _in_stand_ins(e: Any) -> Any:
    """e over one denominator in the stand-ins, factored when small enough."""
    import sympy

    from ..algebra.fields import ExactField, TooLarge, factored, ops

    try:
        field = ExactField([e], roots=False, max_terms=4 * FACTOR_OPS)
        e = field.back(field.to(e))
    except TooLarge:
        return e
    except ZeroDivisionError:
        return e
    if ops(e) <= FACTOR_OPS:
        return factored(e)
    num, den = sympy.fraction(e)
    return sympy.Mul(num, sympy.Pow(den, -1, evaluate=False), evaluate=False)
