"""Safe math expressions: parsed into a tree, checked against a whitelist, never run as code.

A model file is untrusted input, so expression strings go through Python's parser only
(``ast.parse`` builds a tree and executes nothing); every node of the tree must be a
number, a name, an arithmetic operator or a call of a whitelisted function. The tree is
then evaluated by an algebra backend, on floats or on sympy symbols.
"""
from __future__ import annotations

import ast
import keyword
import math
import re
from dataclasses import dataclass
from typing import Any, Callable, Mapping

MAX_LENGTH = 2000
MAX_DEPTH = 60
MAX_EXPONENT = 1000   # |y| in x**y when y is a number: exact powers stay quick to compute

FUNCTIONS = {
    "sqrt": 1, "cbrt": 1, "sin": 1, "cos": 1, "tan": 1, "asin": 1, "acos": 1, "atan": 1,
    "atan2": 2, "exp": 1, "log": 1, "abs": 1, "sinh": 1, "cosh": 1, "tanh": 1,
    "deg": 1, "rad": 1, "radians": 1, "degrees": 1,      # deg, rad, radians: degrees to radians
}
CONSTANTS = ("pi",)

_BINARY = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**", ast.BitXor: "**"}
_UNARY = {ast.USub: "-", ast.UAdd: "+"}


_KEYWORDS = re.compile(r"\b(" + "|".join(keyword.kwlist) + r")\b")
_MANGLE = "_kw_{}_"


def _mangle(source: str) -> str:
    """Rename Python keywords (`lambda`, `in`, `is`) so that they parse as plain names."""
    return _KEYWORDS.sub(lambda m: _MANGLE.format(m.group(1)), source)


def _unmangle(name: str) -> str:
    if name.startswith("_kw_") and name.endswith("_") and keyword.iskeyword(name[4:-1]):
        return name[4:-1]
    return name


class ExpressionError(ValueError):
    """An expression that cannot be read; the caller adds the place."""


@dataclass(frozen=True)
class Expr:
    """A checked expression: its text and tree. Evaluate it with `evaluate`."""

    text: str
    tree: ast.AST

    def names(self) -> set[str]:
        """The identifiers used as values (not function names)."""
        out: set[str] = set()
        _collect_names(self.tree, out)
        return out


def parse(text: str | int | float) -> Expr:
    """Parse a number or an expression string into a checked `Expr`."""
    if isinstance(text, bool):
        raise ExpressionError(f"expected a number or an expression, got {text!r}")
    if isinstance(text, (int, float)):
        if not _finite(text):
            got = repr(text) if isinstance(text, float) else f"an integer of {len(str(abs(text)))} digits"
            raise ExpressionError(f"expected a finite number in the range of floats, got {got}")
        return Expr(repr(text), ast.Constant(text))
    if not isinstance(text, str):
        raise ExpressionError(f"expected a number or an expression, got {text!r}")
    source = text.strip()
    if not source:
        raise ExpressionError("empty expression")
    if len(source) > MAX_LENGTH:
        raise ExpressionError(f"expression longer than {MAX_LENGTH} characters")
    try:
        tree = ast.parse(_mangle(source), mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError) as err:
        detail = getattr(err, "msg", None) or "unreadable"
        raise ExpressionError(f"cannot read expression {source!r}: {detail}") from None
    _check(tree, source, 0)
    return Expr(source, tree)


