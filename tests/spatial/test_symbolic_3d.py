"""Symbolic spatial models: every formula, evaluated at random numbers, equals the numeric
answer of the same model with those numbers (angles, lengths and rates all symbols)."""
from __future__ import annotations

import copy
import math

import pytest
import sympy as sp
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st

from kinematika import solve
from kinematika.report.json_answer import solution_json

from .derive import EXAMPLES


def symbolic_version(example: str, symbols: list[str], drivers: list | None = None) -> dict:
    tree = yaml.safe_load((EXAMPLES / example).read_text())
    tree["parameters"] = {**tree.get("parameters", {}), **dict.fromkeys(symbols)}
    if drivers is not None:
        tree["drivers"] = drivers
    return tree


ARM = symbolic_version("robot_arm_3d.yaml", ["psi", "th", "h", "L", "w1", "a1", "w2", "a2"],
                       [{"joint": "yaw", "rate": "w1", "accel": "a1"},
                        {"joint": "pitch", "rate": "w2", "accel": "a2"}])
GYRO = symbolic_version("gyroscope.yaml", ["th", "d", "r", "p", "n", "n2", "s"],
                        [{"joint": "precession", "rate": "p"},
                         {"joint": "nutation", "rate": "n", "accel": "n2"},
                         {"joint": "spin", "rate": "s"}])
COIN = symbolic_version("coin_rolling.yaml", ["R", "rho", "beta", "W", "W1"],
                        [{"joint": "turn", "rate": "W", "accel": "W1"}])


def flatten(value) -> list:
    if isinstance(value, dict):
        return [x for k in sorted(value) for x in flatten(value[k])]
    if isinstance(value, (list, tuple)):
        return [x for v in value for x in flatten(v)]
    return [value]


def check_at(tree: dict, formulas: list, values: dict[str, float]) -> None:
    numeric = copy.deepcopy(tree)
    numeric["parameters"].update(values)
    numbers = flatten([a["value"] for a in solution_json(solve(numeric))["answers"]])
    names = {k: sp.Symbol(k, positive=True) for k in values}
    subs = {names[k]: v for k, v in values.items()}
    assert len(numbers) == len(formulas)
    for text, number in zip(formulas, numbers):
        if text is None or isinstance(text, bool):
            assert number == text
            continue
        exact = float(sp.sympify(text, locals=names).evalf(subs=subs))
        assert exact == pytest.approx(number, rel=1e-7, abs=1e-9), text


def formulas_of(tree: dict) -> list:
    out = solution_json(solve(tree))
    assert out["symbolic"] is True
    return flatten([a["value"] for a in out["answers"]])


positive = st.floats(0.2, 3.0)
acute = st.floats(0.1, 1.4)


@pytest.fixture(scope="module")
def arm_formulas():
    return formulas_of(ARM)


@pytest.fixture(scope="module")
def gyro_formulas():
    return formulas_of(GYRO)


@settings(max_examples=8)
@given(psi=st.floats(-3, 3), th=acute, h=positive, L=positive, w1=positive, a1=positive,
       w2=positive, a2=positive)
def test_symbolic_robot_arm(arm_formulas, psi, th, h, L, w1, a1, w2, a2):
    check_at(ARM, arm_formulas, dict(psi=psi, th=th, h=h, L=L, w1=w1, a1=a1, w2=w2, a2=a2))


@settings(max_examples=8)
@given(th=acute, d=positive, r=positive, p=positive, n=positive, n2=positive, s=positive)
def test_symbolic_gyroscope(gyro_formulas, th, d, r, p, n, n2, s):
    check_at(GYRO, gyro_formulas, dict(th=th, d=d, r=r, p=p, n=n, n2=n2, s=s))


@pytest.mark.slow
def test_symbolic_rolling_coin():
    """The rolling coin with its lean, radii and rates all symbols; the spin formula is the
    hand result −W ρ/R (for a lean below 90°, where |cos β| = cos β)."""
    formulas = formulas_of(COIN)
    spin_x = sp.sympify(formulas[0], locals={k: sp.Symbol(k, positive=True)
                                             for k in ("R", "rho", "beta", "W", "W1")})
    for values in ({"R": 0.02, "rho": 0.15, "beta": 0.35, "W": 3.0, "W1": 0.5},
                   {"R": 1.3, "rho": 0.4, "beta": 1.2, "W": 0.7, "W1": 2.0}):
        check_at(COIN, formulas, values)
        hand = -values["W"] * values["rho"] / values["R"] * math.cos(values["beta"])
        assert float(spin_x.evalf(subs={sp.Symbol(k, positive=True): v for k, v in values.items()})) \
            == pytest.approx(hand)
