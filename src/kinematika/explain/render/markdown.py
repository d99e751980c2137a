"""Markdown: readable as plain text; equations as aligned blocks (M/D/? above and below
each term, as in the slides) and figures as inline SVG images (data URIs)."""
from __future__ import annotations

import base64
from typing import Any

from ..document import Equation, Figure, Sym
from .base import Renderer
from .svg import svg
from .unicode import unicode_formula


class MarkdownRenderer(Renderer):
    fmt = "md"

    def esc(self, text: str) -> str:
        return text

    def sym(self, s: Sym) -> str:
        sub = self.sub_text(s)
        return s.base + (f"_{sub}" if sub else "") + (f"^{s.sup}" if s.sup else "")

    def power(self, mantissa: str, exponent: int) -> str:
        return f"{mantissa}·10^{exponent}"

    def formula(self, expr: Any) -> str:
        return unicode_formula(expr)

    def page(self, body: str) -> str:
        return body.rstrip() + "\n"

    def heading(self, level: int, text: str) -> str:
        return f"\n{'#' * level} {text}\n"

    def para(self, text: str) -> str:
        return f"{text}\n"

    def equation(self, eq: Equation) -> str:
        cols = [(self.ann(eq.target.mag), self.sym(eq.target.sym), self.ann(eq.target.dir))]
        for side in eq.sides:
            cols.append(("", "=", ""))
            for i, t in enumerate(side):
                if i:
                    cols.append(("", "+", ""))
                cols.append((self.ann(t.mag), self.sym(t.sym), self.ann(t.dir)))
        widths = [max(len(c) for c in col) for col in cols]
        lines = ["  ".join(col[k].center(w) for col, w in zip(cols, widths)).rstrip() for k in range(3)]
        terms = [eq.target] + [t for side in eq.sides for t in side]
        listed = "\n".join(f"- {self.term_line(t)}" for t in terms)
        return "```\n" + "\n".join(lines) + "\n```\n\n" + listed + "\n"

    def table(self, header: list[str], rows: list[list[str]]) -> str:
        def line(cells: list[str]) -> str:
            return "| " + " | ".join(c.replace("|", "\\|") for c in cells) + " |"
        return "\n".join([line(header), line(["---"] * len(header))] + [line(r) for r in rows]) + "\n"

    def figure(self, fig: Figure) -> str:
        caption = self.caption(fig)
        drawing = svg(fig, self.svg_label, self.unit(fig.unit) if not self.doc.symbolic else "")
        data = base64.b64encode(drawing.encode("utf-8")).decode("ascii")
        return f"![{caption}](data:image/svg+xml;base64,{data})\n\n*{caption}*\n"
