"""`move` on models with symbolic parameters whose other bodies follow in closed form: a
planet rolling on a fixed sun, gear trains (Willis), a Geneva wheel, a slider, a coupler
point written in numbers. Every expected value is derived here by hand or with
sympy.physics.vector, never read from the code under test."""
from __future__ import annotations

import copy
import math

import mpmath
import pytest
import sympy
from sympy.physics.vector import Point, ReferenceFrame, dynamicsymbols

import kinematika
from kinematika import KinematikaError
from kinematika.api import prepare
from kinematika.engine.instant import instantiate
from kinematika.questions import answer
from kinematika.report.values import plain

from .test_constructions import four_bar_tree, freudenstein, slider_crank_tree

R, r, w, rs, rp, a, theta = sympy.symbols("R r w rs rp a theta", positive=True)
SYMBOLS = {str(s): s for s in (R, r, w, rs, rp, a, theta)}

PLANET = {
    "name": "planet on a fixed sun",
    "parameters": {"R": None, "r": None, "w": None},
    "points": {"O": [0, 0], "C": {"from": "O", "distance": "R + r", "angle": 0}, "Q": ["R + 2*r", 0]},
    "bodies": {"ground": {"points": ["O"], "circle": {"center": "O", "radius": "R"}},
               "arm": ["O", "C"],
               "planet": {"points": ["C", "Q"], "circle": {"center": "C", "radius": "r"}}},
    "joints": [{"type": "revolute", "bodies": ["ground", "arm"], "at": "O"},
               {"type": "revolute", "bodies": ["arm", "planet"], "at": "C"},
               {"type": "rolling", "bodies": ["ground", "planet"]}],
    "drivers": [{"omega": "arm", "value": "w"}],
    "ask": [{"omega": "planet"}, {"velocity": "Q"}],
}


def formula(text):
    return sympy.sympify(text, locals=SYMBOLS)


def shown(sol, *points: str) -> dict:
    """What `solve --json` shows of a symbolic solution that these tests read: its answers
    and the positions of `points` (each written as the answer writes a formula), without the
    tables of every point's velocity and acceleration, seconds of formulas no test here reads."""
    return {"symbolic": sol.symbolic,
            "answers": [{"value": plain(answer(sol, q), True)} for q in sol.model.questions],
            "points": {ref: {"position": plain(sol.position(ref), True)} for ref in points}}


def same(got, expected) -> bool:
    """The formula `got` equals `expected` exactly: their difference, each sine's and
    cosine's angle written over one denominator, cancels to 0 (as a rational function of the
    symbols, roots and trigonometric terms), or else sympy simplifies it to 0."""
    difference = formula(got) - expected
    angles_cancelled = difference.replace(lambda e: isinstance(e, (sympy.sin, sympy.cos)),
                                          lambda e: e.func(sympy.cancel(e.args[0])))
    return sympy.cancel(angles_cancelled) == 0 or sympy.simplify(difference) == 0


def test_a_planet_on_a_fixed_sun_moved_by_its_arm_is_exact():
    """The issue's case: R, r, w symbols, the arm moved 90°. Hand derivation with
    sympy.physics.vector: no slip at the contact J gives the planet's rate from the arm's; it is
    a constant ratio, so the planet has turned by that ratio times 90°."""
    qa, qp = dynamicsymbols("qa qp")
    N = ReferenceFrame("N")
    arm, planet = N.orientnew("A", "Axis", [qa, N.z]), N.orientnew("P", "Axis", [qp, N.z])
    O = Point("O")
    O.set_vel(N, 0)
    C = O.locatenew("C", (R + r) * arm.x)
    C.v2pt_theory(O, N, arm)
    J = C.locatenew("J", -r * arm.x)                 # the planet's point touching the sun
    J.v2pt_theory(C, N, planet)
    rate = sympy.solve(J.vel(N).dot(arm.y), qp.diff())[0]
    ratio = sympy.simplify(rate / qa.diff())
    assert ratio.free_symbols <= {R, r}              # constant: the rolled angle is ratio × the arm's
    Q = C.locatenew("Q", r * planet.x)               # drawn at C + r x (qa = qp = 0)
    Q.v2pt_theory(C, N, planet)
    at = {qa.diff(): w, qp.diff(): ratio * w, qa: sympy.pi / 2, qp: ratio * sympy.pi / 2}
    position = [Q.pos_from(O).dot(e).subs(at) for e in (N.x, N.y)]
    velocity = [Q.vel(N).dot(e).subs(at) for e in (N.x, N.y)]

    js = shown(kinematika.solve(PLANET, move={"j1": 90}), "Q@planet")
    assert js["symbolic"] is True
    omega, v = (x["value"] for x in js["answers"])
    assert same(omega, ratio * w)
    assert all(same(g, e) for g, e in zip(js["points"]["Q@planet"]["position"], position))
    assert all(same(g, e) for g, e in zip(v, velocity))


