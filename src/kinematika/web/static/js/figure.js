// The mechanism as SVG: the marks of the API's picture (`kinematika.draw.picture`, what
// `kinematika draw` paints with matplotlib) painted as they are — outlines, hatches, symbols,
// dots, arrows and labels in model coordinates, with their colours, widths and layers — and
// moved through the sweep's rows: each body's marks turn by its swept `angle` about one of its
// points, which goes to its swept position (as `kinematika animate` moves them). A 3D body's
// marks turn in space (its `angle` is a rotation vector) from their model coordinates (`xyz`)
// and are projected again. Results only the scene holds (instant centres, Kennedy lines,
// curvature circles, relative vectors) are shown at the position the scene was solved at; the
// arrows of swept points follow the sweep, to the scene's scale (`style.longest`, `shortest`).
import { el, runsText, placeLines, num, shown } from "./svg.js";

const PT = 4 / 3;        // CSS pixels per point: a mark's widths and sizes are in points
const GAP = 3;           // points between a label and what it labels (its `radius` around its anchor)
const MARGIN = 0.05;     // drawing sizes around the swept points' paths
const CAPS = { round: "round", butt: "butt", projecting: "square" };   // matplotlib's names

export class Figure {
  constructor(svg, legend, notes, onDrag, t = (id) => id) {
    this.svg = svg;
    this.legend = legend;
    this.notes = notes;
    this.onDrag = onDrag;
    this.t = t;                  // the page's words (i18n.js)
    this.onPick = null;          // the builder's: a click on a point, a body or a place
    this.onView = null;          // called after the view changed (zoom, pan, a new frame)
    this.onTurn = null;          // a point dragged along the motion (by hand, or with Shift): (name, at, phase)
    this.byHand = false;         // every drag of a point moves the mechanism, not the model
    this.layers = { velocity: true, acceleration: true, centres: true, curvature: true, traces: true };
    this.scene = null;
    this.sweep = null;
    this.row = 0;
    this.sceneRow = 0;
    this.keep = null;            // a view kept (zoom, pan, a drag, building): [x0, y0, x1, y1]
    this.drag = null;            // the point being dragged and where the pointer holds it
    // the figure's own drawing goes in `content`; the builder draws above it in `overlayRoot`
    this.content = el("g", { class: "content" }, svg);
    this.buildRoot = el("g", { class: "build" }, svg);
    new ResizeObserver(() => this.paint()).observe(svg);
    this.pointer();
  }

  /** A new scene (solved at sweep row `sceneRow`), and the sweep it moves through (or null). */
  set(scene, sweep, sceneRow = 0) {
    this.scene = scene;
    this.P = scene.dimension === 3 && scene.projection ? scene.projection : null;   // 2 × 3
    this.raw = sweep && (scene.dimension === 2 || this.P) ? sweep : null;
    this.sweep = this.raw && onPage(this.raw, this.P);
    this.sceneRow = sceneRow;
    this.row = sceneRow;
    this.paint();
  }

  /** Replace the results only the scene holds (after a solve at row `row`). */
  overlay(scene, row) {
    if (!this.scene) return;
    this.overlayScene = scene;
    this.overlayRow = row;
    this.paintOverlay();
    this.show(this.row);
  }

  setLayer(name, on) {
    this.layers[name] = on;
    if (this.scene) this.applyLayers();
  }

  stale(on) { this.svg.classList.toggle("stale", on); }

  // painting --------------------------------------------------------------------------
  /** The box shown: the kept one, else the frame of the scene (or of `this.empty`). */
  frameView() {
    if (this.keep) return this.keep;
    if (this.scene) return this.frameBox();
    return this.empty || [-0.1, -0.1, 0.3, 0.2];
  }

  /** Set the SVG's viewBox to `box` widened to the element's aspect (so that a kept view
   * maps the pointer the same way after every repaint). */
  applyView(box) {
    const w = this.svg.clientWidth || 800, h = this.svg.clientHeight || 440;
    let [x0, y0, x1, y1] = box;
    const px = Math.max((x1 - x0) / w, (y1 - y0) / h);
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    [x0, x1, y0, y1] = [cx - (px * w) / 2, cx + (px * w) / 2, cy - (px * h) / 2, cy + (px * h) / 2];
    this.view = [x0, y0, x1, y1];
    this.px = px;                                              // model units per CSS pixel
    this.svg.setAttribute("viewBox", `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`);
    this.svg.style.setProperty("--halo", String(3 * this.px));  // the white halo of labels
  }

