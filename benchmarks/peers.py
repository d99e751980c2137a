"""The peers' versions of the benchmark cases: pylinkage, `mechanism` and sympy (run in .venv-bench).

Each `*_work(n)` function does the benchmark's work for n positions of a crank turn at
10 rad/s: positions, velocities and accelerations of every point and ω, α of every body
(the peers give points only; ω and α of a link follow from two of its points:
ω = (r × Δv)/|r|², α = (r × Δa)/|r|², done with numpy). Build functions are not timed.
Run as a script (`python peers.py TOOL CASE N`) it is a peer's whole process, for timing.
`python peers.py sympy four_bar_general 0` derives by hand with sympy what
`kinematika solve benchmarks/models/symbolic/four_bar_general.yaml --symbolic` answers.
"""
from __future__ import annotations

import math
import sys

import numpy as np

W = 10.0
BX = (48 + 8 * math.sqrt(2)) / 17          # the crank-rocker's B with the crank at 90°
BY = 4 * BX - 11


def link_rates(p, q, vp, vq, ap, aq):
    """ω, α of the link through points p and q (arrays (n, 2))."""
    r = q - p
    r2 = (r * r).sum(axis=1)
    dv, da = vq - vp, aq - ap
    return ((r[:, 0] * dv[:, 1] - r[:, 1] * dv[:, 0]) / r2, (r[:, 0] * da[:, 1] - r[:, 1] * da[:, 0]) / r2)


# pylinkage ---------------------------------------------------------------------------------
def pylinkage_build(case: str, n: int):
    """The linkage, its crank, and the point pairs of each link (for ω, α)."""
    import pylinkage as pl

    step = 2 * math.pi / n
    if case == "four_bar":
        o2, o4 = pl.Ground(0.0, 0.0, name="O2"), pl.Ground(4.0, 0.0, name="O4")
        crank = pl.Crank(anchor=o2, radius=1.0, angular_velocity=step, initial_angle=math.pi / 2)
        b = pl.RRRDyad(crank.output, o4, distance1=4.0, distance2=3.0, x=BX, y=BY, name="B")
        p = pl.FixedDyad(crank.output, b, distance=math.sqrt(5), angle=math.atan2(1, 2), name="P")
        parts, links = [o2, o4, crank, b, p], [(0, 2), (2, 3), (1, 3)]
    elif case == "slider_crank":
        o, l1, l2 = pl.Ground(0.0, 0.0), pl.Ground(0.0, 0.5), pl.Ground(1.0, 0.5)
        crank = pl.Crank(anchor=o, radius=1.0, angular_velocity=step, initial_angle=math.pi / 2)
        b = pl.RRPDyad(crank.output, l1, l2, distance=3.0, x=math.sqrt(8.75), y=0.5)
        parts, links = [o, l1, l2, crank, b], [(0, 3), (3, 4)]
    elif case == "watt_six_bar":
        o2, o4, o6 = pl.Ground(0.0, 0.0), pl.Ground(4.0, 0.0), pl.Ground(8.0, 0.0)
        crank = pl.Crank(anchor=o2, radius=1.0, angular_velocity=step, initial_angle=math.pi / 2)
        b = pl.RRRDyad(crank.output, o4, distance1=4.0, distance2=3.0, x=BX, y=BY)
        # C on the rocker: 1 from O4 along the ground line when B is drawn
        c = pl.FixedDyad(o4, b, distance=1.0, angle=-math.atan2(BY, BX - 4.0))
        d = pl.RRRDyad(c, o6, distance1=4.0, distance2=3.0, x=23 / 3, y=math.sqrt(80) / 3)
        parts, links = [o2, o4, o6, crank, b, c, d], [(0, 3), (3, 4), (1, 4), (5, 6), (2, 6)]
    elif case == "jansen_leg":
        z, o = pl.Ground(0.0, 0.0), pl.Ground(38.0, 7.8)
        crank = pl.Crank(anchor=o, radius=15.0, angular_velocity=step, initial_angle=math.pi / 2)
        b = pl.RRRDyad(z, crank.output, distance1=41.5, distance2=50.0, x=-8.7357, y=40.5702)
        e = pl.RRRDyad(z, b, distance1=40.1, distance2=55.8, x=-39.6678, y=-5.8717)
        d = pl.RRRDyad(z, crank.output, distance1=39.3, distance2=61.9, x=17.0047, y=-35.4306)
        f = pl.RRRDyad(e, d, distance1=39.4, distance2=36.7, x=-19.4476, y=-39.6874)
        p = pl.RRRDyad(d, f, distance1=49.0, distance2=65.7, x=30.3109, y=-82.5894)
        parts = [z, o, crank, b, e, d, f, p]
        links = [(1, 2), (2, 3), (0, 3), (2, 5), (0, 5), (4, 6), (5, 6)]
    else:
        raise ValueError(case)
    linkage = pl.Linkage(parts, name=case)
    linkage.set_input_velocity(crank, omega=W)
    return linkage, links


