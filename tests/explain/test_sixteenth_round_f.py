"""Issue 30, sixteenth round (f): the explanations' figures and their captions, over the 19
seeds (docs/explain.md, "Sixteenth round (f)").

- a mechanism figure's caption names every velocity arrow the figure draws, a relative one
  too (001's prismatic pair drew v_B∈N rel. M under a caption naming two arrows);
- a velocity arrow starts at its point (C5-2.2's v_O and v_P ended there): read since the
  twenty-eighth round (g), which made it hold where the ground is in the way too, by
  test_twenty_eighth_round_g.py's `test_a_velocity_starts_at_its_point`;
- the M/D marks of the equations are never a name on the page (C5-1.1's point D);
- a slider's block is drawn at its body's own point (C5-1.5's block K sat halfway down its
  strand) and a strand ends at its end points (C5-1.1's strands ran past G1 and G2).
"""
from __future__ import annotations

import functools
import re

import numpy as np
import pytest

from kinematika.draw import draw
from kinematika.draw.build import build_scene
from kinematika.draw.options import DrawOptions
from kinematika.explain.document import Drawing

from tests.draw.artists import axes, pixel
from .helpers import LANGS, SEEDS, explained, figures, over, rendered

# what each language calls a relative and a drag velocity in a caption's list
RELATIVE = {"en": "relative velocity", "es": "velocidad relativa", "ca": "velocitat relativa",
            "eu": "abiadura erlatiboa"}


def _mechanism_drawings(name: str) -> list[Drawing]:
    _, doc = explained(name)
    return [b for b in doc.blocks() if isinstance(b, Drawing) and b.caption.key == "fig.mechanism"]


def _drawings(name: str) -> list[Drawing]:
    _, doc = explained(name)
    return [b for b in doc.blocks() if isinstance(b, Drawing)]


@functools.lru_cache(maxsize=None)
def _drawn(name: str, k: int) -> tuple:
    """The seed's k-th drawing as `kinematika.draw.draw` draws it with the page's options
    (its matplotlib figure) and its scene, drawn once for the tests of this file that read
    its artists (the figures are let go after them: `_let_go`)."""
    sol, _ = explained(name)
    options = DrawOptions(**_drawings(name)[k].options)
    return draw(sol, options=options), build_scene(sol.inst, sol, options)


@pytest.fixture(scope="module", autouse=True)
def _let_go():
    yield
    _drawn.cache_clear()


def _captions(name: str, lang: str) -> list[str]:
    return re.findall(r"^\*(?:The mechanism|El mecanismo|El mecanisme|Mekanismoa).*\*$", rendered(name, lang),
                      flags=re.M)


@over(name=SEEDS, lang=LANGS)
def test_a_caption_names_every_velocity_arrow_drawn(name, lang):
    """As many velocity arrows as the figure draws, as many the caption names: each relative
    arrow by the words "relative velocity" and its symbol's subscript (B∈N … M)."""
    sol, _ = explained(name)
    captions = _captions(name, lang)
    for d, caption in zip(_mechanism_drawings(name), captions):
        scene = build_scene(sol.inst, sol, DrawOptions(**d.options))
        moving = [v for v in scene.vectors if v.kind == "velocity" and v.magnitude > 1e-9 * sol.inst.scale]
        relative = [v for v in moving if v.relative_to]
        assert caption.count(RELATIVE[lang]) == len(relative), caption
        for v in relative:
            point, _, body = v.ref.partition("@")
            assert re.search(rf"{point}∈{body}\W+(?:rel\.? |erl\.? |/)?{v.relative_to}", caption), caption


def test_the_prismatic_pair_caption_lists_three_arrows():
    """001's prismatic pair draws v_B∈N, v_ar,B and v_B∈N rel. M (by hand: the composition
    v_B∈N = v_B∈M + v_B∈N rel. M, all three nonzero): its caption names the three."""
    for lang, words in (("ca", ("la velocitat de B∈N", "la velocitat d’arrossegament (v_{ar,B})",
                                "la velocitat relativa (v_{B∈N rel M})")),
                        ("eu", ("B∈N puntuaren abiadura", "arrastre-abiadura (v_{arr,B})", "abiadura erlatiboa"))):
        (caption,) = _captions("seed_001_p_pair_coriolis", lang)
        for w in words:
            assert w in caption, caption


