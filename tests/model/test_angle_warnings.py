"""An angle far outside one turn where a drawing angle is expected (`angle: 30`, meant as
30°) is answered as written, with a warning naming the place and `deg(30)`: on standard
error, in the JSON answer's `warnings`, and as a Python warning."""
from __future__ import annotations

import json
import math
import subprocess
import sys
import warnings

import pytest
import yaml

from kinematika.commands import solve_data
from kinematika.errors import KinematikaWarning

R, L, W = 0.1, 0.3, 10.0


def slider_crank(angle) -> dict:
    return {"name": "Slider-crank", "parameters": {"r": R, "l": L, "w": W, "theta": angle},
            "points": {"O": [0, 0], "A": {"from": "O", "distance": "r", "angle": "theta"},
                       "B": {"circle": ["A", "l"], "line": {"through": "O", "direction": [1, 0]},
                             "side": "ahead"}},
            "bodies": {"ground": ["O"], "crank": ["O", "A"], "rod": ["A", "B"], "slider": ["B"]},
            "joints": [{"type": "revolute", "bodies": ["ground", "crank"], "at": "O"},
                       {"type": "revolute", "bodies": ["crank", "rod"], "at": "A"},
                       {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"},
                       {"type": "prismatic", "bodies": ["ground", "slider"], "along": [1, 0]}],
            "drivers": [{"omega": "crank", "value": "w"}], "ask": [{"velocity": "B"}]}


def piston_speed(t: float) -> float:
    """v_B = −r ω sin θ (1 + r cos θ / √(l² − r² sin² θ)), the textbook's slider-crank."""
    return -R * W * math.sin(t) * (1 + R * math.cos(t) / math.sqrt(L * L - (R * math.sin(t)) ** 2))


def test_thirty_radians_is_answered_as_written_with_a_warning():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        data = solve_data(slider_crank(30))
    assert data["answers"][0]["value"][0] == pytest.approx(piston_speed(30.0), rel=1e-9)
    assert data["warnings"] == [{"message": "the angle 30 is in radians: 1719°, 4.8 turns; for 30° write deg(30)",
                                 "where": "points.A.angle"}]
    assert [str(w.message) for w in caught if w.category is KinematikaWarning] == \
        ["points.A.angle: the angle 30 is in radians: 1719°, 4.8 turns; for 30° write deg(30)"]


@pytest.mark.parametrize("angle", ["deg(30)", 6, -6.2, "2*pi", "deg(350)", "deg(450)", "3*pi", None])
def test_angles_within_a_turn_written_as_angles_or_symbols_give_no_warning(angle):
    data = solve_data(slider_crank(angle))
    assert "warnings" not in data


def test_a_moved_crank_past_a_turn_gives_no_warning():
    tree = slider_crank("deg(350)")
    tree["move"] = {"j1": 90}                    # 440° as drawn plus moved: the drawing says 350°
    data = solve_data(tree)
    assert "warnings" not in data
    assert data["answers"][0]["value"][0] == pytest.approx(piston_speed(math.radians(440)), rel=1e-9)


def test_the_command_line_prints_one_warning_line(tmp_path):
    path = tmp_path / "crank.yaml"
    path.write_text(yaml.safe_dump(slider_crank(-40)))
    done = subprocess.run([sys.executable, "-m", "kinematika", "solve", str(path), "--json"],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0
    assert done.stderr == ("warning: points.A.angle: the angle -40 is in radians: -2292°, 6.4 turns; "
                           "for -40° write deg(-40)\n")
    assert json.loads(done.stdout)["warnings"][0]["where"] == "points.A.angle"
    given = subprocess.run([sys.executable, "-m", "kinematika", "solve", str(path), "--set", "theta=deg(-40)"],
                           capture_output=True, text=True, timeout=300)
    assert given.returncode == 0 and given.stderr == ""
