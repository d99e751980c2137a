"""Synthesis against designs known in closed form: each test builds its targets from a
four-bar by its own closure (the law of cosines), runs `kinematika synthesize` with a small,
fixed budget (generations, a seed: no clock), and recomputes the written design's error
from the written model file — by the contract's sweep, or by the test's own closure."""
from __future__ import annotations

import csv
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from kinematika.api import as_model
from kinematika.cli import app
from kinematika.explore.plots import pareto_front
from kinematika.explore.synthesis import function_targets
from kinematika.sweep import run_sweep

from .models import FOUR_BAR, SLIDER_CRANK

PAPERS = """
name: Path-generating four-bar
parameters: {x0: 0, y0: 0, theta0: 0, r1: 4, r2: 1, r3: 3.5, r4: 3, rcx: 1.5, rcy: 1, theta2: 0}
points:
  O2: [x0, y0]
  O4: {from: O2, distance: r1, angle: theta0}
  A: {from: O2, distance: r2, angle: theta0 + theta2}
  B: {circles: [[A, r3], [O4, r4]], side: left}
  P: {frame: [A, B], at: [rcx, rcy]}
bodies: {ground: [O2, O4], crank: [O2, A], coupler: [A, B, P], rocker: [O4, B]}
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [ground, rocker], at: O4}
drivers: [{omega: crank, value: 1}]
"""


def closure(o2, o4, r2, r3, r4, c, side, phi):
    """A, B, P of a four-bar at the crank's absolute angle φ, by the law of cosines (None
    where it does not assemble): γ at A between A→O4 and A→B."""
    a = o2 + r2 * np.exp(1j * phi)
    d = o4 - a
    cos = (r3 ** 2 + abs(d) ** 2 - r4 ** 2) / (2 * r3 * abs(d))
    if abs(cos) > 1:
        return None
    theta3 = np.angle(d) + side * np.arccos(cos)
    return a, a + r3 * np.exp(1j * theta3), a + c * np.exp(1j * theta3)


def papers_design(path):
    """The papers' variables of a written model → (O2, O4, r2, r3, r4, c)."""
    p = {k: float(v.value.text) for k, v in as_model(path).parameters.items()}
    o2 = complex(p["x0"], p["y0"])
    return (o2, o2 + p["r1"] * np.exp(1j * p["theta0"]), p["r2"], p["r3"], p["r4"], complex(p["rcx"], p["rcy"]),
            p)


def invoke(tmp_path, model: str, *args: str):
    (tmp_path / "m.yaml").write_text(model)
    return CliRunner().invoke(app, ["synthesize", str(tmp_path / "m.yaml"), *args, "-o", str(tmp_path / "out")])


def write(path, header: str, rows) -> str:
    path.write_text(header + "\n" + "".join(",".join(repr(float(v)) for v in row) + "\n" for row in rows))
    return str(path)


# path generation ------------------------------------------------------------------------------
KNOWN = (0j, 3.7 + 0j, 2.0, 4.0, 2.7, 1.7 + 1.7j, 1.0)      # O2 at the origin, ground along x


def test_a_timed_path_is_met_exactly_and_the_sweep_agrees(tmp_path):
    """Five points of a known crank-rocker's coupler curve, 15° of crank apart from 30°
    (`--timing j1=30`, the model drawn at 0°): the design found meets them to 1e-8, and the
    contract's sweep of the written file (rows every 15°) passes through them."""
    angles = np.radians([30, 45, 60, 75, 90])
    points = [closure(*KNOWN, t)[2] for t in angles]
    targets = write(tmp_path / "t.csv", "x,y,input", [(p.real, p.imag, 15 * i) for i, p in enumerate(points)])
    out = invoke(tmp_path, PAPERS, "--vary", "r1=1:6", "--vary", "r2=1:6", "--vary", "r3=1:6", "--vary", "r4=1:6",
                 "--vary", "rcx=-3:3", "--vary", "rcy=-3:3", "--target", targets, "--point", "P",
                 "--timing", "j1=30", "--objective", "sse", "--generations", "5", "--best", "1")
    assert out.exit_code == 0, out.output
    rows = run_sweep(as_model(tmp_path / "out" / "best-1.yaml"), by=90, steps=6).points["P@coupler"]["position"]
    got = rows[2:, 0] + 1j * rows[2:, 1]
    assert np.sum(np.abs(got - np.array(points)) ** 2) < 1e-16
    sse = float(out.output.split("sse = ")[1].split()[0])
    assert sse == pytest.approx(np.sum(np.abs(got - np.array(points)) ** 2), abs=1e-18)


