"""Issue 30, twenty-first round (c): the figures' geometry.

- A line that places an instant centre (an Aronhold–Kennedy line through a third body's two
  centres, alone or with a joint's normal) is drawn on to that centre: C5-1.2's line through
  I_OQ, O and K1, "the perpendicular to v_O through O", stopped past K1, short of I_OJ.
- A rod sliding through a sleeve of a moving body has the sleeve drawn at the guiding body's
  point on the rod's line (C5-1.3: at the support's centre S, not at the bar's end E).
"""
from __future__ import annotations

import numpy as np

import kinematika
from kinematika.draw.build import build_scene
from kinematika.draw.geometry import Box
from kinematika.draw.joints import scene_symbols
from kinematika.draw.options import DrawOptions
from kinematika.explain.document import Drawing
from kinematika.questions.centres import all_centres
from .helpers import EXAMPLES, NOTES_SEEDS, SEEDS, explained, over, recorded_pages


def _figures(doc, key):
    return [b for b in doc.blocks() if isinstance(b, Drawing) and b.caption.key == key]


def _cross(u, v) -> float:
    return float(u[0]) * float(v[1]) - float(u[1]) * float(v[0])


def _reaches(scene, p, q, centre, tol) -> bool:
    """Whether a drawn line runs through p and q (the two points that give it) and its
    anchors (what it is drawn over, plus a margin) reach `centre`."""
    for k in scene.kennedy + scene.normals:
        d = np.asarray(k.direction, float) / np.linalg.norm(k.direction)
        o = np.asarray(k.through, float)
        if all(abs(_cross(d, np.asarray(x, float) - o)) < tol for x in (p, q, centre)):
            ts = [float((np.asarray(a, float) - o) @ d) for a in k.anchors]
            t = float((centre - o) @ d)
            if ts and min(ts) - tol <= t <= max(ts) + tol:
                return True
    return False


def _num(sol, point) -> np.ndarray:
    """A point's numbers at the instant drawn (a symbolic model's at its drawing values)."""
    return np.asarray(sol.inst.numvec(point), float)[:2]


@over(name=SEEDS)
def test_a_line_that_places_a_centre_reaches_it(name):
    """Each centre of a centres figure the structure places where a Kennedy line (third body
    k: the line through I_ak and I_kb, both finite) meets another line (a joint's normal) has a drawn line through those
    two points whose drawn part reaches the centre: the points are the solver's, the line is
    checked by cross products (collinear to 1e-9 of the figure's size)."""
    sol, doc = explained(name)
    by_pair = {frozenset(c.pair): c for c in all_centres(sol)}
    for fig in _figures(doc, "fig.centres"):
        scene = build_scene(sol.inst, sol, DrawOptions(**fig.options))
        pairs = {frozenset(p) for p in fig.options.get("centre_pairs") or []}
        for key in pairs:
            c = by_pair.get(key)
            if c is None or c.how != "lines" or c.value.get("point") is None:
                continue
            a, b = c.pair
            thirds = [n for kind, n in c.lines if kind == "third"]
            centre = _num(sol, c.value["point"])
            for k in thirds:
                ends = [by_pair[frozenset(x)].value.get("point") for x in ((a, k), (k, b))]
                if any(e is None for e in ends):
                    continue
                p, q = (_num(sol, e) for e in ends)
                if np.linalg.norm(p - q) < 1e-9:
                    continue
                assert _reaches(scene, p, q, centre, 1e-9 * max(1.0, float(np.abs(centre).max()))), \
                    f"I({a},{b}) on the line through I({a},{k}) and I({k},{b}): not drawn to it"


def _block(name: str, joint: str):
    sol = kinematika.solve(EXAMPLES / f"{name}.yaml")
    scene = build_scene(sol.inst, sol, DrawOptions())
    view = Box(*scene.box).grow(0.6 * scene.size)
    block = next(m for m in scene_symbols(scene, view) if m.gid == f"joint:{joint}" and m.kind == "polygon")
    return np.asarray(block.points, float).mean(axis=0), block


def test_the_sleeve_is_drawn_at_the_supports_centre():
    """C5-1.3: the bar (Q = (1, 2), E = (5.5, 0.5)) slides through the support's sleeve at
    its centre S = (4, 1), on QE: (S − Q) = (3, −1) ∥ (E − Q) = (4.5, −1.5). The block's
    four corners average to S (not E), and it is the support's (its fill, and it moves with
    the support)."""
    centre, block = _block("seed_c5_1_3_bar_in_sleeve", "j3")
    assert np.allclose(centre, (4.0, 1.0), atol=1e-9)
    assert block.fill == "body:support" and block.moves_with == "support"


