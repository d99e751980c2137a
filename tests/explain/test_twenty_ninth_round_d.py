"""Issue 30, twenty-ninth round (d): C5-E.4's geometry and chassis, cables round their pulleys,
R's three meanings — as the sixth reading's teachers read the pages
(/work/audit_s_{en,es,ca,eu}/report.md).

1. C5-E.4's lower wheels' centres were 2R apart with radius R: the two lower wheels touched
   at (0, R) and would rub (eu: grade C). Now 2√2·R apart, the upper wheel's centre U 2R from
   each, √2·R above theirs; the answers (v_P = 0, a_P = v²/R down, the rates) derived again.
2. The chassis is the inverted T the Data say (the axle bar A1–A2, a stem from its middle B up
   to U), never a Λ; a circles' intersection one above the other is "the upper one"; the
   figures' v̇ is chosen so that every polygon term shows (no "too short to be seen").
3. A pulley in a cable draws the arc wrapped round it, tangent to both strands.
4. A lower pair's letter is left out where the page writes it as a symbol ("hinge" beside a
   radius R); C5-E.5's wheel of radius R is the rear wheel.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import sympy

import kinematika
from kinematika.draw.build import build_scene
from kinematika.draw.options import DrawOptions

from .helpers import LANGS, explained, figures, over, plain_page, rendered

E4, E5, E3 = "seed_c5_e4_upper_wheel", "seed_c5_e5_unequal_wheels", "seed_c5_e3_wheels_with_rod"
EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _symbols(sol) -> dict:
    """The model's parameters as the solver's own sympy symbols (their assumptions kept)."""
    found = {}
    for c in sol.inst.points.values():
        for e in c:
            found.update({s.name: s for s in sympy.sympify(e).free_symbols})
    found.update({s.name: s for s in sympy.sympify(sol.omega("upper")).free_symbols})
    found.update({s.name: s for s in sympy.sympify(sol.alpha("upper")).free_symbols})
    return found


def _zero(e) -> bool:
    """Zero exactly (a formula), or to rounding (numbers)."""
    e = sympy.sympify(e)
    if not e.free_symbols:
        return abs(float(e)) <= 1e-12
    return sympy.simplify(e) == 0


# ---- 1. C5-E.4: a geometry the notes' figure allows, the answers derived again --------------------
def test_d1_the_lower_wheels_do_not_touch_and_the_upper_wheel_touches_both() -> None:
    """A1 = (−√2·R, R), A2 = (√2·R, R): |A1A2| = 2√2·R > 2R, so the lower wheels (radius R) are
    apart by (2√2 − 2)·R; U is 2R from each (it touches both): U = (0, R + √(4R² − 2R²)) =
    (0, (1 + √2)·R), and P, its top, (0, (2 + √2)·R)."""
    for name in (E4, "vehicle_upper_wheel"):
        sol = kinematika.solve(EXAMPLES / f"{name}.yaml")
        pts = {k: tuple(sympy.sympify(e) for e in v) for k, v in sol.inst.points.items()}
        R = _symbols(sol).get("R") or sympy.Float(0.25)            # the numbers' file: R = 0.25
        a1, a2, u, p = pts["A1"], pts["A2"], pts["U"], pts["P"]

        def dist(a, b):
            return sympy.sqrt((a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2)

        gap = dist(a1, a2) - 2 * R
        assert _zero(gap - (2 * sympy.sqrt(2) - 2) * R), name
        assert float(gap / R) > 0.8, name                          # 2√2 − 2 ≈ 0.83: apart
        assert _zero(dist(u, a1) - 2 * R) and _zero(dist(u, a2) - 2 * R), name
        assert _zero(u[0]) and _zero(u[1] - (1 + sympy.sqrt(2)) * R), name
        assert _zero(p[0]) and _zero(p[1] - (2 + sympy.sqrt(2)) * R), name


def test_d1_the_answers_derived_again() -> None:
    """By hand, for the new geometry. The chassis translates at (−v, 0): each lower wheel turns
    about its contact, R below its centre: (−v, 0) = ω k × (0, R) = (−ωR, 0), ω = v/R (ccw).
    Seen from the chassis (a translation) the upper wheel and a lower wheel meet at the middle N
    of A1U, N − A1 = R·e, N − U = −R·e: ω₁·R = −ω₃·R, ω₃ = −v/R, whatever the angle of A1U. So
    v_P = v_U + ω₃ k × (0, R) = (−v, 0) + (v, 0) = 0 (P the instant centre) and
    a_P = a_U + α₃ k × UP − ω₃²·UP = (−v̇, 0) + (v̇, 0) + (0, −v²/R) = (0, −v²/R)."""
    sol, _ = explained(E4)
    s = _symbols(sol)
    R, v, vd = s["R"], s["v"], s["vd"]
    assert _zero(sol.omega("wheel1") - v / R) and _zero(sol.omega("wheel2") - v / R)
    assert _zero(sol.omega("upper") + v / R) and _zero(sol.alpha("upper") + vd / R)
    vp, ap = sol.velocity("P"), sol.acceleration("P")
    assert _zero(vp[0]) and _zero(vp[1])
    assert _zero(ap[0]) and _zero(ap[1] + v ** 2 / R)


DATA = {"en": "are 2√2 R apart (so they do not touch each other)",
        "es": "están a 2√2 R uno de otro (así que no se tocan entre sí)",
        "ca": "són a 2√2 R l’un de l’altre (de manera que no es toquen)",
        "eu": "elkarrengandik 2√2 R-ra daude (beraz, ez dute elkar ukitzen)"}


@over(lang=LANGS)
def test_d1_the_data_say_the_geometry(lang: str) -> None:
    """The Data give the new distances (2√2 R, √2 R) and never the old √3 R."""
    page = plain_page(E4, lang).replace("*", "")
    assert DATA[lang] in page and "√2 R" in page and "√3" not in page


# ---- 2. the inverted T; the upper one; every polygon term drawn ------------------------------------
def test_d2_the_chassis_is_drawn_as_an_inverted_t() -> None:
    """The chassis's bars: A1–B and B–A2 (the axle bar, level, through B = (0, R)) and B–U (the
    stem, vertical): three bars, none from U to A1 or A2 (the Λ drawn before)."""
    sol = kinematika.solve(EXAMPLES / f"{E4}.yaml")
    scene = build_scene(sol.inst, sol, DrawOptions())
    at = {k: np.asarray(scene.point(k)) for k in ("A1", "A2", "B", "U")}
    bars = [tuple(np.asarray(b, dtype=float)) for b in scene.bodies["chassis"].skeleton]
    assert len(bars) == 3

    def joins(bar, p, q):
        a, b = bar
        return (np.allclose(a, at[p]) and np.allclose(b, at[q])) or (np.allclose(a, at[q]) and np.allclose(b, at[p]))
    for p, q in (("A1", "B"), ("B", "A2"), ("B", "U")):
        assert sum(joins(bar, p, q) for bar in bars) == 1, (p, q)
    assert not any(joins(bar, "U", e) for bar in bars for e in ("A1", "A2"))
    assert math.isclose(at["B"][1], at["A1"][1]) and math.isclose(at["B"][0], at["U"][0], abs_tol=1e-12)


UPPER = {"en": "it is the upper one: U = (0, R·(1 + √2))", "es": "es el de arriba: U = (0; R·(1 + √2))",
         "ca": "és el de dalt: U = (0; R·(1 + √2))", "eu": "goikoa da: U = (0; R·(1 + √2))"}


@over(lang=LANGS)
def test_d2_the_circles_intersection_is_the_upper_one(lang: str) -> None:
    """A1 and A2 at one height: the two intersections lie one above the other, and U is the
    upper one, said so (es: "el de arriba"), not as a look from A1 towards A2."""
    page = plain_page(E4, lang)
    assert UPPER[lang] in page
    assert not re.search(r"looking from A1|as one looks from A1|mirando desde A1|mirant d’A1|A1 puntutik A2", page)


SHORT = {"en": "too short", "es": "demasiado cort", "ca": "massa curt", "eu": "laburregi"}


@over(name=(E4, E5), lang=LANGS)
def test_d2_every_polygon_term_is_seen(name: str, lang: str) -> None:
    """The figures' v̇ is chosen near v²/R: no caption leaves a term out as too short (C5-E.4:
    v̇ = 0.5 beside v²/R = 16; C5-E.5 likewise)."""
    assert SHORT[lang] not in rendered(name, lang, "md")


# ---- 3. the cable wrapped round its pulleys ----------------------------------------------------------
def _wraps(name: str, lang: str) -> list:
    return [m for _, marks, _, _ in figures(name, lang) for m in marks if (m.gid or "").startswith("wrap:")]


@over(name=("seed_c5_1_1_pulley_on_cable", "seed_c5_1_5_pulley_block"), lang=("en", "ca"))
def test_d3_each_pulley_in_a_cable_draws_its_wrapped_arc(name: str, lang: str) -> None:
    """On the mechanism figure each pulley (one in C5-1.1, four in C5-1.5) draws one arc on its
    circle, from one strand's tangent point to the other's, tangent there to both strands."""
    sol, _ = explained(name)
    scene = build_scene(sol.inst, sol, DrawOptions())
    pulleys = [b for b in scene.bodies.values() if any(s.kind == "circle" for s in b.shapes)]
    first = _wraps(name, lang)
    assert {m.gid for m in first} == {f"wrap:{b.name}" for b in pulleys}
    for body in pulleys:
        circle = next(s for s in body.shapes if s.kind == "circle")
        c, r = circle.centre(), circle.radius
        arc = next(np.asarray(m.points) for m in first if m.gid == f"wrap:{body.name}")
        assert np.allclose(np.linalg.norm(arc - c, axis=1), r, rtol=1e-9)
        ends = [np.asarray(j.contact) for j in scene.joints if j.contact is not None and body.name in (j.a, j.b)
                and j.kind.name == "rolling"]
        for end in (arc[0], arc[-1]):
            assert any(np.allclose(end, e, atol=1e-9 * r) for e in ends), (body.name, end)
        for end in (arc[0], arc[-1]):
            # the strand through this end: its direction is perpendicular to the radius there
            j = next(j for j in scene.joints if j.contact is not None and np.allclose(j.contact, end, atol=1e-9 * r)
                     and body.name in (j.a, j.b))
            strand = scene.bodies[j.b if j.a == body.name else j.a]
            _, d = next(s for s in strand.shapes if s.kind == "line").line()
            assert abs(float(np.dot(d, end - c))) <= 1e-9 * r * float(np.linalg.norm(d))


def test_d3_the_wrap_goes_round_the_far_side() -> None:
    """C5-1.1: the pulley hangs in a V of cable tied above it; the strands at 60° to the
    horizontal touch it at J = C + r(−√3/2, −1/2) and K, J's mirror: the cable passes under
    the pulley, so the arc runs through its lowest point (0, −r) and nowhere above J and K."""
    sol, _ = explained("seed_c5_1_1_pulley_on_cable")
    scene = build_scene(sol.inst, sol, DrawOptions())
    c = np.asarray(scene.point("C"))
    r = next(s for s in scene.bodies["pulley"].shapes if s.kind == "circle").radius
    arc = next(np.asarray(m.points) for m in _wraps("seed_c5_1_1_pulley_on_cable", "en") if m.gid == "wrap:pulley")
    assert np.allclose(arc[0], c + r * np.array([-math.sqrt(3) / 2, -0.5]), atol=1e-9 * r) or \
        np.allclose(arc[-1], c + r * np.array([-math.sqrt(3) / 2, -0.5]), atol=1e-9 * r)
    assert min(float(np.linalg.norm(p - (c + np.array([0.0, -r])))) for p in arc) <= 0.05 * r
    assert max(float(p[1] - c[1]) for p in arc) <= -0.5 * r + 1e-9 * r        # nowhere above J, K


def test_d3_a_belt_draws_no_second_wrap() -> None:
    """C5-1.6's belt is one body round two pulleys: its loop is its wrap, no pulley adds one."""
    assert not _wraps("seed_c5_1_6_belt", "en")


