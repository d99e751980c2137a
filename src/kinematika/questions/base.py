"""What a kind of question is: the base class every question module fills in.

A question asks one thing of a solved instant about a target — a material point, a body or
a joint — seen from the fixed frame or from a body (`relative_to`): `{icr: coupler}`,
`{velocity: B@rocker, relative_to: crank}`. What a kind means lives in its module, as a
joint kind's does (`kinematika.joints`), and the rest of kinematika asks the kind through
this class (never by comparing the question's name):

- what the file says: what its target names (`about`: a material point, a body or a
  joint, `target_joint` checking the joint), whether it takes a `moving` body (a
  composition's), the models it exists in (`dimensions`);
- what it needs solved (`level`): the velocities only, or the accelerations too (an
  explanation stops at the velocities when nothing asked needs more);
- how it is answered (`answer`, the formula in its function's docstring): raw backend
  scalars (floats or sympy formulas), read from the solution through `Solved`;
- the kind of quantity it answers (`unit_kind`, whose unit `report.units` writes) and that of
  each field of a compound answer (`fields`), which the JSON's round-off, the terminal's
  table and an exercise's key — one row per number along its fields — read;
- whether its answer is a column of the answer's tables (`column`: a body's ω and α, a
  material point's velocity and acceleration, in the fixed frame; these are the contract's
  default questions, of every body and point), and whether the page's builder offers it on
  a selected point or body (`page`);
- how a figure draws it (`draw`: which of a `Figure`'s ways), how an explanation names it
  and each part of its answer (`label`, `part`, in the explanation's `Words`) and which
  sections of an explanation work it out (`explain`: which of its `Steps`).

The views pass their own toolkits in (a figure, the explanation's words) and the kind calls
their methods, and the solution is read only through its methods (`Solved`), so a question
module needs nothing of the views, the model or the solution: the joints' pattern (their
rows receive the level `lv`), which lets the model's reader ask the kinds what a question
file may say.

Adding a kind is its module (a subclass with `KIND = ...`), its line in `MODULES`
(`kinematika.questions`), its catalogue lines (the explanation's `ask-NAME`, the
exercises' `ask-NAME`, the page's `q-NAME` when `page`) and its docs (docs/questions.md).
"""
from __future__ import annotations

from typing import Any, ClassVar, Literal, Optional, Protocol

from ..errors import KinematikaError

About = Literal["point", "body", "joint"]          # what a question's target names
Level = Literal["velocity", "acceleration"]        # what it needs solved
Quantity = Literal["position", "velocity", "acceleration", "omega", "alpha"]   # report.units' kinds


class Asked(Protocol):
    """What a kind reads of one question (`model.Question`)."""

    kind: str
    index: int
    target: Any                        # a body's or joint's name, or a `PointRef`
    relative_to: Optional[str]
    moving: Optional[str]

    @property
    def name(self) -> str:
        """The body or joint asked of."""

    @property
    def where(self) -> str:
        """Where the question is written, for errors: ``ask[1]``."""


