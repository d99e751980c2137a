"""Issue 30, twenty-seventh round (f): the mechanism's and the instant centres' figures as a
teacher draws them (docs/explain.md, "Twenty-seventh round (f)").

Three readers of the notes' seeds saw: arrows drawn on top of the bars and strands they run
along (C5-1.3's v_E, C5-1.5's v_K and v_T2, C5-2.2's v_O and v_P); values and names set under
the ground's hatching, far from what they name (C5-1.3's v_ar,E, C5-E.6's sprocket and
chainring), an arrow running into the ground (C5-E.3's v_B), a label over its own arrow's
head; centres found from ω and one point's velocity drawn as bare rings (C5-1.6, C5-E.5,
C5-E.6); the fixed strand of C5-1.5 drawn as a hatched wall and its pulleys' supports inside
them, as C5-1.4's sun's; the crank of C5-E.6 drawn from the top of the chainring; C5-E.1's 2R
wheel crossing the track's wall; the given velocities left out (C5-E.4's v_U, C5-2.1's v_F);
001's point A half on the slider's block.

Every figure of the notes' seeds is drawn again here in English and Catalan (the longest words,
`RECORDED_LANGS`; the measure in docs/explain.md reads all four), its marks (what
`draw.picture` made) and its labels' places recorded; each check reads them against the
model or the page's own text, never against numbers the drawing code produced.
"""
from __future__ import annotations

import itertools
import math
import re

import numpy as np

from .helpers import NOTES_SEEDS, RECORDED_LANGS, explained, figures, over, plain_page


def ground_edges(marks: list) -> list:
    """The ground's hatched edges as drawn: (p, q, the unit side its material is on, gid),
    read off each edge's line and the hatched band drawn right after it on that side."""
    out = []
    for line, band in itertools.pairwise(marks):
        if line.kind == "line" and line.gid.startswith("ground:") and len(line.points) == 2 and \
                band.kind == "polygon" and band.hatch and np.allclose(band.points[0], line.points[0]):
            side = np.asarray(band.points[3], float) - np.asarray(band.points[0], float)
            out.append((np.asarray(line.points[0], float), np.asarray(line.points[1], float),
                        side / np.linalg.norm(side), line.gid))
    return out


def crosses(p, q, a, b) -> bool:
    """Whether the segments pq and ab cross (strictly)."""
    def side(o, u, v):
        return (u[0] - o[0]) * (v[1] - o[1]) - (u[1] - o[1]) * (v[0] - o[0])
    return side(a, b, p) * side(a, b, q) < 0 and side(p, q, a) * side(p, q, b) < 0


def arrows_of(marks: list) -> list:
    """The vectors' arrows (start, end) drawn, with their marks."""
    return [(np.asarray(m.points[0], float), np.asarray(m.points[1], float), m) for m in marks
            if m.kind == "arrow" and m.layer in ("velocity", "acceleration")
            and np.linalg.norm(np.subtract(m.points[1], m.points[0])) > 0]


