"""Issue 30, fifth round: the method and data of the C5-1.x examples, each a rule of the
builder checked where the notes' solution shows it. Values are derived by hand in each
docstring (the notes' own numbers: C5-1.4's planet centre at (2/5)r from its axle, C5-1.5's
third pulley's midway)."""
from __future__ import annotations

import sympy

from kinematika.explain.document import CentreNote, Derived, Equation, Table

from .helpers import SEEDS, explained, num, rendered
from .helpers import blocks as _blocks, section as _section




def _notes(doc) -> list[CentreNote]:
    # a centre from two parallel velocities is said in its velocity step (fourteenth round c)
    return [b for s in doc.sections if s.title.key in ("sec.centres", "sec.centres_v", "sec.velocities")
            for b in _blocks(s) if isinstance(b, CentreNote)]


def _sym(expr, name: str):
    """The model's symbol `name` in a formula (its own assumptions, whatever they are)."""
    return next(s for s in expr.free_symbols if str(s) == name)


# -- C5-1.6 (and every seed): a rate written in the steps is in the table of rates -------------------------------
def test_every_rate_the_steps_write_is_in_the_table():
    """The table of rates lists what the explanation found: no body has its ω written as a
    result of the steps and left out of the table (C5-1.6's belt, ω_belt = ω_arm, was
    written and not listed; it is now written and listed, twentieth round g)."""
    for name in SEEDS:
        sol, doc = explained(name)
        if not any(s.title.key == "sec.rates_summary_v" or s.title.key == "sec.rates_summary" for s in doc.sections):
            continue
        summary = next(s for s in doc.sections if s.title.key in ("sec.rates_summary", "sec.rates_summary_v"))
        table = next(b for b in summary.blocks if isinstance(b, Table))
        listed = {r[0].text for r in table.rows}
        written = {d.body for d in doc.derived() if d.kind == "omega" and d.body and d.body != sol.model.frame}
        assert written <= listed, (name, written - listed)


def test_the_belt_run_has_no_rate():
    """C5-1.6: the notes give the belt no angular velocity (round 29 c reversed round 20 g's
    ω_belt = ω_arm, which had reversed this round's "no ω for a run"): none written."""
    _, doc = explained("seed_c5_1_6_belt")
    assert not [d for d in doc.derived() if d.body == "belt"]
    assert "ω_uhala" not in rendered("seed_c5_1_6_belt", "eu", drawings=False)


# -- C5-1.6, C5-1.5: the ground named after a part is the ground as a reference -----------------------------------
def test_the_reference_is_the_ground():
    """The notes: "Els CIR del braç respecte al terra és el centre O de la politja fixa". Where
    the model names its ground after a part that carries a shape (the fixed pulley), an
    instant centre relative to it is said relative to the ground; the part keeps its name
    where it acts (the belt rolls on the fixed pulley). Sixth round: a ground with no shape of
    its own (C5-1.5's ceiling) keeps its one name on the page, never "*lurra*" beside
    "ω_blokea = ω_sabaia"."""
    ca = rendered("seed_c5_1_6_belt", "ca", drawings=False)
    # twenty-ninth round (b): the fixed pulley is the reference by its own name, no ground
    assert "CIR de la *politja mòbil* respecte de la *politja fixa*" in ca
    assert "respecte del *terra*" not in ca
    assert "no llisca sobre la *politja fixa*" in ca
    eu = rendered("seed_c5_1_5_pulley_block", "eu", drawings=False)
    # "solido" said once (ninth round); an instant centre relative to the ground (twentieth round (b))
    # twenty-seventh round (e): the ceiling keeps its own name, as the reference too: "*sabaia*
    # (finkoa)" and "*sabaiarekiko*", never "*lurra*" on a page with no floor
    assert "*3. polearen* biraketa-zentro instantaneoa *sabaiarekiko*" in eu
    assert "| 1 | *sabaia* (finkoa), *1. kable-zatia* barne |" in eu     # the frame's row (29 b)
    assert "*lurr" not in eu and "*sabaia eta 1. kable-zatia* solidoarekiko" not in eu


