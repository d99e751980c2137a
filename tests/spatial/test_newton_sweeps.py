"""Spatial sweeps on the compiled Newton path: the same numbers as the general path, and the
classic results derived apart (Hooke's joint, the spherical four-bar)."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import kinematika.sweep.compiled as compiled
from kinematika.sweep.run import Sweeper

EXAMPLES = Path(__file__).parents[2] / "examples"


def both_paths(name: str, by: float, steps: int):
    """(compiled, general) results of one sweep."""
    sweeper = Sweeper(EXAMPLES / f"{name}.yaml")
    plan = sweeper.plan(by, steps)
    fast = compiled.compiled_sweep(sweeper, plan)
    assert fast is not None, "the compiled path did not take this sweep"
    saved = compiled.compiled_sweep
    compiled.compiled_sweep = lambda *args: None
    try:
        general = Sweeper(EXAMPLES / f"{name}.yaml").run(by, steps)
    finally:
        compiled.compiled_sweep = saved
    return fast, general


@pytest.mark.parametrize("name,by,steps,idle", [
    ("rssr_spatial_four_bar", -60, 30, {"coupler"}),
    ("hooke_joint", 350, 35, set()),
    ("spherical_four_bar", 360, 36, set()),
])
def test_the_compiled_path_gives_the_general_paths_numbers(name, by, steps, idle):
    fast, general = both_paths(name, by, steps)
    assert fast.ok.all() and general.ok.all()
    for body, values in general.bodies.items():
        for q, v in values.items():
            if q == "angle" and body in idle:
                continue        # an idle spin has no position form: its angle depends on the path
            np.testing.assert_allclose(fast.bodies[body][q], v, atol=1e-9, err_msg=f"{body}.{q}")
    for point, values in general.points.items():
        for q, v in values.items():
            np.testing.assert_allclose(fast.points[point][q], v, atol=1e-9, err_msg=f"{point}.{q}")


def test_hookes_joint_follows_the_cardan_formula():
    beta = math.radians(30)
    sweeper = Sweeper(EXAMPLES / "hooke_joint.yaml")
    result = sweeper.run(360, 72)
    assert result.method == "newton" and result.ok.all()
    theta = np.radians(result.coordinate)
    u = np.array([math.cos(beta), math.sin(beta), 0.0])
    phi = np.unwrap(np.arctan2(np.sin(theta), math.cos(beta) * np.cos(theta)))   # tan φ = tan θ / cos β
    np.testing.assert_allclose(result.bodies["output"]["angle"] @ u, np.degrees(phi), atol=1e-7)
    ratio = math.cos(beta) / (1 - math.sin(beta) ** 2 * np.cos(theta) ** 2)
    np.testing.assert_allclose(result.bodies["output"]["omega"], ratio[:, None] * u, atol=1e-9)
    np.testing.assert_allclose(result.bodies["input"]["omega"], np.tile([1.0, 0, 0], (73, 1)), atol=1e-12)


def _cone_meet(a, d, cos_a, cos_d, near):
    """The unit vector at the given angles from a and from d, nearest `near`."""
    n = np.cross(a, d)
    x, y = np.linalg.solve([[a @ a, a @ d], [d @ a, d @ d]], [cos_a, cos_d])
    base = x * a + y * d
    z = math.sqrt((1 - base @ base) / (n @ n))
    return min((base + z * n, base - z * n), key=lambda b: np.linalg.norm(b - near))


def test_the_spherical_four_bar_keeps_its_arcs_and_the_rockers_rate_is_its_angles_rate():
    result = Sweeper(EXAMPLES / "spherical_four_bar.yaml").run(360, 720)
    assert result.method == "newton" and result.ok.all()
    theta = np.radians(result.coordinate)
    a0 = np.array([0.0, 0.5, math.sqrt(3) / 2])
    d = np.array([math.sin(math.pi / 3), 0.0, 0.5])
    b = np.array([0.738834276689, 0.673861538519, 0.005876695946])
    cos_ab, cos_bd = a0 @ b, b @ d
    expected, psi = [], []
    for t in theta:
        a = np.array([-math.sin(t) * a0[1], math.cos(t) * a0[1], a0[2]])   # A turned about z
        b = _cone_meet(a, d, cos_ab, cos_bd, b)
        expected.append(b)
        b0 = np.array([0.738834276689, 0.673861538519, 0.005876695946])
        p0, p = b0 - (b0 @ d) * d, b - (b @ d) * d
        psi.append(math.atan2(np.cross(p0, p) @ d, p0 @ p))
    np.testing.assert_allclose(result.points["B@rocker"]["position"], expected, atol=1e-9)
    psi = np.unwrap(psi)
    rate = np.gradient(psi, theta)                   # dψ/dθ with the crank at 1 rad/s
    omega = result.bodies["rocker"]["omega"]
    np.testing.assert_allclose((omega @ d)[1:-1], rate[1:-1], atol=5e-4 * np.abs(rate).max())      # O(h²) of the differences
    np.testing.assert_allclose(np.cross(omega, d), 0.0, atol=1e-9)     # the rocker turns about D


@pytest.mark.parametrize("name,by,idle", [
    ("rssr_spatial_four_bar", -60, {"coupler"}),
    ("hooke_joint", 350, set()),
    ("spherical_four_bar", 360, set()),
])
def test_a_dense_sweep_gives_the_general_paths_numbers_at_every_tenth_row(name, by, idle):
    """Dense sweeps solve most rows from a neighbour's inverse (levels, refinement): every
    tenth of 720 rows equals the general path's sweep of 72 steps."""
    sweeper = Sweeper(EXAMPLES / f"{name}.yaml")
    fast = compiled.compiled_sweep(sweeper, sweeper.plan(by, 720))
    assert fast is not None and fast.ok.all()
    _, general = both_paths(name, by, 72)
    for body, values in general.bodies.items():
        for q, v in values.items():
            if not (q == "angle" and body in idle):
                np.testing.assert_allclose(fast.bodies[body][q][::10], v, atol=1e-9, err_msg=f"{body}.{q}")
    for point, values in general.points.items():
        for q, v in values.items():
            np.testing.assert_allclose(fast.points[point][q][::10], v, atol=1e-9, err_msg=f"{point}.{q}")


