"""What the three renderers share: walking the document, filling messages, formatting
numbers, formulas, units, symbols and the M/D/? annotations. A subclass gives the markup."""
from __future__ import annotations

import re
from abc import ABC, abstractmethod
from typing import Any, Callable, Optional

from babel.lists import format_list

from ...numerals import DECIMAL, decimal_sign, separator, written
from ...text import shown_lines

from ...draw.names import centre_subscript
from ...model.wording import ARTICLES, NO_ARTICLE, Wording, component_superscript, part_subscript, rate_key
from ..catalogue import CONTRACTIONS, Catalogue
from ..document import (CENTRE_POINT_RE, GEOM_MARK, Ann, centre_point, CentreNote, Derived, Document, Drawing, Equation, Figure, Inline, Lead, Msg, Name, Names, Own,
                        Described, Section, Sym, Table, Told, Value)
from .names import written as written_name
from .unicode import formula_values
from .svg import Text, plain_text, sym_text

TOKEN = "\ue000{}\ue001"
LEGEND = "\ue002legend\ue003"        # where the legend of shortened subscripts goes (`render`)
EARLY_LEGEND = "\ue002early\ue003"   # … or, when a block before it writes one, before that block
CENTRES_INTRO = "\ue002centres\ue003"   # where the centres' first sentence goes (`render`)
TOKEN_RE = re.compile("\ue000(\\d+)\ue001")
# the rates the notes name by the Euler angle a model's notation writes them with: ψ̇, a
# body's rate about the vertical axis, is its precession (`BaseRenderer._rate_named`)
EULER_RATES = {"psidot": "rate.precession"}
# a symbol typed in a model's own words: one letter (with its marks: φ̇) that ends no word, an
# underscore, then a subscript of letters and digits or one in braces (v_B, Ω_pinyó, ℜ_P,
# a_{F∈gurpila}); snake_case (draw_at) is not one, its letter ends a word; a superscript
# after it is the symbol's power, not its subscript (v_P² is v_P squared: twenty-fourth round (e))
TYPED_GEOM = "^{geom}"      # the geometric contact point's mark as a model's words type it
SUBSCRIPTED = re.compile("(?<![\\w\u0300-\u036f])([^\\W\\d_][\u0300-\u036f]*)_(\\{[^{}]+\\}|[^\\W_\u00b2\u00b3\u00b9\u2070-\u207f]+)"
                         "(?:\\^(\\{[^{}]+\\}|[^\\W_\u00b2\u00b3\u00b9\u2070-\u207f]+))?")
# ...and a superscript after it (a_P^n, the normal component as the page writes it)
# what a name's markup begins with before its first letter, by format
LEADING_MARKUP = {"html": re.compile(r"(?:<[^>]*>)*"), "md": re.compile(r"[*_]*"),
                  "tex": re.compile(r"(?:\\[A-Za-z]+\{)*")}


# The article a language's running text gives a body's name that the model writes without
# one: English "The *wheel* rolls", not "*Wheel* rolls" (the notes' digest, like any English
# text, says "the wheel"); Catalan and Spanish models write theirs in the name (la roda).
# A table's cell (a bare name) has none, nor a numbered designation (`NUMBERED`: pulley 1).
SUPPLIED_ARTICLE = {"en": "the "}
# a name ending in a number is a designation, said without an article (pulley 1, planet 2)
NUMBERED = re.compile(r"\s\d+$")
# an English plural noun ends in s, not in ss, us or is (wheels, pedals; not glass, chassis)
ENGLISH_PLURAL = re.compile(r"(?i)[a-z]*[^sui]s$")
# coordinates typed in a model's own words: two or three terms in parentheses, ", " between
# them, none with a space (a term may hold a decimal comma: (0,6, 0,3, 0)), one with a digit
_TERM = r"[^\s();,]+(?:,[^\s();,]+)?"
TYPED_COORDINATES = re.compile(rf"\(({_TERM}(?:, {_TERM}){{1,2}})\)")


class Slot(str):
    """A message variable as Fluent sees it: a token the renderer replaces by the
    variable's markup; `plain` is its text, for the catalogue's grammar (elision)."""

    plain: str = ""
    n_names: int = 1            # how many names it holds (a verb after a list is plural)
    many: bool = False          # a plural name (the wheels): a verb after it is plural


def plain(x: Any) -> str:
    """The text a name argument is read as (its first name for a list)."""
    if isinstance(x, Name):
        return x.text
    if isinstance(x, Names):
        return plain(x.items[0]) if x.items else ""
    if isinstance(x, str):
        return x
    if isinstance(x, Sym):          # read by its letter: I_16 is "i setze" (al voltant d'I_16)
        return x.base + "_"
    return ""

UNITS = {"speed": "{L}/s", "accel": "{L}/s²", "len": "{L}", "rate": "rad/s", "rate2": "rad/s²"}
# the messages that explain the bodies' numbers, and their words where the bodies are named
NAMED_KEYS = {"centres.intro": "centres.intro_named", "fig.centres": "fig.centres_named",
              "fig.mechanism": "fig.mechanism_named"}
SOLIDO_RE = re.compile(r"^ solidoa([a-z]*)\b")      # Basque: " solidoaren" after a body's name (singular)
BODY_SUBS = ("ω", "α", "I", "ω×ω")          # symbols whose subscript is made of bodies


