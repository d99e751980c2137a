"""The page's exercise mode: POST /api/exercise (the statement without the key, answers
marked with the diagnoses `grade` gives, the worked solution on request), and the page
itself in Chromium (browser tests)."""
from __future__ import annotations

import json
import warnings

import pytest

from .conftest import P_PAIR, P_PAIR_VARY


@pytest.fixture(scope="module")
def client():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from starlette.testclient import TestClient

        from kinematika.web.server import create_app

        with TestClient(create_app()) as c:
            yield c


def body(**extra):
    return {"model": P_PAIR.read_text(encoding="utf-8"), "vary": P_PAIR_VARY, "seed": 7, "variant": 3,
            "lang": "eu", **extra}


def test_the_statement_comes_without_the_key(client, p_pair_exercise):
    got = client.post("/api/exercise", json=body())
    assert got.status_code == 200, got.text
    data = got.json()
    v = p_pair_exercise.variants[2]
    assert data["variant"] == 3 and data["title"] == "P bikotea Coriolisekin"
    assert [p["question"] for a in data["asks"] for p in a["parts"]] == [r.question for r in v.rows]
    assert f"AB = {v.stated['s'].normalize():f}\u00a0mm" in data["statement"]
    assert data["figure"].startswith("data:image/png;base64,")
    text = json.dumps(data)
    for r in v.rows:                                   # no value of the key, however written
        assert f"{r.value:.4g}" not in text and f"{r.value:.4g}".replace(".", ",") not in text


def test_answers_are_marked_with_the_diagnoses_grade_gives(client, p_pair_exercise):
    v = p_pair_exercise.variants[2]
    mistakes = {m.kind: m for m in v.mistaken}
    answers = {"q1": repr(v.rows[0].value).replace(".", ","), "q2": repr(mistakes["coriolis-omitted"].rows["q2"].value),
               "q3.x": "12345", "q3.y": ""}
    data = client.post("/api/exercise", json=body(answers=answers)).json()
    marks = {m["question"]: m for m in data["marks"]}
    assert set(marks) == {"q1", "q2", "q3.x"}
    assert marks["q1"]["correct"] and marks["q1"]["feedback"] == "Zuzena."
    assert (marks["q2"]["correct"], marks["q2"]["diagnosis"]) == (False, "coriolis-omitted")
    assert "Coriolis" in marks["q2"]["feedback"]
    assert (marks["q3.x"]["correct"], marks["q3.x"]["diagnosis"]) == (False, None)
    assert data["score"]["right"] == 1 and data["score"]["total"] == 10
    assert "solution" not in data


def test_the_worked_solution_comes_after_a_check(client):
    data = client.post("/api/exercise", json=body(answers={"q1": "1"}, reveal=True)).json()
    assert data["solution"].startswith('<div class="kinematika-solution">') and "Abiadurak" in data["solution"]
    for early in (body(reveal=True), body(answers={}, reveal=True)):
        got = client.post("/api/exercise", json=early)
        assert got.status_code == 400 and got.json()["error"]["where"] == "reveal"


def test_without_vary_the_exercise_is_the_models_own_data(client):
    data = client.post("/api/exercise", json={"model": P_PAIR.read_text(encoding="utf-8"), "lang": "ca"}).json()
    assert data["variant"] == 1 and "AB = 400\u00a0mm" in data["statement"]


@pytest.mark.parametrize("extra, where", [({"variant": 0}, "variant"), ({"vary": "s=1:2"}, "vary"),
                                          ({"answers": ["1"]}, "answers"), ({"reveal": 1}, "reveal"),
                                          ({"answers": {"q9": "1"}}, "answers.q9"), ({"colour": 1}, "colour")])
def test_a_wrong_request_is_the_contracts_error(client, extra, where):
    got = client.post("/api/exercise", json=body(**extra))
    assert got.status_code == 400 and got.json()["error"]["where"] == where
