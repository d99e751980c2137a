"""On one example of each kind (every example in a deep run): each explanation's equations
hold with the solver's values, what it says is known of each term (⊥, ∥) is true, and what
it reads off them equals the solver's answers."""
from __future__ import annotations

import math

import pytest

from kinematika.algebra.vectors import add, dot
from kinematika.explain.document import CentreNote, Sym

from tests.conftest import KINDS, sampled

from .helpers import ALL, is_close, explained, num

NAMES = sampled(ALL, KINDS)


def _sum(terms):
    out = terms[0].value
    for t in terms[1:]:
        out = add(out, t.value)
    return out


def _scale(sol, level):
    accel = max(sol.accel_scale(), sol.rate_scale() * sol.speed_scale())
    return {"v": sol.speed_scale(), "a": accel, "w": sol.rate_scale(),
            "al": accel / sol.inst.scale}[level] or 1.0


def _direction(sol, ref, eq):
    """The vector a ⊥/∥ annotation refers to: a segment 'AB', a guide, a velocity."""
    ctx_points = dict(sol.inst.points)
    if isinstance(ref, Sym):
        return None
    if isinstance(ref, str):
        names = ref.split("-") if "-" in ref else list(ref)
        if len(names) == 2 and all(n in ctx_points for n in names):
            p, q = ctx_points[names[0]], ctx_points[names[1]]
            return tuple(b - a for a, b in zip(p, q))
        return None
    if getattr(ref, "key", None) == "dir.axis":
        return sol.solver.geos[str(ref.args["joint"])].axis
    if getattr(ref, "key", None) == "dir.guide":
        return sol.solver.geos[str(ref.args["joint"])].along
    return None


@pytest.mark.parametrize("name", NAMES)
def test_every_equation_adds_up(name):
    check_every_equation_adds_up(*explained(name), name)


def check_every_equation_adds_up(sol, doc, name):
    assert doc.equations(), "an explanation without equations"
    for eq in doc.equations():
        scale = _scale(sol, eq.level)
        for side in eq.sides:
            assert is_close(sol, _sum(side), eq.target.value, scale), (name, eq.target.sym, side)


@pytest.mark.parametrize("name", NAMES)
def test_targets_are_the_solvers_motion(name):
    check_targets_are_the_solvers_motion(*explained(name), name)


def check_targets_are_the_solvers_motion(sol, doc, name):
    checked = 0
    for eq in doc.equations():
        if eq.point is None or eq.level not in ("v", "a"):
            continue
        state = sol.state(eq.point.body, eq.relative_to)
        where = eq.position if eq.position is not None else sol.inst.points[eq.point.point]
        motion = sol.motion.velocity if eq.level == "v" else sol.motion.acceleration
        expected = motion(state, where)
        assert is_close(sol, eq.target.value, expected, _scale(sol, eq.level)), (name, eq.target.sym)
        checked += 1
    points_asked = any(q.kind in ("velocity", "acceleration", "curvature", "decompose", "intrinsic")
                       for q in sol.model.questions)
    assert checked or not (points_asked or sol.space.dim == 2)    # only what is asked is worked out


@pytest.mark.parametrize("name", NAMES)
def test_annotations_are_true(name):
    check_annotations_are_true(*explained(name), name)


def check_annotations_are_true(sol, doc, name):
    """⊥ AB terms are perpendicular to AB, ∥ terms parallel, '?' only on solved terms."""
    for eq in doc.equations():
        for t in [x for side in eq.sides for x in side]:
            value = num(sol, t.value)
            size = math.sqrt(sum(c * c for c in value))
            if t.mag.code == "?" or t.dir.code == "?":
                assert t.unknown, (name, t.sym)
            if t.dir.code not in ("perp", "para") or size < 1e-9 * _scale(sol, eq.level):
                continue
            d = _direction(sol, t.dir.ref, eq)
            if d is None:
                continue
            d = num(sol, d)
            cos = dot(value, d) / (size * math.sqrt(dot(d, d)))
            if t.dir.code == "perp":
                assert abs(cos) < 1e-7, (name, t.sym, cos)
            else:
                assert abs(abs(cos) - 1) < 1e-7, (name, t.sym, cos)


