"""A cam's figures (matplotlib): the s–v–a–j diagrams and the profile drawing.

`svaj_figure`: four stacked plots over the cam angle (or travel) sharing the abscissa, each
with its unit, the segment boundaries as dotted lines named by their laws, and every jump of
velocity or acceleration (the fundamental law broken) marked in red with its size.
`profile_figure`: the profile, the pitch curve, base and prime circles, the follower at
θ = 0, the place of the largest pressure angle, and undercut stretches in red.
"""
from __future__ import annotations

import math

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ..cams.analysis import CamAnalysis
from ..cams.profile import PlateCam



JUMP = "#d62728"


def _labels(analysis: CamAnalysis, units: str) -> tuple[str, list[str]]:
    plate = isinstance(analysis.cam, PlateCam)
    x = f"cam travel ({units})" if plate else "cam angle θ (°)"
    if analysis.cam.follower.angular:
        return x, ["s (°)", "v (rad/s)", "a (rad/s²)", "j (rad/s³)"]
    return x, [f"s ({units})", f"v ({units}/s)", f"a ({units}/s²)", f"j ({units}/s³)"]


def svaj_figure(analysis: CamAnalysis, units: str = "mm", title: str = "") -> Figure:
    """The s–v–a–j diagrams (module docstring)."""
    fig = Figure(figsize=(8, 9.5))
    FigureCanvasAgg(fig)
    axes = fig.subplots(4, 1, sharex=True)
    xlabel, ylabels = _labels(analysis, units)
    program = analysis.cam.program
    u = analysis.u
    if program.periodic:                    # close the cycle: the last segment's end, from the left
        u = np.append(u, program.period * (1 - 1e-12))
    x = analysis.angle_of(u)
    values = list(program.kinematics(u, analysis.speed))
    if analysis.cam.follower.angular:
        values[0] = np.degrees(values[0])
    bounds = analysis.angle_of(program.boundaries)
    for k, (ax, y, label) in enumerate(zip(axes, values, ylabels)):
        ax.plot(x, y, color="#1f4e79", linewidth=1.4)
        ax.set_ylabel(label)
        ax.grid(True, linewidth=0.4, alpha=0.5)
        ax.axhline(0, color="black", linewidth=0.6)
        for b in bounds:
            ax.axvline(b, color="#777", linestyle=":", linewidth=0.9)
        if k == 0:
            for seg, a, b in zip(program.segments, bounds[:-1], bounds[1:]):
                ax.text((a + b) / 2, 1.02, seg.law.name, transform=ax.get_xaxis_transform(),
                        ha="center", va="bottom", fontsize=8, color="#444")
    _mark_jumps(analysis, axes)
    axes[-1].set_xlabel(xlabel)
    axes[-1].set_xlim(float(x[0]), float(analysis.angle_of(np.array([program.period]))[0]))
    if not isinstance(analysis.cam, PlateCam):
        axes[-1].set_xticks(np.arange(0, 361, 45))
    if title:
        fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    return fig


def _mark_jumps(analysis: CamAnalysis, axes: list) -> None:
    """A red marker and the jump's size where v (order 1) or a (order 2) jumps."""
    omega = analysis.speed
    for j in analysis.cam.program.jumps():
        order = 1 if j.quantity == "velocity" else 2
        ax = axes[order]
        at = float(analysis.angle_of(np.array([j.at]))[0])
        size = j.amount * omega**order
        ax.axvline(at, color=JUMP, linewidth=1.2, alpha=0.8)
        ax.annotate(f"jump {size:+.4g}", (at, 0), xytext=(4, 6), textcoords="offset points",
                    color=JUMP, fontsize=8)


