// A body's angle as a textbook gives it, the one the page's table, its plot and the command
// line's sweep (`kinematika.sweep.angles`) all give: θ, the body's line from the x axis,
// counter-clockwise; and the input on the same footing, the crank's angle θ when the sweep
// turns a crank from the frame, else the driven joint's coordinate from the drawn position.

/** A body's reference line as the scene gives it (`sweep.angles.reference_line`, the one
 * the command line's sweep measures θ along): from its fixed pivot, else its first point, to
 * the first other point drawn elsewhere (a rocker's O4 → B), with its angle from the x axis,
 * counter-clockwise, in (−180°, 180°]; null for the frame, a body with one place, or 3D. */
export function referenceLine(body) {
  return (body && body.reference) || null;
}

/** Every planar body's angle θ at every row of the sweep: its drawn θ plus its rotation
 * since the drawn position (a body with no line is left out). */
export function textbookAngles(scene, sweep) {
  const out = {};
  if (!scene || !sweep || scene.dimension !== 2) return out;
  for (const [name, b] of Object.entries(sweep.bodies)) {
    const line = referenceLine(scene.bodies[name]);
    if (!line || Array.isArray(b.angle.find((x) => x !== null))) continue;
    const a0 = b.angle[0] ?? 0;
    out[name] = b.angle.map((x) => (x === null ? null : Number((line.angle + x - a0).toFixed(9))));
  }
  return out;
}

/** The input as the plot's axis: the angle θ of the crank the sweep turns from the frame
 * (`driver`), else the joint's coordinate. */
export function inputAxis(scene, sweep, angles) {
  const xs = sweep.coordinate;
  for (const [name, theta] of Object.entries(angles)) {
    const line = referenceLine(scene.bodies[name]);
    if (!line || !line.grounded || !sweep.bodies[name]) continue;
    const rot = sweep.bodies[name].angle;
    if (rot.every((r, k) => r === null || Math.abs(r - (rot[0] ?? 0) - (xs[k] - xs[0])) < 1e-6)) {
      return { x: xs.map((c, k) => (theta[k] === null ? theta[0] + c - xs[0] : theta[k])), driver: name };
    }
  }
  return { x: xs, driver: null };
}
