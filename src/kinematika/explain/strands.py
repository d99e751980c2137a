"""Only a round body rolls (issue 30, ninth round): a strand, a belt, a cable or a block's
straight edge on a pulley does not roll, it does not slip ("el tram 2 no llisca sobre la
politja 1", as the notes say of a strand on its pulley). The words of a rolling contact's
condition depend on what its subject is — read off the model's shapes, never its names: a
moving body whose shape is a straight line (and no circle) said to touch a round one takes
the "does not slip" wording; a wheel or a disc still rolls (on the ground, on another
wheel, on a lever's edge)."""
from __future__ import annotations

from typing import Any

from ..model.body_shapes import Circle, Disc, Line
from .context import Ctx
from .document import Msg, Name

# the condition's messages whose subject `$b` "rolls without slipping on" `$a`, and the
# message each becomes when `$b` is straight: the same condition, "does not slip on"
EDGE_KEYS = {"rolling.noslip": "rolling.noslip_edge", "rolling.same": "rolling.same_edge"}


def straight(ctx: Ctx, body: str) -> bool:
    """Whether `body` is a moving straight body: a line shape, no circle (a strand, a belt's
    run, a block's edge); the frame is the ground a wheel rolls on, never a strand."""
    shapes = ctx.model.bodies[body].shapes if body in ctx.model.bodies else []
    return (not ctx.fixed(body) and any(isinstance(s, Line) for s in shapes)
            and not any(isinstance(s, (Circle, Disc)) for s in shapes))


def round_body(ctx: Ctx, body: str) -> bool:
    """Whether `body` has a circle (a pulley, a wheel, a disc)."""
    shapes = ctx.model.bodies[body].shapes if body in ctx.model.bodies else []
    return any(isinstance(s, (Circle, Disc)) for s in shapes)


def strand_words(ctx: Ctx, blocks: Any) -> None:
    """Every rolling condition in `blocks` (walked through sections, messages and their
    arguments) whose subject is a straight body on a round one says it does not slip."""
    for m in _messages(blocks):
        new = EDGE_KEYS.get(m.key)
        b, a = m.args.get("b"), m.args.get("a")
        if new and isinstance(b, Name) and isinstance(a, Name) and straight(ctx, b.text) \
                and round_body(ctx, a.text):
            m.key = new


def _messages(x: Any):
    """The messages in `x` and in their arguments, depth first."""
    if isinstance(x, Msg):
        yield x
        for v in x.args.values():
            yield from _messages(v)
    elif isinstance(x, (list, tuple)):
        for v in x:
            yield from _messages(v)
    elif hasattr(x, "blocks"):
        yield from _messages(x.blocks)
