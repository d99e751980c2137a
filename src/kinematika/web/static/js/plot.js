// Chosen quantities against the input coordinate, from the sweep: one small chart each,
// a cursor at the slider, dead points (where the sweep stops assembling) and limit
// positions (where a body's ω changes sign: its angle is at an extreme) marked. A motion
// through the input's limit positions runs its coordinate back there: its curves go back
// over the axis (a rocker's cycle is a loop), and those positions are dotted lines.
import { el, niceStep, num, shown } from "./svg.js";
import { inputAxis, textbookAngles } from "./angles.js";

const PAD = { left: 62, right: 74, top: 8, bottom: 40 };
const COLOURS = ["#1f5fa8", "#c62828", "#2e7d32", "#7b1fa2", "#ef6c00", "#00838f"];

export class Plot {
  constructor(svg, pick, t = (id) => id) {
    this.svg = svg;
    this.t = t;
    this.pick = pick;
    this.series = [];
    this.chosen = new Set();
    new ResizeObserver(() => this.sweep && this.draw()).observe(svg);
  }

  /** The quantities of a sweep (JSON), and which to show first; with the scene, each body's
   * angle θ and the input as the command line's plot gives them (angles.js). */
  set(sweep, unit, frame, scene = null) {
    this.sweep = sweep;
    this.row = 0;                  // the slider's row is set again after (a new sweep may be shorter)
    this.unit = unit;
    this.pick.replaceChildren();
    if (!sweep) { this.svg.replaceChildren(); return; }
    const theta = textbookAngles(scene, sweep);
    const axis = scene ? inputAxis(scene, sweep, theta) : { x: sweep.coordinate, driver: null };
    this.xs = axis.x;
    this.xlabel = axis.driver ? this.t("plot-input-angle", { body: shown(axis.driver) })
      : this.t("plot-input", { joint: shown((scene && scene.input && scene.input.joint) || ""), unit: unit === "deg" ? "°" : "m" });
    const choices = [];
    const moving = Object.keys(sweep.bodies).filter((b) => b !== frame);
    const size = (xs) => xs.map((x) => (Array.isArray(x) ? Math.hypot(...x) : x));   // 3D: magnitudes
    const planar = !Array.isArray(sweep.bodies[moving[0]]?.omega.find((x) => x !== null));
    for (const b of moving) {
      const q = sweep.bodies[b];
      const t = this.t, name = shown(b);
      if (planar) {
        if (theta[b]) choices.push({ id: `${b}.angle`, label: t("plot-angle", { body: name }), unit: "°", values: theta[b], body: b });
        else choices.push({ id: `${b}.angle`, label: t("plot-rotation", { body: name }), unit: "°", values: q.angle, body: b });
        choices.push({ id: `${b}.omega`, label: t("plot-omega", { body: name }), unit: "rad/s", values: q.omega });
        choices.push({ id: `${b}.alpha`, label: t("plot-alpha", { body: name }), unit: "rad/s²", values: q.alpha });
      } else {
        choices.push({ id: `${b}.angle`, label: t("plot-rotation", { body: name }), unit: "°", values: size(q.angle) });
        choices.push({ id: `${b}.omega`, label: t("plot-omega-size", { body: name }), unit: "rad/s", values: size(q.omega) });
        choices.push({ id: `${b}.alpha`, label: t("plot-alpha-size", { body: name }), unit: "rad/s²", values: size(q.alpha) });
      }
    }
    const seen = new Set();
    for (const [key, v] of Object.entries(sweep.points)) {
      if (key.endsWith(`@${frame}`)) continue;
      const speed = v.velocity.map((x) => (x ? Math.hypot(...x) : null));
      const sig = key.split("@")[0] + JSON.stringify(speed.slice(0, 5));
      if (seen.has(sig)) continue;
      seen.add(sig);
      if (Math.max(...speed.filter((x) => x !== null), 0) === 0) continue;
      choices.push({ id: `${key}.speed`, label: this.t("plot-speed", { point: shown(key) }), unit: "m/s", values: speed });
      choices.push({ id: `${key}.accel`, label: this.t("plot-accel", { point: shown(key) }), unit: "m/s²", values: v.acceleration.map((x) => (x ? Math.hypot(...x) : null)) });
    }
    this.choices = choices;
    const ids = new Set(choices.map((c) => c.id));
    this.chosen = new Set([...this.chosen].filter((id) => ids.has(id)));
    if (!this.chosen.size) this.chosen = new Set(firstChoice(sweep, moving, choices).filter((id) => ids.has(id)));
    for (const c of choices) {
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = `${c.label} (${c.unit})`;
      b.dataset.quantity = c.id;
      b.setAttribute("aria-pressed", String(this.chosen.has(c.id)));
      b.addEventListener("click", () => {
        if (this.chosen.has(c.id)) this.chosen.delete(c.id); else this.chosen.add(c.id);
        b.setAttribute("aria-pressed", String(this.chosen.has(c.id)));
        this.draw();
      });
      this.pick.appendChild(b);
    }
    this.draw();
  }

