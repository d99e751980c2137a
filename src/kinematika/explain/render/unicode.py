"""Exact values as readable one-line Unicode formulas (HTML, Markdown) or LaTeX, with the
model's names written as a teacher writes them (θ₂, x_B: `names`)."""
from __future__ import annotations

import re
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Callable, Iterator

from sympy.printing.str import StrPrinter

from ...memo import Memo
from ...numerals import function_names
from ...report.values import positive_first, printed, turned, written_form, written_latex  # noqa: F401  (turned: its old home)
from .names import latex_name, unicode_name

SUPERSCRIPTS = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
MARK = 0xF0000                              # a symbol's place in a formula's text: one private character
MARKS = re.compile("[\U000F0000-\U000FFFFD]")


class _Marking(StrPrinter):
    """sympy's text with each symbol as one private character (its index in `names`), so
    that no symbol is mistaken for a word, a function or a constant of the same spelling
    (a parameter named `pi`, `E` or `sin`); the constants as a reader writes them."""

    def __init__(self, settings: dict | None = None, names: list | None = None) -> None:
        super().__init__(settings)
        self.names = names if names is not None else []

    def _print_Symbol(self, expr: Any) -> str:
        if expr.name not in self.names:
            self.names.append(expr.name)
        return chr(MARK + self.names.index(expr.name))

    def _as_ordered_terms(self, expr: Any, order: Any = None) -> list:
        """A sum's terms with its positive terms first (`positive_first`): R_w + r − R,
        r₂ − r₁, never −R + R_w + r."""
        return positive_first(super()._as_ordered_terms(expr, order=order))

    def _print_Pow(self, expr: Any, rational: bool = False) -> str:
        """An even power of a difference with its positive value first at the model's numbers
        (`formula_values`): (r₂ − r₁)² when r₂ > r₁, as the notes write it, the same value
        whichever way it is written (sympy keeps (r₁ − r₂)²)."""
        base, exp = expr.as_base_exp()
        if exp.is_Integer and exp.is_even and base.is_Add and len(base.args) == 2 \
                and _negative(base, _VALUES.get()):
            import sympy

            flipped = sympy.Add(*[-t for t in base.args], evaluate=False)
            return super()._print_Pow(sympy.Pow(flipped, exp, evaluate=False), rational)
        return super()._print_Pow(expr, rational)

    def _print_Pi(self, expr: Any) -> str:
        return "π"

    def _print_Exp1(self, expr: Any) -> str:
        return "e"

    def _print_ImaginaryUnit(self, expr: Any) -> str:
        return "i"


# a symbolic model's numbers (its draw_at values) while a page is written: which way round an
# even power of a difference reads (`_Marking._print_Pow`); never a value that is printed
_VALUES: ContextVar[dict | None] = ContextVar("formula_values", default=None)


@contextmanager
def formula_values(values: dict) -> Iterator[None]:
    """Write formulas with the model's numbers `values` (name -> float) at hand."""
    token = _VALUES.set(values)
    try:
        yield
    finally:
        _VALUES.reset(token)


def _negative(x: Any, values: dict | None) -> bool:
    """Whether `x` is negative at `values` (False when some symbol has no value)."""
    values = values or {}
    if not values:
        return False
    try:
        at = x.subs({s: values[s.name] for s in x.free_symbols})
        return bool(at.is_number and float(at) < 0)
    except (KeyError, TypeError, ValueError):
        return False


def _marked(expr: Any) -> tuple[str, tuple[str, ...]]:
    """The Unicode formula with its symbols marked, and their names: printed once in a
    command (a long formula takes long to print), written out by each language and format;
    remembered with the numbers of its symbols (`formula_values`), which may turn a square."""
    shown = written_form(expr)
    values = _VALUES.get() or {}
    key = (shown, tuple(sorted((s.name, values.get(s.name)) for s in getattr(shown, "free_symbols", ()))))
    known = _MARKED.get(key)
    if known is not None:
        return known
    names: list[str] = []
    text = _bars(printed(shown, lambda settings=None: _Marking(settings, names)))
    text = re.sub(r"\*\*(-?\d+)", lambda m: m.group(1).translate(SUPERSCRIPTS), text)
    text = re.sub(r"sqrt\(([\w\U000F0000-\U000FFFFD]+)\)", r"√\1", text)
    text = text.replace("sqrt(", "√(").replace("**", "^").replace("*", "·")
    return _MARKED.put(key, (text.replace(" - ", " − ").replace("-", "−"), tuple(names)))


_MARKED = Memo(4096)    # a command's own memory (kinematika.memo), as sympy's printed texts


def unicode_formula(expr: Any, name: Callable[[str], str] = unicode_name,
                    esc: Callable[[str], str] = lambda text: text, lang: str | None = None) -> str:
    """`sqrt(2)*r**2*theta2/4` as `√2·r²·θ₂/4`: the text through `esc` (HTML's escaping),
    each symbol as `name` writes it, each function as `lang` names it (Spanish sen(β):
    `numerals.function_names`; the symbols are still marks, so a symbol named `sin` stays)."""
    text, names = _marked(expr)
    text = function_names(text, lang)
    return MARKS.sub(lambda m: name(names[ord(m.group()) - MARK]), esc(text))


def _bars(text: str) -> str:
    """sympy's `Abs(x)` as the |x| a reader writes (nested ones too)."""
    while (start := text.find("Abs(")) >= 0:
        depth, end = 0, start + 3
        for end in range(start + 3, len(text)):
            depth += {"(": 1, ")": -1}.get(text[end], 0)
            if depth == 0:
                break
        text = text[:start] + "|" + text[start + 4:end] + "|" + text[end + 1:]
    return text


def latex_formula(expr: Any, spelt: dict[str, str] | None = None) -> str:
    """sympy's LaTeX, each symbol as `latex_name` writes it (a word in a subscript upright:
    R_{\\mathrm{roda}}; a symbol named like the constant π, `pi`, `pi2`, as the word); the
    symbols of `spelt` (a name -> its LaTeX) as given (a model's notation)."""

    shown = written_form(expr)
    spelt = spelt or {}
    own = {s: spelt.get(s.name) or latex_name(s.name) for s in getattr(shown, "free_symbols", ())}
    return written_latex(shown, own)
