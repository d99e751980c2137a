// The page: one model at a time. On every change of the model (typing, a drag, an example,
// a format or assembly), the API solves it, paints its scene and sweeps it once; the slider
// then moves through the sweep's rows locally. See docs/app.md.
import { post, get } from "./api.js";
import { Editor, errorLine } from "./editor.js";
import { Figure } from "./figure.js";
import { Answers } from "./table.js";
import { Plot } from "./plot.js";
import { fragment, fromFragment } from "./link.js";
import { num, shown } from "./svg.js";
import { Builder } from "./builder.js";
import { followRow, movingKey } from "./turn.js";
import * as i18n from "./i18n.js";

const t = i18n.t;

const $ = (id) => document.getElementById(id);
const SETTLE_MS = 250;          // a slider at rest this long is solved exactly there
const ROWS_PER_SECOND = 60;     // playing speed at 1×

const state = { fmt: "yaml", name: "model", assembly: null, lang: i18n.chosen(), gen: 0, row: 0,
                solution: null, sweep: null, scene: null, input: null, explained: null };
const timing = { updates: [] };

const editor = new Editor($("model-editor"), $("gutter"), $("error-line"), () => { remember(); analyse(); });
const figure = new Figure($("figure"), $("legend"), $("notes"), drag, t);
const answers = new Answers($("answers"), t);
const plot = new Plot($("plot"), $("plot-pick"), t);
const builder = new Builder(figure, $("palette"), $("properties-body"), $("build-hint"), t, build);
const slider = $("input-slider");
figure.onTurn = turn;
window.kinematika = { state, timing, figure, builder,
  /** The page coordinates (CSS pixels) of a model point: for tests that click on the grid. */
  toScreen: ([x, y]) => {
    const m = $("figure").getScreenCTM();
    return [m.a * x + m.c * -y + m.e, m.b * x + m.d * -y + m.f];
  } };

// the model -----------------------------------------------------------------------------
function request(extra = {}) {
  const body = { model: editor.text, format: state.fmt, lang: state.lang, ...extra };
  if (state.assembly !== null) body.assembly = state.assembly;
  return body;
}

/** The box the figure keeps showing (a zoom, a pan, a drag), for the scene's picture to be
 * drawn for it; none when the figure frames the scene. */
function keptFrame() {
  return figure.keep && figure.view ? { frame: figure.view } : {};
}

/** Solve, draw and sweep the model in the editor (stale answers are dropped), and sketch
 * it for the builder (where its points are, solvable or not yet). */
