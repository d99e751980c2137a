"""A disc rolling without slipping on a plane: a free coin on a tilting board, the coin
rolling in a circle, and a car's front wheel that steers while it rolls.

The coin's expected motion is derived with sympy.physics.vector, not from the solver's
contact formulas: the board turns by θ about the x axis; the coin's heading ψ (about the
board's normal), lean β and spin φ are Euler angles relative to the board, so its axis is
T.x and its lowest rim point is J = C − R T.z. Rolling says the coin's point at J moves with
the board's point there, so v_C = ω_board × J + R ω_coin × T.z; the centre's coordinates are
dynamic symbols whose derivatives are replaced by that, and a_C, the geometric contact
point J' = v_C − R (T.z)' and J'' follow by differentiating in the fixed frame.
"""
from __future__ import annotations

import functools
import math

import numpy as np
import sympy as sp
from hypothesis import given
from hypothesis import strategies as st
from sympy.physics.mechanics import msubs
from sympy.physics.vector import Point, ReferenceFrame

from kinematika import solve
from kinematika.api import answers

from .derive import EXAMPLES, carried, assert_close, coordinates, fixed_point, t

R_COIN = 0.05


@functools.cache
def _coin_on_board():
    """The coin's vectors as numeric functions of the state, derived once in the process that
    runs the tests (not while the suite is collected: the derivation takes seconds)."""
    th, psi, beta, phi, cx, cy, cz = coordinates("th psi beta phi cx cy cz")
    N = ReferenceFrame("N")
    board = N.orientnew("Bd", "Axis", (th, N.x))
    H = board.orientnew("H", "Axis", (psi, board.z))
    T = H.orientnew("T", "Axis", (beta, H.y))
    D = T.orientnew("D", "Axis", (phi, T.x))
    R = sp.Rational(1, 20)
    centre = cx * N.x + cy * N.y + cz * N.z
    contact = centre - R * T.z
    w_board, w_coin = board.ang_vel_in(N), D.ang_vel_in(N)
    v_c = w_board.cross(contact) + R * w_coin.cross(T.z)
    follow = {c.diff(t): v_c.dot(e) for c, e in ((cx, N.x), (cy, N.y), (cz, N.z))}
    a_c = msubs(v_c.dt(N), follow)
    tz1 = T.z.dt(N)
    jdot = v_c - R * tz1
    jddot = a_c - R * tz1.dt(N)
    # the coin's and the board's material points at J
    C = Point("C")
    C.set_vel(N, v_c)
    C.set_acc(N, a_c)
    Jc = carried(C, "Jc", -R * T.z, N, D)
    Jb = carried(fixed_point("O", N), "Jb", contact, N, board)
    vectors = {"v_C": v_c, "a_C": a_c, "omega": w_coin, "alpha": D.ang_acc_in(N), "jdot": jdot,
               "jddot": jddot, "v_Jc": Jc.vel(N), "a_Jc": Jc.acc(N), "v_Jb": Jb.vel(N),
               "a_Jb": Jb.acc(N), "axis": T.x, "down": -T.z}
    qs = (th, psi, beta, phi)
    args = [cx, cy, cz] + [x for q in qs for x in (q, q.diff(t), q.diff(t, 2))]
    plain = [sp.Symbol(f"x{i}") for i in range(len(args))]
    to_plain = dict(zip(reversed(args), reversed(plain)))   # derivatives before coordinates
    funcs = {k: sp.lambdify(plain, [msubs(c, to_plain) for c in v.to_matrix(N)], "math")
             for k, v in vectors.items()}
    return funcs


angle = st.floats(-math.pi, math.pi, allow_nan=False)
lean = st.floats(-1.2, 1.2, allow_nan=False)
rates = st.floats(-3, 3, allow_nan=False)


def coin_tree(centre, axis, omega, alpha, board_rate, board_accel, on_ground=False):
    plane = {"plane": {"through": "O", "normal": [0, 0, 1]}}
    bodies = {"ground": {"points": ["O"], **(plane if on_ground else {})},
              "coin": {"points": ["C"], "disc": {"center": "C", "radius": R_COIN, "axis": list(axis)}}}
    joints = [{"id": "roll", "type": "rolling", "bodies": ["ground" if on_ground else "board", "coin"]}]
    drivers = [{"omega": "coin", "value": list(omega), "alpha": list(alpha)}]
    if not on_ground:
        bodies["board"] = {"points": ["O"], **plane}
        joints.append({"id": "hinge", "type": "revolute", "bodies": ["ground", "board"], "at": "O",
                       "axis": [1, 0, 0]})
        drivers.append({"joint": "hinge", "rate": board_rate, "accel": board_accel})
    return {"dimension": 3, "points": {"O": [0, 0, 0], "C": list(centre)}, "bodies": bodies,
            "joints": joints, "drivers": drivers, "ask": [{"contact": "roll"}]}