  paint() {
    const s = this.scene;
    this.content.replaceChildren();
    this.size = (s && s.size) || 1;
    this.applyView(this.frameView());
    if (!s) { this.legend.innerHTML = ""; this.onView?.(); return; }
    this.defs = el("defs", {}, this.content);
    this.hatches = {};
    const g = (cls) => el("g", { class: cls }, this.content);
    this.g = { under: g("under"), traces: g("traces"), bodies: g("bodies"), pins: g("pins"), overlay: g("overlay"),
               vectors: g("vectors"), labels: g("labels"), handles: g("handles") };
    this.bodyGroups = {};       // body -> its groups, one in each layer it has marks in
    this.texts = [];            // labels, placed at every row where their body is
    this.tracked = [];          // 3D: marks placed from their model coordinates at every row
    this.points = [];           // each point's dot, label and handle
    for (const [name, b] of Object.entries(s.bodies)) if (!b.frame) this.group("bodies", name);
    this.anchors = Object.fromEntries(Object.entries(s.bodies).map(([name, b]) => [name, this.anchor(name, b)]));
    this.paintTraces();
    const live = this.liveGroups(s);
    const still = s.picture.marks.filter((m) => !m.layer && !(m.still && this.sweep)).sort((m, n) => m.zorder - n.zorder);
    for (const m of still) this.paintMechanism(m);
    this.paintHandles();
    this.liveVectors(live);
    this.overlayScene = this.scene;
    this.overlayRow = this.sceneRow;
    this.paintOverlay();
    this.paintLegend();
    const numbering = (s.numbering || []).length
      ? [this.t("bodies-numbered", { list: s.numbering.map(([n, b]) => `${n} ${shown(b)}`).join(", ") })] : [];
    this.notes.textContent = [...numbering, ...(s.notes || []).map((n) => shown(n, 2000))].join(" · ");
    this.show(this.row);
    this.onView?.();
  }

  /** No scene (a model being built that cannot be solved yet): the figure frames `box`. */
  clear(box) {
    this.scene = null;
    this.sweep = null;
    this.empty = box;
    this.paint();
  }

  // the view: zoom, pan, fit ---------------------------------------------------------------
  zoom(factor, at = null) {
    const [x0, y0, x1, y1] = this.view;
    const [cx, cy] = at || [(x0 + x1) / 2, (y0 + y1) / 2];
    this.keep = [cx + (x0 - cx) * factor, cy + (y0 - cy) * factor, cx + (x1 - cx) * factor, cy + (y1 - cy) * factor];
    this.paint();
  }

  pan(dx, dy) {
    const [x0, y0, x1, y1] = this.view;
    this.keep = [x0 - dx, y0 - dy, x1 - dx, y1 - dy];
    this.paint();
  }

  fit() { this.keep = null; this.paint(); }

  /** Keep the view as it is (a drag or a building step must not move the grid under the hand). */
  hold() { if (this.view) this.keep = [...this.view]; }

  /** The box (model coordinates) the figure frames: the picture's frame, and the paths of
   * the swept points. */
  frameBox() {
    let [x0, y0, x1, y1] = this.scene.picture.frame;
    const m = MARGIN * this.size;
    for (const v of Object.values(this.sweep ? this.sweep.points : {})) {
      for (const p of v.position) {
        if (!p) continue;
        x0 = Math.min(x0, p[0] - m); y0 = Math.min(y0, p[1] - m); x1 = Math.max(x1, p[0] + m); y1 = Math.max(y1, p[1] + m);
      }
    }
    return [x0, y0, x1, y1];
  }

  /** The group of body `name` in `layer` (under, bodies, pins; the layer itself for the
   * frame), which the body's placement moves. */
  group(layer, name) {
    if (!name || this.scene.bodies[name].frame) return this.g[layer];
    const groups = (this.bodyGroups[name] ||= {});
    const cls = { under: "body-under", bodies: "body", pins: "body-pins" }[layer];
    return (groups[layer] ||= el("g", { class: cls, "data-body": name }, this.g[layer]));
  }

  /** Body `name`'s groups. */
  groupsOf(name) { return Object.values(this.bodyGroups[name] || {}); }

  /** The material point a body's placement follows: its first swept point. */
  anchor(name, b) {
    if (!this.sweep || b.frame) return null;
    for (const p of Object.keys(b.points)) if (this.sweep.points[`${p}@${name}`]) return p;
    return null;
  }

  /** A mark of the mechanism, in its body's group (texts above everything, moved with it). */
  paintMechanism(m) {
    if (m.kind === "text") { this.label(m, this.g.labels); return; }
    const layer = m.zorder >= 5 ? "pins" : m.zorder < 2 || !m.body ? "under" : "bodies";
    const node = this.mark(m, this.group(layer, m.body));
    const [role, key] = split(m.group);
    if (role === "joint") node.setAttribute("data-joint", key);
    if (role === "point") {
      node.setAttribute("data-point", key);
      this.points.push({ name: key, body: m.body, xy: m.points[0] });
    }
    if (m.xyz) this.track(node, m);
  }

  /** A draggable handle at every point (a 3D point is moved in the text), with its label. */
  paintHandles() {
    for (const pt of this.points) {
      const text = this.texts.find((x) => x.m.group === `point:${pt.name}`);
      [pt.label, pt.labelMark] = text ? [text.node, text.m] : [null, null];
      if (this.scene.dimension !== 2) continue;
      pt.handle = el("circle", { r: 9 * this.px, class: "draggable", "data-handle": pt.name }, this.g.handles);
      el("title", {}, pt.handle).textContent = this.t("handle-tip", { point: shown(pt.name) });
    }
  }

