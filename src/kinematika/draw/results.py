"""The results a figure shows, read from a `Solution`: vectors, centres, curvature, axes.

Which ones is decided by the model's questions and the `DrawOptions` (see there); the
values come from the Solution and the question modules, never from solving here.
"""
from __future__ import annotations

import math
from typing import Any, Optional

import numpy as np

from ..joints.capabilities import Centre
from ..model.model import PointRef
from ..questions import QUESTIONS, answer
from .options import DrawOptions
from .words import word
from .geometry import perpendicular
from .names import (ANSWER_CHARS, FORMULA_CHARS, bare, body_labels, contact_name, equation, formula,
                    geometric_symbol, pair_symbol, point_symbol, subscript, value_text)
from .scene import (AxisView, CurvatureView, KennedyLine, MarkView, Numbers, Scene, VectorView, drawing_values,
                    vector_label)

KINDS = ("velocity", "acceleration")


def add_results(scene: Scene, sol: Any, options: DrawOptions, num: Numbers) -> None:
    """Add to `scene` the results the questions and `options` ask for, read from the solution:
    velocity and acceleration vectors, instant centres with their Kennedy lines, curvature
    circles, poles, contacts and screw axes."""
    _vectors(scene, sol, options, num)
    _decompositions(scene, sol, options, num)
    _coincident(scene, sol, options, num)         # after: no composition's parts beside them
    _centres(scene, sol, options, num)
    if options.curvature is not False:
        _curvatures(scene, sol, num, options.lang)
    _other_marks(scene, sol, num, options.lang)


# vectors ---------------------------------------------------------------------------------
def _vectors(scene: Scene, sol: Any, options: DrawOptions, num: Numbers) -> None:
    tol = 1e-9 * scene.size
    arrows = drawn_questions(sol.model).arrows
    for kind in KINDS:
        asked = {(q.target, q.relative_to) for q in arrows[kind]}
        flag = options.velocities if kind == "velocity" else options.accelerations
        for ref, rel in vector_targets(sol, options, kind, flag):
            value = (sol.velocity if kind == "velocity" else sol.acceleration)(ref, rel)
            vec = num.vector(value)
            if _negligible(sol, kind, value):
                vec = np.zeros_like(vec)      # round-off, not a vector to draw
            origin = num.page(sol.position(ref))
            label = vector_label(kind, sol.model, ref, rel, options.lang)
            if any(v.kind == kind and v.label == label and np.allclose(v.origin, origin, atol=tol)
                   and np.allclose(v.value, num.proj(vec), atol=1e-9 * (1 + v.magnitude))
                   for v in scene.vectors):
                continue      # the same vector of a point shared by two bodies
            magnitude = float(np.linalg.norm(vec))
            text = magnitude_text(sol, value, magnitude, options.lang, (ref, rel) in asked)
            rel = rel if rel != sol.model.frame else None
            scene.vectors.append(VectorView(kind, str(ref), label, origin, num.proj(vec), magnitude, text, rel))


def _coincident(scene: Scene, sol: Any, options: DrawOptions, num: Numbers) -> None:
    """At each asked contact (`contact` questions, seen from the frame), the three points
    that coincide there, each with its arrow of the kind `options.coincident` asks for, read
    off the question's answer (`questions.contact`): the point of the joint's first body, of
    its second, and the geometric contact point, which belongs to neither and moves along
    both profiles — labelled as the text writes them, v_{J∈a}, v_{J∈b}, v_{J^{geom}}. A zero
    one (a fixed body's point, a rolling body's instant centre) gets its label "= 0" at the
    point (`vectors.draw_vectors`), as the notes write v = 0 beside it (issue 30,
    twenty-eighth round (a): C5-1.8's figure of the three points)."""
    kind = options.coincident
    if kind is None:
        return
    model = sol.model
    letter = "v" if kind == "velocity" else "a"
    labels = body_labels(model, options.lang)
    for q in drawn_questions(model).contacts:
        if q.relative_to not in (None, model.frame):
            continue            # seen from a moving body: the text works the frame's only
        value = answer(sol, q)
        joint = model.joint(q.target)
        name = (options.contacts or {}).get(joint.id) or contact_name(model, joint.id, sol)
        origin = num.page(value["point"])
        for part, body in (("body_a", joint.a), ("body_b", joint.b), ("geometric", None)):
            motion = value[part][kind]
            vec = np.zeros_like(num.vector(motion)) if _negligible(sol, kind, motion) else num.vector(motion)
            magnitude = float(np.linalg.norm(vec))
            label = subscript(letter, name, labels[body]) if body else geometric_symbol(letter, name)
            ref = f"{name}@{body}" if body else f"{name}:geom"
            scene.vectors.append(VectorView(kind, ref, label, origin, num.proj(vec), magnitude,
                                            magnitude_text(sol, motion, magnitude, options.lang)))


