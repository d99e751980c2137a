"""The explanation as data: sections of messages, vector equations and figures.

The builder fills a `Document` with the solver's values and message keys; it holds no
words of any language and no markup. Renderers (Markdown, HTML, LaTeX) translate the
keys through a catalogue and format the values, so one document serves every language
and format, and tests can check its equations on the raw values.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any, Optional, Union

from ..model.model import PointRef


@dataclass(frozen=True)
class Sym:
    """A named quantity as the notes write it: base letter, subscript, superscript.

    `sub_key` names a catalogue message used as (part of) the subscript, for the words
    that change with the course's language (drag: arr / ar; relative: rel / REL).
    """

    base: str
    sub: str = ""
    sup: str = ""
    vector: bool = True
    sub_key: str = ""
    fixed: bool = False            # written as given (a model's notation): no body numbers
    of_body: bool = False          # the subscript is a body's name (ρ of a wheel): written by its label


@dataclass(frozen=True)
class Value:
    """A solver value (scalar or vector) with its kind of unit: len, speed, accel, rate, rate2."""

    value: Any
    unit: str = ""
    result: bool = False           # a result the notes write as x/(k√n) where it is √n·x/(k n) (`render.base.root_form`)


@dataclass
class Msg:
    """A catalogue message with its arguments (str, Sym, Value, Msg or lists of them)."""

    key: str
    args: dict[str, Any] = field(default_factory=dict)


@dataclass
class Inline:
    """A short formula as a message argument: strings and symbols in a row."""

    items: list


@dataclass
class Own:
    """The model's own words as a message argument (a note on the statement): escaped, each
    parameter's name in them written as the formulas write it (`Renderer.own_words`)."""

    text: str

    def __str__(self) -> str:
        return self.text


def msg(key: str, **args: Any) -> Msg:
    """A catalogue message with its arguments: ``msg("curvature.rest", point=Name("B"))``."""
    return Msg(key, args)


@dataclass(frozen=True)
class Name:
    """A name from the model, set as a name: a point (O4), a body (crank) or a joint (j3)."""

    text: str
    kind: str = "point"
    bare: bool = False             # a body's name without its article (in a table's cell)
    reference: bool = False        # the fixed body as the reference of a motion: named by its own
                                   # name ("relative to the fixed pulley"), never a "ground" the
                                   # problem does not have (twenty-ninth round (b))

    def __str__(self) -> str:
        return self.text


@dataclass
class Names:
    """Several names as one message argument: a list with the language's "and". With `each`,
    a catalogue message (its variable `$name`) is written around every name, so a preposition
    applies to each of them, as Catalan and Spanish repeat it: "del pla esquerre i del pla
    dret", not "del pla esquerre i el pla dret"."""

    items: list
    each: str = ""

    def __len__(self) -> int:
        return len(self.items)


# A centre placed as a point when a page places several (C5-1.2's two bars'): its point name
# in the document is this token around the moving body's id, which every renderer writes as
# the centre's symbol in the page's language (I_OQ, I_16 where the bodies go by numbers),
# wherever a point is written: names, subscripts (v_{I_OQ}), segments (O I_OQ), figures. The
# body's label is per language and the document is one for all, so the name is resolved when
# the page is written, as a body's label is. Private-use characters: no model name holds them.
CENTRE_POINT = "\ue010{}\ue011"
CENTRE_POINT_RE = re.compile("\ue010([^\ue011]*)\ue011")


# the geometric contact point of a rolling pair, one name wherever it is written: the point
# F^{geom}, its motion v_{F^{geom}}, a_{F^{geom}}, and its motion about a centre v_{F^{geom}A}
# (twentieth round g: 001's rolling pair wrote F^geom, v_F^geom and v_{FA,geom}). The mark
# follows the contact's name; each format sets it as a superscript on that name
# (`Renderer.geom_mark`), inside a subscript too.
GEOM_MARK = "\ue012"


def geometric_name(name: str) -> str:
    """The name of the geometric contact point at the contact `name` (J -> J^{geom})."""
    return name + GEOM_MARK


def centre_point(body: str) -> str:
    """The point name of `body`'s instant centre relative to the frame (`CENTRE_POINT`)."""
    return CENTRE_POINT.format(body)


def point(name: str) -> Name:
    """A point's name, set as a point."""
    return Name(name, "point")


def body(name: str) -> Name:
    """A body's name, set as a body."""
    return Name(name, "body")


def joint(name: str) -> Name:
    """A joint's id, set as a joint."""
    return Name(name, "joint")


def names(items, kind: str, each: str = "") -> Names:
    """Several names of one kind (point, body, joint) as one message argument; `each` a
    catalogue message written around every name (see `Names`)."""
    return Names([Name(str(i), kind) for i in items], each)


@dataclass
class Lead:
    """An argument that begins a phrase (after "1." or "Step 1:"): a catalogue word, or a
    name with its article (la barra OQ), is written with a capital ("1. La barra OQ, …");
    a bare model name is left as the model spells it."""

    item: Any


