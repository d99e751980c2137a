"""Safe math expressions: parsed into a tree, checked against a whitelist, never run as code.

A model file is untrusted input, so expression strings go through Python's parser only
(``ast.parse`` builds a tree and executes nothing); every node of the tree must be a
number, a name, an arithmetic operator or a call of a whitelisted function. The tree is
then evaluated by an algebra backend, on floats or on sympy symbols.

Names are matched exactly as written. Python's parser would fold identifiers to their NFKC
form (𝑟 → r, ﬁ → fi) and refuses keywords (`lambda`), so every identifier is replaced by a
plain placeholder before parsing and restored in the tree afterwards: `𝑟` and `r`, `lambda`
and any other text are distinct names, each meaning only itself.
"""
from __future__ import annotations

import ast
import math
import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Callable, Mapping, Union

from . import limits
from .errors import Said, parser_problem
from .text import brief

if TYPE_CHECKING:
    from .point_pair import PointPair

MAX_LENGTH = limits.EXPRESSION_CHARS
MAX_DEPTH = limits.EXPRESSION_DEPTH
MAX_EXPONENT = limits.EXPONENT      # |y| in x**y when y is a number: exact powers stay quick to compute

FUNCTIONS = {
    "sqrt": 1, "cbrt": 1, "sin": 1, "cos": 1, "tan": 1, "asin": 1, "acos": 1, "atan": 1,
    "atan2": 2, "exp": 1, "log": 1, "abs": 1, "sinh": 1, "cosh": 1, "tanh": 1,
    "deg": 1, "rad": 1, "radians": 1, "degrees": 1,      # deg, rad, radians: degrees to radians
}
CONSTANTS = ("pi",)

_BINARY = {ast.Add: "+", ast.Sub: "-", ast.Mult: "*", ast.Div: "/", ast.Pow: "**", ast.BitXor: "**"}
_UNARY = {ast.USub: "-", ast.UAdd: "+"}

# a numeric literal as Python reads it (so that `2e-3` is not read as a name `e`)
_NUMBER = re.compile(r"0[xXoObB][0-9a-fA-F_]*|(?:[0-9][0-9_]*(?:\.[0-9_]*)?|\.[0-9][0-9_]*)"
                     r"(?:[eE][+-]?[0-9_]+)?[jJ]?")


def _placeholders(source: str) -> tuple[str, dict[str, str]]:
    """`source` with each identifier replaced by a placeholder `v0`, `v1`, … (the same
    identifier by the same one), and the placeholders' identifiers as written."""
    out: list[str] = []
    names: dict[str, str] = {}
    index: dict[str, str] = {}
    i, n = 0, len(source)
    while i < n:
        c = source[i]
        if c.isascii() and (c.isdigit() or (c == "." and source[i + 1:i + 2].isdigit())):
            match = _NUMBER.match(source, i)
            assert match is not None                # a digit (or a point and a digit) starts one
            out.append(match.group())
            i = match.end()
        elif c == "_" or c.isidentifier():
            j = i + 1
            while j < n and ("_" + source[j]).isidentifier():
                j += 1
            name = source[i:j]
            if name not in index:
                index[name] = f"v{len(index)}"
                names[index[name]] = name
            out.append(index[name])
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out), names


def _restore(tree: ast.AST, names: dict[str, str], source: str) -> None:
    """The identifiers as written, back in the parsed tree."""
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            if node.id not in names:
                raise ExpressionError("expr-unreadable-bare", source=brief(source))
            node.id = names[node.id]
        elif isinstance(node, ast.Attribute):
            node.attr = names.get(node.attr, node.attr)
        elif isinstance(node, ast.keyword) and node.arg is not None:
            node.arg = names.get(node.arg, node.arg)


class ExpressionError(ValueError):
    """An expression that cannot be read; the caller adds the place. Its message is a key
    of the errors' catalogue and its arguments (`said`), as a `KinematikaError`'s."""

    def __init__(self, message: "str | Said", /, **args: Any) -> None:
        self.said = Said.of(message, args)
        super().__init__(self.said)

    def __str__(self) -> str:
        return self.said.said()


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

    def calls(self) -> set[str]:
        """The functions it calls (`deg`, `sqrt`, …)."""
        return {node.func.id for node in ast.walk(self.tree)
                if isinstance(node, ast.Call) and isinstance(node.func, ast.Name)}