  /** One mark as SVG (`kinematika.joints.symbols.Mark`) in `parent`: a dot (a marker of its
   * size in points: a circle, or its `outline` in sizes), a line, a polygon (hatched: the
   * frame's material), a circle, a ring, an arrow; a text is a label. */
  mark(m, parent) {
    const p = m.points, paint = this.paintOf(m);
    if (m.kind === "dot") {
      const size = m.size * PT * this.px, [x, y] = p[0];
      if (!m.outline) return el("circle", { cx: x, cy: -y, r: size / 2, ...paint, class: "dot" }, parent);
      return el("polygon", { points: poly(m.outline.map(([u, v]) => [x + u * size, y + v * size])), ...paint, class: "dot" }, parent);
    }
    if (m.kind === "line") {
      if (p.some((q) => q[0] === null)) return el("path", { d: broken(p), ...paint, fill: "none" }, parent);
      return el("polyline", { points: poly(p), ...paint, fill: "none" }, parent);
    }
    if (m.kind === "polygon") return el("polygon", { points: poly(p), ...paint }, parent);
    if (m.kind === "circle") return el("circle", { cx: p[0][0], cy: -p[0][1], r: m.r, ...paint }, parent);
    if (m.kind === "ring") {
      return el("circle", { cx: p[0][0], cy: -p[0][1], r: m.r - m.band / 2, fill: "none", stroke: paint.fill,
                            "stroke-opacity": paint["fill-opacity"], "stroke-width": m.band, class: "model-width" }, parent);
    }
    if (m.kind === "arrow") return this.arrow(m, p[0], p[1], parent);
    return this.label(m, parent);
  }

  /** A mark's fill and stroke: its colours, opacity, width in points, dashes in line widths. */
  paintOf(m) {
    const a = m.alpha ?? 1, stroked = m.width > 0 && !m.hatch && m.colour !== "none";
    return { fill: m.hatch ? this.hatch(m.colour, typeof m.hatch === "string" && m.hatch.startsWith("\\")) : m.fill, "fill-opacity": a < 1 ? a : null,
             stroke: stroked ? m.colour : "none", "stroke-opacity": a < 1 ? a : null, "stroke-width": stroked ? m.width * PT : null,
             "stroke-dasharray": m.dash && stroked ? m.dash.map((d) => d * m.width * PT).join(" ") : null,
             "stroke-linecap": CAPS[m.cap] || "square", "stroke-linejoin": m.join === "round" ? "round" : null };
  }

  /** The hatching in `colour`: lines rising to the right (falling, across a fixed edge that
   * rises near 45°: the mark's hatch is matplotlib's backslashes), as far apart and as wide
   * (points) as the scene's `style.hatch` says (matplotlib's). */
  hatch(colour, falling = false) {
    const key = `${colour}${falling ? "\\" : "/"}`;
    if (!this.hatches[key]) {
      const { spacing, width } = this.scene.style.hatch;
      const id = `hatch${Object.keys(this.hatches).length}`, step = spacing * PT * this.px;
      const p = el("pattern", { id, patternUnits: "userSpaceOnUse", width: step, height: step, patternTransform: `rotate(${falling ? -45 : 45})` }, this.defs);
      el("line", { x1: 0, y1: 0, x2: 0, y2: step, stroke: colour, "stroke-width": width * PT * this.px, class: "model-width" }, p);
      this.hatches[key] = `url(#${id})`;
    }
    return this.hatches[key];
  }

  /** An arrow from `start` to `end` with its heads (`-|>` or `<|-|>`, of its size in points),
   * set its `shift` (points) sideways; under it, its white casing `halo` points wider on each
   * side (class "casing"), when it has one. */
  arrow(m, start, end, parent) {
    const g = el("g", { class: `arrow kind-${m.layer}` }, parent);
    const strokes = m.halo ? [["white", m.width + 2 * m.halo, { class: "casing" }], [m.colour, m.width, {}]]
      : [[m.colour, m.width, {}]];
    for (const [colour, width, role] of strokes) {
      const paint = { stroke: colour, "stroke-width": width * PT, ...role };
      el("polyline", { fill: "none", ...paint, "stroke-linecap": "butt" }, g);
      el("polygon", { fill: colour, ...paint }, g);
      if (m.head === "<|-|>") el("polygon", { fill: colour, ...paint }, g);
    }
    this.placeArrow(g, m, start, end);
    return g;
  }