  draw() {
    const svg = this.svg;
    svg.replaceChildren();
    if (!this.sweep) return;
    const chosen = this.choices.filter((c) => this.chosen.has(c.id));
    const w = svg.clientWidth || 600, h = svg.clientHeight || 190;
    svg.setAttribute("viewBox", `0 0 ${w} ${h}`);
    const xs = this.xs;
    const x0 = Math.min(...xs), x1 = Math.max(...xs);
    const X = (x) => PAD.left + ((x - x0) / (x1 - x0 || 1)) * (w - PAD.left - PAD.right);
    const band = (h - PAD.top - PAD.bottom) / Math.max(chosen.length, 1);
    this.series = [];
    chosen.forEach((c, i) => {
      const vals = c.values.filter((v) => v !== null);
      let lo = Math.min(...vals), hi = Math.max(...vals);
      if (!(hi - lo > 1e-9 * Math.max(Math.abs(hi), 1))) { lo -= 1; hi += 1; }
      const top = PAD.top + i * band + 4, bottom = PAD.top + (i + 1) * band - 4;
      const Y = (v) => bottom - ((v - lo) / (hi - lo)) * (bottom - top);
      const colour = COLOURS[i % COLOURS.length];
      el("line", { x1: PAD.left, x2: w - PAD.right, y1: bottom, y2: bottom, stroke: "#e3e7eb" }, svg);
      if (lo < 0 && hi > 0) el("line", { x1: PAD.left, x2: w - PAD.right, y1: Y(0), y2: Y(0), stroke: "#cfd6dc", "stroke-dasharray": "2 3" }, svg);
      let d = "";
      c.values.forEach((v, k) => { if (v !== null) d += `${d && c.values[k - 1] !== null ? "L" : "M"}${X(xs[k]).toFixed(1)},${Y(v).toFixed(1)}`; });
      el("path", { d, fill: "none", stroke: colour, "stroke-width": 1.6 }, svg);
      for (const v of ticks(lo, hi, Math.max(2, Math.floor((bottom - top) / 22)))) {      // the value axis
        el("line", { x1: PAD.left - 4, x2: PAD.left, y1: Y(v), y2: Y(v), stroke: "#9aa5ad" }, svg);
        el("line", { x1: PAD.left, x2: w - PAD.right, y1: Y(v), y2: Y(v), stroke: "#f0f2f4" }, svg);
        const tk = el("text", { x: PAD.left - 6, y: Y(v), "text-anchor": "end", "font-size": 10, fill: "#5f6b73", "dominant-baseline": "middle" }, svg);
        tk.textContent = num(v);
      }
      el("line", { x1: PAD.left, x2: PAD.left, y1: top, y2: bottom, stroke: "#9aa5ad" }, svg);
      const name = el("text", { x: PAD.left + 6, y: top + 10, "font-size": 11, fill: colour, "font-weight": 600 }, svg);
      name.textContent = `${c.label} (${c.unit})`;
      if (c.body) this.limits(c, X, Y, svg);
      const dot = el("circle", { r: 3.5, fill: colour, stroke: "white", "stroke-width": 1 }, svg);
      const value = el("text", { x: w - PAD.right + 6, "font-size": 11, fill: colour, "dominant-baseline": "middle", "font-family": "monospace" }, svg);
      this.series.push({ c, X, Y, dot, value });
    });
    this.deadPoints(X, svg, h);
    this.inputLimits(X, svg, h);
    const base = h - PAD.bottom;
    el("line", { x1: PAD.left, x2: w - PAD.right, y1: base, y2: base, stroke: "#9aa5ad" }, svg);
    for (const x of ticks(x0, x1, Math.max(2, Math.floor((w - PAD.left - PAD.right) / 70)))) {   // the input axis
      el("line", { x1: X(x), x2: X(x), y1: base, y2: base + 4, stroke: "#9aa5ad" }, svg);
      const tk = el("text", { x: X(x), y: base + 14, "text-anchor": "middle", "font-size": 10, fill: "#5f6b73" }, svg);
      tk.textContent = num(x);
    }
    const axis = el("text", { x: w - PAD.right + 4, y: base + 14, "font-size": 10.5, fill: "#5f6b73" }, svg);
    axis.textContent = this.unit === "s" ? "t (s)" : this.xlabel;
    axis.setAttribute("text-anchor", "end");
    axis.setAttribute("x", w - PAD.right);
    axis.setAttribute("y", base + 28);
    this.cursorLine = el("line", { y1: PAD.top, y2: h - PAD.bottom, stroke: "#263238", "stroke-width": 1 }, svg);
    this.X = X;
    this.cursor(this.row || 0);
  }