def _negligible(sol: Any, kind: str, value: tuple) -> bool:
    """Zero at the model's scale: the contract's 1e-9 of the largest speed (or acceleration,
    or ω·v, whichever is larger)."""
    return sol.is_zero(value, sol.speed_scale() if kind == "velocity" else sol.shown_accel_scale())


def vector_targets(sol: Any, options: DrawOptions, kind: str,
                   flag: Optional[bool]) -> list[tuple[PointRef, Optional[str]]]:
    """(material point, frame) pairs to draw a vector of `kind` at, in order, no repeats.

    A model without an `ask` section (every point asked by default) counts as asking
    nothing in particular: velocities at its moving points, no accelerations."""
    model = sol.model
    default = default_ask(model)
    arrows = drawn_questions(model).arrows[kind]
    asked = [] if default else [(q.target, q.relative_to) for q in arrows]
    if flag is False:
        return []
    if flag is None and not options.points and not default:
        return _unique(asked + _beside(model, asked, kind))
    if flag is None and not asked and kind != "velocity":
        return []
    if options.points:
        shown = [(model.resolve_point(p, "--points"), None) for p in options.points]
    else:
        shown = [] if default else [(q.target, q.relative_to if any(q is a for a in arrows) else None)
                                    for q in model.questions if QUESTIONS[q.kind].about == "point"]
        shown = shown or _moving_points(sol)
        if kind == "velocity" and not default:
            shown += _given(model)
    return _unique(shown)


def _given(model: Any) -> list:
    """The velocities the data give (a driver's point velocity relative to the frame): a figure
    that draws velocities draws them beside those found, as the notes draw the datum the
    solution starts from (C5-E.4's chassis at v, of which only v_P = 0 was drawn; C5-2.1's
    v_F; issue 30, twenty-seventh round (f))."""
    return [(d.point, None) for d in model.drivers
            if d.kind == "velocity" and d.relative_to in (None, model.frame)]


def _beside(model: Any, asked: list, kind: str) -> list:
    """What a figure draws beside the asked vectors: the absolute vector of a point whose
    relative one is asked (a relative velocity is read against the absolute), and, for
    velocities, the data the model gives (the tractor's v_F)."""
    out = [(ref, None) for ref, rel in asked if rel not in (None, model.frame)]
    return out + (_given(model) if kind == "velocity" else [])


def _decompositions(scene: Scene, sol: Any, options: DrawOptions, num: Numbers) -> None:
    """The parts of each asked composition of motions at its point, for the kinds the figure
    draws: drag (and, for accelerations, Coriolis) beside the relative and the absolute."""
    from ..questions.decompose import decompose

    drawn = {v.kind for v in scene.vectors}
    words = _part_words(options.lang)
    for q in drawn_questions(sol.model).compositions:
        parts = decompose(sol, q)
        origin = num.page(sol.position(q.target))
        for kind in KINDS:
            if kind not in drawn:
                continue
            letter = "v" if kind == "velocity" else "a"
            for part in ("drag", "coriolis") if kind == "acceleration" else ("drag",):
                value = parts[kind][part]
                vec = num.vector(value)
                if _negligible(sol, kind, value):
                    continue
                magnitude = float(np.linalg.norm(vec))
                label = subscript(letter, f"{words[part]},{q.target.point}")
                scene.vectors.append(VectorView(kind, f"{q.target}:{part}", label, origin, num.proj(vec), magnitude,
                                                magnitude_text(sol, value, magnitude, options.lang)))


def _part_words(lang: Optional[str]) -> dict[str, str]:
    """The subscripts of the parts (drag, Cor), as the explanation in `lang` writes them."""
    from ..model.wording import part_subscript

    return {"drag": part_subscript("sub.drag", lang), "coriolis": part_subscript("sub.cor", lang)}