@pytest.mark.parametrize("name", NAMES)
def test_rates_read_off_the_terms(name):
    check_rates_read_off_the_terms(*explained(name), name)


def check_rates_read_off_the_terms(sol, doc, name):
    """ω = v_BA / AB and α = aᵗ_BA / AB: the term equals ω k × AB; ρ = v²/|aⁿ|."""
    for d in doc.derived():
        if d.kind in ("omega", "alpha") and d.body:
            solver = sol.omega(d.body) if d.kind == "omega" else sol.alpha(d.body)
            scale = _scale(sol, "w" if d.kind == "omega" else "al")
            assert is_close(sol, d.value.value, solver if sol.space.dim == 2 else tuple(solver), scale)
        if d.source is None:
            continue
        if d.kind == "radius":
            v, an = num(sol, d.arm), num(sol, d.source.value)
            assert math.isclose(num(sol, d.value.value), dot(v, v) / math.sqrt(dot(an, an)), rel_tol=1e-7)
        else:
            made = sol.space.cross(d.value.value, d.arm)
            assert is_close(sol, made, d.source.value, _scale(sol, "v") + _scale(sol, "a")), (name, d.sym)


@pytest.mark.parametrize("name", NAMES)
def test_rolling_contacts_differ_along_the_normal(name):
    check_rolling_contacts_differ_along_the_normal(*explained(name), name)


def check_rolling_contacts_differ_along_the_normal(sol, doc, name):
    """Contact kept: the relative acceleration of the contact points is along the normal."""
    for eq in doc.equations():
        for t in [x for side in eq.sides for x in side if x.kind == "contact"]:
            moving, _, other = t.sym.sub.partition("∈")[2].partition("/")     # J∈b/a, either way round
            joint = next(j for j in sol.model.joints if j.type in ("rolling", "gear")
                         and {j.a, j.b} == {moving, other})
            normal = num(sol, sol.solver.geos[joint.id].contact.normal)
            value = num(sol, t.value)
            cross = value[0] * normal[1] - value[1] * normal[0]
            assert abs(cross) < 1e-7 * _scale(sol, "a")


def test_fan_in_the_notes_three_ways():
    """Seed 000: ω = (0.5, 0.1, 0), α = α1 + α2 + ω1 × ω2 = (0.01, 0.2, −0.05), v_P = (0, 0, 0.09),
    a_P = (0.024, −0.075, −0.117), drag v_C = (0, 0, −0.06), relative 0.15 k, Coriolis 2 ω1 × v_rel."""
    sol, doc = explained("fan_composition")
    rates = {(e.level, e.target.sym.sub): e for e in doc.equations() if e.level in ("w", "al")}
    alpha = rates[("al", "blades")]
    assert is_close(sol, alpha.target.value, (0.01, 0.2, -0.05), 1)
    assert is_close(sol, alpha.sides[0][2].value, (0, 0, -0.05), 1)       # ω1 × ω2
    assert is_close(sol, rates[("w", "blades")].target.value, (0.5, 0.1, 0), 1)
    parts = [e for e in doc.equations() if e.sides[0][0].kind == "drag"]
    v, a = (next(e for e in parts if e.level == lv) for lv in ("v", "a"))
    assert is_close(sol, v.target.value, (0, 0, 0.09), 1)
    assert is_close(sol, v.sides[0][0].value, (0, 0, -0.06), 1) and is_close(sol, v.sides[0][1].value, (0, 0, 0.15), 1)
    assert is_close(sol, a.target.value, (0.024, -0.075, -0.117), 1)
    assert is_close(sol, a.sides[0][2].value, (0.03, 0, 0), 1)              # 2 (0.1 j) × (0.15 k)


