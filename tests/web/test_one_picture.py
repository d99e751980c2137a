"""One scene, painted twice: the page's figure (`figure.js`, in Chromium) and the matplotlib
painter (`draw.paint`) paint the same picture (`draw.picture`'s marks), primitive by primitive.

For seven examples (every example in a deep run) the page loads the model, paints the scene
`/api/draw` gave it as it is (no motion: `figure.set(scene, null)`), and the SVG elements it
made are read back: how many of each kind (dots, lines, polygons, circles, rings, arrows,
texts), where (model coordinates), and how (stroke and fill colours, a hatching's colour,
spacing and width, widths, opacity, dashes, ends and corners in points, a marker's outline,
arrow heads, a label's colour and font). The same model, drawn with the page's options, is painted by
matplotlib into a figure, and its artists are read back the same way. Neither side is
compared with numbers the other produced: each is read from what it painted.
"""
from __future__ import annotations

import functools
import math
import re
from collections import Counter

import matplotlib
import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.colors import to_hex
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Annulus, Circle, FancyArrowPatch, Polygon

from kinematika import commands
from kinematika.draw import DrawOptions
from kinematika.draw.canvas import Canvas
from kinematika.draw.figure import zoomable
from kinematika.draw.lock import MATPLOTLIB
from kinematika.draw.paint import paint
from kinematika.web.scene_json import _unmath
from tests.conftest import BROWSER_WAIT, EXAMPLES, sampled

from .test_build import example, settled

pytestmark = pytest.mark.browser


@pytest.fixture(scope="module")
def page(browser, server):
    context = browser.new_context(viewport={"width": 1400, "height": 900})
    pg = context.new_page()
    pg.set_default_timeout(BROWSER_WAIT)          # a hang detector
    errors: list[str] = []
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.goto(server.url)
    settled(pg, 0)
    # the picture alone is compared: the page's requests for the motion, the explanation and
    # the assemblies are refused (the epicyclic train's explanation and sweep are 5 s of the
    # server's work), which it takes as any such failure
    pg.route(re.compile(r".*/api/(sweep|explain|assemblies)$"), lambda route: route.abort())
    yield pg
    context.close()
    assert not errors, errors

PT = 4 / 3                     # the page's CSS pixels per point (figure.js)
# a default run: a linkage, a cam's profile, gears, a slider's block, an arc slot, a 3D
# projection, a train's coincident centres (a label on two lines); a deep run every example
DRAWN = sampled(sorted(p.stem for p in EXAMPLES.glob("*.yaml")),
                {"four_bar", "eccentric_cam", "planetary_gears", "slider_crank",
                 "pin_in_circular_slot", "robot_arm_3d", "seed_c5_1_4_epicyclic"})

