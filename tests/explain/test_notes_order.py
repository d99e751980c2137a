"""The notes' worked examples explained in the notes' order and method (issue 30, second
round): what the notes say once is said once, what they find first comes first, and nothing
the questions do not need is worked out. Each test states what the notes do (seed 002, the
Catalan notes C5; seed 001, the Basque slides) and checks the structure of the
explanation against it: the order of its sections and steps, which equations appear and
which quantities are derived, never the numbers the code produced."""
from __future__ import annotations

import re

import pytest

from kinematika.explain.document import GEOM_MARK
from kinematika.explain.document import CentreNote, Derived, Equation, Msg, Section

from tests.conftest import sampled

from .helpers import blocks, explained, num, rendered, section




def steps(doc, key: str = "sec.velocities") -> list[Section]:
    return [b for b in section(doc, key).blocks if isinstance(b, Section)]


def turning_bodies(eq: Equation) -> set[str]:
    """The bodies an equation turns with (ω × r, α × r, ω² r: the first symbol of a term's
    formula) and those whose material points it names (J8∈planet2)."""
    out = set()
    for t in [eq.target] + [t for side in eq.sides for t in side]:
        if t.kind in ("rotation", "tangential", "normal") and t.how and getattr(t.how[0], "base", "") in "ωα":
            out.add(t.how[0].sub)
        if "∈" in t.sym.sub:
            out.add(t.sym.sub.split("∈")[1].split("/")[0])
    return out


# -- what the notes say once (eighth round: each planet asked is worked with its equations) ---------------------------
@pytest.mark.parametrize("name,original,repeated", [
    ("seed_c5_1_4_epicyclic", "planet1", ["planet2"]),     # C5-1.4: three identical planets, the second asked
    ("seed_c5_e2_gear_change", "planet1", ["planet2"]),    # C5-E.2: the two planets, 2Ω each
])
def test_identical_planets_are_each_worked(name, original, repeated):
    """The sixth reader wanted the step written, not "in the same way": each asked planet
    turns in an equation of its own, as the first does, and gets its own step."""
    _, doc = explained(name)
    velocities = blocks(section(doc, "sec.velocities"))
    equations = [b for b in velocities if isinstance(b, Equation)]
    for b in [original] + repeated:
        assert any(b in turning_bodies(eq) for eq in equations), b


def test_the_centres_section_holds_what_is_asked():
    """C5-1.4 asks the instant centre of one planet: the notes place it from the centres of
    the carrier and the ring (both at O) and the points A1 and Q; "el CIR de cada rodeta s'ha
    de trobar entre els dos": the other planets, of its kind, are found the same way, each from
    its own centre in its own step (round 27b), and the answers list only the asked one. The
    planet's centres relative to the carrier and the ring (at A1, at Q) are named as points in
    its note, not listed as lines of their own (ninth round). The planet's note stands in the
    velocity step, after the equations that find v_A1 and v_Q (round 20e), at the head of the
    planet's own step (round 22a); the centres section says where it is placed."""
    _, doc = explained("seed_c5_1_4_epicyclic")
    centres = blocks(section(doc, "sec.centres"))
    assert any(getattr(b, "key", "") == "centres.placed_in_step" and str(b.args["centre"].sub) == "ground,planet1"
               for b in centres)
    notes = [b for b in centres + blocks(section(doc, "sec.velocities")) if isinstance(b, CentreNote)]
    pairs = {frozenset(n.pair) for n in notes}
    assert frozenset(("ground", "planet1")) in pairs
    assert {pair for pair in pairs if pair & {"planet2", "planet3"}} == {frozenset(("ground", "planet2")),
                                                                        frozenset(("ground", "planet3"))}
    answers = rendered("seed_c5_1_4_epicyclic", "en", drawings=False).split("## Answers")[1]
    assert "instant centre of *planet 1*" in answers
    assert "instant centre of *planet 2*" not in answers and "instant centre of *planet 3*" not in answers
    placed = next(n for n in notes if frozenset(n.pair) == frozenset(("ground", "planet1")))
    assert {frozenset(("ground", k)) for k in placed.via} <= pairs
    assert not {frozenset((k, "planet1")) for k in placed.via} & pairs
    assert [w[0] for w in placed.witnesses] == ["A1", "Q"]     # the ring contact j10 (J, K, N, Q …)