async function analyse() {
  const gen = ++state.gen;
  $("busy").hidden = false;
  const [solved, drawn, swept, sketched] = await Promise.allSettled([
    post("solve", request()), post("draw", request({ centres: true, lang: state.lang, ...keptFrame() })),
    post("sweep", request({ skip_bad: true })), post("sketch", { model: editor.text, format: state.fmt, lang: state.lang }),
  ]);
  if (gen !== state.gen) return;
  $("busy").hidden = true;
  const sketch = sketched.status === "fulfilled" ? sketched.value : null;
  if (solved.status === "rejected") {
    // blank: nothing built yet (no moving body, no point), not a model whose points are
    // placed by symbols (a sketch with no points but bodies): its failure is said
    const blank = sketch && !Object.keys(sketch.points).length && !sketch.problem
      && !Object.values(sketch.bodies).some((b) => !b.frame);
    const missing = blank ? null : stillBuilding(solved.reason, sketch);
    showError(blank || missing ? null : solved.reason);
    showMissing(missing, solved.reason);
    showWarnings([]);
    stale(true);
    state.solution = null;
    if (sketch) builder.sketch = sketch;
    if (sketch && (blank || Object.keys(sketch.points).length)) {
      state.scene = state.sweep = state.input = null;      // nothing of the last model is drawn again
      figure.clear(figure.keep || builder.box() || [-0.1, -0.1, 0.3, 0.2]);
      figure.stale(false);                      // the sketch is current: only the numbers are not
      $("coordinate").textContent = "–";
      $("model-name").textContent = shown(sketch.name || t("model"), 120);
      $("plot-box").hidden = true;
      slider.disabled = $("play").disabled = $("by-hand").disabled = true;
      $("notes").textContent = "";
      if (blank) $("dof").textContent = t("dof", { n: "–" });
    }
    if (sketch) builder.update(sketch, false);
    return;
  }
  showError(null);
  showMissing(null);
  stale(false);
  state.solution = solved.value;
  state.answered = true;
  showWarnings(state.solution.warnings || []);
  state.scene = drawn.status === "fulfilled" ? drawn.value : null;
  state.sweep = swept.status === "fulfilled" ? swept.value : null;
  state.playBack = false;
  state.input = state.scene && state.scene.input;
  state.sweepError = swept.status === "rejected" ? swept.reason.message : null;
  if (inTime()) {                    // a motion followed in time: its rows, as a sweep's
    try {
      state.sweep = rowsInTime(await post("simulate", request({ time: state.input.time, steps: state.input.steps })));
      state.sweepError = null;
    } catch (err) {
      state.sweep = err.partial ? rowsInTime(err.partial) : null;
      state.sweepError = err.message;
    }
    if (gen !== state.gen) return;
  }
  state.explained = null;
  const name = shown(state.solution.name || t("model"), 120);
  $("model-name").textContent = name;
  $("model-name").title = name;
  document.title = `${name} — kinematika`;
  const dof = $("dof");
  dof.textContent = t("dof", { n: state.solution.dof });
  dof.classList.remove("bad");
  const frame = state.scene ? Object.keys(state.scene.bodies).find((b) => state.scene.bodies[b].frame) : "ground";
  const rows = state.sweep ? state.sweep.coordinate.length : 1;
  state.row = Math.min(state.row, rows - 1);
  if (state.row !== 0 && !state.sweep) state.row = 0;
  if (sketch) builder.sketch = sketch;
  if (state.scene) figure.set(state.scene, state.sweep, 0);
  else figure.clear(figure.keep || builder.box());
  answers.set(state.solution, state.sweep, frame, state.scene);
  plot.set(state.sweep, state.input ? state.input.unit : "deg", frame, state.scene);
  $("plot-box").hidden = !state.sweep;
  slider.max = String(rows - 1);
  slider.disabled = $("play").disabled = $("by-hand").disabled = !state.sweep;
  slider.title = state.sweepError ? t("no-sweep", { why: state.sweepError }) : "";
  setRow(state.row);
  if (sketch) builder.update(sketch, !!state.scene, state.solution.dimension);
  if (!figure.drag) listAssemblies(gen);
  if (state.sweepError) {
    $("notes").textContent = [$("notes").textContent, t("slider-off", { why: state.sweepError })].filter(Boolean).join(" · ");
  }
  explainSoon();
}

/** After an error, the numbers of the last model that solved are not current: greyed, and
 * said so (the figure greyed too). */
function stale(on) {
  figure.stale(on);
  $("answers").classList.toggle("stale", on);
  $("answers-stale").hidden = !on || !state.answered;
  $("plot-box").classList.toggle("stale", on);
  if (on) {
    $("answers-where").textContent = "";
    plot.clearValues();
  }
}

/** The assemblies of the mechanism at its drawn input (`kinematika assemblies`), to pick one. */
async function listAssemblies(gen) {
  const pick = $("assembly");
  let found = [];
  try {
    found = (await post("assemblies", { model: editor.text, format: state.fmt, lang: state.lang })).assemblies;
  } catch (_) { /* none to offer: the model's own */ }
  if (gen !== state.gen) return;
  const options = [`<option value="">${escapeHtml(t("assembly-as-drawn"))}</option>`];
  for (const a of found) {
    const how = a.closures.length ? `: ${a.closures.join("; ")}` : "";
    options.push(`<option value="${a.number}">${a.number}${a.drawn ? ` (${escapeHtml(t("assembly-drawn"))})` : ""}${escapeHtml(shown(how, 160))}</option>`);
  }
  pick.innerHTML = options.join("");
  pick.value = state.assembly === null ? "" : String(state.assembly);
  pick.disabled = found.length < 2;
  state.assemblies = found.length;
  assemblyTitle();
}

