// Building a mechanism by hand: the palette (its tools come from the server, /api/palette),
// a grid that snaps to points and round values, picks on the figure, and the properties
// panel where the selected element's dimensions are typed. Every action is an edit of the
// model's text made by the server (/api/build): the text stays the one source.
import { el, niceStep, num, shown } from "./svg.js";

const SNAP_PX = 10;          // a pick this close to a point (CSS pixels) takes the point

export class Builder {
  constructor(figure, palette, panel, hint, t, act) {
    this.figure = figure;
    this.palette = palette;
    this.panel = panel;
    this.hint = hint;
    this.t = t;
    this.act = act;                // (op) => Promise: the page applies a build action
    this.tools = [];
    this.tool = "select";
    this.picks = [];
    this.selected = null;
    this.sketch = { points: {}, bodies: {}, joints: [], drivers: [], ask: [], properties: {} };
    this.showGrid = true;
    this.pointerAt = null;
    this.missing = null;           // what the model being built lacks (main.js: a hint's key)
    figure.onPick = (hit, at, e) => this.pick(hit, at, e);
    figure.onView = () => this.draw();
    figure.svg.addEventListener("pointermove", (e) => {
      if (this.tool === "select" || !this.picks.length) return;
      this.pointerAt = this.snap(figure.toModel(e, false)).at;
      this.draw();
    });
    palette.querySelector("[data-tool=select]").addEventListener("click", () => this.choose("select"));
  }

  /** The palette's tools, and the questions asked of a selected point or body, as the server
   * lists them (the kinds of question the builder offers). */
  setTools(tools, questions = {}) {
    this.tools = tools;
    this.questions = questions;
    for (const tool of tools) {
      const b = document.createElement("button");
      b.type = "button";
      b.className = "tool";
      b.dataset.tool = tool.kind;
      b.dataset.testid = `tool-${tool.kind}`;
      b.setAttribute("aria-pressed", "false");
      b.innerHTML = `<svg viewBox="0 0 24 24"><path d="${tool.icon}"/></svg><span data-i18n="tool-${tool.kind}"></span>`;
      b.dataset.i18nTitle = `tool-${tool.kind}-tip`;
      b.addEventListener("click", () => this.choose(tool.kind));
      this.palette.appendChild(b);
    }
  }

  choose(kind) {
    this.tool = kind;
    this.picks = [];
    this.pointerAt = null;
    for (const b of this.palette.querySelectorAll("[data-tool]")) b.setAttribute("aria-pressed", String(b.dataset.tool === kind));
    this.figure.svg.classList.toggle("placing", kind !== "select");
    this.say();
    this.draw();
  }

  /** What the student is asked to click next. */
  say() {
    const tool = this.tools.find((x) => x.kind === this.tool);
    if (this.spatial) { this.hint.textContent = this.t("hint-3d"); return; }
    if (!tool) {
      this.hint.textContent = this.sketch.problem ? this.t("hint-fix") : this.missing ? this.t(this.missing)
        : this.byHand ? this.t("hint-by-hand")
        : Object.keys(this.sketch.points).length ? this.t("hint-select") : this.t("hint-empty");
      return;
    }
    this.hint.textContent = `${this.t(`tool-${tool.kind}`)}: ${this.t(`pick-${tool.kind}-${this.picks.length + 1}`)}`;
  }

  // picks -------------------------------------------------------------------------------
  /** A click on the figure (`hit`: a point, a body, nothing); true when it is taken here. */
  pick(hit, at, e) {
    if (this.spatial && this.tool !== "select") { this.say(); return true; }
    if (this.tool === "select") {
      if (hit.point) { this.select(`point:${hit.point}`); return false; }   // and it may be dragged
      if (hit.body) { this.select(`body:${hit.body}`); return true; }
      if (hit.empty) { this.select(null); return true; }
      return false;
    }
    if (hit.empty) return true;
    const tool = this.tools.find((x) => x.kind === this.tool);
    const need = tool.picks[this.picks.length];
    const near = this.snap(at);
    if (need === "place") this.picks.push(hit.point || near.point || near.at);
    else if (need === "point" && (hit.point || near.point)) this.picks.push(hit.point || near.point);
    else if (need === "body" && hit.body) this.picks.push({ body: hit.body });
    else { this.hint.textContent = `${this.t(`tool-${tool.kind}`)}: ${this.t(`pick-${need}`)}`; return true; }
    if (this.picks.length === tool.picks.length) {
      const picks = this.picks;
      this.picks = [];
      this.pointerAt = null;
      this.figure.hold();
      this.act({ op: "add", kind: tool.kind, picks });
    }
    this.say();
    this.draw();
    return true;
  }