# -- the notes' order: the centres first where the notes find the velocities from them ----------------------------
@pytest.mark.parametrize("name,body", [
    ("seed_c5_1_1_pulley_on_cable", "pulley"),      # C5-1.1: the pulley's centre where the strands meet
    ("seed_c5_1_2_bar_on_inclined_wheels", "OJ"),   # C5-1.2: OJ's from OQ's and the vertical through J
    ("seed_c5_1_3_bar_in_sleeve", "bar"),           # C5-1.3: the bar's on OQ's line and the normal through J
    ("seed_c5_e3_wheels_with_rod", "rod"),          # C5-E.3: the rod's where the perpendiculars meet
    ("seed_c5_1_4_epicyclic", "planet1"),           # C5-1.4: the planet's from the data's speeds of A1 and J10
])
def test_the_centres_come_first_and_give_the_velocities(name, body):
    """The notes place these centres from the joints alone and then write each velocity as
    a rotation about its centre: the centres' section comes before the velocities, and the
    body's ω is read off an equation that starts at its centre (v_Q = v_I + ω × IQ); no
    check of the centre by the velocities follows (it would be circular)."""
    sol, doc = explained(name)
    keys = [s.title.key for s in doc.sections]
    assert keys.index("sec.centres") < keys.index("sec.velocities")
    assert not any(isinstance(b, CentreNote) and b.how == "check" for s in doc.sections for b in blocks(s))
    found = [d for d in blocks(section(doc, "sec.velocities")) if isinstance(d, Derived) and d.body == body
             and d.kind == "omega" and d.source is not None]
    assert found, f"{body}: no ω read off an equation"
    eq = next(e for e in blocks(section(doc, "sec.velocities")) if isinstance(e, Equation)
              and any(t is found[0].source for side in e.sides for t in side))
    side = next(side for side in eq.sides if found[0].source in side)
    site = next(m for m in blocks(section(doc, "sec.velocities")) if isinstance(m, Msg)
                and m.key.startswith("centre.site") and m.args["centre"].sub == f"{sol.model.frame},{body}")
    assert side[0].sym.sub == site.args["point"].text and all(x == 0 for x in side[0].value)


@pytest.mark.parametrize("name", ["seed_c5_e2_gear_change", "seed_c5_e1_cavity"])
def test_centres_at_joints_come_first(name):
    """C5-E.2 (the arm's and the ring's centres at O, the planets' at their contacts with
    the fixed sun) and C5-E.1 (the wheels' at the contact with the track): the notes give
    these centres first, then the rates from them."""
    _, doc = explained(name)
    keys = [s.title.key for s in doc.sections]
    assert keys.index("sec.centres") < keys.index("sec.velocities")


@pytest.mark.parametrize("name", ["seed_001_r_pairs", "seed_c5_1_6_belt", "four_bar"])
def test_velocities_first_where_the_notes_do(name):
    """The slides ask no centre; C5-1.6 finds the pulley's rate by composing from the arm and
    its centre from that rate; a four-bar's coupler comes from its dyad's equation (its
    centre follows): velocities first, the centres (if any) after them. (C5-1.4's planet is
    no longer here: the speeds its centre comes from are the data's, ω·2r and −ω·3r, so the
    notes place the centre first and read ω off it: `test_the_centres_come_first_…`.)"""
    _, doc = explained(name)
    keys = [s.title.key for s in doc.sections]
    assert "sec.centres" not in keys or keys.index("sec.centres") > keys.index("sec.velocities")


@pytest.mark.parametrize("name,body", [
    ("seed_c5_1_7_semicylinder", "wheel"),     # C5-1.7: "ja que J és el CIR", v_C and v_P at once
    ("seed_c5_1_8_contact_points", "wheel"),
    ("seed_c5_e1_cavity", "wheels"),
])
def test_a_wheel_on_a_fixed_body_turns_about_its_contact(name, body):
    """A wheel rolling on a fixed body has its contact at rest: the notes take it as the
    wheel's centre. The explanation says so in a sentence (v_J∈wheel = 0) and starts the
    wheel's velocities there; it never writes the empty equation v_J∈wheel = v_J∈ground."""
    sol, doc = explained(name)
    velocities = blocks(section(doc, "sec.velocities"))
    # said by the rolling sentence, or by the centre the CIR section placed (seventeenth round (a))
    said = [i for i, b in enumerate(velocities) if isinstance(b, Msg) and b.key in ("rolling.centre", "centre.site")]
    assert len(said) == 1
    frame = sol.model.frame
    for i, eq in enumerate(velocities):
        if not isinstance(eq, Equation):
            continue
        for side in eq.sides:
            assert not (len(side) == 1 and side[0].sym.sub.endswith(f"∈{frame}")), "v_J∈b = v_J∈ground"
        if any(t.sym.sub.endswith(f"∈{body}") and t.kind == "point" for side in eq.sides for t in side[:1]):
            assert i > said[0]


