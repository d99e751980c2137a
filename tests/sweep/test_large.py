"""One instant of a large mechanism: the sparse path (a chain of parallelogram loops).

Every loop is a parallelogram, so by hand every rocker turns exactly as the crank does
(ω, α) and every coupler translates. Small chains (dense SVD) and large ones (sparse LU)
must give the same answers, and a dead point must still be reported.
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from kinematika import KinematikaError, solve
from kinematika.engine import linsolve
from kinematika.model.model import Joint

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))
from chain import four_bar_chain


def test_large_chain_moves_as_its_crank():
    sol = solve(four_bar_chain(301, w=10.0, alpha=3.0))
    assert type(sol.solver.analysis).__name__ == "SparseAnalysis"
    assert sol.dof == 1
    for i in (1, 75, 150):
        assert sol.omega(f"rocker{i}") == pytest.approx(10.0, rel=1e-9)
        assert sol.alpha(f"rocker{i}") == pytest.approx(3.0, rel=1e-7)
        assert sol.omega(f"coupler{i}") == pytest.approx(0.0, abs=1e-9)
    # the pin of the last loop moves as the crank pin: v = ω k × (0, 1)
    assert sol.velocity("A150@rocker150") == pytest.approx((-10.0, 0.0), abs=1e-8)


def test_sparse_and_dense_paths_agree(monkeypatch):
    tree = four_bar_chain(61, w=4.0, alpha=-2.0)
    tree["points"]["A5"] = [20.0, 1.0]
    sparse = solve(tree)
    monkeypatch.setattr(linsolve, "LARGE", 10 ** 6)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    dense = solve(tree)
    assert type(dense.solver.analysis).__name__ == "Analysis"
    for body in sparse.model.moving_bodies:
        assert sparse.omega(body) == pytest.approx(dense.omega(body), abs=1e-10)
        assert sparse.alpha(body) == pytest.approx(dense.alpha(body), abs=1e-9)


def test_a_flat_chain_is_reported_as_by_the_dense_path(monkeypatch):
    # crank horizontal: every parallelogram lies flat on the ground line, where each loop
    # gains an instantaneous degree of freedom; the sparse LU fails and the dense analysis
    # names the free bodies, as for a small system
    tree = four_bar_chain(61)
    for name, xy in tree["points"].items():
        if name.startswith("A"):
            xy[0], xy[1] = xy[0] + 1.0, 0.0
    with pytest.raises(KinematikaError) as sparse:
        solve(tree)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    with pytest.raises(KinematikaError) as dense:
        solve(tree)
    assert (sparse.value.kind, str(sparse.value)) == (dense.value.kind, str(dense.value))
    assert sparse.value.kind == "mobility" and "left free: coupler1, rocker1" in str(sparse.value)


@pytest.mark.parametrize("seed", range(6))
def test_the_inverse_norm_estimate_is_a_close_lower_bound(seed):
    """Hager's estimate of ‖A⁻¹‖₁ from the LU against the exact norm of the dense inverse:
    never above it, and within a factor 3 of it (it is exact for almost every matrix)."""
    import numpy as np
    from scipy.sparse import identity, random as sparse_random
    from scipy.sparse.linalg import splu

    n = 60 + 40 * seed
    a = (sparse_random(n, n, density=4 / n, random_state=seed) + 0.3 * identity(n)).tocsc()
    exact = np.abs(np.linalg.inv(a.toarray())).sum(axis=0).max()
    estimate = linsolve.inverse_norm(splu(a), n)
    assert exact / 3 <= estimate <= exact * (1 + 1e-12)


def _mixed_chain() -> dict:
    """A chain whose loops are not parallelograms, some pins written (b, a) rather than
    (a, b), and a slider-crank at its end whose prismatic joint is listed among the pins:
    the rows of the pins filled as arrays must be put back in the joints' order."""
    tree = four_bar_chain(61, w=-2.5, alpha=0.7)
    for i in range(1, 31):
        tree["points"][f"A{i}"] = [4.0 * i + 0.1 * (i % 5), 1.0 + 0.05 * (i % 3)]
    for k, joint in enumerate(tree["joints"]):
        if k % 3 == 1:
            joint["bodies"] = joint["bodies"][::-1]
    tree["points"]["B"] = [4.0 * 30 + 3.0, 1.2]
    tree["points"]["E"] = [4.0 * 30 + 5.0, 0.0]
    tree["bodies"]["rod"] = ["A30", "B"]
    tree["bodies"]["slider"] = ["B"]
    tree["bodies"]["ground"].append("E")
    slider = {"type": "prismatic", "bodies": ["ground", "slider"], "along": ["O30", "E"]}
    tree["joints"][40:40] = [slider]
    tree["joints"] += [{"type": "revolute", "bodies": ["rocker30", "rod"], "at": "A30"},
                       {"type": "revolute", "bodies": ["rod", "slider"], "at": "B"}]
    return tree


