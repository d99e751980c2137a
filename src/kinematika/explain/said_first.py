"""A pair's condition said before the first line that uses it (issue 30, twentieth round e).

A step may carry a rate across a joint before it writes the equation that crosses it: C5-1.3's
step finds ω_bar, then writes ω_support = ω_bar "(prismatic pair: no relative rotation)", and
only after that the sentence saying what the pair means (the bar slides along the support
without turning relative to it) — a reader meets the consequence before its reason. The
notes say the joint's condition first ("L'altre enllaç … dóna informació sobre la direcció de
velocitat dels punts de la barra respecte al suport"), then use it. The rule: within one
step, a joint's condition sentence (`cond.*`, `input.prismatic`) is moved to just before the
first line of that step that uses the joint (a rate carried across it, ω_b = ω_a with
`how.prismatic` or `how.weld`); a sentence already first stays where it is."""
from __future__ import annotations

from typing import Any

from .document import Derived, Msg, Section

# the sentences that say what a joint imposes, each naming the joint by its `joint` argument
SAYS_CONDITION = ("input.prismatic",)
# the parentheses that carry a rate across a joint by its condition
USES_CONDITION = ("how.prismatic", "how.weld")


def said_joint(block: Any) -> Any:
    """The joint a condition sentence states, or None when `block` is no such sentence."""
    if isinstance(block, Msg) and (block.key.startswith("cond.") or block.key in SAYS_CONDITION):
        return block.args.get("joint")
    return None


def used_joints(block: Any) -> list:
    """The joints a line carries a rate across by their condition (ω_b = ω_a (prismatic …))."""
    if not isinstance(block, Derived):
        return []
    items = list(block.how) + ([block.remark] if block.remark is not None else [])
    return [m.args.get("joint") for m in items if isinstance(m, Msg) and m.key in USES_CONDITION]


def conditions_first(blocks: list) -> list:
    """The step's blocks with each joint's condition sentence placed before the first line
    that uses that joint (subsections in their place, each on its own)."""
    out = list(blocks)
    for b in out:
        if isinstance(b, Section):
            b.blocks = conditions_first(b.blocks)
    i = 0
    while i < len(out):
        joint = said_joint(out[i])
        first = next((k for k in range(i) if joint is not None and joint in used_joints(out[k])), None)
        if first is not None:
            out.insert(first, out.pop(i))
        i += 1
    return said_once(out)


def said_once(blocks: list) -> list:
    """The blocks with a rate carried across a joint whose condition a sentence before it
    said written without the parenthesis that says it again (twenty-first round (b):
    C5-1.3's "the bar slides along the support without turning relative to it", then
    "ω_support = ω_bar (prismatic pair: no relative rotation)"): one condition, said once,
    before its use."""
    said: set = set()
    for b in blocks:
        joint = said_joint(b)
        if joint is not None:
            said.add(joint)
        if isinstance(b, Derived) and said & set(used_joints(b)):
            how: list = []
            for m in b.how:
                if isinstance(m, Msg) and m.key in USES_CONDITION and m.args.get("joint") in said:
                    if how and how[-1] == " ":
                        how.pop()
                    continue
                how.append(m)
            b.how = how
            if isinstance(b.remark, Msg) and b.remark.key in USES_CONDITION and b.remark.args.get("joint") in said:
                b.remark = None
    return blocks