  placeArrow(g, m, start, end) {
    const len = Math.hypot(end[0] - start[0], end[1] - start[1]);
    g.setAttribute("visibility", len > 0 ? "visible" : "hidden");
    if (!(len > 0)) return;
    const d = [(end[0] - start[0]) / len, (end[1] - start[1]) / len], n = [-d[1], d[0]];
    const shift = mul(n, (m.shift || 0) * PT * this.px);
    const hl = 0.4 * m.size * PT * this.px, hw = 0.2 * m.size * PT * this.px;
    const [a, b] = [add(start, shift), add(end, shift)];
    const head = (tip, dir) => { const back = add(tip, mul(dir, -hl)); return [tip, add(back, mul(n, hw)), add(back, mul(n, -hw))]; };
    const both = m.head === "<|-|>", each = both ? 3 : 2;      // a stroke's line and heads (the casing's, then the arrow's)
    const parts = [...g.children];
    for (let i = 0; i + each <= parts.length; i += each) {
      const [line, ...heads] = parts.slice(i, i + each);
      line.setAttribute("points", poly([both ? add(a, mul(d, hl)) : a, add(b, mul(d, -hl))]));
      heads[0].setAttribute("points", poly(head(b, d)));
      if (both) heads[1].setAttribute("points", poly(head(a, mul(d, -1))));
    }
  }

  /** A label at its anchor, towards its preferred side (up and right by default); one that
   * says words in the page's language (`about.say`) gets them. */
  label(m, parent) {
    const runs = m.about && m.about.say ? [...m.about.name, { t: ` ${this.t(m.about.say, m.about.args || {})}` }] : m.text;
    const node = runsText(parent, runs, { "font-size": m.size * PT * this.px, fill: m.colour,
      "font-weight": m.weight === "bold" ? "bold" : null, "font-style": m.style === "italic" ? "italic" : null,
      class: m.group && m.group.startsWith("point:") ? "point-label" : null });
    placeText(node, m.points[0], this.gap(m), m.prefer || m.side);
    this.texts.push({ node, m, body: m.body, at: m.points[0] });
    if (m.xyz) this.tracked.push({ node, body: m.body, kind: "text", xyz: m.xyz, m });
    return node;
  }

  /** How far (model units) a label stands from its anchor: `GAP` beyond its `radius`. */
  gap(m) { return (GAP + ((m && m.radius) || 0)) * PT * this.px; }

  /** Keep `node` of a 3D mark to be placed from its model coordinates at every row. */
  track(node, m) {
    if (!this.P || !this.sweep || !m.body) return;
    const kind = m.kind === "circle" || (m.kind === "dot" && !m.outline) ? "circle" : m.kind === "line" || m.kind === "polygon" ? "points" : null;
    if (kind) this.tracked.push({ node, body: m.body, kind, xyz: m.xyz });
  }

  /** The full path of every moving point over the sweep (coupler curves), faint. */
  paintTraces() {
    if (!this.sweep) return;
    const seen = [];
    const asked = new Set(this.scene.vectors.map((v) => v.ref));
    const keys = Object.keys(this.sweep.points).sort((a, b) => asked.has(b) - asked.has(a));
    const colour = this.scene.style.path;
    for (const key of keys) {
      const v = this.sweep.points[key];
      const path = v.position.filter((p) => p !== null);
      if (path.length < 2) continue;
      const spread = Math.max(...path.map((p) => dist(p, path[0])));
      if (spread <= 1e-6 * this.size) continue;
      if (seen.some((q) => q.length === path.length && q.every((p, i) => dist(p, path[i]) < 1e-9 * this.size))) continue;
      seen.push(path);
      const strong = asked.has(key);      // the asked points' paths (coupler curves) stand out
      el("polyline", { points: poly(path), fill: "none", stroke: colour, "stroke-opacity": strong ? 0.75 : 0.4,
                       "stroke-width": strong ? 1.6 : 1.1, "stroke-dasharray": strong ? null : "4 3",
                       "data-trace": key }, this.g.traces);
    }
  }

  /** The groups of the arrows that follow the sweep (the absolute vectors of swept points). */
  liveGroups(s) {
    if (!this.sweep) return new Set();
    return new Set(s.picture.marks.filter((m) => m.kind === "arrow" && m.about && !m.about.relative_to &&
      this.sweep.points[m.about.ref]).map((m) => m.group));
  }

  /** The arrows that follow the sweep, each kind to one scale over the whole motion: the
   * longest `style.longest` of the drawing, none shorter than `style.shortest` (enlarged). */
  liveVectors(live) {
    this.arrows = [];
    this.largest = {};
    const marks = this.scene.picture.marks.filter((m) => live.has(m.group));
    for (const m of marks.filter((x) => x.kind === "arrow")) {
      const { kind, ref, magnitude } = m.about;
      this.largest[kind] = Math.max(this.largest[kind] || 0, magnitude, ...this.sweep.points[ref].size[kind].filter((x) => x));
      const [, key] = split(m.group);
      const g = el("g", { "data-vector": key }, this.g.vectors);
      const text = marks.find((x) => x.kind === "text" && x.group === m.group);
      const label = runsText(g, [...m.about.symbol, { t: " = " }], { "font-size": (text ? text.size : 9) * PT * this.px, fill: m.colour });
      this.arrows.push({ m, g, node: this.arrow(m, m.points[0], m.points[1], g), label, value: el("tspan", {}, label), swept: this.sweep.points[ref] });
    }
  }

