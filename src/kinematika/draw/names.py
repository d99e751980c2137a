"""How figures write names and values: as the course notes do, never in model syntax.

Bodies are numbered as in the notes (the frame 1, the others 2, 3, … in the file's
order); a material point is written with the number of its body and a relative vector
with the number of the reference body: `v_B`, `v_{B∈3}`, `v_{A∈2/3}` (A of body 2 seen
from body 3), instant centres `I_{13}`. Names are set in mathtext (matplotlib's TeX
subset) when they are plain enough, else as plain text; formulas are sympy's LaTeX when
short and mathtext can set them, else their value.
"""
from __future__ import annotations

import re
from typing import Any, Iterable, Optional, Sequence

from ..numerals import DECIMAL, decimal_sign, function_names, separator, superscript_power, written

_SIMPLE = re.compile(r"^[\w.,'·’ -]+$")     # letters of any script (mathtext sets them), digits, _ . , ' · ’ - and spaces
FORMULA_CHARS = 24            # longer formulas (as plain text) are shown by their value
ANSWER_CHARS = 32             # an asked vector's formula (the page's answer) is kept up to this length


def body_numbers(model: Any) -> dict[str, int]:
    """The notes' numbering: the frame 1, the other bodies 2, 3, … in the file's order (the
    order bodies are listed and coloured in); a body welded to the frame is the frame (one
    row of the structure's table, twenty-ninth round (b): C5-1.2's planes were bodies 2 and 3
    "fixed to the ground"), so it is numbered after every moving body, leaving no gap."""
    welded = welded_to_frame(model)
    order = [model.frame] + [b for b in model.bodies if b != model.frame and b not in welded] + \
        [b for b in model.bodies if b in welded]
    return {name: k for k, name in enumerate(order, start=1)}


def welded_to_frame(model: Any) -> set[str]:
    """The bodies welded to the frame, directly or through other welds (C5-1.2's inclined
    planes): a weld leaves no relative motion, so they are ground and are drawn as it."""
    fixed, grew = {model.frame}, True
    while grew:
        grew = False
        for j in model.joints:
            if j.kind.rigid and len({j.a, j.b} & fixed) == 1:
                fixed |= {j.a, j.b}
                grew = True
    return fixed - {model.frame}


def body_labels(model: Any, lang: Optional[str] = None, named: bool = True) -> dict[str, str]:
    """How the text and the figures write each body in a subscript (ω_roda, v_B∈plat): the
    index the model's notation gives it (`notation: index(wheel1): "1"`, the notes' ω_N),
    else, when `named`, a subscript read off its name in `lang`
    (`model.subscripts.named_labels`: ω_roda, ω_{roda sup}), else its number
    (`body_numbers`): the instant centres (I_13) and the bodies' numbering in the figures
    keep the numbers (`named` False)."""
    wording = getattr(model, "wording", None)
    numbers = body_numbers(model)
    if wording is None:
        return {name: str(k) for name, k in numbers.items()}
    if named:
        return wording.labels(list(numbers), lang, tuple(getattr(model, "parameters", {}) or ()))
    out = {}
    for name, k in numbers.items():
        index = wording.index(name, lang)
        out[name] = index if index is not None else str(k)
    return out


def names_bodies(model: Any, lang: Optional[str]) -> bool:
    """Whether the model names its bodies in `lang` (`names: LANG: bodies`): then every symbol
    writes a body by its name's subscript (ω_biela, v_J1∈roda, I_biela), as the notes write
    Ω^roda and CIR^{roda sup}; else by its number (ω_3, I_13)."""
    wording = getattr(model, "wording", None)
    return bool(lang and wording is not None and wording.bodies.get(lang))


def centre_subscript(a: str, b: str, numbers: dict, labels: dict, named: bool, rel_word: str) -> str:
    """The subscript of the instant centre of bodies `a` and `b`, the one rule of the text and
    the figures. Named bodies (`names_bodies`): the moving body's label alone when the other
    is the frame (I_biela, as ω_biela: the notes' CIR^{biela}_T), else the later body's label,
    the language's word for a relative motion and the earlier's (I_{politja rel braç}, as
    ω_{politja rel braç}). Numbered bodies: the two numbers in order, 13, 2N, or 2,11 when a
    label has more than one character (`labels` then the numbers or the notation's indices)."""
    x, y = sorted((a, b), key=lambda n: numbers[n])
    if named:
        return labels[y] if numbers[x] == 1 else f"{labels[y]} {rel_word} {labels[x]}"
    if all(len(t) == 1 for t in labels.values()):
        return labels[x] + labels[y]
    return f"{labels[x]},{labels[y]}"