class Renderer(ABC):
    """Turns a `Document` into text in one language.

    Each format's subclass supplies the markup: `esc(text)`, `sym(Sym)`, `power(mantissa,
    exponent)`, `formula(expr)`, `page(body)`, `heading(level, text)`, `para(text)`,
    `equation(Equation)`, `table(header, rows)` and `figure(Figure)`.
    """

    fmt = ""

    def __init__(self, doc: Document, cat: Catalogue, drawings: bool = True) -> None:
        self.doc = doc
        self.cat = cat
        self.lang = cat.lang
        self.wording = doc.wording or Wording()
        self.drawings = drawings
        self.decimal = decimal_sign(cat.lang)
        self.comma = separator(self.decimal)      # between a vector's components

    # the format's markup (each subclass's) -----------------------------------------------------
    @abstractmethod
    def esc(self, text: str) -> str:
        """`text` escaped for the format."""

    @abstractmethod
    def symbol(self, s: Sym) -> str:
        """A symbol (already as the model's notation writes it) in the format's markup."""

    @abstractmethod
    def power(self, mantissa: str, exponent: int) -> str:
        """A number in scientific notation: mantissa × 10^exponent."""

    @abstractmethod
    def formula(self, expr: Any) -> str:
        """A sympy expression in the format's markup."""

    @abstractmethod
    def page(self, body: str) -> str:
        """The whole page around its body."""

    @abstractmethod
    def heading(self, level: int, text: str) -> str:
        """A heading of `level` (1 for the title)."""

    @abstractmethod
    def para(self, text: str) -> str:
        """A paragraph."""

    @abstractmethod
    def equation(self, eq: Equation) -> str:
        """A vector equation with its M/D/? annotations."""

    @abstractmethod
    def table(self, header: list[str], rows: list[list[str]]) -> str:
        """A table of text cells."""

    @abstractmethod
    def figure(self, fig: Figure) -> str:
        """A figure (a polygon, the centres)."""

    # the walk ---------------------------------------------------------------------------------
    def render(self) -> str:
        """The whole document as one page of the format: its title (the model's, in the
        reader's language when it gives one), then every section. The legend of shortened
        subscripts (`subscripts`) is written last, where it stands, once the page has said
        which labels it writes."""
        self._written: set[str] = set()
        self._rated: set[str] = set()        # bodies whose own symbol (ω_X, α_X, I_X) is written
        self._noted: dict[str, None] = {}     # bodies whose ω the model's notation writes otherwise (ψ̇), as written
        self._noted_rel: dict[tuple[str, str], None] = {}   # (body, other) whose relative ω it writes otherwise (δ̇)
        self._rating = False
        self._member: Optional[tuple[str, str]] = None   # the first v_{J∈b} written (`subscripts`)
        self._members: dict[str, str] = {}   # each body written after ∈, at its first point (`subscripts`)
        self._legend: Optional[Msg] = None
        self._rel: Optional[tuple[str, str, str, str]] = None   # the first symbol written with "rel" (`subscripts`)
        self._rel_told = False               # the data's sentence on relative quantities said "rel"
        self._rates_told: set[str] = set()   # relative rates (b/a) that sentence defined (the fan's ω₂)
        self._rel_centres: list[Sym] = []    # instant centres written with "rel", I_{a rel b}
        self._centres_intro: Optional[tuple[str, str]] = None
        self._early = False                  # the legend stands before the first block that needs it
        body = [self.heading(1, self.esc(shown_lines(self.wording.title(self.lang, self.doc.title))))]
        with formula_values(self.doc.values):
            body += [self.section(s) for s in self.doc.sections]
        page = "\n".join(body)
        if self._legend is not None:
            said = self.subscripts(self._legend)
            if self._early:                  # said where a shortened subscript is first written
                page = page.replace(LEGEND + "\n", "", 1).replace(EARLY_LEGEND + "\n", said + "\n" if said else "", 1)
            page = page.replace(LEGEND if said else LEGEND + "\n", said, 1)
        if self._centres_intro is not None:      # a message may write a centre it then does not show
            centres, self._rel_centres = self._rel_centres, []
            shown = any(self.sym(c) in page for c in centres)
            page = page.replace(CENTRES_INTRO, self._centres_intro[shown], 1)
        return self.page(page)

    def section(self, sec: Section) -> str:
        """A section: its heading at its level, then its blocks in order."""
        parts = [self.heading(sec.level, self.message(sec.title))]
        parts += [self.declared(b) for b in sec.blocks]
        return "\n".join(p for p in parts if p)

    def declared(self, b: Any) -> str:
        """Block `b` as `block` writes it; before the legend of shortened subscripts has its
        place (the structure's notation line), a block that writes one of them first (the
        Data's "Given: ω_wheel1 = −ω" on C5-E.3, a statement's "r ω_pinoia = R ω_platera"
        on C5-E.6, 2.1's v_{F∈furka}) is preceded by the legend's mark: the legend is said
        there, once, before the symbol is read, where the Data has just introduced the
        body (issue 30, twenty-seventh round (g); `render`). The model's statement (`Told`
        "data": what the mechanism is, in the statement's words) is read whole first and the
        legend follows it: a notation before the mechanism is described names bodies the
        reader has not met (twenty-eighth round (e): C5-E.6's Data opened with "Notation:
        ω_wheel1 … ω_{sprocket rel frame}" before the bicycle, because the statement's
        second paragraph writes r ω_sprocket = R ω_chainring)."""
        if self._legend is not None or self._early or not hasattr(self, "_written") or isinstance(b, Section):
            return self.block(b)
        rated, members, member = set(self._rated), set(self._members), self._member
        text = self.block(b)
        if self._legend is not None:
            return text
        spelt = self.wording.bodies.get(self.lang or "", {})
        new = (self._rated - rated) | (set(self._members) - members)
        if (member is None and self._member is not None and spelt) or any(
                not self._plain(x, self.labels().get(x, ""), spelt) for x in new if spelt):
            self._early = True
            if isinstance(b, Told) and b.kind == "data":        # the statement first, then its notation
                return text + "\n" + EARLY_LEGEND + "\n"
            return EARLY_LEGEND + "\n" + text
        return text

    def block(self, b: Any) -> str:
        """One block in the format's markup: a message as a paragraph, an equation (with its
        polygon), a derived value, a table, a figure, a drawing (when drawings are on) or an
        instant centre's note; a nested section as a section."""
        if isinstance(b, Section):
            return self.section(b)
        if isinstance(b, Msg) and b.key == "structure.subscripts":
            if not hasattr(self, "_written"):
                return self.subscripts(b)
            self._legend = b                 # said once the page's symbols are known (`render`)
            return LEGEND
        if isinstance(b, Msg) and b.key == "centres.intro" and self.named() and hasattr(self, "_written"):
            # the clause on two names joined by "rel" only where the page writes such a
            # centre, I_{a rel b}: known once the page is written (twenty-fifth round (a))
            self._centres_intro = (self.para(self.sentence(self.message(b, lead=True))),
                                   self.para(self.sentence(self.message(Msg("centres.intro_named_rel", b.args),
                                                                        lead=True))))
            return CENTRES_INTRO
        if isinstance(b, Msg) and b.key == "data.relative":
            self._rel_told = True            # "rel" said before its first use: no legend for it
            if b.args.get("rate") == "yes" and isinstance(b.args.get("w"), Sym):
                self._rates_told.add(b.args["w"].sub)     # ω_{b rel a} defined there: not again
        if isinstance(b, Msg):
            return self.para(self.sentence(self.message(b, lead=True)))
        if isinstance(b, Equation) and b.equality:
            return self.para(self.equality(b))
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
        if isinstance(b, Told):
            return self.told(b)
        raise TypeError(f"unknown block {type(b).__name__}")

    # messages and their arguments ----------------------------------------------------------
    def message(self, m: Msg, lead: bool = False) -> str:
        """The catalogue's message with its variables: numbers go to Fluent as numbers (for
        plurals), everything else as a token replaced afterwards by its markup, so the
        catalogue's text is escaped and the variables' markup is not. A message that `lead`s a
        paragraph begins with a capital when its first word is the catalogue's (joint j3 … ->
        Joint j3 …), never when it is a symbol (v_Q, ω_2). Only the variables the sentence
        uses are written: writing one notes its symbols for the notation line (`subscripts`),
        which glosses only what the page shows (twenty-ninth round (a): C5-1.1's line glossed
        v_{J∈pulley rel strand1}, an argument its sentence left out)."""
        if m.key in NAMED_KEYS and self.named():          # no numbers to explain
            m = Msg(NAMED_KEYS[m.key], m.args)
        rendered: list[str] = []
        values: list[Any] = []
        args: dict[str, Any] = {}
        for name, x in m.args.items():
            if isinstance(x, int) and not isinstance(x, bool):
                args[name] = x
                continue
            inner = x.item if isinstance(x, Lead) else x
            if isinstance(inner, Names):
                args[f"{name}_n"] = len(inner)
            slot = Slot(TOKEN.format(len(rendered)))
            slot.plain = self.plain(x)
            slot.n_names = len(inner) if isinstance(inner, Names) else 1
            slot.many = isinstance(inner, Name) and self.plural(inner)
            rendered.append("")
            values.append(x)
            args[name] = slot
        args.setdefault("format", self.fmt)     # plain text (md) names no colours
        parts = TOKEN_RE.split(self.cat.format(m.key, args))
        used = {int(p) for p in parts[1::2]}
        rendered = [self.arg(x) if i in used else "" for i, x in enumerate(values)]   # in the arguments' order
        own = self.declined(parts, rendered, values) if self.lang == "eu" else {}
        out = [self.esc(p) if i % 2 == 0 else own.get(i, rendered[int(p)]) for i, p in enumerate(parts)]
        if lead and parts[0][:1].islower():
            out[0] = self.esc(parts[0][0].upper() + parts[0][1:])
        elif lead and parts[0] == "" and len(parts) > 1:
            first = values[int(parts[1])]
            if (isinstance(first, Name) and first.kind == "body") or self.worded(first):   # eu: Besoa O puntu finkoaren …
                out[1] = self.capital(out[1])                        # there only, not where it recurs
        return self.contracted("".join(out))

    def declined(self, parts: list[str], rendered: list[str], values: list[Any]) -> dict[int, str]:
        """Basque: a body's name followed by the catalogue's "solido" and its case ending
        (*1. polea* solidoaren) takes the ending on the name itself wherever the name can
        take it, as the Basque notes decline their nouns (aspen, ardatzaren): *1. polearen*,
        *1. poleak*, never "*1. polea* solidoa *1. kable-zatia* solidoaren gainean". One rule
        on the whole page: the Data's and the structure's tables already say each name is a
        body (their column "solidoa"), so the first mention keeps no word the later ones drop
        (the fourteenth round's reader: "*ezkerreko kable-zatiarekin*" beside "*eskuineko
        kable-zatia* solidoarekin" in one sentence). The word stays where the name cannot
        take the ending: a name that does not end in the article -a (a number, a code: "3
        solidoa"), a list ("*N elementua* eta *P elementua* solidoen", a plural word the
        pattern " solidoa…" does not match); a plural name (one
        the Catalan or Spanish name gives an article les/las to: *gurpilak*) is put in the
        genitive plural before the word, "*gurpilen* solidoaren", never "*gurpilak*
        solidoarenak". Returns the declined names by their place in `parts`, and cuts the
        word from the text after them."""
        own: dict[int, str] = {}
        for i in range(1, len(parts) - 1, 2):
            x = values[int(parts[i])]
            x = x.item if isinstance(x, Lead) else x
            x = x.items[0] if isinstance(x, Names) and len(x) == 1 else x     # a list of one body: its name
            follow = SOLIDO_RE.match(parts[i + 1])
            if not isinstance(x, Name) or x.kind != "body" or follow is None:
                continue        # "N eta P solidoen": a list's word is both names' (no "solidoa" to match)
            word = self.called(x).split()[-1] if self.called(x).split() else ""
            markup = rendered[int(parts[i])]
            at = markup.rfind(self.esc(word)) if word else -1
            if at < 0:
                continue
            end = at + len(self.esc(word))
            if re.fullmatch(r"[^\W\d_][\w-]*ak", word) and self.plural_elsewhere(x):   # gurpilak -> gurpilen solidoa
                own[i] = markup[:at] + self.esc(word[:-2] + "en") + markup[end:]
            elif re.fullmatch(r"[^\W\d_][\w-]*a", word):          # polea, kable-zatia, blokea
                own[i] = markup[:end] + follow.group(1) + markup[end:]
                parts[i + 1] = parts[i + 1][follow.end():]
        return own

    def plural_elsewhere(self, n: Name) -> bool:
        """Whether the model's Catalan or Spanish name of body `n` is plural (les rodes, las
        ruedas): the reading of a Basque name ending in -ak (gurpilak, the wheels) as plural,
        which its spelling alone cannot tell from an ergative singular."""
        for other in ("es", "ca"):
            given = self.wording.bodies.get(other, {}).get(n.text)
            if given and ARTICLES[other].match(given):
                return bool(re.match(r"(?i)(els|les|los|las) ", given))
        return False

    def worded(self, x: Any) -> bool:
        """Whether a body's name (or a list's first) begins with a word in lower case
        (*pulley 1*, *strand 1*, Basque *gurpila*), so that it takes a capital where it
        begins a list item or a sentence ("1. *Pulley 1*, from *strand 1*", "*Strand 1* is
        welded …"), as a name with its article does ("1. La *politja 1*"); a name that
        begins with a symbol or a number (*O2E*, *1. polea*, *s*) is left as spelt."""
        if isinstance(x, Names):
            return bool(x.items) and self.worded(x.items[0])
        if not isinstance(x, Name) or x.kind != "body":
            return False
        return bool(re.match(r"[^\W\d_A-Z]{2,}\b", self.called(x)))

    def capital(self, markup: str) -> str:
        """`markup` with its first letter (past the format's leading tags) a capital."""
        m = LEADING_MARKUP.get(self.fmt, LEADING_MARKUP["md"]).match(markup)
        at = m.end() if m else 0
        return markup[:at] + markup[at:at + 1].upper() + markup[at + 1:]

    def contracted(self, text: str) -> str:
        """The language's contractions of a preposition and the article of a name that
        follows it (Catalan `de el portador` -> `del portador`, `a el` -> `al`)."""
        for pattern, short in CONTRACTIONS.get(self.lang, ()):
            text = pattern.sub(short, text)
        return text

    def sentence(self, text: str) -> str:
        """A paragraph that begins with a name's article begins with a capital (El portador …)."""
        m = ARTICLES.get(self.lang, NO_ARTICLE).match(text)
        return text[0].upper() + text[1:] if m and text[0].islower() else text

    def told(self, t: Told) -> str:
        """The model's words in the reader's language: what its points are (a table), its
        notes on the printed statement (one paragraph each); nothing when it gives none."""
        if t.kind == "points":
            rows = [[self.name(Name(p)), self.own_words(self.wording.point(p, self.lang))] for p in t.points
                    if self.wording.point(p, self.lang)]
            if not rows:
                return ""
            return self.table([self.message(Msg("col.point")), self.message(Msg("col.what"))], rows)
        if t.kind == "data":
            return "\n".join(self.para(self.own_words(n)) for n in self.wording.data.get(self.lang, []))
        notes = self.wording.notes.get(self.lang, [])
        return "\n".join(self.para(self.message(Msg("note.text", {"text": Own(n)}))) for n in notes)

    def own_words(self, text: str) -> str:
        """The model's own words (what a point is, the Data's statements, the notes) escaped,
        each parameter's name in them whose symbol is written otherwise (r1, written r₁ by
        the formulas) written as the formulas write it: C5-E.5's point P "at r1 below its
        centre" sat over (L; r₂ − r₁), and its notes wrote (r2 − r1)²/r1 beside the page's
        (r₂ − r₁)²/r₁; a typed symbol the notation writes per language (C5-E.6's R_roda, the
        English page's R_wheel) is written as this page writes it. A name that reads the same
        either way (v, L) is left as typed."""
        import sympy

        from .names import unicode_name

        text = self.coordinates(text)
        names = [n for n in getattr(self.doc, "parameters", ()) if unicode_name(self.spelt(n)) != n
                 and any(c.isdigit() or c == "_" for c in n)]
        if not names:
            return self.typed(shown_lines(text))
        pattern = re.compile(r"(?<![A-Za-z0-9_.])(" + "|".join(re.escape(n) for n in sorted(names, key=len, reverse=True))
                             + r")(?![A-Za-z0-9_]|\.\d)")         # r1² and (r1) too, not r12, x.r1, r1.5
        parts = pattern.split(shown_lines(text))
        return "".join(self.formula(sympy.Symbol(part)) if k % 2 else self.typed(part) for k, part in enumerate(parts))

    def bodies_marked(self, text: str, write: Callable[[str], str]) -> str:
        """A model's own words with each body's name in them marked as the page marks a body's
        name everywhere else (`body_word`: italics), the rest written by `write`: "centre of
        *pulley 1*" beside "*pulley 2*" (issue 30, sixteenth round: C5-1.5's point table wrote
        "centre of pulley 1" upright under "*pulley 1*"). A name is matched as a whole word
        (its first letter in either case, as a sentence may start with it), the longest
        first, in Basque with its case ending (R arrabolaren); a name of fewer than three letters
        (a bare letter, a number) is not matched."""
        pattern = self.body_pattern()
        if pattern is None:
            return write(text)
        parts = pattern.split(text)
        return "".join(self.body_word(part) if k % 2 else write(part) for k, part in enumerate(parts))

    def body_pattern(self) -> Optional[re.Pattern]:
        """The page's bodies' names (the article taken off) as one pattern, or None."""
        if "body_pattern" in self._cache:
            return self._cache["body_pattern"]
        names = set()
        for b in getattr(self.doc, "numbers", {}) or {}:
            _, proper = self.articled(Name(b, "body", bare=True))
            if sum(c.isalpha() for c in proper) >= 3:
                names.add(proper)
        # Basque declines a name by its ending (R arrabola, R arrabolaren; gurpilak, gurpilen):
        # the stem, without the article -a or -ak, and any ending
        inflected = r"\w*" if self.lang == "eu" else ""
        stems = [re.sub(r"(ak|a)$", "", n) if inflected and len(n) > 4 else n for n in names]
        alternatives = ["[" + n[0].lower() + n[0].upper() + "]" + re.escape(n[1:]) + inflected
                        for n in sorted(stems, key=len, reverse=True)]
        pattern = re.compile(r"(?<!\w)(" + "|".join(alternatives) + r")(?!\w)") if alternatives else None
        self._cache["body_pattern"] = pattern
        return pattern

    @property
    def _cache(self) -> dict[str, Optional[re.Pattern]]:
        """Patterns made once a page (the bodies' names: `body_pattern`)."""
        if "_patterns" not in self.__dict__:
            self.__dict__["_patterns"] = {}
        patterns: dict[str, Optional[re.Pattern]] = self.__dict__["_patterns"]
        return patterns

    def body_word(self, text: str) -> str:
        """A body's name as it stands in a model's words, marked as a name: escaped here; a
        format that marks names (italics) overrides it."""
        return self.esc(text)

    def coordinates(self, text: str) -> str:
        """Coordinates the model typed in its own words, "(4r, r)", written with the page's
        separator between the terms, as the page writes every vector: (4r; r) where the decimal
        sign is a comma (`numerals.separator`), so one page has one form (C5-1.6's Spanish and
        Catalan Data read "(4r, r)" above tables of "(x; y)"). Only terms with no space, one
        of them with a digit: a parenthesis of words is left alone."""
        if self.comma == ", ":
            return text

        def written(m: re.Match) -> str:
            terms = m.group(1).split(", ")
            return f"({self.comma.join(terms)})" if any(c.isdigit() for c in m.group(1)) else m.group(0)
        return TYPED_COORDINATES.sub(written, text)

    def typed(self, text: str) -> str:
        """A model's own text escaped, each symbol typed in it as X_sub (SUBSCRIPTED: C5-E.6's
        "r ω_pinyó = R ω_plat", its notes' "ℜ_P = v(P)²/aⁿ", a Data remark's "v_B") written as
        the page writes its symbols (`subscripted`), so the words and the formulas beside them
        show one symbol one way; the bodies' names in the words marked (`bodies_marked`); the
        geometric contact point typed J^{geom} marked as the body marks it (`geom_mark`: a
        superscript, not the braces; twenty-first round (e), C5-1.8's Catalan note)."""
        if TYPED_GEOM in text:      # J^{geom} in a note as the body writes the point (`geom_mark`)
            return self.geom_mark().join(self.typed(part) for part in text.split(TYPED_GEOM))
        parts = SUBSCRIPTED.split(text)
        for k in range(1, len(parts), 4):
            self.typed_label(parts[k], parts[k + 1])
        return "".join(self.subscripted(parts[k], parts[k + 1], parts[k + 2] or "") if k % 4 == 1
                       else self.bodies_marked(part, self.esc) if k % 4 == 0 else "" for k, part in enumerate(parts))

    def subscripted(self, base: str, sub: str, sup: str = "") -> str:
        """A symbol typed base_sub (or base_sub^sup, a_P^n) in a model's words (sub and sup
        perhaps in braces): as typed, which is how a plain-text page (Markdown) writes a
        subscript itself (v_B, ω_{3/2}, a_P^n); a format with markup overrides it."""
        return self.esc(f"{base}_{sub}" + (f"^{sup}" if sup else ""))

    def typed_label(self, base: str, sub: str) -> None:
        """Note a body's own symbol typed in a model's words (C5-E.6's "r ω_pinoia = R
        ω_platera") as written, as `label` notes one the page writes: the legend of shortened
        subscripts then says which body ω_platera is, before the words use it."""
        if base not in ("ω", "α", "I") or not hasattr(self, "_written"):
            return
        found = [b for b, label in self.labels().items() if label == sub.strip("{}")]
        if len(found) == 1:
            self._rating = True
            try:
                self.label(found[0])
            finally:
                self._rating = False

    def plain(self, x: Any) -> str:
        """The text a name argument is read as, in the reader's language (for elision)."""
        if isinstance(x, Name):
            text = CENTRE_POINT_RE.sub("I", self.called(x))      # a centre's point reads as its letter
            supplied = self.lang in SUPPLIED_ARTICLE and x.kind == "body" and not x.bare
            return self.articled(x)[0] + text if supplied and not ARTICLES[self.lang].match(text) else text
        if isinstance(x, Names):
            return self.plain(x.items[0]) if x.items else ""
        if isinstance(x, Lead):
            return self.plain(x.item)
        return plain(x)

    def arg(self, x: Any) -> str:
        """A message argument or cell in markup: a name, a list of names joined with the
        language's "and" (Babel), text escaped, a symbol, a value, a nested message, an inline
        formula or a list."""
        if isinstance(x, Name):
            return self.name(x)
        if isinstance(x, Names):
            items = [self.message(Msg(x.each, {"name": i})) if x.each else self.arg(i) for i in x.items]
            return format_list(items, locale=self.cat.lang) if items else "—"
        if isinstance(x, Lead):
            text = self.arg(x.item)
            articled = ARTICLES.get(self.lang, NO_ARTICLE).match(self.plain(x.item))
            return self.capital(text) if isinstance(x.item, Msg) or articled or self.worded(x.item) else text
        if isinstance(x, str):
            return self.points(x)
        if isinstance(x, Sym):
            return self.sym(x)
        if isinstance(x, Value):
            return self.value(x)
        if isinstance(x, Msg):
            return self.message(x)
        if isinstance(x, Inline):
            return self.inline(x.items)
        if isinstance(x, Described):
            said = (self.wording.point if x.kind == "point" else self.wording.parameter)(x.name, self.lang)
            if not said and x.fallback is not None:
                return self.message(x.fallback)
            return self.own_words(said)
        if isinstance(x, Own):
            return self.own_words(x.text)
        if isinstance(x, (list, tuple)):
            return ", ".join(self.arg(i) for i in x)
        return self.esc(str(x))

    def inline(self, items: list) -> str:
        """Inline items (text, symbols, values …) written in a row; a point and a centre's
        symbol side by side (a segment to the centre, the arm DI_{roda1}) run together as
        every other segment of the page is (IC, G1J, AI_13), the centre's subscript closed
        (`segment_centre`): no space inside a segment (issue 30, thirteenth round: the readers
        read "I_S2 P" as two things). Inside it a parameter's name is a symbol of the formula
        (`in_formula`), written as the values write it, not an emphasised word: "v_C1 / r", "at
        r φ̇" (issue 30, fourteenth round)."""
        self.in_formula += 1
        try:
            return self._inline(items)
        finally:
            self.in_formula -= 1

    in_formula = 0       # how deep inside inline formulas the writing is (`inline`)

    def _inline(self, items: list) -> str:
        """`inline`'s items, written in a row."""
        out = []
        for k, i in enumerate(items):
            before = k and _segment_end(items[k - 1]) and "I" in (_base(items[k - 1]), _base(i))
            after = k + 1 < len(items) and _segment_end(items[k + 1]) and "I" in (_base(items[k + 1]), _base(i))
            text = self.arg(i)
            if _segment_end(i) and (before or after) and _base(i) == "I":
                text = self.segment_centre(text)
            out.append(text)
        return "".join(out)

    def segment_centre(self, text: str) -> str:
        """A centre's symbol as written inside a segment: where its subscript is plain text
        (I_S2), in braces, so that the segment's other point is read apart from it: I_{S2}P,
        DI_{roda1}, as the notes' LaTeX sets I_{S2}P; a symbol the format sets with a real
        subscript (HTML, LaTeX) is left as it is."""
        return _PLAIN_CENTRE.sub(lambda m: f"{m.group(1)}_{{{m.group(2)}}}", text)

    def cell(self, c: Any) -> str:
        """A table cell; answers come as [(label, Value), ...]."""
        if isinstance(c, list) and c and isinstance(c[0], tuple):
            return "; ".join((self.arg(label) + " = " if label else "")
                             + self.arg(Value(v.value, v.unit, True) if isinstance(v, Value) else v) for label, v in c)
        return self.arg(c)

    def name(self, n: Name) -> str:
        """A model's name as a name (formats set points, bodies and joints apart)."""
        return self.esc(self.called(n))

    # the model's words and notation -----------------------------------------------------------
    def called(self, n: Name) -> str:
        """A body's name in the reader's language (the model's `names`), else the model's."""
        if n.kind == "body":
            return self.wording.body(n.text, self.lang)
        if n.kind == "joint":                            # the model's name, else its point or bodies
            given = getattr(self.wording, "joints", {}).get(self.lang or "", {}).get(n.text)
            place: str | tuple[str, ...] | None = (self.doc.joints or {}).get(n.text)     # a point, or bodies
            if given or place is None:
                return self.wording.joint(n.text, self.lang)
            if isinstance(place, tuple):
                return "–".join(self.label(b) for b in place)
            return place
        if n.kind == "point" and "∈" in n.text:          # O∈wheels as the symbols write it: O∈3
            return self.numbered(Sym("", n.text))
        if n.kind == "index":                            # a body's number in the structure's table
            return self.column().get(n.text, n.text)
        if n.kind == "label":                            # a body as its symbols write it (ω_roda)
            return self.label(n.text)
        return n.text

    def articled(self, n: Name) -> tuple[str, str]:
        """A name split into its article, set as text, and the name proper, set as a name:
        `el ` and `portador` for the body a Catalan model calls `el portador`; in English,
        whose models write names bare, `the ` and `wheel` (SUPPLIED_ARTICLE)."""
        text = self.called(n)
        if n.kind == "body":
            m = ARTICLES.get(self.lang, NO_ARTICLE).match(text)
            if m and m.end() < len(text):
                return ("" if n.bare else text[:m.end()]), text[m.end():]
            if not n.bare and self.lang in SUPPLIED_ARTICLE and not NUMBERED.search(text):
                return SUPPLIED_ARTICLE[self.lang], text
        return "", text

    def plural(self, n: Name) -> bool:
        """Whether a body's name is plural, so that a verb after it is (Catalan and Spanish
        read it off the article, `catalogue.count`). An English name has no article to tell:
        the body is plural when the model's Catalan or Spanish name of it is (las ruedas: the
        wheels roll), else when its last word is an English plural (ENGLISH_PLURAL)."""
        if n.kind != "body" or self.lang not in SUPPLIED_ARTICLE:
            return False
        for other in ("es", "ca"):
            given = self.wording.bodies.get(other, {}).get(n.text)
            if given and ARTICLES[other].match(given):
                return bool(re.match(r"(?i)(els|les|los|las) ", given))
        words = self.called(n).split()
        return bool(words) and bool(ENGLISH_PLURAL.fullmatch(words[-1]))

    def spelt(self, name: str) -> str:
        """How a parameter is written: the model's notation (w0 as omega_0, ω₀), else its name."""
        return self.wording.symbol(name, self.lang) or name

    def noted(self, s: Sym) -> Sym:
        """A rate symbol as the model's notation writes it (the fan's ω₁ for the block's ω,
        ω₂ for the blades' relative to the block), else as it is; a normal or tangential
        component's superscript as the language's course writes it (Basque a_BA^N, a_BA^T:
        `model.wording.component_superscript`). Every format's symbols and the polygons'
        labels pass here."""
        sup = component_superscript(s.sup, self.lang) if s.sup else s.sup
        if sup != s.sup:
            s = Sym(s.base, s.sub, sup, s.vector, s.sub_key, s.fixed, s.of_body)
        if s.fixed or s.base not in ("ω", "α") or not s.sub or s.sub_key:
            return s
        parts = s.sub.split("/")
        spelt = self.wording.symbol(rate_key("omega" if s.base == "ω" else "alpha", *parts[:2]), self.lang)
        if spelt is None:
            return s
        if s.base == "ω" and len(parts) == 1 and hasattr(self, "_noted"):
            self._noted.setdefault(parts[0], None)      # the notation line defines it (`subscripts`)
        if s.base == "ω" and len(parts) == 2 and hasattr(self, "_noted_rel"):
            self._noted_rel.setdefault((parts[0], parts[1]), None)    # δ̇: defined there too
        w = written_name(spelt)
        return Sym(w.base, w.sub, w.sup or s.sup, s.vector, fixed=True)

    def sym(self, s: Sym) -> str:
        """A symbol in the format's markup; ω₁ × ω₂ for the cross term of two rates."""
        if s.base == "ω×ω" and "," in s.sub:
            parent, body = s.sub.split(",", 1)
            return (self.sym(Sym("ω", parent, vector=s.vector)) + self.esc(" × ")
                    + self.sym(Sym("ω", f"{body}/{parent}", vector=s.vector)))
        return self.symbol(self.noted(s))

    def subscripts(self, m: Msg) -> str:
        """Which body each shortened subscript is, said once as a sentence a teacher writes
        ("Notation: ω_wheel is the angular velocity of the *sun wheel*", not the audits'
        terse "In the symbols, ω_wheel: *sun wheel*"): a symbol whose subscript a student cannot read off the body's
        name in this language (an abbreviation, or a letter the model's notation gives) is
        defined on the page that uses it; nothing when every subscript is the name as
        written, the code the name holds (ω_N of *N blokea*, as the slides) or the name's
        words run together (ω_politja1 of *politja 1*, ω_central of *roda central*:
        `model.subscripts.read_off`), or the bodies go by their numbers (the structure's table).
        A page that writes a point's velocity on a body, v_{J∈cylinder}, says once (with its
        first such symbol) what J∈cylinder means: the point of the cylinder at J, which the
        notes write v_T(J) in words beside the figure, and a reader met undefined. A body
        written only after ∈ (v_{J∈zilindroa}, a_{J∈terra}) whose subscript is shortened from
        its name (*zilindro finkoa*, *terra cilíndric*) and that no ω line defines is said
        the same way, once, at its first point: every subscript on the page is read
        (twenty-fourth round (e))."""
        spelt = self.wording.bodies.get(self.lang or "", {}) if self.wording is not None else {}
        items: list = []
        written = getattr(self, "_written", None)
        defined: set[str] = set()
        for b in (m.args["bodies"] if spelt else []):
            label = self.labels().get(b, "")
            if written is not None and b not in getattr(self, "_rated", written):
                continue          # ω_X the page never writes needs no legend (a body written
                # after ∈ only is defined below, with its point)
            if self._plain(b, label, spelt) and b not in self._noted:
                continue          # the name as written, its own code (ω_N of *N blokea*), or
                # its words run together (ω_politja1 of *politja 1*): nothing to define — unless
                # the model's notation writes its ω otherwise (C5-2.1's ψ̇ for ω_xassís): that
                # symbol is defined here, before the steps write it (round 27b: ψ̇ was written
                # in step 1's equation before the line "⇒ ψ̇ = ω_xassís = …")
            said = Msg("structure.subscript_pair", {"sym": self._rate_named(b), "body": Name(b, "body")})
            items += (["; "] if items else []) + [said]
            defined.add(b)
        for b, other in [k for k in getattr(self, "_noted_rel", {}) if f"{k[0]}/{k[1]}" not in self._rates_told]:
            # a relative rate the model's notation writes by a letter of its own (C5-2.1's δ̇,
            # the notes' steering rate): said as what it is, with the page's other symbols,
            # before a step writes "δ̇ = 0" (twenty-eighth round (d): δ was defined nowhere)
            said = Msg("structure.subscript_noted_rel", {"sym": Sym("ω", f"{b}/{other}", vector=False),
                                                         "body": Name(b, "body"), "other": Name(other, "body")})
            items += (["; "] if items else []) + [said]
        member = getattr(self, "_member", None)
        members = [member] if member is not None else []     # v_{J∈cylinder}: the point of the cylinder at J, once a page
        members += [(point_, of) for of, point_ in getattr(self, "_members", {}).items()
                    if (member is None or of != member[1]) and of not in defined and spelt
                    and not self._plain(of, self.labels().get(of, ""), spelt)]
        for point_, of in members:
            said = Msg("structure.subscript_member", {"sym": Sym("v", f"{point_}∈{of}"), "body": Name(of, "body"),
                                                      "point": Name(point_, "point")})
            items += (["; "] if items else []) + [said]
        for level, drag, seen, point_ in m.args.get("drags", []):   # v_arr,B = v_B∈M, said once (builder)
            said = Msg("structure.subscript_drag", {"equal": Inline([drag, " = ", seen]), "point": Name(point_, "point"),
                                                    "kind": "speed" if level == "v" else "accel"})
            items += (["; "] if items else []) + [said]
        rel = self._rel_item()
        if rel is not None:
            items += (["; "] if items else []) + [rel]
        if not items:
            return ""
        return self.para(self.sentence(self.message(Msg(m.key, {"pairs": Inline(items)}), lead=True)))

    def _rate_named(self, b: str) -> Sym | Inline:
        """Body `b`'s ω as the notation line writes it, with the notes' name of the rate when
        the model's notation writes it by an Euler angle's letter (EULER_RATES): ψ̇ (the
        precession), the rate of a body about the vertical axis, as C5-2.1's chassis
        (twenty-ninth round (a): the notes say "la precessió ψ̇", the page never did)."""
        sym = Sym("ω", b, vector=False)
        spelt = self.wording.symbol(rate_key("omega", b), self.lang) if b in self._noted else None
        name = EULER_RATES.get(spelt or "")
        return Inline([sym, " (", Msg(name), ")"]) if name else sym

    def _note_rel(self, base: str, point_: str, body_: str, other: str) -> None:
        """Note the first symbol the page writes with two bodies joined by "rel" (ω_{politja
        fixa rel braç}, v_{E∈barra rel suport}): the notation line defines it, and with it
        "rel", unless the data's sentence on relative quantities has (`subscripts`)."""
        if getattr(self, "_rel", "") is None and base in ("ω", "α", "v", "a"):
            self._rel = (base, point_, body_, other)

    def _rel_item(self) -> Optional[Msg]:
        """The notation line's definition of the first symbol written with "rel", said where
        the page writes one and no sentence before it said what "rel" means (twenty-fifth
        round (a): C5-1.6 wrote ω_{politja fixa rel braç} in step 2 and explained "rel" only
        in the centres' first sentence, after it). The notation line stands under the
        structure, before every step."""
        rel = getattr(self, "_rel", None)
        if rel is None or getattr(self, "_rel_told", False):
            return None
        base, point_, body_, other = rel
        kind = {"ω": "rate", "α": "rate2", "v": "speed", "a": "accel"}[base]
        sub = f"{point_}∈{body_}/{other}" if point_ else f"{body_}/{other}"
        self._rel = ("", "", "", "")         # written once: not noted again while saying it
        return Msg("structure.subscript_rel", {"sym": Sym(base, sub, vector=False), "kind": kind,
                                               "point": Name(point_ or "-", "point"),
                                               "body": Name(body_, "body"), "other": Name(other, "body")})

    def _plain(self, b: str, label: str, spelt: dict) -> bool:
        """Whether body `b`'s subscript `label` needs no definition: no label, its number, the
        name as written, the code the name holds (ω_N of *N blokea*) or the name's words run
        together (ω_politja1 of *politja 1*: `model.subscripts.read_off`)."""
        from ...model.subscripts import CODE, _words, read_off

        words = _words(spelt[b]) if b in spelt else []
        return (not label or label.isdigit() or not words or label == " ".join(words)
                or (label in words and bool(CODE.match(label))) or read_off(label, spelt[b], self.lang))

    def labels(self) -> dict[str, str]:
        """Each body as the symbols write it: the index the model's notation gives it in this
        language (ω_N, ω_1 for wheel 1), else a subscript read off its name in this language
        (ω_roda, ω_{roda sup}: `model.subscripts`), else its number (ω_3), as the figures
        write it."""
        if not hasattr(self, "_labels"):
            order = sorted(self.doc.numbers, key=lambda b: self.doc.numbers[b])
            self._labels = self.wording.labels(order, self.lang, tuple(getattr(self.doc, "parameters", ())))
        return self._labels

    def label(self, b: str) -> str:
        """Body `b` as the symbols write it (`labels`), noted as written on the page (the
        legend of shortened subscripts says only those)."""
        labels = self.labels()
        if b in labels and hasattr(self, "_written"):
            self._written.add(b)
            if getattr(self, "_rating", False):
                self._rated.add(b)
        return labels.get(b, b)

    def named(self) -> bool:
        """Whether the model names its bodies in this language (`draw.names.names_bodies`):
        then the centres are written by the bodies' names (I_biela), as ω_biela, and neither
        text nor figures number the bodies."""
        return bool(self.lang and self.wording is not None and self.wording.bodies.get(self.lang))

    def numbers(self) -> dict[str, str]:
        """Each body as the instant centres (I_13) and the structure's table number it: the
        index the model's notation gives it, else its number."""
        if not hasattr(self, "_numbers"):
            self._numbers = {b: self.wording.index(b, self.lang) or str(k) for b, k in self.doc.numbers.items()}
        return self._numbers

    def column(self) -> dict[str, str]:
        """Each body as the structure's table numbers it, one style down the column: the
        letters the model's notation gives when it letters every body (as slides that letter
        all their elements), else every body's number, the frame 1. The slides letter the
        guide M and the block N of seed 001's P pair but neither its frame nor the rocker,
        so a column of "1, M, N, 4" mixed two styles; the letters stay in the names (*guide
        M*) and in the symbols (ω_M)."""
        given = {b: self.wording.index(b, self.lang) for b in self.doc.numbers}
        if all(given.values()):
            return {b: str(i) for b, i in given.items()}
        return {b: str(k) for b, k in self.doc.numbers.items()}

    def relative(self, body: str, other: str) -> str:
        """The subscript of a quantity of `body` relative to `other` (both labels): the
        body, then the language's word for "relative to" (rel; Catalan rel., relatiu a,
        since the notes' REL names the moving frame and "resp." reads as "respectivament") and
        the reference, `mòb rel. braç`; never a slash, which reads as a fraction."""
        return f"{body} {self.wording.relative_word(self.lang)} {other}"

    def numbered(self, s: Sym) -> str:
        """A symbol's subscript with its bodies by their labels (`labels`), as the notes and the
        figures write them: ω_roda, ω_{mòb rel. braç} (relative to another body), v_B∈plat,
        v_{A∈N rel. M}, a_J∈3; the instant centres by their numbers, I_13 (I_2,11 once a label
        has two characters)."""
        nums, labels = self.doc.numbers, self.labels()
        if not nums or not s.sub or s.fixed:
            return s.sub
        if s.base in BODY_SUBS or s.of_body:
            self._rating = True               # the body's own symbol: the legend may define it
            try:
                return self._body_subscript(s, nums, labels)
            finally:
                self._rating = False
        head, *rest = re.split(r"([∈/,])", s.sub)
        if s.base == "v" and len(rest) == 2 and rest[0] == "∈" and getattr(self, "_member", "") is None:
            self._member = (head, rest[1])     # v_{J∈b}: the legend says once what J∈b means
        if s.base in ("v", "a") and len(rest) == 2 and rest[0] == "∈" and hasattr(self, "_members"):
            self._members.setdefault(rest[1], head)   # v_{J∈cylinder}: which body, if shortened
        out = head
        if s.base in ("v", "a") and len(rest) == 4 and rest[0] == "∈" and rest[2] == "/":
            self._note_rel(s.base, head, rest[1], rest[3])
        for i in range(0, len(rest), 2):
            mark, name = rest[i], rest[i + 1] if i + 1 < len(rest) else ""
            name = self.label(name)
            out += f" {self.wording.relative_word(self.lang)} {name}" if mark == "/" else mark + name
        return out

    def _body_subscript(self, s: Sym, nums: dict, labels: dict) -> str:
        """The subscript of a symbol made of bodies (ω_roda, ω_{mòb rel. braç}, I_13, I_biela)."""
        sep = "," if s.base in ("I", "ω×ω") else "/"
        parts = s.sub.split(sep)
        if not all(p in nums for p in parts):
            return s.sub
        if s.base == "I" and len(parts) == 2:           # the figures' rule: I_biela, or I_13
            named = self.named()
            shown = centre_subscript(parts[0], parts[1], nums, labels if named else self.numbers(), named,
                                     self.wording.relative_word(self.lang))
            for p in parts:           # the frame is left out of I_biela: only what is shown
                if named and labels.get(p) and labels[p] in shown:
                    self.label(p)
            if named and f" {self.wording.relative_word(self.lang)} " in shown and hasattr(self, "_rel_centres"):
                self._rel_centres.append(s)   # I_{a rel b}: the page may or may not show it (`render`)
            return shown
        if sep == "/" and len(parts) == 2:
            self._note_rel(s.base, "", parts[0], parts[1])
            return self.relative(self.label(parts[0]), self.label(parts[1]))
        return sep.join(self.label(p) for p in parts)

    def caption(self, fig: Figure) -> str:
        """A figure's caption, saying the numbers a symbolic model is drawn at (or that it is
        drawn at sample values of the symbols)."""
        text = " ".join([self.message(fig.caption)] + [self.message(m) for m in fig.notes])
        if fig.values:
            return text + " " + self.drawn_at(fig.values)
        return text + " " + self.message(Msg("fig.sample")) if fig.sample else text

    def drawing_caption(self, d: Drawing) -> str:
        """A `draw` figure's caption, with the numbers a symbolic model is drawn at."""
        text = self.message(d.caption)
        return text + " " + self.drawn_at(d.values) if d.values else text

    def drawn_at(self, values: dict) -> str:
        """“Drawn at r = 0,1 and ω = 2.”"""
        shown = [Inline([Name(k, "param"), " = ", Value(v, "")]) for k, v in values.items()]
        return self.message(Msg("fig.drawn_at", {"values": Names(shown)}))

    def drawing(self, d: Drawing) -> str:
        """A `draw` figure; formats that cannot embed one draw its fallback, or nothing."""
        return self.figure(d.fallback) if d.fallback is not None else ""

    def svg_label(self, s: Sym | str) -> Text:
        """A symbol in a figure, or a point's name (a polygon's image b, b∈2 with its body by
        number): its SVG text and measured size."""
        if isinstance(s, str):
            return plain_text(self.centred(self.numbered(Sym("", s)) if "∈" in s else s, lambda t: t,
                                           self.centre_text))
        s = self.noted(s)
        return sym_text(s.base, self.sub_text(s), s.sup)

    def sub_text(self, s: Sym, centres: bool = True) -> str:
        """The subscript of a symbol: the language's word for a part of a motion (arr, rel,
        Cor: `model.wording.PART_SUBSCRIPTS`) and the name; a centre placed as a point
        written as plain text, I_OQ (`centres` False: left as its token, for a format
        that sets it as a symbol inside the subscript)."""
        word = part_subscript(s.sub_key, self.lang) if s.sub_key else ""
        text = ",".join(p for p in (word, self.numbered(s)) if p)
        if centres:
            return self.centred(text, shown_lines, self.centre_text)
        parts = CENTRE_POINT_RE.split(text)        # the tokens kept as they are, the rest shown
        return "".join(GEOM_MARK.join(map(shown_lines, p.split(GEOM_MARK))) if k % 2 == 0 else centre_point(p)
                       for k, p in enumerate(parts))

    # centres placed as points ------------------------------------------------------------------
    def centre_sym(self, body: str) -> Sym:
        """The symbol of `body`'s instant centre relative to the frame (I_OQ), which a centre
        placed as a point is written as (`document.centre_point`)."""
        return Sym("I", f"{self.doc_frame()},{body}", vector=False)

    def centre_text(self, c: Sym) -> str:
        """A centre's symbol as plain text inside a subscript or a figure: I_OQ, I_{roda sup}."""
        sub = self.numbered(c)
        return f"{c.base}_{{{sub}}}" if " " in sub else f"{c.base}_{sub}"

    def centred(self, text: str, write: Callable[[str], str], centre: Callable[[Sym], str], gap: str = "") -> str:
        """`text` (a point's name, a segment, a subscript) with each centre placed as a point
        written as its symbol in this language (`centre`), the rest by `write`. In a segment
        the symbol runs into the other point as any segment's two ends do (OI_{OQ},
        I_{OQ}O: `segment_centre` closes a plain subscript), never with a space between
        (issue 30, thirteenth round); `gap` is kept for a format that wants one."""
        if GEOM_MARK in text:          # J^{geom}: each piece as it is, the mark as the format sets it
            return self.geom_mark().join(self.centred(t, write, centre, gap) for t in text.split(GEOM_MARK))
        parts = CENTRE_POINT_RE.split(text)
        if len(parts) == 1:
            return write(text)
        out = []
        for k, part in enumerate(parts):
            if k % 2 == 0:
                out.append(write(part) if part else "")
                continue
            before, after = parts[k - 1], parts[k + 1]
            end = before[-1:]
            joined_before = bool(end and (end.isalnum() or end in "'′")) or (k > 1 and not before)
            joined_after = after[:1].isalnum()
            written = centre(self.centre_sym(part))
            if joined_before or joined_after:
                written = self.segment_centre(written)
            out.append((gap if joined_before else "") + written + (gap if joined_after else ""))
        return "".join(out)

    def geom_mark(self) -> str:
        """The superscript that makes a contact's name the geometric contact point's,
        J^{geom} (`document.GEOM_MARK`): plain text writes it ^{geom}."""
        return "^{geom}"

    def points(self, text: str) -> str:
        """Text that may hold a centre placed as a point (a segment O I_OQ), escaped, the
        centre as the format writes its symbol."""
        return self.centred(text, self.esc, self.sym)

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
            if v.result:
                text += self.root_also(x)
        if v.unit == "deg":
            return text + "°"
        unit = self.unit(v.unit)
        return text + (" " + unit if unit and not self.doc.symbolic else "")

    def root_also(self, x: Any) -> str:
        """" = x/(k′√n)" beside a result sympy writes √n·x/k (k = k′ n), the form the notes
        print: ω′ = √2·ω/4 = ω/(2·√2) (C5-2.2), |v_P| = √2·r·ω/2 = r·ω/√2. Empty for any other
        value (`root_form`)."""
        form = root_form(x)
        if form is None:
            return ""
        import sympy

        top, k, n = form
        num = self.formula(top)
        if top.is_Add:
            num = "(" + num + ")"
        root = self.formula(sympy.sqrt(n)) if k == 1 else "(" + self.formula(sympy.Mul(k, sympy.sqrt(n))).replace("·√", "√") + ")"
        return " = " + num + self.esc("/") + root

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

    def bar(self, fig: Figure) -> tuple[str, Callable[[float], str]]:
        """A figure's scale bar: its unit and how its count is written.
        Every polygon is drawn at numbers, a symbolic page's at the values given under it, so
        every bar reads as a numeric page's does, a round number in m/s or m/s² ("0,5 m/s"),
        which a student measures the polygon with: a symbolic bar in the symbols ("|a_P|/5",
        "r₁·v²/(5·r₂²)", the twentieth and twenty-fourth rounds') read oddly under a figure
        drawn at r₁ = 0.15 (issue 30, twenty-eighth round (b))."""
        return self.unit(fig.unit), self.bar_number

    def bar_number(self, x: float) -> str:
        """A scale bar's round length, with the language's decimal sign."""
        return f"{x:g}".replace(".", self.decimal)

    def decimals(self, text: str) -> str:
        """A formula's decimal points as the language writes them."""
        return DECIMAL.sub(self.decimal, text) if self.decimal != "." else text

    # annotations and derived values ------------------------------------------------------------
    def ann(self, a: Ann) -> str:
        """An M/D/? annotation of a term (seed 001): M, D or ?, a known magnitude's formula
        (ω²·AB), or the direction ⊥ or ∥ a line. An unknown magnitude is "?" even when it is
        a shared rate times its arm (α·JS, said in the sentence before the equation): the
        notes never write a formula over an unknown (twenty-eighth round (c))."""
        if a.code in ("M", "D", "?"):
            if a.code == "M" and a.ref:
                return self.inline(a.ref)
            return self.esc(a.code)
        sign = {"perp": "⊥ ", "para": "∥ "}[a.code]
        return self.esc(sign) + self.arg(a.ref)

    def derived(self, d: Derived) -> str:
        """A value read off an equation, `ω₃ = v_BA / AB = 2.5 rad/s`, with the sense
        (counter-clockwise or clockwise) when it is a nonzero number and the sense is asked.
        A rate the model's notation writes otherwise is tied to its body where it is found:
        the notes' precession, ψ̇ = ω_txasisa = |v_FI| / IF = √2·v₀/(2·L)."""
        parts = [(self.inline(d.lead) if d.lead else "") + self.sym(d.sym)]
        if (d.how or d.lead) and self.noted(d.sym) is not d.sym and d.sym.base in ("ω", "α"):
            parts.append(self.symbol(d.sym))     # the notes' symbol tied to the body's: ψ̇ = ω_txasisa = …
        if d.how:
            parts.append(self.inline(d.how))
        parts.append(self.value(Value(d.value.value, d.value.unit, True)))
        text = " = ".join(parts)
        if d.sense and isinstance(d.value.value, float) and d.value.value != 0:
            text += " (" + self.message(Msg("sense.ccw" if d.value.value > 0 else "sense.cw")) + ")"
        if d.remark is not None:
            text += " " + self.message(d.remark)
        return text

    def written(self, t) -> str:
        """A term as an equation writes it: its symbol (a_QS^t), or its formula where the
        term is spelt out (a wheel's centre alone on a straight path: a_H = α × GH)."""
        return self.inline(t.how) if t.spelt and t.how else self.sym(t.sym)

    def equality(self, eq: Equation) -> str:
        """Two points' equal motions in one line, v_T2 = v_T1 = (0; −2·v) (`Equation.equality`):
        the sentence before it gives the reason; no marks, no list of terms."""
        t = eq.sides[0][0]
        return " = ".join([self.sym(eq.target.sym), self.written(t), self.value(Value(t.value, _unit(t.sym)))])

    def term_line(self, t) -> str:
        """`v_BA = ω × AB = (…) m/s` for the list of an equation's terms (`α × GH = (…)` for
        a term spelt out)."""
        towards = magnitude_towards(t)
        if towards is not None:
            return self.message(Msg("term.magnitude", {"mag": Inline(["|", t.sym, "|"]), "how": Inline(t.how),
                                                       "point": Name(towards), "sym": t.sym,
                                                       "value": Value(t.value, _unit(t.sym))}))
        parts = [self.written(t)]
        if t.how and not t.spelt and self.inline(t.how) != parts[0]:
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
        if c.how == "check":
            return self.message(Msg("centre.check", self.field_args(c, name)))
        if c.how == "joint":
            moving = b if a == self.doc_frame() else a
            why = Msg(f"centre.joint.{c.joint_type}", {"joint": Name(c.via[0], "joint"),
                                                        "body": Name(moving, "body"),
                                                        "frame": self.frame_name(a if moving == b else b)})
        elif c.how == "weld":
            assert c.same is not None, "a weld's note has the centre it shares (centres.weld)"
            x, other = c.same["pair"]
            why = Msg("centre.weld", {"joint": Name(c.via[0], "joint"), "body": Name(c.same["welded"], "body"),
                                      "other": Name(other, "body"), "same": Sym("I", f"{x},{other}", vector=False)})
        elif c.how == "kennedy" and c.perps:          # the notes' perpendiculars to known velocities
            why = Msg("centre.lines", {"first": c.perps[0], "second": c.perps[1]})
        elif c.how == "kennedy":
            k1, k2 = c.via
            why = Msg("centre.kennedy", {"k1": Name(k1, "body"), "k2": Name(k2, "body"),
                                         "l1": [Sym("I", f"{a},{k1}", vector=False), Sym("I", f"{k1},{b}", vector=False)],
                                         "l2": [Sym("I", f"{a},{k2}", vector=False), Sym("I", f"{k2},{b}", vector=False)]})
        elif c.how == "lines":
            why = Msg("centre.lines", {"first": c.via[0], "second": c.via[1]})
        elif c.how == "proportional" and len(c.witnesses) == 2:
            why = self.proportional(c)
        elif c.how == "parallel":
            (p, vp), (q, vq) = c.witnesses
            sp, sq = c.symbols
            why = Msg(f"centre.parallel.{c.side}", {"p": Name(p), "q": Name(q), "vp": Value(vp, "speed"),
                                                   "vq": Value(vq, "speed"), "frame": self.frame_name(a),
                                                   "dist": Value(c.distance, "len"), "body": Name(b, "body"),
                                                   "sp": sp, "sq": sq})
        elif c.how == "field":
            why = Msg("centre.field", self.field_args(c, name))
        elif c.how == "rate":
            why = Msg("centre.rate_step" if c.step else "centre.rate",
                      {**self.field_args(c, name), "line": Name(c.via[0] if c.via else "", "body"), "step": c.step})
        elif len(c.witnesses) == 2:
            (p, vp), (q, vq) = c.witnesses
            why = Msg("centre.velocities", {"p": Name(p), "q": Name(q), "vp": Value(vp, "speed"),
                                            "vq": Value(vq, "speed"), "frame": self.frame_name(a)})
        else:
            why = Msg("centre.omega", {"frame": self.frame_name(a)})
        where = self.where(c.value)
        if why.key in ("centre.lines", "centre.kennedy"):
            why = Msg(why.key, {**why.args, "far": 0})
        if c.value.get("point") is None and not c.value.get("rest"):
            # nineteenth round (b): a centre at infinity is said as the translation it is, the
            # translation first (the notes: a body whose points all have one velocity translates;
            # its centre is at infinity, perpendicular to that velocity); twenty-eighth round (d):
            # with ω = 0 said with the translation, as the notes do ("es trasllada")
            why = Msg(why.key, {**why.args, "far": 1})
            v = next((m.args["v"] for m in (*c.perps, *c.via) if isinstance(m, Msg) and "v" in m.args), None)
            where = Msg("centre.infinity" if v is not None else "centre.infinity_one",
                        {"body": Name(b, "body"), "frame": self.frame_name(a), "direction": Value(c.value["direction"], ""),
                         "w": Sym("ω", b if a == self.doc_frame() else f"{b}/{a}", vector=False),
                         **({"v": v} if v is not None else {})})
        return self.message(Msg("centre.line", {"centre": name, "a": Name(a, "body"), "b": Name(b, "body"), "why": why,
                                                "where": where}))

    def field_args(self, c: CentreNote, name: Sym) -> dict:
        """0 = v_Q + ω × QI: the point Q, its velocity, ω, the arm QI and its length
        |QI| = |v_Q| / |ω| (the centre on the perpendicular to v_Q through Q, on the side ω turns
        v_Q to, named: below Q, to the left of Q, `centres.side_of`)."""
        a, b = c.pair
        (q, vq), = c.witnesses
        frame = a if a != self.doc_frame() else None
        v = Sym("v", q if frame is None else f"{q}∈{b}/{a}")
        w = Sym("ω", b if frame is None else f"{b}/{a}", vector=False)
        arm = Inline([Name(q), name])
        return {"v": v, "w": w, "arm": arm, "vq": Value(vq, "speed"), "wv": Value(c.rate, "rate"),
                "q": Name(q), "dist": Value(c.distance, "len"), "centre": name, "where": self.where(c.value),
                "side": Msg(f"side.{c.side}", {"q": Name(q)})}

    def frame_name(self, body: str) -> Name:
        """A body as the reference of a motion: the fixed one as a reference (`Name.reference`),
        named as every other sentence of the page names it — its own name (*bastidor*,
        *techo*), or the ground's word where the ground is named after a part of it (issue 30,
        twenty-first round (b): one word for it on a page; twenty-seventh round (e): that word
        the body's own, never "*bastidor* (fijo: el *suelo*)", which reads as two bodies)."""
        fixed = body == self.doc_frame()
        return Name(body, "body", reference=fixed)

    def doc_frame(self) -> str:
        """The fixed body (numbered 1)."""
        return next((b for b, n in self.doc.numbers.items() if n == 1), "")

    def proportional(self, c: CentreNote) -> Msg:
        """Coincident Kennedy lines: the centre from speeds proportional to the distance."""
        a, b = c.pair
        (p, _, vp), (q, _, vq) = c.witnesses
        names = [Sym("I", n[2:], vector=False) if n.startswith("I:") else Name(n) for n in (p, q)]
        lines = [[Sym("I", f"{a},{k}", vector=False), Sym("I", f"{k},{b}", vector=False)] for k in c.via]
        args = {"l1": lines[0], "l2": lines[1], "frame": self.frame_name(a), "p": names[0], "q": names[1],
                "vp": Value(vp, "speed"), "vq": Value(vq, "speed")}
        if c.pivots:        # the notes' words: each point turns with a body about its centre (C5-1.4)
            first = self.carried_before(c)
            if first is not None:
                return Msg("centre.carried_as", {"first": Name(first, "body"), "p": names[0], "q": names[1],
                                                 "near": Name(c.near), "dist": Value(c.distance, "len")})
            key = f"centre.carried.{c.side}" + ("_from" if c.near and c.distance is not None else "")
            return Msg(key, {**args, "k1": Name(c.via[0], "body"), "k2": Name(c.via[1], "body"),
                             "c1": c.pivots[0], "c2": c.pivots[1], "near": Name(c.near),
                             "dist": Value(c.distance, "len"),
                             "why1": self.slip(c, 0), "why2": self.slip(c, 1)})
        return Msg(f"centre.proportional.{c.side}", args)

    def carried_before(self, c: CentreNote) -> Optional[str]:
        """The body whose centre the page found by the very construction of `c` before (C5-1.4's
        planet 1, for planets 2 and 3: the same carrier and ring, pivots, side and distance),
        else None and `c` is recorded as the first. A construction repeated for a body
        symmetric to one done is said once and referred to, "as for *planet 1*, … at 2·r/5 from
        A2" (twenty-ninth round (b): steps 5 and 6 repeated step 3's paragraph word for word)."""
        if not (c.near and c.distance is not None):
            return None
        said = self.__dict__.setdefault("_carried", {})
        key = (c.side, tuple(c.via), tuple(map(str, c.pivots)), str(c.distance), tuple(map(str, c.slips)) != ())
        body = c.pair[1]
        first = said.setdefault(key, body)
        return first if first != body else None

    @staticmethod
    def slip(c: CentreNote, i: int) -> Any:
        """The i-th witness's no-slip reason (`centres._carried_slip`), or nothing at a pin."""
        return c.slips[i] if i < len(c.slips) and c.slips[i] is not None else ""

    def where(self, value: dict) -> Msg:
        """Where a centre is, as a message: at a point, at infinity along a direction, or no
        relative motion."""
        if value.get("rest"):
            return Msg("centre.rest")
        if value.get("point") is None:
            return Msg("centre.infinity", {"direction": Value(value["direction"], "")})
        return Msg("centre.at", {"point": Value(value["point"], "len")})


