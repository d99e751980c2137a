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


def label_faults(fig, share: float = 0.2) -> list[str]:
    """What makes the labels unreadable: two labels (their text extents) overlapping by more
    than `share` of the smaller one, or a leader line passing through another label."""
    boxes = [(t, b) for t, b in label_boxes(fig) if t]
    faults = []
    for i, (t1, b1) in enumerate(boxes):
        for t2, b2 in boxes[i + 1:]:
            smaller = min(b1.width * b1.height, b2.width * b2.height)
            if overlap(b1, b2) > share * smaller:
                faults.append(f"{t1!r} over {t2!r}")
    ax = axes(fig)
    texts = {t.get_gid(): t for t in ax.texts}
    for ln in ax.lines:
        gid = ln.get_gid() or ""
        if not gid.startswith("leader:"):
            continue
        own = texts.get("label:" + gid.removeprefix("leader:"))
        path = ax.transData.transform(ln.get_xydata())
        samples = [path[0] + t * (path[1] - path[0]) for t in np.linspace(0.05, 0.95, 30)]
        for t in ax.texts:
            if t is own or not t.get_text():
                continue
            box = Text.get_window_extent(t, fig.canvas.get_renderer()).shrunk(0.8, 0.8)
            if any(box.contains(*p) for p in samples):
                faults.append(f"leader of {own.get_text() if own else gid!r} through {t.get_text()!r}")
    return faults


def outside_faults(fig) -> list[str]:
    """Artists of the drawing outside the axes, and texts outside the page."""
    renderer = fig.canvas.get_renderer()
    ax = axes(fig)
    box = ax.get_window_extent(renderer)
    faults = []
    for artist in ax.lines + ax.patches:
        ext = artist.get_window_extent(renderer)
        if (ext.width == 0 and ext.height == 0) or not np.isfinite(ext.x0):
            continue
        if not (ext.x0 >= box.x0 - 1 and ext.x1 <= box.x1 + 1 and
                ext.y0 >= box.y0 - 1 and ext.y1 <= box.y1 + 1):
            faults.append(f"{artist.get_gid() or artist} outside the axes")
    for text, ext in label_boxes(fig):
        if not (box.x0 - 1 <= ext.x0 and ext.x1 <= box.x1 + 1 and
                box.y0 - 1 <= ext.y0 and ext.y1 <= box.y1 + 1):
            faults.append(f"label {text!r} outside the axes")
    page = fig.bbox
    for text in fig.texts:
        ext = text.get_window_extent(renderer)
        if not (page.x0 <= ext.x0 and ext.x1 <= page.x1 and page.y0 <= ext.y0 and ext.y1 <= page.y1):
            faults.append(f"text {text.get_text()!r} off the page")
    return faults


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