def test_free_timing_targets_are_met_in_order_by_a_crank_rocker(tmp_path):
    """Six points of a known crank-rocker's curve, their timing free, with `--require
    crank-rocker --require ordered`: the written design is a crank-rocker (its lengths by
    hand), meets each point (nearest point of its curve, by a dense turn of the test's own
    closure) within 1e-6 and meets them in order along the motion."""
    known = (0.5 + 0.3j, 4.3 + 1.1j, 1.2, 4.1, 3.3, 2.2 - 0.9j, 1.0)
    points = [closure(*known, t)[2] for t in np.radians([10, 60, 110, 170, 230, 300])]
    targets = write(tmp_path / "t.csv", "x,y", [(p.real, p.imag) for p in points])
    out = invoke(tmp_path, PAPERS, "--vary", "x0=-2:2", "--vary", "y0=-2:2", "--vary", "theta0=0:6.283185307179586",
                 "--vary", "r1=0.5:6", "--vary", "r2=0.5:6", "--vary", "r3=0.5:6", "--vary", "r4=0.5:6",
                 "--vary", "rcx=-4:4", "--vary", "rcy=-4:4", "--target", targets, "--point", "P", "--objective", "sse",
                 "--require", "crank-rocker", "--require", "ordered", "--generations", "60", "--best", "1")
    assert out.exit_code == 0, out.output
    o2, o4, r2, r3, r4, c, _ = papers_design(tmp_path / "out" / "best-1.yaml")
    r1 = abs(o4 - o2)
    assert r2 < min(r1, r3, r4) and r2 + max(r1, r3, r4) < r1 + r3 + r4 - max(r1, r3, r4)
    turn = np.linspace(0, 2 * np.pi, 20001)
    curve = np.array([closure(o2, o4, r2, r3, r4, c, 1.0, t)[2] for t in turn])
    nearest = [int(np.argmin(np.abs(curve - p))) for p in points]
    assert max(np.min(np.abs(curve - p)) for p in points) < 1e-3
    along = np.mod(np.array(nearest) - nearest[0], 20000)
    assert (np.diff(along) > 0).all()
    sse = float(out.output.split("sse = ")[1].split()[0])
    assert sse < 1e-12


# The best Ellipse10 design compiled in the public code of Nguyen-Van et al. (Symmetry 14 (2022)
# 381; CheckCase5.m, third column): r1, r2, r3, r4, rcx, rcy, x0, y0, theta0, then the ten crank
# angles θ2 (radians from the ground line), and the published table of targets it was scored on.
PUBLISHED_ELLIPSE = (80.0, 8.045662, 50.81902, 42.20801, -10.63697, -2.29109, 8.494813, -0.7579678, 3.88921,
                     (2.449437, 3.153969, 3.837114, 4.520171, 5.204799, 5.898536, 0.316204, 1.023555, 1.738992,
                      2.449437))
ELLIPSE_TABLE = (20 + 10j, 17.66 + 15.142j, 11.736 + 17.878j, 5 + 16.928j, 0.60307 + 12.736j, 0.60307 + 7.2638j,
                 5 + 3.0718j, 11.736 + 2.1215j, 17.66 + 4.8577j, 20 + 10j)


