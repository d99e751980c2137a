"""Construction-built models solved with --symbolic: the formulas the JSON answer shows,
evaluated at two sets of values of their symbols, equal hand derivations that never call
kinematika — each mechanism's output written by loop closure as a function of the crank
angle and differentiated in time by mpmath at 40 digits (tests/cases/derive.py's
`motion`), d/dt = ω d/dθ and d²/dt² = ω² d²/dθ² + α d/dθ. The textbook cases of
tests/cases, solved with every parameter a symbol, equal their hand derivations at the
cases' values. Also: formulas are exact (no floats), and mechanisms whose formulas written
out would be too long (the top of Jansen's leg in its lengths; in a deep run the whole leg
in its 15 lengths, the textbook's Watt six-bar, triad and spherical four-bar) answer with
named coordinates, equal to their hand derivations. A default run checks one model or case
of each kind, at the model's own values; a deep run every model and case, at two sets."""
from __future__ import annotations

import math
from pathlib import Path

import mpmath
import pytest
import sympy as sp

from kinematika.commands import solve_data
from kinematika.errors import KinematikaError
from tests.conftest import DEEP, deep_only, hand_derivations, sampled
from tests.core.models import JANSEN_TOP, jansen

pytestmark = pytest.mark.early      # minutes of work: handed to a worker before the shorter files (tests/conftest.py)

ROOT = Path(__file__).resolve().parents[2]
MODELS = ROOT / "benchmarks" / "models" / "symbolic"
derive = hand_derivations()
meet, polar, motion = derive.meet, derive.polar, derive.motion


def sets(*values: dict) -> list:
    """Parameter sets to check: the model's own values, and the others in a deep run."""
    return list(values if DEEP else values[:1])


def answered(source, *points: str) -> dict:
    """What `kinematika solve MODEL --symbolic --json` (`commands.solve_data`) shows, in
    process, of what these tests read: `symbolic`, the answers, the named quantities of
    `where` and the positions of `points`, each written as the answer writes it, within the
    command's budget of exact work — without its tables of every point's velocity and
    acceleration, seconds of formulas no test here reads."""
    from kinematika.api import prepare, solve
    from kinematika.budget import exact_work
    from kinematika.questions import answer
    from kinematika.report.json_answer import where
    from kinematika.report.values import plain

    model = prepare(source)
    with exact_work(model, True):
        sol = solve(model, True)
        out = {"symbolic": sol.symbolic,
               "answers": [{"value": plain(answer(sol, q), True)} for q in model.questions],
               "points": {ref: {"position": plain(sol.position(ref), True)} for ref in points}}
        named = where(sol)
    return out | ({"where": named} if named else {})


def shown(name: str) -> dict:
    """`kinematika solve MODEL --symbolic --json`'s answers, in process (`answered`)."""
    return answered(MODELS / f"{name}.yaml")


def numbers(value, at: dict):
    """A formula (or nested lists and dicts of them) evaluated at `at` {name: number}."""
    if isinstance(value, list):
        return [numbers(v, at) for v in value]
    if isinstance(value, dict):
        return {k: numbers(v, at) for k, v in value.items()}
    names = {k: sp.Symbol(k, positive=True) for k in at}
    e = sp.sympify(value, locals=names)
    assert not e.atoms(sp.Float), value[:200]                 # exact: no decimals in a formula
    with mpmath.workdps(30):                                  # long formulas cancel: 30 digits
        return float(sp.lambdify(list(names.values()), e, "mpmath")(*[mpmath.mpf(str(v)) for v in at.values()]))


def same(got, exp, rel=1e-8, where="") -> None:
    if isinstance(exp, (list, tuple)):
        assert len(got) == len(exp), where
        for i, (g, e) in enumerate(zip(got, exp)):
            same(g, e, rel, f"{where}[{i}]")
        return
    scale = max(abs(float(exp)), 1e-6)
    assert abs(got - float(exp)) <= rel * scale, (where, got, float(exp))