def pylinkage_work(linkage, links, n: int, fast: bool):
    """Positions, velocities, accelerations of every point; ω, α of every link."""
    if fast:
        pos, vel, acc = linkage.step_fast_with_kinematics(iterations=n)
    else:
        rows = list(linkage.step_with_derivatives(iterations=n))
        pos = np.array([r[0] for r in rows], dtype=float)
        vel = np.array([r[1] for r in rows], dtype=float)
        acc = np.array([r[2] for r in rows], dtype=float)
    rates = [link_rates(pos[:, i], pos[:, j], vel[:, i], vel[:, j], acc[:, i], acc[:, j]) for i, j in links]
    return pos, vel, acc, rates


# mechanism ---------------------------------------------------------------------------------
def mechanism_build(case: str, n: int):
    """`mechanism`'s loop-equation model of the four-bar or the slider-crank (others: None)."""
    from mechanism import Mechanism, Vector, get_joints

    theta = np.linspace(0, 2 * np.pi, n, endpoint=False) + np.pi / 2
    omega, alpha = np.full(n, W), np.zeros(n)
    if case == "four_bar":
        O, A, B, C = get_joints("O A B C")
        a = Vector((O, A), r=1.0)
        b = Vector((A, B), r=4.0)
        c = Vector((C, B), r=3.0)
        d = Vector((O, C), r=4.0, theta=0, style="ground")
        guess = np.array([math.atan2(BY - 1, BX), math.atan2(BY, BX - 4)])

        def loops(x, i):
            return (a(i) + b(x[0]) - c(x[1]) - d()).flatten()

        vectors = (a, b, c, d)
    elif case == "slider_crank":
        O, A, B, C = get_joints("O A B C")
        a = Vector((O, A), r=1.0)
        b = Vector((A, B), r=3.0)
        c = Vector((C, B), theta=0, style="dotted")
        d = Vector((O, C), r=0.5, theta=np.pi / 2, style="ground")
        guess = np.array([math.atan2(-0.5, math.sqrt(8.75)), math.sqrt(8.75)])

        def loops(x, i):
            return (a(i) + b(x[0]) - c(x[1]) - d()).flatten()

        vectors = (a, b, c, d)
    else:
        return None
    return Mechanism(vectors=vectors, origin=O, loops=loops, pos=theta, vel=omega, acc=alpha,
                     guess=(guess, np.zeros(2), np.zeros(2)))


def mechanism_work(model) -> None:
    model.iterate()


# sympy ---------------------------------------------------------------------------------------
def sympy_four_bar() -> dict:
    """The general four-bar (crank a at angle θ turning at w, coupler b, rocker c, ground d)
    as a user would derive it with sympy: B where the circles about A and O4 meet (the left
    one), the velocity loop a ω₂ k×(A−O2) + ω₃ k×(B−A) − ω₄ k×(B−O4) = 0 solved for ω₃, ω₄,
    differentiated in time for α₃ (θ' = w), each result simplified."""
    import sympy as sp

    a, b, c, d, w = sp.symbols("a b c d w", positive=True)
    th = sp.symbols("theta", real=True)
    ax, ay = a * sp.cos(th), a * sp.sin(th)
    dx, dy = d - ax, -ay
    d2 = dx ** 2 + dy ** 2
    f = (b ** 2 - c ** 2 + d2) / (2 * d2)
    h = sp.sqrt(b ** 2 / d2 - f ** 2)
    bx, by = ax + f * dx - h * dy, ay + f * dy + h * dx
    w3, w4 = sp.symbols("omega3 omega4")
    va = sp.Matrix([-w * ay, w * ax])
    loop = va + w3 * sp.Matrix([-(by - ay), bx - ax]) - w4 * sp.Matrix([-by, bx - d])
    sol = sp.solve(list(loop), [w3, w4], dict=True)[0]
    out = {"omega coupler": sp.simplify(sol[w3]), "omega rocker": sp.simplify(sol[w4])}
    out["alpha coupler"] = sp.simplify(sp.diff(sol[w3], th) * w)
    return out


if __name__ == "__main__":
    tool, case, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
    if tool == "sympy":
        found = sympy_four_bar()
        print({k: len(str(v)) for k, v in found.items()})
    elif tool == "pylinkage":
        linkage, links = pylinkage_build(case, n)
        pos, vel, acc, rates = pylinkage_work(linkage, links, n, fast=len(sys.argv) < 5)
        print(f"{case}: {n} positions, speed up to {np.abs(vel).max():.4g}")
    else:
        model = mechanism_build(case, n)
        mechanism_work(model)
        print(f"{case}: {n} positions")
