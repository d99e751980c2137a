"""The compiled Newton path's array helpers against plain numpy/scipy, on random inputs."""
from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from kinematika.sweep.rigid import LinearVectors, exp_rotations, perpendicular
from kinematika.sweep.stacked import refined

seeds = st.integers(0, 2**32 - 1)


@settings(max_examples=40, deadline=None)
@given(seeds, st.floats(1e-3, 0.3))
def test_refinement_from_a_nearby_inverse_solves_as_numpy_does(seed, distance):
    rng = np.random.default_rng(seed)
    s = rng.normal(size=(20, 6, 6)) + 4 * np.eye(6)
    near = s + distance * rng.normal(size=s.shape) / 6          # a neighbour's matrix
    b = rng.normal(size=(20, 6))
    y, ok = refined(s, np.linalg.inv(near), b)
    rho = np.abs(np.eye(6) - np.linalg.inv(near) @ s).sum(axis=-2).max(axis=-1)
    assert ok[rho < 0.2].all()                   # 40 steps of at most 0.2: converged
    exact = np.linalg.solve(s, b[..., None])[..., 0]
    np.testing.assert_allclose(y[ok], exact[ok], rtol=1e-12, atol=1e-12)     # flagged rows are not used


@settings(max_examples=40, deadline=None)
@given(seeds, st.sampled_from([1e-13, 1e-6, 0.5, 3.0]))
def test_rotations_from_vectors_are_scipys(seed, size):
    w = np.random.default_rng(seed).normal(size=(30, 3)) * size
    np.testing.assert_allclose(exp_rotations(w), Rotation.from_rotvec(w).as_matrix(), atol=1e-15)


@settings(max_examples=30, deadline=None)
@given(seeds)
def test_vectors_fixed_in_bodies_are_r_v_plus_t(seed):
    rng = np.random.default_rng(seed)
    rot = Rotation.random(4 * 3, random_state=seed % 2**31).as_matrix().reshape(4, 3, 3, 3)
    t = rng.normal(size=(4, 3, 3))
    v0, v1, v2 = rng.normal(size=(3, 3))
    vectors = LinearVectors(3)
    vectors.add("point", [[(1, v0, True, 1.0)]])
    vectors.add("direction", [[(2, v1, False, 1.0)]])
    vectors.add("frame", [[(-1, v2, True, 1.0)]])
    vectors.add("between", [[(0, v0, True, 1.0), (2, v1, True, -1.0)]])
    vectors.compile()
    out = vectors(rot, t)
    np.testing.assert_allclose(vectors.part(out, "point")[:, 0], rot[:, 1] @ v0 + t[:, 1], atol=1e-12)
    np.testing.assert_allclose(vectors.part(out, "direction")[:, 0], rot[:, 2] @ v1, atol=1e-12)
    np.testing.assert_allclose(vectors.part(out, "frame")[:, 0], np.tile(v2, (4, 1)), atol=1e-15)
    np.testing.assert_allclose(vectors.part(out, "between")[:, 0],
                               rot[:, 0] @ v0 + t[:, 0] - rot[:, 2] @ v1 - t[:, 2], atol=1e-12)


@given(st.lists(st.floats(-1, 1), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 0.1))
def test_a_perpendicular_is_a_unit_vector_at_right_angles(v):
    e = np.array(v) / np.linalg.norm(v)
    u = perpendicular(e)
    assert abs(u @ e) < 1e-12 and abs(np.linalg.norm(u) - 1) < 1e-12
