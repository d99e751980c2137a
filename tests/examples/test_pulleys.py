"""Pulleys, cables and belts: the two-stage belt drive (numbers) and the notes' C5-1.1,
C5-1.5 and C5-1.6 (symbols), each by the reasoning of the notes written out by hand: a
strand or belt run is a rigid body, no slip makes touching points move alike, and a
pulley's velocities are linear in the distance from its instant centre."""
from __future__ import annotations

import math

import sympy
from sympy import sqrt

from .helpers import answer, cli_answers, is_close, cross, line_meet, same, solved, symbols


def test_pulley_train_ratio():
    r1, r2, r3, r4 = 0.05, 0.2, 0.06, 0.15
    w1 = 1500 * 2 * math.pi / 60
    belt1 = w1 * r1                 # each pulley's lowest point moves at w·r, to the right
    w2 = belt1 / r2                 # pulley 3 is keyed to pulley 2
    belt2 = w2 * r3
    w4 = belt2 / r4
    name = "pulley_train"
    assert is_close(answer(name, omega="pulley2"), w2)
    assert is_close(answer(name, omega="pulley4"), w4) and is_close(w4 / w1, 0.1)
    assert is_close(answer(name, velocity="T1@belt1"), [belt1, 0], scale=10)
    assert is_close(answer(name, velocity="T4@belt2"), [belt2, 0], scale=10)
    assert is_close(answer(name, acceleration="T4@belt2"), [0, 0], scale=10)


def test_seed_c5_1_1_pulley_on_a_cable():
    # Each strand turns about its ceiling point, so its point at the contact moves across the
    # strand: the pulley's centre lies on both strands' lines, where they cross.
    name = "seed_c5_1_1_pulley_on_cable"
    s = symbols(name)
    r, v = s["r"], s["v"]
    g1, g2 = [-2 * sqrt(3) * r, 4 * r], [2 * sqrt(3) * r, 4 * r]
    icr = line_meet(g1, [1, -sqrt(3)], g2, [-1, -sqrt(3)])
    assert icr == [0, -2 * r]
    w_pulley = sympy.simplify(v / cross(1, [0 - icr[0], 0 - icr[1]])[0])      # v_C = (v, 0)
    j1 = [-sqrt(3) * r / 2, -r / 2]          # strand 1's contact: radius ⟂ strand
    v_j1 = cross(w_pulley, [j1[0] - icr[0], j1[1] - icr[1]])
    w_strand = sympy.simplify(v_j1[0] / cross(1, [j1[0] - g1[0], j1[1] - g1[1]])[0])
    assert same(name, answer(name, icr="pulley")["point"], icr)
    assert same(name, answer(name, omega="pulley"), w_pulley) and w_pulley == -v / (2 * r)
    assert same(name, answer(name, omega="strand1"), w_strand) and w_strand == v / (6 * r)
    assert same(name, answer(name, omega="strand2"), w_strand)                  # symmetry
    assert same(name, answer(name, icr="strand1")["point"], g1)
    assert same(name, answer(name, velocity="P"), cross(w_pulley, [0, -r - icr[1]]))


def test_seed_c5_1_5_block_rises_at_6v():
    name = "seed_c5_1_5_pulley_block"
    s = symbols(name)
    r, v = s["r"], s["v"]
    # pulley 1 rolls on the tied strand (at x = 0): centre there; centre C1 (r away) at −v
    w1 = -v / r                               # v_C1 = w1 k × (r, 0) = (0, w1 r) = (0, −v)
    strand2 = 2 * r * w1                      # its right point, 2r from the centre: −2v
    w2 = strand2 / (-r)                       # pulley 2 about its axle: left point (−r, 0)
    strand3 = w2 * r                          # its right point: +2v
    # pulley 3: left point up at 2v, centre down at 2v: centre where the velocity vanishes
    w3 = (-2 * v - strand3) / r               # linear from left point to centre
    d = strand3 / -w3                         # distance of its centre from the left point
    strand4 = -2 * v + w3 * r                 # right point
    block = -strand4                          # pulley 4 reverses it
    assert same(name, answer(name, velocity="K"), [0, block]) and sympy.simplify(block - 6 * v) == 0
    assert same(name, answer(name, icr="pulley1")["point"], [0, -4 * r])
    assert same(name, answer(name, icr="pulley3")["point"], [4 * r + d, -4 * r]) and d == r / 2
    assert same(name, answer(name, omega="pulley3"), w3)
    assert same(name, answer(name, velocity="T2@strand2"), [0, strand2])


def test_seed_c5_1_6_belt_composition_of_motions():
    # From the arm (REL): the fixed pulley turns at −w; the belt run moves at 2r·w along
    # itself; the moving pulley (radius r) turns at −2w relative to the arm. Composition:
    # w_pulley = −2w + w = −w, whatever w.
    name = "seed_c5_1_6_belt"
    s = symbols(name)
    r, w = s["r"], s["w"]
    belt = -w * (-2 * r)                       # fixed pulley's top (0, 2r) seen from the arm
    w_rel = -belt / r                          # moving pulley's top (0, r) from A: −w_rel r
    w_abs = w_rel + w
    v_a = cross(w, [4 * r, r])
    assert same(name, answer(name, omega="pulley", relative_to="arm"), w_rel) and w_rel == -2 * w
    assert same(name, answer(name, omega="ground", relative_to="arm"), -w)
    assert same(name, answer(name, omega="pulley"), w_abs) and w_abs == -w
    assert same(name, answer(name, velocity="A"), v_a)
    icr = [4 * r - v_a[1] / w_abs, r + v_a[0] / w_abs]      # A + k × v_A / w
    assert same(name, answer(name, icr="pulley")["point"], icr)


def test_seed_c5_1_5_through_the_cli():
    name = "seed_c5_1_5_pulley_block"
    got = next(a["value"] for a in cli_answers(name) if a["ask"] == {"velocity": "K"})
    assert same(name, got, [0, 6 * symbols(name)["v"]])
    assert solved(name)[1]["symbolic"] is True
