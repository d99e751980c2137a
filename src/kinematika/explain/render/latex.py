"""A LaTeX article (pdflatex, amsmath, TikZ): equations with the M/D/? of each term set
over and under it, polygons as TikZ pictures to scale."""
from __future__ import annotations

import re
from typing import Any

from ..document import Equation, Figure, Name, Sym
from ...text import shown_lines
from ...numerals import function_names
from .base import DECIMAL, Renderer
from .svg import COLOURS, MARGIN, WIDTH, Text, bar_length, layout
from .names import latex_name, upright
from .unicode import latex_formula

TEXT = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_",
        "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}"}
MATH = {"ω": r"\omega", "α": r"\alpha", "ρ": r"\rho", "ℜ": r"\Re", "⊥": r"\perp", "∥": r"\parallel", "∈": r"\in",
        "×": r"\times", "·": r"\cdot", "−": "-", "²": "^2", "³": "^3", "–": "\\text{--}", "→": r"\to",
        "—": "\\text{---}", "ⁿ": "^n", "ᴺ": "^N", "⇒": r"\Rightarrow", "≡": r"\equiv"}

# the Greek letters, as LaTeX's commands (β as \\beta, Φ as \\Phi): pdflatex's utf8 input knows
# none, so one typed in a model's words would stop the compilation; the capitals LaTeX has no
# command for look like Latin ones and are written as those (Α as A), ο as o
_LOWER = (r"\alpha \beta \gamma \delta \epsilon \zeta \eta \theta \iota \kappa \lambda \mu \nu \xi o \pi \rho "
          r"\varsigma \sigma \tau \upsilon \phi \chi \psi \omega")
_UPPER = r"A B \Gamma \Delta E Z H \Theta I K \Lambda M N \Xi O \Pi P \Sigma T \Upsilon \Phi X \Psi \Omega"
GREEK = dict(zip("αβγδεζηθικλμνξοπρςστυφχψω", _LOWER.split())) | dict(zip("ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡΣΤΥΦΧΨΩ", _UPPER.split()))
MATH = GREEK | MATH | {"√": r"\surd", "′": "'"} | {d: f"_{k}" for k, d in enumerate("₀₁₂₃₄₅₆₇₈₉")} \
    | {d: f"^{k}" for k, d in enumerate("⁰¹²³⁴⁵⁶⁷⁸⁹") if d not in MATH}
# a letter with a dot or two over it (φ̇, a note's time derivative): \dot{\phi}, \ddot{x}
MARKED = re.compile("(.)([\u0307\u0308])")
ACCENT = {"\u0307": "dot", "\u0308": "ddot"}
HEAD = r"""\documentclass[11pt]{article}
\usepackage[utf8]{inputenc}
\usepackage[T1]{fontenc}
\usepackage{amsmath,amssymb}
\usepackage{tikz}
\usepackage[margin=2cm]{geometry}
\setlength{\parindent}{0pt}\setlength{\parskip}{0.5em}
"""


def marked(letter: str, mark: str) -> str:
    """A letter and its combining dot(s) as LaTeX math: \\dot{\\phi}."""
    return f"\\{ACCENT[mark]}{{{MATH.get(letter, letter)}}}"


def tex_math(tex: str) -> str:
    """LaTeX math (a name as sympy writes it) with any character pdflatex's utf8 input
    cannot set written as its command: ψ̇ as \\dot{\\psi}, β as \\beta."""
    tex = MARKED.sub(lambda m: marked(m.group(1), m.group(2)), tex)
    return "".join(MATH[ch] + " " if ch in MATH and not ch.isascii() else ch for ch in tex)


def tex_text(text: str) -> str:
    """Plain text for LaTeX: specials escaped, math characters (and a letter with a dot
    over it) set in math mode."""
    parts = MARKED.split(text)              # text, letter, mark, text, letter, mark, …, text
    return "".join(_text(part) if k % 3 == 0 else f"${marked(part, parts[k + 1])}$" if k % 3 == 1 else ""
                   for k, part in enumerate(parts))


def _text(text: str) -> str:
    """Plain text for LaTeX: specials escaped, math characters set in math mode."""
    out = []
    for ch in text:
        if ch in TEXT:
            out.append(TEXT[ch])
        elif ch in MATH:
            out.append(f"${MATH[ch]}$")
        else:
            out.append(ch)
    return "".join(out)


