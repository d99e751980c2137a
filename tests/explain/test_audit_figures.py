"""What the independent audit of issue 30 found in C5-1.2 and C5-1.5, as rules (docs/explain.md,
"The independent audit, and what was fixed after it"): a body welded to the ground is ground,
the wheels drawn do not overlap, a fixed plane is drawn as the segment of ground it is, the
centres' figure shows the centres the text uses, and every point an equation names is in the
Data section's table of points."""
from __future__ import annotations

import math
import re

import pytest

from .helpers import WORKED, explained, render_of

C5_1_2 = "seed_c5_1_2_bar_on_inclined_wheels"


def test_a_body_welded_to_the_ground_is_not_a_moving_body():
    """C5-1.2's planes are welded to the ground: the degrees of freedom are counted over 4 moving
    bodies (the wheels and the two bars: 12 velocity components, 11 independent conditions,
    one degree of freedom — counted by hand: 2 rolling contacts × 2, 3 pins × 2, the floor's
    1 + 1 … of which one is redundant as the engine's diagnosis says), the structure table
    marks the planes fixed, and no step or rates' row is given to them."""
    from kinematika.explain.context import Ctx
    from kinematika.explain.structure import dof_counts

    sol, doc = explained(C5_1_2)
    text = render_of(doc, "en", "md", drawings=False)
    counts = dof_counts(Ctx(sol))
    assert (counts["n"], counts["moving"], counts["rank"], counts["dof"]) == (12, 4, 11, 1)
    assert "The mechanism has one degree of freedom." in text      # the mobility, as said (fifth round)
    assert "| 1 | *ground* (fixed), with the *left plane* and the *right plane* |" in text     # one row (29 b)
    assert "are fixed to the *ground*: they are part of it and do not move" in text   # the notes: part of the ground (seventeenth round (c))
    velocities = text.split("## Velocities", 1)[1].split("## Angular velocities", 1)[0]
    assert "### Step 1: the *bar OQ*" in velocities          # sentence case, the English article (ninth, tenth rounds)
    rates = text.split("## Angular velocities", 1)[1].split("##", 1)[0]
    assert not [row for row in rates.splitlines() if row.startswith("| *") and "plane" in row]   # no row: not a moving body
    for lang, words in (("ca", "un grau de llibertat"), ("eu", "askatasun-gradu bat du"), ("es", "un grado de libertad")):
        assert words in render_of(doc, lang, "md", drawings=False), lang


def _circles(sol) -> list[tuple[str, tuple, float]]:
    """(body, centre, radius) of every circle as drawn (a symbolic model at its draw_at
    values): the figure's own numbers."""
    from kinematika.draw.build import build_scene

    scene = build_scene(sol.inst, sol)
    return [(b.name, tuple(float(c) for c in s.center), float(s.radius))
            for b in scene.bodies.values() for s in b.shapes if s.kind == "circle"]


@pytest.mark.parametrize("name", sorted(p for p in WORKED if p.startswith("seed_")))
def test_no_two_wheels_overlap_at_the_drawn_instant(name):
    """Two circles of different bodies either lie apart, touch (a contact), or one holds the
    other (a ring): they never cross. C5-1.2's wheels at s = 2 crossed (|OQ| = 1.956 < 2r)."""
    sol, _ = explained(name)
    circles = _circles(sol)
    assert len(circles) >= 2 or name != C5_1_2
    # a body with several circles is a stepped wheel, its circles in parallel planes: C5-E.1's
    # 2R wheel reaches over the 3R track's rim, beside the plane its R wheel rolls in
    count = {a: sum(1 for b, _, _ in circles if b == a) for a, _, _ in circles}
    circles = [c for c in circles if count[c[0]] == 1]
    for i, (a, ca, ra) in enumerate(circles):
        for b, cb, rb in circles[i + 1:]:
            if a == b:
                continue
            d = math.dist(ca, cb)
            tol = 1e-9 * (ra + rb)
            crossing = abs(ra - rb) + tol < d < ra + rb - tol
            assert not crossing, (name, a, b, d, ra + rb)


def _drawings(doc, key: str) -> list:
    from kinematika.explain.document import Drawing, Section

    out: list = []

    def walk(blocks) -> None:
        for b in blocks:
            if isinstance(b, Section):
                walk(b.blocks)
            elif isinstance(b, Drawing) and b.caption.key == key:
                out.append(b)
    walk(doc.sections)
    return out


@pytest.mark.parametrize("name", ["seed_c5_1_5_pulley_block", C5_1_2, "seed_c5_1_1_pulley_on_cable",
                                  "seed_c5_1_4_epicyclic", "seed_c5_e2_gear_change"])