def owner(gid: str):
    """The body a label names or a vector's value belongs to (`body:NAME`, `velocity:P@NAME…`)."""
    if gid.startswith("body:"):
        return gid[5:]
    kind, _, ref = gid.partition(":")
    return ref.split("@", 1)[1].split("/")[0].split(":")[0] if kind in ("velocity", "acceleration") and "@" in ref else None


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_an_arrow_is_cased_in_white(name, lang):
    """Every vector's arrow is painted over a white casing wider than its stroke, so that one
    along its bar or strand stays seen (C5-1.3's v_E, C5-1.5's v_K, C5-2.2's v_O): the
    matplotlib artist of each arrow mark strokes white under it."""
    from kinematika.draw.paint import artist

    bad = []
    for _, marks, _, _ in figures(name, lang):
        for _, _, m in arrows_of(marks):
            effects = [e for e in artist(m).get_path_effects() if hasattr(e, "_gc")]
            if not effects or effects[0]._gc.get("foreground") != "white" or \
                    not effects[0]._gc.get("linewidth", 0) > m.width + 2:
                bad.append(m.gid)
    assert not bad, bad


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_name_or_value_is_set_in_the_ground(name, lang):
    """No body's name and no vector's value lies beyond a hatched ground edge, in the ground's
    material (its box's centre on the hatched side, over the edge's length), but a fixed
    body's own name beside its own edge (C5-1.3's v_ar,E, C5-E.6's chainring were there)."""
    bad = []
    for _, marks, placed, transform in figures(name, lang):
        edges = ground_edges(marks)
        for p in placed:
            body = owner(p.label.gid)
            if body is None:
                continue
            c = transform.inverted().transform((p.box[:2] + p.box[2:]) / 2)
            for a, b, side, gid in edges:
                u = (b - a) / np.linalg.norm(b - a)
                if gid != f"ground:{body}" and 0 <= (c - a) @ u <= np.linalg.norm(b - a) and (c - a) @ side > 0:
                    bad.append(p.label.text)
                    break
    assert not bad, bad


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_arrow_runs_into_the_ground(name, lang):
    """No acceleration's arrow crosses a hatched ground edge (C5-E.3's v_B ran down into the
    track). A velocity starts at its point and may cross the ground's line, drawn over it:
    ended at its point it read as applied elsewhere (twenty-eighth round (g))."""
    bad = [m.gid for _, marks, _, _ in figures(name, lang) for s, e, m in arrows_of(marks)
           if m.layer == "acceleration"
           for a, b, _, _ in ground_edges(marks) if crosses(s, e, a, b)]
    assert not bad, bad


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_label_covers_an_arrow_head(name, lang):
    """No label's box holds an arrow's tip or the middle of its head (3 points back along it):
    C5-1.3's v_ar,E sat on the head of its own short arrow."""
    bad = []
    for _, marks, placed, transform in figures(name, lang):
        px = 1.0
        for s, e, _ in arrows_of(marks):
            a, b = transform.transform(np.array([s, e]))
            u = (b - a) / np.linalg.norm(b - a)
            for q in (b, b - 3 * px * u):
                bad += [p.label.text for p in placed
                        if p.box[0] < q[0] < p.box[2] and p.box[1] < q[1] < p.box[3]]
    assert not bad, bad


def drawn_at(sol, x) -> np.ndarray:
    """A model's point (its coordinates, formulas of the parameters) at the numbers the
    figures are drawn at: the model's `draw_at`, else the solver's sample values."""
    import sympy

    given = sol.model.draw_at or {}

    def value(c) -> float:
        expr = sympy.sympify(c)
        if not given or not expr.free_symbols:
            return float(sol.inst.num(c))
        return float(expr.subs({s: given[str(s)] for s in expr.free_symbols if str(s) in given}))
    return np.array([value(c) for c in x], float)


def said_perpendiculars(name: str) -> list[tuple[str, str]]:
    """Each centre the English page says lies "on the perpendicular to v_X through X", as
    (the centre's subscript, X)."""
    page = plain_page(name, "en")
    out = []
    for line in re.finditer(r"^I_(\{[^}]*\}|\S+?): (.*)$", page, re.M):
        out += [(line.group(1).strip("{}"), x) for x in
                re.findall(r"perpendicular to v_(?:\{[^}]*\}|\S+) through (\w+)", line.group(2))]
    return out


@over(name=NOTES_SEEDS)
def test_a_centre_said_on_a_perpendicular_is_drawn_on_it(name):
    """Where the page places a centre "on the perpendicular to v_X through X" (C5-1.6's moving
    pulley, C5-E.5's wheel 1, C5-E.6's chainring, from the body's ω and X's velocity; and
    every such line of a construction), the centres' figure draws that line: a dash-dot line
    through X (where the figure sets X's letter) and the centre (the solution's)."""
    from kinematika.draw.names import body_labels, names_bodies
    from kinematika.questions.centres import all_centres

    said = said_perpendiculars(name)
    if not said:
        return
    sol, _ = explained(name)
    model = sol.model
    labels = body_labels(model, "en", named=names_bodies(model, "en"))
    body_of = {label: body for body, label in labels.items()}
    _, marks, placed, transform = next(f for f in figures(name, "en") if f[0].get("centres"))
    lines = [np.asarray(m.points, float) for m in marks if m.kind == "line" and m.dash
             and m.group.startswith(("kennedy:", "normal:"))]
    at = {p.label.text: np.asarray(p.label.anchor, float) for p in placed
          if p.label.gid.startswith(("point:", "contact:"))}

    def on(q, line) -> bool:
        d = line[-1] - line[0]
        return abs(float(d[0] * (q - line[0])[1] - d[1] * (q - line[0])[0])) <= 1e-6 * np.linalg.norm(d) * max(1.0, float(np.linalg.norm(q - line[0])))

    bad = []
    for sub, x in said:
        body = body_of.get(sub)
        centre = next((c for c in all_centres(sol) if body and set(c.pair) == {model.frame, body}), None)
        if centre is None or centre.value.get("point") is None or x not in at:
            continue
        i = drawn_at(sol, centre.value["point"])
        if not any(on(at[x], ln) and on(i, ln) for ln in lines):
            bad.append(f"I_{sub} not on a line through {x}")
    assert not bad, bad