def tex_math_text(text: str) -> str:
    """A name or subscript inside math, upright as the other formats set it (a word is a
    word, not a product of italic letters): `upright` for each run of text, the math
    characters as commands (ω as \\omega, ∈ as \\in, φ̇ as \\dot{\\phi})."""
    out: list[str] = []
    run: list[str] = []

    def end_run() -> None:
        if run:
            out.append(upright(tex_text("".join(run))))
            run.clear()

    parts = MARKED.split(text)              # text, letter, mark, text, …
    for k, part in enumerate(parts):
        if k % 3 == 1:
            end_run()
            out.append(marked(part, parts[k + 1]) + " ")
        elif k % 3 == 0:
            for ch in part:
                if ch in MATH:
                    end_run()
                    out.append(MATH[ch] + " ")
                else:
                    run.append(ch)
    end_run()
    return "".join(out)


class LatexRenderer(Renderer):
    """The explanation as a LaTeX article (pdflatex, amsmath, TikZ)."""

    fmt = "tex"

    def esc(self, text: str) -> str:
        """Text for LaTeX: specials escaped, math characters in math mode, control characters
        shown."""
        return tex_text(shown_lines(text))

    def name(self, n: Name) -> str:
        """Points and joints sans serif, bodies emphasised, parameters as symbols in math
        (as `sympy.latex` writes them in the formulas: \\theta_{2})."""
        if n.kind == "param":
            return f"${tex_math(latex_name(self.spelt(n.text)))}$"
        article, text = self.articled(n)
        command = {"body": "emph"}.get(n.kind, "textsf")
        return self.esc(article) + f"\\{command}{{{self.points(text) if n.kind == 'point' else self.esc(text)}}}"

    def body_word(self, text: str) -> str:
        """A body's name in a model's words emphasised, as `name` sets it."""
        return f"\\emph{{{self.esc(text)}}}"

    def math_sym(self, s: Sym) -> str:
        """A symbol inside math: an arrow over a vector's letter, the subscript and superscript as upright text; ω₁ × ω₂ for the cross term of two rates."""
        if s.base == "ω×ω" and "," in s.sub:
            parent, body = s.sub.split(",", 1)
            return (self.math_sym(Sym("ω", parent, vector=s.vector)) + r" \times "
                    + self.math_sym(Sym("ω", f"{body}/{parent}", vector=s.vector)))
        s = self.noted(s)
        base = tex_math(s.base).strip() if s.base != "ω×ω" else r"\omega\times\omega"     # ψ̇ as \dot{\psi}
        base = rf"\vec{{{base}}}" if s.vector else base
        sub = self.centred(self.sub_text(s, centres=False), lambda t: tex_math_text(t) if t else "",
                           self.math_sym)          # a centre's symbol inside: v_{O I_{OQ}}, run together
        return base + (f"_{{{sub}}}" if sub else "") + (f"^{{{tex_math_text(s.sup)}}}" if s.sup else "")

    def geom_mark(self) -> str:
        """^{geom} upright, in a symbol's math and in a point's name in text alike
        (`\\ensuremath`)."""
        return r"\ensuremath{^{\mathrm{geom}}}"

    def symbol(self, s: Sym) -> str:
        """A symbol in running text: `math_sym` in $…$."""
        return f"${self.math_sym(s)}$"

    def subscripted(self, base: str, sub: str, sup: str = "") -> str:
        """A symbol typed base_sub in a model's words (`Renderer.typed` finds it, for every
        format) as `math_sym` writes one: the letter in math, the subscript (its braces
        dropped) upright below it, $\\omega_{\\mathrm{besoa}}$, not the text ω\\_besoa; a
        superscript typed after it (a_P^n) upright above."""
        bare = [tex_math_text(t.removeprefix('{').removesuffix('}')) for t in (sub, sup)]
        return f"${tex_math(base).strip()}_{{{bare[0]}}}" + (f"^{{{bare[1]}}}" if sup else "") + "$"

    def power(self, mantissa: str, exponent: int) -> str:
        """m × 10ⁿ in math."""
        return f"{mantissa}\\times 10^{{{exponent}}}"

    def number(self, x: float) -> str:
        """A number in math mode, with a true minus and the language's decimal comma set as {,}."""
        return "$" + super().number(x).replace("−", "-").replace(",", "{,}") + "$"

    def formula(self, expr: Any) -> str:
        """A formula as sympy's LaTeX in math mode (the model's notation), decimals as the language writes them."""
        text = tex_math(latex_formula(expr, {n: latex_name(self.spelt(n)) for n in self.wording.parameter_symbols(self.lang)}))
        text = function_names(text, self.lang, latex=True)        # Spanish \operatorname{sen}
        return f"${DECIMAL.sub('{,}', text) if self.decimal == ',' else text}$"

    def page(self, body: str) -> str:
        """The article around `body`: the preamble, the title (in the reader's language), the document environment."""
        return HEAD + "\\title{" + self.esc(self.wording.title(self.lang, self.doc.title)) + "}\\date{}\n\\begin{document}\n" + body + \
            "\n\\end{document}\n"

    def heading(self, level: int, text: str) -> str:
        """The title (level 1: the article's title) or an unnumbered section, subsection or
        subsubsection."""
        if level == 1:
            return r"\maketitle"
        command = {2: "section*", 3: "subsection*"}.get(level, "subsubsection*")
        return f"\\{command}{{{text}}}"

    def para(self, text: str) -> str:
        """A paragraph (text and a line break)."""
        return text + "\n"

    def equation(self, eq: Equation) -> str:
        """A vector equation in display math, each term's M set over it and its direction under
        it (the unknowns in red), followed by an itemised list of its terms with their values."""
        def cell(t) -> str:
            mag, dir_ = self.ann(t.mag), self.ann(t.dir)
            core = rf"\text{{{self.inline(t.how)}}}" if t.spelt else self.math_sym(t.sym)
            if t.unknown:
                core = r"\textcolor{red!60!black}{" + core + "}"
            return rf"\underset{{\text{{\scriptsize {dir_}}}}}{{\overset{{\text{{\scriptsize {mag}}}}}{{{core}}}}}"
        parts = [cell(eq.target)]
        for side in eq.sides:
            parts.append("=")
            parts.append(" + ".join(cell(t) for t in side))
        terms = eq.terms
        items = "\n".join(rf"\item {self.term_line(t)}" for t in terms)
        return "\\[ " + " ".join(parts) + " \\]\n\\begin{itemize}\n" + items + "\n\\end{itemize}\n"

    def table(self, header: list[str], rows: list[list[str]]) -> str:
        """A tabular with a rule above, below and under the header."""
        spec = "l" * len(header)
        lines = [" & ".join(header) + r" \\ \hline"] + [" & ".join(r) + r" \\" for r in rows]
        return "\\begin{tabular}{" + spec + "}\n\\hline\n" + "\n".join(lines) + "\n\\hline\n\\end{tabular}\n"

    def figure(self, fig: Figure) -> str:
        """A polygon or figure as a TikZ picture, laid out as the SVG is, with its caption."""
        caption = self.caption(fig)
        unit, number = self.bar(fig)
        return tikz(fig, self.svg_label, unit, caption, lambda n: tex_text(number(n)))

    def svg_label(self, s: Sym | str) -> Text:
        """A symbol or a polygon's point name in a figure: its measured size and, for a symbol, its LaTeX for TikZ."""
        text = super().svg_label(s)
        if isinstance(s, Sym):
            text.tex = f"${self.math_sym(s)}$"
        return text