  /** Limit positions of a body: where its ω changes sign (its angle is at an extreme). */
  limits(c, X, Y, svg) {
    const omega = this.sweep.bodies[c.body].omega, xs = this.xs;
    for (let k = 1; k < omega.length; k++) {
      const a = omega[k - 1], b = omega[k];
      if (a === null || b === null || !(a * b < 0)) continue;
      const t = a / (a - b);
      const x = xs[k - 1] + t * (xs[k] - xs[k - 1]);
      const y = c.values[k - 1] + t * (c.values[k] - c.values[k - 1]);
      const m = el("g", { class: "limit" }, svg);
      el("circle", { cx: X(x), cy: Y(y), r: 4, fill: "white", stroke: "#263238", "stroke-width": 1.4 }, m);
      el("title", {}, m).textContent = this.t("limit-position", { body: shown(c.body), angle: num(y), input: num(x) });
    }
  }

  /** Where the sweep stops assembling (edges of its null rows): a dashed red line. */
  deadPoints(X, svg, h) {
    const ok = Object.values(this.sweep.bodies)[0].angle.map((v) => v !== null);
    const xs = this.xs;
    for (let k = 1; k < ok.length; k++) {
      if (ok[k] === ok[k - 1]) continue;
      const x = ok[k] ? xs[k] : xs[k - 1];
      el("line", { x1: X(x), x2: X(x), y1: PAD.top, y2: h - PAD.bottom, stroke: "#c62828", "stroke-dasharray": "4 3" }, svg);
      const t = el("text", { x: X(x) + 3, y: PAD.top + 10, "font-size": 10, fill: "#c62828" }, svg);
      t.textContent = this.t("dead-point");
    }
  }

  /** Where the input cannot go further and runs back (the sweep's `limits`): dotted lines. */
  inputLimits(X, svg, h) {
    for (const x of this.sweep.limits || []) {
      const m = el("g", { class: "input-limit" }, svg);
      el("line", { x1: X(x), x2: X(x), y1: PAD.top, y2: h - PAD.bottom, stroke: "#263238", "stroke-dasharray": "1 3" }, m);
      el("title", {}, m).textContent = this.t("input-limit", { input: num(x) });
    }
  }

  /** After a model error: no value is shown as current. */
  clearValues() {
    for (const s of this.series || []) { s.value.textContent = ""; s.dot.setAttribute("visibility", "hidden"); }
  }

  cursor(k) {
    this.row = k;
    if (!this.sweep || !this.cursorLine) return;
    const x = this.X(this.xs[k]);
    this.cursorLine.setAttribute("x1", x);
    this.cursorLine.setAttribute("x2", x);
    for (const s of this.series) {
      const v = s.c.values[k];
      s.dot.setAttribute("visibility", v === null ? "hidden" : "visible");
      if (v !== null) { s.dot.setAttribute("cx", x); s.dot.setAttribute("cy", s.Y(v)); s.value.setAttribute("y", s.Y(v)); }
      s.value.textContent = num(v);
    }
  }
}

/** About `n` round values (1, 2 or 5 × 10^k apart) between lo and hi. */
function ticks(lo, hi, n) {
  const span = hi - lo;
  if (!(span > 0) || !Number.isFinite(span)) return [];
  let step = niceStep(span / n);
  const at = (st) => {
    const out = [];
    for (let v = Math.ceil(lo / st) * st; v <= hi + st * 1e-9; v += st) out.push(Math.abs(v) < st * 1e-9 ? 0 : Number(v.toPrecision(12)));
    return out;
  };
  let out = at(step);
  while (out.length < 2 && step > span / 100) { step /= 2; out = at(step); }     // at least two ticks
  return out;
}

/** What a plot shows first: the output (the last moving body)'s angle and ω when it turns;
 * a slider (a ram, a piston) does not turn, so its point's speed and acceleration. */
function firstChoice(sweep, moving, choices) {
  const output = moving.at(-1);
  const turns = (b) => {
    const a = sweep.bodies[b].angle.filter((x) => x !== null).map((x) => (Array.isArray(x) ? Math.hypot(...x) : x));
    return a.length > 1 && Math.max(...a) - Math.min(...a) > 1e-9;
  };
  if (!output || turns(output)) return [`${output}.angle`, `${output}.omega`];
  const carried = new Set(Object.keys(sweep.points).filter((k) => k.endsWith(`@${output}`)).map((k) => k.split("@")[0]));
  const speed = choices.find((c) => c.id.endsWith(".speed") && carried.has(c.id.split("@")[0]));
  return speed ? [speed.id, speed.id.replace(/\.speed$/, ".accel")] : [`${output}.angle`, `${output}.omega`];
}