class Solved(Protocol):
    """What a kind reads of a solved instant (`solution.Solution`): positions, velocities and
    accelerations of material points, bodies' states and rates, the scales against which a
    value is zero, and the model, instant and motion for what needs more."""

    model: Any
    inst: Any
    solver: Any                        # the instant's solver: its joints' geometries (`geos`)

    @property
    def symbolic(self) -> bool:
        """Whether the values are formulas."""

    @property
    def space(self) -> Any:
        """The planar or spatial vector operations."""

    @property
    def motion(self) -> Any:
        """The bodies' twists and their derivatives."""

    @property
    def exact(self) -> Any:
        """The exact world of a model with named coordinates, or None."""

    def state(self, body: str, relative_to: Optional[str] = None) -> Any:
        """A body's motion (ω, v₀, α, a₀) relative to another body."""

    def frame_of(self, relative_to: Optional[str]) -> Optional[str]:
        """The frame a `relative_to` names."""

    def geometry(self, joint_id: str) -> Any:
        """A joint's geometry at this instant (its contact)."""

    def point(self, ref: Any) -> Any:
        """A material point named by text or reference."""

    def position(self, ref: Any) -> Any:
        """A point's place."""

    def velocity(self, ref: Any, relative_to: Optional[str] = None) -> Any:
        """A material point's velocity relative to a body."""

    def acceleration(self, ref: Any, relative_to: Optional[str] = None) -> Any:
        """A material point's acceleration relative to a body."""

    def omega(self, body: str, relative_to: Optional[str] = None) -> Any:
        """A body's angular velocity relative to another."""

    def alpha(self, body: str, relative_to: Optional[str] = None) -> Any:
        """A body's angular acceleration relative to another, as seen from it."""

    def is_zero(self, value: Any, scale: float) -> bool:
        """Whether a value is zero at the model's scale."""

    def speed_scale(self) -> float:
        """The model's largest speed."""

    def rate_scale(self) -> float:
        """The model's largest rate."""

    def accel_scale(self) -> float:
        """The model's largest acceleration."""

    def size(self, vec: Any) -> float:
        """A vector's magnitude as a number."""

    def norm(self, vec: Any) -> Any:
        """A vector's magnitude as a backend scalar."""


class Figure(Protocol):
    """The ways a figure draws an asked quantity (`draw.results`); a kind's `draw` picks its."""

    def arrow(self, q: Asked, level: Level) -> None:
        """An arrow of the point's velocity or acceleration, at the point."""

    def composition(self, q: Asked) -> None:
        """A composition's parts (drag, and Coriolis for accelerations) at its point."""

    def instant_centre(self, q: Asked) -> None:
        """The body's instant centre, with the lines it lies on."""

    def path_circle(self, q: Asked) -> None:
        """The osculating circle of the point's path, labelled with its radius."""

    def acceleration_pole(self, q: Asked) -> None:
        """The body's point of zero acceleration, Γ."""

    def contact_point(self, q: Asked) -> None:
        """The contact point of a joint, J."""

    def screw_axis(self, q: Asked) -> None:
        """The body's instantaneous screw axis (3D)."""


class Steps(Protocol):
    """The sections of an explanation that work an asked quantity out (`explain`); a kind's
    `explain` says which (none: its answer is read off the solved motion, in the answers)."""

    def instant_centre(self, q: Asked) -> None:
        """The instant centres' section finds it (and checks it against the velocity field)."""

    def path_curvature(self, q: Asked) -> None:
        """The curvature section: a = aᵗ + aⁿ, ρ = |v|² / |aⁿ| and the centre."""

    def contact_points(self, q: Asked) -> None:
        """The contact section: the three coincident points, each from an equation."""

    def composition(self, q: Asked) -> None:
        """The composition of motions (drag, relative, Coriolis) worked out in 3D."""


class Words(Protocol):
    """What an explanation writes an asked quantity with (`explain.answers`): its document's
    symbols and messages, and the names of the question's point, bodies and joint as the
    notes write them."""

    planar: bool

    def sym(self, base: str, sub: str = "", sup: str = "", vector: bool = True, sub_key: str = "") -> Any:
        """A symbol: v_B, ρ_C (not a vector), v_{arr,B} (`sub_key`: a catalogue word)."""

    def msg(self, key: str, **args: Any) -> Any:
        """A message of the explanation's catalogue with its arguments."""

    def inline(self, items: list) -> Any:
        """A short formula of strings and symbols, as a message's argument."""

    def name(self, text: str, kind: str = "point") -> Any:
        """A name from the model set as a point's, a body's or a joint's."""

    def ref(self, q: Asked) -> Any:
        """The question's material point (`PointRef`)."""

    def point(self, q: Asked) -> str:
        """The question's point as the notes label it (B, A∈4)."""

    def motion(self, q: Asked) -> str:
        """The subscript of the point's motion seen from the question's frame (B, A∈4/2)."""

    def frame(self, q: Asked) -> Any:
        """The question's frame of reference as a body's name (the fixed frame by default)."""

    def rate(self, base: str, q: Asked, vector: bool) -> Any:
        """ω or α (`base`) of the question's body, relative to its frame when not fixed."""

    def contact(self, q: Asked) -> tuple[str, str, str]:
        """The contact point's name of the question's joint, and the joint's bodies a and b."""

    def geometric(self, level: str, name: str) -> Any:
        """v_J^geom (a_J^geom): the geometric contact point's motion."""