def test_a_mixed_chain_gives_the_dense_paths_answers_and_messages(monkeypatch):
    tree = _mixed_chain()
    sparse = solve(tree)
    assert type(sparse.solver.analysis).__name__ == "SparseAnalysis"
    solver = sparse.solver
    assert len(solver.labels) == len(solver.wheres) == len(solver.pairs) == len(solver.b_v)
    # the slider's rows sit where its joint is listed: after the first 40 joints' 80 rows
    assert {solver.wheres[80], solver.wheres[81]} == {"joints[40] (j41)"}
    assert solver.pairs[80] == frozenset(("ground", "slider"))
    assert "j41" in str(solver.labels[80]) and "j40" in str(solver.labels[79])
    monkeypatch.setattr(linsolve, "LARGE", 10 ** 6)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    dense = solve(tree)
    assert [str(x) for x in dense.solver.labels] == [str(x) for x in solver.labels]
    assert dense.solver.wheres == list(solver.wheres) and dense.solver.pairs == list(solver.pairs)
    for body in sparse.model.moving_bodies:
        assert sparse.omega(body) == pytest.approx(dense.omega(body), abs=1e-10)
        assert sparse.alpha(body) == pytest.approx(dense.alpha(body), abs=1e-8)
    assert sparse.velocity("B@slider") == pytest.approx(dense.velocity("B@slider"), abs=1e-9)


def test_the_pins_rows_filled_as_arrays_are_the_textbook_ones():
    # v_P(b) − v_P(a) = 0 with v_P = v₀ + ω k × r, r = P − ref: the x row has 1 at v₀x(b),
    # −r_y at ω_b, −1 at v₀x(a) and +r_y at ω_a; the y row 1, +r_x, −1, −r_x. At the
    # acceleration level the known part is −ω² r for each body: b = (ω_b² − ω_a²) r.
    import numpy as np

    from kinematika.engine.levels import AccelerationLevel, KnownTerms, VelocityLevel
    from kinematika.joints.revolute import KIND

    sol = solve(_mixed_chain())
    solver, u = sol.solver, sol.solver.unknowns
    ref = solver.inst.ref
    pins = [g for g in solver.geos.values() if g.joint.type == "revolute"]
    rows = KIND.numeric_rows(pins, VelocityLevel(u, ref))
    motion = sol.solver._motion(solver.solve_linear(solver.b_v), None)
    known = KIND.numeric_rows(pins, AccelerationLevel(KnownTerms(u), ref, motion))
    for k, geo in enumerate(pins):
        j = geo.joint
        rx, ry = geo.at[0] - ref[0], geo.at[1] - ref[1]
        for axis, (trans, lever) in enumerate(((1, -ry), (2, rx))):
            want = {}
            for body, sign in ((j.b, 1.0), (j.a, -1.0)):
                if body in u.offset:
                    want[u.offset[body] + trans] = sign
                    if lever != 0:
                        want[u.offset[body]] = sign * lever
            i = 2 * k + axis
            got = dict(zip(rows.cols[rows.indptr[i]:rows.indptr[i + 1]].tolist(),
                           rows.vals[rows.indptr[i]:rows.indptr[i + 1]].tolist()))
            assert got == pytest.approx(want, abs=1e-15)
            assert rows.b[i] == 0.0
        wa, wb = (motion.states[x].omega if x in u.offset else 0.0 for x in (j.a, j.b))
        assert known.b[2 * k:2 * k + 2] == pytest.approx((wb ** 2 - wa ** 2) * np.array([rx, ry]), abs=1e-12)


