"""A spatial pose's rotations, points and directions (written out in Python floats for
speed, `sweep.poses`) against scipy's rotations and numpy's products, on random inputs."""
from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from kinematika.sweep.poses import SpatialPoses, exp_rotation

seeds = st.integers(0, 2**32 - 1)


@settings(max_examples=40, deadline=None)
@given(seeds, st.sampled_from([1e-13, 1e-6, 0.5, 3.0, 10.0]))
def test_a_rotation_from_its_vector_is_scipys(seed, size):
    """Rodrigues, R = I + sin θ K + (1 − cos θ) K², against scipy's rotation of the same
    vector (below 1e-12 rad the first order I + K, within 1e-24 of it)."""
    for w in np.random.default_rng(seed).normal(size=(10, 3)) * size:
        np.testing.assert_allclose(exp_rotation(w), Rotation.from_rotvec(w).as_matrix(), atol=1e-15)


@settings(max_examples=30, deadline=None)
@given(seeds)
def test_a_bodys_points_and_directions_are_r_p_minus_c_plus_c_plus_t_and_r_v(seed):
    rng = np.random.default_rng(seed)
    ref = tuple(rng.normal(size=3))
    rot = Rotation.random(2, random_state=seed % 2**31).as_matrix()
    t = rng.normal(size=(2, 3))
    poses = SpatialPoses(ref, {"a": rot[0], "b": rot[1]}, {"a": t[0], "b": t[1]}, {}, {})
    for _ in range(5):
        p0, v = tuple(rng.normal(size=3)), tuple(rng.normal(size=3))
        for i, body in enumerate("ab"):
            expected = rot[i] @ (np.array(p0) - ref) + np.array(ref) + t[i]
            assert np.allclose(poses.point(body, p0), expected, rtol=0, atol=1e-12)
            assert np.allclose(poses.turn(body, v), rot[i] @ np.array(v), rtol=0, atol=1e-12)
        assert poses.point("ground", p0) == p0 and poses.turn("ground", v) == v    # the frame stays