# the bicycle by default, both in a deep run (the same sentence and equations)
@pytest.mark.parametrize("name,body,points", sampled([
    ("seed_c5_e6_bicycle", "frame", ["C"]),             # C5-E.6: "el quadre només es trasllada"
    ("seed_c5_e5_unequal_wheels", "chassis", ["B", "C"]),
], lambda case: case[0] == "seed_c5_e6_bicycle"))
def test_a_body_that_does_not_turn_moves_its_points_alike(name, body, points):
    """Once ω of the chassis is found zero, its other points move as the one known: the
    explanation says the body translates and writes v_K = v_H, not v_K = v_H + 0 × HK."""
    _, doc = explained(name)
    velocities = blocks(section(doc, "sec.velocities"))
    # "translation.points" once the translation is stated before (the eleventh round: both
    # wheels' centres on parallel lines, said before the equations)
    assert any(isinstance(b, Msg) and b.key in ("translation.same", "translation.points")
               and b.args["body"].text == body for b in velocities)
    for p in points:
        eq = next(e for e in velocities if isinstance(e, Equation) and e.target.sym.sub.split("∈")[0] == p)
        assert len(eq.sides) == 1 and len(eq.sides[0]) == 1 and eq.sides[0][0].kind == "point"


def test_the_chain_is_not_worked_where_nothing_asks_it():
    """C5-E.6 asks the pedals: the notes use the chain only through ρ ω = ρ ω seen from the
    frame. No equation, no no-slip sentence, no geometric point of the chain's contacts
    (T1, T2: joints j7, j8) is written at either level."""
    from kinematika.draw.names import contact_names

    sol, doc = explained("seed_c5_e6_bicycle")
    chain = {contact_names(sol.model, sol)[j] for j in ("j7", "j8")}
    assert chain == {"T1", "T2"}
    for key in ("sec.velocities", "sec.accelerations"):
        for b in blocks(section(doc, key)):
            if isinstance(b, Equation):
                assert not any(c in re.split(r"[∈\-/ ]", t.sym.sub) for c in chain
                               for t in [b.target] + [t for side in b.sides for t in side]), b.target.sym
            if isinstance(b, Msg) and "joint" in b.args:
                assert b.args["joint"].text not in ("j7", "j8"), b.key


def test_the_bar_slides_on_its_support_one_way_round():
    """C5-1.3: the bar slides on the support; its relative velocity v_Q∈bar/support is found
    in the velocities (the support seen as the moving frame), the Coriolis term of the
    accelerations uses that same quantity, and the composition of E reads its relative part
    off it (the bar does not turn on the support)."""
    _, doc = explained("seed_c5_1_3_bar_in_sleeve")
    slides = {(b.level, t.sym.sub) for s in ("sec.velocities", "sec.accelerations") for b in blocks(section(doc, s))
              if isinstance(b, Equation) for side in b.sides for t in side if t.kind == "slide"}
    assert ("v", "Q∈bar/support") in slides and ("a", "Q∈bar/support") in slides
    assert not any(sub.endswith("support/bar") for _, sub in slides)
    said = [b for b in blocks(section(doc, "sec.composition")) if isinstance(b, Msg)
            and b.key in ("composition.slide_seen", "composition.slide_seen_step")]
    assert [m.args["seen"].sub for m in said] == ["Q∈bar/support", "Q∈bar/support"]
    assert [m.args.get("step") for m in said] == [2, 2]       # the bar and support are Step 2


def test_a_slider_given_on_a_fixed_guide_needs_no_equation():
    """Seed 001's rolling pair: the slider's datum is v_A along the fixed guide; the slides
    write nothing more for it (v_A = v_A∈1 + v_A∈S/1 would only repeat the datum)."""
    _, doc = explained("seed_001_rolling_pair")
    for key in ("sec.velocities", "sec.accelerations"):
        first = steps(doc, key)[0]
        assert not any(isinstance(b, Equation) for b in first.blocks), key
        assert any(isinstance(b, Msg) and b.key.startswith("driver.") for b in first.blocks)