def answers(name: str, at: dict) -> list:
    return [numbers(a["value"], at) for a in shown(name)["answers"]]


# each model by hand --------------------------------------------------------------------------
def slider_crank(r, l, e, theta, w, al):
    """B on y = e, ahead of A: x_B = r cos θ + √(l² − (e − r sin θ)²); the rod's angle
    φ = atan2(e − r sin θ, x_B − r cos θ); G halfway along A-B."""
    def pos(t):
        ax, ay = r * mpmath.cos(t), r * mpmath.sin(t)
        xb = ax + mpmath.sqrt(l ** 2 - (e - ay) ** 2)
        return [xb, mpmath.atan2(e - ay, xb - ax), (ax + xb) / 2, (ay + e) / 2]

    _, v, a = motion(pos, theta, w, al)
    return v, a


@pytest.mark.parametrize("at", sets(dict(r=0.05, l=0.2, e=0.02, theta=1.0471975511965976, w=150, al=10),
                                     dict(r=0.7, l=2.3, e=0.4, theta=4.1, w=-3, al=2.5)))
def test_offset_slider_crank(at):
    v, a = slider_crank(**at)
    same(answers("slider_crank_offset", at),
         [[v[0], 0], [a[0], 0], v[1], a[1], [v[2], v[3]], [a[2], a[3]]])


def test_in_line_slider_crank():
    at = dict(r=0.3, l=1.1, theta=2.2, w=7)
    v, a = slider_crank(e=0, al=0, **at)
    same(answers("slider_crank_general", at), [[v[0], 0], [a[0], 0], v[1], a[1]])


@deep_only                  # the inverted slider-crank's case tb_inverted_slider_crank is in a default run
@pytest.mark.parametrize("at", sets(dict(r=0.1, d=0.3, theta=1.0471975511965976, w=20, al=5),
                                     dict(r=1.3, d=0.8, theta=2.7, w=-1.5, al=0.3)))
def test_inverted_slider_crank(at):
    """The rod's angle φ = atan2(A − O4) and the block's distance ρ = |A − O4|: seen from
    the rod the block slides ρ' along it; the rod's point at A moves with φ', φ''."""
    r, d = at["r"], at["d"]

    def pos(t):
        x, y = r * mpmath.cos(t) - d, r * mpmath.sin(t)
        return [mpmath.atan2(y, x), mpmath.sqrt(x * x + y * y)]

    (phi, rho), (w4, rho_d), (al4, _) = motion(pos, at["theta"], at["w"], at["al"])
    u = [math.cos(phi), math.sin(phi)]
    got = answers("inverted_slider_crank_general", at)
    same(got[:3], [w4, al4, [rho_d * u[0], rho_d * u[1]]])
    # A of the rod: α k × ρu − ω² ρu
    same(got[4], [-al4 * rho * u[1] - w4 ** 2 * rho * u[0], al4 * rho * u[0] - w4 ** 2 * rho * u[1]])


@deep_only         # a quick return's slotted lever: tb_crank_shaper, a rod on a line: the slider-cranks
@pytest.mark.parametrize("at", sets(dict(r=0.2, d=0.1, R=0.15, l=0.45, theta=1.0471975511965976, w=5),
                                     dict(r=1.1, d=0.35, R=0.6, l=2.0, theta=3.9, w=2)))
def test_whitworth(at):
    """φ = atan2(A − O4), O4 = (0, −d); B = O4 − R(cos φ, sin φ); the ram C on y = −d
    ahead of B: x_C = x_B + √(l² − R² sin² φ)."""
    r, d, big_r, l = at["r"], at["d"], at["R"], at["l"]

    def pos(t):
        phi = mpmath.atan2(r * mpmath.sin(t) + d, r * mpmath.cos(t))
        xb = -big_r * mpmath.cos(phi)
        return [xb + mpmath.sqrt(l ** 2 - (big_r * mpmath.sin(phi)) ** 2), phi]

    _, (vc, w4), (ac, al4) = motion(pos, at["theta"], at["w"])
    same(answers("whitworth", at), [[vc, 0], [ac, 0], w4, al4])


