// Turning the mechanism by hand: a dragged point is followed along the sweep's rows (the
// positions the page already has), from the row shown to the row where the point is
// nearest the pointer, one step at a time, so that the mechanism moves as it can move: it
// stops at a row the pointer cannot pull it past (a limit of the point's path), never jumps
// over rows it cannot assemble, and goes round when the sweep closes on itself (a full
// turn). The model is not changed. Wherever the sweep's rows go (through a limit position,
// the input reversing), the hand goes with them.

/** The sweep's key of a material point of `name` that moves (`B@rod`), or null when the
 * point is only on the frame (it does not move). */
export function movingKey(sweep, name, frame) {
  const keys = Object.keys(sweep.points).filter((k) => k.split("@")[0] === name && k.split("@")[1] !== frame);
  return keys.find((k) => moves(sweep.points[k].position)) || null;
}

function moves(path) {
  const first = path.find(Boolean);
  return !!first && path.some((p) => p && Math.hypot(p[0] - first[0], p[1] - first[1]) > 0);
}

/** Whether the sweep's last row is its first again (a full turn): every point is back. */
export function closes(sweep) {
  const n = sweep.coordinate.length;
  if (n < 3) return false;
  let size = 0, gap = 0;
  for (const v of Object.values(sweep.points)) {
    const a = v.position[0], b = v.position[n - 1];
    if (!a || !b) return false;
    size = Math.max(size, ...a.map(Math.abs));
    gap = Math.max(gap, ...a.map((x, i) => Math.abs(x - b[i])));
  }
  return gap <= 1e-9 * Math.max(size, 1e-300);
}

/** The row the point `key` is moved to when the pointer is at `at`, from row `k`: a descent
 * along the rows, each step to the nearest row within `reach` rows on either side (a small
 * bump of the distance does not stop it), through assembled rows only. */
export function followRow(sweep, key, at, k, cyclic = closes(sweep)) {
  const path = sweep.points[key].position;
  const n = path.length, m = cyclic ? n - 1 : n;
  const reach = Math.max(3, Math.round(m / 36));
  const far = (j) => (path[j] ? Math.hypot(path[j][0] - at[0], path[j][1] - at[1]) : Infinity);
  let best = cyclic ? k % m : k;
  for (let steps = 0; steps < m; steps++) {
    let next = best;
    for (const way of [-1, 1]) {
      for (let s = 1; s <= reach; s++) {
        let j = best + way * s;
        if (cyclic) j = ((j % m) + m) % m;
        else if (j < 0 || j >= n) break;
        if (!path[j]) break;                       // not assembled: the mechanism cannot pass
        if (far(j) < far(next)) next = j;
      }
    }
    if (next === best) break;
    best = next;
  }
  return best;
}
