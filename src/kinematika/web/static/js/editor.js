// The model editor: a plain textarea with line numbers, the error's line marked.

const DEBOUNCE_MS = 250;
const MEASURED_LINES = 3000;     // a longer text is numbered as if no line wrapped

export class Editor {
  constructor(textarea, gutter, mark, onChange) {
    this.area = textarea;
    this.gutter = gutter;
    this.mark = mark;
    this.badLine = null;
    this.timer = null;
    this.area.addEventListener("input", () => {
      this.numberLines();
      clearTimeout(this.timer);
      this.timer = setTimeout(() => onChange(this.text), DEBOUNCE_MS);
    });
    this.area.addEventListener("scroll", () => this.follow());
    this.area.addEventListener("keydown", (e) => this.indent(e));
    this.rows = null;                            // screen rows of each line, when lines wrap
    let width = 0;
    new ResizeObserver(() => {
      if (this.area.clientWidth !== width) { width = this.area.clientWidth; this.numberLines(); }
    }).observe(this.area);
  }

  get text() { return this.area.value; }

  /** Replace the text (keeping the scroll position), as a load or a drag does. */
  set text(value) {
    const top = this.area.scrollTop;
    this.area.value = value;
    this.area.scrollTop = top;
    this.numberLines();
  }

  numberLines() {
    const text = this.area.value.split("\n");
    this.rows = this.measure(text);
    const lines = [];
    for (let i = 1; i <= text.length; i++) {
      lines.push(i === this.badLine ? `<span class="bad">${i}</span>` : String(i));
      for (let r = 1; r < (this.rows ? this.rows[i - 1] : 1); r++) lines.push("");    // its wrapped rows
    }
    this.gutter.innerHTML = lines.join("\n") + "\n";
    this.follow();
  }

  /** How many screen rows each line takes when the text wraps (a narrow screen: app.css),
   * measured on a hidden copy of the text area's lines; null when lines do not wrap. */
  measure(lines) {
    const style = getComputedStyle(this.area);
    if (style.whiteSpace === "pre" || lines.length > MEASURED_LINES || !this.area.clientWidth) return null;
    const copy = document.createElement("div");
    for (const k of ["font", "letterSpacing", "tabSize", "whiteSpace", "overflowWrap", "wordBreak", "paddingLeft", "paddingRight"]) {
      copy.style[k] = style[k];
    }
    Object.assign(copy.style, { position: "absolute", visibility: "hidden", left: "-10000px", top: "0",
                                width: `${this.area.clientWidth}px`, boxSizing: "border-box" });
    for (const line of lines) {
      const d = document.createElement("div");
      d.textContent = line || "\u200b";
      copy.appendChild(d);
    }
    document.body.appendChild(copy);
    const h = parseFloat(style.lineHeight) || 19;
    const rows = [...copy.children].map((d) => Math.max(1, Math.round(d.getBoundingClientRect().height / h)));
    copy.remove();
    return rows;
  }

  follow() {
    this.gutter.scrollTop = this.area.scrollTop;
    if (this.badLine) {
      const h = parseFloat(getComputedStyle(this.area).lineHeight) || 19;
      const before = this.rows ? this.rows.slice(0, this.badLine - 1).reduce((a, b) => a + b, 0) : this.badLine - 1;
      this.mark.style.top = `${8 + before * h - this.area.scrollTop}px`;
    }
  }

  /** Mark line `line` (1-based) as the error's place, or none. */
  markLine(line) {
    this.badLine = line || null;
    this.mark.hidden = !this.badLine;
    this.numberLines();
  }

  /** Two spaces for Tab (a model is indented with spaces). */
  indent(e) {
    if (e.key !== "Tab" || e.shiftKey || e.ctrlKey || e.metaKey) return;
    e.preventDefault();
    const { selectionStart: s, selectionEnd: t, value } = this.area;
    this.area.value = value.slice(0, s) + "  " + value.slice(t);
    this.area.selectionStart = this.area.selectionEnd = s + 2;
    this.area.dispatchEvent(new Event("input"));
  }
}

/** The line (1-based) an error points at: the line its message names, else the line of
 * its place (`points.A`, `joints[2] (j3)`, `drivers[0]`, `ask[1]`) in a YAML or TOML text. */
export function errorLine(text, error) {
  const said = /line (\d+)/.exec(error.message || "");
  if (said) return Number(said[1]);
  const where = (error.where || "").trim();
  const m = /^([A-Za-z_]+)(?:\[(\d+)\]|\.([^\s.]+))?/.exec(where);
  if (!m) return null;
  const lines = text.split("\n");
  const section = m[1];
  const start = lines.findIndex((l) => new RegExp(`^["']?${section}["']?\\s*[:=]|^\\[\\[?${section}\\]`).test(l));
  if (start < 0) return null;
  if (m[3] !== undefined) {            // points.A: the key inside the section
    const key = m[3].replace(/[.*+?^${}()|[\]\\]/g, "\\$&");
    const re = new RegExp(`^\\s*["']?${key}["']?\\s*[:=]|[{,]\\s*["']?${key}["']?\\s*:`);
    for (let i = start; i < lines.length; i++) if (re.test(lines[i])) return i + 1;
    return start + 1;
  }
  if (m[2] !== undefined) {            // joints[2]: the item of the list
    const want = Number(m[2]);
    const inline = lines[start].slice(lines[start].indexOf(":") + 1).trim();
    if (inline.startsWith("[")) return start + 1;
    let count = -1;
    for (let i = start + 1; i < lines.length; i++) {
      if (/^\S/.test(lines[i]) && !lines[i].startsWith("-") && !lines[i].startsWith("#")) break;
      if (/^\s*-\s/.test(lines[i]) || /^\s*-$/.test(lines[i]) || /^\[\[/.test(lines[i])) {
        count += 1;
        if (count === want) return i + 1;
      }
    }
  }
  return start + 1;
}