@given(psi=angle, beta=lean, x=st.floats(-1, 1), y=st.floats(-1, 1),
       rates=st.lists(rates, min_size=8, max_size=8), fixed=st.booleans(), below=st.booleans())
def test_coin_rolling_on_a_tilting_board(psi, beta, x, y, rates, fixed, below):
    """Any heading, lean and rates (nutation included), on a board that tilts or on the ground.

    With `below`, the whole scene is turned half a turn about x (a proper rotation, so every
    vector, angular ones included, turns alike): the coin then hangs under the plane, whose
    normal is still written +z, and touches it with its highest point.
    """
    th1, th2, psi1, psi2, beta1, beta2, phi1, phi2 = rates
    if fixed:
        th1 = th2 = 0.0
    turn = np.diag([1.0, -1.0, -1.0]) if below else np.eye(3)
    centre = (x, y, R_COIN * math.cos(beta))
    args = [*centre, 0, th1, th2, psi, psi1, psi2, beta, beta1, beta2, 0, phi1, phi2]
    e = {k: turn @ np.array(f(*args)) for k, f in _coin_on_board().items()}
    centre = turn @ np.array(centre)
    sol = solve(coin_tree(centre, e["axis"], e["omega"], e["alpha"], th1, th2, on_ground=fixed))
    assert_close(sol.velocity("C"), e["v_C"], 1e-8)
    assert_close(sol.acceleration("C"), e["a_C"], 1e-8)
    assert_close(sol.alpha("coin"), e["alpha"], 1e-8)
    contact = answers(sol)[0][1]
    assert_close(contact["point"], centre + R_COIN * e["down"], 1e-9)
    assert_close(contact["body_b"]["velocity"], e["v_Jc"], 1e-8)
    assert_close(contact["body_b"]["acceleration"], e["a_Jc"], 1e-8)
    assert_close(contact["body_a"]["velocity"], e["v_Jb"], 1e-8)
    assert_close(contact["body_a"]["acceleration"], e["a_Jb"], 1e-8)
    assert_close(contact["geometric"]["velocity"], e["jdot"], 1e-8)
    assert_close(contact["geometric"]["acceleration"], e["jddot"], 1e-8)
    # no slip: the coin's contact point has zero velocity relative to the plane's body
    rel = "board" if not fixed else None
    assert_close(sol.motion.point_velocity("coin", contact["point"], rel), (0, 0, 0), 1e-8)


def test_coin_rolling_in_a_circle_finds_its_spin():
    """The example: heading arm turning at Ω = 3 (Ω' = 0.5), coin leaning by 20°, contact on a
    circle of radius ρ = 0.15. By hand: v_J = 0 along the track gives the spin s = −Ωρ/R."""
    R, rho, beta, W, W1 = 0.02, 0.15, math.radians(20), 3.0, 0.5
    s, s1 = -W * rho / R, -W1 * rho / R
    a = np.array([math.cos(beta), 0, math.sin(beta)])
    k = np.array([0.0, 0, 1])
    J = np.array([rho, 0, 0])
    C = J + R * np.array([-math.sin(beta), 0, math.cos(beta)])
    sol = solve(EXAMPLES / "coin_rolling.yaml")
    assert_close(sol.omega("coin", "heading"), s * a)
    assert_close(sol.omega("coin"), W * k + s * a)
    assert_close(sol.alpha("coin"), W1 * k + s1 * a + np.cross(W * k, s * a))
    assert_close(sol.velocity("C"), np.cross(W * k, C))
    assert_close(sol.acceleration("C"), np.cross(W1 * k, C) - W ** 2 * C * [1, 1, 0])
    assert_close(sol.velocity("J@coin"), (0, 0, 0))
    contact = answers(sol)[7][1]
    assert_close(contact["geometric"]["velocity"], np.cross(W * k, J))
    assert_close(contact["geometric"]["acceleration"], np.cross(W1 * k, J) - W ** 2 * J)
    assert_close(contact["body_a"]["acceleration"], (0, 0, 0))
    # the coin's material point at J: zero velocity, acceleration a_C + α×CJ + ω×(ω×CJ)
    w, al, cj = W * k + s * a, W1 * k + s1 * a + np.cross(W * k, s * a), J - C
    assert_close(contact["body_b"]["acceleration"],
          np.cross(W1 * k, C) - W ** 2 * C * [1, 1, 0] + np.cross(al, cj) + np.cross(w, np.cross(w, cj)))