@pytest.mark.parametrize("at", sets(dict(theta=1.0471975511965976, w=10), dict(theta=1.9, w=-4)))
def test_watt_six_bar_at_a_general_angle(at):
    """Loop 1 (O2, O4 = (4, 0); 1, 4, 3) turns the rocker by φ4(t) − φ4(θ), carrying C,
    drawn at (5, 0) at the instant; loop 2 closes C-D-O6 (4, 3) with O6 = (8, 0)."""
    o4, o6 = [4, 0], [8, 0]

    def rocker(t):
        b = meet(polar([0, 0], 1, t), 4, o4, 3, 1)
        return mpmath.atan2(b[1], b[0] - 4)

    with mpmath.workdps(40):
        drawn = rocker(mpmath.mpf(at["theta"]))

    def pos(t):
        c = polar(o4, 1, rocker(t) - drawn)
        dd = meet(c, 4, o6, 3, 1)
        return [mpmath.atan2(dd[1], dd[0] - 8)]

    _, (w6,), (al6,) = motion(pos, at["theta"], at["w"])
    same(answers("watt_six_bar_theta", at), [w6, al6])


@deep_only     # 30 s: B of a four-bar is tb_fourbar_crossed_near's, a point off a line tb_crank_shaper's
@pytest.mark.parametrize("at", sets(dict(a=3, b=7.5, c=8, d=9, p=4, delta=0.5235987755982988,
                                          theta=2.0943951023931957, w=10),
                                     dict(a=1.2, b=3.1, c=2.6, d=2.9, p=1.7, delta=-0.4, theta=0.8, w=-2)))
def test_four_bar_coupler_point(at):
    """B where the circles (A, b) and (O4, c) meet, left of A→O4; P = A + p(cos, sin)(φ3 + δ)
    with φ3 the angle of AB (Norton's coupler point)."""
    a, b, c, d, p, delta = (at[k] for k in ["a", "b", "c", "d", "p", "delta"])

    def pos(t):
        pa = polar([0, 0], a, t)
        pb = meet(pa, b, [d, 0], c, 1)
        phi3 = mpmath.atan2(pb[1] - pa[1], pb[0] - pa[0])
        return [pa[0] + p * mpmath.cos(phi3 + delta), pa[1] + p * mpmath.sin(phi3 + delta), phi3]

    _, v, acc = motion(pos, at["theta"], at["w"])
    if at["delta"] < 0:                          # a symbol is positive: δ < 0 is δ + 2π
        at = dict(at, delta=at["delta"] + 2 * math.pi)
    same(answers("four_bar_coupler_point", at), [v[:2], acc[:2], v[2]])


# the textbook cases, every parameter a symbol --------------------------------------------------
HEAVY = {"tb_fourbar_coupler_point", "tb_fourbar_inclined_ground", "tb_watt_six_bar"}   # long
NUMERIC_CASES = [pytest.param(n, marks=pytest.mark.slow) if n in HEAVY else n for n in sorted(derive.NUMERIC)
                 if DEEP or n not in HEAVY]        # formulas: seconds to read back; in a deep run
# a default run: one case of each kind not met by the models above (a six-bar is the Watt
# six-bar's, an offset slider-crank test_offset_slider_crank's, a Whitworth's rod on a line
# the slider-cranks'); every case in a deep run
SHOWN_ABOVE = {"tb_stephenson_six_bar", "tb_whitworth", "tb_slider_crank_offset"}
NUMERIC_CASES = sampled(NUMERIC_CASES, lambda n: n not in SHOWN_ABOVE)


