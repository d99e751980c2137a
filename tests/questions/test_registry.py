"""A question kind lives in its module: no other module compares a question's kind with a
name or writes a kind's name as a string (they ask the kind, `QUESTIONS[q.kind]`), and every
kind registered says everything the rest of kinematika asks of it."""
from __future__ import annotations

import re
import typing
from pathlib import Path

import pytest

import kinematika
from kinematika.questions import MODULES, QUESTIONS, Figure, QuestionKind, Steps, field_kinds
from kinematika.questions.base import About, Level, Quantity
from tests.source_scan import SRC, names_written, source_lines

# velocity, acceleration, omega and alpha are also the motion's own words everywhere: a
# point's velocity and acceleration, a body's ω and α (the answer's table columns, the
# drivers' kinds, the levels of a solution, the arrows of a figure, a sweep's columns). Their
# name as a string says nothing, so they are caught by the comparison test, not by the
# names' test; the other kinds' names are caught by both.
MOTION = {"velocity", "acceleration", "omega", "alpha"}
NAMES = "|".join(sorted(set(MODULES) - MOTION, key=len, reverse=True))
# a kind's name as a string literal: 'icr', "pole" (Python and the page's JavaScript)
LITERAL = re.compile(rf"""(?<![\w.-])["']({NAMES})["']""")
# a question's kind compared or taken apart: q.kind == …, question.kind in (…), (q.kind, key)
# == …, q.kind[0]; (any object's `kind` written as one of the other kinds' names is a literal)
COMPARED = re.compile(r"""\b(q|question)\.kind\s*(==|!=|\bin\b|\bnot in\b|\[)|\(\s*(q|question)\.kind\s*,""")
# directories where these words mean something else than a question
OTHER_MEANINGS = {
    "questions": "the question kinds themselves",
    "joints": "the joints' kinds and keys (a `contact` joint, a revolute's `axis`)",
    "sweep": "a joint's `axis` in the sweep's compiled paths and carried shapes",
}
ALLOWED_WORDS = {           # the same words meaning something else, with where and what
    # the generated plain check (its question record's keys, from `schema`)
    **dict.fromkeys(("decompose", "intrinsic", "inflection"), ("model/shape.py",)),
    "contact": ("model/shape.py",
                "draw/results.py", "draw/scene.py", "draw/marks.py", "web/static/js/figure.js",    # a scene's contact mark
                "explain/terms.py",                 # a term's kind: a contact's motion
                "explain/group.py",                 # a route's segment through a contact (beside "slide")
                "cli/cam.py"),                      # a cam design's follower: its `contact` (roller, flat)
    "axis": ("model/shape.py", "model/schema.py",   # a joint's `axis` key
             "model/builder.py",                    # a disc's axis
             "web/rename.py",                       # a joint's `axis` through renamed points
             "web/static/js/builder.js"),           # a drawn axis' CSS class
    "icr": ("model/shape.py", "draw/results.py", "draw/scene.py", "draw/marks.py", "draw/figure.py",   # a scene's centre
            "web/static/js/figure.js"),                                               # mark (every centre)
    "pole": ("model/shape.py", "draw/results.py", "draw/scene.py", "draw/marks.py", "draw/figure.py", "web/static/js/figure.js",   # a scene's
             "explain/answers.py",              # an inflection answer's `pole` field (its unit)   # pole mark
             "explain/polygon.py", "explain/render/svg.py"),   # a velocity polygon's pole
    "curvature": ("model/shape.py", "draw/animation.py", "web/requests.py", "web/server.py",   # the figure's `curvature`
                  "web/scene_json.py", "web/static/js/figure.js", "draw/marks.py",   # layer and its colour
                  "explain/higher.py"),             # a derivation's kind: ρ of a contact's path
}



def test_no_module_compares_a_questions_kind():
    found = [f"{rel}:{i}: {line.strip()}" for rel, i, line in source_lines(OTHER_MEANINGS)
             if COMPARED.search(line)]
    assert not found, "\n".join(found)


def test_no_module_writes_a_question_kinds_name():
    found = names_written(OTHER_MEANINGS, LITERAL, ALLOWED_WORDS)
    assert not found, "\n".join(found)


def test_the_tests_catch_a_kind_named_outside_its_module():
    """The two patterns see what they are for (a test that cannot fail is no test)."""
    assert COMPARED.search('if q.kind == "omega":') and COMPARED.search("if q.kind in POINT_QUESTIONS:")
    assert COMPARED.search('(q.kind, key) == ("axis", "omega")') and COMPARED.search('Sym(q.kind[0], sub)')
    assert not COMPARED.search("kind = QUESTIONS[q.kind]") and not COMPARED.search('d.kind == "omega"')
    assert not COMPARED.search("rows_of(k, q.kind, value)")
    assert LITERAL.search('QUESTIONS = ("velocity", "icr", "curvature")')
    assert not LITERAL.search('msg("ask.icr")') and not LITERAL.search('"velocity"')


def _members(protocol: type) -> set[str]:
    return {name for name in vars(protocol) if not name.startswith("_")}


class _Recorder:
    """Stands in for a view's toolkit: records which of its ways a kind calls."""

    def __init__(self) -> None:
        self.called: list[str] = []

    def __getattr__(self, name: str):
        return lambda *args, **kwargs: self.called.append(name)