  /** Arrow `a` at a row: from the point's place, its value to the kind's scale. */
  placeLive(a, k) {
    const { kind, at_point: flip } = a.m.about, st = this.scene.style;
    const origin = a.swept.position[k], value = a.swept[kind][k], magnitude = a.swept.size[kind][k] || 0;
    const largest = this.largest[kind] || 0;
    if (!origin || !value || largest <= 0 || magnitude <= 1e-9 * largest) {
      this.placeArrow(a.node, a.m, origin || [0, 0], origin || [0, 0]);
      if (origin) placeText(a.label, origin, GAP * PT * this.px, null);
      a.value.textContent = "0";
      return;
    }
    let factor = (st.longest * this.size) / largest, enlarged = false;
    if (magnitude * factor < st.shortest * this.size) { factor = (st.shortest * this.size) / magnitude; enlarged = true; }
    const tip = add(origin, mul(value, factor));
    const [start, end] = flip ? [add(origin, sub(origin, tip)), origin] : [origin, tip];
    this.placeArrow(a.node, a.m, start, end);
    placeText(a.label, flip ? start : end, GAP * PT * this.px, flip ? sub(start, end) : sub(end, start));   // beyond the free end
    a.value.textContent = num(magnitude) + (enlarged ? ` ${this.t("enlarged")}` : "");
  }

  /** The results of the scene solved at the overlay's row: centres, Kennedy lines,
   * curvature, and the vectors that do not follow the sweep, each thing in its group. */
  paintOverlay() {
    const s = this.overlayScene;
    const g = this.g.overlay;
    g.replaceChildren();
    this.overlayParts = { centres: el("g", { class: "centres" }, g), curvature: el("g", { class: "curvature" }, g),
                          vectors: el("g", { class: "relative" }, g) };
    const live = this.liveGroups(s), groups = {};
    const marks = s.picture.marks.filter((m) => m.layer && !live.has(m.group)).sort((m, n) => m.zorder - n.zorder);
    for (const m of marks) {
      const part = this.overlayParts[m.layer] || this.overlayParts.vectors;
      const [role, key] = split(m.group);
      const parent = role ? (groups[m.group] ||= el("g", { [`data-${role}`]: key }, part)) : part;
      this.mark(m, parent);
    }
    this.overlayArrows = [...this.overlayParts.vectors.children];
    this.applyLayers();
  }

  /** Show or hide the layers (as switched, and the scene-only results away from their row). */
  applyLayers() {
    const showOverlay = this.row === this.overlayRow;
    visible(this.g.traces, this.layers.traces);
    if (this.overlayParts) {
      visible(this.overlayParts.centres, this.layers.centres && showOverlay);
      visible(this.overlayParts.curvature, this.layers.curvature && showOverlay);
      for (const a of this.overlayArrows) visible(a, this.layers[kindOf(a)] !== false && showOverlay);
    }
    for (const a of this.arrows) visible(a.g, this.layers[a.m.layer]);
  }

  paintLegend() {
    const items = [];
    const kinds = new Set(this.scene.vectors.map((v) => v.kind));
    const t = this.t;
    if (kinds.has("velocity")) items.push(`<li><i style="background:var(--velocity)"></i>${t("legend-velocity")}</li>`);
    if (kinds.has("acceleration")) items.push(`<li><i style="background:var(--acceleration)"></i>${t("legend-acceleration")}</li>`);
    if (this.scene.marks.some((m) => m.kind === "icr")) items.push(`<li><i class="ring"></i>${t("legend-centre")}</li>`);
    if (this.scene.kennedy.length) items.push(`<li><i class="dash"></i>${t("legend-kennedy")}</li>`);
    if (this.scene.curvatures.length) items.push(`<li><i style="background:var(--curvature)"></i>${t("legend-curvature")}</li>`);
    if (this.sweep) items.push(`<li><i style="background:${this.scene.style.path};opacity:.5"></i>${t("legend-path")}</li>`);
    if (this.scene.dimension === 2) items.push(`<li class="hint">${t("legend-drag")}</li>`);
    this.legend.innerHTML = items.join("");
  }