@pytest.mark.parametrize("name", NUMERIC_CASES)
def test_textbook_case_with_every_parameter_a_symbol(name):
    """Solved with --symbolic and evaluated at the case's values, each answer equals the
    case's hand derivation (the cases without parameters are exact numbers with roots)."""
    from kinematika.api import as_model
    from kinematika.algebra.backend import Numeric
    from kinematika.expressions import evaluate

    path = ROOT / "tests" / "cases" / f"{name}.yaml"
    model = as_model(path)
    at: dict = {}
    for p in model.parameters.values():                 # the cases' parameters are plain values
        at[p.name] = evaluate(p.value, dict(at), Numeric())
    out = answered(path)
    assert out["symbolic"] is True
    expected = derive.expected(name)["answers"]
    names = named(out, at)               # exact numbers: long accelerations in named velocities
    for i, (got, exp) in enumerate(zip(out["answers"], expected)):
        _close(written(got["value"], at, names) if names else numbers(got["value"], at), exp,
               f"{name} answers[{i}]")


def _close(got, exp, where):
    """As the cases' rules: numbers within 1e-9 relative (or 1e-9 absolute)."""
    if isinstance(exp, dict):
        for k in exp:
            _close(got[k], exp[k], f"{where}.{k}")
    elif isinstance(exp, (list, tuple)):
        assert len(got) == len(exp), where
        for i, (g, e) in enumerate(zip(got, exp)):
            _close(g, e, f"{where}[{i}]")
    elif isinstance(exp, (int, float)):
        assert abs(got - exp) <= max(1e-9 * max(abs(got), abs(exp)), 1e-9), (where, got, exp)


def named(out: dict, at: dict) -> dict:
    """The values of an answer's named coordinates (`where`, each a formula in the
    parameters and the names before it) at the parameters' values `at`, in order."""
    values: dict = {}
    for name, text in out.get("where", {}).items():
        names = {k: sp.Symbol(k, positive=True) for k in at} | {k: sp.Symbol(k, real=True) for k in values}
        e = sp.sympify(text, locals=names)
        assert e.free_symbols <= set(names.values()), (name, text[:200])   # earlier names only
        with mpmath.workdps(30):
            values[name] = sp.lambdify(list(names.values()), e, "mpmath")(
                *[mpmath.mpf(str(v)) for v in [*at.values(), *values.values()]])
    return values


def written(value, at: dict, names: dict):
    """A formula of an answer with named quantities (or nested lists and dicts of them)
    evaluated at `at` and the names' values."""
    if isinstance(value, list):
        return [written(v, at, names) for v in value]
    if isinstance(value, dict):
        return {k: written(v, at, names) for k, v in value.items()}
    if value is None or isinstance(value, bool):
        return value
    symbols = {k: sp.Symbol(k, positive=True) for k in at} | {k: sp.Symbol(k, real=True) for k in names}
    e = sp.sympify(value, locals=symbols)
    assert not e.atoms(sp.Float), value[:200]
    assert e.free_symbols <= set(symbols.values()), value[:200]
    with mpmath.workdps(30):
        return float(sp.lambdify(list(symbols.values()), e, "mpmath")(
            *[mpmath.mpf(str(v)) for v in at.values()], *names.values()))


JANSEN = dict(a=38, l=7.8, m=15, j=50, b=41.5, d=40.1, e=55.8, k=61.9, c=39.3, f=39.4, g=36.7,
              i=49, h=65.7, theta=math.pi / 2, w=1)


def jansen_points(t, at=JANSEN) -> dict:
    """Jansen's leg by hand at crank angle t: five circle intersections in a chain."""
    pts = {"Z": [0, 0], "O": [at["a"], at["l"]]}
    pts["A"] = polar(pts["O"], at["m"], t)
    pts["B"] = meet(pts["Z"], at["b"], pts["A"], at["j"], 1)
    pts["E"] = meet(pts["Z"], at["d"], pts["B"], at["e"], 1)
    pts["D"] = meet(pts["Z"], at["c"], pts["A"], at["k"], -1)
    pts["F"] = meet(pts["E"], at["f"], pts["D"], at["g"], -1)
    pts["P"] = meet(pts["D"], at["i"], pts["F"], at["h"], 1)
    return pts