class QuestionKind:
    """A kind of question: its key in model files and everything it means (see the module's
    docstring). One instance per kind, registered in `kinematika.questions.QUESTIONS`."""

    name: ClassVar[str] = ""
    summary: ClassVar[str] = ""             # one line for the docs
    about: ClassVar[About] = "body"         # what its target names
    moving: ClassVar[bool] = False          # it takes (and needs) a `moving` body
    dimensions: ClassVar[tuple[int, ...]] = (2, 3)   # the models it may be asked in
    level: ClassVar[Level] = "velocity"     # the velocities suffice, or it needs accelerations
    unit_kind: ClassVar[Quantity] = "position"   # the kind of quantity a plain answer is
    fields: ClassVar[dict[str, Optional[Quantity]]] = {}   # a compound answer's fields (and
                                            # parts') kinds of quantity; None: a unit vector or a
                                            # pure number; a field not listed (a composition's
                                            # `drag`) is of its parent's kind
    column: ClassVar[bool] = False          # the answer is a column of the answer's tables
    page: ClassVar[bool] = False            # the page's builder offers it
    linear: ClassVar[bool] = False          # its answer is linear in the drivers' rates and
                                            # accelerations (an exercise carries a wrong one)
    needs_rate: ClassVar[bool] = True       # an explanation of it needs its body's ω (an instant
                                            # centre's does not: the joints place it)
    rows_by_part: ClassVar[bool] = False    # an explanation's answers table gives each part
                                            # labelled by its own symbol a row of its own (the
                                            # notes' final list of C5-1.8: one line a point)
    placed: ClassVar[bool] = False          # its answer is a centre placed from a point (planar):
                                            # the answers table also gives its distance from
                                            # that point, as the notes do ((2/5)r from A1)
    working: ClassVar[frozenset[str]] = frozenset()   # fields that are the working of the
                                            # answer, not the answer: an explanation derives
                                            # them in a step and its answers table leaves them
                                            # out (the intrinsic split's |v|, t, aᵗ · t, |aⁿ|)

    def answer(self, sol: Solved, q: Asked) -> Any:
        """The raw answer (backend scalars, nested in dicts for a compound answer)."""
        raise NotImplementedError

    # the model file ----------------------------------------------------------------------
    def target_joint(self, text: str, joints: list, where: str) -> str:
        """The joint a question about a joint names, checked (`joints`: the model's, with
        `id`): an unknown joint is a `schema` error naming the question's key."""
        if not any(j.id == text for j in joints):
            raise KinematikaError("schema", "unknown-joint", where, joint=text, joints=[j.id for j in joints])
        return text

    # views -------------------------------------------------------------------------------
    def draw(self, figure: Figure, q: Asked) -> None:
        """How a figure shows the answer: one of `figure`'s ways; by default not drawn."""

    def explain(self, steps: Steps, q: Asked) -> None:
        """Which sections of an explanation work it out; by default none (its answer is
        read from the solved motion, in the answers' table)."""

    def label(self, words: Words, q: Asked) -> Any:
        """How an explanation names what is asked: the catalogue's `ask.NAME` with the
        question's target (a body's, a joint's or a point's name) and its frame."""
        key = f"ask.{self.name}"
        if self.about == "joint":
            return words.msg(key, joint=words.name(q.target, "joint"))
        if self.about == "point":
            return words.msg(key, point=words.name(words.point(q)), frame=words.frame(q))
        return words.msg(key, body=words.name(q.target, "body"), frame=words.frame(q))

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """How an explanation labels the field `key` (its part `sub`) of a compound answer;
        None: by the field's own word (`ans.KEY`)."""
        return None

    def __repr__(self) -> str:
        return f"<question kind {self.name}>"
