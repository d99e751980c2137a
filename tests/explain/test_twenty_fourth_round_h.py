"""Issue 30, twenty-fourth round (h): the bodies' shapes in the mechanism figure.

- a body that is a part of a disc (`circle: {…, arc: [from, to]}`) is drawn as that part,
  its arc and its flat side, never as the whole circle (C5-1.7's semicylinder, drawn as a
  full circle: en and eu readers);
- a moving body's translucent fill is painted under the frame's hatching and outline, so a
  track a wheel overlaps stays seen (C5-E.1's 2R wheel covered "pista zilindrikoa": eu);
- a vector's arrow is painted above every body and joint (C5-1.3's v_E along the bar: en).

The rules are checked on the marks of each seed's mechanism figure (`draw.picture`, what both
painters paint), drawn in each language.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

import kinematika

from kinematika.draw.build import build_scene
from kinematika.draw.figure import zoomable
from kinematika.draw.options import DrawOptions
from kinematika.errors import KinematikaError

from .helpers import EXAMPLES, LANGS, SEEDS, explained, over

GROUND_OUTLINE = 2        # the frame's outlines (`draw.bodies`); its hatching is 1


def _figure(name: str, lang: str) -> tuple:
    """The scene and the marks of a seed's mechanism figure in `lang`."""
    sol, _ = explained(name)
    scene = build_scene(sol.inst, sol, DrawOptions(lang=lang, bare=True))
    marks, _ = zoomable(scene, DrawOptions(lang=lang, bare=True))
    return scene, marks


def _arcs(scene) -> list:
    return [(body, s) for body in scene.bodies.values() for s in body.shapes
            if s.kind == "circle" and s.arc is not None]


def test_the_semicylinder_is_a_half_disc_in_its_model():
    """C5-1.7's fixed body is the upper half of its circle (the notes' figure: a half-disc on
    the ground), said in the model; the solution reads the radius only."""
    sol, _ = explained("seed_c5_1_7_semicylinder")
    (circle,) = sol.model.bodies["ground"].shapes
    assert circle.arc == (0.0, 180.0)


@over(name=SEEDS, lang=LANGS)
def test_a_part_of_a_disc_is_drawn_as_that_part(name, lang):
    """No mark of a body that is a part of a disc reaches the side of its chord away from the
    arc by more than the hatching's band (the ground it rests on), no whole circle of it is
    drawn, and its flat side is: a line through both ends of the arc. The seed with such a body
    (C5-1.7) shows only the upper half: the figure's marks end near its centre's height."""
    scene, marks = _figure(name, lang)
    for body, s in _arcs(scene):
        c, r = s.centre(), s.radius
        mid = 0.5 * (s.arc[0] + s.arc[1])
        up = np.array([math.cos(mid), math.sin(mid)])       # from the chord towards the arc
        ends = [c + r * np.array([math.cos(a), math.sin(a)]) for a in s.arc]
        chord_at = float((ends[0] - c) @ up)                  # 0 for a half-disc
        own = [m for m in marks if m.gid.startswith(("ground:circle", f"shape:{body.name}"))]
        assert own, f"{body.name}: nothing of its circle is drawn"
        assert not [m for m in marks if m.kind in ("circle", "ring") and
                    np.allclose(m.points[0], c) and abs(m.r - r) < 1e-6 * r], \
            f"{body.name}: its whole circle is drawn"
        band = 0.25 * r
        for m in marks:
            if m.kind in ("line", "polygon") and np.linalg.norm(np.asarray(m.points) - c, axis=1).max() <= 1.5 * r:
                low = float(min((np.asarray(m.points) - c) @ up))
                assert low >= chord_at - band, f"{body.name}: a mark {m.kind} {m.gid!r} reaches {low:.3g} below the chord"
        flat = [m for m in own if m.kind == "line" and
                all(min(np.linalg.norm(np.asarray(m.points) - e, axis=1)) < 1e-6 * r for e in ends)]
        assert flat, f"{body.name}: its flat side is not drawn"
    if name == "seed_c5_1_7_semicylinder":
        assert _arcs(scene), "C5-1.7's semicylinder is drawn as a whole circle"


def test_an_arc_that_is_no_part_of_the_circle_is_refused(tmp_path):
    """An arc is a part of the circle: 0 < to − from < 360 degrees, else a schema error naming it."""
    text = (EXAMPLES / "seed_c5_1_7_semicylinder.yaml").read_text(encoding="utf-8")
    for arc in ("[180, 0]", "[0, 360]", "[30, 30]"):
        path = tmp_path / "m.yaml"
        path.write_text(text.replace("arc: [0, 180]", f"arc: {arc}"), encoding="utf-8")
        with pytest.raises(KinematikaError) as err:
            kinematika.solve(path)
        assert err.value.where == "bodies.ground.circle.arc"


@over(name=SEEDS, lang=LANGS)
def test_a_moving_fill_lies_under_the_frames_hatching_and_outline(name, lang):
    """Every pure fill of a moving body (a wheel's disc, a ring's band, a cam's profile: no
    outline of its own) is painted under every hatching and outline of the frame, so that
    where a wheel overlaps a track (C5-E.1's 2R wheel over the cylindrical track) the track's
    edge and hatching are seen through it, at their full contrast."""
    _, marks = _figure(name, lang)
    fills = [m for m in marks if m.moves_with and m.fill not in ("none", "") and m.width == 0
             and m.kind in ("circle", "polygon", "ring")]
    ground = [m for m in marks if not m.moves_with and (m.hatch or m.gid.startswith("ground:"))]
    if not fills or not ground:
        return
    top = max(f.zorder for f in fills)
    below = min(g.zorder for g in ground)
    assert top < below, f"a moving fill at zorder {top} is not under the frame's marks (from {below})"


@over(name=SEEDS, lang=LANGS)
def test_an_arrow_is_above_every_body(name, lang):
    """Every vector's arrow is painted above every body, joint and point (C5-1.3's v_E runs
    along the bar from E: painted above the bar and the sleeve, not hidden by them)."""
    _, marks = _figure(name, lang)
    arrows = [m for m in marks if m.kind == "arrow"]
    shapes = [m for m in marks if m.kind != "arrow" and m.kind != "text" and
              m.gid.startswith(("body:", "shape:", "ground:", "joint:", "point:"))]
    if arrows and shapes:
        assert min(a.zorder for a in arrows) > max(s.zorder for s in shapes)
