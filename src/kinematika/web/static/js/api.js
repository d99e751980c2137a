// The page's calls to the JSON API (see docs/app.md): every answer is the CLI's.

/** An API error: the contract's {kind, message, where} and the HTTP status; `partial`, the
 * rows a simulation computed before it stopped (or null); `dof` and `conditions`, a
 * mechanism left free's degrees of freedom and its drivers' conditions (else undefined). */
export class ApiError extends Error {
  constructor(status, error, partial = null) {
    super(error.message);
    this.status = status;
    this.kind = error.kind;
    this.where = error.where || "";
    this.partial = partial;
    this.dof = error.dof;
    this.conditions = error.conditions;
  }
}

/** Pauses before a request that failed before any answer is sent again (milliseconds). */
const RESEND_MS = [0, 250, 1000];

/** POST `body` to /api/`endpoint`; the answer as JSON, text or a Blob (`as`). A request
 * that fails before any answer (a kept-alive connection the server closed as it was sent,
 * which a browser does not retry for a POST; a connection refused by a server too busy to
 * accept it) is sent again, up to three times after the pauses of `RESEND_MS`: every
 * endpoint's answer is a function of the body alone, so asking again is safe. */
export async function post(endpoint, body, as = "json") {
  const init = { method: "POST", headers: { "Content-Type": "application/json" }, body: JSON.stringify(body) };
  const response = await send(`/api/${endpoint}`, init);
  if (!response.ok) {
    let error = { kind: "internal", message: `HTTP ${response.status}`, where: "" }, partial = null;
    try {
      const body = await response.json();
      error = body.error || error;
      partial = body.partial || null;
    } catch (_) { /* not JSON: keep the status */ }
    throw new ApiError(response.status, error, partial);
  }
  if (as === "blob") return response.blob();
  if (as === "text") return response.text();
  return response.json();
}

/** `fetch`, sent again after each pause of `RESEND_MS` while it fails before any answer;
 * the last failure is thrown as it came. */
async function send(url, init) {
  for (let k = 0; ; k++) {
    try {
      return await fetch(url, init);
    } catch (err) {
      if (k === RESEND_MS.length) throw err;
      await new Promise((r) => setTimeout(r, RESEND_MS[k]));
    }
  }
}

/** GET a JSON resource of the page (the starting model, a bundled example). */
export async function get(path) {
  const response = await send(path, {});
  if (!response.ok) throw new ApiError(response.status, { kind: "usage", message: `HTTP ${response.status}` });
  return response.json();
}