  /** The point near `at` (within SNAP_PX), else the grid's nearest node. */
  snap(at) {
    const px = this.figure.px || 1;
    let best = null, d = SNAP_PX * px;
    for (const [name, p] of Object.entries(this.sketch.points)) {
      const e = Math.hypot(p[0] - at[0], p[1] - at[1]);
      if (e < d) { d = e; best = name; }
    }
    if (best) return { point: best, at: this.sketch.points[best] };
    const step = this.gridStep();
    const round = (v) => Number((Math.round(v / step) * step).toPrecision(12));
    return { at: [round(at[0]), round(at[1])] };
  }

  /** The grid's spacing: 1, 2 or 5 × 10^k, about 24 CSS pixels. */
  gridStep() {
    return niceStep(24 * (this.figure.px || 0.01));
  }

  // the drawing over the figure ---------------------------------------------------------
  /** A new sketch (/api/sketch) of the model in the editor. */
  update(sketch, solved, dimension = 2) {
    this.sketch = sketch;
    this.solved = solved;
    this.spatial = dimension === 3;          // built by its text: no grid, no picks
    if (this.selected && !this.exists(this.selected)) this.select(null);
    this.draw();
    this.showProperties();
    this.say();
  }

  exists(key) {
    const [kind, name] = key.split(/:(.*)/s);
    if (kind === "point") return name in this.sketch.points || `point:${name}` in this.sketch.properties;
    if (kind === "body") return name in this.sketch.bodies;
    if (kind === "driver") return Number(name) < this.sketch.drivers.length;
    return false;
  }