def _mark_rows(md: str) -> list[list[str]]:
    """The annotation rows (first and third) of every vector equation's code block."""
    rows = []
    for block in re.findall(r"```\n(.*?)```", md, flags=re.S):
        lines = block.splitlines()
        if len(lines) >= 3:
            rows += [lines[0].split(), lines[2].split()]
    return rows


@over(name=SEEDS, lang=LANGS)
def test_the_marks_are_never_a_name_on_the_page(name, lang):
    """Every page writes the notes' M and D (twentieth round (c): the sixteenth round's words
    mòd/dir were a second notation); a page that names a point or contact M or D says in its
    legend that under a term they are never that point (a body, 001's guide M, is no point:
    twenty-first round (a))."""
    sol, doc = explained(name)
    md = rendered(name, lang)
    named = set(sol.model.points) | set(doc.joints.values())
    named |= set(re.findall(r"^\| ([A-Z][A-Za-z0-9]*) \|", md, flags=re.M))       # the points tables
    clash = named & {"M", "D"}
    marks = {tok for row in _mark_rows(md) for tok in row}
    assert not marks & {"mòd", "mag", "mód", "mod", "norab"}
    if _mark_rows(md) and doc.equations():
        assert marks & {"M", "D"}
        # the sentence after the legend (twenty-fourth round (e))
        assert bool(clash) == bool(re.search(r"(not the point|no es el punto|no és el punt|ez da [MD] puntua)", md)), clash


def test_the_pulley_on_a_cable_writes_the_notes_marks():
    """C5-1.1's equations carry the notes' M and D (ca). Its lowest point, D until the
    twenty-eighth round (b), is P: the legend says nothing of a point D."""
    md = rendered("seed_c5_1_1_pulley_on_cable", "ca")
    assert "M: mòdul conegut; D: direcció coneguda; ?: desconegut;" in md
    assert "no és el punt D" not in md
    assert "D" in {tok for row in _mark_rows(md) for tok in row}


def test_the_block_is_drawn_at_its_point():
    """C5-1.5: strand 5 carries T7 (its contact with pulley 4) and the block K; the block's
    rectangle is centred on K = (8r, −6r), not on the midpoint (8r, −3r)."""
    for k in range(len(_drawings("seed_c5_1_5_pulley_block"))):
        fig, scene = _drawn("seed_c5_1_5_pulley_block", k)
        blocks = [p for p in axes(fig).patches if (p.get_gid() or "").startswith("joint:")
                  and len(p.get_path().vertices) >= 4]
        k, t7 = (np.asarray(scene.point(n), dtype=float)[:2] for n in ("K", "T7"))   # drawn at r = 0.1
        assert np.linalg.norm(k - t7) == pytest.approx(0.6, rel=1e-9)              # 6r below T7
        centres = [p.get_path().vertices[:4].mean(axis=0) for p in blocks]
        assert any(np.linalg.norm(c - k) <= 3 * pixel(fig) for c in centres), (centres, k)


@over(name=SEEDS)
def test_a_strand_ends_at_its_points(name):
    """A moving line body that guides nothing (a cable's strand) is drawn from its first point
    or contact to its last, never past them (C5-1.1's strands ran past G1 and G2): read off the
    first figure's line marks as the page drew them (`figures`), 2 px at most."""
    sol, _ = explained(name)
    for options, marks, _, transform in figures(name, "en")[:1]:
        scene = build_scene(sol.inst, sol, DrawOptions(**options))
        for body in scene.bodies.values():
            if body.frame or not any(s.kind == "line" for s in body.shapes):
                continue
            if any(j.a == body.name and (j.kind.slides or j.kind.guides_point) for j in scene.joints):
                continue
            ends = [np.asarray(m.points, float) for m in marks if m.kind == "line" and m.gid == f"shape:{body.name}"]
            if not ends or len(ends[0]) != 2:
                continue                                           # a belt's loop
            places = list(body.points.values()) + [j.contact for j in scene.joints
                                                   if body.name in (j.a, j.b) and j.contact is not None]
            for end in ends[0]:
                gaps = [np.linalg.norm(transform.transform(end) - transform.transform(np.asarray(p, float)[:2])) for p in places]
                assert min(gaps) <= 2, (body.name, end)
