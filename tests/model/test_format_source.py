"""The model format is written once: a joint's keys are those its kinds declare, a body's cam
takes the cam-design file's fields, the questions' keys are the question kinds (and each has
its answer). `shape`, the plain check, is generated from `schema` (tests/core/test_fast_paths.py)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from kinematika import KinematikaError
from kinematika.cams.spec import CamFileSpec, CamSpec
from kinematika.joints import KINDS
from kinematika.model import schema
from kinematika.model.build import build_model
from kinematika.questions import QUESTIONS, QuestionKind


def test_a_joints_keys_are_those_its_kinds_declare():
    declared = {key for kind in KINDS.values() for key in kind.fields}
    assert set(schema.JOINT_KEYS) == declared
    assert list(schema.JointSpec.model_fields) == ["type", "bodies", "id", *schema.JOINT_KEYS, "description"]


def test_a_key_declared_by_a_kind_follows_the_kinds(monkeypatch):
    for kind in KINDS.values():                                             # no kind has `internal`
        monkeypatch.setattr(kind, "fields", {k: v for k, v in kind.fields.items() if k != "internal"})
    assert schema._joint_keys() == ("at", "along", "axis")
    monkeypatch.setattr(KINDS["revolute"], "fields", {"at": "required", "profile": "optional"})
    with pytest.raises(TypeError, match="profile"):                         # a key without a type
        schema._joint_keys()


def test_a_body_cam_takes_the_cam_design_files_fields():
    fields = schema.BodyCamSpec.model_fields
    theirs = {**CamSpec.model_fields, **{k: CamFileSpec.model_fields[k] for k in ("follower", "program", "profile")}}
    assert list(fields) == ["center", "angle", "layout", *theirs]
    for name, field in theirs.items():
        mine = fields[name]
        assert (mine.annotation, mine.metadata, mine.default, mine.is_required()) == \
            (field.annotation, field.metadata, field.default, field.is_required()), name


def _cam(base: float) -> dict:
    return {"points": {"O": [0, 0], "F": [0, 50]},
            "bodies": {"ground": ["O"], "follower": ["F"],
                       "cam": {"points": ["O"], "cam": {"center": "O", "base": base,
                                                        "follower": {"motion": "translating", "contact": "knife"},
                                                        "program": [{"law": "dwell", "over": 360}]}}},
            "joints": [{"type": "revolute", "bodies": ["ground", "cam"], "at": "O"}]}


def test_a_cams_base_circle_is_checked_as_in_a_cam_design_file():
    """A negative base circle was let through by the model's own copy of the cam's fields and
    refused by the cam's (a pydantic traceback); now one check, one `schema` error."""
    assert build_model(_cam(40)).bodies["cam"].shapes
    with pytest.raises(KinematikaError) as info:
        build_model(_cam(-40))
    assert (info.value.kind, info.value.where) == ("schema", "bodies.cam")


def test_the_questions_keys_are_the_question_kinds_and_each_has_its_answer():
    assert list(schema.QuestionSpec.model_fields) == [*QUESTIONS, "relative_to", "moving"]
    assert all(type(kind).answer is not QuestionKind.answer for kind in QUESTIONS.values())


def _table_rows(doc: str, heading: str) -> dict[str, list[str]]:
    """The rows of the first table after `heading` in docs/`doc`, by their first cell's `name`."""
    text = (Path(__file__).parents[2] / "docs" / doc).read_text(encoding="utf-8")
    text = text[text.index(heading):]
    rows = {}
    for line in text.splitlines():
        if line.startswith("| `"):
            cells = [c.strip() for c in line.strip("|").split(" | ")]
            rows[re.match(r"`([a-z_]+)`", cells[0]).group(1)] = cells
        elif rows and not line.startswith("|"):
            break
    return rows


def test_the_formats_joints_table_names_each_kinds_keys():
    """docs/model-format.md's joints table: a row per kind, naming the keys its `fields` declare."""
    rows = _table_rows("model-format.md", "## Joints")
    assert set(rows) == set(KINDS)
    for name, cells in rows.items():
        assert set(re.findall(r"`([a-z_]+)`", cells[1])) == set(KINDS[name].fields), name


def test_the_joints_doc_has_a_row_per_kind_and_its_module():
    rows = _table_rows("joints.md", "# Joints")
    assert {name: cells[1] for name, cells in rows.items()} == \
        {name: f"`{type(kind).__module__.rsplit('.', 1)[1]}.py`" for name, kind in KINDS.items()}