def test_no_slip_between_moving_bodies_is_a_sentence():
    """C5-1.5: each strand takes the speed of the pulley before it at their contact ("aquesta
    velocitat es transmet a tots els punts del segon tram": j2, j5, j7), and the block leaves
    the last pulley at the pulley's speed (j10); no slip says so in the contact's sentence,
    never as an equation of one term."""
    sol, doc = explained("seed_c5_1_5_pulley_block")
    velocities = blocks(section(doc, "sec.velocities"))
    for eq in (b for b in velocities if isinstance(b, Equation)):
        for side in eq.sides:
            one = len(side) == 1 and side[0].kind == "point"
            assert not (one and "∈" in side[0].sym.sub and "∈" in eq.target.sym.sub
                        and side[0].sym.sub.split("∈")[0] == eq.target.sym.sub.split("∈")[0]), eq.target.sym
    said = [b for b in velocities if isinstance(b, Msg) and b.key == "rolling.same"]
    assert not [j for j in (m.args["joint"].text for m in said) if j in ("j2", "j5", "j7", "j10")]
    # there the strand's (the block's) point and the pulley's share one label: no slip is said
    # without an equality, v_T1 = v_{T1∈pulley1} is written nowhere and the strand's points then
    # have v_{T1∈pulley1} (sixteenth round (b), `material.material_contacts`)
    plain = [b for b in velocities if isinstance(b, Msg) and b.key == "rolling.noslip"]
    assert [j for j in (m.args["joint"].text for m in plain) if j in ("j2", "j5", "j7", "j10")] == \
        ["j2", "j5", "j7", "j10"]
    # the others say the equality a pulley's equation uses, v_T2∈pulley2 = v_T2 (thirteenth
    # round (c): each side of v_B = v_A + v_BA one body's), each of a different contact
    others = [m.args["joint"].text for m in said if m.args["joint"].text not in ("j2", "j5", "j7", "j10")]
    assert others and len(set(others)) == len(others)
    assert all(m.args["sym"].sub.startswith("T") for m in said if m.args["joint"].text in others)


# the articulated bar by default, both in a deep run (the same remark after the same zero)
@pytest.mark.parametrize("name,body", sampled([("seed_c5_2_2_articulated", "S1"), ("seed_c5_e4_upper_wheel", "chassis")],
                                              lambda case: case[0] == "seed_c5_2_2_articulated"))
def test_a_translation_says_why_after_its_zero(name, body):
    """ω = 0 of a body that translates reads "ω_2 = 0 (it translates)", the reason after the
    value, never "ω_2 = (it translates) = 0"."""
    _, doc = explained(name)
    rates = [d for d in blocks(section(doc, "sec.velocities")) if isinstance(d, Derived) and d.body == body]
    assert rates and all(not d.how and d.remark is not None for d in rates)


@pytest.mark.parametrize("name,centre,fixed_circle", [
    ("seed_c5_1_7_semicylinder", "C", True),     # C5-1.7: C on a circle of radius 3r about O
    ("seed_c5_1_8_contact_points", "C", True),   # C5-1.8: C's (1/3) r ω0² towards the cylinder's centre
    ("seed_c5_e1_cavity", "C", True),            # C5-E.1: C on a circle of radius 2R about O (a_C from Step 1: path.found)
    ("seed_c5_e6_bicycle", "H", False),          # C5-E.6: the hub on a straight line, α = v̇/R_roda
])
def test_a_wheel_on_a_fixed_body_is_accelerated_through_its_centre(name, centre, fixed_circle):
    """The notes reach the acceleration of a wheel rolling on a fixed profile through its
    centre's path: C keeps its distance from the profile, so a_C = α × JC + v_C²/OC (towards
    O), a_C^t + a_C^n — no geometric contact point, no contact term, in the wheel's step."""
    _, doc = explained(name)
    first = next(s for s in steps(doc, "sec.accelerations")
                 if any(isinstance(b, Msg) and b.key.startswith("path.") for b in s.blocks))
    said = next(b for b in first.blocks if isinstance(b, Msg) and b.key.startswith("path."))
    # a centre whose acceleration an earlier step found is referred to (twentieth round (d): E.1's arm OC)
    circle = ("path.circle", "path.found")
    assert (said.key in circle if fixed_circle else said.key == "path.line")
    assert said.key == "path.found" or said.args["centre"].text == centre
    assert not any(isinstance(b, Msg) and b.key.startswith(("geom.", "rolling.kept")) for b in first.blocks)
    eq = next(b for b in first.blocks if isinstance(b, Equation) and b.target.sym.sub == centre)
    kinds = [t.kind for side in eq.sides for t in side]
    assert "contact" not in kinds and kinds.count("path") == (1 if fixed_circle else 0)
    # the intrinsic components as the notes write them (C5-1.7): tangential, then normal (fifth round)
    assert kinds[0] == "tangential" and (eq.sides[0][0].sym.sub == centre or not fixed_circle)