  // moving ------------------------------------------------------------------------------
  /** The mechanism at sweep row `k`. */
  show(k) {
    this.row = k;
    if (!this.scene) return;
    const sw = this.sweep;
    this.places = {};
    if (sw) {
      const ok = sw.coordinate[k] !== undefined && Object.values(sw.bodies)[0]?.angle[k] !== null;
      this.svg.classList.toggle("unassembled", !ok);
      if (this.P) this.move3(k);
      else for (const name of Object.keys(this.bodyGroups)) this.move2(name, k);
      for (const a of this.arrows) this.placeLive(a, k);
    }
    for (const x of this.texts) {
      const p = this.placed(x.body, x.at);
      if (p && !x.tracked) placeText(x.node, p, this.gap(x.m), x.m.prefer || x.m.side);
      x.node.setAttribute("visibility", p ? "visible" : "hidden");
    }
    for (const pt of this.points) {
      let p = this.placed(pt.body, pt.xy);
      if (this.drag && this.drag.name === pt.name) {                     // under the hand
        p = this.drag.at;
        if (pt.label) placeText(pt.label, p, this.gap(pt.labelMark), null);
      }
      pt.handle?.setAttribute("cx", p ? p[0] : 0);
      pt.handle?.setAttribute("cy", p ? -p[1] : 0);
      pt.handle?.setAttribute("visibility", p ? "visible" : "hidden");
    }
    this.applyLayers();
    this.unclutter();
  }

  /** A 2D body at row `k`: turned by its swept angle since the scene's row about its anchor,
   * which goes to its swept place. */
  move2(name, k) {
    const anchor = this.anchors[name], sw = this.sweep;
    if (!anchor) return;
    const p0 = this.scene.bodies[name].points[anchor];
    const pk = sw.points[`${anchor}@${name}`].position[k];
    const a0 = sw.bodies[name].angle[this.sceneRow], ak = sw.bodies[name].angle[k];
    const here = pk && ak !== null && a0 !== null;
    for (const x of this.groupsOf(name)) visible(x, here);
    if (!here) { this.places[name] = null; return; }
    const turn = ((ak - a0) * Math.PI) / 180, c = Math.cos(turn), s = Math.sin(turn);
    this.places[name] = (p) => [pk[0] + c * (p[0] - p0[0]) - s * (p[1] - p0[1]), pk[1] + s * (p[0] - p0[0]) + c * (p[1] - p0[1])];
    const placed = `translate(${pk[0]} ${-pk[1]}) rotate(${-(ak - a0)}) translate(${-p0[0]} ${p0[1]})`;
    for (const x of this.groupsOf(name)) x.setAttribute("transform", placed);
  }

  /** Where a point of `body` drawn at `p` is at the row shown (null: the body is not there). */
  placed(body, p) {
    if (!body || !(body in this.places)) return p;
    const f = this.places[body];
    return f ? f(p) : null;
  }

  /** Labels that would overlap are moved apart: the points' names stay; each other label
   * after them is shifted up or down (by its height, at most twice) to the first place where
   * it overlaps no label already placed. A label that would stick out of the figure (an
   * arrow's tip near its edge, on a narrow screen) is moved back inside it. */
  unclutter() {
    if (!this.g) return;
    const named = this.points.map((pt) => pt.label).filter(Boolean);
    const texts = [...named, ...this.svg.querySelectorAll(".content .labels text:not(.point-label), .content .vectors text, .content .overlay text")];
    const placed = [];
    const [x0, y0, x1, y1] = this.view, pad = 2 * this.px;
    const inside = (lo, size, from, to) => (size > to - from ? 0 : Math.max(from - lo, 0) + Math.min(to - (lo + size), 0));
    for (const t of texts) {
      t.removeAttribute("transform");
      if (t.getAttribute("visibility") === "hidden" || !t.getClientRects().length) continue;
      const b = t.getBBox();
      if (!b.width) continue;
      const fixed = named.includes(t);
      let dy = 0;
      if (!fixed) {
        const gap = 0.15 * b.height;
        const clash = (d) => placed.some((q) => b.x < q.x + q.width && q.x < b.x + b.width &&
                                              b.y + d < q.y + q.height + gap && q.y < b.y + d + b.height + gap);
        dy = [0, b.height, -b.height, 2 * b.height, -2 * b.height].find((d) => !clash(d)) ?? 0;
      }
      const dx = inside(b.x, b.width, x0 + pad, x1 - pad);       // user units: y is −model y
      dy += inside(b.y + dy, b.height, -y1 + pad, -y0 - pad);
      if (dx || dy) t.setAttribute("transform", `translate(${dx} ${dy})`);
      placed.push({ x: b.x + dx, y: b.y + dy, width: b.width, height: b.height });
    }
  }

