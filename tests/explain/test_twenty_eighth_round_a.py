"""Issue 30, twenty-eighth round (a): the figure of the three coincident points at a contact
(docs/explain.md, "Twenty-eighth round (a)").

Four teachers (en, es, ca, eu) who graded C5-1.8's page said the same: the page has no figure
of the three points that coincide at the contact J. The notes draw the mechanism at the
instant with J and the three points there — the wheel's point J∈roda, the ground's J∈terra and
the geometric contact point J^{geom}, a point of neither body that moves along both profiles —
with their velocities (accelerations) as arrows, named as the notes name them.

Every page whose model asks a rolling contact's points (`contact`) now draws that figure after
each level of its contact section. The arrows are read here against values derived by hand
from C5-1.8's data (below), never against numbers the drawing produced; the figure rules of
the earlier rounds (tests/explain) read the new figures with the others.
"""
from __future__ import annotations

import math
import re

import numpy as np

from .helpers import LANGS, SEEDS, explained, over, rendered
from .helpers import figures
from .test_twenty_seventh_round_f import arrows_of

C5_1_8 = "seed_c5_1_8_contact_points"

# C5-1.8 at its draw_at, r = 0.1 and ω₀ = 2 (the figure's numbers). By hand, from the model's
# data: the fixed cylinder of radius 2r about O = (0, 0), the wheel of radius r on top of it,
# C = (0, 3r), turning clockwise at ω₀ and rolling without slip, so J = (0, 2r).
#  - J∈terra, a point of the fixed body: v = 0, a = 0.
#  - J∈roda: the wheel's instant centre (no slip), v = 0. C runs on the circle of radius 3r
#    about O at |v_C| = ω₀·r (J the instant centre), so a_C = (ω₀ r)² / 3r = r ω₀²/3 towards O
#    (ω₀ constant: no tangential part); a_J∈roda = a_C + ω₀²·r towards C (J → C is up):
#    −r ω₀²/3 + r ω₀² = (2/3) r ω₀², up, towards C.
#  - J^{geom}: on the bar OC at OJ/OC = 2/3; the bar turns at |v_C| / OC = ω₀/3 (constant),
#    clockwise, as C moves to the right on top: v = (2/3)·3r·ω₀/3 = (2/3) r ω₀ to the right,
#    a = 2r·(ω₀/3)² = (2/9) r ω₀² towards O, down.
R, W0 = 0.1, 2.0
J = (0.0, 2 * R)
BY_HAND = {
    "velocity": {"J@ground": (0.0, 0.0), "J@wheel": (0.0, 0.0), "J:geom": (2 / 3 * R * W0, 0.0)},
    "acceleration": {"J@ground": (0.0, 0.0), "J@wheel": (0.0, 2 / 3 * R * W0 ** 2),
                     "J:geom": (0.0, -2 / 9 * R * W0 ** 2)},
}


def asks_contacts(name: str) -> list[str]:
    """The rolling contacts whose three points the seed's model asks (`contact` questions on a
    planar model's rolling joint): read off the model, not the page."""
    sol, _ = explained(name)
    model = sol.model
    if model.dimension != 2:
        return []
    return [q.target for q in model.questions if q.kind == "contact" and model.joint(q.target).kind.rolls]


def contact_drawings(name: str) -> list:
    """The drawings of the page's contact section."""
    from kinematika.explain.document import Drawing

    _, doc = explained(name)
    sec = next((s for s in doc.sections if s.title.key == "sec.contact"), None)
    return [] if sec is None else [b for b in sec.blocks if isinstance(b, Drawing)]


def coincident_figures(name: str, lang: str) -> list:
    """The figures of the coincident points as drawn (options, marks, placements, transform)."""
    return [f for f in figures(name, lang) if f[0].get("coincident")]


def section_text(page: str, title: str) -> str:
    """The text of the page's section `title` up to the next heading."""
    start = page.index(f"## {title}")
    rest = page[start + 3:]
    end = rest.find("\n## ")
    return rest if end < 0 else rest[:end]


@over(name=SEEDS, lang=LANGS)
def test_a_page_asking_a_contact_draws_its_three_points(name, lang):
    """A page whose model asks a rolling contact's three points draws, in its contact section,
    one figure of them after each level (velocities, then accelerations), in every language:
    the section's Markdown has the two images with their captions, which name the three
    points."""
    asked = asks_contacts(name)
    drawings = contact_drawings(name)
    assert len(drawings) == 2 * len(asked), (asked, [d.caption.key for d in drawings])
    if not asked:
        return
    assert [d.options["coincident"] for d in drawings] == ["velocity", "acceleration"] * len(asked)
    assert all(d.caption.key == "fig.contact" for d in drawings)
    page = rendered(name, lang)
    from kinematika.explain.catalogue import catalogue

    title = catalogue(lang).format("sec-contact", {})
    text = section_text(page, title)
    images = re.findall(r"!\[[^\]]*\]\[fig-\d+\]", text)
    assert len(images) == 2 * len(asked), images
    captions = [line for line in text.splitlines() if line.startswith("*") and "^{geom}" in line]
    assert len(captions) == 2 * len(asked), captions


