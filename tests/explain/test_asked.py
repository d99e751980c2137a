"""Every quantity a worked example of the notes asks for is derived before the answers
table: an equation whose target (or a term) is the answer, a value read off an equation, an
instant centre placed by a construction (never "from the velocity and ω" alone), the three
points of a contact each reached by an equation. The answers are the solver's; what is
checked is that the explanation reaches each one, with the same value."""
from __future__ import annotations

import pytest

import kinematika

from kinematika.explain import build, render
from kinematika.explain.document import CentreNote, Derived, Equation, Msg, Section
from kinematika.questions import answer

from .helpers import EXAMPLES, is_close, explained

SEEDS = sorted(p.stem for p in EXAMPLES.glob("seed_*.yaml"))
DERIVED_CENTRES = {"joint", "kennedy", "lines", "proportional", "parallel", "velocities", "field", "weld", "rate"}


def before_answers(doc) -> list:
    """The blocks of every section before the answers, in reading order."""
    out: list = []

    def walk(sec: Section) -> None:
        for b in sec.blocks:
            walk(b) if isinstance(b, Section) else out.append(b)
    for s in doc.sections:
        if s.title.key == "sec.answers":
            break
        walk(s)
    return out


def _scale(sol, level: str) -> float:
    accel = max(sol.accel_scale(), sol.rate_scale() * sol.speed_scale())
    return {"v": sol.speed_scale(), "a": accel, "w": sol.rate_scale(), "al": accel / sol.inst.scale,
            "len": sol.inst.scale}[level] or 1.0


def _point_name(ref) -> str:
    return ref.point


def vector_reached(sol, blocks, level: str, point: str, value, relative: bool) -> bool:
    """Some equation of the level ends (or has a term) with this value, named for the point."""
    for eq in (b for b in blocks if isinstance(b, Equation) and b.level == level):
        for t in [eq.target] + [x for side in eq.sides for x in side]:
            if relative and t.kind == "slide" and is_close(sol, t.value, value, _scale(sol, level)):
                return True              # the slide along a guide: the relative motion asked
            name = t.sym.sub.split("∈")[0].split("/")[0]
            if t.sym.base == level and name == point and ("/" in t.sym.sub) == relative and not t.sym.sup \
                    and is_close(sol, t.value, value, _scale(sol, level)):
                return True
    return False


def rate_reached(sol, blocks, kind: str, body: str, rel, value) -> bool:
    for d in (b for b in blocks if isinstance(b, Derived)):
        sub = body if rel is None else f"{body}/{rel}"
        base = "ω" if kind == "omega" else "α"
        if d.sym.base == base and d.sym.sub == sub and is_close(sol, d.value.value, value, _scale(sol, "w")):
            return True
    level = "w" if kind == "omega" else "al"
    for eq in (b for b in blocks if isinstance(b, Equation) and b.level == level):
        sub = body if rel is None else f"{body}/{rel}"
        if eq.target.sym.sub == sub:
            return True
    return False


def reached(sol, doc, q) -> bool:
    blocks = before_answers(doc)
    frame = sol.model.frame
    rel = None if q.relative_to in (None, frame) else q.relative_to
    got = answer(sol, q)
    if q.kind in ("velocity", "acceleration"):
        return vector_reached(sol, blocks, q.kind[0], q.target.point, got, rel is not None)
    if q.kind in ("omega", "alpha"):
        value = got if sol.space.dim == 2 else tuple(got)
        return rate_reached(sol, blocks, q.kind, q.target, rel, value)
    if q.kind == "icr":
        pair = {rel or frame, q.target}
        notes = [b for b in blocks if isinstance(b, CentreNote) and set(b.pair) == pair]
        # or placed in a velocity step where two lines meet (a vehicle's chassis), and only
        # referred to in the centres section (thirteenth round (c): a construction said once)
        placed = [b for b in blocks if isinstance(b, Msg) and b.key == "vehicle.centre" and rel is None
                  and b.args["body"].text == q.target and got.get("point") is not None
                  and is_close(sol, b.args["where"].value, got["point"], _scale(sol, "len"))]
        return bool(placed) or any(n.how in DERIVED_CENTRES and (n.how != "velocities" or len(n.witnesses) == 2)
                                   for n in notes)
    if q.kind == "curvature":
        return any(isinstance(b, Derived) and b.kind == "radius" and b.sym.sub.split("∈")[0] == q.target.point
                   and is_close(sol, b.value.value, got["radius"], _scale(sol, "len")) for b in blocks)
    if q.kind == "intrinsic":
        return any(isinstance(b, Equation) and b.level == "a" and b.target.sym.sub.split("∈")[0] == q.target.point
                   and any(t.sym.sup == "t" for t in b.sides[0]) for b in blocks)
    if q.kind == "decompose":
        # the sum a step wrote already is referred to (seventeenth round (a)), not written again
        return all(any((isinstance(b, Equation) and b.level == lv and any(t.kind == "drag" for t in b.sides[0]))
                       or (isinstance(b, Msg) and b.key == "composition.sum_seen" and b.args["sym"].base == lv)
                       for b in blocks) for lv in ("v", "a"))
    if q.kind == "contact":
        want = [(part[key], lv) for name, part in got.items() if isinstance(part, dict)
                for key, lv in (("velocity", "v"), ("acceleration", "a"))]
        values = [(t.value, eq.level) for eq in blocks if isinstance(eq, Equation)
                  for t in [eq.target] + [x for side in eq.sides for x in side]]
        return all(any(lv == level and is_close(sol, v, value, _scale(sol, lv)) for v, level in values)
                   for value, lv in want)
    return True


