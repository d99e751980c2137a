"""`kinematika simulate` of the tractor and trailer over 60 s (examples/tractor_trailer_turning.yaml:
300 steps) next to a plain numpy/scipy script of the same ODE, in one run.

    .venv/bin/python benchmarks/simulate.py            # about a minute on 2 busy cores
    .venv/bin/python benchmarks/simulate.py --repeat 3 --methods DOP853

The peer is the vehicle written by hand: the state (x, y, ψ) of the rear axle's middle R and
the tractor's heading, and the trailer's heading ψ_t; with the rear axle driven at v along
the tractor and the steering δ held, ψ' = v tan δ / wb, R' = v e(ψ), and the trailer's knife
edge at T = H − L e(ψ_t) gives ψ_t' = v_H · e⊥(ψ_t) / L, v_H = v e(ψ) − h ψ' e⊥(ψ). It is
integrated by the same solver with the same tolerances and rows, and then computes what
kinematika's rows hold (every point's position, velocity and acceleration, every body's
angle, ω and α) with numpy, from the same formulas differentiated. kinematika solves each
instant with its engine (the model's rows, a least-squares solve), so the ratio is the
price of the one engine against a script that knows the answer's formulas.

Times are CPU times (best of `--repeat`), so that other work on the shared machine counts
less; the load average at the start and the end is printed with them.
"""
from __future__ import annotations

import argparse
import math
import os
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
MODEL = HERE.parent / "examples" / "tractor_trailer_turning.yaml"
V, WB, STEER, H, L = 2.0, 2.5, math.radians(20.0), 1.0, 4.0
RTOL = 1e-10


def numpy_vehicle(method: str, steps: int = 300, duration: float = 60.0) -> dict:
    """The tractor and trailer by hand (see the module): rows of every point's motion."""
    from scipy.integrate import solve_ivp

    w = V * math.tan(STEER) / WB

    def rates(t: float, s: np.ndarray) -> np.ndarray:
        psi, trail = s[2], s[3]
        e, n = np.array([math.cos(psi), math.sin(psi)]), np.array([-math.sin(psi), math.cos(psi)])
        vh = V * e - H * w * n
        return np.array([V * e[0], V * e[1], w, (vh @ [-math.sin(trail), math.cos(trail)]) / L])

    times = np.linspace(0.0, duration, steps + 1)
    atol = np.array([RTOL * 5, RTOL * 5, RTOL, RTOL])
    sol = solve_ivp(rates, (0.0, duration), np.array([0.0, 0.0, 0.0, math.pi * 0.0]), method=method,
                    t_eval=times, rtol=RTOL, atol=atol)
    x, y, psi, trail = sol.y
    e = np.stack([np.cos(psi), np.sin(psi)], 1)
    n = np.stack([-np.sin(psi), np.cos(psi)], 1)
    et = np.stack([np.cos(trail), np.sin(trail)], 1)
    nt = np.stack([-np.sin(trail), np.cos(trail)], 1)
    r = np.stack([x, y], 1)
    hitch = r - H * e
    vh = V * e - H * w * n
    wt = np.einsum("ij,ij->i", vh, nt) / L
    ah = V * w * n + H * w * w * e                     # d/dt of v e − h w n, with w constant
    # ψ_t'' from d/dt (v_H · n_t) / L: (a_H · n_t − wt v_H · e_t) / L
    alt = (np.einsum("ij,ij->i", ah, nt) - wt * np.einsum("ij,ij->i", vh, et)) / L
    out = {"R": (r, V * e, V * w * n), "F": (r + WB * e, V * e + WB * w * n, V * w * n - WB * w * w * e),
           "H": (hitch, vh, ah)}
    out["T"] = (hitch - L * et, vh - L * wt[:, None] * nt,
                ah - L * alt[:, None] * nt + L * (wt * wt)[:, None] * et)
    out["bodies"] = {"tractor": (np.degrees(psi), np.full(len(psi), w), np.zeros(len(psi))),
                     "trailer": (np.degrees(trail), wt, alt)}
    return {"rows": out, "evaluations": sol.nfev}


def best(fn, repeat: int) -> tuple[float, object]:
    """The best CPU time of `repeat` calls, and the last call's answer."""
    times, answer = [], None
    for _ in range(repeat):
        t0 = time.process_time()
        answer = fn()
        times.append(time.process_time() - t0)
    return min(times), answer


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--methods", nargs="+", default=["DOP853", "RK45", "LSODA"])
    args = parser.parse_args()
    import scipy.integrate  # noqa: F401  (imported before timing, by both sides)

    from kinematika.simulate import run_simulation

    load = os.getloadavg()[0]
    print(f"tractor and trailer over 60 s, 301 rows; load average {load:.2f} at the start")
    print(f"{'method':<8}{'kinematika (s)':>16}{'solutions':>11}{'numpy/scipy (s)':>17}{'solutions':>11}"
          f"{'ratio':>8}{'  T@trailer agree to':>22}")
    for method in args.methods:
        ours, result = best(lambda: run_simulation(MODEL, method=method), args.repeat)
        peer, hand = best(lambda: numpy_vehicle(method), args.repeat)
        position = np.asarray(result.points["T@trailer"]["position"])
        agree = float(np.abs(position - hand["rows"]["T"][0]).max())
        print(f"{method:<8}{ours:>16.3f}{result.evaluations:>11}{peer:>17.4f}{hand['evaluations']:>11}"
              f"{ours / peer:>8.0f}{agree:>22.1e}")
    print(f"load average {os.getloadavg()[0]:.2f} at the end; target: kinematika under 1 s (DOP853)")


if __name__ == "__main__":
    main()
