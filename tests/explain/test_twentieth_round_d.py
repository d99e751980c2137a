"""Issue 30, twentieth round (d): a result is derived once, and a step says what it found.

- the curvature of a path the structure makes a circle (a wheel's centre rolling on a fixed
  circle) is read off it, ℜ_C = OC with centre O — not ℜ_C = |v_C|² / |a_C^n| after a step
  wrote a_C^n = v_C² / OC (C5-1.7, C5-1.8);
- a contact point a step found at rest (v_J∈wheel = 0, the wheel's instant centre) is
  referred to in "Contact points", not written again (C5-1.8);
- a wheel's centre whose acceleration an earlier step found is referred to, not put on its
  circle again (C5-E.1, Catalan "El seu centre C manté la distància …");
- the composition's "equation of Step n, which found …" names no datum (001 rolling: v_A);
- no step is a title with no equation while a later step writes its body's points (C5-1.4);
- the mechanism figure's caption names only velocities the page derives (C5-E.3);
- the drag velocity of C5-1.3 is a rotation about J, the support's contact at rest.
"""
from __future__ import annotations

import re

from kinematika.explain.document import Drawing, Equation, Msg, Name, Names, Section, Sym

from .helpers import LANGS, SEEDS, explained, over, rendered


def _section(doc, key: str) -> list[Section]:
    return [s for s in doc.sections if s.title.key == key]


def _steps(sec: Section) -> list[Section]:
    return [b for b in sec.blocks if isinstance(b, Section)]


def _leaves(sec: Section) -> list:
    out: list = []
    for b in sec.blocks:
        out += _leaves(b) if isinstance(b, Section) else [b]
    return out


@over(name=SEEDS)
def test_curvature_not_derived_from_a_path_a_step_wrote(name: str) -> None:
    """A point whose a^n a step wrote as v²/OC (the centre on its circle) gets no second
    a = a^t + a^n in "Curvature of paths"."""
    _, doc = explained(name)
    on_path = {t.sym.sub for e in doc.equations() for side in e.sides for t in side if t.kind == "path"}
    for sec in _section(doc, "sec.curvature"):
        again = [b.target.sym.sub for b in _leaves(sec) if isinstance(b, Equation) and b.target.sym.sub in on_path]
        assert not again, again


@over(lang=LANGS)
def test_semicylinder_centre_curvature_read_off_the_circle(lang: str) -> None:
    """C5-1.7 and 1.8: C stays 3r from O (2r + r), so ℜ_C = OC = 3·r and the centre of
    curvature is O = (0, 0)."""
    for name in ("seed_c5_1_7_semicylinder", "seed_c5_1_8_contact_points"):
        page = rendered(name, lang, drawings=False)
        assert "ℜ_C = OC = 3·r" in page, name
        assert "ℜ_C = |v_C|²" not in page, name


@over(name=SEEDS)
def test_contact_point_at_rest_not_derived_again(name: str) -> None:
    """A material point a step said is at rest (the body's instant centre) has no equation
    in "Contact points"."""
    _, doc = explained(name)
    still = {b.args["sym"].sub for b in doc.blocks() if isinstance(b, Msg)
             and b.key in ("rolling.centre", "centre.site", "centre.site_s")}
    for sec in _section(doc, "sec.contact"):
        again = [b.target.sym.sub for b in _leaves(sec) if isinstance(b, Equation)
                 and b.level == "v" and b.target.sym.sub in still]
        assert not again, again


@over(name=SEEDS)
def test_wheel_centre_found_earlier_is_not_put_on_its_circle_again(name: str) -> None:
    """The sentence "its centre C keeps its distance …: the circle of radius OC" is not
    written for a centre whose acceleration an earlier step's equation found."""
    _, doc = explained(name)
    for sec in _section(doc, "sec.accelerations"):
        earlier: set = set()
        for step in _steps(sec):
            for b in _leaves(step):
                if isinstance(b, Msg) and b.key == "path.circle":
                    assert b.args["ac"].sub not in earlier, b.args["ac"].sub
            earlier |= {e.target.sym.sub for e in _leaves(step) if isinstance(e, Equation)}