def default_ask(model: Any) -> bool:
    """Whether the questions are the contract's default (no `ask` section was written)."""
    return model.default_questions


def _unique(items: list, key: Any = lambda item: (str(item[0]), item[1])) -> list:
    """`items` in order, keeping the first of those with the same key."""
    seen, out = set(), []
    for item in items:
        k = key(item)
        if k not in seen:
            seen.add(k)
            out.append(item)
    return out


def _moving_points(sol: Any) -> list[tuple[PointRef, None]]:
    """Every material point of a moving body that moves; coincident points moving alike
    appear once."""
    inst = sol.inst
    speed, accel = sol.scales()
    moving = []
    for ref in sol.model.material_points():
        if ref.body == sol.model.frame:
            continue
        v, a = inst.numvec(sol.velocity(ref)), inst.numvec(sol.acceleration(ref))
        if np.linalg.norm(v) > 1e-9 * speed or np.linalg.norm(a) > 1e-9 * accel:
            key = tuple(round(x / inst.scale, 9) for x in inst.numvec(sol.position(ref))) + \
                tuple(round(x / max(speed, 1e-300), 6) for x in v)
            moving.append((ref, None, key))
    return [(ref, rel) for ref, rel, _ in _unique(moving, key=lambda item: item[2])]


def magnitude_text(sol: Any, value: tuple, magnitude: float, lang: Optional[str] = None,
                   answer: bool = False) -> str:
    """The magnitude as shown: 3 significant digits, or a short exact formula (symbolic);
    numbers as `lang` writes them (`names.value_text`). The `answer` of an asked vector is
    written with its formula up to `names.ANSWER_CHARS` characters, not `FORMULA_CHARS`: the
    figure's arrow of the asked v_P carries the page's answer beside it, as the teacher
    writes it (C5-E.6's v_P = v(R·R_roda − L·r)/(R·R_roda), shown by its name alone before;
    issue 30, twenty-ninth round (g))."""
    if magnitude == 0:
        return "0"
    if not sol.symbolic:
        return value_text(magnitude, lang)
    return formula(signed_bars(sol.norm(value), drawing_values(sol.inst)), magnitude, lang,
                   sol.model.wording.parameter_symbols(lang), ANSWER_CHARS if answer else FORMULA_CHARS)


def signed_bars(expr: Any, values: dict) -> Any:
    """`expr` with each |x| written as x or −x, the sign x has at `values` (the numbers the
    figure is drawn at): the figure shows that instant, and the text writes the factor signed,
    as the notes do (C5-2.1: v_RL = √2·v₀·(L − s)/(2·L), not |L − s|, with L > s drawn).
    A factor that vanishes there keeps its bars."""
    import sympy

    if not values or not getattr(expr, "has", lambda *_: False)(sympy.Abs):
        return expr

    def unbarred(x: Any) -> Any:
        try:
            at = float(x.xreplace(values))
        except (TypeError, ValueError):
            return sympy.Abs(x)
        return x if at > 0 else -x if at < 0 else sympy.Abs(x)

    return expr.replace(sympy.Abs, unbarred)


# instant centres -------------------------------------------------------------------------
def _centres(scene: Scene, sol: Any, options: DrawOptions, num: Numbers) -> None:
    _asked_centres(scene, sol, options, num)
    _normals(scene)
    if options.centres and scene.dim == 2:
        _radii(scene, sol, num, _pairs(options))
        _construction(scene, sol, num, options.construction or [])


def _construction(scene: Scene, sol: Any, num: Numbers, lines: list) -> None:
    """The lines a text places a centre on, each from its point to the centre (`DrawOptions.
    construction`): a centre said to be where two lines meet is drawn with those lines, as a
    student draws them (issue 30, nineteenth round (d): C5-1.1's I_pulley sat below the
    pulley with the strands' lines, which the text says meet there, stopping at J and K). A
    line already drawn (an Aronhold–Kennedy line, a line to a pin) is that line reaching on."""
    from ..questions.centres import all_centres

    by_pair = {frozenset(c.pair): c for c in all_centres(sol)}
    drawn = scene.normals + scene.kennedy
    for pair, at in lines:
        c = by_pair.get(frozenset(pair))
        if c is None or c.value.get("point") is None:
            continue
        centre, p = num.page(c.value["point"]), num.page(at)
        d = centre - p
        if np.linalg.norm(d) <= 1e-9 * scene.size:
            continue
        same = next((k for k in drawn if _on_line(k, p, d, scene.size)), None)
        if same is not None:
            same.anchors += [p, centre]
            continue
        line = KennedyLine(f"radius:{'-'.join(pair)}:{len(scene.kennedy)}", p, d, [p, centre])
        scene.kennedy.append(line)
        drawn.append(line)


