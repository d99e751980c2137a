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
    assert [float(x) for x in drive_ratio(doc)] == pytest.approx([0.25, 0.4] * 2)     # ω, then α


def drive_ratio(doc) -> list:
    """The ratio each drive step writes: ω_b/K = (ratio) · ω_a/K."""
    from kinematika.explain.document import Derived, Value

    return [d.how[0].value for d in doc.blocks() if isinstance(d, Derived) and d.how and isinstance(d.how[0], Value)
            and len(d.how) == 3 and d.how[1] == " · "]


def test_bicycle_chain_as_the_notes_write_it():
    """r Ω_pinyó = R Ω_plat, the step that gives the chainring's rate (not a check after it):
    seen from the frame, the chainring turns at r/R of the sprocket."""
    sol, doc = explained("seed_c5_e6_bicycle")
    assert len(checks(doc, "drive.relation")) == 1 and not checks(doc, "check.belt")
    r, R = (next(s for s in sol.inst.env.values() if str(s) == n) for n in ("r", "R"))
    ratios = drive_ratio(doc)
    assert len(ratios) == 2 and all(sympy.simplify(x - r / R) == 0 for x in ratios)     # ω, then α


def test_moving_pulley_seen_from_the_arm():
    """C5-1.6: from the arm, 2r ω_ground/arm = r ω_pulley/arm, so the pulley turns at twice the
    fixed one relative to the arm: ω_3/2 = 2 ω_1/2 = −2ω, then ω_3 = ω_3/2 + ω_2 = −ω (the
    notes' ⊗2ω + ⊙ω = ⊗ω)."""
    sol, doc = explained("seed_c5_1_6_belt")
    assert len(checks(doc, "drive.relation")) == 1 and not checks(doc, "check.belt")
    assert [float(x) for x in drive_ratio(doc)] == [2]         # velocities only: nothing asks α
    from kinematika.explain.document import Derived

    w = next(s for s in sol.inst.env.values() if str(s) == "w")
    composed = [d for d in doc.derived() if d.sym.sub == "pulley" and d.how and d.how[-1].sub == "arm"]
    assert len(composed) == 1 and sympy.simplify(composed[0].value.value + w) == 0
    assert isinstance(composed[0], Derived)


def test_quick_return_time_ratio():
    """Crank 0.1, pivots 0.3 apart: θ = acos(1/3), strokes 360° − 2θ and 2θ."""
    _, doc = explained("quick_return")
    quick = checks(doc, "check.quick")
    theta = math.degrees(math.acos(0.1 / 0.3))
    assert len(quick) == 1
    assert quick[0].args["ratio"].value == pytest.approx((360 - 2 * theta) / (2 * theta))
