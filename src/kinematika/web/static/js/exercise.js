// The page's exercise mode (docs/exercises.md): a link `#exercise=1&format=…&model=…&vary=…
// &seed=…&variant=…&lang=…` opens one variant of the model's exercise as the whole page (js/boot.js
// starts this script instead of the builder's): its statement and figure and a box for each
// number asked — no model editor, no answers, nothing that solves. The typed numbers are
// checked by POST /api/exercise, which marks each one as `kinematika grade` does (right within
// its margin, the usual mistake it shows, or following from an earlier answer); after a check
// the worked solution can be shown. Every word comes from the server, in the class's language.
import { post } from "./api.js";
import { fragment, fromFragment } from "./link.js";

const params = new URLSearchParams(location.hash.replace(/^#/, ""));

function element(tag, attrs = {}, ...children) {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (k === "text") el.textContent = v;
    else el.setAttribute(k, v);
  }
  for (const child of children) el.append(child);
  return el;
}

/** The exercise a fragment holds, or null. */
async function linked() {
  if (!params.has("exercise")) return null;
  const model = await fromFragment(location.hash).catch(() => null);
  if (!model) return null;
  return { model: model.text, format: model.fmt, vary: params.getAll("vary"),
           seed: Number(params.get("seed") || 0), variant: Number(params.get("variant") || 1),
           lang: params.get("lang") || "en" };
}

/** The link (fragment) of an exercise's variant. */
async function link(ex, variant) {
  const query = new URLSearchParams({ exercise: "1" });
  for (const v of ex.vary) query.append("vary", v);
  query.set("seed", String(ex.seed));
  query.set("variant", String(variant));
  query.set("lang", ex.lang);
  return `#${query.toString()}&${await fragment(ex.model, ex.format)}`;
}

function request(ex, extra = {}) {
  return { model: ex.model, format: ex.format, vary: ex.vary, seed: ex.seed, variant: ex.variant,
           lang: ex.lang, ...extra };
}

/** The page made the exercise alone: the builder's markup (editor, answers, menus) removed. */
function alone(ex) {
  document.documentElement.lang = ex.lang;
  for (const sheet of document.querySelectorAll('link[rel="stylesheet"]')) sheet.remove();
  document.head.append(element("link", { rel: "stylesheet", href: "/static/exercise.css" }));
  const panel = element("main", { class: "exercise", "data-testid": "exercise" });
  document.body.replaceChildren(panel);
  return panel;
}

async function open(ex) {
  const panel = alone(ex);
  let shown;
  try {
    shown = await post("exercise", request(ex));
  } catch (err) {
    panel.append(element("p", { class: "exercise-error", "data-testid": "exercise-error", text: err.message }));
    return;
  }
  document.title = `${shown.title} — ${shown.words.variant}`;
  const inputs = new Map();
  const list = element("ol", { class: "exercise-asks" });
  for (const ask of shown.asks) {
    const item = element("li", { value: String(ask.number) }, element("span", { class: "words", text: ask.words }));
    for (const part of ask.parts) {
      const box = element("input", { type: "text", inputmode: "decimal", autocomplete: "off",
                                      "aria-label": `${ask.words} ${part.words}`.trim(),
                                      placeholder: shown.words["page-your-answer"],
                                      "data-testid": `exercise-input-${part.question}` });
      const mark = element("span", { class: "mark", "data-testid": `exercise-mark-${part.question}` });
      inputs.set(part.question, { box, mark });
      item.append(element("label", { class: "part" },
                          part.words ? `${part.words} = ` : "= ", box, ` ${part.unit} `, mark));
    }
    list.append(item);
  }
  const statement = element("div", { class: "statement" });
  statement.innerHTML = shown.statement;           // the server's HTML, its text escaped there
  const check = element("button", { type: "button", "data-testid": "exercise-check", text: shown.words["page-check"] });
  const reveal = element("button", { type: "button", "data-testid": "exercise-show", text: shown.words["page-show"] });
  reveal.hidden = true;
  const score = element("span", { class: "score", "data-testid": "exercise-score" });
  const solution = element("div", { class: "solution", "data-testid": "exercise-solution" });
  const here = element("a", { "data-testid": "exercise-link", href: await link(ex, ex.variant),
                              text: shown.words["page-link"] });
  panel.append(
    element("header", {}, element("h1", { text: shown.title }), element("span", { class: "variant", text: shown.words.variant }), here),
    statement, element("img", { src: shown.figure, alt: shown.title, class: "figure" }),
    element("p", { class: "note", text: shown.note }), element("h2", { text: shown.words["sheet-find"] }),
    list, element("p", { class: "actions" }, check, " ", score, " ", reveal), solution);

  let checked = null;                             // the answers of the last check
  const typed = () => {
    const answers = {};
    for (const [question, { box }] of inputs) if (box.value.trim()) answers[question] = box.value.trim();
    return answers;
  };
  check.addEventListener("click", async () => {
    const answers = typed();
    check.disabled = true;
    try {
      const marked = await post("exercise", request(ex, { answers }));
      for (const { mark, box } of inputs.values()) { mark.textContent = ""; box.className = ""; delete mark.dataset.diagnosis; }
      for (const m of marked.marks) {
        const { box, mark } = inputs.get(m.question);
        box.className = m.correct ? "right" : "wrong";
        mark.textContent = `${m.correct ? "✔" : "✘"} ${m.feedback}`;
        mark.className = `mark ${m.correct ? "right" : "wrong"}`;
        if (m.diagnosis) mark.dataset.diagnosis = m.diagnosis;
      }
      score.textContent = marked.score.text;
      checked = answers;
      reveal.hidden = Object.keys(answers).length === 0;
    } catch (err) {
      score.textContent = err.message;
    } finally {
      check.disabled = false;
    }
  });
  reveal.addEventListener("click", async () => {
    if (!checked) return;
    reveal.disabled = true;
    const answered = await post("exercise", request(ex, { answers: checked, reveal: true }));
    const frame = element("iframe", { title: shown.words["page-show"], sandbox: "allow-same-origin" });
    frame.srcdoc = `<!DOCTYPE html><meta charset="utf-8"><body style="font-family:serif">${answered.solution}</body>`;
    solution.replaceChildren(frame);
    frame.addEventListener("load", () => { frame.style.height = `${frame.contentDocument?.body?.scrollHeight || 2000}px`; });
  });
}

linked().then((ex) => { if (ex) open(ex); });
