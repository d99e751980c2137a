"""A contact point's velocity written once, as the material point's (C5-1.5: the notes say
the velocity ↓2v of pulley 1's point "is transmitted to all the points of the second strand",
never v_T1 = v_T1∈pulley1). Where a rolling contact's sentence would equate a point's bare
label with the same point taken on the other body (v_T1 = v_{T1∈pulley1}, the strand's T1
and the pulley's), the sentence says only that the material points have the same velocity,
and the steps that follow write the point by the material point's symbol (v_T2 = v_{T1∈pulley1}):
two names of one velocity in a row read as an equation with nothing in it.
"""
from __future__ import annotations

import dataclasses
from typing import Any

from .document import Msg, Section, Sym

# the contact sentences that say the equality of the two material points
SAME = {"rolling.same": "rolling.noslip", "rolling.same_edge": "rolling.noslip_edge"}


def material_contacts(levels: list[Section]) -> None:
    """In each velocity or acceleration section, each trivial contact equality said in a
    sentence (`trivial`) is dropped from it, and its bare symbol is written as the material
    point's from there to the end of the section."""
    for sec in levels:
        blocks = sec.leaves()
        for i, b in enumerate(blocks):
            if isinstance(b, Msg) and b.key in SAME and trivial(b.args.get("sym"), b.args.get("other")):
                old, new = b.args["sym"], b.args["other"]
                b.key = SAME[b.key]
                del b.args["sym"], b.args["other"]
                for later in blocks[i + 1:]:
                    _rename(later, old, new)


def trivial(sym: Any, other: Any) -> bool:
    """Whether `sym` is a point's bare label and `other` the same point of a body (T1 and
    T1∈pulley1): the same place, one velocity, by the no-slip condition just said."""
    return (isinstance(sym, Sym) and isinstance(other, Sym) and sym.base == other.base and not sym.sup
            and not other.sup and "∈" not in sym.sub and other.sub.startswith(sym.sub + "∈")
            and "/" not in other.sub)


def _rename(block: Any, old: Sym, new: Sym) -> None:
    """Replace, in place, every symbol written as `old` inside a block (an equation's terms
    and their magnitudes, a message's arguments) by `new`."""
    if dataclasses.is_dataclass(block) and not isinstance(block, type):
        for f in dataclasses.fields(block):
            value = getattr(block, f.name)
            swapped = _swapped(value, old, new)
            if swapped is not value:
                object.__setattr__(block, f.name, swapped)


def _swapped(value: Any, old: Sym, new: Sym) -> Any:
    """`value` with `old` replaced by `new` (the same object when nothing changed; lists and
    dicts changed in place)."""
    if isinstance(value, Sym):
        return new if _written(value) == _written(old) else value
    if isinstance(value, list):
        for k, v in enumerate(value):
            value[k] = _swapped(v, old, new)
        return value
    if isinstance(value, dict):
        for k, v in value.items():
            value[k] = _swapped(v, old, new)
        return value
    if isinstance(value, Section):
        return value
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        _rename(value, old, new)
    return value


def _written(sym: Sym) -> tuple:
    """What tells two symbols apart on the page."""
    return (sym.base, sym.sub, sym.sup, sym.sub_key)
