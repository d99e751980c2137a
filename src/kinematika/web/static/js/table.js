// The answers table: the model's questions, then every body and point, at the slider's row.
// Absolute velocities, accelerations, ω and α follow the sweep's rows at once; the other
// answers (centres, curvature, relative motion) are those of the last solve, greyed while
// the slider is away from the position that solve was made at.
import { show, shown } from "./svg.js";

const LONG = 22;      // characters: a longer value (a 3D vector, a formula, a decomposition) wraps in its cell
const LIVE = { velocity: "points", acceleration: "points", omega: "bodies", alpha: "bodies" };

export class Answers {
  constructor(root) {
    this.root = root;
    this.cells = [];
  }

  /** Build the table for a solve (its JSON) and the sweep (JSON, or null). */
  set(solution, sweep, frame = "ground") {
    this.solution = solution;
    this.frameName = frame;
    this.sweep = sweep;
    this.cells = [];
    const rows = [];
    rows.push(section("Answers", "value"));
    solution.answers.forEach((a, i) => {
      const kind = Object.keys(a.ask).find((k) => k !== "relative_to" && k !== "moving");
      const source = this.liveSource(kind, a.ask);
      rows.push(`<tr><td class="q kind-${kind}">${question(a.ask)}</td>` +
                `<td class="v" colspan="3" data-key="answers.${i}"></td></tr>`);
      this.cells.push({ key: `answers.${i}`, fixed: a.value, source });
    });
    rows.push(section("Body", "angle (°)", "ω (rad/s)", "α (rad/s²)"));
    for (const [name, b] of Object.entries(solution.bodies)) {
      rows.push(`<tr><td class="q">${esc(name)}</td><td class="v" data-key="bodies.${attr(name)}.angle"></td>` +
                `<td class="v" data-key="bodies.${attr(name)}.omega"></td><td class="v" data-key="bodies.${attr(name)}.alpha"></td></tr>`);
      const sw = sweep && sweep.bodies[name];
      this.cells.push({ key: `bodies.${name}.angle`, fixed: sw ? sw.angle[0] : 0, source: sw && sw.angle });
      this.cells.push({ key: `bodies.${name}.omega`, fixed: b.omega, source: sw && sw.omega });
      this.cells.push({ key: `bodies.${name}.alpha`, fixed: b.alpha, source: sw && sw.alpha });
    }
    rows.push(section("Point", "position", "velocity", "acceleration"));
    for (const [key, names] of groups(solution.points, sweep)) {
      const p = solution.points[key];
      const label = names.length > 1 ? `${esc(key.split("@")[0])} <span class="where">(${names.map((n) => esc(n.split("@")[1])).join(", ")})</span>` : esc(key);
      rows.push(`<tr><td class="q">${label}</td>` + ["position", "velocity", "acceleration"].map(
        (q) => `<td class="v kind-${q}" data-key="points.${attr(key)}.${q}"></td>`).join("") + "</tr>");
      for (const q of ["position", "velocity", "acceleration"]) {
        this.cells.push({ key: `points.${key}.${q}`, fixed: p[q], source: sweep && sweep.points[key] && sweep.points[key][q] });
      }
    }
    if (solution.where) {            // named quantities of long exact formulas (x_E = …)
      rows.push(section("Where", "formula"));
      for (const [name, formula] of Object.entries(solution.where)) {
        rows.push(`<tr><td class="q">${esc(name)}</td><td class="v" colspan="3" data-key="where.${attr(name)}"></td></tr>`);
        this.cells.push({ key: `where.${name}`, fixed: formula, source: null });
      }
    }
    this.root.innerHTML = `<table>${rows.join("")}</table>`;
    const tds = this.root.querySelectorAll("td[data-key]");       // in the order of the cells
    this.cells.forEach((c, i) => { c.td = tds[i]; });
    this.solvedRow = 0;
    this.show(0);
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
      const live = c.source && c.source[k] !== undefined;
      const value = live ? c.source[k] : c.fixed;
      const held = !live && (c.fixedRow ?? this.solvedRow) !== k;
      const text = shown(format(value), Infinity);
      c.td.textContent = text;
      c.td.classList.toggle("long", text.length > LONG);
      c.td.dataset.value = JSON.stringify(value);
      c.td.classList.toggle("held", held);
      c.td.title = held ? "at the position last solved (move the slider's end there, or wait: it is solved again)" : "";
    }
  }
}

function section(...heads) {
  return `<tr class="section">${heads.map((h, i) => `<td${i === 1 && heads.length === 2 ? ' colspan="3"' : ""}>${h}</td>`).join("")}</tr>`;
}

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

function question(ask) {
  const kind = Object.keys(ask).find((k) => k !== "relative_to" && k !== "moving");
  const rel = ask.relative_to ? ` <span class="where">relative to ${esc(ask.relative_to)}</span>` : "";
  const moving = ask.moving ? ` <span class="where">in ${esc(ask.moving)}</span>` : "";
  return `${kind} <b>${esc(String(ask[kind]))}</b>${rel}${moving}`;
}

/** An answer's value as text (vectors, centres, curvature, decompositions, ...). */
export function format(v) {
  if (v === null || v === undefined) return "–";
  if (typeof v !== "object" || Array.isArray(v)) return show(v);
  if (v.rest) return "at rest (no relative motion)";
  if ("radius" in v) return v.radius === null ? "straight path (infinite radius)" : `ρ = ${show(v.radius)}, centre ${show(v.center)}`;
  if ("point" in v && "slide" in v) return `axis through ${show(v.point)} along ${show(v.direction)}, ω ${show(v.omega)}, slide ${show(v.slide)}`;
  if ("point" in v) return v.point === null ? `at infinity, direction ${show(v.direction)}` : show(v.point);
  return Object.entries(v).map(([k, x]) => `${k}: ${format(x)}`).join("; ");
}

/** A name as text for the table's HTML: shown as one printable line, markup escaped. */
function esc(s) {
  return attr(shown(s));
}

/** Text (a name as written, for a data attribute) with markup escaped. */
function attr(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
}
