"""A joint kind lives in its module: no other module compares a joint's type with a kind's
name or writes one as a string (they ask the kind's capabilities), and every kind registered
has everything the rest of kinematika asks of it."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from kinematika.joints import KINDS, MODULES, JointKind
from kinematika.joints.capabilities import Centre
from tests.source_scan import names_written, source_lines

NAMES = "|".join(sorted(MODULES, key=len, reverse=True))
# a kind's name as a string literal: 'revolute', "cam" (Python and the page's JavaScript)
LITERAL = re.compile(rf"""(?<![\w.-])["']({NAMES})["']""")
# comparisons of a type with anything: j.type == ..., .type in (...), type === in the page
COMPARED = re.compile(r"""\.type\s*(==|!=|===|!==|\bin\b|\bnot in\b)""")
# files where these words mean something else than a joint kind
OTHER_MEANINGS = {
    "cams": "a cam design's own words (a follower's `contact`)",
    "curves": "curves",
    "joints": "the joint kinds themselves",
    "exercise": "the mistakes' names",
}
ALLOWED_WORDS = {           # the same words meaning something else, with where and what
    # a question (`contact`), a shape key (`cam:`), a touching pair's geometry (`.contact`)
    "contact": ("model/model.py", "model/schema.py", "model/shape.py", "model/build.py", "model/generate_shape.py",
                "draw/results.py", "draw/marks.py", "draw/scene.py", "explain/answers.py", "explain/terms.py",
                "explain/contacts.py", "explain/needs.py", "web/static/js/figure.js", "questions/__init__.py", "questions/contact.py",
                "questions/centres.py", "report/json_answer.py",
                "report/units.py",                  # the `contact` question's unit
                "web/rename.py",                    # a renamed body in a `contact` question
                "cli/cam.py",                       # a cam design's follower: its `contact` (roller, flat)
                "explain/group.py"),                # a route's segment through a contact (beside "slide")
    "cam": ("model/build.py", "model/schema.py", "model/shape.py", "model/generate_shape.py",
            "cli/cam.py",                           # the `kinematika cam` answer's key
            "web/palette.py", "web/rename.py"),     # a body's `cam:` shape
    # how a centre was found (`Centre.how`): through a weld
    "weld": ("questions/centres.py", "explain/centres.py", "explain/render/base.py", "report/centres_table.py"),
    # a body's kind: a pitch circle, and the default names of new bodies in the page's languages
    "gear": ("draw/scene.py", "draw/build.py", "draw/bodies.py", "web/static/js/figure.js", "web/build.py", "web/palette.py"),
    "wheel": ("explain/group.py",                   # what a partly known point's motion comes from
              "model/subscripts.py", "model/wording.py",   # the word for a wheel in a body's name
              "web/build.py", "web/palette.py",
              "web/static/js/figure.js"),            # the browser's mouse-wheel event
}

# a capability that is a word compared with a string spelled again (`kind.coordinate == "angle"`),
# or a tuple of them: they compare with `joints.capabilities`' members
CAPABILITY_STRING = re.compile(
    r"""kind\.(coordinate|centre|chain|along_in|point_on)\s*(==|!=|\bin\b|\bnot in\b)\s*\(?\s*["']""")


def test_no_module_compares_a_capability_with_a_string():
    found = [f"{rel}:{i}: {line.strip()}" for rel, i, line in source_lines({"joints"})
             if CAPABILITY_STRING.search(line)]
    assert not found, "\n".join(found)


def test_no_module_compares_a_joints_type():
    found = [f"{rel}:{i}: {line.strip()}" for rel, i, line in source_lines(OTHER_MEANINGS)
             if COMPARED.search(line) and "joint" in line.lower() + Path(rel).name]
    assert not found, "\n".join(found)


def test_no_module_writes_a_kinds_name():
    found = names_written(OTHER_MEANINGS, LITERAL, ALLOWED_WORDS)
    assert not found, "\n".join(found)


@pytest.mark.parametrize("name", list(MODULES))
def test_every_kind_says_what_the_others_ask(name):
    kind = KINDS[name]
    assert isinstance(kind, JointKind) and kind.name == name and kind.summary and type(kind).__doc__
    assert kind.conditions(2 if 2 in kind.dimensions else 3) >= 1
    assert kind.rows is not JointKind.rows, f"{name} writes no rows"
    assert kind.add is not JointKind.add, f"{name} has no builder method"
    if kind.centre is Centre.NORMAL:                       # the explanation names the line it puts
        assert kind.centre_line, f"{name}: which line its centre is on"   # the centre on
    module = __import__(f"kinematika.joints.{MODULES[name]}", fromlist=["KIND"])
    assert module.__doc__ and ("Condition" in module.__doc__ or "condition" in module.__doc__), \
        f"{name}: its module's docstring says its condition"


def test_a_kind_without_its_hooks_cannot_be_made():
    """`JointKind` is abstract in the hooks every kind must fill (`conditions`, `rows`, `add`):
    a kind that forgets one fails where it is made (`KIND = Name()`), not at its first model."""
    class Half(JointKind):
        name = "half"

        def conditions(self, dim: int) -> int:
            return 1

    with pytest.raises(TypeError, match="abstract"):
        Half()
    assert JointKind.__abstractmethods__ == {"conditions", "rows", "add"}


def test_the_docs_table_is_written_from_the_registry():
    """docs/joints.md's table of the kinds is `joints.table`'s, written from the registry."""
    from kinematika.joints import table

    assert table.page(table.TARGET.read_text(encoding="utf-8")) == table.TARGET.read_text(encoding="utf-8"), \
        f"docs/joints.md's table is out of date: run {table.COMMAND}"
