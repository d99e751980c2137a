"""What the three renderers share: walking the document, filling messages, formatting
numbers, formulas, units, symbols and the M/D/? annotations. A subclass gives the markup."""
from __future__ import annotations

import re
from typing import Any

from babel.lists import format_list

from ...numerals import DECIMAL, decimal_sign, separator, written
from ...text import shown

from ..catalogue import Catalogue
from ..document import (Ann, CentreNote, Derived, Document, Drawing, Equation, Figure, Inline, Msg, Name, Names,
                        Section, Sym, Table, Value)
from .svg import Text, sym_text

TOKEN = "\ue000{}\ue001"
TOKEN_RE = re.compile("\ue000(\\d+)\ue001")


class Slot(str):
    """A message variable as Fluent sees it: a token the renderer replaces by the
    variable's markup; `plain` is its text, for the catalogue's grammar (elision)."""

    plain: str = ""


def plain(x: Any) -> str:
    """The text a name argument is read as (its first name for a list)."""
    if isinstance(x, Name):
        return x.text
    if isinstance(x, Names):
        return plain(x.items[0]) if x.items else ""
    if isinstance(x, str):
        return x
    return ""

UNITS = {"speed": "{L}/s", "accel": "{L}/s²", "len": "{L}", "rate": "rad/s", "rate2": "rad/s²"}
BODY_SUBS = ("ω", "α", "I", "ω×ω")          # symbols whose subscript is made of bodies


def visible(text: str) -> str:
    """Text with its control characters (but for line breaks) shown as escapes: a name
    never drives a terminal, a page or a reader's eye (issue 12's `text.shown`)."""
    return "\n".join(shown(line) for line in text.split("\n"))


