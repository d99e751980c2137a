"""Sweep plots and animations.

The plots are tested on a sweep-like result built here from the closed-form four-bar
(ground 4, crank 1, coupler 4, rocker 3: a crank-rocker), so they do not depend on the
sweep engine; the animation runs a real sweep of a slider-crank and is checked against
the slider's closed-form position.
"""
from __future__ import annotations

import math
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from kinematika.draw import plot_sweep
from kinematika.errors import KinematikaError

from .mechanisms import R, L, THETA, cross, slider_crank_tree

EXAMPLES = Path(__file__).parents[2] / "examples"

W2 = 10.0


def closed_form_sweep(n: int = 37) -> SimpleNamespace:
    """Positions by circle intersection (open branch), rates by the cross-product formulas;
    the crank starts at 90° (A = (0, 1)); P is a coupler point off AB."""
    phi = np.linspace(0, 2 * np.pi, n)
    o4 = 4 + 0j
    keys = ("O2@crank", "A@crank", "A@coupler", "B@coupler", "P@coupler", "B@rocker", "O4@rocker")
    rows = {key: {q: [] for q in ("position", "velocity", "acceleration")} for key in keys}
    omega = {"coupler": [], "rocker": []}
    for f in phi:
        a = complex(math.cos(f + math.pi / 2), math.sin(f + math.pi / 2))
        d = o4 - a                       # B on circles |B − A| = 4, |B − O4| = 3
        dist = abs(d)
        x = (dist ** 2 + 16 - 9) / (2 * dist)
        b = a + d / dist * complex(x, -math.sqrt(16 - x * x))
        p = a + 0.5 * (b - a) + 0.6j * (b - a)
        w3 = -W2 * cross(a, b - o4) / cross(b - a, b - o4)
        w4 = W2 * cross(a, b - a) / cross(b - o4, b - a)
        omega["coupler"].append(w3)
        omega["rocker"].append(w4)
        for key, q, v in (("O2@crank", 0j, 0j), ("A@crank", a, 1j * W2 * a),
                          ("A@coupler", a, 1j * W2 * a), ("B@coupler", b, 1j * w4 * (b - o4)),
                          ("P@coupler", p, 1j * W2 * a + 1j * w3 * (p - a)),
                          ("B@rocker", b, 1j * w4 * (b - o4)), ("O4@rocker", o4, 0j)):
            rows[key]["position"].append([q.real, q.imag])
            rows[key]["velocity"].append([v.real, v.imag])
            rows[key]["acceleration"].append([0.0, 0.0])
    points = {k: {q: np.array(v) for q, v in d.items()} for k, d in rows.items()}
    zero = np.zeros(n)
    bodies = {"ground": {"angle": zero, "omega": zero, "alpha": zero},
              "crank": {"angle": np.degrees(phi), "omega": zero + W2, "alpha": zero},
              "coupler": {"angle": zero, "omega": np.array(omega["coupler"]), "alpha": zero},
              "rocker": {"angle": zero, "omega": np.array(omega["rocker"]), "alpha": zero}}
    return SimpleNamespace(coordinate=np.degrees(phi), ok=np.ones(n, bool), bodies=bodies,
                           points=points, dead_points=[123.0], joint="j1", unit="deg",
                           name="Closed-form four-bar")


def lines(fig, prefix):
    return {ln.get_gid().split(":", 1)[1]: ln for ax in fig.axes for ln in ax.lines
            if (ln.get_gid() or "").startswith(prefix)}


def test_plot_sweep_reads_absolute_angles_against_the_crank_angle(tmp_path):
    result = closed_form_sweep()
    fig = plot_sweep(result, tmp_path / "sweep.png")
    assert (tmp_path / "sweep.png").read_bytes()[:4] == b"\x89PNG"
    angles = lines(fig, "angle:")
    assert set(angles) == {"coupler", "rocker"}                   # the crank is the axis
    crank = np.degrees(np.linspace(0, 2 * np.pi, 37)) + 90         # A starts straight up
    assert np.allclose(angles["rocker"].get_xdata(), crank)
    b = result.points["B@rocker"]["position"]
    rocker = np.degrees(np.unwrap(np.arctan2(b[:, 1], b[:, 0] - 4)))   # O4 → B, absolute
    assert np.allclose(angles["rocker"].get_ydata(), rocker)
    assert np.ptp(rocker) < 90                                       # a swing, not 0..360
    omegas = lines(fig, "omega:")
    assert set(omegas) == {"crank", "coupler", "rocker"}          # the frame is left out
    assert np.allclose(omegas["rocker"].get_ydata(), result.bodies["rocker"]["omega"])
    dead = [ln for ax in fig.axes for ln in ax.lines if ln.get_gid() == "dead:123"]
    assert len(dead) == len(fig.axes)
    assert np.allclose(dead[0].get_xdata(), 123 + 90)             # on the crank-angle axis


