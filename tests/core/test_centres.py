"""`kinematika centres`: direct centres at the joints, Kennedy's theorem for the rest."""
from __future__ import annotations

import json
import subprocess
import sys
from itertools import combinations

import pytest

from kinematika import solve
from kinematika.questions.centres import all_centres, collinear
from kinematika.questions.icr import instant_centre

from .models import BX, BY, four_bar

SLIDER_CRANK = {
    "points": {"O": [0, 0], "A": [0.3, 0.4], "B": ["0.3 + sqrt(1.2**2 - 0.4**2)", 0]},
    "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
               {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
               {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
               {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
    "drivers": [{"omega": "crank", "value": 5}],
}


def centres_by_pair(sol):
    return {frozenset(c.pair): c for c in all_centres(sol)}


@pytest.mark.parametrize("tree", [four_bar(), SLIDER_CRANK], ids=["four-bar", "slider-crank"])
def test_every_triple_of_centres_is_collinear(tree):
    sol = solve(tree)
    found = centres_by_pair(sol)
    for a, b, c in combinations(sol.model.bodies, 3):
        trio = [found[frozenset(p)].value for p in ((a, b), (b, c), (a, c))]
        assert collinear(sol, *trio), (a, b, c)


def test_four_bar_centres_joint_and_kennedy():
    found = centres_by_pair(solve(four_bar()))
    assert found[frozenset(("ground", "crank"))].how == "joint"
    assert found[frozenset(("coupler", "rocker"))].value["point"] == pytest.approx((BX, BY))
    coupler = found[frozenset(("ground", "coupler"))]
    assert coupler.how == "kennedy" and set(coupler.via) == {"crank", "rocker"}
    # crank–rocker centre: on the ground line O2O4 (y = 0) and on the coupler line AB
    x = 0 + (BX - 0) * (0 - 1) / (BY - 1)
    assert found[frozenset(("crank", "rocker"))].value["point"] == pytest.approx((x, 0.0))


def test_slider_centre_is_at_infinity_across_the_guide():
    found = centres_by_pair(solve(SLIDER_CRANK))
    guide = found[frozenset(("ground", "slider"))]
    assert guide.how == "joint" and guide.value["point"] is None
    assert [abs(c) for c in guide.value["direction"]] == pytest.approx([0.0, 1.0])


def test_each_centre_has_zero_relative_velocity():
    sol = solve(four_bar())
    for a, b in combinations(sol.model.bodies, 2):
        centre = instant_centre(sol, b, a)
        if centre.get("point") is None:
            continue
        v = sol.motion.velocity(sol.state(b, a), centre["point"])
        assert v == pytest.approx((0.0, 0.0), abs=1e-9)


def test_cli_centres_json(tmp_path):
    path = tmp_path / "m.json"
    path.write_text(json.dumps(four_bar()))
    out = subprocess.run([sys.executable, "-m", "kinematika", "centres", str(path), "--json"],
                         capture_output=True, text=True, check=True)
    rows = json.loads(out.stdout)["centres"]
    assert len(rows) == 6
    assert {r["how"] for r in rows} == {"joint", "kennedy"}


def test_a_welded_body_shares_its_centres():
    """Two bodies welded together are one rigid body: each centre of one with a third body
    is the other's (found as a weld, not from the velocities), at the same point."""
    tree = {
        "points": {"O": [0, 0], "A": [1, 0], "B": [2.5, 1.5], "C": [3, -0.5]},
        "bodies": {"ground": ["O", "C"], "crank": ["O", "A"], "arm": ["A", "B"], "rod": ["B", "C"],
                   "fin": ["A"]},
        "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                   {"type": "revolute", "bodies": ["crank", "arm"], "at": "A"},
                   {"type": "revolute", "bodies": ["arm", "rod"], "at": "B"},
                   {"type": "revolute", "bodies": ["rod", "ground"], "at": "C"},
                   {"type": "weld", "bodies": ["crank", "fin"]}],
        "drivers": [{"omega": "crank", "value": 2}],
    }
    found = centres_by_pair(solve(tree))
    for other in ("ground", "arm", "rod"):
        shared, own = found[frozenset(("fin", other))], found[frozenset(("crank", other))]
        assert shared.how == "weld" and set(shared.value) == set(own.value)
        for key, value in shared.value.items():
            assert value == pytest.approx(own.value[key], abs=1e-9)
    assert found[frozenset(("fin", "ground"))].value["point"] == pytest.approx((0, 0), abs=1e-9)   # O