READ_SVG = """() => {
  const f = window.kinematika.figure;
  f.set(window.kinematika.state.scene, null, 0);          // the picture as given, no motion
  const root = document.querySelector('#figure .content');
  const PT = 4 / 3, pt = PT * f.px;                       // CSS pixels per point; model units per point
  const pts = (s) => s.trim().split(/\\s+/).map((p) => p.split(',').map(Number)).map(([x, y]) => [x, -y]);
  const path = (d) => d.trim().split(/\\s+/).filter(Boolean).map((s) => s.slice(1).split(',').map(Number)).map(([x, y]) => [x, -y]);
  // a paint as written: a colour, "none", or a hatching's pattern as "hatch COLOUR"
  const colour = (c) => { const m = /^url\\(#(.*)\\)$/.exec(c || '');
    return m ? 'hatch ' + root.querySelector(`pattern#${m[1]} line`).getAttribute('stroke') : (c || 'none'); };
  // a hatching's lines: how far apart across them, how wide (points); the pattern is turned
  // 45°, its lines along its height, so its width is the distance across them
  const hatching = (c) => { const m = /^url\\(#(.*)\\)$/.exec(c || ''); if (!m) return null;
    const p = root.querySelector(`pattern#${m[1]}`);
    return [p.getAttribute('width') / pt, p.querySelector('line').getAttribute('stroke-width') / pt]; };
  // how an element is painted: its stroke (colour, width and dashes in points, ends, corners),
  // its fill, its opacity
  const look = (n, stroke = n.getAttribute('stroke') || 'none', fill = n.getAttribute('fill')) => {
    const on = stroke !== 'none', dash = n.getAttribute('stroke-dasharray');
    return { stroke: colour(stroke), width: on ? n.getAttribute('stroke-width') / PT : 0, fill: colour(fill), hatching: hatching(fill),
             alpha: +(n.getAttribute('fill-opacity') ?? n.getAttribute('stroke-opacity') ?? 1),
             dash: on && dash ? dash.split(/\\s+/).map((d) => d / PT) : null,
             cap: n.getAttribute('stroke-linecap') || 'butt', join: n.getAttribute('stroke-linejoin') || 'miter' };
  };
  const at = (n) => [+n.getAttribute('cx'), -n.getAttribute('cy')];
  const out = [];
  for (const layer of ['under', 'bodies', 'pins', 'overlay', 'labels', 'vectors']) {
    for (const n of root.querySelectorAll(`:scope > g.${layer} *`)) {
      const tag = n.tagName;
      if (tag === 'tspan' || tag === 'title' || (n.closest('g.arrow') && n !== n.closest('g.arrow'))) continue;
      if (tag === 'g' && !n.classList.contains('arrow')) continue;
      if (tag === 'g') {
        const casing = n.querySelector(':scope > polyline.casing');
        const [line, ...heads] = [...n.children].filter((c) => !c.classList.contains('casing'));
        const hp = heads.map((h) => pts(h.getAttribute('points') || ''));
        const head = hp.length && hp[0].length === 3 ? [Math.hypot(hp[0][0][0] - (hp[0][1][0] + hp[0][2][0]) / 2, hp[0][0][1] - (hp[0][1][1] + hp[0][2][1]) / 2) / pt,
                                  Math.hypot(hp[0][1][0] - hp[0][2][0], hp[0][1][1] - hp[0][2][1]) / 2 / pt] : null;
        out.push({ kind: 'arrow', hidden: n.getAttribute('visibility') === 'hidden', line: pts(line.getAttribute('points') || ''),
                   heads: hp, look: { ...look(line), fill: colour(heads[0].getAttribute('fill')), head, join: null, dash: null,
                                      halo: casing ? (casing.getAttribute('stroke-width') - line.getAttribute('stroke-width')) / 2 / PT : 0 } });
      } else if (tag === 'text') out.push({ kind: 'text', content: [...n.children].map(
          (t) => (t.hasAttribute('data-line') ? '\\n' : '') + t.textContent).join(''),
          look: { fill: n.getAttribute('fill'), size: n.getAttribute('font-size') / pt,
                  weight: n.getAttribute('font-weight') || 'normal', style: n.getAttribute('font-style') || 'normal' } });
      else if (tag === 'circle' && n.classList.contains('dot')) out.push({ kind: 'dot', at: at(n),
          look: { ...look(n), cap: null, join: null, size: 2 * n.getAttribute('r') / pt, outline: null } });
      else if (tag === 'polygon' && n.classList.contains('dot')) {
        const p = pts(n.getAttribute('points'));
        const c = [p.reduce((s, q) => s + q[0], 0) / p.length, p.reduce((s, q) => s + q[1], 0) / p.length];
        out.push({ kind: 'dot', at: c, look: { ...look(n), cap: null, size: null, outline: p.map((q) => [(q[0] - c[0]) / pt, (q[1] - c[1]) / pt]) } });
      } else if (tag === 'circle' && n.classList.contains('model-width')) {
        // a ring: a circle stroked as wide as the band, in the ring's fill, without an outline
        out.push({ kind: 'ring', at: at(n), r: +n.getAttribute('r') + n.getAttribute('stroke-width') / 2,
                   look: { ...look(n, 'none', n.getAttribute('stroke')), alpha: +(n.getAttribute('stroke-opacity') ?? 1), cap: null, join: null } });
      } else if (tag === 'circle') { const l = look(n);
        out.push({ kind: 'circle', at: at(n), r: +n.getAttribute('r'), look: { ...l, cap: l.dash ? l.cap : null, join: null } }); }
      else if (tag === 'polyline') out.push({ kind: 'line', points: pts(n.getAttribute('points')), look: look(n) });
      else if (tag === 'path') out.push({ kind: 'line', points: path(n.getAttribute('d')), look: look(n) });
      else if (tag === 'polygon') { const l = look(n);
        out.push({ kind: 'polygon', points: pts(n.getAttribute('points')), look: { ...l, cap: l.dash ? l.cap : null } }); }
      else out.push({ kind: tag });
    }
  }
  return { prims: out, px: f.px, frame: window.kinematika.state.scene.picture.frame,
           lang: window.kinematika.state.lang };
}"""


