"""Variants on the statement's grids (same seed, same variants; distinct; away from dead
points) and their key: `solve --set` of each variant, and the hand derivations' values."""
from __future__ import annotations

import json
import subprocess
import sys
from decimal import Decimal

import pytest

from kinematika.errors import KinematikaError
from kinematika.exercise.folder import key_csv, variants_csv
from kinematika.exercise.variants import MAX_CONDITION, parse_vary

from tests.conftest import DEEP
from tests.model.test_cases import kinematika

from . import derive
from .conftest import COUNT, FOUR_BAR, P_PAIR, P_PAIR_VARY, four_bar_data, make, p_pair_data


def test_the_same_seed_gives_the_same_variants(p_pair_exercise):
    """Variants are drawn in the generator's order: the same seed's first few are the first
    of the shared exercise's (all of them made again in a deep run), another seed's are others."""
    count = COUNT if DEEP else 4
    again = make(P_PAIR, P_PAIR_VARY, count, 7)
    assert [v.stated for v in again.variants] == [v.stated for v in p_pair_exercise.variants[:count]]
    other = make(P_PAIR, P_PAIR_VARY, count, 8)
    assert [v.stated for v in other.variants] != [v.stated for v in p_pair_exercise.variants[:count]]


def test_variants_are_distinct_and_on_the_grids(p_pair_exercise, four_bar_exercise):
    for ex in (p_pair_exercise, four_bar_exercise):
        seen = {tuple(v.stated.values()) for v in ex.variants}
        assert len(seen) == len(ex.variants) == COUNT
        for v in ex.variants:
            for vary in ex.varies:
                x = v.stated[vary.name]
                assert vary.low <= x <= vary.high and (x - vary.low) % vary.step == 0


def test_no_variant_is_near_a_dead_point(p_pair_exercise, four_bar_exercise):
    for ex in (p_pair_exercise, four_bar_exercise):
        assert all(v.solution.solver.analysis.diagnosis.condition_number <= MAX_CONDITION
                   for v in ex.variants)


def test_a_grid_of_dead_points_only_is_refused():
    # s = 400 mm, E at (100, 400) mm: B's velocity as the rocker allows it (⊥ EB) lies along
    # the guide at β ≈ 59.7° (hand: the direction ⊥ EB is (0.475, 0.88), the guide's at 60°
    # is (0.5, 0.866)), a dead point; within a degree of it nothing is well conditioned
    with pytest.raises(KinematikaError) as err:
        make(P_PAIR, ["beta=59:61:0.5"], 3, 1)
    assert err.value.kind == "assembly" and "dead point" in err.value.message


def test_a_vary_is_read_with_its_step_or_a_tenth_of_its_magnitude():
    assert parse_vary("s=300:500:10").count == 21
    assert parse_vary("w=0.8:1.2").step == Decimal("0.01")
    assert parse_vary("w=5:15").step == Decimal("1")
    for bad in ("s=300", "s=5:1", "s=1:2:0", "=1:2", "s=a:b"):
        with pytest.raises(KinematikaError) as err:
            parse_vary(bad)
        assert err.value.where == "--vary"


def _close(got, want, size, rel=1e-9):
    assert abs(got - want) <= rel * max(size, 1e-12), (got, want)


def _keys_are_hand_derivations(exercise, derivation, data):
    for v in exercise.variants:
        hand = derive.rows(derivation(**data(v.stated)))
        assert [r.question for r in v.rows] == list(hand)
        for r in v.rows:
            _close(r.value, hand[r.question][0], hand[r.question][1])


def test_every_p_pair_key_is_the_hand_derivation(p_pair_exercise):
    _keys_are_hand_derivations(p_pair_exercise, derive.p_pair, p_pair_data)


def test_every_four_bar_key_is_the_hand_derivation(four_bar_exercise):
    _keys_are_hand_derivations(four_bar_exercise, derive.four_bar, four_bar_data)


def _flat(answers, asks):
    out = {}
    for k in asks:
        value = answers[k - 1]["value"]
        if isinstance(value, list):
            out.update({f"q{k}.{axis}": x for axis, x in zip("xyz", value)})
        else:
            out[f"q{k}"] = value
    return out


