"""The words an explanation lends a question's kind (`kinematika.questions`) to name what is
asked and the parts of its answer (`QuestionKind.label`, `part`): its symbols, messages and
the model's names as the notes write them (`ExplainWords`, a `questions.Words`)."""
from __future__ import annotations

from typing import Any

from ..model.model import PointRef
from .contacts import geometric_sym
from .context import Ctx, alpha_sym, omega_sym
from .document import Inline, Name, Sym, msg
from .terms import relative_name

RATES = {"ω": omega_sym, "α": alpha_sym}


class ExplainWords:
    """The explanation's symbols, messages and names, for a kind's `label` and `part`."""

    def __init__(self, ctx: Ctx) -> None:
        self.ctx = ctx
        self.planar = ctx.planar

    def sym(self, base: str, sub: str = "", sup: str = "", vector: bool = True, sub_key: str = "") -> Sym:
        """A symbol of the document (`Sym`)."""
        return Sym(base, sub, sup, vector=vector, sub_key=sub_key)

    def msg(self, key: str, **args: Any) -> Any:
        """A catalogue message (`msg`)."""
        return msg(key, **args)

    def inline(self, items: list) -> Inline:
        """A short formula (`Inline`)."""
        return Inline(items)

    def name(self, text: str, kind: str = "point") -> Name:
        """A model's name (`Name`)."""
        return Name(text, kind)

    def ref(self, q: Any) -> PointRef:
        """The question's material point."""
        return self.ctx.model.resolve_point(q.target) if isinstance(q.target, str) else q.target

    def point(self, q: Any) -> str:
        """The point's label (B, A∈4)."""
        ref = self.ref(q)
        return self.ctx.point_label(ref.point, ref.body)

    def motion(self, q: Any) -> str:
        """The point's label, or A∈4/2 seen from a moving body."""
        rel = self.ctx.rel(q.relative_to)
        ref = self.ref(q)
        return relative_name(ref.point, ref.body, rel) if rel else self.point(q)

    def frame(self, q: Any) -> Name:
        """The question's frame as a body's name: the fixed one as a reference (`Name.reference`)."""
        moving = self.ctx.rel(q.relative_to)
        return Name(moving, "body") if moving else Name(self.ctx.frame, "body", reference=True)

    def rate(self, base: str, q: Any, vector: bool) -> Sym:
        """ω_body or α_body, relative to the question's frame when it is not the fixed one."""
        return RATES[base](q.target, self.ctx.rel(q.relative_to), vector=vector)

    def contact(self, q: Any) -> tuple[str, str, str]:
        """The contact's name and the joint's bodies."""
        j = self.ctx.model.joint(q.target)
        return self.ctx.contact(j), j.a, j.b

    def geometric(self, level: str, name: str) -> Sym:
        """v_J^geom (`contacts.geometric_sym`)."""
        return geometric_sym(level, name)