function assemblyTitle() {
  const n = state.assemblies || 0;
  $("assembly").title = n < 2 ? t("assembly-one") : t("assembly-many", { n });
  const first = $("assembly").options[0];
  if (first) first.textContent = t("assembly-as-drawn");
}

function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;", "'": "&#39;" })[c]);
}

/** The input answered as written that is most likely a mistake (the answer's `warnings`:
 * an angle of 30 rad where 30° was meant), one line each with its place. */
function showWarnings(list) {
  const box = $("warnings");
  box.hidden = !list.length;
  box.replaceChildren(...list.map((w) => {
    const line = document.createElement("p");
    const kind = document.createElement("b");
    kind.textContent = t("warning");
    line.appendChild(kind);
    if (w.where) {
      const place = document.createElement("span");
      place.className = "place";
      place.textContent = `${w.where}: `;
      line.appendChild(place);
    }
    line.appendChild(document.createTextNode(w.message));
    return line;
  }));
}

/** What a model being built still lacks, when that is all that keeps it from being solved:
 * a moving body (`missing-body`), an input (`missing-input`), another input for one more
 * degree of freedom (`missing-more-input`); null for a real error. */
function stillBuilding(err, sketch) {
  if (!err || err.kind !== "mobility" || !sketch || sketch.problem) return null;
  if (!Object.values(sketch.bodies).some((b) => !b.frame)) return "missing-body";
  if (err.dof === undefined) return null;             // drivers that conflict: a real error
  return sketch.drivers.length ? "missing-more-input" : "missing-input";
}

/** A hint (not an error) of what to add next; the degrees of freedom as the message says. */
function showMissing(key, err = null) {
  const box = $("missing");
  box.hidden = !key;
  box.textContent = key ? t(key) : "";
  builder.missing = key;
  builder.say();
  if (!key) return;
  const dof = $("dof");
  dof.textContent = t("dof", { n: err && err.dof !== undefined && key !== "missing-body" ? err.dof : "–" });
  dof.classList.remove("bad");
}

function showError(err) {
  const box = $("error");
  if (!err) {
    box.hidden = true;
    box.replaceChildren();
    editor.markLine(null);
    return;
  }
  box.hidden = false;
  box.innerHTML = "";
  const kind = document.createElement("b");
  kind.textContent = t(`kind-${err.kind || "internal"}`);
  box.appendChild(kind);
  if (err.where) {
    const place = document.createElement("span");
    place.className = "place";
    place.textContent = `${err.where}: `;
    box.appendChild(place);
  }
  box.appendChild(document.createTextNode(err.message));
  box.dataset.kind = err.kind || "";
  editor.markLine(errorLine(editor.text, err));
  const dof = $("dof");
  dof.textContent = t("dof", { n: err.dof !== undefined ? err.dof : "?" });
  dof.classList.add("bad");
}

function load(text, fmt, name) {
  remember();
  figure.keep = null;
  builder.select(null);
  forget();
  state.fmt = fmt || "yaml";
  state.name = (name || "model").replace(/\.(ya?ml|toml|json)$/, "");
  $("format").value = state.fmt;
  editor.text = text;
  remember();
  state.row = 0;
  analyse();
}

/** A new document (New, an example, a link): nothing of the last model stays on the page,
 * neither its answers nor its plot nor its explanation. */
function forget() {
  state.sweep = state.scene = state.input = state.blank = null;
  state.answered = false;                  // the answers panel holds nothing of this model yet
  state.explained = state.explanation = null;
  answers.clear();
  plot.set(null);
  $("plot-box").hidden = true;
  $("answers-where").textContent = "";
  $("answers-stale").hidden = true;
  $("explanation-where").textContent = "";
  $("explanation").srcdoc = "";
}

// the slider ----------------------------------------------------------------------------
/** Whether the slider moves through time (a simulation's rows: `kinematika simulate`). */
function inTime() {
  return !!(state.input && state.input.unit === "s");
}

/** A simulation's rows read as a sweep's: its times as the coordinate. */
function rowsInTime(rows) {
  return { ...rows, coordinate: rows.time };
}