def magnitude_towards(t: Any) -> Optional[str]:
    """The point a normal acceleration points to, when its formula is a magnitude (ω² · PC,
    v_C² / OC: no cross product): then the term's line writes the magnitude, then the vector
    with its direction, |a_C^n| = v_C² / OC, cap a O: a_C^n = (0; −r·ω²/3), as the notes
    write "component normal de valor (3/2)·r·ω0², dirigida cap a O" — never a magnitude set
    equal to a vector, `a_C^n = v_C² / OC = (0; −r·ω²/3)`. None for any other term."""
    if t.kind not in ("normal", "path") or t.spelt or not t.how or any("×" in str(x) for x in t.how):
        return None
    ends = getattr(getattr(t.dir, "ref", None), "ends", ("", ""))
    return ends[1] or None


def _unit(s: Sym) -> str:
    return {"v": "speed", "a": "accel", "ω": "rate", "α": "rate2", "ω×ω": "rate2"}.get(s.base, "")


# a centre's symbol written as plain text with an open subscript: I_S2, I_OQ (not I_{roda sup})
_PLAIN_CENTRE = re.compile(r"^(I)_([^{\s][^\s]*)$")


def _segment_end(x: Any) -> bool:
    """Whether `x` can end a segment written in a row: a point's name or a centre's symbol."""
    return (isinstance(x, Name) and x.kind == "point") or (isinstance(x, Sym) and x.base == "I")


