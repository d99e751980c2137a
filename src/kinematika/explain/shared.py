"""One unknown rate shared by several terms of one equation (issue 30, sixth round).

A planar vector equation solves two scalar unknowns. When one unknown rate appears in two
of its terms — C5-1.3's support: a_S = α_euskarria × JS (its centre on its straight path)
and a_QS^t = α_euskarria × SQ — marking both terms ? shows three unknowns under the
sentence "a planar equation solves two". The notes count α once, and a sentence before the
equation says the terms share that one unknown and what their magnitudes are (α_euskarria·JS,
α_euskarria·SQ).

The marks row itself says only what the notes' marks say, M, D, ?, ⊥ …, ∥ … (or, for a
known magnitude, the notes' formula ω²·AB): a formula over an unknown term (α_support·SJ over
a_S) reads as a known magnitude, and the notes mark an unknown magnitude "?" (issue 30,
twenty-eighth round (c)). Each such term keeps its "?", carrying the rate and its arm in the
annotation's `ref` (never written in the row) so that the sentence, and a count of the
equation's unknowns, read the shared rate once."""
from __future__ import annotations

from .document import Ann, Equation, Inline, Names, Section, Sym, Term, msg

RATE_TERMS = ("rotation", "tangential")


def _rate(t: Term) -> Sym | None:
    """The unknown rate a term is the product of (ω × QP, α × QP), if it is one."""
    if t.unknown and t.kind in RATE_TERMS and t.mag.code == "?" and len(t.how) == 2 \
            and isinstance(t.how[0], Sym) and isinstance(t.how[1], str):
        return t.how[0]
    return None


def _arm(t: Term) -> str:
    """The term's arm as its magnitude writes it: the segment its direction names (⊥ SJ →
    "·SJ"), the term's own order, so that the annotation above a term and the one below it
    name one segment (twenty-fourth round (c)); else its vector product's (" × JS" → "·JS")."""
    if t.dir.code == "perp" and isinstance(t.dir.ref, str) and t.dir.ref:
        return "·" + t.dir.ref
    return "·" + t.how[1].strip().removeprefix("×").strip()


def share(eq: Equation) -> list:
    """Tie the terms of `eq` that share an unknown rate to that rate (their magnitude stays
    "?", its `ref` the rate and its arm, α·JS) and return the sentence that says so and counts
    their ? once, one per shared rate (none if no rate is shared)."""
    groups: dict[str, list[Term]] = {}
    for side in eq.sides:
        for t in side:
            rate = _rate(t)
            if rate is not None:
                groups.setdefault(repr(rate), []).append(t)
    out = []
    for terms in groups.values():
        if len(terms) < 2:
            continue
        rate = terms[0].how[0]
        for t in terms:
            t.mag = Ann("?", [rate, _arm(t)])
        out.append(msg("eq.shared_rate", rate=rate, terms=Names([t.sym for t in terms]),
                       mags=Names([Inline([rate, _arm(t)]) for t in terms])))
    return out


def shared_rates(blocks: list) -> list:
    """The blocks of a step with every equation's shared rates written once (`share`), the
    sentence just before its equation."""
    out: list = []
    for b in blocks:
        if isinstance(b, Section):
            b.blocks = shared_rates(b.blocks)
        elif isinstance(b, Equation) and b.level in ("v", "a"):
            out += share(b)
        out.append(b)
    return out