@over(name=NOTES_SEEDS, lang=("en",))
def test_no_support_of_a_pivot_sits_in_a_moving_wheel(name, lang):
    """No fixed pivot's triangle lies inside a moving body's disc (the model's circles): C5-1.4's
    sun (turning at 7ω) and C5-1.5's upper pulleys had their supports drawn inside them."""
    sol, _ = explained(name)
    inst = sol.inst
    discs = [(drawn_at(sol, s.center), float(drawn_at(sol, (s.radius,))[0]))
             for b, shapes in inst.shapes.items() if b != sol.model.frame
             for s in shapes if hasattr(s, "radius") and getattr(s, "arc", None) is None]
    # a ring holds other wheels inside it (C5-1.4's, C5-E.2's): what it turns about is its hollow
    discs = [(c, r) for c, r in discs if not any(np.linalg.norm(c2 - c) + r2 <= r + 1e-9 and r2 < r for c2, r2 in discs)]
    bad = []
    for _, marks, _, _ in figures(name, lang):
        for m in marks:
            if m.kind == "polygon" and m.gid == "ground:pivot":
                c = np.mean(np.asarray(m.points, float), axis=0)
                bad += [tuple(c) for centre, r in discs if np.linalg.norm(c - centre) < r and not _fixed_disc(sol, centre, r)]
    assert not bad, bad


def _fixed_disc(sol, centre, r) -> bool:
    """Whether a circle of that centre and radius is a fixed body's (welded to the frame)."""
    from kinematika.draw.build import welded_to_frame

    fixed = welded_to_frame(sol.model)
    inst = sol.inst
    return any(np.allclose(drawn_at(sol, s.center), centre) and math.isclose(float(drawn_at(sol, (s.radius,))[0]), r)
               for b in fixed for s in inst.shapes.get(b, []) if hasattr(s, "radius"))


def test_c5_1_5_strand_1_hangs_from_the_ceiling():
    """C5-1.5's strand 1, welded to the ceiling at G and wrapped round pulley 1 with strand 2,
    is drawn as a cable from G down to its contact J with pulley 1, in no hatched band along
    it, and tied at G to a hatched edge across it, hatched above G (away from J); pulleys 2 and
    4 hang from supports above their rims (y > r over their centres at y = 0)."""
    sol, _ = explained("seed_c5_1_5_pulley_block")
    r = 0.1                                          # the model's draw_at
    g = np.array([0.0, 0.0])
    j = np.array([0.0, -4 * r])                      # pulley 1's contact with strand 1: C1 − r x
    for _, marks, _, _ in figures("seed_c5_1_5_pulley_block", "en"):
        edges = ground_edges(marks)
        along = [e for e in edges if abs(e[0][0] - g[0]) < 1e-9 and abs(e[1][0] - g[0]) < 1e-9]
        assert not along, "strand 1 hatched along its length"
        cable = [m for m in marks if m.kind == "line" and m.gid == "shape:strand1"]
        assert cable and {tuple(np.round(p, 9)) for p in cable[0].points} == {tuple(g), tuple(j)}
        tie = [e for e in edges if e[3].startswith("ground:tie")]
        assert tie and all(abs(e[0][1]) < 1e-9 and abs(e[1][1]) < 1e-9 and e[2][1] > 0.99 for e in tie)
        pivots = [np.mean(np.asarray(m.points, float), axis=0) for m in marks if m.gid == "ground:pivot"]
        assert len(pivots) >= 2 and all(c[1] > r for c in pivots)


def test_c5_e6_the_crank_runs_from_the_axle_to_the_pedal():
    """C5-E.6's chainring is a disc (centre C, radius R) with its crank to the pedal P, L below
    C: its bar is drawn from C to P, never from the chain's contact T2 on the rim (R above C)."""
    p = {"C": (0.7, 0.35 + 0.07 - 0.14), "P": (0.7, 0.35 + 0.07 - 0.14 - 0.18)}      # draw_at (b, R_roda + r - R (- L))
    for _, marks, _, _ in figures("seed_c5_e6_bicycle", "en"):
        bars = [np.asarray(m.points, float) for m in marks if m.kind == "line" and m.gid == "body:chainring"]
        assert len(bars) == 1
        assert {tuple(np.round(x, 9)) for x in bars[0]} == {tuple(np.round(v, 9)) for v in p.values()}