def epicyclic(ring_body: str = "ground") -> dict:
    """A sun (rs) driven at w, one planet (rp) on a carrier, a ring (rs + 2 rp); a marker Q on
    the planet written by coordinates, rp to the right of the planet's centre."""
    ring = {"points": ["O"], "circle": {"center": "O", "radius": "rs + 2*rp"}}
    bodies = {"ground": ring if ring_body == "ground" else ["O"],
              "sun": {"points": ["O"], "circle": {"center": "O", "radius": "rs"}},
              "carrier": ["O", "A"],
              "planet": {"points": ["A", "Q"], "circle": {"center": "A", "radius": "rp"}}}
    joints = [{"id": "js", "type": "revolute", "bodies": ["ground", "sun"], "at": "O"},
              {"type": "revolute", "bodies": ["ground", "carrier"], "at": "O"},
              {"type": "revolute", "bodies": ["carrier", "planet"], "at": "A"},
              {"type": "gear", "bodies": ["sun", "planet"]},
              {"type": "gear", "bodies": [ring_body, "planet"], "internal": True}]
    drivers = [{"omega": "sun", "value": "w"}]
    if ring_body != "ground":
        bodies[ring_body] = ring
        joints.append({"id": "jr", "type": "revolute", "bodies": ["ground", ring_body], "at": "O"})
        drivers.append({"omega": ring_body, "value": 0})
    return {"name": "epicyclic", "parameters": {"rs": None, "rp": None, "w": None},
            "points": {"O": [0, 0], "A": {"from": "O", "distance": "rs + rp", "angle": "deg(90)"},
                       "Q": ["rp", "rs + rp"]},
            "bodies": bodies, "joints": joints, "drivers": drivers,
            "ask": [{"omega": "carrier"}, {"omega": "planet"}]}


def willis(sun, ring):
    """Willis's formula by hand, relative to the carrier c: (φs − φc)/(φr − φc) = −rr/rs
    (external mesh through the planet), and the planet (φp − φc)/(φr − φc) = rr/rp (internal)."""
    rr = rs + 2 * rp
    carrier = (rs * sun + rr * ring) / (rs + rr)
    return carrier, carrier + rr / rp * (ring - carrier)


def marker(carrier, planet):
    """Q after the carrier turned by ψ and the planet by φ: A turned about O, Q − A turned by φ."""
    A = ((rs + rp) * sympy.cos(sympy.pi / 2 + carrier), (rs + rp) * sympy.sin(sympy.pi / 2 + carrier))
    return (A[0] + rp * sympy.cos(planet), A[1] + rp * sympy.sin(planet))


def test_a_sun_driven_train_with_the_ring_fixed_turns_the_carrier_and_planet_by_willis():
    carrier, planet = willis(sympy.pi / 3, 0)
    js = shown(kinematika.solve(epicyclic(), move={"js": 60}), "Q@planet")
    assert all(same(g, e) for g, e in zip(js["points"]["Q@planet"]["position"], marker(carrier, planet)))
    rates = willis(w, 0)
    assert [same(x["value"], e) for x, e in zip(js["answers"], rates)] == [True, True]