@pytest.mark.parametrize("name,body", [("seed_c5_1_6_belt", "pulley"), ("seed_c5_e6_bicycle", "chainring")])
def test_a_belt_wheels_centre_comes_from_its_rate(name, body):
    """C5-1.6 and C5-E.6 find the wheel's rate through the belt (chain) from the arm (frame)
    and then its centre from that rate and one point's velocity, 0 = v_Q + ω × QI: the
    centre's note is that construction, and no Aronhold–Kennedy line is written for it."""
    sol, doc = explained(name)
    keys = [s.title.key for s in doc.sections]
    assert keys.index("sec.velocities") < keys.index("sec.centres")
    notes = [b for b in blocks(section(doc, "sec.centres")) if isinstance(b, CentreNote)]
    assert [(n.how, set(n.pair)) for n in notes] == [("rate", {sol.model.frame, body})]


# -- what nobody asks is not worked out ----------------------------------------------------------------------------
def _meet(p1, d1, p2, d2):
    """Where the lines p1 + t d1 and p2 + u d2 cross (by hand: Cramer's rule)."""
    det = d1[0] * (-d2[1]) - d1[1] * (-d2[0])
    rx, ry = p2[0] - p1[0], p2[1] - p1[1]
    t = (rx * (-d2[1]) - ry * (-d2[0])) / det
    return (p1[0] + t * d1[0], p1[1] + t * d1[1])


def test_a_rate_nobody_asks_is_not_worked_out():
    """C5-1.2 asks the centres of OQ, OJ and the left wheel, ω of OJ and v_J: the notes place
    OQ's centre where the normals to the planes through the wheels' centres meet, and never
    work out how fast the wheels turn. The readers asked for the wheels' rates (round 17a) and
    for a vector equation wherever a step finds a rate (round 27b): each wheel's ω is read off
    v_O = v_{K1∈wheel} + ω × K1O right after its centre's velocity, in the bar's step, and
    nothing else turns with a wheel; what is asked equals the construction by hand: O and Q at r along the planes' normals from contacts
    s = 3 from the corner (the model's Data: at 2 the wheels overlapped), I_OQ where the normals meet, I_OJ on the line I_OQ–O and the
    vertical through J = (−5, 2), ω_OJ = ω_OQ·|I_OQ O| / |I_OJ O| turned the other way
    (O lies between the two centres), v_J = ω_OJ × I_OJ J."""
    import math

    sol, doc = explained("seed_c5_1_2_bar_on_inclined_wheels")
    velocities = blocks(section(doc, "sec.velocities"))
    turning = [eq for eq in velocities if isinstance(eq, Equation) and turning_bodies(eq) & {"wheel1", "wheel2"}]
    assert [(str(eq.target.sym.sub), turning_bodies(eq)) for eq in turning] == [("O", {"wheel1"}), ("Q", {"wheel2"})]
    # the wheels' rates, which two readers asked for (seventeenth round (a)), each read off its
    # equation in the step that finds its centre's velocity (round 24d: the summary only
    # collects; round 27b: by the vector equation, as every step finds a rate)
    summary = next(s for s in doc.sections if s.title.key.startswith("sec.rates_summary"))
    wheel_rates = {d.body: d for d in doc.derived() if d.body in ("wheel1", "wheel2")}
    assert set(wheel_rates) == {"wheel1", "wheel2"}
    assert not any(any(d is b for b in summary.leaves()) for d in wheel_rates.values())
    step = next(s for s in steps(doc) if "OQ" in [n.text for n in s.title.args["bodies"].items])
    assert [n.text for n in step.title.args["bodies"].items] == ["OQ", "wheel1", "wheel2"]
    for body, d in wheel_rates.items():
        assert any(d is b for b in step.leaves()), body
    table = next(b for b in summary.blocks if hasattr(b, "rows"))
    assert [r[0].text for r in table.rows] == ["wheel1", "wheel2", "OQ", "OJ"]   # the planes are ground (welded to it)
    # by hand
    c30, s30, c45 = math.sqrt(3) / 2, 0.5, math.sqrt(2) / 2
    s = 3.0
    k1, k2 = (-s * c30, s * s30), (s * c45, s * c45)
    n1, n2 = (s30, c30), (-c45, c45)                      # the planes' normals, upwards
    o = (k1[0] + n1[0], k1[1] + n1[1])
    i16 = _meet(k1, n1, k2, n2)
    i17 = _meet(i16, (o[0] - i16[0], o[1] - i16[1]), (-5.0, 2.0), (0.0, 1.0))
    w7 = -1.0 * math.dist(i16, o) / math.dist(i17, o)
    q = (k2[0] + n2[0], k2[1] + n2[1])
    for wheel, centre in (("wheel1", o), ("wheel2", q)):       # |v| = ω_OQ·|I_OQ C| over r = 1, clockwise
        assert math.isclose(num(sol, wheel_rates[wheel].value.value), -math.dist(i16, centre), rel_tol=1e-9), wheel
    v_j = (-w7 * (2.0 - i17[1]), 0.0)
    rate = next(d for d in doc.derived() if d.body == "OJ" and d.kind == "omega")
    assert math.isclose(num(sol, rate.value.value), w7, rel_tol=1e-9)
    eq = next(b for b in velocities if isinstance(b, Equation) and b.target.sym.sub.startswith("J"))
    assert all(math.isclose(a, b, abs_tol=1e-9) for a, b in zip(num(sol, eq.target.value), v_j))
    centres = {frozenset(n.pair): n for n in blocks(section(doc, "sec.centres")) if isinstance(n, CentreNote)}
    for body, hand in (("OQ", i16), ("OJ", i17)):
        got = centres[frozenset((sol.model.frame, body))].value
        assert all(math.isclose(num(sol, a), b, abs_tol=1e-9) for a, b in zip(got["point"], hand)), (body, got)