def pair_tag(model: Any, a: str, b: str, lang: Optional[str] = None) -> str:
    """The subscript of a pair of bodies' instant centre (`centre_subscript`): I_biela, or by
    numbers 13, 2N, 2,11 when the model does not name its bodies in `lang`."""

    named = names_bodies(model, lang)
    return centre_subscript(a, b, body_numbers(model), body_labels(model, lang, named=named), named,
                            model.wording.relative_word(lang))


def shows_tag(tag: str, name: str) -> bool:
    """Whether a figure writes a body's symbol tag after its name, `roda (3)`: not when the
    tag is already read in the name (a word of it, or its words run together: `roda 1` for
    1 or roda1, `biela` for biela), which would repeat it (`roda 1 (1)`)."""
    words = [w.strip(".,;:()").lower() for w in name.split()]
    words = [w for w in words if w]
    t = tag.replace(" ", "").lower()
    if t in words or t == "".join(words):
        return False
    return not any(t == a + b for a in words for b in words if a != b)


def plain(text: str) -> str:
    """A model name made safe for ordinary (non-math) text: control characters written as
    escapes (as everywhere names are shown; a font has no glyph for them), and a `$` would
    start mathtext."""
    from ..text import shown

    return shown(text).replace("$", r"\$")


def _roman(name: str) -> str:
    """A name set upright in mathtext: \\mathrm{kable\\ zatia}. A hyphen is set as text
    (\\text{-}): inside \\mathrm mathtext sets "-" as a minus sign with a space either side,
    and a Basque reader read C5-1.1's I_{eskuineko kable-zatia} as "kable − zatia" (issue 30,
    twenty-fourth round (f)); a name is words, not a difference."""
    body = name.replace("_", r"\_").replace(" ", r"\ ")
    return r"\mathrm{" + body.replace("-", r"}\text{-}\mathrm{") + "}"


def subscript(letter: str, name: str, body: Optional[str] = None,
              relative: Optional[str] = None, rel_word: str = "rel") -> str:
    """`letter` with the subscript `name` (a point or a tag), `∈body` and the reference
    `relative` after the language's word for a relative motion (`rel_word`: rel, REL;
    never a slash, which reads as a fraction): $v_{\\mathrm{B}∈3\\ rel\\ 2}$. A name
    mathtext cannot take is written plainly: v(name∈3 rel 2)."""
    tail = (f"∈{body}" if body is not None else "") + (f" {rel_word} {relative}" if relative is not None
                                                       else "")
    if not _SIMPLE.match(name):
        return f"{letter}({plain(name)}{tail})"
    math = _roman(name)
    if body is not None:
        math += r"{\in}" + _roman(str(body))
    if relative is not None:
        math += r"\ " + _roman(rel_word) + r"\ " + _roman(str(relative))
    return "$" + letter + "_{" + math + "}$"


def geometric_symbol(letter: str, name: str) -> str:
    """`letter` of the geometric contact point at the contact `name`, as the text writes it,
    v_{J^{geom}} (the notes' J^{geom}, a point of neither body): "geom" raised just after the
    subscript J, at the subscript's size — $v_{J}{}^{geom}$. Set as a superscript of the
    subscript, mathtext shrinks it twice (4 pt in a 9 pt label: unreadable on the page,
    twenty-eighth round (a)). A name mathtext cannot take is written plainly, v(J^geom)."""
    if not _SIMPLE.match(name):
        return f"{letter}({plain(name)}^geom)"
    return "$" + letter + "_{" + _roman(name) + "}{}" + r"^{\mathrm{geom}}" + "$"


def point_symbol(letter: str, model: Any, point: str, body: Optional[str],
                 relative_to: Optional[str] = None, lang: Optional[str] = None) -> str:
    """`letter` for the material point `point` of `body` (None, or one whose motion all the
    point's carriers share: the bare name), relative to `relative_to` (None or the frame:
    absolute)."""
    labels = body_labels(model, lang)
    rel = None if relative_to in (None, model.frame) else labels[relative_to]
    if body is not None and rel is None and model.share_motion(point, model.carriers(point)):
        body = None          # a relative motion names its body always (v_P∈3/2, as the text does)

    return subscript(letter, point, None if body is None else labels[body], rel, model.wording.relative_word(lang))


# The letters a contact point is named with when the model names none, in order: J first
# (the notes' J, "el punt J de contacte"), then the letters after it. Left out: I (the
# instant centres), L (its polygon image l reads as I or 1), O (a centre, and the
# polygons' pole o), P (the point a problem asks about), T (the notes' terra, as in v_T),
# V (read as a velocity, v_V), R (a radius), and M and D, the marks every equation writes
# under its terms (M magnitude known, D direction known: a contact M beside them read as a
# mark; issue 30, fourteenth round (b), C5-E.4's M).
CONTACT_LETTERS = "JKNQSUWXYZEFGHABC"


