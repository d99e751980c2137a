"""Answers as plain data: floats (cleaned of round-off) or formula strings (simplified)."""
from __future__ import annotations

import math
from typing import Any, Mapping

from ..memo import Memo

SIGNIFICANT = 12


def plain(value: Any, symbolic: bool, scale: float = 1.0,
          fields: Mapping[str, float] | None = None) -> Any:
    """Convert a raw answer (nested dicts, tuples, scalars) into JSON-able data; round-off
    is cleaned against `scale`, or for a field of a compound answer against the scale of
    its own kind (`fields`: a point's against lengths, a direction's against 1)."""
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, dict):
        return {k: plain(v, symbolic, fields.get(k, scale) if fields else scale, fields)
                for k, v in value.items()}
    if isinstance(value, (tuple, list)):
        return [plain(v, symbolic, scale, fields) for v in value]
    if symbolic:
        return formula(value)
    return number(value, scale)


def number(x: Any, scale: float = 1.0) -> float:
    """A float rounded to 12 significant digits, with round-off below 1e-12·scale set to 0."""
    x = float(x)
    if not math.isfinite(x):
        return x
    if abs(x) <= 1e-12 * scale or x == 0:
        return 0.0
    digits = SIGNIFICANT - 1 - math.floor(math.log10(abs(x)))
    return float(round(x, digits)) + 0.0


_POWERS_OF_TEN = [float(10 ** k) for k in range(23)]      # exact doubles


