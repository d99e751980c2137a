"""Sweep plots and animations.

The plots are tested on a sweep-like result built here from the closed-form four-bar
(ground 4, crank 1, coupler 4, rocker 3: a crank-rocker), so they do not depend on the
sweep engine; the animation runs a real sweep of a slider-crank and is checked against
the slider's closed-form position.
"""
from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest

from kinematika.draw import plot_sweep
from kinematika.errors import KinematikaError

from .mechanisms import R, L, THETA, cross, slider_crank_tree

W2 = 10.0


def closed_form_sweep(n: int = 37) -> SimpleNamespace:
    """Positions by circle intersection (open branch), rates by the cross-product formulas."""
    phi = np.linspace(0, 2 * np.pi, n)
    o4 = 4 + 0j
    rows = {key: {q: [] for q in ("position", "velocity", "acceleration")}
            for key in ("O2@crank", "A@crank", "A@coupler", "B@coupler", "B@rocker")}
    omega = {"coupler": [], "rocker": []}
    for f in phi:
        a = complex(math.cos(f + math.pi / 2), math.sin(f + math.pi / 2))
        d = o4 - a                       # B on circles |B − A| = 4, |B − O4| = 3
        dist = abs(d)
        x = (dist ** 2 + 16 - 9) / (2 * dist)
        b = a + d / dist * complex(x, -math.sqrt(16 - x * x))
        w3 = -W2 * cross(a, b - o4) / cross(b - a, b - o4)
        w4 = W2 * cross(a, b - a) / cross(b - o4, b - a)
        omega["coupler"].append(w3)
        omega["rocker"].append(w4)
        for key, p, v in (("O2@crank", 0j, 0j), ("A@crank", a, 1j * W2 * a),
                          ("A@coupler", a, 1j * W2 * a), ("B@coupler", b, 1j * w4 * (b - o4)),
                          ("B@rocker", b, 1j * w4 * (b - o4))):
            rows[key]["position"].append([p.real, p.imag])
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


def test_plot_sweep_draws_rates_and_speeds(tmp_path):
    result = closed_form_sweep()
    fig = plot_sweep(result, tmp_path / "sweep.png")
    assert (tmp_path / "sweep.png").read_bytes()[:4] == b"\x89PNG"
    omegas = lines(fig, "omega:")
    assert set(omegas) == {"crank", "coupler", "rocker"}          # the frame is left out
    assert np.allclose(omegas["rocker"].get_ydata(), result.bodies["rocker"]["omega"])
    speeds = lines(fig, "velocity:")
    assert set(speeds) == {"A", "B"}       # shared pins once, under their bare name; O2 at rest
    assert np.allclose(speeds["B"].get_ydata(), 3 * np.abs(result.bodies["rocker"]["omega"]))
    assert np.allclose(speeds["A"].get_ydata(), W2 * 1.0)
    dead = [ln for ax in fig.axes for ln in ax.lines if ln.get_gid() == "dead:123"]
    assert len(dead) == len(fig.axes)


def test_plot_sweep_leaves_gaps_at_rows_not_assembled():
    result = closed_form_sweep()
    for data in result.points.values():
        data["velocity"][5] = np.nan
    result.ok[5] = False
    speeds = lines(plot_sweep(result), "velocity:")
    assert np.isnan(speeds["B"].get_ydata()[5]) and np.isfinite(speeds["B"].get_ydata()[4])


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
    with pytest.raises(KinematikaError, match="ffmpeg"):
        animate(slider_crank_tree(), tmp_path / "m.mp4")
