// Small helpers to build SVG and to format numbers.
const NS = "http://www.w3.org/2000/svg";

/** An SVG element with attributes, appended to `parent` when given. */
export function el(name, attrs = {}, parent = null) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) {
    if (v !== null && v !== undefined) node.setAttribute(k, v);
  }
  if (parent) parent.appendChild(node);
  return node;
}

// C0 and C1 controls, DEL, line and paragraph separators, bidirectional controls: what
// kinematika.text.shown escapes in the command line's tables (lone surrogates never reach
// the page: the server refuses them).
const UNSAFE = /[\x00-\x1f\x7f-\x9f\u2028\u2029\u200e\u200f\u202a-\u202e\u2066-\u2069]/g;
const NAMED = { "\n": "\\n", "\r": "\\r", "\t": "\\t" };
export const NAME_CHARS = 200;    // kinematika.limits.NAME_CHARS: a name is shown cut there

/** A name (untrusted text) as one printable line, as the command line shows it: control
 * characters and bidirectional overrides written as escapes (\x1b, \u202e), cut to `limit`
 * characters with …. Shown through textContent, never as markup. */
export function shown(text, limit = NAME_CHARS) {
  let s = String(text).replace(UNSAFE, (c) => NAMED[c] ||
    (c.charCodeAt(0) < 0x100 ? `\\x${c.charCodeAt(0).toString(16).padStart(2, "0")}`
                             : `\\u${c.charCodeAt(0).toString(16).padStart(4, "0")}`));
  if (s.length > limit) s = s.slice(0, limit - 1) + "…";
  return s;
}

/** A label from runs ([{t: "v"}, {sub: "B"}, {t: " = 9.25"}]) as SVG tspans. A line break
 * in a text run (a group of coincident centres written a few to a line, as matplotlib
 * writes it) starts a new line: the next tspan is marked `data-line`, one line lower, and
 * `placeLines` puts it at the text's x (an empty tspan would not move the text: the break
 * goes on the first one with characters). */
export function runsText(parent, runs, attrs) {
  const text = el("text", attrs, parent);
  let broken = false;
  const span = (content, more = {}) => {
    const s = el("tspan", broken ? { ...more, dy: "1.2em", "data-line": "" } : more, text);
    s.textContent = shown(content);
    broken = false;
  };
  for (const run of runs) {
    if (run.sub !== undefined) {
      span(run.sub, { "baseline-shift": "sub", "font-size": "75%" });
      continue;
    }
    String(run.t).split("\n").forEach((line, i) => {
      if (i > 0) broken = true;
      if (line) span(line);
    });
  }
  return text;
}

/** A text's later lines at its x (SVG does not break lines itself). */
export function placeLines(text) {
  for (const line of text.querySelectorAll("tspan[data-line]")) line.setAttribute("x", text.getAttribute("x"));
}

let DECIMAL = ".";          // the page's language's decimal mark (i18n.js sets it)

/** Write numbers with `mark` as the decimal mark ("," in es, ca, eu, as the explanations do);
 * the components of a vector are then separated by "; ". */
export function setDecimal(mark) { DECIMAL = mark; }

/** Components of a vector, as text: "(1.5, 2)" or "(1,5; 2)". */
export function pair(values) { return "(" + values.join(DECIMAL === "," ? "; " : ", ") + ")"; }

/** `x` with 4 significant digits, round-off below 1e-9 of `scale` as 0, no trailing zeros. */
export function num(x, scale = 0) {
  if (x === null || x === undefined || Number.isNaN(x)) return "–";
  if (typeof x === "string") return x;
  if (Math.abs(x) <= 1e-9 * scale || x === 0) return "0";
  const a = Math.abs(x);
  let s = a >= 1e-3 && a < 1e6 ? x.toPrecision(4) : x.toExponential(3);
  if (s.includes("e")) {
    const [m, e] = s.split("e");
    s = trim(m) + "e" + e.replace("+", "");
  } else s = trim(s);
  return s.replace("-", "−").replace(".", DECIMAL);
}

function trim(s) {
  return s.includes(".") ? s.replace(/0+$/, "").replace(/\.$/, "") : s;
}

/** A vector or a number, formatted. */
export function show(v, scale = 0) {
  if (Array.isArray(v)) return pair(v.map((c) => num(c, scale)));
  return num(v, scale);
}

/** The round step at least `raw`: 1, 2 or 5 × 10^k (an axis's ticks, the builder's grid). */
export function niceStep(raw) {
  const k = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * k).find((s) => s >= raw) || 10 * k;
}