def test_near_a_limit_position_coarse_rows_stay_on_their_branch():
    """The RSSR's crank cannot pass about −89.9°: swept to −89.5° the two assemblies are
    close, and coarse rows solved five at a time by Newton's method once landed on the
    other one (the rocker turned 0.03 rad away). Each coarse row equals the general path's."""
    from scipy.spatial.transform import Rotation

    name = EXAMPLES / "rssr_spatial_four_bar.yaml"
    saved = compiled.compiled_sweep
    compiled.compiled_sweep = lambda *args: None
    try:
        general = Sweeper(name).run(-89.5, 720)
    finally:
        compiled.compiled_sweep = saved
    sweeper = Sweeper(name)
    plan = sweeper.plan(-89.5, 720)
    kernel = compiled.CompiledNewton(sweeper, plan)
    dq = np.asarray(plan.increments)
    rots, ts = np.empty((len(dq), len(kernel.bodies), 3, 3)), np.empty((len(dq), len(kernel.bodies), 3))
    rots[0], ts[0] = np.eye(3), 0.0
    stride = int(compiled.COARSE_STEP / abs(dq[1] - dq[0]))
    with np.errstate(all="ignore"):
        solved = kernel._coarse(rots, ts, dq, np.unique(np.r_[np.arange(0, len(dq), stride), len(dq) - 1]))
    assert solved is not None and len(solved) > compiled.AHEAD
    rocker = kernel.bodies.index("rocker")
    expected = Rotation.from_rotvec(np.radians(general.bodies["rocker"]["angle"][solved])).as_matrix()
    np.testing.assert_allclose(rots[solved, rocker], expected, atol=1e-9)