def test_the_centres_figure_shows_only_the_centres_the_text_uses(name):
    """The centres' figure marks no centre the text does not name (C5-1.5 drew all 36 pairs'
    centres, ~30 of them unasked and unused, around the two the text writes: I_1,3, I_1,7 —
    the ceiling 1, its tied strand 2, pulleys 1 and 3 the bodies 3 and 7)."""
    from kinematika.draw.build import build_scene
    from kinematika.draw.names import pair_tag
    from kinematika.draw.options import DrawOptions

    sol, doc = explained(name)
    text = render_of(doc, "en", "md", drawings=False)
    figures = _drawings(doc, "fig.centres")
    assert figures, name
    for fig in figures:
        scene = build_scene(sol.inst, sol, DrawOptions(**fig.options))
        drawn = [m.pair for m in scene.marks if m.kind == "icr"]
        assert drawn, name
        tags = [pair_tag(sol.model, *pair, "en") for pair in drawn]          # as the text writes them
        unused = [pair for pair, tag in zip(drawn, tags)       # Markdown: I_{tag} (twenty-seventh round (g))
                  if ("I_{" + tag + "}") not in text]
        assert not unused, (name, unused)
    if name == "seed_c5_1_5_pulley_block":
        # pulleys 1 and 3 are bodies 2 and 6 since the tied strand, welded to the ceiling, is
        # numbered after the moving bodies (twenty-ninth round (b))
        assert sorted(pair_tag(sol.model, *m.pair) for m in scene.marks if m.kind == "icr") == ["1,2", "1,6"]


# an instant centre: defined in the centres section, not in Data (I, I14; a centre written as
# its symbol, `document.centre_point`: C5-1.2's I_OQ)
CENTRE = re.compile("^(?:I\\d*|\ue010[^\ue011]*\ue011)$")


def _defined(name: str, listed: set[str]) -> bool:
    """A point name the table lists, a centre, or a segment of two of them (CJ, P2I, RLI); the
    geometric contact point J^{geom} by its contact J (the contact's section says what it is)."""
    from kinematika.explain.document import GEOM_MARK

    name = name.replace(GEOM_MARK, "")
    if name in listed or CENTRE.match(name):
        return True
    return any((name[:k] in listed or CENTRE.match(name[:k])) and (name[k:] in listed or CENTRE.match(name[k:]))
               for k in range(1, len(name)))


@pytest.mark.parametrize("name", sorted(p for p in WORKED if p.startswith("seed_")))
def test_every_point_an_equation_names_is_in_the_points_table(name):
    """Every point the equations write (v_J4∈3, v_{C1-J1}, ω × CJ) is in the Data section's
    table of points, with what it is — the model's points and the contact points the
    explanation names (C5-1.5's J1 … J10 were in no table); instant centres are defined in
    their own section."""
    from kinematika.explain.data import points_named
    from kinematika.explain.document import Table

    _, doc = explained(name)
    table = next(b for b in doc.sections[0].blocks if isinstance(b, Table)
                 and getattr(b.header[0], "key", "") == "col.point")
    listed = {row[0].text for row in table.rows}
    missing = sorted(p for p in points_named(doc, frozenset(listed)) if not _defined(p, listed))
    assert not missing, (name, missing)
    assert all(row[1] is not None for row in table.rows)
    if name == "seed_c5_1_5_pulley_block":
        what = _points_table_en(doc)
        assert what["T2"] == "the point of *strand 2* where it touches *pulley 2*"
        assert "J4" not in what            # the contact of strand 2 and pulley 2 is T2: one point, one label


def _points_table_en(doc) -> dict[str, str]:
    text = render_of(doc, "en", "md", drawings=False)
    lines = text.split("| point |", 1)[1].split("\n\n", 1)[0].splitlines()[2:]
    return {cells[1].strip(): cells[2].strip() for cells in (line.split("|") for line in lines)}


@pytest.mark.parametrize("name", sorted(p for p in WORKED if p.startswith("seed_")))
def test_no_polygon_piles_labels_on_one_point(name):
    """A polygon writes the images that fall on one point as one label (a, b, d), at most
    four names (C5-2.2's translating chassis: c1, c2, o′, p1); a polygon whose arrows all lie
    on one line with more than three images on a point is left out (C5-1.5's: eight vertical
    arrows, the contact points' images on one point)."""
    from kinematika.explain.document import Figure, Section
    from kinematika.explain.polygon import MAX_AT_POINT

    _, doc = explained(name)
    figures: list = []

    def walk(blocks) -> None:
        for b in blocks:
            if isinstance(b, Section):
                walk(b.blocks)
            elif isinstance(b, Figure):
                figures.append(b)
    walk(doc.sections)
    figures += [eq.polygon for eq in doc.equations() if eq.polygon is not None]
    for fig in figures:
        images = [(label, xy) for label, xy, kind in fig.points if kind == "image"]
        for i, (a, p) in enumerate(images):
            assert a.count(", ") + 1 <= MAX_AT_POINT, (name, a)
            for b, q in images[i + 1:]:
                assert math.dist(p, q) > 1e-9 * max(1.0, math.hypot(*p)), (name, a, b)
    if name == "seed_c5_1_5_pulley_block":
        assert not [f for f in figures if f.caption.key == "fig.level_v"]