class Renderer:
    """Turns a `Document` into text in one language.

    Each format's subclass supplies the markup: `esc(text)`, `sym(Sym)`, `power(mantissa,
    exponent)`, `formula(expr)`, `page(body)`, `heading(level, text)`, `para(text)`,
    `equation(Equation)`, `table(header, rows)` and `figure(Figure)`.
    """

    fmt = ""

    def __init__(self, doc: Document, cat: Catalogue, drawings: bool = True) -> None:
        self.doc = doc
        self.cat = cat
        self.drawings = drawings
        self.decimal = decimal_sign(cat.lang)
        self.comma = separator(self.decimal)      # between a vector's components

    # the walk ---------------------------------------------------------------------------------
    def render(self) -> str:
        """The whole document as one page of the format: its title, then every section."""
        body = [self.heading(1, self.esc(visible(self.doc.title)))]
        body += [self.section(s) for s in self.doc.sections]
        return self.page("\n".join(body))

    def section(self, sec: Section) -> str:
        """A section: its heading at its level, then its blocks in order."""
        parts = [self.heading(sec.level, self.message(sec.title))]
        parts += [self.block(b) for b in sec.blocks]
        return "\n".join(p for p in parts if p)

    def block(self, b: Any) -> str:
        """One block in the format's markup: a message as a paragraph, an equation (with its
        polygon), a derived value, a table, a figure, a drawing (when drawings are on) or an
        instant centre's note; a nested section as a section."""
        if isinstance(b, Section):
            return self.section(b)
        if isinstance(b, Msg):
            return self.para(self.message(b))
        if isinstance(b, Equation):
            out = self.equation(b)
            return out + ("\n" + self.figure(b.polygon) if b.polygon is not None else "")
        if isinstance(b, Derived):
            return self.para(self.derived(b))
        if isinstance(b, Table):
            return self.table([self.arg(h) for h in b.header], [[self.cell(c) for c in r] for r in b.rows])
        if isinstance(b, Figure):
            return self.figure(b)
        if isinstance(b, Drawing):
            return self.drawing(b) if self.drawings else ""
        if isinstance(b, CentreNote):
            return self.para(self.centre(b))
        raise TypeError(f"unknown block {type(b).__name__}")

    # messages and their arguments ----------------------------------------------------------
    def message(self, m: Msg) -> str:
        """The catalogue's message with its variables: numbers go to Fluent as numbers (for
        plurals), everything else as a token replaced afterwards by its markup, so the
        catalogue's text is escaped and the variables' markup is not."""
        rendered: list[str] = []
        args: dict[str, Any] = {}
        for name, x in m.args.items():
            if isinstance(x, int) and not isinstance(x, bool):
                args[name] = x
                continue
            if isinstance(x, Names):
                args[f"{name}_n"] = len(x)
            slot = Slot(TOKEN.format(len(rendered)))
            slot.plain = plain(x)
            rendered.append(self.arg(x))
            args[name] = slot
        parts = TOKEN_RE.split(self.cat.format(m.key, args))
        return "".join(self.esc(p) if i % 2 == 0 else rendered[int(p)] for i, p in enumerate(parts))

    def arg(self, x: Any) -> str:
        """A message argument or cell in markup: a name, a list of names joined with the
        language's "and" (Babel), text escaped, a symbol, a value, a nested message, an inline
        formula or a list."""
        if isinstance(x, Name):
            return self.name(x)
        if isinstance(x, Names):
            return format_list([self.arg(i) for i in x.items], locale=self.cat.lang) if x.items else "—"
        if isinstance(x, str):
            return self.esc(x)
        if isinstance(x, Sym):
            return self.sym(x)
        if isinstance(x, Value):
            return self.value(x)
        if isinstance(x, Msg):
            return self.message(x)
        if isinstance(x, Inline):
            return self.inline(x.items)
        if isinstance(x, (list, tuple)):
            return ", ".join(self.arg(i) for i in x)
        return self.esc(str(x))

    def inline(self, items: list) -> str:
        """Inline items (text, symbols, values …) written in a row."""
        return "".join(self.arg(i) for i in items)

    def cell(self, c: Any) -> str:
        """A table cell; answers come as [(label, Value), ...]."""
        if isinstance(c, list) and c and isinstance(c[0], tuple):
            return "; ".join((self.arg(label) + " = " if label else "") + self.arg(v) for label, v in c)
        return self.arg(c)

    def name(self, n: Name) -> str:
        """A model's name as a name (formats set points, bodies and joints apart)."""
        return self.esc(n.text)

    def numbered(self, s: Sym) -> str:
        """A symbol's subscript with its bodies by number, as the notes and the figures write
        them: ω_3, ω_3/2, v_B∈3, v_A∈2/3, a_J∈3/1, I_13 (I_2,11 past nine bodies)."""
        nums = self.doc.numbers
        if not nums or not s.sub:
            return s.sub
        if s.base in BODY_SUBS:
            sep = "," if s.base in ("I", "ω×ω") else "/"
            parts = s.sub.split(sep)
            if not all(p in nums for p in parts):
                return s.sub
            if s.base == "I":
                ks = sorted(nums[p] for p in parts)
                return "".join(map(str, ks)) if max(nums.values()) < 10 else ",".join(map(str, ks))
            return sep.join(str(nums[p]) for p in parts)
        head, *rest = re.split(r"([∈/])", s.sub)
        return head + "".join(str(nums.get(t, t)) if i % 2 else t for i, t in enumerate(rest))

    def caption(self, fig: Figure) -> str:
        """A figure's caption, saying when it is drawn at sample values of the symbols."""
        text = self.message(fig.caption)
        return text + " " + self.message(Msg("fig.sample")) if fig.sample else text

    def drawing_caption(self, d: Drawing) -> str:
        """A `draw` figure's caption, with the numbers a symbolic model is drawn at."""
        text = self.message(d.caption)
        if d.values:
            values = [Inline([Name(k, "param"), " = ", Value(v, "")]) for k, v in d.values.items()]
            text += " " + self.message(Msg("fig.drawn_at", {"values": Names(values)}))
        return text

    def drawing(self, d: Drawing) -> str:
        """A `draw` figure; formats that cannot embed one draw its fallback, or nothing."""
        return self.figure(d.fallback) if d.fallback is not None else ""

    def svg_label(self, s: Sym) -> Text:
        """A symbol in a figure: its SVG text and measured size."""
        return sym_text(s.base, self.sub_text(s), s.sup)

    def sub_text(self, s: Sym) -> str:
        """The subscript of a symbol: the catalogue's word (arr, rel, Cor) and the name."""
        word = self.cat.get(s.sub_key) if s.sub_key else ""
        return visible(",".join(p for p in (word, self.numbered(s)) if p))

    # values ---------------------------------------------------------------------------------
    def value(self, v: Value) -> str:
        """A value with its unit: a number in the language's writing, a vector as (x, y), a
        formula; angles in degrees."""
        x = v.value
        if x is None:
            return "—"
        if isinstance(x, bool):
            return self.esc(str(x).lower())
        if isinstance(x, tuple):
            text = "(" + self.comma.join(self.scalar(c) for c in x) + ")"
        else:
            text = self.scalar(x)
        if v.unit == "deg":
            return text + "°"
        unit = self.unit(v.unit)
        return text + (" " + unit if unit and not self.doc.symbolic else "")

    def unit(self, kind: str) -> str:
        """The unit of a kind of quantity (speed, accel, len, rate, rate2) in the document's
        length unit: "m/s²", "rad/s"; none for other kinds."""
        if kind not in UNITS:
            return ""
        return self.esc(UNITS[kind].format(L=self.doc.length_unit))

    def scalar(self, x: Any) -> str:
        """A scalar: a number (`number`) or a formula (`formula`)."""
        if isinstance(x, (int, float)):
            return self.number(float(x))
        return self.formula(x)

    def number(self, x: float) -> str:
        """Four significant digits, with the language's decimal sign (Babel's); the figures
        write theirs with the same writer (`numerals.written`), to three digits."""
        return written(x, 4, self.decimal, self.power)

    def bar_number(self, x: float) -> str:
        """A scale bar's round length, with the language's decimal sign."""
        return f"{x:g}".replace(".", self.decimal)

    def decimals(self, text: str) -> str:
        """A formula's decimal points as the language writes them."""
        return DECIMAL.sub(self.decimal, text) if self.decimal != "." else text

    # annotations and derived values ------------------------------------------------------------
    def ann(self, a: Ann) -> str:
        """An M/D/? annotation of a term (seed 001): M, D or ?, a magnitude's formula (ω·AB), or
        the direction ⊥ or ∥ a line."""
        if a.code in ("M", "D", "?"):
            if a.code == "M" and a.ref:
                return self.inline(a.ref)
            return self.esc(a.code)
        sign = {"perp": "⊥ ", "para": "∥ "}[a.code]
        return self.esc(sign) + self.arg(a.ref)

    def derived(self, d: Derived) -> str:
        """A value read off an equation, `ω₃ = v_BA / AB = 2.5 rad/s`, with the sense
        (counter-clockwise or clockwise) when it is a nonzero number and the sense is asked."""
        parts = [self.sym(d.sym)]
        if d.how:
            parts.append(self.inline(d.how))
        parts.append(self.value(d.value))
        text = " = ".join(parts)
        if d.sense and isinstance(d.value.value, float) and d.value.value != 0:
            text += " (" + self.message(Msg("sense.ccw" if d.value.value > 0 else "sense.cw")) + ")"
        return text

    def term_line(self, t) -> str:
        """`v_BA = ω × AB = (…) m/s` for the list of an equation's terms."""
        parts = [self.sym(t.sym)]
        if t.how:
            parts.append(self.inline(t.how))
        parts.append(self.value(Value(t.value, _unit(t.sym))))
        return " = ".join(parts)

    # instant centres ------------------------------------------------------------------------
    def centre(self, c: CentreNote) -> str:
        """One instant centre's line: I_ab, how it follows (at a joint of its kind, by
        Aronhold–Kennedy from two lines, where two lines meet, from speeds proportional to the
        distance, where the perpendiculars to two velocities meet, or from ω) and where it is."""
        a, b = c.pair
        name = Sym("I", f"{a},{b}", vector=False)
        if c.how == "joint":
            why = Msg(f"centre.joint.{c.joint_type}", {"joint": Name(c.via[0], "joint")})
        elif c.how == "kennedy":
            k1, k2 = c.via
            why = Msg("centre.kennedy", {"k1": Name(k1, "body"), "k2": Name(k2, "body"),
                                         "l1": [Sym("I", f"{a},{k1}", vector=False), Sym("I", f"{k1},{b}", vector=False)],
                                         "l2": [Sym("I", f"{a},{k2}", vector=False), Sym("I", f"{k2},{b}", vector=False)]})
        elif c.how == "lines":
            why = Msg("centre.lines", {"first": c.via[0], "second": c.via[1]})
        elif c.how == "proportional" and len(c.witnesses) == 2:
            why = self.proportional(c)
        elif len(c.witnesses) == 2:
            (p, vp), (q, vq) = c.witnesses
            why = Msg("centre.velocities", {"p": Name(p), "q": Name(q), "vp": Value(vp, "speed"),
                                            "vq": Value(vq, "speed"), "frame": Name(a, "body")})
        else:
            why = Msg("centre.omega", {"frame": Name(a, "body")})
        return self.message(Msg("centre.line", {"centre": name, "a": Name(a, "body"), "b": Name(b, "body"), "why": why,
                                                "where": self.where(c.value)}))

    def proportional(self, c: CentreNote) -> Msg:
        """Coincident Kennedy lines: the centre from speeds proportional to the distance."""
        a, b = c.pair
        (p, _, vp), (q, _, vq) = c.witnesses
        names = [Sym("I", n[2:], vector=False) if n.startswith("I:") else Name(n) for n in (p, q)]
        lines = [[Sym("I", f"{a},{k}", vector=False), Sym("I", f"{k},{b}", vector=False)] for k in c.via]
        return Msg(f"centre.proportional.{c.side}",
                   {"l1": lines[0], "l2": lines[1], "frame": Name(a, "body"), "p": names[0], "q": names[1],
                    "vp": Value(vp, "speed"), "vq": Value(vq, "speed")})

    def where(self, value: dict) -> Msg:
        """Where a centre is, as a message: at a point, at infinity along a direction, or no
        relative motion."""
        if value.get("rest"):
            return Msg("centre.rest")
        if value.get("point") is None:
            return Msg("centre.infinity", {"direction": Value(value["direction"], "")})
        return Msg("centre.at", {"point": Value(value["point"], "len")})


def _unit(s: Sym) -> str:
    return {"v": "speed", "a": "accel", "ω": "rate", "α": "rate2", "ω×ω": "rate2"}.get(s.base, "")