function coordinateText(k) {
  if (!state.sweep || !state.input) return t("drawn-position");
  const x = state.sweep.coordinate[k];
  if (inTime()) return `t = ${num(x)} s`;
  return `${shown(state.input.joint, 40)} ${x >= 0 ? "+" : "−"}${num(Math.abs(x))}${state.input.unit === "deg" ? "°" : ""}`;
}

/** Show sweep row `k` in the figure, the table and the plot (the part that must be fast). */
function setRow(k) {
  const t0 = performance.now();
  state.row = k;
  slider.value = String(k);
  figure.show(k);
  if (builder.selected) builder.follow();
  answers.show(k);
  plot.cursor(k);
  $("coordinate").textContent = coordinateText(k);
  $("answers-where").textContent = whereText(k);
  timing.updates.push(performance.now() - t0);
  if (timing.updates.length > 500) timing.updates.shift();
  settleSoon();
}

function whereText(k) {
  return k === 0 ? t("at-drawn") : t("at-coordinate", { where: coordinateText(k) });
}

let settleTimer = null;
function settleSoon() {
  clearTimeout(settleTimer);
  settleTimer = setTimeout(settle, SETTLE_MS);
}

/** With the slider at rest, solve exactly there (`move`): centres, curvature and every
 * answer of that position; and explain it. */
async function settle() {
  const k = state.row, gen = state.gen;
  if (!state.solution) return;             // a model being built: nothing solved to show
  explainSoon();
  if (k === 0 || !state.sweep || !state.input || inTime()) {
    if (state.scene && (k === 0 || !inTime())) place(state.scene, 0);
    return;
  }
  const move = posedAt(k);
  try {
    const [sol, scene] = await Promise.all([post("solve", request(move)), post("draw", request({ ...move, centres: true, frame: figure.view }))]);
    if (gen !== state.gen || k !== state.row) return;
    answers.resolved(sol, k);
    place(scene, k);
  } catch (_) { /* moving is not available: the answers stay those of the drawn position */ }
}

/** The scene solved at row k: its results over the moving figure, or the whole figure
 * when it cannot move through the rows (no sweep). */
function place(scene, k) {
  if (figure.sweep) figure.overlay(scene, k);
  else if (figure.sceneRow !== k || figure.scene !== scene) figure.set(scene, null, k);
}

/** How the API poses the model at sweep row k: `move` the input to the row's coordinate, or,
 * for a motion through limit positions (where a coordinate is reached on two branches), the
 * row itself (`row`: the sweep's row k, through the limit positions before it). */
function posedAt(k) {
  if (k === 0 || !state.input || !state.sweep || inTime()) return {};     // rows in time: posed at the drawing only
  if (state.sweep.limits && state.sweep.limits.length) return { row: k };
  return { move: { [state.input.joint]: state.sweep.coordinate[k] } };
}

/** A motion through limit positions that ends elsewhere than where it started is played
 * back and forth (forward to its last row, then back); one that comes back (a full turn, a
 * rocker's whole cycle) loops. */
function backAndForth(sweep) {
  if (!sweep.limits || !sweep.limits.length) return false;
  if (sweep.bounces === undefined) {              // once a sweep
    const last = sweep.coordinate.length - 1;
    sweep.bounces = !Object.values(sweep.points).every(({ position: p }) => p[0] && p[last] &&
      p[0].every((x, i) => Math.abs(x - p[last][i]) <= 1e-9 * Math.max(1, Math.abs(x))));
  }
  return sweep.bounces;
}

let playing = null;
function play() {
  if (playing) { cancelAnimationFrame(playing.frame); playing = null; $("play").textContent = "▶"; return; }
  $("play").textContent = "❚❚";
  // `phase` runs forward; played back and forth, phases past the last row are the way back
  const rows0 = state.sweep.coordinate.length;
  playing = { last: null, pos: state.row, phase: state.playBack ? 2 * (rows0 - 1) - state.row : state.row };
  const step = (now) => {       // `now`: the frame's time, which can precede the click's
    const rows = state.sweep.coordinate.length;
    const dt = playing.last === null ? 0 : Math.max(now - playing.last, 0);
    const ahead = (dt / 1000) * ROWS_PER_SECOND * Number($("speed").value);
    if (backAndForth(state.sweep) && rows > 1) {
      const period = 2 * (rows - 1);
      playing.phase = (playing.phase + ahead) % period;
      state.playBack = playing.phase > rows - 1;
      playing.pos = state.playBack ? period - playing.phase : playing.phase;
      setRow(state.playBack ? Math.ceil(playing.pos) : Math.floor(playing.pos));
    } else {
      playing.pos = (playing.pos + ahead) % rows;
      setRow(Math.floor(playing.pos));
    }
    playing.last = now;
    playing.frame = requestAnimationFrame(step);
  };
  playing.frame = requestAnimationFrame(step);
}