  /** The 3D bodies at sweep row `k`: each tracked mark turned in space by its body's rotation
   * since the scene's row (R_k R_s^T, from the rotation vectors), about its anchor point
   * carried to its swept place, and projected on the page. */
  move3(k) {
    const placed = {}, P = this.P, s = this.sceneRow;
    for (const name of Object.keys(this.bodyGroups)) {
      const anchor = this.anchors[name];
      if (!anchor) continue;
      const a = this.raw.points[`${anchor}@${name}`].position, turn = this.raw.bodies[name].angle;
      const ok = a[s] && a[k] && turn[s] && turn[k];
      for (const x of this.groupsOf(name)) visible(x, ok);
      if (!ok) continue;
      const R = times(rotation(turn[k]), transpose(rotation(turn[s])));
      const A = times(P, R);                                    // 2 × 3: space to page
      const from = apply(A, a[s]), to = apply(P, a[k]);
      placed[name] = { A, c: [to[0] - from[0], to[1] - from[1]] };
    }
    for (const t of this.tracked) {
      const m = placed[t.body];
      if (!m) continue;
      const pts = t.xyz.map((x) => { const p = apply(m.A, x); return [p[0] + m.c[0], p[1] + m.c[1]]; });
      if (t.kind === "circle") {
        t.node.setAttribute("cx", pts[0][0]);
        t.node.setAttribute("cy", -pts[0][1]);
      } else if (t.kind === "text") placeText(t.node, pts[0], this.gap(t.m), t.m.prefer || t.m.side);
      else t.node.setAttribute("points", poly(pts));
    }
    for (const x of this.texts) x.tracked = !!(this.tracked.find((t) => t.node === x.node) && placed[x.body]);
  }

  // the pointer: dragging a point, picking for the builder, panning ---------------------------
  /** One listener on the SVG element itself, which is never replaced: a drag holds the
   * pointer (setPointerCapture on the SVG) through any number of repaints of its content. */
  pointer() {
    const svg = this.svg;
    let act = null;
    svg.addEventListener("pointerdown", (e) => {
      if (e.button !== 0 && e.button !== 1) return;
      // what is under the pointer, through arrows, labels and lines drawn over the bodies
      const stack = document.elementsFromPoint(e.clientX, e.clientY).filter((n) => svg.contains(n));
      const find = (sel) => stack.map((n) => n.closest(sel)).find(Boolean);
      const handle = find("[data-handle]");
      const body = find("[data-body], [data-build-body]");
      const hit = handle ? { point: handle.dataset.handle }
        : body ? { body: body.dataset.body || body.dataset.buildBody } : {};
      const at = this.toModel(e, false);
      if (e.button === 0 && this.onPick && this.onPick(hit, at, e)) { e.preventDefault(); return; }
      e.preventDefault();
      svg.setPointerCapture(e.pointerId);
      if (e.button === 0 && hit.point && (this.byHand || e.shiftKey) && this.onTurn) {
        act = { kind: "turn", id: e.pointerId, name: hit.point };          // the mechanism moves, not the model
        svg.classList.add("turning");
        this.onTurn(hit.point, at, "start");
      } else if (e.button === 0 && hit.point && this.canDrag(hit.point)) {
        this.hold();
        this.drag = { name: hit.point, at: this.toModel(e) };
        act = { kind: "drag", id: e.pointerId, x: e.clientX, y: e.clientY, moved: false };
      } else {
        act = { kind: "pan", id: e.pointerId, x: e.clientX, y: e.clientY, moved: false };
      }
    });
    svg.addEventListener("pointermove", (e) => {
      if (!act || e.pointerId !== act.id) return;
      if (act.kind === "turn") {
        this.onTurn(act.name, this.toModel(e, false), "move");
      } else if (act.kind === "drag") {
        if (!act.moved && Math.hypot(e.clientX - act.x, e.clientY - act.y) < 3) return;   // a click, not a drag
        if (!act.moved) { act.moved = true; svg.classList.add("dragging"); this.onDrag(this.drag.name, null, false); }
        this.drag.at = this.toModel(e);
        this.placeDragged();
        this.onDrag(this.drag.name, this.drag.at, false);
      } else {
        const dx = (e.clientX - act.x) * this.px, dy = (e.clientY - act.y) * this.px;
        if (!act.moved && Math.hypot(e.clientX - act.x, e.clientY - act.y) < 4) return;
        act.moved = true;
        act.x = e.clientX; act.y = e.clientY;
        this.pan(dx, -dy);
      }
    });
    const end = (e) => {
      if (!act || e.pointerId !== act.id) return;
      const was = act;
      act = null;
      if (was.kind === "turn") {
        svg.classList.remove("turning");
        this.onTurn(was.name, this.toModel(e, false), "end");
      } else if (was.kind === "drag" && !was.moved) {
        this.drag = null;
      } else if (was.kind === "drag") {
        const name = this.drag.name, at = this.toModel(e);
        this.drag.at = at;
        this.drag.done = true;
        svg.classList.remove("dragging");
        this.onDrag(name, at, true);
      } else if (!was.moved && this.onPick) {
        this.onPick({ empty: true }, this.toModel(e, false), e);
      }
    };
    svg.addEventListener("pointerup", end);
    svg.addEventListener("pointercancel", end);
    svg.addEventListener("wheel", (e) => {
      e.preventDefault();
      this.zoom(e.deltaY > 0 ? 1.15 : 1 / 1.15, this.toModel(e, false));
    }, { passive: false });
  }

  /** Where point `name` is drawn now (its handle, at the row shown), or null. */
  at(name) {
    const pt = (this.points || []).find((x) => x.name === name);
    if (!this.scene || !pt || !pt.handle || pt.handle.getAttribute("visibility") === "hidden") return null;
    return [Number(pt.handle.getAttribute("cx")), -Number(pt.handle.getAttribute("cy"))];
  }