@dataclass(frozen=True)
class Ann:
    """What is known of a term (seed 001): magnitude M or ?, direction D, ?, ⊥ or ∥ a line.

    `code` is one of "M", "D", "?", "perp", "para" or "zero"; `ref` names the line (a segment
    "AB", or a guide `Msg`) or a known magnitude's formula (ω²·AB). An unknown magnitude "?"
    whose rate several terms of one equation share keeps that rate and its arm in `ref`
    ([α, "·JS"], `shared.share`): the marks row writes "?", the sentence before it the rate.
    """

    code: str
    ref: Any = ""


@dataclass
class Term:
    """One vector of an equation: its symbol, how it is formed, its value and annotations."""

    sym: Sym
    value: tuple
    mag: Ann
    dir: Ann
    how: list = field(default_factory=list)     # inline items (str, Sym) e.g. [ω, " × AB"]
    unknown: bool = False                        # solved in this step
    kind: str = ""                               # point, rotation, normal, tangential, slide, coriolis, contact
    spelt: bool = False                          # written by its formula (α × JC), not by its symbol


@dataclass
class Equation:
    """target = side₁ = side₂ …: each side a sum of terms, all at one level ('v' or 'a')."""

    target: Term
    sides: list[list[Term]]
    level: str
    point: Optional[PointRef] = None             # the material point the target is the motion of
    relative_to: Optional[str] = None
    figure: bool = True                          # draw its polygon (planar)
    polygon: Optional["Figure"] = None           # filled in by the builder
    position: Optional[tuple] = None             # where the point is, when it has no name
    owned: list = field(default_factory=list, repr=False)    # the sentences written for it alone (a contact's rule)
    contacts: list = field(default_factory=list, repr=False) # the contact points they are about

    @property
    def terms(self) -> list[Term]:
        """Every term it writes: its target, then each side's terms in order."""
        return [self.target] + [t for side in self.sides for t in side]

    @property
    def equality(self) -> bool:
        """Whether the equation only says that two points move alike (v_T2 = v_T1: the two
        points of a contact, a point shared by two bodies, the points of a strand that
        translates): one side of one term, itself a point's motion. That is not a polygon and
        is written as a plain equality after its reason, with no M/D/? marks, which the
        notes keep for a composition of two or more terms (issue 30, thirteenth round)."""
        return len(self.sides) == 1 and len(self.sides[0]) == 1 and self.sides[0][0].kind == "point" \
            and self.target.kind == "point"


@dataclass
class Derived:
    """A value read off an equation (ω = v_BA / AB), with the solver's value."""

    sym: Sym
    how: list                                     # inline items
    value: Value
    body: str = ""
    kind: str = ""                                # omega, alpha
    sense: bool = False                           # say counter-clockwise / clockwise
    source: Optional[Term] = None                 # the term it is read from: ω × r or α × r
    arm: Optional[tuple] = None                   # r, with source.value = value k × r
    remark: Optional[Msg] = None                  # why, after the value: ω_2 = 0 (its centre is at infinity)
    lead: Optional[list] = None                   # written before: the composition it is read off (ω_b = ω_b REL a + ω_a ⇒)


@dataclass
class Table:
    """A table: header cells and rows of cells (messages, names, values, inline formulas or
    text)."""

    header: list[Any]
    rows: list[list[Any]]


@dataclass
class Arrow:
    """An arrow of a figure, in model units, with its symbol; `style` says what it is to the
    step (known, unknown, result, construction) and so how it is drawn."""

    start: tuple
    end: tuple
    label: Optional[Sym] = None
    style: str = "known"                          # known, unknown, result, construction


@dataclass
class Figure:
    """A drawing in model units: arrows, segments, circles and labelled points."""

    caption: Msg
    arrows: list[Arrow] = field(default_factory=list)
    segments: list[tuple[tuple, tuple]] = field(default_factory=list)
    circles: list[tuple[tuple, float]] = field(default_factory=list)
    lines: list[tuple[tuple, tuple]] = field(default_factory=list)        # tracks, guides (thin)
    points: list[tuple[str, tuple, str]] = field(default_factory=list)   # (label, xy, style)
    unit: str = ""                                 # unit of the scale bar (speed, accel, len)
    sample: bool = False                           # drawn at sample values of the symbols
    values: dict = field(default_factory=dict)     # ... namely these (a symbolic model's draw_at)
    notes: list = field(default_factory=list)      # sentences after the caption (how a label reads)
    layouts: dict = field(default_factory=dict, repr=False, compare=False)   # by the labels' texts