ExprVector = tuple[Expr, ...]
"""A point's or direction's coordinates, each an expression."""


Direction = Union[ExprVector, "PointPair"]
"""A direction as a model writes it: its components (a tuple), or two points (`PointPair`, in
`point_pair`, imported where one is made or read: a reader tells the two apart by
`isinstance(d, tuple)`). `model.model` keeps it; the joints' hooks receive it, so it sits
below both."""


def parse(text: str | int | float) -> Expr:
    """Parse a number or an expression string into a checked `Expr`."""
    if isinstance(text, bool):
        raise ExpressionError("expr-expected", got=brief(text))
    if isinstance(text, (int, float)):
        if not _finite(text):
            got = repr(text) if isinstance(text, float) else Said("integer-bits", bits=text.bit_length())
            raise ExpressionError("expr-not-finite", got=got)
        return Expr(repr(text), ast.Constant(text))
    if not isinstance(text, str):
        raise ExpressionError("expr-expected", got=brief(text))
    source = text.strip()
    if not source:
        raise ExpressionError("expr-empty")
    if len(source) > MAX_LENGTH:
        raise ExpressionError("expr-too-long", limit=MAX_LENGTH)
    plain, names = _placeholders(source)
    try:
        tree = ast.parse(plain, mode="eval").body
    except (SyntaxError, ValueError, RecursionError, MemoryError) as err:
        detail = getattr(err, "msg", None) or "unreadable"
        raise ExpressionError("expr-unreadable", source=brief(source), detail=parser_problem(detail)) from None
    _restore(tree, names, source)
    _check(tree, source, 0)
    return Expr(source, tree)


def _check(node: ast.AST, source: str, depth: int) -> None:
    if depth > MAX_DEPTH:
        raise ExpressionError("expr-too-deep", source=brief(source))
    if isinstance(node, ast.Constant):
        if isinstance(node.value, bool) or not isinstance(node.value, (int, float)):
            raise ExpressionError("expr-constant", source=brief(source))
        if not _finite(node.value):
            raise ExpressionError("expr-number-too-large", source=brief(source))
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
            raise ExpressionError("expr-unknown-function", source=brief(source), function=brief(ast.unparse(node.func)),
                                  known=sorted(FUNCTIONS))
        if node.keywords or len(node.args) != FUNCTIONS[name]:
            raise ExpressionError("expr-arguments", source=brief(source), function=name, count=FUNCTIONS[name])
        for arg in node.args:
            _check(arg, source, depth + 1)
        return
    raise ExpressionError("expr-not-allowed", source=brief(source), part=brief(ast.unparse(node)))


def _finite(value: int | float) -> bool:
    """Whether a number written in the model is finite and within the range of floats."""
    try:
        return math.isfinite(value)
    except OverflowError:     # an int too large for a float
        return False


def _collect_names(node: ast.AST, out: set[str]) -> None:
    if isinstance(node, ast.Name):
        out.add(node.id)
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
        name = node.id
        if name in env:
            return env[name]
        if name in CONSTANTS:
            return backend.pi
        raise ExpressionError("expr-unknown-name", source=brief(source), name=brief(name))
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
        if isinstance(result, float) and result == 0 and node.func.id == "exp":
            raise OverflowError("the value is too small for floating-point numbers")
    except (ValueError, ZeroDivisionError, OverflowError) as err:
        raise ExpressionError("expr-function-fails", source=brief(source), function=node.func.id,
                              why=parser_problem(str(err))) from None
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
        raise ExpressionError("expr-exponent", source=brief(source), exponent=float(_magnitude(right)),
                              limit=MAX_EXPONENT)
    try:
        result = _OPS[op](left, right)
    except ZeroDivisionError:
        raise ExpressionError("expr-division-by-zero", source=brief(source)) from None
    except OverflowError:
        raise ExpressionError("expr-too-large", source=brief(source)) from None
    if isinstance(result, complex):
        raise ExpressionError("expr-not-real", source=brief(source))
    if isinstance(result, float) and result == 0 and left != 0 and (op != "*" or right != 0) \
            and op in ("*", "/", "**"):
        raise ExpressionError("expr-underflow", source=brief(source))
    return backend.check(result, source)
