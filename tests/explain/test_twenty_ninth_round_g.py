"""Issue 30, twenty-ninth round (g): crowded mechanism and centre figures, as the sixth reading
saw them (docs/explain.md, "Twenty-ninth round (g)").

C5-E.6's drive was a few millimetres across (all four readers): T1, T2, H, C, P, the chain's
runs and five names round the rear hub and the crank, "P" 100 px from the pedal on a leader,
v_P named without its value. The model's draw_at draws the drive 1.4 times as large; the
asked v_P carries its formula (`draw.names.ANSWER_CHARS`). C5-E.1's "J" and "I_wheels", C5-E.4's
"P" and "I_upper", were two labels jammed on one dot: a centre at a named point is written once,
"I_wheels = J".
"""
from __future__ import annotations

import numpy as np

from .helpers import NOTES_SEEDS, RECORDED_LANGS, figures, over

BIKE = "seed_c5_e6_bicycle"
CENTRE_GIDS = ("icr:", "centre:")
POINT_GIDS = ("point:", "contact:")


def _px() -> float:
    """Display pixels per point of the recorded figures (matplotlib's figure dpi / 72)."""
    import matplotlib
    return matplotlib.rcParams["figure.dpi"] / 72


def _scale(transform) -> float:
    """Display pixels per model unit along x (the figures are drawn at equal scale)."""
    a, b = transform.transform(np.array([[0.0, 0.0], [1.0, 0.0]]))
    return float(np.linalg.norm(b - a))


@over(lang=RECORDED_LANGS)
def test_the_bicycles_drive_is_drawn_large(lang):
    """The chainring's circle (radius R at draw_at) is at least 1/16 of the wheelbase plus a
    wheel's diameter, the bicycle's width (it was R/(e + 2 R_roda) = 0.1/2.05 = 1/20.5), and at
    least 15 points across on the page; the sprocket (r) half of it, beside the hub."""
    import yaml

    from .helpers import EXAMPLES
    at = yaml.safe_load((EXAMPLES / f"{BIKE}.yaml").read_text())["draw_at"]
    assert at["R"] / (at["e"] + 2 * at["R_roda"]) >= 1 / 16
    assert at["R"] == 2 * at["r"]
    assert at["L"] > at["R"]                                   # the pedal beyond the chainring's rim
    assert at["R_roda"] + at["r"] - at["R"] - at["L"] > 0      # and above the ground
    for _, marks, _, transform in figures(BIKE, lang):
        rings = [m for m in marks if m.kind == "circle" and m.gid == "shape:chainring"]
        assert rings
        assert rings[0].r * _scale(transform) / _px() >= 15, lang


@over(lang=RECORDED_LANGS)
def test_the_pedals_letter_sits_at_the_pedal(lang):
    """"P" is set by the pedal's end (its box's centre within 36 points of P: a short leader
    past v_P's start), not next to the rear hub at the end of a long leader (69 points on main
    before this round), on the page's first figure, the mechanism's."""
    for _, _, placed, transform in figures(BIKE, lang)[:1]:
        p = next(p for p in placed if p.label.gid == "point:P")
        anchor = transform.transform(np.asarray(p.label.anchor, float))
        centre = (p.box[:2] + p.box[2:]) / 2
        assert np.linalg.norm(centre - anchor) / _px() <= 36, lang


@over(lang=RECORDED_LANGS)
def test_the_asked_v_p_carries_its_value(lang):
    """v_P, asked, is labelled with its formula, v(R·R_wheel − L·r)/(R·R_wheel) (the notes'
    v − L (r/R) v/R_wheel over one denominator), not by its name alone."""
    found = [p for _, _, placed, _ in figures(BIKE, lang) for p in placed if p.label.gid.startswith("velocity:P@")]
    assert found, lang
    for p in found:
        text = p.label.text
        assert " = " in text and r"\dfrac" in text, text
        assert "L r" in text and "R R_{" in text, text


@over(name=NOTES_SEEDS, lang=RECORDED_LANGS)
def test_a_centre_at_a_named_point_is_written_once(name, lang):
    """No instant centre has a label of its own on the dot of a named point (or the page's
    contact): the point's label says both, "I_wheels = J" (C5-E.1's J, C5-E.4's P)."""
    bad = []
    for _, _, placed, transform in figures(name, lang):
        points = [transform.transform(np.asarray(p.label.anchor, float)) for p in placed
                  if p.label.gid.startswith(POINT_GIDS)]
        for p in placed:
            if not p.label.gid.startswith(CENTRE_GIDS):
                continue
            at = transform.transform(np.asarray(p.label.anchor, float))
            if any(np.linalg.norm(at - q) < 0.5 for q in points):
                bad.append(p.label.text)
    assert not bad, bad


@over(name=["seed_c5_e1_cavity", "seed_c5_e4_upper_wheel"], lang=RECORDED_LANGS)
def test_the_contacts_centre_is_named_with_its_letter(name, lang):
    """C5-E.1's wheels and C5-E.4's upper wheel turn about their contact with the ground: the
    contact's label reads "I_… = J" (E.1) or "I_… = P" (E.4), one label."""
    letter = {"seed_c5_e1_cavity": "J", "seed_c5_e4_upper_wheel": "P"}[name]
    found = [p.label.text for _, _, placed, _ in figures(name, lang) for p in placed
             if p.label.gid.endswith(f":{letter}") and p.label.gid.startswith(POINT_GIDS)]
    assert any(t.startswith("$I_{") and t.endswith(f" = {letter}") for t in found), found


def test_a_centre_is_merged_into_the_letter_only_at_its_point():
    """The merge rule itself (`draw.marks._named_once`): a centre's names go into the label of
    a point at the same place, and into no label elsewhere."""
    from kinematika.draw.marks import _named_once

    class Ctx:
        size = 1.0
        marks: list = []

    from kinematika.joints.symbols import Mark
    j = Mark("text", [[0.0, 1.0]], text="J", gid="contact:J")
    c = Mark("text", [[0.5, 0.0]], text="C", gid="point:C")
    Ctx.marks = [j, c]
    assert _named_once(Ctx, np.array([0.0, 1.0]), "$I_{w}$")
    assert j.text == "$I_{w}$ = J" and c.text == "C"
    assert not _named_once(Ctx, np.array([0.2, 0.2]), "$I_{x}$")
