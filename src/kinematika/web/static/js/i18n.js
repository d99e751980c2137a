// The page's words in the student's language: the catalogues (web/locales/LANG.ftl) served
// as JSON by /api/strings/LANG; one choice sets the page's language and the explanation's,
// kept between visits (localStorage). Elements name their words by attributes:
// data-i18n (text), data-i18n-title (tooltip), data-i18n-label (aria-label).
import { setDecimal } from "./svg.js";

/** The languages the page offers: its language menu's (index.html, kept equal to
 * kinematika.languages.LANGS by tests/web/test_static_lists.py). */
export const LANGS = [...document.querySelectorAll("#ui-language option")].map((o) => o.value);
const KEY = "kinematika.lang";
let words = {};
let lang = "en";

/** The language remembered, else the browser's when the page has it, else English. */
export function chosen() {
  let saved = null;
  try { saved = localStorage.getItem(KEY); } catch (_) { /* storage off */ }
  if (LANGS.includes(saved)) return saved;
  const browser = (navigator.language || "en").slice(0, 2);
  return LANGS.includes(browser) ? browser : "en";
}

/** Load a language's words and write them into the page. */
export async function use(code) {
  const response = await fetch(`/api/strings/${code}`);
  if (!response.ok) throw new Error(`no words for ${code}`);
  const data = await response.json();
  words = data.messages;
  lang = code;
  setDecimal(data.decimal);
  try { localStorage.setItem(KEY, code); } catch (_) { /* storage off */ }
  document.documentElement.lang = code;
  translate(document);
  return data;
}

export function current() { return lang; }

/** A message with its variables ({ $name } in the catalogue) filled in. */
export function t(id, args = {}) {
  const pattern = words[id];
  if (pattern === undefined) return id;
  return pattern.replace(/\{\$(\w+)\}/g, (_, k) => (args[k] !== undefined ? String(args[k]) : ""));
}

/** Write the words of every marked element under `root`. */
export function translate(root) {
  for (const node of root.querySelectorAll("[data-i18n]")) node.textContent = t(node.dataset.i18n);
  for (const node of root.querySelectorAll("[data-i18n-title]")) node.title = t(node.dataset.i18nTitle);
  for (const node of root.querySelectorAll("[data-i18n-label]")) node.setAttribute("aria-label", t(node.dataset.i18nLabel));
}
