"""A model's names as a teacher writes them: `theta2` as θ₂, `omega_link5` as ω with the
subscript link5, `x_B` as x with the subscript B.

The reading is sympy's own (`split_super_sub`, as `sympy.latex` reads a symbol): a trailing
number is a subscript, `_sub` a subscript, `__sup` a superscript; a Greek letter's name is
the letter (`Omega` Ω, `lambda` λ); a name ending in a modifier is marked as sympy marks it
(`thetadot` θ̇). LaTeX is `sympy.latex` itself, so names read alike in a formula and in the
text around it. Two exceptions, in every format: a name `pi` stays `pi` (π is the constant),
and a name whose subscript or superscript is empty (`x_`) is written as it is.

A name's subscript keeps its text: `omega_left_arm` is ω with the subscript left_arm (sympy's
LaTeX separates the parts with a space). In LaTeX a subscript or superscript that is a word
(two letters or more: besoa, link5, left arm) is set upright (`upright`), as the method's
own subscripts are and as HTML and Markdown show it: a word, not a product of italic letters. Plain text (Markdown) writes a subscript of digits
with Unicode's subscript digits (θ₂), any other as `_sub` (x_B, ω_link5): the few Latin
subscript letters Unicode has would leave most names half lowered.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from html import escape

SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
SUPERSCRIPT = str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹")
CONSTANT_LOOKALIKES = ("pi",)        # written as they are: the letter would read as the constant
SCRIPT = re.compile(r"([_^])\{([^{}\\]+)\}")     # a subscript or superscript with no command in it


@dataclass(frozen=True)
class Written:
    """A name's parts as written: its base (a letter, a word, a Greek letter), the text of
    its subscript and of its superscript (empty when it has none)."""

    base: str
    sub: str = ""
    sup: str = ""


@lru_cache(maxsize=4096)
def written(name: str) -> Written:
    """The parts of `name` by sympy's conventions, Greek letters and modifiers translated."""
    from sympy.printing.conventions import split_super_sub

    try:
        base, sups, subs = split_super_sub(name)
    except (ValueError, IndexError):             # not a name sympy reads (its own error)
        return Written(name)
    if "" in sups or "" in subs or not base:
        return Written(name)
    return Written(_letter(base), "_".join(_letter(s) for s in subs), "_".join(_letter(s) for s in sups))


def _letter(word: str) -> str:
    """A word as sympy's pretty printer writes it: a Greek letter's name as the letter,
    a modifier at its end as a mark on the rest (xdot ẋ, vbar v̅); other words as they are."""
    from sympy.printing.pretty.pretty_symbology import greek_unicode, modifier_dict

    if word in CONSTANT_LOOKALIKES:
        return word
    if word in greek_unicode:
        return greek_unicode[word]
    for key in sorted(modifier_dict, key=len, reverse=True):
        if word.lower().endswith(key) and len(word) > len(key):
            return modifier_dict[key](_letter(word[:-len(key)]))
    return word


def unicode_name(name: str) -> str:
    """Plain text: θ₂, x_B, ω_link5, x² for x__2, x^a for x__a."""
    w = written(name)
    text = w.base
    if w.sub:
        text += w.sub.translate(SUBSCRIPT) if _digits(w.sub) else "_" + w.sub
    if w.sup:
        text += w.sup.translate(SUPERSCRIPT) if _digits(w.sup) else "^" + w.sup
    return text


# letters whose top stands above the x-height (δ, θ, b): an overdot sits higher over them
TALL = frozenset("βδζθϑλξφψbdfhklt" + "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789" + "ΓΔΘΛΞΠΣΦΨΩ")
# a dot or two over a letter (a rate, θ̇; a second derivative, θ̈), drawn by the page's CSS
OVERDOTS = {"\u0307": "dt", "\u0308": "dd"}


def html_marked(text: str) -> str:
    """A letter with its combining marks (escaped) in HTML, in the sans font (class `mk`). A
    dot or two over it is drawn by the CSS (classes `dt`, `dd`; `tl` over a tall letter),
    centred over the italic letter: the font's own combining dot, placed for the upright
    letter, stood off to the right of an italic δ and read as δ́ (twenty-ninth round (a))."""
    letter, marks = text[:1], text[1:]
    if marks in OVERDOTS:
        return f'<span class="mk {OVERDOTS[marks]}{" tl" if letter in TALL else ""}">{letter}</span>'
    return f'<span class="mk">{text}</span>'


def html_name(name: str) -> str:
    """HTML: θ<sub>2</sub>, x<sub>B</sub>, every part escaped. A base with a combining mark
    (θ̇, v̇) is set in the sans font (class `mk`): the serif one has no mark for Greek."""
    import unicodedata

    w = written(name)
    base = escape(w.base, quote=False)
    if any(unicodedata.combining(c) for c in w.base):
        base = re.sub("([^\u0300-\u036f][\u0300-\u036f]+)", lambda m: html_marked(m[1]), base)
    return (base + (f"<sub>{escape(w.sub, quote=False)}</sub>" if w.sub else "")
            + (f"<sup>{escape(w.sup, quote=False)}</sup>" if w.sup else ""))


@lru_cache(maxsize=4096)
def latex_name(name: str) -> str:
    """LaTeX math as `sympy.latex` writes the symbol (\\theta_{2}, x_{B}, \\omega_{link5});
    a name `pi` (or pi2, pi_B) as the word pi, not the constant \\pi."""
    import sympy

    if written(name).base not in CONSTANT_LOOKALIKES:
        text = sympy.latex(sympy.Symbol(name))
    else:
        text = r"\mathit{pi}" + sympy.latex(sympy.Symbol("x" + name[2:]))[1:]     # x's sub- and superscripts
    return SCRIPT.sub(lambda m: m.group(1) + "{" + (upright(m.group(2)) if _word(m.group(2)) else m.group(2)) + "}", text)


def upright(tex: str) -> str:
    """LaTeX text (escaped) set upright in math: \\mathrm{besoa}; with a space or a letter
    outside ASCII (pinyó, left arm) as text in the normal font, \\text{\\normalfont pinyó},
    since math mode drops spaces and pdflatex sets no accent there."""
    if tex.isascii() and " " not in tex:
        return r"\mathrm{" + tex + "}"
    return r"\text{\normalfont " + tex + "}"


def _word(text: str) -> bool:
    """A subscript that is a word: two letters or more (besoa, link5), not B, 2 or B2."""
    return sum(c.isalpha() for c in text) >= 2


def _digits(text: str) -> bool:
    return text.isascii() and text.isdigit()
