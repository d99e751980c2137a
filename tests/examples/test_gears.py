"""Gear trains: the planetary train (numbers), the notes' epicyclic transmission C5-1.4 and
gear change C5-E.2 (symbols). Expected values from Willis' formula and from equal
velocities at the pitch points, written by hand."""
from __future__ import annotations

import math

import sympy

from .helpers import answer, is_close, cross, same, solved, symbols


def test_planetary_gears_willis():
    rs, rp, ws = 0.03, 0.015, 100.0
    rr, arm = rs + 2 * rp, rs + rp
    # Willis, ring fixed: (w_s − w_c)/(0 − w_c) = −rr/rs; (w_p − w_c)/(w_s − w_c) = −rs/rp
    wc = ws * rs / (rs + rr)
    wp = wc - (ws - wc) * rs / rp
    name = "planetary_gears"
    assert solved(name)[1]["dof"] == 1          # three planets: redundant, solved by rank
    assert is_close(answer(name, omega="carrier"), wc) and is_close(wc, 100 / 3)
    assert is_close(answer(name, omega="planet1"), wp) and is_close(wp, -100)
    assert is_close(answer(name, omega="planet2", relative_to="carrier"), wp - wc)
    assert is_close(answer(name, velocity="A1"), cross(wc, [0, arm]), scale=1)
    a3 = [arm * math.cos(math.radians(330)), arm * math.sin(math.radians(330))]
    assert is_close(answer(name, acceleration="A3"), [-wc ** 2 * c for c in a3], scale=10)
    # planet 1 rolls on the fixed ring: its instant centre is the pitch point with the ring
    assert is_close(answer(name, icr="planet1")["point"], [0, rr], scale=1)
    # sun/planet 1 pitch point (0, rs): the sun's point, the planet's, and the geometric
    # one, which stays on the carrier's line at radius rs
    contact = answer(name, contact="sun_p1")
    assert is_close(contact["body_a"]["velocity"], cross(ws, [0, rs]), scale=1)
    assert is_close(contact["body_a"]["acceleration"], [0, -ws ** 2 * rs], scale=10)
    assert is_close(contact["body_b"]["velocity"], cross(ws, [0, rs]), scale=1)
    assert is_close(contact["body_b"]["acceleration"], [0, -wc ** 2 * arm + wp ** 2 * rp], scale=10)
    assert is_close(contact["geometric"]["velocity"], cross(wc, [0, rs]), scale=1)
    assert is_close(contact["geometric"]["acceleration"], [0, -wc ** 2 * rs], scale=10)


def test_seed_c5_1_4_epicyclic_transmission():
    # the planet below O: its centre A (at 2r) moves at 2rw (carrier), its contact with the
    # ring (at 3r) at 3rw the other way (ring at −w). Velocities are linear along the radius
    # through the planet: w_p = (−3rw − 2rw)/r = −5w; the centre is at 2rw/(5w) = (2/5) r from
    # A towards the ring; the contact with the sun (at r) moves at 2rw + 5rw = 7rw = r w_sun.
    name = "seed_c5_1_4_epicyclic"
    s = symbols(name)
    r, w = s["r"], s["w"]
    w_p = (-3 * r * w - 2 * r * w) / r
    assert same(name, answer(name, omega="planet1"), w_p)
    assert same(name, answer(name, omega="planet2"), w_p)
    assert same(name, answer(name, icr="planet1")["point"], [0, -2 * r - sympy.Rational(2, 5) * r])
    assert same(name, answer(name, omega="sun"), (2 * r * w - w_p * r) / r)
    assert same(name, answer(name, omega="sun"), 7 * w)
    assert same(name, answer(name, velocity="A1"), [2 * r * w, 0])
    assert solved(name)[1]["dof"] == 2


def test_seed_c5_e2_gear_change():
    # each planet touches the fixed wheel at its instant centre, r from its centre, which
    # moves at 2r·Omega: w_planet = 2 Omega. The planet's contact with the ring is 2r from that
    # centre: 2r·2 Omega = 3r·w_ring, so w_ring = 4 Omega/3.
    name = "seed_c5_e2_gear_change"
    s = symbols(name)
    r, omega = s["r"], s["Omega"]
    w_planet = 2 * r * omega / r
    w_ring = 2 * r * w_planet / (3 * r)
    assert same(name, answer(name, omega="planet1"), w_planet)
    assert same(name, answer(name, omega="planet2"), w_planet)
    assert same(name, answer(name, omega="ring"), w_ring) and w_ring == 4 * omega / 3
    assert same(name, answer(name, icr="planet1")["point"], [0, r])
    assert same(name, answer(name, icr="planet2")["point"], [0, -r])
    assert same(name, answer(name, icr="ring")["point"], [0, 0])
    assert same(name, answer(name, icr="arm")["point"], [0, 0])