def test_the_published_ellipse_design_scores_the_same_by_the_papers_formula_and_the_contracts_solver(tmp_path):
    """The papers' own closed form — the loop closure solved for the coupler's angle by the
    half-angle tangent, θ3 = 2 atan((−E − √(E² − 4DF)) / 2D) with their K1, K4, K5 — and the
    contract's solver on the papers' model (B on the left), the crank turned θ2 from the drawn
    configuration, give the same points: the published design's error, 4.02e-4 on the table."""
    import kinematika

    r1, r2, r3, r4, rcx, rcy, x0, y0, th0, th2 = PUBLISHED_ELLIPSE
    th2 = np.array(th2)
    k1, k4, k5 = r1 / r2, r1 / r3, (r4 ** 2 - r1 ** 2 - r2 ** 2 - r3 ** 2) / (2 * r3 * r2)
    d = np.cos(th2) - k1 + k4 * np.cos(th2) + k5
    e = -2 * np.sin(th2)
    f = k1 + (k4 - 1) * np.cos(th2) + k5
    th3 = 2 * np.arctan((-e - np.sqrt(e * e - 4 * d * f)) / (2 * d))
    papers = complex(x0, y0) + np.exp(1j * th0) * (r2 * np.exp(1j * th2) + complex(rcx, rcy) * np.exp(1j * th3))
    values = dict(zip(("r1", "r2", "r3", "r4", "rcx", "rcy", "x0", "y0", "theta0"), PUBLISHED_ELLIPSE[:9]))
    model = PAPERS.replace("{x0: 0, y0: 0, theta0: 0, r1: 4, r2: 1, r3: 3.5, r4: 3, rcx: 1.5, rcy: 1, theta2: 0}",
                           "{" + ", ".join(f"{k}: {v!r}" for k, v in values.items()) + ", theta2: 0}")
    (tmp_path / "m.yaml").write_text(model)
    ours = np.array([complex(*kinematika.solve(str(tmp_path / "m.yaml"), move={"j1": math.degrees(q)})
                             .position("P@coupler")[:2]) for q in th2])
    assert np.allclose(ours, papers, atol=1e-9)
    sse = float(np.sum(np.abs(papers - np.array(ELLIPSE_TABLE)) ** 2))
    assert sse == pytest.approx(4.02e-4, rel=1e-3)


def test_a_transmission_angle_requirement_holds_over_the_whole_turn(tmp_path):
    """`--require transmission=40 --require crank-rocker`: the written design's least
    transmission angle, over a dense turn of the test's own closure (min(μ, 180° − μ), μ
    between coupler and rocker), is at least 40°."""
    known = (0j, 3.7 + 0j, 1.0, 3.6, 2.9, 1.2 + 1.1j, 1.0)
    points = [closure(*known, t)[2] for t in np.radians([20, 90, 160, 250, 320])]
    targets = write(tmp_path / "t.csv", "x,y", [(p.real, p.imag) for p in points])
    out = invoke(tmp_path, PAPERS, "--vary", "r1=2:6", "--vary", "r2=0.5:2", "--vary", "r3=2:6", "--vary", "r4=2:6",
                 "--vary", "rcx=-3:3", "--vary", "rcy=-3:3", "--target", targets, "--point", "P", "--require",
                 "transmission=40", "--require", "crank-rocker", "--generations", "15", "--best", "1")
    assert out.exit_code == 0, out.output
    o2, o4, r2, r3, r4, c, _ = papers_design(tmp_path / "out" / "best-1.yaml")
    least = 90.0
    for t in np.linspace(0, 2 * np.pi, 7201):
        a, b, _ = closure(o2, o4, r2, r3, r4, c, 1.0, t)
        mu = np.degrees(abs(np.angle((a - b) / (o4 - b))))
        least = min(least, mu, 180 - mu)
    assert least >= 40 - 1e-6


# function generation: Freudenstein -----------------------------------------------------------
FUNCTION = """
name: Function generator
parameters: {d: 1, a: 2, b: 2.5, c: 2.7, theta: 0}
points:
  O2: [0, 0]
  O4: [d, 0]
  A: {from: O2, distance: a, angle: theta}
  B: {circles: [[A, b], [O4, c]], side: left}
bodies: {ground: [O2, O4], crank: [O2, A], coupler: [A, B], rocker: [O4, B]}
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [ground, rocker], at: O4}
drivers: [{omega: crank, value: 1}]
"""


def log_targets(count: int):
    """y = log10 x on [1, 2] at Chebyshev points; the input turns 60° over the range from 0°,
    the output 90° from its zero at 300° (absolute): (x travel, y rotation) in degrees."""
    k = np.arange(1, count + 1)
    x = 1.5 - 0.5 * np.cos((2 * k - 1) * np.pi / (2 * count))
    return 60 * (x - 1), 90 * np.log10(x) / np.log10(2)


def rocker_angles(a, b, c, d, phi):
    """The rocker's absolute angles by the law of cosines (B on the left of A→O4)."""
    out = []
    for t in phi:
        got = closure(0j, d + 0j, a, b, c, 0j, 1.0, t)
        out.append(np.nan if got is None else np.angle(got[1] - d))
    return np.array(out)