// the explanation -----------------------------------------------------------------------
let explainTimer = null;
function explainSoon() {
  clearTimeout(explainTimer);
  if (figure.drag) return;                 // explained when the drag is over (it draws: slow)
  explainTimer = setTimeout(explain, 60);
}

async function explain() {
  const k = state.row, lang = state.lang, gen = state.gen;
  const key = `${gen}|${lang}|${k}`;
  if (state.explained === key || state.explaining === key || !state.solution) return;
  state.explaining = key;            // one request a position (an explanation can take seconds)
  const move = posedAt(k);
  let html, where = inTime() && k !== 0 ? t("at-drawn-only") : whereText(k);
  try {
    html = await post("explain", request({ lang, ...move }), "text");
  } catch (err) {
    if (!move.move && !move.row) { html = null; where = err.message; } else {
      try {
        html = await post("explain", request({ lang }), "text");
        where = t("at-drawn-only");
      } catch (err2) { html = null; where = err2.message; }
    }
  }
  if (state.explaining === key) state.explaining = null;
  if (gen !== state.gen || lang !== state.lang || k !== state.row) return;
  state.explained = key;
  state.explanation = html;
  $("explanation-where").textContent = where;
  $("explanation").srcdoc = html || "";
}

// dragging a point --------------------------------------------------------------------------
let dragWanted = null, dragBusy = false;

/** A point dragged to `to`: its edits are made one at a time, each with the latest place
 * the pointer has reached (places passed while an edit was on its way are skipped). */
async function drag(name, to, final) {
  if (to === null) {                       // a drag starts: edits are made at the drawn position
    if (playing) play();
    if (state.row !== 0) setRow(0);
    batch.begin();                           // the whole drag is one step of Undo
    return;
  }
  dragWanted = { name, to, final };
  if (dragBusy) return;
  dragBusy = true;
  while (dragWanted) {
    const job = dragWanted;
    dragWanted = null;
    try {
      const answer = await post("edit", { model: editor.text, format: state.fmt, lang: state.lang, point: job.name, to: job.to });
      setText(answer.model);
      await analyse();
    } catch (err) {
      toast(err.message);
      showError(err);
    }
  }
  dragBusy = false;
  figure.release();
  if (!figure.drag) { batch.end(); listAssemblies(state.gen); explainSoon(); }
}

// turning the mechanism by hand ----------------------------------------------------------------
let turning = null;

/** A point dragged along the motion (by hand, or with Shift): the mechanism follows it
 * through the sweep's rows as far as it can move (turn.js); the model is not changed. */
function turn(name, at, phase) {
  if (phase === "start") {
    if (playing) play();
    const frame = state.scene && Object.keys(state.scene.bodies).find((b) => state.scene.bodies[b].frame);
    const key = state.sweep && state.scene && state.scene.dimension === 2 ? movingKey(state.sweep, name, frame) : null;
    turning = key ? { key } : null;
    if (!key) toast(t(state.sweep ? "turn-fixed" : "turn-no-motion", { point: shown(name) }));
    return;
  }
  if (!turning) return;
  const k = followRow(state.sweep, turning.key, at, state.row);
  if (k !== state.row) setRow(k);
  if (phase === "end") turning = null;
}

function byHand(on) {
  figure.byHand = on;
  builder.byHand = on;
  $("by-hand").setAttribute("aria-pressed", String(on));
  $("figure").classList.toggle("hand", on);
  builder.say();
}

// downloads and the link ----------------------------------------------------------------------
function save(blob, name) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