def test_four_bar_against_its_loop_equations():
    """ω3, ω4 of the bundled four-bar by Cramer on the loop equation, independent of the engine."""
    sol, doc = explained("four_bar")
    bx = (48 + 8 * math.sqrt(2)) / 17
    by = 4 * bx - 11
    ab, o4b = (bx, by - 1.0), (bx - 4.0, by)
    # ω3 k×AB − ω4 k×O4B = −ω2 k×OA with ω2 = 10, OA = (0, 1): k×OA = (−1, 0)
    c1, c2, rhs = (-ab[1], ab[0]), (o4b[1], -o4b[0]), (10.0, 0.0)
    det = c1[0] * c2[1] - c1[1] * c2[0]
    w3 = (rhs[0] * c2[1] - rhs[1] * c2[0]) / det
    w4 = (c1[0] * rhs[1] - c1[1] * rhs[0]) / det
    read = {d.body: d.value.value for d in doc.derived() if d.kind == "omega" and d.source is not None}
    assert math.isclose(read["coupler"], w3, rel_tol=1e-9) and math.isclose(read["rocker"], w4, rel_tol=1e-9)


def test_symbolic_derivations_of_the_notes():
    """Seed 002: epicyclic planet turns at −5ω with its centre 2r/5 from its axle, the sun at
    7ω; gear change: the ring turns at 4Ω/3; wheel on a semicylinder: ρ of its top is 3r."""
    import sympy

    def rate(name, body):
        sol, doc = explained(name)
        found = [d.value.value for d in doc.derived() if d.kind == "omega" and d.body == body]
        return sol, sympy.simplify(found[0])

    sol, w = rate("seed_c5_1_4_epicyclic", "planet1")
    omega = next(s for s in sol.inst.env.values() if str(s) == "w")
    assert sympy.simplify(w + 5 * omega) == 0
    _, sun = rate("seed_c5_1_4_epicyclic", "sun")
    assert sympy.simplify(sun - 7 * omega) == 0
    _, doc = explained("seed_c5_1_4_epicyclic")
    note = next(c for c in doc.blocks() if isinstance(c, CentreNote) and set(c.pair) == {"ground", "planet1"})
    r = next(s for s in sol.inst.env.values() if str(s) == "r")
    axle = sol.inst.points["A1"]
    gap = sympy.sqrt(sum((sympy.sympify(p) - q) ** 2 for p, q in zip(note.value["point"], axle)))
    assert sympy.simplify(gap - sympy.Rational(2, 5) * r) == 0
    sol, w = rate("seed_c5_e2_gear_change", "ring")
    omega = next(s for s in sol.inst.env.values() if str(s) == "Omega")
    assert sympy.simplify(w - sympy.Rational(4, 3) * omega) == 0


