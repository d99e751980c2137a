"""The bodies a move of a model with symbolic parameters carries, found in closed form.

`move` on a model with symbols turns its input body by the amount, about its pivot (or
shifts it along its guide), and the constructions follow (`engine.turns`). Every other
body is carried too when its pose after the move is a closed form of the input's:

- by an angle that is a linear form in the inputs' turns: bodies rolling on each other
  (circles, no slip) turn by the rolling ratios, Willis's equations solved
  (`joints.rolling.arc_slip` = 0 for each pair, the line of centres turning with a body
  that holds both: a planet of radius r on a fixed sun of radius R, its arm turned by ψ,
  turns by (R + r) ψ / r); or a body turns as another does (a slider on the frame, a body
  held by a driver, or welded);
- by two of its places: its pivot and a point that turns with it, its own or a pin in a
  slot of it through the pivot (a Geneva wheel): the direction between them turns as it.

Every candidate is tried against the numeric motion of the same move at the symbols'
probe values (`Path`, each row of the sweep), and kept only if it agrees with every row;
the points such a body carries are then placed by its turn.
"""
from __future__ import annotations

import dataclasses
import functools
import math
from dataclasses import dataclass
from typing import Any, Iterator, Optional

import numpy as np

from ..engine.instant import Instant, instantiate
from ..engine.turns import moves_with, turn_for
from ..errors import KinematikaError, Said
from ..expressions import parse
from ..joints.rolling import arc_slip
from ..joints.tangency import circles_tangency
from ..model.model import Model
from ..point_pair import PointPair
from ..model.motion_sections import Turn
from ..shapes import Circle

ANGLE_TOLERANCE = 1e-6          # radians: a candidate's turn against the sweep's, every row
PLACE_TOLERANCE = 1e-7          # of the model's size: a place against the sweep's

Form = dict[int, Any]           # a turn as a linear form in the inputs' turns: index -> coefficient


@dataclass
class Path:
    """A move made numerically at the symbols' probe values: per row (row 0 the drawing), each
    body's angle since the drawing (radians), each material point's place ("P@body"), and
    each input's increment (its body's turn in radians, or its shift); and every point
    name's place at the end."""

    angles: dict[str, np.ndarray]
    places: dict[str, np.ndarray]
    inputs: np.ndarray
    final: dict[str, np.ndarray]


@dataclass
class Input:
    """A body the move drives from the frame: its turn, and its angle as a form."""

    turn: Turn
    form: Form


def carried_turns(model: Model, inputs: list[Input], path: Path, values: dict[str, str],
                  inst: Instant) -> list[Turn]:
    """The inputs' turns and the turns of every body found to follow them in closed form
    (`inst`: the drawing, exact; `values`: the probe values the path was made at)."""
    turns = _Finder(model, inputs, path, values, inst).run()
    moved = dataclasses.replace(model, turns=turns)
    used = {id(turn_for(moved, name)) for name in model.points}
    inputs_ = {i.turn.body for i in inputs}
    return [t for t in turns if t.body in inputs_ or id(t) in used or fixture(model, t.body)]


def fixture(model: Model, body: str) -> "Said | str":
    """What of `body` is fixed in it by numbers, which only its turn can carry (a shape's
    place or direction, a joint's direction, as a message), or ''."""
    for s in model.bodies[body].shapes:
        if any(getattr(s, k, ()) for k in ("center", "through")) or not all(
                isinstance(getattr(s, k, None), (PointPair, type(None))) for k in ("direction", "axis", "normal")):
            return Said("fixture-shape", shape=type(s).__name__.lower())
    for j in model.joints:
        fixed_in = j.kind.along_body(j)
        if fixed_in == body and j.along is not None and not isinstance(j.along, PointPair):
            return Said("fixture-joint", joint=j.id)
    return ""


def placed(model: Model, turns: list[Turn], values: dict[str, str]) -> Optional[dict[str, np.ndarray]]:
    """Every point's place in the moved model at the probe values, numerically (None when
    these turns cannot place them)."""
    from ..model.overrides import with_parameters

    twin = with_parameters(dataclasses.replace(model, move={}, turns=turns), values)
    try:
        points = instantiate(twin, False).points
    except KinematikaError:
        return None
    return {k: np.asarray(v, dtype=float) for k, v in points.items()}


