"""A body's reference line, the one rule its angle θ is measured along (the sweep's summary
and plot, the figure's scene, the page's table and plot): from its fixed pivot — its first
point the frame carries at the same place — else its first point, to its first other
point drawn elsewhere. Cases by hand."""
from __future__ import annotations

import math

import pytest

from kinematika.sweep import run_sweep
from kinematika.sweep.angles import body_angle, reference_line

from .models import circle_meet, four_bar_tree


def test_the_line_starts_at_the_pivot_the_frame_carries_whatever_the_order():
    rocker = {"B": (1.0, 3.0), "O4": (4.0, 0.0)}
    line = reference_line(rocker, {"O2": (0.0, 0.0), "O4": (4.0, 0.0)})
    assert (line.start, line.end, line.grounded) == ("O4", "B", True)
    assert line.angle(rocker) == pytest.approx(math.degrees(math.atan2(3.0, -3.0)))   # 135°


def test_a_point_of_the_frames_name_elsewhere_is_no_pivot():
    """A name the frame also has, at another place (a frame's point moved by the sweep is
    never a body's pivot): the body's first point is the line's start."""
    bar = {"P": (0.0, 0.0), "Q": (0.0, 2.0)}
    line = reference_line(bar, {"Q": (5.0, 5.0)})
    assert (line.start, line.end, line.grounded) == ("P", "Q", False)
    assert line.angle(bar) == pytest.approx(90.0)


def test_the_end_is_the_first_point_drawn_elsewhere_and_one_place_has_no_line():
    line = reference_line({"A": (1.0, 1.0), "A2": (1.0, 1.0), "C": (0.0, 1.0)}, {})
    assert (line.start, line.end) == ("A", "C")
    assert line.angle({"A": (1.0, 1.0), "C": (0.0, 1.0)}) == pytest.approx(180.0)
    assert reference_line({"A": (1.0, 1.0), "A2": (1.0, 1.0)}, {}) is None
    assert reference_line({"A": (1.0, 1.0, 0.0), "B": (0.0, 0.0, 1.0)}, {}) is None     # 3D


def test_the_sweep_measures_the_crank_from_its_pivot():
    """The four-bar of `tests/sweep/models.py`, crank O2A drawn at 90° and driven at the pivot:
    its angle over the sweep is 90° plus the joint's turn (continuous, degrees); the rocker's
    line starts at its pivot O4 though B is listed first."""
    result = run_sweep(four_bar_tree(crank_deg=90.0), steps=12)
    turns = [float(x) - float(result.coordinate[0]) for x in result.coordinate]
    assert list(body_angle(result, "crank")) == pytest.approx([90.0 + t for t in turns], abs=1e-9)
    b = circle_meet((0.0, 1.0), 4.0, (4.0, 0.0), 3.0, 1.0)          # B drawn, by hand
    assert body_angle(result, "rocker")[0] == pytest.approx(math.degrees(math.atan2(b[1], b[0] - 4.0)))