def matplotlib_prims(name: str, lang: str) -> tuple[list[dict], list, list[float], float]:
    """The example drawn as the page asks (`centres`, its language), its marks painted by
    matplotlib, read back from the artists and the label board; the marks and the frame."""
    options = DrawOptions(centres=True, lang=lang)
    _, scene = commands.solved_scene(EXAMPLES / f"{name}.yaml", options)
    marks, frame = zoomable(scene, options)
    with MATPLOTLIB:
        fig = Figure(figsize=(8, 6))
        FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_xlim(frame.xmin, frame.xmax)
        ax.set_ylim(frame.ymin, frame.ymax)
        cv = Canvas(ax, scene, frame)
        paint(cv, marks)
        out = [_artist(a) for a in ax.lines + ax.patches]
        out += [{"kind": "text", "content": _unmath(label.text),
                 "look": {"fill": label.colour, "size": label.size, "weight": label.weight, "style": label.style}}
                for label in cv.board.labels]
    return out, marks, [frame.xmin, frame.ymin, frame.xmax, frame.ymax], scene.size


CAP = {"projecting": "square"}           # matplotlib's names of line ends in SVG's words


def _artist(a) -> dict:
    """A matplotlib artist as a primitive: its kind, place and look (as `READ_SVG` reads the
    page's: colours, widths and dashes in points, ends and corners where they show)."""
    if isinstance(a, Line2D):
        xy = np.asarray(a.get_xydata(), dtype=float)
        alpha = 1 if a.get_alpha() is None else a.get_alpha()
        if a.get_marker() not in (None, "None", "") and a.get_linestyle() in ("None", "", " "):
            marker = a._marker
            outline = None if a.get_marker() == "o" else \
                _open(marker.get_path().transformed(marker.get_transform()).to_polygons()[0]) * a.get_markersize()
            mfc, on = a.get_markerfacecolor(), a.get_markeredgewidth() > 0
            return {"kind": "dot", "at": xy[0], "look": {
                "fill": "none" if mfc == "none" else to_hex(mfc), "hatching": None,
                "stroke": to_hex(a.get_markeredgecolor()) if on else "none",
                "width": a.get_markeredgewidth() if on else 0, "alpha": alpha, "dash": None, "cap": None,
                "join": None if outline is None else marker.get_joinstyle(),
                "size": a.get_markersize() if outline is None else None, "outline": outline}}
        dashed = a._dash_pattern[1] is not None
        return {"kind": "line", "points": xy[np.all(np.isfinite(xy), axis=1)], "look": {
            "stroke": to_hex(a.get_color()), "width": a.get_linewidth(), "fill": "none", "hatching": None, "alpha": alpha,
            "dash": a._dash_pattern[1] if dashed else None,
            "cap": a.get_dash_capstyle() if dashed else a.get_solid_capstyle(),
            "join": a.get_dash_joinstyle() if dashed else a.get_solid_joinstyle()}}
    look = _patch_look(a)
    if isinstance(a, FancyArrowPatch):
        style = a.get_arrowstyle()
        return {"kind": "arrow", "ends": np.asarray(a._posA_posB, dtype=float), "look": {
            **look, "head": [style.head_length * a.get_mutation_scale(),
                                                     style.head_width * a.get_mutation_scale()],
            "cap": "butt", "join": None, "dash": None, "halo": _halo(a)}}
    if isinstance(a, Annulus):
        return {"kind": "ring", "at": np.asarray(a.get_center()), "r": max(a.get_radii()),
                "look": {**look, "cap": None, "join": None}}
    if isinstance(a, Circle):
        return {"kind": "circle", "at": np.asarray(a.get_center()), "r": a.get_radius(),
                "look": {**look, "cap": look["cap"] if look["dash"] else None, "join": None}}
    if isinstance(a, Polygon):
        return {"kind": "polygon", "points": _open(a.get_xy()),
                "look": {**look, "cap": look["cap"] if look["dash"] else None}}
    raise AssertionError(f"an artist of no mark: {a!r}")


def _halo(a) -> float:
    """An arrow's white casing, points beyond its stroke on each side (its path effect's
    stroke, `draw.paint`), 0 when it has none."""
    strokes = [e for e in a.get_path_effects() if hasattr(e, "_gc")]
    return (strokes[0]._gc["linewidth"] - a.get_linewidth()) / 2 if strokes else 0