def contact_name(model: Any, joint_id: str, sol: Any = None) -> str:
    """The name of a touching joint's contact point, as the text, the tables and the
    figures all write it (`contact_names`)."""
    return contact_names(model, sol)[joint_id]


def contact_names(model: Any, sol: Any = None) -> dict[str, str]:
    """Every touching joint's contact point -> its name, the one rule of the text, the tables
    and the figures: the name the model's notation gives it (`contact(j4): F`, the slides'
    F); else the model's own point there, when one of the two bodies (or a body welded to
    one) carries a point at the contact (one point, one label on a page: C5-1.2's K1, not K1
    and another name); else a letter as a teacher writes it, never the joint's id (the
    joints' ids are the file's, j3 -> J3 read as a joint): J, then K, M, N … in the
    joints' order (`CONTACT_LETTERS`), skipping any letter a point's name starts with (C
    beside C, G beside G1 and G2), a parameter's name (L, r) or a body's index (the slides'
    N), a body named by one letter, or the M and D marks — so one contact is the notes' J; never another point's name (a prime is added)."""
    touching = [j.id for j in model.joints if getattr(j.kind, "touches", False)]
    wording = getattr(model, "wording", None)
    out: dict[str, str] = {}
    for jid in touching:
        named = getattr(wording, "contacts", {}).get(jid)
        if named is None and sol is not None:
            named = coincident_point(sol, jid)
        if named is not None:
            out[jid] = named
    taken = {n[:1].upper() for n in model.points} | {n.upper() for n in getattr(model, "parameters", {})}
    taken |= {i.upper() for by_lang in getattr(wording, "indices", {}).values() for i in by_lang.values()}
    taken |= {b.upper() for b in getattr(model, "bodies", {}) if len(b) == 1}      # a body's symbol (001's N, R)
    taken |= {n.upper() for n in out.values()}
    letters = iter(c for c in CONTACT_LETTERS if c not in taken)
    for jid in touching:
        if jid not in out:
            base = next(letters, "J")
            while base in model.points or base in out.values():
                base += "'"
            out[jid] = base
    return {jid: out[jid] for jid in touching}


def coincident_point(sol: Any, joint_id: str) -> Optional[str]:
    """The model's point at a touching joint's contact, carried by one of its two bodies or
    a body welded to one (first in the file's order), else None: the contact is that point."""
    model = sol.model
    joint = next((j for j in model.joints if j.id == joint_id), None)
    geometry = sol.geometry(joint_id) if joint is not None else None
    contact = geometry.contact if geometry is not None else None
    if joint is None or contact is None:          # no joint, no geometry: no contact
        return None
    try:
        where = [float(sol.inst.num(c)) for c in contact.point]
    except (TypeError, ValueError):
        return None
    scale = max([1.0] + [abs(c) for c in where])
    bodies = _welded(model, {joint.a, joint.b})
    for name, pos in sol.inst.points.items():
        if not bodies & set(model.carriers(name)):
            continue
        try:
            xs = [float(sol.inst.num(c)) for c in pos]
        except (TypeError, ValueError):
            continue
        if len(xs) == len(where) and all(abs(x - y) <= 1e-9 * scale for x, y in zip(xs, where)):
            return name
    return None


def _welded(model: Any, bodies: set) -> set:
    """`bodies` and every body welded to one of them, directly or through others (a plane
    welded to the ground: the ground's point on it is the plane's point there too)."""
    out = set(bodies)
    welds = [j for j in model.joints if getattr(j.kind, "rigid", False)]
    grown = True
    while grown:
        grown = False
        for w in welds:
            if (w.a in out) != (w.b in out):
                out |= {w.a, w.b}
                grown = True
    return out


def pair_symbol(letter: str, model: Any, a: str, b: str, lang: Optional[str] = None) -> str:
    """`letter` for a pair of bodies' centre as the text writes it (`pair_tag`): $I_{biela}$,
    or by numbers $I_{13}$ (I_{2,11} once a label has two characters)."""
    return subscript(letter, pair_tag(model, a, b, lang))