# ---- 4. R's three meanings -----------------------------------------------------------------------------
HINGE = {"en": "| hinge |", "es": "| articulación |", "ca": "| articulació |", "eu": "| giltzadura |"}
HINGE_BETWEEN = {"en": "hinge between", "es": "articulación entre", "ca": "articulació entre", "eu": "giltzadura, "}
REAR = {"en": "rear wheel", "es": "rueda trasera", "ca": "roda del darrere", "eu": "atzeko gurpil"}
OLD = {"en": r"\bwheel R\b", "es": r"\brueda R\b", "ca": r"\broda R\b", "eu": r"\bR gurpil"}


@over(name=(E5, E3, E4), lang=LANGS)
def test_d4_a_hinge_beside_a_radius_r_is_said_by_its_word(name: str, lang: str) -> None:
    """Where R is a radius, a revolute pair is the word alone: "hinge" (articulación,
    articulació, giltzadura), never "(R)"."""
    page = plain_page(name, lang)
    assert "(R)" not in page
    assert HINGE[lang] in page
    if name == E3:      # its point A is the hinge between the left wheel and the rod
        assert HINGE_BETWEEN[lang] in page


@over(lang=LANGS)
def test_d4_the_wheel_of_radius_r_is_the_rear_wheel(lang: str) -> None:
    """C5-E.5: *rear wheel* (rueda trasera, roda del darrere, atzeko gurpila), never "wheel R"."""
    page = plain_page(E5, lang).replace("*", "")
    assert REAR[lang] in page.lower() and not re.search(OLD[lang], page)


def test_d4_a_letter_the_page_does_not_use_keeps_its_pair() -> None:
    """The four-bar (no parameter or point named R) keeps "revolute (R)": the letter tells the
    pair where it means nothing else."""
    from kinematika.explain import build, render

    page = render(build(kinematika.solve(EXAMPLES / "four_bar.yaml")), "en", "md", drawings=False)
    assert "revolute (R)" in page
