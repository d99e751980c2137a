"""A fixed guide stops short of the wheels and cams of the moving bodies: a follower's guide
does not run through the cam it rides on (as a textbook draws it)."""
from __future__ import annotations

import math

import numpy as np

import kinematika
from kinematika.draw.geometry import Box
from kinematika.draw.joints import scene_symbols
from kinematika.draw.options import DrawOptions
from kinematika.draw.build import build_scene
from kinematika.joints.symbols import kept_out, ring
from tests.conftest import EXAMPLES


def test_a_guide_is_cut_before_a_disc_on_either_side():
    base, along = np.array([0.0, 0.0]), np.array([0.0, 1.0])
    seg = (np.array([0.0, -10.0]), np.array([0.0, 10.0]))
    below = ring(np.array([0.5, -5.0]), 2.0, 721)          # crosses x = 0 at y = −5 ± √3.75
    above = ring(np.array([0.0, 6.0]), 1.0, 721)           # at y = 5 and 7
    p, q = kept_out(seg, base, along, [below, above], 0.1)
    assert abs(p[1] - (-5 + math.sqrt(3.75) + 0.1)) < 1e-4
    assert abs(q[1] - (5 - 0.1)) < 1e-4 and p[0] == 0 and q[0] == 0


def test_a_guide_inside_an_outline_is_not_cut_for_it():
    seg = (np.array([-10.0, 0.0]), np.array([10.0, 0.0]))
    drum = ring(np.array([0.0, 0.0]), 4.0, 361)
    p, q = kept_out(seg, np.array([0.0, 0.0]), np.array([1.0, 0.0]), [drum], 0.1)
    assert (p[0], q[0]) == (-10.0, 10.0)


def test_the_roller_followers_guide_stays_above_the_cam():
    sol = kinematika.solve(EXAMPLES / "cam_roller_follower.yaml")
    scene = build_scene(sol.inst, sol, DrawOptions())
    view = Box(*scene.box).grow(0.6 * scene.size)
    guide = [m for m in scene_symbols(scene, view) if m.gid == "ground:guide"]
    assert len(guide) == 1
    lowest = float(np.min(guide[0].points[:, 1]))
    # the roller's centre F is 50 + s above the cam's centre, s = 25(1/4 − 1/2π): the guide
    # starts above the cam's profile, no lower than the roller's bottom (F − 10) less a margin
    f = 50 + 25 * (0.25 - 1 / (2 * math.pi))
    assert f - 10 - 0.1 * scene.size < lowest < f