def formula(expr: Any, value: float, lang: Optional[str] = None, spelt: Optional[dict] = None,
            chars: int = FORMULA_CHARS) -> str:
    """A short formula in mathtext ($2 r w^{2}$), else the value (`≈ 3.08`); numbers as
    `lang` writes them (`value_text`); the symbols of `spelt` (a parameter -> how the model
    writes it, `w0` -> `omega_0`) written that way (ω₀). `chars`: the longest formula (as
    plain text) written; an asked vector's is `ANSWER_CHARS` (`results.magnitude_text`)."""
    from sympy import Symbol, latex

    from ..report.values import written_form, written_latex

    tidied = written_form(expr)          # the form the text writes (`written_form`)
    if len(str(tidied).replace("Abs", "")) > chars:       # |x| is as short as (x)
        return f"≈ {value_text(value, lang)}"
    known = spelt or {}
    names = {s: latex(Symbol(known[s.name])) for s in getattr(tidied, "free_symbols", ()) if s.name in known}
    body = written_latex(tidied, names)
    body = body.replace(r"\left|", "|").replace(r"\right|", "|")   # mathtext: plain bars
    body = function_names(body, lang, latex=True)          # Spanish sen, as the text
    text = "$" + body.replace(r"\frac", r"\dfrac") + "$"    # full-size fractions
    if not settable(text):
        return f"≈ {value_text(value, lang)}"
    if lang is not None and decimal_sign(lang) == ",":
        text = DECIMAL.sub("{,}", text)      # mathtext's comma without a space after it
    return text


def settable(text: str) -> bool:
    """Whether matplotlib can set `text` (its mathtext parses)."""
    from .labels import text_extent
    from .style import LABEL_SIZE

    try:
        text_extent(text, LABEL_SIZE)
    except ValueError:
        return False
    return True


def equation(lhs: str, rhs: str) -> str:
    """`lhs = rhs`, or `lhs ≈ x` when the value is only approximate."""
    return f"{lhs} {rhs}" if rhs.startswith("≈") else f"{lhs} = {rhs}"


def value_text(x: float, lang: Optional[str] = None) -> str:
    """3 significant digits: as Python writes them (2.5, -0.3, 1e-05) in a figure of no
    language (`draw`'s default), else as the explanation in `lang` writes its numbers, with
    the same writer (2,5, −0,3, 1×10⁻⁵ in es)."""
    if lang is None:
        return f"{x:.3g}"
    return written(x, 3, decimal_sign(lang), superscript_power)


def number(x: float, scale: float = 1.0, lang: Optional[str] = None) -> str:
    """3 significant digits, with round-off below 1e-9 of `scale` shown as 0."""
    return "0" if abs(x) <= 1e-9 * scale else value_text(x, lang)


def listed(items: Sequence[str], lang: Optional[str] = None) -> str:
    """Numbers one after another: `0.32, 1.29`; `0,32; 1,29` where the decimal sign is a
    comma, as the text of an explanation in `lang` parts them."""
    return (", " if lang is None else separator(decimal_sign(lang))).join(items)


def coordinates(xs: Iterable[float], scale: float = 1.0, lang: Optional[str] = None) -> str:
    """`(0.32, 1.29)`; in a language with a decimal comma `(0,32; 1,29)`, as its text."""
    return "(" + listed([number(x, scale, lang) for x in xs], lang) + ")"


def bare(label: str) -> str:
    """A mathtext label as readable plain text, for notes: $I_{\\mathrm{13}}$ -> I13, and a
    subscript longer than a number or a letter in brackets, so that it does not run into its
    letter: $I_{\\mathrm{satèl·lit2}\\ \\mathrm{rel.}\\ \\mathrm{corona}}$ -> I(satèl·lit2 rel. corona)."""
    def piece(math: re.Match) -> str:
        head, sep, sub = math.group(1).partition("_")
        if not sep:
            return _unmath(head)
        sub = _unmath(sub)
        return _unmath(head) + (sub if len(sub) == 1 or sub.isdigit() else f"({sub})")

    out, found = re.subn(r"(?<!\\)\$(.+?)(?<!\\)\$", piece, label)
    return out if found else _unmath(label)


def _unmath(text: str) -> str:
    out = text.replace("$", "").replace(r"\mathrm", "").replace(r"\text", "").replace(r"{\in}", "∈")
    out = out.replace(r"\_", "\0").replace(r"\ ", " ")
    out = out.replace("{", "").replace("}", "").replace("_", "").replace("\\", "")
    return out.replace("\0", "_")


# where a label's subscript names a body: a centre's (I_13, Γ_13), after "∈" (v_{A∈3}) or "/"
_BODY_SLOT = re.compile(r"(?:^\$[IΓ]_\{?|\{\\in\}|/)(?:\\mathrm\{)?\d")


def numbered(label: str) -> bool:
    """Whether a label names bodies by their numbers (then the figure says which is which):
    I_13, v_{A∈3}, a_{B/2}; a label that names them by their names (I_biela) needs no list."""
    return bool(_BODY_SLOT.search(label))