SLIDER_DRIVEN = {
    "name": "Slider-driven crank",
    "points": {"O": [0, 0], "A": [0.1, 0.05], "B": [0.4, 0]},
    "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
    "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
               {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
               {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
               {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
    "drivers": [{"velocity": "B", "value": [-2, 0], "acceleration": [1, 0]}],
}


def test_order_from_the_engines_blocks_still_finds_the_dyad():
    """Driven at the slider, the crank-rod pair is found as an RRR dyad closing at A:
    by hand, v_A ⊥ OA and v_A − v_B ⊥ AB give ω_crank = 30 and ω_rod = −10 rad/s."""
    import kinematika
    from kinematika.explain import build
    from kinematika.explain.order import solution_order

    sol = kinematika.solve(SLIDER_DRIVEN)
    steps = solution_order(sol)
    assert [s.kind for s in steps][-1] == "RRR" and steps[-1].source == "blocks"
    doc = build(sol)
    for check in (check_every_equation_adds_up, check_targets_are_the_solvers_motion,
                  check_annotations_are_true, check_rates_read_off_the_terms):
        check(sol, doc, "slider-driven")
    read = {d.body: d.value.value for d in doc.derived() if d.kind == "omega" and d.source is not None}
    assert math.isclose(read["crank"], 30.0) and math.isclose(read["rod"], -10.0)


def test_curvature_worked_out_as_in_the_notes():
    """C5-1.7: the top P of a wheel (radius r) rolling on a fixed semicylinder (radius 2r)
    has ρ = 3r; derived in the explanation as |v|²/|aⁿ| from its own split of a."""
    import sympy

    sol, doc = explained("seed_c5_1_7_semicylinder")
    r = next(s for s in sol.inst.env.values() if str(s) == "r")
    radius = next(d for d in doc.derived() if d.kind == "radius" and d.sym.sub == "P")
    assert sympy.simplify(radius.value.value - 3 * r) == 0
    v, an = radius.arm, radius.source.value
    assert sympy.simplify(sum(c * c for c in v) / sympy.sqrt(sum(c * c for c in an)) - 3 * r) == 0



@pytest.mark.parametrize("name", NAMES)
def test_no_intersection_of_one_line_with_itself(name):
    """Aronhold–Kennedy is stated only with two lines that meet in one point."""
    sol, doc = explained(name)
    for note in doc.blocks():
        if isinstance(note, CentreNote) and note.how == "kennedy":
            (p1, q1), (p2, q2) = note.lines
            homo = [_homogeneous(sol, c) for c in (p1, q1, p2, q2)]
            l1, l2 = _cross(homo[0], homo[1]), _cross(homo[2], homo[3])
            meet = _cross(l1, l2)
            size = max(abs(x) for x in l1 + l2) ** 2
            assert max(abs(x) for x in meet) > 1e-9 * size, (name, note.pair)


def test_epicyclic_planet_centre_from_proportional_speeds():
    """Notes C5-1.4: the planet's centre is between its centre (2rω) and its contact with
    the ring (3rω the other way), 2r/5 from its centre."""
    sol, doc = explained("seed_c5_1_4_epicyclic")
    note = next(b for b in doc.blocks() if isinstance(b, CentreNote) and set(b.pair) == {"ground", "planet1"})
    assert note.how == "proportional" and note.side == "between"
    speeds = sorted(abs(num(sol, v)[0]) for _, _, v in note.witnesses)
    probe = {str(k): v for k, v in sol.inst.probe.items()}
    r, w = probe["r"], probe["w"]
    assert speeds == pytest.approx([2 * r * w, 3 * r * w])
    assert num(sol, note.value["point"]) == pytest.approx((0, -2 * r - 2 * r / 5))


def _homogeneous(sol, c: dict) -> tuple:
    if c.get("point") is not None:
        x, y = num(sol, tuple(c["point"]))
        return (x, y, 1.0)
    dx, dy = num(sol, tuple(c["direction"]))
    return (dx, dy, 0.0)


def _cross(u: tuple, v: tuple) -> tuple:
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _segment_points(ref: str, points: dict) -> tuple | None:
    names = ref.split("-") if "-" in ref else list(ref)
    return tuple(names) if len(names) == 2 and all(n in points for n in names) else None


@pytest.mark.parametrize("name", NAMES)
def test_no_degenerate_terms(name):
    """No term is written along or across a segment of zero length (ω × AA)."""
    sol, doc = explained(name)
    pts = sol.inst.points
    for eq in doc.equations():
        for t in [eq.target] + [t for side in eq.sides for t in side]:
            if t.dir.code in ("perp", "para") and isinstance(t.dir.ref, str):
                seg = _segment_points(t.dir.ref, pts)
                if seg:
                    d = [a - b for a, b in zip(num(sol, pts[seg[0]]), num(sol, pts[seg[1]]))]
                    assert math.hypot(*d) > 1e-9 * sol.inst.scale, (name, t.sym, t.dir.ref)


def test_quick_return_drag_from_the_rockers_pivot():
    """The drag motion of A is that of the rocker's point at A, worked from O4; the
    relative motion is the slide along the slot."""
    from kinematika.explain.document import Msg

    sol, doc = explained("quick_return")
    drag = [eq for eq in doc.equations() if eq.target.sym.sub_key == "sub.drag"]
    # a drag a step already wrote (v_A∈rocker = v_O4 + …) is referred to, not written again
    said = [b for b in doc.blocks() if isinstance(b, Msg) and b.key in ("composition.drag_seen", "composition.drag_terms")]
    assert len(drag) + len(said) == 2 and all(eq.sides[0][0].sym.sub == "O4" for eq in drag)
    for m in said:
        steps = [eq for eq in doc.equations() if eq.target.sym == m.args.get("seen")]
        assert m.key == "composition.drag_terms" or (steps and all(eq.sides[0][0].sym.sub == "O4" for eq in steps))
    for eq in drag:
        total = eq.sides[0][0].value
        for t in eq.sides[0][1:]:
            total = add(total, t.value)
        assert is_close(sol, total, eq.target.value, 10.0)
