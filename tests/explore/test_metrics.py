"""Each metric of a design study against a derivation by hand (textbook formulas, loop
closure written independently in tests/sweep/models.py), on models written by dimensions."""
from __future__ import annotations

import math

import numpy as np
import pytest

import kinematika.explore as ke

from tests.sweep.models import four_bar_closed_form, slider_crank_closed_form
from .models import FOUR_BAR, QUICK_RETURN, SLIDER_CRANK

FLAT = FOUR_BAR.replace("theta: deg(52)", "theta: 0")      # rows at crank angles 0, 1, ..., 360°


def rows(text, vary, metrics, **kw):
    return ke.explore(text, vary, metrics, **kw)


def four_bar(g, a, b, c):
    return FLAT.replace("g: 5.2", f"g: {g}").replace("a: 2.25", f"a: {a}") \
        .replace("b: 6.1", f"b: {b}").replace("c: 4.35", f"c: {c}")


@pytest.mark.parametrize("lengths, expected", [
    ((5.2, 2.25, 6.1, 4.35), "crank-rocker"),        # s = crank: 2.25 + 6.1 < 5.2 + 4.35
    ((1.0, 2.5, 3.0, 3.0), "double-crank"),          # s = ground
    ((4.0, 3.0, 1.2, 3.5), "double-rocker"),         # s = coupler
    ((4.0, 3.5, 3.0, 1.5), "rocker-crank"),          # s = rocker
    ((4.0, 2.0, 4.0, 2.0), "change-point"),          # s + l = p + q (parallelogram)
    ((4.0, 3.0, 3.0, 3.5), "non-grashof"),           # 3 + 4 > 3 + 3.5
])
def test_grashof_classes_from_the_link_lengths(lengths, expected):
    g, a, b, c = lengths
    text = four_bar(g, a, b, c).replace("theta: 0", "theta: deg(40)")
    table = rows(text, {"a": (a, a)}, ["grashof"], grid=1)
    assert table["assembles"][0], table["reason"][0]
    assert table["grashof"][0] == expected


def test_transmission_angle_is_reached_with_crank_and_ground_in_line():
    g, a, b, c = 5.2, 2.25, 6.1, 4.35
    table = rows(four_bar(g, a, b, c), {"a": (1.5, 2.25)}, ["transmission"], grid=4)
    for a_, got in zip(table["a"], table["transmission"]):
        mu_min = math.degrees(math.acos((b * b + c * c - (g - a_) ** 2) / (2 * b * c)))
        mu_max = math.degrees(math.acos((b * b + c * c - (g + a_) ** 2) / (2 * b * c)))
        assert got == pytest.approx(min(mu_min, 180 - mu_max), abs=1e-9)


def test_time_ratio_of_the_offset_slider_crank():
    """Limit positions at |OB| = l ± r: the crank turns 180° + β between them, β = asin(e/(l − r))
    − asin(e/(l + r)); Q = (180° + β)/(180° − β)."""
    table = rows(SLIDER_CRANK, {"e": (0.2, 0.6)}, ["time_ratio", "time_ratio:slider"], grid=3)
    r, l = 1.0, 3.0
    for e, q, q_named in zip(table["e"], table["time_ratio"], table["time_ratio:slider"]):
        beta = math.degrees(math.asin(e / (l - r)) - math.asin(e / (l + r)))
        assert q == pytest.approx((180 + beta) / (180 - beta), rel=1e-6)
        assert q_named == q


def test_time_ratio_of_the_crank_and_slotted_lever():
    """The lever is at its extremes when the slot is tangent to the crank circle: the crank is then
    at φ = acos(r/c) either side of O2O4, so Q = (360° − 2φ)/(2φ)."""
    table = rows(QUICK_RETURN, {"r": (0.1, 0.2)}, ["time_ratio:rocker"], grid=3)
    for r, q in zip(table["r"], table["time_ratio:rocker"]):
        phi = math.degrees(math.acos(r / 0.3))
        assert q == pytest.approx((360 - 2 * phi) / (2 * phi), rel=1e-6)


def test_peaks_ranges_and_values_at_an_input_match_loop_closure():
    g, a, b, c = 5.2, 2.25, 6.1, 4.35
    metrics = ["range:rocker", "peak_omega:rocker", "peak_alpha:coupler", "peak_speed:P", "peak_accel:P",
               "omega:rocker=90", "alpha:coupler=37", "speed:P=200", "x:P=10", "y:P=10", "angle:rocker=270"]
    table = rows(four_bar(g, a, b, c), {"a": (a, a)}, metrics, grid=1).iloc[0]
    theta = np.radians(np.arange(361.0))
    ex = four_bar_closed_form(theta, g, a, b, c, 1.0, 9.5, -21.0, (3.4, -1.15))
    psi = np.degrees(np.unwrap(np.arctan2(ex["B"][1], ex["B"][0] - g)))
    assert table["range:rocker"] == pytest.approx(psi.max() - psi.min(), abs=1e-9)
    assert table["peak_omega:rocker"] == pytest.approx(np.abs(ex["w4"]).max(), rel=1e-9)
    assert table["peak_alpha:coupler"] == pytest.approx(np.abs(ex["a3"]).max(), rel=1e-9)
    assert table["peak_speed:P"] == pytest.approx(np.hypot(*ex["vP"]).max(), rel=1e-9)
    assert table["peak_accel:P"] == pytest.approx(np.hypot(*ex["aP"]).max(), rel=1e-9)
    assert table["omega:rocker=90"] == pytest.approx(ex["w4"][90], rel=1e-9)
    assert table["alpha:coupler=37"] == pytest.approx(ex["a3"][37], rel=1e-9)
    assert table["speed:P=200"] == pytest.approx(math.hypot(ex["vP"][0][200], ex["vP"][1][200]), rel=1e-9)
    assert (table["x:P=10"], table["y:P=10"]) == pytest.approx((ex["P"][0][10], ex["P"][1][10]), rel=1e-9)
    assert table["angle:rocker=270"] == pytest.approx(psi[270] - psi[0], abs=1e-9)