@pytest.mark.parametrize("name", SEEDS)
def test_every_answer_is_reached_before_the_answers(name):
    sol, doc = explained(name)
    missing = [str(q.echo) for q in sol.model.questions if not reached(sol, doc, q)]
    assert not missing, f"answers given but not derived: {missing}"


def test_velocities_asked_stop_at_velocities():
    """C5-1.4 asks for the planet's instant centre and angular velocities only: no
    acceleration step, and the rates table has no α column (the notes work nothing more)."""
    _, doc = explained("seed_c5_1_4_epicyclic")
    keys = [s.title.key for s in doc.sections]
    assert "sec.velocities" in keys and "sec.accelerations" not in keys
    summary = next(s for s in doc.sections if s.title.key == "sec.rates_summary_v")
    table = next(b for b in summary.blocks if hasattr(b, "header"))   # after planet 3's line (round 20a)
    assert [h.key for h in table.header] == ["col.body", "col.omega"]


@pytest.mark.parametrize("lang", ["en", "es", "ca", "eu"])
def test_a_spatial_model_asked_velocities_states_no_acceleration(lang, tmp_path):
    """The robot arm asked ω of the arm and v_E only: its angular rates are ω = ω_drag +
    ω_rel body by body, with no α, no loop's α and no acceleration step, in every language."""
    text = (EXAMPLES / "robot_arm_3d.yaml").read_text()
    path = tmp_path / "robot_v.yaml"
    path.write_text(text[:text.index("ask:")] + "ask:\n  - {omega: arm}\n  - {velocity: E}\n")
    doc = build(kinematika.solve(path))
    keys = [s.title.key for s in doc.sections]
    assert "sec.rates_summary_v" in keys and "sec.rates" not in keys and "sec.accelerations" not in keys
    page = render(doc, lang, "md", drawings=False)
    assert "α" not in page and "ω" in page


def test_an_inflection_circle_asked_alone_is_explained_with_accelerations(tmp_path):
    """The inflection circle is where the normal acceleration vanishes (a_I/ω²): a four-bar
    asked only {inflection: coupler} is explained up to its accelerations."""
    text = (EXAMPLES / "four_bar.yaml").read_text()
    path = tmp_path / "inflection.yaml"
    path.write_text(text[:text.index("ask:")] + "ask:\n  - {inflection: coupler}\n")
    keys = [s.title.key for s in build(kinematika.solve(path)).sections]
    assert "sec.velocities" in keys and "sec.accelerations" in keys


def test_a_crowded_acceleration_polygon_is_drawn_step_by_step():
    """Jansen's leg's acceleration polygon would hold more than SPLIT arrows: it is drawn
    under each step instead (fig.step_a), with no whole polygon at the level's end. (The
    planetary gears' was, until their planets were said once: "the same for each".)"""
    from kinematika.explain.builder import SPLIT
    from kinematika.explain.document import Figure

    _, doc = explained("jansen_leg")
    acc = next(s for s in doc.sections if s.title.key == "sec.accelerations")
    whole = [b for b in acc.blocks if isinstance(b, Figure)]
    steps = [b for s in acc.blocks if isinstance(s, Section) for b in s.blocks if isinstance(b, Figure)]
    assert not whole and len(steps) >= 2
    assert all(f.caption.key == "fig.step_a" for f in steps)
    assert sum(len(f.arrows) for f in steps) > SPLIT
