"""A body that does not turn moves all its points alike: the notes write "the chassis
translates, so its points have v" (C5-E.4, E.5, E.6's frame, C5-1.5's strands), never
v_K = v_H + 0 × HK. A forward evaluation v_P = v_Q + ω × QP (at accelerations with α × QP
and ω × (ω × QP)) through a body whose ω (and α) is zero at the instant is written
v_P = v_Q, after one sentence that says the body translates.
"""
from __future__ import annotations

from .context import Ctx, alpha_sym, omega_sym
from .document import Derived, Document, Equation, Section, body, msg

LEVELS = {"sec.velocities": "v", "sec.accelerations": "a"}
# the remarks after a derived ω = 0 (α = 0) that already say the body translates
SAYS_TRANSLATES = ("how.translation", "how.centre_infinity", "how.tangent", "how.glides", "how.parallel_paths",
                   "how.translates_always")
TURNING = ("rotation", "normal", "tangential")


def translations(ctx: Ctx, doc: Document) -> None:
    """Rewrite, in the velocity and acceleration steps, the forward evaluations through a
    body at rest in rotation as the translation they are."""
    if not ctx.planar:
        return
    for sec in doc.sections:
        level = LEVELS.get(sec.title.key)
        if level is not None:
            _section(ctx, sec, level, set())


def _section(ctx: Ctx, sec: Section, level: str, said: set[str]) -> None:
    i = 0
    while i < len(sec.blocks):
        b = sec.blocks[i]
        if isinstance(b, Section):
            _section(ctx, b, level, said)
        elif isinstance(b, Equation) and b.level == level:
            turning = _translating(ctx, b, level)
            if turning is not None:
                b.sides = [[b.sides[0][0]]]
                if turning not in said:
                    said.add(turning)
                    key = "translation.points" if _stated(sec.blocks[:i], turning, level) else "translation.same"
                    sec.blocks.insert(i, msg(key, body=body(turning), w=omega_sym(turning),
                                             a=alpha_sym(turning), accel=int(level == "a")))
                    i += 1
        i += 1


def _translating(ctx: Ctx, eq: Equation, level: str) -> str | None:
    """The body a forward evaluation turns with, when it does not turn (ω = 0, and α = 0 at
    accelerations): every term after the first point's is that body's, and zero."""
    if len(eq.sides) != 1 or eq.target.kind != "point" or any(t.unknown for t in eq.sides[0]):
        return None
    first, *rest = eq.sides[0]
    if first.kind != "point" or not rest or any(t.kind not in TURNING for t in rest):
        return None
    bodies = {getattr(t.how[0], "sub", None) for t in rest if t.how and getattr(t.how[0], "base", "") in ("ω", "α")}
    if len(bodies) != 1 or len({t.how[0].base for t in rest if t.how} - {"ω", "α"}):
        return None
    (name,) = bodies
    if name not in ctx.model.bodies or not ctx.is_zero(ctx.omega(name), "rate"):
        return None
    if level == "a" and not ctx.is_zero(ctx.alpha(name), "rate2"):
        return None
    unit = "speed" if level == "v" else "accel"
    if not all(ctx.is_zero(t.value, unit) for t in rest):
        return None
    return name


def _stated(before: list, name: str, level: str) -> bool:
    """Whether the step has just derived the body's ω = 0 (α = 0 at accelerations) with a
    remark that says it translates (C5-E.4: "ω_chassis = 0 (its instant centre is at
    infinity: it translates)"): the sentence before the first v_P = v_Q then says only what
    follows, that all its points have one velocity, not "does not turn (ω = 0): it
    translates" a second time. Said once, as the notes say it."""
    kind = "omega" if level == "v" else "alpha"
    return any(isinstance(b, Derived) and b.body == name and b.kind == kind and b.remark is not None
               and b.remark.key in SAYS_TRANSLATES for b in before)