def test_every_key_equals_solve_with_the_variants_values_through_the_api(p_pair_exercise, four_bar_exercise):
    from kinematika.commands import How, solve_data

    for ex, path in ((p_pair_exercise, P_PAIR), (four_bar_exercise, FOUR_BAR)):
        for v in ex.variants:
            answers = solve_data(path, how=How(set=v.sets))["answers"]
            assert {r.question: r.value for r in v.rows} == _flat(answers, ex.asks)


def test_a_few_keys_equal_solve_set_on_the_command_line(p_pair_exercise, four_bar_exercise):
    """The first variant of each exercise in a child process, as a user runs it; the second
    in this process by click's runner (the same command, without an interpreter's start-up)."""
    for ex, path in ((p_pair_exercise, P_PAIR), (four_bar_exercise, FOUR_BAR)):
        for k, v in enumerate(ex.variants[:2]):
            sets = [a for name, expr in v.sets.items() for a in ("--set", f"{name}={expr}")]
            if k == 0:
                done = subprocess.run([sys.executable, "-m", "kinematika", "solve", str(path), "--json", *sets],
                                      capture_output=True, text=True, check=True)
                answers = json.loads(done.stdout)["answers"]
            else:
                code, out = kinematika("solve", str(path), "--json", *sets)
                assert code == 0, out
                answers = out["answers"]
            assert {r.question: r.value for r in v.rows} == _flat(answers, ex.asks)


def test_the_sets_are_the_stated_values_in_the_models_units(p_pair_exercise):
    v = p_pair_exercise.variants[0]
    assert v.sets["s"] == f"{v.stated['s'].normalize():f}/1000"
    assert v.sets["beta"] == f"deg({v.stated['beta'].normalize():f})"


def test_variants_csv_and_key_csv_are_the_contracts(p_pair_exercise):
    lines = variants_csv(p_pair_exercise).splitlines()
    assert lines[0] == "variant,s,beta,w" and len(lines) == 1 + COUNT
    first = p_pair_exercise.variants[0]
    assert lines[1].split(",") == ["1", *(f"{first.stated[n].normalize():f}" for n in ("s", "beta", "w"))]
    key = key_csv(p_pair_exercise).splitlines()
    assert key[0] == "variant,question,value,tolerance"
    questions = [line.split(",")[1] for line in key[1:11]]
    assert questions == ["q1", "q2", "q3.x", "q3.y", "q4.x", "q4.y", "q5.x", "q5.y", "q6.x", "q6.y"]
    # each box's tolerance: the section's 1 % plus the rounding allowance (at most 8 %: a variant
    # more sensitive is not drawn), or narrowed to tell a mistake apart, never below 0.5 %
    from kinematika.exercise.margins import FLOOR, SENSITIVE

    tolerances = [float(line.split(",")[3]) for line in key[1:]]
    assert all(FLOOR <= t <= 0.01 + SENSITIVE for t in tolerances)
    assert sum(t >= 0.01 for t in tolerances) > len(tolerances) / 2
    assert len(key) == 1 + COUNT * 10


def test_mistakes_that_barely_differ_are_told_apart_or_their_variant_not_drawn(p_pair_exercise):
    """Every kept variant tells each usual mistake from the right answer by 1.5 (right +
    mistaken) margins on each vector it changes; the command says what it narrowed or left out."""
    import math

    from kinematika.exercise.margins import APART, NOISE

    for v in p_pair_exercise.variants:
        stems = {}
        for r in v.rows:
            stems.setdefault(r.question.rsplit(".", 1)[0] if r.question[-2:] in (".x", ".y") else r.question, []).append(r)
        for m in v.mistaken:
            for group in stems.values():
                wrong = [m.rows.get(r.question) for r in group]
                if any(w is None for w in wrong):
                    continue
                size = group[0].size
                gap = math.sqrt(sum((w.value - r.value) ** 2 for w, r in zip(wrong, group))) / size
                tol = v.tolerance_of(group[0])
                if gap <= min(tol, NOISE + p_pair_exercise.tolerance):
                    continue                                   # a change no margin sees
                assert gap >= APART * tol * (1 + min(1.0, wrong[0].size / size)) * (1 - 1e-9), (v.number, m.kind)
    said = [str(n) for n in p_pair_exercise.notes]
    assert said and all(n.startswith(("not drawn: ", "variant ")) for n in said)
    for n in (n for n in said if n.startswith("variant ")):
        number, stem = int(n.split()[1].rstrip(":")), n.split("margin of ")[1].split()[0]
        assert stem in p_pair_exercise.variant(number).narrowed
