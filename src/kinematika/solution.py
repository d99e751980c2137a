"""The result of solving an instant: the model, its evaluated geometry and the motion.

Views (JSON, tables, figures, explanations) read from a `Solution`; they never solve.
Values are backend scalars: floats, or sympy expressions for a symbolic model.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Optional

from .algebra.vectors import dot
from .engine.instant import Instant, instantiate
from .engine.motion import BodyState, Motion
from .engine.system import InstantSolver
from .engine.terms import MECHANICS, Terms
from .errors import KinematikaError
from .model.model import Model, PointRef

ZERO = 1e-9   # the contract's threshold, relative to the model's own scale


@dataclass
class Solution:
    """A mechanism solved at its instant: what every view reads.

    The motion of every body is its twist at this instant, ω and v₀ (the velocity of the
    body's point at the reference), and their derivatives α and a₀; a point P of body B then
    moves as the rigid body does:

        v_P = v₀ + ω × (P − O),   a_P = a₀ + α × (P − O) + ω × (ω × (P − O)).

        >>> sol = kinematika.solve("examples/four_bar.yaml")
        >>> sol.velocity("B@coupler"), sol.omega("rocker"), sol.acceleration("B", relative_to="crank")

    Numbers are floats, or sympy formulas when the model has symbols (`symbolic`).
    """

    model: Model
    inst: Instant
    motion: Motion
    solver: InstantSolver
    _scales: Optional[tuple[float, float]] = field(default=None, repr=False)
    _fields: Optional[tuple] = field(default=None, repr=False)

    @property
    def symbolic(self) -> bool:
        """Whether the answers are exact formulas (a parameter left as a symbol)."""
        return self.inst.symbolic

    @property
    def space(self) -> Any:
        """The vectors' space (planar or 3D: `algebra.vectors.Space`)."""
        return self.inst.space

    @property
    def dof(self) -> int:
        """The mechanism's degrees of freedom, counted by the rank of its joints' conditions."""
        return self.solver.analysis.diagnosis.dof if self.solver.analysis else 0

    @property
    def diagnosis(self) -> Any:
        """The count behind `dof` (`engine.mobility.Diagnosis`): n unknowns, dof = n − rank of
        the joints' rows, the drivers' independent conditions and the velocity system's
        condition number σ_max/σ_n (large near a dead point); None when nothing moves."""
        return self.solver.analysis.diagnosis if self.solver.analysis else None

    # the motion of bodies and points --------------------------------------------------------
    def geometry(self, joint_id: str) -> Any:
        """What joint `joint_id` is at this instant (`joints.JointGeometry`): its point, unit
        directions and their normals, and the contact of a touching pair (`.contact`: its
        point J, common normal n, radii of curvature). For example
        ``sol.geometry("j3").contact.point`` is where a cam touches its follower."""
        return self.solver.geos[joint_id]

    def state(self, body: str, relative_to: str | None = None) -> BodyState:
        """The motion of `body` seen from `relative_to` (default: the fixed frame)."""
        names = [body] if relative_to is None else [body, relative_to]
        for name in names:
            if not isinstance(name, str) or name not in self.model.bodies:
                raise KinematikaError("schema", "unknown-body", "", body=name, bodies=list(self.model.bodies))
        frame = self.frame_of(relative_to)
        if self.exact is not None and frame is not None:
            return self.exact.state(body, frame)
        return self.motion.state(body, frame)

    @property
    def exact(self) -> Any:
        """A symbolic solution in stand-ins (`engine.exact`): point motions are derived there,
        where formulas are small, and revealed once; None for a numeric one."""
        return getattr(self.solver, "exact", None)

    def frame_of(self, relative_to: str | None) -> str | None:
        """The body an answer is relative to, or None for the fixed frame (named or not)."""
        return None if relative_to in (None, self.model.frame) else relative_to

    def point(self, ref: PointRef | str) -> PointRef:
        """A material point from ``P@body`` or a bare ``P``."""
        return self.model.resolve_point(ref)

    def position(self, ref: PointRef | str) -> tuple:
        """Where point `ref` is at this instant (its coordinates), e.g. ``sol.position("B")``."""
        name = ref.point if isinstance(ref, PointRef) else ref.partition("@")[0]
        return self.inst.points[name]

    def velocity(self, ref: PointRef | str, relative_to: str | None = None) -> tuple:
        """v_P = v₀ + ω × (P − O) of material point `ref` (``"B@rocker"``, or a bare ``"B"``
        shared by its bodies), as seen from body `relative_to` (default: the fixed frame):
        ``sol.velocity("B", relative_to="crank")``."""
        ref = self.point(ref)
        if self.exact is not None:
            self.state(ref.body, relative_to)            # the names checked
            raw = self.exact.velocity(ref.body, ref.point, self.frame_of(relative_to))
            return self.exact.reveal.vector(raw)
        return self.motion.velocity(self.state(ref.body, relative_to), self.position(ref))

    def acceleration(self, ref: PointRef | str, relative_to: str | None = None) -> tuple:
        """a_P = a₀ + α × (P − O) + ω × (ω × (P − O)) of material point `ref`, as seen from
        `relative_to` (its acceleration relative to that body: drag and Coriolis taken out):
        ``sol.acceleration("B@coupler")``."""
        ref = self.point(ref)
        if self.exact is not None:
            self.state(ref.body, relative_to)
            raw = self.exact.acceleration(ref.body, ref.point, self.frame_of(relative_to))
            return self.exact.reveal.vector(raw)
        if self.motion.terms.mechanics:
            return self.motion.acceleration(self.state(ref.body, relative_to), self.position(ref))
        self.state(ref.body, relative_to)                # the names checked
        return self.motion.point_acceleration(ref.body, self.position(ref), self.frame_of(relative_to))

    def omega(self, body: str, relative_to: str | None = None) -> Any:
        """ω of `body` (planar: a number, counter-clockwise positive; 3D: a vector), relative
        to `relative_to`: ω_B/F = ω_B − ω_F. ``sol.omega("coupler")``."""
        return self.state(body, relative_to).omega

    def alpha(self, body: str, relative_to: str | None = None) -> Any:
        """α of `body`, relative to `relative_to` the derivative seen from that body:
        α_B/F = α_B − α_F − ω_F × ω_B/F. ``sol.alpha("rocker")``."""
        return self.state(body, relative_to).alpha

    def point_fields(self) -> tuple[list[str], Any, Any, Any]:
        """Every material point (file order), named ``point@body``, with its position, velocity
        and acceleration as (n, dim) float arrays, computed at once from the body twists
        (numeric instants)."""
        if self._fields is None:
            import numpy as np

            from .model.point_ref import written

            pairs = self.model.material_pairs()
            points = self.inst.points
            places = np.array([points[p] for p, _ in pairs], dtype=float).reshape(len(pairs), -1)
            velocity, acceleration = self.motion.fields([b for _, b in pairs], places)
            self._fields = (written(pairs), places, velocity, acceleration)
        return self._fields

    # zero tests at the model's scale --------------------------------------------------------
    def scales(self) -> tuple[float, float]:
        """Characteristic speed and acceleration of the whole mechanism (numerically): the
        largest point speed and acceleration, and the rates' ω·L, α·L and ω²·L."""
        if self._scales is None:
            length = self.inst.scale
            speeds, accels = [0.0], [0.0]
            rates = [0.0]
            if self.symbolic:
                # the numbers come from the formulas in stand-ins, when solved there: nothing revealed
                world = self.exact
                inst = world.inst if world is not None else self.inst
                motion = world.motion if world is not None else self.motion
                for ref in self.model.material_points():
                    state, point = motion.states[ref.body], inst.points[ref.point]
                    speeds.append(_norm(inst.numvec(motion.velocity(state, point))))
                    accels.append(_norm(inst.numvec(motion.acceleration(state, point))))
                for body in self.model.bodies:
                    s = motion.states[body]
                    rates.append(_norm(inst.numvec(self.space.rot_components(s.omega))))
                    speeds.append(rates[-1] * length)
                    accels.append(_norm(inst.numvec(self.space.rot_components(s.alpha))) * length)
            else:                        # the same maxima, from arrays
                _, _, velocity, acceleration = self.point_fields()
                omega, _, alpha, _ = self.motion.arrays()
                rates.append(_largest_norm(omega))
                speeds += [_largest_norm(velocity), rates[-1] * length]
                accels += [_largest_norm(acceleration), _largest_norm(alpha) * length]
            # a body turning at ω has accelerations of order ω² L even where none is asked
            accels.append(max(rates) ** 2 * length)
            self._scales = (max(speeds), max(accels))
        return self._scales

    def is_zero(self, value: Any, scale: float) -> bool:
        """Below 1e-9 times `scale` numerically; exactly zero symbolically."""
        parts = value if isinstance(value, tuple) else (value,)
        if self.symbolic:
            from .algebra.fields import canonical

            if self.size(parts) > 1e-9 * max(scale, 1e-300):
                return False
            return all(canonical(p) == 0 or _vanishes(p) for p in parts)
        return _norm([float(p) for p in parts]) <= ZERO * scale

    def speed_scale(self) -> float:
        """The mechanism's characteristic speed (`scales`)."""
        return self.scales()[0]

    def rate_scale(self) -> float:
        """Its characteristic rate: the speed over the model's size."""
        return self.scales()[0] / self.inst.scale

    def accel_scale(self) -> float:
        """Its characteristic acceleration (`scales`)."""
        return self.scales()[1]

    def shown_accel_scale(self) -> float:
        """The scale below which views show an acceleration as zero: at least ω·v."""
        return max(self.accel_scale(), self.rate_scale() * self.speed_scale())

    def size(self, vec: tuple) -> float:
        """|vec| as a number (at the probe values when symbolic), for zero tests."""
        return _norm(self.inst.numvec(vec))

    def norm(self, vec: tuple) -> Any:
        """|vec|, as a number or a formula."""
        return self.inst.backend.sqrt(dot(vec, vec))



def _norm(values: Any) -> float:
    return math.hypot(*(float(v) for v in values))     # no overflow of the squares


def _largest_norm(rows: Any) -> float:
    """The largest Euclidean norm of an array's rows (no overflow of the squares), 0 for none."""
    import numpy as np

    if not len(rows):
        return 0.0
    norms = np.abs(rows[:, 0])
    for k in range(1, rows.shape[1]):
        norms = np.hypot(norms, rows[:, k])
    return float(norms.max())


def _vanishes(x: Any) -> bool:
    """Whether an expression that the canonical form did not reduce to 0 is zero anyway: a
    trigonometric identity (sin² + cos² − 1) is not seen by the rational canonical form.
    Tested at three random points of the symbols' domains with 40 significant digits, where
    a nonzero expression is, with probability 1, not within 1e-30 of zero."""
    import random

    import sympy

    free = sorted(getattr(x, "free_symbols", ()), key=str)
    rng = random.Random(20261124)
    for _ in range(3):
        at = {s: sympy.Float(rng.uniform(0.2, 1.3) if s.is_positive else rng.uniform(-1.3, 1.3), 40)
              for s in free}
        value = sympy.N(x.subs(at), 40)
        if not value.is_number or abs(complex(value)) > 1e-30:
            return False
    return True


def solve_model(model: Model, symbolic: bool | None = None, terms: Terms = MECHANICS) -> Solution:
    """The instant `model` describes, solved: its velocity and acceleration systems
    (`engine.system`), numerically, or exactly when it has symbols (or `symbolic`); `terms`
    solves it as a student with a known mistake would (`engine.terms`, the exercises'
    diagnoses), else as it is."""
    inst = instantiate(model, symbolic)
    solver = InstantSolver(inst, terms=terms)
    return Solution(model, inst, solver.solve(), solver)