def _normals(scene: Scene) -> None:
    """Where a knife-edge wheel or a pin in a slot joins two bodies whose centre is shown,
    the normal to the wheel's plane (to the slot) at the joint: the centre lies on it. Two
    wheels on one axle give one line."""
    for j in scene.joints:
        if j.kind.centre is not Centre.NORMAL or j.at is None or j.along is None:
            continue
        mark = next((m for m in scene.marks if m.kind == "icr" and not m.rest
                     and set(m.pair) == {j.a, j.b}), None)
        if mark is None:
            continue
        n = np.array([-j.along[1], j.along[0]])
        anchors = [j.at] if mark.point is None else [j.at, mark.point]   # at ∞: along n
        same = next((k for k in scene.normals if abs(float((j.at - k.through) @ perpendicular(
            k.direction))) <= 1e-9 * scene.size and abs(float(n @ k.direction)) > 1 - 1e-9), None)
        if same is None:
            scene.normals.append(KennedyLine(f"normal:{j.id}", j.at, n, anchors))
        else:
            same.anchors += anchors


def _pairs(options: DrawOptions) -> Optional[set]:
    """The pairs of bodies whose centres to draw (`DrawOptions.centre_pairs`), or None: all."""
    return None if options.centre_pairs is None else {frozenset(p) for p in options.centre_pairs}


def _radii(scene: Scene, sol: Any, num: Numbers, pairs: Optional[set] = None) -> None:
    """A centre found from velocities (a vehicle's unit): the line from it to each pin of
    its body, the perpendicular to that pin's velocity (the trailer's centre on the line
    through the tractor's centre and the hitch), unless a line already drawn is that one."""
    from ..questions.centres import all_centres

    drawn = scene.normals + scene.kennedy
    for c in all_centres(sol):
        if c.how != "velocities" or c.value.get("point") is None or sol.model.frame not in c.pair \
                or (pairs is not None and frozenset(c.pair) not in pairs):
            continue
        centre = num.page(c.value["point"])
        for j in scene.joints:
            if not j.kind.pins or j.at is None or not set(c.pair) & {j.a, j.b} - {sol.model.frame}:
                continue
            d = centre - j.at
            if np.linalg.norm(d) <= 1e-9 * scene.size:
                continue
            same = next((k for k in drawn if _on_line(k, j.at, d, scene.size)), None)
            if same is not None:
                same.anchors += [j.at, centre]
                continue
            line = KennedyLine(f"radius:{'-'.join(c.pair)}:{j.id}", j.at, d, [j.at, centre])
            scene.kennedy.append(line)
            drawn.append(line)


def _on_line(k: KennedyLine, p: Any, d: Any, size: float) -> bool:
    """Whether the line through p along d is the line k."""
    u = np.asarray(k.direction, float) / np.linalg.norm(k.direction)
    w = np.asarray(d, float) / np.linalg.norm(d)
    return abs(float((p - k.through) @ perpendicular(u))) <= 1e-6 * size and abs(float(u @ w)) > 1 - 1e-9


def _asked_centres(scene: Scene, sol: Any, options: DrawOptions, num: Numbers) -> None:
    if options.centres is False:
        return
    if options.centres and scene.dim == 2:
        _all_centres(scene, sol, num, options.lang, _pairs(options))
        return
    if options.centres:
        scene.notes.append("instant centres are planar: not drawn for a 3D model")
    model = sol.model
    for q in drawn_questions(model).centres:
        name = q.target if not q.relative_to else f"{q.target}/{q.relative_to}"
        label = pair_symbol("I", model, q.relative_to or model.frame, q.target, options.lang)
        _add_centre(scene, num, answer(sol, q), f"icr:{name}", label,
                    (q.relative_to or model.frame, q.target))