def test_points_on_circles_about_pivots_are_left_to_their_bodies_rates():
    """A and B run on circles about O2 and O4 (their bodies' ω tells their motion): only the
    coupler point P is plotted, its speed signed along its path."""
    result = closed_form_sweep()
    speeds = lines(plot_sweep(result), "speed:")
    assert set(speeds) == {"P"}
    v = result.points["P@coupler"]["velocity"]
    assert np.allclose(np.abs(speeds["P"].get_ydata()), np.hypot(v[:, 0], v[:, 1]))


def test_plot_sweep_leaves_gaps_at_rows_not_assembled():
    result = closed_form_sweep()
    for data in result.points.values():
        data["velocity"][5] = np.nan
    result.ok[5] = False
    speeds = lines(plot_sweep(result), "speed:")
    assert np.isnan(speeds["P"].get_ydata()[5]) and np.isfinite(speeds["P"].get_ydata()[4])


def test_quick_return_ram_stroke_and_time_ratio():
    """Crank r = 0.1 at c = 0.3 above the rocker's pivot: the limit positions have the crank
    square to the rocker, so the quick stroke takes 2 acos(r/c) of crank and the ram moves
    2 L sin(asin(r/c)) = 2 L r / c (B at the same height at both limits)."""
    from kinematika.sweep import run_sweep

    result = run_sweep(EXAMPLES / "quick_return.yaml", steps=720)
    fig = plot_sweep(result)
    ram = lines(fig, "velocity:")["C"].get_ydata()
    assert ram.min() < 0 < ram.max()                             # signed: both strokes show
    (note,) = [ax.get_title("left") for ax in fig.axes if ax.get_title("left")]
    quick = 2 * math.degrees(math.acos(0.1 / 0.3))
    ratio = (360 - quick) / quick
    stroke = 2 * 0.5 * 0.1 / 0.3
    assert f"stroke {stroke:.4g}" in note
    got = float(note.rsplit("time ratio ", 1)[1])
    assert got == pytest.approx(ratio, rel=1e-4)


def test_animation_moves_the_slider_to_its_closed_form_positions():
    from kinematika.draw.animation import Film

    film = Film.of(slider_crank_tree(), by=360, steps=12, frames=13)
    pin = next(ln for ln in film.fig.axes[0].lines if ln.get_gid() == "joint:j3")   # at B
    crank = film.motion.result.bodies["crank"]["angle"]
    for k in (0, 3, 7):
        film.show(k)
        theta = THETA + math.radians(float(crank[k]))
        x_b = R * math.cos(theta) + math.sqrt(L ** 2 - (R * math.sin(theta)) ** 2)
        drawn = pin.get_transform().transform(pin.get_xydata()[0])
        expected = film.fig.axes[0].transData.transform((x_b, 0.0))
        assert np.allclose(drawn, expected, atol=1e-6), k
        trace = next(ln for ln in film.fig.axes[0].lines
                     if (ln.get_gid() or "").startswith("trace:B"))
        assert len(trace.get_xdata()) == k + 1


def test_animation_writes_a_gif_with_the_frames_asked(tmp_path):
    from PIL import Image

    from kinematika.draw import animate

    done = []
    path = animate(slider_crank_tree(), tmp_path / "m.gif", by=90, steps=9, frames=5,
                   progress=lambda i, n: done.append((i, n)))
    with Image.open(path) as im:
        assert im.n_frames == 5
    assert done[-1] == (5, 5)


def test_mp4_without_ffmpeg_is_a_clear_error(tmp_path, monkeypatch):
    from matplotlib import animation

    from kinematika.draw import animate

    monkeypatch.setattr(animation.writers, "is_available", lambda name: False)
    with pytest.raises(KinematikaError, match="apt install ffmpeg") as err:
        animate(slider_crank_tree(), tmp_path / "m.mp4")
    assert err.value.kind == "output"


def test_animation_names_each_point_once_where_it_is():
    """The quick-return's A is the crank's pin sliding in the rocker's slot: named and
    dotted once, moving with the crank (no copy left behind on the rocker)."""
    from kinematika.draw.animation import Film

    film = Film.of(EXAMPLES / "quick_return.yaml", frames=8)
    ax = film.fig.axes[0]
    names = [t for t in ax.texts if t.get_text() == "A"]
    assert len(names) == 1
    assert film.motion.scene.bodies["rocker"].passing == ["A"]
    film.show(film.rows[0])
    assert "crank θ = 30°" in film.title.get_text()            # the drawn crank angle
    assert film.fig.get_size_inches()[0] * film.fig.dpi >= 800    # frames 800 px wide
