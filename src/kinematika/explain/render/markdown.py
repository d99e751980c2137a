"""Markdown: readable as plain text; equations as aligned blocks (M/D/? above and below
each term, as in the slides) and figures as reference-style images (`![caption][fig-1]`).

A figure's data (an SVG of 30–80 kB as a base64 data URI) is one line no reader wants in
the middle of the text: the page's body names each figure by a reference (`[fig-1]`), and
the definitions (`[fig-1]: data:image/svg+xml;base64,…`) come after everything else, so
the page is still one self-contained document. `figure_files` turns those definitions into
SVG files beside a page written to a file (page.fig-1.svg), linked relatively."""
from __future__ import annotations

import base64
import re
from pathlib import PurePath
from typing import Any

from ..document import CENTRE_POINT_RE, Drawing, Equation, Figure, Name, Sym
from ...text import shown_lines
from .base import Renderer
from .html import LONG
from .svg import svg
from .names import unicode_name
from .unicode import unicode_formula

# what Markdown would read as markup; an underscore inside a word (R_roda) is no emphasis
# (CommonMark), so it stays as a reader writes it; "<" only where it opens a tag or an
# autolink (<b, </, <!), ">" only where it opens a quote (a line's start): "r₂ > 2 r₁" reads
# as written. A bar is markup only in a table's cell (`MarkdownRenderer.table`), so |v_A|
# reads as it is written elsewhere
MARKUP = re.compile(r"([\\`*\[\]]|<(?=[A-Za-z/!?])|(?<=^)>|(?<!\w)_|_(?!\w))", re.M)
BAR = re.compile(r"(?<!\\)\|")


# a figure's reference definition, as `MarkdownRenderer.page` writes it at the page's end
DEFINITION = re.compile(r"^\[(fig-\d+)\]: data:image/svg\+xml;base64,([A-Za-z0-9+/=]+)$", re.M)


COMPOUND = "/,-∈ ^"        # a subscript with these holds more than one name (or words: roda sup; J^{geom})