def test_freudensteins_three_points_are_met_exactly(tmp_path):
    """Freudenstein's equation K1 cos ψ − K2 cos φ + K3 = cos(φ − ψ) at three precision
    points, solved here: the design written is that one, its error below 1e-9°."""
    x, y = log_targets(3)
    phi, psi = np.radians(x), np.radians(300 + y)
    k = np.linalg.solve(np.stack([np.cos(psi), -np.cos(phi), np.ones(3)], 1), np.cos(phi - psi))
    a, c = 1 / k[0], 1 / k[1]
    b = math.sqrt(a * a + c * c + 1 - 2 * a * c * k[2])
    out = invoke(tmp_path, FUNCTION, "--vary", "a=0.5:5", "--vary", "b=0.5:5", "--vary", "c=0.5:5",
                 "--target-function", write(tmp_path / "f.csv", "x,y", zip(x, y)), "--output", "rocker",
                 "--output-zero", "300", "--generations", "5", "--best", "1")
    assert out.exit_code == 0, out.output
    p = {k_: float(v.value.text) for k_, v in as_model(tmp_path / "out" / "best-1.yaml").parameters.items()}
    assert (p["a"], p["b"], p["c"]) == pytest.approx((a, b, c), rel=1e-9)
    error = np.degrees(np.abs(np.angle(np.exp(1j * (rocker_angles(p["a"], p["b"], p["c"], 1.0, phi) - psi)))))
    assert error.max() < 1e-9


def test_five_points_reach_the_least_squares_optimum(tmp_path):
    """Five precision points (no exact design): the written design's sum of squared errors
    is stationary (its gradient, by central differences of the test's closure, vanishes) and
    no worse than Freudenstein's linear least-squares design."""
    x, y = log_targets(5)
    phi, psi = np.radians(x), np.radians(300 + y)

    def sse(a, b, c):
        return float(np.sum(np.degrees(np.angle(np.exp(1j * (rocker_angles(a, b, c, 1.0, phi) - psi)))) ** 2))

    out = invoke(tmp_path, FUNCTION, "--vary", "a=0.5:5", "--vary", "b=0.5:5", "--vary", "c=0.5:5",
                 "--target-function", write(tmp_path / "f.csv", "x,y", zip(x, y)), "--output", "rocker",
                 "--output-zero", "300", "--objective", "sse", "--generations", "5", "--best", "1")
    assert out.exit_code == 0, out.output
    p = {k_: float(v.value.text) for k_, v in as_model(tmp_path / "out" / "best-1.yaml").parameters.items()}
    best = sse(p["a"], p["b"], p["c"])
    h = 1e-6
    grad = [(sse(*(v + h * (i == j) for j, v in enumerate((p["a"], p["b"], p["c"])))) -
             sse(*(v - h * (i == j) for j, v in enumerate((p["a"], p["b"], p["c"]))))) / (2 * h) for i in range(3)]
    assert np.max(np.abs(grad)) < 1e-5 * max(best, 1e-3)
    k, *_ = np.linalg.lstsq(np.stack([np.cos(psi), -np.cos(phi), np.ones(5)], 1), np.cos(phi - psi), rcond=None)
    a, c = 1 / k[0], 1 / k[1]
    assert best <= sse(a, math.sqrt(a * a + c * c + 1 - 2 * a * c * k[2]), c) + 1e-12


# motion generation: Burmester -----------------------------------------------------------------
MOTION = """
name: Motion generator
parameters: {x2: 0, y2: 0, x4: 4, y4: 0, a: 1, b: 4, c: 3, px: 2, py: 1, kappa: 0, theta: 1.0}
points:
  O2: [x2, y2]
  O4: [x4, y4]
  A: {from: O2, distance: a, angle: theta}
  B: {circles: [[A, b], [O4, c]], side: left}
  P: {frame: [A, B], at: [px, py]}
  Q: {from: P, distance: 1, angle: kappa, reference: [A, B]}
bodies: {ground: [O2, O4], crank: [O2, A], coupler: [P, Q, A, B], rocker: [O4, B]}
joints:
  - {type: revolute, bodies: [ground, crank], at: O2}
  - {type: revolute, bodies: [crank, coupler], at: A}
  - {type: revolute, bodies: [coupler, rocker], at: B}
  - {type: revolute, bodies: [ground, rocker], at: O4}
drivers: [{omega: crank, value: 1}]
"""
MOTION_VARY = ["--vary", "x2=-3:3", "--vary", "y2=-3:3", "--vary", "x4=0:8", "--vary", "y4=-3:3", "--vary", "a=0.2:5",
               "--vary", "b=0.5:8", "--vary", "c=0.5:8", "--vary", "px=-5:5", "--vary", "py=-5:5",
               "--vary", "kappa=-3.1416:3.1416", "--vary", "theta=-3.1416:3.1416"]