def test_two_inputs_moved_together_add_their_rolling_ratios():
    """A differential: the sun turned 60° and the ring −30° (both driven from the frame)."""
    carrier, planet = willis(sympy.pi / 3, -sympy.pi / 6)
    model = prepare(epicyclic("ring"), move={"js": 60, "jr": -30})
    js = shown(kinematika.solve(model), "Q@planet")
    assert all(same(g, e) for g, e in zip(js["points"]["Q@planet"]["position"], marker(carrier, planet)))


GENEVA = {
    "name": "Geneva wheel, four slots",
    "parameters": {"a": None, "theta": None, "w": None, "c": "a*sqrt(2)"},
    "points": {"O1": [0, 0], "O2": ["c", 0], "P": {"from": "O1", "distance": "a", "angle": "theta"},
               "W": ["c", "a"]},
    "bodies": {"ground": ["O1", "O2"], "crank": ["O1", "P"], "wheel": ["O2", "W"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O1"},
               {"type": "revolute", "bodies": ["ground", "wheel"], "at": "O2"},
               {"type": "slot", "bodies": ["wheel", "crank"], "at": "P", "along": ["O2", "P"]}],
    "drivers": [{"omega": "crank", "value": "w"}],
    "ask": [{"omega": "wheel"}, {"velocity": "W"}],
}


def test_a_geneva_wheels_point_follows_its_slot():
    """The slot runs through the wheel's centre O2, so the wheel turns as the line O2P does:
    by hand, its angle β(θ) = atan2(a sin θ, a cos θ − c); W (drawn a above O2) turns about O2
    by β(θ + 10°) − β(θ), and the wheel's rate is β'(θ + 10°) w."""
    c = a * sympy.sqrt(2)
    beta = sympy.atan2(a * sympy.sin(theta), a * sympy.cos(theta) - c)
    moved = theta + sympy.pi / 18
    turn = beta.subs(theta, moved) - beta
    W = (c - a * sympy.sin(turn), a * sympy.cos(turn))
    rate = sympy.diff(beta, theta).subs(theta, moved) * w
    v_W = (-rate * a * sympy.cos(turn), -rate * a * sympy.sin(turn))      # ω k × (W − O2)
    js = shown(kinematika.solve(GENEVA, move={"j1": 10}), "W@wheel")
    got_W = js["points"]["W@wheel"]["position"]
    omega, v = (x["value"] for x in js["answers"])
    got = [formula(g) for g in [*got_W, omega, *v]]
    for values in ({a: 1.3, theta: 0.5, w: 2.0}, {a: 0.7, theta: -0.3, w: -1.1}):
        for g, e in zip(got, [*W, rate, *v_W]):
            assert float(g.subs(values)) == pytest.approx(float(e.subs(values)), abs=1e-12)


def test_a_point_of_the_slider_written_by_numbers_moves_with_it():
    """An offset slider-crank (r = 3, l = 11, e = −2) at a general crank angle θ, moved 30°:
    the slider translates, so D moves by C's travel, x_C(θ) = r cos θ + √(l² − (r sin θ − e)²)."""
    tree = slider_crank_tree()
    tree["parameters"] = {"theta": None}
    tree["points"]["D"] = [8, -1]
    tree["bodies"]["slider"] = ["C", "D"]
    tree["ask"] = [{"omega": "rod"}]
    js = shown(kinematika.solve(tree, move={"j1": 30}), "D@slider")

    def x_c(t):
        return 3 * math.cos(t) + math.sqrt(121 - (3 * math.sin(t) + 2) ** 2)

    x, y = (formula(c) for c in js["points"]["D@slider"]["position"])
    for t in (0.3, 1.7, 4.0):
        assert float(x.subs(theta, t)) == pytest.approx(8 + x_c(t + math.pi / 6) - x_c(t), abs=1e-12)
        assert y == -1


def test_a_coupler_point_written_by_numbers_turns_with_the_coupler():
    """The four-bar (2.25, 6.1, 4.35, 5.2) at a general crank angle θ moved 30°: P (drawn at
    (2, 4)) turns with the coupler about A by θ3(θ + 30°) − θ3(θ) (Freudenstein)."""
    tree = four_bar_tree()
    tree["parameters"]["theta"] = None
    tree["points"]["P"] = [2, 4]
    tree["bodies"]["coupler"] = ["A", "B", "P"]
    inst = instantiate(prepare(tree, move={"j1": 30}))
    at = _evaluator(inst.names, inst.points["P"])
    for t in (0.4, 1.1, 2.0):
        t3, _ = freudenstein(2.25, 6.1, 4.35, 5.2, t)
        t3m, _ = freudenstein(2.25, 6.1, 4.35, 5.2, t + math.pi / 6)
        A0, A1 = (2.25 * math.cos(t), 2.25 * math.sin(t)), (2.25 * math.cos(t + math.pi / 6), 2.25 * math.sin(t + math.pi / 6))
        d, turn = (2 - A0[0], 4 - A0[1]), t3m - t3
        expected = (A1[0] + math.cos(turn) * d[0] - math.sin(turn) * d[1],
                    A1[1] + math.sin(turn) * d[0] + math.cos(turn) * d[1])
        got = at(t)
        assert got == pytest.approx(expected, abs=1e-9)


def _evaluator(names, exprs):
    """Coordinates in named quantities (x_P …, each defined by the earlier ones) as a function
    of θ, at 30 digits (each formula turned into an mpmath function once: what
    `evalf(subs=...)` gives, in less time)."""
    theta_ = sympy.Symbol("theta", positive=True)
    symbols = [theta_]
    steps = []
    for symbol, definition in names.items():
        steps.append(sympy.lambdify(list(symbols), definition, "mpmath"))
        symbols.append(symbol)
    finals = [sympy.lambdify(list(symbols), e, "mpmath") for e in exprs]

    def at(t):
        with mpmath.workdps(30):
            values = [mpmath.mpf(t)]
            for step in steps:
                values.append(mpmath.re(step(*values)))
            return [float(mpmath.re(f(*values))) for f in finals]
    return at


def test_a_wheel_rolling_on_a_line_says_why_it_cannot_move_exactly():
    tree = {"parameters": {"r": None},
            "points": {"O": [0, 0], "C": [0, "r"], "Q": ["r", "r"]},
            "bodies": {"ground": {"points": ["O"], "line": {"through": "O", "direction": [1, 0]}},
                       "slider": ["C"], "wheel": {"points": ["C", "Q"], "circle": {"center": "C", "radius": "r"}}},
            "joints": [{"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]},
                       {"type": "revolute", "bodies": ["slider", "wheel"], "at": "C"},
                       {"type": "rolling", "bodies": ["ground", "wheel"]}],
            "drivers": [{"velocity": "C@slider", "value": [1, 0]}]}
    with pytest.raises(KinematikaError) as info:
        prepare(tree, move={"j1": 0.5})
    assert info.value.where == "move.j1"
    assert "'Q'" in info.value.message and "rolls on a line" in info.value.message


def test_a_planet_given_by_numbers_with_its_centre_turns_with_its_arm():
    """The same planet with its circle's centre written as coordinates: the shape is carried
    by the planet's turn (its centre stays R + r from O, on the arm)."""
    tree = copy.deepcopy(PLANET)
    tree["bodies"]["planet"]["circle"]["center"] = ["R + r", 0]
    model = prepare(tree, move={"j1": 90})
    circle = instantiate(model).shapes["planet"][0]
    assert sympy.simplify(circle.center[0]) == 0 and sympy.simplify(circle.center[1] - (R + r)) == 0


def test_the_explanation_says_how_each_body_was_carried():
    """The position step of the moved planet: the arm turned 90° about O, the planet by
    90°·(R + r)/r about C, C's polar angle advanced to 90°, Q carried with the planet."""
    from kinematika.explain import explain

    text = explain(prepare(PLANET, move={"j1": 90}), lang="en", fmt="md")
    position = text[text.index("## Position"):text.index("## Velocities")].lower()     # a sentence's first name capitalised
    assert "*arm* has turned by 90° about o." in position
    assert "*planet* has turned by 90·(r + r)/r° about c." in position
    assert "c is at distance r + r from o, at 90° from the x axis" in position
    assert "q is carried with the *planet*" in position