class MarkdownRenderer(Renderer):
    """The explanation as Markdown, readable as plain text: equations as aligned code blocks,
    figures as images by reference, their SVG data URIs at the page's end."""

    fmt = "md"

    code = False            # inside an equation's code block: nothing is markup there

    def esc(self, text: str) -> str:
        """Text with Markdown's markup characters escaped (inside an equation's code block only
        a backquote is changed), control characters shown."""
        text = shown_lines(text)
        if self.code:
            return text.replace("`", "ʼ")
        return MARKUP.sub(r"\\\1", text)

    def name(self, n: Name) -> str:
        """Bodies and parameters in italics (parameters as symbols: θ₂, x_B), the other
        names as they are (escaped); a parameter inside a formula (an equation's block, an
        inline formula: `Renderer.inline`) plain, as the values beside it write it (v_C1 / r)."""
        if n.kind == "param":
            text = self.esc(unicode_name(self.spelt(n.text))).replace("\\_", "_")
            return text if self.code or self.in_formula else f"*{text}*"
        article, text = self.articled(n)
        text = self.points(text)
        return self.esc(article) + (f"*{text}*" if n.kind == "body" and not self.code else text)

    def body_word(self, text: str) -> str:
        """A body's name in a model's words in italics, as `name` sets it (not in a code block)."""
        return self.esc(text) if self.code else f"*{self.esc(text)}*"

    def symbol(self, s: Sym) -> str:
        """A symbol in plain text: v_B, a_B^n; a subscript of more than one name in braces,
        so that it cannot be read as a division or a difference: ω_{3/2}, v_{A∈3/2},
        v_{rel,A}, v_{O2-A}. An instant centre is written one way on a page, its subscript
        always in braces (`centre_braced`): I_{polea}, I_{OQ}, and so in a segment (CI_{polea},
        I_{OQ}O) and inside another symbol's subscript (v_{I_{polea}}, v_{CI_{polea}}, as v_CJ
        is the segment CJ)."""
        raw = self.sub_text(s, centres=False)
        sub = self.centred(raw, lambda t: self.esc(t).replace("\\_", "_"), self.symbol)
        if centre_braced(s, sub) or any(c in sub for c in COMPOUND) or CENTRE_POINT_RE.search(raw):
            sub = "{" + sub + "}"
        return s.base + (f"_{sub}" if sub else "") + (f"^{s.sup}" if s.sup else "")

    def power(self, mantissa: str, exponent: int) -> str:
        """m·10^n."""
        return f"{mantissa}·10^{exponent}"

    def formula(self, expr: Any) -> str:
        """The Unicode formula (its bars |x| as they are: a table's cell escapes them)."""
        return self.decimals(unicode_formula(expr, lambda n: unicode_name(self.spelt(n)), lang=self.lang))

    def page(self, body: str) -> str:
        """The body as the whole page, then each figure's reference definition (its SVG as a
        data URI, one line each) after everything else, ending with one newline."""
        images = getattr(self, "images", [])
        definitions = "".join(f"\n[{label}]: data:image/svg+xml;base64,{base64.b64encode(drawing.encode('utf-8')).decode('ascii')}"
                              for label, drawing in images)
        return body.rstrip() + ("\n" + definitions if images else "") + "\n"

    def image(self, caption: str, drawing: str) -> str:
        """An image by reference (`![title][fig-N]`), its SVG kept for the page's end
        (`page`), and its caption in italics below. The caption is read once: the image's
        alternative text is only the figure's title (the caption's first clause, "Velocity
        polygon"), and the caption below is one emphasis, the italics of the names and
        symbols inside it dropped (`*… *R* = 0.1 …*` nests, and a Markdown reader closes the
        caption's italics at the first inner star)."""
        self.images = getattr(self, "images", [])
        label = f"fig-{len(self.images) + 1}"
        self.images.append((label, drawing))
        plain = UNESCAPED_STAR.sub("", caption)
        return f"![{figure_title(plain)}][{label}]\n\n*{plain}*\n"

    def heading(self, level: int, text: str) -> str:
        """A # heading of the level, between blank lines."""
        return f"\n{'#' * level} {text}\n"

    def para(self, text: str) -> str:
        """A paragraph."""
        return f"{text}\n"

    def equation(self, eq: Equation) -> str:
        """A vector equation as a code block of three aligned rows (each term's M above it, its
        direction below, as in the slides), followed by the list of its terms with their values."""
        self.code = True
        try:
            block = self._block(eq)
        finally:
            self.code = False
        terms = eq.terms
        listed = "\n".join(f"- {self.term_line(t)}" for t in terms)
        return block + "\n" + listed + "\n"

    def _block(self, eq: Equation) -> str:
        """Three lines (M/D/? over and under each term); a long equation one side to a block
        of three lines, each further block starting with =."""
        groups: list[list[tuple]] = [[(self.ann(eq.target.mag), self.sym(eq.target.sym), self.ann(eq.target.dir))]]
        long = sum(len(side) for side in eq.sides) > LONG
        for side in eq.sides:
            if long and len(groups[-1]) > 1:
                groups.append([])
            groups[-1].append(("", "=", ""))
            for i, t in enumerate(side):
                if i:
                    groups[-1].append(("", "+", ""))
                groups[-1].append((self.ann(t.mag), self.written(t), self.ann(t.dir)))
        blocks = []
        for n, cols in enumerate(groups):
            widths = [max(len(c) for c in col) for col in cols]
            indent = "    " if n else ""
            blocks.append("\n".join(indent + "  ".join(col[k].center(w) for col, w in zip(cols, widths)).rstrip()
                                    for k in range(3)))
        return "```\n" + "\n".join(blocks) + "\n```\n"

    def table(self, header: list[str], rows: list[list[str]]) -> str:
        """A pipe table. A bar inside a cell would end the cell, and neither its escape (\\|,
        a backslash a plain-text reader sees) nor another bar character (∣, beside the page's
        |v_A| elsewhere: two bars for one magnitude) reads as the notes write it; so a table
        whose cells hold a magnitude's bars is written as a list of its rows, "- question:
        answer", the other columns named by their headers (issue 30, sixteenth round: C5-1.7's
        "∣v_P∣" beside "|v_P|")."""
        if any(BAR.search(c) for r in rows for c in r):
            return self.rows_as_list(header, rows)

        def line(cells: list[str]) -> str:
            return "| " + " | ".join(cells) + " |"
        return "\n".join([line(header), line(["---"] * len(header))] + [line(r) for r in rows]) + "\n"

    def rows_as_list(self, header: list[str], rows: list[list[str]]) -> str:
        """A table as a list, one row an item: "- first cell: second cell" for two columns,
        "- first cell: header: cell; header: cell" for more."""
        items = []
        for r in rows:
            rest = r[1:] if len(r) == 2 else [f"{h}: {c}" for h, c in zip(header[1:], r[1:])]
            items.append(f"- {r[0]}: " + "; ".join(rest))
        return "\n".join(items) + "\n"

    def figure(self, fig: Figure) -> str:
        """A polygon or figure as an SVG data-URI image, with its caption in italics below."""
        caption = self.caption(fig)
        self.figures = getattr(self, "figures", 0) + 1
        unit, number = self.bar(fig)
        drawing = svg(fig, self.svg_label, unit, f"f{self.figures}", number)
        return self.image(caption, drawing)

    def drawing(self, d: Drawing) -> str:
        """A `draw` figure as an SVG image by reference, with its caption in italics below."""
        return self.image(self.drawing_caption(d), d.svg(self.cat.lang))


def centre_braced(s: Sym, sub: str) -> bool:
    """Whether `s` is an instant centre, whose subscript Markdown always sets in braces
    (issue 30, twenty-seventh round (g): a Basque teacher read "I_polea", "I_{polea}" and
    "v_{C,I_polea}" for one centre on C5-1.1's page, I_OQ beside I_{OQ} on C5-1.2's). A segment
    that starts at a centre must close its subscript (I_{OQ}O, the thirteenth round), so the
    closed form is the one every place can write: standalone, in a segment and inside another
    symbol's subscript alike."""
    return s.base == "I" and bool(sub)


UNESCAPED_STAR = re.compile(r"(?<!\\)\*")
TITLE_END = re.compile(r"[,:;(]|\.(?!\d)")


def figure_title(caption: str) -> str:
    """A figure's title: its caption up to the first comma, colon, semicolon, bracket or full stop
    ("Velocity polygon, to scale: …" → "Velocity polygon"), square brackets left out (they
    would end the image's text)."""
    m = TITLE_END.search(caption)
    return (caption[:m.start()] if m else caption).replace("[", "").replace("]", "").strip()


def figure_files(page: str, path: PurePath) -> tuple[str, dict[str, str]]:
    """A Markdown page to be written to `path` with its figures as files beside it: the
    page with each figure's definition pointing to `<stem>.fig-N.svg` (a relative link,
    so the folder can be moved whole; in angle brackets if the name has a space), and
    those files' names and SVG texts."""
    files: dict[str, str] = {}

    def linked(m: re.Match) -> str:
        name = f"{path.stem}.{m.group(1)}.svg"
        files[name] = base64.b64decode(m.group(2)).decode("utf-8")
        return f"[{m.group(1)}]: " + (f"<{name}>" if re.search(r"[\s()<>]", name) else name)

    return DEFINITION.sub(linked, page), files
