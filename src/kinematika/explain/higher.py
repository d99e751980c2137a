"""Higher pairs (a cam and its follower, a pin in a curved slot, outlines that slide)
explained as the notes explain a sliding pair: one point moves along a path fixed in the
other body, and its motion is composed of the drag, the relative motion and Coriolis.

The pair's equivalent slot (`path_of`): a pin, knife edge or roller's centre runs along
the other body's curve (the pitch curve for a roller); an outline's centre of curvature runs
along a line parallel to a straight outline, or along a circle of radius ρa + ρb about the
other outline's centre of curvature. Then, with P the point on the path and H the body the
path is fixed in:

    v_P = v_P∈H + v_P/H,                         v_P/H ∥ the path's tangent t (magnitude ?)
    a_P = a_P∈H + aᵗ_P/H + aⁿ_P/H + 2 ω_H × v_P/H,   aⁿ_P/H = v²_P/H / ρ towards its centre,

the normal part known once the velocities are: that is the curvature's term a straight slot
has not.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

from ..algebra.vectors import dot, scale, sub
from ..shapes import Circle
from .context import Ctx
from .document import Ann, Msg, Sym, Term, point
from .order import Step
from .terms import guide, relative_name, rotation_terms, slide_terms


@dataclass
class Path:
    """A higher pair as a slot: the named point `pin` of `mover` runs along a path fixed in
    `holder`, tangent `tangent` there, curved about `centre` with radius `radius` (None:
    straight)."""

    pin: str
    mover: str
    holder: str
    tangent: tuple
    radius: Optional[float]
    centre: Optional[tuple]


def path_of(ctx: Ctx, j: Any) -> Optional[Path]:
    """The equivalent slot of a touching joint, when its moving point has a name."""
    t = ctx.sol.geometry(j.id).contact
    n = t.normal
    tangent = (-n[1], n[0])
    if t.radius_b == 0 and j.at:                                  # a point of b on a's outline
        return Path(j.at, j.b, j.a, tangent, t.radius_a, t.centre_a)
    centre_b = _named_centre(t.outline_b)
    centre_a = _named_centre(t.outline_a)
    if t.radius_a is None and centre_b:                          # b's centre along a's line
        return Path(centre_b, j.b, j.a, tangent, None, None)
    if t.radius_b is None and centre_a:                          # a's centre along b's line
        return Path(centre_a, j.a, j.b, tangent, None, None)
    if t.radius_a is not None and t.radius_b is not None and centre_b:
        return Path(centre_b, j.b, j.a, tangent, t.radius_a + t.radius_b, t.centre_a)
    return None


def _named_centre(outline: Any) -> Optional[str]:
    return outline.center_point if isinstance(outline, Circle) else None


def path_terms(ctx: Ctx, level: str, p: Path, tag: str) -> list[Term]:
    """The motion of the pin relative to the path's body: along the tangent; with the normal
    part v²/ρ and Coriolis for accelerations."""
    tangent = Msg("dir.tangent", {"point": point(p.pin)})
    if level == "v" or p.radius is None:
        return slide_terms(ctx, level, p.holder, p.mover, p.pin, tangent, tag)
    a_rel = ctx.acc(p.mover, p.pin, p.holder)
    along = scale(dot(a_rel, p.tangent), p.tangent)
    across = sub(a_rel, along)
    name = relative_name(p.pin, p.mover, p.holder)
    rel = Sym("v", name)
    centre = Msg("dir.centre", {"point": "C"})
    coriolis = slide_terms(ctx, level, p.holder, p.mover, p.pin, tangent, tag)[-1]   # as a straight slide's
    return [Term(Sym("a", name, "t"), ctx.clean(along, "accel"), Ann("?"), Ann("para", tangent),
                 [], True, "slide"),
            Term(Sym("a", name, "n"), ctx.clean(across, "accel"), Ann("M", [rel, "²/ρ"]),
                 Ann("para", centre), [rel, "² / ρ"], False, "curvature"),
            coriolis]


def higher_pair_steps(steps: Any, step: Step) -> Optional[list]:
    """A one-body group held by a revolute or prismatic joint and a higher pair, written as
    one equation at the pair's moving point (two unknowns), then its ω or α read off; None
    when the group is not of that form."""
    ctx, level = steps.ctx, steps.level
    if len(step.bodies) != 1:
        return None
    body = step.bodies[0]
    joints = [ctx.model.joint(j) for j in step.joints]
    higher = [j for j in joints if j.kind.touches and not j.kind.rolls]
    lower = [j for j in joints if len(j.kind.chain) == 1]
    if len(higher) != 1 or len(lower) != 1:
        return None
    pair, first = higher[0], lower[0]
    path = path_of(ctx, pair)
    if path is None:
        return None
    k = first.a if first.b == body else first.b
    intro = Msg("higher.intro" if path.radius is not None else "higher.straight",
                {"joint": pair.id, "point": point(path.pin), "holder": path.holder,
                 "radius": f"{abs(path.radius):.4g}" if path.radius is not None else ""})
    pin = path.pin
    if first.kind.pins:                                    # the body turns about the revolute's point
        o = first.at
        turning = [steps.point(o, body)] + rotation_terms(ctx, level, body, o, pin, True)
    else:                                                  # it slides on k along the guide
        turning = [steps.point(pin, k)] + slide_terms(ctx, level, k, body, pin, guide(first), first.id)
    relative = path_terms(ctx, level, path, pair.id)
    if path.mover == body:                                 # the body carries the pin
        eq = steps.equation(steps.target(pin, body, known=False),
                            [turning, [steps.point(pin, path.holder)] + relative], pin, body)
    else:                                                  # the body carries the path
        eq = steps.equation(steps.target(pin, path.mover, known=True), [turning + relative], pin, path.mover)
        steps.done.add(ctx.point_label(pin, body))         # the body's own point there is known now
    found = steps.read(body, turning[-1], first.at, pin) if first.kind.pins else steps.same(body, k, first)
    return [intro, eq, found]