def poses_of(o2, o4, a, b, c, p, kappa, angles):
    """The coupler's poses (P, direction of P→Q) of a known four-bar."""
    out = []
    for t in np.radians(angles):
        pa, pb, _ = closure(o2, o4, a, b, c, 0j, 1.0, t)
        e = (pb - pa) / b
        out.append((pa + p * e, np.angle(e) + kappa))
    return out


def pose_error(params, poses):
    """Each pose's distance to the written design's nearest pose over a turn (dense grid, then
    a bounded scalar minimisation between the grid's neighbours): √(|ΔP|² + (ρ Δφ)²), ρ the coupler's size."""
    from scipy.optimize import minimize_scalar

    o2, o4 = complex(params["x2"], params["y2"]), complex(params["x4"], params["y4"])
    a, b, c, kappa = params["a"], params["b"], params["c"], params["kappa"]
    local = {"P": complex(params["px"], params["py"]), "A": 0j, "B": b + 0j}
    local["Q"] = local["P"] + np.exp(1j * kappa)
    rho = max(abs(u - v) for u in local.values() for v in local.values())

    def distance(t, target, angle):
        got = closure(o2, o4, a, b, c, local["P"], 1.0, t)
        if got is None:
            return 1e9
        line = np.angle(got[1] - got[0]) + kappa
        return math.hypot(abs(got[2] - target), rho * np.angle(np.exp(1j * (line - angle))))

    errors = []
    grid = np.linspace(0, 2 * np.pi, 3601)
    for target, angle in poses:
        values = [distance(t, target, angle) for t in grid]
        k = int(np.argmin(values))
        step = grid[1] - grid[0]          # the offset from the grid's best, so that Brent's tolerance
        sol = minimize_scalar(             # (relative to the variable) is far below the 1e-8 asked
            lambda u, t0=grid[k], target=target, angle=angle: distance(t0 + u, target, angle) ** 2,
            bounds=(-step, step), method="bounded", options={"xatol": 1e-15, "maxiter": 500})
        errors.append(min(math.sqrt(sol.fun), values[k]))
    return max(errors)


@pytest.mark.parametrize("count", [3, 4])
def test_burmesters_three_and_four_poses_are_met_exactly(tmp_path, count):
    poses = poses_of(0.3 - 0.2j, 4.2 + 0.5j, 1.1, 3.8, 3.2, 2.1 + 1.3j, 0.4, [40, 95, 150, 230][:count])
    targets = write(tmp_path / "p.csv", "x,y,angle", [(p.real, p.imag, np.degrees(a)) for p, a in poses])
    out = invoke(tmp_path, MOTION, *MOTION_VARY, "--target-motion", targets, "--point", "P", "--generations", "1",
                 "--best", "1")
    assert out.exit_code == 0, out.output
    params = {k: float(v.value.text) for k, v in as_model(tmp_path / "out" / "best-1.yaml").parameters.items()}
    assert pose_error(params, poses) < 1e-8


# the task's file, weights, budget, and bad input ---------------------------------------------
def test_a_weight_column_weighs_the_errors_and_designs_csv_lists_the_designs(tmp_path):
    """Targets no four-bar of the family meets exactly, one weighted 100: the reported sse is
    Σ w |P − T|² recomputed from the written design's own sweep rows (timed targets on rows),
    and that target is met closer than without its weight."""
    angles = [0, 30, 60, 90]
    base = [closure(*KNOWN, np.radians(t))[2] for t in angles]
    points = [p + d for p, d in zip(base, (0.05, -0.04j, 0.03, 0.06j))]

    def run(weights, folder):
        rows = [(p.real, p.imag, 30 * i, w) for i, (p, w) in enumerate(zip(points, weights))]
        targets = write(tmp_path / f"{folder}.csv", "x,y,input,weight", rows)
        (tmp_path / "m.yaml").write_text(PAPERS)
        out = CliRunner().invoke(app, ["synthesize", str(tmp_path / "m.yaml"), "--vary", "r1=1:6", "--vary", "r2=1:6",
                                       "--vary", "r3=1:6", "--vary", "r4=1:6", "--vary", "rcx=-3:3", "--vary",
                                       "rcy=-3:3", "--target", targets, "--point", "P", "--timing", "j1=0",
                                       "--objective", "sse", "--generations", "3", "--best", "1", "-o",
                                       str(tmp_path / folder)])
        assert out.exit_code == 0, out.output
        sweep = run_sweep(as_model(tmp_path / folder / "best-1.yaml"), by=90, steps=3).points["P@coupler"]["position"]
        got = sweep[:, 0] + 1j * sweep[:, 1]
        errors = np.abs(got - np.array(points))
        with open(tmp_path / folder / "designs.csv") as f:
            table = list(csv.DictReader(f))
        assert [r["design"] for r in table] == ["best-1.yaml"]
        assert float(table[0]["sse"]) == pytest.approx(float(np.sum(np.array(weights) * errors ** 2)), rel=1e-9)
        return errors

    plain = run([1, 1, 1, 1], "plain")
    weighted = run([1, 100, 1, 1], "weighted")
    assert weighted[1] < plain[1]