@dataclass
class Drawing:
    """The figure `kinematika draw` gives of the solution with these `options` (the
    mechanism with its velocities, its instant centres, a 3D model upright), drawn bare:
    the caption says in the document's language what it shows. LaTeX, one file without
    images, draws `fallback` (TikZ) instead, or nothing."""

    caption: Msg
    solution: Any
    options: dict = field(default_factory=dict)
    fallback: Optional[Figure] = None
    values: dict = field(default_factory=dict)    # symbol -> the number it is drawn at
    _svg: dict = field(default_factory=dict, repr=False)     # lang -> SVG text

    def svg(self, lang: str) -> str:
        """The drawing as SVG text with its numbers as `lang` writes them (2,5 in es),
        drawn once for each language, whatever the format."""
        if lang not in self._svg:
            from ..draw import svg

            self._svg[lang] = svg(self.solution, bare=True, lang=lang, **self.options)
        return self._svg[lang]


@dataclass
class CentreNote:
    """How one instant centre follows (seed 002): at a joint, by Aronhold–Kennedy, or
    from the directions of two velocities; `value` is the solver's centre."""

    pair: tuple[str, str]
    value: dict
    how: str                                       # joint, kennedy, velocities, proportional
    via: list = field(default_factory=list)        # joint id, or the two third bodies
    lines: list = field(default_factory=list)      # kennedy: [(centre a–k, centre k–b), ...]
    witnesses: list = field(default_factory=list)  # velocities: [(point, velocity), ...]
    joint_type: str = ""                           # joint: the type of the joint
    side: str = ""                                 # proportional: the centre "between" or "outside" the witnesses
    same: Optional[dict] = None                    # weld: the centre of the body it is welded to
    rate: Any = None                               # field, check: ω of the pair
    arm: Optional[tuple] = None                    # field, check: QI = ω × v_Q / ω², v_Q turned 90° with ω
    distance: Any = None                           # field, check: |QI| = |v_Q| / |ω|; proportional: from `near`
    perps: list = field(default_factory=list)      # kennedy: each line as the notes draw it (Msg)
    pivots: list = field(default_factory=list)     # proportional: what each witness turns about
    step: Optional[int] = None                     # rate: the step that found ω (builder.refer_rates)
    near: str = ""                                 # proportional with pivots: the witness `distance` is from
    slips: list = field(default_factory=list)      # proportional with pivots: each witness's no-slip reason (Msg) or None
    symbols: list = field(default_factory=list)    # parallel: each witness's velocity as the steps write it (v_{T4∈pulley3})


@dataclass(frozen=True)
class Described:
    """What the model says of one of its things in the reader's language (`names`): what a
    point is (`kind` point) or a parameter (`kind` parameter); when it does not say, `fallback`
    (what the model's structure says of it: a wheel's centre, a joint's point), else empty."""

    kind: str
    name: str
    fallback: Optional["Msg"] = None


@dataclass
class Told:
    """What the model tells in the reader's language (its `names`): `points`, a table of
    what its points are; `data`, its statements of the data (the geometry it chose);
    `notes`, its notes on the printed statement."""

    kind: str
    points: list = field(default_factory=list)     # the model's point names, in order


Block = Union[Msg, Equation, Derived, Table, Figure, Drawing, CentreNote, Told, "Section"]


@dataclass
class Section:
    """A titled part of the explanation: its blocks in reading order (messages, equations,
    derived values, tables, figures, nested sections) and its heading level."""

    title: Msg
    blocks: list[Block] = field(default_factory=list)
    level: int = 2

    def add(self, *blocks: Block) -> "Section":
        """Append blocks, in reading order; returns the section, so that calls chain."""
        self.blocks.extend(blocks)
        return self

    def leaves(self) -> list:
        """Every block of the section and of its nested sections, in reading order."""
        out: list = []
        for b in self.blocks:
            out += b.leaves() if isinstance(b, Section) else [b]
        return out


@dataclass
class Document:
    """The whole explanation as data: the model's title, whether values are formulas, the
    dimension, the length unit, the sections, and the bodies' numbers as the notes and figures
    number them."""

    title: str
    symbolic: bool
    dimension: int
    length_unit: str
    sections: list[Section] = field(default_factory=list)
    numbers: dict = field(default_factory=dict)    # body -> its number, as the notes and figures number them
    wording: Any = None                             # the model's names per language and notation
    joints: dict = field(default_factory=dict)      # joint -> its point or contact (how the text names it)
    parameters: tuple = ()                          # the model's parameters' names (its own words write them)
    values: dict = field(default_factory=dict)      # a symbolic model's numbers (draw_at): how formulas are written
    worded_marks: tuple = ()                        # the page's points named M or D: the legend says the marks are not those points (`marks`)

    def blocks(self) -> list:
        """Every block, nested sections included, in reading order."""
        return [b for s in self.sections for b in s.leaves()]

    def equations(self) -> list[Equation]:
        """Every vector equation, in reading order (tests check them on the raw values)."""
        return [b for b in self.blocks() if isinstance(b, Equation)]

    def derived(self) -> list[Derived]:
        """Every value read off an equation (ω = v_BA / AB …), in reading order."""
        return [b for b in self.blocks() if isinstance(b, Derived)]
