"""Bodies drawn as the notes draw them: a Hooke joint as two yokes and a cross; a vehicle's
centre found from velocities with the line through it and its body's pins."""
from __future__ import annotations

from pathlib import Path

import numpy as np

import kinematika
from kinematika.draw.options import DrawOptions
from kinematika.draw.build import build_scene

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def scene_of(name: str, **options):
    sol = kinematika.solve(EXAMPLES / f"{name}.yaml")
    return build_scene(sol.inst, sol, DrawOptions(**options))


def test_hooke_joint_is_two_yokes_and_a_cross():
    """Input shaft along −x (towards A), its fork holding the cross's arm along y (F at its
    tip); output shaft along u = (cos 30°, sin 30°, 0) (towards B), its fork holding the arm
    along z (G at its tip); the cross is its two arms through O. No sphere."""
    scene = scene_of("hooke_joint")
    assert scene.sphere is None
    o, a, b, f, g = (np.asarray(scene.point(p)) for p in ("O", "A", "B", "F", "G"))
    cross = [np.asarray(line) for line in scene.bodies["cross"].skeleton]
    assert len(cross) == 2 and all(np.allclose(line.mean(axis=0), o) for line in cross)
    assert any(np.allclose(line[1], f) for line in cross) and any(np.allclose(line[1], g) for line in cross)
    for shaft, towards, tip in (("input", a, f), ("output", b, g)):
        bar, fork = (np.asarray(line) for line in scene.bodies[shaft].skeleton)
        assert len(bar) == 2 and len(fork) == 4
        assert np.allclose(fork[0], tip) and np.allclose(fork[3], 2 * o - tip)   # the prongs end at the arm's tips
        out = bar[1] - o                                                         # the shaft goes past its point
        along = towards - o
        assert abs(out[0] * along[1] - out[1] * along[0]) <= 1e-9 * np.linalg.norm(out) ** 2
        assert out @ along > along @ along


def test_trailer_centre_on_the_line_through_the_tractor_centre_and_the_hitch():
    """I14 (trailer) lies where the trailer's axle meets the line I12–H (Kennedy: I12, I24
    = H, I14 collinear); the figure draws that line reaching both centres."""
    scene = scene_of("tractor_trailer", centres=True)
    h = np.asarray(scene.point("H"))
    marks = {m.label: np.asarray(m.point) for m in scene.marks if m.point is not None}
    i12 = next(p for label, p in marks.items() if "12" in label)
    i14 = next(p for label, p in marks.items() if "14" in label)
    lines = [k for k in scene.kennedy if k.key.startswith("radius:")]

    def on(k, p):
        d = np.asarray(k.direction) / np.linalg.norm(k.direction)
        r = p - np.asarray(k.through)
        return abs(r[0] * d[1] - r[1] * d[0]) <= 1e-6 * scene.size

    assert any(on(k, h) and on(k, i12) and on(k, i14) for k in lines)


def test_a_bare_figure_has_no_english_words():
    """A figure embedded in an explanation of any language: far and infinite centres read
    `I₁₄ = (x, y)` and `I₅₆ → ∞`, not "at"; no "(enlarged)"."""
    from matplotlib.text import Text

    from kinematika.draw import draw

    for name, options in (("seed_c5_1_4_epicyclic", {"centres": True}),
                          ("quick_return", {"centres": True, "accelerations": True}),
                          ("coin_rolling", {})):
        for bare in (False, True):
            fig = draw(EXAMPLES / f"{name}.yaml", options=DrawOptions(bare=bare, **options))
            texts = " ".join(t.get_text() for t in fig.findobj(Text))
            english = any(w in texts for w in (" at ∞", " at (", "(enlarged)"))
            assert english != bare, (name, bare, texts)
            if bare and name != "coin_rolling":
                assert "→ ∞" in texts or "= (" in texts


def test_a_bare_figure_numbers_its_bodies():
    """An explanation names bodies by number (ω_2, I_12): its figures say which is which."""
    plain = scene_of("triad_six_bar")
    bare = scene_of("triad_six_bar", bare=True)
    assert not plain.numbered and bare.numbered
