"""A centre's construction placed after the lines that find the velocities it reads (issue 30,
twentieth round e).

The notes find C5-1.4's planet centre from two velocities: "El coneixement dels CIRs i de les
velocitats angulars del portador i de la corona permet calcular la velocitat del centre de les
rodetes i del seu punt de contacte amb la corona. Ja que les velocitats d'aquests dos punts
… són de signe oposat, el CIR de cada rodeta s'ha de trobar entre els dos" — the velocities
first, then the centre. The page placed that centre in "Instant centres", before the
velocities, and wrote there "A1 moves at (2·r·ω, 0) and Q at (−3·r·ω, 0)": two velocities
the steps find only later (v_A1 in step 1, v_Q∈ring in step 3). The rule over the order of
what is said: a block uses what it reads and may only stand after the line that finds it.
A centre found from the velocities of two points (`CentreNote` "proportional") is moved into
the velocity step, just after the equation that finds the last of those velocities — where
the step then starts from it ("I_planet1 has no velocity") — and "Instant centres" says
where it is placed ("found in step 3"). When the step that starts from the centre comes
before those velocities are found, nothing moves (no order would do)."""
from __future__ import annotations

from typing import Optional

from .context import Ctx
from .document import CentreNote, Equation, Msg, Name, Section, Sym, msg, names

# the sentences that a step starts from a centre placed in "Instant centres", and what each
# says once the centre is placed just above it in the step
PLACED_BEFORE = {"centre.site": "centre.site_here", "centre.site_s": "centre.site_s_here"}


def witness_keys(ctx: Ctx, note: CentreNote) -> list[str]:
    """The material points (motion keys) whose velocities a centre's note reads: each witness
    point of a proportional construction, as a point of the body it turns with."""
    if note.how != "proportional" or len(note.witnesses) != len(note.via):
        return []
    return [ctx.motion_key(p, k) for (p, _, _), k in zip(note.witnesses, note.via) if not str(p).startswith("I:")]


def found_keys(ctx: Ctx, block) -> list[str]:
    """The material points whose velocity a block finds: an equation's target."""
    if isinstance(block, Equation) and block.point is not None:
        return [ctx.motion_key(block.point.point, block.point.body)]
    return []


def _where_found(ctx: Ctx, steps: list[Section], keys: list[str]) -> Optional[tuple[int, int]]:
    """(step, block) of the equation that finds the last of `keys`, or None if one is never found."""
    left = set(keys)
    for i, step in enumerate(steps):
        for k, block in enumerate(step.blocks):
            left -= set(found_keys(ctx, block))
            if not left:
                return i, k
    return None


def _starts_from(step: Section, centre: Sym) -> Optional[int]:
    """The index of the step's sentence that the centre, placed in "Instant centres", has no velocity."""
    return next((k for k, b in enumerate(step.blocks) if isinstance(b, Msg) and b.key in PLACED_BEFORE
                 and b.args.get("centre") == centre), None)


def centres_after_found(ctx: Ctx, centres: Section, velocities: Section) -> None:
    """Move each centre of `centres` (the section before the velocities) whose construction
    reads velocities into the velocity step after the equation that finds the last of them."""
    steps = [b for b in velocities.blocks if isinstance(b, Section)]
    for n, note in enumerate(centres.blocks):
        if not isinstance(note, CentreNote) or ctx.frame not in note.pair:
            continue
        keys = witness_keys(ctx, note)
        found = _where_found(ctx, steps, keys) if keys else None
        if found is None:
            continue
        body = next(b for b in note.pair if b != ctx.frame)
        centre = Sym("I", f"{ctx.frame},{body}", vector=False)
        i, k = found
        first_use = next(((s, at) for s, step in enumerate(steps)
                          for at in [_starts_from(step, centre)] if at is not None), None)
        if first_use is not None and (first_use[0], first_use[1]) < (i, k):
            continue            # the step starts from it before the velocities: no order would do
        if first_use is not None and first_use[0] > i:
            # the body's own step starts from it: the paragraph opens that step (twenty-second
            # round (a): C5-1.4's I_planet1 closed the ring's step, then planet 1's step read it)
            s, at = first_use
            steps[s].blocks.insert(at, note)
            at += 1
        else:
            k = _after_equations(steps[i].blocks, k, body)
            steps[i].blocks.insert(k + 1, note)
            if first_use is not None:
                s, at = first_use
                at += 1 if s == i and at > k else 0
        if first_use is not None:
            said = steps[s].blocks[at]
            assert isinstance(said, Msg)        # `_starts_from` finds only these sentences
            steps[s].blocks[at] = Msg(PLACED_BEFORE[said.key], said.args)
        points = [p for p, _, _ in note.witnesses if not str(p).startswith("I:")]
        # the step's number is read off the page after `prune` (`builder.refer_placed`)
        centres.blocks[n] = msg("centres.placed_in_step", centre=centre, step=0, body=Name(body, "body"),
                                points=names(points, "point", each="centres.witness"))
        ctx.worked.add(f"centre:{body}")


def _after_equations(blocks: list, k: int, body: str) -> int:
    """The index after which a centre's paragraph goes in a step: past the equations that
    follow the one it reads, when none of them reads the centre (twenty-first round (b):
    C5-1.4's "I_planet1: A1 moves with the carrier about O…" stood between the ring's
    v_{Q∈ring} and v_{S∈ring}; the notes write a step's equations for its body, then the
    centre found from them)."""
    from .document import CENTRE_POINT, Equation

    token = CENTRE_POINT.format(body)
    while k + 1 < len(blocks) and isinstance(blocks[k + 1], Equation) and token not in repr(blocks[k + 1]):
        k += 1
    return k