def matches_the_leg_by_hand(out: dict, at: dict, point: str, key: str) -> None:
    """Each named coordinate is a short formula, and the answers (velocity, acceleration of
    `point`) and its position, evaluated at `at` through the names, are the leg's motion by
    hand (`jansen_points`, differentiated by mpmath)."""
    assert max(len(text) for text in out["where"].values()) < 2000        # each one short
    place, v, acc = motion(lambda t: jansen_points(t)[point], at["theta"], at["w"])
    names = named(out, at)
    got = [written(a["value"], at, names) for a in out["answers"]]
    same(got, [v, acc], rel=1e-9)
    same(written(out["points"][key]["position"], at, names), place, rel=1e-9)


def jansen_top() -> dict:
    """The top of Jansen's leg (`tests.core.models.jansen`) as given: every length a symbol
    when solved with `symbolic`, E's coordinates written out pass the limit."""
    return jansen(top=True, theta_symbol=False)


TOP = list(JANSEN_TOP)


def test_jansen_legs_top_in_its_lengths_answers_with_named_coordinates():
    """The top of Jansen's leg (`jansen_top`) with every length and the crank angle symbols
    answers in named coordinates (x_B, y_B, x_E, y_E under `where`, each a short formula
    in the lengths and the names before it), and its formulas, evaluated there, are E's
    motion by hand: two circle intersections in a chain, differentiated by mpmath. (The
    whole leg, eight times the work, in a deep run.)"""
    at = {k: JANSEN[k] for k in TOP}
    out = answered(jansen_top(), "E@top")
    assert list(out["where"]) == ["x_B", "y_B", "x_E", "y_E"]
    matches_the_leg_by_hand(out, at, "E", "E@top")


@deep_only
def test_jansen_leg_in_its_15_lengths_answers_with_named_coordinates():
    """Jansen's leg with every length and the crank angle symbols: written out, the foot's
    coordinates alone would have 160 000 operations; the answer names the coordinates of
    the points past the limit (x_B, y_B, ... x_P, y_P: each a short formula in the lengths
    and the names before it, under `where`) and its formulas, evaluated there, are the foot's
    motion by hand: five circle intersections in a chain, differentiated by mpmath."""
    at = JANSEN
    out = answered(ROOT / "examples" / "jansen_leg.yaml", "P@foot")
    assert {"x_F", "y_F", "x_P", "y_P"} <= set(out["where"])
    matches_the_leg_by_hand(out, at, "P", "P@foot")


TEXTBOOK = ROOT / "tests" / "textbook"
NAMED = ["watt_one", "stephenson_triad", "spherical_crank_rocker"]


@pytest.mark.slow
@pytest.mark.parametrize("name", NAMED if DEEP else [])        # seconds each: in a deep run
def test_textbook_mechanism_with_long_formulas(name):
    """Mechanisms whose exact formulas written out are long (a Watt six-bar's second dyad
    on the first loop's roots, a triad, a spherical four-bar given by decimals): solved with
    --symbolic and evaluated at the model's values (the names of `where` first), each
    answer equals the textbook case's hand derivation (tests/textbook)."""
    import json

    from kinematika.algebra.backend import Numeric
    from kinematika.api import as_model
    from kinematika.expressions import evaluate

    path = TEXTBOOK / f"{name}.yaml"
    at: dict = {}
    for p in as_model(path).parameters.values():
        at[p.name] = float(evaluate(p.value, dict(at), Numeric()))
    out = answered(path)
    assert out["symbolic"] is True
    names = named(out, at)
    expected = json.loads((TEXTBOOK / f"{name}.expect.json").read_text())["answers"]
    assert len(out["answers"]) == len(expected)
    for i, (got, exp) in enumerate(zip(out["answers"], expected)):
        _close(written(got["value"], at, names), exp, f"{name} answers[{i}]")