@over(name=NOTES_SEEDS, lang=("en",))
def test_a_wheel_crossing_the_ground_is_drawn_in_another_plane(name, lang):
    """A moving body's circle that cuts a fixed circle of the model twice (it cannot in one
    plane: C5-E.1's 2R wheel, radius 2R about (0, 2R), across the track, radius 3R about O) is
    drawn dashed and lighter than a wheel; every other wheel solid."""
    sol, _ = explained(name)
    inst, frame = sol.inst, sol.model.frame
    from kinematika.draw.build import welded_to_frame

    fixed = {frame} | welded_to_frame(sol.model)
    circles = {b: [(drawn_at(sol, s.center), float(drawn_at(sol, (s.radius,))[0])) for s in shapes
                   if hasattr(s, "radius") and getattr(s, "arc", None) is None]
               for b, shapes in inst.shapes.items()}
    ground = [c for b in fixed for c in circles.get(b, [])]
    bad = []
    for _, marks, _, _ in figures(name, lang):
        for b, cs in circles.items():
            if b in fixed:
                continue
            for centre, r in cs:
                cut = any(abs(r - R) < np.linalg.norm(centre - C) < r + R and
                          not math.isclose(np.linalg.norm(centre - C), abs(r - R), abs_tol=1e-9) for C, R in ground)
                drawn = [m for m in marks if m.kind == "circle" and m.gid == f"shape:{b}" and math.isclose(m.r, r)
                         and np.allclose(m.points[0], centre)]
                if drawn and cut != bool(drawn[0].dash and drawn[0].dash is not True):
                    bad.append(f"{b} r={r:g}: cuts the ground {cut}, dashed {drawn[0].dash}")
    assert not bad, bad


@over(name=NOTES_SEEDS, lang=("en",))
def test_the_given_velocities_are_drawn(name, lang):
    """The mechanism's figure draws every velocity the data give (each driver's point velocity
    relative to the frame, from the model): an arrow at that point along the driver's
    direction (C5-E.4's v_U, C5-2.1's v_F were left out)."""
    sol, _ = explained(name)
    model = sol.model
    given = [d for d in model.drivers if d.kind == "velocity" and d.relative_to in (None, model.frame)]
    if not given:
        return
    mechanism = next(f for f in figures(name, lang) if f[0].get("velocities"))
    arrows = arrows_of(mechanism[1])
    bad = []
    for d in given:
        at = drawn_at(sol, sol.position(d.point))
        v = drawn_at(sol, sol.velocity(d.point))
        ok = [m for s, e, m in arrows if m.layer == "velocity" and (np.allclose(s, at) or np.allclose(e, at))
              and float(np.dot(e - s, v)) > 0.999 * np.linalg.norm(e - s) * np.linalg.norm(v)]
        if not ok:
            bad.append(str(d.point))
    assert not bad, bad


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_no_point_letter_lies_across_a_block(name, lang):
    """No point's letter has the outline of a joint's block (a slider's) through its box: 001's
    A sat half on the slider's block."""
    bad = []
    for _, marks, placed, transform in figures(name, lang):
        blocks = [transform.transform(np.vstack([m.points, m.points[:1]])) for m in marks
                  if m.kind == "polygon" and m.gid.startswith("joint:") and m.fill not in ("none", "")]
        for p in placed:
            if not p.label.gid.startswith(("point:", "contact:")):
                continue
            if any(_through(a, b, p.box) for poly in blocks for a, b in itertools.pairwise(poly)):
                bad.append(p.label.text)
    assert not bad, bad


def _through(a: np.ndarray, b: np.ndarray, box: np.ndarray) -> bool:
    """Whether the segment ab (display), sampled every half pixel, runs through `box`."""
    t = np.linspace(0, 1, max(2, int(np.linalg.norm(b - a) / 0.5)))[:, None]
    s = a + t * (b - a)
    return bool(np.any((s[:, 0] > box[0]) & (s[:, 0] < box[2]) & (s[:, 1] > box[1]) & (s[:, 1] < box[3])))
