"""One self-contained HTML page: inline CSS, inline SVG figures, formulas in plain HTML and
Unicode (no script, no web font, nothing fetched), so a student can open it offline."""
from __future__ import annotations

import re
from html import escape
from typing import Any

from ..document import Drawing, Equation, Figure, Name, Sym
from ...text import shown_lines
from .base import Renderer
from .svg import embedded, svg
from .names import html_marked, html_name
from .unicode import unicode_formula

CSS = """
body{font-family:"DejaVu Serif",Georgia,serif;max-width:60rem;margin:2rem auto;padding:0 1rem;
color:#1b1b1b;line-height:1.45}
h1{font-size:1.7rem;border-bottom:2px solid #1f5fa8}h2{font-size:1.35rem;margin-top:2rem;
border-bottom:1px solid #ccc}h3{font-size:1.1rem;margin-top:1.4rem}
table{border-collapse:collapse;margin:.6rem 0}td,th{padding:.15rem .6rem;text-align:left}
table.grid td,table.grid th{border:1px solid #ccc}table.grid th{background:#f1f4f9}
table.eq{font-size:1.12rem;margin:.8rem 0 .3rem}table.eq td{text-align:center;padding:0 .25rem;white-space:nowrap}
table.eq+table.eq{margin-top:.1rem;margin-left:2rem}
table.eq tr.ann td{font-size:.78rem;color:#555}table.eq td.unknown{color:#c0392b}
ul.terms{margin:.1rem 0 .6rem;font-size:.95rem}figure{margin:.4rem 0 1rem}
figcaption{font-size:.85rem;color:#555}b.v{font-style:italic}
span.pt,span.jt{font-family:"DejaVu Sans",Arial,sans-serif;font-size:.9em}span.jt{color:#444}
p.sample{font-size:.85rem;color:#8a5a00}span.mk{font-family:"DejaVu Sans",Arial,sans-serif}
span.dt,span.dd{position:relative;display:inline-block}span.dt::after,span.dd::after{position:absolute;
left:0;right:0;top:.08em;padding-left:.2em;text-align:center;font-style:normal}span.dt::after{content:"\\02D9"}
span.dd::after{content:"\\00A8"}span.tl::after{top:-.2em}
figure.drawing svg{width:432pt;max-width:100%;height:auto}figure svg{max-width:100%;height:auto}
@media print{@page{size:A4;margin:2cm}body{max-width:none;margin:0;padding:0;font-size:10.5pt}
figure,table.eq{break-inside:avoid}h2,h3{break-after:avoid}}
"""


LONG = 8            # terms: a longer equation is set one side to a line
MARKED = re.compile("(.[\u0300-\u036f]+)")     # a letter and its combining marks
# a letter with a dot or two over it in a model's words (the notes' φ̇ = v₀ …): a rate, set as
# `symbol` sets one, in italics; upright, DejaVu Sans puts φ̇'s dot on the φ's stem and a
# reader saw φ (twenty-fourth round (e))
DOTTED = re.compile("(.[\u0307\u0308]+)")