  /** The box of the sketch's points (for a model that cannot be solved yet). */
  box() {
    const pts = Object.values(this.sketch.points);
    if (!pts.length) return null;
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (const [x, y] of pts) { x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x); y1 = Math.max(y1, y); }
    const m = Math.max(x1 - x0, y1 - y0, 0.05) * 0.4;
    return [x0 - m, y0 - m, x1 + m, y1 + m];
  }

  draw() {
    const root = this.figure.buildRoot, px = this.figure.px || 0.01, view = this.figure.view;
    root.replaceChildren();
    if (!view) return;
    this.figure.svg.appendChild(root);                    // above the figure's content
    if (this.showGrid && !this.spatial) this.drawGrid(root, view, px);
    if (!this.solved) this.drawSketch(root, px);
    this.marked = el("g", { class: "marked" }, root);
    this.follow();
    const placed = this.picks.map((p) => (typeof p === "string" ? this.sketch.points[p] : Array.isArray(p) ? p : null)).filter(Boolean);
    for (const p of placed) el("circle", { cx: p[0], cy: -p[1], r: 5 * px, class: "picked" }, root);
    if (placed.length && this.pointerAt) {
      const p = placed.at(-1), q = this.pointerAt;
      el("line", { x1: p[0], y1: -p[1], x2: q[0], y2: -q[1], class: "rubber" }, root);
      const len = Math.hypot(q[0] - p[0], q[1] - p[1]), ang = (Math.atan2(q[1] - p[1], q[0] - p[0]) * 180) / Math.PI;
      const label = el("text", { x: q[0] + 8 * px, y: -q[1] - 8 * px, "font-size": 12 * px, class: "rubber-label" }, root);
      label.textContent = `${num(len)} m, ${num(ang)}°`;
    }
  }

  /** The selected element marked where the figure shows it now (the slider's row, the
   * mechanism turned by hand), else where it is drawn. */
  follow() {
    const g = this.marked, px = this.figure.px || 0.01;
    if (!g) return;
    g.replaceChildren();
    const sel = this.selected && this.selected.split(/:(.*)/s);
    const at = (n) => (this.solved && this.figure.at(n)) || this.sketch.points[n];
    if (sel && sel[0] === "point" && at(sel[1])) {
      const p = at(sel[1]);
      el("circle", { cx: p[0], cy: -p[1], r: 11 * px, class: "selected" }, g);
    } else if (sel && sel[0] === "body" && this.sketch.bodies[sel[1]]) {
      const pts = this.sketch.bodies[sel[1]].points.map(at).filter(Boolean);
      if (pts.length === 1) el("circle", { cx: pts[0][0], cy: -pts[0][1], r: 14 * px, class: "selected" }, g);
      else el("polyline", { points: pts.map((p) => `${p[0]},${-p[1]}`).join(" "), class: "selected", fill: "none" }, g);
    }
  }

  drawGrid(root, [x0, y0, x1, y1], px) {
    const step = this.gridStep();
    const g = el("g", { class: "grid" }, root);
    const lines = [];
    for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step) lines.push(["v", x]);
    for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step) lines.push(["h", y]);
    if (lines.length > 400) return;
    for (const [k, v] of lines) {
      const axis = Math.abs(v) < step / 1e6;
      const attrs = k === "v" ? { x1: v, x2: v, y1: -y0, y2: -y1 } : { x1: x0, x2: x1, y1: -v, y2: -v };
      el("line", { ...attrs, class: axis ? "axis" : "" }, g);
    }
    const label = el("text", { x: x0 + 6 * px, y: -y0 - 6 * px, "font-size": 11 * px, class: "grid-label" }, g);
    label.textContent = this.t("grid-step", { step: `${num(step)} m` });
  }

  /** A model that cannot be solved yet: its bodies as plain bars, its points as dots, each
   * point a handle (picked, selected, dragged) and each body pickable. */
  drawSketch(root, px) {
    const g = el("g", { class: "sketch" }, root);
    for (const [name, b] of Object.entries(this.sketch.bodies)) {
      const pts = b.points.map((n) => this.sketch.points[n]).filter(Boolean);
      if (b.circle && this.sketch.points[b.circle.center] && b.circle.radius) {
        const c = this.sketch.points[b.circle.center];
        el("circle", { cx: c[0], cy: -c[1], r: b.circle.radius, class: b.frame ? "ground" : "body", "data-build-body": b.frame ? null : name }, g);
      }
      if (b.frame || pts.length < 2) continue;
      el("polyline", { points: pts.map((p) => `${p[0]},${-p[1]}`).join(" "), class: "body", "data-build-body": name }, g);
    }
    const ground = new Set(Object.values(this.sketch.bodies).filter((b) => b.frame).flatMap((b) => b.points));
    for (const [name, p] of Object.entries(this.sketch.points)) {
      el("circle", { cx: p[0], cy: -p[1], r: 4 * px, class: ground.has(name) ? "pivot" : "dot" }, g);
      const t = el("text", { x: p[0] + 6 * px, y: -p[1] - 6 * px, "font-size": 12 * px, class: "name" }, g);
      t.textContent = shown(name);
      el("circle", { cx: p[0], cy: -p[1], r: 9 * px, class: "draggable", "data-handle": name }, g);
    }
  }

  // the properties panel -----------------------------------------------------------------
  select(key) {
    this.selected = key;
    const sheet = this.panel.closest("section");
    sheet?.classList.toggle("open", !!key);          // on a phone: a sheet under the figure (app.css)
    this.draw();
    this.showProperties();
    if (key && sheet && getComputedStyle(sheet).position === "fixed") this.inSight(sheet);
  }

  /** On a phone, the figure above the properties' sheet: the page scrolled to it once the
   * pointer is up (a drag that began with the selection is not moved under the finger). */
  inSight(sheet) {
    const scroll = () => {
      const box = this.figure.svg.getBoundingClientRect(), top = sheet.getBoundingClientRect().top;
      if (box.top < 0 || box.bottom > top) window.scrollBy(0, box.top - Math.max(0, top - box.height) / 2);
    };
    if (this.figure.svg.matches(":active")) window.addEventListener("pointerup", () => requestAnimationFrame(scroll), { once: true });
    else requestAnimationFrame(scroll);
  }

  showProperties() {
    const body = this.panel;
    body.replaceChildren();
    const key = this.selected;
    if (!key) {
      const p = document.createElement("p");
      p.className = "muted";
      p.textContent = this.t("nothing-selected");
      body.appendChild(p);
      return;
    }
    const [kind, name] = key.split(/:(.*)/s);
    const title = document.createElement("h3");
    title.textContent = this.t(`element-${kind}`, { name: shown(name) });
    title.dataset.testid = "selected";
    body.appendChild(title);
    if (kind === "point" || kind === "body") body.appendChild(this.naming(kind, name));
    const rows = this.sketch.properties[key] || [];
    const form = document.createElement("div");
    form.className = "props";
    for (const row of rows) form.appendChild(this.field(row));
    if (!rows.length) {
      const p = document.createElement("p");
      p.className = "muted";
      p.textContent = this.t("no-dimensions");
      form.appendChild(p);
    }
    body.appendChild(form);
    if (kind === "body" && !this.sketch.bodies[name]?.frame) body.appendChild(this.inputSection(name));
    for (const j of this.sketch.joints) {                 // the joints here can be the input too
      const here = kind === "point" ? j.at === name : kind === "body" && !j.at && j.bodies.includes(name);
      if (here && j.bodies.length === 2 && j.rate_unit) body.appendChild(this.jointInput(j));
    }
    body.appendChild(this.askSection(kind, name));
    const del = button(this.t("delete"), "delete", () => { this.select(null); this.act({ op: "delete", element: key }); });
    del.classList.add("danger");
    body.appendChild(del);
  }

  field(row) {
    const about = row.of ? segment(row.of) : row.about ? shown(row.about) : "";
    if (row.kind === "note") {                   // said here, typed elsewhere (a pin's guide)
      const p = document.createElement("p");
      p.className = "muted";
      p.dataset.testid = row.label;
      p.textContent = this.t(row.label, { about });
      return p;
    }
    const label = document.createElement("label");
    label.className = "prop";
    const words = document.createElement("span");
    words.textContent = this.t(row.label, { about, name: row.parameter ? shown(row.parameter) : "" });
    if (row.parameter) words.textContent += ` (${shown(row.parameter)})`;
    const input = document.createElement("input");
    input.type = "text";
    input.inputMode = "decimal";
    input.dataset.testid = row.label;
    input.value = row.value === null || row.value === undefined ? (row.text || "") : plainNumber(row.value);
    const unit = document.createElement("span");
    unit.className = "unit";
    unit.textContent = { length: "m", angle: "°", direction: "°", rate: "rad/s", accel: "rad/s²" }[row.kind] || "";
    const commit = () => {
      const value = parseValue(input.value, row.kind);
      if (value === null || input.value === (row.value === null ? row.text : plainNumber(row.value))) return;
      this.act({ op: "set", path: row.path, value, also: row.also,
                 unit: row.kind === "angle" ? "deg" : row.kind === "direction" ? "direction" : null });
    };
    input.addEventListener("change", commit);
    input.addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); input.blur(); } });
    label.append(words, input, unit);
    return label;
  }

  /** The element's name (renamed everywhere the model names it) and its names per language
   * (the model's `names:`: how the explanations call a body, what a point is). */
  naming(kind, name) {
    const box = document.createElement("div");
    box.className = "naming";
    const { label, input } = this.numberField(this.t("prop-name"), "rename", name, "");
    input.inputMode = "text";
    input.spellcheck = false;
    input.addEventListener("change", () => {
      const to = input.value.trim();
      if (to && to !== name) this.act({ op: "rename", element: `${kind}:${name}`, to });
    });
    input.addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); input.blur(); } });
    box.appendChild(label);
    const more = document.createElement("details");
    more.dataset.testid = "names-per-language";
    const summary = document.createElement("summary");
    summary.textContent = this.t(kind === "body" ? "names-body" : "names-point");
    more.appendChild(summary);
    const section = kind === "body" ? "bodies" : "points";
    for (const o of document.querySelectorAll("#ui-language option")) {
      const now = ((this.sketch.names || {})[o.value] || {})[section] || {};
      const f = this.numberField(o.textContent, `name-${o.value}`, now[name] ?? "", "");
      f.input.inputMode = "text";
      f.input.addEventListener("change", () => this.act({ op: "name", element: `${kind}:${name}`, lang: o.value, text: f.input.value }));
      f.input.addEventListener("keydown", (e) => { if (e.key === "Enter") { e.preventDefault(); f.input.blur(); } });
      more.appendChild(f.label);
    }
    more.open = this.namesOpen || false;
    more.addEventListener("toggle", () => { this.namesOpen = more.open; });
    box.appendChild(more);
    return box;
  }

  /** Make a moving body the input: its ω and α. */
  inputSection(body) {
    const box = document.createElement("div");
    box.className = "input-box";
    const h = document.createElement("h4");
    h.textContent = this.t("input-title");
    box.appendChild(h);
    const driver = this.sketch.drivers.find((d) => d.omega === body && !d.relative_to);
    const omega = this.numberField(this.t("input-omega"), "input-omega", driver ? driver.value : "", "rad/s");
    const alpha = this.numberField(this.t("input-alpha"), "input-alpha", driver ? (driver.alpha ?? 0) : 0, "rad/s²");
    box.append(omega.label, alpha.label);
    box.appendChild(button(this.t(driver ? "input-update" : "input-set"), "set-input", () => {
      const w = parseValue(omega.input.value, "rate"), a = parseValue(alpha.input.value || "0", "accel");
      if (w === null || a === null) return;
      this.act({ op: "drive", body, value: w, alpha: a });
    }));
    return box;
  }

  /** Make a joint the input: its rate (the second body relative to the first) and its
   * acceleration. */
  jointInput(j) {
    const box = document.createElement("div");
    box.className = "input-box";
    const h = document.createElement("h4");
    h.textContent = this.t("input-joint", { joint: shown(j.id), bodies: j.bodies.map((b) => shown(b)).join("–") });
    box.appendChild(h);
    const driver = this.sketch.drivers.find((d) => d.joint === j.id);
    const accelUnit = j.rate_unit === "m/s" ? "m/s²" : "rad/s²";
    const rate = this.numberField(this.t("input-rate"), `input-rate-${j.id}`, driver ? driver.rate : "", j.rate_unit);
    const accel = this.numberField(this.t("input-accel"), `input-accel-${j.id}`, driver ? (driver.accel ?? 0) : 0, accelUnit);
    box.append(rate.label, accel.label);
    box.appendChild(button(this.t(driver ? "input-update" : "input-set"), `set-input-${j.id}`, () => {
      const r = parseValue(rate.input.value, "rate"), a = parseValue(accel.input.value || "0", "accel");
      if (r === null || a === null) return;
      this.act({ op: "drive", joint: j.id, value: r, alpha: a });
    }));
    return box;
  }

  numberField(words, testid, value, unit) {
    const label = document.createElement("label");
    label.className = "prop";
    const span = document.createElement("span");
    span.textContent = words;
    const input = document.createElement("input");
    input.type = "text";
    input.inputMode = "decimal";
    input.dataset.testid = testid;
    input.value = typeof value === "number" ? plainNumber(value) : String(value ?? "");
    const u = document.createElement("span");
    u.className = "unit";
    u.textContent = unit;
    label.append(span, input, u);
    return { label, input };
  }

  /** Ask about the selected point or body. */
  askSection(kind, name) {
    const box = document.createElement("div");
    box.className = "ask-box";
    const h = document.createElement("h4");
    h.textContent = this.t("ask-title");
    box.appendChild(h);
    const questions = kind === "body" && this.sketch.bodies[name]?.frame ? [] : this.questions?.[kind] ?? [];
    for (const q of questions) {
      const asked = this.sketch.ask.some((a) => a[q] === name);
      const b = button(this.t(`q-${q}`), `ask-${q}`, () => this.act({ op: "ask", question: q, target: name }));
      b.disabled = asked;
      box.appendChild(b);
    }
    return box;
  }
}