def _add_centre(scene: Scene, num: Numbers, value: dict, key: str, label: str,
                pair: tuple) -> None:
    if value.get("rest"):
        scene.marks.append(MarkView("icr", key, label, pair=pair, rest=True))
    elif value.get("point") is not None:
        scene.marks.append(MarkView("icr", key, label, point=num.page(value["point"]), pair=pair))
    else:
        d = num.page(value["direction"])
        scene.marks.append(MarkView("icr", key, label, direction=d / np.linalg.norm(d), pair=pair))


def _all_centres(scene: Scene, sol: Any, num: Numbers, lang: Optional[str] = None,
                 pairs: Optional[set] = None) -> None:
    """Every centre (or those of `pairs`), labelled I₁₃ by body numbers, with the Kennedy
    lines that found them (from two centres drawn)."""
    from ..questions.centres import all_centres

    centres = all_centres(sol)
    number = {name: b.number for name, b in scene.bodies.items()}
    by_pair = {frozenset(c.pair): c for c in centres}
    shown = set(by_pair) if pairs is None else set(by_pair) & pairs
    for c in centres:
        if frozenset(c.pair) not in shown:
            continue
        a, b = sorted(c.pair, key=lambda name: number[name])
        _add_centre(scene, num, c.value, f"centre:{a}-{b}", pair_symbol("I", sol.model, a, b, lang),
                    (a, b))
    for c in centres:
        if c.how not in ("kennedy", "lines") or frozenset(c.pair) not in shown:
            continue
        thirds = c.via if c.how == "kennedy" else [name for kind, name in c.lines if kind == "third"]
        for third in thirds:
            if not {frozenset((c.pair[0], third)), frozenset((third, c.pair[1]))} <= shown:
                continue
            line = _kennedy_line(num, by_pair[frozenset((c.pair[0], third))].value,
                                 by_pair[frozenset((third, c.pair[1]))].value, c.value)
            if line is not None:
                scene.kennedy.append(KennedyLine(f"kennedy:{'-'.join(c.pair)}:{third}", *line))


def _kennedy_line(num: Numbers, c1: dict, c2: dict, target: dict):
    """(through, direction, anchors) of the line through two centres (one may be at infinity)."""
    finite = [num.page(c["point"]) for c in (c1, c2, target) if c.get("point") is not None]
    infinite = [num.page(c["direction"]) for c in (c1, c2) if c.get("direction") is not None]
    if len(finite) >= 2 and np.linalg.norm(finite[1] - finite[0]) > 1e-12:
        return finite[0], finite[1] - finite[0], finite
    if finite and infinite:
        return finite[0], infinite[0], finite
    return None


# curvature -------------------------------------------------------------------------------
def _curvatures(scene: Scene, sol: Any, num: Numbers, lang: Optional[str] = None) -> None:
    for q in drawn_questions(sol.model).circles:
        name = point_symbol("ℜ", sol.model, q.target.point, q.target.body, q.relative_to, lang)
        value = answer(sol, q)
        if value.get("rest"):
            scene.notes.append(word("note-curvature-rest", lang, label=bare(name)))
            continue
        if value.get("radius") is None:
            scene.notes.append(word("note-curvature-straight", lang, label=bare(name)))
            continue
        p, c = num.vector(sol.position(q.target)), num.vector(value["center"])
        radius = num.scalar(value["radius"])
        v = num.vector(sol.velocity(q.target, q.relative_to))
        text = formula(value["radius"], radius, lang, sol.model.wording.parameter_symbols(lang)) if sol.symbolic \
            else value_text(radius, lang)
        scene.curvatures.append(CurvatureView(
            str(q.target) + (f"/{q.relative_to}" if q.relative_to else ""),
            equation(name, text), num.proj(p), num.proj(c), radius,
            _circle(num, c, p, v)))


