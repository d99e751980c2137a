"""The teacher's checks: Willis' formula in every epicyclic train, the ratio of belt and
chain drives, the quick-return's time ratio — each compared with a value worked out here
from the models' dimensions, not with the solver."""
from __future__ import annotations

import math

import pytest
import sympy

from kinematika.explain.document import Msg

from .helpers import explained

EPICYCLIC = {"seed_c5_1_4_epicyclic": -3, "seed_c5_e2_gear_change": -3,
             "planetary_gears": -(0.03 + 2 * 0.015) / 0.03}          # −ρ_ring/ρ_sun


def checks(doc, key: str) -> list[Msg]:
    return [b for b in doc.blocks() if isinstance(b, Msg) and b.key == key]


def value(x) -> float:
    return float(sympy.sympify(x.value))


@pytest.mark.parametrize("name", sorted(EPICYCLIC))
def test_willis_in_every_epicyclic_train(name):
    _, doc = explained(name)
    found = checks(doc, "check.willis")
    assert len(found) == 1
    assert value(found[0].args["train"]) == pytest.approx(EPICYCLIC[name])
    assert value(found[0].args["ratio"]) == pytest.approx(EPICYCLIC[name])


def test_no_willis_without_a_train():
    for name in ("four_bar", "seed_c5_e6_bicycle", "pulley_train"):
        _, doc = explained(name)
        assert not checks(doc, "check.willis"), name


def test_pulley_train_ratio():
    """ω₄/ω₁ = (r₁/r₂)(r₃/r₄) = (0.05/0.2)(0.06/0.15) = 0.1."""
    _, doc = explained("pulley_train")
    train = checks(doc, "check.train")
    assert len(train) == 1 and value(train[0].args["value"]) == pytest.approx(0.1)
    assert [value(m.args["ratio"].items[-1]) for m in checks(doc, "check.belt")] == pytest.approx([0.25, 0.4])


def test_bicycle_chain_as_the_notes_write_it():
    """r Ω_pinyó = R Ω_plat: the chainring turns at r/R of the sprocket, seen from the frame."""
    sol, doc = explained("seed_c5_e6_bicycle")
    belt = checks(doc, "check.belt")
    assert len(belt) == 1
    r, R = (next(s for s in sol.inst.env.values() if str(s) == n) for n in ("r", "R"))
    assert sympy.simplify(belt[0].args["ratio"].items[-1].value - r / R) == 0


def test_moving_pulley_seen_from_the_arm():
    """C5-1.6: from the arm, 2r ω_ground = r ω_pulley, so the pulley turns at twice the fixed one."""
    _, doc = explained("seed_c5_1_6_belt")
    belt = checks(doc, "check.belt")
    assert len(belt) == 1 and value(belt[0].args["ratio"].items[-1]) == 2


def test_quick_return_time_ratio():
    """Crank 0.1, pivots 0.3 apart: θ = acos(1/3), strokes 360° − 2θ and 2θ."""
    _, doc = explained("quick_return")
    quick = checks(doc, "check.quick")
    theta = math.degrees(math.acos(0.1 / 0.3))
    assert len(quick) == 1
    assert quick[0].args["ratio"].value == pytest.approx((360 - 2 * theta) / (2 * theta))