def test_a_strand_between_two_pulleys_translates_at_once():
    """C5-1.5: "en no haver-hi moviment pendular" the notes take every strand as translating
    and carry the velocity along it (↓2v over strand 2, ↑2v over strand 3), then turn each
    pulley about its axle. The explanation says ω = 0 of each strand before any equation
    (it is tangent to two pulleys whose centres move alike across it), no equation turns
    with a strand, and each pulley's ω is read off an equation where it is the one rate unknown. By hand
    (y up, pulleys of radius r side by side, v_C1 = ↓v, v_C3 = ↓2v): pulley 1 turns about its
    contact with the tied strand, ω_1 = −v/r, so its right side moves ↓2v; strand 2 carries
    it to pulley 2's left side, ω_2 = 2v/r (axle fixed), right side ↑2v; strand 3 to pulley
    3's left side: ↑2v = ↓2v + ω_3 r, ω_3 = −4v/r; its right side ↓2v − 4v = ↓6v; pulley 4,
    ω_4 = 6v/r, sends the block up at 6v."""
    import sympy

    sol, doc = explained("seed_c5_1_5_pulley_block")
    velocities = blocks(section(doc, "sec.velocities"))
    strands = ["strand2", "strand3", "strand4"]
    said = [i for i, b in enumerate(velocities) if isinstance(b, Derived) and b.body in strands]
    assert [velocities[i].body for i in said] == strands
    assert all(velocities[i].remark.key == "how.tangent" for i in said)
    for eq in (b for b in velocities if isinstance(b, Equation)):
        turning = {t.how[0].sub for side in eq.sides for t in side
                   if t.kind == "rotation" and t.how and getattr(t.how[0], "base", "") == "ω"}
        assert not turning & set(strands), eq.target.sym
    r, v = sympy.symbols("r v", positive=True)
    hand = {"pulley1": -v / r, "pulley2": 2 * v / r, "pulley3": -4 * v / r, "pulley4": 6 * v / r}
    env = {}
    for body, rate in hand.items():
        d = next(b for b in velocities if isinstance(b, Derived) and b.body == body and b.kind == "omega")
        assert d.source is not None and sum(t.unknown and t.kind == "rotation" for e in velocities
                                            if isinstance(e, Equation)
                                            and any(t is d.source for s in e.sides for t in s)
                                            for s in e.sides for t in s) == 1, body
        env.update({str(x): x for x in getattr(d.value.value, "free_symbols", ())})
        got = sympy.sympify(d.value.value).subs({env.get("r", r): r, env.get("v", v): v})
        assert sympy.simplify(got - rate) == 0, body
    for point, vy in (("T2", -2 * v), ("K", 6 * v)):
        eq = next(b for b in velocities if isinstance(b, Equation) and b.target.sym.sub == point)
        got = sympy.sympify(eq.target.value[1]).subs({env.get("r", r): r, env.get("v", v): v})
        assert sympy.simplify(got - vy) == 0 and eq.target.value[0] == 0, point


