"""What kind of joint a joint is, asked in one place: each joint's kind (`joint.kind`, one
module per kind in `kinematika.joints`) says what it can do; the explanation asks here."""
from __future__ import annotations

from typing import Any

from ..joints.capabilities import Chain, Coordinate


def rolls(j: Any) -> bool:
    """A rolling contact (rolling or gear joint): two profiles touching without slip."""
    return bool(j.kind.rolls)


def roller(model: Any, j: Any) -> tuple[str, str]:
    """(the body that rolls, the body it rolls on) at a rolling contact: a body with a circle
    rolls on one with only straight profiles (a pulley on its cable, a wheel on the ground: the
    notes' "les politges no llisquen al damunt del cable"), never a strand on a pulley; other
    pairs (two circles: gears, a planet in its ring) keep the joint's order, `j.b` on `j.a`."""
    def straight(body: str) -> bool:
        shapes = model.bodies[body].shapes
        return bool(shapes) and all(type(s).__name__ in ("Line", "Plane") for s in shapes)

    def round_(body: str) -> bool:
        return any(type(s).__name__ in ("Circle", "Disc") for s in model.bodies[body].shapes)

    if straight(j.b) and round_(j.a):
        return j.a, j.b
    return j.b, j.a


def by_centre_path(j: Any) -> bool:
    """A rolling contact the notes explain through the circle's centre: the centre keeps its
    distance from the other profile, so its path relative to that body is known (a line
    parallel to a straight profile): a_C on its path when the profile is fixed (C5-1.7), the
    slides' axes at the wheel's centre turning with the other body when it moves (4.4),
    then equal tangential components at the contact — never the geometric contact point
    (kept for the `contact` question, C5-1.8)."""
    return bool(getattr(j.kind, "centre_path", False))


def pins(j: Any) -> bool:
    """A pin: the two bodies share a point and turn about it."""
    return bool(j.kind.pins)


def welds(j: Any) -> bool:
    """A weld: the two bodies are one."""
    return bool(j.kind.rigid)


def crossed_by_a_slot(j: Any) -> bool:
    """A pin in a straight slot (a slider block between: the chain PR): the pin's body slides
    along the slotted body and turns about the pin."""
    return j.kind.chain is Chain.PR


def on_fixed_line(j: Any, frame: str) -> bool:
    """A point sliding along a line of the frame (a slot whose slotted body is the frame):
    the notes' bar end on the floor (C5-1.2), a contact with sliding, not a pin in a slot."""
    return crossed_by_a_slot(j) and j.a == frame


def kind_key(j: Any, frame: str) -> str:
    """The name a joint goes by, from its kind and the bodies it joins: `slot_fixed` for a
    point sliding on a line of the frame, else its kind's name."""
    return "slot_fixed" if on_fixed_line(j, frame) else j.kind.name


# the letter a lower pair's kind is written with in the notes (the R of "RRR", the P of "RRP"),
# by the chain it is in, and the key of its name without it
PAIR_LETTER = {Chain.R: ("R", "joint.revolute_word"), Chain.P: ("P", "joint.prismatic_word")}


def joint_kind(ctx: Any, j: Any) -> Any:
    """What a joint is, as the joints' table and the points' glosses write it: "revolute (R)",
    or the word alone ("hinge", "articulación") when the page already uses the letter for
    something else, a parameter or a point (issue 30, twenty-ninth round (d): C5-E.5 wrote
    "revolute (R) | chassis – wheel R | A" with R a radius, C5-E.3 "revolute (R) between …"
    with R the wheels' radius: one letter, three meanings)."""
    from .document import msg

    key = kind_key(j, ctx.frame)
    pair = PAIR_LETTER.get(j.kind.chain) if key == j.kind.name else None
    if pair is not None and pair[0] in _symbols(ctx):
        return msg(pair[1])
    return msg(f"joint.{key}")


def _symbols(ctx: Any) -> set:
    """The letters the page writes as symbols of its own: the parameters' names, the points'
    (the model's, the instance's and the contacts' the explanation names)."""
    model = ctx.model
    found = set(model.parameters) | set(model.points) | set(getattr(ctx.inst, "points", {}) or {})
    return found | set(getattr(ctx, "_contacts", {}).values())


def slider(j: Any) -> bool:
    """A prismatic pair (the chain P): the bodies slide along a straight guide and turn together."""
    return j.kind.chain is Chain.P


def guided(j: Any) -> bool:
    """A straight guide, with a slider block (P) or a pin in a slot (PR): the motion of a
    point across it is relative sliding along the guide's direction."""
    return j.kind.chain in (Chain.P, Chain.PR)


def pin_only(j: Any) -> bool:
    """A planar or spatial pin about one axis (the chain R): not a ball joint."""
    return j.kind.chain is Chain.R


def lower(j: Any) -> bool:
    """A pin or a slider (R or P): the pairs a dyad's name is made of."""
    return j.kind.chain in (Chain.R, Chain.P)


def same_rate(j: Any) -> bool:
    """The two bodies turn together (a weld, or a prismatic pair): one ω, one α."""
    return bool(j.kind.rigid) or j.kind.chain is Chain.P


def knife_edge(j: Any) -> bool:
    """A vehicle's wheel (a knife edge): its point moves only along the wheel's plane."""
    return bool(j.kind.knife_edge)


def turns(j: Any) -> bool:
    """A joint whose driven rate is an angular velocity (a pin, a wheel, a cylindrical
    pair), not a sliding speed (a prismatic pair)."""
    return j.kind.coordinate is Coordinate.ANGLE or j.kind.pins or j.kind.knife_edge


def line_kind(j: Any) -> str:
    """Which line a joint puts its bodies' relative centre on (its kind's `centre_line`): a
    wheel's axle, the common normal at a contact that slides (a cam, a curved slot), the
    normal to a straight slot at its pin."""
    return j.kind.centre_line


def meshes(j: Any) -> int:
    """1 for a gear pair, else 0 (a number: the renderer hands Fluent numbers as they are, so
    a message selects on it): the catalogues say a gear "meshes with" its mate (the gear
    joint's own word), where a wheel "rolls without slipping" on a profile."""
    return int(bool(getattr(j.kind, "pitch", False)))       # the kind is asked, never named