def _circle(num: Numbers, centre: np.ndarray, p: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The osculating circle through p about `centre`, tangent to v, sampled every 2°."""
    r = p - centre
    radius = float(np.linalg.norm(r))
    u = r / radius
    t = v - (v @ u) * u
    w = t / np.linalg.norm(t)
    angles = np.linspace(0, 2 * math.pi, 181)
    pts = centre + radius * (np.outer(np.cos(angles), u) + np.outer(np.sin(angles), w))
    return np.array([num.proj(x) for x in pts])


# poles, contacts, screw axes ---------------------------------------------------------------
def _axis_label(model: Any, q: Any, lang: Optional[str]) -> str:
    """A screw axis in the course's words with its bodies as the text writes them
    (EIRL with 3/2 as its subscript: the blades relative to the block), never English words
    in another language's figure."""
    from ..model.wording import SCREW_AXIS

    labels = body_labels(model, lang, named=False)
    word = SCREW_AXIS.get(lang or "en", SCREW_AXIS["en"]).replace(" ", r"\ ")
    rel = q.relative_to if q.relative_to not in (None, model.frame) else None
    tag = labels[q.target] + (f"/{labels[rel]}" if rel else "")
    return "$\\mathrm{" + word + "}_{\\mathrm{" + tag + "}}$"


def _other_marks(scene: Scene, sol: Any, num: Numbers, lang: Optional[str] = None) -> None:
    for mark, q in drawn_questions(sol.model).marks:
        mark(scene, sol, num, lang, q)


def _pole(scene: Scene, sol: Any, num: Numbers, lang: Optional[str], q: Any) -> None:
    value = answer(sol, q)
    if value.get("point") is not None:
        label = subscript("Γ", body_labels(sol.model, lang)[q.target])
        scene.marks.append(MarkView("pole", f"pole:{q.target}", label,
                                    point=num.page(value["point"]), pair=(q.target,)))


def _contact(scene: Scene, sol: Any, num: Numbers, lang: Optional[str], q: Any) -> None:
    value = answer(sol, q)
    if value.get("point") is not None:
        name = contact_name(sol.model, q.target, sol)
        label = subscript("J", name[1:]) if name[1:].isdigit() else "$\\mathrm{" + name + "}$"
        scene.marks.append(MarkView("contact", f"contact:{q.target}", label, point=num.page(value["point"])))


def _axis(scene: Scene, sol: Any, num: Numbers, lang: Optional[str], q: Any) -> None:
    if scene.dim != 3:
        return
    value = answer(sol, q)
    if value.get("point") is not None:
        scene.axes.append(AxisView(f"axis:{q.target}", _axis_label(sol.model, q, lang),
                                   num.page(value["point"]), num.page(value["direction"])))


# which questions are drawn how ---------------------------------------------------------------
class Drawn:
    """The model's questions by the way a figure draws them, each kind choosing its way
    (`QuestionKind.draw`, a `questions.Figure`): arrows of each level at their points,
    compositions' parts, instant centres, curvature circles, and marks (a pole, a contact
    point, a screw axis) with the function that adds each, in the order asked."""

    def __init__(self, questions: list) -> None:
        self.arrows: dict[str, list] = {kind: [] for kind in KINDS}
        self.compositions: list = []
        self.centres: list = []
        self.circles: list = []
        self.marks: list = []
        self.contacts: list = []
        for q in questions:
            QUESTIONS[q.kind].draw(self, q)

    def arrow(self, q: Any, level: str) -> None:
        """An arrow of the point's velocity or acceleration (`vector_targets`)."""
        self.arrows[level].append(q)

    def composition(self, q: Any) -> None:
        """A composition's parts (`_decompositions`)."""
        self.compositions.append(q)

    def instant_centre(self, q: Any) -> None:
        """An instant centre's mark (`_asked_centres`)."""
        self.centres.append(q)

    def path_circle(self, q: Any) -> None:
        """A curvature circle (`_curvatures`)."""
        self.circles.append(q)

    def acceleration_pole(self, q: Any) -> None:
        """A pole's mark Γ (`_pole`)."""
        self.marks.append((_pole, q))

    def contact_point(self, q: Any) -> None:
        """A contact's mark J (`_contact`), and its three coincident points where a figure
        draws them (`_coincident`)."""
        self.marks.append((_contact, q))
        self.contacts.append(q)

    def screw_axis(self, q: Any) -> None:
        """A screw axis, in a 3D figure (`_axis`)."""
        self.marks.append((_axis, q))


def drawn_questions(model: Any) -> Drawn:
    """The model's questions by the way a figure draws them (`Drawn`)."""
    return Drawn(model.questions)
