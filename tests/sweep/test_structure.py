"""Structural decomposition (Assur groups) and the classical linkages' figures by hand."""
from __future__ import annotations

import math

import numpy as np
import pytest

from kinematika import load_model
from kinematika.model.build import build_model
from kinematika.structure.assur import assur_groups
from kinematika.sweep import run_sweep
from kinematika.sweep.run import Sweeper

from pathlib import Path

from .models import four_bar_tree, slider_crank_tree

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def kinds(tree_or_path):
    model = build_model(tree_or_path) if isinstance(tree_or_path, dict) else load_model(tree_or_path)
    groups = assur_groups(model)
    return None if groups is None else [(g.kind, g.bodies) for g in groups]


def inverted_slider_crank(w: float) -> dict:
    """Crank O-A (1, drawn up); the pin A slides in a slot of a rocker pivoted at C = (2, 0)."""
    return {"points": {"O": [0, 0], "A": [0, 1], "C": [2, 0]},
            "bodies": {"ground": ["O", "C"], "crank": ["O", "A"], "rocker": ["C", "A"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                       {"type": "revolute", "bodies": ["ground", "rocker"], "at": "C"},
                       {"type": "slot", "bodies": ["rocker", "crank"], "at": "A", "along": ["C", "A"]}],
            "drivers": [{"omega": "crank", "value": w}]}


def test_four_bar_and_slider_crank_are_a_crank_and_one_dyad():
    assert kinds(four_bar_tree()) == [("input", ["crank"]), ("RRR", ["coupler", "rocker"])]
    assert kinds(slider_crank_tree()) == [("input", ["crank"]), ("RRP", ["rod", "slider"])]


def test_multi_loop_linkages_decompose_in_solving_order():
    assert kinds(EXAMPLES / "watt_six_bar.yaml") == [
        ("input", ["crank"]), ("RRR", ["coupler", "rocker"]), ("RRR", ["link", "output"])]
    assert kinds(EXAMPLES / "jansen_leg.yaml") == [
        ("input", ["crank"]), ("RRR", ["upper", "top"]), ("RRR", ["lower", "rocker"]),
        ("RRR", ["knee", "foot"])]


def test_slotted_and_sliding_dyads_are_named_by_their_pairs():
    # inverted slider-crank: the crank pin slides in a slot of a rocker pivoted on the ground
    tree = inverted_slider_crank(1.0)
    assert kinds(tree) == [("input", ["crank"]), ("RPR", ["rocker"])]
    # Scotch yoke: a pin on the crank in a slot of a slider on a horizontal guide; slider and
    # slot make two sliding pairs in a row (an RPP dyad), which is not one of the four closed
    # forms: the general path solves it
    yoke = {"points": {"O": [0, 0], "A": [0.6, 0.8], "S": [0.6, 0]},
            "bodies": {"ground": ["O"], "crank": ["O", "A"], "yoke": ["S"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                       {"type": "prismatic", "bodies": ["ground", "yoke"], "along": [1, 0]},
                       {"type": "slot", "bodies": ["yoke", "crank"], "at": "A", "along": [0, 1]}],
            "drivers": [{"omega": "crank", "value": 1}]}
    assert kinds(yoke) == [("input", ["crank"]), ("other", ["yoke"])]
    result = run_sweep(yoke, by=360, steps=12)
    assert result.method == "newton"
    theta = np.radians(np.degrees(math.atan2(0.8, 0.6)) + result.coordinate)
    # the yoke follows the pin's x: x = cos θ, v = −sin θ, a = −cos θ (ω = 1)
    assert result.points["S@yoke"]["position"][:, 0] == pytest.approx(np.cos(theta), abs=1e-9)
    assert result.points["S@yoke"]["velocity"][:, 0] == pytest.approx(-np.sin(theta), abs=1e-9)
    assert result.points["S@yoke"]["acceleration"][:, 0] == pytest.approx(-np.cos(theta), abs=1e-9)


def test_inverted_slider_crank_rocker_follows_the_pin():
    tree = inverted_slider_crank(2.0)
    for general in (False, True):
        sweeper = Sweeper(tree)
        if general:
            sweeper.closed = None
        result = sweeper.run(by=360, steps=12)
        theta = np.radians(90 + result.coordinate)
        pin = np.column_stack([np.cos(theta), np.sin(theta)])
        # the rocker's direction is C→A; its angle is measured from the drawn C→A
        beta = np.arctan2(pin[:, 1], pin[:, 0] - 2)
        assert np.radians(result.bodies["rocker"]["angle"]) == pytest.approx(
            np.unwrap(beta - beta[0]), abs=1e-9)
        # ω of the rocker: d/dt atan2(sin θ, cos θ − 2) = ω2 (1 − 2 cos θ) / (5 − 4 cos θ)
        assert result.bodies["rocker"]["omega"] == pytest.approx(
            2.0 * (1 - 2 * np.cos(theta)) / (5 - 4 * np.cos(theta)), abs=1e-9)


def test_a_gear_pair_is_an_other_group():
    tree = {"points": {"O1": [0, 0], "O2": [3, 0]},
            "bodies": {"ground": ["O1", "O2"],
                       "g1": {"points": ["O1"], "circle": {"center": "O1", "radius": 1}},
                       "g2": {"points": ["O2"], "circle": {"center": "O2", "radius": 2}}},
            "joints": [{"type": "revolute", "bodies": ["ground", "g1"], "at": "O1"},
                       {"type": "revolute", "bodies": ["ground", "g2"], "at": "O2"},
                       {"type": "gear", "bodies": ["g1", "g2"]}],
            "drivers": [{"omega": "g1", "value": 2}]}
    assert kinds(tree) == [("input", ["g1"]), ("other", ["g2"])]
    result = run_sweep(tree, by=90, steps=3)
    assert result.method == "newton"
    assert result.bodies["g2"]["angle"] == pytest.approx([0, -15, -30, -45], abs=1e-9)
    assert result.bodies["g2"]["omega"] == pytest.approx([-1.0] * 4, abs=1e-9)


@pytest.mark.parametrize("lengths, start, verdict", [
    ((4, 1, 4, 3), 90, "Grashof crank-rocker"),
    ((1, 4, 3, 4), 90, "Grashof double crank"),
    ((4, 3, 1, 4), 60, "Grashof double rocker"),
    ((4, 2.5, 3, 3), 90, "non-Grashof"),
    ((4, 1, 4, 1), 90, "change point"),
])
def test_grashof_classification(lengths, start, verdict):
    ground, crank, coupler, rocker = lengths
    linkage = Sweeper(four_bar_tree(ground, crank, coupler, rocker, crank_deg=start, side=1.0)).linkage()
    assert linkage.kind == "four-bar"
    assert linkage.grashof.startswith(verdict)


def test_four_bar_limit_positions_by_hand():
    # 4, 1, 4, 3 with the crank drawn at 90°. Extended: |O2B| = 5, a 3-4-5 triangle, B = (4, 3):
    # crank along O2B at atan2(3, 4), rocker straight up. Folded: |O2B| = 3, B = (2, √5), the
    # crank pointing away from B.
    tree = four_bar_tree(crank_deg=90, side=1.0)          # B above the ground line
    linkage = Sweeper(tree).linkage()
    b0 = tree["points"]["B"]
    rocker0 = math.degrees(math.atan2(b0[1], b0[0] - 4))
    extended, folded = linkage.limits
    assert extended.crank == pytest.approx((math.degrees(math.atan2(3, 4)) - 90) % 360)
    assert extended.output == pytest.approx(90 - rocker0)
    assert folded.crank == pytest.approx((math.degrees(math.atan2(-math.sqrt(5), -2)) - 90) % 360)
    assert folded.output == pytest.approx(math.degrees(math.atan2(math.sqrt(5), -2)) - rocker0)
    # and the sweep's rocker range ends there
    result = run_sweep(tree, by=360, steps=3600)
    assert result.bodies["rocker"]["angle"].min() == pytest.approx(extended.output, abs=1e-4)
    assert result.bodies["rocker"]["angle"].max() == pytest.approx(folded.output, abs=1e-4)


def test_slider_crank_stroke_and_limits():
    r, l, e = 1.0, 3.0, 0.5
    sweeper = Sweeper(slider_crank_tree(r, l, e, crank_deg=60))
    sc = sweeper.linkage()
    assert sc.kind == "slider-crank" and sc.crank_turns
    assert sc.offset == pytest.approx(e)
    stroke = math.sqrt((l + r) ** 2 - e ** 2) - math.sqrt((l - r) ** 2 - e ** 2)
    assert sc.stroke == pytest.approx(stroke)
    x = sweeper.run(by=360, steps=7200).points["B@slider"]["position"][:, 0]
    assert x.max() - x.min() == pytest.approx(stroke, abs=1e-6)
    travel = {lim.name: lim.output for lim in sc.limits}
    assert x.max() - x[0] == pytest.approx(travel["extended"], abs=1e-6)
    assert x.min() - x[0] == pytest.approx(travel["folded"], abs=1e-6)


def test_inverted_slider_crank_with_a_block_is_swept_without_a_classical_linkage(tmp_path):
    # a block pinned at the crank pin A slides along a rod pivoted at O4 (an RPR dyad of two
    # bodies): no four-bar or slider-crank figures, but the sweep and its summary work. The rod
    # swings between the tangents from O4 to the pin's circle: 180° ± asin(r/d) from O4→O2.
    import yaml
    from typer.testing import CliRunner

    from kinematika.cli import app

    r, d, th = 0.1, 0.3, math.radians(60)
    a = [r * math.cos(th), r * math.sin(th)]
    tree = {"points": {"O2": [0, 0], "O4": [d, 0], "A": a},
            "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "block": ["A"], "rod": ["O4", "A"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                       {"type": "revolute", "bodies": ["crank", "block"], "at": "A"},
                       {"type": "revolute", "bodies": ["ground", "rod"], "at": "O4"},
                       {"type": "prismatic", "bodies": ["rod", "block"], "along": ["O4", "A"]}],
            "drivers": [{"omega": "crank", "value": 20}]}
    assert kinds(tree) == [("input", ["crank"]), ("RPR", ["block", "rod"])]
    sweeper = Sweeper(tree)
    assert sweeper.linkage() is None
    angle = sweeper.run(by=360, steps=3600).bodies["rod"]["angle"]
    drawn = math.degrees(math.atan2(a[1], a[0] - d))
    swing = math.degrees(math.asin(r / d))
    assert angle.min() == pytest.approx(180 - swing - drawn, abs=1e-3)
    assert angle.max() == pytest.approx(180 + swing - drawn, abs=1e-3)
    model = tmp_path / "inverted.yaml"
    model.write_text(yaml.safe_dump(tree))
    out = CliRunner().invoke(app, ["sweep", str(model)])
    assert out.exit_code == 0, out.output
    assert "RPR block + rod" in out.stdout and "four-bar" not in out.stdout