async function download(what) {
  $("downloads").open = false;
  const here = posedAt(state.row);
  try {
    if (what === "model") save(new Blob([editor.text], { type: "text/plain" }), `${state.name}.${state.fmt === "yaml" ? "yaml" : state.fmt}`);
    else if (what === "svg" || what === "png") {
      let blob;
      try { blob = await post("draw", request({ ...here, as: what, centres: true }), "blob"); }
      catch (_) { blob = await post("draw", request({ as: what, centres: true }), "blob"); }
      save(blob, `${state.name}.${what}`);
    } else if (what === "csv" && inTime()) save(await post("simulate", request({ time: state.input.time, steps: state.input.steps, as: "csv" }), "blob"), `${state.name}.csv`);
    else if (what === "csv") save(await post("sweep", request({ skip_bad: true, as: "csv" }), "blob"), `${state.name}.csv`);
    else if (what === "html") {
      if (!state.explanation) await explain();
      save(new Blob([state.explanation || ""], { type: "text/html" }), `${state.name}-${state.lang}.html`);
    }
  } catch (err) { toast(t("cannot-download", { why: err.message })); }
}

async function copyLink() {
  const url = `${location.origin}${location.pathname}#${await fragment(editor.text, state.fmt)}`;
  history.replaceState(null, "", url);
  try {
    await navigator.clipboard.writeText(url);
    toast(t("link-copied"));
  } catch (_) {
    toast(t("link-in-bar"));
  }
}

function toast(text) {
  const t = $("toast");
  t.textContent = text;
  t.hidden = false;
  clearTimeout(toast.timer);
  toast.timer = setTimeout(() => { t.hidden = true; }, 3000);
}

// wiring ----------------------------------------------------------------------------------
slider.addEventListener("input", () => { if (playing) play(); setRow(Number(slider.value)); });
$("play").addEventListener("click", play);
$("by-hand").addEventListener("click", () => byHand(!figure.byHand));
$("close-properties").addEventListener("click", () => builder.select(null));
for (const pick of document.querySelectorAll("[data-lang]")) {
  pick.addEventListener("change", (e) => setLanguage(e.target.value));
}
$("format").addEventListener("change", (e) => convertTo(e.target.value));
for (const b of document.querySelectorAll("[data-template]")) b.addEventListener("click", () => newModel(b.dataset.template));
$("undo").addEventListener("click", () => undo(-1));
$("redo").addEventListener("click", () => undo(1));
$("zoom-in").addEventListener("click", () => figure.zoom(1 / 1.4));
$("zoom-out").addEventListener("click", () => figure.zoom(1.4));
$("fit").addEventListener("click", () => figure.fit());
$("grid-on").addEventListener("change", (e) => { builder.showGrid = e.target.checked; builder.draw(); });
$("assembly").addEventListener("change", (e) => { state.assembly = e.target.value === "" ? null : Number(e.target.value); analyse(); });
$("example").addEventListener("change", async (e) => {
  if (!e.target.value) return;
  const ex = await get(`/api/examples/${encodeURIComponent(e.target.value)}`);
  history.replaceState(null, "", location.pathname);
  load(ex.model, ex.format, ex.name);
});
$("copy-link").addEventListener("click", copyLink);
for (const b of document.querySelectorAll("[data-download]")) b.addEventListener("click", () => download(b.dataset.download));
for (const c of document.querySelectorAll("[data-layer]:not(#grid-on)")) c.addEventListener("change", () => figure.setLayer(c.dataset.layer, c.checked));
document.addEventListener("keydown", (e) => {
  const typing = e.target.closest?.("textarea, input, select");
  if (typing) return;
  if ((e.ctrlKey || e.metaKey) && e.key.toLowerCase() === "z") { e.preventDefault(); undo(e.shiftKey ? 1 : -1); return; }
  if ((e.key === "Delete" || e.key === "Backspace") && builder.selected) { e.preventDefault(); build({ op: "delete", element: builder.selected }); return; }
  if (e.key === "Escape") { builder.choose("select"); return; }
  if (e.key === " " && e.target === document.body && state.sweep) { e.preventDefault(); play(); }
});

// building, undo, formats, languages ------------------------------------------------------------
const past = [], future = [];       // earlier and undone states: [text, format]
let last = null;