def wrapped(x: Any) -> Any:
    """Angles brought to (−π, π]."""
    return np.remainder(np.asarray(x) + math.pi, 2 * math.pi) - math.pi


class _Finder:
    """Bodies' turns found round by round: a round places the points with the turns known so
    far, and tries, for each body still unknown, an angle and then two places."""

    def __init__(self, model: Model, inputs: list[Input], path: Path, values: dict[str, str],
                 inst: Instant) -> None:
        self.model, self.path, self.values, self.inst = model, path, values, inst
        self.turns = {i.turn.body: i.turn for i in inputs}
        self.forms: dict[str, Form] = {model.frame: {}, **{i.turn.body: i.form for i in inputs}}
        self.increments = [i.turn.angle.text if i.turn.angle is not None else "0" for i in inputs]
        drawn = placed(model, [], values)
        assert drawn is not None                      # the drawing itself was instantiated
        self.drawn = drawn
        self.tol = PLACE_TOLERANCE * inst.scale
        self.tried: set[str] = set()
        self.rolled = self._rolling()

    def run(self) -> list[Turn]:
        while True:
            known = self._known()
            found = False
            for body in self.model.moving_bodies:
                if body in self.turns or body in self.tried:
                    continue
                turn = self._by_angle(body, known) or self._by_places(body, known)
                if turn is None:
                    continue
                self.turns[body] = turn
                if placed(self.model, list(self.turns.values()), self.values) is None:
                    del self.turns[body]
                    self.forms.pop(body, None)
                    self.tried.add(body)
                    continue
                found = True
            if not found:
                return list(self.turns.values())

    def _known(self) -> set[str]:
        """The point names the turns so far place where the numeric move does."""
        now = placed(self.model, list(self.turns.values()), self.values) or {}
        return {n for n, p in now.items() if np.max(np.abs(p - self.path.final[n])) <= self.tol}

    # by an angle -----------------------------------------------------------------------------
    def _by_angle(self, body: str, known: set[str]) -> Optional[Turn]:
        pivot = next(self._pivots(body, known), None)
        if pivot is None:
            return None
        for form in self._angles(body):
            if self._agrees(body, self._numeric(form)):
                self.forms[body] = form
                return Turn(body, pivot=pivot, angle=parse(self._text(form)))
        return None

    def _angles(self, body: str) -> Iterator[Form]:
        """Candidate turns of `body`: its rolling ratio, then the turns of the bodies it is
        joined to, of the frame, of the others."""
        model = self.model
        if body in self.rolled:
            yield self.rolled[body]
        joined = [j for j in model.joints if body in (j.a, j.b)]
        partners = [j.b if j.a == body else j.a for j in joined]
        for other in dict.fromkeys([*partners, model.frame, *self.forms]):
            if other in self.forms and other != body:
                yield self.forms[other]

    def _rolling(self) -> dict[str, Form]:
        """Willis's method: a rolling circle pair whose centres one body holds rolls equal arcs,
        `arc_slip` = 0 with ψ that body's turn. These equations, linear in the bodies' turns,
        solved with the inputs' turns given: the turns they fix that agree with the path."""
        import sympy

        steps = [sympy.Dummy(f"step{i}") for i in range(len(self.increments))]
        phi = {b: sum((c * steps[i] for i, c in f.items()), sympy.Integer(0)) for b, f in self.forms.items()}
        unknown = {b: sympy.Dummy(b) for b in self.model.moving_bodies if b not in phi}
        phi.update(unknown)
        equations = []
        for j in self.model.joints:
            pair = self._circles(j) if j.kind.rolls else None
            holders = self._holding(pair[0][1].center, pair[1][1].center, among=self.model.bodies) if pair else []
            if pair and holders:
                (ca, na), (cb, nb) = pair
                rho_a, rho_b = circles_tangency(na, nb).places(ca.radius, cb.radius)
                equations.append(arc_slip(rho_a, rho_b, phi[holders[0]], phi[j.a], phi[j.b]))
        solutions = sympy.linsolve(equations, list(unknown.values())) if equations and unknown else sympy.EmptySet
        out: dict[str, Form] = {}
        for body, turn in zip(unknown, next(iter(solutions), ())):
            if turn.free_symbols & set(unknown.values()):
                continue                                  # not fixed by the rolling alone
            form = {i: _simplified(sympy.diff(turn, s)) for i, s in enumerate(steps)}
            form = {i: c for i, c in form.items() if c != 0}
            if self._agrees(body, self._numeric(form)):
                out[body] = form
        return out

    def _circles(self, j: Any) -> Optional[tuple[tuple[Circle, Circle], tuple[Circle, Circle]]]:
        """The touching circles of a rolling pair, exact and at the probe values."""
        numeric = self.shapes
        best = None
        for ea, na in zip(self.inst.shapes[j.a], numeric[j.a]):
            for eb, nb in zip(self.inst.shapes[j.b], numeric[j.b]):
                if isinstance(na, Circle) and isinstance(nb, Circle):
                    gap = abs(circles_tangency(na, nb).gap)
                    if best is None or gap < best[0]:
                        best = (gap, (ea, na), (eb, nb))
        return None if best is None else (best[1], best[2])

    @functools.cached_property
    def shapes(self) -> dict[str, list]:
        """The bodies' shapes at the probe values (the drawing)."""
        from ..model.overrides import with_parameters

        return instantiate(with_parameters(self.model, self.values), False).shapes

    def _holding(self, *centres: tuple, among: Any) -> list[str]:
        """The bodies (`among`) that carry points at every one of `centres`."""
        out = []
        for body in among:
            names = self.model.bodies[body].points
            if all(any(np.allclose(self.drawn[n], c, atol=self.tol, rtol=0) for n in names)
                   for c in centres):
                out.append(body)
        return out

    def _numeric(self, form: Form) -> np.ndarray:
        """The form's turn at every row of the path."""
        total = np.zeros(len(self.path.inputs))
        for i, coefficient in form.items():
            total = total + self.inst.num(coefficient) * self.path.inputs[:, i]
        return total

    def _agrees(self, body: str, turn: np.ndarray) -> bool:
        return bool(np.all(np.abs(wrapped(self.path.angles[body] - turn)) <= ANGLE_TOLERANCE))

    def _text(self, form: Form) -> str:
        import sympy

        terms = [f"({sympy.sstr(c)})*({self.increments[i]})" for i, c in sorted(form.items()) if c != 0]
        return " + ".join(terms) or "0"

    # by two places ------------------------------------------------------------------------------
    def _pivots(self, body: str, known: set[str]) -> Iterator[str]:
        """`body`'s points whose places are known and are its material points there."""
        for name in self.model.bodies[body].points:
            if name in known and np.max(np.abs(self.path.places[f"{name}@{body}"][-1]
                                               - self.path.final[name])) <= self.tol:
                yield name

    def _by_places(self, body: str, known: set[str]) -> Optional[Turn]:
        """A turn that takes the drawn direction from a pivot of `body` to another known place
        to the present one: a point of the body (rigid), else a point that turns with it."""
        model = self.model
        for pivot in self._pivots(body, known):
            others = [n for n in known if n != pivot]
            own = [n for n in others if moves_with(model, n, body)]
            for toward in own + [n for n in others if n not in own]:
                if self._turns_with(body, pivot, toward):
                    return Turn(body, pivot=pivot, toward=toward, slides=toward not in own)
        return None

    def _turns_with(self, body: str, pivot: str, toward: str) -> bool:
        """Whether the direction pivot→toward turns as `body` at every row."""
        if not self.model.carriers(toward):
            return False
        rows = self.path.places[f"{toward}@{self.model.place_owner(toward)}"]
        d = rows - self.path.places[f"{pivot}@{body}"]
        if np.min(np.hypot(d[:, 0], d[:, 1])) <= 1e-6 * self.inst.scale:
            return False
        turn = np.arctan2(d[:, 1], d[:, 0]) - math.atan2(d[0, 1], d[0, 0])
        return self._agrees(body, turn)


def _simplified(x: Any) -> Any:
    import sympy

    return sympy.factor(sympy.cancel(x)) if isinstance(x, sympy.Basic) else x