def test_a_time_budget_of_nothing_still_writes_the_exact_start(tmp_path):
    """`--seconds 0`: one generation, and the exact (Freudenstein) start polished: the same
    design whatever the machine's speed."""
    x, y = log_targets(3)
    out = invoke(tmp_path, FUNCTION, "--vary", "a=0.5:5", "--vary", "b=0.5:5", "--vary", "c=0.5:5",
                 "--target-function", write(tmp_path / "f.csv", "x,y", zip(x, y)), "--output", "rocker",
                 "--output-zero", "300", "--seconds", "0", "--best", "1")
    assert out.exit_code == 0, out.output
    assert float(out.output.split("max = ")[1].split()[0]) < 1e-9


PATH_ARGS = ["--vary", "r2=1:6", "--vary", "r4=1:6", "--point", "P"]


@pytest.mark.parametrize("rows, extra, message", [
    ("x,y\n1,2\n", [], "t.csv: 1 target; synthesis needs at least 2"),
    ("x,y,input\n1,2,0\n1,3,20\n2,3,20\n", ["--timing", "j1"], "t.csv, line 4: the input values must increase (20 then 20)"),
    ("x,y,input\n1,2,5\n1,3,20\n", ["--timing", "j1"], "t.csv, line 2: the first target's input is 0"),
    ("x,y,input\n1,2,0\n1,3,20\n", [], "t.csv: column 'input' is not read by this task (give --timing JOINT"),
    ("1,2,0,1,7\n1,3,20,1,7\n", [], "t.csv: 5 columns; this task reads x,y[,weight]"),
    ("x,y\n1,2\n1,3\n", ["--require", "fast"], "unknown requirement 'fast'"),
    ("x,y\n1,2\n1,3\n", ["--require", "transmission=95"], "DEG is an angle between 0 and 90"),
    ("x,y,input\n1,2,0\n1,3,10\n", ["--timing", "j2"], "joint 'j2' is not driven"),
    ("x,y\n1,2\n1,3\n", ["--objective", "mean"], "--objective is sse or max"),
    ("x,y,weight\n1,2,1\n1,3,-1\n", [], "t.csv, line 3: a weight must be positive"),
])
def test_bad_input_is_one_line_and_exit_2(tmp_path, rows, extra, message):
    (tmp_path / "t.csv").write_text(rows)
    out = invoke(tmp_path, PAPERS, *PATH_ARGS, "--target", str(tmp_path / "t.csv"), *extra)
    assert out.exit_code == 2
    assert message in out.output and len(out.output.strip().splitlines()) == 1, out.output


def test_a_requirement_the_model_cannot_meet_is_refused(tmp_path):
    """A crank-rocker asked of a slider-crank; a crank-rocker no design of the box can be (the
    crank longer than the ground everywhere)."""
    (tmp_path / "t.csv").write_text("x,y\n1,0.2\n1.5,0.6\n")
    out = invoke(tmp_path, SLIDER_CRANK, "--vary", "r=0.5:1.5", "--target", str(tmp_path / "t.csv"),
                 "--point", "B", "--require", "crank-rocker")
    assert out.exit_code == 2 and "crank-rocker needs a four-bar" in out.output
    (tmp_path / "t.csv").write_text("x,y\n20,20\n20,25\n20,30\n")
    out = invoke(tmp_path, PAPERS, "--vary", "r1=1:2", "--vary", "r2=3:4", "--target", str(tmp_path / "t.csv"),
                 "--point", "P", "--require", "crank-rocker", "--generations", "3")
    assert out.exit_code == 2 and "no design within the --vary intervals" in out.output, out.output


