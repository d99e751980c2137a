"""One self-contained HTML page: inline CSS, inline SVG figures, formulas in plain HTML and
Unicode (no script, no web font, nothing fetched), so a student can open it offline."""
from __future__ import annotations

from html import escape
from typing import Any

from ..document import Drawing, Equation, Figure, Name, Sym
from .base import Renderer, visible
from .svg import embedded, svg
from .names import html_name
from .unicode import unicode_formula

CSS = """
body{font-family:"DejaVu Serif",Georgia,serif;max-width:60rem;margin:2rem auto;padding:0 1rem;
color:#1b1b1b;line-height:1.45}
h1{font-size:1.7rem;border-bottom:2px solid #1f5fa8}h2{font-size:1.35rem;margin-top:2rem;
border-bottom:1px solid #ccc}h3{font-size:1.1rem;margin-top:1.4rem}
table{border-collapse:collapse;margin:.6rem 0}td,th{padding:.15rem .6rem;text-align:left}
table.grid td,table.grid th{border:1px solid #ccc}table.grid th{background:#f1f4f9}
table.eq{font-size:1.12rem;margin:.8rem 0 .3rem}table.eq td{text-align:center;padding:0 .25rem}
table.eq tr.ann td{font-size:.78rem;color:#555}table.eq td.unknown{color:#c0392b}
ul.terms{margin:.1rem 0 .6rem;font-size:.95rem}figure{margin:.4rem 0 1rem}
figcaption{font-size:.85rem;color:#555}b.v{font-style:italic}
span.pt,span.jt{font-family:"DejaVu Sans",Arial,sans-serif;font-size:.9em}span.jt{color:#444}
p.sample{font-size:.85rem;color:#8a5a00}
figure.drawing svg{width:100%;max-width:42rem;height:auto}
"""


class HtmlRenderer(Renderer):
    """The explanation as one self-contained HTML page (inline CSS and SVG, nothing fetched)."""

    fmt = "html"

    def esc(self, text: str) -> str:
        """Text escaped for HTML, its control characters shown."""
        return escape(visible(text), quote=False)

    def name(self, n: Name) -> str:
        """Points upright and sans serif (as the figures letter them), bodies in italics,
        joints sans serif, parameters as symbols (θ<sub>2</sub>, as in the formulas)."""
        if n.kind == "param":
            return f"<i>{html_name(n.text)}</i>"
        text = self.esc(n.text)
        if n.kind == "body":
            return f'<i class="bd">{text}</i>'
        return f'<span class="{"jt" if n.kind == "joint" else "pt"}">{text}</span>'

    def sym(self, s: Sym) -> str:
        """A symbol: a vector's letter bold, a scalar's italic, with its subscript and
        superscript."""
        base = f'<b class="v">{escape(s.base)}</b>' if s.vector else f"<i>{escape(s.base)}</i>"
        sub = self.sub_text(s)
        return base + (f"<sub>{escape(sub)}</sub>" if sub else "") + (f"<sup>{escape(s.sup)}</sup>" if s.sup else "")

    def power(self, mantissa: str, exponent: int) -> str:
        """m×10ⁿ with the exponent as a superscript."""
        return f"{mantissa}×10<sup>{str(exponent).replace('-', '−')}</sup>"

    def formula(self, expr: Any) -> str:
        """A formula in Unicode and HTML (θ₂ as θ<sub>2</sub>), decimals as the language writes
        them."""
        return self.decimals(unicode_formula(expr, html_name, escape))

    def page(self, body: str) -> str:
        """The HTML page around `body`: the language, the title, the inline CSS."""
        return (f'<!DOCTYPE html>\n<html lang="{self.cat.lang}">\n<head>\n<meta charset="utf-8">\n'
                f"<title>{self.esc(self.doc.title)}</title>\n<style>{CSS}</style>\n</head>\n<body>\n"
                f"{body}\n</body>\n</html>\n")

    def heading(self, level: int, text: str) -> str:
        """An <h1>…<h3> heading."""
        return f"<h{level}>{text}</h{level}>"

    def para(self, text: str) -> str:
        """A paragraph."""
        return f"<p>{text}</p>"

    def equation(self, eq: Equation) -> str:
        """A vector equation as a three-row table — each term's M above it and its direction
        below, the unknowns in red — followed by the list of its terms with their values."""
        cells = [(self.ann(eq.target.mag), self.sym(eq.target.sym), self.ann(eq.target.dir), eq.target.unknown)]
        for side in eq.sides:
            cells.append(("", "=", "", False))
            for i, t in enumerate(side):
                if i:
                    cells.append(("", "+", "", False))
                cells.append((self.ann(t.mag), self.sym(t.sym), self.ann(t.dir), t.unknown))
        rows = []
        for k in range(3):
            tds = "".join(f'<td class="unknown">{c[k]}</td>' if c[3] and k == 1 else f"<td>{c[k]}</td>"
                          for c in cells)
            rows.append(f'<tr class="{"ann" if k != 1 else "terms"}">{tds}</tr>')
        terms = [eq.target] + [t for side in eq.sides for t in side]
        items = "".join(f"<li>{self.term_line(t)}</li>" for t in terms)
        return f'<table class="eq">{"".join(rows)}</table><ul class="terms">{items}</ul>'

    def table(self, header: list[str], rows: list[list[str]]) -> str:
        """A table with a header row and borders."""
        head = "".join(f"<th>{h}</th>" for h in header)
        body = "".join("<tr>" + "".join(f"<td>{c}</td>" for c in r) + "</tr>" for r in rows)
        return f'<table class="grid"><tr>{head}</tr>{body}</table>'

    def figure(self, fig: Figure) -> str:
        """A polygon or figure as inline SVG, to scale with its scale bar (none for formulas),
        and its caption."""
        caption = self.caption(fig)
        self.figures = getattr(self, "figures", 0) + 1
        drawing = svg(fig, self.svg_label, self.unit(fig.unit) if not self.doc.symbolic else "", f"f{self.figures}",
                      self.bar_number)
        return f"<figure>{drawing}<figcaption>{caption}</figcaption></figure>"

    def drawing(self, d: Drawing) -> str:
        """A `draw` figure embedded as inline SVG (its ids made unique on the page), with its
        caption."""
        self.drawn = getattr(self, "drawn", 0) + 1
        return (f'<figure class="drawing">{embedded(d.svg(self.cat.lang), f"d{self.drawn}")}'
                f"<figcaption>{self.drawing_caption(d)}</figcaption></figure>")
