// The answers table: the model's questions, then every body and point, at the slider's row.
// Absolute velocities, accelerations, ω and α follow the sweep's rows at once; the other
// answers (centres, curvature, relative motion) are those of the last solve, greyed while
// the slider is away from the position that solve was made at.
import { show, shown, num } from "./svg.js";
import { referenceLine } from "./angles.js";

const LONG = 22;      // characters: a longer value (a 3D vector, a formula, a decomposition) wraps in its cell
const LIVE = { velocity: "points", acceleration: "points", omega: "bodies", alpha: "bodies" };

export class Answers {
  constructor(root, t = (id) => id) {
    this.root = root;
    this.t = t;
    this.cells = [];
  }

  /** Build the table for a solve (its JSON) and the sweep (JSON, or null); the scene (or
   * null) gives each body's points at the drawn position, for its textbook angle. */
  set(solution, sweep, frame = "ground", scene = null) {
    const t = this.t;
    this.solution = solution;
    this.frameName = frame;
    this.sweep = sweep;
    this.cells = [];
    const rows = [];
    rows.push(section(t("answers"), t("value")));
    solution.answers.forEach((a, i) => {
      const kind = Object.keys(a.ask).find((k) => k !== "relative_to" && k !== "moving");
      const source = this.liveSource(kind, a.ask);
      rows.push(`<tr><td class="q kind-${kind}">${question(a.ask, t)}</td>` +
                `<td class="v" colspan="4" data-key="answers.${i}"></td></tr>`);
      this.cells.push({ key: `answers.${i}`, fixed: a.value, source });
    });
    rows.push(section(t("body"), t("angle-h"), t("rotation-h"), t("omega-h"), t("alpha-h")));
    for (const [name, b] of Object.entries(solution.bodies)) {
      const line = scene && referenceLine(scene.bodies[name]);
      const sw = sweep && sweep.bodies[name];
      const planar = typeof b.omega === "number" || typeof b.omega === "string";
      const a = `bodies.${attr(name)}`;
      const tip = line ? attr(t("angle-tip", { line: `${shown(line.from)}${shown(line.to)}` })) : "";
      const h = (key) => `data-h="${attr(t(key))}"`;          // its column's heading, for a narrow screen
      rows.push(`<tr><td class="q">${esc(name)}</td><td class="v" data-key="${a}.angle" ${h("angle-h")} title="${tip}"></td>` +
                `<td class="v" data-key="${a}.rotation" ${h("rotation-h")} title="${attr(t("rotation-tip"))}"></td>` +
                `<td class="v" data-key="${a}.omega" ${h("omega-h")}></td><td class="v" data-key="${a}.alpha" ${h("alpha-h")}></td></tr>`);
      const rotation = sw ? sw.angle : null;
      const since = rotation && planar && rotation.map((x) => (x === null ? null : x - (rotation[0] ?? 0)));
      const angle = line && planar ? (since ? since.map((x) => (x === null ? null : round(line.angle + x))) : null) : null;
      this.cells.push({ key: `bodies.${name}.angle`, fixed: line && planar ? round(line.angle) : null, source: angle });
      this.cells.push({ key: `bodies.${name}.rotation`, fixed: sw ? sw.angle[0] : 0, source: sw && sw.angle });
      this.cells.push({ key: `bodies.${name}.omega`, fixed: b.omega, source: sw && sw.omega });
      this.cells.push({ key: `bodies.${name}.alpha`, fixed: b.alpha, source: sw && sw.alpha });
    }
    rows.push(section(t("point"), t("position-h"), t("velocity-h"), t("acceleration-h")));
    for (const [key, names] of groups(solution.points, sweep)) {
      const p = solution.points[key];
      const label = names.length > 1 ? `${esc(key.split("@")[0])} <span class="where">(${names.map((n) => esc(n.split("@")[1])).join(", ")})</span>` : esc(key);
      rows.push(`<tr><td class="q">${label}</td>` + ["position", "velocity", "acceleration"].map(
        (q) => `<td class="v kind-${q}" data-key="points.${attr(key)}.${q}" data-h="${attr(t(`${q}-h`))}"${q === "position" ? "" : ' colspan="2"'}></td>`).join("") + "</tr>");
      for (const q of ["position", "velocity", "acceleration"]) {
        this.cells.push({ key: `points.${key}.${q}`, fixed: p[q], source: sweep && sweep.points[key] && sweep.points[key][q] });
      }
    }
    if (solution.where) {            // named quantities of long exact formulas (x_E = …)
      rows.push(section(t("where-h"), t("formula-h")));
      for (const [name, formula] of Object.entries(solution.where)) {
        rows.push(`<tr><td class="q">${esc(name)}</td><td class="v" colspan="4" data-key="where.${attr(name)}"></td></tr>`);
        this.cells.push({ key: `where.${name}`, fixed: formula, source: null });
      }
    }
    this.root.innerHTML = `<table>${rows.join("")}</table>`;
    const tds = this.root.querySelectorAll("td[data-key]");       // in the order of the cells
    this.cells.forEach((c, i) => { c.td = tds[i]; });
    this.solvedRow = 0;
    this.show(0);
  }