@over(name=SEEDS)
def test_composition_refers_to_what_the_step_found_not_a_datum(name: str) -> None:
    """"… the equation of Step n, which found X": X is never a given point's motion."""
    sol, doc = explained(name)
    given = {d.point.point for d in sol.model.drivers if getattr(d, "point", None) is not None}
    for b in doc.blocks():
        if isinstance(b, Msg) and b.key == "composition.sum_seen":
            seen = b.args["seen"]
            items = seen.items if isinstance(seen, Names) else [seen]
            data = [s for s in items if isinstance(s, Sym) and s.base in ("v", "a") and s.sub in given]
            assert not data, data


@over(lang=LANGS)
def test_rolling_pair_composition_names_rate_and_relative(lang: str) -> None:
    """001's rolling pair: Step 2 found ω_N and v_A∈R rel N (v_A is given)."""
    page = rendered("seed_001_rolling_pair", lang, drawings=False)
    line = next(x for x in page.splitlines() if x.count("v_A = ") and ("2" in x) and "ω_N" in x)
    assert "v_{A∈R" in line.split("ω_N", 1)[1], line


@over(name=SEEDS)
def test_no_step_without_equation_while_a_later_one_writes_its_body(name: str) -> None:
    """A step that names a body writes that body's equations: no title with no equation
    while a later step writes v_{Q∈ring} from the ring's own motion."""
    _, doc = explained(name)
    for key in ("sec.velocities", "sec.accelerations"):
        for sec in _section(doc, key):
            steps = _steps(sec)
            for k, step in enumerate(steps):
                if any(isinstance(b, Equation) for b in _leaves(step)):
                    continue
                bodies = {n.text for n in step.title.args["bodies"].items}
                for later in steps[k + 1:]:
                    own = [e.target.sym.sub for e in _leaves(later) if isinstance(e, Equation)
                           and e.point is not None and e.point.body in bodies and len(e.sides) == 1
                           and not e.relative_to and all(t.kind in ("point", "rotation", "normal", "tangential")
                                                         and not t.unknown for t in e.sides[0])]
                    assert not own, (bodies, own)


@over(name=SEEDS)
def test_mechanism_caption_names_only_derived_velocities(name: str) -> None:
    """Each point the mechanism figure's caption gives a velocity arrow for has its velocity
    on the page: an equation's target, or a datum."""
    sol, doc = explained(name)
    written = {e.point.point for e in doc.equations() if e.level == "v" and e.point is not None}
    written |= {d.point.point for d in sol.model.drivers if getattr(d, "point", None) is not None}
    asked = {q.target.point for q in sol.model.questions if hasattr(q.target, "point")}
    for b in doc.blocks():
        if isinstance(b, Drawing) and b.caption.key == "fig.mechanism" and b.caption.args.get("arrows") == 2:
            named = [n.text for n in b.caption.args["points"].items if isinstance(n, Name)]
            missing = [p for p in named if p.split("∈")[0] not in written | asked]
            assert not missing, missing


def test_wheels_with_rod_caption_by_hand() -> None:
    """C5-E.3 derives v_A (left wheel about J) and v_B (rod about I_rod): those two arrows."""
    page = rendered("seed_c5_e3_wheels_with_rod", "en")
    assert "the arrows are the velocities of A and B," in page
    assert "C1, A, C2" not in page


@over(lang=LANGS)
def test_sleeve_drag_velocity_about_the_contact(lang: str) -> None:
    """C5-1.3: the support rolls on the ground at J (v_J∈support = 0), so its drag motion at
    E is a rotation about J: v_ar,E = v_J∈support + ω_support × JE."""
    _, doc = explained("seed_c5_1_3_bar_in_sleeve")
    drags = [e for e in doc.equations() if e.level == "v" and e.target.sym.sub_key == "sub.drag"]
    assert drags
    first = drags[0].sides[0][0]
    assert first.sym.sub.startswith("J∈") and all(abs(c) < 1e-12 for c in first.value)
    page = rendered("seed_c5_1_3_bar_in_sleeve", lang, drawings=False)
    assert re.search(r"v_\{(drag|ar|arr),E\} +=  v_\{J∈", page)
