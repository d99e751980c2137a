"""Solve an example file once and read its answers as a user sees them (the contract's JSON).

Expected values never come from here: each test derives them by hand (loop closure
differentiated, the notes' reasoning, or sympy.physics.vector). These helpers only run
the tool and turn its formula strings back into sympy expressions for comparison.
"""
from __future__ import annotations

import functools
import json
import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import sympy

import kinematika
from kinematika.report.json_answer import solution_json

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
t = sympy.Symbol("t")


@functools.lru_cache(maxsize=None)
def solved(name: str) -> tuple[kinematika.Solution, dict]:
    """The solution of examples/NAME.yaml and its contract JSON (cached: solve once per run)."""
    sol = kinematika.solve(EXAMPLES / f"{name}.yaml")
    return sol, solution_json(sol)


def answer(name: str, **question: str) -> Any:
    """The JSON answer to the question of examples/NAME.yaml whose echo is `question`."""
    _, js = solved(name)
    found = [a["value"] for a in js["answers"] if a["ask"] == question]
    assert found, f"{name}.yaml does not ask {question}"
    return found[0]


def cli_answers(name: str) -> list[dict]:
    """`kinematika solve examples/NAME.yaml --json` run as a user would; its answers."""
    out = subprocess.run([sys.executable, "-m", "kinematika", "solve",
                          str(EXAMPLES / f"{name}.yaml"), "--json"],
                         capture_output=True, text=True, check=True)
    return json.loads(out.stdout)["answers"]


@functools.lru_cache(maxsize=None)
def symbols(name: str) -> dict[str, sympy.Symbol]:
    """The example's symbolic parameters as sympy symbols, with the file's sign assumptions."""
    model = solved(name)[0].model
    return {p.name: sympy.Symbol(p.name, positive=True) if p.positive else sympy.Symbol(p.name, real=True)
            for p in model.parameters.values() if p.value is None}


def formula(name: str, text: str) -> sympy.Expr:
    """A formula string of the tool's output, read back with the example's symbols."""
    return sympy.parse_expr(text, local_dict=dict(symbols(name)))


def same(name: str, got: Any, expected: Any) -> bool:
    """Whether the tool's formula(s) `got` equal `expected` exactly (simplify(got − exp) == 0)."""
    if isinstance(got, list):
        return len(got) == len(expected) and all(same(name, g, e) for g, e in zip(got, expected))
    return sympy.simplify(formula(name, got) - sympy.sympify(expected)) == 0


def is_close(got: Any, expected: Any, rel: float = 1e-9, scale: float = 1.0) -> bool:
    """Numbers (or vectors) equal to a relative tolerance, zero judged against `scale`."""
    if isinstance(got, (list, tuple)):
        return len(got) == len(expected) and all(is_close(g, e, rel, scale) for g, e in zip(got, expected))
    return math.isclose(float(got), float(expected), rel_tol=rel, abs_tol=rel * scale)


def at_instant(expr: Any, coords: dict) -> tuple[Any, Any, Any]:
    """expr(t) and its first two time derivatives at the instant.

    `coords` maps each coordinate q(t) to (value, rate, acceleration) at the instant.
    """
    expr = sympy.Matrix(expr) if isinstance(expr, (list, tuple)) else expr
    first = expr.diff(t)
    second = first.diff(t)
    subs = {}
    for q, (value, rate, accel) in coords.items():
        subs.update({q.diff(t, 2): accel, q.diff(t): rate, q: value})
    return tuple(_plain(e.xreplace(subs)) for e in (expr, first, second))


def _plain(e: Any) -> Any:
    """A float when nothing symbolic is left (fast), else a simplified formula."""
    if isinstance(e, sympy.MatrixBase):
        return [_plain(c) for c in e]
    return float(e.evalf(30)) if not e.free_symbols else sympy.simplify(e)


def cross(w: Any, r: Any) -> list:
    """ω k × r for a planar scalar ω."""
    return [-w * r[1], w * r[0]]


def curvature(p: Any, v: Any, a: Any) -> tuple[Any, list]:
    """Radius |v|³/|v × a| and centre P + |v|²/(v × a) k × v of a planar path (by hand)."""
    vxa = v[0] * a[1] - v[1] * a[0]
    vv = v[0] ** 2 + v[1] ** 2
    radius = sympy.simplify(sympy.sqrt(vv) ** 3 / sympy.Abs(vxa))
    centre = [sympy.simplify(pc + vv / vxa * kc) for pc, kc in zip(p, cross(1, v))]
    return radius, centre


def line_meet(p: Any, d1: Any, q: Any, d2: Any) -> list:
    """Where the lines p + s d1 and q + u d2 cross (Cramer's rule)."""
    det = sympy.sympify(d1[0] * (-d2[1]) - d1[1] * (-d2[0]))
    s = ((q[0] - p[0]) * (-d2[1]) - (q[1] - p[1]) * (-d2[0])) / det
    return [sympy.simplify(p[0] + s * d1[0]), sympy.simplify(p[1] + s * d1[1])]


def carried(origin: Any, turn: Any, offset: Any) -> list:
    """A body's material point: `origin` + the body's rotation by `turn` (ccw) of `offset`,
    its offset from `origin` when turn = 0."""
    c, s = sympy.cos(turn), sympy.sin(turn)
    return [origin[0] + c * offset[0] - s * offset[1], origin[1] + s * offset[0] + c * offset[1]]


def check_curvature(name: str, point: str, path: tuple, radius: Any) -> None:
    """The example's curvature answer for `point` is that of `path` (p, v, a, derived by
    hand), and its radius is `radius`."""
    expected, centre = curvature(*path)
    assert sympy.simplify(expected - radius) == 0
    got = answer(name, curvature=point)
    assert same(name, got["radius"], expected) and same(name, got["center"], centre)
