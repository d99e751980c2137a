"""Building by hand through the API (`/api/build`, `/api/sketch`), the Format menu's
conversion (`/api/convert`), the page's words (`/api/strings`), its palette, templates and
help pages. The expected texts are written out here by hand."""
from __future__ import annotations

import json
import re

import pytest

from kinematika.languages import LANGS
from kinematika.web.palette import TOOLS
from kinematika.web.strings import page_catalogue

START = """\
# my crank, as the problem states it
parameters:
  r: 0.05   # crank, m
points:
  O: [0, 0]
  A: {from: O, distance: r, angle: deg(30)}
bodies:
  ground: [O]
  crank: [O, A]
joints:
  - {type: revolute, bodies: [ground, crank], at: O}
"""


def build(client, text, op, fmt="yaml", lang="en"):
    answer = client.post("/api/build", json={"model": text, "format": fmt, "op": op, "lang": lang})
    assert answer.status_code == 200, answer.text
    return answer.json()


def test_a_link_is_added_by_construction_and_comments_stay(client):
    out = build(client, START, {"op": "add", "kind": "link", "picks": ["A", [0.2, 0.025]]})
    assert out["select"] == "body:link1"
    assert out["model"] == START.replace(
        "  A: {from: O, distance: r, angle: deg(30)}\n",
        "  A: {from: O, distance: r, angle: deg(30)}\n"
        "  B: {from: A, distance: 0.156699, angle: deg(0)}\n").replace(
        "  crank: [O, A]\n", "  crank: [O, A]\n  link1: [A, B]\n").replace(
        "at: O}\n", "at: O}\n  - {type: revolute, bodies: [crank, link1], at: A}\n")


def test_a_slider_puts_the_pin_on_its_guide(client):
    text = build(client, START, {"op": "add", "kind": "link", "picks": ["A", [0.2, 0.025]]})["model"]
    text = build(client, text, {"op": "add", "kind": "slider", "picks": ["B"]}, lang="eu")["model"]
    assert "  B: {circle: [A, 0.156699], line: {through: [0, 0.025], direction: [1, 0]}, side: ahead}" in text
    assert "  irristaria1: [B]" in text                      # named in the student's language
    assert "  - {type: prismatic, bodies: [ground, irristaria1], along: [1, 0]}" in text


def test_typing_a_length_named_by_a_parameter_changes_the_parameter(client):
    sketch = client.post("/api/sketch", json={"model": START}).json()
    length = next(r for r in sketch["properties"]["body:crank"] if r["label"] == "prop-length")
    assert (length["path"], length["value"], length["parameter"]) == (["parameters", "r"], 0.05, "r")
    assert sketch["points"]["A"] == pytest.approx([0.05 * 3 ** 0.5 / 2, 0.025])
    text = build(client, START, {"op": "set", "path": length["path"], "value": 0.06})["model"]
    assert text == START.replace("r: 0.05   #", "r: 0.06   #")
    angle = next(r for r in sketch["properties"]["body:crank"] if r["label"] == "prop-angle")
    assert angle["value"] == 30
    text = build(client, START, {"op": "set", "path": angle["path"], "value": 45, "unit": "deg"})["model"]
    assert "angle: deg(45)}" in text


def test_delete_takes_what_cannot_stay(client):
    text = build(client, START, {"op": "add", "kind": "link", "picks": ["A", [0.2, 0.025]]})["model"]
    text = build(client, text, {"op": "drive", "body": "crank", "value": 10, "alpha": 0})["model"]
    assert "  - {omega: crank, value: 10, alpha: 0}" in text
    gone = build(client, text, {"op": "delete", "element": "point:A"})["model"]
    import yaml

    tree = yaml.safe_load(gone)          # A, the point built on it, the bodies and their joints and driver
    assert (tree["points"], tree["bodies"], tree["joints"], tree["drivers"]) == \
        ({"O": [0, 0]}, {"ground": ["O"]}, [], [])
    assert gone.startswith("# my crank, as the problem states it\n")


def test_json_and_toml_texts_are_built_in_their_format(client):
    for fmt in ("json", "toml"):
        text = client.post("/api/convert", json={"model": START, "to": fmt}).json()["model"]
        out = build(client, text, {"op": "add", "kind": "pivot", "picks": [[0.3, 0]]}, fmt=fmt)["model"]
        solved = client.post("/api/sketch", json={"model": out, "format": fmt}).json()
        assert solved["points"]["O1"] == [0.3, 0.0] and "O1" in solved["bodies"]["ground"]["points"]


def test_converting_keeps_the_model(client):
    """YAML → TOML → JSON → YAML: the same answers (the same tree), a symbolic parameter as
    TOML's `{symbolic = true}`."""
    driven = START + "drivers:\n  - {omega: crank, value: 10}\n"
    first = client.post("/api/solve", json={"model": driven}).json()
    toml = client.post("/api/convert", json={"model": driven, "to": "toml"}).json()["model"]
    assert "[points]" in toml and 'A = {from = "O", distance = "r", angle = "deg(30)"}' in toml
    js = client.post("/api/convert", json={"model": toml, "format": "toml", "to": "json"}).json()["model"]
    back = client.post("/api/convert", json={"model": js, "format": "json", "to": "yaml"}).json()["model"]
    assert "  A: {from: O, distance: r, angle: deg(30)}" in back
    for text, fmt in ((toml, "toml"), (js, "json"), (back, "yaml")):
        assert client.post("/api/solve", json={"model": text, "format": fmt}).json() == first
    symbolic = driven.replace("r: 0.05", "r: null")
    toml = client.post("/api/convert", json={"model": symbolic, "to": "toml"}).json()["model"]
    assert "r = {symbolic = true}" in toml