def tikz(fig: Figure, label, unit: str, caption: str, number=lambda x: f"{x:g}") -> str:
    """The figure as a TikZ picture 12 cm wide, laid out (labels placed) as the SVG is;
    `number` writes the scale bar's count as LaTeX."""
    lay = layout(fig, label)
    c = 12.0 / WIDTH

    def cm(u: float, v: float) -> str:
        return f"({u * c:.3f},{(lay.height - v) * c:.3f})"

    def at(p: tuple) -> str:
        return cm(*lay.at(p))

    colours = "".join(rf"\definecolor{{k{n}}}{{HTML}}{{{col[1:]}}}" for n, col in COLOURS.items())
    out = [colours, r"\begin{center}\begin{tikzpicture}[>=stealth]"]
    for centre, r in fig.circles:
        out.append(rf"\draw[gray] {at(centre)} circle ({r * lay.k * c:.3f});")
    for p, q in fig.lines:
        out.append(rf"\draw[gray, dashed] {at(p)} -- {at(q)};")
    for p, q in fig.segments:
        out.append(rf"\draw[line width=1.6pt, gray!70!black] {at(p)} -- {at(q)};")
    for a in fig.arrows:
        width = "thick" if a.style == "result" else "semithick"
        out.append(rf"\draw[->, {width}, color=k{a.style}] {at(a.start)} -- {at(a.end)};")
    for _, p, _ in fig.points:
        out.append(rf"\fill {at(p)} circle (1.5pt);")
    for lb in lay.labels:
        colour = next((n for n, col in COLOURS.items() if col == lb.colour), "known")
        if lb.leader is not None:
            out.append(rf"\draw[very thin, color=k{colour}] {cm(*lb.leader[0])} -- {cm(*lb.leader[1])};")
        out.append(rf"\node[color=k{colour}, inner sep=0pt] at {cm(*lb.centre)} {{\small {lb.text.tex or tex_text(lb.text.raw)}}};")
    count = bar_length(lay.k)
    y = lay.height - 14
    out.append(rf"\draw[|-|] {cm(MARGIN, y)} -- {cm(MARGIN + count * lay.k, y)} node[right] "
               rf"{{{number(count)} {unit}}};")
    out.append(r"\end{tikzpicture}\\[2pt]{\small " + caption + r"}\end{center}")
    return "\n".join(out) + "\n"