def test_coin_on_a_ceiling_touches_with_its_top_point():
    """A disc below a plane (a wheel pressed against a ceiling) touches with its highest point,
    whichever way the plane's normal is written."""
    for normal in ([0, 0, 1], [0, 0, -1]):
        tree = {"dimension": 3, "points": {"O": [0, 0, 1], "C": [0, 0, 0.8]},
                "bodies": {"ground": {"points": ["O"], "plane": {"through": "O", "normal": normal}},
                           "wheel": {"points": ["C"], "disc": {"center": "C", "radius": 0.2,
                                                                "axis": [0, 1, 0]}}},
                "joints": [{"id": "roll", "type": "rolling", "bodies": ["ground", "wheel"]}],
                "drivers": [{"omega": "wheel", "value": [0, 2, 0]}],
                "ask": [{"contact": "roll"}]}
        sol = solve(tree)
        assert_close(answers(sol)[0][1]["point"], (0, 0, 1))
        # turning about +y under a ceiling, it rolls towards -x: v_C = -(w R) x
        assert_close(sol.velocity("C"), (-0.4, 0, 0))
        assert_close(sol.acceleration("C"), (0, 0, 0))


def test_the_rolling_coin_from_python():
    """The same coin built with the Python API gives the file's answers."""
    from kinematika import Mechanism

    m = Mechanism("Coin", parameters={"R": 0.02, "rho": 0.15, "beta": "deg(20)"})
    m.points(O=(0, 0, 0), J=("rho", 0, 0), C=("rho - R*sin(beta)", 0, "R*cos(beta)"))
    m.body("ground", "O", plane=("O", (0, 0, 1)))
    m.body("heading", "O", "C")
    m.body("coin", "C", "J", disc=("C", "R", ("cos(beta)", 0, "sin(beta)")))
    turn = m.revolute("ground", "heading", at="O", axis=(0, 0, 1))
    m.revolute("heading", "coin", at="C", axis=("cos(beta)", 0, "sin(beta)"))
    m.rolling("ground", "coin")
    m.drive_joint(turn, 3, 0.5)
    built, read = m.solve(), solve(EXAMPLES / "coin_rolling.yaml")
    for body in ("heading", "coin"):
        assert_close(built.omega(body), read.omega(body))
        assert_close(built.alpha(body), read.alpha(body))
    assert_close(built.acceleration("J@coin"), read.acceleration("J@coin"))


def test_symbolic_lean_gives_plain_formulas_without_absolute_values():
    """A coin leaning by a symbolic angle l spins about the x axis through its contact K.
    K is at rest, so v_C = ω × KC and a_C = ω × v_C (α = 0): with ω = (w, 0, 0) and
    KC = (0, −R sin l, R cos l), a_C = (0, R w² sin l, −R w² cos l), and the coin's
    contact point, its velocity and acceleration are all zero. √(1 − sin² l) must come out
    as cos l, the drawn branch, not |cos l|."""
    l, R, w = sp.symbols("l R w", positive=True)
    tree = {
        "dimension": 3, "parameters": {"l": None, "R": None, "w": None},
        "points": {"K": [0, 0, 0], "C": [0, "-R*sin(l)", "R*cos(l)"]},
        "bodies": {"ground": {"points": ["K"], "plane": {"through": "K", "normal": [0, 0, 1]}},
                   "coin": {"points": ["C", "K"],
                            "disc": {"center": "C", "radius": "R", "axis": [0, "cos(l)", "sin(l)"]}}},
        "joints": [{"id": "roll", "type": "rolling", "bodies": ["ground", "coin"], "at": "K"}],
        "drivers": [{"omega": "coin", "value": ["w", 0, 0]}],
        "ask": [{"acceleration": "C"}, {"contact": "roll"}],
    }
    from kinematika.report.json_answer import solution_json

    data = solution_json(solve(tree))
    (_, a_c), (_, contact) = [(a["ask"], a["value"]) for a in data["answers"]]
    expected = (0, R * w ** 2 * sp.sin(l), -R * w ** 2 * sp.cos(l))
    names = {"l": l, "R": R, "w": w}
    for got, want in zip(a_c, expected):
        assert "Abs" not in got
        assert sp.simplify(sp.sympify(got, locals=names) - want) == 0
    for part in ("body_b", "geometric"):
        assert contact[part] == {"velocity": ["0"] * 3, "acceleration": ["0"] * 3}
