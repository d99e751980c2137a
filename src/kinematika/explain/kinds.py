"""What kind of joint a joint is, asked in one place: each joint's kind (`joint.kind`, one
module per kind in `kinematika.joints`) says what it can do; the explanation asks here."""
from __future__ import annotations

from typing import Any


def rolls(j: Any) -> bool:
    """A rolling contact (rolling or gear joint): two profiles touching without slip."""
    return bool(j.kind.rolls)


def pins(j: Any) -> bool:
    """A pin: the two bodies share a point and turn about it."""
    return bool(j.kind.pins)


def welds(j: Any) -> bool:
    """A weld: the two bodies are one."""
    return bool(j.kind.rigid)


def crossed_by_a_slot(j: Any) -> bool:
    """A pin in a straight slot (a slider block between: the chain PR): the pin's body slides
    along the slotted body and turns about the pin."""
    return j.kind.chain == "PR"


def turns(j: Any) -> bool:
    """A joint whose driven rate is an angular velocity (a pin, a wheel, a cylindrical
    pair), not a sliding speed (a prismatic pair)."""
    return j.kind.coordinate == "angle" or j.kind.pins or j.kind.name == "wheel"


def line_kind(j: Any) -> str:
    """Which line a joint puts its bodies' relative centre on: "wheel" (its axle), "normal"
    (the common normal at a contact that slides: a cam, a curved slot), "slot" (the normal to
    a straight slot at its pin)."""
    if j.kind.name == "wheel":
        return "wheel"
    return "normal" if j.kind.centre == "normal" else "slot"