@pytest.mark.parametrize("name", list(MODULES))
def test_every_kind_says_what_the_others_ask(name):
    kind = QUESTIONS[name]
    assert isinstance(kind, QuestionKind) and kind.name == name and kind.summary and type(kind).__doc__
    assert type(kind).answer is not QuestionKind.answer, f"{name} is not answered"
    assert kind.about in typing.get_args(About) and kind.level in typing.get_args(Level)
    assert kind.unit_kind in typing.get_args(Quantity)
    assert set(kind.dimensions) <= {2, 3} and kind.dimensions
    assert all(k is None or k in typing.get_args(Quantity) for k in kind.fields.values())
    assert not kind.column or (kind.about in ("point", "body") and not kind.fields), \
        f"{name}: a table's column is a point's or a body's plain value"
    module = __import__(f"kinematika.questions.{MODULES[name]}", fromlist=["KIND"])
    assert module.KIND is kind and module.__doc__
    drawing, steps = _Recorder(), _Recorder()
    kind.draw(drawing, None)
    kind.explain(steps, None)
    assert len(drawing.called) <= 1 and set(drawing.called) <= _members(Figure), drawing.called
    assert len(steps.called) <= 1 and set(steps.called) <= _members(Steps), steps.called


def _catalogue(package: str) -> str:
    return (SRC / package / "locales" / "en.ftl").read_text(encoding="utf-8")


@pytest.mark.parametrize("name", list(MODULES))
def test_every_kind_has_its_catalogue_lines(name):
    """The explanation names a kind by its `ask-NAME` (unless it writes a symbol), and the page
    labels the kinds it offers by `q-NAME`."""
    kind = QUESTIONS[name]
    if type(kind).label is QuestionKind.label:
        assert re.search(rf"^ask-{name} = ", _catalogue("explain"), re.M), name
    if kind.page:
        assert re.search(rf"^q-{name} = ", _catalogue("web"), re.M), name


def test_a_field_means_the_same_in_every_answer():
    for kind in QUESTIONS.values():
        for field, quantity in kind.fields.items():
            assert field_kinds()[field] == quantity, (kind.name, field)


PLANAR = {"points": {"O2": [0, 0], "A": [0.1, 0.1], "B": [0.4, 0.2], "O4": [0.35, -0.05]},
          "bodies": {"ground": ["O2", "O4"], "crank": ["O2", "A"], "coupler": ["A", "B"], "rocker": ["O4", "B"]},
          "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O2"},
                     {"type": "revolute", "bodies": ["crank", "coupler"], "at": "A"},
                     {"type": "revolute", "bodies": ["coupler", "rocker"], "at": "B"},
                     {"type": "revolute", "bodies": ["rocker", "ground"], "at": "O4"}],
          "drivers": [{"omega": "crank", "value": 10, "alpha": 3}],
          "ask": [{"velocity": "B@coupler"}, {"acceleration": "B", "relative_to": "crank"}, {"omega": "coupler"},
                  {"alpha": "rocker"}, {"icr": "coupler"}, {"curvature": "B@coupler", "relative_to": "crank"},
                  {"decompose": "B@coupler", "moving": "crank"}, {"pole": "coupler"}, {"intrinsic": "B@coupler"},
                  {"inflection": "coupler"}]}


def _undeclared(kind: QuestionKind, value: object, path: str = "") -> list[str]:
    """The numbers of an answer not under a field its kind declares."""
    if not isinstance(value, dict):
        return [] if isinstance(value, bool) or value is None or not path else [path]
    out = []
    for key, part in value.items():
        if key not in kind.fields:
            out += _undeclared(kind, part, f"{path}.{key}")
    return out


@pytest.mark.parametrize("source", ["planar", "examples/planetary_gears.yaml", "examples/coin_rolling.yaml"])
def test_every_number_of_an_answer_is_in_a_declared_field(source):
    """The JSON's round-off and an exercise's key take a compound answer's kinds of quantity
    from the fields its kind declares: none is left to a default."""
    root = Path(__file__).resolve().parents[2]
    sol = kinematika.solve(PLANAR if source == "planar" else root / source)
    asked = {q.kind for q in sol.model.questions}
    assert source != "planar" or asked == set(MODULES) - {"contact", "axis"}
    for q in sol.model.questions:
        value = kinematika.questions.answer(sol, q)
        assert not _undeclared(QUESTIONS[q.kind], value), (q.kind, _undeclared(QUESTIONS[q.kind], value))


def test_the_questions_doc_has_a_row_per_kind_and_its_module():
    text = (SRC.parents[1] / "docs" / "questions.md").read_text(encoding="utf-8")
    rows = dict(re.findall(r"^\| `([a-z_]+)` \| `([a-z_]+\.py)` \|", text, re.M))
    assert rows == {name: f"{type(kind).__module__.rsplit('.', 1)[1]}.py" for name, kind in QUESTIONS.items()}


def test_the_page_asks_what_the_kinds_offer():
    """The builder's ask buttons are the kinds that say `page` (through `GET /api/palette`); a
    kind that takes a moving body gets it; another kind is refused, naming those offered."""
    from kinematika import KinematikaError
    from kinematika.web.build import apply, offered_questions

    assert offered_questions("point") == ["velocity", "acceleration", "curvature", "decompose"]
    assert offered_questions("body") == ["omega", "alpha", "icr"]
    text = ("points: {O: [0, 0], A: [1, 0], B: [2, 0]}\nbodies: {ground: [O], crank: [O, A], rod: [A, B]}\n"
            "joints:\n  - {type: revolute, bodies: [ground, crank], at: O}\n"
            "  - {type: revolute, bodies: [crank, rod], at: A}\n")
    asked, _ = apply(text, "yaml", {"op": "ask", "question": "decompose", "target": "B@rod"})
    assert "{decompose: B@rod, moving: rod}" in asked
    with pytest.raises(KinematikaError) as info:
        apply(text, "yaml", {"op": "ask", "question": "pole", "target": "rod"})
    assert info.value.said.args["kinds"] == offered_questions()