def test_a_value_between_rows_is_interpolated_linearly():
    table = rows(SLIDER_CRANK.replace("theta: deg(60)", "theta: 0"), {"l": (3, 3)}, ["x:B=10.5"], grid=1)
    ex = slider_crank_closed_form(np.radians([10.0, 11.0]), 1.0, 3.0, 0.5, 10.0)
    assert table["x:B=10.5"][0] == pytest.approx(ex["x"].mean(), rel=1e-12)


def test_path_error_is_the_distance_to_the_polyline_of_the_path(tmp_path):
    """Targets on the crank pin's path (its circle at rows) are at distance 0; its centre is at the
    distance of every chord, a cos(0.5°)."""
    a = 2.25
    on = [(a * math.cos(math.radians(t)), a * math.sin(math.radians(t))) for t in (0, 17, 123, 300)]
    (tmp_path / "on.csv").write_text("x,y\n" + "\n".join(f"{x!r},{y!r}" for x, y in on))
    (tmp_path / "centre.csv").write_text("0,0\n")
    (tmp_path / "m.yaml").write_text(FLAT)
    table = rows(str(tmp_path / "m.yaml"), {"c": (4.35, 4.35)},
                 ["path_error:A@crank=on.csv", "path_error:A@crank=centre.csv"], grid=1)
    assert table["path_error:A@crank=on.csv"][0] == pytest.approx(0.0, abs=1e-12)
    assert table["path_error:A@crank=centre.csv"][0] == pytest.approx(a * math.cos(math.radians(0.5)),
                                                                      rel=1e-12)


def test_structural_error_against_the_rockers_own_rotation(tmp_path):
    g, a, b, c = 5.2, 2.25, 6.1, 4.35
    theta = np.radians(np.arange(361.0))
    ex = four_bar_closed_form(theta, g, a, b, c, 1.0, 9.5, -21.0, (3.4, -1.15))
    psi = np.degrees(np.unwrap(np.arctan2(ex["B"][1], ex["B"][0] - g)))
    psi -= psi[0]
    (tmp_path / "exact.csv").write_text("".join(f"{x},{float(psi[x])!r}\n" for x in (0, 30, 60, 90)))
    (tmp_path / "off.csv").write_text("".join(f"{x},{float(psi[x]) + (1.5 if x == 60 else 0.0)!r}\n"
                                              for x in (0, 30, 60, 90)))
    (tmp_path / "m.yaml").write_text(four_bar(g, a, b, c))
    table = rows(str(tmp_path / "m.yaml"), {"c": (c, c)},
                 ["structural_error:rocker=exact.csv", "structural_error:rocker=off.csv"], grid=1)
    assert table["structural_error:rocker=exact.csv"][0] == pytest.approx(0.0, abs=1e-9)
    assert table["structural_error:rocker=off.csv"][0] == pytest.approx(1.5, abs=1e-9)


def test_a_design_that_cannot_turn_has_null_cycle_metrics_and_its_dead_points():
    # a = 3.5: 3.5 + 6.1 > 5.2 + 4.35, the crank stops at two dead points
    upright = FLAT.replace("theta: 0", "theta: deg(90)")
    table = rows(upright, {"a": (2.25, 3.5)}, ["transmission", "dead_points", "grashof", "omega:rocker=0"],
                 grid=2)
    good, bad = table.iloc[0], table.iloc[1]
    assert good["reason"] == "" and good["dead_points"] == 0
    assert bad["assembles"] and bad["reason"].startswith("assembly: sweep: the mechanism cannot be "
                                                        "assembled at increment")
    assert math.isnan(bad["transmission"]) and bad["dead_points"] == 2
    assert bad["grashof"] == "non-grashof" and not math.isnan(bad["omega:rocker=0"])


def test_a_design_that_cannot_be_drawn_says_why():
    table = rows(FOUR_BAR, {"c": (0.5, 0.5)}, ["grashof", "transmission"], grid=1)
    assert not table["assembles"][0]
    assert table["reason"][0].startswith("geometry: points.B: the circles about A (6.1) and O4 (0.5) "
                                         "do not meet")
    import pandas as pd       # here, not at the top: every worker imports every test module
    assert pd.isna(table["grashof"][0]) and math.isnan(table["transmission"][0])


def test_motion_error_measures_position_and_turn_of_the_body(tmp_path):
    """The crank's poses are (a cos θ, a sin θ, θ): a pose of its own cycle is at distance 0; the
    pivot with the crank's direction at a row is a from the nearest pose (ρ = a, Δφ = 0 there)."""
    a = 2.25
    (tmp_path / "own.csv").write_text(f"{a * math.cos(math.radians(62))!r},{a * math.sin(math.radians(62))!r},62\n")
    (tmp_path / "pivot.csv").write_text("x,y,angle\n0,0,62\n")
    (tmp_path / "m.yaml").write_text(FOUR_BAR)
    table = rows(str(tmp_path / "m.yaml"), {"c": (4.35, 4.35)},
                 ["motion_error:A@crank=own.csv", "motion_error:A@crank=pivot.csv"], grid=1)
    assert table["motion_error:A@crank=own.csv"][0] == pytest.approx(0.0, abs=1e-12)
    assert table["motion_error:A@crank=pivot.csv"][0] == pytest.approx(a, rel=1e-12)