@pytest.mark.slow
@pytest.mark.skipif(not DEEP, reason="seconds: in a deep run (KINEMATIKA_DEEP=1)")
def test_a_model_with_named_quantities_is_drawn_at_its_values():
    """Jansen's leg with only its crank angle a symbol (its decimal lengths make roots of
    roots: named coordinates, and the foot's acceleration in named velocities): the figure
    is drawn at the probe value of θ, its caption naming θ alone, never the names."""
    from kinematika.api import solve
    from kinematika.draw.jupyter import solution_svg

    sol = solve(ROOT / "examples" / "jansen_leg.yaml", set={"theta": None})
    svg = solution_svg(sol)
    assert "symbolic model drawn at generic values theta = " in svg
    assert "x_B" not in svg and "omega_" not in svg


@pytest.mark.slow
@pytest.mark.skipif(not DEEP, reason="seconds: in a deep run (KINEMATIKA_DEEP=1)")
def test_jansen_leg_centres_with_named_coordinates():
    """`centres --symbolic` of Jansen's leg in its 15 lengths: each of the 28 centres,
    evaluated with the names of `where`, is where the two bodies' velocity fields agree by
    hand: each body's ω the rate of the angle of two of its points, v₀ = v_P − ω k × P,
    the centre k × (v₀b − v₀a) / (ωb − ωa)."""
    from kinematika.commands import centres_data

    at = JANSEN
    bodies = {"ground": "ZO", "crank": "OA", "upper": "AB", "top": "ZB", "lower": "AD",
              "rocker": "ZD", "knee": "EF", "foot": "DF"}
    with mpmath.workdps(30):
        t0 = mpmath.mpf(at["theta"])
        pts = jansen_points(t0)
        rate = {}
        for body, (p, q) in bodies.items():
            angle = lambda t, p=p, q=q: mpmath.atan2(*reversed([b - a for a, b in
                                                                 zip(jansen_points(t)[p], jansen_points(t)[q])]))
            w = mpmath.diff(angle, t0) * at["w"]
            vp = [mpmath.diff(lambda t, i=i, p=p: jansen_points(t)[p][i], t0) * at["w"] for i in range(2)]
            rate[body] = (w, [vp[0] + w * pts[p][1], vp[1] - w * pts[p][0]])      # v₀ = v_P − ω k × P
    out = centres_data(ROOT / "examples" / "jansen_leg.yaml", True)
    names = named(out, at)
    assert len(out["centres"]) == 28
    for c in out["centres"]:
        (wa, va), (wb, vb) = rate[c["bodies"][0]], rate[c["bodies"][1]]
        dc = [vb[0] - va[0], vb[1] - va[1]]
        same(written(c["point"], at, names), [float(-dc[1] / (wb - wa)), float(dc[0] / (wb - wa))],
             rel=1e-9, where=str(c["bodies"]))


def test_a_point_too_long_even_in_named_coordinates_is_refused_by_name(monkeypatch):
    """Past `limits.POINT_OPS` even in named coordinates a constructed point is a `limit`
    error naming it, before any time goes into it (no model comes near 2 000: here the
    limit is lowered to 40, which Jansen's leg passes at its first named point, E: its top,
    `jansen_top`, as the whole leg)."""
    from kinematika import limits

    monkeypatch.setattr(limits, "POINT_OPS", 40)
    with pytest.raises(KinematikaError) as err:
        solve_data(jansen_top(), True)
    assert err.value.kind == "limit" and err.value.where == "points.E"
    assert "numbers" in str(err.value) and "--symbolic" in str(err.value)