# the family of docs/explore.md -------------------------------------------------------------
def test_function_targets_are_chebyshev_precision_points():
    rows = [tuple(map(float, line.split(","))) for line in function_targets("x/2 + 1", (0, 90), 3).split()]
    expect_x = [45 - 45 * np.cos(np.pi * (2 * k - 1) / 6) for k in (1, 2, 3)]
    assert [x for x, _ in rows] == pytest.approx(expect_x)
    assert [y for _, y in rows] == pytest.approx([x / 2 + 1 for x in expect_x])


def test_the_pareto_front_keeps_designs_no_other_beats_in_both():
    a = np.array([1.0, 2.0, 3.0, 2.5, 4.0, 1.5])
    b = np.array([5.0, 3.0, 1.0, 3.5, 0.5, 6.0])
    assert sorted(pareto_front(a, b).tolist()) == [0, 1, 2, 4]


def test_the_family_recovers_its_rocker_and_draws_the_curves(tmp_path):
    """The docs' family (crank a, rocker c varied): seven points of its own coupler curve
    (by the test's closure) give back a = 2.25, c = 4.35; the figure is drawn."""
    known = (0j, 5.2 + 0j, 2.25, 6.1, 4.35, 3.4 - 1.15j, 1.0)
    points = [closure(*known, t)[2] for t in np.radians([60.5, 95.3, 150.2, 210.7, 260.1, 300.9, 340.4])]
    targets = write(tmp_path / "t.csv", "x,y", [(p.real, p.imag) for p in points])
    out = invoke(tmp_path, FOUR_BAR, "--vary", "a=1.5:3", "--vary", "c=3.5:5.5", "--target", targets, "--point", "P",
                 "--generations", "8", "--best", "2", "--plot", str(tmp_path / "curves.png"))
    assert out.exit_code == 0, out.output
    p = as_model(tmp_path / "out" / "best-1.yaml").parameters
    assert (float(p["a"].value.text), float(p["c"].value.text)) == pytest.approx((2.25, 4.35), abs=1e-6)
    assert (tmp_path / "curves.png").stat().st_size > 10_000


def test_a_slider_crank_takes_the_general_path(tmp_path):
    """A model the four-bar path does not take (its point on a slider-crank's rod): the rows
    of the sweep score it; the written design passes a turn and its objective is recomputed
    from its own sweep (the largest distance to the polyline of its rows)."""
    from kinematika.explore.metrics import path_distances

    model = SLIDER_CRANK
    (tmp_path / "t.csv").write_text("x,y\n1.9,0.5\n3.1,0.5\n")
    out = invoke(tmp_path, model, "--vary", "r=0.5:1.5", "--vary", "l=2.5:3.5", "--target", str(tmp_path / "t.csv"),
                 "--point", "B", "--generations", "4", "--best", "1")
    assert out.exit_code == 0, out.output
    rows = run_sweep(as_model(tmp_path / "out" / "best-1.yaml"), steps=360).points["B@slider"]["position"]
    path = (rows[:, 0] + 1j * rows[:, 1])[None, :]
    expect = path_distances(path, np.array([1.9 + 0.5j, 3.1 + 0.5j])).max()
    assert float(out.output.split("max = ")[1].split()[0]) == pytest.approx(expect, abs=1e-9)


def test_function_generation_from_an_expression_on_the_command_line(tmp_path):
    """ψ = 0.4 θ over the first 60° of crank travel: the family's rockers turn that way, and the
    best design found meets the five precision points within a degree."""
    out = invoke(tmp_path, FOUR_BAR, "--vary", "a=1.5:3", "--vary", "c=3.5:5.5", "--target-function", "0.4*x",
                 "--output", "rocker", "--over", "0:60", "--points", "5", "--population", "16",
                 "--generations", "15", "--best", "1", "--plot", str(tmp_path / "f.png"))
    assert out.exit_code == 0, out.output
    assert float(out.output.split("max = ")[1].split()[0]) < 1.0
    assert (tmp_path / "out" / "best-1.yaml").exists() and (tmp_path / "f.png").stat().st_size > 10_000