def test_a_block_on_a_moving_guide_stays_at_its_point():
    """001's P pair: the block N (its one point B) on the guide M keeps its place at B —
    the sleeve rule takes a rod (two points along the guide) only."""
    sol = kinematika.solve(EXAMPLES / "seed_001_p_pair_coriolis.yaml")
    b = np.asarray(sol.inst.numvec(sol.inst.points["B"]), float)[:2]
    centre, block = _block("seed_001_p_pair_coriolis", "j2")
    assert np.allclose(centre, b, atol=1e-9)
    assert block.fill == "body:N"


def test_every_circle_of_a_stepped_wheel_is_drawn_and_listed():
    """C5-E.1: the wheels are solidary circles of radii R and 2R about C = (0, 2R) (the
    Data: "the large one's is 2R"); at R = 0.1 the figure's wheels carry two circles centred
    at (0, 0.2), radii 0.1 and 0.2, the point O on the larger's rim (|OC| = 2R); the shapes
    table lists both, and the rolling contact stays the R wheel's J = (0, 3R) = 1.5·C."""
    from .helpers import rendered

    sol = kinematika.solve(EXAMPLES / "seed_c5_e1_cavity.yaml")
    scene = build_scene(sol.inst, sol, DrawOptions())
    circles = sorted((s for s in scene.bodies["wheels"].shapes if s.kind == "circle"), key=lambda s: s.radius)
    assert [round(float(s.radius), 12) for s in circles] == [0.1, 0.2]
    assert all(np.allclose(s.centre(), (0.0, 0.2), atol=1e-12) for s in circles)
    table = [line for line in rendered("seed_c5_e1_cavity", "ca").splitlines() if line.startswith("| *rodes* | ") and "circumfer" in line]
    # twenty-seventh round (e): both in one row, which says which is which
    assert table == ["| *rodes* | dues circumferències concèntriques | centre C, radis R i 2·R |"]
    j = np.asarray(sol.inst.numvec(sol.geometry("j3").contact.point), float)[:2]
    c = np.asarray(sol.inst.numvec(sol.inst.points["C"]), float)[:2]
    assert np.allclose(j, 1.5 * c, rtol=1e-12, atol=1e-12)          # J = (0, 3R), C = (0, 2R)


def test_a_body_takes_a_list_of_circles(tmp_path):
    """`circle: [{…}, {…}]` gives the body both circles, in order; rolling takes the pair
    that touches: a wheel of radii 1 and 2 about C = (0, 1) on the ground line y = 0 touches
    with its radius-1 circle at (0, 0), and v_C = (−ω·1, 0) = (−2, 0) for ω = 2."""
    text = """
points: {O: [0, 0], C: [0, 1]}
bodies:
  ground: {points: [O], line: {through: O, direction: [1, 0]}}
  wheel: {points: [C], circle: [{center: C, radius: 1}, {center: C, radius: 2}]}
joints:
  - {type: rolling, bodies: [ground, wheel]}
drivers:
  - {omega: wheel, value: 2}
"""
    path = tmp_path / "stepped.yaml"
    path.write_text(text)
    sol = kinematika.solve(path)
    radii = [float(s.radius) for s in sol.inst.shapes["wheel"]]
    assert radii == [1.0, 2.0]
    assert np.allclose(np.asarray(sol.inst.numvec(sol.velocity("C")), float)[:2], (-2.0, 0.0), atol=1e-12)


def _through(box, a, b, inset=0.5) -> bool:
    """Whether the segment ab passes through `box` (x0, y0, x1, y1) shrunk by `inset`: sampled
    every 0.05 figure units (a check apart from the layout's exact clipping)."""
    x0, y0, x1, y1 = box[0] + inset, box[1] + inset, box[2] - inset, box[3] - inset
    a, b = np.asarray(a, float), np.asarray(b, float)
    n = max(2, int(np.linalg.norm(b - a) / 0.05) + 1)
    pts = a + np.linspace(0, 1, n)[:, None] * (b - a)
    return bool(np.any((pts[:, 0] > x0) & (pts[:, 0] < x1) & (pts[:, 1] > y0) & (pts[:, 1] < y1)))


@over(name=NOTES_SEEDS)
def test_a_polygon_label_sits_on_no_other_arrow(name):
    """In every velocity and acceleration polygon of the seeds' pages (en, ca), an arrow's
    label box (its text) lies on no other arrow: 001's rolling pair (ca) set a_AB^n over the
    blue a_F∈N at the pole."""
    pages = recorded_pages("polygons")
    for lang in ("en", "ca"):
        for lay, items, placed in pages[(name, lang)]:
            arrows = [(lay.at(a.start), lay.at(a.end)) for a in lay.fig.arrows]
            along_of = {id(item[0]): item[5] for item in items}
            for spot in placed:
                text, along = spot.text, along_of[id(spot.text)]
                if along is None:
                    continue
                own = (lay.at(along[0]), lay.at(along[1]))
                under = [ab for ab in arrows if not (np.allclose(ab[0], own[0]) and np.allclose(ab[1], own[1]))
                         and _through(spot.box, *ab)]
                assert not under, (lang, text.markup, under)