class HtmlRenderer(Renderer):
    """The explanation as one self-contained HTML page (inline CSS and SVG, nothing fetched)."""

    fmt = "html"

    def esc(self, text: str) -> str:
        """Text escaped; a letter with a combining mark (θ̇ in a note) in the sans font, and
        in italics when the mark is a dot (a rate, `DOTTED`), as `symbol` writes it."""
        text = escape(shown_lines(text), quote=False)
        return MARKED.sub(lambda m: (f'<i>{html_marked(m[1])}</i>' if DOTTED.fullmatch(m[1])
                                     else html_marked(m[1])), text)

    def name(self, n: Name) -> str:
        """Points upright and sans serif (as the figures letter them), bodies in italics,
        joints sans serif, parameters as symbols (θ<sub>2</sub>, as in the formulas)."""
        if n.kind == "param":
            return f"<i>{html_name(self.spelt(n.text))}</i>"
        article, text = self.articled(n)
        if n.kind == "body":
            return self.esc(article) + f'<i class="bd">{self.esc(text)}</i>'
        return f'<span class="{"jt" if n.kind == "joint" else "pt"}">{self.points(text)}</span>'

    def body_word(self, text: str) -> str:
        """A body's name in a model's words in italics, as `name` sets it."""
        return f'<i class="bd">{self.esc(text)}</i>'

    def symbol(self, s: Sym) -> str:
        """A symbol: a vector's letter bold, a scalar's italic, with its subscript and superscript;
        a letter with a combining mark (the notes' ψ̇, δ̇) in the sans font, as `html_name`
        sets one: the serif italic puts δ̇'s dot into the δ's curl."""
        letter = MARKED.sub(lambda m: html_marked(m[1]), escape(s.base))
        base = f'<b class="v">{letter}</b>' if s.vector else f"<i>{letter}</i>"
        sub = self.centred(self.sub_text(s, centres=False), lambda t: escape(t, quote=False), self.symbol)
        return base + (f"<sub>{sub}</sub>" if sub else "") + (f"<sup>{escape(s.sup)}</sup>" if s.sup else "")

    def subscripted(self, base: str, sub: str, sup: str = "") -> str:
        """A symbol typed base_sub in a model's words as `symbol` writes one: the letter in
        italics, the subscript (its braces dropped) below: ω<sub>pinyó</sub>, not ω_pinyó;
        a superscript typed after it (a_P^n) above."""
        bare = [self.esc(t.removeprefix('{').removesuffix('}')) for t in (sub, sup)]
        return f"<i>{self.esc(base)}</i><sub>{bare[0]}</sub>" + (f"<sup>{bare[1]}</sup>" if sup else "")

    def geom_mark(self) -> str:
        """J<sup>geom</sup>, inside a subscript too."""
        return "<sup>geom</sup>"

    def power(self, mantissa: str, exponent: int) -> str:
        """m×10ⁿ with the exponent as a superscript."""
        return f"{mantissa}×10<sup>{str(exponent).replace('-', '−')}</sup>"

    def formula(self, expr: Any) -> str:
        """A formula in Unicode and HTML (θ₂ as θ<sub>2</sub>, the model's notation), decimals as
        the language writes them; its symbols in italics, as `name` sets a parameter in the
        prose and the tables (r in "radi r", "(2·r·ω; 0)" and the Data table one letter)."""
        return self.decimals(unicode_formula(expr, lambda n: f"<i>{html_name(self.spelt(n))}</i>", escape, self.lang))

    def page(self, body: str) -> str:
        """The HTML page around `body`: the language, the title, the inline CSS."""
        return (f'<!DOCTYPE html>\n<html lang="{self.cat.lang}">\n<head>\n<meta charset="utf-8">\n'
                f"<title>{escape(shown_lines(self.wording.title(self.lang, self.doc.title)), quote=False)}</title>\n<style>{CSS}</style>\n</head>\n<body>\n"
                f"{body}\n</body>\n</html>\n")

    def heading(self, level: int, text: str) -> str:
        """An <h1>…<h3> heading."""
        return f"<h{level}>{text}</h{level}>"

    def para(self, text: str) -> str:
        """A paragraph."""
        return f"<p>{text}</p>"

    def equation(self, eq: Equation) -> str:
        """The equation as a table of three rows (M/D/? over and under each term); a long one
        (more than LONG terms) one side to a line, each further line starting with =."""
        lines: list[list[tuple]] = [[(self.ann(eq.target.mag), self.sym(eq.target.sym), self.ann(eq.target.dir),
                                      eq.target.unknown)]]
        long = sum(len(side) for side in eq.sides) > LONG
        for side in eq.sides:
            if long and len(lines[-1]) > 1:
                lines.append([])
            lines[-1].append(("", "=", "", False))
            for i, t in enumerate(side):
                if i:
                    lines[-1].append(("", "+", "", False))
                lines[-1].append((self.ann(t.mag), self.written(t), self.ann(t.dir), t.unknown))
        tables = []
        for cells in lines:
            rows = []
            for k in range(3):
                tds = "".join(f'<td class="unknown">{c[k]}</td>' if c[3] and k == 1 else f"<td>{c[k]}</td>"
                              for c in cells)
                rows.append(f'<tr class="{"ann" if k != 1 else "terms"}">{tds}</tr>')
            tables.append(f'<table class="eq">{"".join(rows)}</table>')
        terms = eq.terms
        items = "".join(f"<li>{self.term_line(t)}</li>" for t in terms)
        return "".join(tables) + f'<ul class="terms">{items}</ul>'

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
        unit, number = self.bar(fig)
        drawing = svg(fig, self.svg_label, unit, f"f{self.figures}", number)
        return f"<figure>{drawing}<figcaption>{caption}</figcaption></figure>"

    def drawing(self, d: Drawing) -> str:
        """A `draw` figure embedded as inline SVG (its ids made unique on the page), with its
        caption."""
        self.drawn = getattr(self, "drawn", 0) + 1
        return (f'<figure class="drawing">{embedded(d.svg(self.cat.lang), f"d{self.drawn}")}'
                f"<figcaption>{self.drawing_caption(d)}</figcaption></figure>")
