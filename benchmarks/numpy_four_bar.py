"""The practical limit for Python: a four-bar written by hand in closed form with numpy.

Crank-rocker: ground O2O4 = 4, crank O2A = 1, coupler AB = 4, rocker O4B = 3; coupler point
P at 2 along AB and 1 to its left. Every position at once: positions, velocities and
accelerations of A, B, P and ω, α of the three moving bodies (O2, O4 are fixed).
"""
from __future__ import annotations

import numpy as np

GROUND, CRANK, COUPLER, ROCKER = 4.0, 1.0, 4.0, 3.0
ALONG, LEFT = 2.0, 1.0


def four_bar(theta: np.ndarray, w2: float = 10.0, a2: float = 0.0) -> dict[str, np.ndarray]:
    """Open branch (B above the ground line); θ the crank angle from O2O4 (radians)."""
    c2, s2 = np.cos(theta), np.sin(theta)
    ax, ay = CRANK * c2, CRANK * s2
    vax, vay = -w2 * ay, w2 * ax
    aax, aay = -a2 * ay - w2 * w2 * ax, a2 * ax - w2 * w2 * ay
    # B: circle of radius COUPLER about A meets circle of radius ROCKER about O4
    dx, dy = GROUND - ax, -ay
    d2 = dx * dx + dy * dy
    f = (COUPLER ** 2 - ROCKER ** 2 + d2) / (2 * d2)
    h = np.sqrt(COUPLER ** 2 / d2 - f * f)
    bx, by = ax + f * dx - h * dy, ay + f * dy + h * dx
    r3x, r3y = bx - ax, by - ay                   # A -> B
    r4x, r4y = bx - GROUND, by                    # O4 -> B
    det = r3x * r4y - r3y * r4x
    # w3 k×r3 − w4 k×r4 = −v_A ; α3 k×r3 − α4 k×r4 = −a_A + w3² r3 − w4² r4
    w3 = -(vax * r4x + vay * r4y) / det
    w4 = -(vax * r3x + vay * r3y) / det
    rx, ry = -aax + w3 * w3 * r3x - w4 * w4 * r4x, -aay + w3 * w3 * r3y - w4 * w4 * r4y
    al3 = (rx * r4x + ry * r4y) / det
    al4 = (rx * r3x + ry * r3y) / det
    vbx, vby = -w4 * r4y, w4 * r4x
    abx, aby = -al4 * r4y - w4 * w4 * r4x, al4 * r4x - w4 * w4 * r4y
    # P: ALONG along AB and LEFT to its left
    ux, uy = r3x / COUPLER, r3y / COUPLER
    px, py = ax + ALONG * ux - LEFT * uy, ay + ALONG * uy + LEFT * ux
    qx, qy = px - ax, py - ay
    vpx, vpy = vax - w3 * qy, vay + w3 * qx
    apx, apy = aax - al3 * qy - w3 * w3 * qx, aay + al3 * qx - w3 * w3 * qy
    return {"A": (ax, ay, vax, vay, aax, aay), "B": (bx, by, vbx, vby, abx, aby),
            "P": (px, py, vpx, vpy, apx, apy), "w3": w3, "w4": w4, "a3": al3, "a4": al4}


def script(n: int) -> None:
    """A whole process doing `kinematika sweep --json`'s work by hand: n positions of a crank
    turn, every point's position, velocity and acceleration and every body's ω, α, as JSON on
    standard output (the standard library's writer, as a script would)."""
    import json
    import sys

    coordinate = np.linspace(0, 360, n)
    out = four_bar(np.radians(90 + coordinate))
    points = {name: {"position": np.column_stack(out[name][:2]).tolist(),
                     "velocity": np.column_stack(out[name][2:4]).tolist(),
                     "acceleration": np.column_stack(out[name][4:]).tolist()} for name in "ABP"}
    bodies = {"coupler": {"omega": out["w3"].tolist(), "alpha": out["a3"].tolist()},
              "rocker": {"omega": out["w4"].tolist(), "alpha": out["a4"].tolist()}}
    sys.stdout.write(json.dumps({"coordinate": coordinate.tolist(), "bodies": bodies, "points": points}))


if __name__ == "__main__":
    import sys
    import timeit

    if len(sys.argv) == 3 and sys.argv[1] == "json":
        script(int(sys.argv[2]))
        sys.exit()

    theta = np.radians(90 + np.linspace(0, 360, 3601))
    best = min(timeit.repeat(lambda: four_bar(theta), number=20, repeat=10)) / 20
    print(f"{best * 1e3:.3f} ms for {theta.size} positions ({best / theta.size * 1e6:.3f} us each)")
