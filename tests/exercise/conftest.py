"""The exercises the tests share, made once per session: `COUNT` variants of the notes' P
pair with Coriolis and `COUNT` of a four-bar stated by its lengths (the issue's done-when
quizzes had 30 each; the tests read the count, and the variants are the first of those 30:
the same seed draws the same variants in the same order)."""
from __future__ import annotations

import math

import pytest

from tests.conftest import EXAMPLES

P_PAIR = EXAMPLES / "exercises" / "p_pair_coriolis.yaml"
FOUR_BAR = EXAMPLES / "exercises" / "four_bar.yaml"
P_PAIR_VARY = ["s=300:500:10", "beta=20:40:1", "w=2:6:0.5"]
FOUR_BAR_VARY = ["a=25:35:1", "theta2=0:355:5", "w2=5:15:1"]
# variants of each shared exercise: enough for every index a test reads (variants[5]), for a
# variant whose margin is narrowed (the P pair's 5th) and for a class of five on distinct
# variants; each one costs its statement figure and its sheets' and key's pages
COUNT = 10


def make(path, vary, count, seed, lang="en"):
    from kinematika.exercise import make_exercise
    from kinematika.model.files import load_model

    return make_exercise(load_model(path), vary, count, seed, lang, source=path)


@pytest.fixture(scope="session")
def p_pair_exercise():
    return make(P_PAIR, P_PAIR_VARY, COUNT, 7)


@pytest.fixture(scope="session")
def four_bar_exercise():
    return make(FOUR_BAR, FOUR_BAR_VARY, COUNT, 3)


@pytest.fixture(scope="session")
def folders(tmp_path_factory, p_pair_exercise, four_bar_exercise):
    """The two exercises written (`exercise -o DIR`, without worked solutions and PDF, which
    tests of their own make for a few variants): {"p_pair": DIR, "four_bar": DIR}."""
    from kinematika.exercise import write_exercise

    out = {}
    for name, ex in (("p_pair", p_pair_exercise), ("four_bar", four_bar_exercise)):
        folder = tmp_path_factory.mktemp(name)
        write_exercise(ex, folder, solutions=False, pdf=False)
        out[name] = folder
    return out


def p_pair_data(stated, fixed=None):
    """A P-pair variant's data in SI units and radians, from its stated values (mm, degrees)."""
    data = {"s": 400, "beta": 30, "ex": 100, "ey": 400, "w": 4, "al": -2, **(fixed or {})}
    data.update({k: float(v) for k, v in stated.items()})
    return dict(s=data["s"] / 1000, beta=math.radians(data["beta"]), ex=data["ex"] / 1000,
                ey=data["ey"] / 1000, w=data["w"], al=data["al"])


def four_bar_data(stated):
    data = {"d": 100, "a": 30, "b": 90, "c": 80, "theta2": 60, "w2": 10}
    data.update({k: float(v) for k, v in stated.items()})
    return dict(d=data["d"] / 1000, a=data["a"] / 1000, b=data["b"] / 1000, c=data["c"] / 1000,
                theta=math.radians(data["theta2"]), w2=data["w2"])