/** Two points as a segment's name: O2A for short names (as a textbook writes it), else O2–A. */
export function segment([a, b]) {
  return a.length <= 3 && b.length <= 3 ? `${shown(a)}${shown(b)}` : `${shown(a)}–${shown(b)}`;
}

function button(text, testid, onClick) {
  const b = document.createElement("button");
  b.type = "button";
  b.textContent = text;
  b.dataset.testid = testid;
  b.addEventListener("click", onClick);
  return b;
}

/** A number as typed in a field: no exponent for ordinary sizes, a point as decimal mark. */
function plainNumber(x) {
  return String(Number(x.toPrecision(10)));
}

/** What was typed: a number (in metres, degrees, rad/s; "50 mm", "0,05", "1.2 rad" are
 * converted), else an expression over the parameters (sent as text), else null. */
export function parseValue(text, kind) {
  const s = String(text).trim().replace(/−/g, "-");
  if (!s) return null;
  const m = /^([-+]?(?:\d+[.,]?\d*|[.,]\d+)(?:e[-+]?\d+)?)\s*(mm|cm|m|°|deg|rad|rad\/s|rad\/s²|rad\/s2)?$/i.exec(s);
  if (!m) return s;
  let x = Number(m[1].replace(",", "."));
  const unit = (m[2] || "").toLowerCase();
  if (unit === "mm") x /= 1000;
  else if (unit === "cm") x /= 100;
  else if (unit === "rad" && (kind === "angle" || kind === "direction")) x = (x * 180) / Math.PI;
  return Number.isFinite(x) ? x : null;
}
