"""Naming through the API (`/api/build`'s `rename` and `name`): a body or a point renamed
everywhere the model names it and nowhere else, in YAML, TOML and JSON; names per language
in the model's `names:`; the frame named in the student's language. The expected texts are
written out here by hand."""
from __future__ import annotations

import pytest
import yaml

MODEL = """\
# a four-bar, as stated
parameters:
  B: 0.4          # a parameter spelt like a point: left alone
points:
  O2: [0, 0]
  O4: [0.4, 0]
  A: {from: O2, distance: 0.1, angle: deg(60)}
  B: {circles: [[A, B], [O4, 0.3]], side: left}   # B's circle about A has the radius B
  P: {frame: [A, B], at: [0.2, 0.05]}
bodies:
  ground: [O2, O4]
  crank: [O2, A]
  coupler: [A, B, P]
  rocker: [B, O4]
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [rocker, ground], at: O4}
drivers:
  - {omega: crank, value: 10, alpha: 0}
ask:
  - {velocity: B@coupler, relative_to: crank}
  - {omega: coupler}
  - {decompose: P, moving: coupler}
names:
  ca:
    bodies: {coupler: la biela}
    points: {B: articulació}
notation:
  omega(coupler/crank): omega_32
"""


def build(client, text, op, fmt="yaml", lang="en"):
    answer = client.post("/api/build", json={"model": text, "format": fmt, "op": op, "lang": lang})
    assert answer.status_code == 200, answer.text
    return answer.json()


def refused(client, text, op) -> str:
    answer = client.post("/api/build", json={"model": text, "op": op})
    assert answer.status_code == 400
    return answer.json()["error"]["message"]


def test_a_body_is_renamed_wherever_the_model_names_it(client):
    out = build(client, MODEL, {"op": "rename", "element": "body:coupler", "to": "biela"})
    assert out["select"] == "body:biela"
    assert out["model"] == (MODEL.replace("coupler: [A, B, P]", "biela: [A, B, P]")
                            .replace("[crank, coupler]", "[crank, biela]").replace("[coupler, rocker]", "[biela, rocker]")
                            .replace("B@coupler", "B@biela").replace("omega: coupler", "omega: biela")
                            .replace("moving: coupler", "moving: biela").replace("{coupler: la biela}", "{biela: la biela}")
                            .replace("omega(coupler/crank)", "omega(biela/crank)"))
    before = client.post("/api/solve", json={"model": MODEL}).json()
    after = client.post("/api/solve", json={"model": out["model"]}).json()
    assert after["answers"][1]["value"] == before["answers"][1]["value"]


def test_a_point_is_renamed_in_its_places_not_in_values(client):
    out = build(client, MODEL, {"op": "rename", "element": "point:B", "to": "C"})
    tree = yaml.safe_load(out["model"])
    assert tree["parameters"] == {"B": 0.4}                       # a value spelt B: not a point
    assert tree["points"]["C"] == {"circles": [["A", "B"], ["O4", 0.3]], "side": "left"}
    assert tree["points"]["P"] == {"frame": ["A", "C"], "at": [0.2, 0.05]}
    assert list(tree["points"]) == ["O2", "O4", "A", "C", "P"]    # in its place
    assert tree["bodies"]["coupler"] == ["A", "C", "P"] and tree["bodies"]["rocker"] == ["C", "O4"]
    assert tree["joints"][2]["at"] == "C"
    assert tree["ask"][0] == {"velocity": "C@coupler", "relative_to": "crank"}
    assert tree["names"]["ca"]["points"] == {"C": "articulació"}
    assert "  C: {circles: [[A, B], [O4, 0.3]], side: left}   # B's circle" in out["model"]   # its comment stays


def test_the_frame_is_renamed_and_named(client):
    out = build(client, MODEL, {"op": "rename", "element": "body:ground", "to": "bancada"})["model"]
    tree = yaml.safe_load(out)
    assert out.startswith("# a four-bar, as stated\nframe: bancada\nparameters:\n")   # where the format puts it
    assert tree["joints"][0]["bodies"] == ["bancada", "crank"]
    assert client.post("/api/solve", json={"model": out}).status_code == 200


@pytest.mark.parametrize("fmt", ["toml", "json"])
def test_renaming_in_toml_and_json(client, fmt):
    text = client.post("/api/convert", json={"model": MODEL, "to": fmt}).json()["model"]
    out = build(client, text, {"op": "rename", "element": "body:rocker", "to": "balanci"}, fmt=fmt)["model"]
    out = build(client, out, {"op": "rename", "element": "point:A", "to": "K"}, fmt=fmt)["model"]
    back = client.post("/api/convert", json={"model": out, "format": fmt, "to": "yaml"}).json()["model"]
    tree = yaml.safe_load(back)
    assert tree["bodies"]["balanci"] == ["B", "O4"] and tree["bodies"]["crank"] == ["O2", "K"]
    assert tree["points"]["B"]["circles"][0] == ["K", "B"]


def test_names_per_language_are_written_and_taken_away(client):
    out = build(client, MODEL, {"op": "name", "element": "body:rocker", "lang": "eu", "text": " balantza "})["model"]
    assert yaml.safe_load(out)["names"]["eu"] == {"bodies": {"rocker": "balantza"}}
    out = build(client, out, {"op": "name", "element": "point:P", "lang": "ca", "text": "punt de la biela"})["model"]
    assert yaml.safe_load(out)["names"]["ca"]["points"] == {"B": "articulació", "P": "punt de la biela"}
    out = build(client, out, {"op": "name", "element": "body:coupler", "lang": "ca", "text": ""})["model"]
    assert "coupler" not in yaml.safe_load(out)["names"]["ca"]["bodies"]
    assert client.post("/api/solve", json={"model": out}).status_code == 200


def test_a_name_taken_or_not_a_name_is_refused(client):
    assert "already" in refused(client, MODEL, {"op": "rename", "element": "body:crank", "to": "rocker"})
    assert "already" in refused(client, MODEL, {"op": "rename", "element": "point:A", "to": "B"})
    for bad in ("", "two words", "B@crank", "2A", "a/b"):
        assert "not a name" in refused(client, MODEL, {"op": "rename", "element": "point:A", "to": bad})
    assert "no body" in refused(client, MODEL, {"op": "rename", "element": "body:nothing", "to": "x"})
    assert "language" in refused(client, MODEL, {"op": "name", "element": "body:crank", "lang": "fr", "text": "x"})


def test_a_first_body_names_the_frame_in_the_students_language(client):
    for lang, word in (("eu", "lurra"), ("ca", "terra"), ("es", "bancada")):
        blank = client.get(f"/api/templates/blank?lang={lang}").json()["model"]
        out = build(client, blank, {"op": "add", "kind": "pivot", "picks": [[0, 0]]}, lang=lang)["model"]
        tree = yaml.safe_load(out)
        assert tree["frame"] == word and tree["bodies"] == {word: ["O1"]}
    english = build(client, "", {"op": "add", "kind": "pivot", "picks": [[0, 0]]})["model"]
    assert "frame" not in yaml.safe_load(english)
    named = build(client, "frame: base\n", {"op": "add", "kind": "pivot", "picks": [[0, 0]]}, lang="eu")["model"]
    assert yaml.safe_load(named)["bodies"] == {"base": ["O1"]}
