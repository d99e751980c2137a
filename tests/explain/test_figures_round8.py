"""Strands and figures (issue 30, ninth round, after the seventh audit): a strand is drawn
from its tangent point, never through it (C5-1.1's cable ran past J and K); a roller a
slider carries rests on its fixed guide instead of sinking into it (001's rolling pair); the
mechanism's caption names a composition's drag arrow as the arrow's label does (v_ar,A, not
"A∈N"); and a straight body — a strand, a block's edge — on a pulley "does not slip", only a
round body "rolls" (C5-1.5: "El tram 2 rodola sense lliscar sobre la politja 1")."""
from __future__ import annotations

import math
import re

import numpy as np
import pytest

import kinematika
from kinematika.draw import draw
from kinematika.draw.build import build_scene
from kinematika.draw.geometry import Box
from kinematika.draw.joints import scene_symbols
from kinematika.draw.options import DrawOptions

from tests.draw.artists import axes
from .helpers import EXAMPLES, LANGS, SEEDS, explained, rendered, over
from .helpers import words_of as _words


def _line(fig, gid: str) -> np.ndarray:
    lines = [ln for ln in axes(fig).lines if ln.get_gid() == gid]
    assert len(lines) == 1, gid
    return np.column_stack(lines[0].get_data())


def test_the_cables_strands_end_at_their_tangent_points():
    """C5-1.1 drawn at r = 0.1: the pulley's centre C = (0, 0); the left strand, at 60° below
    the horizontal, touches it at J = r(−√3/2, −1/2) and the right one at K = r(√3/2, −1/2)
    (the radius to a tangent point is perpendicular to the strand). Each strand's lower end is
    its tangent point, not 0.1 of the figure beyond it."""
    fig = draw(EXAMPLES / "seed_c5_1_1_pulley_on_cable.yaml")
    r = 0.1
    for gid, tangent in (("shape:strand1", (-math.sqrt(3) / 2 * r, -r / 2)),
                         ("shape:strand2", (math.sqrt(3) / 2 * r, -r / 2))):
        xy = _line(fig, gid)
        low = xy[np.argmin(xy[:, 1])]
        assert np.allclose(low, tangent, atol=1e-9), (gid, low, tangent)


def test_the_pulley_blocks_strands_run_between_tangent_points():
    """C5-1.5 drawn at r = 0.1: strands 2, 3 and 4 hang between two pulleys' tangent points,
    the model's T1 = (2r, −4r) – T2 = (2r, 0), T3 = (4r, 0) – T4 = (4r, −4r) and
    T5 = (6r, −4r) – T6 = (6r, 0): each drawn strand spans exactly its two points."""
    fig = draw(EXAMPLES / "seed_c5_1_5_pulley_block.yaml")
    r = 0.1
    for body, x in (("strand2", 2 * r), ("strand3", 4 * r), ("strand4", 6 * r)):
        xy = _line(fig, f"shape:{body}")
        assert np.allclose(xy[:, 0], x, atol=1e-9)
        assert math.isclose(xy[:, 1].min(), -4 * r, abs_tol=1e-9) and math.isclose(xy[:, 1].max(), 0, abs_tol=1e-9)


def test_the_roller_rides_on_its_slider_not_on_the_ground():
    """001's rolling pair: the slider carries the roller's centre A = (ρ/sin β, 0) = (0.2, 0)
    along the horizontal through B (ρ = 0.1). The fixed guide is the line under the block, not
    a hatched ground tangent under the roller (which read as the roller rolling on the ground,
    sixteenth round (d)), now a slot (eighteenth round (d)): nothing of it lies on y = −0.1."""
    sol = kinematika.solve(EXAMPLES / "seed_001_rolling_pair.yaml")
    scene = build_scene(sol.inst, sol, DrawOptions())
    view = Box(*scene.box).grow(0.6 * scene.size)
    guide = [m for m in scene_symbols(scene, view) if m.gid.startswith(("ground:guide", "ground:slot"))]
    assert guide
    ys = np.concatenate([np.asarray(m.points, float)[:, 1] for m in guide])
    assert not np.any(np.isclose(ys, -0.1, atol=1e-3)), ys


# the drag's subscript word, as the notes of each language write it (composition section)
DRAG = {"en": "drag", "es": "arr", "ca": "ar", "eu": "arr"}


@pytest.mark.parametrize("lang", LANGS)
def test_the_caption_names_the_drag_as_its_arrow_does(lang):
    """001's rolling pair draws v_A and the drag of A in the lever N: the arrow's label is
    v_{ar,A} (ca), and the caption names that very symbol — never "A∈N", a name no label
    on the figure writes."""
    page = rendered("seed_001_rolling_pair", lang)
    caption = next(line for line in page.splitlines() if line.startswith("*") and "v_{" in line
                   and re.search(r"[Aa]\b", line))
    drag = f"v_{{{DRAG[lang]},A}}"
    assert drag in caption and "A∈N" not in caption, caption
    assert f"\\mathrm{{{DRAG[lang]},A}}" in _words(page)       # the figure's label


# a straight body's name "rolls" (in each language's words) — never written of a strand
ROLLS = {"ca": r"\* rodol(a|en)\b", "es": r"\* rueda(n)?\b", "en": r"\* rolls?\b",
         "eu": r"\* solidoa \*[^*]*\* solidoaren gainean errodatzen da"}


def _straight_bodies(name: str, lang: str) -> list[str]:
    """The model's moving straight bodies (a line, no circle), as the page names them."""
    sol, _ = explained(name)
    out = []
    for b, body in sol.model.bodies.items():
        kinds = {type(s).__name__ for s in body.shapes}
        if b != sol.model.frame and "Line" in kinds and not kinds & {"Circle", "Disc"}:
            out.append(sol.model.wording.body(b, lang) or b)
    return out


@over(name=SEEDS, lang=LANGS)
def test_a_straight_body_never_rolls(name, lang):
    """No sentence says a strand, a belt's run or a block's edge rolls: "*tram 2* rodola"."""
    text = rendered(name, lang, drawings=False)
    for body in _straight_bodies(name, lang):
        bare = re.sub(r"^(el|la|els|les|los|las|the|l’|l')\s*", "", body, flags=re.I)
        said = re.findall(rf"\*{re.escape(bare)}{ROLLS[lang]}", text, flags=re.I)
        assert not said, (name, lang, body, said)


def test_the_pulley_blocks_strands_do_not_slip():
    """C5-1.5 in Catalan, by hand from the notes' words ("la politja no llisca al damunt del
    cable"): each moving strand meets its two pulleys, and the sentence's subject is the
    pulley (the round body rolls, eighth round), never the strand: pulleys 1 and 2 on strand 2,
    2 and 3 on strand 3, 3 and 4 on strand 4, 4 on the block's strand 5."""
    text = rendered("seed_c5_1_5_pulley_block", "ca", drawings=False)
    for pulley, strand in (("politja 1", "tram 2"), ("politja 2", "tram 2"), ("politja 2", "tram 3"),
                           ("politja 3", "tram 3"), ("politja 3", "tram 4"), ("politja 4", "tram 4"),
                           ("politja 4", "tram 5")):
        assert f"La *{pulley}* rodola sense lliscar sobre el *{strand}*" in text, (pulley, strand)
        assert f"*{strand}* rodola" not in text, strand