# -- C5-1.3: a value is written before it is used ------------------------------------------------------------------
def test_the_centre_on_a_straight_path_is_named_where_it_is_found():
    """C5-1.3: the support's centre S keeps its height (it rolls on the straight ground), so
    a_S = α_support × JS whole, with J = (4, 0), S = (4, 1): JS = (0, 1) and α ẑ × (0, 1) =
    (−α, 0). The equation that finds α writes that term as a_S; no later a_S = a_SJ^t."""
    sol, doc = explained("seed_c5_1_3_bar_in_sleeve")
    eqs = [e for e in _blocks(_section(doc, "sec.accelerations")) if isinstance(e, Equation)]
    first = next(e for e in eqs if any(t.sym.base == "a" and t.sym.sub == "S" for side in e.sides for t in side))
    term = next(t for side in first.sides for t in side if t.sym.sub == "S")
    assert term.unknown and term.sym.sup in ("", None)
    alpha = next(d for d in doc.derived() if d.body == "support" and d.kind == "alpha").value.value
    x, y = num(sol, term.value)
    assert abs(x + float(num(sol, alpha))) < 1e-9 and abs(y) < 1e-9
    assert not [e for e in eqs if e.target.sym.sub == "S"]
    assert not [t for e in eqs for side in e.sides for t in side if t.sym.sub == "SJ"]


def test_a_wheel_centre_alone_is_never_written_as_itself():
    """C5-E.4: an equation that finds the centre itself never reads a_A1 = a_A1: the term
    named a_A1 is written by its formula, α × JA1 (sixth round: `Term.spelt`)."""
    _, doc = explained("seed_c5_e4_upper_wheel")
    for e in doc.equations():
        assert not any(t.sym.base == e.target.sym.base and t.sym.sub == e.target.sym.sub and not t.sym.sup
                       and not t.spelt for side in e.sides for t in side), e.target.sym


# -- C5-1.4: the planet's centre first, then ω = v / distance ------------------------------------------------------
def test_the_planet_centre_comes_from_the_data_before_its_rate():
    """C5-1.4: v_A1 = ω × 2r = (2rω, 0) (the carrier), v_J10 = −ω × 3r = (−3rω, 0) (the
    ring), both ⊥ to the vertical A1–J10. Linear along it, v(y) = 2rω + 5ω(y + 2r) vanishes
    at y = −12r/5: I at (0, −12r/5), (2/5)r below A1 as the notes say. Then ω_planet1 from
    v_A1 = ω_z ẑ × (A1 − I) = ω_z ẑ × (0, 2r/5) = (−2rω_z/5, 0): ω_z = −5ω. The centre is in
    the velocity step, after the equations that find v_A1 and v_J10 (round 20e: "Instant
    centres", before the velocities, read them before any line found them), before the rate,
    which is read off an equation starting at it."""
    sol, doc = explained("seed_c5_1_4_epicyclic")
    keys = [s.title.key for s in doc.sections]
    assert keys.index("sec.centres") < keys.index("sec.velocities")
    velocities = _blocks(_section(doc, "sec.velocities"))
    note = next(n for n in velocities if isinstance(n, CentreNote) and set(n.pair) == {"ground", "planet1"})
    rate = next(d for d in velocities if isinstance(d, Derived) and d.body == "planet1" and d.kind == "omega")
    assert velocities.index(note) < velocities.index(rate)
    assert note.how == "proportional" and note.side == "between"
    px, py = (sympy.sympify(c) for c in note.value["point"])
    r = _sym(py, "r")
    assert sympy.simplify(px) == 0 and sympy.simplify(py + sympy.Rational(12, 5) * r) == 0
    found = next(d for d in _blocks(_section(doc, "sec.velocities")) if isinstance(d, Derived)
                 and d.body == "planet1" and d.kind == "omega")
    value = sympy.sympify(found.value.value)
    assert sympy.simplify(value + 5 * _sym(value, "w")) == 0
    eq = next(e for e in _blocks(_section(doc, "sec.velocities")) if isinstance(e, Equation)
              and any(t is found.source for side in e.sides for t in side))
    side = next(side for side in eq.sides if found.source in side)
    assert all(sympy.simplify(c) == 0 for c in side[0].value)       # it starts at the centre, v_I = 0