/** One step of Undo for an action made of many edits (a drag): between `begin` and `end`
 * the text changes without being remembered; `end` remembers the state before `begin`. */
const batch = {
  open: false,
  begin() { remember(); this.open = true; },
  end() { if (!this.open) return; this.open = false; remember(); },
};

/** Keep the state before a change, for undo (typing is kept once per pause; a drag once). */
function remember() {
  if (batch.open) return;
  const now = [editor.text, state.fmt];
  if (last !== null && (last[0] !== now[0] || last[1] !== now[1])) {
    past.push(last);
    if (past.length > 200) past.shift();
    future.length = 0;
  }
  last = now;
  $("undo").disabled = !past.length;
  $("redo").disabled = !future.length;
}

function setText(text) {
  editor.text = text;
  remember();
}

function undo(way) {
  const from = way < 0 ? past : future, to = way < 0 ? future : past;
  if (!from.length) return;
  to.push([editor.text, state.fmt]);
  const [text, fmt] = from.pop();
  editor.text = text;
  state.fmt = fmt;
  $("format").value = fmt;
  last = [text, fmt];
  $("undo").disabled = !past.length;
  $("redo").disabled = !future.length;
  figure.hold();
  analyse();
}

/** A building action (/api/build): the server edits the text, the page solves it again. */
async function build(op) {
  try {
    const answer = await post("build", { model: editor.text, format: state.fmt, lang: state.lang, op });
    figure.hold();
    remember();
    setText(answer.model);
    if (answer.select) builder.select(answer.select);
    await analyse();
  } catch (err) {
    toast(err.message);
  }
}

/** The Format menu: the same model written in another format (server-side). */
async function convertTo(fmt) {
  if (fmt === state.fmt) return;
  try {
    const answer = await post("convert", { model: editor.text, format: state.fmt, lang: state.lang, to: fmt });
    state.fmt = fmt;
    setText(answer.model);
    analyse();
  } catch (err) {
    $("format").value = state.fmt;
    toast(t("cannot-convert", { why: err.message }));
  }
}

async function newModel(name) {
  $("new-menu").open = false;
  const tpl = await get(`/api/templates/${encodeURIComponent(name)}?lang=${state.lang}`);
  $("example").value = "";
  history.replaceState(null, "", location.pathname);
  load(tpl.model, tpl.format, name === "blank" ? "model" : name);
  state.blank = name === "blank" ? tpl.model : null;
  if (name === "blank") figure.clear([-0.1, -0.1, 0.3, 0.2]);
}

/** One choice: the page's words, the explanation's language and the figure's numbers. */
async function setLanguage(code) {
  state.lang = code;
  for (const pick of document.querySelectorAll("[data-lang]")) pick.value = code;
  await i18n.use(code);
  assemblyTitle();
  builder.say();
  builder.showProperties();
  if (state.blank && editor.text === state.blank) newModel("blank");   // not begun: in the new language
  else if (state.solution || editor.text.trim()) analyse(); else explainSoon();     // errors, warnings: said again
}

async function start() {
  const [opening, palette] = await Promise.all([get("/api/start"), get("/api/palette")]);
  builder.setTools(palette.tools, palette.questions);
  for (const pick of document.querySelectorAll("[data-lang]")) pick.value = state.lang;
  await i18n.use(state.lang);
  for (const name of opening.examples) {
    const o = document.createElement("option");
    o.value = name;
    o.textContent = name.replace(/\.(ya?ml|toml|json)$/, "").replace(/_/g, " ");
    $("example").appendChild(o);
  }
  const linked = location.hash ? await fromFragment(location.hash).catch(() => null) : null;
  if (linked) return load(linked.text, linked.fmt, "linked-model");
  if (opening.model) {
    if (opening.examples.includes(opening.name)) $("example").value = opening.name;
    return load(opening.model, opening.format, opening.name);
  }
  const first = opening.examples.find((n) => n === "four_bar.yaml") || opening.examples[0];
  if (first) {
    $("example").value = first;
    const ex = await get(`/api/examples/${encodeURIComponent(first)}`);
    return load(ex.model, ex.format, ex.name);
  }
  load("", "yaml", "model");
}

start();