def _patch_look(a) -> dict:
    """A patch's stroke (none when of no width or no colour), fill (a hatching in its
    colour), opacity, dashes, ends and corners."""
    ec = a.get_edgecolor()
    on = a.get_linewidth() > 0 and ec[3] > 0
    hatch = getattr(a, "get_hatchcolor", lambda: a._hatch_color)()
    fill = f"hatch {to_hex(hatch)}" if a.get_hatch() else to_hex(a.get_facecolor()) if a.get_fill() else "none"
    return {"stroke": to_hex(ec) if on else "none", "width": a.get_linewidth() if on else 0, "fill": fill,
            "hatching": _hatching(a.get_hatch()) if a.get_hatch() else None,
            "alpha": 1 if a.get_alpha() is None else a.get_alpha(),
            "dash": a._dash_pattern[1] if on and a._dash_pattern[1] is not None else None,
            "cap": a.get_capstyle(), "join": a.get_joinstyle()}


@functools.cache
def _hatching(hatch: str) -> list[float]:
    """How matplotlib paints a hatching, measured on what it paints: a hatched square drawn at
    72 dpi (a pixel a point), its lines' period along a row of pixels, which for lines rising
    at 45° is √2 times their distance across them (points); their width, matplotlib's
    `hatch.linewidth`."""
    with MATPLOTLIB:
        fig = Figure(figsize=(2, 2), dpi=72)
        canvas = FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_axis_off()
        ax.add_patch(Polygon([[0, 0], [1, 0], [1, 1], [0, 1]], transform=ax.transAxes, fill=False, lw=0, hatch=hatch))
        canvas.draw()
        row = np.asarray(canvas.buffer_rgba())[72, :, 0]
        dark = np.flatnonzero(np.diff((row < 128).astype(int)) == 1)      # where each line begins
        assert len(dark) > 4, dark
        return [float(np.mean(np.diff(dark))) / math.sqrt(2), float(matplotlib.rcParams["hatch.linewidth"])]


def _same_look(a: dict, b: dict) -> bool:
    """Two looks alike: colours as #rrggbb, numbers and outlines to round-off."""
    if a.keys() != b.keys():
        return False
    for k, x in a.items():
        y = b[k]
        if x is None or y is None:
            if (x is None) != (y is None):
                return False
        elif k in ("stroke", "fill"):
            if _paint(x) != _paint(y):
                return False
        elif k in ("cap", "join"):
            if CAP.get(str(x), str(x)) != CAP.get(str(y), str(y)):
                return False
        elif k == "hatching":           # matplotlib's measured in whole pixels (`_hatching`)
            if not np.allclose(x, y, rtol=1e-3, atol=0):
                return False
        elif isinstance(x, str) or isinstance(y, str):
            if x != y:
                return False
        elif np.shape(x) != np.shape(y) or not np.allclose(np.asarray(x, dtype=float), np.asarray(y, dtype=float),
                                                           rtol=1e-9, atol=1e-9):
            return False
    return True


def _paint(c: str) -> str:
    """A paint as #rrggbb, "none", or "hatch #rrggbb"."""
    return f"hatch {to_hex(c[6:])}" if c.startswith("hatch ") else "none" if c == "none" else to_hex(c)


def _open(points) -> np.ndarray:
    """A closed outline's vertices, its closing vertex not repeated at the end. matplotlib
    closes a polygon by repeating the first vertex unless the last is exactly it, SVG closes
    it without repeating it; an outline the scene already closes (a 3D disc's circle, its last
    vertex the first within round-off) then has one repeat more in matplotlib than on the
    page. Each repeat draws a side of no length (invisible by construction), so every
    trailing repeat is left off on both sides."""
    pts = np.asarray(points, dtype=float)
    while len(pts) > 1 and np.allclose(pts[0], pts[-1], rtol=0, atol=1e-12 * (1 + np.abs(pts).max())):
        pts = pts[:-1]
    return pts


def _key(p) -> tuple:
    return tuple(np.round(np.asarray(p, dtype=float).ravel()[:2], 6))


