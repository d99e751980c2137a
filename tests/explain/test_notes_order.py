"""The notes' worked examples explained in the notes' order and method (issue 30, second
round): what the notes say once is said once, what they find first comes first, and nothing
the questions do not need is worked out. Each test states what the notes do (seed 002, the
Catalan notes C5; seed 001, the Basque slides) and checks the structure of the
explanation against it: the order of its sections and steps, which equations appear and
which quantities are derived, never the numbers the code produced."""
from __future__ import annotations

import pytest

from kinematika.explain.document import CentreNote, Derived, Equation, Msg, Section

from .helpers import explained


def section(doc, key: str) -> Section:
    return next(s for s in doc.sections if s.title.key == key)


def blocks(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        out += blocks(b) if isinstance(b, Section) else [b]
    return out


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


# -- what the notes say once --------------------------------------------------------------------------------------
@pytest.mark.parametrize("name,original,repeated", [
    ("seed_c5_1_4_epicyclic", "planet1", ["planet2", "planet3"]),     # C5-1.4: three identical planets
    ("seed_c5_e2_gear_change", "planet1", ["planet2"]),               # C5-E.2: the two planets, 2Ω each
])
def test_identical_planets_are_worked_once(name, original, repeated):
    """The notes work one planet and say the rest are the same: the explanation writes the
    equations of the first planet only; the others get one step of kind `copy` that says
    so and gives their ω as the first one's (ω_6 = ω_5), and no equation turns with them."""
    _, doc = explained(name)
    velocities = blocks(section(doc, "sec.velocities"))
    equations = [b for b in velocities if isinstance(b, Equation)]
    assert any(original in turning_bodies(eq) for eq in equations)
    for b in repeated:
        assert not any(b in turning_bodies(eq) for eq in equations), b
    copy_steps = [s for s in steps(doc) if s.title.args["kind"].key == "kind.copy"]
    assert len(copy_steps) == 1
    said = [b for b in copy_steps[0].blocks if isinstance(b, Msg) and b.key == "copy.same"]
    assert [m.args["body"].text for m in said] == repeated
    assert all(m.args["original"].text == original for m in said)
    rates = {d.body: d for d in copy_steps[0].blocks if isinstance(d, Derived)}
    assert set(rates) == set(repeated)
    assert all([x.sub for x in rates[b].how] == [original] for b in repeated)
    order = next(b for b in section(doc, "sec.structure").blocks if isinstance(b, Section))
    kinds = [m.args["kind"].key for m in order.blocks if isinstance(m, Msg) and m.key == "order.item"]
    assert kinds.count("kind.copy") == 1


def test_a_planet_is_a_copy_only_when_the_train_looks_the_same_from_it(tmp_path):
    """C5-E.2's lower planet turned a quarter turn about O is still the upper one turned
    (-90°); the same planet not meshing with the ring is not, and is worked on its own."""
    from pathlib import Path

    import kinematika
    from kinematika.explain import build

    text = (Path(__file__).resolve().parents[2] / "examples" / "seed_c5_e2_gear_change.yaml").read_text()
    text = text.replace('A2: [0, "-2*r"]', 'A2: ["2*r", 0]')
    path = tmp_path / "turned.yaml"
    path.write_text(text)
    doc = build(kinematika.solve(path))
    said = [b for b in blocks(section(doc, "sec.velocities")) if isinstance(b, Msg) and b.key == "copy.same"]
    assert [m.args["angle"].value for m in said] == [-90.0]
    path.write_text(text.replace("  - {type: gear, bodies: [ring, planet2], internal: true}\n", ""))
    doc = build(kinematika.solve(path))
    assert not any(s.title.args["kind"].key == "kind.copy" for s in steps(doc))
    equations = [b for b in blocks(section(doc, "sec.velocities")) if isinstance(b, Equation)]
    assert any("planet2" in turning_bodies(eq) for eq in equations)


def test_the_centres_section_holds_what_is_asked():
    """C5-1.4 asks the instant centre of one planet: the notes place it from the centres of
    the carrier, the ring and the contact, and say nothing of the other planets' centres."""
    _, doc = explained("seed_c5_1_4_epicyclic")
    notes = [b for b in blocks(section(doc, "sec.centres")) if isinstance(b, CentreNote)]
    pairs = {frozenset(n.pair) for n in notes}
    assert frozenset(("ground", "planet1")) in pairs
    assert not any(pair & {"planet2", "planet3"} for pair in pairs)
    placed = next(n for n in notes if frozenset(n.pair) == frozenset(("ground", "planet1")))
    needed = {frozenset(p) for k in placed.via for p in (("ground", k), (k, "planet1"))}
    assert needed <= pairs