@over(name=SEEDS, lang=LANGS)
def test_the_caption_names_what_is_drawn(name, lang):
    """Each figure's caption names the arrows it draws and the zero vectors written beside the
    contact, as many as the figure has: C5-1.8's velocities, one arrow (v_J^geom) and two
    zeros; its accelerations, two arrows and one zero. Read against the drawn marks."""
    drawings = contact_drawings(name)
    if not drawings:               # no contact asked: nothing drawn to read (and no page redrawn for it)
        return
    for d, (_, marks, placed, _) in zip(drawings, coincident_figures(name, lang), strict=True):
        drawn = arrows_of(marks)
        zeros = [p for p in placed if p.label.gid.startswith(d.options["coincident"] + ":")
                 and re.search(r"= 0$", p.label.text)]
        assert d.caption.args["moving"] == len(drawn), (d.caption.args, [m.gid for _, _, m in drawn])
        assert d.caption.args["still"] == len(zeros), (d.caption.args, [p.label.text for p in zeros])
        assert len(drawn) + len(zeros) == 3


@over(lang=LANGS)
def test_c5_1_8_arrows_are_the_vectors_derived_by_hand(lang):
    """C5-1.8's two figures draw at J, read off their marks: the velocities — no arrow for
    J∈terra and J∈roda (zero, written "= 0" beside J) and v_J^geom = (2/3) r ω₀ to the right;
    the accelerations — a_J∈roda = (2/3) r ω₀² up towards C, a_J^geom = (2/9) r ω₀² down
    towards O, three times shorter (one scale), and a_J∈terra = 0 written beside J."""
    found = coincident_figures(C5_1_8, lang)
    assert [f[0]["coincident"] for f in found] == ["velocity", "acceleration"]
    for options, marks, placed, _ in found:
        kind = options["coincident"]
        arrows = {m.about["ref"]: (s, e, m) for s, e, m in arrows_of(marks)}
        expected = BY_HAND[kind]
        moving = {ref for ref, v in expected.items() if math.hypot(*v) > 0}
        assert set(arrows) == moving, (kind, sorted(arrows))
        lengths = {}
        for ref in moving:
            s, e, m = arrows[ref]
            d = e - s
            want = np.array(expected[ref])
            # the arrow starts (or, off a bar, ends) at J, along the vector derived by hand
            assert min(np.linalg.norm(s - J), np.linalg.norm(e - J)) < 1e-9, (ref, s, e)
            assert abs(d @ want / (np.linalg.norm(d) * np.linalg.norm(want)) - 1) < 1e-9, (ref, d, want)
            assert math.isclose(m.about["magnitude"], np.linalg.norm(want), rel_tol=1e-9), (ref, m.about)
            lengths[ref] = np.linalg.norm(d)
        if kind == "acceleration":           # one scale: (2/3) / (2/9) = 3
            assert math.isclose(lengths["J@wheel"] / lengths["J:geom"], 3, rel_tol=1e-6), lengths
        zero = {p.label.gid.split(":", 1)[1] for p in placed
                if p.label.gid.startswith(kind + ":") and re.search(r"= 0$", p.label.text)}
        assert zero == set(expected) - moving, (kind, zero)


@over(lang=LANGS)
def test_c5_1_8_labels_are_the_notes_names(lang):
    """The labels write the three points as the text does: the point of each body by the body's
    subscript (v_J∈roda, v_J∈terra in Catalan, as the page's equations), and J^{geom} with its
    mark, readable; the page writes the same symbols."""
    from kinematika.draw.names import body_labels

    sol, _ = explained(C5_1_8)
    labels = body_labels(sol.model, lang)
    for options, _, placed, _ in coincident_figures(C5_1_8, lang):
        letter = "v" if options["coincident"] == "velocity" else "a"
        texts = {p.label.gid.split(":", 1)[1]: p.label.text for p in placed
                 if p.label.gid.startswith(options["coincident"] + ":")}
        for body in ("ground", "wheel"):
            assert texts[f"J@{body}"].startswith(f"${letter}_{{\\mathrm{{J}}{{\\in}}\\mathrm{{{labels[body]}}}}}$"), texts
        # J^{geom}: "geom" raised after the subscript J, at its size (a superscript of the
        # subscript is shrunk twice by mathtext, unreadable)
        assert texts["J:geom"].startswith(f"${letter}_{{\\mathrm{{J}}}}{{}}^{{\\mathrm{{geom}}}}$"), texts
    page = rendered(C5_1_8, lang)
    for body in ("ground", "wheel"):
        assert f"v_{{J∈{labels[body]}}}" in page and f"a_{{J∈{labels[body]}}}" in page


def test_any_model_asking_a_contact_gets_the_figure():
    """Not a rule of C5-1.8's name: the other examples that ask a rolling contact's points in
    the plane (a wheel on a road, 001's roller on its lever) get the same two figures."""
    from kinematika.explain.document import Drawing

    for name in ("wheel_rolling", "seed_001_rolling_pair"):
        _, doc = explained(name)
        drawn = [b for b in doc.blocks() if isinstance(b, Drawing) and b.options.get("coincident")]
        assert [d.options["coincident"] for d in drawn] == ["velocity", "acceleration"], name