def profile_figure(analysis: CamAnalysis, units: str = "mm", title: str = "") -> Figure:
    """The cam's drawing (module docstring), in its own frame at θ = 0."""
    fig = Figure(figsize=(9.5, 7))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    cam = analysis.cam
    a, b = cam.profile.domain
    u = np.linspace(a, b, 1441)
    profile, pitch = cam.profile.point(u), cam.pitch.point(u)
    ax.fill(profile[:, 0], profile[:, 1], color="#dbe7f3", zorder=0) if cam.profile.closed else None
    ax.plot(profile[:, 0], profile[:, 1], color="black", linewidth=1.6, label="profile")
    if cam.follower.contact.radius > 0:
        ax.plot(pitch[:, 0], pitch[:, 1], color="#1f77b4", linestyle="--", linewidth=1.0, label="pitch curve")
    if not isinstance(cam, PlateCam):
        t = np.linspace(0, 2 * math.pi, 361)
        ax.plot(cam.base * np.cos(t), cam.base * np.sin(t), color="#888", linewidth=0.8, label="base circle")
        if cam.follower.contact.radius > 0:
            ax.plot(cam.prime * np.cos(t), cam.prime * np.sin(t), color="#bbb", linewidth=0.8,
                    linestyle="-.", label="prime circle")
        ax.plot([0], [0], marker="+", color="black", markersize=12)
        _rotation(ax, cam)
    _follower(ax, analysis)
    _worst_pressure(ax, analysis, units)
    for r in analysis.ranges(analysis.undercut, analysis.profile_radius):
        mask = (analysis.angle >= r.start) & (analysis.angle <= r.end)
        ax.plot(analysis.profile[mask, 0], analysis.profile[mask, 1], color=JUMP, linewidth=3,
                label="undercut")
    ax.set_aspect("equal")
    ax.grid(True, linewidth=0.3, alpha=0.5)
    ax.set_xlabel(f"x ({units})")
    ax.set_ylabel(f"y ({units})")
    handles, labels = ax.get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    ax.legend(unique.values(), unique.keys(), loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=8,
              frameon=False)
    if title:
        ax.set_title(title, fontsize=11)
    fig.tight_layout()
    return fig


def _follower(ax, analysis: CamAnalysis) -> None:
    """The follower touching the cam at θ = 0 (roller circle, knife point or face line)."""
    cam = analysis.cam
    s0 = analysis.motion[0][0]
    contact = cam.follower.contact
    colour = "#2ca02c"
    if contact.touches_with_face:
        q = analysis.profile[0]
        alpha, _ = cam.follower.face(_jet(s0), cam.base)
        t = np.array([-math.sin(alpha.value), math.cos(alpha.value)])
        span = 0.6 * cam.base
        ends = np.array([q - span * t, q + span * t])
        ax.plot(ends[:, 0], ends[:, 1], color=colour, linewidth=2.5, label="follower")
        return
    centre = analysis.pitch[0]
    if contact.radius > 0:
        t = np.linspace(0, 2 * math.pi, 121)
        ax.plot(centre[0] + contact.radius * np.cos(t), centre[1] + contact.radius * np.sin(t), color=colour,
                linewidth=1.8, label="follower")
    else:
        ax.plot([centre[0]], [centre[1]], marker="v", color=colour, markersize=9, label="follower")


def _rotation(ax, cam) -> None:
    """A curved arrow about the centre in the cam's sense of rotation, marked ω."""
    from matplotlib.patches import FancyArrowPatch

    r = 0.35 * cam.base
    a0, a1 = (math.radians(200), math.radians(320)) if cam.sense > 0 else (math.radians(320), math.radians(200))
    arrow = FancyArrowPatch((r * math.cos(a0), r * math.sin(a0)), (r * math.cos(a1), r * math.sin(a1)),
                            connectionstyle=f"arc3,rad={0.45 * cam.sense}", arrowstyle="-|>", mutation_scale=14,
                            color="#444", linewidth=1.2)
    ax.add_patch(arrow)
    ax.text(0, -1.15 * r, "ω", ha="center", va="top", fontsize=11, color="#444")


def _jet(value: float):
    from ..curves.jet import Jet

    return Jet.variable(np.asarray(value, dtype=float))


def _worst_pressure(ax, analysis: CamAnalysis, units: str) -> None:
    phi = analysis.pressure_angle
    i = int(np.argmax(np.abs(phi)))
    if abs(phi[i]) < 1e-9:
        return
    p = analysis.pitch[i]
    ax.plot([p[0]], [p[1]], marker="o", color="#ff7f0e", markersize=6,
            label=f"largest pressure angle {math.degrees(phi[i]):.1f}° at {analysis.angle[i]:.1f}"
                  + ("" if isinstance(analysis.cam, PlateCam) else "°"))
