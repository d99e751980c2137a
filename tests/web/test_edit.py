"""A point dragged on the page becomes an edit of the model's text (`POST /api/edit`):
only the values that place the point change, and the edited model puts the point where it
was dropped (checked by solving the new text)."""
from __future__ import annotations

import json

import pytest

CONSTRUCTED = """\
# a four-bar drawn by construction
parameters: {theta: "deg(60)"}   # the crank angle
points:
  O2: [0, 0]
  O4: [4, 0]
  A: {from: O2, distance: 1, angle: theta}
  B: {circles: [[A, 4], [O4, 3]], side: left}
  P: {frame: [A, B], at: [2, 1]}
  C: {circle: [A, 3], line: [O2, O4], side: ahead}
  S: {lines: [[O2, A], [O4, B]]}
bodies:
  ground: [O2, O4, C, S]
  crank: [O2, A]
  coupler: [A, B, P]
  rocker: [B, O4]
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [rocker, ground], at: O4}
drivers:
  - {omega: crank, value: 10}
"""


def edit(client, text, point, to, fmt="yaml"):
    return client.post("/api/edit", json={"model": text, "format": fmt, "point": point, "to": to})


def position(client, text, point, fmt="yaml"):
    answer = client.post("/api/solve", json={"model": text, "format": fmt}).json()
    return next(v["position"] for k, v in answer["points"].items() if k.split("@")[0] == point)


def changed_lines(before: str, after: str) -> list[str]:
    return [b for a, b in zip(before.splitlines(), after.splitlines()) if a != b]


@pytest.mark.parametrize("point, to, lines", [
    ("O4", [4.5, 0.25], ["  O4: [4.5, 0.25]"]),
    # polar: the distance, and the angle's parameter (not the construction's text)
    ("A", [0, 1.5], ['parameters: {theta: "deg(90)"}   # the crank angle',
                     "  A: {from: O2, distance: 1.5, angle: theta}"]),
    ("B", [3.2, 3.1], None),          # two circles: both radii
    ("P", [2.5, 4.0], None),          # in the frame of A, B: `at`
])
def test_a_dragged_point_lands_where_it_was_dropped(client, point, to, lines):
    answer = edit(client, CONSTRUCTED, point, to)
    assert answer.status_code == 200
    text = answer.json()["model"]
    changed = changed_lines(CONSTRUCTED, text)
    if lines is not None:
        assert changed == lines
    assert all(point in line or "theta" in line for line in changed)      # nothing else moved
    assert position(client, text, point) == pytest.approx(to, abs=1e-3)


def test_a_point_on_a_circle_and_a_line_slides_along_its_line(client):
    text = edit(client, CONSTRUCTED, "C", [1.0, 0.3]).json()["model"]
    # A = (cos 60°, sin 60°); dropped near (1, 0.3), C stays on O2O4: at (1, 0), 1 from A
    assert changed_lines(CONSTRUCTED, text) == ["  C: {circle: [A, 1], line: [O2, O4], side: ahead}"]
    assert position(client, text, "C") == pytest.approx([1.0, 0.0], abs=1e-9)


def test_crossing_the_line_of_centres_changes_the_side(client):
    text = edit(client, CONSTRUCTED, "B", [3.0, -1.0]).json()["model"]
    assert "side: right" in text
    assert position(client, text, "B") == pytest.approx([3.0, -1.0], abs=1e-3)


def test_where_two_lines_meet_cannot_be_dragged(client):
    answer = edit(client, CONSTRUCTED, "S", [1, 1])
    assert answer.status_code == 400
    assert answer.json()["error"] == {"kind": "usage", "where": "points.S",
                                      "message": "S is where two lines meet: drag the points its "
                                                 "lines go through"}


def test_json_and_toml_texts_keep_their_format(client):
    tree = {"points": {"O": [0, 0], "A": {"from": "O", "distance": 1, "angle": "deg(0)"}},
            "bodies": {"ground": ["O"], "bar": ["O", "A"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "bar"], "at": "O"}],
            "drivers": [{"omega": "bar", "value": 2}]}
    text = edit(client, json.dumps(tree, indent=1), "A", [0, 2], fmt="json").json()["model"]
    moved = json.loads(text)["points"]["A"]
    assert moved == {"from": "O", "distance": 2, "angle": "deg(90)"}
    toml = '[points]\nO = [0, 0]  # pivot\nA = [1, 0]\n[bodies]\nground = ["O"]\nbar = ["O", "A"]\n'
    assert edit(client, toml, "A", [0.5, 0.25], fmt="toml").json()["model"] == \
        toml.replace("A = [1, 0]", "A = [0.5, 0.25]")


def test_a_coordinate_given_by_a_parameter_changes_the_parameter(client):
    """`O4: [d, 0]` dragged to (4.5, 0.25): d becomes 4.5 (the parameter keeps its meaning,
    and its comment), the literal 0 becomes 0.25."""
    text = ("parameters:\n  d: 4   # ground link\npoints:\n  O2: [0, 0]\n  O4: [d, 0]\n"
            "bodies:\n  ground: [O2, O4]\n")
    moved = edit(client, text, "O4", [4.5, 0.25]).json()["model"]
    assert moved == text.replace("d: 4 ", "d: 4.5 ").replace("[d, 0]", "[d, 0.25]")
    formula = text.replace("[d, 0]", '["d/2", 0]')
    answer = edit(client, formula, "O4", [1, 1])
    assert answer.status_code == 400 and "formula" in answer.json()["error"]["message"]
