// The mechanism as SVG, painted from the API's scene (what `kinematika draw` paints) and
// moved through the sweep's rows: each body turns by its swept `angle` about one of its
// points, which goes to its swept position (as `kinematika animate` does). A 3D body turns
// in space (its `angle` is a rotation vector) and is projected again: the scene gives the
// model coordinates of what it draws (`…_xyz`) and the projection. Results that only
// the scene holds (instant centres, Kennedy lines, curvature circles, relative vectors) are
// shown at the position the scene was solved at.
import { el, runsText, num, shown, pair } from "./svg.js";

const REACH = 0.6;      // drawing sizes around the mechanism within which results are framed (farther: at the edge)
const MARGIN = 0.1;     // drawing sizes of margin around the framed content
const KINDS = ["velocity", "acceleration"];

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
    this.defs();
    const g = (cls) => el("g", { class: cls }, this.content);
    this.g = { ground: g("ground"), traces: g("traces"), bodies: g("bodies"), pins: g("pins"), overlay: g("overlay"),
               vectors: g("vectors"), labels: g("labels"), handles: g("handles") };
    this.anchors = {};
    this.bodyGroups = {};
    this.topGroups = {};        // a body's pins and rollers, above every body's outline
    this.tracked = [];          // 3D: elements placed from model coordinates at every row
    this.paintTraces();
    this.paintBodies();
    this.paintJoints();
    this.paintPoints();
    this.liveVectors();
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

  defs() {
    const d = el("defs", {}, this.content);
    const step = 0.012 * this.size;
    const p = el("pattern", { id: "hatch", patternUnits: "userSpaceOnUse", width: step, height: step,
                              patternTransform: "rotate(45)" }, d);
    el("line", { x1: 0, y1: 0, x2: 0, y2: step, stroke: this.scene.style.ground, "stroke-width": step * 0.22,
                 class: "model-width" }, p);
  }

  /** The box (model coordinates) the figure frames: the mechanism over the whole motion,
   * its arrows, and the marks and circles within reach. */
  frameBox() {
    const s = this.scene, size = this.size;
    let [x0, y0, x1, y1] = s.box;
    const add = (p) => {
      if (!p || p[0] === null || p[1] === null) return;
      x0 = Math.min(x0, p[0]); y0 = Math.min(y0, p[1]); x1 = Math.max(x1, p[0]); y1 = Math.max(y1, p[1]);
    };
    const reach = [s.box[0] - REACH * size, s.box[1] - REACH * size, s.box[2] + REACH * size, s.box[3] + REACH * size];
    const inReach = (p) => p && p[0] >= reach[0] && p[0] <= reach[2] && p[1] >= reach[1] && p[1] <= reach[3];
    if (this.sweep) {
      for (const v of Object.values(this.sweep.points)) for (const p of v.position) add(p);
    }
    const longest = s.style.longest * size;
    for (const v of s.vectors) {
      add([v.origin[0] - longest, v.origin[1] - longest]);
      add([v.origin[0] + longest, v.origin[1] + longest]);
    }
    for (const m of s.marks) if (m.point && inReach(m.point)) add(m.point);
    for (const c of s.curvatures) {
      if (c.circle.every(inReach)) c.circle.forEach(add);
      else if (inReach(c.centre)) add(c.centre);
    }
    const m = MARGIN * size;
    return [x0 - m, y0 - m, x1 + m, y1 + m];
  }

  /** The group of body `name` (the frame's: the ground layer); `top`: its group in the
   * layer above all bodies (pins, rollers), moved with it. */
  bodyGroup(name, top = false) {
    const groups = top ? this.topGroups : this.bodyGroups;
    if (!name || this.scene.bodies[name].frame) return top ? this.g.pins : this.g.ground;
    if (!groups[name]) {
      groups[name] = el("g", { class: top ? "body-pins" : "body", "data-body": name }, top ? this.g.pins : this.g.bodies);
    }
    return groups[name];
  }

  /** Body `name`'s groups: its outline's and its pins'. */
  groupsOf(name) { return [this.bodyGroups[name], this.topGroups[name]].filter(Boolean); }

  paintBodies() {
    const s = this.scene;
    if (s.sphere) {
      const [c, r] = s.sphere;
      el("circle", { cx: c[0], cy: -c[1], r, fill: "none", stroke: "#bdbdbd", "stroke-dasharray": "4 3" }, this.g.ground);
    }
    for (const [name, b] of Object.entries(s.bodies)) {
      if (b.frame) {
        for (const shape of b.shapes) this.groundShape(shape);
        for (const line of b.skeleton || []) this.bar(this.g.ground, line, s.style.ground, 3);
        continue;
      }
      const g = this.bodyGroup(name);
      this.anchors[name] = this.anchor(name, b);
      if (this.P && this.sweep && b.points_xyz) {
        this.paintBody3(name, b, g);
        continue;
      }
      if (b.skeleton && b.skeleton.length) {       // a carrier's arms, a chassis, a 3D body's bars
        for (const shape of b.shapes) this.movingShape(g, b, shape);
        for (const line of b.skeleton) this.bar(g, line, b.colour, 8);
        continue;
      }
      const pts = distinct(Object.values(b.points), 1e-9 * this.size);
      const wheels = b.shapes.filter((x) => x.kind === "circle" && !x.ring);
      for (const shape of b.shapes) this.movingShape(g, b, shape);
      if (wheels.length && pts.every((p) => wheels.some((w) => dist(p, w.center) <= w.radius * (1 + 1e-6)))) {
        for (const p of pts) {
          const w = wheels.reduce((a, c) => (dist(p, c.center) < dist(p, a.center) ? c : a));
          el("line", { ...seg(w.center, p), stroke: b.colour, "stroke-width": 2, "stroke-linecap": "round" }, g);
        }
        continue;
      }
      const hull = pts.length >= 3 ? convexHull(pts) : pts;
      if (hull.length >= 3 && area(hull) > 1e-5 * this.size ** 2) {
        el("polygon", { points: poly(hull), fill: b.colour, "fill-opacity": 0.38, stroke: b.colour,
                        "stroke-width": 2.5, "stroke-linejoin": "round", class: "shape" }, g);
      } else if (pts.length >= 2) {
        const [p, q] = extremes(pts);
        el("line", { ...seg(p, q), stroke: b.colour, "stroke-opacity": 0.9, "stroke-width": 8,
                     "stroke-linecap": "round", class: "shape" }, g);
      }
    }
  }

  /** A 3D body, its parts kept with their model coordinates to be moved (`move3`). */
  paintBody3(name, b, g) {
    for (const [i, shape] of b.shapes.entries()) {
      const node = this.movingShape(g, b, shape);
      if (node && shape.vertices_xyz) this.track(node, name, "points", shape.vertices_xyz);
    }
    if (b.skeleton && b.skeleton.length) {
      b.skeleton.forEach((line, i) => this.track(this.bar(g, line, b.colour, 8), name, "points", b.skeleton_xyz[i]));
      return;
    }
    const pts = distinct(Object.values(b.points_xyz), 1e-9 * this.size);
    if (pts.length < 2) return;
    const [p, q] = extremes(pts);
    const line = el("line", { stroke: b.colour, "stroke-opacity": 0.9, "stroke-width": 8, "stroke-linecap": "round",
                              class: "shape" }, g);
    this.track(line, name, "line", [p, q]);
  }

  /** Keep `node` of `body` to be placed from its model coordinates `xyz` at every row (3D). */
  track(node, body, kind, xyz) {
    if (this.P && this.sweep && body && xyz) this.tracked.push({ node, body, kind, xyz });
    return node;
  }

  bar(g, line, colour, width) {
    return el("polyline", { points: poly(line), fill: "none", stroke: colour, "stroke-opacity": 0.9, "stroke-width": width,
                     "stroke-linecap": "round", "stroke-linejoin": "round", class: "shape" }, g);
  }

  /** The material point a body's placement follows: its first swept point. */
  anchor(name, b) {
    if (!this.sweep) return null;
    for (const p of Object.keys(b.points)) if (this.sweep.points[`${p}@${name}`]) return p;
    return null;
  }

  groundShape(sh) {
    const s = this.scene, band = s.style.hatch_band * this.size, g = this.g.ground;
    if (sh.kind === "line") {
      const far = 10 * this.size;
      const p = add(sh.through, mul(sh.direction, -far)), q = add(sh.through, mul(sh.direction, far));
      let n = [-sh.direction[1], sh.direction[0]];
      const towards = sh.hatch_towards || sub(sh.through, this.movingCentroid());
      if (dot(n, towards) < 0) n = mul(n, -1);
      this.hatchedEdge(g, p, q, n, band);
    } else if (sh.kind === "circle") {
      el("circle", { cx: sh.center[0], cy: -sh.center[1], r: sh.radius, fill: "none", stroke: s.style.ground,
                     "stroke-width": 1.8 }, g);
      const width = Math.min(band, 0.5 * sh.radius);
      const r = sh.material_inside ? sh.radius - width / 2 : sh.radius + width / 2;
      el("circle", { cx: sh.center[0], cy: -sh.center[1], r, fill: "none", stroke: "url(#hatch)",
                     "stroke-width": width, class: "model-width" }, g);
    } else if (sh.vertices) {
      el("polygon", { points: poly(sh.vertices), fill: "#f0f0f0", stroke: "#9e9e9e", "stroke-width": 1 }, g);
    }
  }

  hatchedEdge(g, p, q, side, band) {
    el("polygon", { points: poly([p, q, add(q, mul(side, band)), add(p, mul(side, band))]),
                    fill: "url(#hatch)", stroke: "none" }, g);
    el("line", { ...seg(p, q), stroke: this.scene.style.ground, "stroke-width": 1.8 }, g);
  }

  movingShape(g, b, sh) {
    if (sh.kind === "circle") {
      const gear = sh.role === "gear";
      const c = { cx: sh.center[0], cy: -sh.center[1] };
      if (sh.ring) {
        const band = Math.min(1.5 * this.scene.style.hatch_band * this.size, 0.3 * sh.radius);
        el("circle", { ...c, r: sh.radius + band / 2, fill: "none", stroke: b.colour, "stroke-opacity": 0.45,
                       "stroke-width": band, class: "model-width" }, g);
      } else {
        el("circle", { ...c, r: sh.radius, fill: b.colour, "fill-opacity": gear ? 0.18 : 0.25, stroke: "none" }, g);
        for (const d of [[1, 0], [0, 1]]) {
          el("line", { ...seg(add(sh.center, mul(d, -0.8 * sh.radius)), add(sh.center, mul(d, 0.8 * sh.radius))),
                       stroke: b.colour, "stroke-width": 1, "stroke-opacity": 0.8 }, g);
        }
      }
      el("circle", { ...c, r: sh.radius, fill: "none", stroke: b.colour, "stroke-width": gear ? 1.6 : 2.2,
                     "stroke-dasharray": gear ? "10 3 2 3" : null }, g);
    } else if (sh.kind === "line") {
      const far = 10 * this.size;
      el("line", { ...seg(add(sh.through, mul(sh.direction, -far)), add(sh.through, mul(sh.direction, far))),
                   stroke: b.colour, "stroke-width": 2.2 }, g);
    } else if (sh.vertices) {
      return el("polygon", { points: poly(sh.vertices), fill: b.colour, "fill-opacity": 0.3, stroke: b.colour,
                             "stroke-width": 1.5 }, g);
    }
    return null;
  }

  movingCentroid() {
    const pts = [];
    for (const b of Object.values(this.scene.bodies)) if (!b.frame) pts.push(...Object.values(b.points));
    if (!pts.length) return [0, 0];
    return mul(pts.reduce(add, [0, 0]), 1 / pts.length);
  }

  frame() { return Object.keys(this.scene.bodies).find((n) => this.scene.bodies[n].frame); }

  /** Every joint's symbol as its kind draws it (the scene's `symbols`: polygons, lines and
   * dots, `kinematika.joints.symbols`), each in the body it moves with, lowest first; the
   * marks of a still figure only (a contact point) are left out while a motion is shown. */
  paintJoints() {
    const marks = [...(this.scene.symbols || [])].sort((m, n) => m.zorder - n.zorder);
    for (const m of marks) {
      if (m.still && this.sweep) continue;
      const node = this.mark(m, this.bodyGroup(m.body, m.zorder >= 5));
      const joint = m.id.startsWith("joint:") && this.scene.joints.find((j) => `joint:${j.id}` === m.id);
      if (m.kind === "dot" && joint) this.track(node, m.body, "circle", joint.at_xyz);
    }
  }

  /** A colour role of a mark (ink, ground, white, none, body:NAME) as a colour. */
  role(name) {
    const st = this.scene.style;
    if (name.startsWith("body:")) return this.scene.bodies[name.slice(5)].colour;
    return { ink: st.ink, ground: st.ground, white: "white", none: "none" }[name] || name;
  }

  /** One mark: a dot (its size in points), a line or a polygon (hatched: the frame's material). */
  mark(m, g) {
    const stroke = this.role(m.colour), fill = this.role(m.fill), id = m.id.startsWith("joint:") ? m.id.slice(6) : null;
    if (m.kind === "dot") {
      const [p] = m.points;
      return el("circle", { cx: p[0], cy: -p[1], r: (m.size / 2 + m.width / 2) * 1.1 * this.px, fill,
                            stroke: m.width ? stroke : "none", "stroke-width": m.width, "data-joint": id,
                            class: m.size >= 5 ? "pin" : null }, g);
    }
    if (m.kind === "line") {
      return el("polyline", { points: poly(m.points), fill: "none", stroke, "stroke-width": m.width,
                              "stroke-dasharray": m.dash ? "10 3 2 3" : null, "data-joint": id }, g);
    }
    return el("polygon", { points: poly(m.points), fill: m.hatch ? "url(#hatch)" : fill,
                           stroke: m.hatch || !m.width ? "none" : stroke, "stroke-width": m.width, "data-joint": id }, g);
  }

  /** A dot at every point (draggable at the position the scene was solved at) and its name. */
  paintPoints() {
    this.pointLabels = [];
    const named = new Set();
    for (const [name, b] of Object.entries(this.scene.bodies)) {
      for (const [p, xy] of Object.entries(b.points)) {
        if (named.has(p)) continue;
        named.add(p);
        const g = this.bodyGroup(b.frame ? null : name);
        const dot = el("circle", { cx: xy[0], cy: -xy[1], r: 3.2 * this.px, fill: this.scene.style.ink, "data-point": p }, g);
        if (!b.frame) this.track(dot, name, "circle", b.points_xyz && b.points_xyz[p]);
        const label = el("text", { "font-size": 12 * this.px, "font-weight": "bold", fill: this.scene.style.point_label,
                                   class: "point-label" }, this.g.labels);
        label.textContent = shown(p);
        let handle = null;                      // a 3D point is moved in the text (edit takes x, y)
        if (this.scene.dimension === 2) {
          handle = el("circle", { r: 9 * this.px, class: "draggable", "data-handle": p }, this.g.handles);
          el("title", {}, handle).textContent = this.t("handle-tip", { point: shown(p) });
        }
        this.pointLabels.push({ label, handle, name: p, body: name, frame: b.frame, xy });
      }
    }
  }

  /** The full path of every moving point over the sweep (coupler curves), faint. */
  paintTraces() {
    if (!this.sweep) return;
    const seen = [];
    const asked = new Set(this.scene.vectors.map((v) => v.ref));
    const keys = Object.keys(this.sweep.points).sort((a, b) => asked.has(b) - asked.has(a));
    for (const key of keys) {
      const v = this.sweep.points[key];
      const path = v.position.filter((p) => p !== null);
      if (path.length < 2) continue;
      const spread = Math.max(...path.map((p) => dist(p, path[0])));
      if (spread <= 1e-6 * this.size) continue;
      if (seen.some((q) => q.length === path.length && q.every((p, i) => dist(p, path[i]) < 1e-9 * this.size))) continue;
      seen.push(path);
      const strong = asked.has(key);      // the asked points' paths (coupler curves) stand out
      el("polyline", { points: poly(path), fill: "none", stroke: "#6d4c41", "stroke-opacity": strong ? 0.75 : 0.4,
                       "stroke-width": strong ? 1.6 : 1.1, "stroke-dasharray": strong ? null : "4 3",
                       "data-trace": key }, this.g.traces);
    }
  }

  /** The arrows that follow the sweep: the scene's absolute vectors of swept points. */
  liveVectors() {
    this.arrows = [];
    this.largest = {};
    for (const v of this.scene.vectors) {
      const swept = this.sweep && !v.relative_to && this.sweep.points[v.ref];
      this.largest[v.kind] = Math.max(this.largest[v.kind] || 0, v.magnitude);
      if (swept) {
        for (const x of swept.size[v.kind]) if (x) this.largest[v.kind] = Math.max(this.largest[v.kind], x);
      }
    }
    for (const v of this.scene.vectors) this.arrows.push(this.arrowElements(v, this.g.vectors));
  }

  arrowElements(v, parent) {
    const colour = this.scene.style[v.kind];
    const g = el("g", { class: `arrow kind-${v.kind}`, "data-vector": v.key }, parent);
    const line = el("line", { stroke: colour, "stroke-width": 2.2 }, g);
    const head = el("polygon", { fill: colour }, g);
    const label = runsText(g, [...v.label, { t: " = " }], { "font-size": 12 * this.px, fill: colour });
    const value = el("tspan", {}, label);
    return { v, g, line, head, label, value, swept: this.sweep && !v.relative_to && this.sweep.points[v.ref] };
  }

  placeArrow(a, origin, value, magnitude) {
    const st = this.scene.style, largest = this.largest[a.v.kind] || 0;
    if (!origin || !value || largest <= 0 || magnitude <= 1e-9 * largest) {
      a.line.setAttribute("visibility", "hidden");
      a.head.setAttribute("visibility", "hidden");
      if (origin) placeText(a.label, origin, [6 * this.px, 6 * this.px]);
      a.value.textContent = "0";
      return;
    }
    let factor = (st.longest * this.size) / largest;
    let enlarged = false;
    if (magnitude * factor < st.shortest * this.size) { factor = (st.shortest * this.size) / magnitude; enlarged = true; }
    const tip = add(origin, mul(value, factor));
    const d = unit(value), n = [-d[1], d[0]];
    const hl = 11 * this.px, hw = 4.5 * this.px;
    const back = add(tip, mul(d, -hl));
    a.line.setAttribute("visibility", "visible");
    a.head.setAttribute("visibility", "visible");
    setSeg(a.line, origin, back);
    a.head.setAttribute("points", poly([tip, add(back, mul(n, hw)), add(back, mul(n, -hw))]));
    placeText(a.label, tip, mul(d, 6 * this.px), d);
    a.value.textContent = num(magnitude) + (enlarged ? ` (${this.t("enlarged")})` : "");
  }

  paintOverlay() {
    const s = this.overlayScene, st = s.style;
    const g = this.g.overlay;
    g.replaceChildren();
    this.overlayParts = { centres: el("g", { class: "centres" }, g), curvature: el("g", { class: "curvature" }, g),
                          vectors: el("g", { class: "relative" }, this.g.overlay) };
    const far = 10 * this.size;
    for (const k of [...s.kennedy, ...(s.normals || [])]) {     // Kennedy lines; wheel and slot normals
      const d = unit(k.direction), normal = k.key.startsWith("normal:");
      el("line", { ...seg(add(k.through, mul(d, -far)), add(k.through, mul(d, far))), stroke: st.centre,
                   "stroke-width": normal ? 1.1 : 0.9, "stroke-dasharray": normal ? "8 3 1.5 3" : "6 4",
                   "stroke-opacity": 0.8, [normal ? "data-normal" : "data-kennedy"]: k.key },
         this.overlayParts.centres);
    }
    const [x0, y0, x1, y1] = this.view, inset = 14 * this.px;
    for (const m of s.marks) {
      if (!m.point || m.rest) continue;
      const colour = m.kind === "pole" ? st.acceleration : m.kind === "contact" ? st.ink : st.centre;
      const inside = m.point[0] >= x0 && m.point[0] <= x1 && m.point[1] >= y0 && m.point[1] <= y1;
      const p = inside ? m.point : [clamp(m.point[0], x0 + inset, x1 - inset), clamp(m.point[1], y0 + inset, y1 - inset)];
      const mg = el("g", { "data-mark": m.key }, this.overlayParts.centres);
      if (inside) {
        el("circle", { cx: p[0], cy: -p[1], r: 5.5 * this.px, fill: "white", stroke: colour, "stroke-width": 2.2 }, mg);
        el("circle", { cx: p[0], cy: -p[1], r: 1.4 * this.px, fill: colour }, mg);
      } else {
        const d = unit(sub(m.point, p));
        const n = [-d[1], d[0]], r = 7 * this.px;
        el("polygon", { points: poly([add(p, mul(d, r)), add(p, add(mul(d, -r / 2), mul(n, r * 0.8))),
                                      add(p, add(mul(d, -r / 2), mul(n, -r * 0.8)))]), fill: colour }, mg);
      }
      const scale = Math.max(this.size, Math.hypot(...m.point));       // round-off as 0
      const runs = inside ? m.label : [...m.label, { t: ` ${this.t("far-off", { place: pair([num(m.point[0], scale), num(m.point[1], scale)]) })}` }];
      const t = runsText(mg, runs, { "font-size": 12 * this.px, fill: colour });
      const inward = unit(sub(this.centre(), p));
      if (inside) placeText(t, p, [7 * this.px, -7 * this.px], [1, -1]);
      else placeText(t, p, mul(inward, 12 * this.px), inward);
    }
    for (const c of s.curvatures) {
      const cg = el("g", { "data-curvature": c.ref }, this.overlayParts.curvature);
      el("polyline", { points: poly(c.circle), fill: "none", stroke: st.curvature, "stroke-width": 1.3 }, cg);
      el("line", { ...seg(c.point, c.centre), stroke: st.curvature, "stroke-width": 0.8, "stroke-dasharray": "3 3" }, cg);
      el("circle", { cx: c.centre[0], cy: -c.centre[1], r: 2.5 * this.px, fill: st.curvature }, cg);
      placeText(runsText(cg, c.label, { "font-size": 12 * this.px, fill: st.curvature }), c.centre, [6 * this.px, -12 * this.px]);
    }
    this.overlayArrows = [];
    for (const v of s.vectors) {
      if (v.relative_to || !this.sweep || !this.sweep.points[v.ref]) {
        const a = this.arrowElements(v, this.overlayParts.vectors);
        this.placeArrow(a, v.origin, v.value, v.magnitude);
        this.overlayArrows.push(a);
      }
    }
    this.applyLayers();
  }

  centre() { const [x0, y0, x1, y1] = this.view; return [(x0 + x1) / 2, (y0 + y1) / 2]; }

  /** Show or hide the layers (as switched, and the scene-only results away from their row). */
  applyLayers() {
    const showOverlay = this.row === this.overlayRow;
    visible(this.g.traces, this.layers.traces);
    if (this.overlayParts) {
      visible(this.overlayParts.centres, this.layers.centres && showOverlay);
      visible(this.overlayParts.curvature, this.layers.curvature && showOverlay);
      for (const a of this.overlayArrows) visible(a.g, this.layers[a.v.kind] && showOverlay);
    }
    for (const a of this.arrows) visible(a.g, this.layers[a.v.kind] && !!a.swept);
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
    if (this.sweep) items.push(`<li><i style="background:#6d4c41;opacity:.5"></i>${t("legend-path")}</li>`);
    if (this.scene.dimension === 2) items.push(`<li class="hint">${t("legend-drag")}</li>`);
    this.legend.innerHTML = items.join("");
  }

  // moving ------------------------------------------------------------------------------
  /** The mechanism at sweep row `k`. */
  show(k) {
    this.row = k;
    if (!this.scene) return;
    const sw = this.sweep;
    if (sw) {
      const ok = sw.coordinate[k] !== undefined && Object.values(sw.bodies)[0]?.angle[k] !== null;
      this.svg.classList.toggle("unassembled", !ok);
      if (this.P) this.move3(k);
      else for (const name of Object.keys(this.bodyGroups)) {
        const anchor = this.anchors[name];
        if (!anchor) continue;
        const p0 = this.scene.bodies[name].points[anchor];
        const pk = sw.points[`${anchor}@${name}`].position[k];
        const a0 = sw.bodies[name].angle[this.sceneRow], ak = sw.bodies[name].angle[k];
        const here = pk && ak !== null && a0 !== null;
        for (const x of this.groupsOf(name)) visible(x, here);
        if (!here) continue;
        const placed = `translate(${pk[0]} ${-pk[1]}) rotate(${-(ak - a0)}) translate(${-p0[0]} ${p0[1]})`;
        for (const x of this.groupsOf(name)) x.setAttribute("transform", placed);
      }
      for (const a of this.arrows) {
        if (!a.swept) continue;
        this.placeArrow(a, a.swept.position[k], a.swept[a.v.kind][k], a.swept.size[a.v.kind][k] || 0);
      }
    } else {
      for (const a of this.arrows) this.placeArrow(a, a.v.origin, a.v.value, a.v.magnitude);
    }
    for (const pl of this.pointLabels) {
      let p = pl.xy;
      if (sw && !pl.frame) {
        const swept = sw.points[`${pl.name}@${pl.body}`];
        p = swept ? swept.position[k] : null;
      }
      if (this.drag && this.drag.name === pl.name) p = this.drag.at;      // under the hand
      if (p) {
        placeText(pl.label, p, [5 * this.px, 5 * this.px]);
        pl.handle?.setAttribute("cx", p[0]);
        pl.handle?.setAttribute("cy", -p[1]);
      }
      pl.label.setAttribute("visibility", p ? "visible" : "hidden");
      pl.handle?.setAttribute("visibility", p ? "visible" : "hidden");
    }
    this.applyLayers();
    this.unclutter();
  }

  /** Labels that would overlap are moved apart: the points' names stay; each arrow's,
   * centre's and curvature's label after them is shifted up or down (by its height, at most
   * twice) to the first place where it overlaps no label already placed. A label that would
   * stick out of the figure (an arrow's tip near its edge, on a narrow screen) is moved back
   * inside it. */
  unclutter() {
    if (!this.g) return;
    const texts = [...this.pointLabels.map((pl) => pl.label),
      ...this.svg.querySelectorAll(".content .vectors text, .content .overlay text")];
    const placed = [];
    const [x0, y0, x1, y1] = this.view, pad = 2 * this.px;
    const inside = (lo, size, from, to) => (size > to - from ? 0 : Math.max(from - lo, 0) + Math.min(to - (lo + size), 0));
    for (const t of texts) {
      t.removeAttribute("transform");
      if (t.getAttribute("visibility") === "hidden" || !t.getClientRects().length) continue;
      const b = t.getBBox();
      if (!b.width) continue;
      const fixed = this.pointLabels.some((pl) => pl.label === t);
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

  /** The 3D bodies at sweep row `k`: each tracked part turned in space by the body's
   * rotation since the scene's row (R_k R_s^T, from the rotation vectors), about its anchor
   * point carried to its swept place, and projected on the page. */
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
      if (t.kind === "circle") {
        const p = apply(m.A, t.xyz);
        t.node.setAttribute("cx", p[0] + m.c[0]);
        t.node.setAttribute("cy", -(p[1] + m.c[1]));
        continue;
      }
      const pts = t.xyz.map((x) => { const p = apply(m.A, x); return [p[0] + m.c[0], p[1] + m.c[1]]; });
      if (t.kind === "line") setSeg(t.node, pts[0], pts[1]);
      else t.node.setAttribute("points", poly(pts));
    }
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
    const pl = (this.pointLabels || []).find((x) => x.name === name);
    if (!this.scene || !pl || !pl.handle || pl.handle.getAttribute("visibility") === "hidden") return null;
    return [Number(pl.handle.getAttribute("cx")), -Number(pl.handle.getAttribute("cy"))];
  }

  /** A point can be dragged in a planar model (a 3D point is moved in its text). */
  canDrag(name) { return !this.scene || this.scene.dimension === 2; }

  /** The dragged point's handle, dot and label at the pointer (whatever was repainted). */
  placeDragged() {
    const d = this.drag;
    if (!d) return;
    const pl = (this.pointLabels || []).find((x) => x.name === d.name);
    if (pl) {
      pl.handle?.setAttribute("cx", d.at[0]);
      pl.handle?.setAttribute("cy", -d.at[1]);
      placeText(pl.label, d.at, [5 * this.px, 5 * this.px]);
    }
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

// geometry ------------------------------------------------------------------------------
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
const dot = (p, q) => p[0] * q[0] + p[1] * q[1];
const dist = (p, q) => Math.hypot(...p.map((x, i) => x - q[i]));      // in the plane or in space
const unit = (p) => { const n = Math.hypot(p[0], p[1]) || 1; return [p[0] / n, p[1] / n]; };
const clamp = (x, lo, hi) => Math.min(Math.max(x, lo), hi);
const poly = (pts) => pts.map((p) => `${p[0]},${-p[1]}`).join(" ");
const seg = (p, q) => ({ x1: p[0], y1: -p[1], x2: q[0], y2: -q[1] });

/** Display a group or not (`display`, which its children cannot override). */
function visible(node, on) {
  node.style.display = on ? "" : "none";
}

function setSeg(line, p, q) {
  line.setAttribute("x1", p[0]); line.setAttribute("y1", -p[1]);
  line.setAttribute("x2", q[0]); line.setAttribute("y2", -q[1]);
}

/** Put a label at `p` + `offset` (model units), anchored away from `towards` when given. */
function placeText(text, p, offset, towards = null) {
  text.setAttribute("x", p[0] + offset[0]);
  text.setAttribute("y", -(p[1] + offset[1]));
  const c = towards ? towards[0] : 1, s = towards ? towards[1] : 1;
  text.setAttribute("text-anchor", c > 0.3 ? "start" : c < -0.3 ? "end" : "middle");
  text.setAttribute("dominant-baseline", s > 0.3 ? "text-after-edge" : s < -0.3 ? "hanging" : "middle");
}

function distinct(pts, tol) {
  const out = [];
  for (const p of pts) if (out.every((q) => dist(p, q) > tol)) out.push(p);
  return out;
}

function extremes(pts) {
  let best = [pts[0], pts[1]], d = -1;
  for (let i = 0; i < pts.length; i++) for (let j = i + 1; j < pts.length; j++) {
    const e = dist(pts[i], pts[j]);
    if (e > d) { d = e; best = [pts[i], pts[j]]; }
  }
  return best;
}

function convexHull(pts) {
  const p = [...pts].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const cross = (o, a, b) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lower = [], upper = [];
  for (const q of p) { while (lower.length >= 2 && cross(lower.at(-2), lower.at(-1), q) <= 0) lower.pop(); lower.push(q); }
  for (const q of p.reverse()) { while (upper.length >= 2 && cross(upper.at(-2), upper.at(-1), q) <= 0) upper.pop(); upper.push(q); }
  return lower.slice(0, -1).concat(upper.slice(0, -1));
}

function area(h) {
  let s = 0;
  for (let i = 0; i < h.length; i++) { const p = h[i], q = h[(i + 1) % h.length]; s += p[0] * q[1] - q[0] * p[1]; }
  return Math.abs(s) / 2;
}