def test_help_pages_are_served_and_nothing_else(client):
    page = client.get("/help")
    assert page.status_code == 200 and "<h1>Model format" in page.text
    walk = client.get("/docs/from-a-problem.md")
    assert walk.status_code == 200 and 'src="/docs/from-a-problem/' in walk.text
    assert client.get("/docs/../pyproject.toml").status_code == 404
    assert client.get("/docs/..%2F..%2Fpyproject.toml").status_code == 404


def test_every_language_has_every_word_of_the_page(client):
    """The same messages in every catalogue, with the same variables, no selectors (the page
    fills variables itself), and a name, a tip and a hint for each click of every palette kind."""
    english = page_catalogue("en")
    for lang in LANGS:
        cat = page_catalogue(lang)
        assert cat.keys() == english.keys(), lang
        assert "->" not in cat.source, lang
        words = client.get(f"/api/strings/{lang}").json()["messages"]
        for key, text in client.get("/api/strings/en").json()["messages"].items():
            assert set(re.findall(r"\{\$\w+\}", words[key])) == set(re.findall(r"\{\$\w+\}", text)), (lang, key)
        for tool in TOOLS:
            assert f"tool-{tool.kind}" in words and f"tool-{tool.kind}-tip" in words
            for n in range(1, len(tool.picks) + 1):           # what each click of the tool takes
                assert f"pick-{tool.kind}-{n}" in words, (lang, tool.kind, n)
    assert client.get("/api/strings/xx").status_code == 404
    kinds = [t["kind"] for t in client.get("/api/palette").json()["tools"]]
    assert kinds == [t.kind for t in TOOLS] and len(set(kinds)) == len(kinds)


def test_templates_are_stated_by_dimensions_in_each_language(client):
    for lang in LANGS:
        tpl = client.get(f"/api/templates/slider_crank?lang={lang}").json()["model"]
        answer = client.post("/api/solve", json={"model": tpl}).json()
        rod = [b for b in answer["bodies"].values() if abs(b["omega"] + 3.026) < 1e-3]
        assert len(rod) == 1, lang                       # ω_rod = −3.026 rad/s, derived in test_build
    assert json.loads(client.get("/api/templates/nothing").text)["error"]["kind"] == "usage"


def test_a_pin_in_a_circular_slot_from_the_palette(client):
    """The crank O2A (1 at 60°, 2 rad/s) and a rocker about B = (3, 0); the slot tool cuts
    an arc about C = (2.2, 1.6) through A in the rocker. By hand, the equivalent four-bar
    O2-A-C-B: v_A + ω_AC k × (C − A) = ω_r k × (C − B) gives the rocker's ω."""
    import numpy as np

    text = """\
points:
  O2: [0, 0]
  A: {from: O2, distance: 1, angle: deg(60)}
  B: [3, 0]
bodies:
  ground: [O2, B]
  crank: [O2, A]
  rocker: [B]
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [ground, rocker], at: B}
drivers:
  - {omega: crank, value: 2, alpha: 0}
ask:
  - {omega: rocker}
"""
    out = build(client, text, {"op": "add", "kind": "curved_slot",
                               "picks": ["A", {"body": "rocker"}, [2.2, 1.6]]})["model"]
    assert "  - {type: curved_slot, bodies: [rocker, crank], at: A}" in out
    assert "  rocker: {points: [B, C], circle: {center: C, radius: 1.85168}}" in out
    a, b, c = np.array([0.5, 3 ** 0.5 / 2]), np.array([3.0, 0]), np.array([2.2, 1.6])
    va = 2 * np.array([-a[1], a[0]])
    ac, bc = c - a, c - b
    m = np.array([[-ac[1], bc[1]], [ac[0], -bc[0]]])          # va + w3 k×AC = w4 k×BC
    _, w4 = np.linalg.solve(m, -va)
    omega = client.post("/api/solve", json={"model": out}).json()["answers"][0]["value"]
    assert omega == pytest.approx(w4, rel=1e-5)               # the radius is written to 6 digits


def test_a_contact_needs_two_outlines(client):
    text = """\
parameters: {e: 0.02, R: 0.05}
points:
  O: [0, 0]
  C: {from: O, distance: e, angle: deg(30)}
  F: [0, "e*sin(deg(30)) + R"]
bodies:
  ground: [O]
  cam: {points: [O, C], circle: {center: C, radius: R}}
  follower: [F]
joints:
  - {type: revolute, bodies: [ground, cam], at: O}
  - {type: prismatic, bodies: [ground, follower], along: [0, 1]}
"""
    op = {"op": "add", "kind": "contact", "picks": [{"body": "cam"}, {"body": "follower"}]}
    refused = client.post("/api/build", json={"model": text, "op": op})
    assert refused.status_code == 400 and "follower has no outline" in refused.json()["error"]["message"]
    flat = text.replace("  follower: [F]", "  follower: {points: [F], line: {through: F, direction: [1, 0]}}")
    out = build(client, flat + "drivers:\n  - {omega: cam, value: 10, alpha: 0}\nask:\n  - {velocity: F}\n", op)["model"]
    assert "  - {type: contact, bodies: [cam, follower]}" in out
    # by hand: the follower's height e sin θ + R, so v = e ω cos θ upwards
    v = client.post("/api/solve", json={"model": out}).json()["answers"][0]["value"]
    assert v == pytest.approx([0, 0.02 * 10 * 3 ** 0.5 / 2], abs=1e-12)
