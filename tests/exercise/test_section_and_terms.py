"""The model's `exercise` section (the plain check and pydantic alike, its errors), the
exercise catalogues, and the engine's hook for a student's mistakes (`engine.terms`),
against the hand derivations."""
from __future__ import annotations

import copy
import math

import numpy as np
import pytest
import yaml
from pydantic import ValidationError

from kinematika.api import solve
from kinematika.engine.terms import MECHANICS, Terms
from kinematika.errors import KinematikaError
from kinematika.exercise.catalogue import LANGS, catalogue
from kinematika.model import schema, shape
from kinematika.model.build import build_model
from kinematika.report.json_answer import solution_json

from . import derive
from .conftest import FOUR_BAR, P_PAIR

TREE = yaml.safe_load(P_PAIR.read_text(encoding="utf-8"))


def _plain(x):
    if isinstance(x, shape.Record):
        return {k: _plain(getattr(x, k)) for k in x.FIELDS}
    if hasattr(type(x), "model_fields"):
        return {k: _plain(getattr(x, k)) for k in type(x).model_fields}
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_plain(v) for v in x]
    return x


def test_the_plain_check_reads_the_section_as_pydantic_does():
    for path in (P_PAIR, FOUR_BAR):
        tree = yaml.safe_load(path.read_text(encoding="utf-8"))
        mine = shape.spec_of(tree)
        assert mine is not None and _plain(mine) == _plain(schema.ModelSpec.model_validate(tree))
    odd = copy.deepcopy(TREE)
    odd["exercise"]["tolerance"] = "0.01"                  # a string: both refuse it
    assert shape.spec_of(odd) is None
    with pytest.raises(ValidationError):
        schema.ModelSpec.model_validate(odd)


@pytest.mark.parametrize("change, where", [
    ({"units": {"s": "furlong"}}, "exercise.units.s"),
    ({"units": {"nope": "mm"}}, "exercise.units.nope"),
    ({"statement": {"en": "AB = {q}"}}, "exercise.statement.en"),
    ({"statement": {"fr": "AB"}}, "exercise.statement.fr"),
    ({"ask": [7]}, "exercise.ask[0]"),
    ({"tolerance": 2}, "exercise.tolerance"),
    ({"length": "deg"}, "exercise.length"),
    ({"dimensions": [{"between": ["A", "Z"]}]}, "exercise.dimensions[0].between"),
])
def test_a_wrong_section_is_a_schema_error_naming_its_place(change, where):
    tree = copy.deepcopy(TREE)
    tree["exercise"].update(change)
    with pytest.raises(KinematikaError) as err:
        build_model(tree)
    assert (err.value.kind, err.value.where) == ("schema", where)


def test_the_catalogues_have_the_same_messages_and_variables():
    import re

    english = catalogue("en")
    for lang in LANGS:
        cat = catalogue(lang)
        assert cat.keys() == english.keys(), lang
        for key in english.keys():  # noqa: SIM118 (a catalogue's message ids, not a dict)
            message = english.bundle.get_message(key).value
            ours = cat.bundle.get_message(key).value
            assert set(re.findall(r"\$(\w+)", str(message))) <= set(re.findall(r"\$(\w+)", cat.source)), key
            assert ours is not None


def _answers(terms):
    return [a["value"] for a in solution_json(solve(P_PAIR, terms=terms))["answers"]]


@pytest.mark.parametrize("terms", [MECHANICS, Terms(coriolis=0), Terms(coriolis=2), Terms(normal=0),
                                   Terms(coriolis=0, normal=0)])
def test_the_engine_solves_the_p_pair_with_each_terms_as_the_hand_derivation(terms):
    got = _answers(terms)
    want = derive.p_pair(0.4, math.radians(30), 0.1, 0.4, 4, -2, terms.coriolis, terms.normal)
    for g, q in zip(got, ("q1", "q2", "q3", "q4", "q5", "q6")):
        assert np.allclose(g, want[q], rtol=1e-9, atol=1e-9), q


def test_the_decomposition_adds_up_in_a_world_with_a_mistake():
    model = TREE | {"ask": [{"decompose": "B@N", "moving": "M"}]}
    model = {k: v for k, v in model.items() if k != "exercise"}
    for terms in (Terms(coriolis=0), Terms(coriolis=2), Terms(normal=0)):
        parts = solution_json(solve(model, terms=terms))["answers"][0]["value"]["acceleration"]
        total = np.add(np.add(parts["drag"], parts["relative"]), parts["coriolis"])
        assert np.allclose(total, parts["total"], atol=1e-9)
        v_rel = np.asarray(_answers(MECHANICS)[2])                 # the velocities do not change
        assert np.allclose(parts["coriolis"], terms.coriolis * 2 * 4 * derive.k(v_rel), atol=1e-9)  # 2c ω k×v_rel


def test_mechanics_is_what_every_command_solves():
    assert Terms() == MECHANICS and MECHANICS.mechanics
    assert solution_json(solve(P_PAIR)) == solution_json(solve(P_PAIR, terms=MECHANICS))