def _check(node: ast.AST, source: str, depth: int) -> None:
    if depth > MAX_DEPTH:
        raise ExpressionError(f"expression {source!r} is nested too deeply")
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise ExpressionError(f"in {source!r}: only numbers may be written as constants")
        if not _finite(node.value):
            raise ExpressionError(f"in {source!r}: a number is too large")
        return
    if isinstance(node, ast.Name):
        return
    if isinstance(node, ast.BinOp) and type(node.op) in _BINARY:
        _check(node.left, source, depth + 1)
        _check(node.right, source, depth + 1)
        return
    if isinstance(node, ast.UnaryOp) and type(node.op) in _UNARY:
        _check(node.operand, source, depth + 1)
        return
    if isinstance(node, ast.Call):
        name = node.func.id if isinstance(node.func, ast.Name) else None
        if name not in FUNCTIONS:
            raise ExpressionError(f"in {source!r}: unknown function {ast.unparse(node.func)!r} "
                                  f"(known: {', '.join(sorted(FUNCTIONS))})")
        if node.keywords or len(node.args) != FUNCTIONS[name]:
            raise ExpressionError(f"in {source!r}: {name} takes {FUNCTIONS[name]} argument(s)")
        for arg in node.args:
            _check(arg, source, depth + 1)
        return
    raise ExpressionError(f"in {source!r}: {ast.unparse(node)!r} is not allowed in an expression")


def _finite(value: int | float) -> bool:
    """Whether a number written in the model is finite and within the range of floats."""
    try:
        return math.isfinite(value)
    except OverflowError:     # an int too large for a float
        return False


def _collect_names(node: ast.AST, out: set[str]) -> None:
    if isinstance(node, ast.Name):
        out.add(_unmangle(node.id))
    elif isinstance(node, ast.BinOp):
        _collect_names(node.left, out)
        _collect_names(node.right, out)
    elif isinstance(node, ast.UnaryOp):
        _collect_names(node.operand, out)
    elif isinstance(node, ast.Call):
        for arg in node.args:
            _collect_names(arg, out)


def evaluate(expr: Expr, env: Mapping[str, Any], backend: Any) -> Any:
    """Evaluate a checked expression with values from `env` in the algebra `backend`."""
    return _eval(expr.tree, env, backend, expr.text)


def _eval(node: ast.AST, env: Mapping[str, Any], backend: Any, source: str) -> Any:
    if isinstance(node, ast.Constant):
        return backend.number(node.value)
    if isinstance(node, ast.Name):
        name = _unmangle(node.id)
        if name in env:
            return env[name]
        if name in CONSTANTS:
            return backend.pi
        raise ExpressionError(f"in {source!r}: unknown name {name!r} (not a parameter)")
    if isinstance(node, ast.UnaryOp):
        value = _eval(node.operand, env, backend, source)
        return -value if isinstance(node.op, ast.USub) else value
    if isinstance(node, ast.BinOp):
        left = _eval(node.left, env, backend, source)
        right = _eval(node.right, env, backend, source)
        return _binary(_BINARY[type(node.op)], left, right, backend, source)
    assert isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
    args = [_eval(a, env, backend, source) for a in node.args]
    try:
        result = backend.function(node.func.id)(*args)
    except (ValueError, ZeroDivisionError, OverflowError) as err:
        raise ExpressionError(f"in {source!r}: {node.func.id} cannot be evaluated ({err})") from None
    return backend.check(result, source)


_OPS: dict[str, Callable[[Any, Any], Any]] = {
    "+": lambda a, b: a + b, "-": lambda a, b: a - b, "*": lambda a, b: a * b,
    "/": lambda a, b: a / b, "**": lambda a, b: a ** b,
}


def _magnitude(value: Any) -> float:
    """|value|; for an array of designs (`algebra.arrays`), the largest."""
    try:
        return abs(float(value))
    except TypeError:
        return float(abs(value).max())


def _binary(op: str, left: Any, right: Any, backend: Any, source: str) -> Any:
    if op == "**" and not getattr(right, "free_symbols", None) and _magnitude(right) > MAX_EXPONENT:
        raise ExpressionError(f"in {source!r}: the exponent {_magnitude(right):g} is too large "
                              f"(at most {MAX_EXPONENT} in absolute value)")
    try:
        result = _OPS[op](left, right)
    except ZeroDivisionError:
        raise ExpressionError(f"in {source!r}: division by zero") from None
    except OverflowError:
        raise ExpressionError(f"in {source!r}: the value is too large") from None
    if isinstance(result, complex):
        raise ExpressionError(f"in {source!r}: the value is not real")
    return backend.check(result, source)