@pytest.mark.parametrize("name,wheel,known,holder", [
    ("seed_c5_e4_upper_wheel", "upper", "wheel1", "chassis"),      # C5-E.4: α = v̇/R of the upper wheel
    ("seed_c5_e5_unequal_wheels", "wheel1", "wheelR", "chassis"),  # C5-E.5: wheel 1 on wheel R, seen from the chassis
])
def test_wheels_on_one_carrier_are_accelerated_by_their_rates(name, wheel, known, holder):
    """Two moving wheels rolling on each other, both axles on one body: seen from it they
    are a pair of gears at every instant, ρ_a ω_a/K = ∓ρ_b ω_b/K, so the notes differentiate
    the relation of the rates (C5-E.4: "α = v̇/R") and never go through the contact's
    geometric point: at accelerations the wheel's α is said by that relation before any
    equation, and no geometric point nor contact term is written."""
    _, doc = explained(name)
    accel = blocks(section(doc, "sec.accelerations"))
    said = [i for i, b in enumerate(accel) if isinstance(b, Msg) and b.key in ("pair.relation", "drive.relation_a")]
    assert len(said) == 1
    m = accel[said[0]]
    if m.key == "pair.relation":            # said here first (the velocities turned the wheel about its centre)
        assert (m.args["a"].text, m.args["b"].text, m.args["holder"].text) == (known, wheel, holder)
    else:                                   # said at velocities, differentiated here
        first = [b for b in blocks(section(doc, "sec.velocities")) if isinstance(b, Msg) and b.key == "pair.relation_v"]
        assert [(b.args["a"].text, b.args["b"].text, b.args["holder"].text) for b in first] == [(known, wheel, holder)]
    rate = next(i for i, b in enumerate(accel) if isinstance(b, Derived) and b.body == wheel and b.kind == "alpha")
    assert rate > said[0] and accel[rate].how[0].sub == f"{wheel}/{holder}"
    for b in accel:
        if isinstance(b, Msg):
            assert not b.key.startswith(("geom.", "rolling.kept")), b.key
        if isinstance(b, Equation):
            assert not any(t.kind == "contact" or GEOM_MARK in str(t.sym.sub) for side in b.sides for t in side), b.target.sym


def test_the_upper_wheels_top_by_hand():
    """C5-E.4 by hand (x to the right, y up): the chassis translates with a_U = (−v̇, 0); the
    upper wheel turns at ω = −v/R (clockwise, about its top P) at every instant, so
    α = −v̇/R; P = U + R ŷ: a_P = a_U − ω² R ŷ + α ẑ × R ŷ = (−v̇, 0) + (0, −v²/R) + (v̇, 0)
    = (0, −v²/R), the notes' ↓v²/R."""
    import sympy

    sol, doc = explained("seed_c5_e4_upper_wheel")
    accel = blocks(section(doc, "sec.accelerations"))
    d = next(b for b in accel if isinstance(b, Derived) and b.body == "upper" and b.kind == "alpha")
    env = {str(x): x for x in sympy.sympify(d.value.value).free_symbols}
    R, vd = env["R"], env["vd"]
    assert sympy.simplify(d.value.value + vd / R) == 0
    eq = next(b for b in accel if isinstance(b, Equation) and b.target.sym.sub == "P")
    v = next(x for x in sympy.sympify(eq.target.value[1]).free_symbols if x.name == "v")
    assert sympy.simplify(eq.target.value[0]) == 0 and sympy.simplify(eq.target.value[1] + v ** 2 / R) == 0


def test_wheel_one_is_composed_relative_to_the_chassis():
    """C5-E.5: "l'anàlisi cinemàtica de la roda petita respecte del xassís és immediata, i una
    composició de moviments permet obtenir-la respecte del terra", then 0 = v_C + Ω × CI gives
    d = r1. Seen from the chassis (axles fixed) wheel R and wheel 1 are gears: ω_1/c =
    −(R/r1) ω_R/c; with ω_R = −v/R (it rolls on the ground, moving right) and ω_c = 0,
    ω_1 = ω_1/c + ω_c = v/r1 (counter-clockwise, the notes' ⊙ v/r1); its centre
    I = C + (0, d) with 0 = v + (v/r1)·(−d): d = r1, its top point. No equation crosses the
    contact between the wheels at velocities."""
    import sympy

    sol, doc = explained("seed_c5_e5_unequal_wheels")
    velocities = blocks(section(doc, "sec.velocities"))
    assert [b.args["b"].text for b in velocities if isinstance(b, Msg) and b.key == "pair.relation_v"] == ["wheel1"]
    w1 = next(b for b in velocities if isinstance(b, Derived) and b.body == "wheel1")
    assert [getattr(x, "sub", x) for x in w1.how] == ["wheel1/chassis", " + ", "chassis"]
    env = {str(x): x for x in sympy.sympify(w1.value.value).free_symbols}
    v, r1 = env["v"], next(x for n, x in env.items() if n.startswith("r"))
    assert sympy.simplify(w1.value.value - v / r1) == 0
    from kinematika.draw.names import contact_names

    between = contact_names(sol.model, sol)["j6"]          # the wheels' contact (K)
    for eq in (b for b in velocities if isinstance(b, Equation)):
        assert not any(between in re.split(r"[∈\-/ ]", t.sym.sub)
                       for t in [eq.target] + [t for side in eq.sides for t in side]), eq.target.sym
    note = next(n for n in blocks(section(doc, "sec.centres")) if isinstance(n, CentreNote) and "wheel1" in n.pair)
    assert note.how == "rate" and note.via == ["wheelR"]
    (q, _), = note.witnesses
    assert q == "C" and sympy.simplify(note.arm[0]) == 0 and sympy.simplify(note.arm[1] - r1) == 0