def _base(x: Any) -> str:
    return x.base if isinstance(x, Sym) else ""


def root_form(x: Any) -> Optional[tuple[Any, int, int]]:
    """(x, k′, n) when the formula `x` is ±√n·y/k with k = k′ n and y a product of positive
    powers (ω, r·ω): the notes write it y/(k′√n) (C5-2.2's ω′ = ω/(2√2) for sympy's √2·ω/4,
    rω/√2 for √2·r·ω/2); the first item is ±y. None for any other value (a number, a
    quotient of symbols, a coefficient other than ±1/k)."""
    import sympy

    if not isinstance(x, sympy.Expr) or x.is_number:
        return None
    c, rest = x.as_coeff_Mul()
    if not c.is_Rational or abs(c.p) != 1 or c.q == 1:
        return None
    roots = [f for f in sympy.Mul.make_args(rest) if f.is_Pow and f.exp == sympy.S.Half and f.base.is_Integer]
    others = [f for f in sympy.Mul.make_args(rest) if f not in roots]
    if len(roots) != 1 or not others or any(f.as_base_exp()[1].is_negative or f.is_number for f in others):
        return None
    n = int(roots[0].base)
    if c.q % n:
        return None
    return sympy.Mul(*others) * (1 if c.p > 0 else -1), c.q // n, n