# -- C5-1.5: the proportional construction ---------------------------------------------------------------------------
def test_the_third_pulley_centre_is_the_midpoint():
    """C5-1.5: "el punt de l'esquerra del diàmetre horitzontal de la tercera politja puja amb
    2v però el seu centre baixa amb 2v: el CIR estarà en el punt mig". T4 = (4r, −4r) rises at
    2v, C3 = (5r, −4r) falls at 2v, both ⊥ T4C3: equal speeds, opposite senses, so I is midway,
    (9r/2, −4r), r/2 from C3 — by the construction, not by |v_C3| / |ω|."""
    _, doc = explained("seed_c5_1_5_pulley_block")
    note = next(n for n in _notes(doc) if set(n.pair) == {"ground", "pulley3"})
    assert note.how == "parallel" and note.side == "between"
    assert [p for p, _ in note.witnesses] == ["T4", "C3"]
    r = _sym(sympy.sympify(note.distance), "r")
    assert sympy.simplify(sympy.sympify(note.distance) - r / 2) == 0
    x, y = (sympy.sympify(c) for c in note.value["point"])
    assert sympy.simplify(x - sympy.Rational(9, 2) * r) == 0 and sympy.simplify(y + 4 * r) == 0
    eu = rendered("seed_c5_1_5_pulley_block", "eu", drawings=False)
    assert "BZIa bien artean dago" in eu and "C3 puntutik r/2 distantziara" in eu   # eleventh round: the distance plainly


# -- C5-1.2: a part welded to the frame is the frame ----------------------------------------------------------------
def test_a_wheel_on_a_welded_plane_turns_about_its_contact():
    """C5-1.2: the planes are "el terra inclinat": each wheel's centre relative to the ground
    is its contact, said once at the rolling joint (no I_{wheel rel plane}, then "welded: one
    body"); the weld is not a joint of the joints table; the centres' example is a moving body."""
    _, doc = explained("seed_c5_1_2_bar_on_inclined_wheels")
    notes = _notes(doc)
    assert not [n for n in notes if set(n.pair) & {"plane1", "plane2"}]
    for wheel in ("wheel1", "wheel2"):
        note = next(n for n in notes if set(n.pair) == {"ground", wheel})
        assert note.how == "joint" and note.joint_type == "rolling"
    structure = _section(doc, "sec.structure")
    joints = [b for b in structure.blocks if isinstance(b, Table)][1]
    assert len(joints.rows) == len(doc.joints) - 2
    eu = rendered("seed_c5_1_2_bar_on_inclined_wheels", "eu", drawings=False)
    assert "I_{ezkerreko planoa}" not in eu and "zurrunki lotuta daude: solido bakarra" not in eu


def test_the_tied_strand_is_a_part_welded_to_the_ceiling():
    """C5-1.5: "tots els punts del tram de l'esquerra han de tenir velocitat nul·la respecte
    al terra (ja que el punt de dalt està lligat al sostre)": strand 1 is its own body, welded
    to the ceiling, on which pulley 1 rolls; a centre is said relative to the ceiling, the one
    name of the fixed body on the page (sixth round: the ceiling carries no shape of its own)."""
    ca = rendered("seed_c5_1_5_pulley_block", "ca", drawings=False)
    assert "| 1 | *sostre* (fix), amb el *tram 1* |" in ca          # the frame's row (29 b)
    assert "I_{politja1}: el punt de contacte J (rodolament sense lliscament)" in ca   # the centre, said once (17a)
    # an absolute centre is said relative to the ceiling, the fixed body's one name on the page
    # (twentieth round (b) said the ground; twenty-seventh round (e): a page with no floor)
    assert "CIR de la *politja 3* respecte del *sostre*" in ca and "CIR de la *politja 3* respecte del *terra*" not in ca
    assert "ω_tram1" not in ca                   # a part of the frame has no rate to name
