"""Reading a drawn figure back: arrows, markers, lines and labels by their gid."""
from __future__ import annotations

import numpy as np
from matplotlib.path import Path
from matplotlib.text import Text


def axes(fig):
    return fig.axes[0]


def arrow(fig, gid: str) -> tuple[np.ndarray, np.ndarray]:
    """(start, tip) of the arrow `gid`, from the drawn path (data coordinates). The path's tip
    stops short of the stroked tip by about half a line width (under 3 px)."""
    patches = [p for p in axes(fig).patches if p.get_gid() == gid]
    assert len(patches) == 1, f"expected one arrow {gid!r}, found {len(patches)}"
    path = patches[0].get_path()
    verts = path.vertices if path.codes is None else path.vertices[path.codes != Path.CLOSEPOLY]
    start = verts[0]
    tip = max(verts, key=lambda v: np.linalg.norm(v - start))
    return start, tip


def pixel(fig) -> float:
    """Data units per pixel (equal on both axes)."""
    ax = axes(fig)
    x0, x1 = ax.get_xlim()
    return (x1 - x0) / ax.get_window_extent().width


def has_artist(fig, gid: str) -> bool:
    ax = axes(fig)
    return any(a.get_gid() == gid for a in ax.patches + ax.lines)


def marker(fig, gid: str) -> np.ndarray:
    lines = [ln for ln in axes(fig).lines if ln.get_gid() == gid]
    assert len(lines) == 1, f"expected one marker {gid!r}, found {len(lines)}"
    return lines[0].get_xydata()[0]


def line(fig, gid: str) -> np.ndarray:
    lines = [ln for ln in axes(fig).lines if ln.get_gid() == gid]
    assert len(lines) == 1, f"expected one line {gid!r}, found {len(lines)}"
    return lines[0].get_xydata()


def lines_starting(fig, prefix: str) -> list[np.ndarray]:
    return [ln.get_xydata() for ln in axes(fig).lines if (ln.get_gid() or "").startswith(prefix)]


def label(fig, gid: str) -> str:
    texts = [t for t in axes(fig).texts if t.get_gid() == f"label:{gid}"]
    assert len(texts) == 1, f"expected one label {gid!r}, found {len(texts)}"
    return texts[0].get_text()


def label_boxes(fig) -> list[tuple[str, object]]:
    """Every label's text and display box (its text only, not a leader line)."""
    renderer = fig.canvas.get_renderer()
    out = []
    for t in axes(fig).texts:
        if hasattr(t, "update_positions"):
            t.update_positions(renderer)
        out.append((t.get_text(), Text.get_window_extent(t, renderer)))
    return out


def overlap(b1, b2) -> float:
    w = min(b1.x1, b2.x1) - max(b1.x0, b2.x0)
    h = min(b1.y1, b2.y1) - max(b1.y0, b2.y0)
    return max(w, 0.0) * max(h, 0.0)


def angle_between(u, v) -> float:
    u, v = np.asarray(u, dtype=float), np.asarray(v, dtype=float)
    c = u @ v / (np.linalg.norm(u) * np.linalg.norm(v))
    return float(np.degrees(np.arccos(np.clip(c, -1, 1))))


def point_to_line(p, a, b) -> float:
    """Distance from p to the infinite line through a and b."""
    p, a, b = (np.asarray(x, dtype=float) for x in (p, a, b))
    d = b - a
    return abs(d[0] * (p - a)[1] - d[1] * (p - a)[0]) / np.linalg.norm(d)