  /** A point can be dragged in a planar model (a 3D point is moved in its text). */
  canDrag(name) { return !this.scene || this.scene.dimension === 2; }

  /** The dragged point's handle and label at the pointer (whatever was repainted). */
  placeDragged() {
    const d = this.drag;
    const pt = d && (this.points || []).find((x) => x.name === d.name);
    if (!pt) return;
    pt.handle?.setAttribute("cx", d.at[0]);
    pt.handle?.setAttribute("cy", -d.at[1]);
    if (pt.label) placeText(pt.label, d.at, this.gap(pt.labelMark), null);
  }

  /** The drag is over once its last edit has been solved and drawn. */
  release() { if (this.drag && this.drag.done) this.drag = null; }

  /** The model point under a pointer event, rounded to a thousandth of the drawing. */
  toModel(ev, rounded = true) {
    const m = this.svg.getScreenCTM().inverse();
    const x = m.a * ev.clientX + m.c * ev.clientY + m.e, y = m.b * ev.clientX + m.d * ev.clientY + m.f;
    if (!rounded) return [x, -y];
    const step = 10 ** Math.floor(Math.log10(this.size / 500));
    const round = (v) => Number((Math.round(v / step) * step).toFixed(Math.max(0, -Math.log10(step))));
    return [round(x), round(-y)];
  }
}

// moving with the sweep -----------------------------------------------------------------
/** The sweep with its points on the page (3D: projected by P) and the sizes of their
 * velocities and accelerations (in space), which the arrows' scale reads. */
function onPage(sweep, P) {
  const page = P ? (x) => (x ? apply(P, x) : null) : (x) => x;
  const size = (xs) => xs.map((x) => (x ? Math.hypot(...x) : null));
  const points = {};
  for (const [key, v] of Object.entries(sweep.points)) {
    points[key] = { position: v.position.map(page), velocity: v.velocity.map(page),
                    acceleration: v.acceleration.map(page),
                    size: { velocity: size(v.velocity), acceleration: size(v.acceleration) } };
  }
  return { ...sweep, points };
}

/** The rotation matrix of a rotation vector in degrees (Rodrigues). */
function rotation(v) {
  const t = (Math.hypot(...v) * Math.PI) / 180;
  if (t < 1e-12) return [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const [x, y, z] = v.map((c) => (c * Math.PI) / 180 / t);
  const c = Math.cos(t), s = Math.sin(t), C = 1 - c;
  return [[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
          [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
          [z * x * C - y * s, z * y * C + x * s, c + z * z * C]];
}
const transpose = (m) => m[0].map((_, j) => m.map((row) => row[j]));
const times = (a, b) => a.map((row) => b[0].map((_, j) => row.reduce((sum, x, i) => sum + x * b[i][j], 0)));
const apply = (m, x) => m.map((row) => row[0] * x[0] + row[1] * x[1] + row[2] * x[2]);

const add = (p, q) => [p[0] + q[0], p[1] + q[1]];
const sub = (p, q) => [p[0] - q[0], p[1] - q[1]];
const mul = (p, s) => [p[0] * s, p[1] * s];
const dist = (p, q) => Math.hypot(...p.map((x, i) => x - q[i]));      // in the plane or in space
const poly = (pts) => pts.map((p) => `${p[0]},${-p[1]}`).join(" ");
/** A polyline broken where a point is null (outside the picture's reach). */
const broken = (pts) => pts.map((p, i) => (p[0] === null ? "" : `${i && pts[i - 1][0] !== null ? "L" : "M"}${p[0]},${-p[1]}`)).join(" ");
/** A mark's group "ROLE:KEY" as [role, key]. */
const split = (group) => { if (!group) return [null, null]; const i = group.indexOf(":"); return [group.slice(0, i), group.slice(i + 1)]; };
const kindOf = (g) => g.dataset.vector?.split(":")[0];

/** Display a group or not (`display`, which its children cannot override). */
function visible(node, on) {
  node.style.display = on ? "" : "none";
}

/** Put a label `gap` (model units) from `p` towards `towards` (up and right when null),
 * anchored on the side it leaves from. */
function placeText(text, p, gap, towards) {
  const n = towards ? Math.hypot(towards[0], towards[1]) : 0;
  const [c, s] = n > 0 ? [towards[0] / n, towards[1] / n] : [Math.SQRT1_2, Math.SQRT1_2];
  text.setAttribute("x", p[0] + c * gap);
  text.setAttribute("y", -(p[1] + s * gap));
  text.setAttribute("text-anchor", c > 0.3 ? "start" : c < -0.3 ? "end" : "middle");
  text.setAttribute("dominant-baseline", s > 0.3 ? "text-after-edge" : s < -0.3 ? "hanging" : "middle");
  placeLines(text);
}
