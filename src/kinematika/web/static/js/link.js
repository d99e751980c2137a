// A link that holds the model itself: its text deflated and base64url-encoded in the
// URL's fragment (which browsers never send to a server), reopened by any running app.

const KEY = "model=";

async function pipe(bytes, stream) {
  const out = new Blob([bytes]).stream().pipeThrough(stream);
  return new Uint8Array(await new Response(out).arrayBuffer());
}

function toBase64Url(bytes) {
  let s = "";
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}

function fromBase64Url(text) {
  const s = atob(text.replace(/-/g, "+").replace(/_/g, "/"));
  return Uint8Array.from(s, (c) => c.charCodeAt(0));
}

/** The fragment (without '#') for a model's text and format. */
export async function fragment(text, fmt) {
  const packed = await pipe(new TextEncoder().encode(text), new CompressionStream("deflate-raw"));
  return `format=${fmt}&${KEY}${toBase64Url(packed)}`;
}

/** The model a fragment holds ({text, fmt}), or null. */
export async function fromFragment(hash) {
  const params = new URLSearchParams(hash.replace(/^#/, ""));
  const packed = params.get("model");
  if (!packed) return null;
  const bytes = await pipe(fromBase64Url(packed), new DecompressionStream("deflate-raw"));
  return { text: new TextDecoder().decode(bytes), fmt: params.get("format") || "yaml" };
}
