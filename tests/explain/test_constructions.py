"""The constructions the notes draw: a vehicle's centre where its wheels' axles meet, the
triad's Assur point where the lines of two of its links meet."""
from __future__ import annotations

import pytest
import sympy

from kinematika.draw.names import formula
from kinematika.explain.document import CentreNote, Figure, Msg

from .helpers import ALL, explained


def notes(doc) -> dict:
    return {frozenset(b.pair): b for b in doc.blocks() if isinstance(b, CentreNote) and b.how != "check"}


def placed_in_step(doc, body: str):
    """The velocity step's sentence that places `body`'s centre where two lines meet (the
    centres section then refers to it: thirteenth round (c), a construction said once)."""
    return next(b for b in doc.blocks() if isinstance(b, Msg) and b.key == "vehicle.centre"
                and b.args["body"].text == body)


def test_tricycle_centre_by_the_axles():
    """The chassis' centre: the rear axle (perpendicular to wheel j3 at C1) and the
    perpendicular to v_F at F (the front wheel's axle), said in the step, referred to after."""
    _, doc = explained("seed_c5_2_1_tricycle")
    said = placed_in_step(doc, "chassis")
    assert [said.args["first"].key, said.args["second"].key] == ["vehicle.line.wheel", "vehicle.line.velocity"]
    assert said.args["first"].args["joint"].text == "j3"
    assert frozenset(("ground", "chassis")) not in notes(doc)
    assert any(isinstance(b, Msg) and b.key == "centres.found_above_step" and b.args["step"] == 1
               for b in doc.blocks())


def test_trailer_centre_by_its_axle_and_the_hitch():
    _, doc = explained("tractor_trailer")
    said = placed_in_step(doc, "trailer")
    assert said.args["first"].args["joint"].text == "trailer_wheels"
    assert said.args["second"].args["point"].text == "H"


def test_triad_assur_point_drawn():
    """S where AB and O4C meet: A (0.1, 0.1), B (0.25, 0.2), O4 (0.45, 0), C (0.4, 0.15);
    0.1 + 0.15 t = 0.45 − 0.05 u and 0.1 + 0.1 t = 0.15 u give t = 19/11, S = (0.35909, 0.27273)."""
    _, doc = explained("triad_six_bar")
    figs = [b for b in doc.blocks() if isinstance(b, Figure) and b.caption.key == "fig.assur"]
    assert len(figs) == 1
    s = next(p for name, p, _ in figs[0].points if name == "S")
    t = 19 / 11
    assert s == pytest.approx((0.1 + 0.15 * t, 0.1 + 0.1 * t))
    assert len(figs[0].lines) == 2 and all(q == pytest.approx(s) for _, q in figs[0].lines)


def test_absolute_values_in_figure_labels():
    L, s, v = sympy.symbols("L s v0", positive=True)
    label = formula(sympy.sqrt(2) * v * sympy.Abs(L - s) / (2 * L), 0.943)
    assert "|" in label and "≈" not in label and "left" not in label


@pytest.mark.parametrize("name", ALL)
def test_every_centre_a_note_names_is_explained(name):
    """A centre found from others by Aronhold–Kennedy's lines names centres (I_12, I_23)
    that the step lists too. Found from the perpendiculars to velocities, or from speeds
    along one line, it names points (O, A1, N), and the centres about which those points
    turn relative to the reference: those are listed; the relative centres at the points are
    not (ninth round: a listed centre nothing uses adds nothing)."""
    sol, doc = explained(name)
    if sol.space.dim != 2:
        return
    told = notes(doc)
    for note in told.values():
        if note.how in ("kennedy", "proportional"):
            a, b = note.pair
            for k in note.via:
                assert frozenset((a, k)) in told, (note.pair, k)
                if note.how == "kennedy" and not note.perps:
                    assert frozenset((k, b)) in told, (note.pair, k)