  /** No answers (a new model, not solved yet). */
  clear() {
    this.cells = [];
    this.solution = null;
    this.root.replaceChildren();
  }

  /** The sweep's series an answer follows, or null when only a solve gives it. */
  liveSource(kind, ask) {
    if (!this.sweep || !LIVE[kind] || (ask.relative_to && ask.relative_to !== this.frame())) return null;
    const target = ask[kind];
    if (LIVE[kind] === "bodies") return this.sweep.bodies[target] ? this.sweep.bodies[target][kind] : null;
    const key = target.includes("@") ? target : Object.keys(this.sweep.points).find((k) => k.split("@")[0] === target);
    return key && this.sweep.points[key] ? this.sweep.points[key][kind] : null;
  }

  frame() { return this.frameName; }

  /** Answers of a solve made at row `row` (with `move`): they replace the held ones. */
  resolved(solution, row) {
    solution.answers.forEach((a, i) => {
      const c = this.cells.find((x) => x.key === `answers.${i}`);
      if (c) { c.fixed = a.value; c.fixedRow = row; }
    });
    this.show(this.row);
  }

  show(k) {
    this.row = k;
    for (const c of this.cells) {
      // an answer asked in symbols stays the formula at the row it was solved at (the
      // sweep's numbers are those of draw_at); the bodies' and points' rows, and every
      // other row, follow the sweep at once
      const solvedHere = (c.fixedRow ?? this.solvedRow) === k;
      const exact = c.key.startsWith("answers.") && solvedHere && formula(c.fixed);
      const live = c.source && c.source[k] !== undefined && !exact;
      const value = live ? c.source[k] : c.fixed;
      const held = !live && value !== null && !solvedHere;   // "–" is never held
      const text = shown(format(value, this.t), Infinity);
      c.td.textContent = text;
      c.td.classList.toggle("long", text.length > LONG);
      c.td.dataset.value = JSON.stringify(value);
      c.td.classList.toggle("held", held);
      if (held) c.td.title = this.t("held-tip");
    }
  }
}

function section(...heads) {
  const span = (i) => (i === 1 && heads.length === 2 ? ' colspan="4"' : i > 1 && heads.length === 4 ? ' colspan="2"' : "");
  return `<tr class="section">${heads.map((h, i) => `<td${span(i)}>${esc(h)}</td>`).join("")}</tr>`;
}

/** Whether an answer holds an exact formula (a string among its numbers). */
function formula(v) {
  if (typeof v === "string") return true;
  return v !== null && typeof v === "object" && Object.values(v).some(formula);
}

const round = (x) => Number(x.toFixed(9));

/** Material points that move alike over the whole sweep, shown once: [first key, keys]. */
function groups(points, sweep) {
  const out = [];
  const sig = (key) => JSON.stringify(sweep && sweep.points[key] ? sweep.points[key] : points[key]);
  const seen = new Map();
  for (const key of Object.keys(points)) {
    const s = key.split("@")[0] + "|" + sig(key);
    if (seen.has(s)) { seen.get(s).push(key); continue; }
    const names = [key];
    seen.set(s, names);
    out.push([key, names]);
  }
  return out;
}

function question(ask, t) {
  const kind = Object.keys(ask).find((k) => k !== "relative_to" && k !== "moving");
  const rel = ask.relative_to ? ` <span class="where">${esc(t("relative-to", { body: shown(ask.relative_to) }))}</span>` : "";
  const moving = ask.moving ? ` <span class="where">${esc(t("in-body", { body: shown(ask.moving) }))}</span>` : "";
  return `${esc(t(`q-${kind}`))} <b>${esc(String(ask[kind]))}</b>${rel}${moving}`;
}

/** An answer's value as text (vectors, centres, curvature, decompositions, ...). */
export function format(v, t = (id) => id) {
  if (v === null || v === undefined) return "–";
  if (typeof v !== "object" || Array.isArray(v)) return show(v);
  if (v.rest) return t("at-rest");
  if ("radius" in v) return v.radius === null ? t("straight-path") : t("curvature-value", { radius: show(v.radius), centre: show(v.center) });
  if ("point" in v && "slide" in v) return t("axis-value", { point: show(v.point), direction: show(v.direction), omega: show(v.omega), slide: show(v.slide) });
  if ("point" in v) return v.point === null ? t("at-infinity", { direction: show(v.direction) }) : show(v.point);
  return Object.entries(v).map(([k, x]) => `${t(`part-${k}`)}: ${format(x, t)}`).join(" | ");
}

/** A name as text for the table's HTML: shown as one printable line, markup escaped. */
function esc(s) {
  return attr(shown(s));
}

/** Text (a name as written, for a data attribute) with markup escaped. */
function attr(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
}