def test_the_rows_filled_as_arrays_are_the_joints_rows_bit_for_bit(monkeypatch):
    # one statement of each kind's rows: its array fill gives the matrix, right sides and
    # labels that its `rows`, joint by joint, give (signs of zeros included)
    import numpy as np

    from kinematika.engine.levels import AccelerationLevel, KnownTerms, VelocityLevel
    from kinematika.engine.linsolve import sparse_matrix
    from kinematika.engine.system import InstantSolver

    sol = solve(_mixed_chain())
    solver, u = sol.solver, sol.solver.unknowns
    motion = solver._motion(solver.solve_linear(solver.b_v), None)
    level = AccelerationLevel(KnownTerms(u), solver.inst.ref, motion)
    arrays_b, arrays_labels = solver.known_terms(level)
    monkeypatch.setattr(InstantSolver, "batched", property(lambda self: False))
    rows = solver.rows(VelocityLevel(u, solver.inst.ref))
    by_rows = sparse_matrix(rows, u.n)
    for name in ("indptr", "cols", "vals"):
        assert getattr(solver.a_num, name).tobytes() == getattr(by_rows, name).tobytes()
    assert np.array(solver.b_v, float).tobytes() == np.array([-r.lin.const for r in rows], float).tobytes()
    assert [str(x) for x in solver.labels] == [str(r.label) for r in rows]
    joints_b, joints_labels = solver.known_terms(level)
    assert np.array(arrays_b, float).tobytes() == np.array(joints_b, float).tobytes()
    assert [str(x) for x in arrays_labels] == [str(x) for x in joints_labels]


def test_the_rows_labels_are_made_only_when_an_error_reads_them(monkeypatch):
    # a 1000-body instant makes thousands of row labels that only an error reads
    # (docs/performance.md, sixth round): none is said while the instant solves, and read
    # afterwards they are the joint-by-joint path's, row for row
    from kinematika.joints import revolute

    said = []
    shared = revolute._shared
    monkeypatch.setattr(revolute, "_shared", lambda j, i: said.append((j.id, i)) or shared(j, i))
    placed = []         # each row's place in the file and pair of bodies: made when read too
    monkeypatch.setattr(Joint, "where", property(lambda j: placed.append(j.id) or f"joints[{j.index}] ({j.id})"))
    sol = solve(_mixed_chain())
    assert type(sol.solver.analysis).__name__ == "SparseAnalysis"
    assert said == []
    # (the slider's rows, built joint by joint as `Row`s, say their place as they are made)
    pins = {j.id for j in sol.model.joints if j.type == "revolute"}
    assert not pins & set(placed)
    labels = [str(x) for x in sol.solver.labels]
    assert len(said) == 2 * sum(1 for j in sol.model.joints if j.type == "revolute")
    assert sol.solver.wheres[80] == "joints[40] (j41)" and sol.solver.pairs[80] == frozenset(("ground", "slider"))
    assert pins <= set(placed)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    assert [str(x) for x in solve(_mixed_chain()).solver.labels] == labels


def test_conflicting_drivers_of_a_large_chain_are_named_as_by_the_dense_path(monkeypatch):
    # a parallelogram's rocker turns as the crank: ω = 5 for rocker5 against the crank's 10
    # cannot hold; the error names both drivers (rows read from the labels made when read).
    # 61 loops are on the sparse path, as for the neighbours' comparisons (301 before: the
    # dense SVD of its ~1 200 unknowns was most of the test's 20 s under load)
    tree = four_bar_chain(61)
    assert type(solve(tree).solver.analysis).__name__ == "SparseAnalysis"
    tree["drivers"].append({"omega": "rocker5", "value": 5.0})
    with pytest.raises(KinematikaError) as sparse:
        solve(tree)
    monkeypatch.setattr(linsolve, "LARGE", 10 ** 6)
    monkeypatch.setattr("kinematika.engine.system.LARGE", 10 ** 6)
    with pytest.raises(KinematikaError) as dense:
        solve(tree)
    assert (sparse.value.kind, str(sparse.value)) == (dense.value.kind, str(dense.value))
    # both drivers, side by side (in the order the dense path gives them: rocker5 first at 61
    # loops, the crank first at 301)
    crank, rocker = "drivers[0] (ω of crank = 10.0)", "drivers[1] (ω of rocker5 = 5.0)"
    assert f"{crank}; {rocker}" in str(sparse.value) or f"{rocker}; {crank}" in str(sparse.value)