def numbers(values: Any, scale: float = 1.0) -> Any:
    """`number` of every element of a float array, as a float array, without a Python float
    per element: exactly `number`'s results (a model of 10 000 bodies has 300 000 of them).

    x·10^d (or x/10^-d) is rounded to an integer n in floating point and n/10^d taken: both
    operations are exact or correctly rounded while 10^|d| is exact (|d| ≤ 22), which is
    what Python's `round` gives unless x·10^d lies within rounding error of a half-integer:
    those few, and magnitudes beyond 10^±22, go through `number`. Near a power of ten
    (where numpy's log10 and math's might disagree on the floor) the exponent is math's."""
    import numpy as np

    given = np.asarray(values, dtype=float)
    x = given.ravel()
    magnitude = np.abs(x)
    finite = np.isfinite(x)
    live = finite & (magnitude > 1e-12 * scale) & (x != 0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        log = np.log10(np.where(live, magnitude, 1.0))
        exponent = np.floor(log)
        near = np.flatnonzero(live & (np.abs(log - np.rint(log)) <= 1e-9))   # near 1, 10, 100…
        exponent[near] = [math.floor(math.log10(v)) for v in magnitude[near].tolist()]
        digits = SIGNIFICANT - 1 - exponent
        safe = live & (np.abs(digits) <= 22)
        power = np.array(_POWERS_OF_TEN).take(np.abs(np.where(safe, digits, 0.0)).astype(int))
        up = digits >= 0
        scaled = np.where(up, x * power, x / power)
        whole = np.rint(scaled)
        safe &= np.abs(np.abs(scaled - np.floor(scaled)) - 0.5) > 1e-3
        rounded = np.where(up, whole / power, whole * power)
    out = np.where(live, rounded, np.where(finite, 0.0, x)) + 0.0
    for i in np.flatnonzero(live & ~safe):
        out[i] = number(x[i], scale)
    return out.reshape(given.shape)


def formula(x: Any) -> str:
    """A simplified formula in sympy's syntax (`4*Omega/3`, `sqrt(2)*r*w/4`)."""
    shown = tidy(x)
    text = _TEXT.get(shown)
    return _TEXT.put(shown, printed(shown)) if text is None else text


PLAIN_ORDER_OPS = 1000  # longer formulas are printed with their terms in sympy's stored order


def printed(x: Any, printer: Any = None) -> str:
    """sympy's text of `x`; a long formula's sums are not sorted by degree first (sorting
    takes most of the printing there, and such a formula is read by a program anyway).
    `printer`: a StrPrinter subclass to print with (the explanations mark the symbols)."""
    from ..algebra.fields import ops

    if ops(x) <= PLAIN_ORDER_OPS:
        return str(x) if printer is None else printer().doprint(x)
    from sympy.printing.str import StrPrinter

    return (printer or StrPrinter)({"order": "none"}).doprint(x)


_TEXT = Memo(4096)  # printing a long formula takes long: each is printed once


def tidy(x: Any) -> Any:
    """A readable exact form: the canonical rational form, factored, then written as a
    textbook would: √(b² − a² sin² θ) rather than √((b − a sin θ)(b + a sin θ)) when that
    is no longer, and v₀(L − s) rather than −v₀(−L + s)."""
    import sympy

    from ..algebra.fields import canonical

    x = sympy.sympify(x)
    if x.is_Atom:
        return x
    shown = _TIDY.get(x)
    return _TIDY.put(x, _tidy(canonical(x))) if shown is None else shown


_TIDY = Memo(4096)  # a point's velocity is asked of every body that carries it, and
                    # answers repeat the tables' entries


def turned(x: Any) -> Any:
    """A product's minus taken into a difference of two terms, as the notes write their
    results: −v(r₁ − r₂)/r₂ is v(r₂ − r₁)/r₂ (one sign fewer to read)."""
    import sympy

    factors = list(sympy.Mul.make_args(x))
    if not x.is_Mul or sympy.S.NegativeOne not in factors:
        return x
    for f in factors:
        base, power = f.as_base_exp()
        if base.is_Add and len(base.args) == 2 and power in (1, -1) \
                and sum(t.could_extract_minus_sign() for t in base.args) == 1:
            rest = [g for g in factors if g is not f and g is not sympy.S.NegativeOne]
            flipped = sympy.Add(*[-t for t in base.args], evaluate=False)
            return sympy.Mul(*rest, flipped if power == 1 else sympy.Pow(flipped, power, evaluate=False),
                             evaluate=False)
    return x


def written_form(x: Any) -> Any:
    """The form every view writes a formula in — the text (Unicode, LaTeX) and the figures'
    labels (`draw.names.formula`): `tidy`, then a product's minus taken into a difference
    (`turned`), so a figure never labels −v(r₁ − r₂)/r₂ what its text writes v(r₂ − r₁)/r₂
    (issue 30, fourteenth round (d): C5-E.5)."""
    return turned(tidy(x))


def _tidy(x: Any) -> Any:
    """`tidy` of a canonical form."""
    import sympy

    from ..algebra.fields import ops

    if x.is_Atom or ops(x) > MAX_TIDY_OPS:   # past the budget: the canonical form
        return x
    if x.has(sympy.sin, sympy.cos):
        x = x.replace(_trig_sum, _shortest_trig_form)
    return _absorb_sign(x.replace(_factored_root, _expanded_root))


MAX_TRIG_TERMS = 24     # longer sums are left as they are: the rewriting would cost more than it saves
MAX_TIDY_OPS = 200      # longer formulas are shown in their canonical form, not rewritten
TRIG_FACTOR_OPS = 120   # longer sums are not factored after cos² → 1 − sin² (past it, factoring
                        # takes up to seconds, a cost that jumps from one sum to the next)


def _trig_sum(x: Any) -> bool:
    """A sum worth rewriting: in sines and cosines, short, and free of roots (a root inside
    makes the rewritings slow and never shorter)."""
    import sympy

    return (x.is_Add and len(x.args) <= MAX_TRIG_TERMS and x.has(sympy.sin, sympy.cos)
            and not any(p.exp.q != 1 for p in x.atoms(sympy.Pow) if p.exp.is_Rational))


def _shortest_trig_form(x: Any) -> Any:
    """The shortest of a few textbook rewritings of a sum in sines and cosines:
    sin a cos b − cos a sin b = sin(a − b); the square eliminated the other way
    (cos² → 1 − sin², so that (c² + 2cr sin θ + r²)² is seen); the sum made homogeneous
    with sin² + cos² = 1, so that L² cos² δ + 2Ls sin δ cos δ + s² sin² δ = (L cos δ + s sin δ)²."""
    import sympy
    from sympy.simplify.fu import TR6, TR10i

    from ..algebra.fields import factor, ops
    from ..budget import within

    known = _SHORTEST.get(x)
    if known is not None:
        return known
    forms = [x]
    size = ops(x)
    rewrites = (TR10i, lambda e: factor(TR6(e)), _homogeneous) if size <= TRIG_FACTOR_OPS else \
        (TR10i, _homogeneous)
    for rewrite in rewrites:
        try:
            forms.append(within(size, rewrite, x))
        except (sympy.PolynomialError, TypeError, ValueError):   # a form it cannot take
            continue
    return _SHORTEST.put(x, min((f for f in forms if f is not None), key=ops))


_SHORTEST = Memo(4096)  # the same sums recur in the formulas of one mechanism


def _homogeneous(x: Any) -> Any:
    """x with each term raised to the top degree in (sin u, cos u) by factors sin² u + cos² u,
    factored; None when the degrees do not allow it (or there are several angles)."""
    import sympy

    angles = {f.args[0] for f in x.atoms(sympy.sin, sympy.cos)}
    if len(angles) != 1:
        return None
    u = angles.pop()
    sn, cs = sympy.sin(u), sympy.cos(u)
    try:
        poly = sympy.Poly(x, sn, cs)
    except sympy.PolynomialError:
        return None
    degrees = [i + j for i, j in poly.monoms()]
    top = max(degrees)
    if any((top - d) % 2 for d in degrees):
        return None
    one = sn ** 2 + cs ** 2
    lifted = sum(coeff * sn ** i * cs ** j * one ** ((top - i - j) // 2)
                 for (i, j), coeff in poly.terms())
    from ..algebra.fields import factor

    return factor(lifted)


def _reads_better_negated(total: Any) -> bool:
    """−L + s reads better as L − s, and cos θ − 1 as 1 − cos θ (so that −v(cos θ − 1) is
    written v(1 − cos θ))."""
    return total.could_extract_minus_sign() or sum(t for t in total.args if t.is_Number) < 0


def _factored_root(x: Any) -> bool:
    return (x.is_Pow and x.exp.is_Rational and not x.exp.is_Integer and x.base.is_Mul
            and any(f.is_Add for f in x.base.args))


def _expanded_root(x: Any) -> Any:
    import sympy

    flat = sympy.expand(x.base)
    return sympy.Pow(flat, x.exp) if sympy.count_ops(flat) <= sympy.count_ops(x.base) else x


def _absorb_sign(x: Any) -> Any:
    """A negative numeric factor taken into a sum (or a sum's reciprocal) that reads better
    negated: −v₀(−L + s)/2 becomes v₀(L − s)/2."""
    import sympy

    factors = list(sympy.Mul.make_args(x))
    coeff = next((f for f in factors if f.is_Number), None)
    if coeff is None or coeff >= 0:
        return x
    for f in factors:
        base, power = f.as_base_exp()
        if base.is_Add and power in (1, -1) and _reads_better_negated(base):
            rest = [g for g in factors if g is not coeff and g is not f]
            flipped = ([] if coeff == -1 else [-coeff]) + rest + [sympy.Pow(-base, power)]
            # sympy would spread a lone number over a sum (3*(L - s) -> 3*L - 3*s): keep it
            spread = len(flipped) == 2 and power == 1
            return sympy.Mul(*flipped, evaluate=not spread)
    return x


def positive_first(terms: list) -> list:
    """A sum's terms as a teacher writes them: its positive terms first, then its negative
    ones, each group in the order it came (sympy's): R_w + r − R, R_w + r − L − R, never
    −R + R_w + r, whose leading minus a reader takes for the sign of the whole (twenty-fourth
    round a; a difference of two terms, r₂ − r₁, was the first case). A sum with no positive
    term keeps its order, −a − b. The value is the same whichever way it is written: only the
    printed order changes (the formula printers', never a JSON answer's `printed`)."""
    negative = [t.could_extract_minus_sign() for t in terms]
    if not negative or not negative[0] or all(negative):
        return list(terms)
    return [t for t, neg in zip(terms, negative) if not neg] + [t for t, neg in zip(terms, negative) if neg]


def written_latex(x: Any, symbol_names: dict | None = None) -> str:
    """`x` (in its `written_form`) as LaTeX, a sum with its positive terms first
    (`positive_first`), r_2 − r_1 and never −r_1 + r_2, as the Unicode text writes it: the
    LaTeX page and the figures' labels (mathtext) say what the text says."""
    from sympy.printing.latex import LatexPrinter

    class _Written(LatexPrinter):
        def _as_ordered_terms(self, expr: Any, order: Any = None) -> list:
            return positive_first(super()._as_ordered_terms(expr, order=order))

    settings = {"symbol_names": symbol_names} if symbol_names else {}
    return _Written(settings).doprint(written_form(x))