def test_a_chassis_on_two_wheels_on_one_line_slides_along_it():
    """C5-E.4: "el xassís té un moviment de translació": its pins A1 and A2 are the centres of
    wheels rolling on the flat ground, both at height R, so both run on one horizontal line
    and the chassis slides along it at every instant: α = 0 said before any equation (never a
    three-sided equation for it), no equation turns with it at accelerations, and the left
    wheel's α follows from a_A1 = a_U: by hand (−v̇, 0) = α ẑ × (R ŷ) = (−α R, 0), α = v̇/R."""
    import sympy

    _, doc = explained("seed_c5_e4_upper_wheel")
    accel = blocks(section(doc, "sec.accelerations"))
    first = next(i for i, b in enumerate(accel) if isinstance(b, Derived) and b.body == "chassis")
    assert accel[first].remark.key == "how.glides" and not accel[first].how
    assert {accel[first].remark.args["p"].text, accel[first].remark.args["q"].text} == {"A1", "A2"}
    assert not any(isinstance(b, Equation) for b in accel[:first])
    for eq in (b for b in accel if isinstance(b, Equation)):
        assert not any(t.how and getattr(t.how[0], "sub", "") == "chassis" for side in eq.sides for t in side)
    d = next(b for b in accel if isinstance(b, Derived) and b.body == "wheel1" and b.kind == "alpha")
    env = {str(x): x for x in sympy.sympify(d.value.value).free_symbols}
    assert sympy.simplify(d.value.value - env["vd"] / env["R"]) == 0


def test_the_trailing_chassis_goes_by_equiprojectivity():
    """C5-2.2: S1 translates, so v_O = rω along it; "la propietat d'equiprojectivitat permet
    obtenir la velocitat del punt mig de l'eix (P)", then S2's centre, and its ω "a partir de
    la velocitat de P i del CIR". By hand (S1 along x, S2 trailing at 45°, OP = a): P moves
    along S2's wheels, e = (1, 1)/√2, and (v_P − v_O) · OP = 0 with v_O = (rω, 0) gives
    v_P = (rω/√2) e = (rω/2, rω/2); the centre I = (0, −√2 a) (S2's axle and the
    perpendicular to v_O at O), I P = (−a/√2, a/√2), so ω_S2 = −√2 rω / (2a). The
    tricycle (C5-2.1), whose front wheel's velocity is a datum, keeps the notes' road there:
    the centre first, then every point about it."""
    import sympy

    sol, doc = explained("seed_c5_2_2_articulated")
    velocities = blocks(section(doc, "sec.velocities"))
    said = [i for i, b in enumerate(velocities) if isinstance(b, Msg) and b.key.startswith("vehicle.equiprojective")]
    centre = next(i for i, b in enumerate(velocities) if isinstance(b, Msg) and b.key == "vehicle.centre"
                  and b.args["body"].text == "S2")
    assert len(said) == 1 and said[0] < centre
    m = velocities[said[0]]
    assert (m.args["q"].text, m.args["p"].text) == ("O", "P")
    env = {str(x): x for c in m.args["value"].value for x in sympy.sympify(c).free_symbols}
    r, w, a = env["r"], env["w"], None
    assert all(sympy.simplify(c - r * w / 2) == 0 for c in m.args["value"].value)
    rate = next(b for b in velocities if isinstance(b, Derived) and b.body == "S2" and b.kind == "omega")
    a = next(x for x in sympy.sympify(rate.value.value).free_symbols if x.name == "a")
    assert sympy.simplify(rate.value.value + sympy.sqrt(2) * r * w / (2 * a)) == 0
    eq = next(e for e in velocities if isinstance(e, Equation) and any(t is rate.source for s in e.sides for t in s))
    assert eq.target.sym.sub.split("∈")[0] == "P"
    _, tricycle = explained("seed_c5_2_1_tricycle")
    assert not any(isinstance(b, Msg) and b.key.startswith("vehicle.equiprojective") for b in tricycle.blocks())
