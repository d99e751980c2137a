"""The intrinsic components of a point's acceleration (`{intrinsic: C}`): its speed |v|, the
unit tangent t = v / |v|, the tangential aᵗ = (a · t) t and the normal aⁿ = a − aᵗ
(`curvature.intrinsic`)."""
from __future__ import annotations

from typing import Any, Optional

from .base import Asked, QuestionKind, Solved, Words
from .curvature import intrinsic


class Intrinsic(QuestionKind):
    """A point's acceleration split along and across its path."""

    name = "intrinsic"
    summary = "the speed, unit tangent and tangential and normal accelerations of a material point"
    about = "point"
    level = "acceleration"
    unit_kind = "acceleration"
    fields = {"speed": "velocity", "tangent": None, "tangential": "acceleration", "normal": "acceleration",
              "tangential_vector": "acceleration", "normal_vector": "acceleration",
              "acceleration": "acceleration"}
    # the answer is the two vectors aᵗ and aⁿ; the speed, the tangent and the two scalars
    # are how they are found, written in the explanation's curvature section (round 24d)
    working = frozenset({"speed", "tangent", "tangential", "normal"})

    def answer(self, sol: Solved, q: Asked) -> Any:
        """Speed, unit tangent, the signed tangential and the normal acceleration
        (`curvature.intrinsic`)."""
        return intrinsic(sol, q)

    def part(self, words: Words, q: Asked, key: str, sub: Optional[str]) -> Any:
        """|v_C|, the tangent t = v_C/|v_C|, a_C^t · t, |a_C^n|, a_C^t, a_C^n: scalars told from vectors by
        how they are written."""
        p = words.point(q)
        t = words.sym("t", vector=True)
        v = words.sym("v", p)
        symbols = {"speed": words.inline(["|", v, "|"]),
                   # the tangent as the unit vector of the velocity, so a student reproduces it
                   # from |v_C| just above: "unit tangent t = v_C/|v_C| = (1, 0)"
                   "tangent": words.inline([words.msg("ans.tangent"), " ", t, " = ", v, "/|", v, "|"]),
                   "tangential": words.inline([words.sym("a", p, "t"), " · ", t]),
                   "normal": words.inline(["|", words.sym("a", p, "n"), "|"]),
                   "tangential_vector": words.sym("a", p, "t"), "normal_vector": words.sym("a", p, "n")}
        return symbols.get(key)


KIND = Intrinsic()