@pytest.mark.parametrize("name", DRAWN)
def test_the_page_and_matplotlib_paint_the_same_primitives(page, name):
    page.evaluate("window.kinematika.figure.keep = null")
    gen = page.evaluate("window.kinematika.state.gen")
    example(page, f"{name}.yaml")
    settled(page, gen)
    # the page draws what its last analysis answered: name the page's error when it has no scene
    drawn = page.evaluate("[window.kinematika.state.scene !== null, document.getElementById('error').textContent]")
    assert drawn[0], f"{name}: the page has no scene; its error panel reads {drawn[1]!r}"
    svg = page.evaluate(READ_SVG)
    mpl, marks, frame, size = matplotlib_prims(name, svg["lang"])
    assert svg["frame"] == pytest.approx(frame, abs=1e-9 * size)
    page_prims = [p for p in svg["prims"] if not p.get("hidden")]
    for p in page_prims:
        if p["kind"] == "polygon":
            p["points"] = _open(p["points"])
    assert Counter(p["kind"] for p in page_prims) == Counter(p["kind"] for p in mpl), name
    tol = 1e-6 * size

    def close(a, b) -> bool:
        return np.allclose(np.asarray(a, dtype=float), np.asarray(b, dtype=float), atol=tol, rtol=0)

    def pair(kind: str, key, same) -> None:
        """Every primitive of `kind` on the page has one in matplotlib at the same place."""
        mine = sorted((p for p in page_prims if p["kind"] == kind), key=key)
        theirs = sorted((p for p in mpl if p["kind"] == kind), key=key)
        for a, b in zip(mine, theirs):
            assert same(a, b), f"{name}: {kind} {a} ≠ {b}"

    def looks(p) -> tuple:
        """A tie-break by look among primitives at one place."""
        return tuple(_paint(p["look"][k]) for k in ("stroke", "fill"))

    same_look = lambda a, b: _same_look(a["look"], b["look"])
    pair("dot", lambda p: (_key(p["at"]), looks(p)),
         lambda a, b: close(a["at"], b["at"]) and same_look(a, b))
    pair("circle", lambda p: (_key(p["at"]), round(p["r"], 6), looks(p)),
         lambda a, b: close(a["at"], b["at"]) and math.isclose(a["r"], b["r"], abs_tol=tol) and same_look(a, b))
    pair("ring", lambda p: (_key(p["at"]), round(p["r"], 6), looks(p)),
         lambda a, b: close(a["at"], b["at"]) and math.isclose(a["r"], b["r"], abs_tol=tol) and same_look(a, b))
    pair("polygon", lambda p: (len(p["points"]), _key(p["points"][0]), looks(p)),
         lambda a, b: close(a["points"], b["points"]) and same_look(a, b))
    pair("line", lambda p: (len(p["points"]), _key(p["points"][0]), _key(p["points"][-1]), looks(p)),
         lambda a, b: close(a["points"], b["points"]) and same_look(a, b))
    # an arrow: its tip where the mark ends, its tail where it starts (double-headed: both
    # tips), set sideways by its mark's shift (points, at the page's scale)
    def arrow_ends(a: dict) -> np.ndarray:
        tip, tail = np.array(a["heads"][0][0]), np.array(a["heads"][1][0] if len(a["heads"]) > 1 else a["line"][0])
        return np.array([tail, tip])

    def offset(m) -> np.ndarray:
        d = (m.points[1] - m.points[0]) / np.linalg.norm(m.points[1] - m.points[0])
        return np.array([-d[1], d[0]]) * m.shift * PT * svg["px"]

    drawn = [m for m in marks if m.kind == "arrow" and np.linalg.norm(m.points[1] - m.points[0]) > 0]
    painted = [b for b in mpl if b["kind"] == "arrow"]
    for a in (p for p in page_prims if p["kind"] == "arrow"):
        ends = arrow_ends(a)
        k = next((k for k, b in enumerate(painted) for m in drawn
                  if close(b["ends"], m.points) and close(ends, b["ends"] + offset(m)) and same_look(a, b)), None)
        assert k is not None, f"{name}: an arrow {ends} {a['look']} not in matplotlib {[b['look'] for b in painted]}"
        painted.pop(k)
    # texts: the same labels (a label that says words in the page's language, such as a far
    # centre's "far off at", begins with the same name)
    said = {_unmath(m.text): _unmath(m.about["name"]) for m in marks
            if m.kind == "text" and m.about and m.about.get("say")}
    def text(p) -> tuple:
        return (p["content"], to_hex(p["look"]["fill"]), round(p["look"]["size"], 6), p["look"]["weight"], p["look"]["style"])

    mine = Counter(text(p) for p in page_prims if p["kind"] == "text")
    theirs = Counter(text(p) for p in mpl if p["kind"] == "text")
    for (words, *look), n in theirs.items():
        if words in said:
            assert sum(k for (t, *seen), k in mine.items()
                       if t.startswith(said[words] + " ") and seen == look) >= n, (name, words)
        else:
            assert mine[(words, *look)] == n, (name, words, look, mine)
